//! Dual scattering (Zinke, Yuksel, Weber and Keyser 2008) for the fur BCSDF: the light that
//! reaches a fiber through other fibers, as a term added to single scattering
//! (docs/model.md §13).
//!
//! - [`DualTables`]: the per-fiber quantities over θ (ā_f, ā_b, α_f, α_b, β_f², β_b², A_b,
//!   Δ_b, the density-free part of σ_b), each family's longitudinal mean and variance, and the
//!   azimuthal tables N^G of each family, all computed by [`DualTables::compute`] from any
//!   [`crate::Bcsdf`] (every family, the residual included) by quadrature. Fixed-size arrays:
//!   no allocation anywhere.
//! - [`eval`]: the term to add, from the angles, the number of fibers between the shading
//!   point and the light, and the density factors d_f, d_b ([`Density`]). No panic, no NaN.

mod tables;
#[cfg(test)]
mod tests;

pub use tables::{Quadrature, MAX_PHI_STEPS};

use crate::frame::Angles;
use crate::gaussian::Gaussian;
use crate::lobes::FAMILY_COUNT;
use crate::math::{Libm, Math, PI};
use crate::model::inv_cos2_theta_i;
use crate::spectrum::Rgb;

/// Nodes of every table over θ ∈ [−π/2, π/2] (cell centres θ_k = −π/2 + (k + ½)·π/64).
pub const THETA_NODES: usize = 64;
/// Nodes of the N^G tables over |φ| ∈ [0, π] (φ_j = j·π/31, ends included).
pub const PHI_NODES: usize = 32;
/// Largest fiber count [`eval`] uses; larger counts (and +∞) are clamped to it.
pub const MAX_FIBERS: f32 = 1.0e6;
/// Largest density factor [`eval`] uses; larger ones are clamped to it.
pub const MAX_DENSITY: f32 = 4.0;
/// Smallest variance a Gaussian of this module is given (rad²): a lobe narrower than 0.1°
/// is a numerical zero width, not a physical one.
pub const MIN_VARIANCE: f32 = 3.0e-6;

/// How light is attenuated on its way through the fibers between the light and the shading
/// point (docs/model.md §13).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Attenuation {
    /// Zinke et al. 2008: T_f = ā_f^n, light reaches the point by forward scattering only.
    Forward,
    /// A two-stream stack of n identical layers, each transmitting ā_f and reflecting ā_b
    /// (light scattered back by one fiber and forward again by the one before it is kept),
    /// one layer added at a time (the adding method): T_{k+1} = ā_f T_k/(1 − ā_b R_k),
    /// R_{k+1} = ā_b + ā_f² R_k/(1 − ā_b R_k), T_0 = 1, R_0 = 0, with nothing beneath the
    /// shading point; n is clamped to [`MAX_STACK`] here. The local backscatter's energy is
    /// the same stack's, A_b = R_∞ − ā_b ([`semi_infinite_reflectance`] less the single
    /// backscatter S already holds), in place of Zinke's two-term series, in the back half
    /// only.
    TwoStream,
    /// The n fibers between the shading point and the light as [`Attenuation::TwoStream`]'s
    /// stack, lying on the rest of the coat, taken as a semi-infinite stack of the same
    /// layers (reflectance R_∞, [`semi_infinite_reflectance`]): light the coat below sends
    /// back up and the n fibers above send down again reaches the shading point too. The
    /// downward flux there is D_n = T_n/(1 − R_n R_∞) (the adding method with the coat below;
    /// 1 at every depth for lossless fibers, where T_n alone falls as 1/(1 + n ā_b/ā_f)).
    /// The light the coat below sends up to the shading fiber is scattered into both halves
    /// ([`local_backscatter`]). The shipped attenuation.
    Coat,
}

/// Largest fiber count of the two-stream recursion ([`Attenuation::TwoStream`]).
pub const MAX_STACK: u32 = 4096;

