//! The baked sampler is perfect importance sampling for grey fibers (docs/model.md §10,
//! "The pole slivers"): every preset made lossless (σ_ca = σ_ma = 0, so the three channels are
//! equal), baked (profiles at 2 % of the default budget, cached;
//! `fur_tests::LOSSLESS_RESOLUTION`), in both closures, at fixed θ_r ∈ {−70°, −30°, 0°, 45°,
//! 80°, 85°, 89°}, 4 000 samples each:
//!
//! - the weights S·cos θ_i/pdf are one constant to 1e-3, samples in the pole slivers (within
//!   `POLE_SLIVER` of θ_i = ±90°, where S's 1/max(cos²θ_i, 10⁻⁴) holds S·cos²θ_i below M·N)
//!   included: the sampler's θ_i densities carry that guard's factor min(1, cos²θ_i/10⁻⁴);
//! - that constant is the LUT's directional albedo ρ(θ_r) = ∫ S·cos²θ_i dθ_i dφ to 1e-3,
//!   integrated by a dense midpoint rule over (θ_i, φ) with `eval`, independent of the
//!   sampler (the θ_i cells refined tenfold within the slivers);
//! - in the energy closure that constant is 1 within 1e-3, pbrt-v3's `SamplingWeights` bound
//!   (docs/model.md §12), and so is the weight of one sample at every θ_r from −89.75° to
//!   89.75° in steps of 0.25° (the weight being that constant, this is ρ(θ_r) = 1 between the
//!   fixed angles: the residual's kinks between its rows, the 1/Z_g table near grazing view).
use bake::profiles::{build_model, scale_budget, ProfileOptions};
use bake::tables;
use bcsdf_core::baked::BakedBcsdf;
use bcsdf_core::medulla::PhotonBudget;
use bcsdf_core::model::POLE_SLIVER;
use bcsdf_core::rng::{cell_stream, Pcg32};
use bcsdf_core::{presets, Angles, Bcsdf, Closure, FurParams, FurParamsInput, Pigment, Rgb};
use fur_tests::per_preset_tests;
use std::f64::consts::{FRAC_PI_2, PI};
use std::path::PathBuf;

const THETA_R_DEG: [f32; 7] = [-70.0, -30.0, 0.0, 45.0, 80.0, 85.0, 89.0];
const DRAWS: u64 = 4_000;

/// The preset made lossless and grey, in `closure`.
fn lossless(name: &str, closure: Closure) -> FurParamsInput {
    FurParamsInput {
        pigment: Pigment::Absorption(Rgb::ZERO),
        sigma_ma: 0.0,
        closure,
        ..presets::find(name).unwrap().input
    }
}

fn bake(input: &FurParamsInput) -> Vec<u8> {
    let params = FurParams::new(input).unwrap();
    let opts = ProfileOptions {
        budget: scale_budget(PhotonBudget::DEFAULT, 0.02).unwrap(),
        cache_dir: Some(PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("fur-profile-cache")),
        ..ProfileOptions::default()
    };
    let model = build_model(params, &opts).unwrap().0;
    tables::bake(&model, input, fur_tests::LOSSLESS_RESOLUTION)
}

/// ρ(θ_r) = ∫ S·cos²θ_i dθ_i dφ of the LUT, first channel: midpoint rule, 1 024 φ cells and
/// θ_i cells of π/2 048, ten times finer within 2·`POLE_SLIVER` of either pole.
fn albedo(lut: &BakedBcsdf, theta_r: f32) -> f64 {
    let n_p = 1024;
    let dp = 2.0 * PI / n_p as f64;
    let edge = 2.0 * f64::from(POLE_SLIVER);
    // (start, end, cells) of the three θ_i stretches.
    let stretches = [
        (-FRAC_PI_2, -FRAC_PI_2 + edge, 130),
        (-FRAC_PI_2 + edge, FRAC_PI_2 - edge, 2048),
        (FRAC_PI_2 - edge, FRAC_PI_2, 130),
    ];
    let mut rho = 0.0;
    for (a, b, n_t) in stretches {
        let dt = (b - a) / n_t as f64;
        for i in 0..n_t {
            let ti = a + dt * (i as f64 + 0.5);
            let c2 = ti.cos().powi(2);
            let mut row = 0.0;
            for j in 0..n_p {
                let phi = -PI + dp * (j as f64 + 0.5);
                let a = Angles::new(ti as f32, theta_r, phi as f32).unwrap();
                row += f64::from(lut.eval(&a).total().0[0]);
            }
            rho += c2 * row * dt * dp;
        }
    }
    rho
}

