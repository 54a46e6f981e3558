//! Validated fur parameters (MODEL.md §2).
//!
//! [`FurParamsInput`] is what a user or a preset file writes (angles in degrees, optional
//! defaults); [`FurParams::new`] checks it and converts it into [`FurParams`], whose fields can
//! only hold valid values. Every error names the parameter, its value and the valid range.

use crate::pigment::Pigment;
use crate::spectrum::Rgb;
use core::fmt;

/// Name of one user-facing parameter, spelled as in MODEL.md §2 (and in `viewer --set`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
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

impl ParamName {
    /// Every parameter, in MODEL.md order.
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

    /// The key used in preset files and `viewer probe --set`.
    pub const fn key(self) -> &'static str {
        match self {
            ParamName::EtaC => "eta_c",
            ParamName::SigmaCa => "sigma_ca",
            ParamName::Eumelanin => "eumelanin",
            ParamName::Pheomelanin => "pheomelanin",
            ParamName::AlphaDeg => "alpha_deg",
            ParamName::BetaMDeg => "beta_m_deg",
            ParamName::BetaNDeg => "beta_n_deg",
            ParamName::L => "l",
            ParamName::Kappa => "kappa",
            ParamName::EtaM => "eta_m",
            ParamName::SigmaMs => "sigma_ms",
            ParamName::SigmaMa => "sigma_ma",
            ParamName::G => "g",
        }
    }

    /// Looks a parameter up by its key; `None` for an unknown key.
    pub fn from_key(key: &str) -> Option<ParamName> {
        ParamName::ALL.iter().copied().find(|p| p.key() == key)
    }

    /// The valid domain, as `(lo, lo_inclusive, hi, hi_inclusive)`.
    pub const fn domain(self) -> (f32, bool, f32, bool) {
        match self {
            ParamName::EtaC | ParamName::EtaM => (1.0, false, 3.0, true),
            ParamName::SigmaCa => (0.0, true, 1000.0, true),
            ParamName::Eumelanin | ParamName::Pheomelanin => (0.0, true, 100.0, true),
            ParamName::AlphaDeg => (-30.0, true, 30.0, true),
            ParamName::BetaMDeg | ParamName::BetaNDeg => (0.5, true, 45.0, true),
            ParamName::L => (0.0, true, 64.0, true),
            ParamName::Kappa => (0.0, true, 0.99, true),
            ParamName::SigmaMs | ParamName::SigmaMa => (0.0, true, 100.0, true),
            ParamName::G => (-1.0, false, 1.0, false),
        }
    }

    /// The valid domain as text, e.g. `(1, 3]`.
    pub const fn range_text(self) -> &'static str {
        match self {
            ParamName::EtaC | ParamName::EtaM => "(1, 3]",
            ParamName::SigmaCa => "[0, 1000]",
            ParamName::Eumelanin | ParamName::Pheomelanin => "[0, 100]",
            ParamName::AlphaDeg => "[-30, 30]",
            ParamName::BetaMDeg | ParamName::BetaNDeg => "[0.5, 45]",
            ParamName::L => "[0, 64]",
            ParamName::Kappa => "[0, 0.99]",
            ParamName::SigmaMs | ParamName::SigmaMa => "[0, 100]",
            ParamName::G => "(-1, 1)",
        }
    }

    /// Checks one value against this parameter's domain (NaN is never valid).
    pub fn check(self, value: f32) -> Result<f32, ParamError> {
        let (lo, lo_in, hi, hi_in) = self.domain();
        let above = if lo_in { value >= lo } else { value > lo };
        let below = if hi_in { value <= hi } else { value < hi };
        if value.is_finite() && above && below {
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

impl fmt::Display for ParamError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "invalid {} = {}: valid range is {}",
            self.name.key(),
            self.value,
            self.name.range_text()
        )
    }
}

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
    /// Sets one scalar parameter by name (σ_ca becomes the same value in all channels).
    pub fn set(&mut self, name: ParamName, value: f32) {
        match name {
            ParamName::EtaC => self.eta_c = value,
            ParamName::SigmaCa => self.pigment = Pigment::Absorption(Rgb::splat(value)),
            ParamName::Eumelanin => {
                let pheomelanin = match self.pigment {
                    Pigment::Melanin { pheomelanin, .. } => pheomelanin,
                    Pigment::Absorption(_) => 0.0,
                };
                self.pigment = Pigment::Melanin {
                    eumelanin: value,
                    pheomelanin,
                };
            }
            ParamName::Pheomelanin => {
                let eumelanin = match self.pigment {
                    Pigment::Melanin { eumelanin, .. } => eumelanin,
                    Pigment::Absorption(_) => 0.0,
                };
                self.pigment = Pigment::Melanin {
                    eumelanin,
                    pheomelanin: value,
                };
            }
            ParamName::AlphaDeg => self.alpha_deg = value,
            ParamName::BetaMDeg => self.beta_m_deg = value,
            ParamName::BetaNDeg => self.beta_n_deg = Some(value),
            ParamName::L => self.l = value,
            ParamName::Kappa => self.kappa = value,
            ParamName::EtaM => self.eta_m = Some(value),
            ParamName::SigmaMs => self.sigma_ms = value,
            ParamName::SigmaMa => self.sigma_ma = value,
            ParamName::G => self.g = value,
        }
    }
}

/// Validated parameters of the double-cylinder model (MODEL.md §2), angles in radians.
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
    pub fn eta_c(&self) -> f32 {
        self.eta_c
    }
    /// σ_ca, cortex absorption per fiber radius (RGB).
    pub fn sigma_ca(&self) -> Rgb {
        self.sigma_ca
    }
    /// α, cuticle tilt in radians.
    pub fn alpha(&self) -> f32 {
        self.alpha
    }
    /// β_m, longitudinal roughness in radians.
    pub fn beta_m(&self) -> f32 {
        self.beta_m
    }
    /// β_n, azimuthal roughness in radians.
    pub fn beta_n(&self) -> f32 {
        self.beta_n
    }
    /// l, cuticle layers.
    pub fn l(&self) -> f32 {
        self.l
    }
    /// κ, medulla radius / fiber radius.
    pub fn kappa(&self) -> f32 {
        self.kappa
    }
    /// η_m, medulla refractive index.
    pub fn eta_m(&self) -> f32 {
        self.eta_m
    }
    /// σ_ms, medulla scattering per fiber radius.
    pub fn sigma_ms(&self) -> f32 {
        self.sigma_ms
    }
    /// σ_ma, medulla absorption per fiber radius.
    pub fn sigma_ma(&self) -> f32 {
        self.sigma_ma
    }
    /// g, Henyey–Greenstein anisotropy.
    pub fn g(&self) -> f32 {
        self.g
    }
}
