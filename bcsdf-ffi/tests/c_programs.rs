//! The C and C++ clients (`tests/c/eval.c`, `tests/c/eval.cpp`) compiled with the system
//! compiler against `target/release/libbcsdf_ffi.a` (built here with `cargo build --release
//! -p bcsdf-ffi`, i.e. with panic = "abort"), run on a baked LUT, and compared with
//! `BakedBcsdf` bit for bit. eval.c also drives every function with bad input (NULL,
//! zero lengths, misalignment, never-opened, closed and other-build fur_luts, a fur_lut
//! used after its bytes were freed, overlapping buffers, 10⁵ mutated blobs): any crash or
//! abort fails this test.
//!
//! The dual-scattering clients (`tests/c/dual.c`, `tests/c/dual.cpp`) run on a `.furdual`
//! blob computed here from the same baked LUT, and are compared with `DualLut::eval` and
//! `DualLut::eval_dirs` bit for bit (statuses too), with fiber counts toward the light and
//! below the point (`Fibers`: finite coats and the semi-infinite one); dual.c drives `fur_dual_*` with bad
//! input (NULL, misalignment, never-opened, closed and other-build fur_duals, overlaps,
//! each refusal status of a corrupt blob, 3000 mutated blobs) and pairs it with LUTs through
//! `fur_dual_check_lut` (the LUT it was computed from, another LUT, blobs recording another
//! source or none, closed handles).
//!
//! eval.c and eval.cpp also call every colour (`_at`) entry point: at the LUT's own colour
//! (equal to the functions without `_at`), at 24 pseudo-random colours (eval.c's
//! `colour_channel`, repeated here by [`c_colours`]: channels 0, below 20, in [100, 1000) and
//! above 1000) and a melanin mix, compared with `BakedBcsdf::at` bit for bit; eval.c also
//! refuses NaN, negative and NULL colours and overlapping outputs.
//!
//! The same clients also run under Valgrind memcheck and built with
//! `-fsanitize=address,undefined`: any error report fails those tests. Where `valgrind` or
//! the sanitizer runtimes are missing they print "skipped: …" and pass, unless
//! `FUR_BCSDF_REQUIRE_TOOLS` is set (CI installs them and sets it).

use bake::profiles::{build_model, ProfileOptions};
use bcsdf_core::baked::BakedBcsdf;
use bcsdf_core::dual::{self, Attenuation, Density, DualLut, DualTables, Fibers, Quadrature};
use bcsdf_core::lut::LutResolution;
use bcsdf_core::{presets, Absorption, Angles, Bcsdf, FurParams, Libm, Rgb, Sample};
use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::sync::OnceLock;

/// The default LUT resolution with six absorption planes instead of 22 (the quadratic
/// cells still start at four different planes): two residual simulations per energy-closure
/// bake instead of eight. What this file checks does not depend on the axis's node count;
/// colour_budget measures the axis's accuracy at the default.
const TEST_RESOLUTION: LutResolution = LutResolution {
    n_abs: 6,
    ..LutResolution::DEFAULT
};

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
    let output = try_compile(compiler, flags, source, lib, out);
    assert!(
        output.status.success(),
        "{compiler} failed:\n{}",
        String::from_utf8_lossy(&output.stderr)
    );
}

/// [`compile`], returning the compiler's output whatever its status.
fn try_compile(compiler: &str, flags: &[&str], source: &Path, lib: &Path, out: &Path) -> Output {
    Command::new(compiler)
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
        .unwrap_or_else(|e| panic!("cannot run {compiler}: {e}"))
}

