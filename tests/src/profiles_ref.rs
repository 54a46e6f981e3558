//! Medulla profiles for the tests, and the scattered component of docs/model.md §6 written again in
//! f64 from the specification.
//!
//! - [`OwnedProfiles`]: tables generated with `bcsdf_core::medulla::generate` (sequential) into
//!   owned buffers, and a borrowed [`MedullaProfiles`] view of them.
//! - [`ScatterRef`]: A^s_p(h), Φ^s_p(h), h_m and σ_N of the three scattered lobes from the
//!   angles a, c, m, μ of docs/model.md §3 in f64, with the Fresnel terms of [`crate::tracer`].
//! - [`exit_transmittance`], [`refract_into_medulla`], [`mean_exit_transmittance`]: F_t, the
//!   refraction into the medulla and ⟨F_t⟩ = ∫ μ F_t C^M |dθ'/dθ| dθ_i (docs/model.md §6), with
//!   quadrature panels broken at every kink of the tabulated C^M.
//! - [`scattered_energy`]: the scattered part of the white-furnace prediction (docs/model.md §8).
//!
//! The only things taken from the core are the generated tables and their lookup
//! (`MedullaProfiles::cn`, `cm`), which `tests/tests/suite/profiles.rs` checks on its
//! own. Nothing here calls the core's geometry, Fresnel, scattered or far-field code.

use crate::quadrature::{composite_gl_nodes, gauss_legendre};
use crate::tracer::{bravais, cos_refracted, cuticle, dielectric, wrap};
use bcsdf_core::medulla::{generate, Half};
use bcsdf_core::{FurParams, MedullaProfiles, PhotonBudget, ProfileLayout, Resolution};
use std::f64::consts::{FRAC_PI_2, PI, TAU};

/// Profile tables in owned buffers.
#[derive(Clone, Debug)]
pub struct OwnedProfiles {
    /// Axes and resolution.
    pub layout: ProfileLayout,
    /// C^N, `[σ][h_m][ψ]` (with the medulla absorption of the scattered light).
    pub cn: Vec<f32>,
    /// C^M, `[half][θ'_in][θ'_out]`.
    pub cm: Vec<f32>,
}

impl OwnedProfiles {
    /// Generates every table of `layout` with `generate` (sequential) at `budget` and `seed`.
    pub fn generate(layout: ProfileLayout, budget: PhotonBudget, seed: u64) -> OwnedProfiles {
        let mut out = OwnedProfiles {
            layout,
            cn: vec![0.0; layout.cn_len()],
            cm: vec![0.0; layout.cm_len()],
        };
        generate(&layout, &budget, seed, &mut out.cn, &mut out.cm)
            .expect("valid layout and buffers");
        out
    }

    /// The profiles `params` need (`ProfileLayout::for_params`) at resolution `res`.
    pub fn for_params(
        params: &FurParams,
        res: Resolution,
        budget: PhotonBudget,
        seed: u64,
    ) -> OwnedProfiles {
        OwnedProfiles::generate(ProfileLayout::for_params(params, res), budget, seed)
    }

    /// A validated view for the core.
    pub fn view(&self) -> MedullaProfiles<'_> {
        MedullaProfiles::new(self.layout, &self.cn, &self.cm).expect("valid tables")
    }
}

/// The three scattered lobes at one view ray (docs/model.md §6), in f64.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ScatterRef {
    /// Φ^s_p for TttT^s, TtrtT^s, TttRttT^s (rotation of the travel direction before the
    /// scattering chord, exit-azimuth sense, not wrapped).
    pub rotation: [f64; 3],
    /// A^s_p per RGB channel (the medulla absorption of the scattered light is in C^N).
    pub attenuation: [[f64; 3]; 3],
    /// Signed offset inside the medulla, h/(κ·η'_m).
    pub h_m: f64,
    /// σ_N = σ_ms·κ/cos θ_tm.
    pub sigma_n: f64,
    /// The unscattered TttT exit azimuth 2c − 2a − 2m + 2μ + π (docs/model.md §3 table).
    pub phi_tttt: f64,
    /// (c − a) + (μ − m): the refractions before the scattering chord of TttT^s.
    pub refraction: f64,
}

