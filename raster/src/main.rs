//! `raster`: draws a built-in scene of the `render` crate with the raster pipeline and writes
//! raster.exr (RGBA, A = the fur's coverage), raster.png and raster.json into --out; with
//! `--compare SPP`, also path-traces the scene (`path` and `dual`, as `viewer render
//! --compare` does) and judges the raster image against the path tracer (compare.png,
//! compare.json); with `--bench N`, prints per-pass times over N frames.

use bake::fsutil;
use bcsdf_core::baked::BakedBcsdf;
use bcsdf_core::dual::{Density, DualLut};
use bcsdf_core::lut::LutResolution;
use bcsdf_core::FurParams;
use clap::Parser;
use raster::{albedo_table, fragment_instructions, Frame, Raster, Settings, Strands};
use render::{compare, integrator, output, scenes, Method, SceneKind, SceneOptions};
use serde_json::json;
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;

const ABOUT: &str = "\
Draws a built-in scene (ball, patch: the fibers, camera and lights of `viewer render`) with a
headless wgpu raster pipeline: fibers as camera-facing ribbons shaded by the shared WGSL
evaluator (single scattering plus the dual-scattering term), fiber counts from a deep opacity
map rendered from the key light (docs/engines.md).

Output in DIR (each file written to a temporary file, then renamed):
  raster.exr   linear RGB radiance and A = the fur's coverage of the pixel, 32-bit float
  raster.png   8-bit sRGB after the tone curve 1 - exp(-exposure x)
  raster.json  scene, preset, strands, settings, adapter, per-pass times, instruction count
With --compare SPP, also compare.png (path | dual | raster | |raster - path|) and
compare.json: the raster image and the dual method against the path tracer (mean luminance
error, 16 x 16 tile RMSE, over the whole image and over the fur only).

Examples:
  raster --scene ball --preset cat --out ball-cat
  raster --scene ball --preset deer --width 320 --height 240 --compare 64 --out ball-deer
  raster --scene ball --preset cat --bench 5 --out bench

Bad input prints one line starting with `error:` on stderr and exits with 2; an output
folder that cannot be written, or no GPU adapter, exits with 1.";

#[derive(Parser, Debug)]
#[command(name = "raster", version, about = "Fur in a real-time raster pipeline", long_about = ABOUT)]
struct Args {
    /// The scene: ball or patch.
    #[arg(long, value_name = "SCENE")]
    scene: String,

    /// The built-in preset whose fur to draw (baked in memory).
    #[arg(long, value_name = "NAME", required_unless_present = "lut")]
    preset: Option<String>,

    /// Override one parameter of the preset (`viewer probe`'s keys); repeatable.
    #[arg(long = "set", value_name = "KEY=VALUE", requires = "preset")]
    set: Vec<String>,

    /// Draw with this baked LUT (.furlut) instead of a preset; its .furdual beside it is
    /// read if there is one (refused unless it pairs with the LUT), else computed.
    #[arg(long, value_name = "FILE", conflicts_with = "preset")]
    lut: Option<PathBuf>,

    /// Image width in pixels.
    #[arg(long, value_name = "W", default_value_t = 1280)]
    width: u32,

    /// Image height in pixels.
    #[arg(long, value_name = "H", default_value_t = 720)]
    height: u32,

    /// Number of fibers (default: the scene's).
    #[arg(long, value_name = "N")]
    fibers: Option<usize>,

    /// Seed of the fiber placement (and of the path tracer's streams with --compare).
    #[arg(long, value_name = "S", default_value_t = 1)]
    seed: u64,

    /// The side of the light's maps in texels.
    #[arg(long, value_name = "N", default_value_t = Settings::new(1, 1).map_size)]
    map_size: u32,

    /// Where deep opacity layers 0, 1, 2 end behind the first fiber (world units).
    #[arg(long, value_name = "A,B,C", value_delimiter = ',')]
    layers: Option<Vec<f32>>,

    /// Dual scattering's forward density factor d_f.
    #[arg(long, value_name = "D", default_value_t = Density::DEFAULT.d_f)]
    d_f: f32,

    /// Dual scattering's backward density factor d_b.
    #[arg(long, value_name = "D", default_value_t = Density::DEFAULT.d_b)]
    d_b: f32,

    /// Exposure of the PNG's tone curve.
    #[arg(long, value_name = "E", default_value_t = 4.0)]
    exposure: f32,

    /// Draw N frames and print each pass's median wall time (and GPU time where the
    /// adapter has timestamps); raster.json records them.
    #[arg(long, value_name = "N")]
    bench: Option<u32>,

