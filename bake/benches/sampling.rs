//! Importance sampling cost (docs/model.md §10), one call per iteration over fixed lists of
//! 256 pre-generated inputs (θ_r ∈ ±80°, u uniform; directions for `pdf` from the sampler
//! itself, so they lie where the density lives):
//!
//! - `sample_baked/<preset>`: `BakedBcsdf::sample` (direction, pdf, weight: includes one
//!   evaluation and one pdf);
//! - `sample_pdf_baked/<preset>`: `sample` followed by `pdf` of the sampled direction (what a
//!   path tracer with MIS calls, pbrt's Sample_f + Pdf);
//! - `pdf_baked/<preset>`: `BakedBcsdf::pdf` alone;
//! - `view_sample_pdf_baked/<preset>`: `BakedBcsdf::view(θ_r)`, then `sample` and the `pdf`
//!   of another direction (a light's) at that view: one bounce of a path tracer with MIS;
//! - `view_sample_baked/<preset>`: `view(θ_r)` then `sample`;
//! - `view_pdf_baked/<preset>`: `pdf` of a view built once (the θ_r-only work excluded);
//! - `sample_analytic/<preset>`: `FurBcsdf::sample` (the h integrals of eval and pdf in one
//!   pass); `sample_direction_analytic/<preset>`: the direction alone, without eval or pdf.
//!
//! `cargo bench -p bake --bench sampling`.

use bake::profiles::{build_model, scale_budget, ProfileOptions};
use bake::tables;
use bcsdf_core::baked::BakedBcsdf;
use bcsdf_core::bench_support::{QueryStream, QUERY_COUNT};
use bcsdf_core::lut::LutResolution;
use bcsdf_core::medulla::PhotonBudget;
use bcsdf_core::{presets, Angles, Bcsdf, FurParams};
use criterion::{black_box, criterion_group, criterion_main, Criterion};
use std::time::Duration;

fn inputs() -> Vec<(f32, [f32; 3])> {
    let mut stream = QueryStream::new();
    (0..QUERY_COUNT).map(|_| stream.sample_input()).collect()
}

fn bench(c: &mut Criterion) {
    let xs = inputs();
    let opts = ProfileOptions {
        budget: scale_budget(PhotonBudget::DEFAULT, 0.01).unwrap(),
        ..ProfileOptions::default()
    };
    for preset in presets::PRESETS.iter() {
        let name = preset.name;
        let params = FurParams::new(&preset.input).unwrap();
        let (model, _) = build_model(params, &opts).unwrap();
        let blob = tables::bake(&model, &preset.input, LutResolution::DEFAULT);
        let baked = BakedBcsdf::from_bytes(&blob).unwrap();
        let analytic = model.model();
        let dirs: Vec<Angles> = xs
            .iter()
            .filter_map(|&(tr, u)| baked.sample_direction(tr, u).map(|d| d.angles))
            .collect();
        let n = dirs.len();

        let mut i = 0usize;
        c.bench_function(&format!("sample_baked/{name}"), |b| {
            b.iter(|| {
                let (tr, u) = xs[i & 255];
                i += 1;
                black_box(baked.sample(black_box(tr), black_box(u)))
            })
        });
        let mut i = 0usize;
        c.bench_function(&format!("sample_pdf_baked/{name}"), |b| {
            b.iter(|| {
                let (tr, u) = xs[i & 255];
                i += 1;
                let s = baked.sample(black_box(tr), black_box(u));
                black_box(s.map(|s| baked.pdf(&s.angles)))
            })
        });
        // Through a per-view context (docs/model.md §10): built in every iteration, as a path
        // tracer builds one per bounce, then a sample and the density of another direction
        // at the same θ_r (a light's, for MIS).
        let lights: Vec<(f32, f32)> = {
            let mut stream = QueryStream::new();
            (0..QUERY_COUNT)
                .map(|_| {
                    let a = stream.angles();
                    (a.theta_i(), a.phi())
                })
                .collect()
        };
        let mut i = 0usize;
        c.bench_function(&format!("view_sample_pdf_baked/{name}"), |b| {
            b.iter(|| {
                let (tr, u) = xs[i & 255];
                let (ti, phi) = lights[i & 255];
                i += 1;
                let view = baked.view(black_box(tr)).unwrap();
                black_box((view.sample(black_box(u)), view.pdf(ti, phi)))
            })
        });
        let mut i = 0usize;
        c.bench_function(&format!("view_sample_baked/{name}"), |b| {
            b.iter(|| {
                let (tr, u) = xs[i & 255];
                i += 1;
                let view = baked.view(black_box(tr)).unwrap();
                black_box(view.sample(black_box(u)))
            })
        });
        let view = baked.view(xs[0].0).unwrap();
        let mut i = 0usize;
        c.bench_function(&format!("view_pdf_baked/{name}"), |b| {
            b.iter(|| {
                let (ti, phi) = lights[i & 255];
                i += 1;
                black_box(view.pdf(black_box(ti), black_box(phi)))
            })
        });
        let mut i = 0usize;
        c.bench_function(&format!("pdf_baked/{name}"), |b| {
            b.iter(|| {
                let a = &dirs[i % n];
                i += 1;
                black_box(baked.pdf(black_box(a)))
            })
        });
        let mut g = c.benchmark_group(format!("analytic/{name}"));
        g.sample_size(20).measurement_time(Duration::from_secs(3));
        let mut i = 0usize;
        g.bench_function("sample_analytic", |b| {
            b.iter(|| {
                let (tr, u) = xs[i & 255];
                i += 1;
                black_box(analytic.sample(black_box(tr), black_box(u)))
            })
        });
        let mut i = 0usize;
        g.bench_function("sample_direction_analytic", |b| {
            b.iter(|| {
                let (tr, u) = xs[i & 255];
                i += 1;
                black_box(analytic.sample_direction(black_box(tr), black_box(u)))
            })
        });
        g.finish();
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
