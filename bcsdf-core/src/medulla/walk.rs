//! The deterministic Monte Carlo walks that fill the profile tables (docs/model.md §7):
//! photons in the 2D disk for C^N (weighted by their survival of the medulla absorption), in
//! the infinite cylinder for C^M, each table cell from its own PCG32 stream.

use super::{check_len, PhotonBudget, ProfileError, ProfileLayout};
use crate::math::{wrap_angle, PI, TAU};
use crate::rng::{cell_stream, Pcg32};

/// Counts of one simulated cell (for the tests' exact checks).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CellStats {
    /// Photons launched.
    pub launched: u64,
    /// Photons that scattered at least once (and are binned).
    pub scattered: u64,
}

/// Most photons one table cell can count (the histograms accumulate in f32, exact to 2^24);
/// larger budgets are clamped to it.
pub const MAX_PHOTONS_PER_CELL: u32 = 1 << 24;

/// Walks longer than this many scattering events are dropped (never reached in practice for
/// σ ≤ 100; it only guards against an endless loop).
const MAX_EVENTS: u32 = 100_000;

/// Table ids for [`cell_stream`].
const TABLE_CN: u64 = 1;
const TABLE_CM: u64 = 2;

/// Samples the 2D Henyey–Greenstein (wrapped Cauchy) deflection angle.
#[inline]
pub fn sample_hg_2d(g: f32, u: f32) -> f32 {
    let k = (1.0 - g) / (1.0 + g);
    2.0 * libm::atanf(k * libm::tanf(PI * (u - 0.5)))
}

/// Samples cos θ of the 3D Henyey–Greenstein phase function.
#[inline]
pub(super) fn sample_hg_3d_cos(g: f32, u: f32) -> f32 {
    if g.abs() < 1e-4 {
        return 1.0 - 2.0 * u;
    }
    let s = (1.0 - g * g) / (1.0 - g + 2.0 * g * u);
    ((1.0 + g * g - s * s) / (2.0 * g)).clamp(-1.0, 1.0)
}

/// Simulates one C^N cell: photons enter the unit disk at offset `h_m` travelling straight
/// (along −x at y = h_m), scatter with coefficient `sigma` and 2D HG(`g`), and leave when they
/// cross the circle. Only photons that scattered at least once are binned, by the signed
/// rotation ψ of their travel direction (in the exit-azimuth sense of docs/model.md §3: ψ = −Δ of
/// the direction angle), each with weight exp(−`absorption`·ℓ), ℓ its whole path length
/// (absorption coefficient and length per disk radius; weight 1 when `absorption` = 0).
/// Writes into `cn` (`n_psi` long) the summed weights per bin divided by the number of
/// scattered photons and the bin width: the pdf over ψ times the photons' survival, so its
/// integral is their mean survival. Returns the counts.
pub fn simulate_disk_cell(
    sigma: f32,
    h_m: f32,
    g: f32,
    absorption: f32,
    photons: u32,
    stream: u64,
    cn: &mut [f32],
) -> CellStats {
    // The output buffer accumulates the weights first (without absorption they are counts,
    // exact in f32 up to 2^24 photons per cell), so no scratch memory is needed.
    let n_psi = cn.len();
    if n_psi == 0 {
        return CellStats::default();
    }
    let photons = photons.min(MAX_PHOTONS_PER_CELL);
    cn.fill(0.0);
    let mut rng = Pcg32::new(stream, stream.rotate_left(17));
    let mut stats = CellStats::default();
    let h = h_m.clamp(-1.0, 1.0);
    for _ in 0..photons {
        stats.launched += 1;
        let (mut x, mut y) = (libm::sqrtf(1.0 - h * h), h);
        let mut angle = PI; // travel direction angle
        let (mut dx, mut dy) = (-1.0f32, 0.0f32);
        let mut len = 0.0f32;
        let mut events = 0u32;
        loop {
            // Distance to the circle along (dx, dy) from inside: t = −p·d + √((p·d)² + 1 − |p|²).
            let pd = x * dx + y * dy;
            let t_exit = -pd + libm::sqrtf((pd * pd + 1.0 - (x * x + y * y)).max(0.0));
            let s = if sigma > 0.0 {
                -libm::logf(rng.uniform_open0()) / sigma
            } else {
                f32::INFINITY
            };
            if s >= t_exit {
                len += t_exit;
                break;
            }
            x += s * dx;
            y += s * dy;
            len += s;
            events += 1;
            if events > MAX_EVENTS {
                break;
            }
            angle += sample_hg_2d(g, rng.uniform());
            dx = libm::cosf(angle);
            dy = libm::sinf(angle);
        }
        if events == 0 || events > MAX_EVENTS {
            continue;
        }
        stats.scattered += 1;
        let psi = wrap_angle(PI - angle);
        let bin = (((psi + PI) / TAU) * n_psi as f32) as usize;
        let bin = bin.min(n_psi - 1);
        cn[bin] += if absorption > 0.0 {
            libm::expf(-absorption * len)
        } else {
            1.0
        };
    }
    let width = TAU / n_psi as f32;
    // A cell where nothing scattered (σ → 0 or h_m → 1) gets the uniform pdf times the
    // survival along the straight chord, the single-scattering limit.
    let empty = libm::expf(-absorption * 2.0 * libm::sqrtf(1.0 - h * h)) / TAU;
    for c in cn.iter_mut() {
        *c = if stats.scattered > 0 {
            *c / (stats.scattered as f32 * width)
        } else {
            empty
        };
    }
    stats
}