/// The light that reaches a shading point behind `n` fibers (n ≥ 0, fractional n geometric
/// between the neighbouring integers) of forward fraction `t` and backward fraction `r`, per
/// [`Attenuation`]: the stack's transmittance T_n for [`Attenuation::Forward`] and
/// [`Attenuation::TwoStream`], the downward flux D_n = T_n/(1 − R_n R_∞) for
/// [`Attenuation::Coat`]. In [0, 1]; 1 for n ≤ 0 or NaN.
#[must_use]
pub fn transmittance(attenuation: Attenuation, t: f32, r: f32, n: f32) -> f32 {
    let t = if t > 0.0 { t.min(1.0) } else { 0.0 };
    let r = if r > 0.0 { r.min(1.0 - t) } else { 0.0 };
    if n.is_nan() || n <= 0.0 {
        return 1.0;
    }
    match attenuation {
        Attenuation::Forward => libm::powf(t, n.min(MAX_FIBERS)),
        Attenuation::TwoStream | Attenuation::Coat => {
            let below = if attenuation == Attenuation::Coat {
                semi_infinite_reflectance(t, r)
            } else {
                0.0
            };
            // The downward flux under a stack of transmittance tk and reflectance rk lying on
            // a stack of reflectance `below`.
            let down = |tk: f32, rk: f32| tk / (1.0 - rk * below).max(1e-6);
            let n = n.min(MAX_STACK as f32);
            let whole = n as u32; // n ≥ 0, ≤ MAX_STACK
            let frac = n - whole as f32;
            let (mut tk, mut rk) = (1.0f32, 0.0f32);
            for _ in 0..whole {
                if tk < 1e-12 {
                    return 0.0;
                }
                let denom = 1.0 - rk * r;
                let (t1, r1) = (tk * t / denom, r + t * t * rk / denom);
                tk = t1;
                rk = r1.min(1.0);
            }
            let mut flux = down(tk, rk);
            if frac > 0.0 {
                let denom = 1.0 - rk * r;
                let next = down(tk * t / denom, (r + t * t * rk / denom).min(1.0));
                flux *= libm::powf(next / flux.max(1e-30), frac);
            }
            if flux.is_finite() {
                flux.clamp(0.0, 1.0)
            } else {
                0.0
            }
        }
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

/// Zinke's density factors d_f (forward, the spread term) and d_b (local backscatter),
/// docs/model.md §13. [`eval`] maps NaN and negative values to 0 and clamps to
/// [`MAX_DENSITY`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Density {
    /// d_f, the forward scattering density factor.
    pub d_f: f32,
    /// d_b, the backward scattering density factor.
    pub d_b: f32,
}

impl Density {
    /// The default shipped, with [`Attenuation::Coat`]: d_f = d_b = 1, Zinke's values for a
    /// coat whose fibers are as dense as the counted ones (no fit): within issue 23's bounds
    /// of the path tracer for dog and deer on both scenes (docs/model.md §13,
    /// docs/accuracy.md).
    pub const DEFAULT: Density = Density { d_f: 1.0, d_b: 1.0 };

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
fn theta_position(theta: f32) -> (usize, f32) {
    let t = (theta + 0.5 * PI) * (THETA_NODES as f32 / PI) - 0.5;
    let t = if t > 0.0 { t } else { 0.0 }; // NaN → 0
    let t = t.min((THETA_NODES - 1) as f32);
    let k = (t as usize).min(THETA_NODES - 2);
    (k, t - k as f32)
}

fn lerp(a: Rgb, b: Rgb, w: f32) -> Rgb {
    a * (1.0 - w) + b * w
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

    /// [`FiberAverages`] at θ, linear between nodes, clamped at the ends (NaN reads node 0).
    #[must_use]
    pub fn fiber_at(&self, theta: f32) -> FiberAverages {
        let (k, w) = theta_position(theta);
        let (a, b) = (&self.fiber[k], &self.fiber[k + 1]);
        FiberAverages {
            a_f: lerp(a.a_f, b.a_f, w),
            a_b: lerp(a.a_b, b.a_b, w),
            alpha_f: lerp(a.alpha_f, b.alpha_f, w),
            alpha_b: lerp(a.alpha_b, b.alpha_b, w),
            beta2_f: lerp(a.beta2_f, b.beta2_f, w),
            beta2_b: lerp(a.beta2_b, b.beta2_b, w),
            big_a_b: lerp(a.big_a_b, b.big_a_b, w),
            delta_b: lerp(a.delta_b, b.delta_b, w),
            sigma_b0: lerp(a.sigma_b0, b.sigma_b0, w),
        }
    }

    /// Family `g`'s moments at θ_r (linear, clamped).
    #[must_use]
    pub fn moments_at(&self, g: usize, theta_r: f32) -> FamilyMoments {
        let (k, w) = theta_position(theta_r);
        let (a, b) = (&self.moments[k][g], &self.moments[k + 1][g]);
        FamilyMoments {
            mean: lerp(a.mean, b.mean, w),
            variance: lerp(a.variance, b.variance, w),
        }
    }

    /// N^G of family `g` at (θ_r, |φ|), bilinear, clamped (φ folded into [0, π]).
    #[must_use]
    pub fn n_g_at(&self, g: usize, theta_r: f32, phi: f32) -> Rgb {
        let (k, w) = theta_position(theta_r);
        let p = crate::math::wrap_angle(phi).abs() * (PI_STEPS / PI);
        let p = if p > 0.0 { p.min(PI_STEPS) } else { 0.0 };
        let j = (p as usize).min(PHI_NODES - 2);
        let v = p - j as f32;
        let t = &self.n_g[g];
        lerp(
            lerp(t[k][j], t[k][j + 1], v),
            lerp(t[k + 1][j], t[k + 1][j + 1], v),
            w,
        )
    }
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
/// - [`Attenuation::TwoStream`]: A_b = R_∞ − ā_b, back half only;
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
        Attenuation::TwoStream => (r_inf - r, 0.0),
        Attenuation::Coat => {
            let up = r_inf * t / (1.0 - r * r_inf).max(1e-6);
            (t * up, r * up)
        }
    };
    let clean = |v: f32| if v.is_finite() && v > 0.0 { v } else { 0.0 };
    (clean(back), clean(front))
}

/// G(x; √variance), with the variance kept at or above [`MIN_VARIANCE`].
fn gauss(x: f32, variance: f32) -> f32 {
    let v = if variance > MIN_VARIANCE {
        variance
    } else {
        MIN_VARIANCE
    };
    Gaussian::new(libm::sqrtf(v)).eval::<Libm>(x)
}

/// The dual-scattering term to add to single scattering (docs/model.md §13), RGB, in S's
/// units (the caller multiplies by cos θ_i and the light's radiance like S).
///
/// `fibers` is the number of fibers between the shading point and the light (the shadow
/// ray's count, or an engine's deep-opacity-map count; fractional values are allowed). With
/// V = clamp(1 − fibers, 0, 1) the fraction of direct light (what a shadow ray gives), the
/// shading is S·V + this term, which is
///
/// V·d_b·f_back(σ_f² = 0) + (T_f − V)·d_f·(f_s^scatter + d_b·f_back)(σ_f²),
/// T_f = [`transmittance`] of n fibers of ā_f(−θ_i), ā_b(−θ_i) (ā_f^n for
/// [`Attenuation::Forward`]), σ_f² = n·β_f²(−θ_i), f_back(s²) = A·G(x − Δ_b; σ_b² + s²)/(π
/// cos²θ_i) with A the back-half or front-half energy of [`local_backscatter`] at θ_r.
///
/// Contract: `fibers` NaN or below 0 is 0 (unoccluded), above [`MAX_FIBERS`] (or +∞) is
/// [`MAX_FIBERS`]; the density factors as in [`Density`]. The result is finite and ≥ 0 for
/// every input; nothing panics or allocates.
#[must_use]
pub fn eval(
    tables: &DualTables,
    angles: &Angles,
    fibers: f32,
    density: Density,
    attenuation: Attenuation,
) -> Rgb {
    let n = if fibers > 0.0 {
        fibers.min(MAX_FIBERS)
    } else {
        0.0
    };
    let (d_f, d_b) = density.sanitized();
    let (ti, tr, phi) = (angles.theta_i(), angles.theta_r(), angles.phi());
    let x = ti + tr;
    let inv_cos2 = inv_cos2_theta_i(Libm::cos(ti));
    let direct = (1.0 - n).clamp(0.0, 1.0);
    // The light's path: forward scattering out of fibers toward the shading point leaves at
    // θ ≈ −θ_i, the fixed direction of the tables' energy balance.
    let along = tables.fiber_at(-ti);
    let here = tables.fiber_at(tr);
    let back_half = crate::math::wrap_angle(phi).abs() < 0.5 * PI;
    let mut out = [0.0f32; 3];
    for (c, slot) in out.iter_mut().enumerate() {
        let t_f = transmittance(attenuation, along.a_f[c], along.a_b[c], n);
        let sigma2_f = n * along.beta2_f[c].max(0.0);
        let af_here = here.a_f[c].clamp(0.0, 1.0);
        let sigma_b = (1.0 + d_b * af_here * af_here) * here.sigma_b0[c];
        // The local backscatter: its energy toward the back half (|φ| < π/2) and the front
        // half, and its longitudinal Gaussian.
        let (back, front) =
            local_backscatter(attenuation, here.big_a_b[c], here.a_f[c], here.a_b[c]);
        let half = if back_half { back } else { front };
        let f_back =
            |s2f: f32| half * gauss(x - here.delta_b[c], sigma_b * sigma_b + s2f) * inv_cos2 / PI;
        let mut value = direct * d_b * f_back(0.0);
        let spread = (t_f - direct).max(0.0);
        if spread > 0.0 {
            let mut f_s = 0.0;
            for g in 0..FAMILY_COUNT {
                let m = tables.moments_at(g, tr);
                let ng = tables.n_g_at(g, tr, phi)[c].max(0.0);
                f_s += gauss(x - m.mean[c], m.variance[c].max(0.0) + sigma2_f) * ng;
            }
            value += spread * d_f * (f_s * inv_cos2 + d_b * f_back(sigma2_f));
        }
        *slot = if value.is_finite() && value > 0.0 {
            value
        } else {
            0.0
        };
    }
    Rgb(out)
}
