//! The engine-facing interface: one trait, [`Bcsdf`], for the analytic far field
//! ([`crate::FurBcsdf`]) and the baked tables ([`crate::baked::BakedBcsdf`]): evaluation,
//! importance sampling and the sampling density (docs/model.md §10).
//!
//! Conventions (docs/model.md §10):
//! - `eval` is the far-field S(ω_i, ω_r) of docs/model.md §8, per [`LobeFamily`].
//! - `pdf` is the density of ω_i given ω_r **per unit solid angle**, of the whole mixture the
//!   sampler draws from (not of the family it happened to pick). With dω_i = cos θ_i dθ_i dφ,
//!   p_ω = p(θ_i, φ) / cos θ_i ([`solid_angle_pdf`]).
//! - A [`Sample`] carries ω_i, p_ω (the same number `pdf` returns for that direction), the
//!   family it was drawn from and the weight S·cos θ_i / p_ω, the Monte Carlo estimate of
//!   the reflected radiance for unit incident radiance from ω_i.

use crate::frame::{AngleError, Angles, Frame, Vec3};
use crate::lobes::{Families, LobeFamily};
use crate::math::Math;
use crate::spectrum::Rgb;

/// Smallest cos θ_i the solid-angle conversion p_ω = p(θ_i, φ)/cos θ_i divides by. Only
/// directions within 1e-6 rad of the fiber axis are affected, a solid angle of order 1e-12.
pub const MIN_COS_THETA_PDF: f32 = 1e-6;

/// p_ω = p(θ_i, φ)/cos θ_i: a density over (θ_i, φ) as a density per unit solid angle
/// (docs/model.md §10), with cos θ_i kept at or above [`MIN_COS_THETA_PDF`].
#[inline]
#[must_use]
pub fn solid_angle_pdf(p_theta_phi: f32, cos_theta_i: f32) -> f32 {
    p_theta_phi / cos_theta_i.max(MIN_COS_THETA_PDF)
}

/// An importance-sampled incident direction (docs/model.md §10).
#[derive(Clone, Copy, Debug, PartialEq)]
#[must_use]
pub struct Sample {
    /// The sampled ω_i as angles: θ_i, the given θ_r, and φ = φ_r − φ_i.
    pub angles: Angles,
    /// ω_i as a world-space unit vector, from [`Bcsdf::sample_dirs`]; `None` from
    /// [`Bcsdf::sample`] (angles only; [`Frame::to_world`] turns them into a vector).
    pub wi: Option<Vec3>,
    /// Density of ω_i per unit solid angle: equals [`Bcsdf::pdf`] for the same direction.
    pub pdf: f32,
    /// S(ω_i, ω_r)·cos θ_i / pdf, RGB.
    pub weight: Rgb,
    /// The family whose lobe was sampled.
    pub family: LobeFamily,
}

/// A direction evaluated at a path vertex ([`Bcsdf::eval_and_sample_dirs`]): its angles, S
/// and the sampling density, as [`Bcsdf::angles_from_dirs`] and [`Bcsdf::eval_with_pdf`]
/// give them.
#[derive(Clone, Copy, Debug, PartialEq)]
#[must_use]
pub struct Evaluated {
    /// θ_i, θ_r, φ of the direction.
    pub angles: Angles,
    /// S(ω_i, ω_r) per family.
    pub value: Families,
    /// Density per unit solid angle with which [`Bcsdf::sample`] draws the direction.
    pub pdf: f32,
}

/// A sampled direction before evaluation: angles, and the family it came from.
#[derive(Clone, Copy, Debug, PartialEq)]
#[must_use]
pub struct SampledDirection {
    /// θ_i, θ_r, φ.
    pub angles: Angles,
    /// The family whose lobe was sampled.
    pub family: LobeFamily,
}

