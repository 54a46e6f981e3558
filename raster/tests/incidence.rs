//! The shader's `fur_dual_below_at_incidence` and `fur_dual_forward_density_at_incidence` (the
//! raster fragment's coat below and forward density, docs/model.md §13 "The light's incidence
//! on the coat") against `dual::coat`'s functions on a real Vulkan device: counts (density
//! factors) and cosines over the contract's cases (the floor, |cos| above 1, both signs, NaN,
//! the skin's negative count, the semi-infinite coat), each result within 1e-6 relative (or
//! bit for bit where the contract returns the input unchanged); and the same check catches the
//! shader's diffusivity changed to 1.66.
//!
//! Without an adapter the test prints "skipped: no GPU adapter" and passes, unless
//! `FUR_BCSDF_REQUIRE_GPU=1` (set by `.ci/run`).

use bcsdf_core::dual::coat::{below_at_incidence, forward_density_at_incidence};
use bcsdf_core::shader::FUR_BCSDF_WGSL;

mod common;

/// The two shader functions checked.
const BELOW: &str = "fur_dual_below_at_incidence";
const FORWARD: &str = "fur_dual_forward_density_at_incidence";

/// Every (count, cos) pair of the check.
fn pairs() -> Vec<[f32; 2]> {
    let counts = [
        0.0f32,
        -0.0,
        0.5,
        1.0,
        2.5,
        7.0,
        40.0,
        1.0e5,
        999_999.0,
        1.0e6,
        2.0e6,
        f32::INFINITY,
        f32::NAN,
        -1.0,
        -3.5,
    ];
    let cosines = [
        1.0f32,
        0.8,
        0.5,
        0.37,
        0.1,
        0.01,
        0.0,
        -0.0,
        -0.6,
        -1.0,
        1.5,
        f32::NAN,
    ];
    counts
        .iter()
        .flat_map(|&m| cosines.iter().map(move |&c| [m, c]))
        .collect()
}

/// The worst disagreement of the shader's values with the Rust function `cpu`'s: relative to
/// max(|cpu|, 1), NaN against a number or a different infinity counting as infinite.
fn worst(pairs: &[[f32; 2]], gpu: &[f32], cpu: fn(f32, f32) -> f32) -> f32 {
    let mut worst = 0.0f32;
    for (p, g) in pairs.iter().zip(gpu) {
        let c = cpu(p[0], p[1]);
        let e = if c.is_nan() || g.is_nan() || c.is_infinite() || g.is_infinite() {
            if c.to_bits() == g.to_bits() || (c.is_nan() && g.is_nan()) {
                0.0
            } else {
                f32::INFINITY
            }
        } else {
            (g - c).abs() / c.abs().max(1.0)
        };
        worst = worst.max(e);
    }
    worst
}

/// The shader's `function` against the Rust `cpu` at every pair: within 1e-6 (printed), and
/// the same check fails a shader whose diffusivity is 1.66. The shader's values, or `None`
/// without an adapter.
fn check(function: &str, pairs: &[[f32; 2]], cpu: fn(f32, f32) -> f32) -> Option<Vec<f32>> {
    let call = format!("{function}(q.x, q.y)");
    let gpu = common::gpu_call(FUR_BCSDF_WGSL, &call, pairs)?;
    let e = worst(pairs, &gpu, cpu);
    println!(
        "{function}: worst relative difference {e:.2e} over {} pairs",
        pairs.len()
    );
    assert!(e <= 1e-6, "shader against CPU: {e}");
    let wrong = FUR_BCSDF_WGSL.replace(
        "const FUR_DUAL_DIFFUSIVITY: f32 = 2.0;",
        "const FUR_DUAL_DIFFUSIVITY: f32 = 1.66;",
    );
    assert_ne!(wrong, FUR_BCSDF_WGSL, "the mutation applies");
    let wrong_gpu = common::gpu_call(&wrong, &call, pairs).unwrap();
    let e = worst(pairs, &wrong_gpu, cpu);
    assert!(e > 1e-2, "the check missed the diffusivity 1.66 ({e})");
    Some(gpu)
}

#[test]
fn the_shader_turns_the_line_into_the_coat_s_normal_depth_as_the_cpu_does() {
    let pairs = pairs();
    let Some(gpu) = check(BELOW, &pairs, below_at_incidence) else {
        return;
    };
    // The count unchanged where the contract says so: bit for bit.
    for (p, g) in pairs.iter().zip(&gpu) {
        let c = below_at_incidence(p[0], p[1]);
        if c.to_bits() == p[0].to_bits() && !c.is_nan() {
            assert_eq!(g.to_bits(), c.to_bits(), "{p:?}");
        }
    }
}

#[test]
fn the_shader_scales_the_forward_density_by_the_incidence_as_the_cpu_does() {
    // Density factors over the contract's range (and outside it: the term clamps them),
    // against the same cosines.
    let pairs: Vec<[f32; 2]> = pairs()
        .into_iter()
        .filter(|p| p[0] >= 0.0 && p[0] <= 40.0)
        .map(|[d, c]| [d * 0.1, c])
        .collect();
    let Some(gpu) = check(FORWARD, &pairs, forward_density_at_incidence) else {
        return;
    };
    // The factor unchanged where the normal is unknown (NaN): bit for bit.
    for (p, g) in pairs.iter().zip(&gpu) {
        if p[1].is_nan() {
            assert_eq!(g.to_bits(), p[0].to_bits(), "{p:?}");
        }
    }
}
