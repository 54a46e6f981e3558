//! Evaluations per second of the WGSL evaluator on the first adapter: 2^20 random angle
//! queries per dispatch, the median of 7 timed runs after one warm-up (upload of the queries,
//! dispatch, readback included). `cargo run --release -p bcsdf-gpu --example throughput [LUT]`
//! (without a LUT file, human-hair is baked here).
use bcsdf_core::bench_support::indexed_radians;
use bcsdf_gpu::GpuLut;
use std::time::Instant;

fn main() {
    let bytes = match std::env::args().nth(1) {
        Some(path) => std::fs::read(path).expect("readable LUT file"),
        None => {
            let preset = bcsdf_core::presets::find("human-hair").unwrap();
            let params = bcsdf_core::FurParams::new(&preset.input).unwrap();
            let (m, _) = bake::profiles::build_model(params, &Default::default()).unwrap();
            bake::tables::bake(&m, &preset.input, bcsdf_core::lut::LutResolution::DEFAULT)
        }
    };
    let gpu = match GpuLut::new(&bytes) {
        Ok(g) => g,
        Err(e) => {
            eprintln!("error: {e}");
            std::process::exit(2);
        }
    };
    let n = 1usize << 20;
    let q: Vec<[f32; 3]> = (0..n as u64).map(indexed_radians).collect();
    gpu.eval(&q).unwrap();
    let mut times: Vec<f64> = (0..7)
        .map(|_| {
            let t = Instant::now();
            gpu.eval(&q).unwrap();
            t.elapsed().as_secs_f64()
        })
        .collect();
    times.sort_by(f64::total_cmp);
    let median = times[3];
    println!(
        "{}: {:.1} M evaluations/s ({n} per dispatch, median {:.1} ms, range {:.1}-{:.1} ms)",
        gpu.adapter_name(),
        n as f64 / median / 1e6,
        median * 1e3,
        times[0] * 1e3,
        times[6] * 1e3
    );
}
