//! One frame: the passes in order, each submitted and waited for (docs/engines.md "Call
//! order"), the readback and the frame uniform.

use super::*;

impl Raster {
    /// Renders one frame of `strands` with the LUT `lut` (a `.furlut`), the dual-scattering
    /// tables `dual` (a `.furdual` blob) and the fiber's albedo table (`crate::albedo_table`),
    /// each pass submitted on its own and waited for (its wall time).
    ///
    /// # Errors
    /// [`RasterError::Input`] for bad settings, an invalid LUT or blob, or a map larger than
    /// the adapter allows; [`RasterError::Readback`] when the image cannot be read back.
    pub fn draw(
        &self,
        strands: &Strands,
        lut: &[u8],
        dual: &[u8],
        albedo: &[[f32; 4]],
        settings: &Settings,
    ) -> Result<Frame, RasterError> {
        settings.validate()?;
        BakedBcsdf::from_bytes(lut).map_err(|e| RasterError::Input(format!("the LUT: {e}")))?;
        let mut check = Box::new(DualLut::EMPTY);
        check
            .decode(dual)
            .map_err(|e| RasterError::Input(format!("the dual-scattering tables: {e}")))?;
        if albedo.len() < 2 {
            return Err(RasterError::Input(
                "the albedo table needs two nodes".into(),
            ));
        }
        let limit = self.device.limits().max_texture_dimension_2d;
        for (what, v) in [
            ("width", settings.width),
            ("height", settings.height),
            ("light map size", settings.map_size),
        ] {
            if v > limit {
                return Err(RasterError::Input(format!(
                    "{what} {v} is more than the adapter's {limit}"
                )));
            }
        }
        let d = &self.device;
        let buffer = |label: &str, bytes: &[u8], usage| {
            d.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some(label),
                contents: bytes,
                usage,
            })
        };
        let storage = wgpu::BufferUsages::STORAGE;
        let lut_buf = buffer("fur-lut", &words(lut), storage);
        let dual_buf = buffer("fur-dual", &words(dual), storage);
        let albedo_buf = buffer("albedo", bytemuck::cast_slice(albedo), storage);
        let instances = buffer(
            "segments",
            bytemuck::cast_slice(&strands.instances),
            wgpu::BufferUsages::VERTEX,
        );
        let mut tri: Vec<[[f32; 3]; 3]> = strands.triangles.clone();
        if tri.is_empty() {
            tri.push([[0.0; 3]; 3]);
        }
        let triangles = buffer(
            "surfaces",
            bytemuck::cast_slice(&tri),
            wgpu::BufferUsages::VERTEX,
        );
        let uniform = buffer(
            "frame",
            bytemuck::cast_slice(&frame_uniform(strands, settings)),
            wgpu::BufferUsages::UNIFORM,
        );
        let texture = |label: &str, size: (u32, u32), format, samples, usage| {
            d.create_texture(&wgpu::TextureDescriptor {
                label: Some(label),
                size: wgpu::Extent3d {
                    width: size.0,
                    height: size.1,
                    depth_or_array_layers: 1,
                },
                mip_level_count: 1,
                sample_count: samples,
                dimension: wgpu::TextureDimension::D2,
                format,
                usage,
                view_formats: &[],
            })
            .create_view(&Default::default())
        };
        let attach = wgpu::TextureUsages::RENDER_ATTACHMENT;
        let bind = wgpu::TextureUsages::TEXTURE_BINDING;
        let map = (settings.map_size, settings.map_size);
        let image = (settings.width, settings.height);
        let shadow = texture("shadow map", map, DEPTH, 1, attach | bind);
        let first = texture("first fiber", map, DEPTH, 1, attach | bind);
        let layers = texture("layers", map, LAYERS, 1, attach | bind);
        let msaa = texture("image msaa", image, COLOUR, SAMPLES, attach);
        let depth = texture("image depth", image, DEPTH, SAMPLES, attach);
        let resolved_tex = d.create_texture(&wgpu::TextureDescriptor {
            label: Some("image"),
            size: wgpu::Extent3d {
                width: image.0,
                height: image.1,
                depth_or_array_layers: 1,
            },
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: COLOUR,
            usage: attach | wgpu::TextureUsages::COPY_SRC,
            view_formats: &[],
        });
        let resolved = resolved_tex.create_view(&Default::default());
        let group = |layout: &wgpu::BindGroupLayout, entries: &[wgpu::BindGroupEntry<'_>]| {
            d.create_bind_group(&wgpu::BindGroupDescriptor {
                label: None,
                layout,
                entries,
            })
        };
        let entry = |binding, resource| wgpu::BindGroupEntry { binding, resource };
        let fur_group = group(
            &self.fur_layout,
            &[
                entry(0, lut_buf.as_entire_binding()),
                entry(3, dual_buf.as_entire_binding()),
            ],
        );
        let light_group = group(&self.light_layout, &[entry(0, uniform.as_entire_binding())]);
        let layers_group = group(
            &self.layers_layout,
            &[
                entry(0, uniform.as_entire_binding()),
                entry(1, wgpu::BindingResource::TextureView(&shadow)),
                entry(2, wgpu::BindingResource::TextureView(&first)),
            ],
        );
        let frame_group = group(
            &self.frame_layout,
            &[
                entry(0, uniform.as_entire_binding()),
                entry(1, wgpu::BindingResource::TextureView(&shadow)),
                entry(2, wgpu::BindingResource::TextureView(&first)),
                entry(3, wgpu::BindingResource::TextureView(&layers)),
                entry(4, albedo_buf.as_entire_binding()),
            ],
        );
        let queries = self.timestamps.then(|| {
            d.create_query_set(&wgpu::QuerySetDescriptor {
                label: Some("pass times"),
                ty: wgpu::QueryType::Timestamp,
                count: 2 * PASSES as u32,
            })
        });
        let segments = strands.instances.len() as u32;
        let surfaces = strands.triangles.len() as u32;
        let mut passes = Vec::new();
        let depth_clear = |view| wgpu::RenderPassDepthStencilAttachment {
            view,
            depth_ops: Some(wgpu::Operations {
                load: wgpu::LoadOp::Clear(1.0),
                store: wgpu::StoreOp::Store,
            }),
            stencil_ops: None,
        };
        let depth_load = |view| wgpu::RenderPassDepthStencilAttachment {
            view,
            depth_ops: Some(wgpu::Operations {
                load: wgpu::LoadOp::Load,
                store: wgpu::StoreOp::Store,
            }),
            stencil_ops: None,
        };
        let sky = strands.sky;
        let clear_sky = wgpu::Color {
            r: f64::from(sky[0]),
            g: f64::from(sky[1]),
            b: f64::from(sky[2]),
            a: 0.0,
        };
        for (k, name) in PASS_NAMES.iter().enumerate() {
            let t = Instant::now();
            let mut enc = d.create_command_encoder(&Default::default());
            {
                let stamps = queries.as_ref().map(|q| wgpu::RenderPassTimestampWrites {
                    query_set: q,
                    beginning_of_pass_write_index: Some(2 * k as u32),
                    end_of_pass_write_index: Some(2 * k as u32 + 1),
                });
                let colour = |view, resolve, load| {
                    [Some(wgpu::RenderPassColorAttachment {
                        view,
                        depth_slice: None,
                        resolve_target: resolve,
                        ops: wgpu::Operations {
                            load,
                            store: wgpu::StoreOp::Store,
                        },
                    })]
                };
                let (colours, depth_at) = match *name {
                    "shadow" => (None, Some(depth_clear(&shadow))),
                    "dom_depth" => (None, Some(depth_clear(&first))),
                    "dom_layers" => (
                        Some(colour(
                            &layers,
                            None,
                            wgpu::LoadOp::Clear(wgpu::Color::TRANSPARENT),
                        )),
                        None,
                    ),
                    "surfaces" => (
                        Some(colour(&msaa, None, wgpu::LoadOp::Clear(clear_sky))),
                        Some(depth_clear(&depth)),
                    ),
                    _ => (
                        Some(colour(&msaa, Some(&resolved), wgpu::LoadOp::Load)),
                        Some(depth_load(&depth)),
                    ),
                };
                let mut pass = enc.begin_render_pass(&wgpu::RenderPassDescriptor {
                    label: Some(name),
                    color_attachments: colours.as_ref().map_or(&[], |c| c.as_slice()),
                    depth_stencil_attachment: depth_at,
                    timestamp_writes: stamps,
                    occlusion_query_set: None,
                    multiview_mask: None,
                });
                match *name {
                    "shadow" => {
                        pass.set_pipeline(&self.shadow);
                        pass.set_bind_group(1, &light_group, &[]);
                        pass.set_vertex_buffer(0, triangles.slice(..));
                        pass.draw(0..surfaces, 0..1);
                    }
                    "dom_depth" | "dom_layers" => {
                        if *name == "dom_depth" {
                            pass.set_pipeline(&self.dom_depth);
                            pass.set_bind_group(1, &light_group, &[]);
                        } else {
                            pass.set_pipeline(&self.dom_layers);
                            pass.set_bind_group(1, &layers_group, &[]);
                        }
                        pass.set_vertex_buffer(0, instances.slice(..));
                        pass.draw(0..6, 0..segments);
                    }
                    "surfaces" => {
                        pass.set_pipeline(&self.surfaces);
                        pass.set_bind_group(0, &fur_group, &[]);
                        pass.set_bind_group(1, &frame_group, &[]);
                        pass.set_vertex_buffer(0, triangles.slice(..));
                        pass.draw(0..surfaces, 0..1);
                    }
                    _ => {
                        pass.set_pipeline(&self.fur);
                        pass.set_bind_group(0, &fur_group, &[]);
                        pass.set_bind_group(1, &frame_group, &[]);
                        pass.set_vertex_buffer(0, instances.slice(..));
                        pass.draw(0..6, 0..segments);
                    }
                }
            }
            self.queue.submit([enc.finish()]);
            self.wait()?;
            passes.push(PassTime {
                name,
                wall_ms: ms_since(t),
                gpu_ms: None,
            });
        }
        let t = Instant::now();
        let row = (image.0 * 8).div_ceil(256) * 256;
        let size = u64::from(row) * u64::from(image.1);
        let staging = d.create_buffer(&wgpu::BufferDescriptor {
            label: Some("image staging"),
            size,
            usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let stamp_bytes = 16 * PASSES as u64;
        let stamps = queries.as_ref().map(|_| {
            let resolve = d.create_buffer(&wgpu::BufferDescriptor {
                label: Some("timestamps"),
                size: stamp_bytes,
                usage: wgpu::BufferUsages::QUERY_RESOLVE | wgpu::BufferUsages::COPY_SRC,
                mapped_at_creation: false,
            });
            let read = d.create_buffer(&wgpu::BufferDescriptor {
                label: Some("timestamps staging"),
                size: stamp_bytes,
                usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            });
            (resolve, read)
        });
        let mut enc = d.create_command_encoder(&Default::default());
        enc.copy_texture_to_buffer(
            wgpu::TexelCopyTextureInfo {
                texture: &resolved_tex,
                mip_level: 0,
                origin: wgpu::Origin3d::ZERO,
                aspect: wgpu::TextureAspect::All,
            },
            wgpu::TexelCopyBufferInfo {
                buffer: &staging,
                layout: wgpu::TexelCopyBufferLayout {
                    offset: 0,
                    bytes_per_row: Some(row),
                    rows_per_image: Some(image.1),
                },
            },
            wgpu::Extent3d {
                width: image.0,
                height: image.1,
                depth_or_array_layers: 1,
            },
        );
        if let (Some(q), Some((resolve, read))) = (&queries, &stamps) {
            enc.resolve_query_set(q, 0..2 * PASSES as u32, resolve, 0);
            enc.copy_buffer_to_buffer(resolve, 0, read, 0, stamp_bytes);
        }
        self.queue.submit([enc.finish()]);
        let bytes = self.read(&staging)?;
        let mut rgba = Vec::with_capacity((image.0 * image.1) as usize);
        for y in 0..image.1 as usize {
            let line = &bytes[y * row as usize..][..image.0 as usize * 8];
            for px in line.chunks_exact(8) {
                rgba.push(core::array::from_fn(|c| {
                    half::f16::from_le_bytes([px[2 * c], px[2 * c + 1]]).to_f32()
                }));
            }
        }
        if let Some((_, read)) = &stamps {
            let b = self.read(read)?;
            let ticks: Vec<u64> = b
                .chunks_exact(8)
                .map(|w| u64::from_le_bytes(w.try_into().unwrap_or([0; 8])))
                .collect();
            let period = f64::from(self.queue.get_timestamp_period());
            for (k, p) in passes.iter_mut().enumerate() {
                let dt = ticks[2 * k + 1].wrapping_sub(ticks[2 * k]);
                p.gpu_ms = Some(dt as f64 * period * 1e-6);
            }
        }
        passes.push(PassTime {
            name: "readback",
            wall_ms: ms_since(t),
            gpu_ms: None,
        });
        Ok(Frame {
            width: image.0,
            height: image.1,
            rgba,
            passes,
        })
    }

    /// Waits for the queue to finish its work.
    fn wait(&self) -> Result<(), RasterError> {
        self.device
            .poll(wgpu::PollType::wait_indefinitely())
            .map(|_| ())
            .map_err(|e| RasterError::Readback(e.to_string()))
    }

    /// The contents of a mappable buffer, after the queue finished.
    fn read(&self, buffer: &wgpu::Buffer) -> Result<Vec<u8>, RasterError> {
        let slice = buffer.slice(..);
        let (tx, rx) = std::sync::mpsc::channel();
        slice.map_async(wgpu::MapMode::Read, move |r| {
            let _ = tx.send(r);
        });
        self.wait()?;
        rx.recv()
            .map_err(|e| RasterError::Readback(e.to_string()))?
            .map_err(|e| RasterError::Readback(e.to_string()))?;
        let data = slice
            .get_mapped_range()
            .map_err(|e| RasterError::Readback(e.to_string()))?
            .to_vec();
        buffer.unmap();
        Ok(data)
    }
}

