//! Base colour → σ_ca on the GPU (docs/model.md §14, "Inverse"): the shader's
//! `fur_absorption_from_colour`, which takes a preset's coat colour table (24 nodes packed in
//! six vec4, as an engine keeps it in a uniform or storage buffer) and a linear colour, and
//! returns the σ_ca per channel that the CPU's `Absorption::from_base_colour` returns.

use crate::{device, dispatch, pipelines, GpuError, MAX_DISPATCH};
use bcsdf_core::colour::{CoatColour, COAT_NODES};
use bcsdf_core::shader::{ENTRY_ABSORPTION, FUR_BCSDF_WGSL};

/// The coat colour table's vec4s at the head of every dispatch's queries.
const TABLE_VEC4S: usize = COAT_NODES / 4;

/// A device with the pipeline of `fur_absorption_main` (bindings 1 and 2: the table's six
/// vec4 then one colour per query; σ_ca RGB back).
pub struct GpuCoat {
    device: wgpu::Device,
    queue: wgpu::Queue,
    pipeline: wgpu::ComputePipeline,
    adapter: wgpu::AdapterInfo,
}

impl GpuCoat {
    /// The pipeline on the first adapter.
    ///
    /// # Errors
    /// [`GpuError::NoAdapter`] or [`GpuError::Device`] without a usable device.
    pub fn new() -> Result<GpuCoat, GpuError> {
        GpuCoat::with_shader(FUR_BCSDF_WGSL)
    }

    /// [`GpuCoat::new`] with another WGSL source of the same interface (the tests use it to
    /// show that the agreement test catches a wrong interpolation).
    ///
    /// # Errors
    /// As [`GpuCoat::new`].
    pub fn with_shader(wgsl: &str) -> Result<GpuCoat, GpuError> {
        let (device, queue, adapter) = device()?;
        let [pipeline] = pipelines(&device, wgsl, [ENTRY_ABSORPTION]);
        Ok(GpuCoat {
            device,
            queue,
            pipeline,
            adapter,
        })
    }

    /// The adapter's name and type, e.g. "llvmpipe (LLVM 15.0.6, 256 bits) (Cpu)".
    pub fn adapter_name(&self) -> String {
        format!("{} ({:?})", self.adapter.name, self.adapter.device_type)
    }

    /// σ_ca per channel of each linear colour through `coat` (colours validated on the host
    /// as `Absorption::from_base_colour` does: the shader reads a NaN channel as darker than
    /// any node).
    ///
    /// # Errors
    /// [`GpuError::Readback`] if the results cannot be read back.
    pub fn absorption_from_colours(
        &self,
        coat: &CoatColour,
        colours: &[[f32; 3]],
    ) -> Result<Vec<[f32; 3]>, GpuError> {
        let nodes = coat.colours();
        let table: [[f32; 4]; TABLE_VEC4S] =
            core::array::from_fn(|v| core::array::from_fn(|c| nodes[4 * v + c]));
        let mut out = Vec::with_capacity(colours.len());
        for chunk in colours.chunks(MAX_DISPATCH) {
            let q: Vec<[f32; 4]> = table
                .iter()
                .copied()
                .chain(chunk.iter().map(|c| [c[0], c[1], c[2], 0.0]))
                .collect();
            let rows = dispatch(
                &self.device,
                &self.queue,
                &self.pipeline,
                None,
                &q,
                chunk.len(),
            )?;
            out.extend(rows.iter().map(|r| [r[0], r[1], r[2]]));
        }
        Ok(out)
    }
}
