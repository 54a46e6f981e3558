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

/// The two shader functions checked.
const BELOW: &str = "fur_dual_below_at_incidence";
const FORWARD: &str = "fur_dual_forward_density_at_incidence";

/// A compute entry point calling the shader's `function(x, cos)` over (x, cos) pairs, bound
/// beside the shader's own bindings.
fn entry(function: &str) -> String {
    format!(
        r#"
@group(0) @binding(10) var<storage, read> ras_test_in: array<vec2<f32>>;
@group(0) @binding(11) var<storage, read_write> ras_test_out: array<f32>;

@compute @workgroup_size(64)
fn ras_test_call(@builtin(global_invocation_id) id: vec3<u32>) {{
    if (id.x < arrayLength(&ras_test_in)) {{
        let q = ras_test_in[id.x];
        ras_test_out[id.x] = {function}(q.x, q.y);
    }}
}}
"#
    )
}

/// The shader's `function` at every pair, or `None` (after printing why) without an adapter.
fn gpu_call(wgsl: &str, function: &str, pairs: &[[f32; 2]]) -> Option<Vec<f32>> {
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
        label: Some("incidence"),
        source: wgpu::ShaderSource::Wgsl(format!("{wgsl}\n{}", entry(function)).into()),
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
    let gpu = gpu_call(FUR_BCSDF_WGSL, function, pairs)?;
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
    let wrong_gpu = gpu_call(&wrong, function, pairs).unwrap();
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
