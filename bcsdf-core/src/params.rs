//! Validated fur parameters and the parameter schema (docs/model.md §2).
//!
//! [`FurParamsInput`] is what a user or a preset file writes (angles in degrees, optional
//! defaults); [`FurParams::new`] checks it and converts it into [`FurParams`], whose fields can
//! only hold valid values. Every error names the parameter, its value and the valid range.
//!
//! [`SCHEMA`] describes every parameter once (key, symbol, unit, domain, default); the LUT
//! header, the EXR attributes, preset files, `--set` and the viewer's summary iterate it.

use crate::pigment::Pigment;
use crate::spectrum::Rgb;
use core::fmt;

/// Name of one user-facing parameter (docs/model.md §2); its [`ParamSpec`] is
/// [`ParamName::spec`]. The discriminant is the index into [`SCHEMA`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[repr(u8)]
pub enum ParamName {
    /// η_c, cortex (and cuticle) refractive index.
    EtaC,
    /// σ_ca, cortex absorption (RGB), per fiber radius.
    SigmaCa,
    /// Eumelanin concentration (colours σ_ca).
    Eumelanin,
    /// Pheomelanin concentration (colours σ_ca).
    Pheomelanin,
    /// α, cuticle scale tilt in degrees.
    AlphaDeg,
    /// β_m, longitudinal roughness in degrees.
    BetaMDeg,
    /// β_n, azimuthal roughness in degrees (defaults to β_m).
    BetaNDeg,
    /// l, cuticle layers.
    L,
    /// κ, medulla radius / fiber radius.
    Kappa,
    /// η_m, medulla refractive index (defaults to η_c).
    EtaM,
    /// σ_ms, medulla scattering coefficient per fiber radius.
    SigmaMs,
    /// σ_ma, medulla absorption per fiber radius (defaults to 0).
    SigmaMa,
    /// g, Henyey–Greenstein anisotropy in the medulla.
    G,
}

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
    /// One of the colour forms: σ_ca, or eumelanin and/or pheomelanin (an absent
    /// concentration is 0 when the other one is given).
    Colour,
}

/// The value of one parameter: a number, or (σ_ca only) an RGB triple.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ParamValue {
    /// One number (for σ_ca: all three channels).
    Scalar(f32),
    /// Three numbers; only σ_ca takes them.
    Rgb(Rgb),
}

/// One row of the parameter schema (docs/model.md §2): everything a serialisation needs to
/// know about a parameter. Every format — the LUT header, the EXR attributes, preset files,
/// `--set` overrides, the viewer's summary page — iterates [`SCHEMA`], so adding a parameter
/// is a change here (and in [`FurParamsInput`]'s fields).
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
}

