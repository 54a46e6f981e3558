//! # bcsdf-core
//!
//! The double-cylinder fur BCSDF of Yan, Tseng, Jensen and Ramamoorthi (SIGGRAPH Asia 2015),
//! as specified in the project's `MODEL.md`, for embedding anywhere: `#![no_std]`, f32 only,
//! no allocation on the evaluation path, deterministic math through `libm`.
//!
//! ```
//! use bcsdf_core::medulla::{generate, MedullaProfiles, PhotonBudget, ProfileLayout, Resolution};
//! use bcsdf_core::{presets, Angles, FurBcsdf, FurParams, Lobe};
//!
//! let params = FurParams::new(&presets::find("yan-row-a").unwrap().input).unwrap();
//! // Medulla scattering profiles for these parameters, into caller memory (a small photon
//! // budget here; `PhotonBudget::DEFAULT` reaches 1 % noise).
//! let layout = ProfileLayout::for_params(&params, Resolution::DEFAULT);
//! let (mut cn, mut lbar, mut cm) =
//!     (vec![0.0; layout.cn_len()], vec![0.0; layout.cn_len()], vec![0.0; layout.cm_len()]);
//! let budget = PhotonBudget { per_cn_cell: 500, per_cm_row: 500 };
//! generate(&layout, &budget, 1, &mut cn, &mut lbar, &mut cm).unwrap();
//! let profiles = MedullaProfiles::new(layout, &cn, &lbar, &cm).unwrap();
//! let model: FurBcsdf = FurBcsdf::new(params, profiles).unwrap();
//!
//! let angles = Angles::from_degrees(30.0, -20.0, 45.0).unwrap();
//! let far = model.eval_far(&angles); // h integrated, 11 lobes
//! let near = model.eval_near(&angles, 0.3); // at offset h = 0.3
//! assert!(far.total().0.iter().all(|v| v.is_finite() && *v >= 0.0));
//! assert!(near.get(Lobe::TttTs).max_channel() > 0.0);
//! ```
//!
//! Data flow: [`FurParams`] (validated) → [`medulla`] profiles → [`FurBcsdf`] → [`Lobes`] per
//! evaluation. Module names follow the model: [`fresnel`], [`geometry`], [`unscattered`],
//! [`scattered`], [`medulla`], [`longitudinal`], [`gaussian`], [`far_field`].
//! [`FurBcsdf::unscattered`] builds the model without profiles (exact when σ_ms = 0 or κ = 0).
#![no_std]
#![deny(missing_docs)]

pub mod baked;
pub mod bcsdf;
pub mod far_field;
pub mod frame;
pub mod fresnel;
pub mod gaussian;
pub mod geometry;
pub mod lobes;
pub mod longitudinal;
pub mod lut;
pub mod math;
pub mod medulla;
pub mod model;
pub mod params;
pub mod pigment;
pub mod presets;
pub mod rng;
pub mod sampling;
pub mod scattered;
pub mod shader;
pub mod spectrum;
pub mod unscattered;

pub use bcsdf::{Bcsdf, Sample, SampledDirection};
pub use frame::{AngleError, Angles, Frame, Vec3};
pub use lobes::{
    Families, Lobe, LobeFamily, LobeGroup, Lobes, FAMILY_COUNT, LOBE_COUNT, UNSCATTERED_COUNT,
};
#[cfg(feature = "micromath")]
pub use math::FastMath;
pub use math::{Libm, Math};
pub use medulla::{MedullaProfiles, PhotonBudget, ProfileError, ProfileLayout, Resolution};
pub use model::{FurBcsdf, MODEL_VERSION};
pub use params::{
    Domain, FurParams, FurParamsInput, InputError, ParamDefault, ParamError, ParamName, ParamSpec,
    ParamValue, SCHEMA,
};
pub use pigment::Pigment;
pub use spectrum::Rgb;
