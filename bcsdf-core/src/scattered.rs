//! The scattered component (docs/model.md §6, report eq. 6–12): light that scatters at least once
//! inside the medulla, in three lobes TttT^s, TtrtT^s, TttRttT^s.
//!
//! The report's simplifications hold: the scattered distribution is not changed on its way
//! out through the cortex, the exit ignores the cuticle roughness, and the exit path through
//! the cortex is radial, of length 1 − κ.

use crate::fresnel;
use crate::geometry::{Chord, MedullaEvent, ViewSlice};
use crate::math::{asin_clamped, sqrt_pos, Math, PI};
use crate::medulla::{Half, MedullaProfiles, NRow, MAX_N_IN};
use crate::params::FurParams;
use crate::spectrum::Rgb;
use crate::unscattered::{cortex_leg, transmittance, Extinction};

/// Number of scattered lobes.
pub const SCATTERED_COUNT: usize = 3;

/// The three scattered lobes at one chord: rotation Φ^s_p of the travel direction before the
/// scattering chord, and attenuation A^s_p (report eq. 7–9).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ScatteredPaths {
    /// Φ^s_p for TttT^s, TtrtT^s, TttRttT^s.
    pub rotation: [f32; SCATTERED_COUNT],
    /// A^s_p (the medulla absorption of the scattered light is in C^N).
    pub attenuation: [Rgb; SCATTERED_COUNT],
    /// Signed offset inside the medulla, h_m = h/(κη'_m) = sin μ.
    pub h_m: f32,
}

/// Φ^s_p and A^s_p at `chord`; `None` where the ray misses the medulla or is totally
/// reflected at it (all three vanish there).
///
/// With P = 1 − exp(−σ_ms·ℓ_m/cos θ_tm), E_c = exp(−σ_ca·ℓ_c/cos θ_tc),
/// U = exp(−(σ_ms+σ_ma)·ℓ_m/cos θ_tm) and A'_tT = exp(−σ_ca·(1 − κ)/cos θ_tc):
/// - A^s_TttT = (1−f)(1−f_m)·E_c·P·A'_tT, Φ^s = (c − a) + (μ − m)
/// - A^s_TtrtT = (1−f)(1−f_m)·E_c·U·f_m·P·A'_tT, Φ^s = (c − a) + (μ − m) + (π + 2μ)
/// - A^s_TttRttT = (1−f)(1−f_m)·E_c·U·(1−f_m)·E_c·f·E_c·(1−f_m)·P·A'_tT,
///   Φ^s = (c − a) + 3(μ − m) + (π + 2c)
///
/// `exit` is A'_tT = exp(−σ_ca·(1 − κ)/cos θ_tc), which depends only on θ_r
/// ([`exit_transmittance`]).
#[inline]
#[must_use]
pub fn scattered_paths<M: Math>(
    slice: &ViewSlice,
    chord: &Chord,
    ext: &Extinction,
    l: f32,
    exit: Rgb,
) -> Option<ScatteredPaths> {
    let MedullaEvent::Enter {
        m,
        cos_m,
        mu,
        cos_mu,
    } = chord.medulla
    else {
        return None;
    };
    let (a, c) = (chord.a, chord.c);
    let f = fresnel::cuticle::<M>(chord.cos_a, slice.eta_c_prime, l);
    let fm = fresnel::medulla::<M>(cos_m, slice.eta_m_prime / slice.eta_c_prime);
    let ell_m = 2.0 * slice.kappa * cos_mu;
    let ec = transmittance::<M>(ext.cortex, cortex_leg(slice, chord, cos_m));
    let p = 1.0 - M::exp_neg(ext.medulla_scattering * ell_m);
    let u = M::exp_neg(ext.medulla * ell_m);
    let base = ec * exit * ((1.0 - f) * (1.0 - fm) * p);
    let refr = (c - a) + (mu - m);
    Some(ScatteredPaths {
        rotation: [
            refr,
            refr + PI + 2.0 * mu,
            (c - a) + 3.0 * (mu - m) + PI + 2.0 * c,
        ],
        attenuation: [
            base,
            base * (u * fm),
            base * ec * ec * (u * (1.0 - fm) * f * (1.0 - fm)),
        ],
        h_m: (chord.h / (slice.kappa * slice.eta_m_prime)).clamp(-1.0, 1.0),
    })
}

/// A'_tT = exp(−σ_ca·(1 − κ)/cos θ_tc): the radial exit through the cortex (report eq. 7–9).
#[inline]
#[must_use]
pub fn exit_transmittance<M: Math>(slice: &ViewSlice, ext: &Extinction) -> Rgb {
    transmittance::<M>(ext.cortex, 1.0 - slice.kappa)
}

