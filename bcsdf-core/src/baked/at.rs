//! A baked LUT at one colour ([`BakedBcsdf::at`], docs/lut.md "The absorption axis"): the
//! colour is located on the absorption axis once, then every query reads table `N` at that
//! colour. [`BakedAt`] implements [`crate::Bcsdf`] (in `sampling::baked::at`), so a renderer that colours each strand (or each
//! shading point) makes one per query and calls the trait as for the LUT itself.

use super::{BakedBcsdf, ColourAt, EvalAt, EvalDirs};
use crate::absorption::Absorption;
use crate::frame::{AngleError, Angles, Vec3};
use crate::lobes::Families;
use crate::math::Math;

/// A [`BakedBcsdf`] evaluated, sampled and given a pdf at one colour ([`BakedBcsdf::at`]):
/// a borrowed LUT and the colour's place on the absorption axis. Cheap to make (three
/// divisions) and to copy; no allocation.
///
/// ```
/// # fn demo(lut: &bcsdf_core::BakedBcsdf) {
/// use bcsdf_core::{Absorption, Angles, Bcsdf, Rgb};
///
/// let a = Angles::from_degrees(30.0, -20.0, 150.0).unwrap();
/// let ginger = Absorption::from_melanin(0.4, 1.5).unwrap();
/// let s = lut.at(&ginger).eval(&a).total(); // S at this strand's colour
/// let sample = lut.at(&ginger).sample(a.theta_r(), [0.3, 0.6, 0.2]);
/// // The preset's own colour is the default: `lut.eval` = `lut.at(&lut.absorption())`.
/// assert_eq!(lut.eval(&a), lut.at(&lut.absorption()).eval(&a));
/// # let _ = (s, sample);
/// # }
/// ```
#[derive(Clone, Copy, Debug)]
pub struct BakedAt<'l, 'a, M: Math> {
    lut: &'l BakedBcsdf<'a, M>,
    colour: ColourAt,
}

impl<'a, M: Math> BakedBcsdf<'a, M> {
    /// This LUT at colour `absorption` (docs/lut.md "The absorption axis"): each RGB channel
    /// reads table `N` at its own σ_ca.
    #[inline]
    #[must_use]
    pub fn at(&self, absorption: &Absorption) -> BakedAt<'_, 'a, M> {
        BakedAt {
            lut: self,
            colour: self.locate_colour(absorption.sigma()),
        }
    }

    /// This LUT at an already located colour ([`BakedBcsdf::locate_colour`]).
    #[inline]
    #[must_use]
    pub fn at_located(&self, colour: ColourAt) -> BakedAt<'_, 'a, M> {
        BakedAt { lut: self, colour }
    }

    /// The preset's own colour: the σ_ca of the LUT's parameters (clamped to the absorption
    /// axis as [`Absorption::from_sigma`] does; the parameters are validated, so never
    /// refused).
    #[must_use]
    pub fn absorption(&self) -> Absorption {
        Absorption::from_sigma(self.params().sigma_ca()).unwrap_or(Absorption::LOSSLESS)
    }
}

impl<'l, 'a, M: Math> BakedAt<'l, 'a, M> {
    /// The LUT.
    #[must_use]
    pub fn lut(&self) -> &'l BakedBcsdf<'a, M> {
        self.lut
    }

    /// The located colour.
    #[must_use]
    pub fn colour(&self) -> ColourAt {
        self.colour
    }

    /// Far-field S per lobe family at this colour ([`BakedBcsdf::eval_far`]).
    #[inline]
    pub fn eval_far(&self, angles: &Angles) -> Families {
        self.lut.dispatch(EvalAt(angles, &self.colour))
    }

    /// Far-field S from world-space directions at this colour
    /// ([`BakedBcsdf::eval_far_dirs`]); invalid directions give zero.
    #[inline]
    pub fn eval_far_dirs(&self, wi: Vec3, wr: Vec3, tangent: Vec3) -> Families {
        self.try_eval_far_dirs(wi, wr, tangent)
            .unwrap_or(Families::ZERO)
    }

    /// [`BakedAt::eval_far_dirs`], or why the directions were rejected.
    #[inline]
    pub fn try_eval_far_dirs(
        &self,
        wi: Vec3,
        wr: Vec3,
        tangent: Vec3,
    ) -> Result<Families, AngleError> {
        self.lut
            .dispatch(EvalDirs(&wi, &wr, &tangent, &self.colour))
    }
}
