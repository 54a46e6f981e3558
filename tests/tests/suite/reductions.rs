//! The reductions of docs/model.md §3.
//!
//! - κ = 0 (no medulla): the medulla paths TrT … TttRttT are exactly zero, near and far, and
//!   R, TT, TRT are Marschner's three lobes. The near field is compared with an independent
//!   f64 evaluation of M_p·A_p(h)·D_p(φ − Φ_p(h))/max(cos²θ_i, 1e-4) with A_p, Φ_p from the
//!   brute-force tracer and M_p, D_p written from docs/model.md §5.
//! - η_m = η_c (index-matched medulla, the 2017 model): the medulla is just more cortex. With
//!   σ_ca = σ_ms = σ_ma = 0 (so that the medulla and the cortex absorb alike), at an offset h
//!   that meets the medulla TttT(h) equals TT(h) of the same fiber with κ = 0 and TttRttT equals
//!   TRT; TrT, TtrtT and TrRrT (which need a reflection f_m = 0 at the medulla) are exactly 0.
//!   In the far field the split halves add up: TT + TttT of the κ > 0 fiber is TT of the κ = 0
//!   fiber, TRT + TttRttT is TRT.

use bcsdf_core::{presets, Angles, FurBcsdf, FurParams, FurParamsInput, Lobe, Pigment, Rgb};
use fur_tests::furnace::{
    gaussian, group_shapes_of, longitudinal_lobe, wrapped_gaussian, Fiber, GROUP_OF_PATH,
};
use fur_tests::tracer::{bravais, trace, SplitMix64, PATHS};

const MEDULLA_PATHS: [Lobe; 5] = [
    Lobe::TrT,
    Lobe::TttT,
    Lobe::TtrtT,
    Lobe::TrRrT,
    Lobe::TttRttT,
];
const MEDULLA_REFLECTION_PATHS: [Lobe; 3] = [Lobe::TrT, Lobe::TtrtT, Lobe::TrRrT];

fn random_input(rng: &mut SplitMix64) -> FurParamsInput {
    let eta_c = rng.range_f32(1.2, 2.0);
    FurParamsInput {
        eta_c,
        pigment: Pigment::Absorption(Rgb([
            rng.range_f32(0.0, 2.0),
            rng.range_f32(0.0, 2.0),
            rng.range_f32(0.0, 2.0),
        ])),
        alpha_deg: rng.range_f32(-8.0, 8.0),
        beta_m_deg: rng.range_f32(2.0, 20.0),
        beta_n_deg: Some(rng.range_f32(2.0, 25.0)),
        l: rng.range_f32(0.1, 4.0),
        kappa: rng.range_f32(0.2, 0.9),
        eta_m: Some(rng.range_f32(1.05, 2.0)),
        sigma_ms: rng.range_f32(0.0, 4.0),
        sigma_ma: rng.range_f32(0.0, 1.0),
        g: rng.range_f32(0.0, 0.9),
        closure: bcsdf_core::Closure::Energy,
    }
}

fn random_angles(rng: &mut SplitMix64) -> Angles {
    Angles::from_degrees(
        rng.range_f32(-85.0, 85.0),
        rng.range_f32(-80.0, 80.0),
        rng.range_f32(-180.0, 180.0),
    )
    .unwrap()
}

/// Independent near-field value of one lobe: M_p·A_p(h)·D_p(φ − Φ_p(h))/max(cos²θ_i, 1e-4).
fn reference_near(p: &FurParams, a: &Angles, h: f64) -> [[f64; 3]; 8] {
    let (ti, tr, phi) = (a.theta_i() as f64, a.theta_r() as f64, a.phi() as f64);
    let fiber = Fiber::of(p);
    let xs = fiber.cross_section(tr);
    let att = fiber.attenuations(tr, h);
    let shapes = group_shapes_of(p);
    let inv_cos2 = 1.0 / ti.cos().powi(2).max(1e-4);
    let mut out = [[0.0; 3]; 8];
    for (path, name) in PATHS.iter().enumerate() {
        let Some(t) = trace(&xs, h, name) else {
            continue;
        };
        let g = shapes[GROUP_OF_PATH[path]];
        let m = longitudinal_lobe(ti, tr, &g, p.closure());
        let d = wrapped_gaussian(phi - t.exit_azimuth, g.beta_n);
        for ch in 0..3 {
            out[path][ch] = m * d * att[path][ch] * inv_cos2;
        }
    }
    out
}