/// The parameter schema, in [`ParamName::ALL`] order (which is also the order of the LUT
/// header's parameter block, docs/lut.md).
pub const SCHEMA: [ParamSpec; 13] = [
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
    },
    ParamSpec {
        name: ParamName::SigmaCa,
        key: "sigma_ca",
        symbol: "σ_ca",
        unit: "1/R",
        meaning: "cortex absorption (RGB)",
        domain: Domain::closed(0.0, 1000.0),
        default: ParamDefault::Colour,
    },
    ParamSpec {
        name: ParamName::Eumelanin,
        key: "eumelanin",
        symbol: "c_eu",
        unit: "",
        meaning: "eumelanin concentration (colours σ_ca)",
        domain: Domain::closed(0.0, 100.0),
        default: ParamDefault::Colour,
    },
    ParamSpec {
        name: ParamName::Pheomelanin,
        key: "pheomelanin",
        symbol: "c_pheo",
        unit: "",
        meaning: "pheomelanin concentration (colours σ_ca)",
        domain: Domain::closed(0.0, 100.0),
        default: ParamDefault::Colour,
    },
    ParamSpec {
        name: ParamName::AlphaDeg,
        key: "alpha_deg",
        symbol: "α",
        unit: "deg",
        meaning: "cuticle scale tilt",
        domain: Domain::closed(-30.0, 30.0),
        default: ParamDefault::Required,
    },
    ParamSpec {
        name: ParamName::BetaMDeg,
        key: "beta_m_deg",
        symbol: "β_m",
        unit: "deg",
        meaning: "longitudinal roughness",
        domain: Domain::closed(0.5, 45.0),
        default: ParamDefault::Required,
    },
    ParamSpec {
        name: ParamName::BetaNDeg,
        key: "beta_n_deg",
        symbol: "β_n",
        unit: "deg",
        meaning: "azimuthal roughness",
        domain: Domain::closed(0.5, 45.0),
        default: ParamDefault::SameAs(ParamName::BetaMDeg),
    },
    ParamSpec {
        name: ParamName::L,
        key: "l",
        symbol: "l",
        unit: "",
        meaning: "cuticle layers",
        domain: Domain::closed(0.0, 64.0),
        default: ParamDefault::Required,
    },
    ParamSpec {
        name: ParamName::Kappa,
        key: "kappa",
        symbol: "κ",
        unit: "",
        meaning: "medulla radius / fiber radius",
        domain: Domain::closed(0.0, 0.99),
        default: ParamDefault::Required,
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
    },
    ParamSpec {
        name: ParamName::SigmaMs,
        key: "sigma_ms",
        symbol: "σ_ms",
        unit: "1/R",
        meaning: "medulla scattering coefficient",
        domain: Domain::closed(0.0, 100.0),
        default: ParamDefault::Required,
    },
    ParamSpec {
        name: ParamName::SigmaMa,
        key: "sigma_ma",
        symbol: "σ_ma",
        unit: "1/R",
        meaning: "medulla absorption coefficient",
        domain: Domain::closed(0.0, 100.0),
        default: ParamDefault::Value(0.0),
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
    },
];

impl ParamName {
    /// Every parameter, in docs/model.md §2 order (the order of [`SCHEMA`]).
    pub const ALL: [ParamName; 13] = [
        ParamName::EtaC,
        ParamName::SigmaCa,
        ParamName::Eumelanin,
        ParamName::Pheomelanin,
        ParamName::AlphaDeg,
        ParamName::BetaMDeg,
        ParamName::BetaNDeg,
        ParamName::L,
        ParamName::Kappa,
        ParamName::EtaM,
        ParamName::SigmaMs,
        ParamName::SigmaMa,
        ParamName::G,
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

    /// Whether this is one of the colour parameters (σ_ca, eumelanin, pheomelanin).
    #[must_use]
    pub const fn is_colour(self) -> bool {
        matches!(self.spec().default, ParamDefault::Colour)
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

    /// Checks one value against this parameter's domain (NaN is never valid).
    pub fn check(self, value: f32) -> Result<f32, ParamError> {
        if self.domain().contains(value) {
            Ok(value)
        } else {
            Err(ParamError { name: self, value })
        }
    }
}

impl fmt::Display for ParamName {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.key())
    }
}

/// A parameter outside its valid domain.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ParamError {
    /// Which parameter.
    pub name: ParamName,
    /// The rejected value.
    pub value: f32,
}

impl core::error::Error for ParamError {}

impl fmt::Display for ParamError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "invalid {} = {}: valid range is {}",
            self.name.key(),
            self.value,
            self.name.domain()
        )
    }
}

/// Why a set of named values does not make a [`FurParamsInput`]
/// ([`FurParamsInput::from_values`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum InputError {
    /// A parameter without a default is absent.
    Missing(ParamName),
    /// No colour: neither σ_ca nor a melanin concentration is given.
    NoColour,
    /// σ_ca and a melanin concentration (this one) are both given.
    TwoColours {
        /// The melanin parameter given alongside σ_ca.
        melanin: ParamName,
    },
}