/// A far-field fur BCSDF as a path tracer or an engine uses it: evaluation, sampling and
/// the sampling density, from angles and from world-space vectors (docs/model.md §8, §10).
///
/// Implemented by the analytic model ([`crate::FurBcsdf`]) and the baked tables
/// ([`crate::baked::BakedBcsdf`]). No method allocates, panics or returns NaN.
///
/// Conventions (docs/model.md §10): `eval` is the far-field S(ω_i, ω_r) per [`LobeFamily`];
/// `pdf` is the density of ω_i given ω_r **per unit solid angle** of the whole mixture the
/// sampler draws from, p_ω = p(θ_i, φ)/cos θ_i ([`solid_angle_pdf`]); a [`Sample`] carries
/// that same density and the weight S·cos θ_i/p_ω, the Monte Carlo estimate of the radiance
/// reflected toward ω_r for unit radiance arriving from ω_i.
///
/// ```
/// use bcsdf_core::{presets, Bcsdf, FurBcsdf, FurParams, Rgb};
///
/// /// Radiance reflected toward θ_r under uniform unit illumination (the albedo), estimated
/// /// from `n` importance samples. Works for either evaluator.
/// fn albedo(bcsdf: &impl Bcsdf, theta_r: f32, n: u32) -> Rgb {
///     let mut sum = Rgb::ZERO;
///     for k in 0..n {
///         let u = [(k as f32 + 0.5) / n as f32, (k as f32 * 0.618_034).fract(), 0.5];
///         if let Some(s) = bcsdf.sample(theta_r, u) {
///             // The sample's density is the one `pdf` gives for its direction.
///             assert!((s.pdf - bcsdf.pdf(&s.angles)).abs() <= 1e-5 * s.pdf);
///             sum += s.weight;
///         }
///     }
///     sum * (1.0 / n as f32)
/// }
///
/// let params = FurParams::new(&presets::find("human-hair").unwrap().input).unwrap();
/// let hair: FurBcsdf = FurBcsdf::unscattered(params);
/// let a = albedo(&hair, 0.3, 64);
/// // Pigmented hair absorbs part of the light, more of the blue.
/// assert!(a.0.iter().all(|&c| c > 0.0 && c < 1.0) && a.0[2] < a.0[0]);
/// ```
pub trait Bcsdf {
    /// The math backend used for direction-to-angle conversions.
    type Math: Math;

    /// Far-field S(ω_i, ω_r) per [`LobeFamily`]; [`Families::total`] is S (docs/model.md §8).
    fn eval(&self, angles: &Angles) -> Families;

    /// Density per unit solid angle with which [`Bcsdf::sample`] draws ω_i given ω_r
    /// (docs/model.md §10); 0 where it never samples. Positive wherever `eval` is.
    #[must_use]
    fn pdf(&self, angles: &Angles) -> f32;

    /// `eval` and `pdf` of one direction, sharing their work.
    fn eval_with_pdf(&self, angles: &Angles) -> (Families, f32) {
        (self.eval(angles), self.pdf(angles))
    }

    /// Draws ω_i given θ_r from three uniform numbers in [0, 1) (values outside are
    /// clamped) without evaluating S; `None` when θ_r is invalid or nothing can be sampled
    /// (zero albedo).
    #[must_use]
    fn sample_direction(&self, theta_r: f32, u: [f32; 3]) -> Option<SampledDirection>;

    /// Importance-samples ω_i given θ_r (radians) from three uniform numbers in [0, 1):
    /// direction, density, weight S·cos θ_i/pdf and family. `None` when θ_r is not finite or
    /// outside [−π/2, π/2], or when nothing can be sampled (zero albedo).
    #[must_use]
    fn sample(&self, theta_r: f32, u: [f32; 3]) -> Option<Sample> {
        let d = self.sample_direction(theta_r, u)?;
        let (value, pdf) = self.eval_with_pdf(&d.angles);
        finish(d, value, pdf, None)
    }

    /// The one direction-to-angle conversion of this evaluator (docs/model.md §1): θ_i, θ_r
    /// and φ of world-space directions `wi` (toward the light), `wr` (toward the viewer) and
    /// the fiber tangent (none needs to be unit length). [`Bcsdf::eval_dirs`],
    /// [`Bcsdf::pdf_dirs`] and [`Bcsdf::sample_dirs`] all see the angles it gives, so the
    /// value, the density and the sampler of the same vectors agree bit for bit on them.
    ///
    /// By default [`Angles::from_directions`] with [`Bcsdf::Math`]; the baked evaluator
    /// uses its branch-free polynomials ([`crate::baked::BakedBcsdf::angles_from_dirs`]).
    /// θ_r depends on `wr` and the tangent only.
    fn angles_from_dirs(&self, wi: Vec3, wr: Vec3, tangent: Vec3) -> Result<Angles, AngleError> {
        Angles::from_directions::<Self::Math>(wi, wr, tangent)
    }

    /// [`Bcsdf::eval`] from world-space directions `wi` (toward the light), `wr` (toward
    /// the viewer) and the fiber tangent (none needs to be unit length), at the angles of
    /// [`Bcsdf::angles_from_dirs`]; zero for invalid directions.
    fn eval_dirs(&self, wi: Vec3, wr: Vec3, tangent: Vec3) -> Families {
        match self.angles_from_dirs(wi, wr, tangent) {
            Ok(a) => self.eval(&a),
            Err(_) => Families::ZERO,
        }
    }

