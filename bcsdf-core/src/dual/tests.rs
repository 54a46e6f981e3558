extern crate std;
use super::*;
use crate::bcsdf::{Bcsdf, SampledDirection};
use crate::frame::Angles;
use crate::lobes::{Families, LobeFamily};
use crate::math::Libm;
use crate::params::{Closure, FurParams, FurParamsInput};
use crate::pigment::Pigment;
use crate::presets;
use crate::residual::{self, ResidualLayout, ResidualTable};
use crate::FurBcsdf;
use std::boxed::Box;
use std::vec;

/// S = 1/π² everywhere (R family): ∫ S cos θ_i dω_i = 1, half of it in each half of φ.
struct Uniform;

impl Bcsdf for Uniform {
    type Math = Libm;
    fn eval(&self, _a: &Angles) -> Families {
        let mut v = [Rgb::ZERO; 4];
        v[LobeFamily::R as usize] = Rgb::splat(1.0 / (PI * PI));
        Families::from_array(v)
    }
    fn pdf(&self, _a: &Angles) -> f32 {
        0.0
    }
    fn sample_direction(&self, _t: f32, _u: [f32; 3]) -> Option<SampledDirection> {
        None
    }
}

fn tables_of(b: &impl Bcsdf, q: Quadrature) -> Box<DualTables> {
    let mut t = Box::new(DualTables::ZERO);
    t.compute(b, q);
    t
}

/// The evaluator an engine gets for `tables`: encoded to a blob and decoded.
fn lut_of(tables: &DualTables, attenuation: Attenuation) -> Box<DualLut> {
    let mut lut = Box::new(DualLut::EMPTY);
    lut.decode(&encode(tables, attenuation, 7)).unwrap();
    lut
}

/// `lut_of(t, att).eval(a, n, d)`.
fn eval(t: &DualTables, a: &Angles, n: f32, d: Density, att: Attenuation) -> Rgb {
    lut_of(t, att).eval(a, n, d)
}

#[test]
fn a_uniform_fiber_has_the_closed_form_averages() {
    let t = tables_of(&Uniform, Quadrature::DEFAULT);
    // ∫cos²θ θ² dθ / ∫cos²θ dθ over [−π/2, π/2] = π²/12 − 1/2.
    let var = PI * PI / 12.0 - 0.5;
    for k in [0, 10, 31, 32, 50, 63] {
        let f = &t.fiber[k];
        let tr = theta_node(k);
        for c in 0..3 {
            assert!((f.a_f[c] - 0.5).abs() < 2e-4, "a_f {k} {:?}", f.a_f);
            assert!((f.a_b[c] - 0.5).abs() < 2e-4, "a_b {k} {:?}", f.a_b);
            assert!((f.alpha_f[c] - tr).abs() < 1e-4, "alpha_f {k}");
            assert!(
                (f.beta2_f[c] - var).abs() < 1e-3,
                "beta2_f {k} {}",
                f.beta2_f[c]
            );
            assert!((f.beta2_b[c] - var).abs() < 1e-3);
        }
        let m = t.moments[k][LobeFamily::R as usize];
        assert!((m.mean[0] - tr).abs() < 1e-4 && (m.variance[0] - var).abs() < 1e-3);
        assert_eq!(t.moments[k][LobeFamily::TT as usize].variance, Rgb::ZERO);
        // n(φ) = 1/(2π) per unit φ; N^G its mean over half a circle, the same.
        for j in 0..PHI_NODES {
            let ng = t.n_g[LobeFamily::R as usize][k][j][0];
            assert!((ng - 0.5 / PI).abs() < 2e-4, "N^G {k} {j} {ng}");
        }
    }
}