fn lut(res: LutResolution) -> Vec<u8> {
    let preset = presets::find("bobcat").unwrap();
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

/// The colours eval.c draws (its `colour_channel`): 24 colours, 3 channels each.
fn c_colours() -> Vec<[f32; 3]> {
    let mut state: u64 = 0x2545_f491_4f6c_dd1d;
    let scale = [0.01f32, 0.1, 1.0, 4.0, 20.0];
    let mut channel = || {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        let r = (state >> 33) as u32;
        let u = (r & 0xffff) as f32 * (1.0 / 65536.0);
        match (r >> 16) & 7 {
            0 => 0.0,
            1 => 100.0 + 900.0 * u,
            2 => 1000.0 + 4000.0 * u,
            k => u * scale[k as usize - 3],
        }
    };
    (0..24).map(|_| [channel(), channel(), channel()]).collect()
}

fn sample_fields(s: &Sample) -> String {
    format!(
        "{} {} {} {} {} {} {}",
        hex(s.angles.theta_i()),
        hex(s.angles.phi()),
        hex(s.pdf),
        hex(s.weight.0[0]),
        hex(s.weight.0[1]),
        hex(s.weight.0[2]),
        s.family as i32
    )
}

/// The lines eval.c prints for the colour entry points, from `BakedBcsdf::at`.
fn expected_colours(l: &BakedBcsdf<'_>) -> Vec<String> {
    let own = l.absorption().sigma().0;
    let mut out = vec![format!(
        "own {} {} {}",
        hex(own[0]),
        hex(own[1]),
        hex(own[2])
    )];
    let colours = c_colours();
    // The draw covers the axis: lossless channels, the knee, >= 100 and the clamped end.
    let all: Vec<f32> = colours.iter().flatten().copied().collect();
    assert!(all.contains(&0.0) && all.iter().any(|&c| c > 0.0 && c < 1.25));
    assert!(all.iter().any(|&c| (100.0..1000.0).contains(&c)));
    assert!(all.iter().any(|&c| c > 1000.0));
    let mut batch = Vec::new();
    for (k, c) in colours.iter().enumerate() {
        let i = k % 6;
        out.push(format!(
            "colour {k} {} {} {}",
            hex(c[0]),
            hex(c[1]),
            hex(c[2])
        ));
        let at = l.at(&Absorption::from_sigma(Rgb(*c)).unwrap());
        let a = Angles::new(TI[i], TR[i], PH[i]).unwrap();
        let f = at.eval(&a);
        let t = f.total().0;
        out.push(format!("evalat {} {} {}", hex(t[0]), hex(t[1]), hex(t[2])));
        batch.extend(t.map(hex));
        let fam: Vec<String> = f.as_array().iter().flat_map(|c| c.0.map(hex)).collect();
        out.push(format!("familiesat {}", fam.join(" ")));
        out.push(format!("pdfat {}", hex(at.pdf(&a))));
        let d = at
            .eval_dirs([0.3, 0.8, 0.2], [-0.6, 0.7, -0.1], [0.0, 0.2, 1.0])
            .total()
            .0;
        out.push(format!("dirsat {} {} {}", hex(d[0]), hex(d[1]), hex(d[2])));
        let u = [0.1 + 0.03 * k as f32, 0.8, 0.37];
        let s = at.sample(TR[i], u).unwrap();
        out.push(format!("sampleat {}", sample_fields(&s)));
        out.push(format!(
            "samplepdfat {} {}",
            sample_fields(&s),
            hex(at.pdf(&a))
        ));
    }
    out.push(format!("batchat {}", batch.join(" ")));
    let m = Absorption::from_melanin(0.4, 1.5).unwrap().sigma().0;
    out.push(format!("melanin {} {} {}", hex(m[0]), hex(m[1]), hex(m[2])));
    out
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
    // fur_sample_pdf_far: the sample above and fur_pdf_far's density of the i-th query,
    // bit for bit (from the trait's separate calls, not from a view).
    for (i, tr) in TR.iter().enumerate() {
        let u = [0.1 + 0.15 * i as f32, 0.9 - 0.1 * i as f32, 0.37];
        let s = l.sample(*tr, u).unwrap();
        let p = l.pdf(&Angles::new(TI[i], TR[i], PH[i]).unwrap());
        out.push(format!(
            "samplepdf {} {} {} {} {} {} {} {}",
            hex(s.angles.theta_i()),
            hex(s.angles.phi()),
            hex(s.pdf),
            hex(s.weight.0[0]),
            hex(s.weight.0[1]),
            hex(s.weight.0[2]),
            s.family as i32,
            hex(p)
        ));
    }
    out.extend(expected_colours(&l));
    out
}

// The queries dual.c evaluates (its TI, TR, PH, FIBERS, BELOW, DF/DB, WI/WR/WT, DIR_FIBERS,
// DIR_BELOW).
const DUAL_TI: [f32; 8] = [0.5, -0.3, 1.2, 0.0, -1.5, 0.25, 2.0, 0.4];
const DUAL_TR: [f32; 8] = [-0.35, 0.1, -1.0, 0.0, 1.4, 0.6, 0.1, -0.2];
const DUAL_PH: [f32; 8] = [0.785, 3.0, -2.0, 0.0, 1.0, -0.1, 0.3, 7.0];
const DUAL_FIBERS: [f32; 9] = [
    0.0,
    0.25,
    1.0,
    2.75,
    40.0,
    1.0e7,
    f32::INFINITY,
    f32::NAN,
    -3.0,
];
// The fibers below the point: on the skin, fractional, finite, semi-infinite (+inf and NaN),
// negative (0), above MAX_FIBERS.
const DUAL_BELOW: [f32; 7] = [0.0, 2.5, 7.0, f32::INFINITY, f32::NAN, -2.0, 1.0e7];
/// d_f = d_b = 1, what the C programs pass where they do not vary the density factors.
const UNIT_DENSITY: Density = Density { d_f: 1.0, d_b: 1.0 };
const DUAL_DENSITY: [(f32, f32); 4] = [(1.0, 1.0), (0.5, 2.0), (f32::NAN, -1.0), (10.0, 10.0)];
type Dirs = ([f32; 3], [f32; 3], [f32; 3]);
const DUAL_DIRS: [Dirs; 7] = [
    ([0.3, 0.8, 0.2], [-0.6, 0.7, -0.1], [0.0, 0.2, 1.0]),
    ([0.1, -0.9, 0.4], [0.5, 0.5, 0.5], [1.0, 0.0, 0.0]),
    ([0.0, 0.0, 2.0], [0.3, 0.3, 0.9], [0.0, 0.0, 1.0]),
    ([0.0, 0.0, 0.0], [0.3, 0.3, 0.9], [0.0, 1.0, 0.0]),
    ([f32::NAN, 0.0, 1.0], [0.3, 0.3, 0.9], [0.0, 1.0, 0.0]),
    ([0.3, 0.8, 0.2], [-0.6, 0.7, -0.1], [0.0, 0.0, 0.0]),
    ([1.0e20, 1.0e20, -1.0e20], [0.5, -0.5, 0.1], [0.0, 0.0, 3.0]),
];
const DUAL_DIR_FIBERS: [f32; 4] = [0.0, 0.5, 3.0, f32::NAN];
const DUAL_DIR_BELOW: [f32; 4] = [0.0, 2.5, 7.0, f32::INFINITY];
// fur_status values the dual entry points return for these queries.
const FUR_OK: i32 = 0;
const FUR_ERR_ANGLE: i32 = 10;
const FUR_ERR_DIRECTION: i32 = 11;

/// The `.furdual` blob of a baked LUT: the pipeline's recipe (`bake::pipeline::dual_blob`) at
/// a coarser quadrature, to keep the test fast.
fn dual_blob(lut: &[u8]) -> Vec<u8> {
    let baked = BakedBcsdf::from_bytes(lut).unwrap();
    let mut tables = Box::new(DualTables::ZERO);
    let mut blob = vec![0u8; dual::BLOB_LEN];
    dual::encode_axis(
        (&mut blob[..]).try_into().unwrap(),
        &mut tables,
        |sigma, t| {
            let grey = bcsdf_core::Absorption::from_sigma(bcsdf_core::Rgb::splat(sigma)).unwrap();
            t.compute(
                &baked.at(&grey),
                Quadrature {
                    theta_steps: 32,
                    phi_steps: 16,
                },
            );
        },
        Attenuation::Coat,
        bcsdf_core::lut::checksum(lut),
        baked.absorption(),
    );
    blob
}

fn decoded(blob: &[u8]) -> Box<DualLut> {
    let mut d = Box::new(DualLut::EMPTY);
    d.decode(blob).unwrap();
    d
}

fn rgb_line(prefix: String, status: i32, v: [f32; 3]) -> String {
    format!(
        "{prefix} {status} {} {} {}",
        hex(v[0]),
        hex(v[1]),
        hex(v[2])
    )
}

/// `DualLut::eval` from angles, and the status `fur_eval_dual` returns.
fn dual_at(
    d: &DualLut,
    ti: f32,
    tr: f32,
    ph: f32,
    fibers: Fibers,
    density: Density,
) -> (i32, [f32; 3]) {
    match Angles::new(ti, tr, ph) {
        Ok(a) => (FUR_OK, d.eval(&a, fibers, density).0),
        Err(_) => (FUR_ERR_ANGLE, [0.0; 3]),
    }
}

/// The lines dual.c prints for its evaluations, from the Rust API.
fn expected_dual(blob: &[u8]) -> Vec<String> {
    let d = decoded(blob);
    let mut out = Vec::new();
    for i in 0..DUAL_TI.len() {
        for (f, &n) in DUAL_FIBERS.iter().enumerate() {
            for (b, &m) in DUAL_BELOW.iter().enumerate() {
                for (k, &(d_f, d_b)) in DUAL_DENSITY.iter().enumerate() {
                    let (st, v) = dual_at(
                        &d,
                        DUAL_TI[i],
                        DUAL_TR[i],
                        DUAL_PH[i],
                        Fibers::new(n, m),
                        Density { d_f, d_b },
                    );
                    out.push(rgb_line(format!("dual {i} {f} {b} {k}"), st, v));
                }
            }
        }
    }
    for (i, &(wi, wr, t)) in DUAL_DIRS.iter().enumerate() {
        // The status: whether the directions are accepted (eval_dirs gives 0 otherwise).
        let st = match Angles::from_directions::<Libm>(wi, wr, t) {
            Ok(_) => FUR_OK,
            Err(_) => FUR_ERR_DIRECTION,
        };
        for (f, &n) in DUAL_DIR_FIBERS.iter().enumerate() {
            for (b, &m) in DUAL_DIR_BELOW.iter().enumerate() {
                let v = d.eval_dirs(wi, wr, t, Fibers::new(n, m), UNIT_DENSITY).0;
                out.push(rgb_line(format!("dualdirs {i} {f} {b}"), st, v));
            }
        }
    }
    out
}

/// The lines dual.cpp prints, from the Rust API.
fn expected_dual_cpp(blob: &[u8]) -> Vec<String> {
    let d = decoded(blob);
    let fibers = [0.0, 0.25, 3.5, f32::INFINITY, f32::NAN];
    let below = [0.0, 2.5, 7.0, f32::INFINITY, f32::NAN];
    let mut out = Vec::new();
    for i in 0..3 {
        for (f, &n) in fibers.iter().enumerate() {
            for (b, &m) in below.iter().enumerate() {
                let (st, v) = dual_at(
                    &d,
                    DUAL_TI[i],
                    DUAL_TR[i],
                    DUAL_PH[i],
                    Fibers::new(n, m),
                    UNIT_DENSITY,
                );
                out.push(rgb_line(format!("cppdual {i} {f} {b}"), st, v));
            }
        }
    }
    let (wi, wr, t) = DUAL_DIRS[0];
    for (b, &m) in below[..4].iter().enumerate() {
        let v = d
            .eval_dirs(
                wi,
                wr,
                t,
                Fibers::new(2.0, m),
                Density { d_f: 0.5, d_b: 2.0 },
            )
            .0;
        out.push(rgb_line(format!("cppdualdirs {b}"), FUR_OK, v));
    }
    out.push(
        "cppdual refused: the bytes are not a dual-scattering (.furdual) blob (bad magic)".into(),
    );
    out
}

/// The static library, the two LUT files and the `.furdual` file, made once per test process.
struct Fixture {
    lib: PathBuf,
    dir: tempfile::TempDir,
    blob: Vec<u8>,
    dual: Vec<u8>,
}

impl Fixture {
    fn dual_path(&self) -> PathBuf {
        self.dir.path().join("a.furdual")
    }

    fn lut_path(&self) -> PathBuf {
        self.dir.path().join("a.furlut")
    }

    fn small_path(&self) -> PathBuf {
        self.dir.path().join("small.furlut")
    }
}

fn fixture() -> &'static Fixture {
    static FIXTURE: OnceLock<Fixture> = OnceLock::new();
    FIXTURE.get_or_init(|| {
        let lib = static_library();
        let dir = tempfile::tempdir().unwrap();
        let blob = lut(TEST_RESOLUTION);
        let small = lut(LutResolution {
            n_sum: 64,
            n_theta_r: 6,
            n_phi: 16,
            n_ms_i: 8,
            n_ms_r: 8,
            n_abs: 3,
        });
        std::fs::write(dir.path().join("a.furlut"), &blob).unwrap();
        std::fs::write(dir.path().join("small.furlut"), &small).unwrap();
        let dual = dual_blob(&blob);
        std::fs::write(dir.path().join("a.furdual"), &dual).unwrap();
        Fixture {
            lib,
            dir,
            blob,
            dual,
        }
    })
}

