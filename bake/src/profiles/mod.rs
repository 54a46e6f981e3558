//! Medulla profiles for the std tools (docs/model.md §7): parallel generation, a cache file, and
//! a model that owns its profiles.
//!
//! - [`generate`]: [`generate_parallel`] runs the core's per-cell generators
//!   ([`bcsdf_core::medulla::generate_cn_cell`], [`bcsdf_core::medulla::generate_cm_row`]) on
//!   rayon, each cell into its own disjoint chunk of the tables. Every cell draws from its own
//!   random stream, so the tables are the same bits for any thread count and across runs with
//!   the same seed.
//! - [`cache`]: [`load_or_generate`] reuses a cache file when it was made for exactly the same
//!   generator version, layout, photon budget and seed, and otherwise (re)generates and
//!   (re)writes it. A stale or corrupt file is never used: the [`CacheOutcome`] says why it
//!   was replaced. The file format is in the [`cache`] module documentation.
//! - [`model`]: [`build_model`] / [`OwnedModel`]: a [`FurBcsdf`](bcsdf_core::FurBcsdf) for any
//!   valid parameter set, with the profiles when the parameters scatter in the medulla
//!   (σ_ms > 0 and κ > 0) and without them otherwise (the unscattered model is then exact).
//!
//! Everything public in the submodules is re-exported here (`bake::profiles::build_model`).
//!
//! ```no_run
//! use bake::profiles::{build_model, ProfileOptions};
//! use bcsdf_core::{presets, Angles, FurParams};
//!
//! let params = FurParams::new(&presets::find("bobcat").unwrap().input).unwrap();
//! let opts = ProfileOptions {
//!     cache_dir: bake::profiles::default_cache_dir(),
//!     ..ProfileOptions::default()
//! };
//! let (owned, _outcome) = build_model(params, &opts).unwrap();
//! let fur = owned.model();
//! let s = fur.eval_far(&Angles::from_degrees(30.0, -20.0, 45.0).unwrap());
//! # let _ = s;
//! ```

pub mod cache;
pub mod generate;
pub mod model;
pub mod residual;

pub use cache::{
    decode, default_cache_dir, encode, fnv1a64, load_or_generate, CacheError, CacheOutcome,
    ProfileKey, CACHE_EXTENSION, FORMAT_VERSION, LOCK_EXTENSION, MAGIC,
};
pub use generate::{generate_parallel, scale_budget};
pub use model::{build_model, needs_profiles, OwnedModel, ProfileOptions};
pub use residual::{
    decode_residual, encode_residual, generate_residual, generate_residuals,
    load_or_generate_residual, load_or_generate_residuals, ResidualKey, COLOURS_PER_WALK,
    RESIDUAL_EXTENSION, RESIDUAL_FORMAT_VERSION, RESIDUAL_MAGIC,
};

use bcsdf_core::medulla::{MedullaProfiles, PhotonBudget, ProfileError, ProfileLayout};
use std::fmt;
use std::io;
use std::path::PathBuf;

/// The seed used when none is given (`viewer probe --seed` defaults to it).
pub const DEFAULT_SEED: u64 = 1;

/// Medulla profiles in owned memory, with the key they were generated for. The tables are
/// validated at construction, so [`OwnedProfiles::view`] cannot fail.
#[derive(Clone, Debug, PartialEq)]
pub struct OwnedProfiles {
    layout: ProfileLayout,
    budget: PhotonBudget,
    seed: u64,
    cn: Vec<f32>,
    cm: Vec<f32>,
}

impl OwnedProfiles {
    /// Wraps tables in the core's layouts; checks them like [`MedullaProfiles::new`].
    pub fn new(key: ProfileKey, cn: Vec<f32>, cm: Vec<f32>) -> Result<OwnedProfiles, ProfileError> {
        MedullaProfiles::new(key.layout, &cn, &cm)?;
        Ok(OwnedProfiles {
            layout: key.layout,
            budget: key.budget,
            seed: key.seed,
            cn,
            cm,
        })
    }

    /// The borrowed, validated view the model takes.
    pub fn view(&self) -> MedullaProfiles<'_> {
        MedullaProfiles::new(self.layout, &self.cn, &self.cm)
            .expect("OwnedProfiles are validated at construction and immutable")
    }

    /// The layout.
    pub fn layout(&self) -> &ProfileLayout {
        &self.layout
    }

    /// The photon budget they were generated with.
    pub fn budget(&self) -> PhotonBudget {
        self.budget
    }

    /// The seed they were generated with.
    pub fn seed(&self) -> u64 {
        self.seed
    }

    /// Layout, budget and seed.
    pub fn key(&self) -> ProfileKey {
        ProfileKey {
            layout: self.layout,
            budget: self.budget,
            seed: self.seed,
        }
    }

    /// The tables `(C^N, C^M)`.
    pub fn tables(&self) -> (&[f32], &[f32]) {
        (&self.cn, &self.cm)
    }
}

/// Why profiles could not be made or cached.
#[derive(Debug)]
pub enum Error {
    /// The layout is invalid, or the generated tables failed validation.
    Profile(ProfileError),
    /// The local thread pool could not be built.
    ThreadPool(String),
    /// The cache directory cannot be created or written to.
    CacheDir {
        /// The directory.
        dir: PathBuf,
        /// What the system said.
        source: io::Error,
    },
    /// The lock of a cache entry could not be taken (the file system does not support
    /// advisory locks, or the lock file cannot be opened for locking).
    CacheLock {
        /// The entry's lock file.
        path: PathBuf,
        /// What the system said.
        source: io::Error,
    },
    /// A cache file name that would not be directly inside the cache directory (never for
    /// the names [`ProfileKey::stem`] makes).
    CacheName(crate::fsutil::OutputNameError),
    /// Writing or renaming the cache file failed.
    CacheWrite {
        /// The cache file.
        path: PathBuf,
        /// What the system said.
        source: io::Error,
    },
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::Profile(e) => write!(f, "medulla profiles: {e}"),
            Error::ThreadPool(e) => write!(f, "cannot start the profile generator threads: {e}"),
            Error::CacheDir { dir, source } => write!(
                f,
                "profile cache directory {} is not writable: {source}",
                dir.display()
            ),
            Error::CacheLock { path, source } => write!(
                f,
                "cannot lock profile cache entry {}: {source} (use a local --cache-dir or \
                 --no-cache on file systems without advisory locks)",
                path.display()
            ),
            Error::CacheName(e) => write!(f, "profile cache: {e}"),
            Error::CacheWrite { path, source } => {
                write!(f, "cannot write profile cache {}: {source}", path.display())
            }
        }
    }
}

impl std::error::Error for Error {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            Error::CacheDir { source, .. }
            | Error::CacheLock { source, .. }
            | Error::CacheWrite { source, .. } => Some(source),
            Error::CacheName(e) => Some(e),
            _ => None,
        }
    }
}

impl From<ProfileError> for Error {
    fn from(e: ProfileError) -> Error {
        Error::Profile(e)
    }
}
