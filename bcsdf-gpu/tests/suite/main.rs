//! The GPU tests, one test binary (`cargo test -p bcsdf-gpu --test suite`; a module per
//! concern, filtered by its path: `cargo test -p bcsdf-gpu --test suite agreement::`): one
//! build of the fixtures, and the harness runs the tests of different files side by side.

mod agreement;
mod colour;
mod common;
mod dual;
mod translations;