const C_FLAGS: [&str; 6] = [
    "-std=c99",
    "-Wall",
    "-Wextra",
    "-Werror",
    "-pedantic",
    "-O1",
];
const CPP_FLAGS: [&str; 5] = ["-std=c++17", "-Wall", "-Wextra", "-Werror", "-O1"];

/// eval.c's output: the evaluations equal Rust's bit for bit, and every bad input was refused.
fn check_c_output(run: &Output, blob: &[u8]) {
    let stdout = String::from_utf8_lossy(&run.stdout);
    assert!(
        run.status.success(),
        "eval.c failed ({:?}):\n{stdout}\n{}",
        run.status,
        String::from_utf8_lossy(&run.stderr)
    );
    let lines: Vec<&str> = stdout.lines().collect();
    let want = expected(blob);
    assert_eq!(&lines[..want.len()], &want[..]);
    assert!(
        lines.contains(&"mutated refused 100000 of 100000"),
        "{stdout}"
    );
    assert_eq!(lines.last(), Some(&"bad-input ok"));
}

/// eval.cpp's output: its evaluations and sample equal Rust's bit for bit.
fn check_cpp_output(run: &Output, blob: &[u8]) {
    assert!(run.status.success(), "eval.cpp failed: {run:?}");
    let stdout = String::from_utf8_lossy(&run.stdout);
    let want = expected(blob);
    let evals: Vec<&String> = want.iter().filter(|l| l.starts_with("eval ")).collect();
    let got: Vec<&str> = stdout.lines().filter(|l| l.starts_with("eval ")).collect();
    assert_eq!(got, evals);
    let l = BakedBcsdf::from_bytes(blob).unwrap();
    let s = l.sample(0.3, [0.2, 0.4, 0.6]).unwrap();
    let line = format!(
        "sample {} {} {} {}",
        hex(s.angles.theta_i()),
        hex(s.angles.phi()),
        hex(s.pdf),
        s.family as i32
    );
    assert!(stdout.lines().any(|x| x == line), "{stdout}\nwanted {line}");
    // fur_sample_pdf_far: the same sample and fur_pdf_far's density of (TI[0], 0.3, PH[0]).
    let p = l.pdf(&Angles::new(TI[0], 0.3, PH[0]).unwrap());
    let line = format!(
        "samplepdf {} {} {} {} {}",
        hex(s.angles.theta_i()),
        hex(s.angles.phi()),
        hex(s.pdf),
        s.family as i32,
        hex(p)
    );
    assert!(stdout.lines().any(|x| x == line), "{stdout}\nwanted {line}");
    // The colour entry points at the LUT's own colour, lossless, (0.5, 2, 150) and melanin
    // (0.4, 1.5).
    let colours = [
        l.absorption(),
        Absorption::LOSSLESS,
        Absorption::from_sigma(Rgb([0.5, 2.0, 150.0])).unwrap(),
        Absorption::from_melanin(0.4, 1.5).unwrap(),
    ];
    let mut want = Vec::new();
    for (c, colour) in colours.iter().enumerate() {
        let at = l.at(colour);
        for i in 0..6 {
            let t = at
                .eval(&Angles::new(TI[i], TR[i], PH[i]).unwrap())
                .total()
                .0;
            want.push(format!(
                "evalat {c} {} {} {}",
                hex(t[0]),
                hex(t[1]),
                hex(t[2])
            ));
        }
        let s = at.sample(0.3, [0.2, 0.4, 0.6]).unwrap();
        let w = s.weight.0;
        want.push(format!(
            "sampleat {c} {} {} {} {} {} {}",
            hex(s.angles.theta_i()),
            hex(s.angles.phi()),
            hex(s.pdf),
            hex(w[0]),
            hex(w[1]),
            hex(w[2])
        ));
    }
    let got: Vec<&str> = stdout
        .lines()
        .filter(|l| l.starts_with("evalat ") || l.starts_with("sampleat "))
        .collect();
    assert_eq!(got, want);
    assert!(
        stdout
            .lines()
            .any(|x| x.starts_with("refused: a colour is invalid")),
        "{stdout}"
    );
}

