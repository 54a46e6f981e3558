//! The C and C++ clients (`tests/c/eval.c`, `tests/c/eval.cpp`) compiled with the system
//! compiler against `target/release/libbcsdf_ffi.a` (built here with `cargo build --release
//! -p bcsdf-ffi`, i.e. with panic = "abort"), run on a baked LUT, and compared with
//! `BakedBcsdf` bit for bit. eval.c also drives every function with bad input (NULL,
//! zero lengths, misalignment, a never-opened fur_lut, 10⁵ mutated blobs): any crash or abort
//! fails this test.

use bake::profiles::{build_model, ProfileOptions};
use bcsdf_core::baked::BakedBcsdf;
use bcsdf_core::lut::LutResolution;
use bcsdf_core::{presets, Angles, Bcsdf, FurParams};
use std::path::{Path, PathBuf};
use std::process::Command;

const TI: [f32; 6] = [0.5, -0.3, 1.2, 0.0, -1.5, 0.25];
const TR: [f32; 6] = [-0.35, 0.1, -1.0, 0.0, 1.4, 0.6];
const PH: [f32; 6] = [0.785, 3.0, -2.0, 0.0, 1.0, -0.1];

fn manifest() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The workspace's target directory (this test runs from `<target>/<profile>/deps`).
fn target_dir() -> PathBuf {
    let exe = std::env::current_exe().unwrap();
    exe.ancestors().nth(3).unwrap().to_path_buf()
}

/// `cargo build --release -p bcsdf-ffi` into the same target directory; the static library.
fn static_library() -> PathBuf {
    let target = target_dir();
    let status = Command::new(env!("CARGO"))
        .args(["build", "--release", "-p", "bcsdf-ffi"])
        .env("CARGO_TARGET_DIR", &target)
        .status()
        .expect("run cargo");
    assert!(
        status.success(),
        "cargo build --release -p bcsdf-ffi failed"
    );
    let lib = target.join("release").join("libbcsdf_ffi.a");
    assert!(lib.is_file(), "{} missing", lib.display());
    lib
}

/// Compiles `source` with `compiler` and `flags` against the library.
fn compile(compiler: &str, flags: &[&str], source: &Path, lib: &Path, out: &Path) {
    let output = Command::new(compiler)
        .args(flags)
        .arg("-I")
        .arg(manifest().join("include"))
        .arg(source)
        .arg(lib)
        // The native libraries a Rust std static library needs on Linux
        // (`rustc --print native-static-libs`).
        .args([
            "-lgcc_s",
            "-lutil",
            "-lrt",
            "-lpthread",
            "-lm",
            "-ldl",
            "-lc",
        ])
        .arg("-o")
        .arg(out)
        .output()
        .unwrap_or_else(|e| panic!("cannot run {compiler}: {e}"));
    assert!(
        output.status.success(),
        "{compiler} failed:\n{}",
        String::from_utf8_lossy(&output.stderr)
    );
}

fn lut(res: LutResolution) -> Vec<u8> {
    let preset = presets::find("yan-row-a").unwrap();
    let params = FurParams::new(&preset.input).unwrap();
    let opts = ProfileOptions {
        budget: bake::profiles::scale_budget(bcsdf_core::PhotonBudget::DEFAULT, 0.02).unwrap(),
        cache_dir: Some(PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("fur-profile-cache")),
        ..ProfileOptions::default()
    };
    let (model, _) = build_model(params, &opts).unwrap();
    bake::tables::bake(&model, &preset.input, res)
}

fn hex(v: f32) -> String {
    format!("{:08x}", v.to_bits())
}

