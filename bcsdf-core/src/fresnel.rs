//! Fresnel terms of the double cylinder (docs/model.md §4).

use crate::math::{sqrt_pos, Math};

/// Single-interface dielectric reflectances `(r_s, r_p)` for incidence cosine `cos_i`
/// from a medium into one whose relative index is `eta` (= n_t / n_i).
/// Total internal reflection gives `(1, 1)`.
#[inline]
#[must_use]
pub fn dielectric_sp<M: Math>(cos_i: f32, eta: f32) -> (f32, f32) {
    // An index-matched boundary reflects nothing (exactly, not up to rounding).
    if eta == 1.0 {
        return (0.0, 0.0);
    }
    let cos_i = cos_i.clamp(0.0, 1.0);
    let sin2_t = (1.0 - cos_i * cos_i) / (eta * eta);
    if sin2_t >= 1.0 {
        return (1.0, 1.0);
    }
    let cos_t = sqrt_pos::<M>(1.0 - sin2_t);
    let rs = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    let rp = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    (rs * rs, rp * rp)
}

/// Unpolarised dielectric reflectance (r_s + r_p)/2; 1 under total internal reflection.
#[inline]
#[must_use]
pub fn dielectric<M: Math>(cos_i: f32, eta: f32) -> f32 {
    let (rs, rp) = dielectric_sp::<M>(cos_i, eta);
    0.5 * (rs + rp)
}

/// The cos a below which the layered cuticle's `f` ([`cuticle`]) turns from its value inside
/// the fiber's cross-section toward 1 at grazing incidence: where 1 − R1 = l·R1 (the two
/// terms of `f`'s denominator are equal, f = ½ when R1 ≈ 1).
///
/// Near grazing, with cos t = √(1 − 1/η'²), the single interface gives 1 − r_s ≈ 4cos a/(η'cos t)
/// and 1 − r_p ≈ 4η'cos a/cos t, one plate 1 − 2r/(1 + r) ≈ (1 − r)/2, so
/// 1 − R1 ≈ cos a·(η' + 1/η')/cos t, and the knee is at cos a ≈ l·cos t/(η' + 1/η'). For few
/// layers (l ≪ 1) it is very close to a = π/2 and the far field's quadrature refines toward it
/// (docs/model.md §5). Returns 0 for η' ≤ 1 (no knee: nothing to refine).
#[inline]
#[must_use]
pub fn cuticle_grazing_knee<M: Math>(eta_c_prime: f32, l: f32) -> f32 {
    if eta_c_prime <= 1.0 || l <= 0.0 {
        return 0.0;
    }
    let cos_t = sqrt_pos::<M>(1.0 - 1.0 / (eta_c_prime * eta_c_prime));
    (l * cos_t / (eta_c_prime + 1.0 / eta_c_prime)).min(1.0)
}

/// Cuticle reflectance `f` with `l` layers (Stokes pile of plates, docs/model.md §4).
///
/// Per polarisation the single-interface reflectance `r` (2D angle `a`, index `η'_c`) becomes
/// one plate's reflectance `2r/(1+r)`; their average `R1` gives `f = l·R1 / (1 + (l−1)·R1)`.
/// `l = 0.5` is the plain interface, `l → 0` removes the cuticle reflection, `l → ∞` gives 1.
#[inline]
#[must_use]
pub fn cuticle<M: Math>(cos_a: f32, eta_c_prime: f32, l: f32) -> f32 {
    let (rs, rp) = dielectric_sp::<M>(cos_a, eta_c_prime);
    let plate = |r: f32| 2.0 * r / (1.0 + r);
    let r1 = 0.5 * (plate(rs) + plate(rp));
    let denom = 1.0 + (l - 1.0) * r1;
    if denom <= 0.0 {
        // Only reachable for r1 = 1 and l < 1 rounding: a perfect mirror stays one.
        return 1.0;
    }
    (l * r1 / denom).clamp(0.0, 1.0)
}

