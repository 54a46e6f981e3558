//! Built-in presets (docs/model.md §9) as constants, for no_std users.
//!
//! The human-editable source is `bcsdf-core/presets.toml`, which the std tools read (and
//! which users copy to make their own); `tests/tests/suite/presets.rs` checks that these constants
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
// Rabbit's α is 3.14° as the table prints it (docs/model.md §9), not an approximation of π.
#[allow(clippy::approx_constant)]
pub const PRESETS: [Preset; 12] = [
    Preset {
        name: "bobcat",
        source: "Yan, Sun, Jensen and Ramamoorthi 2017 (A BSSRDF Model for Efficient Rendering of Fur with Global Illumination), Table 4, fitted to the 2015 paper's measurements (docs/model.md §9), row 'bobcat'; l = 0.47 from a Mitsuba fur plugin (zibo-ye/mitsuba, src/bsdfs/yanfur.cpp); sigma_ca: the single-channel fit used for R, G and B (grey); eta used for eta_c and eta_m",
        input: FurParamsInput {
            eta_c: 1.69,
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
            closure: crate::params::Closure::Energy,
        },
    },
    Preset {
        name: "cat",
        source: "Yan, Sun, Jensen and Ramamoorthi 2017 (A BSSRDF Model for Efficient Rendering of Fur with Global Illumination), Table 4, fitted to the 2015 paper's measurements (docs/model.md §9), row 'cat'; l not published: 0.5, the plain dielectric interface (docs/model.md §4); sigma_ca: the single-channel fit used for R, G and B (grey); eta used for eta_c and eta_m",
        input: FurParamsInput {
            eta_c: 1.36,
            pigment: Pigment::Absorption(Rgb::splat(0.06)),
            alpha_deg: 3.65,
            beta_m_deg: 5.66,
            beta_n_deg: Some(1.34),
            l: 0.5,
            kappa: 0.87,
            eta_m: None,
            sigma_ms: 2.47,
            sigma_ma: 0.12,
            g: 0.60,
            closure: crate::params::Closure::Energy,
        },
    },
    Preset {
        name: "deer",
        source: "Yan, Sun, Jensen and Ramamoorthi 2017 (A BSSRDF Model for Efficient Rendering of Fur with Global Illumination), Table 4, fitted to the 2015 paper's measurements (docs/model.md §9), row 'deer'; l not published: 0.5, the plain dielectric interface (docs/model.md §4); sigma_ca: the single-channel fit used for R, G and B (grey); eta used for eta_c and eta_m",
        input: FurParamsInput {
            eta_c: 1.60,
            pigment: Pigment::Absorption(Rgb::splat(1.39)),
            alpha_deg: 3.52,
            beta_m_deg: 7.00,
            beta_n_deg: Some(4.53),
            l: 0.5,
            kappa: 0.91,
            eta_m: None,
            sigma_ms: 2.51,
            sigma_ma: 0.09,
            g: 0.46,
            closure: crate::params::Closure::Energy,
        },
    },
    Preset {
        name: "dog",
        source: "Yan, Sun, Jensen and Ramamoorthi 2017 (A BSSRDF Model for Efficient Rendering of Fur with Global Illumination), Table 4, fitted to the 2015 paper's measurements (docs/model.md §9), row 'dog'; l not published: 0.5, the plain dielectric interface (docs/model.md §4); sigma_ca: the single-channel fit used for R, G and B (grey); eta used for eta_c and eta_m",
        input: FurParamsInput {
            eta_c: 1.58,
            pigment: Pigment::Absorption(Rgb::splat(0.01)),
            alpha_deg: 2.94,
            beta_m_deg: 5.77,
            beta_n_deg: Some(18.94),
            l: 0.5,
            kappa: 0.68,
            eta_m: None,
            sigma_ms: 2.44,
            sigma_ma: 0.00,
            g: 0.26,
            closure: crate::params::Closure::Energy,
        },
    },
    Preset {
        name: "mouse",
        source: "Yan, Sun, Jensen and Ramamoorthi 2017 (A BSSRDF Model for Efficient Rendering of Fur with Global Illumination), Table 4, fitted to the 2015 paper's measurements (docs/model.md §9), row 'mouse'; l not published: 0.5, the plain dielectric interface (docs/model.md §4); sigma_ca: the single-channel fit used for R, G and B (grey); eta used for eta_c and eta_m",
        input: FurParamsInput {
            eta_c: 1.35,
            pigment: Pigment::Absorption(Rgb::splat(0.04)),
            alpha_deg: 0.55,
            beta_m_deg: 8.39,
            beta_n_deg: Some(2.80),
            l: 0.5,
            kappa: 0.66,
            eta_m: None,
            sigma_ms: 1.34,
            sigma_ma: 0.06,
            g: 0.36,
            closure: crate::params::Closure::Energy,
        },
    },
    Preset {
        name: "rabbit",
        source: "Yan, Sun, Jensen and Ramamoorthi 2017 (A BSSRDF Model for Efficient Rendering of Fur with Global Illumination), Table 4, fitted to the 2015 paper's measurements (docs/model.md §9), row 'rabbit'; l not published: 0.5, the plain dielectric interface (docs/model.md §4); sigma_ca: the single-channel fit used for R, G and B (grey); eta used for eta_c and eta_m",
        input: FurParamsInput {
            eta_c: 1.47,
            pigment: Pigment::Absorption(Rgb::splat(0.24)),
            alpha_deg: 3.14,
            beta_m_deg: 11.91,
            beta_n_deg: Some(10.52),
            l: 0.5,
            kappa: 0.79,
            eta_m: None,
            sigma_ms: 0.78,
            sigma_ma: 0.10,
            g: 0.12,
            closure: crate::params::Closure::Energy,
        },
    },
    Preset {
        name: "raccoon",
        source: "Yan, Sun, Jensen and Ramamoorthi 2017 (A BSSRDF Model for Efficient Rendering of Fur with Global Illumination), Table 4, fitted to the 2015 paper's measurements (docs/model.md §9), row 'raccoon'; l = 2 from a pbrt-v3 fur implementation (hcaseyal/pbrt-final-project, finalProject/fur.pbrt); sigma_ca: the single-channel fit used for R, G and B (grey); eta used for eta_c and eta_m",
        input: FurParamsInput {
            eta_c: 1.19,
            pigment: Pigment::Absorption(Rgb::splat(0.25)),
            alpha_deg: 1.81,
            beta_m_deg: 7.44,
            beta_n_deg: Some(6.88),
            l: 2.0,
            kappa: 0.65,
            eta_m: None,
            sigma_ms: 2.30,
            sigma_ma: 0.14,
            g: 0.08,
            closure: crate::params::Closure::Energy,
        },
    },
    Preset {
        name: "red-fox",
        source: "Yan, Sun, Jensen and Ramamoorthi 2017 (A BSSRDF Model for Efficient Rendering of Fur with Global Illumination), Table 4, fitted to the 2015 paper's measurements (docs/model.md §9), row 'red fox'; l = 0.68 from a pbrt-v3 fur implementation (hcaseyal/pbrt-final-project, finalProject/fur.pbrt); sigma_ca: the single-channel fit used for R, G and B (grey); eta used for eta_c and eta_m",
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
            closure: crate::params::Closure::Energy,
        },
    },
    Preset {
        name: "springbok",
        source: "Yan, Sun, Jensen and Ramamoorthi 2017 (A BSSRDF Model for Efficient Rendering of Fur with Global Illumination), Table 4, fitted to the 2015 paper's measurements (docs/model.md §9), row 'springbok'; l not published: 0.5, the plain dielectric interface (docs/model.md §4); sigma_ca: the single-channel fit used for R, G and B (grey); eta used for eta_c and eta_m",
        input: FurParamsInput {
            eta_c: 1.48,
            pigment: Pigment::Absorption(Rgb::splat(0.32)),
            alpha_deg: 4.61,
            beta_m_deg: 8.02,
            beta_n_deg: Some(11.46),
            l: 0.5,
            kappa: 0.82,
            eta_m: None,
            sigma_ms: 2.45,
            sigma_ma: 0.31,
            g: 0.19,
            closure: crate::params::Closure::Energy,
        },
    },
    Preset {
        name: "human-fur",
        source: "Yan, Sun, Jensen and Ramamoorthi 2017 (A BSSRDF Model for Efficient Rendering of Fur with Global Illumination), Table 4, fitted to the 2015 paper's measurements (docs/model.md §9), row 'human'; l not published: 0.5, the plain dielectric interface (docs/model.md §4); sigma_ca: the single-channel fit used for R, G and B (grey); eta used for eta_c and eta_m",
        input: FurParamsInput {
            eta_c: 1.20,
            pigment: Pigment::Absorption(Rgb::splat(0.41)),
            alpha_deg: 0.70,
            beta_m_deg: 2.05,
            beta_n_deg: Some(3.75),
            l: 0.5,
            kappa: 0.36,
            eta_m: None,
            sigma_ms: 3.49,
            sigma_ma: 0.00,
            g: 0.28,
            closure: crate::params::Closure::Energy,
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
            closure: crate::params::Closure::Energy,
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
            closure: crate::params::Closure::Energy,
        },
    },
];

