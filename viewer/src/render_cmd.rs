//! `viewer render`: path-traces a built-in scene with the `render` crate and writes
//! render.exr, render.png and render.json through `bake::fsutil` (docs/model.md §11); with
//! `--compare`, path, dual and single side by side with the difference and the numbers that
//! judge them (compare.png, compare.exr, compare.json; docs/model.md §13).

use crate::catalog;
use crate::cli::{Evaluator, Method as MethodArg, PresetsArgs, ProfileArgs, RenderArgs};
use crate::error::Error;
use crate::json;
use crate::source::{preset_model, read_lut};
use bake::fsutil;
use bake::lutfile::read_dual;
use bcsdf_core::baked::BakedBcsdf;
use bcsdf_core::dual::{encode, Attenuation, Density, DualLut, DualTables, Quadrature};
use bcsdf_core::lut::LutResolution;
use bcsdf_core::{Bcsdf, FurParamsInput};
use render::scatter::One;
use render::{
    compare, integrator, output, scenes, Method, Render, SceneKind, SceneOptions, Settings,
};
use serde_json::json;
use std::io::Write;
use std::path::Path;

/// Runs `viewer render`.
pub fn run(args: &RenderArgs) -> Result<(), Error> {
    let kind: SceneKind = args
        .scene
        .parse()
        .map_err(|e| Error::input(format!("--scene: {e}")))?;
    let (threads, note) = bake::limits::threads("--threads", args.threads).map_err(Error::input)?;
    if let Some(note) = note {
        eprintln!("note: {note}");
    }
    let settings = Settings {
        max_depth: args.max_depth,
        seed: args.seed,
        threads,
        progress: true,
        ..Settings::new(args.width, args.height, args.spp)
    };
    settings
        .validate()
        .map_err(|e| Error::input(format!("--{}", flag_of(&e))))?;
    if args.fibers == Some(0) {
        return Err(Error::input("--fibers 0: a scene needs at least one fiber"));
    }
    if let Some(n) = args.fibers.filter(|n| *n > MAX_FIBERS) {
        return Err(Error::input(format!(
            "--fibers {n} is more than {MAX_FIBERS} (the segments and their hierarchy would \
             take about {:.0} GB)",
            n as f64 * FIBER_BYTES / 1e9
        )));
    }
    let renders = if args.compare { 3 } else { 1 };
    if let Some(note) = render_estimate(&settings, renders, threads)? {
        eprintln!("note: {note}");
    }
    if !(args.exposure.is_finite() && args.exposure > 0.0) {
        return Err(Error::input(format!(
            "--exposure {} must be a positive finite number",
            args.exposure
        )));
    }
    for (flag, d) in [("d-f", args.d_f), ("d-b", args.d_b)] {
        if !(d.is_finite() && (0.0..=bcsdf_core::dual::MAX_DENSITY).contains(&d)) {
            return Err(Error::input(format!(
                "--{flag} {d} must be 0 to {}",
                bcsdf_core::dual::MAX_DENSITY
            )));
        }
    }
    let evaluator = match (args.evaluator, &args.lut) {
        (Some(Evaluator::Analytic), Some(_)) => {
            return Err(Error::input(
                "--lut holds baked tables: it renders with --evaluator baked only",
            ))
        }
        (Some(e), _) => e,
        // With --preset too: the preset baked in memory (about 10x the analytic model's rays
        // per second, docs/benchmarks.md "Path tracing"), unless --evaluator analytic.
        (None, _) => Evaluator::Baked,
    };
    let strands = crate::strand_cmd::request(args, evaluator == Evaluator::Baked)?;
    fsutil::prepare_dir(&args.out).map_err(|e| Error::Failure(e.to_string()))?;

    let scene = scenes::build(&SceneOptions {
        kind,
        fibers: args.fibers,
        seed: args.seed,
        aspect: args.width as f32 / args.height as f32,
    });
    let (name, r) = if let Some(path) = &args.lut {
        let blob = read_lut(path)?;
        let baked = BakedBcsdf::from_bytes(&blob)
            .map_err(|e| Error::input(format!("{}: {e}", path.display())))?;
        // The LUT at its preset's colour, or at `--set sigma_ca=…` (docs/lut.md "The
        // absorption axis"); the stored dual tables are read at the same colour.
        let colour = crate::source::lut_colour(path, &blob, &args.set)?;
        let stored = if methods(args).contains(&MethodArg::Dual) {
            stored_dual(path, &baked)?
        } else {
            None
        };
        let stored = stored.map(|mut d: Box<DualLut>| {
            d.set_absorption(&colour);
            d
        });
        let r = match &strands {
            Some(req) => vec![(
                args.method,
                crate::strand_cmd::render(&scene, kind, &baked, req, &settings, args.method)?,
            )],
            None => trace(&scene, &baked.at(&colour), stored, &settings, args)?,
        };
        (path.display().to_string(), r)
    } else {
        // clap requires --preset without --lut.
        let preset = args.preset.as_deref().unwrap_or_default();
        let profile_args = ProfileArgs {
            cache_dir: args.cache_dir.clone(),
            no_cache: args.no_cache,
            seed: bake::profiles::DEFAULT_SEED,
            photons_scale: 1.0,
            threads: args.threads,
        };
        let model = preset_model(preset, &args.presets, &args.set, &profile_args)?;
        let r = match evaluator {
            Evaluator::Analytic => trace(&scene, &model.model(), None, &settings, args)?,
            Evaluator::Baked => {
                let input = preset_input(preset, &args.presets, &args.set)?;
                let blob = bake::tables::bake(&model, &input, LutResolution::DEFAULT);
                let baked = BakedBcsdf::from_bytes(&blob)
                    .map_err(|e| Error::Failure(format!("the LUT baked in memory: {e}")))?;
                match &strands {
                    Some(req) => vec![(
                        args.method,
                        crate::strand_cmd::render(
                            &scene,
                            kind,
                            &baked,
                            req,
                            &settings,
                            args.method,
                        )?,
                    )],
                    None => trace(&scene, &baked, None, &settings, args)?,
                }
            }
        };
        (preset.to_string(), r)
    };

    if args.compare {
        return write_comparison(&scene, &name, kind, evaluator, &r, args);
    }
    let r = &r[0].1;
    let exr = output::exr_bytes(&r.image).map_err(|e| Error::Failure(e.to_string()))?;
    let png =
        output::png_bytes(&r.image, args.exposure).map_err(|e| Error::Failure(e.to_string()))?;
    let whole = r.image.whole();
    let mut report = setup_report(kind, &name, evaluator, args);
    report.extend(json_fields(json!({
        "segments": scene.segment_count(),
        "method": method_name(args.method),
        "seconds": r.seconds,
        "paths": r.paths,
        "rays": r.rays,
        "paths_per_second": r.paths as f64 / r.seconds.max(1e-9),
        "rays_per_second": r.rays as f64 / r.seconds.max(1e-9),
        "mean_radiance": whole.mean,
        "mean_radiance_std_error": whole.std_error,
        "energy_per_bounce_order": r.orders,
    })));
    let report = serde_json::Value::Object(report);
    for (file, bytes) in [
        ("render.exr", exr),
        ("render.png", png),
        ("render.json", json::pretty(&report).into_bytes()),
    ] {
        fsutil::write_atomic(&args.out.join(file), &bytes)?;
    }
    let _ = writeln!(
        std::io::stdout().lock(),
        "{} {} {}x{} {} spp, {}: {:.2} s, {:.3} M rays/s, mean radiance [{:.4}, {:.4}, {:.4}] -> {}",
        kind.name(),
        method_name(args.method),
        args.width,
        args.height,
        args.spp,
        evaluator_said(evaluator, args.lut.is_some()),
        r.seconds,
        r.rays as f64 / r.seconds.max(1e-9) / 1e6,
        whole.mean[0],
        whole.mean[1],
        whole.mean[2],
        args.out.display()
    );
    Ok(())
}

