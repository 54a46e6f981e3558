//! The one-dimensional building blocks of importance sampling (docs/model.md §10): uniform
//! clamping, discrete choice, piecewise-linear masses and their inversion, truncated Gaussian
//! sampling. Used by the medulla profiles' ψ sampler, the LUT's sampling section, the baked
//! evaluator's sphere norms and both samplers (`crate::sampling`, which re-exports them).
//!
//! Guards are written `!(x > 0.0)` on purpose: they are true for NaN too.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use crate::gaussian::erf_mass;
pub use crate::gaussian::gaussian_mass;

/// Clamps a uniform number into [0, 1) (NaN becomes 0).
#[inline]
#[must_use]
pub fn unit(u: f32) -> f32 {
    if u > 0.0 {
        u.min(ONE_MINUS_EPSILON)
    } else {
        0.0
    }
}

/// The largest f32 below 1.
pub const ONE_MINUS_EPSILON: f32 = 1.0 - f32::EPSILON / 2.0;

/// Picks index k with probability `weights[k] / Σ weights` and returns it with `u` rescaled
/// to [0, 1) within the chosen interval, so that the same number can drive a further
/// choice. `None` when no weight is positive. Non-positive or non-finite weights are never
/// chosen.
#[inline]
#[must_use]
pub fn choose(weights: &[f32], u: f32) -> Option<(usize, f32)> {
    let ok = |w: f32| w.is_finite() && w > 0.0;
    let total: f32 = weights.iter().filter(|w| ok(**w)).sum();
    if !(total > 0.0 && total.is_finite()) {
        return None;
    }
    let target = unit(u) * total;
    let mut acc = 0.0;
    let mut last = None;
    for (k, &w) in weights.iter().enumerate() {
        if !ok(w) {
            continue;
        }
        last = Some(k);
        if target < acc + w {
            return Some((k, unit((target - acc) / w)));
        }
        acc += w;
    }
    // Rounding put the target past the last positive weight: take that one.
    last.map(|k| (k, ONE_MINUS_EPSILON))
}

/// Mass of a linear density going from `v0` to `v1` over a length `len`: len·(v0 + v1)/2.
#[inline]
#[must_use]
pub fn linear_mass(v0: f32, v1: f32, len: f32) -> f32 {
    0.5 * len * (v0 + v1)
}

/// Inverts the mass of a linear density over one segment: the offset s ∈ [0, len] at which
/// ∫₀ˢ v = `t`, for v going linearly from `v0` ≥ 0 to `v1` ≥ 0 over `len`. Solves
/// v0·s + (v1 − v0)s²/(2 len) = t in the cancellation-free form s = 2t/(v0 + √(v0² + 2(v1 −
/// v0)t/len)).
///
/// An end where the density is 0 is never returned (s is kept 2⁻²⁰·len inside it): the ends
/// of u's range would otherwise land exactly on a point of zero density, whose sample has no
/// pdf. The mass moved is below 2⁻⁴⁰ of the segment's.
#[inline]
#[must_use]
pub fn invert_linear(v0: f32, v1: f32, len: f32, t: f32) -> f32 {
    if !(len > 0.0) {
        return 0.0;
    }
    let s = if t > 0.0 {
        let disc = (v0 * v0 + 2.0 * (v1 - v0) * t / len).max(0.0);
        let den = v0 + libm::sqrtf(disc);
        if den > 0.0 {
            (2.0 * t / den).clamp(0.0, len)
        } else {
            len
        }
    } else {
        0.0
    };
    let inset = len * (1.0 / 1_048_576.0);
    if v0 <= 0.0 && s < inset {
        inset
    } else if v1 <= 0.0 && s > len - inset {
        len - inset
    } else {
        s
    }
}

/// Mass of a linear density going from `v0` to `v1` over a length `len`, weighted by a
/// factor going linearly from `a` to `b` over the same length (the |φ|/π or 1 − |φ|/π of the
/// scattered family's back/front blend, docs/model.md §10). With τ ∈ [0, 1] along the
/// segment the product is the quadratic a·v0·(1 − τ)² + (a·v1 + b·v0)·τ(1 − τ) + b·v1·τ²,
/// whose Bernstein terms each integrate to 1/3: len·(a·v0 + (a·v1 + b·v0)/2 + b·v1)/3.
#[inline]
#[must_use]
pub fn weighted_linear_mass(v0: f32, v1: f32, a: f32, b: f32, len: f32) -> f32 {
    len * (a * v0 + 0.5 * (a * v1 + b * v0) + b * v1) * (1.0 / 3.0)
}

