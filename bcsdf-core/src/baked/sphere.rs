//! M_g's mass on the sphere from the baked LUT (docs/model.md §12): the prefix-sum reads of
//! table `M` (the sampler's) and the energy closure's factor 1/Z_g(θ_r), read from the LUT's
//! 1/Z_g table ([`crate::lut::norms`]).

use super::BakedBcsdf;
use crate::math::Math;
use crate::sample1d::linear_mass;

impl<M: Math> BakedBcsdf<'_, M> {
    /// ∫ M_g from the first node of the `sum` axis to the point at node `j`, weight `w`
    /// (a location from [`Axis::locate`](super::Axis::locate)), for the three groups at once:
    /// the prefix sum at node j plus the mass of the linear interpolant up to the point.
    #[inline(always)]
    pub(crate) fn m_cdf_at(&self, (j, w): (usize, f32)) -> [f32; 3] {
        let off = w * self.densities[0].step;
        let v = self.nodes.m_pair(j);
        core::array::from_fn(|g| {
            let (v0, v1) = (v[g], v[3 + g]);
            let at = v0 + (v1 - v0) * w;
            self.f32_at(self.densities[g].prefix_at + 4 * j) + linear_mass(v0, at, off)
        })
    }

    /// The energy closure's factor M_g / (tabulated M_g) at θ_r located on the 1/Z_g table's
    /// axis (`self.norm`): 1/Z_g(θ_r), Z_g the baked M_g's mass on the sphere as S weighs it
    /// (docs/model.md §12), interpolated linearly between the table's nodes; 1 in the report
    /// closure, which does not read the table.
    #[inline(always)]
    pub(crate) fn sphere_norms(&self, (j, w): (usize, f32)) -> [f32; 3] {
        if !self.energy {
            return [1.0; 3];
        }
        // Nodes j and j + 1 as one 24-byte read: one bounds check (a short table, which
        // `validate` refuses, would read as 1).
        let Some(b) = self.norms.get(12 * j..12 * j + 24) else {
            return [1.0; 3];
        };
        let z: [f32; 6] = core::array::from_fn(|k| {
            f32::from_le_bytes([b[4 * k], b[4 * k + 1], b[4 * k + 2], b[4 * k + 3]])
        });
        core::array::from_fn(|g| z[g] + (z[3 + g] - z[g]) * w)
    }
}
