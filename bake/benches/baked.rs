//! Baked versus analytic far field, in the same run (RGB, one query per iteration from a fixed
//! list of 256 directions over θ_i, θ_r ∈ ±80°, φ ∈ (−180°, 180°]):
//!
//! - `far_field_analytic/<preset>`: `FurBcsdf::eval_far(..).total()`, the full model (eight
//!   unscattered paths, the scattered lobes and, in the presets' energy closure, the lobes'
//!   sphere normalisation and the residual);
//! - `far_field_analytic_report/<preset>`: the same parameters in the report closure (no
//!   normalisation, no residual), so that the energy closure's analytic cost is a ratio
//!   measured in one run (docs/model.md §12);
//! - `far_field_baked/<preset>`: `BakedBcsdf::eval_far(..).total()` on the LUT of the same
//!   model at the default resolution (the preset's closure: energy);
//! - `far_field_baked_report/<preset>`: the same LUT with its header's closure set to report
//!   (the lookups do not depend on the tables' values), i.e. without the energy closure's 1/Z_g
//!   lookup, so that its cost is a ratio measured in one run.
//!
//! - `far_field_baked_colour/<preset>`: `BakedBcsdf::at(colour).eval_far(..).total()` with a
//!   different random colour per query (docs/lut.md "The absorption axis"), locating the colour
//!   included;
//! - `far_field_baked_batch/<preset>/<size>`: `BakedBcsdf::eval_far_batch` over consecutive
//!   batches of `size` queries (structure of arrays), per query (criterion's throughput),
//!   with the CPU's best kernel (`Kernel::best`), and `sse2-256` with the baseline (SSE2) kernel;
//! - `far_field_baked_dirs/<preset>`: `BakedBcsdf::eval_far_dirs(..).total()` on the same
//!   directions as world-space vectors.
//!
//! Before timing, the setup checks that each closure's scalar path and batch agree bit for bit
//! on the 256 queries.
//!
//! The profiles use a small photon budget: neither evaluation's cost depends on it. The
//! query index is masked (256 queries), not taken modulo: a division would cost as much as a
//! third of a baked evaluation.
//! `cargo bench -p bake --bench baked`; the speed-up is the ratio of the two medians.
//! `BAKED_BENCH_PRESETS=bobcat,human-hair` bakes and times only those presets.

use bake::profiles::{build_model, scale_budget, ProfileOptions};
use bake::tables;
use bcsdf_core::baked::{BakedBcsdf, Kernel};
use bcsdf_core::bench_support::{QueryStream, QUERY_COUNT};
use bcsdf_core::lut::LutResolution;
use bcsdf_core::medulla::PhotonBudget;
use bcsdf_core::{presets, Absorption, Angles, FurParams};
use bcsdf_core::{Rgb, Vec3};
use criterion::{black_box, criterion_group, criterion_main, Criterion, Throughput};

/// The query's directions as world-space vectors (tangent along z, ω_r in the x-z plane).
fn directions(a: &Angles) -> (Vec3, Vec3, Vec3) {
    let (ti, tr, phi) = (a.theta_i(), a.theta_r(), a.phi());
    let wr = [tr.cos(), 0.0, tr.sin()];
    // φ = φ_r − φ_i, so ω_i's azimuth is −φ.
    let wi = [ti.cos() * (-phi).cos(), ti.cos() * (-phi).sin(), ti.sin()];
    (wi, wr, [0.0, 0.0, 1.0])
}

fn queries() -> Vec<Angles> {
    let mut stream = QueryStream::new();
    (0..QUERY_COUNT).map(|_| stream.angles()).collect()
}

