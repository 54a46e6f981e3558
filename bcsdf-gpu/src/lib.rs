//! # bcsdf-gpu
//!
//! The baked fur BCSDF on the GPU (docs/lut.md, "On the GPU"):
//! - [`translate`]: the WGSL evaluator (`bcsdf_core::shader::FUR_BCSDF_WGSL`) translated by
//!   naga to SPIR-V, HLSL (SM 6.0), GLSL (450 core and ES 310) and MSL, one file per entry
//!   point where the language needs it; the results are committed under
//!   `bcsdf-core/shaders/generated/` and a test regenerates and compares them;
//! - [`GpuLut`]: a wgpu compute runner that binds a validated `.furlut` as a storage buffer of
//!   u32 words and evaluates batches of queries through the shader, on the first adapter
//!   (on a machine without a GPU: Mesa's llvmpipe Vulkan driver, an adapter of type Cpu), at
//!   the LUT's own colour ([`GpuLut::eval`], ...) or at a cortex absorption σ_ca per query
//!   ([`GpuLut::eval_at`], ..., LUT format 5: docs/lut.md "The absorption axis");
//! - [`GpuDual`]: the same for the dual-scattering term (docs/model.md §13): a validated
//!   `.furdual` blob bound as its own storage buffer, batches of queries evaluated by the
//!   shader's `fur_eval_dual` / `fur_eval_dual_dirs` ([`ENTRY_DUAL`], [`ENTRY_DUAL_DIRS`]);
//! - [`GpuCoat`]: base colours to σ_ca through the shader's `fur_absorption_from_colour`
//!   (docs/model.md §14, "Inverse"), the CPU's `Absorption::from_base_colour` on the GPU.

use bcsdf_core::baked::BakedBcsdf;
use bcsdf_core::dual::DualError;
use bcsdf_core::lut::LutError;
use bcsdf_core::shader::{
    ENTRY_EVAL, ENTRY_EVAL_DIRS, ENTRY_PDF, ENTRY_SAMPLE, FUR_BCSDF_WGSL, RESULT_FLOATS,
};
use std::fmt;

mod colour;
mod dual;
pub mod translate;

pub use colour::GpuCoat;
pub use dual::{DualDirsQuery, DualQuery, GpuDual, ENTRY_DUAL, ENTRY_DUAL_DIRS};

/// Why the GPU path is unavailable or failed.
#[derive(Debug)]
pub enum GpuError {
    /// No adapter: no GPU and no software Vulkan driver (Debian: `mesa-vulkan-drivers`,
    /// `libvulkan1`).
    NoAdapter(String),
    /// The adapter refused a device.
    Device(String),
    /// The LUT bytes are not a valid LUT.
    Lut(LutError),
    /// The bytes are not a valid `.furdual` blob.
    Dual(DualError),
    /// Reading the results back failed.
    Readback(String),
}

impl fmt::Display for GpuError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            GpuError::NoAdapter(e) => write!(
                f,
                "no GPU adapter ({e}); without a GPU, install Mesa's software Vulkan driver \
                 (Debian: apt-get install mesa-vulkan-drivers libvulkan1)"
            ),
            GpuError::Device(e) => write!(f, "the GPU adapter refused a device: {e}"),
            GpuError::Lut(e) => write!(f, "{e}"),
            GpuError::Dual(e) => write!(f, "{e}"),
            GpuError::Readback(e) => write!(f, "reading the GPU results back failed: {e}"),
        }
    }
}

impl std::error::Error for GpuError {}

/// Queries per dispatch: 64 per workgroup × 16 384 workgroups (within every adapter's
/// 65 535-workgroup limit per dimension).
pub const MAX_DISPATCH: usize = 64 * 16_384;

/// One far-field result: R, TT, TRT, scattered (RGB each), then the total (RGB).
pub type GpuFamilies = [f32; 15];

/// One sampling query: θ_r (radians) and three uniform numbers in [0, 1).
pub type SampleQuery = (f32, [f32; 3]);

/// A GPU result as the CPU's per-family type (the total is recomputed by `Families::total`).
pub fn families(v: &GpuFamilies) -> bcsdf_core::Families {
    bcsdf_core::Families::from_array(core::array::from_fn(|f| {
        bcsdf_core::Rgb([v[3 * f], v[3 * f + 1], v[3 * f + 2]])
    }))
}

