//! [`ResolvedParams`]: parameters with every default written out, as the LUT header stores
//! them (docs/model.md §2, §9; docs/lut.md "Header").

use super::{Closure, FurParamsInput, ParamName};
use crate::pigment::Pigment;

/// [`FurParamsInput`] with its [`ParamDefault::SameAs`](super::ParamDefault::SameAs)
/// defaults written out (β_n = β_m and η_m = η_c when absent): every scalar parameter has a
/// value, so a serialiser ([`LutHeader::encode`](crate::lut::LutHeader::encode)) needs no
/// branch for a missing one. Made by [`FurParamsInput::resolve`], the one place the
/// defaults are applied (docs/model.md §2).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ResolvedParams {
    pub(super) eta_c: f32,
    pub(super) pigment: Pigment,
    pub(super) alpha_deg: f32,
    pub(super) beta_m_deg: f32,
    pub(super) beta_n_deg: f32,
    pub(super) l: f32,
    pub(super) kappa: f32,
    pub(super) eta_m: f32,
    pub(super) sigma_ms: f32,
    pub(super) sigma_ma: f32,
    pub(super) g: f32,
    pub(super) closure: Closure,
}

/// One field of the LUT header's parameter block ([`ResolvedParams::fields`]; docs/model.md
/// §2, docs/lut.md "Header").
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum HeaderField {
    /// The colour, one record at σ_ca's position (it stands for σ_ca, eumelanin and
    /// pheomelanin).
    Pigment(Pigment),
    /// A scalar parameter and its value.
    Scalar(ParamName, f32),
    /// A choice parameter (`closure`) and the index of its value.
    Choice(ParamName, u8),
}

/// Number of fields of the LUT header's parameter block ([`ResolvedParams::fields`], docs/model.md
/// §2): the 14 parameters, the three colour ones as one.
pub const HEADER_FIELDS: usize = 12;

impl FurParamsInput {
    /// The parameters with every default written out (docs/model.md §2): β_n = β_m and
    /// η_m = η_c where absent, the rules of the [`SCHEMA`](super::SCHEMA) rows whose
    /// default is [`ParamDefault::SameAs`](super::ParamDefault::SameAs).
    #[must_use]
    pub fn resolve(&self) -> ResolvedParams {
        ResolvedParams {
            eta_c: self.eta_c,
            pigment: self.pigment,
            alpha_deg: self.alpha_deg,
            beta_m_deg: self.beta_m_deg,
            beta_n_deg: self.beta_n_deg.unwrap_or(self.beta_m_deg),
            l: self.l,
            kappa: self.kappa,
            eta_m: self.eta_m.unwrap_or(self.eta_c),
            sigma_ms: self.sigma_ms,
            sigma_ma: self.sigma_ma,
            g: self.g,
            closure: self.closure,
        }
    }

    /// [`FurParamsInput::resolve`] as a [`FurParamsInput`] (β_n and η_m present).
    #[must_use]
    pub fn resolved(&self) -> FurParamsInput {
        self.resolve().input()
    }
}

impl ResolvedParams {
    /// The same parameters as a [`FurParamsInput`], β_n and η_m given.
    #[must_use]
    pub fn input(&self) -> FurParamsInput {
        FurParamsInput {
            eta_c: self.eta_c,
            pigment: self.pigment,
            alpha_deg: self.alpha_deg,
            beta_m_deg: self.beta_m_deg,
            beta_n_deg: Some(self.beta_n_deg),
            l: self.l,
            kappa: self.kappa,
            eta_m: Some(self.eta_m),
            sigma_ms: self.sigma_ms,
            sigma_ma: self.sigma_ma,
            g: self.g,
            closure: self.closure,
        }
    }

    /// The colour.
    #[must_use]
    pub fn pigment(&self) -> Pigment {
        self.pigment
    }

    /// The parameter block of the LUT header in [`ParamName::ALL`] order, the colour as one
    /// [`HeaderField::Pigment`] at σ_ca's position (docs/lut.md "Header").
    #[must_use]
    pub fn fields(&self) -> [HeaderField; HEADER_FIELDS] {
        use HeaderField::Scalar;
        [
            Scalar(ParamName::EtaC, self.eta_c),
            HeaderField::Pigment(self.pigment),
            Scalar(ParamName::AlphaDeg, self.alpha_deg),
            Scalar(ParamName::BetaMDeg, self.beta_m_deg),
            Scalar(ParamName::BetaNDeg, self.beta_n_deg),
            Scalar(ParamName::L, self.l),
            Scalar(ParamName::Kappa, self.kappa),
            Scalar(ParamName::EtaM, self.eta_m),
            Scalar(ParamName::SigmaMs, self.sigma_ms),
            Scalar(ParamName::SigmaMa, self.sigma_ma),
            Scalar(ParamName::G, self.g),
            HeaderField::Choice(ParamName::Closure, self.closure.index()),
        ]
    }
}
