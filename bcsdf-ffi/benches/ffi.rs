//! The C ABI's cost over the Rust call, in the same run: `fur_eval_far` (through the
//! `extern "C"` function, with its pointer and tag checks) against `BakedBcsdf::eval_far`,
//! on the same LUT and the same 256 directions. Then the colour entry points against their
//! siblings at the LUT's own colour, same LUT, same directions, one of 256 random colours per
//! query (channels 0, log-uniform over [1e-3, 100], or in [100, 1000]): `fur_eval_far_at`,
//! `fur_eval_far_batch_at` (256 queries per call) and `fur_sample_pdf_far_at`.
//! `cargo bench -p bcsdf-ffi`.
#![deny(clippy::undocumented_unsafe_blocks)]

use bake::profiles::{build_model, scale_budget, ProfileOptions};
use bcsdf_core::baked::BakedBcsdf;
use bcsdf_core::bench_support::{QueryStream, QUERY_COUNT};
use bcsdf_core::lut::LutResolution;
use bcsdf_core::medulla::PhotonBudget;
use bcsdf_core::rng::Pcg32;
use bcsdf_core::{presets, Absorption, Angles, FurParams, Rgb};
use bcsdf_ffi::{
    fur_eval_far, fur_eval_far_at, fur_eval_far_batch, fur_eval_far_batch_at, fur_lut_close,
    fur_lut_open, fur_sample, fur_sample_pdf_far, fur_sample_pdf_far_at, fur_status, FUR_LUT_INIT,
};
use criterion::{black_box, criterion_group, criterion_main, Criterion};

