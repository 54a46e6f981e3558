//! The pole slivers in the samplers' θ_i densities (docs/model.md §10).
//!
//! S divides by max(cos²θ_i, 10⁻⁴) ([`crate::model::inv_cos2_theta_i`]), so the integrand
//! of the furnace, S·cos²θ_i, is the sum of products M·N times
//!
//! g(θ_i) = min(1, cos²θ_i / 10⁻⁴),
//!
//! which is 1 except in the pole slivers, |θ_i| within s_c = [`POLE_SLIVER`] of ±90°. There,
//! with s = π/2 − |θ_i| the distance to the pole, cos²θ_i = sin²s. A sampler whose θ_i
//! density is to carry g exactly integrates a piecewise-linear row times g over each
//! sliver and inverts that integral; this module does both on one linear piece:
//!
//! - g inside a sliver is taken as the polynomial k(s) = (s² − s⁴/3)/10⁻⁴ ([`sliver_keep`]):
//!   sin²s = s² − s⁴/3 + 2s⁶/45 − …, so k's relative error is below 2s⁴/45 ≤ 4.5e-10 at
//!   s ≤ s_c, far below f32's resolution;
//! - a linear density times k is a polynomial of degree 5 in the position, which three-point
//!   Gauss–Legendre integrates exactly ([`sliver_piece_mass`]): the closed form, evaluated
//!   without the cancellation that expanding it in powers of s would bring on short pieces;
//! - the inversion ([`invert_sliver_piece`]) solves ∫ = t by Newton steps inside a shrinking
//!   bracket, as [`super::invert_weighted_linear`] does for the back/front blend.
//!
//! The evaluated densities (`pdf`) use g from cos θ_i itself ([`pole_keep`]), the same
//! number S's guard divides by, so that the weight S·cos θ_i/pdf of a grey fiber is the
//! mixture's total mass exactly; the draws use k. The two differ by k's error above (and by
//! the rounding of cos θ_i in f32 within a few 10⁻⁷ rad of the pole).
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use crate::bcsdf::MIN_COS_THETA_PDF;
use crate::model::{MIN_COS2_THETA_I, POLE_SLIVER};

/// g(θ_i) = min(1, cos²θ_i/10⁻⁴) from cos θ_i (docs/model.md §10): the factor S's pole
/// guard leaves on S·cos²θ_i. cos θ_i is kept at or above [`MIN_COS_THETA_PDF`], the floor
/// the pdf divides by, so that g > 0 wherever S > 0 (at most 10⁻⁸, within 10⁻⁶ rad of a
/// pole). Exactly 1 outside the slivers.
#[inline(always)]
#[must_use]
pub fn pole_keep(cos_theta_i: f32) -> f32 {
    let c = cos_theta_i.max(MIN_COS_THETA_PDF);
    (c * c * (1.0 / MIN_COS2_THETA_I)).min(1.0)
}

/// k(s) = (s² − s⁴/3)/10⁻⁴ (docs/model.md §10): g at distance s ∈ [0, s_c] from a pole, sin²s by its Taylor
/// polynomial to s⁴ (relative error below 4.5e-10, module documentation); 1 beyond s_c.
#[inline(always)]
#[must_use]
pub fn sliver_keep(s: f32) -> f32 {
    let s = s.abs();
    if !(s < POLE_SLIVER) {
        return 1.0;
    }
    let s2 = s * s;
    (s2 * (1.0 - s2 * (1.0 / 3.0)) * (1.0 / MIN_COS2_THETA_I)).min(1.0)
}

/// Three-point Gauss–Legendre on [0, 1]: abscissae and weights (summing to 1); exact for
/// polynomials of degree 5 (a linear density times k). The one rule of the pole slivers:
/// [`sliver_piece_mass`] and the baked sampler's node weights (`baked::slivers`) use it.
pub(crate) const GAUSS3: [(f32, f32); 3] = [
    (0.112_701_66, 5.0 / 18.0),
    (0.5, 8.0 / 18.0),
    (0.887_298_3, 5.0 / 18.0),
];

/// (docs/model.md §10) ∫ v(x)·k(|x − pole|) dx over [x0, x0 + len], v going linearly from `v0` at x0 to `v1` at
/// x0 + `len0` (the piece's own length, ≥ len): the mass of the first `len` of a linear
/// piece inside a sliver, exactly (k·v has degree 5: three-point Gauss–Legendre).
#[inline]
#[must_use]
pub fn sliver_piece_mass(v0: f32, v1: f32, len0: f32, x0: f32, pole: f32, len: f32) -> f32 {
    // A zero piece (a lobe's tail rounded to 0 near the pole) has no mass: no work.
    if !(len > 0.0 && len0 > 0.0) || (v0 == 0.0 && v1 == 0.0) {
        return 0.0;
    }
    // v's rise over [x0, x0 + len]; no division for a whole piece (the per-view case).
    let rise = if len == len0 {
        v1 - v0
    } else {
        (v1 - v0) * (len / len0)
    };
    let s0 = x0 - pole;
    let mut acc = 0.0;
    for (t, w) in GAUSS3 {
        acc += w * (v0 + rise * t) * sliver_keep(s0 + t * len);
    }
    acc * len
}

