//! [`DualLut::eval`]: the dual-scattering term from the stored node quantities
//! (docs/model.md §13), channels in the lanes of `[f32; 4]` rows so that the per-channel work
//! (lerps, the six Gaussians) runs as straight-line lane loops.

use super::blob::DualColour;
use super::blob::{A_F2, BACK, BETA_F, DELTA_B, FRONT, LOG2_DECAY, MEAN, SD, SIGMA_B0};
use super::coat::{backscatter_factor, downward_flux, power_of_decay};
use super::{theta_position, Density, DualLut, Fibers, MIN_VARIANCE, PHI_NODES};
use crate::absorption::Absorption;
use crate::frame::{polynomial_angles, AngleError, Angles, Vec3};
use crate::lobes::FAMILY_COUNT;
use crate::math::{
    cos_within_half_pi, erf_polynomial, exp_neg_saturating, rsqrt_newton, wrap_angle, Libm, PI,
};
use crate::model::inv_cos2_theta_i;
use crate::spectrum::Rgb;
use core::f32::consts::FRAC_1_SQRT_2;

type Lanes = [f32; 4];

/// Lanes of the spread term's Gaussians: four per family and four for the backscatter.
const SPREAD_LANES: usize = 4 * (FAMILY_COUNT + 1);

/// The weights of the corners (k, j), (k, j + 1), (k + 1, j), (k + 1, j + 1) of a bilinear
/// lookup at fractions `w` (θ) and `v` (φ).
#[inline(always)]
fn bilinear_weights(w: f32, v: f32) -> [f32; 4] {
    [(1.0 - w) * (1.0 - v), (1.0 - w) * v, w * (1.0 - v), w * v]
}

/// 1/√(2π).
const INV_SQRT_TAU: f32 = 0.398_942_3;

/// Lower bound of the mass [`gauss_reachable`] divides by: a lobe centred far outside the
/// reachable range is not blown up.
const MIN_REACHABLE_MASS: f32 = 0.05;

/// The normalised Gaussian G(d; √v) = e^(−d²/2v)/√(2πv) per lane, divided by its mass over
/// the x = θ_i + θ_r the caller can reach (θ_i ∈ [−π/2, π/2]), given d = x − mean at
/// `ti` = θ_i. v is kept in [[`MIN_VARIANCE`], 1e30]; with s = 1/√v ([`rsqrt_newton`]),
/// G = e^(−(ds)²/2)·s/√(2π), and the mass is ½(erf z₊ − erf z₋), z_± = (d − θ_i ± π/2)·s/√2
/// ([`erf_polynomial`]), kept at or above [`MIN_REACHABLE_MASS`]. No square root, no branch:
/// the lane loop vectorises.
#[inline(always)]
pub(super) fn gauss_reachable<const L: usize>(d: &[f32; L], v: &[f32; L], ti: f32) -> [f32; L] {
    let mut out = [0.0f32; L];
    for c in 0..L {
        let s = rsqrt_newton(v[c].clamp(MIN_VARIANCE, 1e30));
        let z = d[c] * s;
        let g = exp_neg_saturating(0.5 * z * z) * s * INV_SQRT_TAU;
        let centre = (d[c] - ti) * s * FRAC_1_SQRT_2;
        let half_range = 0.5 * PI * s * FRAC_1_SQRT_2;
        let mass =
            0.5 * (erf_polynomial(centre + half_range) - erf_polynomial(centre - half_range));
        out[c] = g / mass.max(MIN_REACHABLE_MASS);
    }
    out
}

impl DualLut {
    /// Per RGB channel, `at(node)` read at the channel's two absorption nodes of the located
    /// colour and linear between them, v₀ + (v₁ − v₀)·w. Lane 3 is 0. The one place the
    /// absorption axis is interpolated; [`DualLut::field`], [`DualLut::rho2`] and
    /// [`DualLut::n_g`] say what is read at a node.
    #[inline(always)]
    fn across_colour(&self, col: &DualColour, at: impl Fn(usize) -> f32) -> Lanes {
        let mut out = [0.0f32; 4];
        for (c, o) in out.iter_mut().take(3).enumerate() {
            let (a, wa) = (col.node[c], col.w[c]);
            let (v0, v1) = (at(a), at(a + 1));
            *o = v0 + (v1 - v0) * wa;
        }
        out
    }

