//! Tight loop over the baked sampler and pdf (for profiling: `perf stat`, callgrind).
//! `FUR_LUT=<file>` reads a baked LUT instead of baking bobcat; `FUR_LUT_SAVE=<file>` writes
//! the one it uses (so that a profiler's run skips the bake).
use bake::profiles::{build_model, scale_budget, ProfileOptions};
use bcsdf_core::baked::BakedBcsdf;
use bcsdf_core::bench_support::{QueryStream, QUERY_COUNT};
use bcsdf_core::lut::LutResolution;
use bcsdf_core::medulla::PhotonBudget;
use bcsdf_core::{presets, Bcsdf, FurParams};
use std::hint::black_box;
use std::time::Instant;

fn main() {
    // A baked .furlut from the environment (FUR_LUT=path), else bobcat baked here.
    let blob = match std::env::var_os("FUR_LUT") {
        Some(path) => std::fs::read(path).expect("FUR_LUT names a readable file"),
        None => {
            let preset = presets::find("bobcat").unwrap();
            let opts = ProfileOptions {
                budget: scale_budget(PhotonBudget::DEFAULT, 0.01).unwrap(),
                ..ProfileOptions::default()
            };
            let (model, _) = build_model(FurParams::new(&preset.input).unwrap(), &opts).unwrap();
            bake::tables::bake(&model, &preset.input, LutResolution::DEFAULT)
        }
    };
    if let Some(path) = std::env::var_os("FUR_LUT_SAVE") {
        std::fs::write(path, &blob).expect("FUR_LUT_SAVE names a writable file");
    }
    let lut = BakedBcsdf::from_bytes(&blob).unwrap();
    let mut stream = QueryStream::new();
    let xs: Vec<(f32, [f32; 3])> = (0..QUERY_COUNT).map(|_| stream.sample_input()).collect();
    let n: usize = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(2_000_000);
    let only = std::env::args().nth(2).unwrap_or_default();
    // One kind of call only, for instruction counts (callgrind: the difference between two
    // call counts): `sample`, `samplepdf` (sample, then the pdf of another direction at the
    // same θ_r, as a path tracer with MIS asks), through the `Bcsdf` trait.
    let lights: Vec<(f32, f32)> = (0..QUERY_COUNT)
        .map(|_| {
            let a = stream.angles();
            (a.theta_i(), a.phi())
        })
        .collect();
    if only == "sample" || only == "samplepdf" {
        let mut acc = 0.0f32;
        for i in 0..n {
            let (tr, u) = xs[i & 255];
            let (ti, phi) = lights[i & 255];
            if let Some(s) = black_box(&lut).sample(black_box(tr), black_box(u)) {
                acc += s.pdf;
            }
            if only == "samplepdf" {
                if let Ok(a) = bcsdf_core::Angles::new(ti, tr, phi) {
                    acc += black_box(&lut).pdf(black_box(&a));
                }
            }
        }
        println!("{only}: checksum {acc}");
        return;
    }
    if only == "view-samplepdf" || only == "view-pdf" {
        // The same through one `BakedBcsdf::view` per θ_r (built in the loop for
        // `view-samplepdf`, as a path tracer does per bounce; built once for `view-pdf`).
        let mut acc = 0.0f32;
        let fixed = lut.view(xs[0].0).unwrap();
        for i in 0..n {
            let (tr, u) = xs[i & 255];
            let (ti, phi) = lights[i & 255];
            if only == "view-pdf" {
                acc += black_box(&fixed).pdf(black_box(ti), black_box(phi));
                continue;
            }
            if let Some(view) = black_box(&lut).view(black_box(tr)) {
                if let Some(s) = view.sample(black_box(u)) {
                    acc += s.pdf;
                }
                acc += view.pdf(black_box(ti), black_box(phi));
            }
        }
        println!("{only}: checksum {acc}");
        return;
    }
    if only == "pdf" {
        let dirs: Vec<_> = xs
            .iter()
            .filter_map(|&(tr, u)| lut.sample_direction(tr, u).map(|d| d.angles))
            .collect();
        let mut acc = 0.0f32;
        for i in 0..n {
            acc += black_box(&lut).pdf(black_box(&dirs[i & 127]));
        }
        println!("pdf only: checksum {acc}");
        return;
    }
    let start = Instant::now();
    let mut acc = 0.0f32;
    for i in 0..n {
        let (tr, u) = xs[i & 255];
        if let Some(s) = black_box(&lut).sample(black_box(tr), black_box(u)) {
            acc += s.pdf;
        }
    }
    let t = start.elapsed().as_secs_f64() / n as f64;
    println!("sample: {:.1} ns per call (checksum {acc})", t * 1e9);
    let dirs: Vec<_> = xs
        .iter()
        .filter_map(|&(tr, u)| lut.sample_direction(tr, u).map(|d| d.angles))
        .collect();
    let m = dirs.len();
    let time = |label: &str, f: &dyn Fn(&bcsdf_core::Angles) -> f32| {
        let start = Instant::now();
        let mut acc = 0.0f32;
        for i in 0..n {
            acc += f(black_box(&dirs[i % m]));
        }
        let t = start.elapsed().as_secs_f64() / n as f64;
        println!("{label}: {:.1} ns per call (checksum {acc})", t * 1e9);
    };
    time("eval", &|a| lut.eval(a).total().0[0]);
    time("pdf", &|a| lut.pdf(a));
    let start = Instant::now();
    let mut acc = 0.0f32;
    for i in 0..n {
        let (tr, u) = xs[i & 255];
        if let Some(d) = black_box(&lut).sample_direction(black_box(tr), black_box(u)) {
            acc += d.angles.phi();
        }
    }
    let t = start.elapsed().as_secs_f64() / n as f64;
    println!(
        "sample_direction: {:.1} ns per call (checksum {acc})",
        t * 1e9
    );
}
