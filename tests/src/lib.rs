//! Shared helpers for the cross-crate tests. Everything here is written from MODEL.md
//! directly and shares no code with the closed forms of `bcsdf-core` that it checks.

pub mod furnace;
pub mod quadrature;
pub mod tracer;