/// The render passes of a frame, in order.
pub const PASS_NAMES: [&str; PASSES] = ["shadow", "dom_depth", "dom_layers", "surfaces", "fur"];

/// The number of render passes of a frame.
const PASSES: usize = 5;

/// The frame uniform (`RasFrame` in raster.wgsl), as floats.
fn frame_uniform(s: &Strands, settings: &Settings) -> [f32; FRAME_BYTES / 4] {
    let mut u = [0.0f32; FRAME_BYTES / 4];
    u[..16].copy_from_slice(s.view_proj.as_slice());
    u[16..32].copy_from_slice(s.light_proj.0.as_slice());
    let (axis, irradiance) = s.key;
    let map = settings.map_size as f32;
    let (floor_at, half, floor_albedo, has) = match s.floor {
        Some((c, h, a)) => (c, h, a, 1.0),
        None => (nalgebra::Vector3::zeros(), 0.0, [0.0; 3], 0.0),
    };
    let skin = s.skin_albedo;
    let rows: [[f32; 4]; 9] = [
        [s.eye.x, s.eye.y, s.eye.z, 0.0],
        [axis.x, axis.y, axis.z, s.light_proj.1],
        [irradiance[0], irradiance[1], irradiance[2], map],
        [s.sky[0], s.sky[1], s.sky[2], s.light_extent / map],
        [floor_albedo[0], floor_albedo[1], floor_albedo[2], half],
        [floor_at.x, floor_at.y, floor_at.z, has],
        [
            settings.layer_ends[0],
            settings.layer_ends[1],
            settings.layer_ends[2],
            settings.bias_radii,
        ],
        [
            settings.density[0],
            settings.density[1],
            settings.shadow_bias,
            match settings.output {
                crate::Output::Radiance => 0.0,
                crate::Output::Counts => 1.0,
            },
        ],
        [skin[0], skin[1], skin[2], 0.0],
    ];
    for (k, r) in rows.iter().enumerate() {
        u[32 + 4 * k..36 + 4 * k].copy_from_slice(r);
    }
    u
}
