//! # raster
//!
//! Fur in a real-time pipeline: the `render` crate's scenes drawn by a headless wgpu
//! vertex/fragment pipeline, the fibers as camera-facing ribbons, the fragment shader calling
//! the shared WGSL evaluator (`bcsdf_core::shader::FUR_BCSDF_WGSL`: `fur_eval_far_dirs` and
//! the dual-scattering term `fur_eval_dual_dirs`, docs/model.md §13), the fiber counts from a
//! deep opacity map (Yuksel and Keyser 2008) rendered from the key light. docs/engines.md
//! says what an engine binds and supplies; docs/model.md §13 "Deep opacity map" gives the
//! method and its parameters.
//!
//! - [`Strands::from_scene`]: the scene's fiber segments as ribbon instances (colour and skin
//!   normal per strand, the coat above each end from [`coat::coat_counts`]), its surfaces
//!   as triangles, its key light and sky;
//! - [`albedo_table`]: the fiber's directional albedo per θ_r, for the sky and floor light;
//! - [`Raster`]: the device and pipelines; [`Raster::draw`] renders one [`Frame`] (RGB
//!   radiance and the fur's coverage, per-pass times);
//! - [`fragment_instructions`]: the fur fragment shader's SPIR-V instruction count.

#![deny(missing_docs)]

use bcsdf_core::shader::FUR_BCSDF_WGSL;
use bcsdf_core::Bcsdf;
use nalgebra::{Matrix4, Vector3};
use render::light::LightShape;
use render::scene::Scene;
use render::surface::{orthonormal_basis, Shape};
use std::fmt;
use std::time::Instant;

pub mod coat;
mod gpu;

pub use gpu::{Raster, PASS_NAMES};

/// The raster shader (ribbons, the deep opacity map, shading), appended to
/// [`FUR_BCSDF_WGSL`] by [`shader_source`].
pub const RASTER_WGSL: &str = include_str!("raster.wgsl");

/// The fur fragment shader's entry point.
pub const FUR_FRAGMENT: &str = "ras_fiber_shade";

/// The whole WGSL module the pipelines compile: the shared evaluator, then the raster passes.
#[must_use]
pub fn shader_source() -> String {
    format!("{FUR_BCSDF_WGSL}\n{RASTER_WGSL}")
}

/// Why a frame could not be drawn.
#[derive(Debug)]
pub enum RasterError {
    /// No adapter: no GPU and no software Vulkan driver (Debian: `mesa-vulkan-drivers`,
    /// `libvulkan1`).
    NoAdapter(String),
    /// The adapter refused a device.
    Device(String),
    /// Bad settings or data (sizes, blobs, a scene without a key light).
    Input(String),
    /// Reading the image back failed.
    Readback(String),
}

impl fmt::Display for RasterError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            RasterError::NoAdapter(e) => write!(
                f,
                "no GPU adapter ({e}); without a GPU, install Mesa's software Vulkan driver \
                 (Debian: apt-get install mesa-vulkan-drivers libvulkan1)"
            ),
            RasterError::Device(e) => write!(f, "the GPU adapter refused a device: {e}"),
            RasterError::Input(e) => f.write_str(e),
            RasterError::Readback(e) => write!(f, "reading the image back failed: {e}"),
        }
    }
}

impl std::error::Error for RasterError {}

/// The deep opacity map's and the frame's settings (docs/model.md §13 "Deep opacity map").
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Settings {
    /// Image width in pixels.
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
    /// The side of the light's maps (shadow map, first-fiber depth, layers), in texels.
    pub map_size: u32,
    /// Where deep opacity layers 0, 1 and 2 end behind the first fiber a light ray meets
    /// (world units, increasing); layer 3 holds every fiber beyond.
    pub layer_ends: [f32; 3],
    /// How far toward the light a fur fragment reads its fiber count, in its fiber's radii
    /// (so that its own fiber is not counted in front of it).
    pub bias_radii: f32,
    /// How far a surface point's shadow test looks past it (world units).
    pub shadow_bias: f32,
    /// The dual-scattering density factors d_f, d_b (docs/model.md §13).
    pub density: [f32; 2],
    /// What the fur fragments write.
    pub output: Output,
}

/// What the fur fragments write into the image's RGB.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Output {
    /// Radiance (the image).
    Radiance,
    /// The deep opacity map's fiber counts at the fragment: between it and the key light (R;
    /// −1 where a surface shadows the fragment), below it (G), along the whole light ray
    /// (B); the tests and `raster --compare`'s breakdown read them.
    Counts,
}

