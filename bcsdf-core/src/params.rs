//! Validated fur parameters and the parameter schema (docs/model.md §2).
//!
//! [`FurParamsInput`] is what a user or a preset file writes (angles in degrees, optional
//! defaults); [`FurParams::new`] checks it and converts it into [`FurParams`], whose fields can
//! only hold valid values. Every error names the parameter, its value and the valid range.
//!
//! [`SCHEMA`] describes every parameter once (key, symbol, unit, domain, default); the LUT
//! header, the EXR attributes, preset files, `--set` and the viewer's summary iterate it.
//!
//! [`check_name`] is the rule for preset names (docs/model.md §9), which become file names.

use crate::pigment::Pigment;
use crate::spectrum::Rgb;
use core::fmt;

mod closure;
mod name;
mod resolved;
mod schema;
pub use closure::Closure;
pub use name::{check_name, NameError, DEVICE_NAMES, NAME_MAX_BYTES};
pub use resolved::{HeaderField, ResolvedParams, HEADER_FIELDS};
pub use schema::{Domain, ParamDefault, ParamSpec, ParamValue, SCHEMA};

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
    /// The base colour, linear RGB: the colour the coat shows (σ_ca through the coat colour
    /// table, docs/model.md §14).
    BaseColour,
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
    /// `closure`, the energy closure ([`Closure`], docs/model.md §12).
    Closure,
}

impl fmt::Display for ParamName {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.key())
    }
}

/// A parameter outside its valid domain; or, for [`ParamName::BaseColour`] with a value inside
/// it, a base colour not yet turned into σ_ca (that needs the fur's coat colour table,
/// docs/model.md §14: `bake` resolves it when it bakes a LUT).
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
        let spec = self.name.spec();
        if self.name == ParamName::BaseColour && spec.domain.contains(self.value) {
            return f.write_str(
                "base_colour needs this fur's coat colour table to become sigma_ca: \
                 bake a LUT from these parameters (the LUT records the sigma_ca found), \
                 or give sigma_ca",
            );
        }
        if spec.is_choice() {
            write!(
                f,
                "invalid {} = {}: valid values are ",
                spec.key, self.value
            )?;
            for (i, c) in spec.choices.iter().enumerate() {
                let sep = if i == 0 { "" } else { ", " };
                write!(f, "{sep}{c}")?;
            }
            return Ok(());
        }
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
    /// Two colour forms are given: σ_ca, melanin or the base colour (eumelanin with
    /// pheomelanin is one form).
    TwoColours {
        /// The colour parameter given first (schema order).
        first: ParamName,
        /// The colour parameter of another form given after it.
        second: ParamName,
    },
}

impl fmt::Display for InputError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            InputError::Missing(name) => write!(f, "missing field `{}`", name.key()),
            InputError::NoColour => f.write_str(
                "no colour: give sigma_ca = value | [r, g, b], eumelanin and/or pheomelanin, \
                 or base_colour = [r, g, b]",
            ),
            InputError::TwoColours { first, second } => write!(
                f,
                "{} and {} both given: give exactly one colour form, \
                 sigma_ca, eumelanin/pheomelanin or base_colour",
                first.key(),
                second.key()
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
    /// The energy closure (docs/model.md §12).
    pub closure: Closure,
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
            (ParamName::BaseColour, Pigment::BaseColour(rgb)) => Some(ParamValue::Rgb(rgb)),
            (
                ParamName::SigmaCa
                | ParamName::Eumelanin
                | ParamName::Pheomelanin
                | ParamName::BaseColour,
                _,
            ) => None,
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
            (ParamName::Closure, _) => Some(ParamValue::Choice(self.closure.index())),
        }
    }

    /// Sets one parameter. σ_ca or the base colour (scalar: grey, or RGB) replaces any other
    /// colour form; eumelanin or pheomelanin replaces σ_ca or a base colour (the other
    /// concentration then starts from 0). An RGB value for any other parameter sets its first
    /// channel. A choice sets `closure` (index
    /// past the end: left unchanged); a number sets it by index, and a choice sets any
    /// number parameter to its index.
    pub fn set_value(&mut self, name: ParamName, value: ParamValue) {
        let v = match value {
            ParamValue::Scalar(v) => v,
            ParamValue::Choice(i) => f32::from(i),
            ParamValue::Rgb(rgb) => {
                match name {
                    ParamName::SigmaCa => self.pigment = Pigment::Absorption(rgb),
                    ParamName::BaseColour => self.pigment = Pigment::BaseColour(rgb),
                    _ => {
                        self.set_value(name, ParamValue::Scalar(rgb.0[0]));
                    }
                }
                return;
            }
        };
        let (eumelanin, pheomelanin) = match self.pigment {
            Pigment::Melanin {
                eumelanin,
                pheomelanin,
            } => (eumelanin, pheomelanin),
            Pigment::Absorption(_) | Pigment::BaseColour(_) => (0.0, 0.0),
        };
        match name {
            ParamName::EtaC => self.eta_c = v,
            ParamName::SigmaCa => self.pigment = Pigment::Absorption(Rgb::splat(v)),
            ParamName::BaseColour => self.pigment = Pigment::BaseColour(Rgb::splat(v)),
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
            ParamName::Closure => {
                // Only whole indices name a closure (FurParams::new rejects nothing here:
                // the closure field can only hold a valid one).
                if v == libm::floorf(v) && (0.0..=255.0).contains(&v) {
                    if let Some(c) = Closure::from_index(v as u8) {
                        self.closure = c;
                    }
                }
            }
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
                        let melanin =
                            |n| matches!(n, ParamName::Eumelanin | ParamName::Pheomelanin);
                        if !(melanin(first) && melanin(spec.name)) {
                            return Err(InputError::TwoColours {
                                first,
                                second: spec.name,
                            });
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
            closure: Closure::Report,
        }
    }

    /// Sets one scalar parameter by name (σ_ca becomes the same value in all channels); see
    /// [`FurParamsInput::set_value`].
    pub fn set(&mut self, name: ParamName, value: f32) {
        self.set_value(name, ParamValue::Scalar(value));
    }
}