    /// Also path-trace the scene at SPP samples per pixel (`path` and `dual`) and judge
    /// the raster image against the path tracer.
    #[arg(long, value_name = "SPP")]
    compare: Option<u32>,

    /// Output folder.
    #[arg(long, value_name = "DIR")]
    out: PathBuf,
}

/// A failure: bad input (exit 2) or anything else (exit 1).
enum Failure {
    Input(String),
    Other(String),
}

fn input(e: impl ToString) -> Failure {
    Failure::Input(e.to_string())
}

fn other(e: impl ToString) -> Failure {
    Failure::Other(e.to_string())
}

fn main() -> ExitCode {
    let args = Args::parse();
    match run(&args) {
        Ok(()) => ExitCode::SUCCESS,
        Err(Failure::Input(e)) => {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }
        Err(Failure::Other(e)) => {
            eprintln!("error: {e}");
            ExitCode::from(1)
        }
    }
}

/// The LUT and dual-scattering blobs and the name to report.
fn load(args: &Args) -> Result<(String, Vec<u8>, Vec<u8>), Failure> {
    if let Some(path) = &args.lut {
        let blob = std::fs::read(path).map_err(|e| input(format!("{}: {e}", path.display())))?;
        BakedBcsdf::from_bytes(&blob).map_err(|e| input(format!("{}: {e}", path.display())))?;
        let beside = path.with_extension(bake::pipeline::DUAL_EXTENSION);
        let dual = if beside.is_file() {
            let bytes =
                std::fs::read(&beside).map_err(|e| input(format!("{}: {e}", beside.display())))?;
            let mut d = Box::new(DualLut::EMPTY);
            d.decode(&bytes)
                .map_err(|e| input(format!("{}: {e}", beside.display())))?;
            let baked = BakedBcsdf::from_bytes(&blob).map_err(input)?;
            d.check_lut(&baked)
                .map_err(|e| input(format!("{}: {e}", beside.display())))?;
            bytes
        } else {
            let baked = BakedBcsdf::from_bytes(&blob).map_err(input)?;
            bake::pipeline::dual_blob(&blob, &baked, bcsdf_core::dual::Quadrature::DEFAULT).to_vec()
        };
        return Ok((path.display().to_string(), blob, dual));
    }
    let (name, blob) = {
        let name = args.preset.as_deref().unwrap_or_default();
        let list = bake::presets::builtin().map_err(other)?;
        let (preset, alias) = bake::presets::lookup(&list, name).ok_or_else(|| {
            let names: Vec<&str> = list.iter().map(|p| p.name.as_str()).collect();
            input(format!(
                "unknown preset `{name}` (known: {})",
                names.join(", ")
            ))
        })?;
        if let Some(a) = alias {
            eprintln!("note: {a}");
        }
        let mut params = preset.input;
        bake::apply_overrides(&mut params, &args.set).map_err(|e| input(format!("--set {e}")))?;
        let fur = FurParams::new(&params).map_err(|e| input(format!("--set: {e}")))?;
        let (model, _) =
            bake::profiles::build_model(fur, &bake::profiles::ProfileOptions::default())
                .map_err(other)?;
        (
            preset.name.clone(),
            bake::tables::bake(&model, &params, LutResolution::DEFAULT),
        )
    };
    let baked = BakedBcsdf::from_bytes(&blob)
        .map_err(|e| other(format!("the LUT baked in memory: {e}")))?;
    let dual =
        bake::pipeline::dual_blob(&blob, &baked, bcsdf_core::dual::Quadrature::DEFAULT).to_vec();
    Ok((name, blob, dual))
}

