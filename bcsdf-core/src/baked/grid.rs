//! A uniform table axis of the baked evaluator: where a coordinate falls between the
//! table's nodes (docs/lut.md, the axes of `M`, `N` and `M_s`).

use crate::lut;

/// One uniform table axis over [lo, lo + span] with `nodes` nodes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Axis {
    pub(crate) lo: f32,
    inv_step: f32,
    /// Node index of x = 0: 0, or (nodes − 1)/2 for an axis centred on 0.
    offset: f32,
    last: f32,
    pub(crate) nodes: usize,
}

impl Axis {
    /// The axis over [lo, lo + span] given 1/span, with lo = 0 or lo = −span/2. The node
    /// position of x is u = x·inv_step + offset, inv_step = (nodes − 1)·(1/span) and offset =
    /// 0 or (nodes − 1)/2: only correctly rounded products and sums of constants, no division
    /// (WGSL's is not correctly rounded), so that the WGSL evaluator forms the same u. A shader
    /// compiler that fuses x·inv_step + offset into one rounding moves u by at most one ulp
    /// (docs/lut.md, "On the GPU").
    pub(super) fn new(lo: f32, inv_span: f32, nodes: u32) -> Axis {
        let last = (nodes - 1) as f32;
        Axis {
            lo,
            inv_step: last * inv_span,
            offset: if lo == 0.0 { 0.0 } else { 0.5 * last },
            last,
            nodes: nodes as usize,
        }
    }

    /// Lower node index and weight of the upper node for `x` (clamped to the axis ends).
    #[inline(always)]
    pub(crate) fn locate(&self, x: f32) -> (usize, f32) {
        // `max` first: NaN becomes 0 (the callers pass finite angles anyway).
        let u = (x * self.inv_step + self.offset).max(0.0).min(self.last);
        debug_assert!((2..=lut::MAX_NODES as usize).contains(&self.nodes) && u <= self.last);
        // SAFETY: u ∈ [0, nodes − 1] and never NaN (`max` maps NaN to 0), and every axis has
        // 2 ..= MAX_NODES = 8192 nodes (`lut::validate` refuses others before an `Axis` is
        // built), so u ≤ 8191 and the truncation to i32 is in range; unchecked, it is one
        // instruction instead of a saturating sequence with two compares.
        let i = unsafe { u.to_int_unchecked::<i32>() }.min(self.nodes as i32 - 2);
        (i as u32 as usize, u - i as f32)
    }
}