impl FurParamsInput {
    /// Checks every parameter as [`FurParams::new`] does, except that a base colour
    /// ([`Pigment::BaseColour`]) only has its channels checked (in [0, 1]): it becomes σ_ca
    /// through the fur's coat colour table (docs/model.md §14), and every other parameter is
    /// valid at any σ_ca. What a preset file or an override is checked with when it is read.
    pub fn check(&self) -> Result<(), ParamError> {
        let mut rest = *self;
        if let Pigment::BaseColour(c) = self.pigment {
            for v in c.0 {
                ParamName::BaseColour.check(v)?;
            }
            rest.pigment = Pigment::Absorption(Rgb::ZERO);
        }
        FurParams::new(&rest).map(|_| ())
    }

    /// This input with its base colour (if it has one) replaced by the σ_ca `absorption`:
    /// what [`FurParams::new`] accepts once the coat colour table has inverted the colour.
    #[must_use]
    pub fn with_sigma_ca(&self, absorption: &crate::absorption::Absorption) -> FurParamsInput {
        FurParamsInput {
            pigment: Pigment::Absorption(absorption.sigma()),
            ..*self
        }
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
    closure: Closure,
}

impl FurParams {
    /// Validates `input`; the first invalid parameter is reported.
    pub fn new(input: &FurParamsInput) -> Result<FurParams, ParamError> {
        // The defaults (β_n = β_m, η_m = η_c) come from `resolve`, the one place they live.
        let input = input.resolve();
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
                input.pigment.sigma_ca().unwrap_or(Rgb::ZERO)
            }
            Pigment::BaseColour(c) => {
                for v in c.0 {
                    ParamName::BaseColour.check(v)?;
                }
                // A base colour becomes σ_ca only through the fur's coat colour table
                // (docs/model.md §14); without one there is no model to build.
                return Err(ParamError {
                    name: ParamName::BaseColour,
                    value: c.0[0],
                });
            }
        };
        let beta_m_deg = ParamName::BetaMDeg.check(input.beta_m_deg)?;
        let beta_n_deg = ParamName::BetaNDeg.check(input.beta_n_deg)?;
        let eta_m = ParamName::EtaM.check(input.eta_m)?;
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
            closure: input.closure,
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
    /// The energy closure (docs/model.md §12).
    #[must_use]
    pub fn closure(&self) -> Closure {
        self.closure
    }
    /// The same parameters with another energy closure (docs/model.md §12).
    #[must_use]
    pub fn with_closure(mut self, closure: Closure) -> FurParams {
        self.closure = closure;
        self
    }
    /// The same parameters at another colour: σ_ca of `absorption` (validated, within the
    /// parameter's domain), every other field bit for bit unchanged (docs/lut.md "The
    /// absorption axis": the analytic model a LUT evaluated at that colour is measured
    /// against).
    #[must_use]
    pub fn with_absorption(mut self, absorption: &crate::absorption::Absorption) -> FurParams {
        self.sigma_ca = absorption.sigma();
        self
    }

    /// Whether `other` is these parameters at another colour: every field but σ_ca the same
    /// bits (what the absorption planes of one LUT share, so that one residual walk serves
    /// them all: [`crate::residual_gen::generate_rows`]).
    #[must_use]
    pub fn same_but_absorption(&self, other: &FurParams) -> bool {
        let bits = |p: &FurParams| {
            [
                p.eta_c, p.alpha, p.beta_m, p.beta_n, p.l, p.kappa, p.eta_m, p.sigma_ms,
                p.sigma_ma, p.g,
            ]
            .map(f32::to_bits)
        };
        bits(self) == bits(other) && self.closure == other.closure
    }
}

/// The analytic model's parameters at a colour (here, with the parameters, so that
/// `absorption` stays below `params` in the module order).
impl crate::absorption::Absorption {
    /// `input` with its colour replaced by this σ_ca: the parameters of the analytic model at
    /// this colour (every other parameter unchanged).
    #[must_use]
    pub fn apply(&self, input: &FurParamsInput) -> FurParamsInput {
        FurParamsInput {
            pigment: Pigment::Absorption(self.sigma()),
            ..*input
        }
    }
}

#[cfg(test)]
mod tests;
