//! Colouring a fiber: the cortex absorption σ_ca (docs/model.md §2) from melanin, given
//! directly, or from the base colour of the coat (docs/model.md §14).

use crate::spectrum::Rgb;

/// Eumelanin absorption per unit concentration, per fiber radius (d'Eon 2011, pbrt-v4).
pub const EUMELANIN_SIGMA_A: Rgb = Rgb([0.419, 0.697, 1.37]);
/// Pheomelanin absorption per unit concentration, per fiber radius (d'Eon 2011, pbrt-v4).
pub const PHEOMELANIN_SIGMA_A: Rgb = Rgb([0.187, 0.4, 1.05]);

/// How a fiber's cortex absorption σ_ca is specified.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Pigment {
    /// σ_ca given directly, per RGB channel, per fiber radius.
    Absorption(Rgb),
    /// σ_ca = eumelanin · σ_eu + pheomelanin · σ_pheo (concentrations ≥ 0).
    Melanin {
        /// Eumelanin concentration.
        eumelanin: f32,
        /// Pheomelanin concentration.
        pheomelanin: f32,
    },
    /// The linear RGB colour the coat should show (docs/model.md §14), channels in [0, 1]:
    /// σ_ca is the inverse of the fur's coat colour table
    /// ([`Absorption::from_base_colour`](crate::Absorption::from_base_colour)), so it needs
    /// that table (measured from a baked LUT) before it is a σ_ca.
    BaseColour(Rgb),
}

impl Pigment {
    /// The cortex absorption σ_ca this pigment stands for (not validated here); `None` for a
    /// base colour, whose σ_ca depends on the fur's coat colour table (docs/model.md §14).
    #[must_use]
    pub fn sigma_ca(&self) -> Option<Rgb> {
        match *self {
            Pigment::Absorption(s) => Some(s),
            Pigment::Melanin {
                eumelanin,
                pheomelanin,
            } => Some(EUMELANIN_SIGMA_A * eumelanin + PHEOMELANIN_SIGMA_A * pheomelanin),
            Pigment::BaseColour(_) => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn melanin_mixes_the_two_pigments_linearly() {
        let eu = Pigment::Melanin {
            eumelanin: 1.0,
            pheomelanin: 0.0,
        };
        assert_eq!(eu.sigma_ca(), Some(EUMELANIN_SIGMA_A));
        let mix = Pigment::Melanin {
            eumelanin: 0.5,
            pheomelanin: 2.0,
        };
        let want = EUMELANIN_SIGMA_A * 0.5 + PHEOMELANIN_SIGMA_A * 2.0;
        assert_eq!(mix.sigma_ca(), Some(want));
        // Melanin absorbs blue most: brown and red fibers.
        for s in [EUMELANIN_SIGMA_A, PHEOMELANIN_SIGMA_A] {
            assert!(s.0[0] < s.0[1] && s.0[1] < s.0[2]);
        }
        let given = Rgb([0.1, 0.2, 0.3]);
        assert_eq!(Pigment::Absorption(given).sigma_ca(), Some(given));
        assert_eq!(Pigment::BaseColour(given).sigma_ca(), None);
    }
}
