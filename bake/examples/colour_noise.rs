//! How much of a LUT's error at a colour is the residual simulation's noise (docs/model.md
//! §12, "Common random numbers across colours"): the analytic model at one colour with the
//! residual of other seeds against the model with its own (the simulation's own noise), and
//! the LUT (baked with the model's seed) against both; E_albedo per RGB channel, %.
//! `cargo run --release -p bake --example colour_noise -- deer 3.4,5.6,11.0 7,8`
use bake::metrics::{compare, MetricSet};
use bake::profiles::{build_model, default_cache_dir, generate_residual, ProfileOptions};
use bake::tables;
use bcsdf_core::baked::BakedBcsdf;
use bcsdf_core::lut::LutResolution;
use bcsdf_core::residual::ResidualLayout;
use bcsdf_core::{presets, Absorption, FurParams, Rgb};

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let preset = presets::find(&args[1]).unwrap();
    let s: Vec<f32> = args[2].split(',').map(|v| v.parse().unwrap()).collect();
    let seeds: Vec<u64> = args.get(3).map_or(vec![7], |a| {
        a.split(',').map(|v| v.parse().unwrap()).collect()
    });
    let colour = Absorption::from_sigma(Rgb([s[0], s[1], s[2]])).unwrap();
    let opts = ProfileOptions {
        cache_dir: default_cache_dir(),
        ..ProfileOptions::default()
    };
    let params = FurParams::new(&preset.input).unwrap();
    let (model, _) = build_model(params, &opts).unwrap();
    let reference = model.at_sigma(&colour).unwrap();
    let blob = tables::bake(&model, &preset.input, LutResolution::DEFAULT);
    let lut = BakedBcsdf::from_bytes(&blob).unwrap();
    let pct = |e: [f64; 3]| {
        format!(
            "{:.3} {:.3} {:.3}",
            100.0 * e[0],
            100.0 * e[1],
            100.0 * e[2]
        )
    };
    let m = compare(&reference.model(), &lut.at(&colour), &MetricSet::DEFAULT);
    println!("LUT vs own seed: E_albedo per channel {}", pct(m.e_albedo));
    for seed in seeds {
        let (data, _) = generate_residual(
            &reference.model_without_residual(),
            &ResidualLayout::DEFAULT,
            seed,
            None,
        )
        .unwrap();
        let other = reference.clone().with_residual(data).unwrap();
        let a = compare(&reference.model(), &other.model(), &MetricSet::DEFAULT);
        let b = compare(&other.model(), &lut.at(&colour), &MetricSet::DEFAULT);
        println!(
            "seed {seed}: own vs other seed {}; LUT vs other seed {}",
            pct(a.e_albedo),
            pct(b.e_albedo)
        );
    }
}
