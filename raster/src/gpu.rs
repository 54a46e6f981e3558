//! The device, the pipelines and one frame's passes (docs/engines.md "Call order").

use crate::{ms_since, shader_source, Frame, PassTime, RasterError, Settings, Strands};
use bcsdf_core::baked::BakedBcsdf;
use bcsdf_core::dual::DualLut;
use std::time::Instant;
use wgpu::util::DeviceExt;

mod frame;

pub use frame::PASS_NAMES;

/// MSAA samples of the camera pass (the fur's coverage).
const SAMPLES: u32 = 4;

/// The image's format (radiance and coverage; resolvable, blendable).
const COLOUR: wgpu::TextureFormat = wgpu::TextureFormat::Rgba16Float;

/// The deep opacity map's layers (four counts, additive blending).
const LAYERS: wgpu::TextureFormat = wgpu::TextureFormat::Rgba16Float;

/// Depth for every map and the camera.
const DEPTH: wgpu::TextureFormat = wgpu::TextureFormat::Depth32Float;

/// A headless wgpu device with the raster pipelines of [`shader_source`].
pub struct Raster {
    device: wgpu::Device,
    queue: wgpu::Queue,
    adapter: wgpu::AdapterInfo,
    timestamps: bool,
    fur_layout: wgpu::BindGroupLayout,
    light_layout: wgpu::BindGroupLayout,
    layers_layout: wgpu::BindGroupLayout,
    frame_layout: wgpu::BindGroupLayout,
    shadow: wgpu::RenderPipeline,
    dom_depth: wgpu::RenderPipeline,
    dom_layers: wgpu::RenderPipeline,
    surfaces: wgpu::RenderPipeline,
    fur: wgpu::RenderPipeline,
}

/// Bytes of the frame uniform (two matrices, nine vec4).
const FRAME_BYTES: usize = 2 * 64 + 9 * 16;

fn instance_layout() -> wgpu::VertexBufferLayout<'static> {
    const ATTRS: [wgpu::VertexAttribute; 5] = wgpu::vertex_attr_array![
        0 => Float32x4, 1 => Float32x4, 2 => Float32x4, 3 => Float32x4, 4 => Float32x4
    ];
    wgpu::VertexBufferLayout {
        array_stride: 80,
        step_mode: wgpu::VertexStepMode::Instance,
        attributes: &ATTRS,
    }
}

fn vertex_layout() -> wgpu::VertexBufferLayout<'static> {
    const ATTRS: [wgpu::VertexAttribute; 3] =
        wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32x3, 2 => Float32x3];
    wgpu::VertexBufferLayout {
        array_stride: 36,
        step_mode: wgpu::VertexStepMode::Vertex,
        attributes: &ATTRS,
    }
}

fn depth_state(write: bool) -> wgpu::DepthStencilState {
    wgpu::DepthStencilState {
        format: DEPTH,
        depth_write_enabled: Some(write),
        depth_compare: Some(wgpu::CompareFunction::Less),
        stencil: Default::default(),
        bias: Default::default(),
    }
}

fn texture_entry(binding: u32, sample_type: wgpu::TextureSampleType) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility: wgpu::ShaderStages::FRAGMENT,
        ty: wgpu::BindingType::Texture {
            sample_type,
            view_dimension: wgpu::TextureViewDimension::D2,
            multisampled: false,
        },
        count: None,
    }
}

fn storage_entry(binding: u32) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility: wgpu::ShaderStages::FRAGMENT,
        ty: wgpu::BindingType::Buffer {
            ty: wgpu::BufferBindingType::Storage { read_only: true },
            has_dynamic_offset: false,
            min_binding_size: None,
        },
        count: None,
    }
}

/// A blob as little-endian u32 words, zero-padded to a whole word (the shader's view of a
/// `.furlut` or `.furdual`).
fn words(bytes: &[u8]) -> Vec<u8> {
    let mut out = bytes.to_vec();
    out.resize(bytes.len().div_ceil(4) * 4, 0);
    out
}