/// Inverts [`weighted_linear_mass`] over one segment: the offset s ∈ [0, len] at which the
/// integral of the weighted density from the segment start is `t`. The integral is the cubic
/// F(τ) = len·(Aτ + Bτ²/2 + Cτ³/3), τ = s/len, with A = a·v0, B = a·(v1 − v0) + v0·(b − a),
/// C = (b − a)·(v1 − v0), increasing (its derivative, the density, is ≥ 0); it is solved by
/// Newton steps kept inside a shrinking bracket, from the linear density's inversion, at
/// most eight, until a step moves τ by at most 1.2e-7 (F is a cubic: the steps converge
/// quadratically, and the bracket halves on any step that would leave it). As [`invert_linear`], an end where the density
/// is 0 is never returned (s is kept 2⁻²⁰·len inside it).
#[inline]
#[must_use]
pub fn invert_weighted_linear(v0: f32, v1: f32, a: f32, b: f32, len: f32, t: f32) -> f32 {
    if !(len > 0.0) {
        return 0.0;
    }
    let (ca, cb, cc) = (a * v0, a * (v1 - v0) + v0 * (b - a), (b - a) * (v1 - v0));
    let (q0, q1) = (ca, b * v1);
    let target = t / len;
    let f = |x: f32| x * (ca + x * (0.5 * cb + x * (1.0 / 3.0) * cc)) - target;
    let total = ca + 0.5 * cb + (1.0 / 3.0) * cc;
    // Start: the density taken linear from q0 to q1, its mass rescaled to the segment's.
    let linear_mass = 0.5 * (q0 + q1);
    let mut x = if total > 0.0 && linear_mass > 0.0 {
        invert_linear(q0, q1, 1.0, target * (linear_mass / total))
    } else {
        0.5
    };
    let (mut lo, mut hi) = (0.0f32, 1.0f32);
    for _ in 0..8 {
        let fx = f(x);
        if fx > 0.0 {
            hi = x;
        } else {
            lo = x;
        }
        let d = ca + x * (cb + x * cc);
        let mut next = if d > 0.0 { x - fx / d } else { f32::NAN };
        if !(next >= lo && next <= hi) {
            next = 0.5 * (lo + hi);
        }
        // Converged: the step is below f32's resolution of τ near 1 (2⁻²³ ≈ 1.2e-7).
        let done = (next - x).abs() <= 1.2e-7;
        x = next;
        if done {
            break;
        }
    }
    let s = (x * len).clamp(0.0, len);
    let inset = len * (1.0 / 1_048_576.0);
    if q0 <= 0.0 && s < inset {
        inset
    } else if q1 <= 0.0 && s > len - inset {
        len - inset
    } else {
        s
    }
}