/// `--compare`: path | dual | single | |dual − path| in compare.png and compare.exr, the
/// numbers (render::compare, over the whole image and over the fur) in compare.json and on
/// stdout.
fn write_comparison(
    scene: &render::scene::Scene,
    name: &str,
    kind: SceneKind,
    evaluator: Evaluator,
    renders: &[(MethodArg, Render)],
    args: &RenderArgs,
) -> Result<(), Error> {
    let image = |m: MethodArg| {
        renders
            .iter()
            .find(|(k, _)| *k == m)
            .map(|(_, r)| &r.image)
            .ok_or_else(|| Error::Failure(format!("no {} render", method_name(m))))
    };
    let (path, dual, single) = (
        image(MethodArg::Path)?,
        image(MethodArg::Dual)?,
        image(MethodArg::Single)?,
    );
    let diff = compare::difference(dual, path);
    let strip = compare::side_by_side(&[path, dual, single, &diff]);
    let mask = compare::fur_mask(scene, args.width, args.height);
    let numbers = |img: &render::Image| {
        let (all, fur) = (
            compare::metrics(img, path, compare::TILE_GRID, None),
            compare::metrics(img, path, compare::TILE_GRID, Some(&mask)),
        );
        (all, fur)
    };
    let mut methods = serde_json::Map::new();
    let mut lines = Vec::new();
    for (m, img) in [(MethodArg::Dual, dual), (MethodArg::Single, single)] {
        let (all, fur) = numbers(img);
        methods.insert(
            method_name(m).into(),
            json!({
                "mean_error": all.mean,
                "tile_rmse": all.tiles,
                "tile_rmse_from_noise": all.noise,
                "fur_mean_error": fur.mean,
                "fur_tile_rmse": fur.tiles,
            }),
        );
        lines.push(format!(
            "  {:6} mean {:+6.1} %  tiles {:5.1} % (noise {:4.1} %) | fur only: mean {:+6.1} %  tiles {:5.1} %",
            method_name(m),
            100.0 * all.mean,
            100.0 * all.tiles,
            100.0 * all.noise,
            100.0 * fur.mean,
            100.0 * fur.tiles
        ));
    }
    let seconds: serde_json::Map<String, serde_json::Value> = renders
        .iter()
        .map(|(m, r)| (method_name(*m).to_string(), json!(r.seconds)))
        .collect();
    let mut report = setup_report(kind, name, evaluator, args);
    report.extend(json_fields(json!({
        "tile_grid": compare::TILE_GRID,
        "against_path": methods,
        "seconds": seconds,
        "panels": ["path", "dual", "single", "|dual - path|"],
    })));
    let report = serde_json::Value::Object(report);
    let exr = output::exr_bytes(&strip).map_err(|e| Error::Failure(e.to_string()))?;
    let png =
        output::png_bytes(&strip, args.exposure).map_err(|e| Error::Failure(e.to_string()))?;
    for (file, bytes) in [
        ("compare.exr", exr),
        ("compare.png", png),
        ("compare.json", json::pretty(&report).into_bytes()),
    ] {
        fsutil::write_atomic(&args.out.join(file), &bytes)?;
    }
    let mut out = std::io::stdout().lock();
    let _ = writeln!(
        out,
        "{} {} {}x{} {} spp, against path (tile RMSE over {}x{} tiles):",
        kind.name(),
        name,
        args.width,
        args.height,
        args.spp,
        compare::TILE_GRID,
        compare::TILE_GRID
    );
    for l in lines {
        let _ = writeln!(out, "{l}");
    }
    let _ = writeln!(
        out,
        "  panels: path | dual | single | |dual - path| -> {}",
        args.out.display()
    );
    Ok(())
}

