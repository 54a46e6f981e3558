//! The coat above each strand vertex (`raster::coat`, docs/model.md §13 "Deep opacity map",
//! *Indirect light*), the counts a groom importer bakes for the sky and floor light, on the
//! `ball` scene (CPU only):
//!
//! - at the roots, the mean count along the skin normal is the coat's expected count from the
//!   fibers' geometry alone: every segment's cross-section 2r̄·ℓ·|t × ρ̂|, projected radially
//!   onto the unit sphere (÷ ρ²) and spread over its area 4π;
//! - the count falls from root to tip;
//! - the bake is the same bits on one thread and on two.

use nalgebra::Vector3;
use raster::coat::{coat_at, coat_counts};
use render::scene::Scene;
use render::surface::Shape;
use render::{scenes, SceneKind, SceneOptions};

fn ball() -> Scene {
    scenes::build(&SceneOptions {
        kind: SceneKind::Ball,
        fibers: Some(3000),
        seed: 7,
        aspect: 1.0,
    })
}

/// The ball's centre and radius.
fn sphere(scene: &Scene) -> (Vector3<f32>, f32) {
    scene
        .surfaces
        .iter()
        .find_map(|s| match s.shape {
            Shape::Sphere { center, radius } => Some((center, radius)),
            Shape::Square { .. } => None,
        })
        .expect("the ball scene has a sphere")
}

#[test]
fn the_count_at_the_roots_is_the_coat_s_expected_crossings() {
    let scene = ball();
    let (center, radius) = sphere(&scene);
    let segs = scene.fibers.segments();
    // Expected crossings of a line along the normal through a uniform point of the skin, from
    // the geometry (f64): Σ 2 r̄ ℓ |t × ρ̂| / |ρ|² over the sphere's 4π (radius 1 here).
    assert!((radius - 1.0).abs() < 1e-6);
    let mut expected = 0.0f64;
    for s in segs {
        let d = s.p1 - s.p0;
        let len = f64::from(d.norm());
        let mid = (s.p0 + s.p1) * 0.5 - center;
        let rho = f64::from(mid.norm());
        let sin = f64::from(d.normalize().cross(&mid.normalize()).norm());
        expected += f64::from(s.r0 + s.r1) * len * sin / (rho * rho);
    }
    expected /= 4.0 * std::f64::consts::PI;
    let roots: Vec<_> = segs.iter().filter(|s| s.v0 == 0.0).collect();
    assert_eq!(roots.len(), 3000);
    let mean = roots
        .iter()
        .map(|s| {
            let n = scene.root_normals[s.fiber as usize];
            f64::from(coat_at(&scene, &s.p0, &n, s.r0, s.fiber)[0])
        })
        .sum::<f64>()
        / roots.len() as f64;
    println!(
        "mean count above the roots {mean:.4}, expected from the geometry {expected:.4} ({:+.1} %)",
        100.0 * (mean / expected - 1.0)
    );
    assert!(
        (mean / expected - 1.0).abs() < 0.08,
        "{mean} against {expected}"
    );
}

#[test]
fn the_count_falls_from_root_to_tip_and_is_the_same_on_any_thread_count() {
    let scene = ball();
    let (center, _) = sphere(&scene);
    let segs = scene.fibers.segments();
    let normals: Vec<Vector3<f32>> = segs.iter().map(|s| (s.p0 - center).normalize()).collect();
    let two = coat_counts(&scene, &normals);
    let one = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .unwrap()
        .install(|| coat_counts(&scene, &normals));
    let bits = |v: &[[f32; 4]]| -> Vec<u32> { v.iter().flatten().map(|x| x.to_bits()).collect() };
    assert_eq!(bits(&one), bits(&two), "one thread against two");
    assert!(two.iter().flatten().all(|x| x.is_finite() && *x >= 0.0));
    // Mean `above` at the roots and at the tips (the last segment's p1).
    let mean = |pick: &dyn Fn(usize) -> Option<f32>| {
        let v: Vec<f32> = (0..segs.len()).filter_map(pick).collect();
        v.iter().sum::<f32>() / v.len() as f32
    };
    let root = mean(&|i| (segs[i].v0 == 0.0).then_some(two[i][0]));
    let tip = mean(&|i| (segs[i].v1 == 1.0).then_some(two[i][2]));
    println!("mean count above: roots {root:.3}, tips {tip:.3}");
    assert!(root > 0.2, "the coat is there: {root}");
    assert!(tip < 0.3 * root, "tips {tip} against roots {root}");
}
