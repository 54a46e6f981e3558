//! Sampling the analytic far field (docs/model.md §10).
//!
//! S·cos²θ_i = Σ_p M_{g(p)}(θ_i + θ_r)·N_p(φ) + M^s(θ_i, θ_r, φ)·Σ_k N^s_k(φ) is sampled as a
//! mixture with one part per unscattered path p (eight) and per scattered lobe k and C^M
//! half x (three × two). Part weights are a cheap, always-positive proxy of each part's
//! albedo at θ_r (a 2-point Gauss–Legendre estimate of ∫ A_p dh per h-segment, floored at
//! 1e-3 of the largest so that no existing path is ever starved), times the longitudinal
//! mass for the unscattered parts. Within a part:
//!
//! - unscattered path p: θ_i from G(θ_i + θ_r − α_g; β_g) restricted to the Gaussian's support
//!   (±6.2β) inside [−π/2, π/2]; h uniform over the h ≥ 0 where the path exists, then
//!   φ = ±(Φ_p(h) + δ), δ from the Gaussian of width β_N (its support ±6.2β), sign uniform.
//!   The φ density is (1/2|H_p|)∫_{H_p} [D_p(φ − Φ_p) + D_p(−φ − Φ_p)] dh, integrated with the
//!   far field's own nodes in the same pass as N_p;
//! - scattered lobe k, half x: θ' from C^M_x(· | θ'_in) over the θ' reachable from
//!   θ_i ∈ [−π/2, π/2] (each monotonic branch of θ_i ↦ θ' separately), then θ_i on that
//!   branch, density C^M_x·|dθ'/dθ_i| / Z_x; h uniform over the h that enter the medulla,
//!   ψ from the interpolated C^N row at (σ_N, h_m), φ = ±(π + Φ^s_k(h) + ψ);
//! - the residual (energy closure with a residual table, docs/model.md §12): θ_i from TRT's
//!   M as for the TRT paths, |φ| piecewise constant over D_res's bins, each weighted by the
//!   largest channel-mean value of itself and its neighbours (`ResidualTable::phi_density`:
//!   positive wherever D_res, linear between the bins' centres, is), sign uniform; proxy
//!   ⟨A_res⟩_h.
//!
//! The 1/cos²θ_i of S, the Fresnel and absorption factors, μ and F_t, and the back/front
//! blend of M^s are left to the weight. `pdf` is the full mixture and costs about one
//! far-field evaluation (the h integrals); `sample` evaluates S and the density in one pass.

use super::{choose, gaussian_mass, invert_linear, linear_mass, sample_gaussian, unit};
use crate::bcsdf::SampledDirection;
use crate::far_field::{segment_scale, segments, Segment};
use crate::frame::Angles;
use crate::gaussian::CUTOFF_SIGMAS;
use crate::geometry::{Chord, Region, ViewSlice};
use crate::lobes::{Lobe, LobeFamily, LobeGroup, UNSCATTERED_COUNT};
use crate::math::{asin_clamped, wrap_angle, Math, PI};
use crate::medulla::{Half, MedullaProfiles};
use crate::model::{FurBcsdf, Scattering};
use crate::scattered::{
    exit_transmittance, scattered_paths, ScatteredLongitudinal, SCATTERED_COUNT,
};
use crate::unscattered::{attenuations, exit_azimuths, Extinction};

mod view;
pub use view::AnalyticView;

/// Floor of a part's proxy weight, relative to the largest proxy.
const PROXY_FLOOR: f32 = 1e-3;

/// 2-point Gauss–Legendre nodes on [−1, 1] (weights 1) for the proxies.
const PROXY_NODES: [f32; 2] = [-0.577_350_26, 0.577_350_26];

/// Number of mixture parts: eight unscattered paths, then (lobe k, half x) for k = 0..3,
/// then the residual (energy closure, docs/model.md §12).
const PARTS: usize = UNSCATTERED_COUNT + 2 * SCATTERED_COUNT + 1;

/// The residual's part: θ_i from TRT's M, |φ| from D_res, sign uniform.
const RESIDUAL_PART: usize = PARTS - 1;

/// The longitudinal interval of an unscattered group: θ_i ∈ [lo, hi] around `center`.
#[derive(Clone, Copy, Debug, Default)]
struct Longitudinal {
    center: f32,
    lo: f32,
    hi: f32,
    beta: f32,
    mass: f32,
}