/// The fields render.json and compare.json share: what was rendered and how.
fn setup_report(
    kind: SceneKind,
    name: &str,
    evaluator: Evaluator,
    args: &RenderArgs,
) -> serde_json::Map<String, serde_json::Value> {
    json_fields(json!({
        "scene": kind.name(),
        "fibers": args.fibers.unwrap_or(kind.default_fibers()),
        "preset": name,
        "set": args.set,
        "evaluator": evaluator_name(evaluator),
        "d_f": args.d_f,
        "d_b": args.d_b,
        "width": args.width,
        "height": args.height,
        "spp": args.spp,
        "max_depth": args.max_depth,
        "seed": args.seed,
        "colour": args.colour,
        "tip_colour": args.tip_colour,
        "colour_jitter_percent": args.colour_jitter,
        "colour_stripes": args.colour_stripes,
        "colour_texture": args.colour_texture,
    }))
}

/// The fields of a `json!({..})` object.
fn json_fields(v: serde_json::Value) -> serde_json::Map<String, serde_json::Value> {
    match v {
        serde_json::Value::Object(m) => m,
        _ => serde_json::Map::new(),
    }
}

fn evaluator_name(e: Evaluator) -> &'static str {
    match e {
        Evaluator::Analytic => "analytic",
        Evaluator::Baked => "baked",
    }
}

