//! The white furnace of docs/model.md §8 in f64, and the lobe shapes of docs/model.md §5 it needs.
//!
//! - [`furnace`] integrates ρ(ω_r) = ∫ S(ω_i, ω_r) cos θ_i dω_i numerically over the sphere of
//!   light directions (dω = cos θ dθ dφ), calling the core's far field as a black box.
//! - [`predicted_rho`] is what docs/model.md §8 says ρ must be: Σ_p ⟨A_p⟩_h · (mass of M_p inside
//!   ±π/2), with ⟨A_p⟩_h = ½∫A_p(h)dh integrated over h from the brute-force ray tracer
//!   ([`crate::tracer`]) and the M mass from erf (written here).
//!
//! Nothing here calls the core's geometry, Fresnel, Gaussian or quadrature code. For the full
//! model (scattered lobes), [`furnace_on`] with [`theta_i_nodes_with`] breaks the θ_i panels
//! at the kinks of M^s, and `crate::profiles_ref::predicted_rho_full` adds the scattered energy
//! to the prediction.

use crate::quadrature::{composite_gl_nodes, gauss_legendre, smoothstep_nodes};
use crate::tracer::{bravais, cos_refracted, cuticle, trace, CrossSection, PATHS};
use bcsdf_core::{Angles, Closure, FurBcsdf, FurParams, Math};
use std::f64::consts::{FRAC_PI_2, PI, TAU};

/// The model divides by max(cos²θ_i, MIN_COS2) (bcsdf-core `model::MIN_COS2_THETA_I`; the
/// furnace test asserts that the two agree).
pub const MIN_COS2: f64 = 1e-4;

/// Cuticle group of each path in `PATHS` order: 0 = R, 1 = TT, 2 = TRT (docs/model.md §5).
pub const GROUP_OF_PATH: [usize; 8] = [0, 1, 2, 1, 1, 1, 2, 2];

/// Longitudinal shift α_p, longitudinal width β_M and azimuthal width β_N of one cuticle
/// group (docs/model.md §5), radians.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GroupShape {
    /// α_p.
    pub shift: f64,
    /// β_M.
    pub beta_m: f64,
    /// β_N.
    pub beta_n: f64,
}

/// The three groups' shapes for tilt `alpha` and roughnesses `beta_m`, `beta_n` (radians):
/// R (−2α, β_m, β_n), TT (α, β_m/2, √2·β_n), TRT (3α, 3β_m/2, √3·β_n).
pub fn group_shapes(alpha: f64, beta_m: f64, beta_n: f64) -> [GroupShape; 3] {
    [
        GroupShape {
            shift: -2.0 * alpha,
            beta_m,
            beta_n,
        },
        GroupShape {
            shift: alpha,
            beta_m: 0.5 * beta_m,
            beta_n: 2f64.sqrt() * beta_n,
        },
        GroupShape {
            shift: 3.0 * alpha,
            beta_m: 1.5 * beta_m,
            beta_n: 3f64.sqrt() * beta_n,
        },
    ]
}

/// The groups of a validated parameter set.
pub fn group_shapes_of(p: &FurParams) -> [GroupShape; 3] {
    group_shapes(p.alpha() as f64, p.beta_m() as f64, p.beta_n() as f64)
}

/// Normalised Gaussian G(x; β) = exp(−x²/2β²)/(√(2π)·β).
pub fn gaussian(x: f64, beta: f64) -> f64 {
    (-0.5 * (x / beta).powi(2)).exp() / ((TAU).sqrt() * beta)
}

/// G(·; β) wrapped onto the circle: Σ_k G(x + 2πk; β) over enough periods for β ≤ 2.
pub fn wrapped_gaussian(x: f64, beta: f64) -> f64 {
    let x = crate::tracer::wrap(x);
    (-6..=6).map(|k| gaussian(x + TAU * k as f64, beta)).sum()
}

