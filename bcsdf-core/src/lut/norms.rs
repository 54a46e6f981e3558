//! The sphere-normalisation section of a LUT (format version 4, docs/lut.md "The 1/Z_g
//! table", docs/model.md §12): for each cuticle group g, 1/Z_g(θ_r) at uniformly spaced
//! nodes θ_r ∈ [−π/2, π/2], stored after the sampling section as little-endian f32, node by
//! node with the three groups adjacent (R, TT, TRT).
//!
//! Z_g(θ_r) is the mass on the sphere of the baked M_g — the linear interpolant of table `M`
//! over x = θ_i + θ_r — as S weighs it:
//!
//! Z_g(θ_r) = ∫_{−π/2}^{π/2} M_g(θ_i + θ_r)·min(1, cos²θ_i / 10⁻⁴) dθ_i,
//!
//! the factor being S's pole guard 1/max(cos²θ_i, 10⁻⁴) times the cos²θ_i of the furnace
//! (docs/model.md §8). It is the interpolant's mass between the range ends, from the `M`
//! prefix sums of the sampling section ([`super::cdf`]), less each pole sliver's loss
//! ∫₀^{s_c} M_g·(1 − sin²s/10⁻⁴) ds (s the distance to the pole, s_c = [`POLE_SLIVER`]),
//! integrated exactly: the sliver split at the table's nodes, four-point Gauss–Legendre on
//! each piece (M_g linear there, 1 − sin²s a polynomial of degree 6 to f32 precision, so
//! the rule is exact). Z_g is floored at [`MIN_SPHERE_MASS`] as the analytic closure does.
//!
//! The energy closure's evaluator multiplies M_g by 1/Z_g interpolated linearly at θ_r: one
//! axis location and six f32 reads per query instead of the per-query prefix-sum work of
//! format 3. The section is derived data, like the sampling section: [`super::seal`] writes
//! it, [`super::validate`] recomputes it and requires the same bits. It is stored for every
//! LUT; the report closure does not read it.

use super::{cdf::Density, cdf::Nodes, LutResolution, TABLE_COUNT};
use crate::longitudinal::MIN_SPHERE_MASS;
use crate::math::PI;
use crate::model::{MIN_COS2_THETA_I, POLE_SLIVER};
use crate::sample1d::linear_mass;

/// Values per node of the section (one per cuticle group).
pub const NORM_GROUPS: usize = 3;

impl LutResolution {
    /// Nodes of the 1/Z_g table over θ_r ∈ [−π/2, π/2]: as many as table `M` has over twice
    /// that span, so the spacing is half of `M`'s (docs/lut.md gives the error it was chosen
    /// by).
    #[must_use]
    pub fn n_norm(&self) -> usize {
        self.n_sum as usize
    }

    /// Byte offset of the 1/Z_g section (after the sampling section).
    #[must_use]
    pub fn norm_start(&self) -> usize {
        self.sampling_start() + 4 * self.sampling_values()
    }

    /// Number of f32 values of the 1/Z_g section.
    #[must_use]
    pub fn norm_values(&self) -> usize {
        NORM_GROUPS * self.n_norm()
    }
}

/// Gauss–Legendre abscissae on [0, 1] and weights (summing to 1), four points.
const GAUSS4: [(f32, f32); 4] = [
    (0.069_431_84, 0.173_927_42),
    (0.330_009_5, 0.326_072_58),
    (0.669_990_5, 0.326_072_58),
    (0.930_568_16, 0.173_927_42),
];

/// Table `M` as the linear interpolant over x ∈ [−π, π], with its running integral.
struct MInterpolant<'b> {
    nodes: Nodes<'b>,
    /// The `M` prefix sums (little-endian f32, [`Density::M`] order, one per node).
    prefix: &'b [u8],
    n: usize,
    step: f32,
    inv_step: f32,
}

