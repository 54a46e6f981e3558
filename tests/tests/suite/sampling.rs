//! Sampling consistency, the white furnace with importance sampling, and robustness of the
//! `Bcsdf` trait's sample/pdf (docs/model.md §10), for the analytic model and the baked
//! tables.
//!
//! - Consistency: the pdf in a `Sample` equals `pdf()` of the same direction (1e-5
//!   relative), the weight equals eval·cos θ_i/pdf (1e-5), the vector form agrees with the
//!   angle form, and pdf > 0 wherever eval > 0.
//! - Furnace: lossless fibers (σ_ca = 0, κ = 0): the importance-sampled ρ(ω_r) from 10⁴
//!   samples is within 1 % of the far field's ρ integrated by quadrature, with a standard
//!   deviation at least 10× below uniform-sphere sampling's for the glossiest preset.
//! - Robustness (proptest): any θ_r, any u including the ends, any vectors: no NaN, no
//!   negative pdf or weight, no panic.

use bake::profiles::{build_model, scale_budget, OwnedModel, ProfileOptions};
use bake::tables;
use bcsdf_core::baked::BakedBcsdf;
use bcsdf_core::lut::LutResolution;
use bcsdf_core::medulla::PhotonBudget;
use bcsdf_core::rng::{cell_stream, Pcg32};
use bcsdf_core::{
    presets, Absorption, Angles, Bcsdf, Frame, FurParams, FurParamsInput, Pigment, Rgb,
};
use fur_tests::furnace::furnace;
use proptest::prelude::*;
use std::f32::consts::{FRAC_PI_2, PI};
use std::path::PathBuf;
use std::sync::OnceLock;

const PRESETS: [&str; 5] = ["bobcat", "red-fox", "raccoon", "human-hair", "air-medulla"];

fn model_for(input: &FurParamsInput) -> OwnedModel {
    let params = FurParams::new(input).unwrap();
    let opts = ProfileOptions {
        budget: scale_budget(PhotonBudget::DEFAULT, 0.02).unwrap(),
        cache_dir: Some(PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("fur-profile-cache")),
        ..ProfileOptions::default()
    };
    build_model(params, &opts).unwrap().0
}

fn input(name: &str) -> FurParamsInput {
    presets::find(name).unwrap().input
}

/// The analytic model and the LUT baked from it, per preset, built once.
struct Pair {
    model: OwnedModel,
    blob: Vec<u8>,
}

fn pairs() -> &'static [Pair] {
    static PAIRS: OnceLock<Vec<Pair>> = OnceLock::new();
    PAIRS.get_or_init(|| {
        PRESETS
            .iter()
            .map(|n| {
                let model = model_for(&input(n));
                let blob = tables::bake(&model, &input(n), LutResolution::DEFAULT);
                Pair { model, blob }
            })
            .collect()
    })
}

fn uniforms(seed: u64, i: u64) -> [f32; 3] {
    let mut rng = Pcg32::new(cell_stream(seed, 1, i), cell_stream(seed, 2, i));
    [rng.uniform(), rng.uniform(), rng.uniform()]
}

fn rel(a: f32, b: f32) -> f32 {
    (a - b).abs() / a.abs().max(b.abs()).max(f32::MIN_POSITIVE)
}

