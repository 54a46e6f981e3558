//! The C ABI's cost over the Rust call, in the same run: `fur_eval_far` (through the
//! `extern "C"` function, with its pointer and tag checks) against `BakedBcsdf::eval_far`,
//! on the same LUT and the same 256 directions. `cargo bench -p bcsdf-ffi`.
#![deny(clippy::undocumented_unsafe_blocks)]

use bake::profiles::{build_model, scale_budget, ProfileOptions};
use bcsdf_core::baked::BakedBcsdf;
use bcsdf_core::bench_support::{QueryStream, QUERY_COUNT};
use bcsdf_core::lut::LutResolution;
use bcsdf_core::medulla::PhotonBudget;
use bcsdf_core::{presets, Angles, FurParams};
use bcsdf_ffi::{fur_eval_far, fur_lut_close, fur_lut_open, fur_status, FUR_LUT_INIT};
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
    // SAFETY: lut is a valid fur_lut; closed before `blob` (declared first) is dropped.
    let closed = unsafe { fur_lut_close(&mut lut) };
    assert_eq!(closed, fur_status::FUR_OK);
}

criterion_group!(benches, bench);
criterion_main!(benches);
