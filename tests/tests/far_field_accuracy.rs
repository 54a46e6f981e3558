//! The far field's fast quadrature against a much finer brute-force integral of the near field
//! (MODEL.md §5: accurate to 1e-4 relative).

use bcsdf_core::{presets, FurBcsdf, FurParams, Lobe, LOBE_COUNT};
use fur_tests::quadrature::integrate_smoothstep;

/// Bravais index, written here from MODEL.md §3.
fn bravais(eta: f64, theta: f64) -> f64 {
    (eta * eta - theta.sin().powi(2)).sqrt() / theta.cos()
}

/// ½ ∫ N_p(h, φ) dh from the near field, split at ±κη'_c and ±κη'_m.
fn reference(model: &FurBcsdf, theta_r: f32, phi: f32, panels: usize) -> [[f64; 3]; LOBE_COUNT] {
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
    let mut out = [[0.0; 3]; LOBE_COUNT];
    for w in cuts.windows(2) {
        for lobe in 0..LOBE_COUNT {
            for ch in 0..3 {
                out[lobe][ch] += 0.5
                    * integrate_smoothstep(w[0], w[1], panels, 6, |h| {
                        model.azimuthal_near(theta_r, phi, h as f32)[lobe].0[ch] as f64
                    });
            }
        }
    }
    out
}

#[test]
fn far_field_matches_fine_reference() {
    let mut worst = 0.0f64;
    for preset in presets::PRESETS.iter() {
        let model: FurBcsdf = FurBcsdf::new(FurParams::new(&preset.input).unwrap());
        for theta_r_deg in [-60.0f32, -20.0, 0.0, 35.0, 70.0] {
            let theta_r = theta_r_deg.to_radians();
            let phis: Vec<f32> = (0..24).map(|i| (-180.0 + 15.0 * i as f32 + 3.7).to_radians()).collect();
            let refs: Vec<_> = phis.iter().map(|&phi| reference(&model, theta_r, phi, 400)).collect();
            let peak = refs
                .iter()
                .map(|r| (0..3).map(|c| r.iter().map(|l| l[c]).sum::<f64>()).fold(0.0, f64::max))
                .fold(0.0, f64::max);
            for (phi, r) in phis.iter().zip(&refs) {
                let fast = model.azimuthal_far(theta_r, *phi);
                for lobe in Lobe::ALL {
                    for ch in 0..3 {
                        let (f, e) = (fast[lobe.index()].0[ch] as f64, r[lobe.index()][ch]);
                        let err = (f - e).abs() / e.abs().max(1e-3 * peak);
                        if err > worst {
                            worst = err;
                            eprintln!("{} θr={theta_r_deg} φ={:.1} {} ch{ch}: fast {f:.6e} ref {e:.6e} err {err:.2e}", preset.name, phi.to_degrees(), lobe.name());
                        }
                    }
                }
            }
        }
    }
    eprintln!("worst {worst:.3e}");
    assert!(worst <= 1e-4, "worst relative error {worst:.3e}");
}
