//! The colour of one query: the cortex absorption σ_ca per RGB channel (docs/model.md §2), as a
//! baked LUT takes it per query (docs/lut.md "The absorption axis").
//!
//! σ_ma, η, β, κ and l are scalars of a parameter set, so a channel's far field depends on its
//! own σ_ca alone and every channel is the same function of it: a baked LUT holds table `N` at
//! a set of σ_ca nodes and looks each channel up at its own σ_ca
//! ([`crate::BakedBcsdf::at`]). The analytic model at another colour is the model of the
//! parameters with that σ_ca (`Absorption::apply`, beside the parameters in `params`).

use crate::pigment::Pigment;
use crate::spectrum::Rgb;
use core::fmt;

/// The largest cortex absorption σ_ca per fiber radius (the parameter's domain, docs/model.md
/// §2): the last node of the absorption axis (re-exported as `lut::SIGMA_CA_MAX`).
pub const SIGMA_CA_MAX: f32 = 1000.0;

/// A validated per-channel cortex absorption σ_ca (per fiber radius, docs/model.md §2), each
/// channel in [0, [`SIGMA_CA_MAX`]].
///
/// Rule for inputs outside the domain: NaN and negative values are refused
/// ([`AbsorptionError`]); values above σ_max = 1000 (+∞ included) are clamped to σ_max, the
/// last node of the absorption axis (at σ = 1000 per radius the light a channel sends through
/// the cortex is below 10⁻⁶ of its lossless value: the clamp keeps the fully absorbing limit).
///
/// ```
/// use bcsdf_core::{Absorption, Rgb};
///
/// let red = Absorption::from_sigma(Rgb([0.2, 1.5, 4.0])).unwrap();
/// assert_eq!(red.sigma(), Rgb([0.2, 1.5, 4.0]));
/// // Melanin concentrations (the same mix as `Pigment::Melanin`).
/// let brown = Absorption::from_melanin(1.2, 0.3).unwrap();
/// assert!(brown.sigma().0[2] > brown.sigma().0[0]);
/// // Out of the domain: refused or clamped.
/// assert!(Absorption::from_sigma(Rgb([f32::NAN, 0.0, 0.0])).is_err());
/// assert!(Absorption::from_sigma(Rgb([-1.0, 0.0, 0.0])).is_err());
/// assert_eq!(Absorption::from_sigma(Rgb::splat(f32::INFINITY)).unwrap().sigma(), Rgb::splat(1000.0));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Absorption {
    sigma: Rgb,
}

/// Why a colour was refused: a channel is NaN or negative ([`Absorption`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AbsorptionError {
    /// The first offending input: 0–2 the R, G, B channel of σ_ca, or for
    /// [`Absorption::from_melanin`] 0 eumelanin and 1 pheomelanin.
    pub channel: usize,
    /// Its value.
    pub value: f32,
    /// Whether the value is a melanin concentration (else a σ_ca channel).
    pub melanin: bool,
}

impl fmt::Display for AbsorptionError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.melanin {
            let name = if self.channel == 0 {
                "eumelanin"
            } else {
                "pheomelanin"
            };
            write!(
                f,
                "invalid {name} = {}: a concentration must be a number >= 0",
                self.value
            )
        } else {
            write!(
                f,
                "invalid sigma_ca channel {} = {}: valid range is [0, {SIGMA_CA_MAX}] (larger values are clamped to {SIGMA_CA_MAX})",
                ["R", "G", "B"][self.channel.min(2)],
                self.value
            )
        }
    }
}

impl core::error::Error for AbsorptionError {}

impl Absorption {
    /// Lossless fibers: σ_ca = 0 in every channel.
    pub const LOSSLESS: Absorption = Absorption { sigma: Rgb::ZERO };