/// A former preset name that still selects a built-in preset (docs/model.md §9).
///
/// The three parameter rows the project first shipped as `yan-row-a/b/c` turned out to be
/// rows of the species table; their old names keep working, and the tools print
/// [`Alias`]'s `Display` text, one line naming the new preset.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Alias {
    /// The former name.
    pub name: &'static str,
    /// The name of the preset it now selects.
    pub preset: &'static str,
}

impl core::fmt::Display for Alias {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(
            f,
            "preset '{}' is now called '{}' (docs/model.md §9); using '{}'",
            self.name, self.preset, self.preset
        )
    }
}

/// The former preset names (docs/model.md §9): `yan-row-a` is bobcat (with the table's
/// η = 1.69 instead of the 1.55 it had), `yan-row-b` red fox, `yan-row-c` raccoon (with the
/// table's grey σ_ca = 0.25 instead of the melanin colour it had).
pub const ALIASES: [Alias; 3] = [
    Alias {
        name: "yan-row-a",
        preset: "bobcat",
    },
    Alias {
        name: "yan-row-b",
        preset: "red-fox",
    },
    Alias {
        name: "yan-row-c",
        preset: "raccoon",
    },
];

/// The alias called `name`, if `name` is a former preset name.
#[must_use]
pub fn alias(name: &str) -> Option<&'static Alias> {
    ALIASES.iter().find(|a| a.name == name)
}

/// The built-in preset called `name`, or the one a former name ([`ALIASES`]) now selects.
///
/// ```
/// use bcsdf_core::{presets, FurParams};
///
/// let preset = presets::find("bobcat").unwrap();
/// assert_eq!(preset.input.eta_c, 1.69);
/// let params = FurParams::new(&preset.input).unwrap();
/// assert!((params.beta_m().to_degrees() - 11.64).abs() < 1e-4);
/// assert_eq!(presets::find("yan-row-a"), Some(preset));
/// assert!(presets::find("no-such-fur").is_none());
/// ```
#[must_use]
pub fn find(name: &str) -> Option<&'static Preset> {
    let name = alias(name).map_or(name, |a| a.preset);
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
        assert_eq!(find("Bobcat"), None, "names are case-sensitive");
        for a in &ALIASES {
            let p = find(a.preset).expect("an alias names a preset");
            assert_eq!(find(a.name), Some(p));
            assert!(
                PRESETS.iter().all(|q| q.name != a.name),
                "{} is both",
                a.name
            );
        }
    }
}
