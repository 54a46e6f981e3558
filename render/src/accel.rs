//! Ray queries against the fiber segments through the `bvh` crate's SAH BVH (docs/model.md §11).
//!
//! The crate builds the tree and walks it; what it walks with is our `SegmentQuery`: a ray
//! with a t_max that shrinks as closer hits are found (a `Cell`), so subtrees beyond the
//! closest hit so far are skipped.

use crate::fiber::{FiberSegment, SegmentHit};
use bvh::aabb::{Aabb, IntersectsAabb};
use bvh::bvh::Bvh;
use core::cell::Cell;
use nalgebra::Vector3;

/// A ray segment (origin, unit direction, t in [0, t_max]) as a BVH query.
struct SegmentQuery {
    origin: Vector3<f32>,
    inv_dir: Vector3<f32>,
    t_max: Cell<f32>,
}

impl IntersectsAabb<f32, 3> for SegmentQuery {
    /// The slab test: the ray's t-interval inside each axis' slab, intersected.
    fn intersects_aabb(&self, aabb: &Aabb<f32, 3>) -> bool {
        let mut lo = 0.0f32;
        let mut hi = self.t_max.get();
        for k in 0..3 {
            let t0 = (aabb.min[k] - self.origin[k]) * self.inv_dir[k];
            let t1 = (aabb.max[k] - self.origin[k]) * self.inv_dir[k];
            // NaN (origin on a slab face, direction parallel to it) counts as inside.
            let (near, far) = if t0 <= t1 { (t0, t1) } else { (t1, t0) };
            if near > lo {
                lo = near;
            }
            if far < hi {
                hi = far;
            }
        }
        lo <= hi
    }
}

/// The fiber segments and their BVH.
pub struct FiberAccel {
    segments: Vec<FiberSegment>,
    bvh: Bvh<f32, 3>,
}

/// Which nearby hits to ignore: those on fiber `fiber` closer than `dist` (a ray leaving a
/// fiber starts on its axis and must not hit that fiber again right there).
#[derive(Clone, Copy, Debug, Default)]
pub struct Skip {
    /// The fiber the ray leaves, if any.
    pub fiber: Option<u32>,
    /// Distance within which hits on that fiber are ignored.
    pub dist: f32,
}

impl FiberAccel {
    /// Builds the BVH (SAH, single-threaded: the tree is the same for any thread count).
    #[must_use]
    pub fn new(mut segments: Vec<FiberSegment>) -> FiberAccel {
        let bvh = Bvh::build(&mut segments);
        FiberAccel { segments, bvh }
    }

    /// The segments (in build order).
    #[must_use]
    pub fn segments(&self) -> &[FiberSegment] {
        &self.segments
    }

    /// The closest segment hit in (t_min, t_max), and the segment. The traversal order is
    /// fixed by the tree, so ties (equal t) are broken the same way on every run.
    #[must_use]
    pub fn closest(
        &self,
        origin: &Vector3<f32>,
        dir: &Vector3<f32>,
        t_min: f32,
        t_max: f32,
        skip: Skip,
    ) -> Option<(&FiberSegment, SegmentHit)> {
        if self.segments.is_empty() {
            return None;
        }
        let query = SegmentQuery {
            origin: *origin,
            inv_dir: dir.map(|x| 1.0 / x),
            t_max: Cell::new(t_max),
        };
        let mut best = None;
        for seg in self.bvh.traverse_iterator(&query, &self.segments) {
            if let Some(hit) = seg.intersect(origin, dir, t_min, query.t_max.get()) {
                if skip.fiber == Some(seg.fiber) && hit.t < skip.dist {
                    continue;
                }
                best = Some((seg, hit));
                query.t_max.set(hit.t);
            }
        }
        best
    }

    /// Whether any segment lies on the ray in (t_min, t_max).
    #[must_use]
    pub fn any(
        &self,
        origin: &Vector3<f32>,
        dir: &Vector3<f32>,
        t_min: f32,
        t_max: f32,
        skip: Skip,
    ) -> bool {
        if self.segments.is_empty() {
            return false;
        }
        let query = SegmentQuery {
            origin: *origin,
            inv_dir: dir.map(|x| 1.0 / x),
            t_max: Cell::new(t_max),
        };
        self.bvh
            .traverse_iterator(&query, &self.segments)
            .any(|seg| match seg.intersect(origin, dir, t_min, t_max) {
                Some(hit) => !(skip.fiber == Some(seg.fiber) && hit.t < skip.dist),
                None => false,
            })
    }
}
