//! Mirror symmetries of docs/model.md §8.
//!
//! - Far field: S(θ_i, θ_r, φ) = S(θ_i, θ_r, −φ). The core folds the h-integral onto h ≥ 0 and
//!   evaluates D_p(φ − Φ) + D_p(−φ − Φ) (bcsdf-core `far_field` module docs), which makes the
//!   symmetry exact to the bit; the test asserts bitwise equality for every lobe and channel.
//! - Near field: mirroring the cross-section maps h → −h and φ → −φ, so
//!   S(h, φ) = S(−h, −φ) per lobe. The core evaluates D_p(wrap(φ − Φ_p(h))) with f32 exit
//!   azimuths Φ_p up to ~3π in magnitude (Φ_TttT has a +π, so Φ_p(−h) = −Φ_p(h) only mod 2π):
//!   the two sides' arguments differ by the rounding of an f32 angle of that size, a few ulp of
//!   4π ≈ 1e-6 rad. The test therefore allows 1e-6 relative plus what an azimuth shift of
//!   `PHI_ROUNDING` changes: |S(h, φ) − S(−h, −φ)| ≤ 1e-6·|S| + PHI_ROUNDING·|∂S/∂φ| (central
//!   difference); the number of bitwise-equal pairs is printed.

use bcsdf_core::{presets, Angles, FurBcsdf, FurParams, FurParamsInput, Lobe, Lobes, Pigment, Rgb};
use fur_tests::tracer::SplitMix64;

fn random_params(rng: &mut SplitMix64) -> FurParams {
    let eta_c = rng.range_f32(1.1, 2.5);
    FurParams::new(&FurParamsInput {
        eta_c,
        pigment: Pigment::Absorption(Rgb([
            rng.range_f32(0.0, 5.0),
            rng.range_f32(0.0, 5.0),
            rng.range_f32(0.0, 5.0),
        ])),
        alpha_deg: rng.range_f32(-15.0, 15.0),
        beta_m_deg: rng.range_f32(1.0, 30.0),
        beta_n_deg: Some(rng.range_f32(1.0, 30.0)),
        l: rng.range_f32(0.0, 6.0),
        kappa: if rng.unit() < 0.2 {
            0.0
        } else {
            rng.range_f32(0.0, 0.99)
        },
        eta_m: Some(if rng.unit() < 0.3 {
            eta_c
        } else {
            rng.range_f32(1.01, 2.5)
        }),
        sigma_ms: rng.range_f32(0.0, 10.0),
        sigma_ma: rng.range_f32(0.0, 2.0),
        g: rng.range_f32(-0.9, 0.95),
        closure: bcsdf_core::Closure::Energy,
    })
    .expect("valid parameters")
}

fn parameter_sets() -> Vec<(String, FurParams)> {
    let mut rng = SplitMix64(0x5133_e7e7_0000_0001);
    let mut out: Vec<(String, FurParams)> = presets::PRESETS
        .iter()
        .map(|p| (p.name.to_string(), FurParams::new(&p.input).unwrap()))
        .collect();
    out.extend((0..25).map(|i| (format!("random {i}"), random_params(&mut rng))));
    out
}

fn angle_samples(rng: &mut SplitMix64, n: usize) -> Vec<Angles> {
    let mut v: Vec<Angles> = (0..n)
        .map(|_| {
            Angles::from_degrees(
                rng.range_f32(-89.0, 89.0),
                rng.range_f32(-89.0, 89.0),
                rng.range_f32(-180.0, 180.0),
            )
            .unwrap()
        })
        .collect();
    // The special azimuths: forward, backward, and either side of them.
    for phi in [0.0f32, 180.0, -179.99, 179.99, 0.01, 90.0] {
        v.push(Angles::from_degrees(20.0, -35.0, phi).unwrap());
    }
    v
}

/// Allowed difference of the D_p arguments of the two mirrored evaluations, radians: 4 ulp of
/// an f32 angle near 4π (ulp = 9.5e-7).
const PHI_ROUNDING: f64 = 4e-6;

fn bits(l: &Lobes) -> Vec<u32> {
    l.iter().flat_map(|(_, v)| v.0.map(f32::to_bits)).collect()
}

