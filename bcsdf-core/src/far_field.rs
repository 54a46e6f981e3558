//! Far-field azimuthal lobes N_p(φ) = ½ ∫ A_p(h)·D_p(φ − Φ_p(h)) dh (MODEL.md §5).
//!
//! # Quadrature
//!
//! A_p and Φ_p are odd/even in h (Φ_p(−h) = −Φ_p(h), A_p(−h) = A_p(h)) and D_p is even, so
//! N_p(φ) = ½ ∫₀¹ A_p(h)·[D_p(φ − Φ_p(h)) + D_p(−φ − Φ_p(h))] dh, which makes φ → −φ
//! symmetry exact to the bit.
//!
//! [0, 1] is split where the integrand jumps: at h = κη'_c (the ray stops meeting the
//! medulla) and h = κη'_m (total internal reflection at the medulla). Each segment ends at a
//! point where exactly one of the angles a, m, μ has a square-root singularity in h, so it is
//! integrated in that angle t, with h = K·sin t (K = 1, κη'_c or κη'_m): every angle, length
//! and Fresnel factor is then smooth in t, and the Jacobian is K·cos t.
//!
//! The only remaining difficulty is that D_p is narrow (β_N can be ~1°) while Φ_p sweeps
//! up to 2π over a segment. Each segment is probed at [`PROBES`] + 1 points; on every probe
//! panel and for every path, the range Φ_p covers (the chord between the panel ends, widened
//! by a curvature bound from second differences) is compared with ±φ. A panel where no path
//! comes within D_p's reach (6.2·β_N) is skipped; otherwise it is integrated with 4-point
//! Gauss–Legendre on sub-panels each spanning at most [`SUBPANEL_BETAS`]·β_N in Φ_p, which
//! integrates a Gaussian to ~1e-6. The accuracy against a much finer reference is checked by
//! `tests/tests/far_field_accuracy.rs` and stated in `docs/accuracy.md`.

use crate::geometry::{Chord, ChordVariable, ViewSlice};
use crate::lobes::{Lobe, LOBE_COUNT};
use crate::longitudinal::GroupLobes;
use crate::math::{asin_clamped, wrap_angle, Math, PI};
use crate::spectrum::Rgb;
use crate::unscattered::{attenuations, exit_azimuths, Extinction};

/// Probe panels per segment.
pub const PROBES: usize = 12;
/// Largest Φ-span of one Gauss–Legendre sub-panel, in units of β_N.
pub const SUBPANEL_BETAS: f32 = 1.5;
/// Upper bound on sub-panels per probe panel (reached only for β_N near its minimum).
const MAX_SUBPANELS: usize = 256;

/// 4-point Gauss–Legendre nodes and weights on [−1, 1].
const GL_NODES: [f32; 4] = [
    -0.861_136_3,
    -0.339_981_04,
    0.339_981_04,
    0.861_136_3,
];
const GL_WEIGHTS: [f32; 4] = [0.347_854_85, 0.652_145_15, 0.652_145_15, 0.347_854_85];

/// Bit mask of lobes by [`Lobe::index`].
type PathMask = u16;

const fn mask(lobes: &[Lobe]) -> PathMask {
    let mut m = 0;
    let mut i = 0;
    while i < lobes.len() {
        m |= 1 << lobes[i] as usize;
        i += 1;
    }
    m
}

/// Paths that exist where the ray misses the medulla.
const MISS_PATHS: PathMask = mask(&[Lobe::R, Lobe::TT, Lobe::TRT]);
/// Paths that exist where the ray enters the medulla.
const ENTER_PATHS: PathMask = mask(&[
    Lobe::R,
    Lobe::TrT,
    Lobe::TttT,
    Lobe::TtrtT,
    Lobe::TrRrT,
    Lobe::TttRttT,
]);
/// Paths that exist under total internal reflection at the medulla.
const TIR_PATHS: PathMask = mask(&[Lobe::R, Lobe::TrT, Lobe::TrRrT]);
/// Paths that carry a medulla reflection f_m and vanish when η_m = η_c.
const MEDULLA_REFLECTION_PATHS: PathMask = mask(&[Lobe::TrT, Lobe::TtrtT, Lobe::TrRrT]);

/// One smooth piece of h ∈ [0, 1].
#[derive(Clone, Copy, Debug)]
struct Segment {
    var: ChordVariable,
    t0: f32,
    t1: f32,
    paths: PathMask,
}

/// The segments of [0, 1] for this slice, at most three.
fn segments<M: Math>(slice: &ViewSlice, index_matched: bool) -> ([Segment; 3], usize) {
    let empty = Segment {
        var: ChordVariable::A,
        t0: 0.0,
        t1: 0.0,
        paths: 0,
    };
    let mut out = [empty; 3];
    let mut n = 0;
    let t_of = |h: f32, k: f32| {
        if h >= k {
            PI / 2.0
        } else {
            asin_clamped::<M>(h / k)
        }
    };
    let h_med = slice.h_medulla();
    if slice.kappa <= 0.0 || h_med <= 0.0 {
        out[0] = Segment {
            var: ChordVariable::A,
            t0: 0.0,
            t1: PI / 2.0,
            paths: MISS_PATHS,
        };
        return (out, 1);
    }
    let strip = if index_matched {
        !MEDULLA_REFLECTION_PATHS
    } else {
        !0
    };
    let hit_end = h_med.min(1.0);
    let (end_var, end_k) = if h_med < 1.0 {
        (ChordVariable::M, h_med)
    } else {
        (ChordVariable::A, 1.0)
    };
    let h_tir = slice.h_tir();
    if h_tir < hit_end {
        out[n] = Segment {
            var: ChordVariable::Mu,
            t0: 0.0,
            t1: PI / 2.0,
            paths: ENTER_PATHS & strip,
        };
        n += 1;
        out[n] = Segment {
            var: end_var,
            t0: t_of(h_tir, end_k),
            t1: t_of(hit_end, end_k),
            paths: TIR_PATHS & strip,
        };
        n += 1;
    } else {
        out[n] = Segment {
            var: end_var,
            t0: 0.0,
            t1: t_of(hit_end, end_k),
            paths: ENTER_PATHS & strip,
        };
        n += 1;
    }
    if h_med < 1.0 {
        out[n] = Segment {
            var: ChordVariable::A,
            t0: t_of(h_med, 1.0),
            t1: PI / 2.0,
            paths: MISS_PATHS,
        };
        n += 1;
    }
    (out, n)
}

