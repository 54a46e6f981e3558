//! `--gpu`: the baked LUT evaluated by the WGSL shader on the first adapter (`bcsdf-gpu`),
//! for `viewer compare` (the fur render through the shader against the CPU's).

use crate::render;
use bcsdf_core::baked::BakedBcsdf;
use bcsdf_core::{Angles, Bcsdf, Families, Libm, SampledDirection};
use std::collections::HashMap;

/// Far-field values computed elsewhere (on the GPU) for a known set of angles, served as a
/// [`Bcsdf`] so that the renderer can use them like any evaluator. Angles it was not given
/// evaluate to zero; it does not sample.
struct Precomputed(HashMap<[u32; 3], Families>);

fn key(a: &Angles) -> [u32; 3] {
    [
        a.theta_i().to_bits(),
        a.theta_r().to_bits(),
        a.phi().to_bits(),
    ]
}

impl Bcsdf for Precomputed {
    type Math = Libm;
    fn eval(&self, angles: &Angles) -> Families {
        self.0.get(&key(angles)).copied().unwrap_or(Families::ZERO)
    }
    fn pdf(&self, _: &Angles) -> f32 {
        0.0
    }
    fn sample_direction(&self, _: f32, _: [f32; 3]) -> Option<SampledDirection> {
        None
    }
}

/// Renders the fur patch with the CPU's baked evaluator and with the shader on the first
/// adapter: (adapter name, mean relative difference of the GPU render to the CPU's, RGB).
pub fn render_difference(blob: &[u8], cpu: &BakedBcsdf<'_>) -> Result<(String, [f64; 3]), String> {
    let gpu = bcsdf_gpu::GpuLut::new(blob).map_err(|e| e.to_string())?;
    let angles = render::segment_angles();
    let queries: Vec<[f32; 3]> = angles
        .iter()
        .map(|a| [a.theta_i(), a.theta_r(), a.phi()])
        .collect();
    let values = gpu.eval(&queries).map_err(|e| e.to_string())?;
    let map = angles
        .iter()
        .zip(&values)
        .map(|(a, v)| (key(a), bcsdf_gpu::families(v)))
        .collect();
    let renders = render::render(cpu, &Precomputed(map));
    Ok((gpu.adapter_name(), renders.mean_relative_difference()))
}