/// N^s_p(h, φ) = A^s_p(h)·C^N(φ − π − Φ^s_p(h); h_m, σ_N, g) (report eq. 6, 10), for the
/// three lobes. `sigma_n` = σ_ms·κ/cos θ_tm is the medulla's 2D optical radius; C^N carries
/// the medulla absorption of the scattered light (docs/model.md §7).
#[inline]
#[must_use]
pub fn azimuthal_at(
    profiles: &MedullaProfiles<'_>,
    paths: &ScatteredPaths,
    sigma_n: f32,
    phi: f32,
) -> [Rgb; SCATTERED_COUNT] {
    let row = profiles.n_row(sigma_n, paths.h_m);
    azimuthal_on_row(profiles, &row, paths, phi)
}

/// [`azimuthal_at`] with the C^N row already prepared (shared by ±φ in the far field).
#[inline]
#[must_use]
pub fn azimuthal_on_row(
    profiles: &MedullaProfiles<'_>,
    row: &NRow,
    paths: &ScatteredPaths,
    phi: f32,
) -> [Rgb; SCATTERED_COUNT] {
    let mut out = [Rgb::ZERO; SCATTERED_COUNT];
    for (k, o) in out.iter_mut().enumerate() {
        if paths.attenuation[k].max_channel() <= 0.0 {
            continue;
        }
        *o = paths.attenuation[k] * profiles.cn_at(row, phi - PI - paths.rotation[k]);
    }
    out
}

/// Number of θ'_in nodes of the μ tables (both signs).
const MU_NODES: usize = 2 * MAX_N_IN - 1;

/// θ_i samples for the μ normalisation integral.
const MU_SAMPLES: usize = 512;

/// The longitudinal scattered lobe M^s (report eq. 11–12), with the normalisation μ
/// precomputed per θ'_in node.
#[derive(Clone, Copy, Debug)]
pub struct ScatteredLongitudinal {
    /// The cuticle tilt per crossing, α/2 (docs/model.md §6): the scattered paths cross the
    /// cuticle twice, like TT, whose lobe is shifted by α in all.
    tilt: f32,
    eta_c: f32,
    eta_m: f32,
    layers: f32,
    /// θ'_in nodes: −θ_max … θ_max, `2·n_in − 1` of them.
    nodes: usize,
    theta_in_max: f32,
    /// 1/μ (the normalisation integral) per half and node.
    mu: [[f32; MU_NODES]; 2],
}

impl ScatteredLongitudinal {
    /// Precomputes μ_x(θ'_in) = 1 / ∫ C^M_x(θ'_i(θ_i) | θ'_in)·|dθ'_i/dθ_i| dθ_i over
    /// θ_i ∈ [−π/2, π/2] (only directions that can leave the fiber; photons trapped by total
    /// internal reflection are not sent anywhere else).
    #[must_use]
    pub fn new<M: Math>(params: &FurParams, profiles: &MedullaProfiles<'_>) -> Self {
        let layout = profiles.layout();
        let n_in = layout.res.n_in.min(MAX_N_IN);
        let mut s = ScatteredLongitudinal {
            tilt: 0.5 * params.alpha(),
            eta_c: params.eta_c(),
            eta_m: params.eta_m(),
            layers: params.l(),
            nodes: 2 * n_in - 1,
            theta_in_max: layout.theta_in_max,
            mu: [[0.0; MU_NODES]; 2],
        };
        let step = PI / MU_SAMPLES as f32;
        for half in [Half::Back, Half::Front] {
            for j in 0..s.nodes {
                let theta_in = s.node(j);
                let mut integral = 0.0f32;
                for k in 0..MU_SAMPLES {
                    let theta_i = -PI / 2.0 + (k as f32 + 0.5) * step;
                    let (theta_p, jac) = s.refract::<M>(theta_i);
                    integral += profiles.cm(half, theta_p, theta_in) * jac * step;
                }
                // Stored as the integral: C^M is linear in the θ'_in weight between nodes, so
                // interpolating the integral and inverting normalises exactly in between.
                s.mu[half as usize][j] = integral;
            }
        }
        s
    }

    fn node(&self, j: usize) -> f32 {
        let half = (self.nodes - 1) / 2;
        self.theta_in_max * (j as f32 - half as f32) / half as f32
    }

    /// θ' inside the medulla for an outside angle θ (sin θ' = sin(θ − α/2)/η_m, docs/model.md
    /// §6) and the Jacobian |dθ'/dθ| = |cos(θ − α/2)|/(η_m cos θ').
    #[inline]
    #[must_use]
    pub fn refract<M: Math>(&self, theta: f32) -> (f32, f32) {
        let e = theta - self.tilt;
        let (sin_e, cos_e) = M::sin_cos(e);
        let s = sin_e / self.eta_m;
        let cos_p = sqrt_pos::<M>((1.0 - s) * (1.0 + s)).max(1e-6);
        (asin_clamped::<M>(s), cos_e.abs() / (self.eta_m * cos_p))
    }

    /// θ'_in = −θ'_r, the view ray's travel direction inside the medulla at θ_r.
    #[must_use]
    pub fn theta_in<M: Math>(&self, theta_r: f32) -> f32 {
        -self.refract::<M>(theta_r).0
    }

