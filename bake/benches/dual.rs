//! The dual-scattering term against one baked evaluation, in the same run (the term's speed
//! check: the term at most 2× the cost of a baked eval; docs/model.md §13):
//!
//! - `dual_baked_eval/<preset>`: `BakedBcsdf::eval_far(..).total()`, the LUT at the default
//!   resolution (what an engine evaluates per light for single scattering);
//! - `dual_term/<preset>/<n>`: `DualLut::eval` with the shipped `Attenuation::Coat` and
//!   `Density::DEFAULT` from tables computed from that LUT (through the `.furdual` blob), at
//!   fiber counts n = 0 (unoccluded: the local backscatter only), 1.5 and 6 (the spread term
//!   too: six Gaussians per channel), each with m = 3 fibers below (the finite coat; its
//!   cost does not depend on m);
//! - `dual_term_colour/<preset>/<n>`: `DualLut::eval_at` at the same counts with a different
//!   random colour per query (the 256 σ_ca of `baked`'s `far_field_baked_colour`, each channel
//!   log-uniform over [0.01, 1000]), locating the colour included.
//!
//! One query per iteration from the fixed list of 256 directions of `bench_support`, index
//! masked. `cargo bench -p bake --bench dual`.

use bake::profiles::{build_model, scale_budget, ProfileOptions};
use bake::tables;
use bcsdf_core::baked::BakedBcsdf;
use bcsdf_core::bench_support::{QueryStream, QUERY_COUNT};
use bcsdf_core::dual::{encode, Attenuation, Density, DualLut, DualTables, Fibers, Quadrature};
use bcsdf_core::lut::LutResolution;
use bcsdf_core::medulla::PhotonBudget;
use bcsdf_core::{presets, Absorption, Angles, FurParams, Rgb};
use criterion::{black_box, criterion_group, criterion_main, Criterion};

fn bench(c: &mut Criterion) {
    let mut stream = QueryStream::new();
    let qs: Vec<Angles> = (0..QUERY_COUNT).map(|_| stream.angles()).collect();
    // A colour per query: each channel log-uniform over [0.01, 1000] (as `baked`'s).
    let colours: Vec<Absorption> = (0..256)
        .map(|k| {
            let u = |j: u32| ((k * 3 + j) as f32 * 0.618_034).fract();
            Absorption::from_sigma(Rgb([0, 1, 2].map(|j| 10f32.powf(-2.0 + 5.0 * u(j))))).unwrap()
        })
        .collect();
    let opts = ProfileOptions {
        budget: scale_budget(PhotonBudget::DEFAULT, 0.01).unwrap(),
        ..ProfileOptions::default()
    };
    for name in ["bobcat", "dog", "human-hair"] {
        let preset = presets::find(name).unwrap();
        let params = FurParams::new(&preset.input).unwrap();
        let (model, _) = build_model(params, &opts).unwrap();
        let blob = tables::bake(&model, &preset.input, LutResolution::DEFAULT);
        let baked = BakedBcsdf::from_bytes(&blob).unwrap();
        let mut dual_tables = Box::new(DualTables::ZERO);
        dual_tables.compute(&baked, Quadrature::DEFAULT);
        let mut lut = Box::new(DualLut::EMPTY);
        lut.decode(&encode(&dual_tables, Attenuation::Coat, 0))
            .unwrap();

        let mut i = 0usize;
        c.bench_function(&format!("dual_baked_eval/{name}"), |b| {
            b.iter(|| {
                let a = &qs[i & 255];
                i += 1;
                black_box(baked.eval_far(black_box(a)).total())
            })
        });
        for n in [0.0f32, 1.5, 6.0] {
            let mut i = 0usize;
            c.bench_function(&format!("dual_term/{name}/{n}"), |b| {
                b.iter(|| {
                    let a = &qs[i & 255];
                    i += 1;
                    let counts = Fibers::new(black_box(n), black_box(3.0));
                    black_box(lut.eval(black_box(a), counts, Density::DEFAULT))
                })
            });
            let mut i = 0usize;
            c.bench_function(&format!("dual_term_colour/{name}/{n}"), |b| {
                b.iter(|| {
                    let k = i & 255;
                    i += 1;
                    let counts = Fibers::new(black_box(n), black_box(3.0));
                    black_box(lut.eval_at(
                        black_box(&qs[k]),
                        counts,
                        Density::DEFAULT,
                        black_box(&colours[k]),
                    ))
                })
            });
        }
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
