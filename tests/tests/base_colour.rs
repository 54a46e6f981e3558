//! What you pick is what the coat shows (docs/model.md §14): a preset's coat colour table
//! measured by the random walk through a statistical coat (`CoatColour::measure`), inverted
//! for a requested colour (`Absorption::from_base_colour`), and the thick coat slab rendered by
//! the path tracer (`render::coat`, explicit fibers) at the σ_ca found: its mean colour within
//! 5 % relative (or 0.01 absolute, whichever is larger) per channel of the colour asked for.
//!
//! The LUT is baked with the shipped profile budget into the profile cache `bake_budget` fills
//! (the same folder), so in a whole test run its profiles and residual tables are generated
//! once.

use bake::profiles::{build_model, ProfileOptions};
use bcsdf_core::colour::{CoatColour, CoatWalk};
use bcsdf_core::lut::LutResolution;
use bcsdf_core::{presets, Absorption, BakedBcsdf, FurParams, Rgb};
use render::coat::{coat_scene, CoatSlab};
use render::scatter::One;
use render::{integrator, Settings};
use std::path::PathBuf;
use std::time::Instant;

/// The baked LUT of a built-in preset.
fn lut_bytes(name: &str) -> Vec<u8> {
    let preset = presets::find(name).unwrap();
    let opts = ProfileOptions {
        cache_dir: Some(PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("fur-profile-cache")),
        ..ProfileOptions::default()
    };
    let (model, _) = build_model(FurParams::new(&preset.input).unwrap(), &opts).unwrap();
    bake::tables::bake(&model, &preset.input, LutResolution::DEFAULT)
}

/// The path-traced coat slab's mean colour at `absorption`, and its standard error.
fn rendered(lut: &BakedBcsdf, absorption: &Absorption, side: u32, spp: u32) -> (Rgb, Rgb) {
    let scene = coat_scene(&CoatSlab::DEFAULT);
    let settings = Settings {
        max_depth: 1024,
        ..Settings::new(side, side, spp)
    };
    let r = integrator::render(&scene, &One(&lut.at(absorption)), &settings).unwrap();
    let e = r.image.whole();
    (
        Rgb(e.mean.map(|m| m as f32)),
        Rgb(e.std_error.map(|s| s as f32)),
    )
}

/// Whether `got` is within 5 % relative or 0.01 absolute of `want`, per channel.
fn within(got: Rgb, want: Rgb) -> bool {
    (0..3).all(|c| (got[c] - want[c]).abs() <= (0.05 * want[c]).max(0.01))
}

#[test]
fn a_picked_colour_is_the_colour_the_coat_shows() {
    let bytes = lut_bytes("human-hair");
    let lut = BakedBcsdf::from_bytes(&bytes).unwrap();
    let t = Instant::now();
    let coat = CoatColour::measure(&lut, &CoatWalk::DEFAULT);
    println!(
        "human-hair coat table in {:.2} s: {:?}",
        t.elapsed().as_secs_f64(),
        coat.colours()
    );
    let mut failures = Vec::new();
    for want in [Rgb([0.5, 0.25, 0.08]), Rgb::splat(0.18)] {
        let b = Absorption::from_base_colour(want, &coat).unwrap();
        assert!(!b.is_clamped(), "{b}");
        let t = Instant::now();
        let (got, err) = rendered(&lut, &b.absorption, 16, 64);
        println!(
            "  {b}: path traced {:.4?} ± {:.4?} ({:.2} s)",
            got.0,
            err.0,
            t.elapsed().as_secs_f64()
        );
        if !within(got, want) {
            failures.push(format!("{b}: the coat shows {:?}", got.0));
        }
    }
    assert!(failures.is_empty(), "{failures:#?}");
}