impl MInterpolant<'_> {
    /// Lower node and offset (radians) of x, clamped to the axis.
    fn locate(&self, x: f32) -> (usize, f32) {
        let u = ((x + PI) * self.inv_step).clamp(0.0, (self.n - 1) as f32);
        let j = (libm::floorf(u) as usize).min(self.n - 2);
        (j, (u - j as f32) * self.step)
    }

    /// M_g at x.
    fn value(&self, g: usize, x: f32) -> f32 {
        let (j, off) = self.locate(x);
        let (v0, v1) = (
            self.nodes.value(Density::M(g), 0, j),
            self.nodes.value(Density::M(g), 0, j + 1),
        );
        v0 + (v1 - v0) * (off * self.inv_step)
    }

    /// ∫ M_g from −π to x: the prefix sum at the lower node plus the partial segment.
    fn cdf(&self, g: usize, x: f32) -> f32 {
        let (j, off) = self.locate(x);
        let at = 4 * (g * self.n + j);
        let prefix = match self.prefix.get(at..at + 4) {
            Some(b) => f32::from_le_bytes([b[0], b[1], b[2], b[3]]),
            None => 0.0,
        };
        let v0 = self.nodes.value(Density::M(g), 0, j);
        prefix + linear_mass(v0, self.value(g, x), off)
    }

    /// The pole sliver's loss ∫₀^{s_c} M_g(pole + dir·s)·(1 − sin²s/10⁻⁴) ds, exactly (see
    /// the module documentation): the pieces between the table nodes inside the sliver,
    /// four Gauss–Legendre points each.
    fn sliver_loss(&self, g: usize, pole: f32, dir: f32) -> f32 {
        // The sliver's ends in node units, and the node boundaries between them.
        let node = |x: f32| (x + PI) * self.inv_step;
        let (a, b) = (node(pole), node(pole + dir * POLE_SLIVER));
        let (lo, hi) = (a.min(b), a.max(b));
        let mut loss = 0.0;
        let mut start = lo;
        while start < hi {
            let end = (libm::floorf(start) + 1.0).min(hi);
            let len = (end - start) * self.step;
            for (t, w) in GAUSS4 {
                let x = -PI + (start + t * (end - start)) * self.step;
                let s = (x - pole).abs().min(POLE_SLIVER);
                let sin = libm::sinf(s);
                let keep = (sin * sin * (1.0 / MIN_COS2_THETA_I)).min(1.0);
                loss += w * len * self.value(g, x) * (1.0 - keep);
            }
            start = end;
        }
        loss
    }

    /// 1/Z_g(θ_r) (see the module documentation).
    fn inv_sphere_mass(&self, g: usize, theta_r: f32) -> f32 {
        let (lo, hi) = (theta_r - PI / 2.0, theta_r + PI / 2.0);
        let inside = self.cdf(g, hi) - self.cdf(g, lo);
        let z = inside - self.sliver_loss(g, lo, 1.0) - self.sliver_loss(g, hi, -1.0);
        1.0 / z.max(MIN_SPHERE_MASS)
    }
}

/// θ_r of node k of the 1/Z_g table.
#[must_use]
pub fn norm_node(res: &LutResolution, k: usize) -> f32 {
    let last = (res.n_norm() - 1) as f32;
    -PI / 2.0 + PI * (k as f32 / last)
}

/// Computes every value of the section in order (node, then group) from the tables and the
/// `M` prefix sums of the sampling section of `blob`, and hands it to `sink` with its index.
fn for_each_norm(
    blob: &[u8],
    res: LutResolution,
    scales: [f32; TABLE_COUNT],
    mut sink: impl FnMut(usize, f32),
) {
    let n = res.n_sum as usize;
    let prefix = res.prefix_range(Density::M(0)).start;
    let m = MInterpolant {
        nodes: Nodes::new(blob, res, scales),
        prefix: blob.get(prefix..).unwrap_or(&[]),
        n,
        step: res.density_step(Density::M(0)),
        inv_step: (n - 1) as f32 * (1.0 / (2.0 * PI)),
    };
    for k in 0..res.n_norm() {
        let theta_r = norm_node(&res, k);
        for g in 0..NORM_GROUPS {
            sink(NORM_GROUPS * k + g, m.inv_sphere_mass(g, theta_r));
        }
    }
}

/// Writes the 1/Z_g section of `blob` (header, tables and sampling section filled in).
pub(super) fn write(blob: &mut [u8], res: LutResolution, scales: [f32; TABLE_COUNT]) {
    let start = res.norm_start();
    let (before, section) = blob.split_at_mut(start.min(blob.len()));
    for_each_norm(before, res, scales, |i, v| {
        if let Some(dst) = section.get_mut(4 * i..4 * i + 4) {
            dst.copy_from_slice(&v.to_le_bytes());
        }
    });
}

/// Checks that the 1/Z_g section of `blob` holds exactly the values its tables give; returns
/// the index of the first that differs.
pub(super) fn check(
    blob: &[u8],
    res: LutResolution,
    scales: [f32; TABLE_COUNT],
) -> Result<(), usize> {
    let start = res.norm_start();
    let mut bad = None;
    for_each_norm(blob, res, scales, |i, v| {
        let at = start + 4 * i;
        let stored = blob
            .get(at..at + 4)
            .map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]));
        if bad.is_none() && stored != Some(v.to_bits()) {
            bad = Some(i);
        }
    });
    match bad {
        Some(i) => Err(i),
        None => Ok(()),
    }
}
