//! One preset at one colour, at several resolutions: which table axis limits E_albedo there.
//! `cargo run --release -p bake --example colour_probe -- bobcat 5.316,59.075,651.508 22:64:128,40:64:128,22:96:128`
use bake::metrics::{compare, MetricSet};
use bake::profiles::{build_model, default_cache_dir, ProfileOptions};
use bake::tables;
use bcsdf_core::baked::BakedBcsdf;
use bcsdf_core::lut::LutResolution;
use bcsdf_core::{presets, Absorption, FurParams, Rgb};

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let preset = presets::find(&args[1]).unwrap();
    let s: Vec<f32> = args[2].split(',').map(|v| v.parse().unwrap()).collect();
    let colour = Absorption::from_sigma(Rgb([s[0], s[1], s[2]])).unwrap();
    let opts = ProfileOptions {
        cache_dir: default_cache_dir(),
        ..ProfileOptions::default()
    };
    let params = FurParams::new(&preset.input).unwrap();
    let (model, _) = build_model(params, &opts).unwrap();
    let reference = model.at_sigma(&colour).unwrap();
    for r in args[3].split(',') {
        let v: Vec<u32> = r.split(':').map(|v| v.parse().unwrap()).collect();
        let res = LutResolution {
            n_abs: v[0],
            n_theta_r: v[1],
            n_phi: v[2],
            ..LutResolution::DEFAULT
        };
        let blob = tables::bake(&model, &preset.input, res);
        let lut = BakedBcsdf::from_bytes(&blob).unwrap();
        let m = compare(&reference.model(), &lut.at(&colour), &MetricSet::DEFAULT);
        let w = m.worst();
        println!(
            "{} {r} bytes {} E1 {:.3} E_albedo {:.3} E_peak {:.3}",
            args[1],
            blob.len(),
            100.0 * w[0],
            100.0 * w[1],
            100.0 * w[2]
        );
    }
}