/// Sample.pdf = pdf(), weight = eval·cos θ_i/pdf, and the vector form agrees.
fn check_consistency<B: Bcsdf>(name: &str, m: &B, draws: u64) {
    let mut n = 0;
    for (k, tr_deg) in [-80.0f32, -45.0, -10.0, 0.0, 25.0, 60.0, 89.0]
        .iter()
        .enumerate()
    {
        let tr = tr_deg.to_radians();
        for i in 0..draws {
            let u = uniforms(k as u64, i);
            let Some(s) = m.sample(tr, u) else {
                panic!("{name}: sample failed at theta_r {tr_deg} u {u:?}")
            };
            n += 1;
            let pdf = m.pdf(&s.angles);
            assert!(
                rel(s.pdf, pdf) <= 1e-5,
                "{name}: pdf {} vs pdf() {pdf}",
                s.pdf
            );
            let f = m.eval(&s.angles).total();
            let cos = s.angles.theta_i().cos();
            for c in 0..3 {
                let expect = f.0[c] * cos / pdf;
                assert!(
                    rel(s.weight.0[c], expect) <= 1e-5 || (s.weight.0[c] - expect).abs() < 1e-12,
                    "{name}: weight {:?} vs eval·cos/pdf {expect} at {:?}",
                    s.weight,
                    s.angles
                );
            }
            // The angle form has no vector; the fiber frame turns the angles into a unit vector
            // with the same angles.
            assert!(s.wi.is_none());
            let wi = Frame::canonical().to_world(&s.angles);
            let len = wi.iter().map(|c| c * c).sum::<f32>().sqrt();
            assert!((len - 1.0).abs() < 1e-5, "{name}: |wi| = {len}");
            let back = Angles::from_directions::<bcsdf_core::Libm>(
                wi,
                [tr.cos(), 0.0, tr.sin()],
                [0.0, 0.0, 1.0],
            )
            .unwrap();
            // asin loses precision toward the poles: about one ulp of sin θ_i over cos θ_i.
            let tol = 1e-5 + 2e-7 / cos.max(1e-6);
            assert!(
                (back.theta_i() - s.angles.theta_i()).abs() < tol,
                "{name}: {back:?} {:?}",
                s.angles
            );
            if s.angles.theta_i().abs() < 1.5 {
                let dphi = (back.phi() - s.angles.phi() + PI).rem_euclid(2.0 * PI) - PI;
                assert!(dphi.abs() < 1e-4, "{name}: {back:?} {:?}", s.angles);
            }
        }
    }
    assert!(n > 0);
}

/// The vector form: a world frame, sample_dirs, then eval_dirs/pdf_dirs of the result.
fn check_vectors<B: Bcsdf>(name: &str, m: &B) {
    let tangent = [0.3f32, -0.5, 0.81];
    for i in 0..200u64 {
        let u = uniforms(99, i);
        let wr = [u[0] - 0.5, u[1] - 0.5, u[2] - 0.5];
        let Some(s) = m.sample_dirs(wr, tangent, uniforms(7, i)) else {
            continue;
        };
        let wi = s.wi.expect("the vector form returns a vector");
        let len = wi.iter().map(|c| c * c).sum::<f32>().sqrt();
        assert!((len - 1.0).abs() < 1e-5, "{name}: |wi| = {len}");
        let a = Angles::from_directions::<bcsdf_core::Libm>(wi, wr, tangent).unwrap();
        assert!(
            (a.theta_i() - s.angles.theta_i()).abs() < 1e-4,
            "{name}: {a:?} {:?}",
            s.angles
        );
        assert!(
            (a.theta_r() - s.angles.theta_r()).abs() < 1e-4,
            "{name}: {a:?} {:?}",
            s.angles
        );
        if s.angles.theta_i().abs() < 1.5 && s.angles.theta_r().abs() < 1.5 {
            let dphi = (a.phi() - s.angles.phi() + PI).rem_euclid(2.0 * PI) - PI;
            assert!(dphi.abs() < 1e-3, "{name}: {a:?} {:?}", s.angles);
        }
        let p = m.pdf_dirs(wi, wr, tangent);
        assert!(rel(p, s.pdf) < 2e-2, "{name}: pdf_dirs {p} vs {}", s.pdf);
    }
    // Degenerate input gives None or zero, never a panic or NaN.
    assert!(m.sample_dirs([0.0; 3], tangent, [0.5; 3]).is_none());
    assert!(m.sample_dirs([1.0, 0.0, 0.0], [0.0; 3], [0.5; 3]).is_none());
    assert!(m
        .sample_dirs([f32::NAN, 0.0, 1.0], tangent, [0.5; 3])
        .is_none());
    assert_eq!(m.pdf_dirs([0.0; 3], [1.0, 0.0, 0.0], tangent), 0.0);
    // ω_r along the fiber still samples.
    if let Some(s) = m.sample_dirs(tangent, tangent, [0.3, 0.6, 0.2]) {
        assert!(s.pdf > 0.0 && s.weight.is_finite());
    }
}

