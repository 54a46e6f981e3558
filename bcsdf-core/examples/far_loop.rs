//! A tight loop over the far field, for profilers (`perf record`, `valgrind --tool=callgrind`)
//! and for a checksum that shows whether a change moved the numbers.
//!
//! `cargo run --release -p bcsdf-core --example far_loop -- PRESET [unscattered|full] [N]`
//! evaluates N far-field queries (default 20 000) from the same 256-query list as
//! `benches/eval.rs` and prints the time per query and the sum of all lobes.

use bcsdf_core::medulla::{generate, MedullaProfiles, PhotonBudget, ProfileLayout, Resolution};
use bcsdf_core::{presets, Angles, FurBcsdf, FurParams};
use std::time::Instant;

fn queries() -> Vec<Angles> {
    // The LCG of benches/eval.rs, so that both see the same directions.
    let mut state = 0x2545_f491_4f6c_dd1du64;
    let mut next = move || {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((state >> 40) as f32) / (1u64 << 24) as f32
    };
    (0..256)
        .map(|_| {
            let a = Angles::from_degrees(
                -80.0 + 160.0 * next(),
                -80.0 + 160.0 * next(),
                -180.0 + 360.0 * next(),
            )
            .unwrap();
            let _h = next();
            a
        })
        .collect()
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let name = args.get(1).map_or("yan-row-a", String::as_str);
    let full = args.get(2).is_some_and(|m| m == "full");
    let n: usize = args.get(3).and_then(|s| s.parse().ok()).unwrap_or(20_000);
    let params = FurParams::new(&presets::find(name).expect("unknown preset").input).unwrap();
    let layout = ProfileLayout::for_params(&params, Resolution::DEFAULT);
    let budget = PhotonBudget {
        per_cn_cell: 2_000,
        per_cm_row: 4_000,
    };
    let (mut cn, mut lbar, mut cm) = (
        vec![0.0; layout.cn_len()],
        vec![0.0; layout.cn_len()],
        vec![0.0; layout.cm_len()],
    );
    let model: FurBcsdf = if full {
        generate(&layout, &budget, 1, &mut cn, &mut lbar, &mut cm).unwrap();
        let profiles = MedullaProfiles::new(layout, &cn, &lbar, &cm).unwrap();
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
