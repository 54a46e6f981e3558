//! Unit tests of dual scattering: the tables by quadrature, the term's properties through the
//! blob; the attenuation ([`attenuation`]), the finite coat ([`coat`]) and the stored blob
//! ([`stored`]) in their own files.

extern crate std;
use super::*;
use crate::bcsdf::{Bcsdf, SampledDirection};
use crate::frame::Angles;
use crate::lobes::{Families, LobeFamily};
use crate::math::Libm;
use crate::params::{Closure, FurParams, FurParamsInput};
use crate::pigment::Pigment;
use crate::presets;
use crate::residual::{ResidualLayout, ResidualTable};
use crate::residual_gen as residual;
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

/// `lut_of(t, att).eval(a, n, d)` over a semi-infinite coat ([`Fibers::deep`]).
fn eval(t: &DualTables, a: &Angles, n: f32, d: Density, att: Attenuation) -> Rgb {
    lut_of(t, att).eval(a, Fibers::deep(n), d)
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
                for &m in &counts {
                    for &d_f in &dens {
                        for &d_b in &dens {
                            for lut in &luts {
                                let v = lut.eval(a, Fibers::new(n, m), Density { d_f, d_b });
                                assert!(v.0.iter().all(|x| x.is_finite() && *x >= 0.0), "{v:?}");
                            }
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

mod attenuation;
mod axis;
mod coat;
mod stored;