/// The largest image side and light-map side accepted (the adapter may allow less).
pub const MAX_SIDE: u32 = 8192;

impl Settings {
    /// The defaults for a `width` × `height` image: a 2048² light map, layers ending 0.02,
    /// 0.06 and 0.15 behind the first fiber, a bias of one radius, the term's default density
    /// factors (`bcsdf_core::dual::Density::DEFAULT`).
    #[must_use]
    pub fn new(width: u32, height: u32) -> Settings {
        Settings {
            width,
            height,
            map_size: 2048,
            layer_ends: [0.02, 0.06, 0.15],
            bias_radii: 1.0,
            shadow_bias: 0.01,
            density: [
                bcsdf_core::dual::Density::DEFAULT.d_f,
                bcsdf_core::dual::Density::DEFAULT.d_b,
            ],
            output: Output::Radiance,
        }
    }

    /// One message for the first setting out of range.
    ///
    /// # Errors
    /// [`RasterError::Input`] naming the setting.
    pub fn validate(&self) -> Result<(), RasterError> {
        let bad = |m: String| Err(RasterError::Input(m));
        for (name, v) in [
            ("width", self.width),
            ("height", self.height),
            ("light map size", self.map_size),
        ] {
            if v == 0 || v > MAX_SIDE {
                return bad(format!("{name} {v} must be 1 to {MAX_SIDE}"));
            }
        }
        let [a, b, c] = self.layer_ends;
        if !(a > 0.0 && b > a && c > b && c.is_finite()) {
            return bad(format!(
                "layer ends {a}, {b}, {c} must be positive, finite and increasing"
            ));
        }
        if !(self.bias_radii.is_finite() && self.bias_radii >= 0.0) {
            return bad(format!("bias {} must be finite and >= 0", self.bias_radii));
        }
        if !(self.shadow_bias.is_finite() && self.shadow_bias >= 0.0) {
            return bad(format!(
                "shadow bias {} must be finite and >= 0",
                self.shadow_bias
            ));
        }
        for d in self.density {
            if !(d.is_finite() && (0.0..=bcsdf_core::dual::MAX_DENSITY).contains(&d)) {
                return bad(format!(
                    "density factor {d} must be 0 to {}",
                    bcsdf_core::dual::MAX_DENSITY
                ));
            }
        }
        Ok(())
    }
}

/// One fiber segment as the shader's instance: (p0, r0), (p1, r1), (σ_ca RGB, 0), (the skin
/// normal under it, the whole coat's count along it at the strand's root), and the coat
/// above both ends ([`coat::coat_counts`]: above and across at p0, then at p1).
pub type Instance = [[f32; 4]; 5];

/// One surface vertex: position, normal, albedo.
pub type Vertex = [[f32; 3]; 3];

/// What the raster pipeline draws of a scene: fibers, surfaces, lights, camera.
pub struct Strands {
    /// One instance per fiber segment.
    pub instances: Vec<Instance>,
    /// The surfaces as a triangle list.
    pub triangles: Vec<Vertex>,
    /// Unit vector toward the key light and its irradiance (the scene's first distant light).
    pub key: (Vector3<f32>, [f32; 3]),
    /// The uniform sky's radiance (the sum of the scene's uniform lights).
    pub sky: [f32; 3],
    /// The floor (a square, normal +y): centre, half side, albedo; `None` without one.
    pub floor: Option<(Vector3<f32>, f32, [f32; 3])>,
    /// The albedo of the skin, the surface nearest the first strand's root (black without
    /// surfaces).
    pub skin_albedo: [f32; 3],
    /// The number of fibers (strands).
    pub strands: usize,
    /// World to camera clip space (column-major), for the image's aspect.
    pub view_proj: Matrix4<f32>,
    /// Eye position.
    pub eye: Vector3<f32>,
    /// World to the light's orthographic clip space, and the world depth of its z range.
    pub light_proj: (Matrix4<f32>, f32),
    /// The world size of the light map (its side).
    pub light_extent: f32,
}

/// Half the side of the quad that stands for an endless floor.
const ENDLESS: f32 = 400.0;

/// Far plane of the camera.
const FAR: f32 = 1000.0;

/// Near plane of the camera.
const NEAR: f32 = 0.05;

