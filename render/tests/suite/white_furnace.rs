//! The whole-coat white furnace (docs/model.md §11): a clump of fibers in a uniform environment of
//! radiance 1 and nothing else. If the fibers lose no energy, every pixel's expected value
//! is exactly 1, however many times light scatters between them.
//!
//! - The integrator itself is proved with an ideal fiber: S = 1/π² in every direction, so
//!   ∫ S cos θ_i dω_i = (1/π²)·2π·∫cos²θ dθ = 1 exactly, and its exact uniform-sphere sampler.
//! - The fur BCSDF, made lossless (σ_ca = σ_ma = 0), in the energy closure (docs/model.md §12:
//!   M on the sphere, the residual) keeps the furnace white like the ideal fiber, for a plain
//!   and a medullated preset; in the report closure its deficit per bounce order is printed.

use crate::common;

use bcsdf_core::{
    Angles, Bcsdf, Closure, Families, Libm, LobeFamily, Pigment, Rgb, SampledDirection,
};
use core::f32::consts::PI;
use render::scatter::One;
use render::{integrator, scenes, Render, SceneKind, SceneOptions, Settings};

/// The ideal fiber: S = 1/π² everywhere, sampled with density p_ω = cos θ_i/π² (per
/// (θ_i, φ): cos²θ_i/π², so θ_i has density (2/π)cos²θ_i and φ is uniform). Every sample's
/// weight S·cos θ_i/p_ω is exactly 1. `Uniform`: the same S sampled uniformly on the
/// sphere (p_ω = 1/4π), whose weights 4cos θ_i/π vary, so Russian roulette is exercised.
#[derive(Clone, Copy)]
enum IdealFiber {
    Exact,
    Uniform,
}

impl Bcsdf for IdealFiber {
    type Math = Libm;

    fn eval(&self, _angles: &Angles) -> Families {
        let mut values = [Rgb::ZERO; 4];
        values[LobeFamily::R as usize] = Rgb::splat(1.0 / (PI * PI));
        Families::from_array(values)
    }

    fn pdf(&self, angles: &Angles) -> f32 {
        match self {
            IdealFiber::Exact => angles.theta_i().cos().max(0.0) / (PI * PI),
            IdealFiber::Uniform => 1.0 / (4.0 * PI),
        }
    }

    fn sample_direction(&self, theta_r: f32, u: [f32; 3]) -> Option<SampledDirection> {
        if let IdealFiber::Uniform = self {
            // sin θ_i uniform in [−1, 1], φ uniform.
            return Some(SampledDirection {
                angles: Angles::new(
                    (2.0 * u[0] - 1.0).clamp(-1.0, 1.0).asin(),
                    theta_r,
                    PI * (2.0 * u[1] - 1.0),
                )
                .ok()?,
                family: LobeFamily::R,
            });
        }
        // Invert F(θ) = (θ + sin θ cos θ + π/2)/π = u by Newton's method (F' = (2/π)cos²θ).
        let target = f64::from(u[0]);
        let mut t = (2.0 * target - 1.0).asin() * 0.5;
        for _ in 0..40 {
            let f = (t + t.sin() * t.cos() + core::f64::consts::FRAC_PI_2) / core::f64::consts::PI;
            let df = 2.0 / core::f64::consts::PI * t.cos() * t.cos();
            if df < 1e-12 {
                break;
            }
            t = (t - (f - target) / df)
                .clamp(-core::f64::consts::FRAC_PI_2, core::f64::consts::FRAC_PI_2);
        }
        let phi = PI * (2.0 * u[1] - 1.0);
        Some(SampledDirection {
            angles: Angles::new(t as f32, theta_r, phi).ok()?,
            family: LobeFamily::R,
        })
    }
}

fn settings() -> Settings {
    Settings {
        max_depth: 1024,
        seed: 21,
        ..Settings::new(20, 20, 128)
    }
}

fn furnace(fibers: usize) -> render::scene::Scene {
    scenes::build(&SceneOptions {
        kind: SceneKind::Furnace,
        fibers: Some(fibers),
        seed: 5,
        aspect: 1.0,
    })
}

/// Every pixel's mean within 5 of its standard errors of 1, the image mean within 0.5 %.
fn assert_white(r: &Render, what: &str) {
    let whole = r.image.whole();
    for c in 0..3 {
        assert!(
            (whole.mean[c] - 1.0).abs() < 0.005,
            "{what}: image mean {:?} ± {:?}",
            whole.mean,
            whole.std_error
        );
    }
    assert_pixels_white(r, what);
}

/// Every pixel within 5 of its standard errors of 1.
fn assert_pixels_white(r: &Render, what: &str) {
    let mut worst = 0.0f64;
    for (m, v) in r.image.mean.iter().zip(&r.image.variance) {
        for c in 0..3 {
            let se = f64::from(v[c]).sqrt();
            let dev = (f64::from(m[c]) - 1.0).abs();
            // A pixel whose samples all agree has no spread: it must be 1 to rounding.
            let z = if se > 0.0 {
                dev / se
            } else if dev < 1e-5 {
                0.0
            } else {
                f64::INFINITY
            };
            worst = worst.max(z);
        }
    }
    assert!(
        worst < 5.0,
        "{what}: a pixel lies {worst:.2} standard errors from 1"
    );
}