/// The C^M half x seen from one θ_r: θ'_in, its θ' branches and their total mass Z_x.
#[derive(Clone, Copy, Debug)]
struct CmRow {
    half: Half,
    theta_in: f32,
    branches: [Option<(f32, f32)>; 2],
    mass: f32,
}

/// Everything the sampler and its density need at one θ_r.
struct Plan<'m, 'a, M: Math> {
    model: &'m FurBcsdf<'a, M>,
    slice: ViewSlice,
    ext: Extinction,
    segs: [Segment; 3],
    n_segs: usize,
    /// Unnormalised part weights.
    weights: [f32; PARTS],
    total: f32,
    /// |H_p|: length of the h ≥ 0 where path p exists.
    h_len: [f32; UNSCATTERED_COUNT],
    /// Index of the segment where the rays enter the medulla, and its h-length.
    enter: Option<(usize, f32)>,
    groups: [Longitudinal; 3],
    /// Mass of each group's D_p within its support (the δ sampler's normaliser).
    d_mass: [f32; 3],
    cm: [Option<CmRow>; 2],
}

/// h-range [h0, h1] of a segment.
fn h_range(slice: &ViewSlice, seg: &Segment) -> (f32, f32) {
    let k = segment_scale(slice, seg.var);
    (k * libm::sinf(seg.t0), k * libm::sinf(seg.t1))
}

/// Bin centres of C^M's θ'_out axis inside (lo, hi), with lo and hi: the breakpoints of the
/// piecewise-linear C^M row on [lo, hi], handed to `f` as consecutive pairs. Stops early when
/// `f` returns true.
fn cm_segments(n_out: usize, lo: f32, hi: f32, mut f: impl FnMut(f32, f32) -> bool) -> bool {
    let w = PI / n_out as f32;
    let first = -PI / 2.0 + 0.5 * w;
    let mut b = libm::ceilf((lo - first) / w).max(0.0) as usize;
    let mut x0 = lo;
    loop {
        let c = first + b as f32 * w;
        let x1 = if b < n_out && c < hi { c } else { hi };
        if x1 > x0 && f(x0, x1) {
            return true;
        }
        if x1 >= hi {
            return false;
        }
        x0 = x1;
        b += 1;
    }
}

impl CmRow {
    fn new<M: Math>(
        profiles: &MedullaProfiles<'_>,
        lon: &ScatteredLongitudinal,
        half: Half,
        theta_r: f32,
    ) -> CmRow {
        let mut row = CmRow {
            half,
            theta_in: lon.theta_in::<M>(theta_r),
            branches: lon.branches::<M>(),
            mass: 0.0,
        };
        let n_out = profiles.layout().res.n_out;
        let mut mass = 0.0;
        for (lo, hi) in row.branches.iter().flatten() {
            cm_segments(n_out, *lo, *hi, |x0, x1| {
                let v0 = profiles.cm(half, x0, row.theta_in);
                let v1 = profiles.cm(half, x1, row.theta_in);
                mass += linear_mass(v0, v1, x1 - x0);
                false
            });
        }
        row.mass = mass;
        row
    }

    /// Draws θ_i: θ' by the mass of the interpolated C^M row over both branches, then θ_i on
    /// the branch it fell on.
    fn sample<M: Math>(
        &self,
        profiles: &MedullaProfiles<'_>,
        lon: &ScatteredLongitudinal,
        u: f32,
    ) -> Option<f32> {
        if !(self.mass > 0.0) {
            return None;
        }
        let n_out = profiles.layout().res.n_out;
        let target = unit(u) * self.mass;
        let mut acc = 0.0;
        let mut found = None;
        let mut last = None;
        for (branch, range) in self.branches.iter().enumerate() {
            let Some((lo, hi)) = range else { continue };
            let done = cm_segments(n_out, *lo, *hi, |x0, x1| {
                let v0 = profiles.cm(self.half, x0, self.theta_in);
                let v1 = profiles.cm(self.half, x1, self.theta_in);
                let m = linear_mass(v0, v1, x1 - x0);
                if m > 0.0 {
                    if target - acc <= m {
                        let s = invert_linear(v0, v1, x1 - x0, target - acc);
                        found = Some((branch, x0 + s));
                        return true;
                    }
                    // Rounding past the last segment of positive mass lands at its end.
                    last = Some((branch, x0 + invert_linear(v0, v1, x1 - x0, m)));
                }
                acc += m;
                false
            });
            if done {
                break;
            }
        }
        let (branch, theta_p) = found.or(last)?;
        Some(lon.unrefract::<M>(theta_p, branch))
    }