/// Medulla-boundary reflectance `f_m` at incidence `m` (cosine `cos_m`) from the cortex side,
/// relative index `η'_m / η'_c`; 1 under total internal reflection.
#[inline]
#[must_use]
pub fn medulla<M: Math>(cos_m: f32, eta_rel: f32) -> f32 {
    dielectric::<M>(cos_m, eta_rel)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::Libm;

    #[test]
    fn cuticle_is_half_way_to_one_at_its_grazing_knee() {
        // The knee is where f's two denominator terms are equal, so f ≈ ½ there, and f is
        // small a decade inside it (well away from grazing) and near 1 a decade outside.
        for eta in [1.2f32, 1.55, 2.3] {
            for l in [1e-3f32, 5e-3, 2e-2] {
                let knee = cuticle_grazing_knee::<Libm>(eta, l);
                let f = |cos_a: f32| cuticle::<Libm>(cos_a, eta, l);
                assert!(
                    (f(knee) - 0.5).abs() < 0.05,
                    "η' {eta} l {l}: f(knee) = {}",
                    f(knee)
                );
                assert!(f(10.0 * knee) < 0.15, "η' {eta} l {l}: {}", f(10.0 * knee));
                assert!(f(0.1 * knee) > 0.85, "η' {eta} l {l}: {}", f(0.1 * knee));
            }
        }
        assert_eq!(cuticle_grazing_knee::<Libm>(1.0, 0.5), 0.0);
        assert_eq!(cuticle_grazing_knee::<Libm>(1.5, 0.0), 0.0);
    }

    fn close(a: f32, b: f32, tol: f32) -> bool {
        (a - b).abs() <= tol
    }

    #[test]
    fn normal_incidence_is_the_textbook_formula() {
        for eta in [1.2f32, 1.55, 2.0, 1.0 / 1.55] {
            let want = ((eta - 1.0) / (eta + 1.0)) * ((eta - 1.0) / (eta + 1.0));
            let (rs, rp) = dielectric_sp::<Libm>(1.0, eta);
            assert!(close(rs, want, 1e-7) && close(rp, want, 1e-7), "η {eta}");
            assert!(close(dielectric::<Libm>(1.0, eta), want, 1e-7));
        }
    }

    #[test]
    fn grazing_and_total_internal_reflection_reflect_everything() {
        assert_eq!(dielectric::<Libm>(0.0, 1.55), 1.0);
        // From the dense side (η < 1) beyond the critical angle sin θ_c = η.
        let eta = 1.0 / 1.55;
        let cos_c = libm::sqrtf(1.0 - eta * eta);
        for cos_i in [0.0, 0.3, 0.9 * cos_c] {
            assert_eq!(dielectric_sp::<Libm>(cos_i, eta), (1.0, 1.0), "cos {cos_i}");
            assert_eq!(medulla::<Libm>(cos_i, eta), 1.0);
        }
        // Inside the critical angle: below 1, rising toward it as θ_i nears θ_c.
        let r =
            [1.0, 1.1 * cos_c, 1.01 * cos_c, 1.0001 * cos_c].map(|c| dielectric::<Libm>(c, eta));
        assert!(r.windows(2).all(|w| w[0] < w[1]) && r[3] < 1.0, "{r:?}");
        assert!(r[3] > 0.9, "{r:?}");
        // An index-matched boundary reflects nothing at any angle.
        for cos_i in [0.0, 0.5, 1.0] {
            assert_eq!(dielectric_sp::<Libm>(cos_i, 1.0), (0.0, 0.0));
        }
    }

    #[test]
    fn brewster_angle_and_reciprocity() {
        let eta = 1.55f32;
        // r_p vanishes at tan θ_B = η.
        let cos_b = 1.0 / libm::sqrtf(1.0 + eta * eta);
        let (rs, rp) = dielectric_sp::<Libm>(cos_b, eta);
        assert!(rp < 1e-10 && rs > 0.1, "{rs} {rp}");
        // Stokes: the same reflectance from either side of the interface.
        for k in 1..20 {
            let cos_i = k as f32 / 20.0;
            let sin_t = libm::sqrtf(1.0 - cos_i * cos_i) / eta;
            let cos_t = libm::sqrtf(1.0 - sin_t * sin_t);
            let outside = dielectric::<Libm>(cos_i, eta);
            let inside = dielectric::<Libm>(cos_t, 1.0 / eta);
            assert!(
                close(outside, inside, 1e-5),
                "cos {cos_i}: {outside} vs {inside}"
            );
        }
        // Clamped cosines: beyond 1 is normal incidence, below 0 grazing.
        assert_eq!(dielectric::<Libm>(1.5, eta), dielectric::<Libm>(1.0, eta));
        assert_eq!(dielectric::<Libm>(-0.5, eta), 1.0);
    }

    #[test]
    fn cuticle_layers_interpolate_between_no_reflection_and_a_mirror() {
        let eta = 1.55;
        // Half a layer is the plain interface (at normal incidence r_s = r_p).
        assert!(close(
            cuticle::<Libm>(1.0, eta, 0.5),
            dielectric::<Libm>(1.0, eta),
            1e-7
        ));
        for cos_a in [0.1f32, 0.5, 0.9, 1.0] {
            assert_eq!(cuticle::<Libm>(cos_a, eta, 0.0), 0.0);
            let mut prev = 0.0;
            for l in [0.25, 0.5, 1.0, 2.0, 8.0, 64.0] {
                let f = cuticle::<Libm>(cos_a, eta, l);
                assert!(f > prev && f <= 1.0, "cos {cos_a}, l {l}: {f}");
                prev = f;
            }
            assert!(cuticle::<Libm>(cos_a, eta, 1e6) > 0.999);
        }
        // Under total internal reflection every plate is a mirror.
        assert_eq!(cuticle::<Libm>(0.2, 0.7, 0.3), 1.0);
    }
}