fn print_orders(what: &str, r: &Render) {
    let total: f64 = r.orders.iter().map(|o| o[1]).sum();
    let shown: Vec<String> = r
        .orders
        .iter()
        .take(12)
        .map(|o| format!("{:.4}", o[1]))
        .collect();
    println!(
        "{what}: mean {:.4} (deficit {:.2} %), energy per bounce order 0..11 (G): {}",
        total,
        100.0 * (1.0 - total),
        shown.join(" ")
    );
}

#[test]
fn ideal_fibers_keep_the_furnace_white() {
    let scene = furnace(1500);
    let r = integrator::render(&scene, &One(&IdealFiber::Exact), &settings()).unwrap();
    print_orders("ideal fiber", &r);
    println!("ideal fiber: {:?}", r.image.whole());
    // The clump scatters: most light arrives after one or more bounces.
    assert!(
        r.orders[0][0] < 0.6 && r.orders[2][0] > 0.05,
        "{:?}",
        &r.orders[..4]
    );
    assert_white(&r, "ideal fiber");
}

/// The ideal fiber sampled uniformly: throughputs vary, Russian roulette kills and
/// reweights paths, and the furnace must stay white within its noise (|mean − 1| below 4
/// standard errors, every pixel within 5 of its own).
#[test]
fn ideal_fibers_with_roulette_keep_the_furnace_white() {
    let scene = furnace(1500);
    let r = integrator::render(&scene, &One(&IdealFiber::Uniform), &settings()).unwrap();
    let whole = r.image.whole();
    println!("ideal fiber, uniform sampling: {whole:?}");
    assert!(
        (whole.mean[0] - 1.0).abs() < 4.0 * whole.std_error[0],
        "{whole:?}"
    );
    assert_pixels_white(&r, "ideal fiber, uniform sampling");
}

/// With BCSDF sampling alone every path carries weight 1 until it escapes into radiance 1:
/// every sample, hence every pixel, is 1 to rounding. A path lost anywhere (a failed
/// sample, a self-hit, a wrong weight) shows up here.
#[test]
fn ideal_fibers_with_bcsdf_sampling_give_exactly_one_per_pixel() {
    let scene = furnace(1500);
    let settings = Settings {
        strategy: render::Strategy::Bcsdf,
        max_depth: 4096,
        ..Settings::new(12, 12, 8)
    };
    let r = integrator::render(&scene, &One(&IdealFiber::Exact), &settings).unwrap();
    assert!(r.orders[1][0] > 0.1, "{:?}", &r.orders[..3]);
    let worst = r
        .image
        .mean
        .iter()
        .flatten()
        .map(|&m| (m - 1.0).abs())
        .fold(0.0, f32::max);
    assert!(worst < 1e-4, "a pixel is {worst} away from 1");
}

/// The fur BCSDF, lossless, in the energy closure: the image mean within 0.5 % of 1 and every
/// pixel within 5 of its standard errors, for a plain and a medullated preset.
#[test]
fn lossless_fur_in_the_energy_closure_keeps_the_furnace_white() {
    let scene = furnace(1500);
    for preset in [common::plain(), common::medullated()] {
        let mut input = preset.input;
        input.pigment = Pigment::Absorption(Rgb::ZERO);
        input.sigma_ma = 0.0;
        input.closure = Closure::Energy;
        let settings = Settings {
            max_depth: 1024,
            seed: 21,
            ..Settings::new(32, 32, 128)
        };
        let r = common::with_model(&input, |model| {
            integrator::render(&scene, &One(model), &settings)
        })
        .unwrap();
        let name = format!("{} lossless, energy closure", preset.name);
        print_orders(&name, &r);
        println!("{name}: {:?}", r.image.whole());
        assert_white(&r, &name);
    }
}

/// The fur BCSDF, lossless, in report mode: prints the deficit per bounce order. The
/// model's energy deficit compounds with every bounce; what can be asserted without the
/// energy closure is that no energy is created.
#[test]
fn lossless_fur_reports_its_deficit_per_bounce() {
    let scene = furnace(1500);
    for preset in [common::plain(), common::medullated()] {
        let mut input = preset.input;
        input.pigment = Pigment::Absorption(Rgb::ZERO);
        input.sigma_ma = 0.0;
        input.closure = Closure::Report;
        let settings = Settings {
            max_depth: 256,
            ..Settings::new(16, 16, 8)
        };
        let r = common::with_model(&input, |model| {
            integrator::render(&scene, &One(model), &settings)
        })
        .unwrap();
        print_orders(&format!("{} lossless", preset.name), &r);
        let whole = r.image.whole();
        for c in 0..3 {
            assert!(
                whole.mean[c] < 1.0 + 5.0 * whole.std_error[c] && whole.mean[c] > 0.3,
                "{}: {:?} ± {:?}",
                preset.name,
                whole.mean,
                whole.std_error
            );
        }
    }
}
