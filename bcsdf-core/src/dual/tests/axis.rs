//! The absorption axis of the `.furdual` blob (format 2): at the node colours the blob
//! evaluates exactly the tables computed at that grey colour; between nodes the interpolated
//! term against the tables computed directly at the colour (the measured error).

extern crate std;
use super::*;
use crate::absorption::Absorption;
use crate::dual::blob::axis_node;
use crate::frame::Angles;
use crate::params::{FurParams, FurParamsInput};
use crate::presets;
use crate::rng::Pcg32;
use crate::FurBcsdf;
use std::boxed::Box;
use std::vec::Vec;

/// Coarser than [`Quadrature::DEFAULT`]: the same quadrature on both sides of every
/// comparison, so only the axis is measured.
const Q: Quadrature = Quadrature {
    theta_steps: 48,
    phi_steps: 24,
};

fn model_input() -> FurParamsInput {
    presets::find("human-hair").unwrap().input
}

/// The tables of the preset at colour `sigma` (RGB σ_ca), by quadrature over the analytic
/// model without the residual.
fn tables_at(sigma: Rgb, out: &mut DualTables) {
    let input = Absorption::from_sigma(sigma).unwrap().apply(&model_input());
    let params = FurParams::new(&input).unwrap();
    let model: FurBcsdf<'_> = FurBcsdf::unscattered(params);
    out.compute(&model, Q);
}

/// The node tables of the whole axis (grey colour σ_k at node k).
fn node_tables() -> Vec<Box<DualTables>> {
    (0..ABS_NODES)
        .map(|k| {
            let mut t = Box::new(DualTables::ZERO);
            tables_at(Rgb::splat(axis_node(k)), &mut t);
            t
        })
        .collect()
}

/// A decoded blob whose node k holds `pick(k)`'s channel 0.
fn axis_lut(nodes: &[Box<DualTables>], pick: impl Fn(usize) -> usize) -> Box<DualLut> {
    let mut blob = Box::new([0u8; BLOB_LEN]);
    let mut scratch = Box::new(DualTables::ZERO);
    let mut k = 0usize;
    encode_axis(
        &mut blob,
        &mut scratch,
        |_sigma, t| {
            t.clone_from(&nodes[pick(k)]);
            k += 1;
        },
        Attenuation::Coat,
        3,
        Absorption::from_sigma(Rgb([0.5, 1.0, 2.0])).unwrap(),
    );
    let mut lut = Box::new(DualLut::EMPTY);
    lut.decode(&blob[..]).unwrap();
    lut
}

fn random_query(rng: &mut Pcg32) -> (Angles, Fibers) {
    let u = |rng: &mut Pcg32| rng.uniform();
    let a = Angles::new(
        (u(rng) - 0.5) * 3.0,
        (u(rng) - 0.5) * 3.0,
        (u(rng) - 0.5) * 6.2,
    )
    .unwrap();
    (a, Fibers::new(u(rng) * 6.0, u(rng) * 20.0))
}

#[test]
fn the_axis_reads_each_channel_at_its_own_node() {
    let nodes = node_tables();
    let full = axis_lut(&nodes, |k| k);
    let sigma_of = |k: usize| axis_node(k);
    let mut rng = Pcg32::new(11, 5);
    let mut compared = 0;
    for (kr, kg, kb) in [(0, 0, 0), (3, 3, 3), (7, 2, 12), (15, 9, 1), (5, 14, 15)] {
        let colour =
            Absorption::from_sigma(Rgb([sigma_of(kr), sigma_of(kg), sigma_of(kb)])).unwrap();
        // The blob computed at each channel's grey colour alone (every node the same).
        let single = [kr, kg, kb].map(|k| axis_lut(&nodes, move |_| k));
        for _ in 0..200 {
            let (a, fibers) = random_query(&mut rng);
            let got = full.eval_at(&a, fibers, Density::DEFAULT, &colour);
            for c in 0..3 {
                let want = single[c].eval(&a, fibers, Density::DEFAULT)[c];
                assert_eq!(
                    got[c], want,
                    "nodes {kr} {kg} {kb} channel {c} at {a:?} {fibers:?}"
                );
                compared += usize::from(want > 0.0);
            }
        }
    }
    assert!(compared > 1000, "{compared} non-zero values compared");
    // The preset colour recorded in the header is the default.
    let (a, fibers) = random_query(&mut rng);
    assert_eq!(
        full.eval(&a, fibers, Density::DEFAULT),
        full.eval_at(&a, fibers, Density::DEFAULT, &full.absorption())
    );
    assert_eq!(full.absorption().sigma(), Rgb([0.5, 1.0, 2.0]));
}

#[test]
fn between_nodes_the_term_is_within_the_measured_interpolation_error() {
    let nodes = node_tables();
    let full = axis_lut(&nodes, |k| k);
    let mut rng = Pcg32::new(29, 3);
    let mut direct = Box::new(DualTables::ZERO);
    // Worst per-channel relative L1, in the first cell (σ below node 1) and above it.
    let first = axis_node(1);
    let (mut worst_first, mut worst_rel) = (0.0f64, 0.0f64);
    let (mut sum_abs, mut sum_ref) = (0.0f64, 0.0f64);
    for trial in 0..12 {
        // Random colours over the axis: log-uniform σ in [0.01, 100] per channel.
        let sigma = Rgb([0, 1, 2].map(|_| 10f32.powf(rng.uniform() * 4.0 - 2.0)));
        tables_at(sigma, &mut direct);
        // The blob of the tables computed at this colour (channel c at node c, its own
        // colour the default): the reference, with the same half rounding.
        let mut reference = Box::new(DualLut::EMPTY);
        reference
            .decode(&encode(&direct, Attenuation::Coat, 3)[..])
            .unwrap();
        let colour = Absorption::from_sigma(sigma).unwrap();
        let (mut num, mut den) = ([0.0f64; 3], [0.0f64; 3]);
        for _ in 0..400 {
            let (a, fibers) = random_query(&mut rng);
            let got = full.eval_at(&a, fibers, Density::DEFAULT, &colour);
            let want = reference.eval(&a, fibers, Density::DEFAULT);
            for c in 0..3 {
                num[c] += f64::from((got[c] - want[c]).abs());
                den[c] += f64::from(want[c]);
            }
        }
        for c in 0..3 {
            // Relative L1 over the queries, per channel (channels whose term is negligible
            // are skipped: a fully absorbing channel has no dual scattering).
            if den[c] > 1e-3 * 400.0 {
                let e = num[c] / den[c];
                if sigma.0[c] < first {
                    worst_first = worst_first.max(e);
                } else {
                    worst_rel = worst_rel.max(e);
                }
            }
            sum_abs += num[c];
            sum_ref += den[c];
        }
        std::println!(
            "trial {trial}: σ {:?}: relative L1 per channel {:?}",
            sigma.0,
            [0, 1, 2].map(|c| num[c] / den[c].max(1e-30))
        );
    }
    std::println!(
        "axis interpolation: worst per-channel relative L1 {worst_rel:.4} above σ = {first}, \
         {worst_first:.4} below it; overall {:.4}",
        sum_abs / sum_ref
    );
    // Measured (human hair, these 12 colours): 0.022 above the first node, 0.20 in the first
    // cell (σ in (0, 0.21)), where the lossless node σ = 0 differs most from its neighbour;
    // linear in the axis coordinate instead of √σ measured 0.020 and 0.34.
    assert!(
        worst_rel < 0.03,
        "worst relative L1 above node 1: {worst_rel}"
    );
    assert!(
        worst_first < 0.25,
        "worst relative L1 in the first cell: {worst_first}"
    );
}
