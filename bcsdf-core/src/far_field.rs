//! Far-field azimuthal lobes N_p(φ) = ½ ∫ A_p(h)·D_p(φ − Φ_p(h)) dh (docs/model.md §5).
//!
//! The same pass can integrate the analytic sampler's density (docs/model.md §10),
//! Σ_p c_p·½ ∫ D_p(φ − Φ_p(h)) dh over the h where path p exists, with the same nodes
//! ([`FarFieldQuery::azimuthal_with_density`]).
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
//! The remaining difficulty is that D_p is narrow (β_N can be ~1°) while Φ_p sweeps up to
//! 2π over a segment. Each segment is probed at [`PROBES`] + 1 points, graded toward the
//! segment's end (where the singular angle and grazing Fresnel make A_p change fastest). On
//! every probe panel and for every path, the chord of Φ_p between the panel ends, widened by
//! a curvature bound from divided differences, tells over which part of the panel Φ_p comes
//! within D_p's reach (6.2·β_N) of ±φ. Panels out of reach of every path are skipped. Each run
//! of contiguous active panels is integrated as one piece with 6-point Gauss–Legendre
//! sub-panels, placed so that each spans at most [`SUBPANEL_BETAS`]·β_N in Φ_p for every
//! active path (a Gaussian is then integrated to ~2e-5 of its mass; 1.5 nodes per β_N) and at
//! most 1/[`MIN_DENSITY`] probe panels, 1/[`END_DENSITY`] on the last [`END_PANELS`] (which
//! resolves A_p where Φ_p is flat; this floor, not β_N, sets the node count of most queries,
//! and A_p changes fastest at a segment's end).
//!
//! A segment ending at grazing incidence (a = π/2) also has the layered cuticle's Fresnel knee
//! ([`cuticle_grazing_knee`]) there; when it is narrower than the last sub-panel (few cuticle
//! layers), that sub-panel is cut geometrically toward π/2.
//!
//! Measured against a 50× finer reference (`tests/tests/suite/far_field_accuracy.rs`): worst
//! relative error 5.0e-5 over the presets, 2.9e-5 over its 96 random parameter sets and 6.9e-5
//! over three pinned sets from an 800-set scan, against the 1e-4 budget (`docs/accuracy.md`).

use crate::fresnel::cuticle_grazing_knee;
use crate::geometry::{Chord, ChordVariable, Region, ViewSlice};
use crate::lobes::{Lobe, UNSCATTERED_COUNT};
use crate::longitudinal::GroupLobes;
use crate::math::{asin_clamped, Math, PI};
use crate::medulla::MedullaProfiles;
use crate::scattered::{azimuthal_on_row, exit_transmittance, scattered_paths, SCATTERED_COUNT};
use crate::spectrum::Rgb;
use crate::unscattered::{attenuations, exit_azimuths, Extinction};

mod probes;
use probes::{window, Panel, Probes};

/// Probe panels per segment.
pub const PROBES: usize = 12;
/// Largest Φ-span of one Gauss–Legendre sub-panel, in units of β_N.
pub const SUBPANEL_BETAS: f32 = 4.0;
/// Upper bound on sub-panels per run of probe panels (reached only for β_N near its minimum).
const MAX_SUBPANELS: usize = 1024;
/// Fewest Gauss–Legendre sub-panels per probe panel: resolves A_p and the Jacobian where
/// Φ_p is flat.
pub const MIN_DENSITY: f32 = 0.25;
/// [`MIN_DENSITY`] on the last [`END_PANELS`] probe panels of a segment, where its singular
/// angle and grazing Fresnel (or f_m near total internal reflection) make A_p change fastest.
pub const END_DENSITY: f32 = 0.5;
/// Probe panels at a segment's end that get [`END_DENSITY`].
pub const END_PANELS: usize = 3;

