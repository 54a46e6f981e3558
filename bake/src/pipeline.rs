//! One preset from parameters to files: profiles → analytic model → sampled tables → f16 blob
//! → dual-scattering tables from the baked LUT → measured error → `<out>/<preset>.exr`,
//! `<out>/<preset>.furlut` and `<out>/<preset>.furdual`, each written atomically.

use crate::colour::{resolve_into, ResolveError};
use crate::fsutil;
use crate::lutfile::{self, LutFile, LutFileError, LutMeta};
use crate::metrics::{compare, ErrorSummary, MetricSet};
use crate::presets::NamedPreset;
use crate::profiles::{self, build_model, CacheOutcome, ProfileOptions};
use crate::tables;
use bcsdf_core::baked::BakedBcsdf;
use bcsdf_core::colour::BaseColour;
use bcsdf_core::dual::{self, Attenuation, DualTables, Quadrature};
use bcsdf_core::lut::{self as core_lut, LutResolution};
use bcsdf_core::{Absorption, FurParams, ParamError, Pigment, Rgb};
use std::fmt;
use std::io;
use std::path::{Path, PathBuf};
use std::time::Instant;

/// File extension of the raw blob.
pub const BLOB_EXTENSION: &str = "furlut";

/// File extension of the OpenEXR file.
pub const EXR_EXTENSION: &str = "exr";

/// File extension of the dual-scattering tables (docs/model.md §13).
pub const DUAL_EXTENSION: &str = "furdual";

/// What [`bake_preset`] does.
#[derive(Clone, Debug)]
pub struct BakeOptions {
    /// Table resolution.
    pub res: LutResolution,
    /// Where the medulla profiles come from.
    pub profiles: ProfileOptions,
    /// Output directory (must exist and be writable, see [`prepare_out_dir`]).
    pub out_dir: PathBuf,
    /// The set the error metrics are measured on (`None`: skip the measurement).
    pub metrics: Option<MetricSet>,
    /// The quadrature of the dual-scattering tables ([`Quadrature::DEFAULT`] unless a coarser
    /// one is asked for, `bake --res-dual`; checked by [`crate::limits::dual_quadrature`]).
    pub dual: Quadrature,
}

/// The steps of a bake, reported as they start.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Step {
    /// Generating or loading the medulla profiles.
    Profiles,
    /// Sampling the analytic model into tables.
    Tables,
    /// Computing the dual-scattering tables from the baked LUT.
    Dual,
    /// Measuring baked against analytic.
    Metrics,
    /// Writing the files.
    Writing,
}

impl Step {
    /// What the step does, for a progress line.
    pub fn describe(self) -> &'static str {
        match self {
            Step::Profiles => "medulla profiles",
            Step::Tables => "sampling tables",
            Step::Dual => "dual-scattering tables",
            Step::Metrics => "measuring error",
            Step::Writing => "writing files",
        }
    }
}

/// What a bake made and measured.
#[derive(Debug)]
pub struct BakeReport {
    /// Preset name.
    pub preset: String,
    /// The EXR file.
    pub exr: PathBuf,
    /// The raw blob.
    pub blob: PathBuf,
    /// Bytes of f16 table data.
    pub table_bytes: usize,
    /// Bytes of the raw blob (header included).
    pub blob_bytes: usize,
    /// Bytes of the EXR file.
    pub exr_bytes: u64,
    /// The dual-scattering tables (`.furdual`).
    pub dual: PathBuf,
    /// Bytes of the `.furdual` file ([`dual::BLOB_LEN`]).
    pub dual_bytes: usize,
    /// Seconds spent computing and encoding the dual-scattering tables.
    pub dual_seconds: f64,
    /// Seconds spent on profiles and, in the energy closure, the residual table (generation
    /// or cache load).
    pub profile_seconds: f64,
    /// Seconds spent sampling and encoding the tables.
    pub table_seconds: f64,
    /// Seconds spent measuring the error.
    pub metric_seconds: f64,
    /// The measured error, when measured.
    pub errors: Option<ErrorSummary>,
    /// What the profile cache did (`None`: the preset needs no profiles).
    pub cache: Option<CacheOutcome>,
    /// Why the residual's cache file was rejected, when it was (and regenerated).
    pub residual_note: Option<String>,
    /// For a preset given as a base colour: the σ_ca found and written as the LUT's default
    /// colour (docs/model.md §14; its `Display` says which channels were out of reach).
    pub base_colour: Option<BaseColour>,
}

impl BakeReport {
    /// Profiles plus tables: the time to bake the preset.
    pub fn bake_seconds(&self) -> f64 {
        self.profile_seconds + self.table_seconds
    }
}

