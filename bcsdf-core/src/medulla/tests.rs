//! Unit tests of the profile generator and lookups: the phase-function samplers, the
//! normalisation and determinism of the walks, the layout, and the lookups' symmetries.

extern crate std;

use super::lookup::locate;
use super::walk::{sample_hg_2d, sample_hg_3d_cos};
use super::*;
use crate::math::TAU;
use crate::presets;
use std::vec;
use std::vec::Vec;

/// Midpoints of `n` equal cells of [0, 1).
fn midpoints(n: usize) -> impl Iterator<Item = f32> {
    (0..n).map(move |k| (k as f32 + 0.5) / n as f32)
}

#[test]
fn henyey_greenstein_samplers_have_mean_cosine_g() {
    let n = 200_000;
    for g in [-0.6f32, 0.0, 0.3, 0.79, 0.95] {
        let mean3: f64 = midpoints(n)
            .map(|u| f64::from(sample_hg_3d_cos(g, u)))
            .sum::<f64>()
            / n as f64;
        assert!((mean3 - f64::from(g)).abs() < 2e-3, "3D g {g}: {mean3}");
        let mean2: f64 = midpoints(n)
            .map(|u| f64::from(libm::cosf(sample_hg_2d(g, u))))
            .sum::<f64>()
            / n as f64;
        assert!((mean2 - f64::from(g)).abs() < 2e-3, "2D g {g}: {mean2}");
    }
    // Forward and backward ends of the 3D sampler.
    assert_eq!(sample_hg_3d_cos(0.5, 1.0), 1.0);
    assert_eq!(sample_hg_3d_cos(0.5, 0.0), -1.0);
}

#[test]
fn disk_cells_are_normalised_and_deterministic() {
    let n_psi = 36;
    let width = TAU / n_psi as f32;
    let mut cn = vec![0.0; n_psi];
    let stats = simulate_disk_cell(2.0, 0.4, 0.5, 0.0, 20_000, 11, &mut cn);
    assert_eq!(stats.launched, 20_000);
    assert!(
        stats.scattered > 10_000 && stats.scattered < 20_000,
        "{stats:?}"
    );
    let mass: f32 = cn.iter().sum::<f32>() * width;
    assert!((mass - 1.0).abs() < 1e-5, "{mass}");
    let mut cn2 = vec![0.0; n_psi];
    assert_eq!(
        simulate_disk_cell(2.0, 0.4, 0.5, 0.0, 20_000, 11, &mut cn2),
        stats
    );
    assert_eq!(cn2, cn);
    // With absorption the same photons are binned, each weighted by its survival: no bin
    // grows, and the row's integral, their mean survival, lies between e^(−a·ℓ) for the
    // shortest possible scattered path (0) and a mean path of 4 radii (the unit disk's
    // scattered paths average well below that at σ = 2).
    let a = 0.3;
    let mut weighted = vec![0.0; n_psi];
    assert_eq!(
        simulate_disk_cell(2.0, 0.4, 0.5, a, 20_000, 11, &mut weighted),
        stats
    );
    assert!(weighted.iter().zip(&cn).all(|(w, c)| w <= c && *w > 0.0));
    let survival: f32 = weighted.iter().sum::<f32>() * width;
    assert!(
        survival < 0.95 && survival > libm::expf(-a * 4.0),
        "{survival}"
    );
    // No scattering medium: nothing is binned; the row is uniform, times the survival along
    // the straight chord (1.6 at h_m = 0.6).
    let stats = simulate_disk_cell(0.0, 0.6, 0.5, 0.0, 1_000, 11, &mut cn);
    assert_eq!((stats.launched, stats.scattered), (1_000, 0));
    assert!(cn.iter().all(|&c| c == 1.0 / TAU));
    simulate_disk_cell(0.0, 0.6, 0.5, a, 1_000, 11, &mut cn);
    let want = libm::expf(-a * 1.6) / TAU;
    assert!(cn.iter().all(|&c| (c - want).abs() < 1e-7), "{cn:?}");
    // Empty outputs: nothing to do.
    assert_eq!(
        simulate_disk_cell(1.0, 0.0, 0.0, 0.0, 10, 1, &mut []),
        CellStats::default()
    );
}

#[test]
fn cylinder_rows_are_normalised_per_half() {
    let n_out = 32;
    let (mut back, mut front) = (vec![0.0; n_out], vec![0.0; n_out]);
    let stats = simulate_cylinder_row(1.5, 0.3, 0.6, 20_000, 5, &mut back, &mut front);
    assert_eq!(stats.launched, 20_000);
    assert!(stats.scattered > 0);
    let width = PI / n_out as f32;
    for half in [&back, &front] {
        let mass: f32 = half.iter().sum::<f32>() * width;
        assert!((mass - 1.0).abs() < 1e-5, "{mass}");
        assert!(half.iter().all(|v| v.is_finite() && *v >= 0.0));
    }
}

