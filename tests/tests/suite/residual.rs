//! The residual (docs/model.md §12, "Residual"), against what is known independently:
//!
//! - `kappa_zero_residual_is_the_geometric_series`: without a medulla the paths beyond TRT
//!   are the plain cylinder's TRRT, TRRRT, …, whose energy at offset h is the geometric series
//!   Σ_{p≥3} (1 − f)²·f^{p−1}·T^p = (1 − f)²·f²·T³/(1 − f·T) (pbrt's A_{p_max}), f the
//!   cuticle reflectance and T one cortex chord's transmittance. The table's simulated A_res
//!   (the values stored at the offsets) must equal it to 1e-4 per channel at every θ_r and h
//!   node, absorbing and not, plain and layered
//!   cuticle. The series is computed here in f64 from the f64 tracer's Fresnel
//!   (`fur_tests::tracer`), sharing no code with the core.
//! - `absorbing_*` (one per preset): the core simulation's exiting energy and the energy
//!   closure's ρ(θ_r) of the preset as it is against the total exiting energy of the tests' own
//!   full cross-section simulation (`fur_tests::cross_section_mc`, `Options::FULL`) at
//!   θ_r = 0°, 40°, 75°, per channel (see `check_absorbing`).

use bake::profiles::{build_model, scale_budget, ProfileOptions};
use bcsdf_core::medulla::PhotonBudget;
use bcsdf_core::residual::{ResidualLayout, ResidualTable};
use bcsdf_core::residual_gen::{generate, simulate_view};
use bcsdf_core::{presets, Closure, FurBcsdf, FurParams, FurParamsInput, Libm, Pigment, Rgb};
use fur_tests::cross_section_mc::{simulate, McParams, Options};
use fur_tests::furnace::{furnace_on, group_shapes_of, theta_i_nodes_with};
use fur_tests::profiles_ref::m_s_kinks;
use fur_tests::tracer::{bravais, cos_refracted, cuticle};
use std::f64::consts::TAU;
use std::path::PathBuf;

/// Σ_{p≥3} A_p(h) of the plain cylinder (κ = 0) at θ_r, per channel.
fn series(p: &FurParams, theta_r: f64, h: f64) -> [f64; 3] {
    let eta = bravais(f64::from(p.eta_c()), theta_r);
    let cos_a = (1.0 - h * h).sqrt();
    let f = cuticle(cos_a, 1.0, eta, f64::from(p.l()));
    let sin_c = h / eta;
    let cos_c = (1.0 - sin_c * sin_c).sqrt();
    let inv_cos_tc = 1.0 / cos_refracted(f64::from(p.eta_c()), theta_r);
    p.sigma_ca().0.map(|s| {
        let t = (-f64::from(s) * 2.0 * cos_c * inv_cos_tc).exp();
        (1.0 - f).powi(2) * f * f * t.powi(3) / (1.0 - f * t)
    })
}

fn check_series(input: &FurParamsInput) -> f64 {
    let p = FurParams::new(input).unwrap();
    assert_eq!(p.kappa(), 0.0);
    let model: FurBcsdf = FurBcsdf::unscattered(p);
    let layout = ResidualLayout::DEFAULT;
    let mut data = vec![0.0; layout.len()];
    generate(&model, &layout, 1, &mut data).unwrap();
    ResidualTable::new(p, layout, &data).unwrap();
    let mut worst = 0.0f64;
    // Every node but the last (θ_r = 90°, where the Bravais index is unbounded).
    for k in 0..layout.n_theta - 1 {
        let theta_r = layout.theta_node(k);
        for j in 0..layout.n_h {
            let h = layout.h_node(j);
            // The simulated value stored at the offset (the near field scales the offsets to
            // the far field's mean, `ResidualTable::magnitude`).
            let at = k * layout.row_len() + 3 * j;
            let got = Rgb([data[at], data[at + 1], data[at + 2]]);
            let want = series(&p, f64::from(theta_r), f64::from(h));
            for (c, (g, w)) in got.0.iter().zip(want).enumerate() {
                let err = (f64::from(*g) - w).abs();
                worst = worst.max(err);
                assert!(
                    err <= 1e-4,
                    "θ_r {theta_r} h {h} channel {c}: A_res {g} vs series {w}"
                );
            }
        }
    }
    worst
}

#[test]
fn kappa_zero_residual_is_the_geometric_series() {
    let hair = presets::find("human-hair").unwrap().input;
    let cases = [
        ("pigmented", hair),
        (
            "lossless",
            FurParamsInput {
                pigment: Pigment::Absorption(Rgb::ZERO),
                ..hair
            },
        ),
        (
            "layered, light",
            FurParamsInput {
                l: 2.0,
                pigment: Pigment::Absorption(Rgb([0.05, 0.2, 0.6])),
                ..hair
            },
        ),
    ];
    for (name, input) in cases {
        let input = FurParamsInput {
            closure: Closure::Energy,
            ..input
        };
        let worst = check_series(&input);
        eprintln!("κ = 0, {name}: worst |A_res − Σ_(p≥3) A_p| = {worst:.2e}");
    }
}

/// The θ_r of the absorbing check, degrees.
const ABSORBING_THETAS: [f64; 3] = [0.0, 40.0, 75.0];

/// Photons of the cross-section simulation per (θ_r, channel).
const MC_PHOTONS: u64 = 400_000;