/// A validated LUT on a GPU device, with the compute pipelines of the evaluator.
///
/// Every query carries a colour, σ_ca per RGB channel (per fiber radius), which the shader
/// functions take as a `vec3<f32>`: the `*_at` methods pass the caller's, the others the LUT's
/// own ([`GpuLut::sigma_ca`], `BakedBcsdf::absorption`). Validate colours as
/// `bcsdf_core::Absorption::from_sigma` does: the shader reads NaN and negative channels as
/// 0 and channels above 1000 as 1000.
pub struct GpuLut {
    /// The LUT's own colour, σ_ca per RGB channel (`BakedBcsdf::absorption`).
    sigma_ca: [f32; 3],
    device: wgpu::Device,
    queue: wgpu::Queue,
    lut: wgpu::Buffer,
    eval: wgpu::ComputePipeline,
    eval_dirs: wgpu::ComputePipeline,
    sample: wgpu::ComputePipeline,
    pdf: wgpu::ComputePipeline,
    adapter: wgpu::AdapterInfo,
}

/// A sample drawn on the GPU (`fur_sample_far`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GpuSample {
    /// θ_i (radians).
    pub theta_i: f32,
    /// φ (radians).
    pub phi: f32,
    /// Density per unit solid angle.
    pub pdf: f32,
    /// S·cos θ_i/pdf, RGB.
    pub weight: [f32; 3],
    /// Family: 0 R, 1 TT, 2 TRT, 3 scattered.
    pub family: u32,
}

/// The first adapter (any backend wgpu was built with: Vulkan here).
fn adapter() -> Result<wgpu::Adapter, GpuError> {
    let instance = wgpu::Instance::new(wgpu::InstanceDescriptor::new_without_display_handle());
    pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions {
        power_preference: wgpu::PowerPreference::HighPerformance,
        ..Default::default()
    }))
    .map_err(|e| GpuError::NoAdapter(e.to_string()))
}

/// A device and queue on the first adapter, with the adapter's description.
fn device() -> Result<(wgpu::Device, wgpu::Queue, wgpu::AdapterInfo), GpuError> {
    let adapter = adapter()?;
    let info = adapter.get_info();
    let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
        label: Some("fur-bcsdf"),
        required_limits: adapter.limits(),
        ..Default::default()
    }))
    .map_err(|e| GpuError::Device(e.to_string()))?;
    Ok((device, queue, info))
}

/// A blob as a read-only storage buffer of little-endian u32 words, zero-padded to a whole
/// word.
fn words_buffer(device: &wgpu::Device, label: &str, bytes: &[u8]) -> wgpu::Buffer {
    let mut words = Vec::with_capacity(bytes.len().div_ceil(4));
    for chunk in bytes.chunks(4) {
        let mut w = [0u8; 4];
        w[..chunk.len()].copy_from_slice(chunk);
        words.push(u32::from_le_bytes(w));
    }
    buffer_init(device, label, as_bytes(&words), wgpu::BufferUsages::STORAGE)
}

/// The compute pipelines of `entries` in the WGSL `wgsl` (layouts derived from the shader:
/// each binds only what its entry point uses).
fn pipelines<const N: usize>(
    device: &wgpu::Device,
    wgsl: &str,
    entries: [&str; N],
) -> [wgpu::ComputePipeline; N] {
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("fur_bcsdf.wgsl"),
        source: wgpu::ShaderSource::Wgsl(wgsl.to_owned().into()),
    });
    entries.map(|entry| {
        device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: Some(entry),
            layout: None,
            module: &module,
            entry_point: Some(entry),
            compilation_options: Default::default(),
            cache: None,
        })
    })
}

impl GpuLut {
    /// Validates `bytes` (`BakedBcsdf::from_bytes`) and uploads them to the first adapter.
    pub fn new(bytes: &[u8]) -> Result<GpuLut, GpuError> {
        GpuLut::with_shader(bytes, FUR_BCSDF_WGSL)
    }

    /// [`GpuLut::new`] with another WGSL source of the same interface (the tests use it to
    /// show that the agreement test catches a wrong table index).
    pub fn with_shader(bytes: &[u8], wgsl: &str) -> Result<GpuLut, GpuError> {
        let sigma_ca = BakedBcsdf::from_bytes(bytes)
            .map_err(GpuError::Lut)?
            .absorption()
            .sigma()
            .0;
        let (device, queue, info) = device()?;
        let lut = words_buffer(&device, "fur-lut", bytes);
        let [eval, eval_dirs, sample, pdf] = pipelines(
            &device,
            wgsl,
            [ENTRY_EVAL, ENTRY_EVAL_DIRS, ENTRY_SAMPLE, ENTRY_PDF],
        );
        Ok(GpuLut {
            sigma_ca,
            device,
            queue,
            lut,
            eval,
            eval_dirs,
            sample,
            pdf,
            adapter: info,
        })
    }

    /// The adapter's name and type, e.g. "llvmpipe (LLVM 15.0.6, 256 bits) (Cpu)".
    pub fn adapter_name(&self) -> String {
        format!("{} ({:?})", self.adapter.name, self.adapter.device_type)
    }

