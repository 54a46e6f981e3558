//! The energy closure's longitudinal part (docs/model.md §12): every M_p divided by
//! its mass inside θ_i ∈ [−π/2, π/2].
//!
//! - `lossless_furnace_keeps_the_azimuthal_energy` (the core presets; the other species in
//!   `lossless_furnace_other_species::full_sweep`): a preset made lossless (σ_ca = σ_ma = 0),
//!   its unscattered paths (the part M_p shapes; the scattered lobes' M^s is already normalised
//!   on the sphere and the residual is not part of the model yet), analytic and baked far
//!   field: the white furnace ρ(θ_r) equals Σ_p ⟨A_p⟩_h — the azimuthal energy, all of it
//!   reaching the sphere — within 0.5 % at θ_r ∈ {0°, ±30°, ±60°, ±80°, ±85°, ±89°}, where the
//!   report closure loses up to two thirds of it. ⟨A_p⟩_h is the f64 ray tracer's
//!   (`fur_tests::furnace`), the furnace calls the evaluators as black boxes. Measured: analytic
//!   within 3.0e-6 everywhere; baked (default resolution with three absorption planes,
//!   `fur_tests::LOSSLESS_RESOLUTION`; LUT format 4: 1/Z_g from the LUT's
//!   table, the pole slivers integrated exactly) within 4e-3 below 85°, but over by up to
//!   6.4e-3 at ±85° (human-fur) and 9.8e-3 at ±89° (human-fur), so at |θ_r| ≥ 80° the baked
//!   check is held to 1 % only — not yet the 0.5 % budget. With format 3's per-query masses
//!   and three-point sliver estimate it was 6.2e-3 and 9.2e-3: the normalisation is not the
//!   cause; table `N`'s θ_r interpolation is (nodes 1.9° apart where Σ⟨A_p⟩ curves sharply
//!   toward grazing view; docs/lut.md, "The 1/Z_g table").
//! - `report_closure_keeps_todays_numbers`: the report closure's lossless ρ(θ_r), pinned.
//! - `residual_furnace_*` (one per preset): the model with its residual (docs/model.md §12,
//!   "Residual"), lossless, analytic far field, near field averaged over 48 offsets (θ_r ≥ 0), and baked
//!   far field (`fur_tests::LOSSLESS_RESOLUTION`, today's baked 1/Z_g): ρ(θ_r) = 1 within 0.5 % at every θ_r
//!   above (the residual returns what the lobes leave out; measured worst 1.5e-3 analytic,
//!   1.4e-3 baked, both air-medulla).

use bake::profiles::{build_model, scale_budget, OwnedModel, ProfileOptions};
use bake::tables::{encode, sample};
use bcsdf_core::medulla::PhotonBudget;
use bcsdf_core::Absorption;
use bcsdf_core::{
    presets, Angles, BakedBcsdf, Bcsdf, Closure, FurBcsdf, FurParams, FurParamsInput, Pigment, Rgb,
};
use fur_tests::furnace::{group_shapes_of, predicted_rho, theta_i_nodes, theta_i_nodes_with};
use fur_tests::profiles_ref::m_s_kinks;
use std::f64::consts::{PI, TAU};
use std::path::PathBuf;

/// The view angles of the lossless furnace check (docs/accuracy.md), degrees.
const THETAS: [f32; 11] = [
    0.0, 30.0, -30.0, 60.0, -60.0, 80.0, -80.0, 85.0, -85.0, 89.0, -89.0,
];

/// h panels per piece for ⟨A_p⟩_h (white_furnace.rs shows 32 converged to < 1e-9).
const H_PANELS: usize = 32;

/// `input` with no absorption anywhere, in closure `closure` (what the LUT header stores).
fn lossless_input(input: &FurParamsInput, closure: Closure) -> FurParamsInput {
    FurParamsInput {
        pigment: Pigment::Absorption(Rgb::ZERO),
        sigma_ma: 0.0,
        closure,
        ..*input
    }
}

/// [`lossless_input`], validated.
fn lossless(input: &FurParamsInput, closure: Closure) -> FurParams {
    FurParams::new(&lossless_input(input, closure)).unwrap()
}

/// φ nodes: spacing at most β_n/1.5 (the narrowest β_N), at least 48.
fn n_phi(p: &FurParams) -> usize {
    ((TAU / (p.beta_n() as f64 / 1.5)).ceil() as usize).max(48)
}

