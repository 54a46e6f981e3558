//! Shared helpers for the cross-crate tests. Everything here is written from docs/model.md
//! directly and shares no code with the closed forms of `bcsdf-core` that it checks.

pub mod chi2;
pub mod cross_section_mc;
pub mod furnace;
pub mod per_preset;
pub mod profiles_ref;
pub mod quadrature;
pub mod tracer;

use bcsdf_core::lut::LutResolution;

/// The default LUT resolution with the fewest absorption planes (three), for the tests of
/// lossless fibers (σ_ca = 0): σ_ca = 0 is the axis's first node, read with weights exactly
/// (1, 0, 0), so the other planes never reach a value those tests evaluate; with 22 planes an
/// energy-closure bake simulates eight residual tables instead of one.
pub const LOSSLESS_RESOLUTION: LutResolution = LutResolution {
    n_abs: 3,
    ..LutResolution::DEFAULT
};
