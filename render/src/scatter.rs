//! What the integrator asks of a fiber (docs/model.md §11): S·cos θ_i with the sampling
//! density for a given pair of directions, and an importance-sampled direction, through the
//! [`Bcsdf`] trait in the fiber's frame (docs/model.md §1, §10).
//!
//! Usually one BCSDF does both ([`One`]). [`Guided`] evaluates one BCSDF and samples with
//! another: the baked-versus-analytic comparison renders both evaluators along the very same
//! paths (the guide's), so what differs between the two images is the evaluator, not the
//! noise. Either is unbiased wherever the guide's density is positive where S is.

use bcsdf_core::{Angles, Bcsdf, Evaluated, Frame, Sample};
use nalgebra::Vector3;

/// A scattering direction drawn at a fiber.
#[derive(Clone, Copy, Debug)]
pub struct Scattered {
    /// ω_i, world space, unit.
    pub wi: Vector3<f32>,
    /// S(ω_i, ω_r)·cos θ_i / pdf, RGB.
    pub weight: [f32; 3],
    /// Density per unit solid angle.
    pub pdf: f32,
}

/// A fiber's scattering as the integrator uses it.
pub trait Scatterer: Sync {
    /// S(ω_i, ω_r)·cos θ_i (RGB) and the density with which [`Scatterer::sample`] draws
    /// `wi`; zeros for degenerate directions.
    fn eval(&self, wi: &Vector3<f32>, wr: &Vector3<f32>, tangent: &Vector3<f32>)
        -> ([f32; 3], f32);

    /// Draws ω_i given ω_r = `wr` from three uniform numbers; `None` when nothing can be
    /// sampled.
    fn sample(&self, wr: &Vector3<f32>, tangent: &Vector3<f32>, u: [f32; 3]) -> Option<Scattered>;

    /// A vertex's two questions at once: [`Scatterer::eval`] of the light's direction `wl`
    /// and [`Scatterer::sample`], with the same values; a BCSDF with a per-view context
    /// builds it once ([`Bcsdf::eval_and_sample_dirs`]).
    fn eval_and_sample(
        &self,
        wl: &Vector3<f32>,
        wr: &Vector3<f32>,
        tangent: &Vector3<f32>,
        u: [f32; 3],
    ) -> (([f32; 3], f32), Option<Scattered>) {
        (self.eval(wl, wr, tangent), self.sample(wr, tangent, u))
    }
}

/// S·cos θ_i, RGB, with negative or non-finite channels as 0.
fn s_cos(s: bcsdf_core::Rgb, angles: &Angles) -> [f32; 3] {
    let cos_theta_i = angles.theta_i().cos().max(0.0);
    s.0.map(|c| {
        let v = c * cos_theta_i;
        if v.is_finite() && v > 0.0 {
            v
        } else {
            0.0
        }
    })
}

/// A borrowed scatterer scatters as the scatterer (what a uniform
/// [`crate::strand::FiberMaterial`] hands out at every hit).
impl<S: Scatterer + ?Sized> Scatterer for &S {
    fn eval(
        &self,
        wi: &Vector3<f32>,
        wr: &Vector3<f32>,
        tangent: &Vector3<f32>,
    ) -> ([f32; 3], f32) {
        (**self).eval(wi, wr, tangent)
    }

    fn sample(&self, wr: &Vector3<f32>, tangent: &Vector3<f32>, u: [f32; 3]) -> Option<Scattered> {
        (**self).sample(wr, tangent, u)
    }

    fn eval_and_sample(
        &self,
        wl: &Vector3<f32>,
        wr: &Vector3<f32>,
        tangent: &Vector3<f32>,
        u: [f32; 3],
    ) -> (([f32; 3], f32), Option<Scattered>) {
        (**self).eval_and_sample(wl, wr, tangent, u)
    }
}

/// S·cos θ_i and the density of an evaluated direction, or zeros.
fn light_value(e: Option<Evaluated>) -> ([f32; 3], f32) {
    e.map_or(([0.0; 3], 0.0), |e| {
        (s_cos(e.value.total(), &e.angles), e.pdf)
    })
}