    /// Density of the θ_i this row draws: C^M_x(θ'(θ_i) | θ'_in)·|dθ'/dθ_i| / Z_x.
    fn density<M: Math>(
        &self,
        profiles: &MedullaProfiles<'_>,
        lon: &ScatteredLongitudinal,
        theta_i: f32,
    ) -> f32 {
        if !(self.mass > 0.0) {
            return 0.0;
        }
        let (theta_p, jac) = lon.refract::<M>(theta_i);
        profiles.cm(self.half, theta_p, self.theta_in) * jac / self.mass
    }
}

impl<'m, 'a, M: Math> Plan<'m, 'a, M> {
    fn new(model: &'m FurBcsdf<'a, M>, theta_r: f32) -> Self {
        let (slice, ext) = model.slice_and_extinction(theta_r);
        let index_matched = model.index_matched();
        let (segs, n_segs) = segments::<M>(&slice, index_matched);
        let l = model.params().l();

        // Proxies: ∫ mean(A_p) dh over each segment (2-point Gauss–Legendre in t) and |H_p|.
        let mut est = [0.0f32; PARTS];
        let mut h_len = [0.0f32; UNSCATTERED_COUNT];
        let mut exists = [false; PARTS];
        let mut enter = None;
        let scattering = model
            .scattering
            .as_ref()
            .filter(|_| ext.medulla_scattering > 0.0);
        let exit = exit_transmittance::<M>(&slice, &ext);
        for (i, seg) in segs[..n_segs].iter().enumerate() {
            if !(seg.t1 > seg.t0) {
                continue;
            }
            let (h0, h1) = h_range(&slice, seg);
            let k = segment_scale(&slice, seg.var);
            for p in 0..UNSCATTERED_COUNT {
                if seg.paths & (1 << p) != 0 {
                    h_len[p] += h1 - h0;
                    exists[p] = true;
                }
            }
            let enters = seg.region == Region::Enter && scattering.is_some();
            if enters {
                enter = Some((i, h1 - h0));
                for (k, e) in exists[UNSCATTERED_COUNT..RESIDUAL_PART]
                    .chunks_mut(2)
                    .enumerate()
                {
                    // TtrtT^s carries f_m, which is 0 when index-matched.
                    let present = !(index_matched && k == 1);
                    e[0] = present;
                    e[1] = present;
                }
            }
            let (mid, half) = (0.5 * (seg.t0 + seg.t1), 0.5 * (seg.t1 - seg.t0));
            for x in PROXY_NODES {
                let t = mid + half * x;
                let chord = Chord::at_variable::<M>(&slice, seg.var, t, seg.region);
                let dh = k * chord.variable_cos(seg.var) * half;
                let att = attenuations::<M>(&slice, &chord, &ext, l);
                for p in 0..UNSCATTERED_COUNT {
                    if seg.paths & (1 << p) != 0 {
                        est[p] += mean(att[p].0) * dh;
                    }
                }
                if enters {
                    if let Some(sp) = scattered_paths::<M>(&slice, &chord, &ext, l, exit) {
                        for k in 0..SCATTERED_COUNT {
                            let v = 0.5 * mean(sp.attenuation[k].0) * dh;
                            est[UNSCATTERED_COUNT + 2 * k] += v;
                            est[UNSCATTERED_COUNT + 2 * k + 1] += v;
                        }
                    }
                }
            }
        }
        if let Some(t) = model.active_residual() {
            est[RESIDUAL_PART] = mean(t.mean(theta_r).0);
            exists[RESIDUAL_PART] = est[RESIDUAL_PART] > 0.0;
        }
        let largest = est.iter().copied().fold(0.0f32, f32::max);
        let floor = PROXY_FLOOR * largest;

        // Longitudinal intervals and masses of the three groups.
        let g = &model.groups;
        let groups: [Longitudinal; 3] = core::array::from_fn(|j| {
            let beta = g.longitudinal[j].beta();
            let center = g.shift[j] - theta_r;
            let reach = CUTOFF_SIGMAS * beta;
            let lo = (center - reach).max(-PI / 2.0);
            let hi = (center + reach).min(PI / 2.0);
            // The mass of M_p = G·(sphere norm) over [lo, hi] (docs/model.md §12).
            let group = [LobeGroup::R, LobeGroup::TT, LobeGroup::TRT][j];
            let mass =
                gaussian_mass(beta, lo - center, hi - center) * g.sphere_norm(group, theta_r);
            Longitudinal {
                center,
                lo,
                hi,
                beta,
                mass,
            }
        });
        let d_mass: [f32; 3] = core::array::from_fn(|j| {
            let beta = g.azimuthal[j].beta();
            gaussian_mass(beta, -CUTOFF_SIGMAS * beta, CUTOFF_SIGMAS * beta)
        });
        let cm = match scattering {
            Some(Scattering {
                profiles,
                longitudinal,
            }) => [Half::Back, Half::Front]
                .map(|h| Some(CmRow::new::<M>(profiles, longitudinal, h, theta_r))),
            None => [None, None],
        };

        let mut weights = [0.0f32; PARTS];
        for (i, w) in weights.iter_mut().enumerate() {
            if !exists[i] || largest <= 0.0 {
                continue;
            }
            let proxy = est[i].max(floor);
            *w = if i < UNSCATTERED_COUNT {
                proxy * groups[Lobe::unscattered_group(i) as usize].mass
            } else if i == RESIDUAL_PART {
                proxy * groups[LobeGroup::TRT as usize].mass
            } else {
                let half = (i - UNSCATTERED_COUNT) % 2;
                match cm[half] {
                    Some(row) if row.mass > 0.0 => proxy,
                    _ => 0.0,
                }
            };
            if !(w.is_finite() && *w > 0.0) {
                *w = 0.0;
            }
        }
        let total = weights.iter().sum();
        Plan {
            model,
            slice,
            ext,
            segs,
            n_segs,
            weights,
            total,
            h_len,
            enter,
            groups,
            d_mass,
            cm,
        }
    }