    /// The LUT's own colour, σ_ca per RGB channel: what the methods without `_at` evaluate.
    pub fn sigma_ca(&self) -> [f32; 3] {
        self.sigma_ca
    }

    /// Far field per family for `(theta_i, theta_r, phi)` queries (radians), at the LUT's own
    /// colour.
    pub fn eval(&self, queries: &[[f32; 3]]) -> Result<Vec<GpuFamilies>, GpuError> {
        self.eval_at(&self.own(queries))
    }

    /// Far field per family for `((theta_i, theta_r, phi), sigma_ca)` queries: angles in
    /// radians, each at its own colour.
    pub fn eval_at(&self, queries: &[([f32; 3], [f32; 3])]) -> Result<Vec<GpuFamilies>, GpuError> {
        let mut out = Vec::with_capacity(queries.len());
        for chunk in queries.chunks(MAX_DISPATCH) {
            let q: Vec<[f32; 4]> = chunk
                .iter()
                .flat_map(|(a, s)| [[a[0], a[1], a[2], 0.0], [s[0], s[1], s[2], 0.0]])
                .collect();
            out.extend(self.run(&self.eval, &q, chunk.len())?);
        }
        Ok(out)
    }

    /// Far field per family for `(wi, wr, tangent)` world-space vector queries, at the LUT's
    /// own colour.
    pub fn eval_dirs(&self, queries: &[[[f32; 3]; 3]]) -> Result<Vec<GpuFamilies>, GpuError> {
        self.eval_dirs_at(&self.own(queries))
    }

    /// Far field per family for `((wi, wr, tangent), sigma_ca)` queries, each at its own
    /// colour.
    pub fn eval_dirs_at(
        &self,
        queries: &[([[f32; 3]; 3], [f32; 3])],
    ) -> Result<Vec<GpuFamilies>, GpuError> {
        let mut out = Vec::with_capacity(queries.len());
        for chunk in queries.chunks(MAX_DISPATCH) {
            let q: Vec<[f32; 4]> = chunk
                .iter()
                .flat_map(|(v, s)| (0..3).map(move |k| [v[k][0], v[k][1], v[k][2], s[k]]))
                .collect();
            out.extend(self.run(&self.eval_dirs, &q, chunk.len())?);
        }
        Ok(out)
    }

    /// The sampling density (per unit solid angle) of `(theta_i, theta_r, phi)` queries.
    pub fn pdf(&self, queries: &[[f32; 3]]) -> Result<Vec<f32>, GpuError> {
        self.pdf_at(&self.own(queries))
    }

    /// The sampling density of `((theta_i, theta_r, phi), sigma_ca)` queries: the same at
    /// every colour (the sampler draws from the LUT's lossless plane); the colour is passed
    /// through the shader's `fur_pdf_far` as for the other entry points.
    pub fn pdf_at(&self, queries: &[([f32; 3], [f32; 3])]) -> Result<Vec<f32>, GpuError> {
        let mut out = Vec::with_capacity(queries.len());
        for chunk in queries.chunks(MAX_DISPATCH) {
            let q: Vec<[f32; 4]> = chunk
                .iter()
                .flat_map(|(a, s)| [[a[0], a[1], a[2], 0.0], [s[0], s[1], s[2], 0.0]])
                .collect();
            out.extend(self.run(&self.pdf, &q, chunk.len())?.iter().map(|r| r[0]));
        }
        Ok(out)
    }

    /// Samples for `(theta_r, [u0, u1, u2])` queries at the LUT's own colour; `None` where
    /// nothing could be sampled.
    pub fn sample(&self, queries: &[SampleQuery]) -> Result<Vec<Option<GpuSample>>, GpuError> {
        self.sample_at(&self.own(queries))
    }

    /// Samples for `((theta_r, [u0, u1, u2]), sigma_ca)` queries: the direction and pdf do not
    /// depend on the colour, the weight is this colour's; `None` where nothing could be
    /// sampled.
    pub fn sample_at(
        &self,
        queries: &[(SampleQuery, [f32; 3])],
    ) -> Result<Vec<Option<GpuSample>>, GpuError> {
        let mut out = Vec::with_capacity(queries.len());
        for chunk in queries.chunks(MAX_DISPATCH) {
            let q: Vec<[f32; 4]> = chunk
                .iter()
                .flat_map(|((t, u), s)| [[*t, u[0], u[1], u[2]], [s[0], s[1], s[2], 0.0]])
                .collect();
            out.extend(self.run(&self.sample, &q, chunk.len())?.iter().map(|r| {
                (r[7] == 1.0).then_some(GpuSample {
                    theta_i: r[0],
                    phi: r[1],
                    pdf: r[2],
                    weight: [r[3], r[4], r[5]],
                    family: r[6] as u32,
                })
            }));
        }
        Ok(out)
    }

