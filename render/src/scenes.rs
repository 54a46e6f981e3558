//! The built-in scenes (docs/model.md §11), deterministic from a seed: `ball` (a furry sphere on a grey ground
//! under a key light and a dim sky), `patch` (a square of skin with fur, rim-lit) and
//! `furnace` (a clump of fibers in a uniform white environment of radiance 1, nothing else).
//!
//! Fibers grow as chains of straight segments that taper from root to tip, each bending a
//! little toward a comb direction with seeded jitter.

use crate::camera::Camera;
use crate::fiber::FiberSegment;
use crate::light::{DistantDisc, Light, Lights, UniformEnvironment};
use crate::scene::Scene;
use crate::surface::{orthonormal_basis, Shape, Surface};
use bcsdf_core::rng::Pcg32;
use core::f32::consts::PI;
use core::fmt;
use core::str::FromStr;
use nalgebra::Vector3;

/// Which built-in scene.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SceneKind {
    /// A clump of fibers in a uniform environment of radiance 1 (the white furnace).
    Furnace,
    /// A square of skin with fur, a rim light and a dim environment.
    Patch,
    /// A sphere covered in fur on a grey ground, a key light and a dim environment.
    Ball,
}

impl SceneKind {
    /// Every scene, in the order `--help` lists them.
    pub const ALL: [SceneKind; 3] = [SceneKind::Furnace, SceneKind::Patch, SceneKind::Ball];

    /// The scene's name on the command line.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            SceneKind::Furnace => "furnace",
            SceneKind::Patch => "patch",
            SceneKind::Ball => "ball",
        }
    }

    /// Default number of fibers.
    #[must_use]
    pub fn default_fibers(self) -> usize {
        match self {
            SceneKind::Furnace => 1500,
            SceneKind::Patch => 6000,
            SceneKind::Ball => 20_000,
        }
    }

    /// Segments per fiber.
    #[must_use]
    pub fn segments_per_fiber(self) -> usize {
        match self {
            SceneKind::Furnace => 3,
            SceneKind::Patch => 4,
            SceneKind::Ball => 6,
        }
    }
}

impl fmt::Display for SceneKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for SceneKind {
    type Err = String;

    fn from_str(s: &str) -> Result<SceneKind, String> {
        SceneKind::ALL
            .into_iter()
            .find(|k| k.name() == s)
            .ok_or_else(|| format!("unknown scene `{s}` (expected furnace, patch or ball)"))
    }
}

/// How to build a scene.
#[derive(Clone, Copy, Debug)]
pub struct SceneOptions {
    /// Which scene.
    pub kind: SceneKind,
    /// Number of fibers (`None`: the scene's default).
    pub fibers: Option<usize>,
    /// Seed of the fiber placement.
    pub seed: u64,
    /// Image aspect ratio width/height (the camera's field of view is vertical).
    pub aspect: f32,
}

/// The ball scene's skin: a sphere of radius 1 around this point.
const BALL_CENTER: Vector3<f32> = Vector3::new(0.0, 1.3, 0.0);

/// The patch scene's skin: the square |x| ≤ 1, |z| ≤ 1 of the plane y = 0.
const PATCH_HALF: f32 = 1.0;

/// Where a fiber's root at `root` is on the body of scene `kind`, as texture coordinates
/// (u, v) in [0, 1]² (docs/model.md §14, "Stripes and textures"): on the patch, u along x and
/// v along z (u = (x + 1)/2, v = (z + 1)/2: an image laid on the skin with its top row at the
/// far edge, z = −1, as the camera sees it); on the ball, the longitude and the colatitude of
/// the root's direction from the centre (u = 1/2 + atan2(x, z)/(2π), 1/2 facing the camera;
/// v = acos(y)/π, 0 at the top: an equirectangular map); the furnace's clump as the ball, from
/// the clump's centre. A root at the centre itself reads as the top.
#[must_use]
pub fn body_uv(kind: SceneKind, root: &Vector3<f32>) -> [f32; 2] {
    match kind {
        SceneKind::Patch => [
            ((root.x / PATCH_HALF + 1.0) * 0.5).clamp(0.0, 1.0),
            ((root.z / PATCH_HALF + 1.0) * 0.5).clamp(0.0, 1.0),
        ],
        SceneKind::Ball | SceneKind::Furnace => {
            let d = if kind == SceneKind::Ball {
                root - BALL_CENTER
            } else {
                *root
            };
            let n = d.try_normalize(1e-12).unwrap_or_else(Vector3::y);
            let u = 0.5 + n.x.atan2(n.z) / (2.0 * PI);
            let v = n.y.clamp(-1.0, 1.0).acos() / PI;
            [u.clamp(0.0, 1.0), v.clamp(0.0, 1.0)]
        }
    }
}

