//! The finite coat (docs/model.md §13, "The coat below"): the fibers around a shading point
//! as a stack of identical two-stream layers, n between the point and the light and m below
//! it (away from the light) over a black floor, in closed form so that fractional counts
//! cost no loop. Per channel, from what a `.furdual` stores: the per-fiber decay μ of the
//! semi-infinite stack and the layer's forward fraction t = ā_f.
//!
//! One layer transmits t and reflects r. In the semi-infinite stack (reflectance ρ = R_∞)
//! the light decays by μ per layer, and one layer on top of it gives the two balances
//! μ(1 − rρ) = t (what passes the layer, with its reflections on the stack below) and
//! ρ(1 − tμ) = r (ρ = r + tρμ), so r never has to be recovered:
//! rρ = 1 − t/μ and ρ² = (μ − t)/(μ(1 − tμ)).
//! For n layers, R_n = ρ(1 − μ²ⁿ)/(1 − ρ²μ²ⁿ) and T_n = μⁿ(1 − ρ²)/(1 − ρ²μ²ⁿ) (the
//! adding recursion's closed form); over a black floor the m layers below reflect R_m.
//!
//! ρ² depends on the node alone: [`node_coat`] derives it once per θ node when a blob is
//! decoded, and [`crate::dual::DualLut::eval`] interpolates it linearly between nodes like
//! the stored fields (the shader derives it at both nodes and interpolates).

use super::MAX_FIBERS;
use crate::math::{exp_neg_saturating, rsqrt_newton};
use core::f32::consts::LN_2;

/// Smallest denominator the closed forms divide by; below it (a lossless or nearly lossless
/// layer with no fibers in the way) they keep the semi-infinite coat's value.
const TINY: f32 = 1e-6;

/// ρ² = R_∞², the semi-infinite stack's reflectance squared, from its decay `mu` = μ and the
/// layer's forward fraction `t`: (μ − t)/(μ(1 − tμ)), kept in [0, 1]; 0 when μ(1 − tμ) is
/// below 1e-6 (no transmission, or t = μ = 1: a layer that reflects nothing).
#[inline(always)]
#[must_use]
pub fn reflectance_squared(mu: f32, t: f32) -> f32 {
    let den = mu * (1.0 - t * mu);
    let v = (mu - t) / den.max(TINY);
    // max/min, not clamp: NaN becomes 0.
    #[allow(clippy::manual_clamp)]
    let v = v.max(0.0).min(1.0);
    if den > TINY {
        v
    } else {
        0.0
    }
}

/// The downward flux at a point under n layers with m layers below it over a black floor,
/// D = T_n/(1 − R_n R_m) = μⁿ(1 − ρ²μ²ᵐ)/(1 − ρ²μ²⁽ⁿ⁺ᵐ⁾), from `mu_n` = μⁿ,
/// `mu_2m` = μ²ᵐ and `rho2` = ρ². μⁿ when m is infinite (the semi-infinite coat) and T_n
/// when m = 0; in [0, μⁿ]. A denominator below 1e-6 keeps μⁿ.
#[inline(always)]
#[must_use]
pub fn downward_flux(mu_n: f32, mu_2m: f32, rho2: f32) -> f32 {
    let num = 1.0 - rho2 * mu_2m;
    let den = 1.0 - rho2 * mu_n * mu_n * mu_2m;
    let d = mu_n * (num / den.max(TINY));
    // max/min, not clamp: NaN becomes 0.
    #[allow(clippy::manual_clamp)]
    let d = d.max(0.0).min(mu_n);
    if den > TINY {
        d
    } else {
        mu_n
    }
}

/// The local backscatter's energy with m layers below, as a factor on the stored energy
/// (docs/model.md §13, "The coat below"). The stored energy holds the semi-infinite layer
/// stack's U_∞ = ρt/(1 − rρ) = ρμ, the light a coat returns through one more layer, the
/// shading fiber's own. But the light that comes back up to the point was reflected by the
/// coat below its neighbourhood, which the downward flux reaches beside the fiber, not
/// through it: the fiber is a point of its layer, not the whole layer. So the coat below
/// returns U_m = R_m = ρ·g per unit of the downward flux, g = (1 − μ²ᵐ)/(1 − ρ²μ²ᵐ), and the
/// factor is U_m/U_∞ = g/μ. From `rho2` = ρ², `mu` = μ and `mu_2m` = μ²ᵐ: 1/μ for an
/// infinite m, 0 for m = 0; g is kept in [0, 1] and μ at or above 1e-6. A denominator of g
/// below 1e-6 (a lossless layer, whose closed form degenerates) gives g = 1.
#[inline(always)]
#[must_use]
pub fn backscatter_factor(rho2: f32, mu: f32, mu_2m: f32) -> f32 {
    let g_den = 1.0 - rho2 * mu_2m;
    let g = (1.0 - mu_2m) / g_den.max(TINY);
    // max/min, not clamp: NaN becomes 0.
    #[allow(clippy::manual_clamp)]
    let g = g.max(0.0).min(1.0);
    let g = if g_den > TINY { g } else { 1.0 };
    g / mu.max(TINY)
}

/// μᵏ = e^(−k·ln 2·(−log₂ μ)) for k ≥ 0 from the stored log₂ μ ≤ 0
/// ([`exp_neg_saturating`]).
#[inline(always)]
#[must_use]
pub fn power_of_decay(log2_mu: f32, k: f32) -> f32 {
    exp_neg_saturating(-k * LN_2 * log2_mu)
}