/// The evaluator as the summary line names it: the analytic model, the LUT read from
/// --lut, or the preset's tables baked in memory.
fn evaluator_said(e: Evaluator, from_file: bool) -> &'static str {
    match (e, from_file) {
        (Evaluator::Analytic, _) => "analytic evaluator",
        (Evaluator::Baked, true) => "baked evaluator (--lut)",
        (Evaluator::Baked, false) => "baked evaluator (the preset baked in memory)",
    }
}

fn method_name(m: MethodArg) -> &'static str {
    match m {
        MethodArg::Path => "path",
        MethodArg::Dual => "dual",
        MethodArg::Single => "single",
    }
}

/// The `.furdual` that `bake` wrote beside the LUT at `lut_path` (same name, extension
/// `furdual`), decoded, if there is one: what an engine loads with the LUT. Refused unless
/// it was computed from that LUT (`DualLut::check_lut`, docs/model.md §13 "Stored tables").
fn stored_dual(lut_path: &Path, lut: &BakedBcsdf) -> Result<Option<Box<DualLut>>, Error> {
    let file = lut_path.with_extension(bake::pipeline::DUAL_EXTENSION);
    if !file.is_file() {
        return Ok(None);
    }
    let dual = read_dual(&file).map_err(|e| Error::input(e.to_string()))?;
    dual.check_lut(lut).map_err(|e| {
        Error::input(format!(
            "{}: {e} ({}); re-bake the pair with `bake`, or move the .furdual away to compute the tables from the LUT",
            file.display(),
            lut_path.display()
        ))
    })?;
    Ok(Some(dual))
}

/// The methods `args` renders: its `--method`, or path, dual and single with `--compare`
/// (the one place that decides whether the dual tables are needed).
fn methods(args: &RenderArgs) -> &[MethodArg] {
    if args.compare {
        &[MethodArg::Path, MethodArg::Dual, MethodArg::Single]
    } else {
        core::slice::from_ref(&args.method)
    }
}

/// Renders with one evaluator and the method of `args`, or path, dual and single with
/// `--compare`. For `dual` the term reads `stored` (the `.furdual` beside `--lut`, see
/// [`stored_dual`]), or else tables computed from the evaluator first (docs/model.md §13).
fn trace<B: Bcsdf + Sync>(
    scene: &render::scene::Scene,
    bcsdf: &B,
    stored: Option<Box<DualLut>>,
    settings: &Settings,
    args: &RenderArgs,
) -> Result<Vec<(MethodArg, Render)>, Error> {
    let kinds = methods(args);
    // What an engine loads: the tables through the `.furdual` blob (f16).
    let lut = match stored {
        Some(lut) => lut,
        None => {
            let mut lut = Box::new(DualLut::EMPTY);
            if kinds.contains(&MethodArg::Dual) {
                let mut tables = Box::new(DualTables::ZERO);
                tables.compute(bcsdf, Quadrature::DEFAULT);
                lut.decode(&encode(&tables, Attenuation::Coat, 0))
                    .map_err(|e| Error::input(e.to_string()))?;
            }
            lut
        }
    };
    let mut out = Vec::new();
    for &kind in kinds {
        let method = match kind {
            MethodArg::Path => Method::Path,
            MethodArg::Single => Method::Single,
            MethodArg::Dual => Method::Dual {
                lut: &lut,
                density: Density {
                    d_f: args.d_f,
                    d_b: args.d_b,
                },
            },
        };
        let r = integrator::render_method(scene, &One(bcsdf), settings, &method)
            .map_err(|e| Error::input(e.to_string()))?;
        out.push((kind, r));
    }
    Ok(out)
}