/// The largest |h| at which the view ray enters the medulla (no miss, no total internal
/// reflection): min(κη'_c, κη'_m, 1).
pub fn enter_limit(p: &FurParams, theta_r: f64) -> f64 {
    let kappa = p.kappa() as f64;
    let ec = bravais(p.eta_c() as f64, theta_r);
    let em = bravais(p.eta_m() as f64, theta_r);
    (kappa * ec).min(kappa * em).min(1.0)
}

/// A^s_p, Φ^s_p, h_m, σ_N of docs/model.md §6 at view angle `theta_r` and offset `h`; `None` where
/// the ray misses the medulla or is totally reflected at it.
///
/// With P = 1 − exp(−σ_ms·ℓ_m/cos θ_tm), E_c = exp(−σ_ca·ℓ_c/cos θ_tc),
/// U = exp(−(σ_ms+σ_ma)·ℓ_m/cos θ_tm), A'_tT = exp(−σ_ca·(1 − κ)/cos θ_tc):
/// TttT^s = (1−f)(1−f_m)E_c·P·A'; TtrtT^s = that ·U·f_m; TttRttT^s = that ·U(1−f_m)·E_c f E_c (1−f_m).
pub fn scattered_ref(p: &FurParams, theta_r: f64, h: f64) -> Option<ScatterRef> {
    let kappa = p.kappa() as f64;
    if kappa <= 0.0 || h.abs() >= 1.0 {
        return None;
    }
    let (eta_c, eta_m) = (p.eta_c() as f64, p.eta_m() as f64);
    let ec = bravais(eta_c, theta_r);
    let em = bravais(eta_m, theta_r);
    let (cos_tc, cos_tm) = (cos_refracted(eta_c, theta_r), cos_refracted(eta_m, theta_r));
    let a = h.asin();
    let b = h / ec;
    if b.abs() >= kappa {
        return None;
    }
    let sin_mu = h / (kappa * em);
    if sin_mu.abs() >= 1.0 {
        return None;
    }
    let c = b.asin();
    let m = (b / kappa).asin();
    let mu = sin_mu.asin();
    let f = cuticle(a.cos(), 1.0, ec, p.l() as f64);
    let fm = dielectric(m.cos(), ec, em);
    let ell_c = c.cos() - kappa * m.cos();
    let ell_m = 2.0 * kappa * mu.cos();
    let (sms, sma) = (p.sigma_ms() as f64, p.sigma_ma() as f64);
    let p_scatter = 1.0 - (-sms * ell_m / cos_tm).exp();
    let u = (-(sms + sma) * ell_m / cos_tm).exp();
    let mut attenuation = [[0.0; 3]; 3];
    for (ch, &sca) in p.sigma_ca().0.iter().enumerate() {
        let sca = sca as f64 / cos_tc;
        let e_c = (-sca * ell_c).exp();
        let exit = (-sca * (1.0 - kappa)).exp();
        let base = (1.0 - f) * (1.0 - fm) * e_c * p_scatter * exit;
        attenuation[0][ch] = base;
        attenuation[1][ch] = base * u * fm;
        attenuation[2][ch] = base * u * (1.0 - fm) * e_c * f * e_c * (1.0 - fm);
    }
    let refraction = (c - a) + (mu - m);
    Some(ScatterRef {
        rotation: [
            refraction,
            refraction + (PI + 2.0 * mu),
            (c - a) + 3.0 * (mu - m) + (PI + 2.0 * c),
        ],
        attenuation,
        h_m: sin_mu,
        sigma_n: sms * kappa / cos_tm,
        phi_tttt: 2.0 * c - 2.0 * a - 2.0 * m + 2.0 * mu + PI,
        refraction,
    })
}

/// The cuticle tilt of the scattered longitudinal lobe, α/2 per crossing (docs/model.md §6).
fn scattered_tilt(p: &FurParams) -> f64 {
    0.5 * p.alpha() as f64
}

/// θ' inside the medulla for an outside longitudinal angle θ (docs/model.md §6:
/// sin θ' = sin(θ − α/2)/η_m) and the Jacobian |dθ'/dθ| = |cos(θ − α/2)|/(η_m·cos θ').
pub fn refract_into_medulla(p: &FurParams, theta: f64) -> (f64, f64) {
    let e = theta - scattered_tilt(p);
    let eta_m = p.eta_m() as f64;
    let s = e.sin() / eta_m;
    let tp = s.asin();
    (tp, e.cos().abs() / (eta_m * tp.cos()))
}

