//! The raster pipeline on a real Vulkan device (a GPU, or Mesa's llvmpipe), small and fast:
//!
//! - the deep opacity map's fiber count between a fur fragment and the key light against the
//!   exact count along the same light ray (`render::scene::Scene::fibers_crossed`, the path
//!   tracer's `dual` count): the `ball` scene with 8000 fibers at 160 × 120 pixels, every pixel
//!   fully covered by fur whose light ray meets no surface; the mean counts agree within
//!   [`MEAN_COUNT`] and the counts averaged over blocks of 8 × 8 pixels correlate (Pearson
//!   ≥ [`CORRELATION`]);
//! - the image itself: finite, non-negative, the fur's coverage in [0, 1] and present;
//! - the image against the path tracer (`render`'s `path`, [`PATH_SPP`] samples per pixel,
//!   the same baked BCSDF) for a light and a dark preset, cat and deer: over the fur's pixels
//!   the mean luminance within [`FUR_MEAN`] and the 16 × 16 tile RMSE at most [`FUR_TILES`],
//!   `raster --compare`'s figures (docs/benchmarks.md "Raster pipeline") on a small image.
//!
//! Without an adapter the tests print "skipped: no GPU adapter" and pass, unless
//! `FUR_BCSDF_REQUIRE_GPU=1` (set by `.ci/run`), which makes a missing adapter a failure.

use bcsdf_core::baked::BakedBcsdf;
use bcsdf_core::dual::Quadrature;
use bcsdf_core::lut::LutResolution;
use bcsdf_core::{presets, Closure, FurParams, FurParamsInput};
use raster::{albedo_table, Frame, Output, Raster, RasterError, Settings, Strands};
use render::light::LightShape;
use render::scene::{HitKind, Scene};
use render::{compare, integrator, scatter, scenes, Method, SceneKind, SceneOptions};

/// Largest relative difference of the mean counts (raster against exact).
const MEAN_COUNT: f64 = 0.05;

/// Smallest correlation of the mean counts per block of [`BLOCK`] × [`BLOCK`] pixels (a
/// pixel's count is one ray's integer against a texel's mean; blocks average both).
const CORRELATION: f64 = 0.7;

/// The side of the blocks of the correlation, in pixels.
const BLOCK: u32 = 8;

/// Largest relative difference of the fur's mean luminance from the path tracer's.
const FUR_MEAN: f64 = 0.10;

/// Largest tile RMSE over the fur (relative to its mean tile luminance).
const FUR_TILES: f64 = 0.25;

/// The path tracer's samples per pixel.
const PATH_SPP: u32 = 16;

const WIDTH: u32 = 160;
const HEIGHT: u32 = 120;

/// The device, or None (after printing why) without an adapter unless
/// `FUR_BCSDF_REQUIRE_GPU=1`.
fn or_skip(made: Result<Raster, RasterError>) -> Option<Raster> {
    match made {
        Ok(g) => Some(g),
        Err(e @ RasterError::NoAdapter(_)) => {
            if std::env::var("FUR_BCSDF_REQUIRE_GPU").as_deref() == Ok("1") {
                panic!("FUR_BCSDF_REQUIRE_GPU=1 but {e}");
            }
            println!("skipped: no GPU adapter ({e})");
            None
        }
        Err(e) => panic!("{e}"),
    }
}

/// `model`'s LUT at the fewest absorption nodes, and its dual-scattering blob at a 32 × 16
/// quadrature (`bake::pipeline::dual_blob`, paired with the LUT).
fn small_lut_and_blob(
    model: &bake::profiles::OwnedModel,
    input: &FurParamsInput,
) -> (Vec<u8>, Vec<u8>) {
    let res = LutResolution {
        n_abs: bcsdf_core::lut::MIN_ABSORPTION_NODES,
        ..LutResolution::DEFAULT
    };
    let lut = bake::tables::bake(model, input, res);
    let baked = BakedBcsdf::from_bytes(&lut).unwrap();
    let quadrature = Quadrature {
        theta_steps: 32,
        phi_steps: 16,
    };
    let blob = bake::pipeline::dual_blob(&lut, &baked, quadrature).to_vec();
    (lut, blob)
}