    /// [`Bcsdf::eval_with_pdf`] from world-space directions, at the angles of
    /// [`Bcsdf::angles_from_dirs`], with those angles; `None` for invalid directions.
    fn eval_with_pdf_dirs(&self, wi: Vec3, wr: Vec3, tangent: Vec3) -> Option<Evaluated> {
        let angles = self.angles_from_dirs(wi, wr, tangent).ok()?;
        let (value, pdf) = self.eval_with_pdf(&angles);
        Some(Evaluated { angles, value, pdf })
    }

    /// [`Bcsdf::pdf`] from world-space directions, at the angles of
    /// [`Bcsdf::angles_from_dirs`]; zero for invalid directions.
    #[must_use]
    fn pdf_dirs(&self, wi: Vec3, wr: Vec3, tangent: Vec3) -> f32 {
        match self.angles_from_dirs(wi, wr, tangent) {
            Ok(a) => self.pdf(&a),
            Err(_) => 0.0,
        }
    }

    /// [`Bcsdf::sample`] from the world-space view direction `wr` and fiber tangent, at the
    /// θ_r of [`Bcsdf::angles_from_dirs`]; the sample's `wi` is a world-space unit vector
    /// ([`Frame::to_world`]). `None` for invalid directions.
    #[must_use]
    fn sample_dirs(&self, wr: Vec3, tangent: Vec3, u: [f32; 3]) -> Option<Sample> {
        // θ_r depends on ω_r and the tangent only: ω_r itself stands in for ω_i.
        let theta_r = self.angles_from_dirs(wr, wr, tangent).ok()?.theta_r();
        let frame = Frame::from_view::<Self::Math>(wr, tangent)?;
        let s = self.sample(theta_r, u)?;
        Some(Sample {
            wi: Some(frame.to_world(&s.angles)),
            ..s
        })
    }

    /// What a path tracer asks at one vertex, all at the same ω_r and tangent (docs/model.md
    /// §10, §11): S and the density of the light's direction `wl` (next-event estimation,
    /// [`Bcsdf::eval_with_pdf_dirs`]; `None` for an invalid `wl`),
    /// and a sampled continuation ([`Bcsdf::sample_dirs`]). The same bits as those calls
    /// made apart; the baked evaluator builds its per-view context ([`crate::BakedView`])
    /// once for both.
    fn eval_and_sample_dirs(
        &self,
        wl: Vec3,
        wr: Vec3,
        tangent: Vec3,
        u: [f32; 3],
    ) -> (Option<Evaluated>, Option<Sample>) {
        (
            self.eval_with_pdf_dirs(wl, wr, tangent),
            self.sample_dirs(wr, tangent, u),
        )
    }
}

/// [`Bcsdf::eval_and_sample_dirs`] of an evaluator with a per-view context (docs/model.md
/// §10): `view` builds it at θ_r, `eval` gives S and the density of a direction at it,
/// `sample` draws at it. θ_r is the light's angles' (it depends on ω_r and the tangent
/// alone), or ω_r's own when the light's direction has no angles.
#[inline]
pub(crate) fn at_one_view<B: Bcsdf + ?Sized, V>(
    b: &B,
    (wl, wr, tangent): (Vec3, Vec3, Vec3),
    u: [f32; 3],
    view: impl FnOnce(f32) -> Option<V>,
    eval: impl FnOnce(&V, &Angles) -> (Families, f32),
    sample: impl FnOnce(&V, [f32; 3]) -> Option<Sample>,
) -> (Option<Evaluated>, Option<Sample>) {
    let light = b.angles_from_dirs(wl, wr, tangent);
    let theta_r = match &light {
        Ok(a) => a.theta_r(),
        Err(_) => match b.angles_from_dirs(wr, wr, tangent) {
            Ok(a) => a.theta_r(),
            Err(_) => return (None, None),
        },
    };
    let Some(v) = view(theta_r) else {
        return (None, None);
    };
    let light = light.ok().map(|angles| {
        let (value, pdf) = eval(&v, &angles);
        Evaluated { angles, value, pdf }
    });
    let sample = Frame::from_view::<B::Math>(wr, tangent).and_then(|frame| {
        let s = sample(&v, u)?;
        Some(Sample {
            wi: Some(frame.to_world(&s.angles)),
            ..s
        })
    });
    (light, sample)
}