#[test]
fn far_field_is_mirror_symmetric_in_phi() {
    let mut rng = SplitMix64(0x5133_e7e7_0000_0002);
    let mut checked = 0;
    let mut nonzero = 0;
    for (name, p) in parameter_sets() {
        let model: FurBcsdf = FurBcsdf::unscattered(p);
        for a in angle_samples(&mut rng, 40) {
            let m = a.mirrored();
            assert!(
                (m.phi() + a.phi()).abs() < 1e-6
                    || (a.phi().abs() - core::f32::consts::PI).abs() < 1e-6
            );
            let (s, t) = (model.eval_far_lobes(&a), model.eval_far_lobes(&m));
            assert_eq!(
                bits(&s),
                bits(&t),
                "{name}: far field not mirror symmetric at θ_i={} θ_r={} φ={}: {:?} vs {:?}",
                a.theta_i(),
                a.theta_r(),
                a.phi(),
                s,
                t
            );
            checked += 1;
            if s.total().max_channel() > 0.0 {
                nonzero += 1;
            }
        }
    }
    eprintln!("far field: {checked} mirror pairs bitwise equal ({nonzero} non-zero)");
    assert!(nonzero > checked / 2);
}

#[test]
fn near_field_is_symmetric_under_h_and_phi_mirror() {
    let mut rng = SplitMix64(0x5133_e7e7_0000_0003);
    let (mut worst, mut pairs, mut bitwise) = (0.0f64, 0usize, 0usize);
    let mut worst_rel = 0.0f64;
    for (name, p) in parameter_sets() {
        let model: FurBcsdf = FurBcsdf::unscattered(p);
        let angles = angle_samples(&mut rng, 60);
        let hs: Vec<f32> = (0..40)
            .map(|_| rng.range_f32(-1.0, 1.0))
            .chain([0.0, 1.0, 0.999_999, 0.5])
            .collect();
        let mut rows = Vec::new();
        let mut peak = 0.0f64;
        for a in &angles {
            for &h in &hs {
                let (s, t) = (model.eval_near(a, h), model.eval_near(&a.mirrored(), -h));
                peak = peak.max(s.total().max_channel() as f64);
                // ∂S/∂φ by central difference over ±1e-3 rad.
                let shifted = |d: f32| {
                    let b = Angles::new(a.theta_i(), a.theta_r(), a.phi() + d).unwrap();
                    model.eval_near(&b, h)
                };
                let (up, down) = (shifted(1e-3), shifted(-1e-3));
                let slope: Vec<f64> = Lobe::ALL
                    .iter()
                    .flat_map(|&l| {
                        (0..3).map(move |ch| {
                            (up.get(l).0[ch] as f64 - down.get(l).0[ch] as f64).abs() / 2e-3
                        })
                    })
                    .collect();
                rows.push((a, h, s, t, slope));
            }
        }
        for (a, h, s, t, slope) in rows {
            pairs += 1;
            if bits(&s) == bits(&t) {
                bitwise += 1;
            }
            for lobe in Lobe::ALL {
                for ch in 0..3 {
                    let (x, y) = (s.get(lobe).0[ch] as f64, t.get(lobe).0[ch] as f64);
                    let allowed = 1e-6 * x.abs().max(y.abs())
                        + PHI_ROUNDING * slope[lobe.index() * 3 + ch]
                        + 1e-12 * peak;
                    let err = (x - y).abs() / allowed.max(1e-300);
                    worst = worst.max(err);
                    worst_rel = worst_rel
                        .max((x - y).abs() / x.abs().max(y.abs()).max(1e-4 * peak).max(1e-300));
                    assert!(
                        err <= 1.0,
                        "{name}: S(h, φ) ≠ S(−h, −φ) for {} at h={h} θ_i={} θ_r={} φ={}: {x:e} vs {y:e}",
                        lobe.name(),
                        a.theta_i(),
                        a.theta_r(),
                        a.phi()
                    );
                }
            }
        }
    }
    eprintln!(
        "near field: {pairs} pairs, {bitwise} bitwise equal, worst difference / allowance {worst:.3e}, worst relative (floor 1e-4·peak) {worst_rel:.3e}"
    );
}