    /// Field `f` at θ and the located colour (per channel: linear between the θ nodes,
    /// clamped to the end nodes, NaN reads node 0; then along the absorption axis,
    /// [`DualLut::across_colour`]). Lane 3 is 0.
    #[inline(always)]
    fn field(&self, col: &DualColour, (k, w): (usize, f32), f: usize) -> Lanes {
        self.across_colour(col, |a| {
            let n = &self.nodes[a];
            n[k][f] + (n[k + 1][f] - n[k][f]) * w
        })
    }

    /// The coat's ρ² at θ and the colour ([`super::coat::node_coat`], derived per node at
    /// decode), interpolated like [`DualLut::field`].
    #[inline(always)]
    fn rho2(&self, col: &DualColour, (k, w): (usize, f32)) -> Lanes {
        self.across_colour(col, |a| {
            let r = &self.coat[a];
            r[k] + (r[k + 1] - r[k]) * w
        })
    }

    /// N^G of family `g` at θ node `k` and |φ| node `j` (bilinear with the corner weights
    /// `w`, which [`bilinear_weights`] computes once for the four families), then along the
    /// absorption axis ([`DualLut::across_colour`]).
    #[inline(always)]
    fn n_g(&self, col: &DualColour, g: usize, k: usize, j: usize, w: &[f32; 4]) -> Lanes {
        self.across_colour(col, |a| {
            let t = &self.n_g[a][g];
            w[0] * t[k][j] + w[1] * t[k][j + 1] + w[2] * t[k + 1][j] + w[3] * t[k + 1][j + 1]
        })
    }

    /// [`DualLut::eval_located`] at the preset's own colour ([`DualLut::absorption`]).
    #[must_use]
    pub fn eval(&self, angles: &Angles, fibers: Fibers, density: Density) -> Rgb {
        self.eval_located(angles, fibers, density, &self.default_at)
    }

    /// [`DualLut::eval_located`] at colour `absorption` (each RGB channel reads the
    /// absorption axis at its own σ_ca).
    #[must_use]
    pub fn eval_at(
        &self,
        angles: &Angles,
        fibers: Fibers,
        density: Density,
        absorption: &Absorption,
    ) -> Rgb {
        self.eval_located(angles, fibers, density, &self.locate(absorption))
    }