/// dual.c's output: every evaluation equals Rust's bit for bit (and its status), there are no
/// other evaluation lines, and every bad input was refused.
fn check_dual_c_output(run: &Output, blob: &[u8]) {
    let stdout = String::from_utf8_lossy(&run.stdout);
    assert!(
        run.status.success(),
        "dual.c failed ({:?}):\n{stdout}\n{}",
        run.status,
        String::from_utf8_lossy(&run.stderr)
    );
    let lines: Vec<&str> = stdout.lines().collect();
    let want = expected_dual(blob);
    assert_eq!(want.len(), 8 * 9 * 7 * 4 + 7 * 4 * 4);
    assert_eq!(&lines[..want.len()], &want[..]);
    assert_eq!(
        &lines[want.len()..],
        &["dual mutated refused 3000 of 3000", "dual-bad-input ok"]
    );
}

/// dual.cpp's output: its evaluations equal Rust's bit for bit, the corrupt blob is refused.
fn check_dual_cpp_output(run: &Output, blob: &[u8]) {
    let stdout = String::from_utf8_lossy(&run.stdout);
    assert!(
        run.status.success(),
        "dual.cpp failed ({:?}):\n{stdout}\n{}",
        run.status,
        String::from_utf8_lossy(&run.stderr)
    );
    let lines: Vec<&str> = stdout.lines().collect();
    assert_eq!(lines, expected_dual_cpp(blob));
}