/// A BCSDF's sample as the integrator takes it (it needs the world-space direction).
fn scattered(s: Option<Sample>) -> Option<Scattered> {
    let s = s?;
    Some(Scattered {
        wi: Vector3::from(s.wi?),
        weight: s.weight.0,
        pdf: s.pdf,
    })
}

/// S·cos θ_i and the density of one BCSDF ([`One`], [`Owned`]), at the BCSDF's own
/// direction-to-angle conversion ([`Bcsdf::eval_with_pdf_dirs`]).
fn eval_one<B: Bcsdf>(
    b: &B,
    wi: &Vector3<f32>,
    wr: &Vector3<f32>,
    tangent: &Vector3<f32>,
) -> ([f32; 3], f32) {
    light_value(b.eval_with_pdf_dirs((*wi).into(), (*wr).into(), (*tangent).into()))
}

/// A direction drawn from one BCSDF's sampler ([`One`], [`Owned`]).
fn sample_one<B: Bcsdf>(
    b: &B,
    wr: &Vector3<f32>,
    tangent: &Vector3<f32>,
    u: [f32; 3],
) -> Option<Scattered> {
    scattered(b.sample_dirs((*wr).into(), (*tangent).into(), u))
}

/// Both at one vertex ([`Bcsdf::eval_and_sample_dirs`]).
fn eval_and_sample_one<B: Bcsdf>(
    b: &B,
    wl: &Vector3<f32>,
    wr: &Vector3<f32>,
    tangent: &Vector3<f32>,
    u: [f32; 3],
) -> (([f32; 3], f32), Option<Scattered>) {
    let (light, s) = b.eval_and_sample_dirs((*wl).into(), (*wr).into(), (*tangent).into(), u);
    (light_value(light), scattered(s))
}

/// One BCSDF evaluates and samples.
pub struct One<'a, B>(pub &'a B);

impl<B: Bcsdf + Sync> Scatterer for One<'_, B> {
    fn eval(
        &self,
        wi: &Vector3<f32>,
        wr: &Vector3<f32>,
        tangent: &Vector3<f32>,
    ) -> ([f32; 3], f32) {
        eval_one(self.0, wi, wr, tangent)
    }

    fn sample(&self, wr: &Vector3<f32>, tangent: &Vector3<f32>, u: [f32; 3]) -> Option<Scattered> {
        sample_one(self.0, wr, tangent, u)
    }

    fn eval_and_sample(
        &self,
        wl: &Vector3<f32>,
        wr: &Vector3<f32>,
        tangent: &Vector3<f32>,
        u: [f32; 3],
    ) -> (([f32; 3], f32), Option<Scattered>) {
        eval_and_sample_one(self.0, wl, wr, tangent, u)
    }
}

/// [`One`] owning its BCSDF: a value made per hit, such as a LUT at one strand's colour
/// (`BakedBcsdf::at`, [`crate::strand`]).
pub struct Owned<B>(pub B);

impl<B: Bcsdf + Sync> Scatterer for Owned<B> {
    fn eval(
        &self,
        wi: &Vector3<f32>,
        wr: &Vector3<f32>,
        tangent: &Vector3<f32>,
    ) -> ([f32; 3], f32) {
        eval_one(&self.0, wi, wr, tangent)
    }

    fn sample(&self, wr: &Vector3<f32>, tangent: &Vector3<f32>, u: [f32; 3]) -> Option<Scattered> {
        sample_one(&self.0, wr, tangent, u)
    }

    fn eval_and_sample(
        &self,
        wl: &Vector3<f32>,
        wr: &Vector3<f32>,
        tangent: &Vector3<f32>,
        u: [f32; 3],
    ) -> (([f32; 3], f32), Option<Scattered>) {
        eval_and_sample_one(&self.0, wl, wr, tangent, u)
    }
}

/// `eval` gives S, `guide` samples and gives the density.
pub struct Guided<'a, E, G> {
    /// The BCSDF whose image is rendered.
    pub eval: &'a E,
    /// The BCSDF whose sampler draws the paths.
    pub guide: &'a G,
}