/// Human hair's LUT and blob ([`small_lut_and_blob`]; no medulla, reported closure: no
/// profiles or residual to generate).
fn lut_and_blob() -> (Vec<u8>, Vec<u8>) {
    let input = FurParamsInput {
        closure: Closure::Report,
        ..presets::find("human-hair").unwrap().input
    };
    let model = bake::profiles::OwnedModel::new(FurParams::new(&input).unwrap(), None).unwrap();
    small_lut_and_blob(&model, &input)
}

fn scene() -> Scene {
    scenes::build(&SceneOptions {
        kind: SceneKind::Ball,
        fibers: Some(8000),
        seed: 3,
        aspect: WIDTH as f32 / HEIGHT as f32,
    })
}

fn draw(gpu: &Raster, scene: &Scene, output: Output) -> Frame {
    let (lut, blob) = lut_and_blob();
    let baked = BakedBcsdf::from_bytes(&lut).unwrap();
    let strands = Strands::from_scene(scene, baked.absorption().sigma().0, WIDTH, HEIGHT).unwrap();
    let settings = Settings {
        map_size: 1024,
        output,
        ..Settings::new(WIDTH, HEIGHT)
    };
    gpu.draw(&strands, &lut, &blob, &albedo_table(&baked), &settings)
        .unwrap()
}

#[test]
fn deep_opacity_counts_follow_the_fibers_along_the_light() {
    let Some(gpu) = or_skip(Raster::new()) else {
        return;
    };
    let scene = scene();
    let axis = scene
        .lights
        .shapes()
        .find_map(|s| match s {
            LightShape::Distant { axis, .. } => Some(axis),
            LightShape::Uniform { .. } => None,
        })
        .unwrap();
    let frame = draw(&gpu, &scene, Output::Counts);
    let (mut pairs, mut skipped) = (Vec::new(), 0usize);
    for y in 0..HEIGHT {
        for x in 0..WIDTH {
            let px = frame.rgba[(y * WIDTH + x) as usize];
            if px[3] < 1.0 || px[0] < 0.0 {
                continue;
            }
            let (o, d) = scene
                .camera
                .ray(x as f32 + 0.5, y as f32 + 0.5, WIDTH, HEIGHT);
            let Some(hit) = scene.intersect(&o, &d, None) else {
                continue;
            };
            let HitKind::Fiber { fiber, .. } = hit.kind else {
                skipped += 1;
                continue;
            };
            match scene.fibers_crossed(&hit.point, &axis, Some(fiber)) {
                Some(n) => pairs.push((x / BLOCK, y / BLOCK, f64::from(px[0]), f64::from(n))),
                None => skipped += 1,
            }
        }
    }
    assert!(
        pairs.len() > 1000,
        "{} fur pixels lit by the key",
        pairs.len()
    );
    let n = pairs.len() as f64;
    let ma = pairs.iter().map(|p| p.2).sum::<f64>() / n;
    let me = pairs.iter().map(|p| p.3).sum::<f64>() / n;
    // Per block of BLOCK × BLOCK pixels with at least BLOCK of them: the mean counts.
    let mut blocks = std::collections::BTreeMap::new();
    for &(bx, by, a, e) in &pairs {
        let b = blocks.entry((bx, by)).or_insert((0.0, 0.0, 0.0));
        *b = (b.0 + a, b.1 + e, b.2 + 1.0);
    }
    let blocks: Vec<(f64, f64)> = blocks
        .values()
        .filter(|b| b.2 >= f64::from(BLOCK))
        .map(|b| (b.0 / b.2, b.1 / b.2))
        .collect();
    let k = blocks.len() as f64;
    let (ba, be) = (
        blocks.iter().map(|b| b.0).sum::<f64>() / k,
        blocks.iter().map(|b| b.1).sum::<f64>() / k,
    );
    let cov = blocks.iter().map(|b| (b.0 - ba) * (b.1 - be)).sum::<f64>();
    let sa = blocks
        .iter()
        .map(|b| (b.0 - ba).powi(2))
        .sum::<f64>()
        .sqrt();
    let se = blocks
        .iter()
        .map(|b| (b.1 - be).powi(2))
        .sum::<f64>()
        .sqrt();
    let r = cov / (sa * se);
    println!(
        "{} pixels ({skipped} skipped): mean count raster {ma:.3}, exact {me:.3} ({:+.1} %); \
         {} blocks of {BLOCK}x{BLOCK}: correlation {r:.3}",
        pairs.len(),
        100.0 * (ma / me - 1.0),
        blocks.len()
    );
    assert!(
        (ma / me - 1.0).abs() <= MEAN_COUNT,
        "mean fiber count {ma:.3} against the exact {me:.3}"
    );
    assert!(r >= CORRELATION, "correlation {r:.3} of the block counts");
}

