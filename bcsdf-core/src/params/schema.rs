//! The parameter schema (docs/model.md §2): one [`ParamSpec`] per parameter in [`SCHEMA`],
//! and the [`ParamName`] lookups that read it. Every serialisation of the parameter set
//! iterates this table.

use super::{Closure, ParamError, ParamName};
use crate::spectrum::Rgb;
use core::fmt;

/// A parameter's valid domain: an interval whose ends are open or closed.
///
/// [`Display`](fmt::Display) writes it in interval notation, e.g. `(1, 3]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Domain {
    /// Lower end.
    pub lo: f32,
    /// Whether `lo` itself is valid.
    pub lo_inclusive: bool,
    /// Upper end.
    pub hi: f32,
    /// Whether `hi` itself is valid.
    pub hi_inclusive: bool,
}

impl Domain {
    const fn closed(lo: f32, hi: f32) -> Domain {
        Domain {
            lo,
            lo_inclusive: true,
            hi,
            hi_inclusive: true,
        }
    }

    /// Whether `value` lies in the domain (NaN and ±∞ never do).
    #[must_use]
    pub fn contains(&self, value: f32) -> bool {
        let above = if self.lo_inclusive {
            value >= self.lo
        } else {
            value > self.lo
        };
        let below = if self.hi_inclusive {
            value <= self.hi
        } else {
            value < self.hi
        };
        value.is_finite() && above && below
    }
}

impl fmt::Display for Domain {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let open = if self.lo_inclusive { '[' } else { '(' };
        let close = if self.hi_inclusive { ']' } else { ')' };
        write!(f, "{open}{}, {}{close}", self.lo, self.hi)
    }
}

/// What a parameter is when a preset or override leaves it out.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ParamDefault {
    /// It must be given.
    Required,
    /// This value.
    Value(f32),
    /// The (resolved) value of another parameter, e.g. η_m = η_c.
    SameAs(ParamName),
    /// One of the colour forms: σ_ca, eumelanin and/or pheomelanin (an absent
    /// concentration is 0 when the other one is given), or the base colour.
    Colour,
}

/// The value of one parameter: a number, or (σ_ca and the base colour only) an RGB triple.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ParamValue {
    /// One number (for σ_ca: all three channels).
    Scalar(f32),
    /// Three numbers; only σ_ca and the base colour take them ([`ParamName::takes_rgb`]).
    Rgb(Rgb),
    /// One of a choice parameter's values, by index into [`ParamSpec::choices`] (`closure`).
    Choice(u8),
}

/// One row of the parameter schema (docs/model.md §2): everything a serialisation needs to
/// know about a parameter. Every format — the LUT header, the EXR attributes, preset files,
/// `--set` overrides, the viewer's summary page — iterates [`SCHEMA`], so adding a parameter
/// is a change here (and in [`FurParamsInput`](super::FurParamsInput)'s fields).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ParamSpec {
    /// Which parameter.
    pub name: ParamName,
    /// The key in preset files, EXR attributes and `--set` (`eta_c`).
    pub key: &'static str,
    /// The symbol of docs/model.md (`η_c`).
    pub symbol: &'static str,
    /// Unit: `""` (dimensionless), `"deg"`, or `"1/R"` (per fiber radius).
    pub unit: &'static str,
    /// What it is, in a few words.
    pub meaning: &'static str,
    /// The valid values.
    pub domain: Domain,
    /// What an absent value means.
    pub default: ParamDefault,
    /// For a choice ([`ParamValue::Choice`]): the names of its values, by index (the
    /// domain is then the index range); empty for a number.
    pub choices: &'static [&'static str],
}

impl ParamSpec {
    /// Whether the parameter is a choice among [`ParamSpec::choices`] (not a number).
    #[must_use]
    pub const fn is_choice(&self) -> bool {
        !self.choices.is_empty()
    }

