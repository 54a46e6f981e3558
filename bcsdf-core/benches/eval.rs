//! Near- and far-field evaluation cost (RGB): the eight unscattered paths alone
//! (`near_field/`, `far_field/`) and the full model with the scattered lobes (`*_full/`); and
//! the base colour inversion per call (`base_colour/`).
//!
//! Each iteration evaluates one query from a fixed, deterministic list spread over
//! θ_i, θ_r ∈ ±80° and φ ∈ (−180°, 180°], so branch and cache behaviour is that of a renderer
//! rather than of one repeated point.

use bcsdf_core::bench_support::{QueryStream, QUERY_COUNT};
use bcsdf_core::{presets, Angles, FurBcsdf, FurParams};
use criterion::{black_box, criterion_group, criterion_main, Criterion};

fn queries() -> Vec<(Angles, f32)> {
    // The shared deterministic list (bcsdf_core::bench_support): angles, then an offset h.
    let mut stream = QueryStream::new();
    (0..QUERY_COUNT)
        .map(|_| stream.angles_and_offset())
        .collect()
}

fn bench(c: &mut Criterion) {
    let qs = queries();
    for name in ["bobcat", "red-fox", "raccoon", "human-hair", "air-medulla"] {
        let preset = presets::find(name).unwrap();
        let model: FurBcsdf = FurBcsdf::unscattered(FurParams::new(&preset.input).unwrap());
        let mut i = 0usize;
        c.bench_function(&format!("near_field/{name}"), |b| {
            b.iter(|| {
                let (a, h) = &qs[i % qs.len()];
                i += 1;
                black_box(model.eval_near(black_box(a), black_box(*h)).total())
            })
        });
        let mut i = 0usize;
        c.bench_function(&format!("far_field/{name}"), |b| {
            b.iter(|| {
                let (a, _) = &qs[i % qs.len()];
                i += 1;
                black_box(model.eval_far(black_box(a)).total())
            })
        });
    }
}

/// The full model (unscattered + scattered lobes). Profiles at a small photon budget: the
/// evaluation cost does not depend on how many photons made the tables.
fn bench_full(c: &mut Criterion) {
    use bcsdf_core::medulla::{generate, MedullaProfiles, PhotonBudget, ProfileLayout, Resolution};
    let qs = queries();
    for name in ["bobcat", "red-fox", "raccoon", "air-medulla"] {
        let params = FurParams::new(&presets::find(name).unwrap().input).unwrap();
        let layout = ProfileLayout::for_params(&params, Resolution::DEFAULT);
        let budget = PhotonBudget {
            per_cn_cell: 2_000,
            per_cm_row: 4_000,
        };
        let (mut cn, mut cm) = (vec![0.0; layout.cn_len()], vec![0.0; layout.cm_len()]);
        generate(&layout, &budget, 1, &mut cn, &mut cm).unwrap();
        let profiles = MedullaProfiles::new(layout, &cn, &cm).unwrap();
        let model: FurBcsdf = FurBcsdf::new(params, profiles).unwrap();
        let mut i = 0usize;
        c.bench_function(&format!("near_field_full/{name}"), |b| {
            b.iter(|| {
                let (a, h) = &qs[i % qs.len()];
                i += 1;
                black_box(model.eval_near(black_box(a), black_box(*h)).total())
            })
        });
        let mut i = 0usize;
        c.bench_function(&format!("far_field_full/{name}"), |b| {
            b.iter(|| {
                let (a, _) = &qs[i % qs.len()];
                i += 1;
                black_box(model.eval_far(black_box(a)).total())
            })
        });
    }
}

/// The same queries with the `FastMath` backend (`--features micromath`).
#[cfg(feature = "micromath")]
fn bench_fast(c: &mut Criterion) {
    use bcsdf_core::FastMath;
    let qs = queries();
    for name in ["bobcat", "human-hair"] {
        let preset = presets::find(name).unwrap();
        let model = FurBcsdf::<FastMath>::unscattered(FurParams::new(&preset.input).unwrap());
        let mut i = 0usize;
        c.bench_function(&format!("near_field_fastmath/{name}"), |b| {
            b.iter(|| {
                let (a, h) = &qs[i % qs.len()];
                i += 1;
                black_box(model.eval_near(black_box(a), black_box(*h)).total())
            })
        });
        let mut i = 0usize;
        c.bench_function(&format!("far_field_fastmath/{name}"), |b| {
            b.iter(|| {
                let (a, _) = &qs[i % qs.len()];
                i += 1;
                black_box(model.eval_far(black_box(a)).total())
            })
        });
    }
}

#[cfg(not(feature = "micromath"))]
fn bench_fast(_: &mut Criterion) {}

/// One base colour inverted per iteration (`Absorption::from_base_colour`, docs/model.md §14):
/// 256 colours from a fixed list, each channel spread over [0, 1] (so over every cell of the
/// table, and beyond its ends: clamped channels included), on the made-up table of the
/// rustdoc example, c(σ) = 0.02 + 0.9/(1 + 4σ). The cost is a linear search through up to 23
/// cells per channel and a square root's inverse, so it grows with σ (darker channels search
/// further): the spread list gives the mean over the table.
fn bench_base_colour(c: &mut Criterion) {
    use bcsdf_core::colour::{coat_node, CoatColour};
    use bcsdf_core::{Absorption, Rgb};
    let coat = CoatColour::from_colours(core::array::from_fn(|k| {
        0.02 + 0.9 / (1.0 + 4.0 * coat_node(k))
    }))
    .unwrap();
    // Three incommensurate strides (the golden ratio's and two others) modulo 1.
    let colours: Vec<Rgb> = (0..256)
        .map(|i| {
            let f = i as f32;
            Rgb([
                (f * 0.618_034).fract(),
                (f * 0.414_214 + 0.3).fract(),
                (f * 0.732_051 + 0.7).fract(),
            ])
        })
        .collect();
    let mut i = 0usize;
    c.bench_function("base_colour/from_base_colour", |b| {
        b.iter(|| {
            let colour = colours[i % colours.len()];
            i += 1;
            black_box(Absorption::from_base_colour(
                black_box(colour),
                black_box(&coat),
            ))
        })
    });
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(30).warm_up_time(std::time::Duration::from_millis(500)).measurement_time(std::time::Duration::from_secs(2));
    targets = bench, bench_full, bench_fast, bench_base_colour
}
criterion_main!(benches);
