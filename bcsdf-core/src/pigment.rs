//! Colouring a fiber: the cortex absorption σ_ca (docs/model.md §2) from melanin or given directly.

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
}

impl Pigment {
    /// The cortex absorption σ_ca this pigment stands for (not validated here).
    #[must_use]
    pub fn sigma_ca(&self) -> Rgb {
        match *self {
            Pigment::Absorption(s) => s,
            Pigment::Melanin {
                eumelanin,
                pheomelanin,
            } => EUMELANIN_SIGMA_A * eumelanin + PHEOMELANIN_SIGMA_A * pheomelanin,
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
        assert_eq!(eu.sigma_ca(), EUMELANIN_SIGMA_A);
        let mix = Pigment::Melanin {
            eumelanin: 0.5,
            pheomelanin: 2.0,
        };
        let want = EUMELANIN_SIGMA_A * 0.5 + PHEOMELANIN_SIGMA_A * 2.0;
        assert_eq!(mix.sigma_ca(), want);
        // Melanin absorbs blue most: brown and red fibers.
        for s in [EUMELANIN_SIGMA_A, PHEOMELANIN_SIGMA_A] {
            assert!(s.0[0] < s.0[1] && s.0[1] < s.0[2]);
        }
        let given = Rgb([0.1, 0.2, 0.3]);
        assert_eq!(Pigment::Absorption(given).sigma_ca(), given);
    }
}
