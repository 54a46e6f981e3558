//! The fur fragment's coat transmittance for the sky and floor light (`ras_coat_transmittance`
//! in raster.wgsl, docs/model.md §13 "Deep opacity map", *Indirect light*) on a real Vulkan
//! device, against the integral it stands for computed here independently: the mean over the
//! cosine c ∈ (0, 1] of μ^min(N/c, N_t), by a 20 000-point midpoint rule in f64. Within 5e-3
//! (its 8-point Gauss–Legendre rule on the integrand's kink at c = N/N_t measured at most
//! 3.9e-3 over these cases), and the same check catches the shader without the cap N_t or without the slant 1/c.
//!
//! Without an adapter the test prints "skipped: no GPU adapter" and passes, unless
//! `FUR_BCSDF_REQUIRE_GPU=1` (set by `.ci/run`).

mod common;

/// The integral, in f64: ∫₀¹ 2^(log2_mu·min(above/c, across)) dc (midpoint rule).
fn transmittance(log2_mu: f32, above: f32, across: f32) -> f64 {
    const STEPS: usize = 20_000;
    let (l, a, b) = (
        f64::from(log2_mu),
        f64::from(above),
        f64::from(across).max(0.0),
    );
    (0..STEPS)
        .map(|i| {
            let c = (i as f64 + 0.5) / STEPS as f64;
            (l * (a / c).min(b)).exp2()
        })
        .sum::<f64>()
        / STEPS as f64
}

/// (above, across) pairs: no coat, thin and deep coats, caps below, at and above the flat
/// coat's counts, and a negative cap (read as 0).
fn pairs() -> Vec<[f32; 2]> {
    let above = [0.0f32, 0.05, 0.3, 0.75, 1.0, 2.0, 4.0];
    let across = [-1.0f32, 0.0, 0.5, 1.0, 2.5, 6.0, 40.0, 1.0e6];
    above
        .iter()
        .flat_map(|&a| across.iter().map(move |&b| [a, b]))
        .collect()
}

/// The worst absolute difference of `wgsl`'s `ras_coat_transmittance` from the integral, over
/// every pair and three decays (nearly lossless, a light and a dark coat), or `None` without an
/// adapter.
fn worst(wgsl: &str) -> Option<f64> {
    let pairs = pairs();
    let mut worst = 0.0f64;
    for log2_mu in [-0.02f32, -0.4, -2.5] {
        let call = format!(
            "ras_coat_transmittance(vec3<f32>({log2_mu:?}, {log2_mu:?}, {log2_mu:?}), q.x, q.y).y"
        );
        let gpu = common::gpu_call(wgsl, &call, &pairs)?;
        for (p, g) in pairs.iter().zip(gpu) {
            let e = (f64::from(g) - transmittance(log2_mu, p[0], p[1])).abs();
            assert!(g.is_finite(), "{p:?} at log2 mu {log2_mu}: {g}");
            worst = worst.max(e);
        }
    }
    Some(worst)
}

#[test]
fn the_coat_passes_the_mean_of_the_downward_flux_over_the_half_sphere() {
    let wgsl = raster::shader_source();
    let Some(e) = worst(&wgsl) else {
        return;
    };
    println!("ras_coat_transmittance: worst absolute difference {e:.2e}");
    assert!(e <= 5e-3, "shader against the integral: {e}");
    for (name, from, to) in [
        (
            "without the cap",
            "let k = min(above / RAS_GL_X[i], max(across, 0.0));",
            "let k = above / RAS_GL_X[i];",
        ),
        (
            "without the slant",
            "let k = min(above / RAS_GL_X[i], max(across, 0.0));",
            "let k = min(above, max(across, 0.0));",
        ),
    ] {
        let wrong = wgsl.replace(from, to);
        assert_ne!(wrong, wgsl, "the mutation {name} applies");
        let e = worst(&wrong).unwrap();
        assert!(e > 2e-2, "the check missed the shader {name} ({e})");
    }
}
