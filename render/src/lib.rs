//! # render
//!
//! A path-traced reference renderer of fur coats with the fur BCSDF (docs/model.md §11,
//! "Rendering"): light followed through thousands of fibers, each fiber a far-field
//! scatterer evaluated and importance-sampled through [`bcsdf_core::Bcsdf`] in its own frame.
//!
//! - [`scenes`]: the built-in scenes (`furnace`, `patch`, `ball`), deterministic from a seed;
//!   fibers are chains of tapering cylinder segments ([`fiber`]) in a SAH BVH ([`accel`],
//!   the `bvh` crate), on Lambertian skin and ground ([`surface`]), lit by lights at
//!   infinity ([`light`]) and seen by a pinhole [`camera`].
//! - [`integrator`]: unidirectional path tracing, next-event estimation with the power
//!   heuristic, Russian roulette, per-pixel random streams ([`sampler`]): the same bits for
//!   any thread count.
//! - [`scatter`]: what the integrator asks of a fiber; [`scatter::One`] wraps any `Bcsdf`
//!   (the analytic `FurBcsdf` or the baked `BakedBcsdf`), [`scatter::Guided`] evaluates one
//!   and samples with another.
//! - [`strand`]: what a fiber scatters like at a hit ([`strand::FiberMaterial`]): any
//!   scatterer (one colour), or a colour per strand from root to tip with a per-strand
//!   variation ([`strand::Coloured`], docs/model.md §14); [`pattern`]: a colour per fiber
//!   from where its root is on the body (stripes, an image).
//! - [`method`]: `path`, and the engine approximations `single` and `dual` (dual scattering,
//!   docs/model.md §13) judged against it.
//! - [`coat`]: the thick coat slab under a white sky (docs/model.md §14) whose rendered mean is
//!   the coat colour a base colour asks for.
//! - [`compare`]: an approximation's image against the reference (the dual-scattering mean and tile
//!   metrics) and the side-by-side pictures of `viewer render --compare`.
//! - [`film`], [`output`]: the image with per-pixel standard errors, bounce-order energies,
//!   and the EXR/PNG bytes.
//!
//! ```
//! use bcsdf_core::{presets, FurBcsdf, FurParams};
//! use render::{integrator, scatter::One, scenes};
//!
//! let params = FurParams::new(&presets::find("human-hair").unwrap().input).unwrap();
//! let hair: FurBcsdf = FurBcsdf::unscattered(params);
//! let scene = scenes::build(&scenes::SceneOptions {
//!     kind: scenes::SceneKind::Patch,
//!     fibers: Some(200),
//!     seed: 1,
//!     aspect: 1.0,
//! });
//! let settings = integrator::Settings::new(8, 8, 2);
//! let r = integrator::render(&scene, &One(&hair), &settings).unwrap();
//! assert!(r.image.whole().mean.iter().all(|m| m.is_finite() && *m >= 0.0));
//! ```
#![deny(missing_docs)]

pub mod accel;
pub mod camera;
pub mod coat;
pub mod compare;
pub mod fiber;
pub mod film;
pub mod integrator;
pub mod light;
pub mod method;
pub mod output;
pub mod pattern;
pub mod sampler;
pub mod scatter;
pub mod scene;
pub mod scenes;
pub mod strand;
pub mod surface;

pub use film::{Estimate, Image, Render};
pub use integrator::{render, render_method, Settings, SettingsError, Strategy};
pub use method::{Method, MethodKind};
pub use scenes::{SceneKind, SceneOptions};
