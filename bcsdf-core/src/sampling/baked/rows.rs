//! One interpolated table row as a one-dimensional density, inverted exactly (docs/model.md
//! §10, docs/lut.md "Sampling data"): the rows of the baked sampler's parts, including the
//! scattered family's |φ| rows weighted by the back/front blend of M^s.

use super::super::sliver::invert_sliver_piece;
use super::super::{invert_linear, invert_weighted_linear, linear_mass, unit};
use super::slivers::{pieces, Piece};
use crate::baked::{Axis, BakedBcsdf};
use crate::lut::cdf::{front_weights, Density, NodeRow};
use crate::math::Math;
use crate::model::POLE_SLIVER;
use crate::sampling::weighted_linear_mass;

/// The factor a row's density is weighted by along its axis: the back/front blend of the
/// scattered family, (1 − |φ|/π)·n_s for the back part and (|φ|/π)·n_s for the front part.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Weighting {
    /// The row as it is.
    One,
    /// Times 1 − |φ|/π (prefix sums: `N(3)`'s less [`Density::Front`]'s).
    Back,
    /// Times |φ|/π (prefix sums: [`Density::Front`]'s).
    Front,
}

/// One pole sliver of a part's θ_i range (docs/model.md §10): the row's mass over it as
/// stored (`raw`) and as S weighs it, times g = min(1, cos²θ_i/10⁻⁴) (`kept`).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct Sliver {
    pub(crate) raw: f32,
    pub(crate) kept: f32,
}

/// A part's θ_i range on its row's axis, [lo, hi] with a pole at each end (hi − lo = π),
/// and its masses: `start` the row's running integral at lo, `raw` its integral over the
/// range, `slivers` the pieces within s_c of lo and of hi.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct Range {
    pub(crate) lo: f32,
    pub(crate) hi: f32,
    pub(crate) start: f32,
    pub(crate) raw: f32,
    pub(crate) slivers: [Sliver; 2],
}

impl Range {
    /// The range's mass with g: the raw mass outside the slivers plus their kept masses.
    #[inline(always)]
    pub(crate) fn kept(&self) -> f32 {
        let [a, b] = self.slivers;
        (self.raw - a.raw - b.raw).max(0.0) + a.kept + b.kept
    }
}

/// Two adjacent rows of one density blended with weights (1 − w, w): itself a piecewise-
/// linear function on the rows' nodes (times the [`Weighting`]), with prefix sums blended the
/// same way. The rows' nodes and prefix entries are located once, in [`Rows::new`].
pub(super) struct Rows<'a> {
    /// The two rows' nodes.
    values: (NodeRow<'a>, NodeRow<'a>),
    /// The two rows' prefix entries (little-endian f32).
    prefixes: (&'a [u8], &'a [u8]),
    /// The two rows' [`Density::Front`] prefix entries (for [`Weighting::Back`], which
    /// subtracts them; empty otherwise).
    fronts: (&'a [u8], &'a [u8]),
    weighting: Weighting,
    w: f32,
    /// The rows' axis (its node location, for the pole slivers).
    axis: Axis,
    /// Axis origin and node spacing.
    pub(super) origin: f32,
    pub(super) step: f32,
    pub(super) nodes: usize,
    entries: usize,
    block: usize,
}

impl<'a> Rows<'a> {
    /// Rows `row` and `row + 1` of `density` (weighted as the density says: [`Density::Front`]
    /// by |φ|/π), blended with weight `w`.
    #[inline]
    pub(super) fn new<M: Math>(
        lut: &BakedBcsdf<'a, M>,
        density: Density,
        axis: &Axis,
        at: (usize, f32),
    ) -> Self {
        let weighting = match density {
            Density::Front => Weighting::Front,
            _ => Weighting::One,
        };
        Self::with(lut, density, weighting, axis, at)
    }

    /// The scattered family's |φ| rows weighted by 1 − |φ|/π (the back part of the blend).
    #[inline]
    pub(super) fn back<M: Math>(lut: &BakedBcsdf<'a, M>, axis: &Axis, at: (usize, f32)) -> Self {
        Self::with(lut, Density::N(3), Weighting::Back, axis, at)
    }