fn layout() -> ProfileLayout {
    let params = FurParams::new(&presets::find("air-medulla").unwrap().input).unwrap();
    ProfileLayout::for_params(
        &params,
        Resolution {
            n_sigma: 3,
            n_h: 4,
            n_psi: 24,
            n_in: 4,
            n_out: 16,
        },
    )
}

#[test]
fn layouts_follow_the_parameters_and_are_validated() {
    let params = FurParams::new(&presets::find("air-medulla").unwrap().input).unwrap();
    let l = layout();
    assert!(l.matches(&params));
    assert_eq!(l.g, params.g());
    assert!((l.sigma_m - params.sigma_ms() * params.kappa()).abs() < 1e-7);
    assert!((l.theta_in_max - libm::asinf(1.0 / params.eta_m())).abs() < 1e-7);
    assert!(params.sigma_ma() > 0.0);
    assert_eq!(l.absorption, params.sigma_ma() / params.sigma_ms());
    assert_eq!((l.cn_len(), l.cm_len()), (3 * 4 * 24, 2 * 4 * 16));
    assert_eq!(l.sigma_n_node(0), l.sigma_n_min);
    assert!((l.sigma_n_node(2) - l.sigma_n_max).abs() < 1e-6);
    assert_eq!((l.h_node(0), l.h_node(3)), (0.0, 0.75));
    assert!((l.theta_in_node(3) - l.theta_in_max).abs() < 1e-7);
    assert_eq!(l.validate(), Ok(()));
    let other = FurParams::new(&presets::find("bobcat").unwrap().input).unwrap();
    assert!(!l.matches(&other));
    let bad = |f: fn(&mut ProfileLayout)| {
        let mut b = l;
        f(&mut b);
        b.validate()
    };
    assert_eq!(bad(|b| b.res.n_psi = 0), Err(ProfileError::BadResolution));
    assert_eq!(bad(|b| b.res.n_in = 1), Err(ProfileError::BadResolution));
    assert_eq!(
        bad(|b| b.res.n_in = MAX_N_IN + 1),
        Err(ProfileError::BadResolution)
    );
    assert_eq!(bad(|b| b.g = 1.0), Err(ProfileError::BadAxis));
    assert_eq!(bad(|b| b.absorption = -0.1), Err(ProfileError::BadAxis));
    assert_eq!(
        bad(|b| b.absorption = f32::INFINITY),
        Err(ProfileError::BadAxis)
    );
    assert_eq!(bad(|b| b.sigma_n_max = -1.0), Err(ProfileError::BadAxis));
    assert_eq!(
        bad(|b| b.theta_in_max = f32::NAN),
        Err(ProfileError::BadAxis)
    );
}

/// Small profiles of [`layout`], generated.
fn tables() -> (Vec<f32>, Vec<f32>) {
    let l = layout();
    let (mut cn, mut cm) = (vec![0.0; l.cn_len()], vec![0.0; l.cm_len()]);
    let budget = PhotonBudget {
        per_cn_cell: 3_000,
        per_cm_row: 3_000,
    };
    generate(&l, &budget, 3, &mut cn, &mut cm).unwrap();
    (cn, cm)
}

#[test]
fn cells_do_not_depend_on_the_order_they_are_made_in() {
    let l = layout();
    let (cn, cm) = tables();
    let budget = PhotonBudget {
        per_cn_cell: 3_000,
        per_cm_row: 3_000,
    };
    let n = l.res.n_psi;
    let mut c = vec![0.0; n];
    generate_cn_cell(&l, 7, &budget, 3, &mut c);
    assert_eq!(&c[..], &cn[7 * n..8 * n]);
    let m = l.res.n_out;
    let (mut back, mut front) = (vec![0.0; m], vec![0.0; m]);
    generate_cm_row(&l, 2, &budget, 3, &mut back, &mut front);
    let half = l.res.n_in * m;
    assert_eq!(&back[..], &cm[2 * m..3 * m]);
    assert_eq!(&front[..], &cm[half + 2 * m..half + 3 * m]);
    // Out-of-range cells and rows simulate nothing.
    assert_eq!(
        generate_cn_cell(&l, 12, &budget, 3, &mut c),
        CellStats::default()
    );
    assert_eq!(
        generate_cm_row(&l, 4, &budget, 3, &mut back, &mut front),
        CellStats::default()
    );
    // Wrong buffer sizes are refused before anything is simulated.
    let mut short = vec![0.0; l.cm_len() - 1];
    let mut cn2 = cn.clone();
    assert!(matches!(
        generate(&l, &budget, 3, &mut cn2, &mut short),
        Err(ProfileError::WrongLength { table: "C^M", .. })
    ));
}