/// ρ(θ_r) = ∫ S cos θ_i dω_i of `eval` (first channel: the fibers are grey), θ_i on the white
/// furnace's panels, φ by the periodic trapezoid rule.
fn furnace(p: &FurParams, theta_r: f32, eval: impl Fn(&Angles) -> f32) -> f64 {
    let nodes = theta_i_nodes(theta_r as f64, &group_shapes_of(p));
    let n = n_phi(p);
    let dphi = TAU / n as f64;
    let mut rho = 0.0;
    for &(ti, wi) in &nodes {
        let c2 = ti.cos().powi(2);
        for j in 0..n {
            let phi = -PI + dphi * (j as f64 + 0.5);
            let a = Angles::new(ti as f32, theta_r, phi as f32).unwrap();
            rho += wi * c2 * dphi * f64::from(eval(&a));
        }
    }
    rho
}

/// Σ_p ⟨A_p⟩_h at θ_r, first channel, from the f64 ray tracer.
fn azimuthal_energy(p: &FurParams, theta_r: f32) -> f64 {
    let pred = predicted_rho(p, theta_r as f64, H_PANELS);
    pred.mean_attenuation.iter().map(|a| a[0]).sum()
}

/// One preset's lossless furnace (analytic, baked) against Σ⟨A_p⟩: its worst relative errors
/// and the least share of Σ⟨A_p⟩ the report closure keeps.
fn lossless_furnace(preset: &presets::Preset) -> ([f64; 2], f64) {
    let res = fur_tests::LOSSLESS_RESOLUTION;
    let mut worst = [0.0f64; 2];
    let mut least_report = f64::MAX;
    let p = lossless(&preset.input, Closure::Energy);
    let analytic: FurBcsdf = FurBcsdf::unscattered(p);
    // Table `N`'s absorption planes: the same model at the nodes' σ_ca, three nodes (one
    // per channel) per model, as `tables::absorption_planes` makes them.
    let scale = bcsdf_core::lut::absorption_scale(p.kappa());
    let planes: Vec<FurBcsdf> = (0..(res.n_abs as usize).div_ceil(3))
        .map(|j| {
            let s = bcsdf_core::Rgb(
                [0, 1, 2].map(|c| bcsdf_core::lut::absorption_node(3 * j + c, res.n_abs, scale)),
            );
            FurBcsdf::unscattered(p.with_absorption(&Absorption::from_sigma(s).unwrap()))
        })
        .collect();
    let blob = encode(
        &sample(&analytic, &planes, res),
        &lossless_input(&preset.input, Closure::Energy),
        None,
    );
    let baked = BakedBcsdf::from_bytes(&blob).unwrap();
    let report: FurBcsdf = FurBcsdf::unscattered(lossless(&preset.input, Closure::Report));
    for t in THETAS {
        let tr = t.to_radians();
        let want = azimuthal_energy(&p, tr);
        let got = [
            furnace(&p, tr, |a| analytic.eval_far(a).total().0[0]),
            furnace(&p, tr, |a| baked.eval(a).total().0[0]),
        ];
        for (k, g) in got.iter().enumerate() {
            let err = (g - want).abs() / want;
            worst[k] = worst[k].max(err);
            // The baked far field at |θ_r| ≥ 80° is held to 1 % (see the module
            // documentation); 0.5 % everywhere else.
            let tol = if k == 1 && t.abs() >= 80.0 {
                1e-2
            } else {
                5e-3
            };
            if err > 4e-3 {
                eprintln!(
                    "{} θ_r {t}° {k}: ρ {g:.5} vs {want:.5} ({err:.2e})",
                    preset.name
                );
            }
            assert!(
                err <= tol,
                "{} θ_r {t}° {}: ρ {g:.5} vs Σ⟨A_p⟩ {want:.5} ({err:.2e})",
                preset.name,
                ["analytic", "baked"][k]
            );
        }
        let r = furnace(&p, tr, |a| report.eval_far(a).total().0[0]) / want;
        least_report = least_report.min(r);
    }
    (worst, least_report)
}

#[test]
fn lossless_furnace_keeps_the_azimuthal_energy() {
    lossless_furnace_for(false);
}

/// The other species' lossless furnace (the full sweep).
mod lossless_furnace_other_species {
    #[test]
    #[ignore = "full sweep: cargo test --workspace -- --ignored full_sweep"]
    fn full_sweep() {
        super::lossless_furnace_for(true);
    }
}