/// The error function, to ~1e-15: Maclaurin series for |x| < 2.5, continued fraction for
/// erfc beyond.
pub fn erf(x: f64) -> f64 {
    if x < 0.0 {
        return -erf(-x);
    }
    if x < 2.5 {
        // erf x = 2/√π Σ (−1)ⁿ x^(2n+1) / (n! (2n+1))
        let (mut term, mut sum) = (x, x);
        let x2 = x * x;
        for n in 1..200 {
            term *= -x2 / n as f64;
            let add = term / (2 * n + 1) as f64;
            sum += add;
            if add.abs() < 1e-17 * sum.abs() {
                break;
            }
        }
        return 2.0 / PI.sqrt() * sum;
    }
    // erfc x = exp(−x²)/√π · 1/(x + (1/2)/(x + 1/(x + (3/2)/(x + 2/(x + …))))), evaluated
    // from the tail.
    let mut f = x;
    for k in (1..120).rev() {
        f = x + (k as f64 / 2.0) / f;
    }
    1.0 - (-x * x).exp() / PI.sqrt() / f
}

/// ∫ G(x; β) dx over [lo, hi].
pub fn gaussian_mass(lo: f64, hi: f64, beta: f64) -> f64 {
    let s = beta * 2f64.sqrt();
    0.5 * (erf(hi / s) - erf(lo / s))
}

/// The divisor of M_p in closure `closure` (docs/model.md §12): 1 for the report's
/// Gaussian; for the energy closure the Gaussian's mass over θ_i ∈ [−π/2, π/2] as S weighs
/// it, with the pole guard of 1/cos²θ_i ([`longitudinal_mass`]: this module's erf and
/// Gauss–Legendre in the slivers), at least 1e-4 (bcsdf-core's
/// `longitudinal::MIN_SPHERE_MASS`).
pub fn sphere_mass(theta_r: f64, g: &GroupShape, closure: Closure) -> f64 {
    match closure {
        Closure::Report => 1.0,
        Closure::Energy => longitudinal_mass(theta_r, g, MIN_COS2).max(1e-4),
    }
}

/// M_p(θ_i, θ_r) of one group (docs/model.md §5, §12): G(θ_r + θ_i − α_p; β_M) divided by
/// [`sphere_mass`].
pub fn longitudinal_lobe(theta_i: f64, theta_r: f64, g: &GroupShape, closure: Closure) -> f64 {
    gaussian(theta_r + theta_i - g.shift, g.beta_m) / sphere_mass(theta_r, g, closure)
}

/// Mass of the report's M_p(θ_i, θ_r) = G(θ_r + θ_i − α_p; β_M) over θ_i ∈ [−π/2, π/2], weighted as the
/// furnace weights it: S·cos θ_i dω = S·cos²θ_i dθ_i dφ and S carries 1/max(cos²θ_i, c2min),
/// so θ_i contributes min(1, cos²θ_i/c2min).
pub fn longitudinal_mass(theta_r: f64, g: &GroupShape, c2min: f64) -> f64 {
    let x = |ti: f64| theta_r + ti - g.shift;
    let full = gaussian_mass(x(-FRAC_PI_2), x(FRAC_PI_2), g.beta_m);
    // Near the poles, cos²θ_i < c2min: remove G·(1 − cos²θ_i/c2min) there.
    let tc = c2min.sqrt().acos();
    let gl = gauss_legendre(8);
    let mut loss = 0.0;
    for (a, b) in [(-FRAC_PI_2, -tc), (tc, FRAC_PI_2)] {
        let panels = 16;
        let w = (b - a) / panels as f64;
        for j in 0..panels {
            for &(u, wt) in &gl {
                let ti = a + w * (j as f64 + 0.5 + 0.5 * u);
                let weight = 1.0 - ti.cos().powi(2) / c2min;
                loss += 0.5 * w * wt * gaussian(x(ti), g.beta_m) * weight;
            }
        }
    }
    full - loss
}

/// A fiber's parameters in f64, read from validated [`FurParams`].
#[derive(Clone, Copy, Debug)]
pub struct Fiber {
    /// η_c.
    pub eta_c: f64,
    /// η_m.
    pub eta_m: f64,
    /// κ.
    pub kappa: f64,
    /// l.
    pub layers: f64,
    /// σ_ca, RGB.
    pub sigma_ca: [f64; 3],
    /// σ_ms + σ_ma: unscattered light leaves the medulla at the full extinction rate.
    pub sigma_medulla: f64,
}

