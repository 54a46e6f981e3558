//! The walk's tree (docs/model.md §11 "Ray queries"): the `bvh` crate's binary SAH tree
//! collapsed into four-wide nodes, and the crate tree's depth.

use bvh::aabb::Aabb;
use bvh::bvh::{Bvh, BvhNode};

/// A child reference of the walk's tree: an index into the [`Wide`] nodes, or, with this
/// bit set, a segment index (a leaf: the crate's leaves hold one segment each).
pub(super) const LEAF: u32 = 1 << 31;

/// The reference of an empty child slot.
pub(super) const EMPTY: u32 = u32::MAX;

/// One node of the walk's tree: up to four children, their boxes axis by axis (`lo[k][c]`,
/// `hi[k][c]` for slot c) and their references ([`LEAF`], [`EMPTY`]), 112 bytes. Each is a
/// node of the crate's binary tree with its children and, where they are inner nodes, their
/// children in their place (the largest box opened first): the walk pops fewer nodes and
/// tests four boxes with the vector operations that tested two.
#[derive(Clone, Copy, Debug)]
pub(super) struct Wide {
    pub(super) lo: [[f32; 4]; 3],
    pub(super) hi: [[f32; 4]; 3],
    pub(super) child: [u32; 4],
}

/// A box's surface area, which decides which child of a wide node is opened next.
fn area(b: &Aabb<f32, 3>) -> f32 {
    let d = b.max - b.min;
    d.x * d.y + d.y * d.z + d.z * d.x
}

/// The crate's tree collapsed into [`Wide`] nodes, depth first, and the root's reference;
/// `None` if an index does not fit the references. Slots keep the crate's left-to-right
/// order.
pub(super) fn collapse(bvh: &Bvh<f32, 3>) -> Option<(Vec<Wide>, u32)> {
    let nodes = &bvh.nodes;
    let children = |index: usize| match nodes.get(index)? {
        BvhNode::Node {
            child_l_index,
            child_l_aabb,
            child_r_index,
            child_r_aabb,
            ..
        } => Some([
            (*child_l_index, *child_l_aabb),
            (*child_r_index, *child_r_aabb),
        ]),
        BvhNode::Leaf { .. } => None,
    };
    let leaf = |index: usize| match nodes.get(index) {
        Some(BvhNode::Leaf { shape_index, .. }) => u32::try_from(*shape_index)
            .ok()
            .filter(|i| i & LEAF == 0 && *i | LEAF != EMPTY)
            .map(|i| Some(i | LEAF)),
        Some(BvhNode::Node { .. }) => Some(None),
        None => None,
    };
    if let Some(root) = leaf(0)? {
        return Some((Vec::new(), root));
    }
    let empty = Wide {
        lo: [[0.0; 4]; 3],
        hi: [[0.0; 4]; 3],
        child: [EMPTY; 4],
    };
    let mut wide = vec![empty];
    let mut pending = vec![(0usize, 0usize)];
    while let Some((index, at)) = pending.pop() {
        let mut slots: Vec<(usize, Aabb<f32, 3>)> = children(index)?.to_vec();
        // Open the inner child with the largest box (the first on a tie) until four.
        while slots.len() < 4 {
            let mut open: Option<(usize, f32)> = None;
            for (j, (child, b)) in slots.iter().enumerate() {
                if children(*child).is_some() && open.is_none_or(|(_, a)| area(b) > a) {
                    open = Some((j, area(b)));
                }
            }
            let Some((j, _)) = open else { break };
            let [l, r] = children(slots[j].0)?;
            slots[j] = l;
            slots.insert(j + 1, r);
        }
        let mut node = empty;
        for (c, (child, b)) in slots.iter().enumerate() {
            node.child[c] = match leaf(*child)? {
                Some(reference) => reference,
                None => {
                    let slot = wide.len();
                    wide.push(empty);
                    pending.push((*child, slot));
                    u32::try_from(slot).ok().filter(|i| i & LEAF == 0)?
                }
            };
            for k in 0..3 {
                node.lo[k][c] = b.min[k];
                node.hi[k][c] = b.max[k];
            }
        }
        wide[at] = node;
    }
    Some((wide, 0))
}

/// The number of nodes on the tree's longest root-to-leaf path.
pub(super) fn depth(bvh: &Bvh<f32, 3>) -> usize {
    let mut deepest = 0;
    let mut pending = vec![(0usize, 1usize)];
    while let Some((index, d)) = pending.pop() {
        deepest = deepest.max(d);
        if let Some(BvhNode::Node {
            child_l_index,
            child_r_index,
            ..
        }) = bvh.nodes.get(index)
        {
            pending.push((*child_l_index, d + 1));
            pending.push((*child_r_index, d + 1));
        }
    }
    deepest
}
