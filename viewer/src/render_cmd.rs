//! `viewer render`: path-traces a built-in scene with the `render` crate and writes
//! render.exr, render.png and render.json through `bake::fsutil` (docs/model.md §11).

use crate::catalog;
use crate::cli::{Evaluator, Method as MethodArg, PresetsArgs, ProfileArgs, RenderArgs};
use crate::error::Error;
use crate::json;
use crate::source::{preset_model, read_lut};
use bake::fsutil;
use bcsdf_core::baked::BakedBcsdf;
use bcsdf_core::dual::{Attenuation, Density, DualTables, Quadrature};
use bcsdf_core::lut::LutResolution;
use bcsdf_core::{Bcsdf, FurParamsInput};
use render::scatter::One;
use render::{integrator, output, scenes, Method, Render, SceneKind, SceneOptions, Settings};
use serde_json::json;
use std::io::Write;

/// Runs `viewer render`.
pub fn run(args: &RenderArgs) -> Result<(), Error> {
    let kind: SceneKind = args
        .scene
        .parse()
        .map_err(|e| Error::input(format!("--scene: {e}")))?;
    let settings = Settings {
        max_depth: args.max_depth,
        seed: args.seed,
        threads: args.threads,
        progress: true,
        ..Settings::new(args.width, args.height, args.spp)
    };
    settings
        .validate()
        .map_err(|e| Error::input(format!("--{}", flag_of(&e))))?;
    if args.fibers == Some(0) {
        return Err(Error::input("--fibers 0: a scene needs at least one fiber"));
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
        (None, Some(_)) => Evaluator::Baked,
        (None, None) => Evaluator::Analytic,
    };
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
        (
            path.display().to_string(),
            trace(&scene, &baked, &settings, args)?,
        )
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
            Evaluator::Analytic => trace(&scene, &model.model(), &settings, args)?,
            Evaluator::Baked => {
                let input = preset_input(preset, &args.presets, &args.set)?;
                let blob = bake::tables::bake(&model, &input, LutResolution::DEFAULT);
                let baked = BakedBcsdf::from_bytes(&blob)
                    .map_err(|e| Error::Failure(format!("the LUT baked in memory: {e}")))?;
                trace(&scene, &baked, &settings, args)?
            }
        };
        (preset.to_string(), r)
    };

    let exr = output::exr_bytes(&r.image).map_err(|e| Error::Failure(e.to_string()))?;
    let png =
        output::png_bytes(&r.image, args.exposure).map_err(|e| Error::Failure(e.to_string()))?;
    let whole = r.image.whole();
    let report = json!({
        "scene": kind.name(),
        "fibers": args.fibers.unwrap_or(kind.default_fibers()),
        "segments": scene.segment_count(),
        "preset": name,
        "set": args.set,
        "evaluator": match evaluator { Evaluator::Analytic => "analytic", Evaluator::Baked => "baked" },
        "method": method_name(args.method),
        "d_f": args.d_f,
        "d_b": args.d_b,
        "width": args.width,
        "height": args.height,
        "spp": args.spp,
        "max_depth": args.max_depth,
        "seed": args.seed,
        "seconds": r.seconds,
        "paths": r.paths,
        "rays": r.rays,
        "paths_per_second": r.paths as f64 / r.seconds.max(1e-9),
        "rays_per_second": r.rays as f64 / r.seconds.max(1e-9),
        "mean_radiance": whole.mean,
        "mean_radiance_std_error": whole.std_error,
        "energy_per_bounce_order": r.orders,
    });
    for (file, bytes) in [
        ("render.exr", exr),
        ("render.png", png),
        ("render.json", json::pretty(&report).into_bytes()),
    ] {
        fsutil::write_atomic(&args.out.join(file), &bytes)?;
    }
    let _ = writeln!(
        std::io::stdout().lock(),
        "{} {} {}x{} {} spp: {:.2} s, {:.3} M rays/s, mean radiance [{:.4}, {:.4}, {:.4}] -> {}",
        kind.name(),
        method_name(args.method),
        args.width,
        args.height,
        args.spp,
        r.seconds,
        r.rays as f64 / r.seconds.max(1e-9) / 1e6,
        whole.mean[0],
        whole.mean[1],
        whole.mean[2],
        args.out.display()
    );
    Ok(())
}

fn method_name(m: MethodArg) -> &'static str {
    match m {
        MethodArg::Path => "path",
        MethodArg::Dual => "dual",
        MethodArg::Single => "single",
    }
}

/// Renders with one evaluator and the method of `args` (for `dual`, the tables are computed
/// from that evaluator first, docs/model.md §13).
fn trace<B: Bcsdf + Sync>(
    scene: &render::scene::Scene,
    bcsdf: &B,
    settings: &Settings,
    args: &RenderArgs,
) -> Result<Render, Error> {
    let mut tables = Box::new(DualTables::ZERO);
    let method = match args.method {
        MethodArg::Path => Method::Path,
        MethodArg::Single => Method::Single,
        MethodArg::Dual => {
            tables.compute(bcsdf, Quadrature::DEFAULT);
            Method::Dual {
                tables: &tables,
                density: Density {
                    d_f: args.d_f,
                    d_b: args.d_b,
                },
                attenuation: Attenuation::Coat,
            }
        }
    };
    integrator::render_method(scene, &One(bcsdf), settings, &method)
        .map_err(|e| Error::input(e.to_string()))
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
