//! M_g's mass on the sphere from the baked LUT (docs/model.md §12): the prefix-sum reads of
//! table `M` and the energy closure's factor 1/Z_g(θ_r) built from them.

use super::BakedBcsdf;
use crate::longitudinal::MIN_SPHERE_MASS;
use crate::math::Math;
use crate::model::POLE_SLIVER;
use crate::sampling::linear_mass;

impl<M: Math> BakedBcsdf<'_, M> {
    /// ∫ M_g from the first node of the `sum` axis to the point at node `j`, weight `w`
    /// (a location from [`Axis::locate`]), for the three groups at once: the prefix sum at
    /// node j plus the mass of the linear interpolant up to the point.
    #[inline(always)]
    pub(crate) fn m_cdf_at(&self, at: (usize, f32)) -> [f32; 3] {
        self.m_cdf_and_value(at).0
    }

    /// [`BakedBcsdf::m_cdf_at`] and the interpolated M_g at the point.
    #[inline(always)]
    fn m_cdf_and_value(&self, (j, w): (usize, f32)) -> ([f32; 3], [f32; 3]) {
        let off = w * self.densities[0].step;
        let v = self.nodes.m_pair(j);
        let mut cdf = [0.0; 3];
        let mut value = [0.0; 3];
        for g in 0..3 {
            let (v0, v1) = (v[g], v[3 + g]);
            let at = v0 + (v1 - v0) * w;
            cdf[g] = self.f32_at(self.densities[g].prefix_at + 4 * j) + linear_mass(v0, at, off);
            value[g] = at;
        }
        (cdf, value)
    }

    /// The interpolated M_g at `dx` from a location on the `sum` axis.
    #[inline(always)]
    fn m_value_beside(&self, at: (usize, f32), dx: f32) -> [f32; 3] {
        let (j, w) = self.sum.shifted(at, dx);
        let v = self.nodes.m_pair(j);
        core::array::from_fn(|g| v[g] + (v[3 + g] - v[g]) * w)
    }

    /// The energy closure's factor M_g / (tabulated M_g) for the range between the located
    /// ends (docs/model.md §12): 1/Z_g with Z_g the interpolant's mass over
    /// θ_i ∈ [−π/2, π/2] (at least [`MIN_SPHERE_MASS`]); 1 in the report closure.
    #[inline(always)]
    pub(crate) fn sphere_norms(&self, range: [(usize, f32); 2]) -> [f32; 3] {
        if !self.energy {
            return [1.0; 3];
        }
        let (lo, lo_pole) = self.m_cdf_and_value(range[0]);
        let (hi, hi_pole) = self.m_cdf_and_value(range[1]);
        // The pole slivers: ∫ M·(1 − s²/s_c²) ds over s ∈ [0, s_c] from the pole, M taken
        // quadratic through s = 0, s_c/2, s_c: s_c·(11·M_0 + 28·M_½ + M_1)/60.
        let inside = |at: (usize, f32), dir: f32| {
            [0.5, 1.0].map(|f| self.m_value_beside(at, dir * f * POLE_SLIVER))
        };
        let [lo_half, lo_end] = inside(range[0], 1.0);
        let [hi_half, hi_end] = inside(range[1], -1.0);
        let sliver = |m0: f32, m_half: f32, m1: f32| {
            POLE_SLIVER * (1.0 / 60.0) * (11.0 * m0 + 28.0 * m_half + m1)
        };
        core::array::from_fn(|g| {
            let loss = sliver(lo_pole[g], lo_half[g], lo_end[g])
                + sliver(hi_pole[g], hi_half[g], hi_end[g]);
            1.0 / (hi[g] - lo[g] - loss).max(MIN_SPHERE_MASS)
        })
    }
}
