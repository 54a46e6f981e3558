//! Baked versus analytic under multiple scattering: for every built-in preset, the
//! `ball` rendered with the analytic far field and with its baked LUT along the very same paths
//! (both sampled by the baked sampler, `render::scatter::Guided`; same seed), so the two images
//! differ by the evaluator only. Mean radiance within 0.5 %, every 16×16 tile within 2 %; the
//! difference per bounce order is printed.
//!
//! The profiles are the shipped full-budget ones, from the profile cache `bake_budget` fills
//! (the same folder; the cache's per-entry lock makes sharing it safe), so in a whole test run
//! they are generated once.

use bake::profiles::{build_model, ProfileOptions};
use bcsdf_core::lut::LutResolution;
use bcsdf_core::presets;
use bcsdf_core::{BakedBcsdf, FurParams};
use render::scatter::{Guided, One};
use render::{integrator, scenes, SceneKind, SceneOptions, Settings};
use std::path::PathBuf;

fn check(name: &str) {
    let preset = presets::find(name).unwrap();
    let opts = ProfileOptions {
        cache_dir: Some(PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("fur-profile-cache")),
        ..ProfileOptions::default()
    };
    let (model, _) = build_model(FurParams::new(&preset.input).unwrap(), &opts).unwrap();
    let blob = bake::tables::bake(&model, &preset.input, LutResolution::DEFAULT);
    let baked = BakedBcsdf::from_bytes(&blob).unwrap();
    let analytic = model.model();
    let scene = scenes::build(&SceneOptions {
        kind: SceneKind::Ball,
        fibers: None,
        seed: 1,
        aspect: 4.0 / 3.0,
    });
    let settings = Settings {
        max_depth: 32,
        ..Settings::new(40, 30, 8)
    };
    let b = integrator::render(&scene, &One(&baked), &settings).unwrap();
    let a = integrator::render(
        &scene,
        &Guided {
            eval: &analytic,
            guide: &baked,
        },
        &settings,
    )
    .unwrap();
    let (ma, mb) = (a.image.whole().mean, b.image.whole().mean);
    let rel: Vec<f64> = (0..3).map(|c| (mb[c] - ma[c]) / ma[c]).collect();
    let per_order: Vec<String> = a
        .orders
        .iter()
        .zip(&b.orders)
        .take(8)
        .map(|(x, y)| {
            if x[1] > 0.0 {
                format!("{:+.3}%", 100.0 * (y[1] - x[1]) / x[1])
            } else {
                "-".to_string()
            }
        })
        .collect();
    let share: Vec<String> = a
        .orders
        .iter()
        .take(8)
        .map(|x| format!("{:.3}", x[1] / ma[1]))
        .collect();
    println!(
        "{}: mean analytic {:?} baked {:?}, (baked-analytic)/analytic {:+.3?} %",
        preset.name,
        ma,
        mb,
        rel.iter().map(|r| r * 100.0).collect::<Vec<_>>()
    );
    println!(
        "{}: G share of the image per bounce order 0..7: {}",
        preset.name,
        share.join(" ")
    );
    println!(
        "{}: G (baked-analytic)/analytic per bounce order 0..7: {}",
        preset.name,
        per_order.join(" ")
    );
    for r in &rel {
        assert!(
            r.abs() < 0.005,
            "{}: mean differs by {:.3} %",
            preset.name,
            100.0 * r
        );
    }
    let floor = 0.01 * ma.iter().copied().fold(0.0, f64::max);
    let mut worst = 0.0f64;
    for (ta, tb) in a.image.tiles(16).iter().zip(b.image.tiles(16)) {
        for c in 0..3 {
            worst = worst.max((tb.mean[c] - ta.mean[c]).abs() / ta.mean[c].max(floor));
        }
    }
    println!(
        "{}: largest 16x16 tile difference {:.3} %",
        preset.name,
        100.0 * worst
    );
    assert!(
        worst < 0.02,
        "{}: a tile differs by {:.3} %",
        preset.name,
        100.0 * worst
    );
}

fur_tests::per_preset_tests! {
    check, every_builtin_preset_is_rendered_baked_and_analytic;
    ball_bobcat: "bobcat",
    ball_cat: "cat",
    ball_deer: "deer",
    ball_dog: "dog",
    ball_mouse: "mouse",
    ball_rabbit: "rabbit",
    ball_raccoon: "raccoon",
    ball_red_fox: "red-fox",
    ball_springbok: "springbok",
    ball_human_fur: "human-fur",
    ball_human_hair: "human-hair",
    ball_air_medulla: "air-medulla",
}
