//! What the GPU tests (`agreement.rs`, `dual.rs`) share: a preset's LUT at test size and the
//! rule for a machine without an adapter.

use bake::profiles::{build_model, scale_budget, ProfileOptions};
use bcsdf_core::lut::LutResolution;
use bcsdf_core::medulla::PhotonBudget;
use bcsdf_core::{presets, Closure, FurParams, FurParamsInput};
use bcsdf_gpu::GpuError;
use std::collections::BTreeMap;
use std::path::PathBuf;
use std::sync::{Arc, Mutex, OnceLock};

/// The preset's LUT in `closure` at resolution `res`, from medulla profiles at 2 % of
/// the default photon budget (cached in the target folder across test runs), baked once per
/// test process: the tests of a file that ask for the same LUT share it.
pub fn preset_lut(name: &str, closure: Closure, res: LutResolution) -> Vec<u8> {
    type Baked = Arc<OnceLock<Vec<u8>>>;
    static LUTS: Mutex<BTreeMap<String, Baked>> = Mutex::new(BTreeMap::new());
    let key = format!("{name} {closure:?} {res:?}");
    // The map's lock only finds the entry; the bake runs under the entry's own OnceLock, so
    // different LUTs bake in parallel and a second asker of the same one waits for it.
    let entry = Arc::clone(LUTS.lock().unwrap().entry(key).or_default());
    entry
        .get_or_init(|| bake_preset(name, closure, res))
        .clone()
}

fn bake_preset(name: &str, closure: Closure, res: LutResolution) -> Vec<u8> {
    let preset = presets::find(name).unwrap();
    let input = FurParamsInput {
        closure,
        ..preset.input
    };
    let opts = ProfileOptions {
        budget: scale_budget(PhotonBudget::DEFAULT, 0.02).unwrap(),
        cache_dir: Some(PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("fur-profile-cache")),
        ..ProfileOptions::default()
    };
    let (model, _) = build_model(FurParams::new(&input).unwrap(), &opts).unwrap();
    bake::tables::bake(&model, &input, res)
}

/// The GPU evaluator `made` built, or None (after printing why) when the machine has no
/// adapter and the GPU is not required (`FUR_BCSDF_REQUIRE_GPU=1`, set by `.ci/run`, makes
/// a missing adapter a failure). Any other error fails the test.
pub fn or_skip<T>(made: Result<T, GpuError>) -> Option<T> {
    match made {
        Ok(g) => Some(g),
        Err(e @ GpuError::NoAdapter(_)) => {
            if std::env::var("FUR_BCSDF_REQUIRE_GPU").as_deref() == Ok("1") {
                panic!("FUR_BCSDF_REQUIRE_GPU=1 but {e}");
            }
            println!("skipped: no GPU adapter ({e})");
            None
        }
        Err(e) => panic!("{e}"),
    }
}
