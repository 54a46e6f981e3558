//! MIS consistency on `patch` (docs/model.md §11): BCSDF sampling only, light sampling only and
//! their MIS combination estimate the same image, so their means agree within their noise,
//! over the whole image and per 16×16 tile (z-tests).

use crate::common;

use render::scatter::One;
use render::{integrator, scenes, SceneKind, SceneOptions, Settings, Strategy};

#[test]
fn bcsdf_light_and_mis_sampling_agree_on_the_patch() {
    let scene = scenes::build(&SceneOptions {
        kind: SceneKind::Patch,
        fibers: Some(3000),
        seed: 3,
        aspect: 1.0,
    });
    common::with_model(&common::plain().input, |hair| {
        let run = |strategy, seed| {
            let settings = Settings {
                strategy,
                seed,
                max_depth: 8,
                ..Settings::new(48, 48, 24)
            };
            integrator::render(&scene, &One(hair), &settings)
                .unwrap()
                .image
        };
        // Independent seeds: the z-test's variances add.
        let mis = run(Strategy::Mis, 1);
        let bcsdf = run(Strategy::Bcsdf, 2);
        let light = run(Strategy::Light, 3);
        let m = mis.whole();
        assert!(m.mean[0] > 0.01, "the patch is lit: {m:?}");
        for (name, other) in [("BCSDF-only", &bcsdf), ("light-only", &light)] {
            let z = common::z(&m, &other.whole());
            println!(
                "image mean: MIS {:?} vs {name} {:?}: z = {z:.2}",
                m.mean,
                other.whole().mean
            );
            assert!(z < 4.0, "{name}: image mean z = {z:.2}");
            let tiles: Vec<f64> = mis
                .tiles(16)
                .iter()
                .zip(other.tiles(16))
                .map(|(a, b)| common::z(a, &b))
                .collect();
            let worst = tiles.iter().copied().fold(0.0, f64::max);
            println!("{name}: {} tiles, largest z = {worst:.2}", tiles.len());
            // 9 tiles × 3 channels × 2 comparisons: 4.5 keeps chance failures below 1e-3.
            assert!(
                worst < 4.5,
                "{name}: a 16x16 tile differs by z = {worst:.2}"
            );
        }
    });
}