/// The lossless furnace of the core presets, or of the others with `sweep`
/// (fur_tests::per_preset::presets_of).
fn lossless_furnace_for(sweep: bool) {
    use rayon::prelude::*;
    let t0 = std::time::Instant::now();
    // The presets side by side (each one's check is independent of the others').
    let each: Vec<([f64; 2], f64)> = fur_tests::per_preset::presets_of(sweep)
        .into_par_iter()
        .map(lossless_furnace)
        .collect();
    let worst = each
        .iter()
        .fold([0.0f64; 2], |w, (e, _)| [w[0].max(e[0]), w[1].max(e[1])]);
    let least_report = each.iter().map(|e| e.1).fold(f64::MAX, f64::min);
    eprintln!(
        "energy closure: worst |ρ − Σ⟨A_p⟩|/Σ⟨A_p⟩ analytic {:.2e}, baked {:.2e}; report keeps \
         as little as {least_report:.3} of it ({:.1} s)",
        worst[0],
        worst[1],
        t0.elapsed().as_secs_f64()
    );
    // The report closure loses a large part at grazing view: the check above can fail.
    assert!(least_report < 0.5, "{least_report}");
}

#[test]
fn report_closure_keeps_todays_numbers() {
    // Lossless human hair (κ = 0: the unscattered paths are the whole model), analytic far
    // field, report closure. A separate run measured 0.993, 0.991, 0.967, 0.748, 0.346 through the
    // C ABI (baked); the pins are this evaluator's values, which the closure setting leaves
    // bit for bit as model version 2 computed them (M_p times exactly 1).
    let p = lossless(&presets::find("human-hair").unwrap().input, Closure::Report);
    let model: FurBcsdf = FurBcsdf::unscattered(p);
    let pins: [(f32, f64); 5] = [
        (0.0, PIN[0]),
        (30.0, PIN[1]),
        (60.0, PIN[2]),
        (80.0, PIN[3]),
        (88.0, PIN[4]),
    ];
    let issue = [0.993, 0.991, 0.967, 0.748, 0.346];
    let energy: FurBcsdf = FurBcsdf::unscattered(p.with_closure(Closure::Energy));
    for ((t, pin), from_issue) in pins.into_iter().zip(issue) {
        let rho = furnace(&p, t.to_radians(), |a| model.eval_far(a).total().0[0]);
        let kept = furnace(&p, t.to_radians(), |a| energy.eval_far(a).total().0[0]);
        eprintln!("human-hair θ_r {t}°: ρ report {rho:.9}, energy {kept:.6}");
        assert!(
            (rho - pin).abs() <= 1e-6,
            "θ_r {t}°: ρ {rho:.9} vs pinned {pin}"
        );
        assert!(
            (rho - from_issue).abs() <= 2e-3,
            "θ_r {t}°: {rho} vs the C ABI's {from_issue}"
        );
    }
}

/// The report closure's lossless human-hair ρ at θ_r = 0°, 30°, 60°, 80°, 88°.
const PIN: [f64; 5] = [
    0.993_021_4,
    0.990_711_7,
    0.967_344_4,
    0.748_391_3,
    0.346_917_0,
];

/// h midpoints of the near-field furnace over [−1, 1].
const NEAR_H: usize = 48;

/// The analytic model of `name` made lossless in the energy closure, with profiles (a
/// twentieth of the default photon budget: the residual closes the energy of whatever
/// profiles the model has, so their noise does not matter here; cached beside bake_budget's)
/// and its residual table.
fn lossless_with_residual(name: &str) -> OwnedModel {
    let p = lossless(&presets::find(name).unwrap().input, Closure::Energy);
    let opts = ProfileOptions {
        budget: scale_budget(PhotonBudget::DEFAULT, 0.05).unwrap(),
        cache_dir: Some(PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("fur-profile-cache")),
        ..ProfileOptions::default()
    };
    build_model(p, &opts).unwrap().0
}

/// The full model's θ_i nodes: the furnace panels broken at M^s's kinks.
fn full_nodes(model: &FurBcsdf, theta_r: f32) -> Vec<(f64, f64)> {
    let p = model.params();
    let kinks = match model.profiles() {
        Some(prof) => m_s_kinks(p, prof.layout()),
        None => Vec::new(),
    };
    theta_i_nodes_with(f64::from(theta_r), &group_shapes_of(p), &kinks, 0.1)
}

/// φ nodes for a model with a residual: [`n_phi`] rounded up to a multiple of twice the
/// residual's 2·n_phi bins over the circle, so that the midpoint rule puts an even number of
/// nodes in every bin: D_res is linear between the bins' centres (its kinks), which are then
/// boundaries of the rule's intervals, and is integrated exactly.
fn n_phi_residual(model: &FurBcsdf) -> usize {
    let bins = 4 * model.residual().map_or(1, |t| t.layout().n_phi);
    n_phi(model.params()).div_ceil(bins) * bins
}