    /// Queries paired with the LUT's own colour.
    fn own<Q: Copy>(&self, queries: &[Q]) -> Vec<(Q, [f32; 3])> {
        queries.iter().map(|&q| (q, self.sigma_ca)).collect()
    }

    fn run(
        &self,
        pipeline: &wgpu::ComputePipeline,
        queries: &[[f32; 4]],
        n: usize,
    ) -> Result<Vec<GpuFamilies>, GpuError> {
        let table = (0, &self.lut);
        let rows = dispatch(&self.device, &self.queue, pipeline, Some(table), queries, n)?;
        Ok(rows
            .iter()
            .map(|r| core::array::from_fn(|k| r[k]))
            .collect())
    }
}

/// Runs `pipeline` over `n` queries (`queries`: the query buffer's vec4s) with `table` (if
/// any: an entry point that reads none has no binding for it) bound at its binding, and reads
/// back [`RESULT_FLOATS`] floats per query.
fn dispatch(
    d: &wgpu::Device,
    queue: &wgpu::Queue,
    pipeline: &wgpu::ComputePipeline,
    table: Option<(u32, &wgpu::Buffer)>,
    queries: &[[f32; 4]],
    n: usize,
) -> Result<Vec<[f32; RESULT_FLOATS]>, GpuError> {
    if n == 0 {
        return Ok(Vec::new());
    }
    let input = buffer_init(
        d,
        "fur-queries",
        as_bytes(queries),
        wgpu::BufferUsages::STORAGE,
    );
    let size = (n * RESULT_FLOATS * 4) as u64;
    let output = d.create_buffer(&wgpu::BufferDescriptor {
        label: Some("fur-results"),
        size,
        usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
        mapped_at_creation: false,
    });
    let staging = d.create_buffer(&wgpu::BufferDescriptor {
        label: Some("fur-staging"),
        size,
        usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    });
    let bind = d.create_bind_group(&wgpu::BindGroupDescriptor {
        label: None,
        layout: &pipeline.get_bind_group_layout(0),
        entries: &table
            .map(|(binding, buffer)| wgpu::BindGroupEntry {
                binding,
                resource: buffer.as_entire_binding(),
            })
            .into_iter()
            .chain([
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: input.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 2,
                    resource: output.as_entire_binding(),
                },
            ])
            .collect::<Vec<_>>(),
    });
    let mut enc = d.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: None });
    {
        let mut pass = enc.begin_compute_pass(&wgpu::ComputePassDescriptor {
            label: None,
            timestamp_writes: None,
        });
        pass.set_pipeline(pipeline);
        pass.set_bind_group(0, &bind, &[]);
        // 64 invocations per workgroup; n ≤ MAX_DISPATCH keeps it within one dimension.
        pass.dispatch_workgroups(n.div_ceil(64) as u32, 1, 1);
    }
    enc.copy_buffer_to_buffer(&output, 0, &staging, 0, size);
    queue.submit([enc.finish()]);
    let slice = staging.slice(..);
    let (tx, rx) = std::sync::mpsc::channel();
    slice.map_async(wgpu::MapMode::Read, move |r| {
        let _ = tx.send(r);
    });
    d.poll(wgpu::PollType::wait_indefinitely())
        .map_err(|e| GpuError::Readback(e.to_string()))?;
    rx.recv()
        .map_err(|e| GpuError::Readback(e.to_string()))?
        .map_err(|e| GpuError::Readback(e.to_string()))?;
    let data = slice
        .get_mapped_range()
        .map_err(|e| GpuError::Readback(e.to_string()))?;
    let out = data
        .chunks_exact(RESULT_FLOATS * 4)
        .map(|r| {
            let mut v = [0.0f32; RESULT_FLOATS];
            for (o, b) in v.iter_mut().zip(r.chunks_exact(4)) {
                *o = f32::from_le_bytes([b[0], b[1], b[2], b[3]]);
            }
            v
        })
        .collect();
    drop(data);
    staging.unmap();
    Ok(out)
}

fn buffer_init(
    device: &wgpu::Device,
    label: &str,
    contents: &[u8],
    usage: wgpu::BufferUsages,
) -> wgpu::Buffer {
    use wgpu::util::DeviceExt;
    device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: Some(label),
        contents,
        usage,
    })
}

/// The bytes of a slice of plain numbers (u32 words, f32 quadruples).
fn as_bytes<T: bytemuck::Pod>(v: &[T]) -> &[u8] {
    bytemuck::cast_slice(v)
}
