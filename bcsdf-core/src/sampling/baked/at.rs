//! Sampling a baked LUT at one colour ([`BakedAt`], docs/model.md §10 "Colour per query"):
//! the sampler's mixture is the lossless plane's whatever the colour, so a view at a colour is
//! the LUT's view with that colour's values.

use crate::baked::BakedAt;
use crate::bcsdf::{Bcsdf, Evaluated, Sample, SampledDirection};
use crate::frame::{AngleError, Angles, Vec3};
use crate::lobes::Families;
use crate::math::Math;
use crate::sampling::baked::BakedView;

impl<'l, 'a, M: Math> BakedAt<'l, 'a, M> {
    /// The sampler at view direction θ_r for this colour ([`crate::baked::BakedBcsdf::view`]): the mixture
    /// does not depend on the colour (it is built from the lossless plane), the values do.
    #[inline]
    #[must_use]
    pub fn view(&self, theta_r: f32) -> Option<BakedView<'l, 'a, M>> {
        self.lut().view_with(theta_r, self.colour())
    }
}

impl<M: Math> Bcsdf for BakedAt<'_, '_, M> {
    type Math = M;

    #[inline]
    fn eval(&self, angles: &Angles) -> Families {
        self.eval_far(angles)
    }

    /// [`crate::baked::BakedBcsdf::angles_from_dirs`].
    #[inline]
    fn angles_from_dirs(&self, wi: Vec3, wr: Vec3, tangent: Vec3) -> Result<Angles, AngleError> {
        self.lut().angles_from_dirs(wi, wr, tangent)
    }

    /// [`BakedAt::eval_far_dirs`].
    #[inline]
    fn eval_dirs(&self, wi: Vec3, wr: Vec3, tangent: Vec3) -> Families {
        self.eval_far_dirs(wi, wr, tangent)
    }

    fn pdf(&self, angles: &Angles) -> f32 {
        self.view(angles.theta_r())
            .map_or(0.0, |v| v.pdf_at(angles))
    }

    fn eval_with_pdf(&self, angles: &Angles) -> (Families, f32) {
        self.view(angles.theta_r())
            .map_or((Families::ZERO, 0.0), |v| v.eval_with_pdf_at(angles))
    }

    fn sample_direction(&self, theta_r: f32, u: [f32; 3]) -> Option<SampledDirection> {
        self.view(theta_r)?.sample_direction(u)
    }

    fn sample(&self, theta_r: f32, u: [f32; 3]) -> Option<Sample> {
        self.view(theta_r)?.sample(u)
    }

    /// One [`BakedView`] at this colour for the light's direction and the sample.
    fn eval_and_sample_dirs(
        &self,
        wl: Vec3,
        wr: Vec3,
        tangent: Vec3,
        u: [f32; 3],
    ) -> (Option<Evaluated>, Option<Sample>) {
        self.lut()
            .eval_and_sample_dirs_with(self.colour(), wl, wr, tangent, u)
    }
}
