//! The pole slivers of the baked sampler's θ_i ranges as weights on the table's nodes
//! (docs/model.md §10, "Importance sampling", implementation): several rows on one axis at
//! once.
//!
//! A sliver [a, b] (one end at the pole) is cut at the axis's nodes into pieces; on the piece
//! of segment j from node weight w0 to w1 the row is v(τ) = v_j·(1 − τ) + v_{j+1}·τ, so its
//! mass times g, ∫ v·k, is v_j·K_0 + v_{j+1}·K_1 with node weights K that depend on the
//! piece's place alone (three-point Gauss–Legendre on k·v, exact: [`super::super::sliver`]),
//! and likewise its raw mass. The weights are computed once per piece and applied to every
//! row on the axis: the three M_g of table `M` (one texel pair per node), the two halves of
//! M^s. The inversion inside the chosen part's sliver ([`super::rows`]) forms its pieces'
//! masses with the same weights, so that they add up to the view's masses bit for bit.

use super::rows::Sliver;
use crate::baked::Axis;
use crate::sampling::sliver::{sliver_keep, GAUSS3};

/// One piece of a sliver: segment `j` of the axis from node weight `w0` to `w1`, starting
/// `off` after the sliver's start, `len` long.
#[derive(Clone, Copy, Debug)]
pub(super) struct Piece {
    pub(super) j: usize,
    pub(super) w0: f32,
    pub(super) w1: f32,
    pub(super) off: f32,
    pub(super) len: f32,
}

impl Piece {
    /// The piece's node weights `[K_0, K_1, R_0, R_1]`: its mass times g is v_j·K_0 +
    /// v_{j+1}·K_1 and its raw mass v_j·R_0 + v_{j+1}·R_1 (docs/model.md §10). `s0` is the
    /// signed distance of the piece's start from the pole (k takes its magnitude).
    #[inline(always)]
    pub(super) fn weights(&self, s0: f32) -> [f32; 4] {
        let span = self.w1 - self.w0;
        let (mut k0, mut k1) = (0.0f32, 0.0f32);
        for (t, w) in GAUSS3 {
            let tau = self.w0 + span * t;
            let k = w * sliver_keep(s0 + t * self.len);
            k0 += k * (1.0 - tau);
            k1 += k * tau;
        }
        let mid = 0.5 * (self.w0 + self.w1);
        [
            k0 * self.len,
            k1 * self.len,
            (1.0 - mid) * self.len,
            mid * self.len,
        ]
    }

    /// The mass times g and the raw mass of a row with node values `v0`, `v1` at the piece's
    /// segment, from [`Piece::weights`].
    #[inline(always)]
    pub(super) fn masses(k: &[f32; 4], v0: f32, v1: f32) -> Sliver {
        Sliver {
            raw: v0 * k[2] + v1 * k[3],
            kept: v0 * k[0] + v1 * k[1],
        }
    }
}

/// Calls `f` on the pieces of [a, b] between the nodes of `axis` (spacing `step`), in axis
/// order, until it returns true. The pieces are found where `eval` finds them: by the axis's
/// own location of a and b ([`Axis::locate`], which the WGSL twin forms with the same
/// roundings), lengths as differences of node weights times the node spacing (no division).
#[inline(always)]
pub(super) fn pieces(axis: &Axis, step: f32, a: f32, b: f32, mut f: impl FnMut(Piece) -> bool) {
    let ((ja, wa), (jb, wb)) = (axis.locate(a), axis.locate(b));
    let mut off = 0.0;
    for j in ja..=jb {
        let w0 = if j == ja { wa } else { 0.0 };
        let w1 = if j == jb { wb } else { 1.0 };
        if w1 > w0 {
            let len = (w1 - w0) * step;
            if f(Piece {
                j,
                w0,
                w1,
                off,
                len,
            }) {
                return;
            }
            off += len;
        }
    }
}

/// The sliver [a, b] (one end at `pole`) of `G` rows on one axis: each row's raw mass and
/// mass times g (docs/model.md §10), the pieces' node weights computed once for all rows.
/// `values(j)` gives the rows' values at nodes j and j + 1. A piece where every row is 0
/// costs no weights.
#[inline(always)]
pub(super) fn sliver_masses<const G: usize>(
    axis: &Axis,
    step: f32,
    (a, b): (f32, f32),
    pole: f32,
    values: impl Fn(usize) -> ([f32; G], [f32; G]),
) -> [Sliver; G] {
    let mut out = [Sliver::default(); G];
    let at = a - pole;
    pieces(axis, step, a, b, |p| {
        let (v0, v1) = values(p.j);
        if v0.iter().chain(v1.iter()).all(|&v| v == 0.0) {
            return false;
        }
        let k = p.weights(at + p.off);
        for g in 0..G {
            let m = Piece::masses(&k, v0[g], v1[g]);
            out[g].raw += m.raw;
            out[g].kept += m.kept;
        }
        false
    });
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sampling::linear_mass;
    use crate::sampling::sliver::sliver_piece_mass;

    /// The node weights give the masses the per-row formulas give: [`sliver_piece_mass`]
    /// and [`linear_mass`] of the piece's end values.
    #[test]
    fn piece_weights_give_the_piece_masses() {
        let sc = crate::model::POLE_SLIVER;
        let cases: [(f32, f32, f32, f32, f32); 5] = [
            (0.0, 1.0, 0.0, 1.0, 0.0),
            (0.2, 0.9, 0.3, 2.0, 0.1 * sc),
            (0.5, 1.0, 5.0, 0.0, -0.4 * sc),
            (0.0, 0.35, 1.0, 1.0, -sc),
            (0.6, 0.61, 0.0, 3.0, 0.9 * sc),
        ];
        for (w0, w1, v0, v1, s0) in cases {
            let step = 0.004f32;
            let p = Piece {
                j: 0,
                w0,
                w1,
                off: 0.0,
                len: (w1 - w0) * step,
            };
            let k = p.weights(s0);
            let m = Piece::masses(&k, v0, v1);
            let (a, b) = (v0 + (v1 - v0) * w0, v0 + (v1 - v0) * w1);
            let kept = sliver_piece_mass(a, b, p.len, s0, 0.0, p.len);
            let raw = linear_mass(a, b, p.len);
            assert!(
                (m.kept - kept).abs() <= 1e-6 * kept.abs().max(1e-9),
                "{m:?} {kept}"
            );
            assert!(
                (m.raw - raw).abs() <= 1e-6 * raw.abs().max(1e-9),
                "{m:?} {raw}"
            );
        }
    }
}
