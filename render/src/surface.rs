//! Lambertian surfaces: the skin under the fur and the ground (docs/model.md §11).
//!
//! A Lambertian surface reflects f = ρ/π; its sampler draws cosine-weighted directions
//! (pdf cos θ/π), so the sample weight f·cos θ/pdf is ρ.

use core::f32::consts::PI;
use nalgebra::Vector3;

/// The shape of a surface.
#[derive(Clone, Copy, Debug)]
pub enum Shape {
    /// A sphere (outward normal).
    Sphere {
        /// Centre.
        center: Vector3<f32>,
        /// Radius.
        radius: f32,
    },
    /// The square |x − cx|, |z − cz| ≤ half of the plane y = `y`, normal +y.
    Square {
        /// Centre (its y is the plane's height).
        center: Vector3<f32>,
        /// Half the side (infinite for an endless ground).
        half: f32,
    },
}

/// A one-sided Lambertian surface.
#[derive(Clone, Copy, Debug)]
pub struct Surface {
    /// Its shape.
    pub shape: Shape,
    /// Reflectance ρ per RGB channel.
    pub albedo: [f32; 3],
}

impl Surface {
    /// The distance in (t_min, t_max) at which the unit ray meets the surface, and the
    /// outward normal there.
    #[must_use]
    pub fn intersect(
        &self,
        origin: &Vector3<f32>,
        dir: &Vector3<f32>,
        t_min: f32,
        t_max: f32,
    ) -> Option<(f32, Vector3<f32>)> {
        match self.shape {
            Shape::Sphere { center, radius } => {
                let oc = origin - center;
                let b = oc.dot(dir);
                let c = oc.norm_squared() - radius * radius;
                let disc = b * b - c;
                if disc < 0.0 {
                    return None;
                }
                let root = disc.sqrt();
                [-b - root, -b + root]
                    .into_iter()
                    .find(|&t| t > t_min && t < t_max)
                    .map(|t| (t, (origin + dir * t - center) / radius))
            }
            Shape::Square { center, half } => {
                if dir.y.abs() < 1e-12 {
                    return None;
                }
                let t = (center.y - origin.y) / dir.y;
                if !(t > t_min && t < t_max) {
                    return None;
                }
                let p = origin + dir * t;
                ((p.x - center.x).abs() <= half && (p.z - center.z).abs() <= half)
                    .then_some((t, Vector3::new(0.0, 1.0, 0.0)))
            }
        }
    }
}

/// The Lambertian BRDF ρ/π.
#[inline]
#[must_use]
pub fn lambert_f(albedo: [f32; 3]) -> [f32; 3] {
    albedo.map(|a| a / PI)
}

/// Density per unit solid angle of the cosine-weighted sampler: cos θ/π above the surface.
#[inline]
#[must_use]
pub fn cosine_pdf(cos_theta: f32) -> f32 {
    cos_theta.max(0.0) / PI
}

/// A cosine-weighted direction about the unit normal `n` from two uniform numbers
/// (Malley's method: a uniform point on the disc, lifted to the hemisphere).
#[must_use]
pub fn sample_cosine(n: &Vector3<f32>, u: [f32; 2]) -> Vector3<f32> {
    let r = u[0].sqrt();
    let phi = 2.0 * PI * u[1];
    let (x, y) = (r * phi.cos(), r * phi.sin());
    let z = (1.0 - u[0]).max(0.0).sqrt();
    let (t, b) = orthonormal_basis(n);
    (t * x + b * y + n * z).normalize()
}

/// Two unit vectors completing the unit `n` to a right-handed orthonormal basis
/// (Duff et al. 2017).
#[must_use]
pub fn orthonormal_basis(n: &Vector3<f32>) -> (Vector3<f32>, Vector3<f32>) {
    let sign = 1.0f32.copysign(n.z);
    let a = -1.0 / (sign + n.z);
    let b = n.x * n.y * a;
    (
        Vector3::new(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x),
        Vector3::new(b, sign + n.y * n.y * a, -n.y),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sphere_and_square_hits() {
        let s = Surface {
            shape: Shape::Sphere {
                center: Vector3::new(0.0, 0.0, 5.0),
                radius: 1.0,
            },
            albedo: [0.5; 3],
        };
        let (t, n) = s
            .intersect(&Vector3::zeros(), &Vector3::new(0.0, 0.0, 1.0), 0.0, 100.0)
            .unwrap();
        assert!((t - 4.0).abs() < 1e-5 && (n.z + 1.0).abs() < 1e-5);
        let g = Surface {
            shape: Shape::Square {
                center: Vector3::zeros(),
                half: 1.0,
            },
            albedo: [0.5; 3],
        };
        let down = Vector3::new(0.0, -1.0, 0.0);
        assert!(g
            .intersect(&Vector3::new(0.5, 2.0, 0.5), &down, 0.0, 9.0)
            .is_some());
        assert!(g
            .intersect(&Vector3::new(1.5, 2.0, 0.5), &down, 0.0, 9.0)
            .is_none());
    }

    #[test]
    fn cosine_samples_stay_above_the_surface_with_mean_cosine_two_thirds() {
        let n = Vector3::new(0.3, -0.5, 0.8).normalize();
        let mut mean = 0.0;
        let k = 4096;
        for i in 0..k {
            let u = [(i as f32 + 0.5) / k as f32, (i as f32 * 0.618_034).fract()];
            let w = sample_cosine(&n, u);
            assert!(w.dot(&n) >= 0.0 && (w.norm() - 1.0).abs() < 1e-5);
            mean += w.dot(&n) / k as f32;
        }
        // E[cos θ] under p = cos θ/π is 2/3.
        assert!((mean - 2.0 / 3.0).abs() < 2e-3, "{mean}");
    }
}