/// F_t(θ_i) = (1 − dielectric(cos θ'_i; η_m → η_c))·(1 − cuticle(cos(θ_i − α/2); 1 → η_c, l)).
pub fn exit_transmittance(p: &FurParams, theta_i: f64) -> f64 {
    let (tp, _) = refract_into_medulla(p, theta_i);
    let e = theta_i - scattered_tilt(p);
    let medulla = 1.0 - dielectric(tp.cos(), p.eta_m() as f64, p.eta_c() as f64);
    let cut = 1.0 - cuticle(e.cos().abs(), 1.0, p.eta_c() as f64, p.l() as f64);
    medulla * cut
}

/// θ_i ∈ (−π/2, π/2) where the θ_i-integrand of M^s has a kink: every θ'_out bin centre of
/// C^M (the lookup is piecewise linear between them) mapped back through both branches of
/// sin(θ_i − α/2) = η_m sin θ', and the fold θ_i − α/2 = ±π/2.
pub fn m_s_kinks(p: &FurParams, layout: &ProfileLayout) -> Vec<f64> {
    let tilt = scattered_tilt(p);
    let eta_m = p.eta_m() as f64;
    let n_out = layout.res.n_out;
    let w = PI / n_out as f64;
    let mut out = vec![tilt - FRAC_PI_2, tilt + FRAC_PI_2];
    for b in 0..n_out {
        let s = eta_m * (-FRAC_PI_2 + (b as f64 + 0.5) * w).sin();
        if s.abs() < 1.0 {
            let e = s.asin();
            out.extend([tilt + e, tilt + PI - e, tilt - PI - e]);
        }
    }
    out.retain(|x| x.abs() < FRAC_PI_2);
    out
}

/// θ_i quadrature nodes and weights on [−π/2, π/2]: 4-point Gauss–Legendre panels at most
/// `max_width` wide, broken at `breaks` (which must lie inside the interval).
pub fn panel_nodes(breaks: &[f64], max_width: f64) -> Vec<(f64, f64)> {
    let mut br: Vec<f64> = breaks
        .iter()
        .copied()
        .filter(|x| x.abs() < FRAC_PI_2)
        .collect();
    br.extend([-FRAC_PI_2, FRAC_PI_2]);
    br.sort_by(|a, b| a.partial_cmp(b).unwrap());
    br.dedup_by(|a, b| (*a - *b).abs() < 1e-12);
    composite_gl_nodes(&br, max_width)
}

/// ⟨F_t⟩ for one half of C^M at view angle `theta_r`: ∫ F_t·C^M·J·k dθ_i / ∫ C^M·J dθ_i over
/// θ_i ∈ [−π/2, π/2], with C^M = C^M_half(θ'_i | −θ'_r) and J = |dθ'_i/dθ_i| (docs/model.md §6, the
/// normalisation μ being 1/denominator). `clamp` = Some(c2min) weights the numerator by
/// k = min(1, cos²θ_i/c2min), as the white furnace weights S (the model divides by
/// max(cos²θ_i, c2min)); `None` gives k = 1.
pub fn mean_exit_transmittance(
    p: &FurParams,
    profiles: &MedullaProfiles<'_>,
    theta_r: f64,
    half: Half,
    clamp: Option<f64>,
) -> f64 {
    let theta_in = -refract_into_medulla(p, theta_r).0;
    let mut breaks = m_s_kinks(p, profiles.layout());
    if let Some(c2) = clamp {
        let tc = c2.sqrt().acos();
        breaks.extend([-tc, tc]);
    }
    let (mut num, mut den) = (0.0, 0.0);
    for (ti, w) in panel_nodes(&breaks, 0.02) {
        let (tp, jac) = refract_into_medulla(p, ti);
        let c = profiles.cm(half, tp as f32, theta_in as f32) as f64 * jac;
        let k = clamp.map_or(1.0, |c2| (ti.cos().powi(2) / c2).min(1.0));
        num += w * c * exit_transmittance(p, ti) * k;
        den += w * c;
    }
    num / den
}