/// The offset d ∈ [0, len] at which [`sliver_piece_mass`]`(v0, v1, len, x0, pole, d)` = `t`,
/// for v ≥ 0 on the piece (docs/model.md §10): Newton steps inside a shrinking bracket from the offset that a
/// uniform density would give, at most sixteen, until a step moves d by at most 1.2e-7 of
/// len (the mass is increasing; its derivative v·k vanishes only at the pole, where the
/// bracket's bisection takes over).
#[must_use]
pub fn invert_sliver_piece(v0: f32, v1: f32, len: f32, x0: f32, pole: f32, t: f32) -> f32 {
    let total = sliver_piece_mass(v0, v1, len, x0, pole, len);
    if !(total > 0.0) || !(t > 0.0) {
        return 0.0;
    }
    if !(t < total) {
        return len;
    }
    let slope = (v1 - v0) / len;
    let (mut lo, mut hi) = (0.0f32, len);
    let mut d = len * (t / total);
    for _ in 0..16 {
        let f = sliver_piece_mass(v0, v1, len, x0, pole, d) - t;
        if f > 0.0 {
            hi = d;
        } else {
            lo = d;
        }
        let dens = (v0 + slope * d) * sliver_keep((x0 - pole) + d);
        let mut next = if dens > 0.0 { d - f / dens } else { f32::NAN };
        if !(next >= lo && next <= hi) {
            next = 0.5 * (lo + hi);
        }
        let done = (next - d).abs() <= 1.2e-7 * len;
        d = next;
        if done {
            break;
        }
    }
    d.clamp(0.0, len)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// ∫ v·sin²(s)/10⁻⁴ over [x0, x0 + d] by a fine midpoint sum in f64, with sin itself.
    fn reference(v0: f64, v1: f64, len: f64, x0: f64, pole: f64, d: f64) -> f64 {
        let n = 20_000;
        let h = d / n as f64;
        (0..n)
            .map(|k| {
                let x = x0 + (k as f64 + 0.5) * h;
                let s = (x - pole).abs();
                let keep = (s.sin().powi(2) / f64::from(MIN_COS2_THETA_I)).min(1.0);
                (v0 + (v1 - v0) * (x - x0) / len) * keep * h
            })
            .sum()
    }

    #[test]
    fn the_keep_factor_is_the_guard_of_s() {
        // k against sin²s/10⁻⁴, and pole_keep against cos² of the same angle.
        for k in 0..=100 {
            let s = POLE_SLIVER * k as f32 / 100.0;
            let want = (f64::from(s).sin().powi(2) / 1e-4).min(1.0);
            assert!((f64::from(sliver_keep(s)) - want).abs() < 2e-6, "{s}");
            let c = libm::cosf(core::f32::consts::FRAC_PI_2 - s);
            assert!(
                (f64::from(pole_keep(c)) - want).abs() < 2e-3 * want + 1e-6,
                "{s}"
            );
        }
        assert_eq!(sliver_keep(POLE_SLIVER), 1.0);
        assert_eq!(sliver_keep(0.3), 1.0);
        assert_eq!(pole_keep(0.5), 1.0);
        assert_eq!(pole_keep(0.0), 1e-8);
        assert_eq!(pole_keep(f32::NAN), 1e-8);
    }

    #[test]
    fn sliver_pieces_integrate_and_invert() {
        // Pieces at the lower pole (x rising away from it) and at the upper one (towards it),
        // densities rising, falling and zero at an end.
        let sc = POLE_SLIVER;
        let cases: [(f32, f32, f32, f32, f32); 5] = [
            (1.0, 1.0, sc, 0.0, 0.0),
            (0.0, 2.0, 0.6 * sc, 0.2 * sc, 0.0),
            (2.0, 0.5, 0.7 * sc, -0.7 * sc, 0.0),
            (0.3, 5.0, 0.004, 1.565, 1.570_796_4),
            (5.0, 0.0, 0.003, 1.567_796_4, 1.570_796_4),
        ];
        for (v0, v1, len, x0, pole) in cases {
            let (f, x, p) = (f64::from(len), f64::from(x0), f64::from(pole));
            let mass = sliver_piece_mass(v0, v1, len, x0, pole, len);
            let want = reference(f64::from(v0), f64::from(v1), f, x, p, f);
            assert!(
                (f64::from(mass) - want).abs() < 2e-6 * want.max(1e-9),
                "{v0} {v1} {len} {x0}: {mass} vs {want}"
            );
            for k in 0..=20 {
                let t = mass * k as f32 / 20.0;
                let d = invert_sliver_piece(v0, v1, len, x0, pole, t);
                assert!((0.0..=len).contains(&d));
                let got = reference(f64::from(v0), f64::from(v1), f, x, p, f64::from(d));
                assert!(
                    (got - f64::from(t)).abs() < 2e-6 * f64::from(mass),
                    "{v0} {v1} {len} {x0} t {t}: at {d} {got}"
                );
            }
        }
        assert_eq!(invert_sliver_piece(0.0, 0.0, 0.01, 0.0, 0.0, 0.5), 0.0);
        assert_eq!(sliver_piece_mass(1.0, 1.0, 0.0, 0.0, 0.0, 0.0), 0.0);
    }
}
