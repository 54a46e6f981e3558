//! Importance sampling of the far field (docs/model.md §10): the analytic model's mixture
//! ([`analytic`]) and the baked tables' ([`baked`]); the shared one-dimensional building
//! blocks live in `crate::sample1d` (below the tables and the model, which use them too) and
//! are re-exported here.
//!
//! Every sampler here is paired with the density it draws from, written next to it, so that
//! `pdf` can return exactly the density of what `sample` does.
//!
//! Guards are written `!(x > 0.0)` on purpose: they are true for NaN too.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod analytic;
pub mod baked;
pub mod sliver;

pub use crate::sample1d::{
    choose, gaussian_mass, invert_linear, invert_weighted_linear, linear_mass, sample_gaussian,
    unit, weighted_linear_mass, ONE_MINUS_EPSILON,
};
