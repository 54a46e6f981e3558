//! Dual scattering (Zinke, Yuksel, Weber and Keyser 2008) for the fur BCSDF: the light that
//! reaches a fiber through other fibers, as a term added to single scattering
//! (docs/model.md §13).
//!
//! - [`DualTables`]: the per-fiber quantities over θ (ā_f, ā_b, α_f, α_b, β_f², β_b², A_b,
//!   Δ_b, the density-free part of σ_b), each family's longitudinal mean and variance, and the
//!   azimuthal tables N^G of each family, all computed by [`DualTables::compute`] from any
//!   [`crate::Bcsdf`] (every family, the residual included) by quadrature. Fixed-size arrays:
//!   no allocation anywhere.
//! - [`DualLut`]: what an engine keeps, the quantities [`DualLut::eval`] reads at each θ node,
//!   derived from the tables for one [`Attenuation`] and stored as f16 in a `.furdual` blob of
//!   [`BLOB_LEN`] bytes ([`encode`], [`DualLut::decode`]; format in `blob.rs`).
//! - [`DualLut::eval`]: the term to add, from the angles, the fibers between the shading
//!   point and the light and below it ([`Fibers`]), and the density factors d_f, d_b
//!   ([`Density`]). No panic, no NaN, no allocation.
//! - [`coat`]: the finite coat's closed forms (n fibers above, m below over a black floor).

pub(crate) mod blob;
pub mod coat;
mod eval;
mod half_range;
mod tables;
#[cfg(test)]
mod tests;

pub use blob::{
    axis_coordinate, axis_node, encode, encode_axis, DualColour, DualError, DualLut, ABS_NODES,
    BLOB_LEN, DUAL_FORMAT_VERSION, DUAL_MAGIC, FIELDS,
};
pub use tables::{Quadrature, MAX_PHI_STEPS};

use crate::lobes::FAMILY_COUNT;
use crate::math::PI;
use crate::spectrum::Rgb;

/// Nodes of every table over θ ∈ [−π/2, π/2] (cell centres θ_k = −π/2 + (k + ½)·π/64).
pub const THETA_NODES: usize = 64;
/// Nodes of the N^G tables over |φ| ∈ [0, π] (φ_j = j·π/31, ends included).
pub const PHI_NODES: usize = 32;
/// Largest fiber count [`DualLut::eval`] uses; larger counts (and +∞) are clamped to it.
pub const MAX_FIBERS: f32 = 1.0e6;
/// Largest density factor [`DualLut::eval`] uses; larger ones are clamped to it.
pub const MAX_DENSITY: f32 = 4.0;
/// Smallest variance a Gaussian of this module is given (rad²): a lobe narrower than 0.1°
/// is a numerical zero width, not a physical one.
pub const MIN_VARIANCE: f32 = 3.0e-6;

/// How light is attenuated on its way through the fibers between the light and the shading
/// point (docs/model.md §13).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Attenuation {
    /// Zinke et al. 2008: T_f = ā_f^n, light reaches the point by forward scattering only;
    /// Zinke's two-term A_b in the back half.
    Forward,
    /// The n fibers between the shading point and the light as a stack of identical layers,
    /// each transmitting ā_f and reflecting ā_b, lying on the rest of the coat, taken as a
    /// semi-infinite stack of the same layers (reflectance R_∞,
    /// [`semi_infinite_reflectance`]): light the coat below sends back up and the fibers above
    /// send down again reaches the shading point too. The downward flux there is
    /// D_n = T_n/(1 − R_n R_∞) = μⁿ ([`coat_decay`]; 1 at every depth for lossless fibers).
    /// The light the coat below sends up to the shading fiber is scattered into both halves
    /// ([`local_backscatter`]). The shipped attenuation. This is what the blob stores;
    /// [`DualLut::eval`] replaces the semi-infinite coat below by the m fibers of
    /// [`Fibers::below`] over a black floor ([`coat`]).
    Coat,
}

impl Attenuation {
    /// The number a `.furdual` blob stores for it.
    #[must_use]
    pub const fn code(self) -> u32 {
        match self {
            Attenuation::Forward => 1,
            Attenuation::Coat => 2,
        }
    }

    /// The attenuation of a stored number.
    #[must_use]
    pub const fn from_code(code: u32) -> Option<Attenuation> {
        match code {
            1 => Some(Attenuation::Forward),
            2 => Some(Attenuation::Coat),
            _ => None,
        }
    }
}

