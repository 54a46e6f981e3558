//! Tight loop over the baked evaluator (for profiling: `perf stat`, callgrind).
use bake::profiles::{build_model, scale_budget, ProfileOptions};
use bcsdf_core::baked::BakedBcsdf;
use bcsdf_core::bench_support::{QueryStream, QUERY_COUNT};
use bcsdf_core::lut::LutResolution;
use bcsdf_core::medulla::PhotonBudget;
use bcsdf_core::{presets, Absorption, Angles, FurParams, Rgb};
use std::hint::black_box;
use std::time::Instant;

fn main() {
    let preset = presets::find("bobcat").unwrap();
    let opts = ProfileOptions {
        budget: scale_budget(PhotonBudget::DEFAULT, 0.01).unwrap(),
        ..ProfileOptions::default()
    };
    // BAKED_LOOP_LUT=path: the LUT from that file, baked and written there if it is missing
    // (so that callgrind does not simulate the bake on every run).
    let cached = std::env::var_os("BAKED_LOOP_LUT");
    let blob = match cached.as_ref().map(std::fs::read) {
        Some(Ok(blob)) => blob,
        _ => {
            let (model, _) = build_model(FurParams::new(&preset.input).unwrap(), &opts).unwrap();
            let blob = bake::tables::bake(&model, &preset.input, LutResolution::DEFAULT);
            if let Some(path) = &cached {
                std::fs::write(path, &blob).unwrap();
            }
            blob
        }
    };
    let lut = BakedBcsdf::from_bytes(&blob).unwrap();
    let mut stream = QueryStream::new();
    let qs: Vec<Angles> = (0..QUERY_COUNT).map(|_| stream.angles()).collect();
    // Arguments: evaluations (default 20M), index mask into the 256 queries (default 255),
    // batch size (default 0: the scalar `eval_far`; `dirs`: the scalar `eval_far_dirs` on the
    // same queries as vectors; otherwise `eval_far_batch` over consecutive batches of that
    // size cycling through the 256 queries; the mask is ignored). A fourth argument `colour`
    // evaluates each query at its own random colour (`at(..).eval_far`, or
    // `eval_far_batch_colours`; each channel log-uniform over [0.01, 1000], as the benches).
    let arg = |k: usize| std::env::args().nth(k);
    let n: usize = arg(1).map_or(20_000_000, |s| s.parse().unwrap());
    let mask: usize = arg(2).map_or(255, |s| s.parse::<usize>().unwrap() & 255);
    let mode = arg(3).unwrap_or_default();
    let batch: usize = if mode == "dirs" {
        0
    } else {
        mode.parse().unwrap_or(0)
    };
    let colours: Vec<Absorption> = (0..256)
        .map(|k| {
            let u = |j: u32| ((k * 3 + j) as f32 * 0.618_034).fract();
            Absorption::from_sigma(Rgb([0, 1, 2].map(|j| 10f32.powf(-2.0 + 5.0 * u(j))))).unwrap()
        })
        .collect();
    // `own`: every colour the LUT's own (the colour path, the same planes for every
    // query); `grey`: the random colours' red channel in all three (one plane triple per
    // query, different across queries).
    let colours: Vec<Absorption> = match arg(5).as_deref() {
        Some("own") => vec![lut.absorption(); 256],
        Some("grey") => colours
            .iter()
            .map(|c| Absorption::from_sigma(Rgb([c.sigma().0[0]; 3])).unwrap())
            .collect(),
        _ => colours,
    };
    let colour = arg(4).as_deref() == Some("colour");
    // `located`: the same colours located once beforehand (`at_located`), `locate`: only
    // the locating.
    let located: Vec<_> = colours
        .iter()
        .map(|c| lut.locate_colour(c.sigma()))
        .collect();
    let pre = arg(4).as_deref() == Some("located");
    let only_locate = arg(4).as_deref() == Some("locate");
    let t = Instant::now();
    let mut acc = 0.0f32;
    if mode == "dirs" {
        // Tangent along z, ω_r in the x-z plane; φ = φ_r − φ_i, so ω_i's azimuth is −φ.
        let dirs: Vec<[[f32; 3]; 3]> = qs
            .iter()
            .map(|a| {
                let (ti, tr, phi) = (a.theta_i(), a.theta_r(), a.phi());
                [
                    [ti.cos() * (-phi).cos(), ti.cos() * (-phi).sin(), ti.sin()],
                    [tr.cos(), 0.0, tr.sin()],
                    [0.0, 0.0, 1.0],
                ]
            })
            .collect();
        for i in 0..n {
            let [wi, wr, u] = *black_box(&dirs[i & mask]);
            acc += black_box(black_box(&lut).eval_far_dirs(wi, wr, u).total()).0[0];
        }
    } else if batch == 0 && pre {
        for i in 0..n {
            let k = i & mask;
            let at = black_box(&lut).at_located(*black_box(&located[k]));
            acc += black_box(at.eval_far(black_box(&qs[k])).total()).0[0];
        }
    } else if batch == 0 && only_locate {
        for i in 0..n {
            let c = black_box(&lut).locate_colour(black_box(&colours[i & mask]).sigma());
            black_box(c);
            acc += 1.0;
        }
    } else if batch == 0 && colour {
        for i in 0..n {
            let k = i & mask;
            let at = black_box(&lut).at(black_box(&colours[k]));
            acc += black_box(at.eval_far(black_box(&qs[k])).total()).0[0];
        }
    } else if batch == 0 {
        for i in 0..n {
            // black_box on the whole RGB result: all three channels are computed.
            acc += black_box(black_box(&lut).eval_far(black_box(&qs[i & mask])).total()).0[0];
        }
    } else {
        // The 256 queries as structure-of-arrays, twice over so a batch can start anywhere.
        let soa = |f: fn(&Angles) -> f32| -> Vec<f32> { qs.iter().chain(&qs).map(f).collect() };
        let (ti, tr, phi) = (soa(Angles::theta_i), soa(Angles::theta_r), soa(Angles::phi));
        let batch = batch.min(256);
        let mut out = vec![bcsdf_core::Rgb::ZERO; batch];
        let mut start = 0;
        for _ in 0..n / batch {
            let r = start..start + batch;
            if colour {
                let c = &colours[..batch];
                black_box(&lut)
                    .eval_far_batch_colours(&ti[r.clone()], &tr[r.clone()], &phi[r], c, &mut out)
                    .unwrap();
            } else {
                black_box(&lut)
                    .eval_far_batch(&ti[r.clone()], &tr[r.clone()], &phi[r], black_box(&mut out))
                    .unwrap();
            }
            acc += black_box(&out)[0].0[0];
            start = (start + batch) & 255;
        }
    }
    let dt = t.elapsed().as_secs_f64();
    println!("{:.2} ns/eval (acc {acc})", dt / n as f64 * 1e9);
}
