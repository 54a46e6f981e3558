//! The far field's fast quadrature against a much finer brute-force integral of the near field
//! (docs/model.md §5: accurate to 1e-4 relative).
//!
//! Metric, per lobe and RGB channel: |fast − reference| / max(|reference|, 1e-3 · peak), with
//! peak the largest total N(φ) at that θ_r (docs/model.md). The reference integrates
//! `azimuthal_near` over h in f64, split at ±κη'_c and ±κη'_m (computed here from docs/model.md),
//! with a smoothstep substitution against the square-root ends and 400 panels of 6-point
//! Gauss–Legendre per piece (~50× the fast rule's nodes); its own convergence is checked too.

use bcsdf_core::medulla::{generate, MedullaProfiles, PhotonBudget, ProfileLayout, Resolution};
use bcsdf_core::{
    presets, FurBcsdf, FurParams, FurParamsInput, Lobe, Pigment, Rgb, LOBE_COUNT, UNSCATTERED_COUNT,
};
use fur_tests::quadrature::integrate_smoothstep_into;

const TOLERANCE: f64 = 1e-4;

/// Budget for the scattered far field (docs/model.md gives none). Its rule is built for tabulated,
/// linearly interpolated profiles; measured ≤ 1.2e-3 with 100k-photon tables (noisier tables
/// have sharper kinks and a larger error). The tables' own Monte Carlo noise is ~1 % RMS at
/// the default budget (docs/profiles.md), well above this.
const SCATTERED_TOLERANCE: f64 = 5e-3;

/// Bravais index, written here from docs/model.md §3.
fn bravais(eta: f64, theta: f64) -> f64 {
    (eta * eta - theta.sin().powi(2)).sqrt() / theta.cos()
}

/// ½ ∫ N_p(h, φ) dh from the near field, flattened as [lobe][channel].
fn reference(model: &FurBcsdf, theta_r: f32, phi: f32, panels: usize) -> Vec<f64> {
    let p = model.params();
    let kappa = p.kappa() as f64;
    let mut cuts = vec![-1.0, 1.0, 0.0];
    for eta in [p.eta_c(), p.eta_m()] {
        let hk = kappa * bravais(eta as f64, theta_r as f64);
        if hk > 0.0 && hk < 1.0 {
            cuts.push(hk);
            cuts.push(-hk);
        }
    }
    cuts.sort_by(|a, b| a.partial_cmp(b).unwrap());
    cuts.dedup();
    let mut acc = vec![0.0; LOBE_COUNT * 3];
    // The pieces that end at the rim |h| = 1 are integrated in the angle a = asin h
    // (dh = cos a da): it removes the square-root end, and it resolves the layered cuticle's
    // Fresnel knee, which for few layers (l ~ 1e-3) lies within ~1e-7 of |h| = 1 (cos a ~ 1e-3).
    for w in cuts.windows(2) {
        let at_rim = w[0] <= -1.0 || w[1] >= 1.0;
        let (lo, hi) = if at_rim {
            (w[0].asin(), w[1].asin())
        } else {
            (w[0], w[1])
        };
        integrate_smoothstep_into(lo, hi, panels, 6, &mut acc, |x, out| {
            let (h, jac) = if at_rim { (x.sin(), x.cos()) } else { (x, 1.0) };
            let n = model.azimuthal_near(theta_r, phi, h as f32);
            for (l, v) in n.iter().enumerate() {
                for c in 0..3 {
                    out[3 * l + c] = 0.5 * jac * v.0[c] as f64;
                }
            }
        });
    }
    acc
}

fn flatten(n: &[Rgb; LOBE_COUNT]) -> Vec<f64> {
    n.iter()
        .flat_map(|v| v.0.iter().map(|&c| c as f64))
        .collect()
}

fn peak_total(vals: &[Vec<f64>]) -> f64 {
    vals.iter()
        .map(|r| {
            (0..3)
                .map(|c| (0..LOBE_COUNT).map(|l| r[3 * l + c]).sum::<f64>())
                .fold(0.0, f64::max)
        })
        .fold(0.0, f64::max)
}

/// Worst relative error of the fast far field over a φ grid at each θ_r.
fn worst_error(model: &FurBcsdf, thetas_deg: &[f32], n_phi: usize) -> f64 {
    worst_error_with(model, thetas_deg, n_phi, 400)
}