/// Per-fiber decay μ of the downward flux under a stack of layers transmitting `t` and
/// reflecting `r` per [`Attenuation`]: D_n = μⁿ for every n ≥ 0 (fractional n included).
///
/// - [`Attenuation::Forward`]: μ = ā_f.
/// - [`Attenuation::Coat`]: inside a semi-infinite stack the light is the decaying eigenmode
///   of one layer's transfer matrix [[(t² − r²)/t, r/t], [−r/t, 1/t]] (determinant 1), so
///   the downward flux at depth n is μⁿ with μ + 1/μ = 2c, c = (1 + t² − r²)/(2t):
///   μ = 1/(c + √(c² − 1)) (the smaller root, in the form without cancellation). The same as
///   T_n/(1 − R_n R_∞) of the adding method; μ = 1 for lossless layers, μ = t without
///   reflection.
#[must_use]
pub fn coat_decay(attenuation: Attenuation, t: f32, r: f32) -> f32 {
    let t = if t > 0.0 { t.min(1.0) } else { 0.0 };
    let r = if r > 0.0 { r.min(1.0 - t) } else { 0.0 };
    match attenuation {
        Attenuation::Forward => t,
        Attenuation::Coat => {
            if t <= 0.0 {
                return 0.0;
            }
            let c = ((1.0 + t * t - r * r) / (2.0 * t)).max(1.0);
            let mu = 1.0 / (c + libm::sqrtf((c * c - 1.0).max(0.0)));
            if mu.is_finite() {
                mu.clamp(0.0, 1.0)
            } else {
                0.0
            }
        }
    }
}

/// The light that reaches a shading point behind `n` fibers (n ≥ 0) of forward fraction `t`
/// and backward fraction `r`, per [`Attenuation`]: μⁿ ([`coat_decay`]). In [0, 1]; 1 for
/// n ≤ 0 or NaN, n above [`MAX_FIBERS`] is [`MAX_FIBERS`].
#[must_use]
pub fn transmittance(attenuation: Attenuation, t: f32, r: f32, n: f32) -> f32 {
    if n.is_nan() || n <= 0.0 {
        return 1.0;
    }
    let v = libm::powf(coat_decay(attenuation, t, r), n.min(MAX_FIBERS));
    if v.is_finite() {
        v.clamp(0.0, 1.0)
    } else {
        0.0
    }
}

/// Reflectance of a semi-infinite two-stream stack of layers transmitting `t` and reflecting
/// `r` (the fixed point of R = r + t²R/(1 − rR)):
/// R_∞ = [1 + r² − t² − √((1 + r² − t²)² − 4r²)]/(2r); 1 for lossless layers (t + r = 1).
#[must_use]
pub fn semi_infinite_reflectance(t: f32, r: f32) -> f32 {
    let t = if t > 0.0 { t.min(1.0) } else { 0.0 };
    let r = if r > 0.0 { r.min(1.0 - t) } else { 0.0 };
    if r < 1e-7 {
        return r;
    }
    let b = 1.0 + r * r - t * t;
    let disc = (b * b - 4.0 * r * r).max(0.0);
    let v = (b - libm::sqrtf(disc)) / (2.0 * r);
    if v.is_finite() {
        v.clamp(0.0, 1.0)
    } else {
        0.0
    }
}

/// The per-light fiber counts at a shading point that [`DualLut::eval`] takes (docs/model.md
/// §13, "The coat below"): what an engine reads from its deep opacity map or voxel density
/// along the light's direction, and what the renderer's shadow rays count.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fibers {
    /// n: the fibers between the shading point and the light (fractional allowed). NaN or
    /// below 0 is 0 (unoccluded), above [`MAX_FIBERS`] (or +∞) is [`MAX_FIBERS`].
    pub to_light: f32,
    /// m: the fibers beyond the shading point, on the line from the light through it (along
    /// −ω_i), up to the skin or out of the coat: one line's sample of the coat below, which
    /// sends light back up. The term sees the neighbourhood's coat below, m +
    /// [`coat::LINE_SAMPLE_OFFSET`] layers (docs/model.md §13 "The coat below").
    /// Below 0 is no coat at all (the point lies on the skin: 0 layers); NaN, +∞ and anything
    /// above [`MAX_FIBERS`] is [`MAX_FIBERS`], a semi-infinite coat ([`Fibers::deep`]).
    pub below: f32,
}

impl Fibers {
    /// `to_light` fibers toward the light and `below` beyond the point.
    #[must_use]
    pub const fn new(to_light: f32, below: f32) -> Fibers {
        Fibers { to_light, below }
    }

    /// `to_light` fibers toward the light over a semi-infinite coat (below = +∞): for a
    /// caller that does not know how deep the coat is.
    #[must_use]
    pub const fn deep(to_light: f32) -> Fibers {
        Fibers {
            to_light,
            below: f32::INFINITY,
        }
    }