    /// The index of the choice named `name`; `None` for a number or an unknown name.
    #[must_use]
    pub fn choice_index(&self, name: &str) -> Option<u8> {
        self.choices
            .iter()
            .position(|c| *c == name)
            .map(|i| i as u8)
    }

    /// The name of choice `index`; `None` past the end (or for a number).
    #[must_use]
    pub fn choice_name(&self, index: u8) -> Option<&'static str> {
        self.choices.get(usize::from(index)).copied()
    }
}

/// The parameter schema, in [`ParamName::ALL`] order (which is also the order of the LUT
/// header's parameter block, docs/lut.md).
pub const SCHEMA: [ParamSpec; 15] = [
    ParamSpec {
        name: ParamName::EtaC,
        key: "eta_c",
        symbol: "η_c",
        unit: "",
        meaning: "cortex and cuticle refractive index",
        domain: Domain {
            lo: 1.0,
            lo_inclusive: false,
            hi: 3.0,
            hi_inclusive: true,
        },
        default: ParamDefault::Required,
        choices: &[],
    },
    ParamSpec {
        name: ParamName::SigmaCa,
        key: "sigma_ca",
        symbol: "σ_ca",
        unit: "1/R",
        meaning: "cortex absorption (RGB)",
        domain: Domain::closed(0.0, 1000.0),
        default: ParamDefault::Colour,
        choices: &[],
    },
    ParamSpec {
        name: ParamName::Eumelanin,
        key: "eumelanin",
        symbol: "c_eu",
        unit: "",
        meaning: "eumelanin concentration (colours σ_ca)",
        domain: Domain::closed(0.0, 100.0),
        default: ParamDefault::Colour,
        choices: &[],
    },
    ParamSpec {
        name: ParamName::Pheomelanin,
        key: "pheomelanin",
        symbol: "c_pheo",
        unit: "",
        meaning: "pheomelanin concentration (colours σ_ca)",
        domain: Domain::closed(0.0, 100.0),
        default: ParamDefault::Colour,
        choices: &[],
    },
    ParamSpec {
        name: ParamName::BaseColour,
        key: "base_colour",
        symbol: "c_base",
        unit: "",
        meaning: "colour the coat shows, linear RGB (colours σ_ca through the coat colour table)",
        domain: Domain::closed(0.0, 1.0),
        default: ParamDefault::Colour,
        choices: &[],
    },
    ParamSpec {
        name: ParamName::AlphaDeg,
        key: "alpha_deg",
        symbol: "α",
        unit: "deg",
        meaning: "cuticle scale tilt",
        domain: Domain::closed(-30.0, 30.0),
        default: ParamDefault::Required,
        choices: &[],
    },
    ParamSpec {
        name: ParamName::BetaMDeg,
        key: "beta_m_deg",
        symbol: "β_m",
        unit: "deg",
        meaning: "longitudinal roughness",
        domain: Domain::closed(0.5, 45.0),
        default: ParamDefault::Required,
        choices: &[],
    },
    ParamSpec {
        name: ParamName::BetaNDeg,
        key: "beta_n_deg",
        symbol: "β_n",
        unit: "deg",
        meaning: "azimuthal roughness",
        domain: Domain::closed(0.5, 45.0),
        default: ParamDefault::SameAs(ParamName::BetaMDeg),
        choices: &[],
    },
    ParamSpec {
        name: ParamName::L,
        key: "l",
        symbol: "l",
        unit: "",
        meaning: "cuticle layers",
        domain: Domain::closed(0.0, 64.0),
        default: ParamDefault::Required,
        choices: &[],
    },
    ParamSpec {
        name: ParamName::Kappa,
        key: "kappa",
        symbol: "κ",
        unit: "",
        meaning: "medulla radius / fiber radius",
        domain: Domain::closed(0.0, 0.99),
        default: ParamDefault::Required,
        choices: &[],
    },
    ParamSpec {
        name: ParamName::EtaM,
        key: "eta_m",
        symbol: "η_m",
        unit: "",
        meaning: "medulla refractive index",
        domain: Domain {
            lo: 1.0,
            lo_inclusive: false,
            hi: 3.0,
            hi_inclusive: true,
        },
        default: ParamDefault::SameAs(ParamName::EtaC),
        choices: &[],
    },
    ParamSpec {
        name: ParamName::SigmaMs,
        key: "sigma_ms",
        symbol: "σ_ms",
        unit: "1/R",
        meaning: "medulla scattering coefficient",
        domain: Domain::closed(0.0, 100.0),
        default: ParamDefault::Required,
        choices: &[],
    },
    ParamSpec {
        name: ParamName::SigmaMa,
        key: "sigma_ma",
        symbol: "σ_ma",
        unit: "1/R",
        meaning: "medulla absorption coefficient",
        domain: Domain::closed(0.0, 100.0),
        default: ParamDefault::Value(0.0),
        choices: &[],
    },
    ParamSpec {
        name: ParamName::G,
        key: "g",
        symbol: "g",
        unit: "",
        meaning: "Henyey–Greenstein anisotropy in the medulla",
        domain: Domain {
            lo: -1.0,
            lo_inclusive: false,
            hi: 1.0,
            hi_inclusive: false,
        },
        default: ParamDefault::Required,
        choices: &[],
    },
    ParamSpec {
        name: ParamName::Closure,
        key: "closure",
        symbol: "closure",
        unit: "",
        meaning: "energy closure: report (as published) or energy (lobes normalised on the sphere)",
        domain: Domain::closed(0.0, 1.0),
        // energy: the fiber keeps the light it should (docs/model.md §12); `report` is kept
        // for checking against the report's equations.
        default: ParamDefault::Value(1.0),
        choices: &Closure::NAMES,
    },
];