/// How one fiber grows.
struct Growth {
    length: f32,
    r_root: f32,
    /// Tip radius as a fraction of the root's.
    taper: f32,
    segments: usize,
    /// How far each segment turns toward the comb direction.
    bend: f32,
    /// Random turn per segment.
    jitter: f32,
}

/// A random unit vector (uniform on the sphere).
fn uniform_sphere(rng: &mut Pcg32) -> Vector3<f32> {
    let z = 1.0 - 2.0 * rng.uniform();
    let r = (1.0 - z * z).max(0.0).sqrt();
    let phi = 2.0 * PI * rng.uniform();
    Vector3::new(r * phi.cos(), r * phi.sin(), z)
}

/// Grows fiber `id` from `root` along `dir`, turning toward `comb`; appends its segments.
fn grow(
    id: u32,
    root: Vector3<f32>,
    dir: Vector3<f32>,
    comb: Vector3<f32>,
    g: &Growth,
    rng: &mut Pcg32,
    out: &mut Vec<FiberSegment>,
) {
    let step = g.length / g.segments as f32;
    let mut p = root;
    let mut d = dir.normalize();
    for k in 0..g.segments {
        let s0 = k as f32 / g.segments as f32;
        let s1 = (k + 1) as f32 / g.segments as f32;
        let q = p + d * step;
        out.push(FiberSegment {
            p0: p,
            p1: q,
            r0: g.r_root * (1.0 - (1.0 - g.taper) * s0),
            r1: g.r_root * (1.0 - (1.0 - g.taper) * s1),
            v0: s0,
            v1: s1,
            fiber: id,
            node: 0,
        });
        p = q;
        d = (d + comb * g.bend + uniform_sphere(rng) * g.jitter).normalize();
    }
}