    /// The θ' ranges that θ_i ∈ [−π/2, π/2] maps onto under [`ScatteredLongitudinal::refract`],
    /// one per monotonic branch: with t = θ − α/2, the main branch is t ∈ [−π/2, π/2] ∩ range
    /// and the fold is the part of the range beyond ±π/2 (|α|/2 wide, where sin t turns back), which
    /// covers some θ' a second time. Each entry is (θ'_lo, θ'_hi) with θ'_lo < θ'_hi, or
    /// `None` when the branch is empty (the fold when α = 0).
    #[must_use]
    pub fn branches<M: Math>(&self) -> [Option<(f32, f32)>; 2] {
        let half = PI / 2.0;
        let (t_lo, t_hi) = (-half - self.tilt, half - self.tilt);
        let out = |t: f32| asin_clamped::<M>(M::sin(t) / self.eta_m);
        let main = (out(t_lo.max(-half)), out(t_hi.min(half)));
        let fold = if t_lo < -half {
            // sin t falls from sin(t_lo) to −1: θ' from out(t_lo) down to −θ'_max.
            Some((out(-half), out(t_lo)))
        } else if t_hi > half {
            Some((out(t_hi), out(half)))
        } else {
            None
        };
        let ok = |r: (f32, f32)| if r.1 > r.0 { Some(r) } else { None };
        [ok(main), fold.and_then(ok)]
    }

    /// The outside angle θ on branch `branch` (0 main, 1 fold, see
    /// [`ScatteredLongitudinal::branches`]) whose refracted angle is θ'.
    #[must_use]
    pub fn unrefract<M: Math>(&self, theta_p: f32, branch: usize) -> f32 {
        let t0 = asin_clamped::<M>(self.eta_m * M::sin(theta_p));
        let t = match branch {
            0 => t0,
            _ if self.tilt > 0.0 => -PI - t0,
            _ => PI - t0,
        };
        (t + self.tilt).clamp(-PI / 2.0, PI / 2.0)
    }

    /// μ_x at θ'_in: the inverse of the normalisation integral interpolated linearly between
    /// nodes (exact, because the C^M lookup is linear in θ'_in there).
    fn mu(&self, half: Half, theta_in: f32) -> f32 {
        let half_nodes = (self.nodes - 1) / 2;
        let u = ((theta_in / self.theta_in_max + 1.0) * half_nodes as f32)
            .clamp(0.0, (self.nodes - 1) as f32);
        let i = (u as usize).min(self.nodes - 2);
        let w = u - i as f32;
        let row = &self.mu[half as usize];
        let integral = row[i] * (1.0 - w) + row[i + 1] * w;
        if integral > 0.0 {
            1.0 / integral
        } else {
            0.0
        }
    }

    /// F_t(θ_i): Fresnel transmittance leaving the medulla (incidence θ'_i, index η_c/η_m)
    /// times that of the cuticle (incidence θ_i − α/2 from outside, index η_c, layers l), for
    /// the radial exit of the report's simplification, in full 3D.
    #[inline]
    #[must_use]
    pub fn fresnel_exit<M: Math>(&self, theta_i: f32) -> f32 {
        let e = theta_i - self.tilt;
        let (sin_e, cos_e) = M::sin_cos(e);
        let s = sin_e / self.eta_m;
        let cos_p = sqrt_pos::<M>((1.0 - s) * (1.0 + s));
        let medulla = 1.0 - fresnel::dielectric::<M>(cos_p, self.eta_c / self.eta_m);
        let cuticle = 1.0 - fresnel::cuticle::<M>(cos_e.abs(), self.eta_c, self.layers);
        medulla * cuticle
    }

    /// M^s(θ_i, θ_r, φ) = (1 − |φ|/π)·M^s_back + (|φ|/π)·M^s_front with
    /// M^s_x = μ_x(θ_r)·F_t(θ_i)·C^M_x(θ'_i | θ'_in)·|dθ'_i/dθ_i|, where θ'_in = −θ'_r is the
    /// travel direction of the view ray inside the medulla.
    #[must_use]
    pub fn eval<M: Math>(
        &self,
        profiles: &MedullaProfiles<'_>,
        theta_i: f32,
        theta_r: f32,
        phi: f32,
    ) -> f32 {
        let (theta_r_p, _) = self.refract::<M>(theta_r);
        let theta_in = -theta_r_p;
        let (theta_i_p, jac) = self.refract::<M>(theta_i);
        let ft = self.fresnel_exit::<M>(theta_i);
        let w = (phi.abs() / PI).clamp(0.0, 1.0);
        let lobe = |half: Half| self.mu(half, theta_in) * profiles.cm(half, theta_i_p, theta_in);
        ft * jac * ((1.0 - w) * lobe(Half::Back) + w * lobe(Half::Front))
    }
}
