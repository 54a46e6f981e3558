//! Longitudinal lobes M_p(θ_i, θ_r) = G(θ_r + θ_i − α_p; β_p) (report eq. 2–3, docs/model.md §5),
//! in the energy closure divided by their mass inside θ_i ∈ [−π/2, π/2] (docs/model.md §12).

use crate::gaussian::{erf_mass, Gaussian, WrappedGaussian, CUTOFF_SIGMAS};
use crate::lobes::LobeGroup;
use crate::math::Math;
use crate::params::{Closure, FurParams};
use core::f64::consts::FRAC_2_SQRT_PI;

/// 1/√π (G(y; β) = e^{−y²/2β²}·k/√π with k = 1/(√2·β)).
const FRAC_1_SQRT_PI: f64 = 0.5 * FRAC_2_SQRT_PI;

/// Smallest cos²θ_i the 1/cos²θ_i factor of eq. 1 divides by (θ_i ≈ ±89.4°): keeps S finite
/// for grazing light (docs/model.md §8; re-exported as `model::MIN_COS2_THETA_I`).
pub const MIN_COS2_THETA_I: f32 = 1e-4;

/// Width of the pole slivers where that guard acts: cos²θ_i < [`MIN_COS2_THETA_I`] within
/// s_c = asin √1e-4 ≈ 0.573° of θ_i = ±90° (the energy closure's normalisation accounts for
/// them, docs/model.md §12; re-exported as `model::POLE_SLIVER`).
pub const POLE_SLIVER: f32 = 0.010_000_167;

/// 1/cos²θ_i of eq. 1 (docs/model.md §8), with cos²θ_i kept at or above
/// [`MIN_COS2_THETA_I`]. The analytic and the baked evaluators both divide by this
/// (re-exported as `model::inv_cos2_theta_i`).
#[inline]
#[must_use]
pub fn inv_cos2_theta_i(cos_theta_i: f32) -> f32 {
    1.0 / (cos_theta_i * cos_theta_i).max(MIN_COS2_THETA_I)
}

/// Smallest mass inside [−π/2, π/2] the energy closure divides by (docs/model.md §12): keeps
/// M_p finite when a lobe lies almost wholly beyond a pole (a large tilt α seen at grazing
/// θ_r); such a lobe then keeps less than its full mass.
pub const MIN_SPHERE_MASS: f32 = 1e-4;

/// Per cuticle group: the longitudinal Gaussian (shift α_p, width β_M) and the azimuthal
/// roughness D_p (width β_N) of docs/model.md §5.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GroupLobes {
    /// α_p for R, TT, TRT: −2α, α, 3α.
    pub shift: [f32; 3],
    /// M_p Gaussians with β_M = β_m, β_m/2, 3β_m/2.
    pub longitudinal: [Gaussian; 3],
    /// D_p wrapped Gaussians with β_N = β_n, √2·β_n, √3·β_n.
    pub azimuthal: [WrappedGaussian; 3],
    /// The energy closure: whether M_p is divided by its mass on the sphere.
    pub closure: Closure,
}

impl GroupLobes {
    /// The three groups' constants for `params`.
    #[must_use]
    pub fn new(params: &FurParams) -> GroupLobes {
        let (alpha, bm, bn) = (params.alpha(), params.beta_m(), params.beta_n());
        GroupLobes {
            shift: [-2.0 * alpha, alpha, 3.0 * alpha],
            longitudinal: [
                Gaussian::new(bm),
                Gaussian::new(0.5 * bm),
                Gaussian::new(1.5 * bm),
            ],
            azimuthal: [
                WrappedGaussian::new(bn),
                WrappedGaussian::new(core::f32::consts::SQRT_2 * bn),
                WrappedGaussian::new(1.732_050_8 * bn),
            ],
            closure: params.closure(),
        }
    }

    /// M_p(θ_i, θ_r) for one group: the Gaussian G(θ_r + θ_i − α_p; β_M)
    /// ([`GroupLobes::gaussian`]) times [`GroupLobes::sphere_norm`].
    #[inline]
    #[must_use]
    pub fn m<M: Math>(&self, group: LobeGroup, theta_i: f32, theta_r: f32) -> f32 {
        self.gaussian::<M>(group, theta_i, theta_r) * self.sphere_norm(group, theta_r)
    }

