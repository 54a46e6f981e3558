extern crate std;
use super::sim::{simulate_cell, simulate_cells, Events, MODELLED_UNSCATTERED};
use super::*;
use crate::frame::Angles;
use crate::math::{Libm, TAU};
use crate::medulla::{generate as generate_profiles, MedullaProfiles, PhotonBudget};
use crate::medulla::{ProfileLayout, Resolution};
use crate::model::FurBcsdf;
use crate::params::FurParams;
use crate::params::{Closure, FurParamsInput};
use crate::pigment::Pigment;
use crate::presets;
use crate::residual_gen::{generate, generate_row, generate_rows, section, RowStats};
use crate::rng::Pcg32;
use crate::spectrum::Rgb;
use std::vec;
use std::vec::Vec;

fn lossless(name: &str) -> FurParams {
    let input = FurParamsInput {
        pigment: Pigment::Absorption(Rgb::ZERO),
        sigma_ma: 0.0,
        closure: Closure::Energy,
        ..presets::find(name).unwrap().input
    };
    FurParams::new(&input).unwrap()
}

fn small_profiles(p: &FurParams) -> (ProfileLayout, Vec<f32>, Vec<f32>) {
    let layout = ProfileLayout::for_params(p, Resolution::DEFAULT);
    let (mut cn, mut cm) = (vec![0.0; layout.cn_len()], vec![0.0; layout.cm_len()]);
    let budget = PhotonBudget {
        per_cn_cell: 2000,
        per_cm_row: 4000,
    };
    generate_profiles(&layout, &budget, 1, &mut cn, &mut cm).unwrap();
    (layout, cn, cm)
}

const DEFAULT_NODES: usize = ResidualLayout::DEFAULT.n_theta;

const SMALL: ResidualLayout = ResidualLayout {
    n_theta: 4,
    n_h: 8,
    n_phi: 12,
    photons: 200,
};

#[test]
fn event_strings_tell_the_modelled_paths_apart() {
    assert_eq!(Events::parse(b"TT"), MODELLED_UNSCATTERED[1]);
    assert_ne!(Events::parse(b"TRT"), Events::parse(b"TRRT"));
    assert_ne!(Events::parse(b"TrT"), Events::parse(b"TtT"));
    assert!(!MODELLED_UNSCATTERED.contains(&Events::parse(b"TRRT")));
    assert!(!MODELLED_UNSCATTERED.contains(&Events::parse(b"TrRttT")));
    // Long strings saturate and are never one of the eight.
    let long = Events::parse(b"TRRRRRRRRRRRRRRRRRRRT");
    assert_eq!(long, Events::parse(b"TRRRRRRRRRRRRRRRRRRRRRRRRRRRRRRT"));
}

#[test]
fn a_lossless_fiber_returns_every_photon_and_beam() {
    // σ_ca = σ_ma = 0: everything that enters leaves, up to what the cutoffs drop.
    for name in ["bobcat", "air-medulla", "human-hair"] {
        let p = lossless(name);
        for theta_r in [0.0f32, 0.7, 1.3] {
            let sec = section(&p, theta_r);
            for h in [0.05f32, 0.4, 0.8, 0.97] {
                let mut rng = Pcg32::new(3, 4);
                let mut hist = [[0.0; 3]; 12];
                let t = simulate_cell(&sec, h, 500, &mut rng, &mut hist);
                for c in 0..3 {
                    let sum = t.exiting[c] + t.dropped[c];
                    assert!((sum - 1.0).abs() < 2e-5, "{name} {theta_r} {h}: {t:?}");
                    assert!(t.dropped[c] < 1e-5, "{name} {theta_r} {h}: {t:?}");
                    let binned: f64 = hist.iter().map(|b| b[c]).sum();
                    assert!((binned - t.unmodelled[c]).abs() < 1e-9);
                }
            }
        }
    }
}

#[test]
fn a_cell_draws_the_same_random_numbers_at_every_colour() {
    // Common random numbers (the `sim` module's documentation): the beam tree, the photon
    // count and the draws go by the weight without cortex absorption, so a cell ends on the
    // same generator state with the same beams and photons at any σ_ca, and its tallies
    // fall off smoothly with σ_ca instead of changing noise.
    let base = presets::find("bobcat").unwrap().input;
    let at = |sigma: [f32; 3]| {
        let input = FurParamsInput {
            pigment: Pigment::Absorption(Rgb(sigma)),
            ..base
        };
        FurParams::new(&input).unwrap()
    };
    for theta_r in [0.0f32, 0.7, 1.3] {
        for h in [0.05f32, 0.4, 0.8] {
            let run = |sigma: [f32; 3]| {
                let sec = section(&at(sigma), theta_r);
                let mut rng = Pcg32::new(3, 4);
                let mut hist = [[0.0; 3]; 12];
                let t = simulate_cell(&sec, h, 500, &mut rng, &mut hist);
                (t, rng.next_u32())
            };
            let (clear, next) = run([0.0, 0.0, 0.0]);
            for sigma in [[0.3, 3.0, 30.0], [5.3, 59.1, 651.5]] {
                let (t, n) = run(sigma);
                assert_eq!((t.beams, t.photons, n), (clear.beams, clear.photons, next));
                for c in 0..3 {
                    assert!(t.exiting[c] <= clear.exiting[c], "{sigma:?} {t:?}");
                }
            }
            // The same draws: a lighter channel keeps more than a darker one, cell by cell.
            let (t, _) = run([0.3, 3.0, 30.0]);
            assert!(
                t.exiting[0] >= t.exiting[1] && t.exiting[1] >= t.exiting[2],
                "{t:?}"
            );
        }
    }
}