    /// The dual-scattering term to add to single scattering (docs/model.md §13), RGB, in S's
    /// units (the caller multiplies by cos θ_i and the light's radiance like S).
    ///
    /// `fibers` holds n, the fibers between the shading point and the light (the shadow ray's
    /// count, or an engine's deep-opacity-map count; fractional values are allowed), and m,
    /// the fibers beyond the point along −ω_i (the coat below), which the term takes as the
    /// neighbourhood's m + 1 layers ([`super::coat::coat_below_layers`]; m in the formulas
    /// below is those layers). With V = clamp(1 − n, 0, 1)
    /// the fraction of direct light (what a shadow ray gives), the shading is S·V + this
    /// term, which is
    ///
    /// V·d_b·f_back(0) + (T_f − V)·d_f·(f_s^scatter(σ_f²) + d_b·f_back(σ_f²)),
    ///
    /// - T_f = μⁿ(1 − ρ²μ²ᵐ)/(1 − ρ²μ²⁽ⁿ⁺ᵐ⁾) ([`super::coat::downward_flux`]), μ the stored
    ///   decay and ρ² derived from μ and ā_f at the θ nodes ([`super::coat::node_coat`], at
    ///   decode) and interpolated between them, at −θ_i (the light's path leaves the fibers
    ///   above at θ ≈ −θ_i); σ_f² = n·β_f²(−θ_i);
    /// - f_s^scatter(s²) = Σ_g N^G_g(θ_r, φ)·Ĝ(x − mean_g; sd_g² + s²)/cos²θ_i, x = θ_i + θ_r;
    /// - f_back(s²) = A·k_m·Ĝ(x − Δ_b; σ_b² + s²)/(π cos²θ_i), σ_b = (1 + d_b ā_f²)·σ_b0, A the
    ///   stored back-half or front-half energy of the local backscatter at θ_r and k_m its
    ///   factor for the m fibers below the point's neighbourhood ([`super::coat::backscatter_factor`],
    ///   from ρ² interpolated like T_f's and μ at θ_r);
    /// - Ĝ a Gaussian divided by its mass over the x the caller can reach at this θ_r
    ///   (θ_i ∈ [−π/2, π/2]; the mass kept at or above 0.05), so that each lobe returns its
    ///   stored energy.
    ///
    /// Every quantity is read at the located colour `colour` ([`DualLut::locate`]): each RGB
    /// channel interpolates its node quantities linearly along the absorption axis (in
    /// [`super::axis_coordinate`]) at its own σ_ca.
    ///
    /// Contract: the counts as in [`Fibers`]; the density factors as in [`Density`]. The
    /// result is finite and ≥ 0 for every input; nothing panics or allocates.
    #[must_use]
    pub fn eval_located(
        &self,
        angles: &Angles,
        fibers: Fibers,
        density: Density,
        colour: &DualColour,
    ) -> Rgb {
        let col = colour;
        let (n, m) = fibers.sanitized();
        let (d_f, d_b) = density.sanitized();
        let (ti, tr, phi) = (angles.theta_i(), angles.theta_r(), angles.phi());
        let x = ti + tr;
        // cos θ_i by the baked evaluator's polynomial (θ_i ∈ [−π/2, π/2]), as in the shader.
        let inv_cos2 = inv_cos2_theta_i(cos_within_half_pi(ti));
        let direct = (1.0 - n).clamp(0.0, 1.0);
        let here = theta_position(tr);
        let abs_phi = wrap_angle(phi).abs();
        let back_half = abs_phi < 0.5 * PI;
        let stored = self.field(col, here, if back_half { BACK } else { FRONT });
        // The coat below at θ_r: m layers instead of the semi-infinite stack.
        let log2_mu_here = self.field(col, here, LOG2_DECAY);
        let a_f2 = self.field(col, here, A_F2);
        let rho2_here = self.rho2(col, here);
        // Lane loops, not `array::from_fn` closures: those were left as calls per lane.
        let mut half = [0.0f32; 4];
        for c in 0..4 {
            let mu = power_of_decay(log2_mu_here[c], 1.0);
            let mu_2m = power_of_decay(log2_mu_here[c], 2.0 * m);
            half[c] = stored[c] * backscatter_factor(rho2_here[c], mu, mu_2m);
        }
        let sigma_b0 = self.field(col, here, SIGMA_B0);
        let delta = self.field(col, here, DELTA_B);
        let d_back: Lanes = core::array::from_fn(|c| x - delta[c]);
        let v_back: Lanes = core::array::from_fn(|c| {
            let s = (1.0 + d_b * a_f2[c]) * sigma_b0[c];
            s * s
        });
        // f_back without its variance increase, times π cos²θ_i.
        let back_scale = d_b * inv_cos2 / PI;
        let mut out = [0.0f32; 4];
        if direct > 0.0 {
            let g = gauss_reachable(&d_back, &v_back, ti);
            for c in 0..4 {
                out[c] = direct * back_scale * half[c] * g[c];
            }
        }
        if n > 0.0 {
            let along = theta_position(-ti);
            let log2_mu = self.field(col, along, LOG2_DECAY);
            let rho2 = self.rho2(col, along);
            let beta_f = self.field(col, along, BETA_F);
            let mut spread = [0.0f32; 4];
            for c in 0..4 {
                let mu_n = power_of_decay(log2_mu[c], n);
                let mu_2m = power_of_decay(log2_mu[c], 2.0 * m);
                let t_f = downward_flux(mu_n, mu_2m, rho2[c]);
                spread[c] = (t_f - direct).max(0.0) * d_f;
            }
            if spread.iter().any(|&s| s > 0.0) {
                let s2f: Lanes = core::array::from_fn(|c| n * beta_f[c] * beta_f[c]);
                let p = abs_phi * ((PHI_NODES - 1) as f32 / PI);
                let p = if p > 0.0 {
                    p.min((PHI_NODES - 1) as f32)
                } else {
                    0.0
                };
                let j = (p as usize).min(PHI_NODES - 2); // p ∈ [0, PHI_NODES − 1]
                let corners = bilinear_weights(here.1, p - j as f32);
                // The spread term's five Gaussians (one per family, then the spread
                // backscatter) in one lane pass: independent chains the CPU overlaps.
                let mut d = [0.0f32; SPREAD_LANES];
                let mut v = [0.0f32; SPREAD_LANES];
                for g in 0..FAMILY_COUNT {
                    let mean = self.field(col, here, MEAN + g);
                    let sd = self.field(col, here, SD + g);
                    for c in 0..4 {
                        d[4 * g + c] = x - mean[c];
                        v[4 * g + c] = sd[c] * sd[c] + s2f[c];
                    }
                }
                for c in 0..4 {
                    d[4 * FAMILY_COUNT + c] = d_back[c];
                    v[4 * FAMILY_COUNT + c] = v_back[c] + s2f[c];
                }
                let gv = gauss_reachable(&d, &v, ti);
                let mut f_s = [0.0f32; 4];
                for g in 0..FAMILY_COUNT {
                    let ng = self.n_g(col, g, here.0, j, &corners);
                    for c in 0..4 {
                        f_s[c] += ng[c] * gv[4 * g + c];
                    }
                }
                for c in 0..4 {
                    out[c] += spread[c]
                        * (f_s[c] * inv_cos2 + back_scale * half[c] * gv[4 * FAMILY_COUNT + c]);
                }
            }
        }
        // Finite and ≥ 0: NaN and negative lanes are 0, +∞ the largest finite value (lane
        // loop, no branch; not clamp, which passes NaN on).
        #[allow(clippy::manual_clamp)]
        let out: Lanes = core::array::from_fn(|c| out[c].max(0.0).min(f32::MAX));
        Rgb([out[0], out[1], out[2]])
    }