#[test]
fn no_medulla_leaves_marschner_lobes() {
    let mut rng = SplitMix64(0x4a11_0000_0000_0001);
    let mut inputs: Vec<FurParamsInput> = presets::PRESETS.iter().map(|p| p.input).collect();
    inputs.extend((0..40).map(|_| random_input(&mut rng)));
    let mut worst = 0.0f64;
    let mut seen_nonzero = [false; 3];
    let mut significant = 0usize;
    for mut input in inputs {
        input.kappa = 0.0;
        let p = FurParams::new(&input).unwrap();
        let model: FurBcsdf = FurBcsdf::unscattered(p);
        // Angles and offsets, then the lobes' peak values to scale the comparison.
        let cases: Vec<(Angles, f32)> = (0..200)
            .map(|_| (random_angles(&mut rng), rng.range_f32(-0.999, 0.999)))
            .collect();
        let mut rows = Vec::new();
        let shapes = group_shapes_of(&p);
        for (a, h) in &cases {
            let near = model.eval_near(a, *h);
            let far = model.eval_far_lobes(a);
            for lobe in MEDULLA_PATHS {
                assert_eq!(near.get(lobe), Rgb::ZERO, "near {} with κ = 0", lobe.name());
                assert_eq!(far.get(lobe), Rgb::ZERO, "far {} with κ = 0", lobe.name());
            }
            let r = reference_near(&p, a, *h as f64);
            for (seen, lobe) in seen_nonzero.iter_mut().zip(Lobe::ALL) {
                *seen |= far.get(lobe).max_channel() > 0.0;
            }
            // The largest value each lobe could take at these θ's: M_p and D_p at their peaks,
            // A_p ≤ 1, over the clamped cos²θ_i.
            let ti = a.theta_i() as f64;
            let cap = shapes.map(|g| {
                gaussian(0.0, g.beta_m) * gaussian(0.0, g.beta_n) / ti.cos().powi(2).max(1e-4)
            });
            rows.push((near, r, cap));
        }
        for (near, r, cap) in rows {
            for (g, (lobe, cap)) in Lobe::ALL.into_iter().zip(cap).enumerate() {
                for (ch, &want) in r[g].iter().enumerate() {
                    let v = near.get(lobe).0[ch] as f64;
                    // Relative to max(value, 1e-4 · the lobe's largest possible value here): the
                    // core's Gaussians are cut off at 6.2σ (4.5e-9 of their peak) and the f32
                    // exit azimuth's ~1e-7 rad error is a large relative error only far out in
                    // the tails of D_p.
                    let err = (v - want).abs() / want.max(1e-4 * cap);
                    worst = worst.max(err);
                    if want >= 1e-4 * cap {
                        significant += 1;
                    }
                    assert!(
                        err <= 1e-4,
                        "{}: core {v:e} reference {want:e} (err {err:.2e})",
                        lobe.name()
                    );
                }
            }
        }
    }
    assert!(
        seen_nonzero.iter().all(|&s| s),
        "R/TT/TRT far never non-zero"
    );
    eprintln!(
        "κ = 0: worst R/TT/TRT near-field relative error vs independent Marschner: {worst:.3e} ({significant} values compared relatively)"
    );
    assert!(significant > 2000, "only {significant} significant values");
}

/// The same fiber with κ = 0 and with an index-matched medulla of radius κ, no absorption.
fn matched_pair(rng: &mut SplitMix64) -> (FurParams, FurParams) {
    let mut input = random_input(rng);
    input.pigment = Pigment::Absorption(Rgb::ZERO);
    input.sigma_ms = 0.0;
    input.sigma_ma = 0.0;
    input.eta_m = Some(input.eta_c);
    let with = FurParams::new(&input).unwrap();
    input.kappa = 0.0;
    (with, FurParams::new(&input).unwrap())
}

