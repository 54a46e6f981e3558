//! Where a command's BCSDF comes from (`--preset` with `--set` and the medulla profiles, or
//! `--lut`): the analytic model of a preset, built like `viewer probe` always built it, or a
//! baked LUT read from disk.

use crate::catalog;
use crate::cli::{ModelArgs, PresetsArgs, ProfileArgs};
use crate::error::Error;
use bake::lutfile;
use bake::profiles::{self, CacheOutcome, OwnedModel, ProfileKey, ProfileOptions};
use bcsdf_core::baked::BakedBcsdf;
use bcsdf_core::lut;
use bcsdf_core::{
    Absorption, FurBcsdf, FurParams, PhotonBudget, Pigment, ProfileLayout, Resolution,
};
use std::fs::File;
use std::io::{self, IsTerminal, Read, Write};
use std::path::{Path, PathBuf};

/// The first four bytes of every OpenEXR file (the magic number 20000630, little-endian);
/// raw blobs start with [`lut::MAGIC`].
const EXR_MAGIC: [u8; 4] = [0x76, 0x2f, 0x31, 0x01];

/// The loaded BCSDF, owning its data; [`Source::target`] borrows the evaluator.
// One per run, made once and passed by reference: its size does not matter.
#[allow(clippy::large_enum_variant)]
pub enum Source {
    /// The analytic model of a preset, with its medulla profiles.
    Analytic(OwnedModel),
    /// A baked LUT: the validated blob, the file it came from and the colour to read it at.
    Baked {
        /// The LUT file (named in messages).
        path: PathBuf,
        /// The blob (`bcsdf_core::lut` layout), validated.
        blob: Vec<u8>,
        /// The colour (σ_ca) the LUT is evaluated at: its preset's, or `--set`'s.
        colour: Absorption,
    },
}

/// The evaluator of a [`Source`].
// One per run, made once and passed by reference: its size does not matter.
#[allow(clippy::large_enum_variant)]
pub enum Target<'a> {
    /// The analytic model: far field per lobe, near field, sampling.
    Analytic(FurBcsdf<'a>),
    /// The baked tables at one colour: far field per lobe family, sampling.
    Baked(BakedBcsdf<'a>, Absorption),
}

impl Source {
    /// Loads what `args` selects: the LUT of `--lut`, else the preset's model with its
    /// medulla profiles made as `profile_args` say.
    pub fn load(args: &ModelArgs, profile_args: &ProfileArgs) -> Result<Source, Error> {
        match (&args.lut, &args.preset) {
            (Some(path), _) => {
                let blob = read_lut(path)?;
                let colour = lut_colour(path, &blob, &args.set)?;
                Ok(Source::Baked {
                    path: path.clone(),
                    blob,
                    colour,
                })
            }
            (None, Some(preset)) => {
                preset_model(preset, &args.presets, &args.set, profile_args).map(Source::Analytic)
            }
            // clap requires --preset without --lut.
            (None, None) => Err(Error::input("--preset NAME or --lut FILE is required")),
        }
    }

    /// The evaluator over the loaded data.
    pub fn target(&self) -> Result<Target<'_>, Error> {
        match self {
            Source::Analytic(model) => Ok(Target::Analytic(model.model())),
            Source::Baked { path, blob, colour } => BakedBcsdf::from_bytes(blob)
                .map(|lut| Target::Baked(lut, *colour))
                .map_err(|e| Error::input(format!("{}: {e}", path.display()))),
        }
    }
}

/// The colour a LUT is read at: its parameters' σ_ca, or the σ_ca that `set` (`--set`
/// overrides applied to the LUT's parameters) gives. Only the colour keys can change: every
/// other parameter is baked into the tables, and an override of one is refused by name.
/// `base_colour=r,g,b` is inverted with the coat colour table measured from this LUT
/// (docs/model.md §14, a few seconds); a channel out of the fur's reach is clamped and
/// reported on stderr.
pub fn lut_colour(path: &Path, blob: &[u8], set: &[String]) -> Result<Absorption, Error> {
    let header = lut::LutHeader::decode(blob)
        .map_err(|e| Error::input(format!("{}: {e}", path.display())))?;
    let mut input = header.params;
    bake::apply_overrides(&mut input, set).map_err(|e| Error::input(format!("--set {e}")))?;
    let mut rest = input;
    rest.pigment = header.params.pigment;
    if rest != header.params {
        return Err(Error::input(format!(
            "--set with --lut {}: only the colour (sigma_ca, the melanin keys or base_colour) \
             can change; the LUT's other parameters are baked into its tables",
            path.display()
        )));
    }
    if let Pigment::BaseColour(c) = input.pigment {
        let found = bake::colour::base_colour_of(blob, c)
            .map_err(|e| Error::input(format!("--set base_colour: {e}")))?;
        let tag = if found.is_clamped() {
            "warning"
        } else {
            "note"
        };
        let _ = writeln!(io::stderr().lock(), "{tag}: {found}");
        return Ok(found.absorption);
    }
    let params = FurParams::new(&input).map_err(|e| Error::input(format!("--set: {e}")))?;
    Absorption::from_sigma(params.sigma_ca()).map_err(|e| Error::input(format!("--set: {e}")))
}

