//! `cargo bench -p fur-tests --bench render`: rays per second of the path tracer
//! on `ball` (64 spp, max depth 32, the baked evaluator of human-hair, two threads and one; the
//! image scaled down to 24×18 so one iteration takes about a second), and the parts a
//! path vertex spends its time in, timed alone: the BVH (closest hit of a scattered ray in
//! the ball), the BCSDF (one baked eval+pdf and one baked sample, made apart and at one
//! per-view context as a fiber vertex makes them) and the sampler (the seven uniform numbers
//! a vertex draws). docs/benchmarks.md turns them into shares.

use bake::profiles::{build_model, ProfileOptions};
use bcsdf_core::lut::LutResolution;
use bcsdf_core::{presets, BakedBcsdf, FurParams};
use criterion::{black_box, criterion_group, criterion_main, Criterion, Throughput};
use nalgebra_free::unit;
use render::sampler::Sampler;
use render::scatter::{One, Scatterer};
use render::{integrator, scenes, SceneKind, SceneOptions, Settings};

/// Plain 3-vectors for the bench's ray generation (render's API takes nalgebra vectors,
/// built from these).
mod nalgebra_free {
    pub fn unit(v: [f32; 3]) -> [f32; 3] {
        let n = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
        [v[0] / n, v[1] / n, v[2] / n]
    }
}

fn bench(c: &mut Criterion) {
    let preset = presets::find("human-hair").unwrap();
    let (model, _) = build_model(
        FurParams::new(&preset.input).unwrap(),
        &ProfileOptions::default(),
    )
    .unwrap();
    let blob = bake::tables::bake(&model, &preset.input, LutResolution::DEFAULT);
    let baked = BakedBcsdf::from_bytes(&blob).unwrap();
    let scene = scenes::build(&SceneOptions {
        kind: SceneKind::Ball,
        fibers: None,
        seed: 1,
        aspect: 4.0 / 3.0,
    });
    let settings = Settings {
        max_depth: 32,
        threads: Some(2),
        ..Settings::new(24, 18, 64)
    };
    let probe = integrator::render(&scene, &One(&baked), &settings).unwrap();
    println!(
        "ball 24x18 64 spp: {} paths, {} rays ({:.2} rays per path), {:.2} s in the probe run",
        probe.paths,
        probe.rays,
        probe.rays as f64 / probe.paths as f64,
        probe.seconds
    );
    let mut g = c.benchmark_group("render");
    g.sample_size(10);
    g.throughput(Throughput::Elements(probe.rays));
    g.bench_function("ball_64spp_depth32_baked_2threads", |b| {
        b.iter(|| integrator::render(&scene, &One(&baked), black_box(&settings)).unwrap())
    });
    // Per core without the two threads' share of 18 rows: the same render on one thread.
    let one = Settings {
        threads: Some(1),
        ..settings
    };
    g.bench_function("ball_64spp_depth32_baked_1thread", |b| {
        b.iter(|| integrator::render(&scene, &One(&baked), black_box(&one)).unwrap())
    });
    g.finish();

    // The parts, per call, on one thread.
    let mut parts = c.benchmark_group("render_parts");
    let rays: Vec<(nalgebra::Vector3<f32>, nalgebra::Vector3<f32>)> = (0..256u32)
        .map(|k| {
            let mut s = Sampler::for_pixel(7, u64::from(k));
            // From points in the coat (radius 1.0–1.3 around the ball's centre), random directions.
            let d = unit([s.next_1d() - 0.5, s.next_1d() - 0.5, s.next_1d() - 0.5]);
            let r = 1.02 + 0.25 * s.next_1d();
            let o = [d[0] * r, 1.3 + d[1] * r, d[2] * r];
            let w = unit([s.next_1d() - 0.5, s.next_1d() - 0.5, s.next_1d() - 0.5]);
            (nalgebra::Vector3::from(o), nalgebra::Vector3::from(w))
        })
        .collect();
    let mut k = 0usize;
    parts.bench_function("bvh_closest_hit_in_the_coat", |b| {
        b.iter(|| {
            k = (k + 1) & 255;
            black_box(scene.intersect(&rays[k].0, &rays[k].1, None))
        })
    });
    let fiber = One(&baked);
    let tangent = nalgebra::Vector3::new(0.3, 0.9, 0.1);
    parts.bench_function("bcsdf_eval_pdf_and_sample_baked", |b| {
        b.iter(|| {
            k = (k + 1) & 255;
            let (wr, wi) = (&rays[k].1, &rays[(k + 7) & 255].1);
            let e = fiber.eval(wi, wr, &tangent);
            let s = fiber.sample(wr, &tangent, [0.3, 0.6, 0.9]);
            black_box((e, s))
        })
    });
    // What a fiber vertex does since the two share the per-view context.
    parts.bench_function("bcsdf_eval_and_sample_baked_one_view", |b| {
        b.iter(|| {
            k = (k + 1) & 255;
            let (wr, wi) = (&rays[k].1, &rays[(k + 7) & 255].1);
            black_box(fiber.eval_and_sample(wi, wr, &tangent, [0.3, 0.6, 0.9]))
        })
    });
    let mut sampler = Sampler::for_pixel(1, 1);
    parts.bench_function("sampler_seven_numbers", |b| {
        b.iter(|| {
            let x =
                sampler.next_1d() + sampler.next_2d()[0] + sampler.next_3d()[2] + sampler.next_1d();
            black_box(x)
        })
    });
    parts.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
