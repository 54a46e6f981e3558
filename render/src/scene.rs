//! A scene: fiber segments (in a BVH), Lambertian surfaces, lights at infinity and a camera (docs/model.md §11).

use crate::accel::{FiberAccel, Skip};
use crate::camera::Camera;
use crate::fiber::FiberSegment;
use crate::light::Lights;
use crate::surface::Surface;
use nalgebra::Vector3;

/// What a ray hit.
#[derive(Clone, Copy, Debug)]
pub enum HitKind {
    /// A fiber segment, far-field scatterer: its tangent (root to tip, not unit) and fiber.
    Fiber {
        /// p1 − p0 of the segment.
        tangent: Vector3<f32>,
        /// The fiber's index.
        fiber: u32,
        /// Position along the strand, 0 at the root, 1 at the tip ([`FiberSegment::along`]).
        v: f32,
    },
    /// A Lambertian surface: its outward unit normal and reflectance.
    Surface {
        /// Outward unit normal.
        normal: Vector3<f32>,
        /// Reflectance ρ.
        albedo: [f32; 3],
    },
}

/// A ray's closest hit.
#[derive(Clone, Copy, Debug)]
pub struct Hit {
    /// Distance along the unit ray.
    pub t: f32,
    /// The hit point (on the fiber's axis for a fiber).
    pub point: Vector3<f32>,
    /// What was hit.
    pub kind: HitKind,
}

/// Everything a render needs besides the BCSDF.
pub struct Scene {
    /// The fiber segments and their BVH.
    pub fibers: FiberAccel,
    /// Lambertian surfaces (skin, ground).
    pub surfaces: Vec<Surface>,
    /// Lights at infinity.
    pub lights: Lights,
    /// The camera.
    pub camera: Camera,
    /// Distance below which a ray leaving a point ignores hits: surfaces and other fibers
    /// (scene units).
    pub epsilon: f32,
    /// Distance within which a ray leaving a fiber ignores that same fiber (a few radii).
    pub self_distance: f32,
    /// The unit skin normal at each fiber's root, by fiber index (what an engine's groom
    /// carries per strand); empty when the scene has no skin under its fibers. The `dual`
    /// method gives the term the light's incidence on the coat from it ([`CoatBelow`]).
    pub root_normals: Vec<Vector3<f32>>,
}

/// The coat below a fiber's shading point toward one light (docs/model.md §13, "The coat
/// below", "The light's incidence on the coat"): what [`Scene::fibers_below`] finds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CoatBelow {
    /// The fibers beyond the point on the line from the light through it, up to the first
    /// surface or out of the scene (m of [`bcsdf_core::dual::Fibers`]).
    pub count: u32,
    /// cos ι between the direction toward the light and the skin normal at the fiber's root
    /// (what [`bcsdf_core::dual::coat::below_at_incidence`] takes); NaN when the scene has no
    /// root normal for the fiber.
    pub incidence: f32,
}

impl Scene {
    /// Assembles a scene; the segments' BVH is built here.
    #[must_use]
    pub fn new(
        segments: Vec<FiberSegment>,
        surfaces: Vec<Surface>,
        lights: Lights,
        camera: Camera,
    ) -> Scene {
        let r_max = segments
            .iter()
            .map(|s| s.r0.max(s.r1))
            .fold(0.0f32, f32::max);
        Scene {
            fibers: FiberAccel::new(segments),
            surfaces,
            lights,
            camera,
            epsilon: 1e-4,
            self_distance: 4.0 * r_max,
            root_normals: Vec::new(),
        }
    }

    /// The scene with `normals[i]` the unit skin normal at fiber i's root
    /// ([`Scene::root_normals`]).
    #[must_use]
    pub fn with_root_normals(mut self, normals: Vec<Vector3<f32>>) -> Scene {
        self.root_normals = normals;
        self
    }

    /// Number of fiber segments.
    #[must_use]
    pub fn segment_count(&self) -> usize {
        self.fibers.segments().len()
    }

    /// The closest hit along the unit ray leaving `origin` (from fiber `from`, if any).
    #[must_use]
    pub fn intersect(
        &self,
        origin: &Vector3<f32>,
        dir: &Vector3<f32>,
        from: Option<u32>,
    ) -> Option<Hit> {
        let mut best = self.intersect_surfaces(origin, dir);
        let t_max = best.as_ref().map_or(f32::INFINITY, |h| h.t);
        if let Some((seg, hit)) =
            self.fibers
                .closest(origin, dir, self.epsilon, t_max, self.skip(from))
        {
            best = Some(Hit {
                t: hit.t,
                point: origin + dir * hit.t,
                kind: HitKind::Fiber {
                    tangent: seg.tangent(),
                    fiber: seg.fiber,
                    v: seg.along(hit.s),
                },
            });
        }
        best
    }