/// The lossless plain fiber of the energy closure, with its residual (docs/model.md §12).
fn with_lossless_hair<R>(f: impl FnOnce(&FurBcsdf<'_>) -> R) -> R {
    let input = FurParamsInput {
        pigment: Pigment::Absorption(Rgb::ZERO),
        closure: Closure::Energy,
        ..presets::find("human-hair").unwrap().input
    };
    let params = FurParams::new(&input).unwrap();
    let model: FurBcsdf<'_> = FurBcsdf::unscattered(params);
    let layout = ResidualLayout::DEFAULT;
    let mut data = vec![0.0; layout.len()];
    residual::generate(&model, &layout, 1, &mut data).unwrap();
    let table = ResidualTable::new(params, layout, &data).unwrap();
    f(&model.with_residual(table).unwrap())
}

#[test]
fn front_and_back_sum_to_the_furnace_albedo() {
    with_lossless_hair(|model| {
        let t = tables_of(model, Quadrature::DEFAULT);
        // The furnace's albedo by importance sampling (an independent integrator).
        let mut worst = 0.0f32;
        for k in [2usize, 16, 31, 40, 52, 60] {
            let tr = theta_node(k);
            let n = 4000;
            let mut sum = Rgb::ZERO;
            for s in 0..n {
                let u = [
                    (s as f32 + 0.5) / n as f32,
                    ((s as f32) * 0.618_034).fract(),
                    ((s as f32) * 0.754_877_7).fract(),
                ];
                if let Some(x) = model.sample(tr, u) {
                    sum += x.weight;
                }
            }
            let rho = sum * (1.0 / n as f32);
            let f = &t.fiber[k];
            std::println!(
                "θ_r {tr:.3}: a_f {:?} a_b {:?} sampled ρ {:?}",
                f.a_f,
                f.a_b,
                rho
            );
            for c in 0..3 {
                let total = f.a_f[c] + f.a_b[c];
                worst = worst.max((total - rho[c]).abs());
                // Lossless in the energy closure: 1 (the midpoint rule's error at grazing
                // view, where the lobes meet the pole, is the tolerance).
                let tol = if tr.abs() > 1.3 { 0.02 } else { 0.005 };
                assert!((total - 1.0).abs() < tol, "θ_r {tr}: a_f + a_b = {total}");
            }
            // Lossless hair scatters mostly forward (TT) at normal view.
            if k == 31 {
                assert!(f.a_f[0] > 0.8 && f.a_b[0] > 0.05, "{f:?}");
            }
        }
        assert!(
            worst < 0.02,
            "a_f + a_b against the sampled furnace: {worst}"
        );
    });
}

/// A gently varying fiber for the evaluation tests: the uniform fiber's tables with Gaussian
/// shapes and an absorbing fiber's averages.
fn absorbing_tables() -> Box<DualTables> {
    let mut t = tables_of(
        &Uniform,
        Quadrature {
            theta_steps: 32,
            phi_steps: 16,
        },
    );
    for f in t.fiber.iter_mut() {
        f.a_f = Rgb([0.6, 0.4, 0.2]);
        f.a_b = Rgb([0.2, 0.15, 0.1]);
        f.beta2_f = Rgb::splat(0.01);
        f.beta2_b = Rgb::splat(0.02);
        for c in 0..3 {
            let [a, d, s] = backscatter(f.a_f[c], f.a_b[c], 0.05, -0.1, 0.01, 0.02);
            f.big_a_b[c] = a;
            f.delta_b[c] = d;
            f.sigma_b0[c] = s;
        }
    }
    t
}

#[test]
fn unoccluded_light_gets_only_the_local_backscatter() {
    let t = absorbing_tables();
    let a = Angles::new(0.3, -0.2, 0.4).unwrap();
    let none = Density { d_f: 0.7, d_b: 0.0 };
    // n = 0 (and NaN, negative): the spread term vanishes; with d_b = 0 nothing is left.
    for n in [0.0, -3.0, f32::NAN, f32::NEG_INFINITY] {
        assert_eq!(
            eval(&t, &a, n, none, Attenuation::Forward),
            Rgb::ZERO,
            "n = {n}"
        );
    }
    let d = Density { d_f: 0.7, d_b: 0.5 };
    let b0 = eval(&t, &a, 0.0, d, Attenuation::Forward);
    assert!(b0.0.iter().all(|&v| v > 0.0), "{b0:?}");
    assert_eq!(eval(&t, &a, -1.0, d, Attenuation::Forward), b0);
    assert_eq!(eval(&t, &a, f32::NAN, d, Attenuation::Forward), b0);
    // Continuous as the first fiber comes in.
    let b1 = eval(&t, &a, 1e-4, d, Attenuation::Forward);
    for c in 0..3 {
        assert!((b1[c] - b0[c]).abs() < 1e-3 * b0[c] + 1e-6, "{b0:?} {b1:?}");
    }
    // The front half gets no local backscatter.
    let front = Angles::new(0.3, -0.2, 2.5).unwrap();
    assert_eq!(eval(&t, &front, 0.0, d, Attenuation::Forward), Rgb::ZERO);
}

#[test]
fn occluded_light_fades_with_the_fiber_count() {
    let t = absorbing_tables();
    let a = Angles::new(0.25, -0.2, 2.8).unwrap();
    let d = Density::DEFAULT;
    let mut last = eval(&t, &a, 1.0, d, Attenuation::Forward);
    assert!(last.0.iter().all(|&v| v > 0.0), "{last:?}");
    for n in [2.0, 4.0, 8.0, 16.0] {
        let v = eval(&t, &a, n, d, Attenuation::Forward);
        for c in 0..3 {
            assert!(v[c] < last[c], "n = {n}: {v:?} !< {last:?}");
        }
        last = v;
    }
    // Blue (ā_f = 0.2) fades fastest.
    let v = eval(&t, &a, 4.0, d, Attenuation::Forward);
    assert!(v[2] < v[1] && v[1] < v[0], "{v:?}");
    // The spread term is linear in d_f.
    let no_b = |d_f| Density { d_f, d_b: 0.0 };
    let (x, y) = (
        eval(&t, &a, 3.0, no_b(0.35), Attenuation::Forward),
        eval(&t, &a, 3.0, no_b(0.7), Attenuation::Forward),
    );
    for c in 0..3 {
        assert!((2.0 * x[c] - y[c]).abs() <= 1e-6 * y[c]);
    }
    // With the coat's backscatter kept more light gets through than forward alone.
    let coat = eval(&t, &a, 4.0, d, Attenuation::Coat);
    for c in 0..3 {
        assert!(coat[c] > v[c], "{coat:?} vs {v:?}");
    }
    // Many fibers: nothing gets through.
    assert_eq!(eval(&t, &a, 1e5, d, Attenuation::Forward), Rgb::ZERO);
    assert_eq!(
        eval(&t, &a, f32::INFINITY, d, Attenuation::Forward),
        Rgb::ZERO
    );
}

#[test]
fn the_term_is_even_in_phi() {
    let t = absorbing_tables();
    let d = Density::DEFAULT;
    for (ti, tr, phi, n) in [
        (0.2, 0.1, 0.5, 0.0),
        (-0.4, 0.3, 2.0, 3.0),
        (0.0, 0.0, 1.2, 1.0),
    ] {
        let p = eval(
            &t,
            &Angles::new(ti, tr, phi).unwrap(),
            n,
            d,
            Attenuation::Coat,
        );
        let m = eval(
            &t,
            &Angles::new(ti, tr, -phi).unwrap(),
            n,
            d,
            Attenuation::Coat,
        );
        assert_eq!(p, m);
    }
}

#[test]
fn degenerate_input_stays_finite() {
    let tables = [absorbing_tables(), Box::new(DualTables::ZERO), {
        let mut t = absorbing_tables();
        for f in t.fiber.iter_mut() {
            f.a_f = Rgb([1.0, f32::NAN, 2.0]);
            f.sigma_b0 = Rgb([0.0, f32::INFINITY, -1.0]);
            f.beta2_f = Rgb([-1.0, f32::NAN, 0.0]);
        }
        t.moments[5][0].variance = Rgb([f32::NAN, -1.0, 0.0]);
        t
    }];
    let half = 0.5 * PI;
    let angles = [
        Angles::new(half, half, PI).unwrap(),
        Angles::new(-half, half, 0.0).unwrap(),
        Angles::new(0.0, -half, 1e-30).unwrap(),
        Angles::new(1e-7, 0.0, -PI).unwrap(),
    ];
    let counts = [
        0.0,
        1.0,
        0.5,
        1e9,
        f32::MAX,
        f32::INFINITY,
        f32::NAN,
        -f32::MAX,
        1e-38,
    ];
    let dens = [0.0, 0.7, f32::NAN, f32::INFINITY, -1.0, 1e30];
    for t in &tables {
        let luts = [
            lut_of(t, Attenuation::Forward),
            lut_of(t, Attenuation::Coat),
            Box::new(DualLut::EMPTY),
        ];
        for a in &angles {
            for &n in &counts {
                for &d_f in &dens {
                    for &d_b in &dens {
                        for lut in &luts {
                            let v = lut.eval(a, n, Density { d_f, d_b });
                            assert!(v.0.iter().all(|x| x.is_finite() && *x >= 0.0), "{v:?}");
                        }
                    }
                }
            }
        }
    }
    // Positions at NaN or out-of-range θ are the end nodes.
    assert_eq!(theta_position(f32::NAN), (0, 0.0));
    assert_eq!(theta_position(9.0), (THETA_NODES - 2, 1.0));
}

#[test]
fn the_local_backscatter_is_zinkes_series() {
    // A₁ = Σ_{k≥1} ā_b ā_f^{2k}: k fibers crossed in, one back, k out. Summed directly.
    for (af, ab) in [(0.5f32, 0.2f32), (0.9, 0.05), (0.2, 0.6)] {
        let a1: f32 = (1..400).map(|k| ab * af.powi(2 * k)).sum();
        // A₃ = ā_b³ ā_f² Σ_k C(k+2, 2) ā_f^{2k}: three back events and the forward legs
        // around them (the generating function 1/(1 − x)³).
        let a3: f32 = (0..400)
            .map(|k| {
                let kk = k as f32;
                ab * ab * ab * af * af * (kk + 1.0) * (kk + 2.0) * 0.5 * af.powi(2 * k)
            })
            .sum();
        let [a, _, s] = backscatter(af, ab, 0.0, 0.0, 0.01, 0.02);
        assert!(
            (a - (a1 + a3)).abs() < 1e-5 * (a1 + a3),
            "{a} vs {}",
            a1 + a3
        );
        // σ_b lies between the two path classes' widths.
        assert!(
            s >= 0.04f32.sqrt() - 1e-6 && s <= 0.08f32.sqrt() + 1e-6,
            "{s}"
        );
    }
    assert_eq!(backscatter(0.0, 0.5, 0.1, 0.1, 0.01, 0.01)[0], 0.0);
    assert!(backscatter(1.0, 1.0, 0.1, 0.1, 0.01, 0.01)
        .iter()
        .all(|v| v.is_finite()));
}

/// The adding method, one layer at a time (T_{k+1} = t T_k/(1 − r R_k),
/// R_{k+1} = r + t² R_k/(1 − r R_k)), in f64: the stack's (T_n, R_n).
fn adding(t: f64, r: f64, n: u32) -> (f64, f64) {
    let (mut tk, mut rk) = (1.0f64, 0.0f64);
    for _ in 0..n {
        let d = 1.0 - rk * r;
        (tk, rk) = (tk * t / d, r + t * t * rk / d);
    }
    (tk, rk)
}

#[test]
fn the_coat_decay_is_the_adding_method_on_a_semi_infinite_stack() {
    for (t, r) in [
        (0.537f32, 0.40f32),
        (0.30, 0.28),
        (0.8, 0.1),
        (0.2, 0.05),
        (0.9, 0.0999),
    ] {
        let (t64, r64) = (f64::from(t), f64::from(r));
        let (_, r_inf) = adding(t64, r64, 100_000);
        for n in [1u32, 2, 5, 17] {
            // D_n = T_n/(1 − R_n R_∞), the adding method with the coat below.
            let (tn, rn) = adding(t64, r64, n);
            let want = tn / (1.0 - rn * r_inf);
            let got = f64::from(transmittance(Attenuation::Coat, t, r, n as f32));
            assert!(
                (got - want).abs() < 2e-5 + 1e-4 * want,
                "t {t} r {r} n {n}: {got} vs {want}"
            );
        }
        // Fractional n: geometric between the integers (D_n is geometric).
        let (a, b) = (
            transmittance(Attenuation::Coat, t, r, 2.0),
            transmittance(Attenuation::Coat, t, r, 3.0),
        );
        let mid = transmittance(Attenuation::Coat, t, r, 2.5);
        assert!(
            (mid - (a * b).sqrt()).abs() < 1e-5,
            "{mid} vs {}",
            (a * b).sqrt()
        );
        // The semi-infinite stack's reflectance is the limit of the recursion's R_n.
        let closed = semi_infinite_reflectance(t, r);
        assert!(
            (f64::from(closed) - r_inf).abs() < 1e-4,
            "t {t} r {r}: {closed} vs {r_inf}"
        );
    }
    // Lossless layers: D_n = 1 at every depth; no reflection: t^n; Forward: ā_f^n.
    for (t, r) in [(0.54f32, 0.46f32), (0.9, 0.1), (0.3, 0.7)] {
        assert_eq!(coat_decay(Attenuation::Coat, t, r), 1.0, "t {t}");
    }
    for n in [1.0f32, 3.0, 7.0] {
        let a = transmittance(Attenuation::Coat, 0.6, 0.0, n);
        assert!((a - 0.6f32.powf(n)).abs() < 1e-6, "{a}");
        assert_eq!(
            transmittance(Attenuation::Forward, 0.6, 0.3, n),
            0.6f32.powf(n)
        );
    }
    for n in [0.0, -1.0, f32::NAN] {
        assert_eq!(transmittance(Attenuation::Coat, 0.5, 0.3, n), 1.0);
    }
    for bad in [f32::NAN, -1.0, f32::INFINITY, 0.0] {
        let mu = coat_decay(Attenuation::Coat, bad, 0.3);
        assert!((0.0..=1.0).contains(&mu), "{bad}: {mu}");
    }
    assert!(transmittance(Attenuation::Coat, 1.0, 0.0, f32::INFINITY) <= 1.0);
    assert_eq!(semi_infinite_reflectance(0.5, 0.0), 0.0);
}

/// A random walk through the layered coat, independent of the adding method's closed forms:
/// a photon enters at the top going down; each layer it meets passes it on (probability t),
/// turns it round (r) or absorbs it. Returns the mean number of downward crossings of the
/// boundary under `depth` layers (the downward flux there, D) and of upward crossings of the
/// boundary under `depth + 1` layers (the flux the coat below sends up to layer depth + 1,
/// U), for a stack of `total` layers (deep enough to stand for the semi-infinite coat).
fn walk_fluxes(t: f32, r: f32, depth: u32, total: u32, photons: u32) -> (f64, f64) {
    let mut rng = crate::rng::Pcg32::new(23, u64::from(depth));
    let (mut down, mut up) = (0u64, 0u64);
    for _ in 0..photons {
        // Position: the boundary index (0 = top), direction: +1 down, −1 up.
        let (mut at, mut dir) = (0i64, 1i64);
        loop {
            if dir > 0 && at == i64::from(depth) {
                down += 1;
            }
            if dir < 0 && at == i64::from(depth) + 1 {
                up += 1;
            }
            // The layer crossed next: at (going down) or at − 1 (going up).
            let layer = if dir > 0 { at } else { at - 1 };
            if layer < 0 || layer >= i64::from(total) {
                break; // left by the top, or out of the bottom of the deep stack
            }
            let u = rng.uniform();
            if u < t {
                at += dir;
            } else if u < t + r {
                dir = -dir;
            } else {
                break;
            }
        }
    }
    let p = f64::from(photons);
    (down as f64 / p, up as f64 / p)
}

#[test]
fn the_coat_fluxes_match_a_random_walk_through_the_layers() {
    // Absorbing layers (the walk ends: a deep stack is semi-infinite) and lossless ones
    // (the walk on a lossless stack is a recurrent random walk: it would not end, so only the
    // closed form's limit, D_n = 1, is checked there).
    for (t, r) in [(0.537f32, 0.40f32), (0.30, 0.28), (0.8, 0.1), (0.5, 0.0)] {
        for depth in [0u32, 1, 2, 5] {
            let (d, u) = walk_fluxes(t, r, depth, 400, 200_000);
            let got_d = f64::from(transmittance(Attenuation::Coat, t, r, depth as f32));
            // U per unit of D: the light through the fiber at `depth`, reflected back by the
            // coat below, with the inter-reflections (what `local_backscatter` divides by ā_f).
            let (back, front) = local_backscatter(Attenuation::Coat, 0.0, t, r);
            let got_u = if t > 0.0 { f64::from(back / t) } else { 0.0 } * got_d;
            let tol_d = 4.0 * (d / 200_000.0).sqrt() + 2e-3 * d;
            assert!(
                (got_d - d).abs() <= tol_d,
                "t {t} r {r} n {depth}: D {got_d} vs walk {d}"
            );
            let tol_u = 4.0 * (u.max(1e-3) / 200_000.0).sqrt() + 2e-3 * u;
            assert!(
                (got_u - u).abs() <= tol_u,
                "t {t} r {r} n {depth}: U {got_u} vs walk {u}"
            );
            // The fiber scatters U forward (back half) and back (front half).
            assert!((f64::from(front) - f64::from(r) * got_u / got_d.max(1e-12)).abs() < 1e-5);
        }
    }
    // Lossless layers: the coat below returns everything, the downward flux is 1 at every
    // depth (a finite stack alone gives 1/(1 + n r/t)), and the fiber scatters all of U.
    // In f32, R_∞'s square root of a vanishing discriminant is off by ~1e-3, which the
    // denominator 1 − R_n R_∞ feels more as T_n falls: 2.7e-3 at n = 40 for t = 0.9.
    for (t, r) in [(0.54f32, 0.46f32), (0.9, 0.1)] {
        for n in [1.0f32, 2.0, 7.5, 40.0] {
            let d = transmittance(Attenuation::Coat, t, r, n);
            assert!((d - 1.0).abs() < 4e-3, "t {t} n {n}: {d}");
            let (tn, _) = adding(f64::from(t), f64::from(r), n as u32);
            assert!(
                f64::from(d) > tn,
                "the finite stack alone lets less through"
            );
        }
        let (back, front) = local_backscatter(Attenuation::Coat, 0.0, t, r);
        assert!((back + front - 1.0).abs() < 2e-3, "{back} + {front}");
    }
    for n in [0.0, -1.0, f32::NAN] {
        assert_eq!(transmittance(Attenuation::Coat, 0.5, 0.3, n), 1.0);
    }
    // Coat's back-half energy is R_∞ − ā_b (= ā_f U); Zinke's is its own.
    let (b_c, _) = local_backscatter(Attenuation::Coat, 0.7, 0.5, 0.3);
    let r_inf = semi_infinite_reflectance(0.5, 0.3);
    assert!(
        (b_c - (r_inf - 0.3)).abs() < 1e-6,
        "{b_c} vs {}",
        r_inf - 0.3
    );
    assert_eq!(
        local_backscatter(Attenuation::Forward, 0.7, 0.5, 0.3),
        (0.7, 0.0)
    );
    for bad in [f32::NAN, -1.0, f32::INFINITY] {
        let (b, f) = local_backscatter(Attenuation::Coat, bad, bad, bad);
        assert!(b.is_finite() && f.is_finite() && b >= 0.0 && f >= 0.0);
    }
}

#[test]
fn the_blob_round_trips_to_half_precision() {
    let t = absorbing_tables();
    let blob = encode(&t, Attenuation::Coat, 0xfeed);
    assert_eq!(blob.len(), BLOB_LEN);
    let mut lut = Box::new(DualLut::EMPTY);
    lut.decode(&blob).unwrap();
    assert_eq!(
        (lut.attenuation(), lut.source()),
        (Attenuation::Coat, 0xfeed)
    );
    // Encoding what was decoded gives the same bytes (f16 values are exact in f32).
    for k in [0usize, 17, 63] {
        let f = &t.fiber[k];
        for c in 0..3 {
            let mu = coat_decay(Attenuation::Coat, f.a_f[c], f.a_b[c]);
            let got = libm::exp2f(lut.nodes[k][blob::LOG2_DECAY][c]);
            assert!((got - mu).abs() < 1e-3 * mu, "μ {got} vs {mu}");
            let (back, front) =
                local_backscatter(Attenuation::Coat, f.big_a_b[c], f.a_f[c], f.a_b[c]);
            assert!((lut.nodes[k][blob::BACK][c] - back).abs() <= 5e-4 * back);
            assert!((lut.nodes[k][blob::FRONT][c] - front).abs() <= 5e-4 * front);
            assert_eq!(lut.nodes[k][blob::BACK][3], 0.0);
        }
        let ng = t.n_g[0][k][5][1];
        assert!((lut.n_g[0][k][5][1] - ng).abs() <= 5e-4 * ng);
    }
    // Forward stores μ = ā_f.
    let fwd = lut_of(&t, Attenuation::Forward);
    assert!((libm::exp2f(fwd.nodes[3][blob::LOG2_DECAY][0]) - 0.6).abs() < 1e-3);
}

#[test]
fn a_damaged_blob_is_refused_and_leaves_the_evaluator_alone() {
    let good = encode(&absorbing_tables(), Attenuation::Coat, 1);
    let mut lut = Box::new(DualLut::EMPTY);
    lut.decode(&good).unwrap();
    let before = lut.clone();
    let reseal = |b: &mut [u8]| {
        let sum = blob::checksum_of(b);
        b[56..64].copy_from_slice(&sum.to_le_bytes());
    };
    let mut cases: std::vec::Vec<(std::vec::Vec<u8>, DualError)> = std::vec::Vec::new();
    cases.push((good[..100].to_vec(), DualError::Length(100)));
    let mut b = good.to_vec();
    b.push(0);
    cases.push((b, DualError::Length(BLOB_LEN + 1)));
    let mut b = good.to_vec();
    b[0] = b'X';
    cases.push((b, DualError::Magic));
    let mut b = good.to_vec();
    b[8] = 9;
    cases.push((b, DualError::FormatVersion(9)));
    let mut b = good.to_vec();
    b[12] = 99;
    cases.push((b, DualError::ModelVersion(99)));
    let mut b = good.to_vec();
    b[16] = 65;
    cases.push((b, DualError::Layout));
    let mut b = good.to_vec();
    b[50] = 1;
    cases.push((b, DualError::Layout));
    let mut b = good.to_vec();
    b[32] = 3;
    cases.push((b, DualError::Attenuation(3)));
    let mut b = good.to_vec();
    b[1000] ^= 1;
    cases.push((b, DualError::Checksum));
    // Sealed but hostile values: a NaN, an infinity, a negative width, ā_f² above 1, a
    // positive log₂ μ, a negative N^G.
    let field = |k: usize, f: usize, c: usize| (k * FIELDS + f) * 3 + c;
    let ng0 = THETA_NODES * FIELDS * 3;
    for (i, bits) in [
        (field(4, blob::MEAN, 1), 0x7e00u16),
        (field(4, blob::DELTA_B, 0), 0x7c00),
        (field(9, blob::SD + 2, 2), 0xbc00),
        (field(9, blob::A_F2, 0), 0x3c01),
        (field(0, blob::LOG2_DECAY, 0), 0x3c00),
        (ng0 + 77, 0x8001),
    ] {
        let mut b = good.to_vec();
        b[64 + 2 * i..66 + 2 * i].copy_from_slice(&bits.to_le_bytes());
        reseal(&mut b);
        cases.push((b, DualError::Value(i)));
    }
    for (bytes, want) in cases {
        assert_eq!(lut.decode(&bytes), Err(want));
        assert_eq!(lut, before, "{want:?} changed the evaluator");
        assert!(!std::format!("{want}").is_empty());
    }
}

#[test]
fn the_evaluator_is_allocation_free_and_matches_the_stored_formula() {
    // The term recomputed from the decoded node values with f64 Gaussians (independent of
    // the lane code): back half, n = 2.5, default density.
    let t = absorbing_tables();
    let lut = lut_of(&t, Attenuation::Coat);
    let (ti, tr, phi, n) = (0.31f32, -0.22f32, 0.7f32, 2.5f32);
    let got = lut.eval(&Angles::new(ti, tr, phi).unwrap(), n, Density::DEFAULT);
    let g = |d: f64, v: f64| (-d * d / (2.0 * v)).exp() / (2.0 * std::f64::consts::PI * v).sqrt();
    let lerp_at = |theta: f32, f: usize, c: usize| {
        let (k, w) = theta_position(theta);
        f64::from(lut.nodes[k][f][c]) * f64::from(1.0 - w)
            + f64::from(lut.nodes[k + 1][f][c]) * f64::from(w)
    };
    for c in 0..3 {
        let x = f64::from(ti + tr);
        let inv = 1.0 / f64::from(ti).cos().powi(2);
        let mu = lerp_at(-ti, blob::LOG2_DECAY, c).exp2();
        let s2 = f64::from(n) * lerp_at(-ti, blob::BETA_F, c).powi(2);
        let sb = (1.0 + lerp_at(tr, blob::A_F2, c)) * lerp_at(tr, blob::SIGMA_B0, c);
        let back = lerp_at(tr, blob::BACK, c);
        let db = x - lerp_at(tr, blob::DELTA_B, c);
        let mut fs = 0.0;
        for fam in 0..FAMILY_COUNT {
            let (k, w) = theta_position(tr);
            let p = f64::from(phi) * (PHI_NODES - 1) as f64 / std::f64::consts::PI;
            let (j, v) = (p as usize, p - p.floor());
            let tab = &lut.n_g[fam];
            let at = |kk: usize, jj: usize| f64::from(tab[kk][jj][c]);
            let ng = (at(k, j) * (1.0 - v) + at(k, j + 1) * v) * f64::from(1.0 - w)
                + (at(k + 1, j) * (1.0 - v) + at(k + 1, j + 1) * v) * f64::from(w);
            let m = lerp_at(tr, blob::MEAN + fam, c);
            let sd = lerp_at(tr, blob::SD + fam, c);
            fs += ng * g(x - m, (sd * sd + s2).max(f64::from(MIN_VARIANCE)));
        }
        let want = mu.powf(f64::from(n))
            * (fs * inv
                + back * g(db, (sb * sb + s2).max(f64::from(MIN_VARIANCE))) * inv
                    / std::f64::consts::PI);
        let err = (f64::from(got[c]) - want).abs() / want;
        assert!(err < 1e-4, "channel {c}: {} vs {want} ({err:e})", got[c]);
    }
}
