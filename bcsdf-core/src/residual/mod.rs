//! The residual (docs/model.md §12, "Residual"): the energy of every path the eight
//! unscattered and three scattered lobes leave out, from the model's own simulation of the
//! cross-section ([`sim`]), as a term of S in the energy closure.
//!
//! Per view angle θ_r (node) and offset h (node), the simulation gives the energy leaving
//! the fiber, E_sim, and the energy on unmodelled paths by exit azimuth; the model's own
//! lobes carry E_model(θ_r, h) (computed by calling them: Σ_p A_p(h), the M_p having mass 1
//! on the sphere in the energy closure, plus per scattered lobe A^s_k(h) times the ψ-integral
//! of C^N against the back/front blend of ∫ M^s_x dθ_i). The residual's magnitude is
//! A_res = max(0, E_sim − E_model) per channel; its shape D_res(θ_r, |φ|) is the unmodelled
//! energy's exit-azimuth histogram, normalised to unit integral over φ ∈ (−π, π]:
//!
//! N_res(θ_r, h, φ) = A_res(θ_r, h)·D_res(θ_r, |φ|), far field ⟨A_res⟩_h·D_res(θ_r, |φ|),
//!
//! and S gains M_TRT(θ_i, θ_r)·N_res/cos²θ_i (folded into the TRT family).
//!
//! # Layout
//! Flat f32 in caller memory, per θ_r node (`n_theta` nodes θ_k = (π/2)·(1 − (1 − x_k)²),
//! x_k = k/(n_theta − 1): graded toward grazing view, where the Bravais index grows as
//! 1/cos θ_r and the residual changes fastest) one row
//! of [`ResidualLayout::row_len`] values: A_res at the `n_h` offsets h_j = (j + ½)/n_h (RGB
//! interleaved), then ⟨A_res⟩_h (RGB, the midpoint rule over those offsets, which is exactly the
//! h-mean of the near field's piecewise-linear interpolant), then D_res in `n_phi` bins of
//! |φ| ∈ [0, π] (RGB). Every cell draws from its own PCG32 stream ([`cell_stream`]), so a
//! table is the same bits for any thread count.

pub mod sim;

use crate::frame::Angles;
use crate::geometry::Chord;
use crate::lobes::LobeGroup;
use crate::math::{Libm, Math, PI, TAU};
use crate::medulla::ProfileError;
use crate::model::{inv_cos2_theta_i, FurBcsdf};
use crate::params::FurParams;
use crate::rng::{cell_stream, Pcg32};
use crate::scattered::{azimuthal_on_row, exit_transmittance, scattered_paths};
use crate::spectrum::Rgb;
use crate::unscattered::attenuations;
use sim::{simulate_cell, CellTally, Section};

/// Table id of the residual cells for [`cell_stream`] (C^N is 1, C^M 2).
const TABLE_RESIDUAL: u64 = 3;

/// θ_i midpoints of the ∫ M^s_x dθ_i integrals.
const MS_SAMPLES: usize = 1024;

/// φ midpoints per C^N bin of the ψ-integrals of the scattered lobes' energy.
const PSI_SUBSAMPLES: usize = 4;

/// Axes and photon budget of a residual table.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ResidualLayout {
    /// θ_r nodes over [0, π/2].
    pub n_theta: usize,
    /// h nodes (midpoints) over [0, 1].
    pub n_h: usize,
    /// |φ| bins over [0, π].
    pub n_phi: usize,
    /// Photons per unit of scattered weight in a cell (K).
    pub photons: u32,
}

impl ResidualLayout {
    /// The default: 32 θ_r nodes, 32 offsets, 36 azimuth bins, K = 500 (docs/model.md §12).
    pub const DEFAULT: ResidualLayout = ResidualLayout {
        n_theta: 32,
        n_h: 32,
        n_phi: 36,
        photons: 500,
    };

    /// Values per θ_r row: 3·(2·(n_h + 1) + n_phi).
    #[must_use]
    pub fn row_len(&self) -> usize {
        3 * (2 * (self.n_h + 1) + self.n_phi)
    }

