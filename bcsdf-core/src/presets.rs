//! Built-in presets (docs/model.md §9) as constants, for no_std users.
//!
//! The human-editable source is `bcsdf-core/presets.toml`, which the std tools read (and
//! which users copy to make their own); `tests/tests/presets.rs` checks that these constants
//! and that file agree exactly.

use crate::params::FurParamsInput;
use crate::pigment::Pigment;
use crate::spectrum::Rgb;

/// A named parameter set and where its numbers come from.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Preset {
    /// Preset name (`viewer probe --preset NAME`).
    pub name: &'static str,
    /// Provenance of the numbers.
    pub source: &'static str,
    /// The parameters (validated when a model is built).
    pub input: FurParamsInput,
}

/// The text of `presets.toml` (docs/model.md §9), the human-editable source of [`PRESETS`]:
/// it ships inside this crate so that the std tools (`bake::presets`) parse the same file
/// whether built in the repository or from a packaged crate.
pub const PRESETS_TOML: &str = include_str!("../presets.toml");

/// The built-in presets, in `presets.toml` order.
pub const PRESETS: [Preset; 5] = [
    Preset {
        name: "yan-row-a",
        source: "docs/model.md §9 row A: default parameters of independent re-implementations of Yan et al. 2015 (species not recorded); single-channel sigma_ca used for all of RGB",
        input: FurParamsInput {
            eta_c: 1.55,
            pigment: Pigment::Absorption(Rgb::splat(0.64)),
            alpha_deg: 5.48,
            beta_m_deg: 11.64,
            beta_n_deg: Some(7.49),
            l: 0.47,
            kappa: 0.88,
            eta_m: None,
            sigma_ms: 1.69,
            sigma_ma: 0.17,
            g: 0.44,
        },
    },
    Preset {
        name: "yan-row-b",
        source: "docs/model.md §9 row B: default parameters of independent re-implementations of Yan et al. 2015 (species not recorded); single-channel sigma_ca used for all of RGB",
        input: FurParamsInput {
            eta_c: 1.49,
            pigment: Pigment::Absorption(Rgb::splat(0.39)),
            alpha_deg: 2.64,
            beta_m_deg: 9.45,
            beta_n_deg: Some(17.63),
            l: 0.68,
            kappa: 0.86,
            eta_m: None,
            sigma_ms: 3.15,
            sigma_ma: 0.21,
            g: 0.79,
        },
    },
    Preset {
        name: "yan-row-c",
        source: "docs/model.md §9 row C (species not recorded; the row gives no sigma_ca): colour is this project's choice, eumelanin 0.3 + pheomelanin 0.3 (d'Eon 2011 coefficients)",
        input: FurParamsInput {
            eta_c: 1.19,
            pigment: Pigment::Melanin {
                eumelanin: 0.3,
                pheomelanin: 0.3,
            },
            alpha_deg: 1.81,
            beta_m_deg: 7.44,
            beta_n_deg: Some(6.88),
            l: 2.0,
            kappa: 0.65,
            eta_m: None,
            sigma_ms: 2.30,
            sigma_ma: 0.14,
            g: 0.08,
        },
    },
    Preset {
        name: "human-hair",
        source: "project choice: kappa = 0 limit (Marschner et al. 2003 hair); eta 1.55 and tilt/roughness in Marschner's typical ranges, brown colour from eumelanin 1.3 + pheomelanin 0.1 (d'Eon 2011 coefficients)",
        input: FurParamsInput {
            eta_c: 1.55,
            pigment: Pigment::Melanin {
                eumelanin: 1.3,
                pheomelanin: 0.1,
            },
            alpha_deg: 2.0,
            beta_m_deg: 7.0,
            beta_n_deg: Some(10.0),
            l: 0.5,
            kappa: 0.0,
            eta_m: None,
            sigma_ms: 0.0,
            sigma_ma: 0.0,
            g: 0.0,
        },
    },
    Preset {
        name: "air-medulla",
        source: "project choice, illustrative: a medulla of lower index than the cortex (eta_m 1.2 < eta_c 1.55), so that all eight paths and total internal reflection at the medulla are exercised; not a measured species",
        input: FurParamsInput {
            eta_c: 1.55,
            pigment: Pigment::Melanin {
                eumelanin: 0.5,
                pheomelanin: 0.0,
            },
            alpha_deg: 3.0,
            beta_m_deg: 8.0,
            beta_n_deg: Some(9.0),
            l: 1.0,
            kappa: 0.5,
            eta_m: Some(1.2),
            sigma_ms: 2.0,
            sigma_ma: 0.1,
            g: 0.6,
        },
    },
];

/// The built-in preset called `name`.
///
/// ```
/// use bcsdf_core::{presets, FurParams};
///
/// let preset = presets::find("yan-row-a").unwrap();
/// assert_eq!(preset.input.eta_c, 1.55);
/// let params = FurParams::new(&preset.input).unwrap();
/// assert!((params.beta_m().to_degrees() - 11.64).abs() < 1e-4);
/// assert!(presets::find("no-such-fur").is_none());
/// ```
#[must_use]
pub fn find(name: &str) -> Option<&'static Preset> {
    PRESETS.iter().find(|p| p.name == name)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::params::FurParams;

    #[test]
    fn every_preset_is_valid_findable_and_named_once() {
        for (i, p) in PRESETS.iter().enumerate() {
            assert!(FurParams::new(&p.input).is_ok(), "{}", p.name);
            assert_eq!(find(p.name), Some(p));
            assert!(!p.source.is_empty());
            assert!(PRESETS[..i].iter().all(|q| q.name != p.name), "{}", p.name);
        }
        assert_eq!(find("Yan-Row-A"), None, "names are case-sensitive");
    }
}