#[test]
fn one_walk_at_several_colours_is_each_colours_own_walk_bit_for_bit() {
    // The walk does not depend on the colour (common random numbers), so the colours of a
    // LUT's absorption planes share one walk: each colour's tally, histogram and row must be
    // the bits of its own walk.
    let base = presets::find("bobcat").unwrap().input;
    let at = |sigma: [f32; 3]| {
        let input = FurParamsInput {
            pigment: Pigment::Absorption(Rgb(sigma)),
            ..base
        };
        FurParams::new(&input).unwrap()
    };
    let colours = [[0.0, 0.004, 0.018], [0.3, 3.0, 30.0], [5.3, 59.1, 1000.0]];
    for theta_r in [0.0f32, 0.7, 1.3] {
        for h in [0.05f32, 0.4, 0.8] {
            let sec = section(&at(colours[0]), theta_r);
            let cortex = colours.map(|s| section(&at(s), theta_r).ext.cortex);
            let mut rng = Pcg32::new(3, 4);
            let mut hist = [[0.0; 3]; 3 * 12];
            let all = simulate_cells(&sec, &cortex, h, 500, &mut rng, &mut hist, 12);
            let next = rng.next_u32();
            for (k, sigma) in colours.into_iter().enumerate() {
                let mut rng = Pcg32::new(3, 4);
                let mut own = [[0.0; 3]; 12];
                let t = simulate_cell(&section(&at(sigma), theta_r), h, 500, &mut rng, &mut own);
                assert_eq!(all[k], t, "{sigma:?} at θ_r {theta_r}, h {h}");
                assert_eq!(&hist[12 * k..12 * (k + 1)], &own[..], "{sigma:?}");
                assert_eq!(rng.next_u32(), next);
            }
        }
    }
    // Rows: the models of three colours with the same profiles.
    let p = at(colours[0]);
    let (layout, cn, cm) = small_profiles(&p);
    let profiles = MedullaProfiles::new(layout, &cn, &cm).unwrap();
    let models = colours.map(|s| FurBcsdf::<Libm>::new(at(s), profiles).unwrap());
    let len = SMALL.row_len();
    let mut rows = vec![0.0; 3 * len];
    let mut hist = vec![[0.0; 3]; 3 * SMALL.n_phi];
    let (r0, rest) = rows.split_at_mut(len);
    let (r1, r2) = rest.split_at_mut(len);
    let stats = generate_rows(
        &[&models[0], &models[1], &models[2]],
        &SMALL,
        1,
        9,
        [r0, r1, r2],
        &mut hist,
    );
    for (k, model) in models.iter().enumerate() {
        let mut own = vec![0.0; len];
        let s = generate_row(model, &SMALL, 1, 9, &mut own);
        assert_eq!(&rows[k * len..(k + 1) * len], &own[..], "colour {k}");
        assert_eq!(stats[k], s);
    }
    // Models that differ in more than σ_ca are refused: nothing is written.
    let other = FurBcsdf::<Libm>::new(
        FurParams::new(&FurParamsInput {
            alpha_deg: base.alpha_deg + 1.0,
            pigment: Pigment::Absorption(Rgb(colours[1])),
            ..base
        })
        .unwrap(),
        profiles,
    )
    .unwrap();
    let mut out = vec![7.0; 2 * len];
    let (o0, o1) = out.split_at_mut(len);
    let refused = generate_rows(&[&models[0], &other], &SMALL, 1, 9, [o0, o1], &mut hist);
    assert_eq!(refused, [RowStats::default(); 2]);
    assert!(out.iter().all(|&v| v == 7.0));
}