impl Fiber {
    /// From validated parameters.
    pub fn of(p: &FurParams) -> Fiber {
        Fiber {
            eta_c: p.eta_c() as f64,
            eta_m: p.eta_m() as f64,
            kappa: p.kappa() as f64,
            layers: p.l() as f64,
            sigma_ca: p.sigma_ca().0.map(|s| s as f64),
            sigma_medulla: p.sigma_ms() as f64 + p.sigma_ma() as f64,
        }
    }

    /// The traced cross-section at view angle `theta_r`.
    pub fn cross_section(&self, theta_r: f64) -> CrossSection {
        CrossSection::at_view(self.eta_c, self.eta_m, self.kappa, self.layers, theta_r)
    }

    /// The offsets in (−1, 1) where the set of paths changes (±κη'_c, ±κη'_m) and 0.
    pub fn cuts(&self, theta_r: f64) -> Vec<f64> {
        let xs = self.cross_section(theta_r);
        let mut cuts = vec![-1.0, 0.0, 1.0];
        for e in [xs.kappa * xs.eta_c, xs.kappa * xs.eta_m] {
            if e > 0.0 && e < 1.0 {
                cuts.push(e);
                cuts.push(-e);
            }
        }
        cuts.sort_by(|a, b| a.partial_cmp(b).unwrap());
        cuts.dedup();
        cuts
    }

    /// A_p(h) for all eight paths, RGB, from the tracer (zero where a path does not exist).
    pub fn attenuations(&self, theta_r: f64, h: f64) -> [[f64; 3]; 8] {
        let xs = self.cross_section(theta_r);
        let (ctc, ctm) = (
            cos_refracted(self.eta_c, theta_r),
            cos_refracted(self.eta_m, theta_r),
        );
        let mut out = [[0.0; 3]; 8];
        for (p, name) in PATHS.iter().enumerate() {
            if let Some(t) = trace(&xs, h, name) {
                out[p] = self
                    .sigma_ca
                    .map(|s| t.attenuation(s / ctc, self.sigma_medulla / ctm));
            }
        }
        out
    }

    /// ⟨A_p⟩_h = ½ ∫_{−1}^{1} A_p(h) dh for all eight paths, RGB, split at [`Fiber::cuts`]
    /// and integrated with `panels` panels of 8-point Gauss–Legendre per piece after the
    /// smoothstep substitution (square-root behaviour at the piece ends becomes smooth).
    pub fn mean_attenuations(&self, theta_r: f64, panels: usize) -> [[f64; 3]; 8] {
        let mut acc = [[0.0; 3]; 8];
        average_over_h(&self.cuts(theta_r), panels, |h, w| {
            let a = self.attenuations(theta_r, h);
            for p in 0..8 {
                for ch in 0..3 {
                    acc[p][ch] += w * a[p][ch];
                }
            }
        });
        acc
    }
}

/// Calls `f(h, weight)` at the nodes of ½ ∫_{−1}^{1} · dh split at `cuts` (which must include
/// ±1), smoothstep-substituted Gauss–Legendre, 8 points per panel.
pub fn average_over_h(cuts: &[f64], panels: usize, mut f: impl FnMut(f64, f64)) {
    for w in cuts.windows(2) {
        for (h, wt) in smoothstep_nodes(w[0], w[1], panels, 8) {
            f(h, 0.5 * wt);
        }
    }
}

/// What docs/model.md §8 predicts for the unscattered paths.
#[derive(Clone, Copy, Debug)]
pub struct Prediction {
    /// ρ per channel.
    pub rho: [f64; 3],
    /// ⟨A_p⟩_h per path and channel.
    pub mean_attenuation: [[f64; 3]; 8],
    /// Longitudinal mass per group (with the 1/cos² clamp).
    pub mass: [f64; 3],
}

/// ρ(θ_r) = Σ_p ⟨A_p⟩_h · mass_p (docs/model.md §8, unscattered paths), with mass_p the
/// mass of M_p in the parameters' closure (§12): [`longitudinal_mass`] / [`sphere_mass`].
pub fn predicted_rho(p: &FurParams, theta_r: f64, panels: usize) -> Prediction {
    let fiber = Fiber::of(p);
    let shapes = group_shapes_of(p);
    let mass = shapes
        .map(|g| longitudinal_mass(theta_r, &g, MIN_COS2) / sphere_mass(theta_r, &g, p.closure()));
    let mean = fiber.mean_attenuations(theta_r, panels);
    let mut rho = [0.0; 3];
    for (path, a) in mean.iter().enumerate() {
        for ch in 0..3 {
            rho[ch] += a[ch] * mass[GROUP_OF_PATH[path]];
        }
    }
    Prediction {
        rho,
        mean_attenuation: mean,
        mass,
    }
}