/// 6-point Gauss–Legendre nodes and weights on [−1, 1].
pub(crate) const GL_NODES: [f32; 6] = [
    -0.932_469_5,
    -0.661_209_4,
    -0.238_619_2,
    0.238_619_2,
    0.661_209_4,
    0.932_469_5,
];
pub(crate) const GL_WEIGHTS: [f32; 6] = [
    0.171_324_49,
    0.360_761_57,
    0.467_913_93,
    0.467_913_93,
    0.360_761_57,
    0.171_324_49,
];

/// Most panel bounds of the scattered far-field rule.
const MAX_SCATTER_BOUNDS: usize = 72;

/// Gauss–Legendre nodes per panel of the scattered far-field rule (2 points).
const SCATTER_NODES: [f32; 2] = [-0.577_350_26, 0.577_350_26];
const SCATTER_WEIGHTS: [f32; 2] = [1.0, 1.0];

/// Smallest knee width (in a, radians) the end refinement resolves: below it the pieces
/// would be lost to f32 rounding near π/2, and their Jacobian cos a makes them negligible.
const MIN_KNEE: f32 = 2e-5;

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

/// One smooth piece of h ∈ [0, 1]: h = K·sin t for t ∈ [t0, t1] (K from [`segment_scale`]).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Segment {
    pub(crate) var: ChordVariable,
    pub(crate) t0: f32,
    pub(crate) t1: f32,
    /// Bit p set: unscattered path p ([`Lobe::index`]) exists on this segment.
    pub(crate) paths: PathMask,
    pub(crate) region: Region,
}

