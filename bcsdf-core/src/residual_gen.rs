//! Generation of the energy closure's residual table (docs/model.md §12, "Residual"): per θ_r
//! node and offset h, the cross-section simulation ([`crate::residual::sim`]) against the energy
//! the model's own lobes carry (E_model, from a [`FurBcsdf`] without a residual), written in the
//! layout of [`ResidualLayout`]. It sits above `model` (it calls the model), while the table's
//! lookups ([`crate::residual::ResidualTable`]) sit below it.

use crate::far_field::{segment_scale, segments, GL_NODES, GL_WEIGHTS};
use crate::frame::Angles;
use crate::geometry::{Chord, ViewSlice};
use crate::longitudinal::inv_cos2_theta_i;
use crate::math::{Libm, Math, PI, TAU};
use crate::medulla::ProfileError;
use crate::model::FurBcsdf;
use crate::params::FurParams;
use crate::residual::sim::{simulate_cells, CellTally, Section};
use crate::residual::{ResidualLayout, MEAN_SUBDIVISION};
use crate::rng::{cell_stream, Pcg32};
use crate::scattered::{azimuthal_on_row, exit_transmittance, scattered_paths};
use crate::spectrum::Rgb;
use crate::unscattered::{attenuations, Extinction};

/// Table id of the residual cells for [`cell_stream`] (C^N is 1, C^M 2).
const TABLE_RESIDUAL: u64 = 3;

/// θ_i midpoints of the ∫ M^s_x dθ_i integrals.
const MS_SAMPLES: usize = 1024;

/// φ midpoints per C^N bin of the ψ-integrals of the scattered lobes' energy.
const PSI_SUBSAMPLES: usize = 4;

/// 6-point Gauss–Legendre panels per smooth piece of h ∈ [0, 1] in the h-means of E_model
/// that the row's ⟨A_res⟩_h is made to complete (`ModelEnergy::mean`).
const MEAN_PANELS: usize = 16;

/// What one θ_r row's simulation found, h-means (midpoint rule) per channel, for the
/// numbers docs/model.md §12 reports.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RowStats {
    /// ⟨E_sim⟩_h: all energy leaving the fiber.
    pub exiting: [f64; 3],
    /// ⟨E_model⟩_h: the energy the model's lobes carry (the far field's h-mean, integrated
    /// piece by piece between the jumps of E_model(h), not the offsets' midpoint rule).
    pub model: [f64; 3],
    /// ⟨max(0, E_model − E_sim)⟩_h: what the scattered lobes carry beyond the simulation
    /// (removed by their scale factor).
    pub excess: [f64; 3],
    /// ⟨A_res⟩_h as stored: ⟨max(0, E_sim − E_model)⟩_h over the offsets, completed so that
    /// the far field's lobes, scale and residual carry ⟨E_sim⟩_h (see [`generate_row`]).
    pub residual: [f64; 3],
    /// ⟨classified unmodelled energy⟩_h; its gap to E_sim − E_model is the scattered lobes'
    /// approximation (F_t's radial exit against the actual one).
    pub unmodelled: [f64; 3],
    /// ⟨energy dropped by the cutoffs⟩_h.
    pub dropped: [f64; 3],
    /// Largest dropped energy of one cell (largest channel).
    pub dropped_max: f64,
    /// Beams processed.
    pub beams: u64,
    /// Photons walked.
    pub photons: u64,
}

/// The section of the simulation at `theta_r` for `params`.
pub(crate) fn section(params: &FurParams, theta_r: f32) -> Section {
    let slice = crate::geometry::ViewSlice::new::<Libm>(params, theta_r);
    Section {
        slice,
        ext: crate::unscattered::Extinction::new(params, &slice),
        medulla_absorption: params.sigma_ma() * slice.inv_cos_tm,
        layers: params.l(),
        g: params.g(),
    }
}

/// Simulates θ_r row `row` of `layout` for `model` (whose lobes give E_model) into `out`
/// ([`ResidualLayout::row_len`] values). Nothing is written when the layout is invalid or
/// `out` has the wrong length.
pub fn generate_row<M: Math>(
    model: &FurBcsdf<'_, M>,
    layout: &ResidualLayout,
    row: usize,
    seed: u64,
    out: &mut [f32],
) -> RowStats {
    if layout.validate().is_err() || row >= layout.n_theta || out.len() != layout.row_len() {
        return RowStats::default();
    }
    simulate_row(model, layout, layout.theta_node(row), row as u64, seed, out)
}

