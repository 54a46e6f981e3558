//! The per-view context of the baked sampler (docs/model.md §10): what `pdf` and `sample`
//! need of θ_r alone, computed once per view direction.
//!
//! A path tracer asks, at each bounce, for one sample and the density of one or more other
//! directions (the lights', for multiple importance sampling), all for the same ω_r. The
//! mixture weights A_c(θ_r), their total W and the parts' θ_i ranges with their pole
//! slivers' masses depend on θ_r only; [`BakedBcsdf::view`] computes them once and [`BakedView`] answers `pdf`,
//! `eval_with_pdf` and `sample` from them. The [`Bcsdf`](crate::Bcsdf) methods of
//! [`BakedBcsdf`] go through a view too, so both give the same bits.

use super::rows::Range;
use crate::baked::{BakedBcsdf, ColourAt};
use crate::bcsdf::{at_one_view, finish, Evaluated, Sample, SampledDirection};
use crate::frame::{Angles, Vec3};
use crate::lobes::Families;
use crate::math::{cos_within_half_pi, Math, PI};

/// The baked sampler at one view direction θ_r ([`BakedBcsdf::view`]): the mixture weights
/// and the parts' θ_i range masses (with S's pole factor, including the pole slivers) of
/// docs/model.md §10, computed once; `pdf`, `eval_with_pdf` and
/// `sample` then cost the table lookups of one direction (and, for `sample`, the row
/// inversions).
///
/// ```
/// # fn demo(lut: &bcsdf_core::BakedBcsdf) {
/// use bcsdf_core::Bcsdf;
/// let view = lut.view(0.3).unwrap(); // θ_r = 0.3 rad
/// if let Some(s) = view.sample([0.2, 0.7, 0.4]) {
///     // The light's direction at the same bounce: the density of the same mixture.
///     let p_light = view.pdf(-0.1, 2.5);
///     assert_eq!(s.pdf, view.pdf(s.angles.theta_i(), s.angles.phi()));
///     assert_eq!(s.pdf, lut.pdf(&s.angles));
///     # let _ = p_light;
/// }
/// # }
/// ```
#[derive(Clone, Copy, Debug)]
pub struct BakedView<'l, 'a, M: Math> {
    lut: &'l BakedBcsdf<'a, M>,
    theta_r: f32,
    /// A_c(θ_r) of the five parts (R, TT, TRT, scattered back, front).
    weights: [f32; 5],
    /// The five parts' θ_i ranges and their masses with S's pole factor.
    ranges: [Range; 5],
    /// W = Σ_c A_c.
    total_weight: f32,
    /// The colour the values are evaluated at (the mixture is the lossless plane's).
    colour: ColourAt,
}

impl<'a, M: Math> BakedBcsdf<'a, M> {
    /// The sampler at view direction θ_r (radians), its θ_r-only work done once
    /// (docs/model.md §10); `None` unless θ_r is finite and within [−π/2, π/2].
    #[inline]
    #[must_use]
    pub fn view(&self, theta_r: f32) -> Option<BakedView<'_, 'a, M>> {
        self.view_with(theta_r, self.default_colour())
    }

    /// [`BakedBcsdf::view`] evaluating at a located colour ([`crate::BakedAt::view`]).
    #[inline]
    pub(crate) fn view_with(&self, theta_r: f32, colour: ColourAt) -> Option<BakedView<'_, 'a, M>> {
        if !(theta_r.is_finite() && theta_r.abs() <= PI / 2.0) {
            return None;
        }
        let (weights, ranges) = self.parts(theta_r);
        let [a, b, c, d, e] = weights;
        Some(BakedView {
            lut: self,
            theta_r,
            weights,
            ranges,
            total_weight: a + b + c + d + e,
            colour,
        })
    }

    /// [`Bcsdf::eval_and_sample_dirs`](crate::Bcsdf::eval_and_sample_dirs) at `colour`: one
    /// view for the light's direction and the sample.
    pub(crate) fn eval_and_sample_dirs_with(
        &self,
        colour: ColourAt,
        wl: Vec3,
        wr: Vec3,
        tangent: Vec3,
        u: [f32; 3],
    ) -> (Option<Evaluated>, Option<Sample>) {
        at_one_view(
            self,
            (wl, wr, tangent),
            u,
            |theta_r| self.view_with(theta_r, colour),
            |v, a| v.eval_with_pdf_at(a),
            |v, u| v.sample(u),
        )
    }
}

impl<M: Math> BakedView<'_, '_, M> {
    /// θ_r of the view (radians).
    #[must_use]
    pub fn theta_r(&self) -> f32 {
        self.theta_r
    }