/// Why a bake failed.
#[derive(Debug)]
pub enum BakeError {
    /// The preset's parameters are invalid.
    Params {
        /// Preset name.
        preset: String,
        /// The first invalid parameter.
        error: ParamError,
    },
    /// The profiles could not be made or cached.
    Profiles(profiles::Error),
    /// The output directory cannot be created or written to.
    OutDir {
        /// The directory.
        dir: PathBuf,
        /// What the system said.
        source: io::Error,
    },
    /// Writing a LUT file failed (the previous file, if any, is untouched).
    Write(LutFileError),
    /// The freshly baked blob did not validate (a bug; reported, never written).
    Invalid(bcsdf_core::lut::LutError),
    /// The preset's base colour could not be turned into the LUT's default σ_ca.
    BaseColour {
        /// Preset name.
        preset: String,
        /// Why.
        error: ResolveError,
    },
    /// The preset's name cannot be a file name in the output directory
    /// ([`fsutil::output_path`]); checked before any work.
    Name(fsutil::OutputNameError),
}

impl fmt::Display for BakeError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            BakeError::Params { preset, error } => write!(f, "preset {preset}: {error}"),
            BakeError::Profiles(e) => write!(f, "{e}"),
            BakeError::OutDir { dir, source } => write!(
                f,
                "output directory {} is not writable: {source}",
                dir.display()
            ),
            BakeError::Write(e) => write!(f, "{e}"),
            BakeError::Invalid(e) => write!(f, "baked LUT failed validation: {e}"),
            BakeError::BaseColour { preset, error } => {
                write!(f, "preset {preset}: base_colour: {error}")
            }
            BakeError::Name(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for BakeError {}

/// Creates `dir` if needed and checks a file can be created in it ([`fsutil::prepare_dir`]).
pub fn prepare_out_dir(dir: &Path) -> Result<(), BakeError> {
    fsutil::prepare_dir(dir).map_err(|e| BakeError::OutDir {
        dir: e.dir,
        source: e.source,
    })
}

/// The files a bake of preset `name` writes in `out_dir`.
#[derive(Clone, Debug)]
pub struct OutputPaths {
    /// `<name>.exr`.
    pub exr: PathBuf,
    /// `<name>.furlut`.
    pub blob: PathBuf,
    /// `<name>.furdual`.
    pub dual: PathBuf,
}

/// The three files a bake of preset `name` writes in `out_dir`, built by
/// [`fsutil::output_path`] (never outside `out_dir`).
pub fn output_paths(out_dir: &Path, name: &str) -> Result<OutputPaths, BakeError> {
    let path = |ext| fsutil::output_path(out_dir, name, ext).map_err(BakeError::Name);
    Ok(OutputPaths {
        exr: path(EXR_EXTENSION)?,
        blob: path(BLOB_EXTENSION)?,
        dual: path(DUAL_EXTENSION)?,
    })
}

/// The `.furdual` blob of a baked LUT (docs/model.md §13): [`DualTables::compute`] over the
/// baked evaluator at each node of the blob's absorption axis, at the grey colour of the node
/// (`baked.at(σ_k, σ_k, σ_k)`, [`dual::encode_axis`]), at quadrature `q` (the shipped LUTs:
/// [`Quadrature::DEFAULT`]), encoded
/// for the shipped [`Attenuation::Coat`], tagged with the LUT's checksum and the preset's own
/// colour.
pub fn dual_blob(
    lut_blob: &[u8],
    baked: &BakedBcsdf<'_>,
    q: Quadrature,
) -> Box<[u8; dual::BLOB_LEN]> {
    let mut tables = Box::new(DualTables::ZERO);
    let mut blob: Box<[u8; dual::BLOB_LEN]> = vec![0u8; dual::BLOB_LEN]
        .into_boxed_slice()
        .try_into()
        .expect("BLOB_LEN bytes");
    dual::encode_axis(
        &mut blob,
        &mut tables,
        |sigma, t| {
            let grey = Absorption::from_sigma(Rgb::splat(sigma)).unwrap_or(Absorption::LOSSLESS);
            t.compute(&baked.at(&grey), q);
        },
        Attenuation::Coat,
        core_lut::checksum(lut_blob),
        baked.absorption(),
    );
    blob
}

/// A preset's tables, dual-scattering tables and measured error, computed and not yet
/// written ([`compute`], then [`write_bake`]).
pub struct Computed {
    file: LutFile,
    dual_bytes: Box<[u8; dual::BLOB_LEN]>,
    table_bytes: usize,
    dual_seconds: f64,
    profile_seconds: f64,
    table_seconds: f64,
    metric_seconds: f64,
    cache: Option<CacheOutcome>,
    residual_note: Option<String>,
    base_colour: Option<BaseColour>,
}

/// Bakes one preset into `opts.out_dir`; `on_step` hears each step as it starts. The name is
/// checked ([`output_paths`]) before any work, so a bad name costs nothing.
pub fn bake_preset(
    preset: &NamedPreset,
    opts: &BakeOptions,
    on_step: &dyn Fn(Step),
) -> Result<BakeReport, BakeError> {
    output_paths(&opts.out_dir, &preset.name)?;
    let c = compute(preset, opts, on_step)?;
    on_step(Step::Writing);
    let OutputPaths { exr, blob, dual } = write_bake(&opts.out_dir, &preset.name, &c)?;
    let exr_bytes = std::fs::metadata(&exr).map(|m| m.len()).unwrap_or(0);
    Ok(BakeReport {
        preset: preset.name.clone(),
        exr,
        blob,
        table_bytes: c.table_bytes,
        blob_bytes: c.file.blob.len(),
        exr_bytes,
        dual,
        dual_bytes: c.dual_bytes.len(),
        dual_seconds: c.dual_seconds,
        profile_seconds: c.profile_seconds,
        table_seconds: c.table_seconds,
        metric_seconds: c.metric_seconds,
        errors: c.file.meta.errors,
        cache: c.cache,
        residual_note: c.residual_note,
        base_colour: c.base_colour,
    })
}

/// Everything [`bake_preset`] does before writing: profiles, tables, dual-scattering tables and
/// (when `opts.metrics` asks) the measured error. `opts.out_dir` is not touched.
///
/// A preset given as a base colour (docs/model.md §14) is baked at σ_ca = 0 (the tables do
/// not depend on it), then the colour is inverted with the coat colour table of the baked
/// LUT and the σ_ca found becomes the LUT's default colour ([`crate::colour::resolve_into`]),
/// before the dual-scattering tables and the metrics, which read that colour.
pub fn compute(
    preset: &NamedPreset,
    opts: &BakeOptions,
    on_step: &dyn Fn(Step),
) -> Result<Computed, BakeError> {
    let params_error = |error| BakeError::Params {
        preset: preset.name.clone(),
        error,
    };
    let (input, base) = match preset.input.pigment {
        Pigment::BaseColour(c) => (preset.input.with_sigma_ca(&Absorption::LOSSLESS), Some(c)),
        _ => (preset.input, None),
    };
    let params = FurParams::new(&input).map_err(params_error)?;

    on_step(Step::Profiles);
    let t = Instant::now();
    let (model, cache) = build_model(params, &opts.profiles).map_err(BakeError::Profiles)?;
    let profile_seconds = t.elapsed().as_secs_f64();

    on_step(Step::Tables);
    let t = Instant::now();
    let mut blob = tables::try_bake(&model, &input, opts.res).map_err(BakeError::Profiles)?;
    let table_seconds = t.elapsed().as_secs_f64();
    let base_colour = match base {
        Some(c) => Some(
            resolve_into(&mut blob, c).map_err(|error| BakeError::BaseColour {
                preset: preset.name.clone(),
                error,
            })?,
        ),
        None => None,
    };
    let model = match &base_colour {
        Some(b) => model.at_sigma(&b.absorption).map_err(BakeError::Profiles)?,
        None => model,
    };
    let baked = BakedBcsdf::from_bytes(&blob).map_err(BakeError::Invalid)?;

    on_step(Step::Dual);
    let t = Instant::now();
    let dual_bytes = dual_blob(&blob, &baked, opts.dual);
    let dual_seconds = t.elapsed().as_secs_f64();

    let t = Instant::now();
    let errors = opts.metrics.map(|set| {
        on_step(Step::Metrics);
        compare(&model.model(), &baked, &set)
    });
    let metric_seconds = t.elapsed().as_secs_f64();

    Ok(Computed {
        file: LutFile {
            blob,
            meta: LutMeta {
                preset: preset.name.clone(),
                errors,
            },
        },
        dual_bytes,
        table_bytes: 2 * opts.res.total_values(),
        dual_seconds,
        profile_seconds,
        table_seconds,
        metric_seconds,
        cache,
        residual_note: model.residual_cache_note().map(str::to_owned),
        base_colour,
    })
}

/// Writes a [`Computed`] bake as preset `name` into `out_dir`: the three files of
/// [`output_paths`] (a name that would leave `out_dir` is refused and nothing is written),
/// each atomically; the EXR's metadata carries `name`. Returns the files written.
pub fn write_bake(out_dir: &Path, name: &str, c: &Computed) -> Result<OutputPaths, BakeError> {
    let paths = output_paths(out_dir, name)?;
    let file = LutFile {
        blob: c.file.blob.clone(),
        meta: LutMeta {
            preset: name.to_owned(),
            errors: c.file.meta.errors,
        },
    };
    lutfile::write_exr(&paths.exr, &file).map_err(BakeError::Write)?;
    lutfile::write_blob(&paths.blob, &file.blob).map_err(BakeError::Write)?;
    lutfile::write_dual(&paths.dual, &c.dual_bytes[..]).map_err(BakeError::Write)?;
    Ok(paths)
}