impl<E: Bcsdf + Sync, G: Bcsdf + Sync> Scatterer for Guided<'_, E, G> {
    fn eval(
        &self,
        wi: &Vector3<f32>,
        wr: &Vector3<f32>,
        tangent: &Vector3<f32>,
    ) -> ([f32; 3], f32) {
        match Angles::from_directions::<G::Math>((*wi).into(), (*wr).into(), (*tangent).into()) {
            Ok(a) => (s_cos(self.eval.eval(&a).total(), &a), self.guide.pdf(&a)),
            Err(_) => ([0.0; 3], 0.0),
        }
    }

    fn sample(&self, wr: &Vector3<f32>, tangent: &Vector3<f32>, u: [f32; 3]) -> Option<Scattered> {
        let frame = Frame::from_view::<G::Math>((*wr).into(), (*tangent).into())?;
        let d = self.guide.sample_direction(frame.theta_r(), u)?;
        let pdf = self.guide.pdf(&d.angles);
        if !(pdf > 0.0 && pdf.is_finite()) {
            return None;
        }
        let value = s_cos(self.eval.eval(&d.angles).total(), &d.angles);
        Some(Scattered {
            wi: Vector3::from(frame.to_world(&d.angles)),
            weight: value.map(|v| {
                let w = v / pdf;
                if w.is_finite() {
                    w
                } else {
                    0.0
                }
            }),
            pdf,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use bcsdf_core::rng::Pcg32;
    use bcsdf_core::{presets, FurBcsdf, FurParams, Libm};

    fn random_direction(rng: &mut Pcg32) -> Vector3<f32> {
        Vector3::new(
            2.0 * rng.uniform() - 1.0,
            2.0 * rng.uniform() - 1.0,
            2.0 * rng.uniform() - 1.0,
        )
    }

    /// [`Scatterer::eval_and_sample`] of a scatterer taken by value (a reference is one).
    fn vertex<S: Scatterer>(
        s: S,
        (wl, wr, t): (&Vector3<f32>, &Vector3<f32>, &Vector3<f32>),
        u: [f32; 3],
    ) -> (([f32; 3], f32), Option<Scattered>) {
        s.eval_and_sample(wl, wr, t, u)
    }

    /// A vertex's call answers what `eval` and `sample` answer apart, bit for bit, through
    /// `One`, `Owned` and a reference to a scatterer.
    #[test]
    fn eval_and_sample_is_eval_then_sample() {
        let params = FurParams::new(&presets::find("human-hair").unwrap().input).unwrap();
        let hair: FurBcsdf<'static, Libm> = FurBcsdf::unscattered(params);
        let one = One(&hair);
        let owned = Owned(FurBcsdf::<'static, Libm>::unscattered(params));
        let mut rng = Pcg32::new(4, 21);
        let mut sampled = 0;
        for _ in 0..60 {
            let (wl, wr, t) = (
                random_direction(&mut rng),
                random_direction(&mut rng),
                random_direction(&mut rng),
            );
            let u = [rng.uniform(), rng.uniform(), rng.uniform()];
            let apart = (one.eval(&wl, &wr, &t), one.sample(&wr, &t, u));
            let bits = |r: &(([f32; 3], f32), Option<Scattered>)| {
                let ((v, p), s) = r;
                (
                    v.map(f32::to_bits),
                    p.to_bits(),
                    s.map(|s| (s.wi.map(f32::to_bits), s.weight.map(f32::to_bits), s.pdf)),
                )
            };
            sampled += usize::from(apart.1.is_some());
            assert_eq!(bits(&one.eval_and_sample(&wl, &wr, &t, u)), bits(&apart));
            assert_eq!(bits(&owned.eval_and_sample(&wl, &wr, &t, u)), bits(&apart));
            // `&One` as a scatterer of its own: the forwarding impl for references.
            assert_eq!(bits(&vertex(&one, (&wl, &wr, &t), u)), bits(&apart));
        }
        assert!(sampled > 40, "{sampled} of 60 sampled");
    }
}