impl Strands {
    /// The scene's fibers (every strand coloured `sigma_ca`), surfaces, key light, sky and
    /// camera for a `width` × `height` image.
    ///
    /// # Errors
    /// [`RasterError::Input`] for a scene without a distant light (the deep opacity map is
    /// rendered from it).
    pub fn from_scene(
        scene: &Scene,
        sigma_ca: [f32; 3],
        width: u32,
        height: u32,
    ) -> Result<Strands, RasterError> {
        let mut key = None;
        let mut sky = [0.0f32; 3];
        for s in scene.lights.shapes() {
            match s {
                LightShape::Distant { axis, irradiance } if key.is_none() => {
                    key = Some((axis, irradiance));
                }
                LightShape::Distant { .. } => {}
                LightShape::Uniform { radiance } => {
                    for c in 0..3 {
                        sky[c] += radiance[c];
                    }
                }
            }
        }
        let key = key.ok_or_else(|| {
            RasterError::Input("the scene has no distant light to cast the deep opacity map".into())
        })?;
        let segs = scene.fibers.segments();
        // The surface nearest a point: its normal there and its albedo.
        let skin_at = |p: &Vector3<f32>| -> (Vector3<f32>, [f32; 3]) {
            let mut best = (f32::INFINITY, Vector3::y(), [0.0; 3]);
            for s in &scene.surfaces {
                let (d, n) = match s.shape {
                    Shape::Sphere { center, radius } => {
                        let v = p - center;
                        ((v.norm() - radius).abs(), v.normalize())
                    }
                    Shape::Square { center, .. } => ((p.y - center.y).abs(), Vector3::y()),
                };
                if d < best.0 {
                    best = (d, n, s.albedo);
                }
            }
            (best.1, best.2)
        };
        let [r, g, b] = sigma_ca;
        let normals: Vec<Vector3<f32>> = segs.iter().map(|s| skin_at(&s.p0).0).collect();
        let skin_albedo = segs.first().map_or([0.0; 3], |s| skin_at(&s.p0).1);
        let coat = coat::coat_counts(scene, &normals);
        // The whole coat's count at each strand's root: `above` at its root segment's p0.
        let fibers = segs.iter().map(|s| s.fiber as usize + 1).max().unwrap_or(0);
        let mut root = vec![0.0f32; fibers];
        for (s, c) in segs.iter().zip(&coat).filter(|(s, _)| s.v0 == 0.0) {
            root[s.fiber as usize] = c[0];
        }
        let instances = segs
            .iter()
            .zip(&normals)
            .zip(&coat)
            .map(|((s, n), coat)| {
                [
                    [s.p0.x, s.p0.y, s.p0.z, s.r0],
                    [s.p1.x, s.p1.y, s.p1.z, s.r1],
                    [r, g, b, 0.0],
                    [n.x, n.y, n.z, root[s.fiber as usize]],
                    *coat,
                ]
            })
            .collect();
        let mut strands: Vec<u32> = segs.iter().map(|s| s.fiber).collect();
        strands.sort_unstable();
        strands.dedup();
        let mut triangles = Vec::new();
        let mut floor = None;
        for s in &scene.surfaces {
            match s.shape {
                Shape::Sphere { center, radius } => {
                    sphere(center, radius, s.albedo, &mut triangles)
                }
                Shape::Square { center, half } => {
                    let h = half.min(ENDLESS);
                    let c = |dx: f32, dz: f32| {
                        [
                            [center.x + dx * h, center.y, center.z + dz * h],
                            [0.0, 1.0, 0.0],
                            s.albedo,
                        ]
                    };
                    triangles.extend([
                        c(-1.0, -1.0),
                        c(1.0, -1.0),
                        c(1.0, 1.0),
                        c(-1.0, -1.0),
                        c(1.0, 1.0),
                        c(-1.0, 1.0),
                    ]);
                    if floor.is_none() {
                        floor = Some((center, h, s.albedo));
                    }
                }
            }
        }
        let light = light_frame(scene, key.0);
        Ok(Strands {
            instances,
            triangles,
            key,
            sky,
            floor,
            skin_albedo,
            strands: strands.len(),
            view_proj: view_proj(&scene.camera, width, height),
            eye: scene.camera.eye(),
            light_proj: (light.0, light.1),
            light_extent: light.2,
        })
    }
}