/// ⟨(1 − f)·f²⟩_h for a fiber without medulla and absorption: the energy of the paths beyond
/// TRT (TRRT, TRRRT, …), with the plain single-layer cuticle f at the view angle.
pub fn energy_beyond_trt(eta_c: f64, layers: f64, theta_r: f64, panels: usize) -> f64 {
    let eta = bravais(eta_c, theta_r);
    let mut sum = 0.0;
    average_over_h(&[-1.0, 0.0, 1.0], panels, |h, w| {
        let f = cuticle((1.0 - h * h).sqrt(), 1.0, eta, layers);
        sum += w * (1.0 - f) * f * f;
    });
    sum
}

/// θ_i nodes and weights on [−π/2, π/2] for the furnace: 4-point Gauss–Legendre on panels
/// broken at the poles' clamp edges (cos²θ_i = MIN_COS2), one β_M apart around each group's
/// peak θ_i = α_p − θ_r out to ±8β_M, and at most 0.1 rad wide elsewhere.
pub fn theta_i_nodes(theta_r: f64, shapes: &[GroupShape; 3]) -> Vec<(f64, f64)> {
    theta_i_nodes_with(theta_r, shapes, &[], 0.1)
}

/// [`theta_i_nodes`] with further break points `extra` (those outside (−π/2, π/2) are
/// ignored) and panels at most `max_width` wide: for the full model, whose M^s has kinks where
/// the tabulated C^M is piecewise linear (`crate::profiles_ref::m_s_kinks`).
pub fn theta_i_nodes_with(
    theta_r: f64,
    shapes: &[GroupShape; 3],
    extra: &[f64],
    max_width: f64,
) -> Vec<(f64, f64)> {
    let tc = MIN_COS2.sqrt().acos();
    let mut br = vec![-FRAC_PI_2, -tc, tc, FRAC_PI_2];
    for g in shapes {
        let c = g.shift - theta_r;
        for k in -8..=8 {
            br.push(c + k as f64 * g.beta_m);
        }
    }
    br.extend(extra.iter().copied());
    br.retain(|x| x.abs() <= FRAC_PI_2);
    br.sort_by(|a, b| a.partial_cmp(b).unwrap());
    br.dedup_by(|a, b| (*a - *b).abs() < 1e-9);
    composite_gl_nodes(&br, max_width)
}

/// ρ(θ_r) = ∫ S_far(ω_i, ω_r) cos θ_i dω_i, integrated numerically: θ_i by
/// [`theta_i_nodes`], φ by the periodic trapezoid rule on `n_phi` nodes (spectrally accurate
/// for the smooth periodic far field once the spacing is below ~β_N).
pub fn furnace<M: Math>(model: &FurBcsdf<M>, theta_r: f32, n_phi: usize) -> [f64; 3] {
    let shapes = group_shapes_of(model.params());
    let nodes = theta_i_nodes(theta_r as f64, &shapes);
    furnace_on(model, theta_r, n_phi, &nodes)
}

/// [`furnace`] on given θ_i nodes and weights (e.g. [`theta_i_nodes_with`]).
pub fn furnace_on<M: Math>(
    model: &FurBcsdf<M>,
    theta_r: f32,
    n_phi: usize,
    nodes: &[(f64, f64)],
) -> [f64; 3] {
    let dphi = TAU / n_phi as f64;
    let mut rho = [0.0; 3];
    for &(ti, wi) in nodes {
        let c2 = ti.cos().powi(2);
        for j in 0..n_phi {
            let phi = -PI + dphi * (j as f64 + 0.5);
            let angles = Angles::new(ti as f32, theta_r, phi as f32).expect("valid angles");
            let s = model.eval_far(&angles).total();
            for (r, v) in rho.iter_mut().zip(s.0) {
                *r += wi * c2 * dphi * v as f64;
            }
        }
    }
    rho
}