    /// (n, m̄) by the contract of the fields: n in [0, [`MAX_FIBERS`]], m̄ the layers of the
    /// coat below the term uses ([`coat::coat_below_layers`]).
    fn sanitized(self) -> (f32, f32) {
        let n = if self.to_light > 0.0 {
            self.to_light.min(MAX_FIBERS)
        } else {
            0.0
        };
        (n, coat::coat_below_layers(self.below))
    }
}

/// Zinke's density factors d_f (forward, the spread term) and d_b (local backscatter),
/// docs/model.md §13. [`DualLut::eval`] maps NaN and negative values to 0 and clamps to
/// [`MAX_DENSITY`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Density {
    /// d_f, the forward scattering density factor.
    pub d_f: f32,
    /// d_b, the backward scattering density factor.
    pub d_b: f32,
}

impl Density {
    /// The default shipped, with [`Attenuation::Coat`]: d_f = 1 (the counted fibers are the
    /// coat's; a caller that knows the light's incidence on the coat scales it by
    /// [`coat::forward_density_at_incidence`]) and d_b = 0.8, measured: of 0.7 (Zinke et
    /// al.'s value), 0.8, 0.9 and 1, the one whose worst mean over the fur on `ball` against
    /// the path tracer, over five presets from light to dark, is least (docs/model.md §13
    /// "Status", docs/accuracy.md "Dual scattering").
    pub const DEFAULT: Density = Density { d_f: 1.0, d_b: 0.8 };

    fn sanitized(self) -> (f32, f32) {
        let clean = |d: f32| {
            if d > 0.0 {
                d.min(MAX_DENSITY)
            } else {
                0.0
            }
        };
        (clean(self.d_f), clean(self.d_b))
    }
}

/// The per-fiber quantities of Zinke et al. 2008 for one fiber (RGB each), at one θ
/// (docs/model.md §13). Angles are in the model's longitudinal variable x = θ_i + θ_r.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct FiberAverages {
    /// ā_f: energy scattered into the front half (|φ| > π/2).
    pub a_f: Rgb,
    /// ā_b: energy scattered into the back half (|φ| < π/2).
    pub a_b: Rgb,
    /// α_f: energy-weighted mean of x over the front half (rad).
    pub alpha_f: Rgb,
    /// α_b: energy-weighted mean of x over the back half (rad).
    pub alpha_b: Rgb,
    /// β_f²: energy-weighted variance of x over the front half (rad²).
    pub beta2_f: Rgb,
    /// β_b²: energy-weighted variance of x over the back half (rad²).
    pub beta2_b: Rgb,
    /// A_b: the local backscatter's energy.
    pub big_a_b: Rgb,
    /// Δ_b: the local backscatter's mean shift (rad).
    pub delta_b: Rgb,
    /// The local backscatter's width before the density factor: σ_b = (1 + d_b ā_f²)·this.
    pub sigma_b0: Rgb,
}

/// One family's longitudinal mean and variance of x = θ_i + θ_r at one θ_r (docs/model.md
/// §13).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct FamilyMoments {
    /// Mean of x (rad).
    pub mean: Rgb,
    /// Variance of x (rad²).
    pub variance: Rgb,
}

/// The dual-scattering tables of one BCSDF (docs/model.md §13): 64 θ nodes of
/// [`FiberAverages`] and per-family [`FamilyMoments`], and the N^G tables of the four
/// families over (θ_r, |φ|). About 111 KB of f32.
#[derive(Clone, Debug, PartialEq)]
pub struct DualTables {
    /// Per-fiber averages at θ_k (the fixed direction of the energy balance, θ_r).
    pub fiber: [FiberAverages; THETA_NODES],
    /// Each family's moments at θ_r = θ_k, in [`crate::LobeFamily::ALL`] order.
    pub moments: [[FamilyMoments; FAMILY_COUNT]; THETA_NODES],
    /// N^G_g(θ_k, φ_j) = (1/π)∫_{|φ'−φ_j|<π/2} n_g(θ_k, φ') dφ', n_g the family's energy per
    /// unit φ (docs/model.md §13).
    pub n_g: [[[Rgb; PHI_NODES]; THETA_NODES]; FAMILY_COUNT],
}

/// θ of table node k.
#[must_use]
pub fn theta_node(k: usize) -> f32 {
    -0.5 * PI + (k as f32 + 0.5) * (PI / THETA_NODES as f32)
}

/// |φ| of N^G node j.
#[must_use]
pub fn phi_node(j: usize) -> f32 {
    j as f32 * (PI / (PI_STEPS))
}

const PI_STEPS: f32 = (PHI_NODES - 1) as f32;

/// Linear interpolation position (lower node, weight of the upper) of θ on the θ axis,
/// clamped to the end nodes.
pub(super) fn theta_position(theta: f32) -> (usize, f32) {
    let t = (theta + 0.5 * PI) * (THETA_NODES as f32 / PI) - 0.5;
    let t = if t > 0.0 { t } else { 0.0 }; // NaN → 0
    let t = t.min((THETA_NODES - 1) as f32);
    let k = (t as usize).min(THETA_NODES - 2);
    (k, t - k as f32)
}

