//! The WGSL base colour inverse (`fur_absorption_from_colour`, docs/model.md §14, "Inverse")
//! on a real Vulkan device (a GPU, or Mesa's llvmpipe) against the CPU's
//! `Absorption::from_base_colour`, on three coat colour tables (a smooth one, one with flat
//! cells where the smallest σ_ca is the answer, one that starts below white and ends above
//! black so that both ends clamp): 4096 random colours per table, every node's colour and
//! every cell's midpoint, and the clamped ends. GPU = CPU within 1e-5 relative per channel
//! (σ_ca below 1e-6 compared at 1e-11 absolute). A shader that reverses the interpolation
//! within a cell, or whose σ_max coordinate is off by 1e-4, must fail the same check.
//!
//! Without an adapter the tests print "skipped: no GPU adapter" and pass, unless
//! `FUR_BCSDF_REQUIRE_GPU=1` (set by `.ci/run`), which makes a missing adapter a failure.

use crate::common::or_skip;
use bcsdf_core::colour::{coat_node, CoatColour, COAT_NODES};
use bcsdf_core::rng::Pcg32;
use bcsdf_core::shader::FUR_BCSDF_WGSL;
use bcsdf_core::{Absorption, Rgb};
use bcsdf_gpu::GpuCoat;

/// The agreement asked for, relative.
const RELATIVE: f32 = 1e-5;

/// The tables: c(σ) = dark + (bright − dark)/(1 + 4σ); the same with flat cells; and one
/// from 0.6 down to 0.05.
fn tables() -> Vec<(&'static str, CoatColour)> {
    let smooth = |dark: f32, bright: f32| -> [f32; COAT_NODES] {
        core::array::from_fn(|k| dark + (bright - dark) / (1.0 + 4.0 * coat_node(k)))
    };
    let mut flat = smooth(0.03, 0.6);
    for k in 5..9 {
        flat[k] = flat[4];
    }
    for k in 15..COAT_NODES {
        flat[k] = flat[14];
    }
    [
        ("smooth", smooth(0.0137, 0.987)),
        ("flat cells", flat),
        ("narrow", smooth(0.05, 0.6)),
    ]
    .into_iter()
    .map(|(name, c)| (name, CoatColour::from_colours(c).unwrap()))
    .collect()
}

/// The colours asked of `coat`: random, every node, every midpoint, the ends and past them.
fn colours(coat: &CoatColour) -> Vec<[f32; 3]> {
    let mut rng = Pcg32::new(7, 11);
    let mut out: Vec<[f32; 3]> = (0..4096)
        .map(|_| [rng.uniform(), rng.uniform(), rng.uniform()])
        .collect();
    let nodes = coat.colours();
    for (k, w) in nodes.windows(2).enumerate() {
        out.push([nodes[k], 0.5 * (w[0] + w[1]), w[1]]);
    }
    out.push([0.0, 1.0, coat.brightest()]);
    out.push([
        coat.darkest(),
        (coat.darkest() - 1e-4).max(0.0),
        coat.brightest() + 1e-4,
    ]);
    out
}

/// The worst relative GPU − CPU difference (σ below 1e-6 at 1e-11 absolute), with the colour
/// and both answers.
fn worst(coat: &CoatColour, colours: &[[f32; 3]], gpu: &[[f32; 3]]) -> (f32, String) {
    let mut worst = (0.0f32, String::new());
    for (c, g) in colours.iter().zip(gpu) {
        let cpu = Absorption::from_base_colour(Rgb(*c), coat)
            .unwrap()
            .absorption
            .sigma()
            .0;
        for k in 0..3 {
            let e = (g[k] - cpu[k]).abs() / cpu[k].max(1e-6);
            if e > worst.0 || e.is_nan() {
                worst = (
                    if e.is_nan() { f32::INFINITY } else { e },
                    format!("colour {c:?} channel {k}: gpu {} cpu {}", g[k], cpu[k]),
                );
            }
        }
    }
    worst
}

#[test]
fn the_shader_s_sigma_max_coordinate_is_the_cpu_s() {
    let line = FUR_BCSDF_WGSL
        .lines()
        .find(|l| l.starts_with("const FUR_COAT_AXIS_END: f32 = "))
        .unwrap();
    let value: f32 = line
        .trim_start_matches("const FUR_COAT_AXIS_END: f32 = ")
        .trim_end_matches(';')
        .parse()
        .unwrap();
    // What the CPU's coat_node uses: √(σ_max/(σ_max + 1)) in f32, correctly rounded.
    let sigma_max = coat_node(COAT_NODES - 1);
    assert_eq!(
        value.to_bits(),
        (sigma_max / (sigma_max + 1.0)).sqrt().to_bits()
    );
}

#[test]
fn gpu_absorption_from_colour_matches_cpu() {
    let Some(g) = or_skip(GpuCoat::new()) else {
        return;
    };
    println!("adapter: {}", g.adapter_name());
    for (name, coat) in tables() {
        let c = colours(&coat);
        let gpu = g.absorption_from_colours(&coat, &c).unwrap();
        assert_eq!(gpu.len(), c.len());
        let (e, at) = worst(&coat, &c, &gpu);
        println!(
            "{name}: {} colours, worst relative difference {e:.2e} ({at})",
            c.len()
        );
        assert!(e <= RELATIVE, "{name}: {e} at {at}");
    }
}

#[test]
fn a_wrong_colour_shader_is_caught() {
    let mutations = [
        (
            "the interpolation within a cell reversed",
            "t = (hi - c) / (hi - lo);",
            "t = (c - lo) / (hi - lo);",
        ),
        (
            "the sigma_max coordinate off by 1e-4",
            "const FUR_COAT_AXIS_END: f32 = 0.999500394;",
            "const FUR_COAT_AXIS_END: f32 = 0.999400394;",
        ),
    ];
    let (_, coat) = tables().remove(0);
    let c = colours(&coat);
    for (what, from, to) in mutations {
        let wrong = FUR_BCSDF_WGSL.replace(from, to);
        assert_ne!(wrong, FUR_BCSDF_WGSL, "the mutation {what} applies");
        let Some(g) = or_skip(GpuCoat::with_shader(&wrong)) else {
            return;
        };
        let (e, at) = worst(&coat, &c, &g.absorption_from_colours(&coat, &c).unwrap());
        println!("{what}: worst relative difference {e:.2e} ({at})");
        assert!(e > RELATIVE, "the agreement check missed {what} ({e})");
    }
}
