//! Lights at infinity behind one trait (docs/model.md §11): a distant disc (a sun-like key or rim light that
//! subtends a small cone) and a uniform environment.
//!
//! Both have finite densities, so every light can be reached by BCSDF sampling as well as by
//! light sampling and multiple importance sampling applies to all of them. The lights of a
//! scene form one light-sampling strategy ([`Lights`]): pick a light with fixed
//! probabilities, sample a direction from it; the density of that mixture and the summed
//! radiance of all lights are what the integrator's MIS weights use.

use crate::surface::orthonormal_basis;
use core::f32::consts::PI;
use nalgebra::Vector3;

/// A light at infinity, seen in direction `dir` (unit, pointing toward the light).
pub trait Light: Send + Sync {
    /// Radiance arriving from `dir`, RGB.
    fn radiance(&self, dir: &Vector3<f32>) -> [f32; 3];
    /// Density per unit solid angle with which [`Light::sample`] draws `dir`.
    fn pdf(&self, dir: &Vector3<f32>) -> f32;
    /// A direction toward the light from two uniform numbers, and its density.
    fn sample(&self, u: [f32; 2]) -> (Vector3<f32>, f32);
    /// What the light is, for a renderer that does not sample it (a raster pipeline).
    fn shape(&self) -> LightShape;
}

/// A light's description, for renderers that shade with it directly instead of sampling it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LightShape {
    /// A [`DistantDisc`]: its unit axis and the irradiance (RGB) it gives a surface facing it.
    Distant {
        /// Unit vector toward the light.
        axis: Vector3<f32>,
        /// Irradiance normal to the axis, RGB.
        irradiance: [f32; 3],
    },
    /// A [`UniformEnvironment`]: its radiance (RGB).
    Uniform {
        /// The radiance, RGB.
        radiance: [f32; 3],
    },
}

/// A distant light of radiance `radiance` inside the cone of half-angle `half_angle` around
/// `axis`: irradiance normal to the axis π sin²(half_angle)·radiance.
#[derive(Clone, Copy, Debug)]
pub struct DistantDisc {
    axis: Vector3<f32>,
    cos_max: f32,
    radiance: [f32; 3],
}

impl DistantDisc {
    /// A disc light toward `axis` (need not be unit) of angular radius `half_angle_deg`
    /// degrees giving irradiance `irradiance` on a surface facing it.
    #[must_use]
    pub fn with_irradiance(axis: Vector3<f32>, half_angle_deg: f32, irradiance: [f32; 3]) -> Self {
        let sin = half_angle_deg.to_radians().sin();
        let k = 1.0 / (PI * sin * sin);
        DistantDisc {
            axis: axis.normalize(),
            cos_max: half_angle_deg.to_radians().cos(),
            radiance: irradiance.map(|e| e * k),
        }
    }

    /// Solid angle of the cone, 2π(1 − cos θ_max).
    fn solid_angle(&self) -> f32 {
        2.0 * PI * (1.0 - self.cos_max)
    }
}

impl Light for DistantDisc {
    fn radiance(&self, dir: &Vector3<f32>) -> [f32; 3] {
        if dir.dot(&self.axis) >= self.cos_max {
            self.radiance
        } else {
            [0.0; 3]
        }
    }

    fn pdf(&self, dir: &Vector3<f32>) -> f32 {
        if dir.dot(&self.axis) >= self.cos_max {
            1.0 / self.solid_angle()
        } else {
            0.0
        }
    }

    /// Uniform in the cone: cos θ uniform in [cos θ_max, 1].
    fn sample(&self, u: [f32; 2]) -> (Vector3<f32>, f32) {
        let cos = 1.0 - u[0] * (1.0 - self.cos_max);
        let sin = (1.0 - cos * cos).max(0.0).sqrt();
        let phi = 2.0 * PI * u[1];
        let (t, b) = orthonormal_basis(&self.axis);
        let dir = (t * (sin * phi.cos()) + b * (sin * phi.sin()) + self.axis * cos).normalize();
        // Rounding can put a sample a hair outside the cone; it still carries the density.
        (dir, 1.0 / self.solid_angle())
    }

    fn shape(&self) -> LightShape {
        let sin2 = 1.0 - self.cos_max * self.cos_max;
        LightShape::Distant {
            axis: self.axis,
            irradiance: self.radiance.map(|l| l * PI * sin2),
        }
    }
}

/// Radiance `radiance` from every direction.
#[derive(Clone, Copy, Debug)]
pub struct UniformEnvironment {
    /// The radiance, RGB.
    pub radiance: [f32; 3],
}

impl Light for UniformEnvironment {
    fn radiance(&self, _dir: &Vector3<f32>) -> [f32; 3] {
        self.radiance
    }

    fn pdf(&self, _dir: &Vector3<f32>) -> f32 {
        1.0 / (4.0 * PI)
    }