/// The scattered part of the white-furnace prediction at view angle `theta_r` (docs/model.md §8),
/// per RGB channel:
///
/// Σ_p ½∫dh A^s_p(h) ∫dφ C^N(φ − π − Φ^s_p(h); h_m, σ_N)·
/// [(1 − |φ|/π)·⟨F_t⟩_back + (|φ|/π)·⟨F_t⟩_front],
///
/// which is what ∫ M^s·Σ_p N^s_p cos θ_i dω_i / cos²θ_i·cos²θ_i leaves once M^s is integrated
/// over θ_i (it is μ·F_t·C^M·J, and μ normalises C^M·J). `f_back`, `f_front` are the ⟨F_t⟩ of
/// the two halves. h runs over the part that enters the medulla, split at 0 and smoothstep-
/// substituted at ±[`enter_limit`] (square-root ends), `h_panels` panels of 8-point
/// Gauss–Legendre per side; φ is integrated in ψ = φ − π − Φ^s_p, exactly per C^N bin
/// (4 sub-panels of 4-point Gauss–Legendre between consecutive bin centres).
pub fn scattered_energy(
    p: &FurParams,
    profiles: &MedullaProfiles<'_>,
    theta_r: f64,
    f_back: f64,
    f_front: f64,
    h_panels: usize,
) -> [f64; 3] {
    let mut out = [0.0; 3];
    let he = enter_limit(p, theta_r);
    if he <= 0.0 || p.sigma_ms() <= 0.0 {
        return out;
    }
    let n_psi = profiles.layout().res.n_psi;
    let wb = TAU / n_psi as f64;
    let gl4 = gauss_legendre(4);
    let sub = 4;
    // ψ nodes between consecutive bin centres, covering one period.
    let mut psi_nodes = Vec::with_capacity(n_psi * sub * 4);
    for b in 0..n_psi {
        let lo = -PI + (b as f64 + 0.5) * wb;
        for s in 0..sub {
            let a = lo + wb * s as f64 / sub as f64;
            let hw = 0.5 * wb / sub as f64;
            for &(u, w) in &gl4 {
                psi_nodes.push((a + hw * (1.0 + u), hw * w));
            }
        }
    }
    crate::furnace::average_over_h(&[-he, 0.0, he], h_panels, |h, wh| {
        let Some(r) = scattered_ref(p, theta_r, h) else {
            return;
        };
        for (k, att) in r.attenuation.iter().enumerate() {
            let mut acc = 0.0;
            for &(psi, w) in &psi_nodes {
                let c = profiles.cn(r.sigma_n as f32, r.h_m as f32, psi as f32) as f64;
                let phi = wrap(psi + PI + r.rotation[k]).abs() / PI;
                acc += w * c * ((1.0 - phi) * f_back + phi * f_front);
            }
            for ch in 0..3 {
                out[ch] += wh * att[ch] * acc;
            }
        }
    });
    out
}

/// The white-furnace prediction of docs/model.md §8 for the full model at one view angle.
#[derive(Clone, Copy, Debug)]
pub struct FullPrediction {
    /// ρ per channel: unscattered + scattered.
    pub rho: [f64; 3],
    /// Σ_p ⟨A_p⟩_h·mass_p ([`crate::furnace::predicted_rho`]).
    pub unscattered: [f64; 3],
    /// [`scattered_energy`].
    pub scattered: [f64; 3],
    /// ⟨F_t⟩_back with the furnace's pole clamp.
    pub f_back: f64,
    /// ⟨F_t⟩_front with the furnace's pole clamp.
    pub f_front: f64,
}

/// ρ(θ_r) predicted for the full model: the unscattered paths as in
/// [`crate::furnace::predicted_rho`] (tracer and erf, `panels` per h-piece) plus
/// [`scattered_energy`] with ⟨F_t⟩ weighted by the furnace's clamp min(1, cos²θ_i/MIN_COS2)
/// (`h_panels` per side).
pub fn predicted_rho_full(
    p: &FurParams,
    profiles: &MedullaProfiles<'_>,
    theta_r: f64,
    panels: usize,
    h_panels: usize,
) -> FullPrediction {
    let unscattered = crate::furnace::predicted_rho(p, theta_r, panels).rho;
    let c2 = Some(crate::furnace::MIN_COS2);
    let f_back = mean_exit_transmittance(p, profiles, theta_r, Half::Back, c2);
    let f_front = mean_exit_transmittance(p, profiles, theta_r, Half::Front, c2);
    let scattered = scattered_energy(p, profiles, theta_r, f_back, f_front, h_panels);
    let mut rho = [0.0; 3];
    for ch in 0..3 {
        rho[ch] = unscattered[ch] + scattered[ch];
    }
    FullPrediction {
        rho,
        unscattered,
        scattered,
        f_back,
        f_front,
    }
}