fn bench(c: &mut Criterion) {
    let qs = queries();
    let opts = ProfileOptions {
        budget: scale_budget(PhotonBudget::DEFAULT, 0.01).unwrap(),
        ..ProfileOptions::default()
    };
    // BAKED_BENCH_PRESETS=a,b: only those presets (each preset's setup bakes its LUT).
    let only = std::env::var("BAKED_BENCH_PRESETS").ok();
    let wanted = |name: &str| {
        only.as_deref()
            .is_none_or(|l| l.split(',').any(|n| n == name))
    };
    for preset in presets::PRESETS.iter().filter(|p| wanted(p.name)) {
        let name = preset.name;
        let params = FurParams::new(&preset.input).unwrap();
        let (model, _) = build_model(params, &opts).unwrap();
        let blob = tables::bake(&model, &preset.input, LutResolution::DEFAULT);
        let baked = BakedBcsdf::from_bytes(&blob).unwrap();
        // The presets use the energy closure; the same tables in the report closure (header
        // word 27, after g, is the closure) measure what the energy closure's 1/Z_g lookup
        // costs, with nothing else different.
        assert_eq!(baked.params().closure(), bcsdf_core::Closure::Energy);
        let mut report_blob = blob.clone();
        report_blob[108..112].copy_from_slice(&0u32.to_le_bytes());
        bcsdf_core::lut::seal(&mut report_blob);
        let report = BakedBcsdf::from_bytes(&report_blob).unwrap();
        assert_eq!(report.params().closure(), bcsdf_core::Closure::Report);
        let analytic = model.model();
        // The report closure's analytic model: no sphere normalisation, no residual.
        let (report_model, _) =
            build_model(params.with_closure(bcsdf_core::Closure::Report), &opts).unwrap();
        let analytic_report = report_model.model();

        let mut i = 0usize;
        c.bench_function(&format!("far_field_analytic/{name}"), |b| {
            b.iter(|| {
                let a = &qs[i & 255];
                i += 1;
                black_box(analytic.eval_far(black_box(a)).total())
            })
        });
        let mut i = 0usize;
        c.bench_function(&format!("far_field_analytic_report/{name}"), |b| {
            b.iter(|| {
                let a = &qs[i & 255];
                i += 1;
                black_box(analytic_report.eval_far(black_box(a)).total())
            })
        });
        let (ti, tr, ph): (Vec<f32>, Vec<f32>, Vec<f32>) = {
            let cycle = || qs.iter().chain(&qs);
            (
                cycle().map(Angles::theta_i).collect(),
                cycle().map(Angles::theta_r).collect(),
                cycle().map(Angles::phi).collect(),
            )
        };
        for lut in [&baked, &report] {
            let mut batch_out = vec![Rgb::ZERO; 256];
            lut.eval_far_batch(&ti[..256], &tr[..256], &ph[..256], &mut batch_out)
                .unwrap();
            for (a, b) in qs.iter().zip(&batch_out) {
                let scalar = lut.eval_far(a).total();
                assert_eq!(scalar.0.map(f32::to_bits), b.0.map(f32::to_bits));
            }
        }
        let dirs: Vec<(Vec3, Vec3, Vec3)> = qs.iter().map(directions).collect();

        let mut i = 0usize;
        c.bench_function(&format!("far_field_baked/{name}"), |b| {
            b.iter(|| {
                let a = &qs[i & 255];
                i += 1;
                black_box(baked.eval_far(black_box(a)).total())
            })
        });
        // A colour per query (docs/lut.md "The absorption axis"): 256 random σ_ca.
        let colours: Vec<Absorption> = (0..256)
            .map(|k| {
                let u = |j: u32| ((k * 3 + j) as f32 * 0.618_034).fract();
                Absorption::from_sigma(Rgb([0, 1, 2].map(|j| 10f32.powf(-2.0 + 5.0 * u(j)))))
                    .unwrap()
            })
            .collect();
        let mut i = 0usize;
        c.bench_function(&format!("far_field_baked_colour/{name}"), |b| {
            b.iter(|| {
                let k = i & 255;
                i += 1;
                black_box(
                    baked
                        .at(black_box(&colours[k]))
                        .eval_far(black_box(&qs[k]))
                        .total(),
                )
            })
        });
        let mut i = 0usize;
        c.bench_function(&format!("far_field_baked_report/{name}"), |b| {
            b.iter(|| {
                let a = &qs[i & 255];
                i += 1;
                black_box(report.eval_far(black_box(a)).total())
            })
        });
        let mut i = 0usize;
        c.bench_function(&format!("far_field_baked_dirs/{name}"), |b| {
            b.iter(|| {
                // The vectors read from the query array behind an opaque reference, as
                // `far_field_baked` reads its angles: `black_box` on each vector's value
                // stored it to the stack and read it back right before the call, a store
                // forwarding stall of the harness's own.
                let (wi, wr, u) = *black_box(&dirs[i & 255]);
                i += 1;
                black_box(baked.eval_far_dirs(wi, wr, u).total())
            })
        });
        let mut group = c.benchmark_group(format!("far_field_baked_batch/{name}"));
        // The CPU's best kernel at two sizes, and the SSE2 kernel (x86-64's baseline).
        let sse2 = baked.with_kernel(Kernel::Baseline).unwrap();
        let kernels = [
            (&baked, 64usize, ""),
            (&baked, 256, ""),
            (&sse2, 256, "sse2-"),
        ];
        for (lut, size, label) in kernels {
            group.throughput(Throughput::Elements(size as u64));
            let mut out = vec![Rgb::ZERO; size];
            let mut start = 0usize;
            group.bench_function(format!("{label}{size}"), |b| {
                b.iter(|| {
                    let r = start..start + size;
                    start = (start + size) & 255;
                    black_box(lut)
                        .eval_far_batch(&ti[r.clone()], &tr[r.clone()], &ph[r], &mut out)
                        .unwrap();
                    black_box(&out);
                })
            });
        }
        group.throughput(Throughput::Elements(256));
        let mut out = vec![Rgb::ZERO; 256];
        group.bench_function("colours-256", |b| {
            b.iter(|| {
                black_box(&baked)
                    .eval_far_batch_colours(&ti[..256], &tr[..256], &ph[..256], &colours, &mut out)
                    .unwrap();
                black_box(&out);
            })
        });
        group.finish();
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
