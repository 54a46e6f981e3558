//! The thick coat of docs/model.md §14 as explicit geometry: a slab of straight fiber segments
//! over a black floor under a white sky of radiance 1, seen from straight above. The path
//! tracer's mean over the image is the coat colour that `bcsdf_core::colour` defines and
//! measures by a random walk through a statistical coat; this scene is built independently of
//! that walk (its own placement and tangents, real ray–cylinder queries), so rendering it
//! checks the walk.
//!
//! Segments are placed independently (the walk's Boolean medium): centres uniform in the slab,
//! tangents with the skin-normal component uniform in [0, sin 30°] (tips up, within 30° of the
//! skin plane, `bcsdf_core::colour::COAT_TANGENT_MAX_SIN`) and a uniform azimuth. The slab
//! is wide and deep in free paths so that light leaving through its sides or reaching the floor
//! is rare; the camera sees only its centre.

use crate::camera::Camera;
use crate::fiber::FiberSegment;
use crate::light::{Light, Lights, UniformEnvironment};
use crate::scene::Scene;
use crate::surface::{Shape, Surface};
use bcsdf_core::colour::COAT_TANGENT_MAX_SIN;
use bcsdf_core::rng::Pcg32;
use core::f32::consts::PI;
use nalgebra::Vector3;

/// How to build the coat slab.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CoatSlab {
    /// Depth of the slab in free paths of a ray along the skin normal through fibers at
    /// the majorant rate 2rλ (r the radius, λ the fiber length per unit volume).
    pub depth_free_paths: f32,
    /// Half the slab's width, in free paths.
    pub half_width_free_paths: f32,
    /// Fiber radius as a fraction of a free path (the Boolean medium's limit is 0).
    pub radius_per_free_path: f32,
    /// Segment length, in free paths.
    pub segment_free_paths: f32,
    /// Half the width of the region the camera sees, in free paths.
    pub view_half_width_free_paths: f32,
    /// Seed of the placement.
    pub seed: u64,
}

impl CoatSlab {
    /// 20 free paths deep, ±30 wide, radius 1/13 of a free path, segments 5 free paths long,
    /// the camera on the central ±10.
    pub const DEFAULT: CoatSlab = CoatSlab {
        depth_free_paths: 20.0,
        half_width_free_paths: 30.0,
        radius_per_free_path: 1.0 / 13.0,
        segment_free_paths: 5.0,
        view_half_width_free_paths: 10.0,
        seed: 1,
    };

    /// Segments [`CoatSlab::for_absorption`] may spend on one slab.
    pub const SEGMENT_BUDGET: f32 = 1.2e6;

    /// The slab that checks the coat colour at cortex absorption `sigma` (the smallest of a
    /// colour's channels), docs/model.md §14 "Checked against the path tracer": as deep as
    /// that absorption needs for the floor not to show, 4/√σ free paths clamped to [10, 80]
    /// (light diffuses about 1/√σ deep in a nearly lossless coat), 10 free paths wider than
    /// half its depth on each side, and its fibers as thin as [`CoatSlab::SEGMENT_BUDGET`]
    /// allows, radius from 1/13 (deep slabs) down to 1/120 of a free path (shallow ones), toward
    /// the definition's limit of fibers far apart compared with their radius. NaN or negative
    /// `sigma` reads as 0.
    #[must_use]
    pub fn for_absorption(sigma: f32) -> CoatSlab {
        let sigma = if sigma > 0.0 { sigma } else { 0.0 };
        let depth = (4.0 / sigma.sqrt()).clamp(10.0, 80.0);
        let half_width = 10.0 + 0.5 * depth;
        let len = CoatSlab::DEFAULT.segment_free_paths;
        // segments = λ·volume/len with λ = 1/(2r): the radius that spends the budget.
        let radius = ((2.0 * half_width).powi(2) * depth / (2.0 * len * Self::SEGMENT_BUDGET))
            .clamp(1.0 / 120.0, 1.0 / 13.0);
        CoatSlab {
            depth_free_paths: depth,
            half_width_free_paths: half_width,
            radius_per_free_path: radius,
            ..CoatSlab::DEFAULT
        }
    }