/// Whether a missing tool fails the test (CI) rather than skipping it.
fn tools_required() -> bool {
    std::env::var_os("FUR_BCSDF_REQUIRE_TOOLS").is_some()
}

/// The four clients (eval.c, eval.cpp, dual.c, dual.cpp), compiled into one folder.
struct Clients {
    eval: PathBuf,
    eval_cpp: PathBuf,
    dual: PathBuf,
    dual_cpp: PathBuf,
}

impl Clients {
    /// Compiles the four clients into `dir` with `c_flags` (cc) and `cpp_flags` (c++).
    fn build(dir: &Path, c_flags: &[&str], cpp_flags: &[&str]) -> Clients {
        let lib = &fixture().lib;
        let one = |compiler: &str, flags: &[&str], source: &str, name: &str| {
            let exe = dir.join(name);
            compile(
                compiler,
                flags,
                &manifest().join("tests/c").join(source),
                lib,
                &exe,
            );
            exe
        };
        Clients {
            eval: one("cc", c_flags, "eval.c", "eval"),
            eval_cpp: one("c++", cpp_flags, "eval.cpp", "eval_cpp"),
            dual: one("cc", c_flags, "dual.c", "dual"),
            dual_cpp: one("c++", cpp_flags, "dual.cpp", "dual_cpp"),
        }
    }

