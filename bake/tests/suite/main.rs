//! bake's tests, one test binary (`cargo test -p bake --test suite`; a module per concern,
//! filtered by its path: `cargo test -p bake --test suite shard_cli::`), so that the harness
//! runs the long tests of different files side by side.

mod cache_cli;
mod cli_support;
mod common;
mod lutfile;
mod lutfile_damage;
mod names_cli;
mod presets_cli;
mod shard_cli;
mod version;