/// Assembles a [`Sample`]: weight = S·cos θ_i / pdf; `None` unless the density is positive
/// and finite.
#[inline]
pub(crate) fn finish(
    d: SampledDirection,
    value: Families,
    pdf: f32,
    wi: Option<Vec3>,
) -> Option<Sample> {
    if !(pdf > 0.0 && pdf.is_finite()) {
        return None;
    }
    let cos_theta_i = libm::cosf(d.angles.theta_i()).max(0.0);
    let k = cos_theta_i / pdf;
    let weight = value.total().map(|c| {
        if (c * k).is_finite() {
            (c * k).max(0.0)
        } else {
            0.0
        }
    });
    Some(Sample {
        angles: d.angles,
        wi,
        pdf,
        weight,
        family: d.family,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::baked::BakedBcsdf;
    use crate::math::Libm;
    use crate::rng::Pcg32;
    use crate::{presets, FurBcsdf, FurParams};
    use core::cell::Cell;

    /// A [`Bcsdf`] that forwards to `inner` and records the angles each entry point saw,
    /// so that the trait's own `*_dirs` methods can be checked, not only an override.
    struct Recorder<'b, B: Bcsdf> {
        inner: &'b B,
        eval: Cell<Option<Angles>>,
        pdf: Cell<Option<Angles>>,
        theta_r: Cell<Option<f32>>,
    }

    impl<B: Bcsdf> Bcsdf for Recorder<'_, B> {
        type Math = B::Math;
        fn angles_from_dirs(&self, wi: Vec3, wr: Vec3, t: Vec3) -> Result<Angles, AngleError> {
            self.inner.angles_from_dirs(wi, wr, t)
        }
        fn eval(&self, angles: &Angles) -> Families {
            self.eval.set(Some(*angles));
            self.inner.eval(angles)
        }
        fn pdf(&self, angles: &Angles) -> f32 {
            self.pdf.set(Some(*angles));
            self.inner.pdf(angles)
        }
        fn sample_direction(&self, theta_r: f32, u: [f32; 3]) -> Option<SampledDirection> {
            self.theta_r.set(Some(theta_r));
            self.inner.sample_direction(theta_r, u)
        }
    }

    fn bits(a: &Angles) -> [u32; 3] {
        [a.theta_i(), a.theta_r(), a.phi()].map(f32::to_bits)
    }

    fn family_bits(f: &Families) -> [[u32; 3]; 4] {
        f.as_array().map(|c| c.0.map(f32::to_bits))
    }

    /// A direction with components in [−1, 1], scaled by up to 10³ (lengths do not matter).
    fn random_vector(rng: &mut Pcg32) -> Vec3 {
        let s = 1e-3 + 1e3 * rng.uniform() * rng.uniform();
        [0, 1, 2].map(|_| s * (2.0 * rng.uniform() - 1.0))
    }

    /// `eval_dirs`, `pdf_dirs` and `sample_dirs` of `bcsdf` see the angles of its
    /// `angles_from_dirs`, bit for bit: through the trait's own methods (recorded) and
    /// through whatever `bcsdf` overrides (compared with the angle entry points).
    fn check_one_conversion(bcsdf: &impl Bcsdf, queries: usize) {
        let mut rng = Pcg32::new(22, 5);
        let mut checked = 0;
        for _ in 0..queries {
            let (wi, wr, t) = (
                random_vector(&mut rng),
                random_vector(&mut rng),
                random_vector(&mut rng),
            );
            let u = [rng.uniform(), rng.uniform(), rng.uniform()];
            let Ok(a) = bcsdf.angles_from_dirs(wi, wr, t) else {
                continue;
            };
            checked += 1;
            let rec = Recorder {
                inner: bcsdf,
                eval: Cell::new(None),
                pdf: Cell::new(None),
                theta_r: Cell::new(None),
            };
            // Each call checked before the next (sampling evaluates too).
            let _ = rec.eval_dirs(wi, wr, t);
            assert_eq!(rec.eval.get().map(|e| bits(&e)), Some(bits(&a)));
            let _ = rec.pdf_dirs(wi, wr, t);
            assert_eq!(rec.pdf.get().map(|e| bits(&e)), Some(bits(&a)));
            let _ = rec.sample_dirs(wr, t, u);
            assert_eq!(
                rec.theta_r.get().map(f32::to_bits),
                Some(a.theta_r().to_bits())
            );
            // The implementation's own (possibly overridden) `*_dirs` methods.
            let value = bcsdf.eval_dirs(wi, wr, t);
            assert_eq!(family_bits(&value), family_bits(&bcsdf.eval(&a)), "{a:?}");
            let pdf = bcsdf.pdf_dirs(wi, wr, t);
            assert_eq!(pdf.to_bits(), bcsdf.pdf(&a).to_bits(), "{a:?}");
            let s = bcsdf.sample_dirs(wr, t, u);
            let plain = bcsdf.sample(a.theta_r(), u);
            assert_eq!(s.map(|s| Sample { wi: None, ..s }), plain, "{a:?}");
            // A vertex's light direction and continuation at once: the calls made apart.
            let (value, pdf) = bcsdf.eval_with_pdf(&a);
            let apart = bcsdf
                .eval_with_pdf_dirs(wi, wr, t)
                .expect("valid directions");
            assert_eq!(bits(&apart.angles), bits(&a));
            assert_eq!(family_bits(&apart.value), family_bits(&value), "{a:?}");
            assert_eq!(apart.pdf.to_bits(), pdf.to_bits(), "{a:?}");
            let (light, vertex_sample) = bcsdf.eval_and_sample_dirs(wi, wr, t, u);
            let light = light.expect("a valid light direction is evaluated");
            assert_eq!(bits(&light.angles), bits(&a));
            assert_eq!(family_bits(&light.value), family_bits(&value), "{a:?}");
            assert_eq!(light.pdf.to_bits(), pdf.to_bits(), "{a:?}");
            assert_eq!(vertex_sample, s, "{a:?}");
            // A zero light direction has no angles; the continuation is still drawn.
            assert!(bcsdf.angles_from_dirs([0.0; 3], wr, t).is_err());
            let (none, still) = bcsdf.eval_and_sample_dirs([0.0; 3], wr, t, u);
            assert_eq!((none, still), (None, s), "{a:?}");
        }
        assert!(checked * 10 >= queries * 9, "{checked} of {queries}");
    }

    #[test]
    fn dirs_methods_share_one_conversion_baked() {
        let b = crate::baked::tests::random();
        let lut = BakedBcsdf::from_bytes(b).unwrap();
        check_one_conversion(&lut, 2000);
    }

    #[test]
    fn dirs_methods_share_one_conversion_baked_at_a_colour() {
        let b = crate::baked::tests::random();
        let lut = BakedBcsdf::from_bytes(b).unwrap();
        let colour = crate::Absorption::from_sigma(Rgb([0.4, 1.3, 7.0])).unwrap();
        check_one_conversion(&lut.at(&colour), 500);
    }

    #[test]
    fn dirs_methods_share_one_conversion_analytic() {
        let params = FurParams::new(&presets::find("human-hair").unwrap().input).unwrap();
        let hair: FurBcsdf<'static, Libm> = FurBcsdf::unscattered(params);
        check_one_conversion(&hair, 40);
    }

    fn direction(theta_i: f32) -> SampledDirection {
        SampledDirection {
            angles: Angles::new(theta_i, 0.2, 1.0).unwrap(),
            family: LobeFamily::TT,
        }
    }

    #[test]
    fn solid_angle_pdf_divides_by_a_guarded_cosine() {
        assert_eq!(solid_angle_pdf(1.0, 0.5), 2.0);
        assert_eq!(solid_angle_pdf(1.0, 0.0), 1.0 / MIN_COS_THETA_PDF);
        assert_eq!(solid_angle_pdf(1.0, -0.3), 1.0 / MIN_COS_THETA_PDF);
        assert_eq!(solid_angle_pdf(0.0, 0.0), 0.0);
    }

    #[test]
    fn finish_forms_the_weight_and_refuses_bad_densities() {
        let value = Families::from_array([Rgb([1.0, 2.0, 3.0]), Rgb::ZERO, Rgb::ZERO, Rgb::ZERO]);
        let d = direction(0.5);
        let s = finish(d, value, 0.25, Some([0.0, 0.0, 1.0])).unwrap();
        let k = libm::cosf(0.5) / 0.25;
        assert_eq!(s.weight, Rgb([k, 2.0 * k, 3.0 * k]));
        assert_eq!(
            (s.pdf, s.family, s.angles),
            (0.25, LobeFamily::TT, d.angles)
        );
        assert_eq!(s.wi, Some([0.0, 0.0, 1.0]));
        for pdf in [0.0, -1.0, f32::NAN, f32::INFINITY] {
            assert_eq!(finish(d, value, pdf, None), None, "pdf {pdf}");
        }
        // A weight that would overflow (or a NaN value) becomes 0, never NaN or ∞.
        let huge = Families::from_array([Rgb([f32::MAX, f32::NAN, 1.0]); 4]);
        let s = finish(d, huge, 1e-30, None).unwrap();
        assert_eq!(s.weight.0[..2], [0.0, 0.0]);
        assert!(s.weight.is_finite());
    }
}