    /// Runs each client on the fixture's files through `run` (the program and its
    /// arguments: plainly, under Valgrind, with the sanitizers' options) and checks its
    /// output against the Rust API.
    fn check(&self, run: impl Fn(&Path, &[PathBuf]) -> Output) {
        let f = fixture();
        let (lut, small, dual) = (f.lut_path(), f.small_path(), f.dual_path());
        check_c_output(&run(&self.eval, &[lut.clone(), small.clone()]), &f.blob);
        check_cpp_output(&run(&self.eval_cpp, std::slice::from_ref(&lut)), &f.blob);
        check_dual_c_output(&run(&self.dual, &[dual.clone(), lut, small]), &f.dual);
        check_dual_cpp_output(&run(&self.dual_cpp, &[dual]), &f.dual);
    }
}

#[test]
fn c_and_cpp_clients_agree_with_rust_bit_for_bit() {
    let f = fixture();
    let dir = tempfile::tempdir().unwrap();
    Clients::build(dir.path(), &C_FLAGS, &CPP_FLAGS)
        .check(|exe, args| Command::new(exe).args(args).output().unwrap());

    // The README's example compiles as C99 and refuses a non-LUT with a status message.
    let example = dir.path().join("shade");
    compile(
        "cc",
        &C_FLAGS[..5],
        &manifest().join("examples/c/shade.c"),
        &f.lib,
        &example,
    );
    let run = Command::new(&example).output().unwrap();
    assert!(run.status.success(), "{run:?}");
    assert!(
        String::from_utf8_lossy(&run.stderr).contains("LUT refused: the LUT bytes are truncated")
    );
}