/// The row of [`generate_row`] at any view angle `theta_r` (its cells on their own streams,
/// distinct from the table's): for measuring the residual between nodes (docs/model.md §12).
/// Nothing is written when the layout is invalid or `out` has the wrong length.
pub fn simulate_view<M: Math>(
    model: &FurBcsdf<'_, M>,
    layout: &ResidualLayout,
    theta_r: f32,
    seed: u64,
    out: &mut [f32],
) -> RowStats {
    if layout.validate().is_err() || out.len() != layout.row_len() || !theta_r.is_finite() {
        return RowStats::default();
    }
    let id = (1u64 << 40) | u64::from(theta_r.to_bits());
    simulate_row(model, layout, theta_r, id, seed, out)
}

fn simulate_row<M: Math>(
    model: &FurBcsdf<'_, M>,
    layout: &ResidualLayout,
    theta_r: f32,
    row: u64,
    seed: u64,
    out: &mut [f32],
) -> RowStats {
    let mut hist = [[0.0f64; 3]; 4096];
    let [stats] = simulate_rows(
        &[model],
        layout,
        theta_r,
        row,
        seed,
        [out],
        &mut hist[..layout.n_phi],
    );
    stats
}

/// Row `row` of `layout` for `P` models at once, one walk for all ([`simulate_cells`]):
/// model k's row goes to `out[k]` ([`ResidualLayout::row_len`] values each), bit for bit what
/// [`generate_row`] writes for it alone. The models must differ in σ_ca only (the colours of
/// a LUT's absorption planes: [`FurParams::same_but_absorption`]); `hist` is scratch of at
/// least `P·n_phi` bins. Nothing is written (and the statistics are zero) when the layout is
/// invalid, the row is out of range, an `out` has the wrong length, `hist` is too short or
/// the models differ in more than σ_ca. What a bake's absorption planes are generated with:
/// the photon walks' geometry is computed once for all `P` colours.
pub fn generate_rows<M: Math, const P: usize>(
    models: &[&FurBcsdf<'_, M>; P],
    layout: &ResidualLayout,
    row: usize,
    seed: u64,
    out: [&mut [f32]; P],
    hist: &mut [[f64; 3]],
) -> [RowStats; P] {
    let n_phi = layout.n_phi;
    let fits = layout.validate().is_ok()
        && row < layout.n_theta
        && out.iter().all(|o| o.len() == layout.row_len())
        && hist.len() >= P * n_phi
        && models
            .iter()
            .all(|m| m.params().same_but_absorption(models[0].params()));
    if !fits {
        return [RowStats::default(); P];
    }
    simulate_rows(
        models,
        layout,
        layout.theta_node(row),
        row as u64,
        seed,
        out,
        &mut hist[..P * n_phi],
    )
}

/// The rows of `models` (differing in σ_ca only) at `theta_r`, cell streams of row id `row`,
/// into `out`, with `hist` (`P·n_phi` bins) as the colours' histograms.
fn simulate_rows<M: Math, const P: usize>(
    models: &[&FurBcsdf<'_, M>; P],
    layout: &ResidualLayout,
    theta_r: f32,
    row: u64,
    seed: u64,
    mut out: [&mut [f32]; P],
    hist: &mut [[f64; 3]],
) -> [RowStats; P] {
    let sec = section(models[0].params(), theta_r);
    let cortex: [Rgb; P] =
        core::array::from_fn(|k| section(models[k].params(), theta_r).ext.cortex);
    let mut rows: [RowAcc<'_, '_, M>; P] =
        core::array::from_fn(|k| RowAcc::new(models[k], theta_r));
    hist.fill([0.0; 3]);
    let n_h = layout.n_h;
    for j in 0..n_h {
        let h = layout.h_node(j);
        let stream = cell_stream(seed, TABLE_RESIDUAL, row * n_h as u64 + j as u64);
        let mut rng = Pcg32::new(stream, stream.rotate_left(17));
        let tallies = simulate_cells(
            &sec,
            &cortex,
            h,
            layout.photons,
            &mut rng,
            hist,
            layout.n_phi,
        );
        for ((acc, t), o) in rows.iter_mut().zip(&tallies).zip(out.iter_mut()) {
            acc.cell(layout, j, t, o);
        }
    }
    let n = layout.n_phi;
    core::array::from_fn(|k| rows[k].finish(layout, &hist[k * n..(k + 1) * n], &mut *out[k]))
}

/// One colour's row in the making ([`simulate_rows`]): its model's E_model per offset and
/// the h-means of the offsets' energies.
struct RowAcc<'m, 'a, M: Math> {
    energies: ModelEnergy<'m, 'a, M>,
    stats: RowStats,
    scattered_mean: [f64; 3],
    excess_mean: [f64; 3],
    unscattered_mean: [f64; 3],
    lossless_mean: [f64; 3],
}

impl<'m, 'a, M: Math> RowAcc<'m, 'a, M> {
    fn new(model: &'m FurBcsdf<'a, M>, theta_r: f32) -> Self {
        RowAcc {
            energies: ModelEnergy::new(model, theta_r),
            stats: RowStats::default(),
            scattered_mean: [0.0; 3],
            excess_mean: [0.0; 3],
            unscattered_mean: [0.0; 3],
            lossless_mean: [0.0; 3],
        }
    }

    /// Offset `j`'s cell: the simulation's tally `t` against E_model, written into `out`.
    fn cell(&mut self, layout: &ResidualLayout, j: usize, t: &CellTally, out: &mut [f32]) {
        let h = layout.h_node(j);
        let scale_at = layout.scale_offset();
        let inv_n = 1.0 / layout.n_h as f64;
        let stats = &mut self.stats;
        let (e_unscattered, e_scattered) = self.energies.at(h);
        let e_lossless = self.energies.lossless_at(h);
        let mut cell_drop = 0.0f64;
        for c in 0..3 {
            let (eu, es) = (f64::from(e_unscattered.0[c]), f64::from(e_scattered.0[c]));
            // What the cutoffs dropped is still in the fiber: counted as leaving (exact for
            // lossless fibers, where all of it does; a bound otherwise).
            let e_sim = t.exiting[c] + t.dropped[c];
            let res = (e_sim - eu - es).max(0.0);
            // Where the scattered lobes carry more than the simulation lets out, they are
            // scaled down to it (the eight unscattered paths are part of E_sim exactly).
            let excess = (eu + es - e_sim).max(0.0).min(es);
            out[3 * j + c] = res as f32;
            out[scale_at + 3 * j + c] = if es > 0.0 {
                (1.0 - excess / es) as f32
            } else {
                1.0
            };
            self.scattered_mean[c] += es * inv_n;
            self.unscattered_mean[c] += eu * inv_n;
            self.lossless_mean[c] += f64::from(e_lossless.0[c]) * inv_n;
            self.excess_mean[c] += excess * inv_n;
            stats.exiting[c] += t.exiting[c] * inv_n;
            stats.excess[c] += excess * inv_n;
            stats.residual[c] += res * inv_n;
            stats.unmodelled[c] += t.unmodelled[c] * inv_n;
            stats.dropped[c] += t.dropped[c] * inv_n;
            cell_drop = cell_drop.max(t.dropped[c]);
        }
        stats.dropped_max = stats.dropped_max.max(cell_drop);
        stats.beams += t.beams;
        stats.photons += t.photons;
    }

    /// The row's means, scale factors and D_res from the colour's histogram `hist`, into
    /// `out`.
    fn finish(&mut self, layout: &ResidualLayout, hist: &[[f64; 3]], out: &mut [f32]) -> RowStats {
        let n_h = layout.n_h;
        let scale_at = layout.scale_offset();
        // The far field carries the lobes' exact h-means; the offsets' midpoint rule misses them
        // where E_model(h) jumps (h = κη'_c, the medulla's total reflection; the jumps move with
        // θ_r) or turns steeply (the cuticle's Fresnel toward h = 1) by up to half a jump times
        // 1/n_h. Lossless, E_sim ≡ 1 is smooth and those features are the residual's:
        // ⟨A_res⟩_h = 1 − exact⟨E_model⟩ (the midpoint rule for E_sim, exact means for the lobes).
        // Absorption makes E_sim itself jump with the paths (and leaves the series beyond TRT of a
        // medulla-free fiber smooth, where midpoint⟨res⟩ was right): the correction
        // (midpoint − exact)⟨E_u + s·E_s⟩ is weighted by τ = midpoint⟨E_sim − E_u⟩ /
        // midpoint⟨1 − E_0⟩, the part of the energy off the eight unscattered paths that survives
        // absorption (E_0: Σ_p A_p without absorption; τ = 1 lossless, → 0 for dark fibers). The
        // offsets keep the simulation's values and their mean; the near field scales them to the
        // far field's mean (`ResidualTable::magnitude`).
        let (unscattered_exact, scattered_exact) = self.energies.mean();
        for c in 0..3 {
            let scale = if self.scattered_mean[c] > 0.0 {
                (1.0 - self.excess_mean[c] / self.scattered_mean[c]).clamp(0.0, 1.0)
            } else {
                1.0
            };
            let (eu, es) = (
                f64::from(unscattered_exact.0[c]),
                f64::from(scattered_exact.0[c]),
            );
            let off_paths =
                self.stats.exiting[c] + self.stats.dropped[c] - self.unscattered_mean[c];
            let lossless_off_paths = 1.0 - self.lossless_mean[c];
            let tau = if lossless_off_paths > 1e-12 {
                (off_paths / lossless_off_paths).clamp(0.0, 1.0)
            } else {
                1.0
            };
            let midpoint = self.stats.residual[c];
            let correction =
                (self.unscattered_mean[c] - eu) + scale * (self.scattered_mean[c] - es);
            let mean = (midpoint + tau * correction).max(0.0);
            self.stats.residual[c] = mean;
            self.stats.model[c] = eu + es;
            out[3 * n_h + c] = midpoint as f32;
            out[layout.far_mean_offset() + c] = mean as f32;
            out[scale_at + 3 * n_h + c] = scale as f32;
        }
        // D_res: the histogram over |φ| ∈ [0, π] as a density over φ ∈ (−π, π] (both signs).
        let width = PI / layout.n_phi as f32;
        let d = &mut out[3 * (n_h + 1)..scale_at];
        for c in 0..3 {
            let total: f64 = hist.iter().map(|b| b[c]).sum();
            for (k, b) in hist.iter().enumerate() {
                d[3 * k + c] = if total > 0.0 {
                    (b[c] / (total * 2.0 * f64::from(width))) as f32
                } else {
                    1.0 / TAU
                };
            }
        }
        self.stats
    }
}

/// Generates the whole table sequentially into `out` ([`ResidualLayout::len`]); the std
/// tools run the rows in parallel with identical results.
pub fn generate<M: Math>(
    model: &FurBcsdf<'_, M>,
    layout: &ResidualLayout,
    seed: u64,
    out: &mut [f32],
) -> Result<(), ProfileError> {
    layout.validate()?;
    if out.len() != layout.len() {
        return Err(ProfileError::WrongLength {
            table: "residual",
            expected: layout.len(),
            found: out.len(),
        });
    }
    let (rows, _) = out.split_at_mut(layout.means_offset());
    for (row, chunk) in rows.chunks_exact_mut(layout.row_len()).enumerate() {
        generate_row(model, layout, row, seed, chunk);
    }
    fill_means(layout, |i| mean_node_energy(model, layout, i), out);
    Ok(())
}

/// The lobes' exact h-means at mean node `i` ([`ResidualLayout::mean_node`]): (⟨Σ_p A_p⟩_h,
/// the scattered lobes' unscaled ⟨energy⟩_h), for [`fill_means`]. Deterministic (no photons);
/// the std tools run the nodes in parallel.
pub fn mean_node_energy<M: Math>(
    model: &FurBcsdf<'_, M>,
    layout: &ResidualLayout,
    i: usize,
) -> (Rgb, Rgb) {
    ModelEnergy::new(model, layout.mean_node(i)).mean()
}

/// (⟨Σ_p A_p⟩_h, the scattered lobes' unscaled ⟨energy⟩_h) at one θ_r.
type Energies = (Rgb, Rgb);

/// Writes the far field's ⟨A_res⟩_h at every mean node into `data` (a whole table whose rows
/// [`generate_row`] has written), `energy(i)` being [`mean_node_energy`] at mean node `i`
/// (called in increasing `i`, each row's node once): ⟨E_sim⟩_h interpolated between the rows
/// as the far field interpolates them (each row's ⟨E_sim⟩_h being what its lobes, scaled, and
/// its residual carry), less the lobes' exact h-means at the node, the scattered ones at the
/// rows' interpolated scale; floored at 0. At the rows this is the row's own mean; between them
/// it follows E_model's kinks. Nothing is written when the sizes do not match.
pub fn fill_means(
    layout: &ResidualLayout,
    mut energy: impl FnMut(usize) -> (Rgb, Rgb),
    data: &mut [f32],
) {
    if layout.validate().is_err() || data.len() != layout.len() {
        return;
    }
    let (n, len, n_h) = (layout.n_theta, layout.row_len(), layout.n_h);
    let scale_at = layout.scale_offset() + 3 * n_h;
    let far_at = layout.far_mean_offset();
    let (rows, means) = data.split_at_mut(layout.means_offset());
    // ⟨E_sim⟩_h and the far-field scale of row k, channel c, from its lobes' energies.
    let row = |k: usize, c: usize, (u, v): (Rgb, Rgb)| {
        let r = &rows[k * len..(k + 1) * len];
        let s = f64::from(r[scale_at + c]);
        let e_sim = f64::from(r[far_at + c]) + f64::from(u.0[c]) + s * f64::from(v.0[c]);
        (e_sim, s)
    };
    // The lobes' energies at the current interval's two rows.
    let mut ends: Option<(usize, Energies, Energies)> = None;
    for i in 0..layout.n_mean() {
        let x = layout.theta_position(layout.mean_node(i));
        let k = (x as usize).min(n - 2);
        let (lo, hi) = match ends {
            Some((at, lo, hi)) if at == k => (lo, hi),
            Some((at, _, hi)) if at + 1 == k => (hi, energy(MEAN_SUBDIVISION * (k + 1))),
            _ => (
                energy(MEAN_SUBDIVISION * k),
                energy(MEAN_SUBDIVISION * (k + 1)),
            ),
        };
        ends = Some((k, lo, hi));
        let (u, v) = if i == MEAN_SUBDIVISION * k {
            lo
        } else if i == MEAN_SUBDIVISION * (k + 1) {
            hi
        } else {
            energy(i)
        };
        let w = f64::from(x - k as f32);
        for c in 0..3 {
            let ((e0, s0), (e1, s1)) = (row(k, c, lo), row(k + 1, c, hi));
            let e_sim = e0 * (1.0 - w) + e1 * w;
            let s = s0 * (1.0 - w) + s1 * w;
            let mean = e_sim - f64::from(u.0[c]) - s * f64::from(v.0[c]);
            means[3 * i + c] = mean.max(0.0) as f32;
        }
    }
}

/// E_model(θ_r, h): the energy the model's lobes carry at one view angle, from the model's own
/// functions.
struct ModelEnergy<'m, 'a, M: Math> {
    model: &'m FurBcsdf<'a, M>,
    slice: ViewSlice,
    ext: Extinction,
    /// `ext` without absorption (σ_ca = σ_ma = 0; the medulla's scattering kept).
    lossless: Extinction,
    /// ∫ M^s_back dθ_i and ∫ M^s_front dθ_i at θ_r (weighted like S's 1/cos²θ_i guard).
    exit_mass: [f32; 2],
}

impl<'m, 'a, M: Math> ModelEnergy<'m, 'a, M> {
    fn new(model: &'m FurBcsdf<'a, M>, theta_r: f32) -> Self {
        let mut exit_mass = [0.0f32; 2];
        if model.profiles().is_some() {
            let step = PI / MS_SAMPLES as f32;
            for (x, phi) in [0.0, PI].into_iter().enumerate() {
                let mut sum = 0.0f64;
                for k in 0..MS_SAMPLES {
                    let ti = -PI / 2.0 + (k as f32 + 0.5) * step;
                    let Ok(a) = Angles::new(ti, theta_r, phi) else {
                        continue;
                    };
                    let c = M::cos(ti);
                    let w = c * c * inv_cos2_theta_i(c);
                    sum += f64::from(model.longitudinal_scattered(&a) * w * step);
                }
                exit_mass[x] = sum as f32;
            }
        }
        let (slice, ext) = model.slice_and_extinction(theta_r);
        let lossless = Extinction {
            cortex: Rgb::ZERO,
            medulla: ext.medulla_scattering,
            medulla_scattering: ext.medulla_scattering,
        };
        ModelEnergy {
            model,
            slice,
            ext,
            lossless,
            exit_mass,
        }
    }

    /// (Σ_p A_p(h), the scattered lobes' energy at h).
    fn at(&self, h: f32) -> (Rgb, Rgb) {
        self.on_chord(&Chord::at_offset::<M>(&self.slice, h))
    }

    /// Σ_p A_p(h) without absorption.
    fn lossless_at(&self, h: f32) -> Rgb {
        let chord = Chord::at_offset::<M>(&self.slice, h);
        let l = self.model.params().l();
        let mut e = Rgb::ZERO;
        for a in attenuations::<M>(&self.slice, &chord, &self.lossless, l) {
            e += a;
        }
        e
    }

    /// (⟨Σ_p A_p⟩_h, the scattered lobes' ⟨energy⟩_h) over h ∈ [0, 1] (both even in h):
    /// Gauss–Legendre on the far field's smooth pieces of [0, 1] (`far_field::segments`,
    /// h = K·sin t, which also takes the square-root ends smoothly), [`MEAN_PANELS`] panels
    /// each.
    fn mean(&self) -> (Rgb, Rgb) {
        let (segs, n) = segments::<M>(&self.slice, self.model.index_matched());
        let (mut eu, mut es) = ([0.0f64; 3], [0.0f64; 3]);
        for seg in &segs[..n] {
            let k = segment_scale(&self.slice, seg.var);
            let width = (seg.t1 - seg.t0) / MEAN_PANELS as f32;
            for panel in 0..MEAN_PANELS {
                let mid = seg.t0 + (panel as f32 + 0.5) * width;
                for (x, w) in GL_NODES.iter().zip(GL_WEIGHTS.iter()) {
                    let t = mid + 0.5 * width * x;
                    let chord = Chord::at_variable::<M>(&self.slice, seg.var, t, seg.region);
                    let dh = f64::from(k * chord.variable_cos(seg.var) * 0.5 * width * w);
                    let (u, v) = self.on_chord(&chord);
                    for c in 0..3 {
                        eu[c] += f64::from(u.0[c]) * dh;
                        es[c] += f64::from(v.0[c]) * dh;
                    }
                }
            }
        }
        let rgb = |v: [f64; 3]| Rgb(v.map(|x| x as f32));
        (rgb(eu), rgb(es))
    }

    /// (Σ_p A_p, the scattered lobes' energy) on `chord`.
    fn on_chord(&self, chord: &Chord) -> (Rgb, Rgb) {
        let model = self.model;
        let (slice, ext) = (&self.slice, &self.ext);
        let l = model.params().l();
        let mut e = Rgb::ZERO;
        for a in attenuations::<M>(slice, chord, ext, l) {
            e += a;
        }
        let Some(profiles) = model.profiles() else {
            return (e, Rgb::ZERO);
        };
        if ext.medulla_scattering <= 0.0 {
            return (e, Rgb::ZERO);
        }
        let exit = exit_transmittance::<M>(slice, ext);
        let Some(sp) = scattered_paths::<M>(slice, chord, ext, l, exit) else {
            return (e, Rgb::ZERO);
        };
        let mut es = Rgb::ZERO;
        let row = profiles.n_row(model.sigma_n(slice), sp.h_m);
        let n = PSI_SUBSAMPLES * profiles.layout().res.n_psi;
        let step = TAU / n as f32;
        for k in 0..n {
            let phi = -PI + (k as f32 + 0.5) * step;
            let w = phi.abs() / PI;
            let blend = (1.0 - w) * self.exit_mass[0] + w * self.exit_mass[1];
            for v in azimuthal_on_row(profiles, &row, &sp, phi) {
                es += v * (blend * step);
            }
        }
        (e, es)
    }
}