/// The most fibers `--fibers` accepts (each fiber's segments and their share of the
/// hierarchy take about [`FIBER_BYTES`]).
const MAX_FIBERS: usize = 1_000_000;

/// Bytes per fiber of a scene, generously (up to 8 segments of 64 bytes and the hierarchy).
const FIBER_BYTES: f64 = 1024.0;

/// Rays per second per core the estimate assumes: the measured 0.5–0.6 M rays/s per core of
/// the analytic model on the built-in scenes (release build; the baked model is faster).
const RAYS_PER_CORE_SECOND: f64 = 5e5;

/// Rays per path the estimate assumes: a camera ray and a light ray per vertex, up to 4
/// vertices on average (Russian roulette ends most paths early) and never more than the depth.
fn rays_per_path(max_depth: u32) -> f64 {
    2.0 * f64::from(max_depth.min(4)) + 1.0
}

/// Estimated seconds above which a render is refused (a week).
const MAX_RENDER_SECONDS: f64 = 7.0 * 86_400.0;

/// Estimated seconds above which the estimate is printed.
const NOTE_RENDER_SECONDS: f64 = 30.0;

/// Bytes per pixel of one render kept in memory (the film's sums, the rows, the encoders).
const PIXEL_BYTES: f64 = 64.0;

/// The largest memory estimate a render may reach.
const MAX_RENDER_BYTES: f64 = 16e9;

/// spp × pixels × depth: refuses a render estimated to take more than a week or 16 GB, and
/// returns a note with the estimate when it should take more than half a minute.
fn render_estimate(
    settings: &Settings,
    renders: u32,
    threads: Option<usize>,
) -> Result<Option<String>, Error> {
    let pixels = f64::from(settings.width) * f64::from(settings.height);
    let paths = pixels * f64::from(settings.spp) * f64::from(renders);
    let cores = threads
        .unwrap_or_else(bake::limits::cores)
        .min(bake::limits::cores()) as f64;
    let seconds =
        paths * rays_per_path(settings.max_depth) / (RAYS_PER_CORE_SECOND * cores.max(1.0));
    let bytes = pixels * PIXEL_BYTES * f64::from(renders);
    let what = format!(
        "{} x {} pixels x {} spp{} = {paths:.3e} paths, depth up to {}: about {} on {cores} \
         cores (at {RAYS_PER_CORE_SECOND:.0e} rays/s per core) and {:.1} GB",
        settings.width,
        settings.height,
        settings.spp,
        if renders > 1 { " x 3 methods" } else { "" },
        settings.max_depth,
        bake::limits::duration(seconds),
        bytes / 1e9
    );
    if seconds > MAX_RENDER_SECONDS || bytes > MAX_RENDER_BYTES {
        return Err(Error::input(format!(
            "{what}: more than a week or 16 GB; lower --spp, --width or --height"
        )));
    }
    Ok((seconds > NOTE_RENDER_SECONDS).then_some(what))
}

/// The flag a settings error is about, with the message.
fn flag_of(e: &render::SettingsError) -> String {
    use render::SettingsError as E;
    let flag = match e {
        E::Width(_) => "width",
        E::Height(_) => "height",
        E::Spp => "spp",
        E::MaxDepth(_) => "max-depth",
        E::Threads => "threads",
    };
    format!("{flag}: {e}")
}

/// The parameters of preset `name` with the overrides (what the baker records in the LUT).
fn preset_input(
    name: &str,
    presets: &PresetsArgs,
    set: &[String],
) -> Result<FurParamsInput, Error> {
    let list = catalog::load(presets)?;
    let mut input = catalog::find(&list, name)?.input;
    bake::apply_overrides(&mut input, set).map_err(|e| Error::input(format!("--set {e}")))?;
    Ok(input)
}