impl Raster {
    /// The first adapter's device (timestamp queries enabled where the adapter has them) and
    /// the pipelines.
    ///
    /// # Errors
    /// [`RasterError::NoAdapter`] or [`RasterError::Device`] without a usable device.
    pub fn new() -> Result<Raster, RasterError> {
        let instance = wgpu::Instance::new(wgpu::InstanceDescriptor::new_without_display_handle());
        let adapter = pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions {
            power_preference: wgpu::PowerPreference::HighPerformance,
            ..Default::default()
        }))
        .map_err(|e| RasterError::NoAdapter(e.to_string()))?;
        let timestamps = adapter.features().contains(wgpu::Features::TIMESTAMP_QUERY);
        let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
            label: Some("fur-raster"),
            required_limits: adapter.limits(),
            required_features: if timestamps {
                wgpu::Features::TIMESTAMP_QUERY
            } else {
                wgpu::Features::empty()
            },
            ..Default::default()
        }))
        .map_err(|e| RasterError::Device(e.to_string()))?;
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("fur_bcsdf.wgsl + raster.wgsl"),
            source: wgpu::ShaderSource::Wgsl(shader_source().into()),
        });
        let fur_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("fur tables"),
            entries: &[storage_entry(0), storage_entry(3)],
        });
        let uniform = wgpu::BindGroupLayoutEntry {
            binding: 0,
            visibility: wgpu::ShaderStages::VERTEX | wgpu::ShaderStages::FRAGMENT,
            ty: wgpu::BindingType::Buffer {
                ty: wgpu::BufferBindingType::Uniform,
                has_dynamic_offset: false,
                min_binding_size: None,
            },
            count: None,
        };
        let light_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("light passes"),
            entries: &[uniform],
        });
        let layers_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("layer pass"),
            entries: &[
                uniform,
                texture_entry(1, wgpu::TextureSampleType::Depth),
                texture_entry(2, wgpu::TextureSampleType::Depth),
            ],
        });
        let frame_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("camera passes"),
            entries: &[
                uniform,
                texture_entry(1, wgpu::TextureSampleType::Depth),
                texture_entry(2, wgpu::TextureSampleType::Depth),
                texture_entry(3, wgpu::TextureSampleType::Float { filterable: false }),
                storage_entry(4),
            ],
        });
        let layout = |groups: &[Option<&wgpu::BindGroupLayout>]| {
            device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
                label: None,
                bind_group_layouts: groups,
                immediate_size: 0,
            })
        };
        let light_pl = layout(&[None, Some(&light_layout)]);
        let layers_pl = layout(&[None, Some(&layers_layout)]);
        let camera_pl = layout(&[Some(&fur_layout), Some(&frame_layout)]);
        let pipeline = |label: &str,
                        pl: &wgpu::PipelineLayout,
                        vs: &str,
                        buffer: wgpu::VertexBufferLayout<'static>,
                        fs: Option<(&str, wgpu::ColorTargetState)>,
                        depth: Option<wgpu::DepthStencilState>,
                        samples: u32| {
            let targets = fs.as_ref().map(|(_, t)| [Some(t.clone())]);
            device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                label: Some(label),
                layout: Some(pl),
                vertex: wgpu::VertexState {
                    module: &module,
                    entry_point: Some(vs),
                    compilation_options: Default::default(),
                    buffers: &[Some(buffer)],
                },
                primitive: wgpu::PrimitiveState::default(),
                depth_stencil: depth,
                multisample: wgpu::MultisampleState {
                    count: samples,
                    ..Default::default()
                },
                fragment: fs.as_ref().map(|(entry, _)| wgpu::FragmentState {
                    module: &module,
                    entry_point: Some(entry),
                    compilation_options: Default::default(),
                    targets: targets.as_ref().map_or(&[], |t| t.as_slice()),
                }),
                multiview_mask: None,
                cache: None,
            })
        };
        let add = wgpu::BlendComponent {
            src_factor: wgpu::BlendFactor::One,
            dst_factor: wgpu::BlendFactor::One,
            operation: wgpu::BlendOperation::Add,
        };
        let shadow = pipeline(
            "shadow",
            &light_pl,
            "ras_surface_light",
            vertex_layout(),
            None,
            Some(depth_state(true)),
            1,
        );
        let dom_depth = pipeline(
            "dom_depth",
            &light_pl,
            "ras_fiber_light",
            instance_layout(),
            None,
            Some(depth_state(true)),
            1,
        );
        let dom_layers = pipeline(
            "dom_layers",
            &layers_pl,
            "ras_fiber_light",
            instance_layout(),
            Some((
                "ras_dom_layers",
                wgpu::ColorTargetState {
                    format: LAYERS,
                    blend: Some(wgpu::BlendState {
                        color: add,
                        alpha: add,
                    }),
                    write_mask: wgpu::ColorWrites::ALL,
                },
            )),
            None,
            1,
        );
        let opaque = wgpu::ColorTargetState {
            format: COLOUR,
            blend: None,
            write_mask: wgpu::ColorWrites::ALL,
        };
        let surfaces = pipeline(
            "surfaces",
            &camera_pl,
            "ras_surface_camera",
            vertex_layout(),
            Some(("ras_surface_shade", opaque.clone())),
            Some(depth_state(true)),
            SAMPLES,
        );
        let fur = pipeline(
            "fur",
            &camera_pl,
            "ras_fiber_camera",
            instance_layout(),
            Some((crate::FUR_FRAGMENT, opaque)),
            Some(depth_state(true)),
            SAMPLES,
        );
        Ok(Raster {
            device,
            queue,
            adapter: adapter.get_info(),
            timestamps,
            fur_layout,
            light_layout,
            layers_layout,
            frame_layout,
            shadow,
            dom_depth,
            dom_layers,
            surfaces,
            fur,
        })
    }

    /// The adapter's name and type, e.g. "llvmpipe (LLVM 15.0.6, 256 bits) (Cpu)".
    #[must_use]
    pub fn adapter_name(&self) -> String {
        format!("{} ({:?})", self.adapter.name, self.adapter.device_type)
    }

    /// Whether the passes carry GPU timestamps ([`PassTime::gpu_ms`]).
    #[must_use]
    pub fn has_timestamps(&self) -> bool {
        self.timestamps
    }
}
