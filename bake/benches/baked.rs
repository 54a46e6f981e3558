//! Baked versus analytic far field, in the same run (RGB, one query per iteration from a fixed
//! list of 256 directions over θ_i, θ_r ∈ ±80°, φ ∈ (−180°, 180°]):
//!
//! - `far_field_analytic/<preset>`: `FurBcsdf::eval_far(..).total()`, the full model (eight
//!   unscattered paths and the scattered lobes);
//! - `far_field_baked/<preset>`: `BakedBcsdf::eval_far(..).total()` on the LUT of the same
//!   model at the default resolution.
//!
//! The profiles use a small photon budget: neither evaluation's cost depends on it. The
//! query index is masked (256 queries), not taken modulo: a division would cost as much as a
//! third of a baked evaluation.
//! `cargo bench -p bake --bench baked`; the speed-up is the ratio of the two medians.

use bake::profiles::{build_model, scale_budget, ProfileOptions};
use bake::tables;
use bcsdf_core::baked::BakedBcsdf;
use bcsdf_core::lut::LutResolution;
use bcsdf_core::medulla::PhotonBudget;
use bcsdf_core::{presets, Angles, FurParams};
use criterion::{black_box, criterion_group, criterion_main, Criterion};

fn queries() -> Vec<Angles> {
    let mut state = 0x2545_f491_4f6c_dd1du64;
    let mut next = move || {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((state >> 40) as f32) / (1u64 << 24) as f32
    };
    (0..256)
        .map(|_| {
            Angles::from_degrees(
                -80.0 + 160.0 * next(),
                -80.0 + 160.0 * next(),
                -180.0 + 360.0 * next(),
            )
            .unwrap()
        })
        .collect()
}

fn bench(c: &mut Criterion) {
    let qs = queries();
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

        let mut i = 0usize;
        c.bench_function(&format!("far_field_analytic/{name}"), |b| {
            b.iter(|| {
                let a = &qs[i & 255];
                i += 1;
                black_box(analytic.eval_far(black_box(a)).total())
            })
        });
        let mut i = 0usize;
        c.bench_function(&format!("far_field_baked/{name}"), |b| {
            b.iter(|| {
                let a = &qs[i & 255];
                i += 1;
                black_box(baked.eval_far(black_box(a)).total())
            })
        });
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