fn run(args: &Args) -> Result<(), Failure> {
    let kind: SceneKind = args
        .scene
        .parse()
        .map_err(|e| input(format!("--scene: {e}")))?;
    if kind == SceneKind::Furnace {
        return Err(input(
            "--scene furnace has no key light to cast the deep opacity map (expected ball or patch)",
        ));
    }
    let mut settings = Settings::new(args.width, args.height);
    settings.map_size = args.map_size;
    if let Some(l) = &args.layers {
        settings.layer_ends = <[f32; 3]>::try_from(l.as_slice()).map_err(|_| {
            input(format!(
                "--layers takes three values A,B,C, not {}",
                l.len()
            ))
        })?;
    }
    settings.density = [args.d_f, args.d_b];
    settings
        .validate()
        .map_err(|e| input(format!("--{}", flag_of(&e.to_string()))))?;
    if args.fibers == Some(0) {
        return Err(input("--fibers 0: a scene needs at least one fiber"));
    }
    if let Some(n) = args.fibers.filter(|n| *n > 1_000_000) {
        return Err(input(format!("--fibers {n} is more than 1000000")));
    }
    if !(args.exposure.is_finite() && args.exposure > 0.0) {
        return Err(input(format!(
            "--exposure {} must be a positive finite number",
            args.exposure
        )));
    }
    if args.bench == Some(0) || args.compare == Some(0) {
        return Err(input("--bench and --compare take at least 1"));
    }
    fsutil::prepare_dir(&args.out).map_err(other)?;
    let (name, lut, dual) = load(args)?;
    let baked = BakedBcsdf::from_bytes(&lut).map_err(input)?;
    let colour = baked.absorption();
    let scene = scenes::build(&SceneOptions {
        kind,
        fibers: args.fibers,
        seed: args.seed,
        aspect: args.width as f32 / args.height as f32,
    });
    let strands =
        Strands::from_scene(&scene, colour.sigma().0, args.width, args.height).map_err(input)?;
    let albedo = albedo_table(&baked);
    let gpu = Raster::new().map_err(other)?;
    let frames = args.bench.unwrap_or(1);
    let mut all: Vec<Frame> = Vec::new();
    for _ in 0..frames {
        all.push(
            gpu.draw(&strands, &lut, &dual, &albedo, &settings)
                .map_err(input)?,
        );
    }
    let frame = all.pop().ok_or_else(|| other("no frame drawn"))?;
    all.push(frame.clone());
    let (instructions, spirv) = fragment_instructions().map_err(other)?;
    let optimised = spirv_opt_count(&spirv);
    let medians: Vec<serde_json::Value> = frame
        .passes
        .iter()
        .enumerate()
        .map(|(k, p)| {
            let wall = median(all.iter().map(|f| f.passes[k].wall_ms).collect());
            let gpu = p
                .gpu_ms
                .map(|_| median(all.iter().filter_map(|f| f.passes[k].gpu_ms).collect()));
            json!({"pass": p.name, "wall_ms": wall, "gpu_ms": gpu})
        })
        .collect();
    let frame_ms = median(all.iter().map(Frame::wall_ms).collect());
    let image = frame.image();
    let exr = output::exr_rgba_bytes(&image, &frame.coverage()).map_err(other)?;
    let png = output::png_bytes(&image, args.exposure).map_err(other)?;
    let mut report = json!({
        "scene": kind.name(),
        "preset": name,
        "set": args.set,
        "strands": strands.strands,
        "segments": strands.instances.len(),
        "width": args.width,
        "height": args.height,
        "seed": args.seed,
        "sigma_ca": colour.sigma().0,
        "settings": {
            "map_size": settings.map_size,
            "layer_ends": settings.layer_ends.map(|v| (f64::from(v) * 1e6).round() / 1e6),
            "bias_radii": settings.bias_radii,
            "shadow_bias": (f64::from(settings.shadow_bias) * 1e6).round() / 1e6,
            "d_f": settings.density[0],
            "d_b": settings.density[1],
            "msaa": 4,
        },
        "adapter": gpu.adapter_name(),
        "timestamps": gpu.has_timestamps(),
        "frames": frames,
        "frame_wall_ms": frame_ms,
        "passes": medians,
        "fragment_spirv_instructions": instructions,
        "fragment_spirv_instructions_optimised": optimised,
        "load_average": load_average(),
    });
    if let Some(spp) = args.compare {
        let judged = judge(
            &scene,
            (&baked, &lut),
            &dual,
            &image,
            (spp, &settings),
            args,
        )?;
        report["against_path"] = judged;
    }
    let text = serde_json::to_string_pretty(&report).map_err(other)? + "\n";
    for (file, bytes) in [
        ("raster.exr", exr),
        ("raster.png", png),
        ("raster.json", text.into_bytes()),
    ] {
        fsutil::write_atomic(&args.out.join(file), &bytes).map_err(other)?;
    }
    println!(
        "{} {} {}x{}, {} strands ({} segments) on {}: frame {:.1} ms wall (median of {frames}), \
         fur fragment shader {instructions} SPIR-V instructions{} -> {}",
        kind.name(),
        name,
        args.width,
        args.height,
        strands.strands,
        strands.instances.len(),
        gpu.adapter_name(),
        frame_ms,
        optimised.map_or(String::new(), |n| format!(" ({n} after spirv-opt -O)")),
        args.out.display()
    );
    if args.bench.is_some() {
        for m in &medians {
            println!(
                "  {:10} wall {:8.2} ms{}",
                m["pass"].as_str().unwrap_or(""),
                m["wall_ms"].as_f64().unwrap_or(0.0),
                m["gpu_ms"]
                    .as_f64()
                    .map_or(String::new(), |g| format!("  gpu {g:8.2} ms"))
            );
        }
        println!("  load average {}", load_average());
    }
    Ok(())
}