    /// The per-path constants c_p of the φ density integral at θ_i: part probability ×
    /// θ_i density / |H_p| (/ the D_p normaliser), and the same for the scattered lobes.
    fn coefficients(
        &self,
        theta_i: f32,
        theta_r: f32,
    ) -> ([f32; UNSCATTERED_COUNT], [f32; SCATTERED_COUNT]) {
        let mut c = [0.0f32; UNSCATTERED_COUNT];
        let mut cs = [0.0f32; SCATTERED_COUNT];
        if !(self.total > 0.0) {
            return (c, cs);
        }
        let inv_total = 1.0 / self.total;
        let mut theta_density = [0.0f32; 3];
        for (j, d) in theta_density.iter_mut().enumerate() {
            let lon = &self.groups[j];
            if lon.mass > 0.0 && theta_i >= lon.lo && theta_i <= lon.hi {
                let group = [LobeGroup::R, LobeGroup::TT, LobeGroup::TRT][j];
                *d = self.model.longitudinal(group, theta_i, theta_r) / lon.mass;
            }
        }
        for (p, cp) in c.iter_mut().enumerate() {
            let j = Lobe::unscattered_group(p) as usize;
            if self.weights[p] > 0.0 && self.h_len[p] > 0.0 {
                *cp = self.weights[p] * inv_total * theta_density[j]
                    / (self.h_len[p] * self.d_mass[j]);
            }
        }
        if let (Some(s), Some((_, len))) = (self.model.scattering.as_ref(), self.enter) {
            let dens: [f32; 2] = core::array::from_fn(|x| match &self.cm[x] {
                Some(row) => row.density::<M>(&s.profiles, &s.longitudinal, theta_i),
                None => 0.0,
            });
            for (k, ck) in cs.iter_mut().enumerate() {
                let i = UNSCATTERED_COUNT + 2 * k;
                let v = self.weights[i] * dens[0] + self.weights[i + 1] * dens[1];
                if v > 0.0 && len > 0.0 {
                    *ck = v * inv_total / len;
                }
            }
        }
        (c, cs)
    }

