//! Measures the baked-vs-analytic error metrics for every built-in preset at several LUT
//! resolutions (the study behind `LutResolution::DEFAULT`, docs/lut.md).
//!
//! `cargo run --release -p bake --example resolution_study [-- --photons-scale 0.25]`

use bake::metrics::{compare, MetricSet};
use bake::profiles::{build_model, default_cache_dir, ProfileOptions};
use bake::tables;
use bcsdf_core::baked::BakedBcsdf;
use bcsdf_core::lut::LutResolution;
use bcsdf_core::FurParams;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let only: Option<&str> = args
        .iter()
        .position(|a| a == "--preset")
        .map(|i| args[i + 1].as_str());
    let presets = bake::presets::builtin().expect("built-in presets parse");
    let candidates = [
        LutResolution {
            n_sum: 512,
            n_theta_r: 24,
            n_phi: 64,
            n_ms_i: 48,
            n_ms_r: 48,
            n_abs: LutResolution::DEFAULT.n_abs,
        },
        LutResolution {
            n_sum: 1024,
            n_theta_r: 32,
            n_phi: 96,
            n_ms_i: 64,
            n_ms_r: 64,
            n_abs: LutResolution::DEFAULT.n_abs,
        },
        LutResolution::DEFAULT,
        LutResolution {
            n_sum: 2048,
            n_theta_r: 64,
            n_phi: 181,
            n_ms_i: 128,
            n_ms_r: 128,
            n_abs: LutResolution::DEFAULT.n_abs,
        },
    ];
    let opts = ProfileOptions {
        cache_dir: default_cache_dir(),
        ..ProfileOptions::default()
    };
    println!("preset        | n_sum n_tr n_phi n_ms | KB    | E1 %    E_albedo %  E_peak %");
    for p in &presets {
        if only.is_some_and(|o| o != p.name) {
            continue;
        }
        let params = FurParams::new(&p.input).unwrap();
        let (model, _) = build_model(params, &opts).unwrap();
        for res in candidates {
            let blob = tables::bake(&model, &p.input, res);
            let baked = BakedBcsdf::from_bytes(&blob).unwrap();
            let s = compare(&model.model(), &baked, &MetricSet::DEFAULT);
            let w = s.worst();
            println!(
                "{:13} | {:5} {:4} {:5} {:4} | {:5.1} | {:7.4} {:10.4} {:8.4}",
                p.name,
                res.n_sum,
                res.n_theta_r,
                res.n_phi,
                res.n_ms_i,
                (blob.len() as f64) / 1024.0,
                100.0 * w[0],
                100.0 * w[1],
                100.0 * w[2]
            );
        }
    }
}
