//! Throughput of the WGSL evaluator on the first adapter (criterion, elements = evaluations):
//! 2^18 random angle queries per iteration, upload, dispatch and readback included.
//! `cargo bench -p bcsdf-gpu`. Prints "skipped: no GPU adapter" without one.
use bcsdf_core::bench_support::indexed_radians;
use bcsdf_gpu::GpuLut;
use criterion::{criterion_group, criterion_main, Criterion, Throughput};

fn bench(c: &mut Criterion) {
    let preset = bcsdf_core::presets::find("human-hair").unwrap();
    let params = bcsdf_core::FurParams::new(&preset.input).unwrap();
    let (m, _) = bake::profiles::build_model(params, &Default::default()).unwrap();
    let bytes = bake::tables::bake(&m, &preset.input, bcsdf_core::lut::LutResolution::DEFAULT);
    let gpu = match GpuLut::new(&bytes) {
        Ok(g) => g,
        Err(e) => {
            println!("skipped: no GPU adapter ({e})");
            return;
        }
    };
    let n = 1usize << 18;
    let q: Vec<[f32; 3]> = (0..n as u64).map(indexed_radians).collect();
    let mut g = c.benchmark_group(format!("gpu_eval/{}", gpu.adapter_name()));
    g.throughput(Throughput::Elements(n as u64)).sample_size(10);
    g.bench_function("eval_far_2^18", |b| b.iter(|| gpu.eval(&q).unwrap()));
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