/// Simulates one C^M row: photons enter the infinite unit cylinder at uniformly distributed
/// offsets with travel direction at longitudinal angle `theta_in`, scatter with coefficient
/// `sigma` and 3D HG(`g`), and leave through the side. Photons that scattered at least once
/// are binned by the longitudinal angle of their exit travel direction, into `back` when the
/// exit heads back toward the source (azimuth within 90°) and `front` otherwise; each half is
/// normalised to unit integral over [−π/2, π/2]. Returns the counts (both halves).
pub fn simulate_cylinder_row(
    sigma: f32,
    theta_in: f32,
    g: f32,
    photons: u32,
    stream: u64,
    back: &mut [f32],
    front: &mut [f32],
) -> CellStats {
    let n_out = back.len().min(front.len());
    if n_out == 0 {
        return CellStats::default();
    }
    let photons = photons.min(MAX_PHOTONS_PER_CELL);
    back[..n_out].fill(0.0);
    front[..n_out].fill(0.0);
    let mut rng = Pcg32::new(stream, stream.rotate_left(29));
    let mut stats = CellStats::default();
    let (st, ct) = (libm::sinf(theta_in), libm::cosf(theta_in));
    for _ in 0..photons {
        stats.launched += 1;
        let h = 2.0 * rng.uniform() - 1.0;
        let (mut x, mut y) = (libm::sqrtf(1.0 - h * h), h);
        let (mut dx, mut dy, mut dz) = (-ct, 0.0f32, st);
        let mut events = 0u32;
        loop {
            let a = dx * dx + dy * dy;
            let t_exit = if a < 1e-12 {
                f32::INFINITY
            } else {
                let pd = x * dx + y * dy;
                let c = x * x + y * y - 1.0;
                (-pd + libm::sqrtf((pd * pd - a * c).max(0.0))) / a
            };
            let s = if sigma > 0.0 {
                -libm::logf(rng.uniform_open0()) / sigma
            } else {
                f32::INFINITY
            };
            if s >= t_exit {
                break;
            }
            x += s * dx;
            y += s * dy;
            events += 1;
            if events > MAX_EVENTS {
                break;
            }
            // New direction: HG polar angle about the old one, uniform azimuth.
            let cos_t = sample_hg_3d_cos(g, rng.uniform());
            let sin_t = libm::sqrtf((1.0 - cos_t * cos_t).max(0.0));
            let az = TAU * rng.uniform();
            let (sa, ca) = (libm::sinf(az), libm::cosf(az));
            // Orthonormal basis (t1, t2) perpendicular to d (Duff et al. 2017).
            let sign = if dz >= 0.0 { 1.0 } else { -1.0 };
            let aa = -1.0 / (sign + dz);
            let bb = dx * dy * aa;
            let t1 = [1.0 + sign * dx * dx * aa, sign * bb, -sign * dx];
            let t2 = [bb, sign + dy * dy * aa, -dy];
            let nx = sin_t * (ca * t1[0] + sa * t2[0]) + cos_t * dx;
            let ny = sin_t * (ca * t1[1] + sa * t2[1]) + cos_t * dy;
            let nz = sin_t * (ca * t1[2] + sa * t2[2]) + cos_t * dz;
            let norm = libm::sqrtf(nx * nx + ny * ny + nz * nz);
            dx = nx / norm;
            dy = ny / norm;
            dz = nz / norm;
        }
        if events == 0 || events > MAX_EVENTS {
            continue;
        }
        stats.scattered += 1;
        let theta_out = libm::asinf(dz.clamp(-1.0, 1.0));
        let bin = (((theta_out + PI / 2.0) / PI) * n_out as f32) as usize;
        let out = if dx > 0.0 { &mut *back } else { &mut *front };
        out[bin.min(n_out - 1)] += 1.0;
    }
    let width = PI / n_out as f32;
    for out in [back, front] {
        let total: f32 = out[..n_out].iter().sum();
        for v in out[..n_out].iter_mut() {
            *v = if total > 0.0 {
                *v / (total * width)
            } else {
                1.0 / PI
            };
        }
    }
    stats
}