/// pdf > 0 wherever eval > 0, on a grid.
fn check_support<B: Bcsdf>(name: &str, m: &B, steps: usize) {
    for a in 0..=steps {
        let ti = -FRAC_PI_2 + PI * a as f32 / steps as f32;
        for b in 0..=steps / 2 {
            let tr = -FRAC_PI_2 + PI * b as f32 / (steps / 2) as f32;
            for c in 0..2 * steps {
                let phi = -PI + PI * c as f32 / steps as f32;
                let angles = Angles::new(ti, tr, phi).unwrap();
                let (f, p) = m.eval_with_pdf(&angles);
                assert!(p >= 0.0 && p.is_finite());
                assert_eq!(p, m.pdf(&angles), "{name}: eval_with_pdf and pdf differ");
                if f.total().max_channel() > 0.0 {
                    assert!(
                        p > 0.0,
                        "{name}: eval {:?} > 0 but pdf 0 at {angles:?}",
                        f.total()
                    );
                }
            }
        }
    }
}

#[test]
fn sample_pdf_and_weight_agree_with_pdf_and_eval() {
    for (name, pair) in PRESETS.iter().zip(pairs()) {
        let lut = BakedBcsdf::from_bytes(&pair.blob).unwrap();
        check_consistency(name, &lut, 400);
        check_vectors(name, &lut);
        check_consistency(name, &pair.model.model(), 40);
        check_vectors(name, &pair.model.model());
    }
}

/// [`FurBcsdf::view`](bcsdf_core::FurBcsdf::view) (the analytic sampler's per-view set-up
/// done once) gives the bits of the [`Bcsdf`] methods, which build a view per call: the same
/// draws, densities and values, at views from pole to pole.
#[test]
fn analytic_views_give_the_trait_bits() {
    for (name, pair) in PRESETS.iter().zip(pairs()) {
        let model = pair.model.model();
        for tr in [-1.5f32, -0.6, 0.0, 0.3, 1.2, FRAC_PI_2] {
            let view = model.view(tr).unwrap();
            assert_eq!(view.theta_r(), tr);
            for i in 0..64 {
                let u = uniforms(0xa11, i);
                let d = view.sample_direction(u);
                assert_eq!(d, model.sample_direction(tr, u), "{name} θ_r {tr}");
                let Some(d) = d else { continue };
                let a = d.angles;
                let (ti, phi) = (a.theta_i(), a.phi());
                assert_eq!(
                    view.pdf(ti, phi).to_bits(),
                    model.pdf(&a).to_bits(),
                    "{name}"
                );
                let (v, p) = view.eval_with_pdf(ti, -phi);
                let (w, q) = model.eval_with_pdf(&Angles::new(ti, tr, -phi).unwrap());
                assert_eq!((v, p.to_bits()), (w, q.to_bits()), "{name}");
            }
        }
        assert!(model.view(f32::NAN).is_none() && model.view(1.6).is_none());
    }
}

/// Sampling at colours the sampling data was not built for (docs/model.md §10, "Sampling at
/// any colour"): the density is the lossless plane's whatever the colour, so `sample`, `pdf`
/// and `eval` stay consistent (the same checks as at the preset's colour), pdf > 0 wherever
/// eval > 0, and each weight is at most the lossless LUT's weight for the same uniforms
/// (S at σ_ca ≥ 0 is at most S at σ_ca = 0, direction by direction, up to the interpolation's
/// error; measured ratio 1.00000, bound 1.001). Prints the spread of the weights.
#[test]
fn sampling_at_colours_the_data_was_not_built_for() {
    let colours = bake::metrics::random_colours(8);
    for (name, pair) in PRESETS.iter().zip(pairs()) {
        let lut = BakedBcsdf::from_bytes(&pair.blob).unwrap();
        let lossless = lut.at(&Absorption::LOSSLESS);
        let mut worst_ratio = 0.0f32;
        let mut spread = (f32::MAX, 0.0f32);
        for (label, colour) in &colours {
            let at = lut.at(colour);
            check_consistency(&format!("{name} at {label}"), &at, 40);
            check_support(&format!("{name} at {label}"), &at, 12);
            for (k, tr_deg) in [-70.0f32, -20.0, 0.0, 35.0, 80.0].iter().enumerate() {
                let tr = tr_deg.to_radians();
                for i in 0..400u64 {
                    let u = uniforms(500 + k as u64, i);
                    let (Some(s), Some(l)) = (at.sample(tr, u), lossless.sample(tr, u)) else {
                        continue;
                    };
                    assert_eq!(s.angles, l.angles, "{name}: the colour moved the sample");
                    for c in 0..3 {
                        let (w, wl) = (s.weight.0[c], l.weight.0[c]);
                        spread = (spread.0.min(w), spread.1.max(w));
                        if wl > 0.0 {
                            worst_ratio = worst_ratio.max(w / wl);
                        }
                    }
                }
            }
        }
        println!(
            "{name}: weights at 8 random colours in [{:.4}, {:.4}]; largest weight / lossless weight {:.5}",
            spread.0, spread.1, worst_ratio
        );
        assert!(worst_ratio <= 1.001, "{name}: weight ratio {worst_ratio}");
    }
}

