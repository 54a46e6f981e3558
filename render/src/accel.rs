//! Ray queries against the fiber segments through the `bvh` crate's SAH BVH (docs/model.md §11).
//!
//! The crate builds the tree; the queries walk it front to back, collapsed into four-wide
//! nodes (`tree`: four children's boxes axis by axis, leaves marked in the child
//! reference): at a node the four boxes are clipped against the ray's current interval, the
//! children the ray enters are visited nearest first, and a child whose box starts beyond the
//! closest hit so far is never opened. A closest hit in a dense coat then opens a few dozen
//! nodes instead of every node the ray's whole length crosses (the crate's own iterator has
//! no order and no shrinking interval: 12 500 instructions per closest hit in `ball`, 80 % of
//! a render).

use crate::fiber::{FiberSegment, SegmentHit};
use bvh::bvh::Bvh;
use tree::{collapse, depth, Wide, EMPTY, LEAF};

mod tree;
use core::cell::Cell;
use nalgebra::Vector3;

/// A ray segment (origin, unit direction, t in [0, t_max]) as a BVH query.
struct SegmentQuery {
    origin: [f32; 3],
    inv_dir: [f32; 3],
    t_max: Cell<f32>,
}

impl SegmentQuery {
    fn new(origin: &Vector3<f32>, dir: &Vector3<f32>, t_max: f32) -> SegmentQuery {
        SegmentQuery {
            origin: [origin.x, origin.y, origin.z],
            inv_dir: [1.0 / dir.x, 1.0 / dir.y, 1.0 / dir.z],
            t_max: Cell::new(t_max),
        }
    }
}

impl SegmentQuery {
    /// The slab test for the four child slots of `node` at once: per slot, the ray's
    /// t-interval inside each axis' slab, intersected with [0, t_max], and the interval's
    /// start if it is not empty, `INFINITY` for a box the ray misses. The same operations per
    /// slot (lane c is slot c), so that the four boxes' slabs are one set of 4-wide vector
    /// operations per axis. NaN (origin on a slab face, direction parallel to it) counts as
    /// inside. An empty slot's lane is meaningless ([`EMPTY`]).
    #[inline]
    fn entries(&self, node: &Wide) -> [f32; 4] {
        let mut lo = [0.0f32; 4];
        let mut hi = [self.t_max.get(); 4];
        for k in 0..3 {
            let (o, inv) = (self.origin[k], self.inv_dir[k]);
            let t0: [f32; 4] = core::array::from_fn(|c| (node.lo[k][c] - o) * inv);
            let t1: [f32; 4] = core::array::from_fn(|c| (node.hi[k][c] - o) * inv);
            // Selects, not branches, lane by lane: one vector compare and blend each.
            for c in 0..4 {
                let ordered = t0[c] <= t1[c];
                let near = if ordered { t0[c] } else { t1[c] };
                let far = if ordered { t1[c] } else { t0[c] };
                lo[c] = if near > lo[c] { near } else { lo[c] };
                hi[c] = if far < hi[c] { far } else { hi[c] };
            }
        }
        core::array::from_fn(|c| if lo[c] <= hi[c] { lo[c] } else { f32::INFINITY })
    }
}

/// Nodes a front-to-back walk keeps pending on its fixed stack: three per level of the tree,
/// for trees up to 63 levels deep (a SAH tree over 10⁵ segments is about 40). A deeper tree's
/// walk allocates its stack.
const STACK: usize = 192;

/// What a walk does at a leaf.
enum Visit {
    /// Go on (with the query's t_max possibly shrunk).
    Continue,
    /// Stop the walk.
    Stop,
}

