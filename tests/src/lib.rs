//! Shared helpers for the cross-crate tests. Everything here is written from docs/model.md
//! directly and shares no code with the closed forms of `bcsdf-core` that it checks.

pub mod chi2;
pub mod cross_section_mc;
pub mod furnace;
pub mod per_preset;
pub mod profiles_ref;
pub mod quadrature;
pub mod tracer;