#[test]
fn pdf_is_positive_wherever_eval_is() {
    for (name, pair) in PRESETS.iter().zip(pairs()) {
        let lut = BakedBcsdf::from_bytes(&pair.blob).unwrap();
        check_support(name, &lut, 48);
        check_support(name, &pair.model.model(), 16);
    }
}

/// Mean and standard deviation (per sample) of the luminance-free channel mean.
fn mean_std(v: &[f64]) -> (f64, f64) {
    let n = v.len() as f64;
    let mean = v.iter().sum::<f64>() / n;
    let var = v.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1.0);
    (mean, var.sqrt())
}

/// Importance-sampled and uniform-sphere estimates of ρ(θ_r) (channel means per sample).
fn estimates<B: Bcsdf>(m: &B, theta_r: f32, n: u64) -> (Vec<f64>, Vec<f64>) {
    let mut is = Vec::new();
    let mut uniform = Vec::new();
    for i in 0..n {
        let u = uniforms(1234, i);
        let w = m.sample(theta_r, u).map(|s| s.weight).unwrap_or(Rgb::ZERO);
        is.push(w.0.iter().map(|&c| f64::from(c)).sum::<f64>() / 3.0);
        // Uniform on the sphere: sin θ_i uniform in [−1, 1], φ uniform; pdf 1/(4π).
        let ti = (2.0 * u[1] - 1.0).clamp(-1.0, 1.0).asin();
        let phi = -PI + 2.0 * PI * u[2];
        let a = Angles::new(ti, theta_r, phi).unwrap();
        let f = m.eval(&a).total();
        let est = f64::from(f.0.iter().sum::<f32>() / 3.0)
            * f64::from(ti.cos())
            * 4.0
            * std::f64::consts::PI;
        uniform.push(est);
    }
    (is, uniform)
}

#[test]
fn furnace_with_importance_sampling() {
    for name in PRESETS {
        let mut p = input(name);
        p.pigment = Pigment::Absorption(Rgb::ZERO);
        p.kappa = 0.0;
        let owned = model_for(&p);
        let model = owned.model();
        let blob = tables::bake(&owned, &p, fur_tests::LOSSLESS_RESOLUTION);
        let lut = BakedBcsdf::from_bytes(&blob).unwrap();
        for tr_deg in [-50.0f32, 0.0, 35.0] {
            let tr = tr_deg.to_radians();
            let rho = furnace(&model, tr, 720);
            let rho = rho.iter().sum::<f64>() / 3.0;
            for (kind, (is, uni)) in [
                ("analytic", estimates(&model, tr, 10_000)),
                ("baked", estimates(&lut, tr, 10_000)),
            ] {
                let (m_is, s_is) = mean_std(&is);
                let (m_u, s_u) = mean_std(&uni);
                println!(
                    "{name} {kind} theta_r {tr_deg}: rho {rho:.5}, IS {m_is:.5} (sd {s_is:.4}), uniform {m_u:.5} (sd {s_u:.4}), sd ratio {:.1}",
                    s_u / s_is
                );
                assert!(
                    (m_is - rho).abs() <= 0.01 * rho,
                    "{name} {kind} theta_r {tr_deg}: IS {m_is} vs rho {rho}"
                );
                // Every preset, the glossiest (raccoon, β_n = 6.88°) included.
                assert!(s_u >= 10.0 * s_is, "{name} {kind}: sd ratio {}", s_u / s_is);
            }
        }
    }
}

