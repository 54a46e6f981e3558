//! Profile generation: wall time per preset with 1 and 2 threads at the default resolution
//! and photon budget, and the noise of the result measured with two seeds.
//!
//! Each generation takes seconds, so this is a plain timing harness (one run per
//! configuration) rather than criterion's repeated sampling. Run with
//! `cargo bench -p bake --bench profiles`.
//!
//! Noise: for each table, RMS(table_seed1 − table_seed2) / RMS(table) / √2, the RMS noise of
//! one table relative to its RMS value (the difference of two independent seeds has √2 times
//! the noise of one).

use bake::profiles::generate_parallel;
use bcsdf_core::medulla::{PhotonBudget, ProfileLayout, Resolution};
use bcsdf_core::{presets, FurParams};
use std::time::Instant;

fn rms(v: impl Iterator<Item = f64>) -> f64 {
    let (mut s, mut n) = (0.0, 0usize);
    for x in v {
        s += x * x;
        n += 1;
    }
    (s / n.max(1) as f64).sqrt()
}

fn noise(a: &[f32], b: &[f32]) -> f64 {
    let diff = rms(a.iter().zip(b).map(|(x, y)| (*x - *y) as f64));
    let level = rms(a.iter().map(|x| *x as f64));
    diff / level / std::f64::consts::SQRT_2
}

fn main() {
    // `cargo bench` passes `--bench`; a filter argument selects presets by name.
    let filter: Vec<String> = std::env::args()
        .skip(1)
        .filter(|a| !a.starts_with("--"))
        .collect();
    let budget = PhotonBudget::DEFAULT;
    println!(
        "budget: {} photons per C^N cell, {} per C^M row; resolution {:?}",
        budget.per_cn_cell,
        budget.per_cm_row,
        Resolution::DEFAULT
    );
    println!("preset        1 thread   2 threads   noise C^N   noise C^M");
    for preset in presets::PRESETS.iter() {
        if !filter.is_empty() && !filter.iter().any(|f| preset.name.contains(f.as_str())) {
            continue;
        }
        let params = FurParams::new(&preset.input).expect("valid preset");
        if params.sigma_ms() == 0.0 || params.kappa() == 0.0 {
            println!("{:<13} (no medulla scattering: no profiles)", preset.name);
            continue;
        }
        let layout = ProfileLayout::for_params(&params, Resolution::DEFAULT);
        let mut times = [0.0f64; 2];
        let mut first = None;
        for (slot, threads) in [1usize, 2].into_iter().enumerate() {
            let t = Instant::now();
            let p = generate_parallel(&layout, &budget, 1, Some(threads)).expect("generate");
            times[slot] = t.elapsed().as_secs_f64();
            first = Some(p);
        }
        let a = first.expect("generated");
        let b = generate_parallel(&layout, &budget, 2, None).expect("generate");
        let ((cn_a, cm_a), (cn_b, cm_b)) = (a.tables(), b.tables());
        println!(
            "{:<13} {:>7.2} s  {:>8.2} s   {:>8.2} %  {:>9.2} %",
            preset.name,
            times[0],
            times[1],
            100.0 * noise(cn_a, cn_b),
            100.0 * noise(cm_a, cm_b)
        );
    }
}
