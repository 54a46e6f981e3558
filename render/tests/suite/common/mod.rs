//! Shared by render's tests: the analytic model of a preset (profiles generated in memory
//! with a small photon budget), the presets the tests use, the statistics, and coarse
//! dual-scattering tables.
#![allow(dead_code)]

use bcsdf_core::dual::{DualTables, Quadrature};
use bcsdf_core::medulla::{generate_cm_row, generate_cn_cell};
use bcsdf_core::presets::{Preset, PRESETS};
use bcsdf_core::residual::{ResidualLayout, ResidualTable};
use bcsdf_core::residual_gen as residual;
use bcsdf_core::{
    presets, Closure, FurBcsdf, FurParams, FurParamsInput, MedullaProfiles, PhotonBudget,
    ProfileLayout, Resolution,
};
use rayon::prelude::*;
use render::Estimate;

/// Pigment-free hair (κ = 0: no medulla).
pub fn plain() -> &'static Preset {
    presets::find("human-hair").expect("human-hair preset")
}

/// The first built-in preset with a scattering medulla (κ > 0, σ_ms > 0).
pub fn medullated() -> &'static Preset {
    PRESETS
        .iter()
        .find(|p| p.input.kappa > 0.0 && p.input.sigma_ms > 0.0)
        .expect("a medullated preset")
}

/// Calls `f` with the analytic model of `input` (profiles, when needed, generated here from
/// a small photon budget: the tests need a model, not the preset's reference profiles). In the
/// energy closure the model gets its residual table (docs/model.md §12), generated here with
/// the default layout.
pub fn with_model<R>(input: &FurParamsInput, f: impl FnOnce(&FurBcsdf<'_>) -> R) -> R {
    let params = FurParams::new(input).expect("valid parameters");
    if input.kappa > 0.0 && input.sigma_ms > 0.0 {
        let layout = ProfileLayout::for_params(&params, Resolution::DEFAULT);
        let (mut cn, mut cm) = (vec![0.0; layout.cn_len()], vec![0.0; layout.cm_len()]);
        let budget = PhotonBudget {
            per_cn_cell: 400,
            per_cm_row: 400,
        };
        generate_parallel(&layout, &budget, &mut cn, &mut cm);
        let profiles = MedullaProfiles::new(layout, &cn, &cm).expect("profiles");
        with_residual(FurBcsdf::new(params, profiles).expect("model"), f)
    } else {
        with_residual(FurBcsdf::unscattered(params), f)
    }
}

/// `bcsdf_core::medulla::generate` (seed 1) with its cells and rows as rayon tasks: the same
/// bits, each cell and row having its own random stream.
fn generate_parallel(
    layout: &ProfileLayout,
    budget: &PhotonBudget,
    cn: &mut [f32],
    cm: &mut [f32],
) {
    cn.par_chunks_exact_mut(layout.res.n_psi)
        .enumerate()
        .for_each(|(cell, c)| {
            generate_cn_cell(layout, cell, budget, 1, c);
        });
    let n_out = layout.res.n_out;
    let (back, front) = cm.split_at_mut(layout.res.n_in * n_out);
    back.par_chunks_exact_mut(n_out)
        .zip(front.par_chunks_exact_mut(n_out))
        .enumerate()
        .for_each(|(row, (b, f))| {
            generate_cm_row(layout, row, budget, 1, b, f);
        });
}

/// `f` of `model`, with its residual table in the energy closure.
fn with_residual<R>(model: FurBcsdf<'_>, f: impl FnOnce(&FurBcsdf<'_>) -> R) -> R {
    if model.params().closure() != Closure::Energy {
        return f(&model);
    }
    let layout = ResidualLayout::DEFAULT;
    let mut data = vec![0.0; layout.len()];
    // `residual::generate`'s rows and mean nodes, each a task (the same bits: every row has
    // its own random stream).
    data[..layout.means_offset()]
        .par_chunks_mut(layout.row_len())
        .enumerate()
        .for_each(|(row, chunk)| {
            residual::generate_row(&model, &layout, row, 1, chunk);
        });
    let energies: Vec<_> = (0..layout.n_mean())
        .into_par_iter()
        .map(|i| residual::mean_node_energy(&model, &layout, i))
        .collect();
    residual::fill_means(&layout, |i| energies[i], &mut data);
    let table = ResidualTable::new(*model.params(), layout, &data).expect("residual table");
    f(&model
        .with_residual(table)
        .expect("residual for these parameters"))
}

/// z-score of the difference of two estimates, channel by channel (largest |z|).
pub fn z(a: &Estimate, b: &Estimate) -> f64 {
    (0..3)
        .map(|c| {
            let se = (a.std_error[c].powi(2) + b.std_error[c].powi(2)).sqrt();
            if se > 0.0 {
                (a.mean[c] - b.mean[c]).abs() / se
            } else if a.mean[c] == b.mean[c] {
                0.0
            } else {
                f64::INFINITY
            }
        })
        .fold(0.0, f64::max)
}

/// A preset's dual-scattering tables at a coarse quadrature (32 θ × 16 |φ|): for tests that need a term, not its
/// accuracy.
pub fn coarse_dual_tables(model: &FurBcsdf<'_>) -> Box<DualTables> {
    let mut tables = Box::new(DualTables::ZERO);
    tables.compute(
        model,
        Quadrature {
            theta_steps: 32,
            phi_steps: 16,
        },
    );
    tables
}