    /// G(θ_r + θ_i − α_p; β_M) of one group, the report's M_p (docs/model.md §5), normalised
    /// on the whole line.
    #[inline]
    #[must_use]
    pub fn gaussian<M: Math>(&self, group: LobeGroup, theta_i: f32, theta_r: f32) -> f32 {
        let g = group as usize;
        self.longitudinal[g].eval::<M>(theta_r + theta_i - self.shift[g])
    }

    /// The factor M_p / G of docs/model.md §12: 1 in the report closure; in the energy
    /// closure 1/Z_p(θ_r), Z_p(θ_r) = ∫ G(θ_r + θ_i − α_p; β_M) dθ_i over θ_i ∈ [−π/2, π/2]
    /// with the pole guard of S's 1/cos²θ_i ([`sphere_mass`]; at least [`MIN_SPHERE_MASS`]),
    /// so that M_p/cos²θ_i·cos²θ_i, as S weights it, integrates to 1 at every θ_r.
    #[inline]
    #[must_use]
    pub fn sphere_norm(&self, group: LobeGroup, theta_r: f32) -> f32 {
        match self.closure {
            Closure::Report => 1.0,
            Closure::Energy => {
                let g = group as usize;
                let mass = sphere_mass(
                    f64::from(self.longitudinal[g].beta()),
                    f64::from(theta_r) - f64::from(self.shift[g]),
                );
                1.0 / mass.max(MIN_SPHERE_MASS)
            }
        }
    }

    /// D_p for one group.
    #[inline]
    #[must_use]
    pub fn d(&self, group: LobeGroup) -> &WrappedGaussian {
        &self.azimuthal[group as usize]
    }
}