    /// Where the scattered lobes' scale factors start in a row: 3·(n_h + 1 + n_phi).
    #[must_use]
    pub fn scale_offset(&self) -> usize {
        3 * (self.n_h + 1 + self.n_phi)
    }

    /// Values of the whole table.
    #[must_use]
    pub fn len(&self) -> usize {
        self.n_theta * self.row_len()
    }

    /// True when the table has no values.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// θ_r of node `k`: (π/2)·(1 − (1 − x)²), x = k/(n_theta − 1).
    #[must_use]
    pub fn theta_node(&self, k: usize) -> f32 {
        let x = 1.0 - k as f32 / (self.n_theta - 1) as f32;
        (PI / 2.0) * (1.0 - x * x)
    }

    /// The fractional node position of |θ_r| (the inverse of [`ResidualLayout::theta_node`]),
    /// clamped to [0, n_theta − 1].
    #[must_use]
    pub fn theta_position(&self, theta_r: f32) -> f32 {
        let t = (theta_r.abs() / (PI / 2.0)).min(1.0);
        let x = 1.0 - libm::sqrtf(1.0 - t);
        (x * (self.n_theta - 1) as f32).clamp(0.0, (self.n_theta - 1) as f32)
    }

    /// h of node `j`: (j + ½)/n_h.
    #[must_use]
    pub fn h_node(&self, j: usize) -> f32 {
        (j as f32 + 0.5) / self.n_h as f32
    }

    /// Checks the sizes.
    pub fn validate(&self) -> Result<(), ProfileError> {
        let ok = |n: usize| (2..=4096).contains(&n);
        if ok(self.n_theta) && ok(self.n_h) && ok(self.n_phi) && self.photons > 0 {
            Ok(())
        } else {
            Err(ProfileError::BadResolution)
        }
    }
}