    /// Density per unit solid angle of ω_i = (θ_i, φ) at this view (docs/model.md §10), the
    /// same bits as [`Bcsdf::pdf`](crate::Bcsdf::pdf) of those angles; 0 for invalid angles.
    #[must_use]
    pub fn pdf(&self, theta_i: f32, phi: f32) -> f32 {
        match Angles::new(theta_i, self.theta_r, phi) {
            Ok(a) => self.pdf_at(&a),
            Err(_) => 0.0,
        }
    }

    /// S and the density of ω_i = (θ_i, φ) at this view, sharing the table lookups; the same
    /// bits as [`Bcsdf::eval_with_pdf`](crate::Bcsdf::eval_with_pdf). Zero for invalid angles.
    pub fn eval_with_pdf(&self, theta_i: f32, phi: f32) -> (Families, f32) {
        match Angles::new(theta_i, self.theta_r, phi) {
            Ok(a) => self.eval_with_pdf_at(&a),
            Err(_) => (Families::ZERO, 0.0),
        }
    }

    /// Draws ω_i from three uniform numbers, without evaluating S, as
    /// [`Bcsdf::sample_direction`](crate::Bcsdf::sample_direction).
    #[must_use]
    pub fn sample_direction(&self, u: [f32; 3]) -> Option<SampledDirection> {
        self.lut.draw(self.theta_r, (self.weights, self.ranges), u)
    }

    /// Importance-samples ω_i from three uniform numbers: direction, density, weight, as
    /// [`Bcsdf::sample`](crate::Bcsdf::sample) (the same bits).
    #[must_use]
    pub fn sample(&self, u: [f32; 3]) -> Option<Sample> {
        let d = self.sample_direction(u)?;
        let (value, pdf) = self.eval_with_pdf_at(&d.angles);
        finish(d, value, pdf, None)
    }

    /// [`BakedView::pdf`] of validated angles whose θ_r is the view's.
    #[inline(always)]
    pub(crate) fn pdf_at(&self, a: &Angles) -> f32 {
        let l = self.lut.lookups(a, &self.colour);
        BakedBcsdf::<M>::density(&l, self.total_weight, cos_within_half_pi(a.theta_i()))
    }

    /// [`BakedView::eval_with_pdf`] of validated angles whose θ_r is the view's.
    #[inline]
    pub(crate) fn eval_with_pdf_at(&self, a: &Angles) -> (Families, f32) {
        let l = self.lut.lookups(a, &self.colour);
        let pdf = BakedBcsdf::<M>::density(&l, self.total_weight, cos_within_half_pi(a.theta_i()));
        (BakedBcsdf::<M>::assemble(&l), pdf)
    }
}

#[cfg(test)]
mod tests {
    use crate::baked::tests::random as blob;
    use crate::baked::BakedBcsdf;
    use crate::rng::Pcg32;
    use crate::{Angles, Bcsdf};

    #[test]
    fn a_view_answers_as_the_trait_does_at_its_theta_r() {
        let b = blob();
        let lut = BakedBcsdf::from_bytes(b).unwrap();
        let mut rng = Pcg32::new(22, 3);
        let mut positive = 0;
        // Under Miri (CI's unsafe-code check, ~10⁴ times slower) a thirtieth of the views.
        let views = if cfg!(miri) { 10 } else { 300 };
        for k in 0..views {
            let theta_r = (rng.uniform() - 0.5) * core::f32::consts::PI;
            let view = lut.view(theta_r).unwrap();
            assert_eq!(view.theta_r(), theta_r);
            // Several calls at one view, interleaved, each equal to the trait's.
            for _ in 0..4 {
                let u = [rng.uniform(), rng.uniform(), rng.uniform()];
                assert_eq!(view.sample(u), lut.sample(theta_r, u), "{k}");
                assert_eq!(view.sample_direction(u), lut.sample_direction(theta_r, u));
                let (ti, phi) = ((rng.uniform() - 0.5) * 3.1, (rng.uniform() - 0.5) * 6.2);
                let a = Angles::new(ti, theta_r, phi).unwrap();
                let p = view.pdf(ti, phi);
                assert_eq!(p.to_bits(), lut.pdf(&a).to_bits(), "{a:?}");
                let (value, p2) = view.eval_with_pdf(ti, phi);
                assert_eq!(p2.to_bits(), p.to_bits());
                assert_eq!(value, lut.eval(&a));
                positive += usize::from(p > 0.0);
            }
        }
        // Most random (θ_i, φ) carry density (1000 of 1200 in the full run).
        assert!(positive * 6 > views * 4 * 5, "{positive} of {}", views * 4);
        // Invalid angles: no view, or zero.
        assert!(lut.view(f32::NAN).is_none() && lut.view(1.6).is_none());
        let view = lut.view(0.2).unwrap();
        assert_eq!(view.pdf(1.6, 0.3), 0.0);
        assert_eq!(view.pdf(0.1, f32::INFINITY), 0.0);
        assert_eq!(view.eval_with_pdf(f32::NAN, 0.3).1, 0.0);
    }
}