/// The segments of [0, 1] for this slice, at most three.
pub(crate) fn segments<M: Math>(slice: &ViewSlice, index_matched: bool) -> ([Segment; 3], usize) {
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
    /// N_p(φ) for the eight unscattered paths, in [`Lobe::UNSCATTERED`] order.
    #[must_use]
    pub fn azimuthal<M: Math>(&self, phi: f32) -> [Rgb; UNSCATTERED_COUNT] {
        self.azimuthal_with_density::<M>(phi, &[0.0; UNSCATTERED_COUNT])
            .0
    }

    /// N_p(φ) as [`FarFieldQuery::azimuthal`], and with the same nodes
    /// Σ_p c_p·½ ∫ [D_p(φ − Φ_p(h)) + D_p(−φ − Φ_p(h))] dh over h ∈ [0, 1] where path p exists
    /// (the analytic sampler's density, docs/model.md §10), for `coeffs` c_p.
    #[must_use]
    pub fn azimuthal_with_density<M: Math>(
        &self,
        phi: f32,
        coeffs: &[f32; UNSCATTERED_COUNT],
    ) -> ([Rgb; UNSCATTERED_COUNT], f32) {
        let mut acc = Accumulator {
            value: [Rgb::ZERO; UNSCATTERED_COUNT],
            density: 0.0,
            coeffs,
        };
        let (segs, n) = segments::<M>(self.slice, self.index_matched);
        for seg in &segs[..n] {
            if seg.t1 > seg.t0 {
                self.segment::<M>(seg, phi, &mut acc);
            }
        }
        (acc.value, acc.density)
    }

    /// Far-field N^s_p(φ) of the three scattered lobes, ½ ∫ N^s_p(h, φ) dh over the part of h
    /// that enters the medulla, folded onto h ≥ 0 like the unscattered lobes. C^N is broad
    /// but tabulated with linear interpolation, so the integrand is smooth between the h where
    /// h_m crosses a table node: panels end there (and at graded points toward the segment
    /// end), each integrated with 2-point Gauss–Legendre in the segment's smooth variable.
    /// Measured against a fine reference: ≤ 1.2e-3 relative (docs/accuracy.md), below the
    /// tables' own Monte Carlo noise.
    #[must_use]
    pub fn azimuthal_scattered<M: Math>(
        &self,
        profiles: &MedullaProfiles<'_>,
        sigma_n: f32,
        phi: f32,
    ) -> [Rgb; SCATTERED_COUNT] {
        self.azimuthal_scattered_with_density::<M>(profiles, sigma_n, phi, &[0.0; SCATTERED_COUNT])
            .0
    }

    /// N^s_p(φ) as [`FarFieldQuery::azimuthal_scattered`], and with the same nodes
    /// Σ_k c_k·½ ∫ [C^N(φ − π − Φ^s_k) + C^N(−φ − π − Φ^s_k)]/‖C^N row‖ dh over the h that
    /// enter the medulla (the analytic sampler's density, docs/model.md §10).
    #[must_use]
    pub fn azimuthal_scattered_with_density<M: Math>(
        &self,
        profiles: &MedullaProfiles<'_>,
        sigma_n: f32,
        phi: f32,
        coeffs: &[f32; SCATTERED_COUNT],
    ) -> ([Rgb; SCATTERED_COUNT], f32) {
        let mut acc = [Rgb::ZERO; SCATTERED_COUNT];
        let mut density = 0.0;
        let want_density = coeffs.iter().any(|c| *c > 0.0);
        let (segs, n) = segments::<M>(self.slice, false);
        let Some(seg) = segs[..n].iter().find(|s| s.region == Region::Enter) else {
            return (acc, density);
        };
        let k = segment_scale(self.slice, seg.var);
        let exit = exit_transmittance::<M>(self.slice, self.extinction);
        // Panels end where h_m = h/(κη'_m) crosses a node of the C^N table (the tables are
        // interpolated linearly in h_m, so the integrand has kinks exactly there), and at
        // graded points toward the segment end, where grazing Fresnel changes fastest.
        let n_h = profiles.layout().res.n_h.min(MAX_SCATTER_BOUNDS - 8);
        let h_tir = self.slice.h_tir();
        let mut bounds = [0.0f32; MAX_SCATTER_BOUNDS];
        let mut n_b = 0;
        let span = seg.t1 - seg.t0;
        for frac in [0.0, 0.75, 0.9, 0.96, 0.99, 1.0] {
            bounds[n_b] = seg.t0 + span * frac;
            n_b += 1;
        }
        for j in 1..n_h {
            let h = h_tir * j as f32 / n_h as f32;
            if h < k {
                let t = asin_clamped::<M>(h / k);
                if t > seg.t0 && t < seg.t1 {
                    bounds[n_b] = t;
                    n_b += 1;
                }
            }
        }
        let bounds = &mut bounds[..n_b];
        bounds.sort_unstable_by(|x, y| x.total_cmp(y));
        for pair in bounds.windows(2) {
            let (ta, tb) = (pair[0], pair[1]);
            if tb - ta <= 1e-6 * span {
                continue;
            }
            let (mid, half) = (0.5 * (ta + tb), 0.5 * (tb - ta));
            for (x, w) in SCATTER_NODES.iter().zip(SCATTER_WEIGHTS.iter()) {
                let t = mid + half * x;
                let chord = Chord::at_variable::<M>(self.slice, seg.var, t, seg.region);
                let Some(paths) =
                    scattered_paths::<M>(self.slice, &chord, self.extinction, self.layers, exit)
                else {
                    continue;
                };
                let weight = 0.5 * k * chord.variable_cos(seg.var) * (half * w);
                let row = profiles.n_row(sigma_n, paths.h_m);
                let plus = azimuthal_on_row(profiles, &row, &paths, phi);
                let minus = azimuthal_on_row(profiles, &row, &paths, -phi);
                for ((a, p), m) in acc.iter_mut().zip(plus).zip(minus) {
                    *a += (p + m) * weight;
                }
                if want_density {
                    let mass = profiles.row_mass(&row);
                    if mass > 0.0 {
                        for (c, rot) in coeffs.iter().zip(paths.rotation) {
                            if *c > 0.0 {
                                let d = profiles.cn_at(&row, phi - PI - rot)
                                    + profiles.cn_at(&row, -phi - PI - rot);
                                density += c * weight * d / mass;
                            }
                        }
                    }
                }
            }
        }
        (acc, density)
    }

    fn segment<M: Math>(&self, seg: &Segment, phi: f32, acc: &mut Accumulator<'_>) {
        let k = segment_scale(self.slice, seg.var);
        let probes = Probes::new::<M>(self.slice, seg);
        // Pass 1: which paths come within reach of ±φ on each probe panel, over which part
        // of it (s ∈ [0, 1] along the panel), and how densely that part must be sampled.
        let mut panels = [Panel::default(); PROBES];
        for (j, panel) in panels.iter_mut().enumerate() {
            *panel = self.screen(seg, &probes, j, phi);
        }
        // Pass 2: integrate each run of contiguous active panels as one piece, so that a
        // window spread over several probe panels is not rounded up panel by panel.
        let mut j = 0;
        while j < PROBES {
            if panels[j].active == 0 {
                j += 1;
                continue;
            }
            let mut end = j;
            while end + 1 < PROBES
                && panels[end + 1].active != 0
                && panels[end].hi >= 1.0
                && panels[end + 1].lo <= 0.0
            {
                end += 1;
            }
            let run = Run {
                seg,
                k,
                bounds: &probes.bounds[j..=end + 1],
                panels: &panels[j..=end],
                phi,
            };
            self.run::<M>(&run, acc);
            j = end + 1;
        }
    }

    /// Screens probe panel `j` of `seg` for the targets ±φ.
    fn screen(&self, seg: &Segment, probes: &Probes, j: usize, phi: f32) -> Panel {
        let mut out = Panel {
            active: 0,
            lo: 1.0,
            hi: 0.0,
            density: 0.0,
            floor: if j + END_PANELS >= PROBES {
                END_DENSITY
            } else {
                MIN_DENSITY
            },
        };
        for p in 0..UNSCATTERED_COUNT {
            if seg.paths & (1 << p) == 0 {
                continue;
            }
            let d = self.groups.d(Lobe::unscattered_group(p));
            let (pa, span, margin) = (probes.phi[j][p], probes.span[j][p], probes.margin[j][p]);
            let reach = d.reach() + margin;
            let mut hit = false;
            for target in [phi, -phi] {
                if let Some((lo, hi)) = window(pa, span, target, reach) {
                    hit = true;
                    out.lo = out.lo.min(lo);
                    out.hi = out.hi.max(hi);
                }
            }
            if hit {
                out.active |= 1 << p;
                let cover = span.abs() + 2.0 * margin;
                out.density = out.density.max(cover / (SUBPANEL_BETAS * d.beta()));
            }
        }
        if out.hi <= out.lo {
            out.active = 0;
        }
        out
    }

    /// Integrates a run of contiguous active panels with Gauss–Legendre sub-panels placed at
    /// equal increments of required work.
    fn run<M: Math>(&self, r: &Run<'_>, acc: &mut Accumulator<'_>) {
        let (seg, bounds, run) = (r.seg, r.bounds, r.panels);
        // Work of each panel: sub-panels it needs (at least its floor, MIN_DENSITY or
        // END_DENSITY per probe panel, so that A_p and the Jacobian are resolved even where
        // Φ_p is flat).
        let work = |p: &Panel| p.density.max(p.floor) * (p.hi - p.lo);
        let total: f32 = run.iter().map(work).sum();
        let n = (libm::ceilf(total).max(1.0) as usize).min(MAX_SUBPANELS);
        // t at cumulative work u, walking the panels in order.
        let t_at = |u: f32| -> f32 {
            let mut left = u;
            for (i, p) in run.iter().enumerate() {
                let w = work(p);
                if left <= w || i + 1 == run.len() {
                    let frac = if w > 0.0 {
                        (left / w).clamp(0.0, 1.0)
                    } else {
                        1.0
                    };
                    let s = p.lo + frac * (p.hi - p.lo);
                    return bounds[i] + s * (bounds[i + 1] - bounds[i]);
                }
                left -= w;
            }
            bounds[run.len()]
        };
        // The layered cuticle's knee (f turning toward 1 at grazing incidence, at cos a ≈
        // `knee`) sits within the last sub-panel of a segment ending at a = π/2 when the
        // cuticle has few layers: that sub-panel is then cut at π/2 − knee·4^j, j = 0, 1, …
        // (6-point Gauss–Legendre converges fast on each piece, whose distance to the knee's
        // pole at −knee is at least its half-width).
        let ends_grazing =
            seg.var == ChordVariable::A && seg.t1 >= PI / 2.0 && bounds[run.len()] >= seg.t1;
        let knee = if ends_grazing {
            cuticle_grazing_knee::<M>(self.slice.eta_c_prime, self.layers).max(MIN_KNEE)
        } else {
            0.0
        };
        let mut ta = t_at(0.0);
        for q in 0..n {
            let tb = t_at(total * (q + 1) as f32 / n as f32);
            if q + 1 == n && knee > 0.0 && 2.0 * knee < tb - ta {
                let mut cut = knee;
                while 4.0 * cut < tb - ta {
                    cut *= 4.0;
                }
                let mut from = ta;
                while cut >= knee {
                    self.gauss_panel::<M>(r, from, seg.t1 - cut, acc);
                    from = seg.t1 - cut;
                    cut *= 0.25;
                }
                self.gauss_panel::<M>(r, from, tb, acc);
            } else {
                self.gauss_panel::<M>(r, ta, tb, acc);
            }
            ta = tb;
        }
    }

    /// One 6-point Gauss–Legendre sub-panel [ta, tb] of a run (see [`Self::run`]).
    fn gauss_panel<M: Math>(&self, r: &Run<'_>, ta: f32, tb: f32, acc: &mut Accumulator<'_>) {
        let (seg, k, bounds, run, phi) = (r.seg, r.k, r.bounds, r.panels, r.phi);
        let (mid, half) = (0.5 * (ta + tb), 0.5 * (tb - ta));
        for (x, w) in GL_NODES.iter().zip(GL_WEIGHTS.iter()) {
            let t = mid + half * x;
            let panel = bounds[1..run.len()].iter().take_while(|&&b| b <= t).count();
            let active = run[panel].active;
            let chord = Chord::at_variable::<M>(self.slice, seg.var, t, seg.region);
            // ½ (far-field average) · dh/dt = K cos t · quadrature weight.
            let weight = 0.5 * k * chord.variable_cos(seg.var) * (half * w);
            let azimuths = exit_azimuths(&chord);
            let att = attenuations::<M>(self.slice, &chord, self.extinction, self.layers);
            for p in 0..UNSCATTERED_COUNT {
                if active & (1 << p) == 0 {
                    continue;
                }
                let d = self.groups.d(Lobe::unscattered_group(p));
                let dist = d.eval::<M>(phi - azimuths[p]) + d.eval::<M>(-phi - azimuths[p]);
                acc.value[p] += att[p] * (weight * dist);
                acc.density += acc.coeffs[p] * (weight * dist);
            }
        }
    }
}

/// A run of contiguous active probe panels of one segment, at one φ.
struct Run<'r> {
    seg: &'r Segment,
    /// K in h = K·sin t.
    k: f32,
    /// Probe bounds of the run: one more than panels.
    bounds: &'r [f32],
    panels: &'r [Panel],
    phi: f32,
}

/// What one far-field pass accumulates: N_p per path, and the sampling density.
struct Accumulator<'c> {
    value: [Rgb; UNSCATTERED_COUNT],
    density: f32,
    coeffs: &'c [f32; UNSCATTERED_COUNT],
}

/// K in h = K·sin t for the segment variable.
pub(crate) fn segment_scale(slice: &ViewSlice, var: ChordVariable) -> f32 {
    match var {
        ChordVariable::A => 1.0,
        ChordVariable::M => slice.h_medulla(),
        ChordVariable::Mu => slice.h_tir(),
    }
}