/// The fiber segments and their BVH.
pub struct FiberAccel {
    segments: Vec<FiberSegment>,
    /// The crate's tree collapsed to four children per node ([`Wide`]); the root is `root`,
    /// `None` when there is no tree (no segments, or more than the references can index:
    /// every segment is then tested).
    wide: Vec<Wide>,
    root: Option<u32>,
    /// The most nodes a walk keeps pending (three per level, and the root).
    stack: usize,
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

impl Skip {
    /// Whether a hit at distance `t` on fiber `fiber` is one to ignore.
    #[inline]
    #[must_use]
    pub fn ignores(&self, fiber: u32, t: f32) -> bool {
        self.fiber == Some(fiber) && t < self.dist
    }
}

impl FiberAccel {
    /// Builds the BVH (SAH, single-threaded: the tree is the same for any thread count).
    #[must_use]
    pub fn new(mut segments: Vec<FiberSegment>) -> FiberAccel {
        let bvh = Bvh::build(&mut segments);
        let flat = if segments.is_empty() {
            None
        } else {
            collapse(&bvh)
        };
        // A wide node on the path holds at most three pending siblings; the crate's depth
        // bounds the wide tree's.
        let stack = 3 * depth(&bvh) + 1;
        let (wide, root) = flat.map_or((Vec::new(), None), |(w, r)| (w, Some(r)));
        FiberAccel {
            segments,
            wide,
            root,
            stack,
        }
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
        let query = SegmentQuery::new(origin, dir, t_max);
        let mut best = None;
        self.walk(&query, |seg| {
            if let Some(hit) = seg.intersect(origin, dir, t_min, query.t_max.get()) {
                if !skip.ignores(seg.fiber, hit.t) {
                    best = Some((seg, hit));
                    query.t_max.set(hit.t);
                }
            }
            Visit::Continue
        });
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
        let query = SegmentQuery::new(origin, dir, t_max);
        let mut found = false;
        self.walk(&query, |seg| {
            match seg.intersect(origin, dir, t_min, t_max) {
                Some(hit) if !skip.ignores(seg.fiber, hit.t) => {
                    found = true;
                    Visit::Stop
                }
                _ => Visit::Continue,
            }
        });
        found
    }

    /// The number of distinct fibers with a segment on the ray in (t_min, t_max), `skip`
    /// applied as in [`FiberAccel::closest`]: the strand count an engine reads from its deep
    /// opacity map (docs/model.md §13). A fiber met by several of its segments counts once.
    #[must_use]
    pub fn count_fibers(
        &self,
        origin: &Vector3<f32>,
        dir: &Vector3<f32>,
        t_min: f32,
        t_max: f32,
        skip: Skip,
    ) -> u32 {
        if self.segments.is_empty() {
            return 0;
        }
        let query = SegmentQuery::new(origin, dir, t_max);
        let mut hit = FiberSet::<64>::new();
        self.walk(&query, |seg| {
            match seg.intersect(origin, dir, t_min, t_max) {
                Some(h) if !skip.ignores(seg.fiber, h.t) => hit.insert(seg.fiber),
                _ => {}
            }
            Visit::Continue
        });
        hit.distinct()
    }

    /// Calls `leaf` for the segments whose leaves the ray reaches within the query's
    /// (shrinking) t_max, nearer subtrees first; the order is fixed by the tree and the ray.
    fn walk<'a>(&'a self, query: &SegmentQuery, mut leaf: impl FnMut(&'a FiberSegment) -> Visit) {
        let Some(root) = self.root else {
            for seg in &self.segments {
                if let Visit::Stop = leaf(seg) {
                    return;
                }
            }
            return;
        };
        // Pending nodes (references, [`LEAF`]) and where the ray enters their box.
        let mut fixed = [(0u32, 0.0f32); STACK];
        let mut deep = Vec::new();
        let stack: &mut [(u32, f32)] = if self.stack <= STACK {
            &mut fixed
        } else {
            deep.resize(self.stack, (0u32, 0.0f32));
            &mut deep
        };
        stack[0] = (root, 0.0);
        let mut len = 1;
        while len > 0 {
            len -= 1;
            let (reference, enter) = stack[len];
            if enter > query.t_max.get() {
                continue;
            }
            if reference & LEAF != 0 {
                if let Visit::Stop = leaf(&self.segments[(reference & !LEAF) as usize]) {
                    return;
                }
                continue;
            }
            let node = &self.wide[reference as usize];
            let entries = query.entries(node);
            // The children the ray enters, pushed far first so that the nearest is popped
            // next (insertion by entry distance; equal distances keep the slot order).
            let base = len;
            for (c, &enter) in entries.iter().enumerate() {
                let child = node.child[c];
                if child == EMPTY || enter == f32::INFINITY {
                    continue;
                }
                let mut at = len;
                while at > base && stack[at - 1].1 <= enter {
                    stack[at] = stack[at - 1];
                    at -= 1;
                }
                stack[at] = (child, enter);
                len += 1;
            }
        }
    }
}

/// The fibers a shadow ray met, kept on the stack while they fit (no allocation per ray) and
/// spilled to the heap past `N`; a fiber met by several of its segments counts once.
struct FiberSet<const N: usize> {
    inline: [u32; N],
    len: usize,
    spill: Vec<u32>,
}

impl<const N: usize> FiberSet<N> {
    fn new() -> Self {
        FiberSet {
            inline: [0; N],
            len: 0,
            spill: Vec::new(),
        }
    }

