//! [`ResidualTable`]: the residual table of one parameter set, borrowed from caller memory,
//! and its lookups (docs/model.md §12, "Residual"; layout in the parent module).

use super::ResidualLayout;
use crate::lobes::LobeGroup;
use crate::math::PI;
use crate::medulla::ProfileError;
use crate::params::FurParams;
use crate::spectrum::Rgb;

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

    /// The far field's ⟨A_res⟩_h at θ_r: linear in θ_r between the mean nodes
    /// ([`ResidualLayout::mean_node`], finer than the rows).
    #[must_use]
    pub fn mean(&self, theta_r: f32) -> Rgb {
        let n = self.layout.n_mean();
        let u = self.layout.mean_position(theta_r);
        let (k, w) = if u.is_finite() {
            let k = (u as usize).min(n - 2);
            (k, u - k as f32)
        } else {
            (0, 0.0)
        };
        let means = &self.data[self.layout.means_offset()..];
        Self::rgb(means, k) * (1.0 - w) + Self::rgb(means, k + 1) * w
    }

    /// The rows' own ⟨A_res⟩_h at θ_r (linear in θ_r between the rows): the h-mean of the
    /// offsets' values there.
    fn row_mean(&self, theta_r: f32) -> Rgb {
        let (a, b, w) = self.rows(theta_r);
        let n_h = self.layout.n_h;
        Self::rgb(a, n_h) * (1.0 - w) + Self::rgb(b, n_h) * w
    }

    /// A_res(θ_r, h): the simulation's values at the offsets, linear in θ_r and in |h| between
    /// them (constant beyond the first and last), scaled per channel by
    /// [`ResidualTable::mean`] over their h-mean at θ_r, so that the near field's h-mean is
    /// the far field's ⟨A_res⟩_h at every θ_r (uniform in h where the offsets' mean is 0). The
    /// scale completes the offsets' midpoint rule to the lobes' exact h-means (docs/model.md
    /// §12); it is 1 where E_model(h) has no jumps or steep ends.
    #[must_use]
    pub fn magnitude(&self, theta_r: f32, h: f32) -> Rgb {
        let (mean, rows) = (self.mean(theta_r), self.row_mean(theta_r));
        let mut a = self.row_magnitude(theta_r, h);
        for c in 0..3 {
            a.0[c] = if rows.0[c] > 0.0 {
                a.0[c] * (mean.0[c] / rows.0[c])
            } else {
                mean.0[c]
            };
        }
        a
    }

    /// A_res(θ_r, h) of the rows alone (see [`ResidualTable::magnitude`]).
    fn row_magnitude(&self, theta_r: f32, h: f32) -> Rgb {
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