/// What one θ_r row's simulation found, h-means (midpoint rule) per channel, for the
/// numbers docs/model.md §12 reports.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RowStats {
    /// ⟨E_sim⟩_h: all energy leaving the fiber.
    pub exiting: [f64; 3],
    /// ⟨E_model⟩_h: the energy the model's lobes carry.
    pub model: [f64; 3],
    /// ⟨max(0, E_model − E_sim)⟩_h: what the scattered lobes carry beyond the simulation
    /// (removed by their scale factor).
    pub excess: [f64; 3],
    /// ⟨A_res⟩_h = ⟨max(0, E_sim − E_model)⟩_h.
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
fn section(params: &FurParams, theta_r: f32) -> Section {
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
    let mut stats = RowStats::default();
    let params = model.params();
    let sec = section(params, theta_r);
    let energies = ModelEnergy::new(model, theta_r);
    let n_h = layout.n_h;
    let mut hist = [[0.0f64; 3]; 4096];
    let scale_at = layout.scale_offset();
    let (mut scattered_mean, mut excess_mean) = ([0.0f64; 3], [0.0f64; 3]);
    let hist = &mut hist[..layout.n_phi];
    let inv_n = 1.0 / n_h as f64;
    for j in 0..n_h {
        let h = layout.h_node(j);
        let stream = cell_stream(seed, TABLE_RESIDUAL, row * n_h as u64 + j as u64);
        let mut rng = Pcg32::new(stream, stream.rotate_left(17));
        let t: CellTally = simulate_cell(&sec, h, layout.photons, &mut rng, hist);
        let (e_unscattered, e_scattered) = energies.at(h);
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
            scattered_mean[c] += es * inv_n;
            excess_mean[c] += excess * inv_n;
            stats.exiting[c] += t.exiting[c] * inv_n;
            stats.model[c] += (eu + es) * inv_n;
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
    for c in 0..3 {
        out[3 * n_h + c] = stats.residual[c] as f32;
        out[scale_at + 3 * n_h + c] = if scattered_mean[c] > 0.0 {
            (1.0 - excess_mean[c] / scattered_mean[c]).clamp(0.0, 1.0) as f32
        } else {
            1.0
        };
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
    stats
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
    for (row, chunk) in out.chunks_exact_mut(layout.row_len()).enumerate() {
        generate_row(model, layout, row, seed, chunk);
    }
    Ok(())
}

/// E_model(θ_r, h): the energy the model's lobes carry at one view angle, from the model's own
/// functions.
struct ModelEnergy<'m, 'a, M: Math> {
    model: &'m FurBcsdf<'a, M>,
    theta_r: f32,
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
        ModelEnergy {
            model,
            theta_r,
            exit_mass,
        }
    }

    /// (Σ_p A_p(h), the scattered lobes' energy at h).
    fn at(&self, h: f32) -> (Rgb, Rgb) {
        let model = self.model;
        let (slice, ext) = model.slice_and_extinction(self.theta_r);
        let chord = Chord::at_offset::<M>(&slice, h);
        let l = model.params().l();
        let mut e = Rgb::ZERO;
        for a in attenuations::<M>(&slice, &chord, &ext, l) {
            e += a;
        }
        let Some(profiles) = model.profiles() else {
            return (e, Rgb::ZERO);
        };
        if ext.medulla_scattering <= 0.0 {
            return (e, Rgb::ZERO);
        }
        let exit = exit_transmittance::<M>(&slice, &ext);
        let Some(sp) = scattered_paths::<M>(&slice, &chord, &ext, l, exit) else {
            return (e, Rgb::ZERO);
        };
        let mut es = Rgb::ZERO;
        let row = profiles.n_row(model.sigma_n(&slice), sp.h_m);
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

/// A residual table for one parameter set, borrowed from caller memory and validated.
#[derive(Clone, Copy, Debug)]
pub struct ResidualTable<'a> {
    params: FurParams,
    layout: ResidualLayout,
    data: &'a [f32],
}

impl<'a> ResidualTable<'a> {
    /// Wraps `data` laid out as in the module documentation, generated for `params`; sizes
    /// and values are checked.
    pub fn new(
        params: FurParams,
        layout: ResidualLayout,
        data: &'a [f32],
    ) -> Result<ResidualTable<'a>, ProfileError> {
        layout.validate()?;
        if data.len() != layout.len() {
            return Err(ProfileError::WrongLength {
                table: "residual",
                expected: layout.len(),
                found: data.len(),
            });
        }
        if let Some(index) = data.iter().position(|v| !(v.is_finite() && *v >= 0.0)) {
            return Err(ProfileError::BadValue {
                table: "residual",
                index,
            });
        }
        Ok(ResidualTable {
            params,
            layout,
            data,
        })
    }

    /// True when the table was made for `params` (the closure aside: the residual is the
    /// same for both, and only the energy closure uses it).
    #[must_use]
    pub fn matches(&self, params: &FurParams) -> bool {
        self.params.with_closure(params.closure()) == *params
    }

    /// The layout.
    #[must_use]
    pub fn layout(&self) -> &ResidualLayout {
        &self.layout
    }

    /// The raw table.
    #[must_use]
    pub fn data(&self) -> &'a [f32] {
        self.data
    }

    /// The two θ_r rows around |θ_r| and the weight of the upper.
    fn rows(&self, theta_r: f32) -> (&'a [f32], &'a [f32], f32) {
        let n = self.layout.n_theta;
        let u = self.layout.theta_position(theta_r);
        let k = if u.is_finite() {
            (u as usize).min(n - 2)
        } else {
            0
        };
        let w = if u.is_finite() { u - k as f32 } else { 0.0 };
        let len = self.layout.row_len();
        (
            &self.data[k * len..(k + 1) * len],
            &self.data[(k + 1) * len..(k + 2) * len],
            w,
        )
    }

    fn rgb(row: &[f32], i: usize) -> Rgb {
        Rgb([row[3 * i], row[3 * i + 1], row[3 * i + 2]])
    }

    /// ⟨A_res⟩_h at θ_r (linear in θ_r between nodes).
    #[must_use]
    pub fn mean(&self, theta_r: f32) -> Rgb {
        let (a, b, w) = self.rows(theta_r);
        let n_h = self.layout.n_h;
        Self::rgb(a, n_h) * (1.0 - w) + Self::rgb(b, n_h) * w
    }

    /// A_res(θ_r, h): linear in θ_r and in |h| between the offsets (constant beyond the first
    /// and last).
    #[must_use]
    pub fn magnitude(&self, theta_r: f32, h: f32) -> Rgb {
        let (a, b, w) = self.rows(theta_r);
        let n_h = self.layout.n_h;
        let u = (h.abs() * n_h as f32 - 0.5).clamp(0.0, (n_h - 1) as f32);
        let j = if u.is_finite() {
            (u as usize).min(n_h - 2)
        } else {
            0
        };
        let v = if u.is_finite() { u - j as f32 } else { 0.0 };
        let at = |row: &[f32]| Self::rgb(row, j) * (1.0 - v) + Self::rgb(row, j + 1) * v;
        at(a) * (1.0 - w) + at(b) * w
    }

    /// D_res(θ_r, |φ|): linear in |φ| between the centres of its bins (flat from 0 to the first
    /// centre and from the last to π), linear in θ_r; unit integral over φ ∈ (−π, π] per
    /// channel. (The interpolant through the centres, flat at the ends, has each bin's mass:
    /// a bin keeps ¾ of its own value and gets ⅛ of each neighbour's, and gives the same
    /// back. Unlike the histogram itself it has no jumps, which a baked table's linear
    /// interpolation could not follow: piecewise constant, mouse's baked E_peak in the energy
    /// closure was 2.45 % at any φ resolution.)
    #[must_use]
    pub fn density(&self, theta_r: f32, phi: f32) -> Rgb {
        let (a, b, w) = self.rows(theta_r);
        let n = self.layout.n_phi;
        let x =
            (crate::math::wrap_angle(phi).abs() / PI * n as f32 - 0.5).clamp(0.0, (n - 1) as f32);
        let (k, v) = if x.is_finite() {
            let k = (x as usize).min(n - 2);
            (k, x - k as f32)
        } else {
            (0, 0.0)
        };
        let off = self.layout.n_h + 1;
        let at =
            |row: &[f32]| Self::rgb(row, off + k) * (1.0 - v) + Self::rgb(row, off + k + 1) * v;
        at(a) * (1.0 - w) + at(b) * w
    }

    /// The channel mean of bin `k` of D_res at θ_r (linear in θ_r).
    fn bin_mean(&self, theta_r: f32, k: usize) -> f32 {
        let (a, b, w) = self.rows(theta_r);
        let off = self.layout.n_h + 1;
        let d = (Self::rgb(a, off + k) * (1.0 - w) + Self::rgb(b, off + k) * w).0;
        (d[0] + d[1] + d[2]) * (1.0 / 3.0)
    }

    /// The weight of bin `k` in the analytic sampler's φ density: the largest channel-mean
    /// bin value among `k` and its neighbours, so that the density is positive wherever
    /// [`ResidualTable::density`] is (which reaches half a bin into a neighbour).
    fn sampling_weight(&self, theta_r: f32, k: usize) -> f32 {
        let n = self.layout.n_phi;
        let lo = k.saturating_sub(1);
        let hi = (k + 1).min(n - 1);
        (lo..=hi)
            .map(|j| self.bin_mean(theta_r, j))
            .fold(0.0, f32::max)
    }

    /// The |φ| bin of φ.
    fn bin(&self, phi: f32) -> usize {
        let n = self.layout.n_phi;
        let x = crate::math::wrap_angle(phi).abs() / PI * n as f32;
        if x.is_finite() {
            (x as usize).min(n - 1)
        } else {
            0
        }
    }

    /// The φ density the analytic sampler draws the residual part from (unit integral over
    /// φ ∈ (−π, π]): piecewise constant in |φ|, bin k weighted by the largest channel-mean
    /// value of bins k − 1, k, k + 1 (positive wherever [`ResidualTable::density`] is; uniform
    /// where every bin is empty).
    #[must_use]
    pub fn phi_density(&self, theta_r: f32, phi: f32) -> f32 {
        let n = self.layout.n_phi;
        let width = PI / n as f32;
        let total: f32 = (0..n).map(|k| self.sampling_weight(theta_r, k)).sum();
        if total > 0.0 && total.is_finite() {
            self.sampling_weight(theta_r, self.bin(phi)) / (2.0 * width * total)
        } else {
            1.0 / (2.0 * PI)
        }
    }

    /// Draws |φ| ∈ [0, π] with density 2·[`ResidualTable::phi_density`] from `u` ∈ [0, 1):
    /// a bin by its weight, then uniformly inside it.
    #[must_use]
    pub fn sample_abs_phi(&self, theta_r: f32, u: f32) -> f32 {
        let n = self.layout.n_phi;
        let width = PI / n as f32;
        let mass = |k: usize| self.sampling_weight(theta_r, k);
        let total: f32 = (0..n).map(mass).sum();
        if !(total > 0.0 && total.is_finite()) {
            return u.clamp(0.0, 1.0) * PI;
        }
        let target = u.clamp(0.0, 1.0) * total;
        let mut acc = 0.0f32;
        for k in 0..n {
            let m = mass(k);
            if m > 0.0 && (target < acc + m || k == n - 1) {
                let v = ((target - acc) / m).clamp(0.0, 1.0);
                return ((k as f32 + v) * width).min(PI);
            }
            acc += m;
        }
        // Rounding past the end: the last bin of positive mass.
        (0..n)
            .rev()
            .find(|&k| mass(k) > 0.0)
            .map_or(0.5 * PI, |k| (k as f32 + 1.0) * width)
    }

    /// The far-field scale of the scattered lobes at θ_r: 1 − ⟨excess⟩_h/⟨E_s⟩_h, E_s the
    /// scattered lobes' energy (linear in θ_r).
    #[must_use]
    pub fn scattered_scale(&self, theta_r: f32) -> Rgb {
        let (a, b, w) = self.rows(theta_r);
        let k = self.layout.scale_offset() / 3 + self.layout.n_h;
        Self::rgb(a, k) * (1.0 - w) + Self::rgb(b, k) * w
    }

    /// The near-field scale of the scattered lobes at (θ_r, h): 1 − excess/E_s at the
    /// offsets, interpolated like [`ResidualTable::magnitude`].
    #[must_use]
    pub fn scattered_scale_near(&self, theta_r: f32, h: f32) -> Rgb {
        let (a, b, w) = self.rows(theta_r);
        let n_h = self.layout.n_h;
        let base = self.layout.scale_offset() / 3;
        let u = (h.abs() * n_h as f32 - 0.5).clamp(0.0, (n_h - 1) as f32);
        let j = if u.is_finite() {
            (u as usize).min(n_h - 2)
        } else {
            0
        };
        let v = if u.is_finite() { u - j as f32 } else { 0.0 };
        let at =
            |row: &[f32]| Self::rgb(row, base + j) * (1.0 - v) + Self::rgb(row, base + j + 1) * v;
        at(a) * (1.0 - w) + at(b) * w
    }

    /// Far field N_res(θ_r, φ) = ⟨A_res⟩_h·D_res(θ_r, |φ|).
    #[must_use]
    pub fn far(&self, theta_r: f32, phi: f32) -> Rgb {
        self.mean(theta_r) * self.density(theta_r, phi)
    }

    /// Near field N_res(θ_r, h, φ) = A_res(θ_r, h)·D_res(θ_r, |φ|).
    #[must_use]
    pub fn near(&self, theta_r: f32, h: f32, phi: f32) -> Rgb {
        self.magnitude(theta_r, h) * self.density(theta_r, phi)
    }

    /// The longitudinal group whose M the residual uses (TRT, docs/model.md §12).
    pub const GROUP: LobeGroup = LobeGroup::TRT;
}

#[cfg(test)]
mod tests;
