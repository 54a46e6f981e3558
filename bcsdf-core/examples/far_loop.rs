//! A tight loop over the far field, for profilers (`perf record`, `valgrind --tool=callgrind`)
//! and for a checksum that shows whether a change moved the numbers.
//!
//! `cargo run --release -p bcsdf-core --example far_loop -- PRESET [unscattered|full] [N]`
//! evaluates N far-field queries (default 20 000) from the same 256-query list as
//! `benches/eval.rs` and prints the time per query and the sum of all lobes.

use bcsdf_core::bench_support::{QueryStream, QUERY_COUNT};
use bcsdf_core::medulla::{generate, MedullaProfiles, PhotonBudget, ProfileLayout, Resolution};
use bcsdf_core::{presets, Angles, FurBcsdf, FurParams};
use std::time::Instant;

fn queries() -> Vec<Angles> {
    // The list of benches/eval.rs (each query there also draws an offset h), so that both
    // see the same directions.
    let mut stream = QueryStream::new();
    (0..QUERY_COUNT)
        .map(|_| stream.angles_and_offset().0)
        .collect()
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let name = args.get(1).map_or("bobcat", String::as_str);
    let full = args.get(2).is_some_and(|m| m == "full");
    let n: usize = args.get(3).and_then(|s| s.parse().ok()).unwrap_or(20_000);
    let params = FurParams::new(&presets::find(name).expect("unknown preset").input).unwrap();
    let layout = ProfileLayout::for_params(&params, Resolution::DEFAULT);
    let budget = PhotonBudget {
        per_cn_cell: 2_000,
        per_cm_row: 4_000,
    };
    let (mut cn, mut cm) = (vec![0.0; layout.cn_len()], vec![0.0; layout.cm_len()]);
    let model: FurBcsdf = if full {
        generate(&layout, &budget, 1, &mut cn, &mut cm).unwrap();
        let profiles = MedullaProfiles::new(layout, &cn, &cm).unwrap();
        FurBcsdf::new(params, profiles).unwrap()
    } else {
        FurBcsdf::unscattered(params)
    };
    let qs = queries();
    let start = Instant::now();
    let mut sum = 0.0f64;
    for i in 0..n {
        let v = model.eval_far(std::hint::black_box(&qs[i % qs.len()]));
        sum += f64::from(v.total().0.iter().sum::<f32>());
    }
    let dt = start.elapsed().as_secs_f64() / n as f64;
    println!(
        "{name} {}: {:.2} µs per far field, checksum {sum:.9e}",
        if full { "full" } else { "unscattered" },
        dt * 1e6
    );
}
