//! viewer's tests, one test binary (`cargo test -p viewer --test suite`; a module per concern,
//! filtered by its path: `cargo test -p viewer --test suite compare::`), so that the harness
//! runs the long tests of different files side by side.

mod cli;
mod compare;
mod every_path;
mod render_cli;
mod sampling_cli;
mod strand;
mod version;