/// Within the last 2% of the medulla's edge |h| = κη'_c the f32 angles m = asin(b/κ) and
/// μ = asin(h/(κη'_m)) — equal in exact arithmetic when η_m = η_c — round differently, and
/// asin's slope 1/cos m turns their ~1e-7 argument difference into ~5e-6 rad, i.e. up to
/// ~3e-5 relative in D_p. There the tolerance is 1e-4; elsewhere 1e-5.
const NEAR_EDGE: f64 = 0.98;

/// At offsets that meet an index-matched medulla (no absorption anywhere): TttT(h) = TT(h) and
/// TttRttT(h) = TRT(h) of the same fiber without medulla, to 1e-5 relative (against
/// max(value, 1% of the lobe's value at the peak of D_p)); R is unchanged bit for bit and TT,
/// TRT vanish. (TrT, TtrtT, TrRrT: `index_matched_medulla_reflections_vanish_near_field`.)
#[test]
fn index_matched_medulla_is_cortex_near_field() {
    let mut rng = SplitMix64(0x1dec_0000_0000_0002);
    let (mut worst, mut worst_edge) = (0.0f64, 0.0f64);
    let mut compared = 0;
    for _ in 0..60 {
        let (with, without) = matched_pair(&mut rng);
        let (m1, m0): (FurBcsdf, FurBcsdf) =
            (FurBcsdf::unscattered(with), FurBcsdf::unscattered(without));
        let shapes = group_shapes_of(&without);
        for _ in 0..100 {
            let a = random_angles(&mut rng);
            // An offset that meets the medulla: |h| < κη'_c (with a margin for f32 rounding).
            let edge = with.kappa() as f64 * bravais(with.eta_c() as f64, a.theta_r() as f64);
            let h = (edge.min(1.0) * (0.999 * (2.0 * rng.unit() - 1.0))) as f32;
            let (s1, s0) = (m1.eval_near(&a, h), m0.eval_near(&a, h));
            assert_eq!(s1.get(Lobe::R), s0.get(Lobe::R), "R depends on the medulla");
            for lobe in [Lobe::TT, Lobe::TRT] {
                assert_eq!(
                    s1.get(lobe),
                    Rgb::ZERO,
                    "{} where the ray meets the medulla",
                    lobe.name()
                );
            }
            for (lobe, twin) in [(Lobe::TttT, Lobe::TT), (Lobe::TttRttT, Lobe::TRT)] {
                let (v1, v0) = (s1.get(lobe).0[0] as f64, s0.get(twin).0[0] as f64);
                // Scale: the twin's value at the peak of D_p.
                let g = shapes[GROUP_OF_PATH[twin.index()]];
                let ti = a.theta_i() as f64;
                let peak = gaussian(a.theta_r() as f64 + ti - g.shift, g.beta_m)
                    * gaussian(0.0, g.beta_n)
                    / ti.cos().powi(2).max(1e-4);
                let err = (v1 - v0).abs() / v0.max(0.01 * peak).max(1e-30);
                let near_edge = (h as f64).abs() > NEAR_EDGE * edge;
                let tol = if near_edge { 1e-4 } else { 1e-5 };
                if near_edge {
                    worst_edge = worst_edge.max(err);
                } else {
                    worst = worst.max(err);
                }
                assert!(
                    err <= tol,
                    "{} = {v1:e} vs {} = {v0:e}, err {err:.2e} at h={h} (edge {edge}) θ_r={}",
                    lobe.name(),
                    twin.name(),
                    a.theta_r()
                );
                compared += 1;
            }
        }
    }
    eprintln!(
        "η_m = η_c near field: {compared} comparisons, worst relative {worst:.3e} (|h| ≤ {NEAR_EDGE}·κη'_c), {worst_edge:.3e} (closer to the edge)"
    );
}