fn special_u() -> impl Strategy<Value = f32> {
    prop_oneof![
        Just(0.0f32),
        Just(1.0 - f32::EPSILON / 2.0),
        Just(1.0f32),
        Just(0.5f32),
        0.0f32..1.0,
    ]
}

fn any_theta() -> impl Strategy<Value = f32> {
    prop_oneof![
        Just(FRAC_PI_2),
        Just(-FRAC_PI_2),
        Just(0.0f32),
        -FRAC_PI_2..=FRAC_PI_2,
        Just(f32::NAN),
        Just(2.0f32),
    ]
}

fn check_robust<B: Bcsdf>(
    m: &B,
    tr: f32,
    u: [f32; 3],
    wr: [f32; 3],
    t: [f32; 3],
) -> Result<(), TestCaseError> {
    let valid = tr.is_finite() && tr.abs() <= FRAC_PI_2;
    match m.sample(tr, u) {
        Some(s) => {
            prop_assert!(valid, "sampled at an invalid theta_r {tr}");
            prop_assert!(s.pdf > 0.0 && s.pdf.is_finite(), "{s:?}");
            prop_assert!(
                s.weight.0.iter().all(|c| c.is_finite() && *c >= 0.0),
                "{s:?}"
            );
            prop_assert!(s.wi.is_none());
        }
        // None means an invalid θ_r or zero albedo (S = 0 everywhere, e.g. at exactly
        // θ_r = ±90°): wherever S > 0 somewhere, every u (u = 1 included) must sample.
        None => {
            let lit = valid
                && (0..=16).any(|a| {
                    (0..32).any(|b| {
                        let ti = -FRAC_PI_2 + PI * a as f32 / 16.0;
                        let phi = -PI + PI * b as f32 / 16.0;
                        let a = Angles::new(ti, tr, phi).unwrap();
                        m.eval(&a).total().max_channel() > 0.0
                    })
                });
            prop_assert!(!lit, "no sample at theta_r {tr} with u {u:?}, yet S > 0");
        }
    }
    if let Some(s) = m.sample_dirs(wr, t, u) {
        prop_assert!(s.pdf > 0.0 && s.pdf.is_finite(), "{s:?}");
        prop_assert!(
            s.weight.0.iter().all(|c| c.is_finite() && *c >= 0.0),
            "{s:?}"
        );
        prop_assert!(s.wi.is_some_and(|w| w.iter().all(|c| c.is_finite())));
    }
    let p = m.pdf_dirs(wr, t, wr);
    prop_assert!(p.is_finite() && p >= 0.0);
    if let Ok(a) = Angles::new(u[0] * PI - FRAC_PI_2, tr, u[1] * 7.0 - 3.5) {
        let (f, p) = m.eval_with_pdf(&a);
        prop_assert!(p.is_finite() && p >= 0.0);
        prop_assert!(f.total().0.iter().all(|c| c.is_finite() && *c >= 0.0));
    }
    Ok(())
}

fn any_vec() -> impl Strategy<Value = [f32; 3]> {
    prop_oneof![
        Just([0.0f32; 3]),
        Just([f32::NAN, 0.0, 1.0]),
        Just([0.0, 0.0, 1.0]),
        Just([f32::MAX, 1.0, 0.0]),
        prop::array::uniform3(-1.0f32..1.0),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 300,
        failure_persistence: None,
        ..ProptestConfig::default()
    })]

    #[test]
    fn sampling_never_returns_nan_or_negative(
        which in 0usize..5,
        tr in any_theta(),
        u0 in special_u(), u1 in special_u(), u2 in special_u(),
        wr in any_vec(), t in any_vec(),
    ) {
        let pair = &pairs()[which];
        let lut = BakedBcsdf::from_bytes(&pair.blob).unwrap();
        check_robust(&lut, tr, [u0, u1, u2], wr, t)?;
        check_robust(&pair.model.model(), tr, [u0, u1, u2], wr, t)?;
    }
}