/// The lines eval.c prints for the evaluation entry points, from the Rust evaluator.
fn expected(blob: &[u8]) -> Vec<String> {
    let l = BakedBcsdf::from_bytes(blob).unwrap();
    let mut out = vec![format!(
        "version {} format {} model {}",
        env!("CARGO_PKG_VERSION"),
        bcsdf_core::lut::FORMAT_VERSION,
        bcsdf_core::MODEL_VERSION
    )];
    let mut batch = Vec::new();
    for i in 0..6 {
        let a = Angles::new(TI[i], TR[i], PH[i]).unwrap();
        let f = l.eval_far(&a);
        let t = f.total().0;
        out.push(format!("eval {} {} {}", hex(t[0]), hex(t[1]), hex(t[2])));
        let fam: Vec<String> = f.as_array().iter().flat_map(|c| c.0.map(hex)).collect();
        out.push(format!("families {}", fam.join(" ")));
        out.push(format!("pdf {}", hex(l.pdf(&a))));
        batch.extend(t.map(hex));
    }
    out.push(format!("batch {}", batch.join(" ")));
    let d = l
        .eval_dirs([0.3, 0.8, 0.2], [-0.6, 0.7, -0.1], [0.0, 0.2, 1.0])
        .total()
        .0;
    out.push(format!("dirs {} {} {}", hex(d[0]), hex(d[1]), hex(d[2])));
    for (i, tr) in TR.iter().enumerate() {
        let u = [0.1 + 0.15 * i as f32, 0.9 - 0.1 * i as f32, 0.37];
        let s = l.sample(*tr, u).unwrap();
        out.push(format!(
            "sample {} {} {} {} {} {} {}",
            hex(s.angles.theta_i()),
            hex(s.angles.phi()),
            hex(s.pdf),
            hex(s.weight.0[0]),
            hex(s.weight.0[1]),
            hex(s.weight.0[2]),
            s.family as i32
        ));
    }
    out
}

#[test]
fn c_and_cpp_clients_agree_with_rust_bit_for_bit() {
    let lib = static_library();
    let dir = tempfile::tempdir().unwrap();
    let blob = lut(LutResolution::DEFAULT);
    let small = lut(LutResolution {
        n_sum: 64,
        n_theta_r: 6,
        n_phi: 16,
        n_ms_i: 8,
        n_ms_r: 8,
    });
    let (lut_path, small_path) = (dir.path().join("a.furlut"), dir.path().join("small.furlut"));
    std::fs::write(&lut_path, &blob).unwrap();
    std::fs::write(&small_path, &small).unwrap();

    let c_exe = dir.path().join("eval");
    compile(
        "cc",
        &[
            "-std=c99",
            "-Wall",
            "-Wextra",
            "-Werror",
            "-pedantic",
            "-O1",
        ],
        &manifest().join("tests/c/eval.c"),
        &lib,
        &c_exe,
    );
    let run = Command::new(&c_exe)
        .arg(&lut_path)
        .arg(&small_path)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&run.stdout);
    assert!(
        run.status.success(),
        "eval.c failed ({:?}):\n{stdout}\n{}",
        run.status,
        String::from_utf8_lossy(&run.stderr)
    );
    let lines: Vec<&str> = stdout.lines().collect();
    let want = expected(&blob);
    assert_eq!(&lines[..want.len()], &want[..]);
    assert!(
        lines.contains(&"mutated refused 100000 of 100000"),
        "{stdout}"
    );
    assert_eq!(lines.last(), Some(&"bad-input ok"));

    // The README's example compiles as C99 and refuses a non-LUT with a status message.
    let example = dir.path().join("shade");
    compile(
        "cc",
        &["-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic"],
        &manifest().join("examples/c/shade.c"),
        &lib,
        &example,
    );
    let run = Command::new(&example).output().unwrap();
    assert!(run.status.success(), "{run:?}");
    assert!(
        String::from_utf8_lossy(&run.stderr).contains("LUT refused: the LUT bytes are truncated")
    );

    let cpp_exe = dir.path().join("eval_cpp");
    compile(
        "c++",
        &["-std=c++17", "-Wall", "-Wextra", "-Werror", "-O1"],
        &manifest().join("tests/c/eval.cpp"),
        &lib,
        &cpp_exe,
    );
    let run = Command::new(&cpp_exe).arg(&lut_path).output().unwrap();
    assert!(run.status.success(), "eval.cpp failed: {run:?}");
    let stdout = String::from_utf8_lossy(&run.stdout);
    let evals: Vec<&String> = want.iter().filter(|l| l.starts_with("eval ")).collect();
    let got: Vec<&str> = stdout.lines().filter(|l| l.starts_with("eval ")).collect();
    assert_eq!(got, evals);
    let l = BakedBcsdf::from_bytes(&blob).unwrap();
    let s = l.sample(0.3, [0.2, 0.4, 0.6]).unwrap();
    let line = format!(
        "sample {} {} {} {}",
        hex(s.angles.theta_i()),
        hex(s.angles.phi()),
        hex(s.pdf),
        s.family as i32
    );
    assert!(stdout.lines().any(|x| x == line), "{stdout}\nwanted {line}");
}