/// docs/model.md §3: with η_m = η_c, f_m = 0, so TrT, TtrtT and TrRrT vanish — exactly, as they do
/// in the far field (and as the 2017 five-lobe model has no such lobes).
#[test]
fn index_matched_medulla_reflections_vanish_near_field() {
    let mut rng = SplitMix64(0x1dec_0000_0000_0004);
    let mut nonzero = Vec::new();
    let mut total = 0;
    for _ in 0..60 {
        let mut input = random_input(&mut rng);
        input.eta_m = Some(input.eta_c);
        let p = FurParams::new(&input).unwrap();
        let model: FurBcsdf = FurBcsdf::unscattered(p);
        for _ in 0..100 {
            let a = random_angles(&mut rng);
            let edge = p.kappa() as f64 * bravais(p.eta_c() as f64, a.theta_r() as f64);
            let h = (edge.min(1.0) * (2.0 * rng.unit() - 1.0)) as f32;
            let s = model.eval_near(&a, h);
            for lobe in MEDULLA_REFLECTION_PATHS {
                total += 1;
                let v = s.get(lobe);
                if v != Rgb::ZERO {
                    nonzero.push(format!(
                        "{} = {:e} (TttT = {:e}) at h={h} θ_i={} θ_r={} φ={} κ={} η={}",
                        lobe.name(),
                        v.max_channel(),
                        s.get(Lobe::TttT).max_channel(),
                        a.theta_i(),
                        a.theta_r(),
                        a.phi(),
                        p.kappa(),
                        p.eta_c()
                    ));
                }
            }
        }
    }
    for m in nonzero.iter().take(5) {
        eprintln!("non-zero medulla reflection: {m}");
    }
    assert!(
        nonzero.is_empty(),
        "{} of {total} near-field TrT/TtrtT/TrRrT values are non-zero with η_m = η_c (f_m must be exactly 0)",
        nonzero.len()
    );
}

#[test]
fn index_matched_medulla_is_cortex_far_field() {
    let mut rng = SplitMix64(0x1dec_0000_0000_0003);
    let mut worst = 0.0f64;
    for _ in 0..12 {
        let (with, without) = matched_pair(&mut rng);
        let (m1, m0): (FurBcsdf, FurBcsdf) =
            (FurBcsdf::unscattered(with), FurBcsdf::unscattered(without));
        let theta_r = rng.range_f32(-80.0, 80.0);
        let theta_i = rng.range_f32(-60.0, 60.0);
        let grid: Vec<Angles> = (0..48)
            .map(|j| Angles::from_degrees(theta_i, theta_r, -180.0 + 7.5 * j as f32 + 1.3).unwrap())
            .collect();
        let v1: Vec<_> = grid.iter().map(|a| m1.eval_far_lobes(a)).collect();
        let v0: Vec<_> = grid.iter().map(|a| m0.eval_far_lobes(a)).collect();
        for (twin, parts) in [
            (Lobe::TT, [Lobe::TT, Lobe::TttT]),
            (Lobe::TRT, [Lobe::TRT, Lobe::TttRttT]),
        ] {
            let peak = v0
                .iter()
                .map(|s| s.get(twin).0[0] as f64)
                .fold(0.0, f64::max);
            for (s1, s0) in v1.iter().zip(&v0) {
                let sum: f64 = parts.iter().map(|&l| s1.get(l).0[0] as f64).sum();
                let want = s0.get(twin).0[0] as f64;
                // Each far-field value is good to 1e-4 relative (docs/model.md §5) against
                // max(value, 1e-3·peak); two of them are added here.
                let err = (sum - want).abs() / want.max(1e-3 * peak).max(1e-30);
                worst = worst.max(err);
                assert!(
                    err <= 2e-4,
                    "{} far: parts {sum:e} vs κ = 0 {want:e} (err {err:.2e})",
                    twin.name()
                );
            }
        }
        for s1 in &v1 {
            for lobe in MEDULLA_REFLECTION_PATHS {
                assert_eq!(
                    s1.get(lobe),
                    Rgb::ZERO,
                    "far {} with η_m = η_c",
                    lobe.name()
                );
            }
        }
    }
    eprintln!("η_m = η_c far field: worst relative error of TT+TttT vs TT, TRT+TttRttT vs TRT: {worst:.3e}");
}
