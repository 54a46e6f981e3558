//! The validated profile tables and their lookups: C^N interpolated in σ_N, h_m and
//! (circularly) ψ, C^M in θ'_in and θ'_out, and the ψ sampler of the analytic model's
//! scattered lobes.

use super::{check_len, ProfileError, ProfileLayout};
use crate::math::{wrap_angle, PI, TAU};

/// Which half of C^M.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Half {
    /// Exits heading back toward the source (used at φ = 0).
    Back = 0,
    /// The rest (used at φ = ±π).
    Front = 1,
}

/// A prepared C^N lookup at fixed σ_N and h_m ([`MedullaProfiles::n_row`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NRow {
    offsets: [usize; 4],
    weights: [f32; 4],
    flip: bool,
}

/// Validated profiles over borrowed tables: C^N (`[σ][h_m][ψ]`) and C^M
/// (`[half][θ'_in][θ'_out]`), laid out as the [`medulla`](super) documentation says, usually
/// filled by [`generate`](super::generate) for the [`ProfileLayout`] of a parameter set.
///
/// ```
/// use bcsdf_core::medulla::generate;
/// use bcsdf_core::{
///     presets, FurParams, MedullaProfiles, PhotonBudget, ProfileError, ProfileLayout, Resolution,
/// };
///
/// let params = FurParams::new(&presets::find("air-medulla").unwrap().input).unwrap();
/// let res = Resolution { n_sigma: 2, n_h: 4, n_psi: 16, n_in: 3, n_out: 8 };
/// let layout = ProfileLayout::for_params(&params, res);
/// let (mut cn, mut cm) = (vec![0.0; layout.cn_len()], vec![0.0; layout.cm_len()]);
/// let budget = PhotonBudget { per_cn_cell: 2_000, per_cm_row: 2_000 };
/// generate(&layout, &budget, 7, &mut cn, &mut cm).unwrap();
/// let profiles = MedullaProfiles::new(layout, &cn, &cm).unwrap();
///
/// // Each C^N row is a density over ψ times the scattered photons' survival of the medulla
/// // absorption (air-medulla has σ_ma > 0): its integral over the circle is their mean
/// // survival, below 1 and, as their mean path is below 4 radii here, above exp(−k·σ_N·4).
/// let row = profiles.n_row(layout.sigma_n_min, 0.3);
/// let mass = profiles.row_mass(&row);
/// let floor = (-layout.absorption * layout.sigma_n_min * 4.0).exp();
/// assert!(mass < 1.0 && mass > floor, "{mass}");
///
/// // Tables of the wrong size (or with negative or non-finite values) are refused.
/// let short = MedullaProfiles::new(layout, &cn[1..], &cm).unwrap_err();
/// assert_eq!(
///     short,
///     ProfileError::WrongLength { table: "C^N", expected: cn.len(), found: cn.len() - 1 }
/// );
/// ```
#[derive(Clone, Copy, Debug)]
pub struct MedullaProfiles<'a> {
    layout: ProfileLayout,
    cn: &'a [f32],
    cm: &'a [f32],
}

/// Linear interpolation position on `n` nodes spaced `step` apart starting at `x0`:
/// (lower index, weight of the upper), clamped to the ends.
#[inline]
pub(super) fn locate(x: f32, x0: f32, step: f32, n: usize) -> (usize, f32) {
    if n <= 1 || step.is_nan() || step <= 0.0 {
        return (0, 0.0);
    }
    let u = ((x - x0) / step).clamp(0.0, (n - 1) as f32);
    let i = (u as usize).min(n - 2);
    (i, u - i as f32)
}

