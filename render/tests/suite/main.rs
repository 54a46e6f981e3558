//! render's tests, one test binary (`cargo test -p render --test suite`; a module per concern,
//! filtered by its path: `cargo test -p render --test suite dual::`): the analytic fixtures
//! are compiled once, and the harness runs the long tests of different files side by side.

mod common;
mod determinism;
mod dual;
mod mis_consistency;
mod strand_colour;
mod white_furnace;