/// Draws x from the normalised Gaussian G(x; β) restricted to [lo, hi], by inverting its
/// CDF: Newton steps on erf inside a shrinking bracket, in f64 (f32's erf has no precision
/// left in the tails). The density of the result is G(x; β)/[`gaussian_mass`]`(β, lo, hi)`.
/// Returns `None` when the interval is empty.
#[must_use]
pub fn sample_gaussian(beta: f32, lo: f32, hi: f32, u: f32) -> Option<f32> {
    if !(hi > lo) || !(beta > 0.0) {
        return None;
    }
    let k = 1.0 / (core::f64::consts::SQRT_2 * f64::from(beta));
    let (a, b) = (f64::from(lo) * k, f64::from(hi) * k);
    let total = erf_mass(a, b);
    if !(total > 0.0) {
        return None;
    }
    let target = f64::from(unit(u)) * total;
    // Solve erf_mass(a, z) = target for z ∈ [a, b]; d/dz erf_mass(a, z) = 2/√π·e^{−z²}.
    let (mut lo_z, mut hi_z) = (a, b);
    let mut z = a + f64::from(unit(u)) * (b - a);
    for _ in 0..60 {
        let f = erf_mass(a, z) - target;
        if f > 0.0 {
            hi_z = z;
        } else {
            lo_z = z;
        }
        let d = core::f64::consts::FRAC_2_SQRT_PI * libm::exp(-z * z);
        let mut next = if d > 0.0 { z - f / d } else { f64::NAN };
        if !(next > lo_z && next < hi_z) {
            next = 0.5 * (lo_z + hi_z);
        }
        if (next - z).abs() <= 1e-12 * (1.0 + z.abs()) || hi_z - lo_z <= 1e-13 {
            z = next;
            break;
        }
        z = next;
    }
    Some(((z / k) as f32).clamp(lo, hi))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn choose_follows_the_weights_and_rescales() {
        let w = [1.0, 0.0, 3.0];
        assert_eq!(choose(&w, 0.0).map(|c| c.0), Some(0));
        assert_eq!(choose(&w, 0.24).map(|c| c.0), Some(0));
        assert_eq!(choose(&w, 0.26).map(|c| c.0), Some(2));
        let (k, r) = choose(&w, 0.625).unwrap();
        assert_eq!(k, 2);
        assert!((r - 0.5).abs() < 1e-6);
        assert_eq!(choose(&[0.0, -1.0, f32::NAN], 0.5), None);
        assert_eq!(choose(&w, 1.0).map(|c| c.0), Some(2));
    }

    #[test]
    fn linear_inversion_round_trips() {
        for (v0, v1) in [(1.0, 1.0), (0.0, 2.0), (2.0, 0.0), (0.3, 5.0), (5.0, 0.3)] {
            let len = 0.7;
            for k in 0..=10 {
                let s = len * k as f32 / 10.0;
                let t = s * v0 + (v1 - v0) * s * s / (2.0 * len);
                let back = invert_linear(v0, v1, len, t);
                assert!((back - s).abs() < 2e-5, "{v0} {v1} {s} {back}");
            }
        }
    }

    #[test]
    fn weighted_linear_inversion_round_trips() {
        // (v0, v1, a, b): densities and weights rising, falling, zero at an end.
        let cases: [(f32, f32, f32, f32); 5] = [
            (1.0, 1.0, 0.0, 0.1),
            (0.0, 2.0, 0.5, 0.6),
            (2.0, 0.0, 0.9, 1.0),
            (0.3, 5.0, 1.0, 0.9),
            (5.0, 0.3, 0.2, 0.0),
        ];
        for (v0, v1, a, b) in cases {
            let len = 0.05;
            // The mass against a fine midpoint sum of the product.
            let n = 4000;
            let mid: f64 = (0..n)
                .map(|k| {
                    let x = (k as f64 + 0.5) / n as f64;
                    let (a, b, v0, v1) = (f64::from(a), f64::from(b), f64::from(v0), f64::from(v1));
                    (a + (b - a) * x) * (v0 + (v1 - v0) * x) * f64::from(len) / n as f64
                })
                .sum();
            let mass = weighted_linear_mass(v0, v1, a, b, len);
            assert!(
                (f64::from(mass) - mid).abs() < 1e-6 * mid.max(1e-3),
                "{mass} {mid}"
            );
            // The integral from the segment start to s, in f64.
            let to = |s: f64| {
                let x = s / f64::from(len);
                let (a, b, v0, v1) = (f64::from(a), f64::from(b), f64::from(v0), f64::from(v1));
                let (ca, cb, cc) = (a * v0, a * (v1 - v0) + v0 * (b - a), (b - a) * (v1 - v0));
                f64::from(len) * x * (ca + x * (0.5 * cb + x * cc / 3.0))
            };
            for k in 0..=20 {
                let t = mass * k as f32 / 20.0;
                let back = invert_weighted_linear(v0, v1, a, b, len, t);
                assert!((0.0..=len).contains(&back));
                // The mass reached, to f32 rounding of the target (a position error can be
                // larger where the density vanishes at an end: the mass grows quadratically).
                let got = to(f64::from(back));
                assert!(
                    (got - f64::from(t)).abs() < 1e-6 * f64::from(mass),
                    "{v0} {v1} {a} {b} {t} {back} {got}"
                );
            }
        }
    }

    #[test]
    fn gaussian_sampling_inverts_its_cdf() {
        for (beta, lo, hi) in [(0.1, -0.62, 0.62), (0.05, 0.1, 0.3), (0.2, -1.5, -0.2)] {
            let mass = gaussian_mass(beta, lo, hi);
            for k in 0..=16 {
                let u = k as f32 / 16.0;
                let x = sample_gaussian(beta, lo, hi, u).unwrap();
                assert!((lo..=hi).contains(&x));
                let cdf = gaussian_mass(beta, lo, x) / mass;
                assert!(
                    (cdf - u.min(ONE_MINUS_EPSILON)).abs() < 1e-5,
                    "{beta} {u} {x} {cdf}"
                );
            }
        }
        assert_eq!(sample_gaussian(0.1, 0.3, 0.3, 0.5), None);
    }
}