/// [`worst_error`] with a reference of `panels` panels per piece.
fn worst_error_with(model: &FurBcsdf, thetas_deg: &[f32], n_phi: usize, panels: usize) -> f64 {
    let mut worst = 0.0f64;
    for &tr_deg in thetas_deg {
        let tr = tr_deg.to_radians();
        let phis: Vec<f32> = (0..n_phi)
            .map(|i| (-180.0 + 360.0 * (i as f32 + 0.37) / n_phi as f32).to_radians())
            .collect();
        let refs: Vec<Vec<f64>> = phis
            .iter()
            .map(|&p| reference(model, tr, p, panels))
            .collect();
        let peak = peak_total(&refs);
        for (phi, r) in phis.iter().zip(&refs) {
            let fast = flatten(&model.azimuthal_far(tr, *phi));
            for (f, e) in fast.iter().zip(r) {
                let err = (f - e).abs() / e.abs().max(1e-3 * peak);
                if err > worst {
                    worst = err;
                }
            }
        }
    }
    worst
}

fn model(input: &FurParamsInput) -> FurBcsdf<'static> {
    FurBcsdf::unscattered(FurParams::new(input).unwrap())
}

#[test]
fn reference_itself_is_converged() {
    // Doubling the reference's panels changes it by far less than the tolerance.
    for preset in presets::PRESETS.iter() {
        let m = model(&preset.input);
        for (tr, phi) in [(0.3f32, 0.4f32), (-0.9, 2.9), (1.2, -1.7)] {
            let (a, b) = (reference(&m, tr, phi, 400), reference(&m, tr, phi, 800));
            let peak = a.iter().fold(0.0f64, |x, y| x.max(y.abs()));
            for (x, y) in a.iter().zip(&b) {
                assert!(
                    (x - y).abs() <= 1e-6 * peak.max(1e-12),
                    "{}: {x} vs {y}",
                    preset.name
                );
            }
        }
    }
}

#[test]
fn far_field_matches_fine_reference_for_presets() {
    for preset in presets::PRESETS.iter() {
        let worst = worst_error(&model(&preset.input), &[-60.0, -20.0, 0.0, 35.0, 70.0], 24);
        eprintln!("{}: worst relative error {worst:.2e}", preset.name);
        assert!(
            worst <= TOLERANCE,
            "{}: worst relative error {worst:.3e}",
            preset.name
        );
    }
}

#[test]
fn far_field_matches_fine_reference_for_random_parameters() {
    // Deterministic LCG over the whole valid domain that matters for the geometry.
    let mut state = 0x9e37_79b9_7f4a_7c15u64;
    let mut u = move || {
        state = state.wrapping_mul(6364136223846793005).wrapping_add(1);
        (state >> 40) as f32 / (1u64 << 24) as f32
    };
    let mut overall = 0.0f64;
    for _ in 0..96 {
        let input = FurParamsInput {
            eta_c: 1.2 + 0.7 * u(),
            pigment: Pigment::Absorption(Rgb([3.0 * u(), 3.0 * u(), 3.0 * u()])),
            alpha_deg: -8.0 + 16.0 * u(),
            beta_m_deg: 2.0 + 25.0 * u(),
            beta_n_deg: Some(2.0 + 25.0 * u()),
            l: 3.0 * u(),
            kappa: 0.95 * u(),
            eta_m: Some(1.05 + 0.9 * u()),
            sigma_ms: 5.0 * u(),
            sigma_ma: u(),
            g: 0.9 * u(),
            closure: bcsdf_core::Closure::Energy,
        };
        let m = model(&input);
        let tr = -70.0 + 140.0 * u();
        let worst = worst_error(&m, &[tr], 12);
        overall = overall.max(worst);
        assert!(
            worst <= TOLERANCE,
            "{input:?} θr={tr}: worst relative error {worst:.3e}"
        );
    }
    eprintln!("random parameters: worst relative error {overall:.2e}");
}