/// Builds the scene `opts` describe.
#[must_use]
pub fn build(opts: &SceneOptions) -> Scene {
    let mut rng = Pcg32::new(opts.seed, 0x7363_656e); // "scen"
    let fibers = opts.fibers.unwrap_or(opts.kind.default_fibers());
    let segments_per_fiber = opts.kind.segments_per_fiber();
    let mut segments = Vec::with_capacity(fibers * segments_per_fiber);
    match opts.kind {
        SceneKind::Furnace => {
            let g = Growth {
                length: 0.5,
                r_root: 0.01,
                taper: 0.5,
                segments: segments_per_fiber,
                bend: 0.0,
                jitter: 0.2,
            };
            for id in 0..fibers {
                // A uniform point in the ball of radius 0.8, a uniform direction.
                let root = uniform_sphere(&mut rng) * (0.8 * rng.uniform().cbrt());
                let dir = uniform_sphere(&mut rng);
                grow(
                    id as u32,
                    root,
                    dir,
                    Vector3::zeros(),
                    &g,
                    &mut rng,
                    &mut segments,
                );
            }
            let env: Box<dyn Light> = Box::new(UniformEnvironment { radiance: [1.0; 3] });
            let camera = Camera::look_at(
                Vector3::new(0.0, 0.0, 3.2),
                Vector3::zeros(),
                Vector3::y(),
                40.0 / opts.aspect.min(1.0),
            );
            Scene::new(segments, Vec::new(), Lights::new(vec![(env, 1.0)]), camera)
        }
        SceneKind::Patch => {
            let g = Growth {
                length: 0.35,
                r_root: 0.006,
                taper: 0.3,
                segments: segments_per_fiber,
                bend: 0.25,
                jitter: 0.12,
            };
            let comb = Vector3::new(1.0, 0.0, 0.3).normalize();
            for id in 0..fibers {
                let root = Vector3::new(
                    PATCH_HALF * (2.0 * rng.uniform() - 1.0),
                    0.0,
                    PATCH_HALF * (2.0 * rng.uniform() - 1.0),
                );
                let dir = Vector3::y() + comb * 0.6 + uniform_sphere(&mut rng) * 0.25;
                grow(id as u32, root, dir, comb, &g, &mut rng, &mut segments);
            }
            let skin = Surface {
                shape: Shape::Square {
                    center: Vector3::zeros(),
                    half: PATCH_HALF,
                },
                albedo: [0.35, 0.25, 0.2],
            };
            let rim: Box<dyn Light> = Box::new(DistantDisc::with_irradiance(
                Vector3::new(-0.2, 0.45, -1.0),
                12.0,
                [3.0; 3],
            ));
            let env: Box<dyn Light> = Box::new(UniformEnvironment { radiance: [0.1; 3] });
            let camera = Camera::look_at(
                Vector3::new(0.0, 1.7, 2.4),
                Vector3::new(0.0, 0.1, 0.0),
                Vector3::y(),
                38.0,
            );
            Scene::new(
                segments,
                vec![skin],
                Lights::new(vec![(rim, 0.7), (env, 0.3)]),
                camera,
            )
            .with_root_normals(vec![Vector3::y(); fibers])
        }
        SceneKind::Ball => {
            let g = Growth {
                length: 0.3,
                r_root: 0.004,
                taper: 0.3,
                segments: segments_per_fiber,
                bend: 0.12,
                jitter: 0.08,
            };
            let center = BALL_CENTER;
            let mut normals = Vec::with_capacity(fibers);
            for id in 0..fibers {
                let n = uniform_sphere(&mut rng);
                normals.push(n);
                // Combed downward: gravity projected onto the tangent plane.
                let down = Vector3::new(0.0, -1.0, 0.0);
                let mut comb = down - n * n.dot(&down);
                if comb.norm_squared() < 1e-6 {
                    comb = orthonormal_basis(&n).0;
                }
                let comb = comb.normalize();
                let dir = n + comb * 0.8 + uniform_sphere(&mut rng) * 0.2;
                grow(
                    id as u32,
                    center + n,
                    dir,
                    comb,
                    &g,
                    &mut rng,
                    &mut segments,
                );
            }
            let skin = Surface {
                shape: Shape::Sphere {
                    center,
                    radius: 1.0,
                },
                albedo: [0.3, 0.25, 0.2],
            };
            let ground = Surface {
                shape: Shape::Square {
                    center: Vector3::zeros(),
                    half: f32::INFINITY,
                },
                albedo: [0.5; 3],
            };
            let key: Box<dyn Light> = Box::new(DistantDisc::with_irradiance(
                Vector3::new(0.6, 0.9, 0.8),
                4.0,
                [2.5; 3],
            ));
            let env: Box<dyn Light> = Box::new(UniformEnvironment {
                radiance: [0.08; 3],
            });
            let camera = Camera::look_at(
                Vector3::new(0.0, 1.7, 5.2),
                Vector3::new(0.0, 1.2, 0.0),
                Vector3::y(),
                34.0,
            );
            Scene::new(
                segments,
                vec![skin, ground],
                Lights::new(vec![(key, 0.8), (env, 0.2)]),
                camera,
            )
            .with_root_normals(normals)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scenes_are_deterministic_and_the_ball_has_its_segments() {
        let opts = |kind, fibers| SceneOptions {
            kind,
            fibers,
            seed: 7,
            aspect: 1.0,
        };
        let ball = build(&opts(SceneKind::Ball, None));
        assert!(ball.segment_count() >= 100_000, "{}", ball.segment_count());
        let a = build(&opts(SceneKind::Patch, Some(50)));
        let b = build(&opts(SceneKind::Patch, Some(50)));
        assert_eq!(a.segment_count(), 200);
        for (x, y) in a.fibers.segments().iter().zip(b.fibers.segments()) {
            assert_eq!((x.p0, x.p1, x.r0, x.r1), (y.p0, y.p1, y.r0, y.r1));
        }
        assert_eq!("ball".parse::<SceneKind>(), Ok(SceneKind::Ball));
        assert!("cube".parse::<SceneKind>().unwrap_err().contains("cube"));
    }
}
