//! The cross-crate tests, one test binary (`cargo test -p fur-tests --test suite`; a module
//! per concern, filtered by its path: `cargo test -p fur-tests --test suite energy_closure::`).
//!
//! One binary instead of one per file: the core's generic and inlined code is compiled and
//! linked once rather than 26 times, and the harness runs the long tests of different files
//! side by side instead of one file after another.

mod bake_budget;
mod baked_batch;
mod baked_format;
mod base_colour;
mod changelog;
mod colour_budget;
mod energy_closure;
mod far_field_accuracy;
mod fast_math;
mod module_cycles;
mod parameter_schema;
mod presets;
mod profile_generation;
mod profiles;
mod ray_tracer;
mod readme_sampling;
mod reductions;
mod render_baked;
mod residual;
mod robustness;
mod sampling;
mod sampling_chi2;
mod sampling_weights;
mod scattered;
mod scattered_mc;
mod symmetry;
mod white_furnace;