/// Parameter sets where the fast rule once exceeded the budget, found by drawing 800 sets with
/// the generator of `far_field_matches_fine_reference_for_random_parameters` from the seeds
/// 0x1234_5678_9abc_def1 and 0x0fed_cba9_8765_4321 (400 each; docs/accuracy.md): two with a
/// cuticle of very few layers (l ≈ 2e-3, 5e-3), whose Fresnel knee lies within 1e-3 rad of
/// grazing incidence (4.3e-4 and 1.9e-4 before the rule refined toward it), and one whose
/// medulla reaches h = 0.977 (1.1e-4 against the 400-panel reference, which had not converged
/// there; 3.5e-5 against a converged one).
fn pinned_sets() -> [(FurParamsInput, f32); 3] {
    let set =
        |eta_c, ca: [f32; 3], alpha_deg, beta_m_deg, beta_n_deg, l, kappa, eta_m, ms, ma, g| {
            FurParamsInput {
                eta_c,
                pigment: Pigment::Absorption(Rgb(ca)),
                alpha_deg,
                beta_m_deg,
                beta_n_deg: Some(beta_n_deg),
                l,
                kappa,
                eta_m: Some(eta_m),
                sigma_ms: ms,
                sigma_ma: ma,
                g,
                closure: bcsdf_core::Closure::Energy,
            }
        };
    [
        (
            set(
                1.726_978_7,
                [1.608_206_7, 1.479_287_3, 1.212_858_1],
                1.355_291_4,
                2.109_705_4,
                14.285_738,
                0.001_721_441_7,
                0.699_132_44,
                1.887_080_9,
                2.364_782_3,
                0.586_060_05,
                0.428_549_68,
            ),
            46.551_163,
        ),
        (
            set(
                1.820_149,
                [2.101_752_3, 2.349_760_8, 1.600_971_7],
                1.117_270_5,
                19.928_968,
                25.878_626,
                0.004_768_61,
                0.065_409_064,
                1.694_180_3,
                3.468_669,
                0.349_198_04,
                0.065_020_72,
            ),
            48.881_744,
        ),
        (
            set(
                1.418_785_8,
                [0.852_551_04, 0.367_930_6, 0.621_220_2],
                4.789_436_3,
                9.4423,
                6.465_605_3,
                1.522_760_9,
                0.634_436_96,
                1.440_725_9,
                3.661_18,
                0.170_014_38,
                0.593_451_74,
            ),
            30.745_712,
        ),
    ]
}

#[test]
fn far_field_matches_converged_reference_for_pinned_parameter_sets() {
    for (input, tr) in pinned_sets() {
        let m = model(&input);
        let worst = worst_error_with(&m, &[tr], 12, 6400);
        eprintln!("pinned θr={tr}: worst relative error {worst:.2e}");
        assert!(
            worst <= TOLERANCE,
            "{input:?} θr={tr}: worst relative error {worst:.3e}"
        );
    }
}

/// Worst relative error of the summed scattered lobes' far field, against the same brute-force
/// integral of the near field (same metric; peak = largest scattered total over φ).
fn worst_scattered_error(model: &FurBcsdf, thetas_deg: &[f32], n_phi: usize) -> f64 {
    let scattered =
        |v: &[f64]| -> f64 { (UNSCATTERED_COUNT..LOBE_COUNT - 1).map(|l| v[3 * l]).sum() };
    let mut worst = 0.0f64;
    for &tr_deg in thetas_deg {
        let tr = tr_deg.to_radians();
        let mut rows = Vec::new();
        let mut peak = 0.0f64;
        for i in 0..n_phi {
            let phi = (-180.0 + 360.0 * (i as f32 + 0.37) / n_phi as f32).to_radians();
            let r = scattered(&reference(model, tr, phi, 400));
            let f = scattered(&flatten(&model.azimuthal_far(tr, phi)));
            peak = peak.max(r);
            rows.push((f, r));
        }
        for (f, r) in rows {
            worst = worst.max((f - r).abs() / r.max(1e-3 * peak));
        }
    }
    worst
}

#[test]
fn scattered_far_field_matches_fine_reference() {
    for name in ["bobcat", "red-fox", "raccoon", "air-medulla"] {
        let params = FurParams::new(&presets::find(name).unwrap().input).unwrap();
        let layout = ProfileLayout::for_params(&params, Resolution::DEFAULT);
        let budget = PhotonBudget {
            per_cn_cell: 100_000,
            per_cm_row: 4_000,
        };
        let (mut cn, mut cm) = (vec![0.0; layout.cn_len()], vec![0.0; layout.cm_len()]);
        generate(&layout, &budget, 3, &mut cn, &mut cm).unwrap();
        let profiles = MedullaProfiles::new(layout, &cn, &cm).unwrap();
        let model: FurBcsdf = FurBcsdf::new(params, profiles).unwrap();
        // The scattered lobes sit between the unscattered ones and the residual (last).
        assert!(Lobe::ALL[UNSCATTERED_COUNT..LOBE_COUNT - 1]
            .iter()
            .all(|l| l.is_scattered()));
        assert_eq!(Lobe::ALL[LOBE_COUNT - 1], Lobe::Residual);
        let worst = worst_scattered_error(&model, &[-65.0, -20.0, 10.0, 60.0], 16);
        eprintln!("{name}: scattered far field, worst relative error {worst:.2e}");
        assert!(worst <= SCATTERED_TOLERANCE, "{name}: {worst:.3e}");
    }
}
