//! Fresnel terms of the double cylinder (MODEL.md §4).

use crate::math::{sqrt_pos, Math};

/// Single-interface dielectric reflectances `(r_s, r_p)` for incidence cosine `cos_i`
/// from a medium into one whose relative index is `eta` (= n_t / n_i).
/// Total internal reflection gives `(1, 1)`.
#[inline]
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
pub fn dielectric<M: Math>(cos_i: f32, eta: f32) -> f32 {
    let (rs, rp) = dielectric_sp::<M>(cos_i, eta);
    0.5 * (rs + rp)
}

/// Cuticle reflectance `f` with `l` layers (Stokes pile of plates, MODEL.md §4).
///
/// Per polarisation the single-interface reflectance `r` (2D angle `a`, index `η'_c`) becomes
/// one plate's reflectance `2r/(1+r)`; their average `R1` gives `f = l·R1 / (1 + (l−1)·R1)`.
/// `l = 0.5` is the plain interface, `l → 0` removes the cuticle reflection, `l → ∞` gives 1.
#[inline]
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
pub fn medulla<M: Math>(cos_m: f32, eta_rel: f32) -> f32 {
    dielectric::<M>(cos_m, eta_rel)
}