fn bench(c: &mut Criterion) {
    let preset = presets::find("bobcat").unwrap();
    let opts = ProfileOptions {
        budget: scale_budget(PhotonBudget::DEFAULT, 0.01).unwrap(),
        ..ProfileOptions::default()
    };
    let (model, _) = build_model(FurParams::new(&preset.input).unwrap(), &opts).unwrap();
    let blob = bake::tables::bake(&model, &preset.input, LutResolution::DEFAULT);
    let rust = BakedBcsdf::from_bytes(&blob).unwrap();
    let mut lut = FUR_LUT_INIT;
    // SAFETY: blob outlives lut (closed below); lut is a valid fur_lut.
    let opened = unsafe { fur_lut_open(blob.as_ptr(), blob.len(), &mut lut) };
    assert_eq!(opened, fur_status::FUR_OK);
    let mut stream = QueryStream::new();
    let qs: Vec<[f32; 3]> = (0..QUERY_COUNT)
        .map(|_| stream.degrees().map(f32::to_radians))
        .collect();
    let mut i = 0usize;
    c.bench_function("eval_far_rust", |b| {
        b.iter(|| {
            let q = qs[i & 255];
            i += 1;
            let a = Angles::new(q[0], q[1], q[2]).unwrap();
            black_box(rust.eval_far(black_box(&a)).total())
        })
    });
    let mut i = 0usize;
    c.bench_function("eval_far_c_abi", |b| {
        b.iter(|| {
            let q = qs[i & 255];
            i += 1;
            let mut out = [0.0f32; 3];
            // SAFETY: lut is open on live bytes; out has 3 floats.
            let s = unsafe { fur_eval_far(black_box(&lut), q[0], q[1], q[2], out.as_mut_ptr()) };
            black_box((s, out))
        })
    });
    // One colour per query.
    let mut rng = Pcg32::new(17, 5);
    let colours: Vec<[f32; 3]> = (0..QUERY_COUNT)
        .map(|_| {
            core::array::from_fn(|_| {
                let (pick, v) = (rng.uniform(), rng.uniform());
                if pick < 0.125 {
                    0.0
                } else if pick < 0.25 {
                    100.0 + 900.0 * v
                } else {
                    10f32.powf(5.0 * v - 3.0)
                }
            })
        })
        .collect();
    let mut i = 0usize;
    c.bench_function("eval_far_at_c_abi", |b| {
        b.iter(|| {
            let (q, s) = (qs[i & 255], &colours[i & 255]);
            i += 1;
            let mut out = [0.0f32; 3];
            // SAFETY: lut is open on live bytes; s has 3 floats, out has 3.
            let st = unsafe {
                fur_eval_far_at(
                    black_box(&lut),
                    s.as_ptr(),
                    q[0],
                    q[1],
                    q[2],
                    out.as_mut_ptr(),
                )
            };
            black_box((st, out))
        })
    });
    // Batches of 256 queries (structure of arrays).
    let ti: Vec<f32> = qs.iter().map(|q| q[0]).collect();
    let tr: Vec<f32> = qs.iter().map(|q| q[1]).collect();
    let ph: Vec<f32> = qs.iter().map(|q| q[2]).collect();
    let flat: Vec<f32> = colours.iter().flatten().copied().collect();
    let n = qs.len();
    let mut out = vec![0.0f32; 3 * n];
    c.bench_function("eval_far_batch_256_c_abi", |b| {
        b.iter(|| {
            // SAFETY: lut is open on live bytes; the slices hold n (3n) floats.
            let st = unsafe {
                fur_eval_far_batch(
                    black_box(&lut),
                    n,
                    ti.as_ptr(),
                    tr.as_ptr(),
                    ph.as_ptr(),
                    out.as_mut_ptr(),
                )
            };
            black_box(st)
        })
    });
    c.bench_function("eval_far_batch_at_256_c_abi", |b| {
        b.iter(|| {
            // SAFETY: lut is open on live bytes; the slices hold n (3n) floats.
            let st = unsafe {
                fur_eval_far_batch_at(
                    black_box(&lut),
                    n,
                    flat.as_ptr(),
                    ti.as_ptr(),
                    tr.as_ptr(),
                    ph.as_ptr(),
                    out.as_mut_ptr(),
                )
            };
            black_box(st)
        })
    });
    // The core's batch with a colour per query (what fur_eval_far_batch_at calls, 32
    // queries per call), for the C ABI's share of the cost.
    let absorptions: Vec<Absorption> = colours
        .iter()
        .map(|c| Absorption::from_sigma(Rgb(*c)).unwrap())
        .collect();
    let mut rgb_out = vec![Rgb::ZERO; n];
    c.bench_function("eval_far_batch_colours_256_rust", |b| {
        b.iter(|| {
            black_box(rust.eval_far_batch_colours(
                &ti,
                &tr,
                &ph,
                black_box(&absorptions),
                &mut rgb_out,
            ))
        })
    });
    // One path-tracer bounce: a sample and a light's pdf at the same view.
    let mut i = 0usize;
    c.bench_function("sample_pdf_far_c_abi", |b| {
        b.iter(|| {
            let q = qs[i & 255];
            i += 1;
            let (mut s, mut p) = (fur_sample_zero(), 0.0f32);
            // SAFETY: lut is open on live bytes; s and p are writable.
            let st = unsafe {
                fur_sample_pdf_far(
                    black_box(&lut),
                    q[1],
                    0.3,
                    0.6,
                    0.2,
                    q[0],
                    q[2],
                    &mut s,
                    &mut p,
                )
            };
            black_box((st, s.weight, p))
        })
    });
    let mut i = 0usize;
    c.bench_function("sample_pdf_far_at_c_abi", |b| {
        b.iter(|| {
            let (q, c) = (qs[i & 255], &colours[i & 255]);
            i += 1;
            let (mut s, mut p) = (fur_sample_zero(), 0.0f32);
            // SAFETY: lut is open on live bytes; c has 3 floats; s and p are writable.
            let st = unsafe {
                fur_sample_pdf_far_at(
                    black_box(&lut),
                    c.as_ptr(),
                    q[1],
                    0.3,
                    0.6,
                    0.2,
                    q[0],
                    q[2],
                    &mut s,
                    &mut p,
                )
            };
            black_box((st, s.weight, p))
        })
    });
    // SAFETY: lut is a valid fur_lut; closed before `blob` (declared first) is dropped.
    let closed = unsafe { fur_lut_close(&mut lut) };
    assert_eq!(closed, fur_status::FUR_OK);
}

criterion_group!(benches, bench);
criterion_main!(benches);

/// A `fur_sample` to write into.
fn fur_sample_zero() -> fur_sample {
    fur_sample {
        theta_i: 0.0,
        phi: 0.0,
        pdf: 0.0,
        weight: [0.0; 3],
        family: bcsdf_ffi::fur_family::FUR_FAMILY_R,
    }
}