/// ρ of `eval` on the full model's θ_i nodes (first channel), φ by the periodic trapezoid rule.
fn furnace_full(model: &FurBcsdf, theta_r: f32, eval: impl Fn(&Angles) -> f32) -> f64 {
    let nodes = full_nodes(model, theta_r);
    let n = n_phi_residual(model);
    let dphi = TAU / n as f64;
    let mut rho = 0.0;
    for &(ti, wi) in &nodes {
        let c2 = ti.cos().powi(2);
        for j in 0..n {
            let phi = -PI + dphi * (j as f64 + 0.5);
            let a = Angles::new(ti as f32, theta_r, phi as f32).unwrap();
            rho += wi * c2 * dphi * f64::from(eval(&a));
        }
    }
    rho
}

/// Lossless furnace with the residual, far field (analytic S) and near field (averaged over
/// h): ρ(θ_r) = 1 within 0.5 % at every θ_r of [`THETAS`].
fn check_residual_furnace(name: &str) {
    let t0 = std::time::Instant::now();
    let owned = lossless_with_residual(name);
    let model = owned.model();
    assert!(model.residual().is_some());
    // Baked at the default resolution (three absorption planes: lossless fibers read the
    // first): N_TRT carries the residual.
    let input = lossless_input(&presets::find(name).unwrap().input, Closure::Energy);
    let blob = bake::tables::bake(&owned, &input, fur_tests::LOSSLESS_RESOLUTION);
    let baked = BakedBcsdf::from_bytes(&blob).unwrap();
    // Each view's three furnaces side by side (rayon), then checked in order.
    use rayon::prelude::*;
    let rhos: Vec<[f64; 3]> = THETAS
        .par_iter()
        .map(|&t| {
            let tr = t.to_radians();
            let far = furnace_full(&model, tr, |a| model.eval_far(a).total().0[0]);
            // Near field: S at h (eleven lobes and the residual's own h-profile), h by the
            // midpoint rule; at the non-negative θ_r only, which halves the test's cost (the
            // far field and the LUT are checked at both signs; the near field's every-path
            // agreement with the far field at random angles is viewer/tests/suite/every_path.rs's).
            // Summed in h order, whatever the threads.
            let near_h: Vec<f64> = (0..if t >= 0.0 { NEAR_H } else { 0 })
                .into_par_iter()
                .map(|k| {
                    let h = -1.0 + (k as f32 + 0.5) * 2.0 / NEAR_H as f32;
                    furnace_full(&model, tr, |a| model.eval_near(a, h).total().0[0])
                })
                .collect();
            let near = near_h.iter().sum::<f64>() / NEAR_H as f64;
            let lut = furnace_full(&model, tr, |a| baked.eval(a).total().0[0]);
            [far, near, lut]
        })
        .collect();
    let mut worst = [0.0f64; 3];
    for (t, rho3) in THETAS.into_iter().zip(rhos) {
        for (k, rho) in rho3.into_iter().enumerate() {
            if k == 1 && t < 0.0 {
                continue;
            }
            let err = (rho - 1.0).abs();
            worst[k] = worst[k].max(err);
            assert!(
                err <= 5e-3,
                "{name} θ_r {t}° {}: ρ = {rho:.5}",
                ["far", "near", "baked"][k]
            );
        }
    }
    eprintln!(
        "{name}: lossless energy closure with the residual, worst |ρ − 1| far {:.2e}, near {:.2e}, \
         baked {:.2e} ({:.1} s)",
        worst[0],
        worst[1],
        worst[2],
        t0.elapsed().as_secs_f64()
    );
}

fur_tests::per_preset_tests! {
    check_residual_furnace, every_builtin_preset_has_a_residual_furnace_test;
    residual_furnace_bobcat: "bobcat",
    residual_furnace_cat: "cat",
    residual_furnace_deer: "deer",
    residual_furnace_dog: "dog",
    residual_furnace_mouse: "mouse",
    residual_furnace_rabbit: "rabbit",
    residual_furnace_raccoon: "raccoon",
    residual_furnace_red_fox: "red-fox",
    residual_furnace_springbok: "springbok",
    residual_furnace_human_fur: "human-fur",
    residual_furnace_human_hair: "human-hair",
    residual_furnace_air_medulla: "air-medulla",
}
