//! The analytic sampler's per-view context (docs/model.md §10): [`AnalyticView`], and the
//! [`Bcsdf`] methods of [`FurBcsdf`], which go through one.

use super::Plan;
use crate::bcsdf::{
    at_one_view, finish, solid_angle_pdf, Bcsdf, Evaluated, Sample, SampledDirection,
};
use crate::frame::{Angles, Vec3};
use crate::lobes::Families;
use crate::math::{cos_within_half_pi, Math, PI};
use crate::model::FurBcsdf;

/// The analytic sampler at one view direction θ_r ([`FurBcsdf::view`]): the mixture's part
/// weights, h-segments, longitudinal intervals and C^M rows of docs/model.md §10, computed
/// once; `sample_direction` then costs one draw, and `pdf` one far-field evaluation (the h
/// integrals) without the per-view set-up. The [`Bcsdf`] methods of [`FurBcsdf`] build a view
/// per call, so both give the same bits.
///
/// ```
/// # fn demo(model: &bcsdf_core::FurBcsdf) {
/// use bcsdf_core::Bcsdf;
/// let view = model.view(0.3).unwrap(); // θ_r = 0.3 rad
/// if let Some(d) = view.sample_direction([0.2, 0.7, 0.4]) {
///     let a = d.angles;
///     assert_eq!(view.pdf(a.theta_i(), a.phi()), model.pdf(&a));
/// }
/// # }
/// ```
pub struct AnalyticView<'m, 'a, M: Math> {
    plan: Plan<'m, 'a, M>,
    theta_r: f32,
}

impl<'a, M: Math> FurBcsdf<'a, M> {
    /// The analytic sampler at view direction θ_r (radians), its θ_r-only work done once
    /// (docs/model.md §10); `None` unless θ_r is finite and within [−π/2, π/2].
    #[must_use]
    pub fn view(&self, theta_r: f32) -> Option<AnalyticView<'_, 'a, M>> {
        if !(theta_r.is_finite() && theta_r.abs() <= PI / 2.0) {
            return None;
        }
        Some(AnalyticView {
            plan: Plan::new(self, theta_r),
            theta_r,
        })
    }

    /// S and the mixture density of one direction, sharing the h integrals.
    fn eval_and_density(&self, angles: &Angles) -> (Families, f32) {
        self.eval_and_density_with(&Plan::new(self, angles.theta_r()), angles)
    }

    /// [`FurBcsdf::eval_and_density`] with the view's plan built (θ_r of `angles` is the
    /// plan's).
    fn eval_and_density_with(&self, plan: &Plan<'_, 'a, M>, angles: &Angles) -> (Families, f32) {
        let (ti, tr) = (angles.theta_i(), angles.theta_r());
        let coeffs = plan.coefficients(ti, tr);
        let (n, p) = self.azimuthal_far_with_density(tr, angles.phi(), &coeffs);
        let p = p + plan.residual_density(ti, tr, angles.phi());
        let value = self.assemble(angles, &n).families();
        let pdf = solid_angle_pdf(p, cos_within_half_pi(ti));
        (
            value,
            if pdf.is_finite() && pdf > 0.0 {
                pdf
            } else {
                0.0
            },
        )
    }
}

impl<M: Math> Bcsdf for FurBcsdf<'_, M> {
    type Math = M;

    fn eval(&self, angles: &Angles) -> Families {
        self.eval_far(angles)
    }

    fn pdf(&self, angles: &Angles) -> f32 {
        self.eval_and_density(angles).1
    }

    fn eval_with_pdf(&self, angles: &Angles) -> (Families, f32) {
        self.eval_and_density(angles)
    }

    fn sample_direction(&self, theta_r: f32, u: [f32; 3]) -> Option<SampledDirection> {
        self.view(theta_r)?.sample_direction(u)
    }

    /// A sample with its density and S, from one view.
    fn sample(&self, theta_r: f32, u: [f32; 3]) -> Option<Sample> {
        self.view(theta_r)?.sample(u)
    }

    /// One [`AnalyticView`] for the light's direction and the sample.
    fn eval_and_sample_dirs(
        &self,
        wl: Vec3,
        wr: Vec3,
        tangent: Vec3,
        u: [f32; 3],
    ) -> (Option<Evaluated>, Option<Sample>) {
        at_one_view(
            self,
            (wl, wr, tangent),
            u,
            |theta_r| self.view(theta_r),
            |v, a| self.eval_and_density_with(&v.plan, a),
            |v, u| v.sample(u),
        )
    }
}

impl<M: Math> AnalyticView<'_, '_, M> {
    /// θ_r of the view (radians).
    #[must_use]
    pub fn theta_r(&self) -> f32 {
        self.theta_r
    }

    /// Draws ω_i from three uniform numbers, without evaluating S, as
    /// [`Bcsdf::sample_direction`] (the same bits).
    #[must_use]
    pub fn sample_direction(&self, u: [f32; 3]) -> Option<SampledDirection> {
        self.plan.draw(self.theta_r, u)
    }

    /// Importance-samples ω_i from three uniform numbers, as [`Bcsdf::sample`] (the same
    /// bits): the draw, then S and the density at the same plan.
    #[must_use]
    pub fn sample(&self, u: [f32; 3]) -> Option<Sample> {
        let d = self.sample_direction(u)?;
        let (value, pdf) = self.plan.model.eval_and_density_with(&self.plan, &d.angles);
        finish(d, value, pdf, None)
    }

    /// S and the density of ω_i = (θ_i, φ) at this view, as [`Bcsdf::eval_with_pdf`] (the
    /// same bits); zero for invalid angles.
    pub fn eval_with_pdf(&self, theta_i: f32, phi: f32) -> (Families, f32) {
        match Angles::new(theta_i, self.theta_r, phi) {
            Ok(a) => self.plan.model.eval_and_density_with(&self.plan, &a),
            Err(_) => (Families::ZERO, 0.0),
        }
    }

    /// Density per unit solid angle of ω_i = (θ_i, φ) at this view (docs/model.md §10), as
    /// [`Bcsdf::pdf`] (the same bits); 0 for invalid angles.
    #[must_use]
    pub fn pdf(&self, theta_i: f32, phi: f32) -> f32 {
        self.eval_with_pdf(theta_i, phi).1
    }
}