    /// The closest surface (skin, ground) along the unit ray leaving `origin`, fibers ignored.
    #[must_use]
    pub fn intersect_surfaces(&self, origin: &Vector3<f32>, dir: &Vector3<f32>) -> Option<Hit> {
        let mut best: Option<Hit> = None;
        let mut t_max = f32::INFINITY;
        for s in &self.surfaces {
            if let Some((t, normal)) = s.intersect(origin, dir, self.epsilon, t_max) {
                t_max = t;
                best = Some(Hit {
                    t,
                    point: origin + dir * t,
                    kind: HitKind::Surface {
                        normal,
                        albedo: s.albedo,
                    },
                });
            }
        }
        best
    }

    /// The fibers the unit ray leaving `origin` (from fiber `from`) crosses before it meets
    /// a surface, or `None` when it meets none (docs/model.md §13: how `single` and `dual`
    /// carry light from surfaces to a fiber).
    #[must_use]
    pub fn fibers_before_surface(
        &self,
        origin: &Vector3<f32>,
        dir: &Vector3<f32>,
        from: Option<u32>,
    ) -> Option<u32> {
        let surface = self.intersect_surfaces(origin, dir)?;
        Some(self.count_fibers(origin, dir, from, surface.t))
    }

    /// Whether the unit ray leaving `origin` (from fiber `from`) escapes to infinity.
    #[must_use]
    pub fn escapes(&self, origin: &Vector3<f32>, dir: &Vector3<f32>, from: Option<u32>) -> bool {
        !self.surface_blocks(origin, dir)
            && !self
                .fibers
                .any(origin, dir, self.epsilon, f32::INFINITY, self.skip(from))
    }

    /// The fibers the unit ray leaving `origin` (from fiber `from`) crosses on its way to
    /// infinity, or `None` when a surface (skin, ground: opaque) blocks it (docs/model.md §13).
    #[must_use]
    pub fn fibers_crossed(
        &self,
        origin: &Vector3<f32>,
        dir: &Vector3<f32>,
        from: Option<u32>,
    ) -> Option<u32> {
        if self.surface_blocks(origin, dir) {
            return None;
        }
        Some(self.count_fibers(origin, dir, from, f32::INFINITY))
    }

    /// The coat below a point of fiber `from` toward a light in direction `toward_light`
    /// (unit): the fibers beyond `origin` (other than `from`) on the line from the light
    /// through it, along −`toward_light` up to the first surface (skin, ground) or out of the
    /// scene, and the light's incidence on the skin under the fiber (docs/model.md §13, "The
    /// coat below", "The light's incidence on the coat").
    #[must_use]
    pub fn fibers_below(
        &self,
        origin: &Vector3<f32>,
        toward_light: &Vector3<f32>,
        from: Option<u32>,
    ) -> CoatBelow {
        let away = -toward_light;
        let t_max = self
            .intersect_surfaces(origin, &away)
            .map_or(f32::INFINITY, |s| s.t);
        let incidence = from
            .and_then(|id| self.root_normals.get(id as usize))
            .map_or(f32::NAN, |n| n.dot(toward_light));
        CoatBelow {
            count: self.count_fibers(origin, &away, from, t_max),
            incidence,
        }
    }

    /// The distinct fibers (other than `from`) on the unit ray before distance `t_max`.
    fn count_fibers(
        &self,
        origin: &Vector3<f32>,
        dir: &Vector3<f32>,
        from: Option<u32>,
        t_max: f32,
    ) -> u32 {
        self.fibers
            .count_fibers(origin, dir, self.epsilon, t_max, self.skip(from))
    }

    /// Whether a surface (opaque) lies on the unit ray leaving `origin`.
    fn surface_blocks(&self, origin: &Vector3<f32>, dir: &Vector3<f32>) -> bool {
        self.surfaces.iter().any(|s| {
            s.intersect(origin, dir, self.epsilon, f32::INFINITY)
                .is_some()
        })
    }

    fn skip(&self, from: Option<u32>) -> Skip {
        Skip {
            fiber: from,
            dist: self.self_distance,
        }
    }
}