impl ParamName {
    /// Every parameter, in docs/model.md §2 order (the order of [`SCHEMA`]).
    pub const ALL: [ParamName; 15] = [
        ParamName::EtaC,
        ParamName::SigmaCa,
        ParamName::Eumelanin,
        ParamName::Pheomelanin,
        ParamName::BaseColour,
        ParamName::AlphaDeg,
        ParamName::BetaMDeg,
        ParamName::BetaNDeg,
        ParamName::L,
        ParamName::Kappa,
        ParamName::EtaM,
        ParamName::SigmaMs,
        ParamName::SigmaMa,
        ParamName::G,
        ParamName::Closure,
    ];

    /// This parameter's row of [`SCHEMA`].
    #[must_use]
    pub const fn spec(self) -> &'static ParamSpec {
        &SCHEMA[self as usize]
    }

    /// The key used in preset files, EXR attributes and `--set`.
    #[must_use]
    pub const fn key(self) -> &'static str {
        self.spec().key
    }

    /// Whether this is one of the colour parameters (σ_ca, eumelanin, pheomelanin,
    /// base colour).
    #[must_use]
    pub const fn is_colour(self) -> bool {
        matches!(self.spec().default, ParamDefault::Colour)
    }

    /// Whether the parameter takes three numbers `[r, g, b]` as well as one (σ_ca, the base
    /// colour).
    #[must_use]
    pub const fn takes_rgb(self) -> bool {
        matches!(self, ParamName::SigmaCa | ParamName::BaseColour)
    }

    /// Looks a parameter up by its key; `None` for an unknown key.
    #[must_use]
    pub fn from_key(key: &str) -> Option<ParamName> {
        SCHEMA.iter().find(|s| s.key == key).map(|s| s.name)
    }

    /// The valid domain.
    #[must_use]
    pub const fn domain(self) -> Domain {
        self.spec().domain
    }

    /// Checks one value against this parameter's domain (NaN is never valid; a choice's
    /// value must be a whole index).
    pub fn check(self, value: f32) -> Result<f32, ParamError> {
        let whole = !self.spec().is_choice() || value == libm::floorf(value);
        if self.domain().contains(value) && whole {
            Ok(value)
        } else {
            Err(ParamError { name: self, value })
        }
    }
}