#[test]
fn lookups_interpolate_clamp_and_keep_the_symmetries() {
    let l = layout();
    let (cn, cm) = tables();
    let p = MedullaProfiles::new(l, &cn, &cm).unwrap();
    assert_eq!(p.tables(), (&cn[..], &cm[..]));
    assert_eq!(p.layout(), &l);
    let sigma = 0.5 * (l.sigma_n_min + l.sigma_n_max);
    for h in [0.0f32, 0.3, 0.74, 0.99] {
        for psi in [-3.0f32, -1.0, 0.0, 0.5, 2.9, PI] {
            // C^N(ψ | −h) = C^N(−ψ | h) (at h = 0 only up to the photon noise: not checked).
            if h > 0.0 {
                let a = p.cn(sigma, -h, psi);
                assert!(
                    (a - p.cn(sigma, h, -psi)).abs() <= 1e-6 * a.max(1.0),
                    "{h} {psi}"
                );
            }
            let row = p.n_row(sigma, h);
            assert_eq!(p.cn_at(&row, psi), p.cn(sigma, h, psi));
        }
        // Circular: ψ and ψ + 2π are the same bin.
        assert!((p.cn(sigma, h, 1.0) - p.cn(sigma, h, 1.0 - TAU)).abs() < 1e-5);
        // Each row integrates to the scattered photons' mean survival (air-medulla absorbs:
        // below 1, above e^(−k·σ_N·4)) and its samples stay on the circle, in CDF order: the
        // segments run from the first bin centre, −π + w/2, once around the circle.
        let row = p.n_row(sigma, h);
        let mass = p.row_mass(&row);
        assert!(
            mass < 1.0 && mass > libm::expf(-l.absorption * sigma * 4.0),
            "{mass}"
        );
        let first = -PI + 0.5 * TAU / l.res.n_psi as f32;
        let mut prev = first;
        for u in midpoints(50) {
            let psi = p.sample_psi(&row, u).unwrap();
            assert!(psi > -PI && psi <= PI);
            let unwrapped = if psi < first { psi + TAU } else { psi };
            assert!(unwrapped >= prev, "h {h}: ψ({u}) = {psi} before {prev}");
            prev = unwrapped;
        }
    }
    // Outside the tabulated σ_N: the end rows (clamped).
    assert_eq!(
        p.cn(l.sigma_n_max * 10.0, 0.3, 1.0),
        p.cn(l.sigma_n_max, 0.3, 1.0)
    );
    assert_eq!(p.cn(-1.0, 0.3, 1.0), p.cn(l.sigma_n_min, 0.3, 1.0));
    // C^M(out | −in) = C^M(−out | in), and each half a density over θ'_out.
    for half in [Half::Back, Half::Front] {
        for (out, inn) in [(0.3f32, 0.2f32), (-1.0, 0.5), (1.4, 0.05)] {
            assert_eq!(p.cm(half, out, -inn), p.cm(half, -out, inn));
        }
        let n = 4_000;
        let mass: f32 = midpoints(n)
            .map(|u| p.cm(half, -PI / 2.0 + PI * u, 0.3) * (PI / n as f32))
            .sum();
        // Linear interpolation between bin centres, flat half bins at the ends.
        assert!((mass - 1.0).abs() < 0.05, "{half:?}: {mass}");
    }
}

#[test]
fn locate_clamps_and_survives_degenerate_axes() {
    assert_eq!(locate(0.25, 0.0, 0.5, 5), (0, 0.5));
    let (i, w) = locate(1.9, 0.0, 0.5, 5);
    assert!(i == 3 && (w - 0.8).abs() < 1e-6, "{i} {w}");
    assert_eq!(locate(-3.0, 0.0, 0.5, 5), (0, 0.0));
    assert_eq!(locate(9.0, 0.0, 0.5, 5), (3, 1.0));
    assert_eq!(locate(0.3, 0.0, 0.5, 1), (0, 0.0));
    assert_eq!(locate(0.3, 0.0, f32::NAN, 5), (0, 0.0));
    assert_eq!(locate(0.3, 0.0, 0.0, 5), (0, 0.0));
}

#[test]
fn profile_errors_explain_themselves() {
    let e = ProfileError::WrongLength {
        table: "C^M",
        expected: 10,
        found: 9,
    };
    assert_eq!(
        std::format!("{e}"),
        "profile table C^M: expected 10 values, found 9"
    );
    let _: &dyn core::error::Error = &e;
    let l = layout();
    let (cn, mut cm) = tables();
    cm[5] = -1.0;
    assert_eq!(
        MedullaProfiles::new(l, &cn, &cm).unwrap_err(),
        ProfileError::BadValue {
            table: "C^M",
            index: 5
        }
    );
}