impl fmt::Display for InputError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            InputError::Missing(name) => write!(f, "missing field `{}`", name.key()),
            InputError::NoColour => f.write_str(
                "no colour: give sigma_ca = value | [r, g, b], or eumelanin and/or pheomelanin",
            ),
            InputError::TwoColours { melanin } => write!(
                f,
                "sigma_ca and {} both given: give exactly one colour form, \
                 sigma_ca or eumelanin/pheomelanin",
                melanin.key()
            ),
        }
    }
}

impl core::error::Error for InputError {}

/// Unvalidated parameters as a user or preset writes them (angles in degrees).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FurParamsInput {
    /// η_c.
    pub eta_c: f32,
    /// How σ_ca is given.
    pub pigment: Pigment,
    /// α in degrees.
    pub alpha_deg: f32,
    /// β_m in degrees.
    pub beta_m_deg: f32,
    /// β_n in degrees; `None` means β_n = β_m.
    pub beta_n_deg: Option<f32>,
    /// l, cuticle layers.
    pub l: f32,
    /// κ.
    pub kappa: f32,
    /// η_m; `None` means η_m = η_c (index-matched medulla).
    pub eta_m: Option<f32>,
    /// σ_ms.
    pub sigma_ms: f32,
    /// σ_ma (0 in the report).
    pub sigma_ma: f32,
    /// g.
    pub g: f32,
}

impl FurParamsInput {
    /// The value of one parameter as given: `None` when it is left to its default
    /// (β_n, η_m) or belongs to the colour form not in use (σ_ca vs. melanin).
    #[must_use]
    pub fn value(&self, name: ParamName) -> Option<ParamValue> {
        let scalar = |v: f32| Some(ParamValue::Scalar(v));
        match (name, self.pigment) {
            (ParamName::SigmaCa, Pigment::Absorption(rgb)) => Some(ParamValue::Rgb(rgb)),
            (ParamName::Eumelanin, Pigment::Melanin { eumelanin, .. }) => scalar(eumelanin),
            (ParamName::Pheomelanin, Pigment::Melanin { pheomelanin, .. }) => scalar(pheomelanin),
            (ParamName::SigmaCa | ParamName::Eumelanin | ParamName::Pheomelanin, _) => None,
            (ParamName::EtaC, _) => scalar(self.eta_c),
            (ParamName::AlphaDeg, _) => scalar(self.alpha_deg),
            (ParamName::BetaMDeg, _) => scalar(self.beta_m_deg),
            (ParamName::BetaNDeg, _) => self.beta_n_deg.map(ParamValue::Scalar),
            (ParamName::L, _) => scalar(self.l),
            (ParamName::Kappa, _) => scalar(self.kappa),
            (ParamName::EtaM, _) => self.eta_m.map(ParamValue::Scalar),
            (ParamName::SigmaMs, _) => scalar(self.sigma_ms),
            (ParamName::SigmaMa, _) => scalar(self.sigma_ma),
            (ParamName::G, _) => scalar(self.g),
        }
    }

    /// Sets one parameter. σ_ca (scalar or RGB) replaces a melanin colour; eumelanin or
    /// pheomelanin replaces an RGB σ_ca (the other concentration then starts from 0). An RGB
    /// value for any other parameter sets its first channel.
    pub fn set_value(&mut self, name: ParamName, value: ParamValue) {
        let v = match value {
            ParamValue::Scalar(v) => v,
            ParamValue::Rgb(rgb) => {
                if name == ParamName::SigmaCa {
                    self.pigment = Pigment::Absorption(rgb);
                    return;
                }
                rgb.0[0]
            }
        };
        let (eumelanin, pheomelanin) = match self.pigment {
            Pigment::Melanin {
                eumelanin,
                pheomelanin,
            } => (eumelanin, pheomelanin),
            Pigment::Absorption(_) => (0.0, 0.0),
        };
        match name {
            ParamName::EtaC => self.eta_c = v,
            ParamName::SigmaCa => self.pigment = Pigment::Absorption(Rgb::splat(v)),
            ParamName::Eumelanin => {
                self.pigment = Pigment::Melanin {
                    eumelanin: v,
                    pheomelanin,
                }
            }
            ParamName::Pheomelanin => {
                self.pigment = Pigment::Melanin {
                    eumelanin,
                    pheomelanin: v,
                }
            }
            ParamName::AlphaDeg => self.alpha_deg = v,
            ParamName::BetaMDeg => self.beta_m_deg = v,
            ParamName::BetaNDeg => self.beta_n_deg = Some(v),
            ParamName::L => self.l = v,
            ParamName::Kappa => self.kappa = v,
            ParamName::EtaM => self.eta_m = Some(v),
            ParamName::SigmaMs => self.sigma_ms = v,
            ParamName::SigmaMa => self.sigma_ma = v,
            ParamName::G => self.g = v,
        }
    }