    /// [`DualLut::eval`] from world-space directions toward the light `wi` and the viewer `wr`
    /// and the fiber tangent (any lengths), converted to angles exactly as
    /// [`crate::BakedBcsdf::angles_from_dirs`] and the shader do (the branch-free polynomials,
    /// within about 3e-7 rad of [`Angles::from_directions`]); zero when the directions are
    /// rejected (zero, non-finite, parallel to the tangent).
    #[must_use]
    pub fn eval_dirs(
        &self,
        wi: Vec3,
        wr: Vec3,
        tangent: Vec3,
        fibers: Fibers,
        density: Density,
    ) -> Rgb {
        self.try_eval_dirs(wi, wr, tangent, fibers, density)
            .unwrap_or(Rgb::ZERO)
    }

    /// [`DualLut::eval_dirs`], or why the directions were rejected (one conversion for the
    /// value and the verdict; the C ABI's status comes from it).
    ///
    /// # Errors
    /// The [`AngleError`] of the direction-to-angle conversion.
    pub fn try_eval_dirs(
        &self,
        wi: Vec3,
        wr: Vec3,
        tangent: Vec3,
        fibers: Fibers,
        density: Density,
    ) -> Result<Rgb, AngleError> {
        self.try_eval_dirs_located(wi, wr, tangent, fibers, density, &self.default_at)
    }

    /// [`DualLut::try_eval_dirs`] at a located colour ([`DualLut::locate`]), the value of
    /// [`DualLut::eval_located`].
    ///
    /// # Errors
    /// The [`AngleError`] of the direction-to-angle conversion.
    pub fn try_eval_dirs_located(
        &self,
        wi: Vec3,
        wr: Vec3,
        tangent: Vec3,
        fibers: Fibers,
        density: Density,
        colour: &DualColour,
    ) -> Result<Rgb, AngleError> {
        let [ti, tr, phi] = polynomial_angles::<Libm>(wi, wr, tangent)?;
        Ok(self.eval_located(&Angles::new(ti, tr, phi)?, fibers, density, colour))
    }
}