/// Reads a LUT written by `bake` and returns its validated blob. The reader is chosen by
/// content: OpenEXR for a file starting with the OpenEXR magic number, a raw blob for one
/// starting with the blob's; anything else by name (`*.exr` as OpenEXR, else as a raw blob),
/// whose reader then says what is wrong. A missing, unreadable or corrupt file is bad input,
/// the message naming the file.
pub fn read_lut(path: &Path) -> Result<Vec<u8>, Error> {
    let head = file_head(path);
    let exr = if head.starts_with(&EXR_MAGIC) {
        true
    } else if head.starts_with(&lut::MAGIC) {
        false
    } else {
        path.extension()
            .is_some_and(|x| x.eq_ignore_ascii_case("exr"))
    };
    let result = if exr {
        lutfile::read_exr(path).map(|file| file.blob)
    } else {
        lutfile::read_blob(path)
    };
    result.map_err(Error::input)
}

/// Up to the first 8 bytes of a file; fewer (or none) when it is shorter or cannot be read
/// (the reader that follows reports why).
fn file_head(path: &Path) -> Vec<u8> {
    let mut head = Vec::with_capacity(8);
    if let Ok(file) = File::open(path) {
        let _ = file.take(8).read_to_end(&mut head);
    }
    head
}

/// The profile options `args` select: the cache directory (`--cache-dir`, else the default
/// one, none with `--no-cache`), the seed, the scaled photon budget and the thread count.
pub fn profile_options(args: &ProfileArgs) -> Result<ProfileOptions, Error> {
    let (budget, note) = bake::limits::photon_budget(PhotonBudget::DEFAULT, args.photons_scale)
        .map_err(Error::input)?;
    if let Some(note) = note {
        eprintln!("note: {note}");
    }
    let (threads, note) = bake::limits::threads("--threads", args.threads).map_err(Error::input)?;
    if let Some(note) = note {
        eprintln!("note: {note}");
    }
    let cache_dir = if args.no_cache {
        None
    } else {
        args.cache_dir.clone().or_else(profiles::default_cache_dir)
    };
    Ok(ProfileOptions {
        res: Resolution::DEFAULT,
        budget,
        seed: args.seed,
        cache_dir,
        threads,
    })
}

/// The model for preset `name` (from `presets`) with the `--set` overrides applied: the
/// full model, its medulla profiles from the cache or generated. A rejected (stale or
/// corrupt) cache file is reported as one `note:` line on stderr.
pub fn preset_model(
    name: &str,
    presets: &PresetsArgs,
    set: &[String],
    profile_args: &ProfileArgs,
) -> Result<OwnedModel, Error> {
    let list = catalog::load(presets)?;
    let preset = catalog::find(&list, name)?;
    let mut input = preset.input;
    bake::apply_overrides(&mut input, set).map_err(|e| Error::input(format!("--set {e}")))?;
    let params = FurParams::new(&input)
        .map_err(|e| Error::input(format!("preset `{}` with the overrides: {e}", preset.name)))?;
    let mut opts = profile_options(profile_args)?;
    announce_generation(&params, &opts);
    let (model, outcome) = match profiles::build_model(params, &opts) {
        // The default cache directory is a convenience: when it cannot be used, say so and
        // go on without a cache. A directory the user named is an error.
        Err(e @ profiles::Error::CacheDir { .. }) if profile_args.cache_dir.is_none() => {
            let _ = writeln!(io::stderr().lock(), "note: {e}; continuing without a cache");
            opts.cache_dir = None;
            profiles::build_model(params, &opts).map_err(|e| Error::Failure(e.to_string()))?
        }
        result => result.map_err(|e| Error::Failure(e.to_string()))?,
    };
    if let Some(note) = outcome.as_ref().and_then(CacheOutcome::note) {
        let _ = writeln!(io::stderr().lock(), "note: {note}");
    }
    if let Some(note) = model.residual_cache_note() {
        let _ = writeln!(io::stderr().lock(), "note: {note}");
    }
    Ok(model)
}

/// On a terminal, says that the profiles are about to be generated (it takes seconds) when
/// the parameters need them and the cache holds no file for them. Pipes and scripts get
/// nothing: stderr stays quiet unless a cache file is rejected.
fn announce_generation(params: &FurParams, opts: &ProfileOptions) {
    if !profiles::needs_profiles(params) || !io::stderr().is_terminal() {
        return;
    }
    let key = ProfileKey {
        layout: ProfileLayout::for_params(params, opts.res),
        budget: opts.budget,
        seed: opts.seed,
    };
    let where_to = match &opts.cache_dir {
        Some(dir) if key.path_in(dir).is_ok_and(|p| p.is_file()) => return,
        Some(dir) => format!("cached in {}", dir.display()),
        None => "not cached".to_string(),
    };
    let _ = writeln!(
        io::stderr().lock(),
        "note: generating the medulla profiles for these parameters ({where_to})"
    );
}
