//! Colouring a fiber: the cortex absorption σ_ca (MODEL.md §2) from melanin or given directly.

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