    /// Assembles parameters from named values, `get` being asked once per [`SCHEMA`] row
    /// in order; absent values take their [`ParamDefault`] (β_n and η_m stay absent, i.e.
    /// follow β_m and η_c). Values are not range-checked here ([`FurParams::new`] does that).
    pub fn from_values(
        mut get: impl FnMut(ParamName) -> Option<ParamValue>,
    ) -> Result<FurParamsInput, InputError> {
        let mut input = FurParamsInput::zeroed();
        let mut colour: Option<ParamName> = None;
        for spec in &SCHEMA {
            match (get(spec.name), spec.default) {
                (Some(v), ParamDefault::Colour) => {
                    if let Some(first) = colour {
                        if first == ParamName::SigmaCa {
                            return Err(InputError::TwoColours { melanin: spec.name });
                        }
                    }
                    colour = Some(spec.name);
                    input.set_value(spec.name, v);
                }
                (Some(v), _) => input.set_value(spec.name, v),
                (None, ParamDefault::Required) => return Err(InputError::Missing(spec.name)),
                (None, ParamDefault::Value(d)) => input.set(spec.name, d),
                (None, ParamDefault::SameAs(_) | ParamDefault::Colour) => {}
            }
        }
        match colour {
            Some(_) => Ok(input),
            None => Err(InputError::NoColour),
        }
    }

    /// All zeros, every default absent: the starting point of a decoder that then sets every
    /// parameter (not valid on its own).
    pub(crate) const fn zeroed() -> FurParamsInput {
        FurParamsInput {
            eta_c: 0.0,
            pigment: Pigment::Absorption(Rgb([0.0; 3])),
            alpha_deg: 0.0,
            beta_m_deg: 0.0,
            beta_n_deg: None,
            l: 0.0,
            kappa: 0.0,
            eta_m: None,
            sigma_ms: 0.0,
            sigma_ma: 0.0,
            g: 0.0,
        }
    }

    /// Sets one scalar parameter by name (σ_ca becomes the same value in all channels); see
    /// [`FurParamsInput::set_value`].
    pub fn set(&mut self, name: ParamName, value: f32) {
        self.set_value(name, ParamValue::Scalar(value));
    }

    /// The same parameters with every [`ParamDefault::SameAs`] default written out
    /// (β_n = β_m, η_m = η_c when absent), as the LUT header stores them.
    #[must_use]
    pub fn resolved(&self) -> FurParamsInput {
        let mut out = *self;
        for spec in &SCHEMA {
            if let ParamDefault::SameAs(source) = spec.default {
                if out.value(spec.name).is_none() {
                    if let Some(v) = out.value(source) {
                        out.set_value(spec.name, v);
                    }
                }
            }
        }
        out
    }
}

/// Validated parameters of the double-cylinder model (docs/model.md §2), angles in radians.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FurParams {
    eta_c: f32,
    sigma_ca: Rgb,
    alpha: f32,
    beta_m: f32,
    beta_n: f32,
    l: f32,
    kappa: f32,
    eta_m: f32,
    sigma_ms: f32,
    sigma_ma: f32,
    g: f32,
}

