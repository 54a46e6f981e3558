//! The absorption axis, measured (docs/lut.md "The absorption axis"): bakes presets with
//! `n_abs` absorption nodes and measures E1 / E_albedo / E_peak (`bake::metrics`, worst RGB
//! channel) of the LUT evaluated at a colour against the analytic model at that colour, for
//! the preset's own σ_ca, 16 random colours (each channel log-uniform over [0.01, 1000] with
//! 0 and ≥ 100 among them) and eight melanin mixes (eumelanin 0–8, pheomelanin 0–2).
//!
//! ```sh
//! cargo run --release -p bake --example colour_study -- human-hair,bobcat 8,16
//! ```
//! Arguments: comma-separated presets (default every built-in), comma-separated node counts
//! (default the format's). Profiles and residuals are cached in the default cache directory.

use bake::metrics::{colour_set, compare, ErrorBudget, MetricSet};
use bake::profiles::{build_model, default_cache_dir, ProfileOptions};
use bake::tables;
use bcsdf_core::baked::BakedBcsdf;
use bcsdf_core::lut::LutResolution;
use bcsdf_core::{presets, FurParams};

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let names: Vec<String> = match args.get(1) {
        Some(a) => a.split(',').map(str::to_owned).collect(),
        None => presets::PRESETS.iter().map(|p| p.name.to_owned()).collect(),
    };
    let counts: Vec<u32> = match args.get(2) {
        Some(a) => a.split(',').map(|n| n.parse().unwrap()).collect(),
        None => vec![LutResolution::DEFAULT.n_abs],
    };
    let opts = ProfileOptions {
        cache_dir: default_cache_dir(),
        ..ProfileOptions::default()
    };
    println!("| preset | n_abs | .furlut bytes | colour | σ_ca | E1 % | E_albedo % | E_peak % | within |");
    println!("|---|---|---|---|---|---|---|---|---|");
    for name in &names {
        let preset = presets::find(name).expect("a built-in preset");
        let params = FurParams::new(&preset.input).unwrap();
        let (model, _) = build_model(params, &opts).unwrap();
        for &n_abs in &counts {
            let res = LutResolution {
                n_abs,
                ..LutResolution::DEFAULT
            };
            let blob = tables::bake(&model, &preset.input, res);
            let lut = BakedBcsdf::from_bytes(&blob).unwrap();
            let mut worst = [0.0f64; 3];
            let colours = colour_set(params.sigma_ca());
            let absorptions: Vec<_> = colours.iter().map(|(_, c)| *c).collect();
            let references = model.at_sigmas(&absorptions).unwrap();
            for ((label, colour), reference) in colours.into_iter().zip(&references) {
                let s = compare(&reference.model(), &lut.at(&colour), &MetricSet::DEFAULT);
                let w = s.worst();
                for (a, b) in worst.iter_mut().zip(w) {
                    *a = a.max(b);
                }
                let ok = ErrorBudget::DEFAULT.check(&s).is_empty();
                let [r, g, b] = colour.sigma().0;
                println!(
                    "| {name} | {n_abs} | {} | {label} | {r:.3}, {g:.3}, {b:.3} | {:.3} | {:.3} | {:.3} | {} |",
                    blob.len(),
                    100.0 * w[0],
                    100.0 * w[1],
                    100.0 * w[2],
                    if ok { "yes" } else { "NO" }
                );
            }
            println!(
                "| {name} | {n_abs} | {} | **worst** | | {:.3} | {:.3} | {:.3} | |",
                blob.len(),
                100.0 * worst[0],
                100.0 * worst[1],
                100.0 * worst[2]
            );
        }
    }
}