#[test]
fn rows_are_the_same_bits_alone_or_in_a_table() {
    let p = lossless("bobcat");
    let (layout, cn, cm) = small_profiles(&p);
    let profiles = MedullaProfiles::new(layout, &cn, &cm).unwrap();
    let model: FurBcsdf = FurBcsdf::new(p, profiles).unwrap();
    let mut all = vec![0.0; SMALL.len()];
    generate(&model, &SMALL, 9, &mut all).unwrap();
    let mut row = vec![0.0; SMALL.row_len()];
    generate_row(&model, &SMALL, 2, 9, &mut row);
    let len = SMALL.row_len();
    assert_eq!(&all[2 * len..3 * len], &row[..]);
    // Another seed gives other photons.
    generate_row(&model, &SMALL, 2, 10, &mut row);
    assert_ne!(&all[2 * len..3 * len], &row[..]);
}

#[test]
fn the_table_normalises_its_shape_and_its_near_field_averages_to_its_far_field() {
    let p = lossless("bobcat");
    let (layout, cn, cm) = small_profiles(&p);
    let profiles = MedullaProfiles::new(layout, &cn, &cm).unwrap();
    let model: FurBcsdf = FurBcsdf::new(p, profiles).unwrap();
    let mut data = vec![0.0; SMALL.len()];
    generate(&model, &SMALL, 1, &mut data).unwrap();
    let table = ResidualTable::new(p, SMALL, &data).unwrap();
    for k in 0..DEFAULT_NODES {
        let l = ResidualLayout::DEFAULT;
        let at = l.theta_position(l.theta_node(k));
        assert!((at - k as f32).abs() < 1e-3, "node {k}: {at}");
    }
    for theta_r in [0.0f32, 0.3, -0.9, 1.5] {
        // A multiple of the 2·n_phi bins: the midpoint rule is exact on the step function D.
        let n = 2400;
        let (mut d, mut near) = (Rgb::ZERO, Rgb::ZERO);
        for k in 0..n {
            let x = (k as f32 + 0.5) / n as f32;
            d += table.density(theta_r, -PI + TAU * x) * (TAU / n as f32);
            near += table.magnitude(theta_r, x) * (1.0 / n as f32);
        }
        let mean = table.mean(theta_r);
        for c in 0..3 {
            assert!((d.0[c] - 1.0).abs() < 1e-4, "{theta_r}: ∫D = {d:?}");
            assert!(
                (near.0[c] - mean.0[c]).abs() < 1e-4 * mean.0[c].max(1e-3),
                "{theta_r}"
            );
        }
        assert!(mean.max_channel() > 0.0);
    }
    // Made for bobcat: refused by another parameter set, accepted in either closure.
    let other: FurBcsdf = FurBcsdf::unscattered(lossless("cat"));
    assert_eq!(
        other.with_residual(table).err(),
        Some(ProfileError::Mismatch)
    );
    let report = FurBcsdf::<Libm>::new(p.with_closure(Closure::Report), profiles).unwrap();
    let report = report.with_residual(table).unwrap();
    let a = Angles::new(0.1, 0.2, 0.3).unwrap();
    assert_eq!(report.eval_residual(&a, None), Rgb::ZERO);
    let energy = model.with_residual(table).unwrap();
    assert!(energy.eval_residual(&a, None).max_channel() > 0.0);
}

#[test]
fn the_far_field_means_hold_the_rows_means_at_the_rows() {
    let p = lossless("bobcat");
    let (layout, cn, cm) = small_profiles(&p);
    let profiles = MedullaProfiles::new(layout, &cn, &cm).unwrap();
    let model: FurBcsdf = FurBcsdf::new(p, profiles).unwrap();
    let mut data = vec![0.0; SMALL.len()];
    generate(&model, &SMALL, 1, &mut data).unwrap();
    let table = ResidualTable::new(p, SMALL, &data).unwrap();
    assert_eq!(SMALL.n_mean(), MEAN_SUBDIVISION * (SMALL.n_theta - 1) + 1);
    for l in [SMALL, ResidualLayout::DEFAULT] {
        for k in 0..l.n_theta {
            // Row k is mean node MEAN_SUBDIVISION·k, at the same bits.
            let i = MEAN_SUBDIVISION * k;
            assert_eq!(l.mean_node(i).to_bits(), l.theta_node(k).to_bits());
        }
        for i in 0..l.n_mean() {
            // f32's sqrt(1 − t) near grazing view: a few thousandths of a node.
            let at = l.mean_position(l.mean_node(i));
            assert!((at - i as f32).abs() < 1e-2, "mean node {i}: {at}");
        }
    }
    // At the rows (but the last, θ_r = 90°, where every lobe's energy is R's) the far field's
    // mean is the row's own, stored after its scattered scale.
    let len = SMALL.row_len();
    for k in 0..SMALL.n_theta - 1 {
        let mean = table.mean(SMALL.theta_node(k));
        for c in 0..3 {
            let row = data[k * len + SMALL.far_mean_offset() + c];
            assert!(
                (mean.0[c] - row).abs() <= 1e-5 * row.max(1e-2),
                "row {k}: {} vs {row}",
                mean.0[c]
            );
        }
    }
}