    #[inline]
    fn with<M: Math>(
        lut: &BakedBcsdf<'a, M>,
        density: Density,
        weighting: Weighting,
        axis: &Axis,
        (row, w): (usize, f32),
    ) -> Self {
        let l = &lut.densities[density.index()];
        let rows = (row.min(l.rows - 1), (row + 1).min(l.rows - 1));
        let prefix = |d: Density, r: usize| {
            let l = &lut.densities[d.index()];
            let at = l.prefix_at + 4 * r * l.entries;
            lut.blob.get(at..at + 4 * l.entries).unwrap_or(&[])
        };
        let fronts = if weighting == Weighting::Back {
            (
                prefix(Density::Front, rows.0),
                prefix(Density::Front, rows.1),
            )
        } else {
            (&[][..], &[][..])
        };
        Rows {
            values: (
                lut.nodes.row(density, rows.0),
                lut.nodes.row(density, rows.1),
            ),
            prefixes: (prefix(density, rows.0), prefix(density, rows.1)),
            fronts,
            weighting,
            w,
            axis: *axis,
            origin: axis.lo,
            step: l.step,
            nodes: l.nodes,
            entries: l.entries,
            block: l.block,
        }
    }

    /// The blended node value at node j (the interpolant, before the weighting).
    #[inline(always)]
    pub(super) fn value(&self, j: usize) -> f32 {
        let v0 = self.values.0.value(j);
        if self.w == 0.0 {
            return v0;
        }
        let v1 = self.values.1.value(j);
        (1.0 - self.w) * v0 + self.w * v1
    }

    /// Prefix entry k of one row (0 past its end).
    #[inline(always)]
    fn stored(row: &[u8], k: usize) -> f32 {
        match row.get(4 * k..4 * k + 4) {
            Some(b) => f32::from_le_bytes([b[0], b[1], b[2], b[3]]),
            None => 0.0,
        }
    }

    /// Entry k of two rows' prefixes, blended.
    #[inline(always)]
    fn blended(&self, rows: (&[u8], &[u8]), k: usize) -> f32 {
        let p0 = Self::stored(rows.0, k);
        if self.w == 0.0 {
            return p0;
        }
        (1.0 - self.w) * p0 + self.w * Self::stored(rows.1, k)
    }

    /// Blended prefix entry k: ∫ (weighted) from the first node to node min(k·block, nodes − 1).
    #[inline(always)]
    fn prefix(&self, k: usize) -> f32 {
        let p = self.blended(self.prefixes, k);
        if self.weighting == Weighting::Back {
            p - self.blended(self.fronts, k)
        } else {
            p
        }
    }

    /// ∫ over the whole axis.
    #[inline(always)]
    pub(super) fn total(&self) -> f32 {
        self.prefix(self.entries - 1)
    }

    /// The weights at nodes j and j + 1 ([`Weighting`]).
    #[inline(always)]
    fn weights(&self, j: usize) -> (f32, f32) {
        let (a, b) = front_weights(j, self.nodes);
        match self.weighting {
            Weighting::Back => (1.0 - a, 1.0 - b),
            _ => (a, b),
        }
    }

    /// Mass of segment j with node values v0, v1.
    #[inline(always)]
    pub(super) fn segment_mass(&self, j: usize, v0: f32, v1: f32) -> f32 {
        if self.weighting == Weighting::One {
            return linear_mass(v0, v1, self.step);
        }
        let (a, b) = self.weights(j);
        weighted_linear_mass(v0, v1, a, b, self.step)
    }

    /// The offset within segment j where its running integral reaches t.
    #[inline(always)]
    fn invert_segment(&self, j: usize, v0: f32, v1: f32, t: f32) -> f32 {
        if self.weighting == Weighting::One {
            return invert_linear(v0, v1, self.step, t);
        }
        let (a, b) = self.weights(j);
        invert_weighted_linear(v0, v1, a, b, self.step, t)
    }

