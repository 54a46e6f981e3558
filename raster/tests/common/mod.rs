//! What the raster tests share: a WGSL expression evaluated over pairs of numbers on a real
//! Vulkan device. Without an adapter it prints "skipped: no GPU adapter" and returns `None`,
//! unless `FUR_BCSDF_REQUIRE_GPU=1` (set by `.ci/run`), which makes it panic.

/// A compute entry point evaluating the WGSL expression `call` (of `q`, one pair) over pairs,
/// bound beside the shader's own bindings.
fn entry(call: &str) -> String {
    format!(
        r#"
@group(0) @binding(10) var<storage, read> ras_test_in: array<vec2<f32>>;
@group(0) @binding(11) var<storage, read_write> ras_test_out: array<f32>;

@compute @workgroup_size(64)
fn ras_test_call(@builtin(global_invocation_id) id: vec3<u32>) {{
    if (id.x < arrayLength(&ras_test_in)) {{
        let q = ras_test_in[id.x];
        ras_test_out[id.x] = {call};
    }}
}}
"#
    )
}

/// The WGSL expression `call` (of `q: vec2<f32>`) compiled after `wgsl` and evaluated at every
/// pair, or `None` (after printing why) without an adapter.
pub fn gpu_call(wgsl: &str, call: &str, pairs: &[[f32; 2]]) -> Option<Vec<f32>> {
    use wgpu::util::DeviceExt;
    let instance = wgpu::Instance::new(wgpu::InstanceDescriptor::new_without_display_handle());
    let adapter = match pollster::block_on(instance.request_adapter(&Default::default())) {
        Ok(a) => a,
        Err(e) => {
            if std::env::var("FUR_BCSDF_REQUIRE_GPU").as_deref() == Ok("1") {
                panic!("FUR_BCSDF_REQUIRE_GPU=1 but no adapter: {e}");
            }
            println!("skipped: no GPU adapter ({e})");
            return None;
        }
    };
    let (device, queue) =
        pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor::default())).unwrap();
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("raster test"),
        source: wgpu::ShaderSource::Wgsl(format!("{wgsl}\n{}", entry(call)).into()),
    });
    let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
        label: Some("ras_test_call"),
        layout: None,
        module: &module,
        entry_point: Some("ras_test_call"),
        compilation_options: Default::default(),
        cache: None,
    });
    let input = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: Some("pairs"),
        contents: bytemuck::cast_slice(pairs),
        usage: wgpu::BufferUsages::STORAGE,
    });
    let size = (pairs.len() * 4) as u64;
    let output = device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("out"),
        size,
        usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
        mapped_at_creation: false,
    });
    let staging = device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("staging"),
        size,
        usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    });
    let bind = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: None,
        layout: &pipeline.get_bind_group_layout(0),
        entries: &[
            wgpu::BindGroupEntry {
                binding: 10,
                resource: input.as_entire_binding(),
            },
            wgpu::BindGroupEntry {
                binding: 11,
                resource: output.as_entire_binding(),
            },
        ],
    });
    let mut enc = device.create_command_encoder(&Default::default());
    {
        let mut pass = enc.begin_compute_pass(&Default::default());
        pass.set_pipeline(&pipeline);
        pass.set_bind_group(0, &bind, &[]);
        pass.dispatch_workgroups(pairs.len().div_ceil(64) as u32, 1, 1);
    }
    enc.copy_buffer_to_buffer(&output, 0, &staging, 0, size);
    queue.submit([enc.finish()]);
    let slice = staging.slice(..);
    slice.map_async(wgpu::MapMode::Read, |r| r.unwrap());
    device.poll(wgpu::PollType::wait_indefinitely()).unwrap();
    let data = slice.get_mapped_range().unwrap();
    let out = bytemuck::cast_slice::<u8, f32>(&data).to_vec();
    drop(data);
    staging.unmap();
    Some(out)
}