/// Path-traces the scene (`path`, `dual`) at `spp` and compares the raster image and the
/// dual method with the path tracer, whole image and fur only (render::compare); writes
/// compare.png and returns the numbers.
fn judge(
    scene: &render::scene::Scene,
    (baked, lut_bytes): (&BakedBcsdf<'_>, &[u8]),
    dual: &[u8],
    raster: &render::Image,
    (spp, raster_settings): (u32, &Settings),
    args: &Args,
) -> Result<serde_json::Value, Failure> {
    let settings = render::Settings {
        seed: args.seed,
        progress: false,
        ..render::Settings::new(args.width, args.height, spp)
    };
    settings
        .validate()
        .map_err(|e| input(format!("--compare: {e}")))?;
    let mut lut = Box::new(DualLut::EMPTY);
    lut.decode(dual).map_err(other)?;
    let t = Instant::now();
    let path = integrator::render_method(
        scene,
        &render::scatter::One(baked),
        &settings,
        &Method::Path,
    )
    .map_err(other)?;
    let path_s = t.elapsed().as_secs_f64();
    let t = Instant::now();
    let dual_r = integrator::render_method(
        scene,
        &render::scatter::One(baked),
        &settings,
        &Method::Dual {
            lut: &lut,
            density: Density {
                d_f: args.d_f,
                d_b: args.d_b,
            },
        },
    )
    .map_err(other)?;
    let dual_s = t.elapsed().as_secs_f64();
    let mask = compare::fur_mask(scene, args.width, args.height);
    let numbers = |img: &render::Image| {
        let all = compare::metrics(img, &path.image, compare::TILE_GRID, None);
        let fur = compare::metrics(img, &path.image, compare::TILE_GRID, Some(&mask));
        json!({
            "mean_error": all.mean,
            "tile_rmse": all.tiles,
            "tile_rmse_from_noise": all.noise,
            "fur_mean_error": fur.mean,
            "fur_tile_rmse": fur.tiles,
            "fur_tile_rmse_from_noise": fur.noise,
        })
    };
    let regions = regions(
        scene,
        (baked, lut_bytes),
        dual,
        [raster, &path.image, &dual_r.image],
        &mask,
        raster_settings,
    )?;
    let out = json!({
        "fur_regions": regions,
        "spp": spp,
        "tile_grid": compare::TILE_GRID,
        "raster": numbers(raster),
        "dual": numbers(&dual_r.image),
        "seconds": {"path": path_s, "dual": dual_s},
        "panels": ["path", "dual", "raster", "|raster - path|"],
    });
    let diff = compare::difference(raster, &path.image);
    let strip = compare::side_by_side(&[&path.image, &dual_r.image, raster, &diff]);
    let png = output::png_bytes(&strip, args.exposure).map_err(other)?;
    fsutil::write_atomic(&args.out.join("compare.png"), &png).map_err(other)?;
    let text = serde_json::to_string_pretty(&out).map_err(other)? + "\n";
    fsutil::write_atomic(&args.out.join("compare.json"), text.as_bytes()).map_err(other)?;
    for (name, r) in out["fur_regions"].as_object().into_iter().flatten() {
        let pc = |k: &str| 100.0 * r[k].as_f64().unwrap_or(f64::NAN);
        println!(
            "  fur {name:8}: {:4.1} % of the fur's pixels, {:4.1} % of its light in path; mean raster {:+6.1} %, dual {:+6.1} %",
            pc("pixels"),
            pc("path_light"),
            pc("raster_mean_error"),
            pc("dual_mean_error")
        );
    }
    for m in ["raster", "dual"] {
        let v = &out[m];
        let pc = |k: &str| 100.0 * v[k].as_f64().unwrap_or(f64::NAN);
        println!(
            "  {m:6} against path ({spp} spp): mean {:+6.1} %  tiles {:5.1} % (noise {:4.1} %) | fur only: mean {:+6.1} %  tiles {:5.1} %",
            pc("mean_error"),
            pc("tile_rmse"),
            pc("tile_rmse_from_noise"),
            pc("fur_mean_error"),
            pc("fur_tile_rmse")
        );
    }
    Ok(out)
}

/// A settings message with the option that sets it named first (`width 0 …` → `width 0 …`,
/// `light map size 9 …` → `map-size 9 …`, `layer ends …` → `layers …`).
fn flag_of(message: &str) -> String {
    for (text, flag) in [
        ("light map size", "map-size"),
        ("layer ends", "layers"),
        ("density factor", "d-f/--d-b"),
    ] {
        if let Some(rest) = message.strip_prefix(text) {
            return format!("{flag}{rest}");
        }
    }
    message.to_owned()
}

/// The fur's pixels split by what the deep opacity map says of their key light — shadowed by
/// a surface, in front (n < 0.5 fibers toward the light) or inside the coat (n ≥ 0.5) — with
/// each region's share of the fur's pixels and its mean luminance error against path, for
/// the raster image and for `dual` (where in the coat the light is missing).
fn regions(
    scene: &render::scene::Scene,
    (baked, lut_bytes): (&BakedBcsdf<'_>, &[u8]),
    dual: &[u8],
    [raster, path, dual_image]: [&render::Image; 3],
    mask: &[bool],
    settings: &Settings,
) -> Result<serde_json::Value, Failure> {
    let strands = Strands::from_scene(
        scene,
        baked.absorption().sigma().0,
        settings.width,
        settings.height,
    )
    .map_err(input)?;
    let settings = Settings {
        output: raster::Output::Counts,
        ..*settings
    };
    let gpu = Raster::new().map_err(other)?;
    let counts = gpu
        .draw(&strands, lut_bytes, dual, &albedo_table(baked), &settings)
        .map_err(input)?;
    let names = ["shadowed", "front", "inside"];
    let mut sums = [[0.0f64; 4]; 3];
    for (i, px) in counts.rgba.iter().enumerate() {
        if !mask[i] || px[3] <= 0.0 {
            continue;
        }
        let r = if px[0] < 0.0 {
            0
        } else if px[0] < 0.5 {
            1
        } else {
            2
        };
        sums[r][0] += compare::luminance(&path.mean[i]);
        sums[r][1] += compare::luminance(&raster.mean[i]);
        sums[r][2] += compare::luminance(&dual_image.mean[i]);
        sums[r][3] += 1.0;
    }
    let total: f64 = sums.iter().map(|s| s[3]).sum();
    let fur_path: f64 = sums.iter().map(|s| s[0]).sum();
    Ok(serde_json::Value::Object(
        names
            .iter()
            .zip(sums)
            .map(|(name, s)| {
                let err = |k: usize| if s[0] > 0.0 { s[k] / s[0] - 1.0 } else { 0.0 };
                (
                    (*name).to_string(),
                    json!({
                        "pixels": s[3] / total.max(1.0),
                        "path_light": s[0] / fur_path.max(1e-30),
                        "raster_mean_error": err(1),
                        "dual_mean_error": err(2),
                    }),
                )
            })
            .collect(),
    ))
}

/// The median of some times (0 for none).
fn median(mut v: Vec<f64>) -> f64 {
    if v.is_empty() {
        return 0.0;
    }
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// The 1-minute load average (Linux `/proc/loadavg`), or "unknown".
fn load_average() -> String {
    std::fs::read_to_string("/proc/loadavg")
        .ok()
        .and_then(|s| s.split_whitespace().next().map(str::to_owned))
        .unwrap_or_else(|| "unknown".into())
}

/// The instruction count after `spirv-opt -O` (spirv-tools), if it is installed.
fn spirv_opt_count(words: &[u32]) -> Option<usize> {
    let dir = std::env::temp_dir().join(format!("raster-spirv-{}", std::process::id()));
    std::fs::create_dir_all(&dir).ok()?;
    let (src, dst) = (dir.join("fur.spv"), dir.join("fur-opt.spv"));
    let bytes: Vec<u8> = words.iter().flat_map(|w| w.to_le_bytes()).collect();
    std::fs::write(&src, bytes).ok()?;
    let ok = std::process::Command::new("spirv-opt")
        .arg("-O")
        .arg(&src)
        .arg("-o")
        .arg(&dst)
        .status()
        .ok()?
        .success();
    let out = if ok { std::fs::read(&dst).ok() } else { None };
    let _ = std::fs::remove_dir_all(&dir);
    let out = out?;
    let w: Vec<u32> = out
        .chunks_exact(4)
        .map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]]))
        .collect();
    raster::spirv_instructions(&w).ok()
}
