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
//! comes within D_p's reach (6.2·β_N) is skipped; otherwise it is integrated with 6-point
//! Gauss–Legendre on sub-panels each spanning at most [`SUBPANEL_BETAS`]·β_N in Φ_p, which
//! integrates a Gaussian to ~6e-7 (2 nodes per β_N). The accuracy against a much finer reference is checked by
//! `tests/tests/far_field_accuracy.rs` and stated in `docs/accuracy.md`.

use crate::geometry::{Chord, ChordVariable, Region, ViewSlice};
use crate::lobes::{Lobe, LOBE_COUNT};
use crate::longitudinal::GroupLobes;
use crate::math::{asin_clamped, wrap_angle, Math, PI};
use crate::spectrum::Rgb;
use crate::unscattered::{attenuations, exit_azimuths, Extinction};

/// Probe panels per segment.
pub const PROBES: usize = 12;
/// Largest Φ-span of one Gauss–Legendre sub-panel, in units of β_N.
pub const SUBPANEL_BETAS: f32 = 4.0;
/// Upper bound on sub-panels per probe panel (reached only for β_N near its minimum).
const MAX_SUBPANELS: usize = 256;

/// 6-point Gauss–Legendre nodes and weights on [−1, 1].
const GL_NODES: [f32; 6] = [
    -0.932_469_5,
    -0.661_209_4,
    -0.238_619_19,
    0.238_619_19,
    0.661_209_4,
    0.932_469_5,
];
const GL_WEIGHTS: [f32; 6] = [
    0.171_324_49,
    0.360_761_57,
    0.467_913_93,
    0.467_913_93,
    0.360_761_57,
    0.171_324_49,
];

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
    region: Region,
}

/// The segments of [0, 1] for this slice, at most three.
fn segments<M: Math>(slice: &ViewSlice, index_matched: bool) -> ([Segment; 3], usize) {
    let empty = Segment {
        var: ChordVariable::A,
        t0: 0.0,
        t1: 0.0,
        paths: 0,
        region: Region::Miss,
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
            region: Region::Miss,
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
            region: Region::Enter,
        };
        n += 1;
        out[n] = Segment {
            var: end_var,
            t0: t_of(h_tir, end_k),
            t1: t_of(hit_end, end_k),
            paths: TIR_PATHS & strip,
            region: Region::TotalReflection,
        };
        n += 1;
    } else {
        out[n] = Segment {
            var: end_var,
            t0: 0.0,
            t1: t_of(hit_end, end_k),
            paths: ENTER_PATHS & strip,
            region: Region::Enter,
        };
        n += 1;
    }
    if h_med < 1.0 {
        out[n] = Segment {
            var: ChordVariable::A,
            t0: t_of(h_med, 1.0),
            t1: PI / 2.0,
            paths: MISS_PATHS,
            region: Region::Miss,
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
            let chord = Chord::at_variable::<M>(self.slice, seg.var, t, seg.region);
            *row = exit_azimuths(&chord);
        }
        let lobes = Lobe::ALL;
        for j in 0..PROBES {
            // Which paths come within reach of ±φ on this panel, over which part of it
            // (s ∈ [0, 1] along the panel), and how densely that part must be sampled.
            let mut active: PathMask = 0;
            let (mut s_lo, mut s_hi) = (1.0f32, 0.0f32);
            let mut density = 0.0f32; // sub-panels per unit s
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
                // The chord of Φ over the panel is within Δ²Φ/8 of Φ; twice that is the margin.
                let margin = 0.25 * curvature(j).max(curvature(j + 1));
                let reach = d.reach() + margin;
                let mut hit = false;
                for target in [phi, -phi] {
                    let Some((lo, hi)) = window(pa, span, target, reach) else {
                        continue;
                    };
                    hit = true;
                    s_lo = s_lo.min(lo);
                    s_hi = s_hi.max(hi);
                }
                if hit {
                    active |= 1 << p;
                    let cover = span.abs() + 2.0 * margin;
                    density = density.max(cover / (SUBPANEL_BETAS * d.beta()));
                }
            }
            if active == 0 || s_hi <= s_lo {
                continue;
            }
            let need = libm::ceilf(density * (s_hi - s_lo)).max(1.0) as usize;
            let subpanels = need.min(MAX_SUBPANELS);
            let t_start = seg.t0 + dt * (j as f32 + s_lo);
            let dsub = dt * (s_hi - s_lo) / subpanels as f32;
            for s in 0..subpanels {
                let mid = t_start + dsub * (s as f32 + 0.5);
                for (x, w) in GL_NODES.iter().zip(GL_WEIGHTS.iter()) {
                    let t = mid + 0.5 * dsub * x;
                    let chord = Chord::at_variable::<M>(self.slice, seg.var, t, seg.region);
                    // ½ (far-field average) · dh/dt = K cos t · quadrature weight.
                    let weight = 0.5 * k * chord.variable_cos(seg.var) * (0.5 * dsub * w);
                    let azimuths = exit_azimuths(&chord);
                    let att = attenuations::<M>(self.slice, &chord, self.extinction, self.layers);
                    for (p, lobe) in lobes.iter().enumerate() {
                        if active & (1 << p) == 0 {
                            continue;
                        }
                        let d = self.groups.d(lobe.group());
                        let dist = d.eval::<M>(phi - azimuths[p]) + d.eval::<M>(-phi - azimuths[p]);
                        acc[p] += att[p] * (weight * dist);
                    }
                }
            }
        }
    }
}

/// The part `[s_lo, s_hi]` ⊂ [0, 1] of a panel on which Φ(s) = pa + span·s comes within
/// `reach` of `target` (mod 2π); `None` when it never does. Wide reaches take the whole panel.
fn window(pa: f32, span: f32, target: f32, reach: f32) -> Option<(f32, f32)> {
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
