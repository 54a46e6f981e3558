//! # bake
//!
//! The `std` side of the fur BCSDF (`bcsdf-core` is `no_std`): the LUT baker — sampling the
//! analytic far field into half-float tables ([`tables`]), writing and reading them as
//! OpenEXR and raw blobs ([`lutfile`]), the shared baked-vs-analytic error metrics
//! ([`metrics`]), one preset end to end ([`pipeline`], used by the `bake` binary) — plus
//! preset files, `key=value` parameter overrides, a base colour as a LUT's default colour
//! ([`colour`]), splitting a preset list over N jobs
//! ([`shard`], `bake --shard K/N`), and generating (in parallel) and caching
//! the medulla profiles the full model needs ([`profiles`]). [`fsutil`] writes files atomically
//! and checks output folders (the viewer uses it too).
//!
//! ```
//! let presets = bake::presets::builtin().unwrap();
//! let row_a = bake::presets::find(&presets, "bobcat").unwrap();
//! let mut input = row_a.input;
//! bake::apply_overrides(&mut input, ["kappa=0.5", "sigma_ca=0.2,0.3,0.6"]).unwrap();
//! assert!(bcsdf_core::FurParams::new(&input).is_ok());
//! ```
#![deny(missing_docs)]

pub mod colour;
pub mod fsutil;
pub mod limits;
pub mod lutfile;
pub mod metrics;
pub mod overrides;
pub mod pipeline;
pub mod presets;
pub mod profiles;
pub mod shard;
pub mod tables;

pub use overrides::{apply_overrides, Override, OverrideError, OverrideErrorKind};
pub use presets::{NamedPreset, PresetError};
