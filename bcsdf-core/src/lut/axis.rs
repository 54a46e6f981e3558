//! The absorption axis of table `N` (docs/lut.md "The absorption axis"): where σ_ca sits
//! on it and its nodes.

use super::SIGMA_CA_MAX;

/// The absorption axis's scale for a fiber without a medulla, s₀ at κ = 0 (per fiber
/// radius; chosen by measurement, docs/lut.md "The absorption axis").
pub const ABSORPTION_SCALE_HAIR: f32 = 1.25;

/// The scale of the absorption axis's square-root term, s_q (per fiber radius; docs/lut.md
/// "The absorption axis").
pub const ABSORPTION_SCALE_ROOT: f32 = 0.25;

/// The scale s₀ of the absorption axis of a LUT whose fibers have medulla ratio `kappa`:
/// [`ABSORPTION_SCALE_HAIR`]/(1 − κ), κ clamped to [0, 0.95]. The light a fiber's absorbing
/// families carry falls off with σ_ca over the cortex path it crosses, about 2(1 − κ) radii
/// for light that reaches the medulla, so the axis stretches with 1/(1 − κ) (docs/lut.md
/// "The absorption axis"). Stored in the header (byte 156) and checked against this rule.
#[must_use]
pub fn absorption_scale(kappa: f32) -> f32 {
    #[allow(clippy::manual_clamp)]
    let k = kappa.max(0.0).min(0.95);
    ABSORPTION_SCALE_HAIR / (1.0 - k)
}

/// The share of the absorption axis's nodes given to its square-root term.
pub const ROOT_SHARE: f32 = 0.4;

/// log₂(e)²/s_q: e^(−√(σ/s_q)) = 2^(−√(σ·ROOT_RATE)) ([`ABSORPTION_SCALE_ROOT`]); the
/// shader's `FUR_ROOT_RATE`.
pub const ROOT_RATE: f32 =
    core::f32::consts::LOG2_E * core::f32::consts::LOG2_E / ABSORPTION_SCALE_ROOT;

/// The position of σ_ca on an absorption axis of scale s₀ = `scale` ([`absorption_scale`]),
/// in [0, 1]: x = 1 − r·e^(−√(σ/s_q)) − (1 − r)·e^(−σ/s₀), r = [`ROOT_SHARE`] (0.4),
/// s_q = [`ABSORPTION_SCALE_ROOT`] (docs/lut.md "The absorption axis"): the square-root term
/// follows the diffusive fall-off near σ = 0 of light that scatters in a medulla, the
/// exponential term the fall-off over the cortex path, which stretches with 1/(1 − κ).
/// Node k of n lies at x = k/(n − 1)
/// ([`absorption_node`]); the last node, x = 1, is σ = [`SIGMA_CA_MAX`] (the fully
/// absorbing limit: every σ above about 110 s₀ maps to 1 in f32). NaN and negative σ give 0
/// (the callers pass validated [`crate::Absorption`]s). The exponentials are powers of two,
/// e^(−√(σ/s_q)) = 2^(−√(σ·[`ROOT_RATE`])) and e^(−σ/s₀) = 2^(−(σ/s₀)·log₂e), by
/// [`crate::math::pow2_neg`] (a short dependency chain: the coordinate lies on the path from
/// a query's colour to its texel reads). Branch-free, so a lane loop over channels or queries
/// vectorises (`baked::texels::locate_colour`, the batch).
#[inline(always)]
#[must_use]
pub fn absorption_coordinate(sigma: f32, scale: f32) -> f32 {
    // `max` first maps NaN to 0 (`clamp` would keep it).
    #[allow(clippy::manual_clamp)]
    let s = sigma.max(0.0).min(SIGMA_CA_MAX);
    let e = ROOT_SHARE * crate::math::pow2_neg(crate::math::sqrt(s * ROOT_RATE))
        + (1.0 - ROOT_SHARE) * crate::math::pow2_neg(s / scale * core::f32::consts::LOG2_E);
    (1.0 - e).min(1.0)
}

/// σ_ca of node `k` of an absorption axis of `nodes` nodes and scale `scale`: the inverse of
/// [`absorption_coordinate`] at x = k/(nodes − 1), found by bisection on that function (f32,
/// to the last bit of σ); node 0 is σ = 0 (lossless) and the last node is exactly [`SIGMA_CA_MAX`].
#[must_use]
pub fn absorption_node(k: usize, nodes: u32, scale: f32) -> f32 {
    let last = nodes.saturating_sub(1).max(1) as usize;
    if k >= last {
        return SIGMA_CA_MAX;
    }
    if k == 0 {
        return 0.0;
    }
    let x = k as f32 / last as f32;
    // Bisection on the coordinate itself (one formula): the largest f32 σ whose coordinate
    // is below x, or the smallest at or above it, whichever lands nearer.
    let (mut lo, mut hi) = (0.0f32, SIGMA_CA_MAX);
    for _ in 0..64 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if absorption_coordinate(mid, scale) < x {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let near = |s: f32| (absorption_coordinate(s, scale) - x).abs();
    if near(lo) < near(hi) {
        lo
    } else {
        hi
    }
}

/// Fewest nodes of the absorption axis: a colour reads three planes
/// (quadratic interpolation, docs/lut.md "The absorption axis").
pub const MIN_ABSORPTION_NODES: u32 = 3;