/// A UV sphere of 64 × 128 quads, outward normals.
fn sphere(center: Vector3<f32>, radius: f32, albedo: [f32; 3], out: &mut Vec<Vertex>) {
    let (rows, cols) = (64u32, 128u32);
    let at = |i: u32, j: u32| {
        let th = std::f32::consts::PI * i as f32 / rows as f32;
        let ph = std::f32::consts::TAU * j as f32 / cols as f32;
        let n = Vector3::new(th.sin() * ph.cos(), th.cos(), th.sin() * ph.sin());
        let p = center + n * radius;
        [[p.x, p.y, p.z], [n.x, n.y, n.z], albedo]
    };
    for i in 0..rows {
        for j in 0..cols {
            let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
            out.extend([a, b, c, a, c, d]);
        }
    }
}

/// World to camera clip space (wgpu's: y up, z in [0, 1]) of the render crate's pinhole
/// camera, so that pixel (x, y) sees what `Camera::ray(x, y, ..)` does.
fn view_proj(camera: &render::camera::Camera, width: u32, height: u32) -> Matrix4<f32> {
    let [f, r, u] = camera.basis();
    let eye = camera.eye();
    let t = camera.tan_half_fov();
    let aspect = width as f32 / height as f32;
    let k = FAR / (FAR - NEAR);
    let (sx, sy) = (1.0 / (t * aspect), 1.0 / t);
    Matrix4::new(
        r.x * sx,
        r.y * sx,
        r.z * sx,
        -r.dot(&eye) * sx,
        u.x * sy,
        u.y * sy,
        u.z * sy,
        -u.dot(&eye) * sy,
        f.x * k,
        f.y * k,
        f.z * k,
        -k * (f.dot(&eye) + NEAR),
        f.x,
        f.y,
        f.z,
        -f.dot(&eye),
    )
}

/// How far the light's depth range reaches past the scene's lowest point (for the floor).
const DEPTH_MARGIN: f32 = 10.0;

/// The light's orthographic projection around the fibers and the finite surfaces: a square
/// map (same texel size in x and y); z is the depth from the light over the scene's depth
/// plus [`DEPTH_MARGIN`] (an endless floor is clipped beyond it). Returns the matrix, the
/// world depth of z's range and the map's side in world units.
fn light_frame(scene: &Scene, axis: Vector3<f32>) -> (Matrix4<f32>, f32, f32) {
    let (x, y) = orthonormal_basis(&axis);
    let mut lo = Vector3::repeat(f32::INFINITY);
    let mut hi = Vector3::repeat(f32::NEG_INFINITY);
    let mut add = |p: Vector3<f32>, pad: f32| {
        let q = Vector3::new(p.dot(&x), p.dot(&y), p.dot(&axis));
        lo = lo.inf(&(q - Vector3::repeat(pad)));
        hi = hi.sup(&(q + Vector3::repeat(pad)));
    };
    for s in scene.fibers.segments() {
        add(s.p0, s.r0);
        add(s.p1, s.r1);
    }
    for s in &scene.surfaces {
        match s.shape {
            Shape::Sphere { center, radius } => add(center, radius),
            Shape::Square { center, half } if half.is_finite() => {
                for (dx, dz) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
                    add(center + Vector3::new(dx * half, 0.0, dz * half), 0.0);
                }
            }
            Shape::Square { .. } => {}
        }
    }
    let margin = 0.02 * (hi - lo).xy().norm().max(1e-3);
    let half = 0.5 * (hi.x - lo.x).max(hi.y - lo.y) + margin;
    let (cx, cy) = (0.5 * (hi.x + lo.x), 0.5 * (hi.y + lo.y));
    let top = hi.z + margin;
    let range = hi.z - lo.z + 2.0 * margin + DEPTH_MARGIN;
    let m = Matrix4::new(
        x.x / half,
        x.y / half,
        x.z / half,
        -cx / half,
        y.x / half,
        y.y / half,
        y.z / half,
        -cy / half,
        -axis.x / range,
        -axis.y / range,
        -axis.z / range,
        top / range,
        0.0,
        0.0,
        0.0,
        1.0,
    );
    (m, range, 2.0 * half)
}

/// Nodes of [`albedo_table`] over θ_r.
pub const ALBEDO_NODES: usize = 32;