    /// The position in the sliver [a, b] (one end at `pole`) where its running mass times g
    /// from a reaches t (b if t is past its mass): the pieces' masses from the same node
    /// weights as the view's ([`super::slivers`]), so that they add up to its
    /// [`Sliver::kept`] bit for bit, then [`invert_sliver_piece`] inside the piece.
    fn invert_sliver(&self, a: f32, b: f32, pole: f32, t: f32) -> f32 {
        let (mut acc, mut out) = (0.0, b);
        let at = a - pole;
        pieces(&self.axis, self.step, a, b, |p| {
            let (v0, v1) = (self.value(p.j), self.value(p.j + 1));
            if v0 == 0.0 && v1 == 0.0 {
                return false;
            }
            let m = Piece::masses(&p.weights(at + p.off), v0, v1).kept;
            if m > 0.0 && t - acc <= m {
                let (s, e) = (v0 + (v1 - v0) * p.w0, v0 + (v1 - v0) * p.w1);
                let d = invert_sliver_piece(s, e, p.len, at + p.off, 0.0, t - acc);
                out = a + (p.off + d);
                return true;
            }
            acc += m;
            false
        });
        out
    }

    /// The position in `r` where the running mass times g (docs/model.md §10) reaches the
    /// fraction u of [`Range::kept`], the target kept 2⁻²⁰ of the mass inside its ends as
    /// [`Rows::invert_between`] does: in a sliver by [`invert_sliver_piece`], elsewhere by
    /// the row's own inversion at the raw mass it corresponds to.
    #[inline]
    pub(super) fn invert_kept(&self, r: &Range, u: f32) -> f32 {
        let total = r.kept();
        let inset = total * (1.0 / 1_048_576.0);
        let t = (unit(u) * total).clamp(inset, total - inset);
        let [low, high] = r.slivers;
        if t < low.kept {
            return self.invert_sliver(r.lo, r.lo + POLE_SLIVER, r.lo, t);
        }
        let mid = (r.raw - low.raw - high.raw).max(0.0);
        let t = t - low.kept;
        if t <= mid || !(high.kept > 0.0) {
            return self.invert(r.start + low.raw + t.min(mid));
        }
        self.invert_sliver(r.hi - POLE_SLIVER, r.hi, r.hi, t - mid)
    }

    /// The axis position where the running integral reaches t0 + u·(t1 − t0), with the
    /// target kept 2⁻²⁰ of the span inside (t0, t1), so that the ends of u never fall on a
    /// stretch of zero density before or after the mass (mass moved: below 2⁻²⁰).
    #[inline(always)]
    pub(super) fn invert_between(&self, t0: f32, t1: f32, u: f32) -> f32 {
        let inset = (t1 - t0) * (1.0 / 1_048_576.0);
        let t = (t0 + unit(u) * (t1 - t0)).clamp(t0 + inset, t1 - inset);
        self.invert(t)
    }

    /// The axis position where the running integral reaches `t` (0 ≤ t ≤ total).
    pub(super) fn invert(&self, t: f32) -> f32 {
        // Last prefix entry strictly below t among entries 0 ..= entries − 2 (0 when t is 0):
        // the block where the running integral crosses t, also when the integral is flat
        // (zero density) before or after. A branch-free binary search.
        let mut lo = 0usize;
        let mut len = self.entries - 1;
        while len > 1 {
            let half = len / 2;
            lo = if self.prefix(lo + half) < t {
                lo + half
            } else {
                lo
            };
            len -= half;
        }
        let first = lo * self.block;
        let end = (first + self.block).min(self.nodes - 1);
        let mut acc = self.prefix(lo);
        let mut prev = self.value(first);
        // The last segment of positive mass seen, for a t that rounding put past the block.
        let mut last = None;
        for j in first..end {
            let v = self.value(j + 1);
            let m = self.segment_mass(j, prev, v);
            if m > 0.0 {
                if t - acc <= m {
                    let s = self.invert_segment(j, prev, v, t - acc);
                    return self.origin + j as f32 * self.step + s;
                }
                last = Some((j, prev, v, m));
            }
            acc += m;
            prev = v;
        }
        match last {
            Some((j, v0, v1, m)) => {
                // The segment's whole mass (twice it for the unweighted rows: the clamp then
                // lands on the segment's end, as before format 4).
                let whole = if self.weighting == Weighting::One {
                    self.step * (v0 + v1)
                } else {
                    m
                };
                let s = self.invert_segment(j, v0, v1, whole);
                self.origin + j as f32 * self.step + s
            }
            None => self.origin + end as f32 * self.step,
        }
    }
}
