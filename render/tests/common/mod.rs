//! Shared by render's tests: the analytic model of a preset (profiles generated in memory
//! with a small photon budget), the presets the tests use, and the statistics.
#![allow(dead_code)]

use bcsdf_core::medulla::generate;
use bcsdf_core::presets::{Preset, PRESETS};
use bcsdf_core::residual::{ResidualLayout, ResidualTable};
use bcsdf_core::residual_gen as residual;
use bcsdf_core::{
    presets, Closure, FurBcsdf, FurParams, FurParamsInput, MedullaProfiles, PhotonBudget,
    ProfileLayout, Resolution,
};
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
        generate(&layout, &budget, 1, &mut cn, &mut cm).expect("profiles");
        let profiles = MedullaProfiles::new(layout, &cn, &cm).expect("profiles");
        with_residual(FurBcsdf::new(params, profiles).expect("model"), f)
    } else {
        with_residual(FurBcsdf::unscattered(params), f)
    }
}

/// `f` of `model`, with its residual table in the energy closure.
fn with_residual<R>(model: FurBcsdf<'_>, f: impl FnOnce(&FurBcsdf<'_>) -> R) -> R {
    if model.params().closure() != Closure::Energy {
        return f(&model);
    }
    let layout = ResidualLayout::DEFAULT;
    let mut data = vec![0.0; layout.len()];
    residual::generate(&model, &layout, 1, &mut data).expect("residual table");
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