    fn insert(&mut self, fiber: u32) {
        if self.len < N {
            self.inline[self.len] = fiber;
            self.len += 1;
        } else {
            if self.spill.is_empty() {
                self.spill.extend_from_slice(&self.inline);
            }
            self.spill.push(fiber);
        }
    }

    /// The number of distinct fibers inserted.
    fn distinct(mut self) -> u32 {
        let ids: &mut [u32] = if self.spill.is_empty() {
            &mut self.inline[..self.len]
        } else {
            &mut self.spill
        };
        ids.sort_unstable();
        let repeats = ids.windows(2).filter(|w| w[0] == w[1]).count();
        (ids.len() - repeats) as u32
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use bcsdf_core::rng::Pcg32;
    use bvh::aabb::Bounded;

    /// A random unit vector from two uniforms.
    fn direction(rng: &mut Pcg32) -> Vector3<f32> {
        let z = 2.0 * rng.uniform() - 1.0;
        let phi = 2.0 * core::f32::consts::PI * rng.uniform();
        let r = (1.0 - z * z).max(0.0).sqrt();
        Vector3::new(r * phi.cos(), r * phi.sin(), z)
    }

    /// 3000 short segments in 200 fibers, scattered in a unit box: a small coat.
    fn coat(rng: &mut Pcg32) -> Vec<FiberSegment> {
        let mut segments = Vec::new();
        for fiber in 0..200u32 {
            let mut p = Vector3::new(rng.uniform(), rng.uniform(), rng.uniform());
            for _ in 0..15 {
                let q = p + direction(rng) * 0.05;
                segments.push(FiberSegment {
                    p0: p,
                    p1: q,
                    r0: 0.01,
                    r1: 0.008,
                    v0: 0.0,
                    v1: 1.0,
                    fiber,
                    node: 0,
                });
                p = q;
            }
        }
        segments
    }

    /// The front-to-back walk finds what testing every segment finds: the same closest t
    /// (a different segment only on an exact tie) and the same answer to "any hit", on the
    /// fixed stack, on a stack of a deeper tree's (allocated), and without a tree.
    #[test]
    fn ordered_walk_agrees_with_testing_every_segment() {
        let mut rng = Pcg32::new(7, 11);
        let segments = coat(&mut rng);
        let mut accel = FiberAccel::new(segments.clone());
        assert!(
            accel.stack <= STACK,
            "a 3000-segment tree fits the fixed stack"
        );
        agrees_with_every_segment(&accel, &segments, &mut rng);
        accel.stack = STACK + 1;
        agrees_with_every_segment(&accel, &segments, &mut rng);
        accel.root = None;
        agrees_with_every_segment(&accel, &segments, &mut rng);
    }

    fn agrees_with_every_segment(accel: &FiberAccel, segments: &[FiberSegment], rng: &mut Pcg32) {
        let (mut hits, mut misses) = (0, 0);
        for i in 0..4000 {
            let origin = Vector3::new(
                1.4 * rng.uniform() - 0.2,
                1.4 * rng.uniform() - 0.2,
                1.4 * rng.uniform() - 0.2,
            );
            let dir = direction(rng);
            let t_max = if i % 2 == 0 { f32::INFINITY } else { 0.3 };
            let skip = Skip {
                fiber: (i % 3 == 0).then_some(i % 200),
                dist: 0.05,
            };
            let brute = segments
                .iter()
                .filter_map(|s| {
                    let hit = s.intersect(&origin, &dir, 1e-4, t_max)?;
                    (!(skip.fiber == Some(s.fiber) && hit.t < skip.dist)).then_some(hit.t)
                })
                .fold(f32::INFINITY, f32::min);
            let found = accel.closest(&origin, &dir, 1e-4, t_max, skip);
            match found {
                Some((_, hit)) => {
                    hits += 1;
                    assert_eq!(hit.t, brute, "ray {i}: closest t");
                }
                None => {
                    misses += 1;
                    assert!(brute.is_infinite(), "ray {i}: missed a hit at {brute}");
                }
            }
            assert_eq!(
                accel.any(&origin, &dir, 1e-4, t_max, skip),
                brute.is_finite(),
                "ray {i}: any"
            );
        }
        assert!(hits > 500 && misses > 500, "{hits} hits, {misses} misses");
    }

    /// The collapsed tree references every segment exactly once, each slot's box holds its
    /// subtree, and a node with an empty slot has nothing left to open (every child a leaf).
    #[test]
    fn collapsed_nodes_hold_four_children_and_every_segment_once() {
        let mut rng = Pcg32::new(3, 17);
        let segments = coat(&mut rng);
        let accel = FiberAccel::new(segments.clone());
        let mut seen = vec![0u32; segments.len()];
        let (mut slots, mut nodes) = (0, 0);
        // (reference, the box its parent holds for it)
        let mut pending = vec![(accel.root.expect("a tree"), None::<([f32; 3], [f32; 3])>)];
        while let Some((reference, bounds)) = pending.pop() {
            let inside = |lo: [f32; 3], hi: [f32; 3]| {
                bounds.is_none_or(|(blo, bhi)| (0..3).all(|k| blo[k] <= lo[k] && hi[k] <= bhi[k]))
            };
            if reference & LEAF != 0 {
                let seg = &segments[(reference & !LEAF) as usize];
                let b = seg.aabb();
                assert!(inside(
                    [b.min.x, b.min.y, b.min.z],
                    [b.max.x, b.max.y, b.max.z]
                ));
                seen[(reference & !LEAF) as usize] += 1;
                continue;
            }
            let node = &accel.wide[reference as usize];
            nodes += 1;
            if node.child.contains(&EMPTY) {
                assert!(
                    node.child.iter().all(|&c| c == EMPTY || c & LEAF != 0),
                    "a node with an empty slot and an inner child: {:?}",
                    node.child
                );
            }
            for c in 0..4 {
                if node.child[c] == EMPTY {
                    continue;
                }
                slots += 1;
                let lo = [0, 1, 2].map(|k| node.lo[k][c]);
                let hi = [0, 1, 2].map(|k| node.hi[k][c]);
                assert!(inside(lo, hi), "a child's box outside its parent's");
                pending.push((node.child[c], Some((lo, hi))));
            }
        }
        assert!(seen.iter().all(|&n| n == 1), "every segment once");
        // Against the binary tree's two per node (3000 segments: 4446 slots in 1447 nodes).
        assert!(
            slots as f64 / nodes as f64 > 3.0,
            "{slots} slots in {nodes} nodes"
        );
    }

    /// `FiberSet` counts distinct fibers on the stack and after spilling to the heap (a
    /// capacity of 4 spills), against a sort and dedup of everything inserted.
    #[test]
    fn fiber_set_counts_distinct_fibers_inline_and_spilled() {
        let mut rng = Pcg32::new(5, 9);
        let mut spilled = 0;
        for round in 0..500 {
            let count = round % 12;
            let ids: Vec<u32> = (0..count).map(|_| (rng.uniform() * 6.0) as u32).collect();
            let mut set = FiberSet::<4>::new();
            for &id in &ids {
                set.insert(id);
            }
            spilled += usize::from(!set.spill.is_empty());
            let mut expected = ids.clone();
            expected.sort_unstable();
            expected.dedup();
            assert_eq!(set.distinct(), expected.len() as u32, "{ids:?}");
        }
        assert!(spilled > 100, "only {spilled} rounds spilled");
    }

    /// `count_fibers` counts distinct fibers: brute force over every segment, a fiber met
    /// by several of its segments once, and the skipped fiber not at all.
    #[test]
    fn count_fibers_counts_each_fiber_once() {
        let mut rng = Pcg32::new(11, 3);
        let segments = coat(&mut rng);
        let accel = FiberAccel::new(segments.clone());
        let mut several = 0;
        for _ in 0..2000 {
            let o = Vector3::new(rng.uniform(), rng.uniform(), rng.uniform());
            let d = direction(&mut rng);
            let skip = Skip {
                fiber: Some(0),
                dist: 0.04,
            };
            let mut ids: Vec<u32> = segments
                .iter()
                .filter_map(|s| {
                    let h = s.intersect(&o, &d, 1e-4, f32::INFINITY)?;
                    (!(skip.fiber == Some(s.fiber) && h.t < skip.dist)).then_some(s.fiber)
                })
                .collect();
            let hits = ids.len();
            ids.sort_unstable();
            ids.dedup();
            if hits > ids.len() {
                several += 1;
            }
            assert_eq!(
                accel.count_fibers(&o, &d, 1e-4, f32::INFINITY, skip),
                ids.len() as u32
            );
        }
        // Rays that met one fiber through several segments were part of the sample.
        assert!(several > 10, "{several}");
    }
}
