//! Fibers as chains of thin tapering cylinder segments, and the ray–segment test (docs/model.md §11).
//!
//! A fiber is a far-field scatterer (docs/model.md §8, §11): the BCSDF S(ω_i, ω_r) already
//! integrates over the offset h across the fiber, so a hit needs only the point where the
//! ray crosses the fiber's axis and the segment's tangent, never h.
//!
//! The hit test: a ray meets an infinite cylinder of radius r exactly when the distance
//! between the ray's line and the axis is below r. Here the axis point is clamped to the
//! segment (so segment ends behave as round caps and a chain has no gaps at its joints) and
//! r is interpolated along the segment (the taper); the hit distance is the ray's closest
//! approach to the axis.

use bvh::aabb::{Aabb, Bounded};
use bvh::bounding_hierarchy::BHShape;
use nalgebra::{Point3, Vector3};

/// One segment of a fiber: a cylinder from `p0` (radius `r0`) to `p1` (radius `r1`).
#[derive(Clone, Copy, Debug)]
pub struct FiberSegment {
    /// Start of the axis (toward the root).
    pub p0: Vector3<f32>,
    /// End of the axis (toward the tip).
    pub p1: Vector3<f32>,
    /// Radius at `p0`.
    pub r0: f32,
    /// Radius at `p1`.
    pub r1: f32,
    /// Position along the whole strand at `p0`: 0 at the root, 1 at the tip (what a colour
    /// gradient from root to tip reads, [`crate::strand`]).
    pub v0: f32,
    /// Position along the whole strand at `p1`.
    pub v1: f32,
    /// Which fiber the segment belongs to (a scattered ray ignores its own fiber nearby).
    pub fiber: u32,
    /// Node index in the BVH (set by the BVH build).
    pub node: usize,
}

/// Where a ray crosses a fiber segment.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SegmentHit {
    /// Distance along the (unit) ray to the closest approach to the axis.
    pub t: f32,
    /// Position along the segment, 0 at `p0`, 1 at `p1`.
    pub s: f32,
}

impl FiberSegment {
    /// The segment's (unnormalised) tangent p1 − p0, root to tip.
    #[inline]
    #[must_use]
    pub fn tangent(&self) -> Vector3<f32> {
        self.p1 - self.p0
    }

    /// Position along the strand (0 root, 1 tip) of the point at `s` along this segment
    /// ([`SegmentHit::s`]): linear between [`FiberSegment::v0`] and [`FiberSegment::v1`].
    #[inline]
    #[must_use]
    pub fn along(&self, s: f32) -> f32 {
        self.v0 + (self.v1 - self.v0) * s.clamp(0.0, 1.0)
    }

    /// Where the ray `origin + t·dir` (`dir` unit length) passes within the segment's
    /// radius of its axis, for t in (t_min, t_max); `None` otherwise, and for a ray parallel
    /// to the segment.
    #[inline]
    #[must_use]
    pub fn intersect(
        &self,
        origin: &Vector3<f32>,
        dir: &Vector3<f32>,
        t_min: f32,
        t_max: f32,
    ) -> Option<SegmentHit> {
        let e = self.p1 - self.p0;
        let w = origin - self.p0;
        let b = dir.dot(&e);
        let c = e.dot(&e);
        let d = dir.dot(&w);
        let f = e.dot(&w);
        // |dir|² = 1: the closest points of the two lines solve a 2×2 system of determinant
        // c − b² (zero when they are parallel).
        let det = c - b * b;
        if det.is_nan() || det <= 1e-12 * c {
            return None;
        }
        let s = ((f - b * d) / det).clamp(0.0, 1.0);
        // The ray's point closest to the axis point at s.
        let t = s * b - d;
        if !(t > t_min && t < t_max) {
            return None;
        }
        let gap = origin + dir * t - (self.p0 + e * s);
        let r = self.r0 + (self.r1 - self.r0) * s;
        (gap.norm_squared() < r * r).then_some(SegmentHit { t, s })
    }
}

impl Bounded<f32, 3> for FiberSegment {
    fn aabb(&self) -> Aabb<f32, 3> {
        let r = self.r0.max(self.r1);
        let lo = self.p0.inf(&self.p1) - Vector3::repeat(r);
        let hi = self.p0.sup(&self.p1) + Vector3::repeat(r);
        Aabb::with_bounds(Point3::from(lo), Point3::from(hi))
    }
}

impl BHShape<f32, 3> for FiberSegment {
    fn set_bh_node_index(&mut self, index: usize) {
        self.node = index;
    }

    fn bh_node_index(&self) -> usize {
        self.node
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn segment() -> FiberSegment {
        FiberSegment {
            p0: Vector3::new(0.0, 0.0, 0.0),
            p1: Vector3::new(0.0, 0.0, 2.0),
            r0: 0.1,
            r1: 0.05,
            v0: 0.5,
            v1: 1.0,
            fiber: 0,
            node: 0,
        }
    }

    #[test]
    fn hits_within_the_tapered_radius_at_the_axis() {
        let seg = segment();
        let dir = Vector3::new(1.0, 0.0, 0.0);
        // At s = 0.5 the radius is 0.075: offsets 0.07 hit, 0.08 miss.
        let hit = seg
            .intersect(&Vector3::new(-5.0, 0.07, 1.0), &dir, 0.0, f32::INFINITY)
            .unwrap();
        assert!((hit.t - 5.0).abs() < 1e-5 && (hit.s - 0.5).abs() < 1e-6);
        assert_eq!(seg.along(hit.s), 0.75);
        assert!(seg
            .intersect(&Vector3::new(-5.0, 0.08, 1.0), &dir, 0.0, f32::INFINITY)
            .is_none());
        // Beyond t_max, behind the origin, past the tip cap, or parallel: no hit.
        assert!(seg
            .intersect(&Vector3::new(-5.0, 0.0, 1.0), &dir, 0.0, 4.9)
            .is_none());
        assert!(seg
            .intersect(&Vector3::new(5.0, 0.0, 1.0), &dir, 0.0, 100.0)
            .is_none());
        assert!(seg
            .intersect(&Vector3::new(-5.0, 0.0, 2.06), &dir, 0.0, 100.0)
            .is_none());
        let along = Vector3::new(0.0, 0.0, 1.0);
        assert!(seg
            .intersect(&Vector3::new(0.0, 0.0, -1.0), &along, 0.0, 100.0)
            .is_none());
    }

    #[test]
    fn the_box_holds_the_radius() {
        let b = segment().aabb();
        assert_eq!(b.min, Point3::new(-0.1, -0.1, -0.1));
        assert_eq!(b.max, Point3::new(0.1, 0.1, 2.1));
    }
}