/// Simulates C^N cell `cell` (= k·n_h + j for σ node k and h node j) of `layout` into `cn`
/// (`n_psi` long), with the absorption coefficient k·σ_N per disk radius, k =
/// [`ProfileLayout::absorption`] (docs/model.md §7). An invalid layout or cell simulates
/// nothing.
pub fn generate_cn_cell(
    layout: &ProfileLayout,
    cell: usize,
    budget: &PhotonBudget,
    seed: u64,
    cn: &mut [f32],
) -> CellStats {
    if layout.validate().is_err() || cell >= layout.res.n_sigma * layout.res.n_h {
        return CellStats::default();
    }
    let (k, j) = (cell / layout.res.n_h, cell % layout.res.n_h);
    let sigma = layout.sigma_n_node(k);
    simulate_disk_cell(
        sigma,
        layout.h_node(j),
        layout.g,
        layout.absorption * sigma,
        budget.per_cn_cell,
        cell_stream(seed, TABLE_CN, cell as u64),
        cn,
    )
}

/// Simulates C^M row `row` (θ'_in node) of `layout` into `back` and `front` (each `n_out`).
/// An invalid layout or row simulates nothing.
pub fn generate_cm_row(
    layout: &ProfileLayout,
    row: usize,
    budget: &PhotonBudget,
    seed: u64,
    back: &mut [f32],
    front: &mut [f32],
) -> CellStats {
    if layout.validate().is_err() || row >= layout.res.n_in {
        return CellStats::default();
    }
    simulate_cylinder_row(
        layout.sigma_m,
        layout.theta_in_node(row),
        layout.g,
        budget.per_cm_row,
        cell_stream(seed, TABLE_CM, row as u64),
        back,
        front,
    )
}

/// Generates every table of `layout` sequentially into caller buffers (`cn` of
/// [`ProfileLayout::cn_len`], `cm` of [`ProfileLayout::cm_len`]). The std tools run the same
/// cells in parallel, with identical results.
pub fn generate(
    layout: &ProfileLayout,
    budget: &PhotonBudget,
    seed: u64,
    cn: &mut [f32],
    cm: &mut [f32],
) -> Result<(), ProfileError> {
    layout.validate()?;
    check_len("C^N", layout.cn_len(), cn.len())?;
    check_len("C^M", layout.cm_len(), cm.len())?;
    let n_psi = layout.res.n_psi;
    for (cell, c) in cn.chunks_exact_mut(n_psi).enumerate() {
        generate_cn_cell(layout, cell, budget, seed, c);
    }
    let n_out = layout.res.n_out;
    let (back, front) = cm.split_at_mut(layout.res.n_in * n_out);
    for (row, (b, f)) in back
        .chunks_exact_mut(n_out)
        .zip(front.chunks_exact_mut(n_out))
        .enumerate()
    {
        generate_cm_row(layout, row, budget, seed, b, f);
    }
    Ok(())
}