    /// How many segments the slab holds: the fiber length per unit volume λ = 1/(2r) in units
    /// of one free path, times the volume, over the segment length.
    #[must_use]
    pub fn segments(&self) -> usize {
        let r = self.radius_per_free_path;
        let lambda = 1.0 / (2.0 * r);
        let volume = (2.0 * self.half_width_free_paths).powi(2) * self.depth_free_paths;
        (lambda * volume / self.segment_free_paths).round().max(1.0) as usize
    }
}

/// The coat slab (lengths in free paths; the skin normal is +y, the coat's top at y = 0):
/// segments, an endless black floor at its bottom, a uniform white environment of radiance 1,
/// and a pinhole camera 1000 free paths above looking straight down at the central
/// ±`view_half_width` (every camera ray within 0.6° of the normal).
#[must_use]
pub fn coat_scene(slab: &CoatSlab) -> Scene {
    let mut rng = Pcg32::new(slab.seed, 0x636f_6174_736c_6162); // "coatslab"
    let (w, h, len, r) = (
        slab.half_width_free_paths,
        slab.depth_free_paths,
        slab.segment_free_paths,
        slab.radius_per_free_path,
    );
    let n = slab.segments();
    let mut segments = Vec::with_capacity(n);
    for id in 0..n {
        let centre = Vector3::new(
            w * (2.0 * rng.uniform() - 1.0),
            -h * rng.uniform(),
            w * (2.0 * rng.uniform() - 1.0),
        );
        let up = COAT_TANGENT_MAX_SIN * rng.uniform();
        let across = (1.0 - up * up).max(0.0).sqrt();
        let azimuth = 2.0 * PI * rng.uniform();
        let t = Vector3::new(across * azimuth.cos(), up, across * azimuth.sin());
        segments.push(FiberSegment {
            p0: centre - t * (0.5 * len),
            p1: centre + t * (0.5 * len),
            r0: r,
            r1: r,
            v0: 0.0,
            v1: 1.0,
            fiber: id as u32,
            node: 0,
        });
    }
    let floor = Surface {
        shape: Shape::Square {
            center: Vector3::new(0.0, -h, 0.0),
            half: f32::INFINITY,
        },
        albedo: [0.0; 3],
    };
    let sky: Box<dyn Light> = Box::new(UniformEnvironment { radiance: [1.0; 3] });
    let distance = 1000.0;
    let fov = 2.0
        * (slab.view_half_width_free_paths / distance)
            .atan()
            .to_degrees();
    let camera = Camera::look_at(
        Vector3::new(0.0, distance, 0.0),
        Vector3::zeros(),
        Vector3::z(),
        fov,
    );
    Scene::new(segments, vec![floor], Lights::new(vec![(sky, 1.0)]), camera)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_slab_has_its_density_and_the_tangents_their_band() {
        let slab = CoatSlab {
            half_width_free_paths: 6.0,
            depth_free_paths: 4.0,
            ..CoatSlab::DEFAULT
        };
        let scene = coat_scene(&slab);
        // λ = 6.5 per free path², volume 576, segments of 5: 749.
        assert_eq!(scene.segment_count(), 749);
        for s in scene.fibers.segments() {
            let t = (s.p1 - s.p0).normalize();
            assert!((0.0..=0.5 + 1e-6).contains(&t.y), "{t:?}");
            assert!(s.p0.y + s.p1.y <= 0.0 && s.p0.y + s.p1.y >= -8.0);
        }
        // Straight down: the camera's central ray points along −y.
        let (_, d) = scene.camera.ray(50.0, 50.0, 100, 100);
        assert!(d.y < -0.9999, "{d:?}");
    }
}