impl DualTables {
    /// All tables zero (a fiber that scatters nothing).
    pub const ZERO: DualTables = DualTables {
        fiber: [FiberAverages {
            a_f: Rgb::ZERO,
            a_b: Rgb::ZERO,
            alpha_f: Rgb::ZERO,
            alpha_b: Rgb::ZERO,
            beta2_f: Rgb::ZERO,
            beta2_b: Rgb::ZERO,
            big_a_b: Rgb::ZERO,
            delta_b: Rgb::ZERO,
            sigma_b0: Rgb::ZERO,
        }; THETA_NODES],
        moments: [[FamilyMoments {
            mean: Rgb::ZERO,
            variance: Rgb::ZERO,
        }; FAMILY_COUNT]; THETA_NODES],
        n_g: [[[Rgb::ZERO; PHI_NODES]; THETA_NODES]; FAMILY_COUNT],
    };
}

/// Zinke's local backscatter from the fiber averages (docs/model.md §13): A_b, Δ_b and the
/// density-free σ_b, per channel.
///
/// A_b = ā_b ā_f²/(1 − ā_f²) + ā_b³ ā_f²/(1 − ā_f²)³;
/// Δ_b = α_b(1 − 2ā_b²/(1 − ā_f²)²) + α_f(2(1 − ā_f²)² + 4ā_f²ā_b²)/(1 − ā_f²)³;
/// σ_b0 = [A₁√(2β_f² + β_b²) + A₃√(2β_f² + 3β_b²)]/(A₁ + A₃), A₁, A₃ the two terms of A_b.
/// ā_f is kept at or below 0.999 (a lossless fiber's geometric series would diverge).
#[must_use]
pub fn backscatter(a_f: f32, a_b: f32, alpha_f: f32, alpha_b: f32, b2f: f32, b2b: f32) -> [f32; 3] {
    let af = if a_f > 0.0 { a_f.min(0.999) } else { 0.0 };
    let ab = if a_b > 0.0 { a_b.min(1.0) } else { 0.0 };
    let af2 = af * af;
    let ab2 = ab * ab;
    let one = 1.0 - af2;
    let a1 = ab * af2 / one;
    let a3 = ab * ab2 * af2 / (one * one * one);
    let delta = alpha_b * (1.0 - 2.0 * ab2 / (one * one))
        + alpha_f * (2.0 * one * one + 4.0 * af2 * ab2) / (one * one * one);
    let (b2f, b2b) = (b2f.max(0.0), b2b.max(0.0));
    let w1 = libm::sqrtf(2.0 * b2f + b2b);
    let w3 = libm::sqrtf(2.0 * b2f + 3.0 * b2b);
    let sigma = if a1 + a3 > 0.0 {
        (a1 * w1 + a3 * w3) / (a1 + a3)
    } else {
        w1
    };
    let finite = |v: f32| if v.is_finite() { v } else { 0.0 };
    [finite(a1 + a3), finite(delta), finite(sigma)]
}

/// The local backscatter's energy (toward the back half |φ| < π/2, toward the front half) at
/// a fiber of forward and backward fractions `a_f`, `a_b` (docs/model.md §13), per unit of
/// light reaching the fiber from the light's side:
///
/// - [`Attenuation::Forward`]: Zinke's A_b (`zinke_a_b`, [`backscatter`]), back half only;
/// - [`Attenuation::Coat`]: the light the coat below sends up to the fiber,
///   U = R_∞ ā_f/(1 − ā_b R_∞) (through the fiber, reflected by the coat below, with the
///   inter-reflections between the two), scattered by the fiber: forward through it,
///   ā_f U = R_∞ − ā_b, toward the back half, and back, ā_b U, toward the front half.
#[must_use]
pub fn local_backscatter(
    attenuation: Attenuation,
    zinke_a_b: f32,
    a_f: f32,
    a_b: f32,
) -> (f32, f32) {
    let t = if a_f > 0.0 { a_f.min(1.0) } else { 0.0 };
    let r = if a_b > 0.0 { a_b.min(1.0 - t) } else { 0.0 };
    let r_inf = semi_infinite_reflectance(t, r);
    let (back, front) = match attenuation {
        Attenuation::Forward => (zinke_a_b, 0.0),
        Attenuation::Coat => {
            let up = r_inf * t / (1.0 - r * r_inf).max(1e-6);
            (t * up, r * up)
        }
    };
    let clean = |v: f32| if v.is_finite() && v > 0.0 { v } else { 0.0 };
    (clean(back), clean(front))
}