#[test]
fn c_and_cpp_clients_are_clean_under_valgrind_memcheck() {
    let probe = Command::new("valgrind").arg("--version").output();
    if !probe.is_ok_and(|o| o.status.success()) {
        assert!(
            !tools_required(),
            "valgrind is missing (FUR_BCSDF_REQUIRE_TOOLS is set)"
        );
        eprintln!("skipped: valgrind is not installed");
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let c_flags: Vec<&str> = C_FLAGS.iter().copied().chain(["-g"]).collect();
    let cpp_flags: Vec<&str> = CPP_FLAGS.iter().copied().chain(["-g"]).collect();
    // Any memcheck error (invalid read or write, uninitialised value used, bad free,
    // a definite or indirect leak) exits with 99.
    Clients::build(dir.path(), &c_flags, &cpp_flags).check(|exe, args| {
        Command::new("valgrind")
            .args([
                "--tool=memcheck",
                "--error-exitcode=99",
                "--leak-check=full",
                "--errors-for-leak-kinds=definite,indirect",
                "--track-origins=yes",
            ])
            .arg(exe)
            .args(args)
            .output()
            .unwrap()
    });
}

#[test]
fn c_and_cpp_clients_are_clean_under_address_and_undefined_sanitizers() {
    let f = fixture();
    let dir = tempfile::tempdir().unwrap();
    let sanitize = [
        "-g",
        "-fsanitize=address,undefined",
        "-fno-sanitize-recover=all",
        "-fno-omit-frame-pointer",
    ];
    let c_flags: Vec<&str> = C_FLAGS.iter().chain(&sanitize).copied().collect();
    // Whether the compiler has the sanitizer runtimes at all.
    let out = try_compile(
        "cc",
        &c_flags,
        &manifest().join("tests/c/eval.c"),
        &f.lib,
        &dir.path().join("probe"),
    );
    if !out.status.success() {
        let err = String::from_utf8_lossy(&out.stderr);
        let missing = err.contains("lasan") || err.contains("lubsan");
        assert!(
            missing && !tools_required(),
            "cc -fsanitize=address,undefined failed:\n{err}"
        );
        eprintln!("skipped: the compiler's libasan/libubsan are not installed");
        return;
    }
    let cpp_flags: Vec<&str> = CPP_FLAGS.iter().chain(&sanitize).copied().collect();
    // Any report stops the program with a failing status.
    Clients::build(dir.path(), &c_flags, &cpp_flags).check(|exe, args| {
        Command::new(exe)
            .args(args)
            .env("ASAN_OPTIONS", "detect_leaks=1:halt_on_error=1:exitcode=98")
            .env(
                "UBSAN_OPTIONS",
                "halt_on_error=1:print_stacktrace=1:exitcode=97",
            )
            .output()
            .unwrap()
    });
}