impl FurParams {
    /// Validates `input`; the first invalid parameter is reported.
    pub fn new(input: &FurParamsInput) -> Result<FurParams, ParamError> {
        let eta_c = ParamName::EtaC.check(input.eta_c)?;
        let sigma_ca = match input.pigment {
            Pigment::Absorption(s) => {
                for c in s.0 {
                    ParamName::SigmaCa.check(c)?;
                }
                s
            }
            Pigment::Melanin {
                eumelanin,
                pheomelanin,
            } => {
                ParamName::Eumelanin.check(eumelanin)?;
                ParamName::Pheomelanin.check(pheomelanin)?;
                input.pigment.sigma_ca()
            }
        };
        let beta_m_deg = ParamName::BetaMDeg.check(input.beta_m_deg)?;
        let beta_n_deg = ParamName::BetaNDeg.check(input.beta_n_deg.unwrap_or(beta_m_deg))?;
        let eta_m = ParamName::EtaM.check(input.eta_m.unwrap_or(eta_c))?;
        Ok(FurParams {
            eta_c,
            sigma_ca,
            alpha: ParamName::AlphaDeg.check(input.alpha_deg)?.to_radians(),
            beta_m: beta_m_deg.to_radians(),
            beta_n: beta_n_deg.to_radians(),
            l: ParamName::L.check(input.l)?,
            kappa: ParamName::Kappa.check(input.kappa)?,
            eta_m,
            sigma_ms: ParamName::SigmaMs.check(input.sigma_ms)?,
            sigma_ma: ParamName::SigmaMa.check(input.sigma_ma)?,
            g: ParamName::G.check(input.g)?,
        })
    }