/// ρ² of one channel at one θ node from its stored fields: μ = 2^(log₂ μ)
/// ([`power_of_decay`]) and t = ā_f = √(ā_f²) (ā_f² kept in [0, 1]; ā_f²/√(ā_f²) by
/// [`rsqrt_newton`]), then [`reflectance_squared`]. What
/// [`crate::dual::DualLut::decode`] derives per node and the shader's `fur_dual_coat_node`
/// repeats.
#[inline(always)]
#[must_use]
pub fn node_coat(log2_mu: f32, a_f2: f32) -> f32 {
    let mu = power_of_decay(log2_mu, 1.0);
    let a = a_f2.clamp(0.0, 1.0);
    let t = a * rsqrt_newton(a.max(1e-30));
    reflectance_squared(mu, t)
}

/// What the term adds to a caller's count of the fibers below a point that lies in the coat
/// (docs/model.md §13 "The coat below"): the count m along the one line from the light through
/// the point is a single sample of the coat around it (Poisson, with the neighbourhood's mean
/// count m̄), while the light that comes back up to the point was scattered through that
/// neighbourhood; the sample's posterior mean of m̄ (a flat prior) is m + 1. Without it a
/// point whose line happens to cross no fiber below (m = 0: e^(−m̄) of the points, 14 % where
/// the coat below holds two fibers on average) is treated as lying on bare skin and gets no
/// local backscatter at all.
pub const LINE_SAMPLE_OFFSET: f32 = 1.0;

/// The layers of the coat below the term uses for a caller's count `below`
/// ([`crate::dual::Fibers::below`]): `below` + [`LINE_SAMPLE_OFFSET`] for a count ≥ 0,
/// at most [`MAX_FIBERS`]; 0 for a negative count (the point lies on the skin: no coat);
/// [`MAX_FIBERS`] (a semi-infinite coat) for NaN and +∞. The shader's `fur_dual_below`
/// repeats it.
#[inline(always)]
#[must_use]
pub fn coat_below_layers(below: f32) -> f32 {
    if below >= 0.0 {
        (below + LINE_SAMPLE_OFFSET).min(MAX_FIBERS)
    } else if below < 0.0 {
        0.0
    } else {
        MAX_FIBERS // NaN
    }
}

/// The two-stream diffusivity factor 1/μ̄ (docs/model.md §13 "The light's incidence on the
/// coat"): light scattered inside a coat crosses a plane of it as a diffuse flux; for
/// radiance isotropic over the hemisphere the crossing directions' cosines μ are distributed
/// as 2μ dμ, so its mean path through a layer of normal depth d is d·E[1/μ] = 2d. (The
/// atmospheric two-stream practice's 1.66 was measured too: §13.)
pub const DIFFUSIVITY: f32 = 2.0;

/// The count of the coat below to pass as [`crate::dual::Fibers::below`] when the caller
/// knows the light's incidence on the coat (docs/model.md §13 "The light's incidence on the
/// coat"): `line_count` is m counted along the light's line (what [`Fibers::below`] takes
/// without the normal) and `cos_to_normal` = cos ι between the direction toward the light
/// and the skin normal under the strand (the strand's root normal). A flat coat's chord along
/// the light is its normal depth over |cos ι|, and the light the coat returns to the point
/// is diffuse, crossing [`DIFFUSIVITY`] normal depths; so the layers the term uses are
/// [`DIFFUSIVITY`]·|cos ι|·(m + [`LINE_SAMPLE_OFFSET`]), at least [`LINE_SAMPLE_OFFSET`]
/// (the point lies in the coat), returned as the count that [`coat_below_layers`] maps to
/// them. |cos ι| is clamped to 1. A negative, NaN or infinite `line_count` (the skin, the
/// semi-infinite coat) and a NaN `cos_to_normal` (the normal unknown) return `line_count`
/// unchanged: the behaviour without the normal. The shader's `fur_dual_below_at_incidence`
/// repeats it.
///
/// [`Fibers::below`]: crate::dual::Fibers::below
#[inline(always)]
#[must_use]
pub fn below_at_incidence(line_count: f32, cos_to_normal: f32) -> f32 {
    if !(0.0..MAX_FIBERS).contains(&line_count) || cos_to_normal.is_nan() {
        return line_count;
    }
    let layers = DIFFUSIVITY * cos_to_normal.abs().min(1.0) * (line_count + LINE_SAMPLE_OFFSET);
    (layers - LINE_SAMPLE_OFFSET).max(0.0)
}

/// The forward density factor d_f to pass in [`crate::dual::Density`] when the caller knows
/// the light's incidence on the coat (docs/model.md §13 "The light's incidence on the
/// coat"): `d_f`·[`DIFFUSIVITY`]·|cos ι|, `cos_to_normal` = cos ι between the direction
/// toward the light and the skin normal under the strand, |cos ι| clamped to 1. The light
/// that reaches the point through the n fibers above (the spread term, which d_f scales) has
/// been scattered inside the coat: a diffuse flux, set by the light the coat takes in per
/// unit of its area, |cos ι| times the beam's irradiance, and crossing a fiber's layer along
/// [`DIFFUSIVITY`] times its normal depth, so a fiber in it intercepts [`DIFFUSIVITY`] times
/// the flux. The term's layer stack counts along the light's line in the beam's units, as
/// if the light fell along the normal; this is the factor between the two. A NaN
/// `cos_to_normal` (the normal unknown) returns `d_f` unchanged: the behaviour without the
/// normal. The shader's `fur_dual_forward_density_at_incidence` repeats it.
#[inline(always)]
#[must_use]
pub fn forward_density_at_incidence(d_f: f32, cos_to_normal: f32) -> f32 {
    if cos_to_normal.is_nan() {
        return d_f;
    }
    d_f * DIFFUSIVITY * cos_to_normal.abs().min(1.0)
}
