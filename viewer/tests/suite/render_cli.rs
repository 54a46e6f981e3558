//! `viewer render` (docs/model.md §11): outputs written atomically inside --out, the JSON report,
//! the same EXR bytes for 1 and 2 threads, and bad input → exit 2 with one `error:` line.

use std::path::Path;
use std::process::{Command, Output};

fn viewer(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_viewer"))
        .args(args)
        .env_remove("FUR_BCSDF_CACHE")
        .output()
        .expect("viewer runs")
}

fn render(out: &Path, threads: &str) -> Output {
    render_with(out, threads, &[])
}

/// The small patch every render here draws: 300 fibers, 2 spp, 16 × 12 pixels.
const SMALL_PATCH: [&str; 10] = [
    "--scene", "patch", "--fibers", "300", "--spp", "2", "--width", "16", "--height", "12",
];

/// Renders into `out` with the profile cache in `out`'s parent folder (a test's temporary
/// folder): the first render of a test generates the preset's profiles and residuals for the
/// LUT it bakes in memory, the second reads them.
fn render_with(out: &Path, threads: &str, extra: &[&str]) -> Output {
    let cache = out.parent().unwrap().join("cache");
    let mut args = vec!["render", "--preset", "human-hair"];
    args.extend_from_slice(&SMALL_PATCH);
    args.extend_from_slice(&[
        "--max-depth",
        "6",
        "--threads",
        threads,
        "--cache-dir",
        cache.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    args.extend_from_slice(extra);
    viewer(&args)
}

/// `--compare`: path | dual | single | |dual − path| in one picture, the numbers
/// in compare.json, the same bits for 1 and 2 threads.
#[test]
fn compare_writes_the_four_panels_and_the_numbers() {
    let dir = tempfile::tempdir().unwrap();
    let (a, b) = (dir.path().join("a"), dir.path().join("b"));
    let run = render_with(&a, "1", &["--compare"]);
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let stdout = String::from_utf8_lossy(&run.stdout);
    assert!(
        stdout.contains("dual") && stdout.contains("single"),
        "{stdout}"
    );
    assert!(render_with(&b, "2", &["--compare"]).status.success());
    let mut names: Vec<String> = std::fs::read_dir(&a)
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    names.sort();
    assert_eq!(names, ["compare.exr", "compare.json", "compare.png"]);
    assert!(
        std::fs::read(a.join("compare.exr")).unwrap()
            == std::fs::read(b.join("compare.exr")).unwrap(),
        "1 and 2 threads differ"
    );
    // Four 16-pixel panels side by side (PNG IHDR: width, height big-endian at 16..24).
    let png = std::fs::read(a.join("compare.png")).unwrap();
    assert_eq!(u32::from_be_bytes(png[16..20].try_into().unwrap()), 64);
    assert_eq!(u32::from_be_bytes(png[20..24].try_into().unwrap()), 12);
    let report: serde_json::Value =
        serde_json::from_slice(&std::fs::read(a.join("compare.json")).unwrap()).unwrap();
    for m in ["dual", "single"] {
        for k in ["mean_error", "tile_rmse", "fur_mean_error", "fur_tile_rmse"] {
            let v = report["against_path"][m][k].as_f64();
            assert!(v.is_some_and(f64::is_finite), "{m} {k}: {report}");
        }
    }
    assert_eq!(report["panels"][3], "|dual - path|");
    // One render per method otherwise: --compare and --method exclude each other.
    let o = render_with(
        &dir.path().join("c"),
        "1",
        &["--compare", "--method", "dual"],
    );
    assert_eq!(o.status.code(), Some(2));
}

#[test]
fn writes_exr_png_and_json_inside_out_and_nothing_else() {
    let dir = tempfile::tempdir().unwrap();
    let (a, b) = (dir.path().join("a"), dir.path().join("b"));
    let run = render(&a, "1");
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    assert!(render(&b, "2").status.success());
    let mut names: Vec<String> = std::fs::read_dir(&a)
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    names.sort();
    // No temporary file is left behind: every file went through the atomic writer.
    assert_eq!(names, ["render.exr", "render.json", "render.png"]);
    let exr = std::fs::read(a.join("render.exr")).unwrap();
    assert_eq!(&exr[..4], &[0x76, 0x2f, 0x31, 0x01]);
    assert!(
        exr == std::fs::read(b.join("render.exr")).unwrap(),
        "1 and 2 threads differ"
    );
    let png = std::fs::read(a.join("render.png")).unwrap();
    assert_eq!(&png[1..4], b"PNG");
    let report: serde_json::Value =
        serde_json::from_slice(&std::fs::read(a.join("render.json")).unwrap()).unwrap();
    assert_eq!(report["scene"], "patch");
    // --preset renders with the preset baked in memory unless --evaluator analytic, and
    // says so.
    assert_eq!(report["evaluator"], "baked");
    let said = String::from_utf8_lossy(&run.stdout);
    assert!(
        said.contains("baked evaluator (the preset baked in memory)"),
        "{said}"
    );
    assert_eq!(report["spp"], 2);
    assert_eq!(report["paths"], 16 * 12 * 2);
    assert!(report["rays_per_second"].as_f64().unwrap() > 0.0);
    let orders = report["energy_per_bounce_order"].as_array().unwrap();
    assert_eq!(orders.len(), 7);
    let mean = report["mean_radiance"][0].as_f64().unwrap();
    let sum: f64 = orders.iter().map(|o| o[0].as_f64().unwrap()).sum();
    assert!(
        (sum - mean).abs() <= 1e-6 * mean.max(1e-6),
        "orders sum {sum} vs mean {mean}"
    );
}

#[test]
fn bad_input_exits_2_with_one_error_line() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let out = out.to_str().unwrap();
    let base = ["render", "--preset", "human-hair", "--out", out];
    for (extra, needle) in [
        (
            vec!["--scene", "cube", "--spp", "1"],
            "unknown scene `cube`",
        ),
        (vec!["--scene", "ball", "--spp", "0"], "--spp"),
        (
            vec!["--scene", "ball", "--spp", "1", "--width", "0"],
            "--width",
        ),
        (
            vec!["--scene", "ball", "--spp", "1", "--max-depth", "0"],
            "--max-depth",
        ),
        (
            vec!["--scene", "ball", "--spp", "1", "--fibers", "0"],
            "--fibers 0",
        ),
        (
            vec!["--scene", "ball", "--spp", "1", "--exposure", "0"],
            "--exposure",
        ),
        (
            vec!["--scene", "ball", "--spp", "1", "--set", "kappa=7"],
            "kappa",
        ),
    ] {
        let mut args = base.to_vec();
        args.extend(extra.iter().copied());
        let o = viewer(&args);
        crate::assert_refused(&o, &args, &[needle]);
    }
    // --lut with the analytic evaluator, and a missing LUT.
    for (args, needle) in [
        (
            vec![
                "render",
                "--scene",
                "ball",
                "--spp",
                "1",
                "--lut",
                "x.furlut",
                "--evaluator",
                "analytic",
                "--out",
                out,
            ],
            "--evaluator baked",
        ),
        (
            vec![
                "render",
                "--scene",
                "ball",
                "--spp",
                "1",
                "--lut",
                "missing.furlut",
                "--out",
                out,
            ],
            "missing.furlut",
        ),
    ] {
        let o = viewer(&args);
        crate::assert_refused(&o, &args, &[needle]);
    }
    // Nothing was rendered into the folder.
    assert!(!Path::new(out).join("render.exr").exists());
}

/// `--lut FILE` with `dual`: the `.furdual` of the same name beside it (what `bake` writes
/// with the LUT) is what the term reads, and only if it was computed from that LUT
/// (`DualLut::check_lut`); without one the tables are computed from the LUT.
#[test]
fn dual_reads_the_furdual_beside_the_lut_only_if_it_was_computed_from_it() {
    use bcsdf_core::baked::BakedBcsdf;
    use bcsdf_core::dual::{encode, Attenuation, DualTables, Quadrature};
    use bcsdf_core::lut::LutResolution;
    use bcsdf_core::{presets, FurParams};

    let dir = tempfile::tempdir().unwrap();
    // Human hair: no medulla, so no photon profiles to simulate.
    let preset = presets::find("human-hair").unwrap();
    let params = FurParams::new(&preset.input).unwrap();
    let (model, _) =
        bake::profiles::build_model(params, &bake::profiles::ProfileOptions::default()).unwrap();
    let blob = bake::tables::bake(&model, &preset.input, LutResolution::DEFAULT);
    let lut_path = dir.path().join("hair.furlut");
    std::fs::write(&lut_path, &blob).unwrap();
    let baked = BakedBcsdf::from_bytes(&blob).unwrap();
    let mut tables = Box::new(DualTables::ZERO);
    tables.compute(
        &baked,
        Quadrature {
            theta_steps: 16,
            phi_steps: 8,
        },
    );
    let dual_path = dir.path().join("hair.furdual");
    let render = |name: &str| {
        let out = dir.path().join(name);
        let mut args = vec!["render", "--lut", lut_path.to_str().unwrap()];
        args.extend_from_slice(&SMALL_PATCH);
        args.extend_from_slice(&["--method", "dual", "--out", out.to_str().unwrap()]);
        let o = viewer(&args);
        (o, out.join("render.exr"))
    };

    // No .furdual: the tables come from the LUT.
    let (o, computed) = render("computed");
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    // The pair bake would write (coarser tables here): read, so the image changes.
    std::fs::write(
        &dual_path,
        encode(&tables, Attenuation::Coat, baked.checksum()),
    )
    .unwrap();
    let (o, stored) = render("stored");
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert_ne!(
        std::fs::read(&computed).unwrap(),
        std::fs::read(&stored).unwrap()
    );
    // Tables of another LUT, and tables that record none: refused, naming the file.
    for source in [baked.checksum() ^ 1, 0] {
        std::fs::write(&dual_path, encode(&tables, Attenuation::Coat, source)).unwrap();
        let (o, exr) = render(&format!("refused-{source}"));
        crate::assert_refused(&o, &source, &["hair.furdual"]);
        assert!(!exr.exists());
    }
}