fn check(name: &str) {
    for closure in Closure::ALL {
        let input = lossless(name, closure);
        let blob = bake(&input);
        let lut = BakedBcsdf::from_bytes(&blob).unwrap();
        for tr_deg in THETA_R_DEG {
            let tr = tr_deg.to_radians();
            let rho = albedo(&lut, tr);
            let (mut lo, mut hi) = (f64::MAX, 0.0f64);
            let mut in_slivers = 0;
            for i in 0..DRAWS {
                let mut rng = Pcg32::new(cell_stream(20, 1, i), cell_stream(20, 2, i));
                let u = [rng.uniform(), rng.uniform(), rng.uniform()];
                let Some(s) = lut.sample(tr, u) else {
                    panic!("{name} {closure:?} θ_r {tr_deg}: no sample")
                };
                if s.angles.theta_i().abs() > std::f32::consts::FRAC_PI_2 - POLE_SLIVER {
                    in_slivers += 1;
                }
                let w = f64::from(s.weight.0[0]);
                lo = lo.min(w);
                hi = hi.max(w);
            }
            println!(
                "{name} {closure:?} θ_r {tr_deg}°: weights {lo:.6} – {hi:.6}, ρ {rho:.6} \
                 ({in_slivers} of {DRAWS} in the pole slivers)"
            );
            assert!(
                hi - lo <= 1e-3 * hi,
                "{name} {closure:?} θ_r {tr_deg}°: weights {lo} – {hi} not constant"
            );
            assert!(
                (hi - rho).abs() <= 1e-3 * rho,
                "{name} {closure:?} θ_r {tr_deg}°: weight {hi} vs the LUT's ρ {rho}"
            );
            if closure == Closure::Energy {
                assert!(
                    (lo - 1.0).abs() <= 1e-3 && (hi - 1.0).abs() <= 1e-3,
                    "{name} energy θ_r {tr_deg}°: weights {lo} – {hi}, not 1 within 1e-3"
                );
            }
        }
        if closure == Closure::Energy {
            sweep(name, &lut);
        }
    }
}

/// One sample's weight at every θ_r from −89.75° to 89.75° in steps of 0.25°, energy
/// closure: 1 within 1e-3.
fn sweep(name: &str, lut: &BakedBcsdf) {
    let (mut lo, mut hi) = ((f64::MAX, 0.0f32), (0.0f64, 0.0f32));
    for k in -359..=359 {
        let tr_deg = k as f32 * 0.25;
        let mut rng = Pcg32::new(cell_stream(21, 1, k as u64), cell_stream(21, 2, k as u64));
        let u = [rng.uniform(), rng.uniform(), rng.uniform()];
        let Some(s) = lut.sample(tr_deg.to_radians(), u) else {
            panic!("{name} energy θ_r {tr_deg}: no sample")
        };
        let w = f64::from(s.weight.0[0]);
        if w < lo.0 {
            lo = (w, tr_deg);
        }
        if w > hi.0 {
            hi = (w, tr_deg);
        }
    }
    println!(
        "{name} Energy, θ_r −89.75°…89.75° every 0.25°: weights {:.6} ({}°) – {:.6} ({}°)",
        lo.0, lo.1, hi.0, hi.1
    );
    assert!(
        (lo.0 - 1.0).abs() <= 1e-3 && (hi.0 - 1.0).abs() <= 1e-3,
        "{name} energy: weights {:.6} at θ_r {}° – {:.6} at {}°, not 1 within 1e-3",
        lo.0,
        lo.1,
        hi.0,
        hi.1
    );
}

per_preset_tests!(check, every_preset_is_checked;
    bobcat: "bobcat",
    cat: "cat",
    deer: "deer",
    dog: "dog",
    mouse: "mouse",
    rabbit: "rabbit",
    raccoon: "raccoon",
    red_fox: "red-fox",
    springbok: "springbok",
    human_fur: "human-fur",
    human_hair: "human-hair",
    air_medulla: "air-medulla",
);