    /// η_c, cortex and cuticle refractive index.
    #[must_use]
    pub fn eta_c(&self) -> f32 {
        self.eta_c
    }
    /// σ_ca, cortex absorption per fiber radius (RGB).
    #[must_use]
    pub fn sigma_ca(&self) -> Rgb {
        self.sigma_ca
    }
    /// α, cuticle tilt in radians.
    #[must_use]
    pub fn alpha(&self) -> f32 {
        self.alpha
    }
    /// β_m, longitudinal roughness in radians.
    #[must_use]
    pub fn beta_m(&self) -> f32 {
        self.beta_m
    }
    /// β_n, azimuthal roughness in radians.
    #[must_use]
    pub fn beta_n(&self) -> f32 {
        self.beta_n
    }
    /// l, cuticle layers.
    #[must_use]
    pub fn l(&self) -> f32 {
        self.l
    }
    /// κ, medulla radius / fiber radius.
    #[must_use]
    pub fn kappa(&self) -> f32 {
        self.kappa
    }
    /// η_m, medulla refractive index.
    #[must_use]
    pub fn eta_m(&self) -> f32 {
        self.eta_m
    }
    /// σ_ms, medulla scattering per fiber radius.
    #[must_use]
    pub fn sigma_ms(&self) -> f32 {
        self.sigma_ms
    }
    /// σ_ma, medulla absorption per fiber radius.
    #[must_use]
    pub fn sigma_ma(&self) -> f32 {
        self.sigma_ma
    }
    /// g, Henyey–Greenstein anisotropy.
    #[must_use]
    pub fn g(&self) -> f32 {
        self.g
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use std::string::ToString;

    fn human_hair() -> FurParamsInput {
        crate::presets::find("human-hair").unwrap().input
    }

    #[test]
    fn schema_rows_follow_all_and_keys_are_unique() {
        for (i, (spec, name)) in SCHEMA.iter().zip(ParamName::ALL).enumerate() {
            assert_eq!(spec.name, name, "row {i}");
            assert_eq!(name.spec(), spec);
            assert_eq!(ParamName::from_key(spec.key), Some(name));
            assert!(
                SCHEMA[..i].iter().all(|s| s.key != spec.key),
                "{}",
                spec.key
            );
            assert!(!spec.symbol.is_empty() && !spec.meaning.is_empty());
        }
        assert_eq!(ParamName::from_key("Eta_C"), None);
        assert_eq!(ParamName::from_key(""), None);
    }

    #[test]
    fn domain_text_is_interval_notation() {
        assert_eq!(ParamName::EtaC.domain().to_string(), "(1, 3]");
        assert_eq!(ParamName::Kappa.domain().to_string(), "[0, 0.99]");
        assert_eq!(ParamName::G.domain().to_string(), "(-1, 1)");
        assert_eq!(ParamName::AlphaDeg.domain().to_string(), "[-30, 30]");
    }

    #[test]
    fn domains_honour_open_and_closed_ends() {
        for spec in &SCHEMA {
            let d = spec.domain;
            assert_eq!(d.contains(d.lo), d.lo_inclusive, "{}", spec.key);
            assert_eq!(d.contains(d.hi), d.hi_inclusive, "{}", spec.key);
            assert!(d.contains(0.5 * (d.lo + d.hi)), "{}", spec.key);
            for bad in [
                f32::NAN,
                f32::INFINITY,
                f32::NEG_INFINITY,
                d.lo - 1.0,
                d.hi + 1.0,
            ] {
                assert!(!d.contains(bad), "{} {bad}", spec.key);
                assert!(spec.name.check(bad).is_err());
            }
        }
    }

    #[test]
    fn param_error_names_key_value_and_range() {
        let e = ParamName::Kappa.check(1.2).unwrap_err();
        assert_eq!(
            e.to_string(),
            "invalid kappa = 1.2: valid range is [0, 0.99]"
        );
        let mut input = human_hair();
        input.g = 1.0;
        let e = FurParams::new(&input).unwrap_err();
        assert_eq!(e.name, ParamName::G);
    }

    #[test]
    fn set_value_then_value_round_trips_every_parameter() {
        for (i, spec) in SCHEMA.iter().enumerate() {
            let mut input = human_hair();
            let v = 0.25 + i as f32 * 0.01;
            input.set(spec.name, v);
            let expected = if spec.name == ParamName::SigmaCa {
                ParamValue::Rgb(Rgb::splat(v))
            } else {
                ParamValue::Scalar(v)
            };
            assert_eq!(input.value(spec.name), Some(expected), "{}", spec.key);
        }
        let mut input = human_hair();
        input.set_value(ParamName::SigmaCa, ParamValue::Rgb(Rgb([0.1, 0.2, 0.3])));
        assert_eq!(input.pigment, Pigment::Absorption(Rgb([0.1, 0.2, 0.3])));
        assert_eq!(input.value(ParamName::Eumelanin), None);
    }

    #[test]
    fn colour_forms_exclude_each_other() {
        let mut input = human_hair();
        input.set(ParamName::SigmaCa, 0.7);
        input.set(ParamName::Eumelanin, 1.5);
        assert_eq!(input.value(ParamName::SigmaCa), None);
        assert_eq!(
            input.value(ParamName::Pheomelanin),
            Some(ParamValue::Scalar(0.0))
        );
        input.set(ParamName::Pheomelanin, 0.5);
        assert_eq!(
            input.pigment,
            Pigment::Melanin {
                eumelanin: 1.5,
                pheomelanin: 0.5
            }
        );
        input.set(ParamName::SigmaCa, 2.0);
        assert_eq!(input.value(ParamName::Eumelanin), None);
        assert_eq!(
            input.value(ParamName::SigmaCa),
            Some(ParamValue::Rgb(Rgb::splat(2.0)))
        );
    }

    #[test]
    fn resolved_fills_same_as_defaults_only() {
        let mut input = human_hair();
        input.beta_n_deg = None;
        input.eta_m = None;
        let r = input.resolved();
        assert_eq!(r.beta_n_deg, Some(input.beta_m_deg));
        assert_eq!(r.eta_m, Some(input.eta_c));
        assert_eq!(r.resolved(), r);
        input.eta_m = Some(1.4);
        assert_eq!(input.resolved().eta_m, Some(1.4));
        // Validation gives the same parameters either way.
        assert_eq!(FurParams::new(&input), FurParams::new(&input.resolved()));
    }
}