/// Every preset as it is (absorbing), energy closure, θ_r ∈ {0°, 40°, 75°}, per channel,
/// against the total energy leaving the fiber in `fur_tests::cross_section_mc` with
/// `Options::FULL` (the physical flatland problem, f64, independent of the core):
/// - the core's own simulation (the residual's E_sim, h-averaged over 128 offsets) within 1 %;
/// - the model's ρ (its white furnace: θ_i on the furnace panels broken at M^s's kinks, φ
///   trapezoidal) within 1 %: the residual adds what the lobes leave out, and the scattered
///   lobes' scale removes what they carry beyond the simulation (docs/model.md §12).
fn check_absorbing(name: &str) {
    let t0 = std::time::Instant::now();
    let input = FurParamsInput {
        closure: Closure::Energy,
        ..presets::find(name).unwrap().input
    };
    let p = FurParams::new(&input).unwrap();
    let opts = ProfileOptions {
        budget: scale_budget(PhotonBudget::DEFAULT, 0.05).unwrap(),
        cache_dir: Some(PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("fur-profile-cache")),
        ..ProfileOptions::default()
    };
    let owned = build_model(p, &opts).unwrap().0;
    let model = owned.model();
    let kinks = match model.profiles() {
        Some(prof) => m_s_kinks(&p, prof.layout()),
        None => Vec::new(),
    };
    // φ spacing at most β_n/1.5 and an even number of nodes in each of the residual's 2·n_phi
    // bins over the circle (D_res is linear between the bins' centres, which are then
    // boundaries of the midpoint rule's intervals: it is integrated exactly).
    let bins = 4 * model.residual().unwrap().layout().n_phi;
    let n_phi = ((TAU / (f64::from(p.beta_n()) / 1.5)).ceil() as usize)
        .max(48)
        .div_ceil(bins)
        * bins;
    let mut worst = [0.0f64; 2];
    let bare = owned.model_without_residual::<Libm>();
    let fine = ResidualLayout {
        n_h: 128,
        ..ResidualLayout::DEFAULT
    };
    let mut scratch = vec![0.0; fine.row_len()];
    for t in ABSORBING_THETAS {
        let tr = t.to_radians();
        let nodes = theta_i_nodes_with(tr, &group_shapes_of(&p), &kinks, 0.1);
        let rho = furnace_on(&model, tr as f32, n_phi, &nodes);
        // The core's own simulation at this θ_r (128 offsets).
        let sim = simulate_view(&bare, &fine, tr as f32, 5, &mut scratch);
        let sigma = p.sigma_ca().0;
        for c in 0..3 {
            // Grey fibers: one simulation serves every channel.
            if c > 0 && sigma[c] == sigma[0] {
                let err = (rho[c] - rho[0]).abs();
                assert!(
                    err <= 1e-6,
                    "{name} θ_r {t}°: channels differ on a grey fiber"
                );
                continue;
            }
            let mc = McParams {
                eta_c: f64::from(p.eta_c()),
                eta_m: f64::from(p.eta_m()),
                kappa: f64::from(p.kappa()),
                layers: f64::from(p.l()),
                sigma_ca: f64::from(sigma[c]),
                sigma_ms: f64::from(p.sigma_ms()),
                sigma_ma: f64::from(p.sigma_ma()),
                g: f64::from(p.g()),
                theta_r: tr,
            };
            let tally = simulate(&mc, &Options::FULL, 8, MC_PHOTONS, 17 + c as u64, 2);
            let want = tally.all_exiting();
            let err = (rho[c] - want).abs() / want;
            let err_sim = (sim.exiting[c] - want).abs() / want;
            worst[0] = worst[0].max(err);
            worst[1] = worst[1].max(err_sim);
            eprintln!(
                "{name} θ_r {t}° channel {c}: ρ {:.5}, tests' simulation {want:.5} ± {:.5} \
                 ({err:.2e}); core simulation {:.5} ({err_sim:.2e}), E_model {:.5}, A_res {:.5}, \
                 excess {:.5}, unmodelled {:.5}",
                rho[c],
                tally.all_exiting_std_error(),
                sim.exiting[c],
                sim.model[c],
                sim.residual[c],
                sim.excess[c],
                sim.unmodelled[c],
            );
            assert!(
                err_sim <= 1e-2,
                "{name} θ_r {t}° channel {c}: core simulation {:.5} vs tests' {want:.5}",
                sim.exiting[c]
            );
            assert!(
                err <= 1e-2,
                "{name} θ_r {t}° channel {c}: ρ {:.5} vs the simulation's {want:.5}",
                rho[c]
            );
        }
    }
    eprintln!(
        "{name}: energy-closure ρ against the full cross-section simulation, worst {:.2e}; core \
         simulation against it, worst {:.2e} ({:.1} s)",
        worst[0],
        worst[1],
        t0.elapsed().as_secs_f64()
    );
}

fur_tests::per_preset_tests! {
    check_absorbing, every_builtin_preset_has_an_absorbing_residual_test;
    absorbing_bobcat: "bobcat",
    absorbing_cat: "cat",
    absorbing_deer: "deer",
    absorbing_dog: "dog",
    absorbing_mouse: "mouse",
    absorbing_rabbit: "rabbit",
    absorbing_raccoon: "raccoon",
    absorbing_red_fox: "red-fox",
    absorbing_springbok: "springbok",
    absorbing_human_fur: "human-fur",
    absorbing_human_hair: "human-hair",
    absorbing_air_medulla: "air-medulla",
}