#[test]
fn the_image_is_finite_with_the_fur_coverage_in_alpha() {
    let Some(gpu) = or_skip(Raster::new()) else {
        return;
    };
    let scene = scene();
    let frame = draw(&gpu, &scene, Output::Radiance);
    assert_eq!(frame.rgba.len(), (WIDTH * HEIGHT) as usize);
    assert!(frame
        .rgba
        .iter()
        .all(|p| p.iter().all(|v| v.is_finite() && *v >= 0.0) && p[3] <= 1.0));
    let fur = frame.rgba.iter().filter(|p| p[3] > 0.0).count();
    let mask = render::compare::fur_mask(&scene, WIDTH, HEIGHT);
    let exact = mask.iter().filter(|m| **m).count();
    assert!(
        fur >= exact / 2 && fur <= 2 * exact,
        "{fur} pixels with fur coverage, {exact} whose centre sees a fiber"
    );
    let lit = frame
        .rgba
        .iter()
        .filter(|p| p[3] >= 1.0)
        .map(|p| p[1])
        .fold(0.0f32, f32::max);
    assert!(lit > 0.0, "the fur is black");
    assert_eq!(frame.passes.len(), 6);
}

/// Preset `name`'s LUT and blob ([`small_lut_and_blob`], its profiles generated or read from
/// the shared cache).
fn preset_lut_and_blob(name: &str) -> (Vec<u8>, Vec<u8>) {
    let input = presets::find(name).unwrap().input;
    let fur = FurParams::new(&input).unwrap();
    let (model, _) =
        bake::profiles::build_model(fur, &bake::profiles::ProfileOptions::default()).unwrap();
    small_lut_and_blob(&model, &input)
}

/// The raster image of `scene` drawn with preset `name` against the path tracer's with the
/// same LUT, over the fur's pixels: (mean error, tile RMSE).
fn against_path(gpu: &Raster, scene: &Scene, name: &str) -> (f64, f64) {
    let (lut, blob) = preset_lut_and_blob(name);
    let baked = BakedBcsdf::from_bytes(&lut).unwrap();
    let sigma = baked.absorption().sigma().0;
    let strands = Strands::from_scene(scene, sigma, WIDTH, HEIGHT).unwrap();
    let settings = Settings {
        map_size: 1024,
        ..Settings::new(WIDTH, HEIGHT)
    };
    let frame = gpu
        .draw(&strands, &lut, &blob, &albedo_table(&baked), &settings)
        .unwrap();
    let path = integrator::render_method(
        scene,
        &scatter::One(&baked),
        &render::Settings {
            seed: 3,
            progress: false,
            ..render::Settings::new(WIDTH, HEIGHT, PATH_SPP)
        },
        &Method::Path,
    )
    .unwrap();
    let mask = compare::fur_mask(scene, WIDTH, HEIGHT);
    let fur = compare::metrics(&frame.image(), &path.image, compare::TILE_GRID, Some(&mask));
    (fur.mean, fur.tiles)
}

#[test]
fn the_fur_is_within_the_bounds_of_the_path_tracer_for_a_light_and_a_dark_preset() {
    let Some(gpu) = or_skip(Raster::new()) else {
        return;
    };
    let scene = scene();
    for name in ["cat", "deer"] {
        let t = std::time::Instant::now();
        let (mean, tiles) = against_path(&gpu, &scene, name);
        println!(
            "{name}: fur mean {:+.1} %, tiles {:.1} % ({:.1} s)",
            100.0 * mean,
            100.0 * tiles,
            t.elapsed().as_secs_f64()
        );
        assert!(mean.abs() <= FUR_MEAN, "{name}: fur mean {mean}");
        assert!(tiles <= FUR_TILES, "{name}: fur tiles {tiles}");
    }
}