/// The directional albedo ρ(θ_r) = ∫ S cos θ_i dω_i of `bcsdf` (RGB) at [`ALBEDO_NODES`]
/// centred θ_r nodes over [−π/2, π/2], as the mean of its importance samples' weights
/// (16³ stratified samples per node): what the fragment shader scales the sky and floor
/// light by.
#[must_use]
pub fn albedo_table<B: Bcsdf>(bcsdf: &B) -> Vec<[f32; 4]> {
    const STRATA: u32 = 16;
    (0..ALBEDO_NODES)
        .map(|k| {
            let theta_r = -std::f32::consts::FRAC_PI_2
                + (k as f32 + 0.5) * std::f32::consts::PI / ALBEDO_NODES as f32;
            let mut sum = [0.0f64; 3];
            let u = |i: u32| (i as f32 + 0.5) / STRATA as f32;
            for i in 0..STRATA {
                for j in 0..STRATA {
                    for l in 0..STRATA {
                        if let Some(s) = bcsdf.sample(theta_r, [u(i), u(j), u(l)]) {
                            for (acc, w) in sum.iter_mut().zip(s.weight.0) {
                                *acc += f64::from(w);
                            }
                        }
                    }
                }
            }
            let n = f64::from(STRATA.pow(3));
            [
                (sum[0] / n) as f32,
                (sum[1] / n) as f32,
                (sum[2] / n) as f32,
                0.0,
            ]
        })
        .collect()
}

/// What one pass of a frame cost.
#[derive(Clone, Debug, PartialEq)]
pub struct PassTime {
    /// The pass: `shadow`, `dom_depth`, `dom_layers`, `surfaces`, `fur`, `readback`.
    pub name: &'static str,
    /// Wall time from submission to completion (the pass alone in its submission), ms.
    pub wall_ms: f64,
    /// The GPU's own timestamps around the pass, ms (adapters with timestamp queries).
    pub gpu_ms: Option<f64>,
}

/// One rendered frame.
#[derive(Clone, Debug)]
pub struct Frame {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Linear RGB radiance and the fur's coverage of each pixel (A), rows top to bottom.
    pub rgba: Vec<[f32; 4]>,
    /// Per-pass costs, in the order they ran.
    pub passes: Vec<PassTime>,
}

impl Frame {
    /// The radiance as the render crate's image (zero variance), for its EXR/PNG writers and
    /// the comparison metrics.
    #[must_use]
    pub fn image(&self) -> render::Image {
        render::Image {
            width: self.width,
            height: self.height,
            mean: self.rgba.iter().map(|p| [p[0], p[1], p[2]]).collect(),
            variance: vec![[0.0; 3]; self.rgba.len()],
        }
    }

    /// The coverage channel.
    #[must_use]
    pub fn coverage(&self) -> Vec<f32> {
        self.rgba.iter().map(|p| p[3]).collect()
    }

    /// The frame's wall time over its passes, ms.
    #[must_use]
    pub fn wall_ms(&self) -> f64 {
        self.passes.iter().map(|p| p.wall_ms).sum()
    }
}

/// The SPIR-V instruction count of the fur fragment shader ([`FUR_FRAGMENT`] and every
/// function it calls), as naga writes it from [`shader_source`] (no optimisation), and the
/// SPIR-V words themselves (for spirv-tools).
///
/// # Errors
/// A message when naga cannot parse, validate or translate the module.
pub fn fragment_instructions() -> Result<(usize, Vec<u32>), String> {
    let src = shader_source();
    let module = naga::front::wgsl::parse_str(&src).map_err(|e| e.emit_to_string(&src))?;
    let info = naga::valid::Validator::new(
        naga::valid::ValidationFlags::all(),
        naga::valid::Capabilities::all(),
    )
    .validate(&module)
    .map_err(|e| format!("{e:?}"))?;
    let options = naga::back::spv::Options::default();
    let pipeline = naga::back::spv::PipelineOptions {
        shader_stage: naga::ShaderStage::Fragment,
        entry_point: FUR_FRAGMENT.into(),
    };
    let words = naga::back::spv::write_vec(&module, &info, &options, Some(&pipeline))
        .map_err(|e| e.to_string())?;
    Ok((spirv_instructions(&words)?, words))
}

/// The number of instructions in a SPIR-V module: after the header of five words, each
/// instruction's first word holds its word count in the high 16 bits.
///
/// # Errors
/// A message for a truncated module or an instruction of zero words.
pub fn spirv_instructions(words: &[u32]) -> Result<usize, String> {
    let (mut at, mut count) = (5usize, 0usize);
    while at < words.len() {
        let n = (words[at] >> 16) as usize;
        if n == 0 {
            return Err("malformed SPIR-V: an instruction of zero words".into());
        }
        at += n;
        count += 1;
    }
    if at != words.len() {
        return Err("malformed SPIR-V: the last instruction is cut off".into());
    }
    Ok(count)
}

/// Milliseconds since `t`.
fn ms_since(t: Instant) -> f64 {
    t.elapsed().as_secs_f64() * 1e3
}
