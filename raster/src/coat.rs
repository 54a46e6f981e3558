//! The coat above each strand vertex, as the sky and floor light see it (docs/model.md §13,
//! "Deep opacity map", *Indirect light*): what a groom importer bakes once per groom, as
//! engines bake per-vertex ambient occlusion, so that the fragment shader can take the
//! ambient light through the fibers above the fragment.
//!
//! Two mean fiber counts per vertex, other fibers only (the vertex's own is left out at any
//! distance), each along lines that end at the first surface (skin, ground) or leave the
//! scene:
//!
//! - **above**: along the skin normal, over [`NORMAL_LINES`] parallel lines through points
//!   spread over a disc of [`SPREAD_RADII`] fiber radii around the vertex (golden-angle
//!   spiral, uniform in area): the N of a flat coat's N/cos γ at angle γ to the normal;
//! - **across**: along [`TANGENT_LINES`] directions evenly spread over the skin's tangent
//!   plane from the vertex: the most a direction can count, because a curved coat (a body,
//!   a limb) ends sooner than the flat coat's N/cos γ → ∞ at grazing angles.
//!
//! The lines are fixed (no random numbers): the same groom gives the same bits.

use nalgebra::Vector3;
use rayon::prelude::*;
use render::accel::Skip;
use render::scene::Scene;
use render::surface::orthonormal_basis;
use std::collections::HashMap;

/// Lines along the skin normal per vertex.
pub const NORMAL_LINES: usize = 16;

/// Radius of the disc the normal lines pass through, in the vertex's fiber radii.
pub const SPREAD_RADII: f32 = 8.0;

/// Directions in the skin's tangent plane per vertex.
pub const TANGENT_LINES: usize = 8;

/// The golden angle, 2π(1 − 1/φ) (radians): consecutive spiral points' turn.
const GOLDEN_ANGLE: f32 = 2.399_963;

/// The coat above one vertex: (above, across), as the module says.
#[must_use]
pub fn coat_at(
    scene: &Scene,
    point: &Vector3<f32>,
    normal: &Vector3<f32>,
    radius: f32,
    fiber: u32,
) -> [f32; 2] {
    let (u, v) = orthonormal_basis(normal);
    // The vertex's own fiber is left out at any distance (a line through a neighbouring point
    // would otherwise meet the vertex's own fiber leaning over it).
    let own = Skip {
        fiber: Some(fiber),
        dist: f32::INFINITY,
    };
    let count = |origin: &Vector3<f32>, dir: &Vector3<f32>| {
        let end = scene
            .intersect_surfaces(origin, dir)
            .map_or(f32::INFINITY, |hit| hit.t);
        scene
            .fibers
            .count_fibers(origin, dir, scene.epsilon, end, own) as f32
    };
    let mut above = 0.0;
    for i in 0..NORMAL_LINES {
        let k = i as f32 + 0.5;
        let a = k * GOLDEN_ANGLE;
        let r = SPREAD_RADII * radius * (k / NORMAL_LINES as f32).sqrt();
        above += count(&(point + (u * a.cos() + v * a.sin()) * r), normal);
    }
    let mut across = 0.0;
    for i in 0..TANGENT_LINES {
        let a = i as f32 * core::f32::consts::TAU / TANGENT_LINES as f32;
        across += count(point, &(u * a.cos() + v * a.sin()));
    }
    [above / NORMAL_LINES as f32, across / TANGENT_LINES as f32]
}

/// [`coat_at`] at both ends of every fiber segment of `scene`, with the skin normal
/// `normals[i]` under segment i: `[above(p0), across(p0), above(p1), across(p1)]`. A vertex
/// two segments share is counted once, under the normal of the segment that starts there
/// (in parallel; the same bits for any thread count).
#[must_use]
pub fn coat_counts(scene: &Scene, normals: &[Vector3<f32>]) -> Vec<[f32; 4]> {
    let segs = scene.fibers.segments();
    // Where each segment's p1 starts the next segment of its fiber (the same place along
    // the strand), if one does.
    let starts: HashMap<(u32, u32), usize> = segs
        .iter()
        .enumerate()
        .map(|(i, s)| ((s.fiber, s.v0.to_bits()), i))
        .collect();
    let next: Vec<Option<usize>> = segs
        .iter()
        .map(|s| starts.get(&(s.fiber, s.v1.to_bits())).copied())
        .collect();
    let at_start: Vec<[f32; 2]> = segs
        .par_iter()
        .zip(normals.par_iter())
        .map(|(s, n)| coat_at(scene, &s.p0, n, s.r0, s.fiber))
        .collect();
    segs.par_iter()
        .zip(normals.par_iter())
        .zip(next.par_iter())
        .zip(at_start.par_iter())
        .map(|(((s, n), next), a)| {
            let b = next.map_or_else(|| coat_at(scene, &s.p1, n, s.r1, s.fiber), |j| at_start[j]);
            [a[0], a[1], b[0], b[1]]
        })
        .collect()
}