    /// Uniform on the sphere.
    fn sample(&self, u: [f32; 2]) -> (Vector3<f32>, f32) {
        let z = 1.0 - 2.0 * u[0];
        let r = (1.0 - z * z).max(0.0).sqrt();
        let phi = 2.0 * PI * u[1];
        (
            Vector3::new(r * phi.cos(), r * phi.sin(), z),
            1.0 / (4.0 * PI),
        )
    }

    fn shape(&self) -> LightShape {
        LightShape::Uniform {
            radiance: self.radiance,
        }
    }
}

/// The scene's lights and the probability of picking each for light sampling.
pub struct Lights {
    lights: Vec<(Box<dyn Light>, f32)>,
}

impl Lights {
    /// Lights with their selection weights (normalised here; non-positive weights are never
    /// picked).
    #[must_use]
    pub fn new(lights: Vec<(Box<dyn Light>, f32)>) -> Lights {
        let total: f32 = lights.iter().map(|(_, w)| w.max(0.0)).sum();
        let lights = lights
            .into_iter()
            .map(|(l, w)| (l, if total > 0.0 { w.max(0.0) / total } else { 0.0 }))
            .collect();
        Lights { lights }
    }

    /// Whether there is no light at all.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.lights.is_empty()
    }

    /// Each light's description ([`LightShape`]), in the order given to [`Lights::new`].
    pub fn shapes(&self) -> impl Iterator<Item = LightShape> + '_ {
        self.lights.iter().map(|(l, _)| l.shape())
    }

    /// Radiance of all lights arriving from `dir`.
    #[must_use]
    pub fn radiance(&self, dir: &Vector3<f32>) -> [f32; 3] {
        let mut sum = [0.0; 3];
        for (l, _) in &self.lights {
            let r = l.radiance(dir);
            for c in 0..3 {
                sum[c] += r[c];
            }
        }
        sum
    }

    /// Density per unit solid angle of the light-sampling strategy: Σ P(light)·pdf_light.
    #[must_use]
    pub fn pdf(&self, dir: &Vector3<f32>) -> f32 {
        self.lights.iter().map(|(l, p)| p * l.pdf(dir)).sum()
    }

    /// A direction from the light-sampling strategy: `u_pick` picks the light, `u` the
    /// direction. `None` without lights.
    #[must_use]
    pub fn sample(&self, u_pick: f32, u: [f32; 2]) -> Option<Vector3<f32>> {
        let mut acc = 0.0;
        let last = self.lights.iter().rposition(|(_, p)| *p > 0.0)?;
        for (i, (l, p)) in self.lights.iter().enumerate() {
            acc += p;
            if (u_pick < acc && *p > 0.0) || i == last {
                return Some(l.sample(u).0);
            }
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn disc_samples_lie_in_the_cone_and_carry_its_density() {
        let d = DistantDisc::with_irradiance(Vector3::new(1.0, 1.0, 0.0), 5.0, [2.0; 3]);
        for i in 0..64 {
            let (w, p) = d.sample([(i as f32 + 0.5) / 64.0, (i as f32 * 0.618_034).fract()]);
            assert!(d.pdf(&w) > 0.0 && (d.pdf(&w) - p).abs() < 1e-3 * p);
            assert_eq!(d.radiance(&w), d.radiance);
        }
        // Irradiance facing the axis: ∫ L cos θ dω = L π sin² θ_max.
        let e = d.radiance[0] * PI * 5f32.to_radians().sin().powi(2);
        assert!((e - 2.0).abs() < 1e-4);
        assert_eq!(d.pdf(&Vector3::new(0.0, 0.0, 1.0)), 0.0);
        // The shape a raster pipeline reads gives the irradiance back.
        let LightShape::Distant { axis, irradiance } = d.shape() else {
            panic!("a disc is a distant light")
        };
        assert!((axis - Vector3::new(1.0, 1.0, 0.0).normalize()).norm() < 1e-6);
        assert!(
            irradiance.iter().all(|e| (e - 2.0).abs() < 1e-4),
            "{irradiance:?}"
        );
    }

    #[test]
    fn the_mixture_density_sums_the_picked_lights() {
        let lights = Lights::new(vec![
            (
                Box::new(DistantDisc::with_irradiance(Vector3::y(), 10.0, [1.0; 3])),
                3.0,
            ),
            (Box::new(UniformEnvironment { radiance: [0.5; 3] }), 1.0),
        ]);
        let up = Vector3::y();
        let disc_pdf = 1.0 / (2.0 * PI * (1.0 - 10f32.to_radians().cos()));
        assert!((lights.pdf(&up) - (0.75 * disc_pdf + 0.25 / (4.0 * PI))).abs() < 1e-3);
        assert!((lights.pdf(&-up) - 0.25 / (4.0 * PI)).abs() < 1e-7);
        assert!(lights.radiance(&up)[0] > 0.5 && lights.radiance(&-up) == [0.5; 3]);
        // u_pick below 0.75 picks the disc, above it the environment.
        assert!(lights.sample(0.7, [0.3, 0.3]).unwrap().dot(&up) > 0.98);
        assert!(lights.sample(0.8, [0.99, 0.3]).unwrap().z < -0.9);
    }
}
