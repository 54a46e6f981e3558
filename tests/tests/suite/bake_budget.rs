//! The bake's error budget (docs/lut.md, "Error metrics and budget") and determinism:
//!
//! - every built-in preset (one test each; a test checks none is missing), baked at the
//!   default resolution from its full-budget profiles, is within E1 ≤ 1 %, E_albedo ≤ 0.5 %,
//!   E_peak ≤ 2 % of the analytic model on the shared metric set (`bake::metrics`), in the
//!   report closure and, a second test each, in the energy closure, every preset's default
//!   (docs/model.md §12: the LUT's 1/Z_g table and the residual folded into N_TRT against the
//!   analytic erf-renormalised lobes and residual);
//! - the same metrics flag a LUT whose azimuthal table is off by 3 % (so the budget test can
//!   fail);
//! - the baked blob and the metrics are the same bits across runs and thread counts.
//!
//! Profiles are cached under Cargo's per-target temporary directory, so only the first run
//! generates them (≈ 10 s per preset on two cores).

use bake::metrics::{compare, ErrorBudget, MetricSet};
use bake::profiles::{build_model, scale_budget, OwnedModel, ProfileOptions};
use bake::tables;
use bcsdf_core::baked::BakedBcsdf;
use bcsdf_core::lut::{self, LutResolution, Table};
use bcsdf_core::medulla::PhotonBudget;
use bcsdf_core::{presets, Closure, FurParams, FurParamsInput};
use std::path::PathBuf;

fn cache_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("fur-profile-cache")
}

fn model(name: &str, budget: PhotonBudget) -> OwnedModel {
    model_in(&presets::find(name).unwrap().input, budget)
}

fn model_in(input: &FurParamsInput, budget: PhotonBudget) -> OwnedModel {
    let params = FurParams::new(input).unwrap();
    let opts = ProfileOptions {
        budget,
        cache_dir: Some(cache_dir()),
        ..ProfileOptions::default()
    };
    build_model(params, &opts).unwrap().0
}

fn check_preset(name: &str) {
    check_preset_in(name, Closure::Report);
}

fn check_preset_energy(name: &str) {
    check_preset_in(name, Closure::Energy);
}

fn check_preset_in(name: &str, closure: Closure) {
    let input = FurParamsInput {
        closure,
        ..presets::find(name).unwrap().input
    };
    let m = model_in(&input, PhotonBudget::DEFAULT);
    let blob = tables::bake(&m, &input, LutResolution::DEFAULT);
    assert!(
        blob.len() <= 1536 * 1024,
        "LUT of {} bytes above the 1.5 MiB budget",
        blob.len()
    );
    let baked = BakedBcsdf::from_bytes(&blob).unwrap();
    let s = compare(&m.model(), &baked, &MetricSet::DEFAULT);
    println!("{name} ({closure:?}): {s:?}");
    let exceeded = ErrorBudget::DEFAULT.check(&s);
    assert!(exceeded.is_empty(), "{name} ({closure:?}): {exceeded:?}");
}

fur_tests::per_preset_tests! {
    check_preset, every_builtin_preset_has_a_budget_test;
    budget_bobcat: "bobcat",
    budget_cat: "cat",
    budget_deer: "deer",
    budget_dog: "dog",
    budget_mouse: "mouse",
    budget_rabbit: "rabbit",
    budget_raccoon: "raccoon",
    budget_red_fox: "red-fox",
    budget_springbok: "springbok",
    budget_human_fur: "human-fur",
    budget_human_hair: "human-hair",
    budget_air_medulla: "air-medulla",
}

fur_tests::per_preset_tests! {
    check_preset_energy, every_builtin_preset_has_an_energy_budget_test;
    energy_budget_bobcat: "bobcat",
    energy_budget_cat: "cat",
    energy_budget_deer: "deer",
    energy_budget_dog: "dog",
    energy_budget_mouse: "mouse",
    energy_budget_rabbit: "rabbit",
    energy_budget_raccoon: "raccoon",
    energy_budget_red_fox: "red-fox",
    energy_budget_springbok: "springbok",
    energy_budget_human_fur: "human-fur",
    energy_budget_human_hair: "human-hair",
    energy_budget_air_medulla: "air-medulla",
}

fn small_budget() -> PhotonBudget {
    scale_budget(PhotonBudget::DEFAULT, 0.01).unwrap()
}

#[test]
fn a_lut_three_percent_off_exceeds_the_budget() {
    let name = "human-hair";
    let m = model(name, small_budget());
    let mut blob = tables::bake(
        &m,
        &presets::find(name).unwrap().input,
        LutResolution::DEFAULT,
    );
    // Scale every stored N value by 1.03 through the f16 values themselves.
    let range = LutResolution::DEFAULT.byte_range(Table::N);
    for pair in blob[range].chunks_exact_mut(2) {
        let h = half::f16::from_bits(u16::from_le_bytes([pair[0], pair[1]]));
        let v = half::f16::from_f32(h.to_f32() * 1.03);
        pair.copy_from_slice(&v.to_bits().to_le_bytes());
    }
    lut::seal(&mut blob);
    let baked = BakedBcsdf::from_bytes(&blob).unwrap();
    let s = compare(&m.model(), &baked, &MetricSet::DEFAULT);
    let exceeded = ErrorBudget::DEFAULT.check(&s);
    let metrics: Vec<&str> = exceeded.iter().map(|e| e.metric).collect();
    assert!(metrics.contains(&"E1"), "{s:?}");
    assert!(metrics.contains(&"E_albedo"), "{s:?}");
    assert!(metrics.contains(&"E_peak"), "{s:?}");
}

#[test]
fn bake_and_metrics_are_the_same_bits_for_any_thread_count() {
    let name = "air-medulla";
    let input = presets::find(name).unwrap().input;
    let m = model(name, small_budget());
    let res = LutResolution {
        n_sum: 256,
        n_theta_r: 16,
        n_phi: 48,
        n_ms_i: 32,
        n_ms_r: 32,
        n_abs: 4,
    };
    let set = MetricSet {
        n_theta_r: 8,
        n_theta_i: 24,
        n_phi: 24,
        ..MetricSet::DEFAULT
    };
    let run = |threads: usize| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        pool.install(|| {
            let blob = tables::bake(&m, &input, res);
            let s = compare(&m.model(), &BakedBcsdf::from_bytes(&blob).unwrap(), &set);
            (blob, s)
        })
    };
    let (one, s1) = run(1);
    let (two, s2) = run(2);
    let (again, s3) = run(2);
    assert_eq!(one, two, "1 vs 2 threads");
    assert_eq!(two, again, "two runs");
    assert_eq!(s1, s2);
    assert_eq!(s2, s3);
}
