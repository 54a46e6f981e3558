//! Tight loop over the baked evaluator (for profiling: `perf stat`, callgrind).
use bake::profiles::{build_model, scale_budget, ProfileOptions};
use bcsdf_core::baked::BakedBcsdf;
use bcsdf_core::lut::LutResolution;
use bcsdf_core::medulla::PhotonBudget;
use bcsdf_core::{presets, Angles, FurParams};
use std::hint::black_box;
use std::time::Instant;

fn main() {
    let preset = presets::find("yan-row-a").unwrap();
    let opts = ProfileOptions {
        budget: scale_budget(PhotonBudget::DEFAULT, 0.01).unwrap(),
        ..ProfileOptions::default()
    };
    let (model, _) = build_model(FurParams::new(&preset.input).unwrap(), &opts).unwrap();
    let blob = bake::tables::bake(&model, &preset.input, LutResolution::DEFAULT);
    let lut = BakedBcsdf::from_bytes(&blob).unwrap();
    let mut state = 0x2545_f491_4f6c_dd1du64;
    let mut next = move || {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((state >> 40) as f32) / (1u64 << 24) as f32
    };
    let qs: Vec<Angles> = (0..256)
        .map(|_| {
            Angles::from_degrees(
                -80.0 + 160.0 * next(),
                -80.0 + 160.0 * next(),
                -180.0 + 360.0 * next(),
            )
            .unwrap()
        })
        .collect();
    // Arguments: evaluations (default 20M), index mask into the 256 queries (default 255).
    let mask: usize = std::env::args()
        .nth(2)
        .map_or(255, |s| s.parse::<usize>().unwrap() & 255);
    let n: usize = std::env::args()
        .nth(1)
        .map_or(20_000_000, |s| s.parse().unwrap());
    let t = Instant::now();
    let mut acc = 0.0f32;
    for i in 0..n {
        acc += black_box(&lut).eval_far(black_box(&qs[i & mask])).total().0[0];
    }
    let dt = t.elapsed().as_secs_f64();
    println!("{:.2} ns/eval (acc {acc})", dt / n as f64 * 1e9);
}