/// Z = ∫ G(c + θ_i; β)·min(1, cos²θ_i / 1e-4) dθ_i over θ_i ∈ [−π/2, π/2]
/// (docs/model.md §12): the mass of the Gaussian inside the sphere, less what the guard of
/// S's 1/cos²θ_i removes in the pole slivers (|θ_i| within s_c = [`POLE_SLIVER`] of ±90°,
/// [`MIN_COS2_THETA_I`]), so that S·cos θ_i integrates M_p to exactly 1. In the slivers cos²θ_i = sin²s is
/// taken as s²·(1e-4/s_c²) (s the distance to the pole; relative error below s_c²/3 =
/// 3.3e-5 of the sliver's part), which leaves Gaussian moments: closed forms in erf and exp, in f64.
fn sphere_mass(beta: f64, c: f64) -> f32 {
    let half_pi = core::f64::consts::FRAC_PI_2;
    let k = 1.0 / (core::f64::consts::SQRT_2 * beta);
    let mass = |a: f64, b: f64| 0.5 * erf_mass(a * k, b * k);
    let sliver = f64::from(POLE_SLIVER);
    // ∫ G(y)·(1 − (y − pole)²/s_c²) dy over [a, b] (the pole at one end): with
    // ∫ y G = β²(G(a) − G(b)) and ∫ y² G = β²·∫G + β²(a G(a) − b G(b)).
    let reach = f64::from(CUTOFF_SIGMAS) * beta + sliver;
    let loss = |a: f64, b: f64, pole: f64| {
        if pole.abs() > reach {
            return 0.0; // G is cut off there: S has nothing to lose
        }
        let gauss = |y: f64| libm::exp(-0.5 * (y / beta) * (y / beta)) * k * FRAC_1_SQRT_PI;
        let (ga, gb) = (gauss(a), gauss(b));
        let i0 = mass(a, b);
        let i1 = beta * beta * (ga - gb);
        let i2 = beta * beta * (i0 + a * ga - b * gb);
        i0 - (i2 - 2.0 * pole * i1 + pole * pole * i0) / (sliver * sliver)
    };
    let (lo, hi) = (c - half_pi, c + half_pi);
    let z = mass(lo, hi) - loss(lo, lo + sliver, lo) - loss(hi - sliver, hi, hi);
    z as f32
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::Libm;
    use crate::presets;

    #[test]
    fn groups_are_shifted_and_scaled_as_the_model_says() {
        let params = FurParams::new(&presets::PRESETS[0].input).unwrap();
        let g = GroupLobes::new(&params);
        let (a, bm, bn) = (params.alpha(), params.beta_m(), params.beta_n());
        assert_eq!(g.shift, [-2.0 * a, a, 3.0 * a]);
        for (k, scale) in [1.0f32, 0.5, 1.5].into_iter().enumerate() {
            assert!((g.longitudinal[k].beta() - scale * bm).abs() < 1e-7);
        }
        for (k, scale) in [1.0f32, 2.0, 3.0].into_iter().enumerate() {
            let want = libm::sqrtf(scale) * bn;
            assert!((g.azimuthal[k].beta() - want).abs() < 1e-6);
            assert_eq!(
                g.d([LobeGroup::R, LobeGroup::TT, LobeGroup::TRT][k]).beta(),
                g.azimuthal[k].beta()
            );
        }
        // The report's M_p peaks where θ_i + θ_r = α_p and depends on the sum only.
        let report = GroupLobes::new(&params.with_closure(Closure::Report));
        for (k, group) in [LobeGroup::R, LobeGroup::TT, LobeGroup::TRT]
            .into_iter()
            .enumerate()
        {
            let peak = report.m::<Libm>(group, 0.4, g.shift[k] - 0.4);
            assert_eq!(peak, report.m::<Libm>(group, -0.1, g.shift[k] + 0.1));
            assert!(peak > report.m::<Libm>(group, 0.41, g.shift[k] - 0.4));
            assert!(peak > report.m::<Libm>(group, 0.39, g.shift[k] - 0.4));
            assert_eq!(peak, g.gaussian::<Libm>(group, 0.4, g.shift[k] - 0.4));
            assert_eq!(report.sphere_norm(group, 0.3), 1.0);
        }
    }

    /// ∫ M_p·min(1, cos²θ_i/1e-4) dθ_i over [−π/2, π/2] (M_p as S·cos θ_i dω weighs it, with
    /// the pole guard of 1/cos²θ_i) by the composite Simpson rule in f64, fine enough for the
    /// narrowest lobe (β_M = β_m/2) and the 0.01 rad pole slivers (40 000 panels).
    fn mass_on_sphere(g: &GroupLobes, group: LobeGroup, theta_r: f32) -> f64 {
        let n = 40_000;
        let h = core::f64::consts::PI / n as f64;
        let f = |k: usize| {
            let ti = -core::f64::consts::FRAC_PI_2 + k as f64 * h;
            let guard = (libm::cos(ti) * libm::cos(ti) / 1e-4).min(1.0);
            f64::from(g.m::<Libm>(group, ti as f32, theta_r)) * guard
        };
        let mut acc = f(0) + f(n);
        for k in 1..n {
            acc += if k % 2 == 1 { 4.0 } else { 2.0 } * f(k);
        }
        acc * h / 3.0
    }

    #[test]
    fn energy_closure_normalises_every_lobe_on_the_sphere() {
        // Every preset, every group, θ_r from pole to pole (docs/model.md §12): the mass
        // inside θ_i ∈ [−π/2, π/2], as S weighs it, is 1 in the energy closure; in the report
        // closure it is the Gaussian's mass there, which falls to about a third at grazing view.
        let mut least_report = f64::MAX;
        for preset in presets::PRESETS.iter() {
            let params = FurParams::new(&preset.input)
                .unwrap()
                .with_closure(Closure::Energy);
            let energy = GroupLobes::new(&params);
            let report = GroupLobes::new(&params.with_closure(Closure::Report));
            for deg in [
                -89.0f32, -85.0, -80.0, -60.0, -30.0, 0.0, 30.0, 60.0, 80.0, 85.0, 89.0,
            ] {
                let tr = deg.to_radians();
                for group in [LobeGroup::R, LobeGroup::TT, LobeGroup::TRT] {
                    let m = mass_on_sphere(&energy, group, tr);
                    assert!(
                        (m - 1.0).abs() < 1e-4,
                        "{} {group:?} θ_r {deg}: {m}",
                        preset.name
                    );
                    let r = mass_on_sphere(&report, group, tr);
                    least_report = least_report.min(r);
                    let want = 1.0 / f64::from(energy.sphere_norm(group, tr));
                    assert!(
                        (r - want).abs() < 1e-4,
                        "{} {group:?} {deg}: {r} vs {want}",
                        preset.name
                    );
                }
            }
        }
        assert!(
            least_report < 0.5,
            "grazing lobes lose mass in the report: {least_report}"
        );
    }
}