/// Everything the far-field integral needs for one θ_r.
pub struct FarFieldQuery<'a> {
    /// The cross-section slice at θ_r.
    pub slice: &'a ViewSlice,
    /// Extinction along the chord at θ_r.
    pub extinction: &'a Extinction,
    /// Cuticle layers l.
    pub layers: f32,
    /// Per-group lobe constants (D_p widths).
    pub groups: &'a GroupLobes,
    /// True when η_m = η_c (f_m ≡ 0).
    pub index_matched: bool,
}

impl FarFieldQuery<'_> {
    /// N_p(φ) for the eight unscattered paths, in [`Lobe::ALL`] order.
    pub fn azimuthal<M: Math>(&self, phi: f32) -> [Rgb; LOBE_COUNT] {
        let mut acc = [Rgb::ZERO; LOBE_COUNT];
        let (segs, n) = segments::<M>(self.slice, self.index_matched);
        for seg in &segs[..n] {
            if seg.t1 > seg.t0 {
                self.segment::<M>(seg, phi, &mut acc);
            }
        }
        acc
    }

    fn segment<M: Math>(&self, seg: &Segment, phi: f32, acc: &mut [Rgb; LOBE_COUNT]) {
        let k = match seg.var {
            ChordVariable::A => 1.0,
            ChordVariable::M => self.slice.h_medulla(),
            ChordVariable::Mu => self.slice.h_tir(),
        };
        let dt = (seg.t1 - seg.t0) / PROBES as f32;
        // Exit azimuths at the probe points.
        let mut probe = [[0.0f32; LOBE_COUNT]; PROBES + 1];
        for (j, row) in probe.iter_mut().enumerate() {
            let t = seg.t0 + dt * j as f32;
            let chord = Chord::at_variable::<M>(self.slice, seg.var, t);
            *row = exit_azimuths(&chord);
        }
        let lobes = Lobe::ALL;
        for j in 0..PROBES {
            // Which paths come within reach of ±φ on this panel, and how finely to sample.
            let mut active: PathMask = 0;
            let mut subpanels = 1usize;
            for (p, lobe) in lobes.iter().enumerate() {
                if seg.paths & (1 << p) == 0 {
                    continue;
                }
                let d = self.groups.d(lobe.group());
                let (pa, pb) = (probe[j][p], probe[j + 1][p]);
                let span = wrap_angle(pb - pa);
                let curvature = |i: usize| {
                    if i == 0 || i >= PROBES {
                        0.0
                    } else {
                        let d1 = wrap_angle(probe[i + 1][p] - probe[i][p]);
                        let d0 = wrap_angle(probe[i][p] - probe[i - 1][p]);
                        (d1 - d0).abs()
                    }
                };
                let margin = 0.25 * curvature(j).max(curvature(j + 1));
                let center = pa + 0.5 * span;
                let half = 0.5 * span.abs() + margin;
                let gap_plus = wrap_angle(phi - center).abs() - half;
                let gap_minus = wrap_angle(-phi - center).abs() - half;
                if gap_plus.min(gap_minus) < d.reach() {
                    active |= 1 << p;
                    let cover = span.abs() + 2.0 * margin;
                    let need = libm::ceilf(cover / (SUBPANEL_BETAS * d.beta())) as usize;
                    subpanels = subpanels.max(need.min(MAX_SUBPANELS));
                }
            }
            if active == 0 {
                continue;
            }
            let t_start = seg.t0 + dt * j as f32;
            let dsub = dt / subpanels as f32;
            for s in 0..subpanels {
                let mid = t_start + dsub * (s as f32 + 0.5);
                for (x, w) in GL_NODES.iter().zip(GL_WEIGHTS.iter()) {
                    let t = mid + 0.5 * dsub * x;
                    let chord = Chord::at_variable::<M>(self.slice, seg.var, t);
                    // ½ (far-field average) · dh/dt · quadrature weight.
                    let weight = 0.5 * k * M::cos(t).max(0.0) * (0.5 * dsub * w);
                    let azimuths = exit_azimuths(&chord);
                    let att = attenuations::<M>(self.slice, &chord, self.extinction, self.layers);
                    for (p, lobe) in lobes.iter().enumerate() {
                        if active & (1 << p) == 0 {
                            continue;
                        }
                        let d = self.groups.d(lobe.group());
                        let dist =
                            d.eval::<M>(phi - azimuths[p]) + d.eval::<M>(-phi - azimuths[p]);
                        acc[p] += att[p] * (weight * dist);
                    }
                }
            }
        }
    }
}
