//! The far field's probes (docs/model.md §5): Φ_p at graded points of a segment, the part of
//! each probe panel within a lobe's reach of ±φ, and what a panel needs from the quadrature.

use super::{Segment, PROBES};
use crate::geometry::{Chord, ViewSlice};
use crate::lobes::UNSCATTERED_COUNT;
use crate::math::{wrap_angle, Math, PI};
use crate::unscattered::exit_azimuths;

/// Exit azimuths at a segment's probe points, with per-panel spans and curvature margins.
pub(super) struct Probes {
    /// Probe points t_j, graded toward the segment's end.
    pub(super) bounds: [f32; PROBES + 1],
    /// Φ_p(t_j).
    pub(super) phi: [[f32; UNSCATTERED_COUNT]; PROBES + 1],
    /// Φ_p(t_{j+1}) − Φ_p(t_j), wrapped: the chord of Φ_p over panel j.
    pub(super) span: [[f32; UNSCATTERED_COUNT]; PROBES],
    /// How far Φ_p may stray from that chord inside panel j (twice |Φ''|Δ²/8).
    pub(super) margin: [[f32; UNSCATTERED_COUNT]; PROBES],
}

impl Probes {
    pub(super) fn new<M: Math>(slice: &ViewSlice, seg: &Segment) -> Probes {
        let mut pr = Probes {
            bounds: [0.0; PROBES + 1],
            phi: [[0.0; UNSCATTERED_COUNT]; PROBES + 1],
            span: [[0.0; UNSCATTERED_COUNT]; PROBES],
            margin: [[0.0; UNSCATTERED_COUNT]; PROBES],
        };
        // t_j = t0 + (t1 − t0)(1 − (1 − j/P)²): denser toward the segment's end, where its
        // singular angle and grazing Fresnel make A_p change fastest.
        for j in 0..=PROBES {
            let x = 1.0 - j as f32 / PROBES as f32;
            let t = if j == PROBES {
                seg.t1
            } else {
                seg.t0 + (seg.t1 - seg.t0) * (1.0 - x * x)
            };
            pr.bounds[j] = t;
            pr.phi[j] = exit_azimuths(&Chord::at_variable::<M>(slice, seg.var, t, seg.region));
        }
        for j in 0..PROBES {
            let (a, b) = (pr.phi[j], pr.phi[j + 1]);
            for (span, (pa, pb)) in pr.span[j].iter_mut().zip(a.iter().zip(b.iter())) {
                *span = wrap_angle(pb - pa);
            }
        }
        // |Φ''| at interior probe i from divided differences (taken as 0 at the ends).
        let mut curv = [[0.0f32; UNSCATTERED_COUNT]; PROBES + 1];
        for (i, row) in curv.iter_mut().enumerate().take(PROBES).skip(1) {
            let (w0, w1) = (
                pr.bounds[i] - pr.bounds[i - 1],
                pr.bounds[i + 1] - pr.bounds[i],
            );
            let (s0, s1) = (pr.span[i - 1], pr.span[i]);
            for (c, (d0, d1)) in row.iter_mut().zip(s0.iter().zip(s1.iter())) {
                *c = 2.0 * (d1 / w1 - d0 / w0).abs() / (w0 + w1);
            }
        }
        for j in 0..PROBES {
            let w = pr.bounds[j + 1] - pr.bounds[j];
            for (p, m) in pr.margin[j].iter_mut().enumerate() {
                *m = 0.25 * curv[j][p].max(curv[j + 1][p]) * w * w;
            }
        }
        pr
    }
}

/// Screening result of one probe panel.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct Panel {
    /// Paths within reach of ±φ somewhere on the panel.
    pub(super) active: super::PathMask,
    /// Part of the panel to integrate, s ∈ [lo, hi] ⊂ [0, 1].
    pub(super) lo: f32,
    pub(super) hi: f32,
    /// Sub-panels needed per unit s.
    pub(super) density: f32,
    /// Fewest sub-panels per unit s ([`MIN_DENSITY`] or [`END_DENSITY`]).
    pub(super) floor: f32,
}

/// The part `[s_lo, s_hi]` ⊂ [0, 1] of a panel on which Φ(s) = pa + span·s comes within
/// `reach` of `target` (mod 2π); `None` when it never does. Wide reaches take the whole panel.
pub(super) fn window(pa: f32, span: f32, target: f32, reach: f32) -> Option<(f32, f32)> {
    let center = pa + 0.5 * span;
    let offset = wrap_angle(target - center);
    let half = 0.5 * span.abs();
    if offset.abs() - half >= reach {
        return None;
    }
    if reach + half >= PI || half < 1e-6 {
        return Some((0.0, 1.0));
    }
    // Nearest representative of the target, relative to the panel start, in units of span.
    let rel = 0.5 * span + offset;
    let (a, b) = ((rel - reach) / span, (rel + reach) / span);
    let (lo, hi) = if a < b { (a, b) } else { (b, a) };
    Some((lo.max(0.0), hi.min(1.0)))
}
