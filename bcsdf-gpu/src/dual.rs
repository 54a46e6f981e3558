//! [`GpuDual`]: the dual-scattering term (docs/model.md §13) on the GPU, the WGSL
//! `fur_eval_dual` of `bcsdf-core/shaders/fur_bcsdf.wgsl` reading a `.furdual` blob from its
//! own storage buffer (binding 3), checked against `bcsdf_core::dual::DualLut::eval`.

use crate::{device, dispatch, pipelines, words_buffer, GpuError, MAX_DISPATCH};
use bcsdf_core::dual::{Density, DualLut, Fibers};
use bcsdf_core::shader::FUR_BCSDF_WGSL;

/// Entry point evaluating dual-scattering angle queries: two vec4 per query,
/// `(theta_i, theta_r, phi, fibers.to_light)` and `(d_f, d_b, fibers.below, _)`; RGB in the
/// first three floats of each result.
pub const ENTRY_DUAL: &str = "fur_dual_main";

/// Entry point evaluating dual-scattering vector queries: four vec4 per query,
/// `(wi, fibers.to_light)`, `(wr, d_f)`, `(tangent, d_b)`, `(fibers.below, _, _, _)`; RGB in
/// the first three floats of each result.
pub const ENTRY_DUAL_DIRS: &str = "fur_dual_dirs_main";

/// The binding of the `.furdual` words in the shader (group 0).
const DUAL_BINDING: u32 = 3;

/// One dual-scattering query from angles (`DualLut::eval`'s arguments).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DualQuery {
    /// θ_i, θ_r, φ (radians).
    pub angles: [f32; 3],
    /// The fibers between the shading point and the light and below it (any f32s: the
    /// contract of [`Fibers`] maps NaN, negative and huge counts).
    pub fibers: Fibers,
    /// The density factors d_f, d_b.
    pub density: Density,
    /// The colour: σ_ca per fiber radius, RGB (each channel reads the blob's absorption
    /// axis at its own value, `DualLut::eval_at`; the preset's own is
    /// `DualLut::absorption`).
    pub sigma_ca: [f32; 3],
}

/// One dual-scattering query from world-space vectors (`DualLut::eval_dirs`'s arguments).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DualDirsQuery {
    /// Toward the light (any length).
    pub wi: [f32; 3],
    /// Toward the viewer (any length).
    pub wr: [f32; 3],
    /// The fiber tangent (any length).
    pub tangent: [f32; 3],
    /// The fibers between the shading point and the light and below it (any f32s, as in
    /// [`DualQuery::fibers`]).
    pub fibers: Fibers,
    /// The density factors d_f, d_b.
    pub density: Density,
    /// The colour, as in [`DualQuery::sigma_ca`].
    pub sigma_ca: [f32; 3],
}

/// A validated `.furdual` blob on a GPU device, with the compute pipelines of the shader's
/// dual-scattering evaluator.
pub struct GpuDual {
    device: wgpu::Device,
    queue: wgpu::Queue,
    blob: wgpu::Buffer,
    eval: wgpu::ComputePipeline,
    eval_dirs: wgpu::ComputePipeline,
    adapter: wgpu::AdapterInfo,
}

impl GpuDual {
    /// Validates `blob` (`DualLut::decode`: the shader trusts what it reads) and uploads it,
    /// as little-endian u32 words, to the first adapter.
    ///
    /// # Errors
    /// [`GpuError::Dual`] for an invalid blob, [`GpuError::NoAdapter`] or
    /// [`GpuError::Device`] without a usable device.
    pub fn new(blob: &[u8]) -> Result<GpuDual, GpuError> {
        GpuDual::with_shader(blob, FUR_BCSDF_WGSL)
    }

    /// [`GpuDual::new`] with another WGSL source of the same interface (the tests use it to
    /// show that the agreement test catches a wrong constant).
    ///
    /// # Errors
    /// As [`GpuDual::new`].
    pub fn with_shader(blob: &[u8], wgsl: &str) -> Result<GpuDual, GpuError> {
        let mut check = Box::new(DualLut::EMPTY);
        check.decode(blob).map_err(GpuError::Dual)?;
        let (device, queue, adapter) = device()?;
        let blob = words_buffer(&device, "fur-dual", blob);
        let [eval, eval_dirs] = pipelines(&device, wgsl, [ENTRY_DUAL, ENTRY_DUAL_DIRS]);
        Ok(GpuDual {
            device,
            queue,
            blob,
            eval,
            eval_dirs,
            adapter,
        })
    }

    /// The adapter's name and type, e.g. "llvmpipe (LLVM 15.0.6, 256 bits) (Cpu)".
    pub fn adapter_name(&self) -> String {
        format!("{} ({:?})", self.adapter.name, self.adapter.device_type)
    }

    /// The dual-scattering term (RGB) of each angle query, as `DualLut::eval` computes it.
    ///
    /// # Errors
    /// [`GpuError::Readback`] when the results cannot be read back.
    pub fn eval(&self, queries: &[DualQuery]) -> Result<Vec<[f32; 3]>, GpuError> {
        let mut out = Vec::with_capacity(queries.len());
        for chunk in queries.chunks(MAX_DISPATCH) {
            let q: Vec<[f32; 4]> = chunk
                .iter()
                .flat_map(|q| {
                    let [ti, tr, phi] = q.angles;
                    let [r, g, b] = q.sigma_ca;
                    [
                        [ti, tr, phi, q.fibers.to_light],
                        [q.density.d_f, q.density.d_b, q.fibers.below, 0.0],
                        [r, g, b, 0.0],
                    ]
                })
                .collect();
            out.extend(self.run(&self.eval, &q, chunk.len())?);
        }
        Ok(out)
    }

    /// The dual-scattering term (RGB) of each vector query, at the angles of the baked
    /// evaluator's direction conversion (`BakedBcsdf::angles_from_dirs`, the shader's
    /// `fur_angles_from_dirs`); zero for unusable vectors.
    ///
    /// # Errors
    /// [`GpuError::Readback`] when the results cannot be read back.
    pub fn eval_dirs(&self, queries: &[DualDirsQuery]) -> Result<Vec<[f32; 3]>, GpuError> {
        let mut out = Vec::with_capacity(queries.len());
        for chunk in queries.chunks(MAX_DISPATCH) {
            let q: Vec<[f32; 4]> = chunk
                .iter()
                .flat_map(|q| {
                    let w = |v: [f32; 3], x: f32| [v[0], v[1], v[2], x];
                    [
                        w(q.wi, q.fibers.to_light),
                        w(q.wr, q.density.d_f),
                        w(q.tangent, q.density.d_b),
                        [q.fibers.below, q.sigma_ca[0], q.sigma_ca[1], q.sigma_ca[2]],
                    ]
                })
                .collect();
            out.extend(self.run(&self.eval_dirs, &q, chunk.len())?);
        }
        Ok(out)
    }

    fn run(
        &self,
        pipeline: &wgpu::ComputePipeline,
        queries: &[[f32; 4]],
        n: usize,
    ) -> Result<Vec<[f32; 3]>, GpuError> {
        let table = (DUAL_BINDING, &self.blob);
        let rows = dispatch(&self.device, &self.queue, pipeline, Some(table), queries, n)?;
        Ok(rows.iter().map(|r| [r[0], r[1], r[2]]).collect())
    }
}