    /// σ_ca per channel; NaN or negative channels are refused, channels above
    /// [`SIGMA_CA_MAX`] (+∞ included) clamped to it.
    pub fn from_sigma(sigma: Rgb) -> Result<Absorption, AbsorptionError> {
        for (channel, &value) in sigma.0.iter().enumerate() {
            if value.is_nan() || value < 0.0 {
                return Err(AbsorptionError {
                    channel,
                    value,
                    melanin: false,
                });
            }
        }
        Ok(Absorption {
            sigma: sigma.map(|v| v.min(SIGMA_CA_MAX)),
        })
    }

    /// σ_ca from eumelanin and pheomelanin concentrations, mixed as [`Pigment::Melanin`]
    /// does ([`Pigment::sigma_ca`], the one formula); NaN or negative concentrations are
    /// refused, the resulting channels clamped as [`Absorption::from_sigma`].
    pub fn from_melanin(eumelanin: f32, pheomelanin: f32) -> Result<Absorption, AbsorptionError> {
        for (channel, value) in [eumelanin, pheomelanin].into_iter().enumerate() {
            if value.is_nan() || value < 0.0 {
                return Err(AbsorptionError {
                    channel,
                    value,
                    melanin: true,
                });
            }
        }
        let mix = Pigment::Melanin {
            eumelanin,
            pheomelanin,
        }
        .sigma_ca()
        .unwrap_or(Rgb::ZERO);
        Absorption::from_sigma(mix)
    }

    /// The colour of a pigment ([`Pigment::sigma_ca`]), checked as [`Absorption::from_sigma`];
    /// `Ok(None)` for a base colour, which needs the fur's coat colour table
    /// ([`Absorption::from_base_colour`], docs/model.md §14).
    pub fn from_pigment(pigment: &Pigment) -> Result<Option<Absorption>, AbsorptionError> {
        match *pigment {
            Pigment::Absorption(s) => Absorption::from_sigma(s).map(Some),
            Pigment::Melanin {
                eumelanin,
                pheomelanin,
            } => Absorption::from_melanin(eumelanin, pheomelanin).map(Some),
            Pigment::BaseColour(_) => Ok(None),
        }
    }

    /// σ_ca per channel.
    #[must_use]
    pub fn sigma(&self) -> Rgb {
        self.sigma
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pigment::{EUMELANIN_SIGMA_A, PHEOMELANIN_SIGMA_A};

    #[test]
    fn colours_are_checked_and_clamped_by_the_documented_rule() {
        let ok = Absorption::from_sigma(Rgb([0.0, 3.5, 1000.0])).unwrap();
        assert_eq!(ok.sigma(), Rgb([0.0, 3.5, 1000.0]));
        let big = Absorption::from_sigma(Rgb([1e30, f32::INFINITY, 1000.5])).unwrap();
        assert_eq!(big.sigma(), Rgb::splat(SIGMA_CA_MAX));
        for (c, bad) in [(0, f32::NAN), (1, -1e-9), (2, f32::NEG_INFINITY)] {
            let mut s = [0.5; 3];
            s[c] = bad;
            let e = Absorption::from_sigma(Rgb(s)).unwrap_err();
            assert_eq!(e.channel, c);
            assert!(!e.melanin);
            assert!(std::format!("{e}").contains("sigma_ca"));
        }
        let e = Absorption::from_melanin(1.0, f32::NAN).unwrap_err();
        assert!(e.melanin && e.channel == 1);
        assert!(std::format!("{e}").contains("pheomelanin"));
        assert!(Absorption::from_melanin(-0.1, 0.0).is_err());
    }

    #[test]
    fn melanin_uses_the_pigment_mix() {
        let a = Absorption::from_melanin(2.0, 0.5).unwrap();
        assert_eq!(
            a.sigma(),
            EUMELANIN_SIGMA_A * 2.0 + PHEOMELANIN_SIGMA_A * 0.5
        );
        let p = Pigment::Melanin {
            eumelanin: 2.0,
            pheomelanin: 0.5,
        };
        assert_eq!(Absorption::from_pigment(&p).unwrap(), Some(a));
    }

    extern crate std;
}