    /// Density of the residual part at (θ_i, φ): its probability × TRT's θ_i density ×
    /// D_res's channel mean (0 without a residual).
    fn residual_density(&self, theta_i: f32, theta_r: f32, phi: f32) -> f32 {
        let w = self.weights[RESIDUAL_PART];
        let lon = &self.groups[LobeGroup::TRT as usize];
        let Some(t) = self.model.active_residual() else {
            return 0.0;
        };
        if !(w > 0.0 && self.total > 0.0 && lon.mass > 0.0) || theta_i < lon.lo || theta_i > lon.hi
        {
            return 0.0;
        }
        let theta = self.model.longitudinal(LobeGroup::TRT, theta_i, theta_r) / lon.mass;
        w / self.total * theta * t.phi_density(theta_r, phi)
    }

    /// Draws (θ_i, φ) and the family.
    fn draw(&self, theta_r: f32, u: [f32; 3]) -> Option<SampledDirection> {
        let (part, u0) = choose(&self.weights, u[0])?;
        let negative = u0 < 0.5;
        let u0 = unit(if negative { 2.0 * u0 } else { 2.0 * u0 - 1.0 });
        let (theta_i, phi, family) = if part == RESIDUAL_PART {
            let t = self.model.active_residual()?;
            let lon = &self.groups[LobeGroup::TRT as usize];
            let theta_i = lon.center
                + sample_gaussian(lon.beta, lon.lo - lon.center, lon.hi - lon.center, u[1])?;
            (theta_i, t.sample_abs_phi(theta_r, u[2]), LobeFamily::TRT)
        } else if part < UNSCATTERED_COUNT {
            let j = Lobe::unscattered_group(part) as usize;
            let lon = &self.groups[j];
            let theta_i = lon.center
                + sample_gaussian(lon.beta, lon.lo - lon.center, lon.hi - lon.center, u[1])?;
            // h uniform over the segments where the path exists, by their h-length.
            let mut lens = [0.0f32; 3];
            for (i, seg) in self.segs[..self.n_segs].iter().enumerate() {
                if seg.paths & (1 << part) != 0 && seg.t1 > seg.t0 {
                    let (h0, h1) = h_range(&self.slice, seg);
                    lens[i] = h1 - h0;
                }
            }
            let (i, uh) = choose(&lens, u0)?;
            let chord = self.chord_at(i, uh);
            let az = exit_azimuths(&chord)[part];
            let beta = self.model.groups.azimuthal[j].beta();
            let reach = CUTOFF_SIGMAS * beta;
            let delta = sample_gaussian(beta, -reach, reach, u[2])?;
            let family = LobeFamily::of(Lobe::UNSCATTERED[part]);
            (theta_i, az + delta, family)
        } else {
            let (s, (seg, _)) = (self.model.scattering.as_ref()?, self.enter?);
            let k = (part - UNSCATTERED_COUNT) / 2;
            let half = (part - UNSCATTERED_COUNT) % 2;
            let theta_i = self.cm[half]?.sample::<M>(&s.profiles, &s.longitudinal, u[1])?;
            let chord = self.chord_at(seg, u0);
            let l = self.model.params().l();
            let exit = exit_transmittance::<M>(&self.slice, &self.ext);
            let sp = scattered_paths::<M>(&self.slice, &chord, &self.ext, l, exit)?;
            let row = s.profiles.n_row(self.model.sigma_n(&self.slice), sp.h_m);
            let psi = s.profiles.sample_psi(&row, u[2])?;
            (theta_i, PI + sp.rotation[k] + psi, LobeFamily::Scattered)
        };
        let phi = wrap_angle(if negative { -phi } else { phi });
        let angles = Angles::new(theta_i.clamp(-PI / 2.0, PI / 2.0), theta_r, phi).ok()?;
        Some(SampledDirection { angles, family })
    }

    /// The chord at fraction `u` of segment `i`'s h-range (h uniform).
    fn chord_at(&self, i: usize, u: f32) -> Chord {
        let seg = &self.segs[i];
        let (h0, h1) = h_range(&self.slice, seg);
        let k = segment_scale(&self.slice, seg.var);
        let h = h0 + unit(u) * (h1 - h0);
        let t = if h >= k {
            PI / 2.0
        } else {
            asin_clamped::<M>(h / k)
        };
        Chord::at_variable::<M>(&self.slice, seg.var, t.clamp(seg.t0, seg.t1), seg.region)
    }
}

fn mean(c: [f32; 3]) -> f32 {
    (c[0] + c[1] + c[2]) * (1.0 / 3.0)
}