impl<'a> MedullaProfiles<'a> {
    /// Wraps tables laid out as in the module documentation; sizes, axes and values are
    /// checked, so lookups never read out of bounds.
    pub fn new(
        layout: ProfileLayout,
        cn: &'a [f32],
        cm: &'a [f32],
    ) -> Result<MedullaProfiles<'a>, ProfileError> {
        layout.validate()?;
        check_len("C^N", layout.cn_len(), cn.len())?;
        check_len("C^M", layout.cm_len(), cm.len())?;
        for (table, data) in [("C^N", cn), ("C^M", cm)] {
            if let Some(index) = data.iter().position(|v| !(v.is_finite() && *v >= 0.0)) {
                return Err(ProfileError::BadValue { table, index });
            }
        }
        Ok(MedullaProfiles { layout, cn, cm })
    }

    /// The layout.
    #[must_use]
    pub fn layout(&self) -> &ProfileLayout {
        &self.layout
    }

    /// The raw tables `(C^N, C^M)`.
    #[must_use]
    pub fn tables(&self) -> (&'a [f32], &'a [f32]) {
        (self.cn, self.cm)
    }

    /// Prepares C^N lookups at fixed σ_N and h_m: the four (σ, h) corner rows and their
    /// bilinear weights, with the h → −h symmetry folded in.
    #[must_use]
    pub fn n_row(&self, sigma_n: f32, h_m: f32) -> NRow {
        let r = self.layout.res;
        let sig_step = if r.n_sigma > 1 {
            (self.layout.sigma_n_max - self.layout.sigma_n_min) / (r.n_sigma - 1) as f32
        } else {
            0.0
        };
        let (ks, ws) = locate(sigma_n, self.layout.sigma_n_min, sig_step, r.n_sigma);
        let (jh, wh) = locate(h_m.abs(), 0.0, 1.0 / r.n_h as f32, r.n_h);
        let row = |k: usize, j: usize| (k.min(r.n_sigma - 1) * r.n_h + j.min(r.n_h - 1)) * r.n_psi;
        NRow {
            offsets: [
                row(ks, jh),
                row(ks, jh + 1),
                row(ks + 1, jh),
                row(ks + 1, jh + 1),
            ],
            weights: [
                (1.0 - ws) * (1.0 - wh),
                (1.0 - ws) * wh,
                ws * (1.0 - wh),
                ws * wh,
            ],
            flip: h_m < 0.0,
        }
    }

    /// ψ interpolation position: the two neighbouring bin centres and the upper weight.
    #[inline]
    fn psi_position(&self, row: &NRow, psi: f32) -> (usize, usize, f32) {
        let n_psi = self.layout.res.n_psi;
        let psi = if row.flip { -psi } else { psi };
        // ψ bin centres at −π + (b + ½)·w; circular interpolation between them. u ∈ [−½, n − ½].
        let u = (wrap_angle(psi) + PI) * (n_psi as f32 / TAU) - 0.5;
        let (b0, wp) = if u < 0.0 {
            (n_psi - 1, u + 1.0)
        } else {
            // u ≥ 0: truncation is the floor (through i32: a cheaper conversion than to
            // usize on x86-64, and n_psi ≤ 4096).
            let b = u as i32 as usize;
            (b.min(n_psi - 1), u - b as f32)
        };
        let b1 = if b0 + 1 == n_psi { 0 } else { b0 + 1 };
        (b0, b1, wp)
    }

    /// Interpolates a `[σ][h][ψ]` table along a prepared row at a ψ position.
    #[inline]
    fn at_position(table: &[f32], row: &NRow, (b0, b1, wp): (usize, usize, f32)) -> f32 {
        let mut v = 0.0;
        for (o, wt) in row.offsets.iter().zip(row.weights.iter()) {
            v += wt * (table[o + b0] * (1.0 - wp) + table[o + b1] * wp);
        }
        v
    }

    /// C^N(ψ) along a prepared row (see [`MedullaProfiles::n_row`]).
    #[inline]
    #[must_use]
    pub fn cn_at(&self, row: &NRow, psi: f32) -> f32 {
        Self::at_position(self.cn, row, self.psi_position(row, psi))
    }

    /// ∫ C^N(ψ) dψ over the circle along a prepared row: the scattered photons' mean survival
    /// of the medulla absorption (1 without it: each tabulated row is then a pdf), since linear
    /// interpolation between bin centres keeps the integral; 0 for an all-zero row. Exact for the interpolant: bin width × Σ of the blended
    /// bin values.
    #[must_use]
    pub fn row_mass(&self, row: &NRow) -> f32 {
        let n_psi = self.layout.res.n_psi;
        let mut sum = 0.0;
        for b in 0..n_psi {
            sum += self.row_value(row, b);
        }
        sum * (TAU / n_psi as f32)
    }

    /// The blended row value at bin centre `b` (before the h_m flip).
    #[inline]
    fn row_value(&self, row: &NRow, b: usize) -> f32 {
        let mut v = 0.0;
        for (o, wt) in row.offsets.iter().zip(row.weights.iter()) {
            v += wt * self.cn.get(o + b).copied().unwrap_or(0.0);
        }
        v
    }

    /// Draws ψ from C^N along a prepared row (density [`MedullaProfiles::cn_at`] /
    /// [`MedullaProfiles::row_mass`]): picks a segment between adjacent bin centres (circular)
    /// by its mass and inverts the linear interpolant inside it. `None` for an empty row.
    #[must_use]
    pub fn sample_psi(&self, row: &NRow, u: f32) -> Option<f32> {
        let n_psi = self.layout.res.n_psi;
        let w = TAU / n_psi as f32;
        let total = self.row_mass(row);
        if !(total > 0.0 && total.is_finite()) {
            return None;
        }
        let target = crate::sample1d::unit(u) * total;
        let mut acc = 0.0;
        let mut found = None;
        let mut last = None;
        for b in 0..n_psi {
            let (v0, v1) = (self.row_value(row, b), self.row_value(row, (b + 1) % n_psi));
            let m = crate::sample1d::linear_mass(v0, v1, w);
            if m > 0.0 {
                if target - acc <= m {
                    found = Some((b, crate::sample1d::invert_linear(v0, v1, w, target - acc)));
                    break;
                }
                last = Some((b, crate::sample1d::invert_linear(v0, v1, w, m)));
            }
            acc += m;
        }
        // Bin centre b sits at −π + (b + ½)·w.
        let (b, s) = found.or(last)?;
        let psi = -PI + (b as f32 + 0.5) * w + s;
        let psi = wrap_angle(psi);
        Some(if row.flip { -psi } else { psi })
    }

    /// C^N(ψ | h_m, σ_N, g): pdf over ψ of the rotation of scattered photons times their
    /// survival of the medulla absorption; trilinear, circular in ψ, with
    /// C^N(ψ | −h_m) = C^N(−ψ | h_m).
    #[must_use]
    pub fn cn(&self, sigma_n: f32, h_m: f32, psi: f32) -> f32 {
        self.cn_at(&self.n_row(sigma_n, h_m), psi)
    }

    /// C^M_half(θ'_out | θ'_in, σ_M, g) (travel-direction angles), bilinear, with the
    /// θ → −θ symmetry.
    #[must_use]
    pub fn cm(&self, half: Half, theta_out: f32, theta_in: f32) -> f32 {
        let r = self.layout.res;
        let (out, inn) = if theta_in < 0.0 {
            (-theta_out, -theta_in)
        } else {
            (theta_out, theta_in)
        };
        let (ji, wi) = locate(
            inn,
            0.0,
            self.layout.theta_in_max / (r.n_in - 1) as f32,
            r.n_in,
        );
        let w = PI / r.n_out as f32;
        let (bo, wo) = locate(out, -PI / 2.0 + 0.5 * w, w, r.n_out);
        let base = half as usize * r.n_in * r.n_out;
        let at = |j: usize, b: usize| -> f32 {
            let j = j.min(r.n_in - 1);
            let b = b.min(r.n_out - 1);
            self.cm[base + j * r.n_out + b]
        };
        let row = |j: usize| at(j, bo) * (1.0 - wo) + at(j, bo + 1) * wo;
        row(ji) * (1.0 - wi) + row(ji + 1) * wi
    }
}
