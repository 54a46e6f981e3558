use bake::profiles::{build_model, ProfileOptions};
use bcsdf_core::residual::{simulate_view, ResidualLayout};
use bcsdf_core::{presets, Closure, FurParams, FurParamsInput, Libm, Pigment, Rgb};
use std::path::PathBuf;
#[test]
fn numbers() {
    let opts = ProfileOptions {
        cache_dir: Some(PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("fur-profile-cache")),
        ..ProfileOptions::default()
    };
    for (name, lossless) in [("human-hair", true), ("bobcat", true)] {
        let mut input = FurParamsInput {
            closure: Closure::Energy,
            ..presets::find(name).unwrap().input
        };
        if lossless {
            input.pigment = Pigment::Absorption(Rgb::ZERO);
            input.sigma_ma = 0.0;
        }
        let p = FurParams::new(&input).unwrap();
        let owned = build_model(p, &opts).unwrap().0;
        let with = owned.model();
        let without = owned.model_without_residual::<Libm>();
        let report = owned.model_without_residual::<Libm>();
        let _ = report;
        for deg in [0.0f32, 30.0, 60.0, 80.0, 88.0] {
            let th = deg.to_radians();
            let bins = 72;
            let n = (((std::f64::consts::TAU / (p.beta_n() as f64 / 1.5)).ceil() as usize).max(48))
                .div_ceil(bins)
                * bins;
            let a = fur_tests::furnace::furnace(&without, th, n)[0];
            let b = fur_tests::furnace::furnace(&with, th, n)[0];
            eprintln!("RHO {name} {deg}: energy without residual {a:.4} with {b:.4}");
        }
    }
    let fine = ResidualLayout {
        n_h: 64,
        ..ResidualLayout::DEFAULT
    };
    let mut scratch = vec![0.0; fine.row_len()];
    for pr in presets::PRESETS.iter() {
        for lossless in [true, false] {
            let mut input = FurParamsInput {
                closure: Closure::Energy,
                ..pr.input
            };
            if lossless {
                input.pigment = Pigment::Absorption(Rgb::ZERO);
                input.sigma_ma = 0.0;
            }
            let p = FurParams::new(&input).unwrap();
            let owned = build_model(p, &opts).unwrap().0;
            let bare = owned.model_without_residual::<Libm>();
            for deg in [0.0f32, 40.0, 75.0, 88.0] {
                let s = simulate_view(&bare, &fine, deg.to_radians(), 5, &mut scratch);
                eprintln!("GAP {} {} {deg}: E_sim {:.4} E_model {:.4} diff {:.4} classified {:.4} A_res {:.4} excess {:.4} dropped {:.2e} max {:.2e} beams {} photons {}",
                    pr.name, if lossless {"lossless"} else {"as-is"}, s.exiting[0], s.model[0], s.exiting[0]-s.model[0], s.unmodelled[0], s.residual[0], s.excess[0], s.dropped[0], s.dropped_max, s.beams, s.photons);
            }
        }
    }
}
