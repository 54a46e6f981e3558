//! Longitudinal lobes M_p(θ_i, θ_r) = G(θ_r + θ_i − α_p; β_p) (report eq. 2–3, docs/model.md §5).

use crate::gaussian::{Gaussian, WrappedGaussian};
use crate::lobes::LobeGroup;
use crate::math::Math;
use crate::params::FurParams;

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
        }
    }

    /// M_p(θ_i, θ_r) for one group.
    #[inline]
    #[must_use]
    pub fn m<M: Math>(&self, group: LobeGroup, theta_i: f32, theta_r: f32) -> f32 {
        let g = group as usize;
        self.longitudinal[g].eval::<M>(theta_r + theta_i - self.shift[g])
    }

    /// D_p for one group.
    #[inline]
    #[must_use]
    pub fn d(&self, group: LobeGroup) -> &WrappedGaussian {
        &self.azimuthal[group as usize]
    }
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
        // M_p peaks where θ_i + θ_r = α_p and depends on the sum only.
        for (k, group) in [LobeGroup::R, LobeGroup::TT, LobeGroup::TRT]
            .into_iter()
            .enumerate()
        {
            let peak = g.m::<Libm>(group, 0.4, g.shift[k] - 0.4);
            assert_eq!(peak, g.m::<Libm>(group, -0.1, g.shift[k] + 0.1));
            assert!(peak > g.m::<Libm>(group, 0.41, g.shift[k] - 0.4));
            assert!(peak > g.m::<Libm>(group, 0.39, g.shift[k] - 0.4));
        }
    }
}
