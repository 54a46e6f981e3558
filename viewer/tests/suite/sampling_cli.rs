//! `viewer probe --lut`, `viewer probe --pdf` and `viewer sample` end to end, against the
//! library in-process:
//! (Over 600 lines: twelve end-to-end cases sharing the in-process reference harness.)
//!
//! - `probe --lut` reads a `.furlut` and the `.exr` of the same LUT (told apart by content,
//!   whatever the name) and prints the same lines, bit for bit `BakedBcsdf::eval`;
//! - `--pdf` appends `"pdf":p`, bit for bit `Bcsdf::pdf`, to the unchanged line, for a
//!   preset and for a LUT; `--stdin` with `--lut` answers like single probes and rejects a
//!   line with h by its number;
//! - `viewer sample` prints N lines that are the library's own draws from the documented
//!   PCG32 stream, each with the pdf of its direction and non-negative weights; the same
//!   seed gives the same output and another seed another; a zero-albedo LUT prints nothing
//!   and a note;
//! - bad input (N = 0, θ_r at or past 90°, NaN, missing, garbage or truncated LUT) exits 2
//!   with one `error:` line.
//!
//! LUTs are baked here from `human-hair` (no medulla profiles, so no photon budget to set)
//! and written with `bake::lutfile::write_blob`; only `exr_lut_reads_like_the_furlut` needs
//! the OpenEXR form (`write_exr`). Every run has `FUR_BCSDF_CACHE` pointing at a temporary
//! directory.

use bake::lutfile::{self, LutFile, LutMeta};
use bake::profiles::{self, OwnedModel, ProfileOptions};
use bcsdf_core::baked::BakedBcsdf;
use bcsdf_core::lut::{self, LutResolution, Table};
use bcsdf_core::rng::Pcg32;
use bcsdf_core::{presets, Angles, Bcsdf, FurParams, Lobe, LobeFamily};
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::sync::OnceLock;

/// The preset of every test here: its model needs no medulla profiles.
const PRESET: &str = "human-hair";

/// Query angles (degrees): ordinary ones, both signs, φ = 0 and ±180, grazing θ.
const ANGLES: [[f32; 3]; 8] = [
    [30.0, -20.0, 45.0],
    [20.0, -25.0, 180.0],
    [-10.0, 10.0, -30.0],
    [0.0, 0.0, 0.0],
    [60.0, -50.0, -180.0],
    [-85.0, 40.0, 90.0],
    [12.5, 33.0, 170.0],
    [45.0, 89.0, -5.0],
];

fn temp_dir() -> tempfile::TempDir {
    tempfile::Builder::new()
        .prefix("viewer-sampling-")
        .tempdir_in(env!("CARGO_TARGET_TMPDIR"))
        .unwrap()
}

/// The profile cache the viewer runs see (never the user's).
fn cache() -> &'static Path {
    static DIR: OnceLock<tempfile::TempDir> = OnceLock::new();
    DIR.get_or_init(temp_dir).path()
}

/// The analytic model of [`PRESET`], as the viewer builds it.
fn model() -> &'static OwnedModel {
    static MODEL: OnceLock<OwnedModel> = OnceLock::new();
    MODEL.get_or_init(|| {
        let p = presets::find(PRESET).unwrap();
        let params = FurParams::new(&p.input).unwrap();
        assert!(!profiles::needs_profiles(&params));
        let opts = ProfileOptions {
            cache_dir: None,
            ..ProfileOptions::default()
        };
        profiles::build_model(params, &opts).unwrap().0
    })
}

/// [`PRESET`] baked at the default resolution, written as `human-hair.furlut` in a
/// directory of its own.
struct Lut {
    dir: tempfile::TempDir,
    blob: Vec<u8>,
    furlut: PathBuf,
}

fn baked_lut() -> &'static Lut {
    static LUT: OnceLock<Lut> = OnceLock::new();
    LUT.get_or_init(|| {
        let p = presets::find(PRESET).unwrap();
        let blob = bake::tables::bake(model(), &p.input, LutResolution::DEFAULT);
        let dir = temp_dir();
        let furlut = dir.path().join("human-hair.furlut");
        lutfile::write_blob(&furlut, &blob).unwrap();
        Lut { dir, blob, furlut }
    })
}

/// The same LUT as OpenEXR, `human-hair.exr` beside the `.furlut` (written on first use, so
/// that only the tests of the EXR form depend on `bake::lutfile::write_exr`).
fn exr_file() -> &'static Path {
    static EXR: OnceLock<PathBuf> = OnceLock::new();
    EXR.get_or_init(|| {
        let path = baked_lut().dir.path().join("human-hair.exr");
        let file = LutFile {
            blob: baked_lut().blob.clone(),
            meta: LutMeta {
                preset: PRESET.to_string(),
                errors: None,
            },
        };
        lutfile::write_exr(&path, &file)
            .unwrap_or_else(|e| panic!("bake::lutfile::write_exr cannot write the LUT: {e}"));
        path
    })
}

fn baked() -> BakedBcsdf<'static> {
    BakedBcsdf::from_bytes(&baked_lut().blob).unwrap()
}

fn path_str(p: &Path) -> &str {
    p.to_str().expect("UTF-8 temporary path")
}

fn viewer(args: &[&str], stdin: Option<&str>) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_viewer"))
        .args(args)
        .env("FUR_BCSDF_CACHE", cache())
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("spawning viewer");
    let mut pipe = child.stdin.take().unwrap();
    if let Some(text) = stdin {
        pipe.write_all(text.as_bytes()).unwrap();
    }
    drop(pipe);
    child.wait_with_output().unwrap()
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8(bytes.to_vec()).expect("UTF-8 output")
}

/// Runs successfully with nothing on stderr and returns stdout.
#[track_caller]
fn ok(args: &[&str], stdin: Option<&str>) -> String {
    let o = viewer(args, stdin);
    assert!(
        o.status.success(),
        "viewer {args:?} failed: {}\n{}",
        o.status,
        text(&o.stderr)
    );
    assert!(
        o.stderr.is_empty(),
        "unexpected stderr: {}",
        text(&o.stderr)
    );
    text(&o.stdout)
}

/// Exits with code 2 and exactly one stderr line, starting `error:` and holding every
/// needle; returns the output.
#[track_caller]
fn bad_input(args: &[&str], stdin: Option<&str>, needles: &[&str]) -> Output {
    let o = viewer(args, stdin);
    crate::assert_refused(&o, &args, needles);
    o
}

fn one_line(out: &str) -> &str {
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(lines.len(), 1, "one line expected: {out:?}");
    assert!(out.ends_with('\n'));
    lines[0]
}

/// A JSON line read exactly: the keys in order, each with the numbers after it, each number
/// parsed straight to f32 (the line is also checked to be JSON).
fn tokens(line: &str) -> Vec<(String, Vec<f32>)> {
    serde_json::from_str::<serde_json::Value>(line)
        .unwrap_or_else(|e| panic!("not JSON ({e}): {line}"));
    let cleaned: String = line
        .chars()
        .map(|c| if "{}[]:,".contains(c) { ' ' } else { c })
        .collect();
    let mut keys: Vec<(String, Vec<f32>)> = Vec::new();
    for tok in cleaned.split_whitespace() {
        if let Some(name) = tok.strip_prefix('"').and_then(|t| t.strip_suffix('"')) {
            keys.push((name.to_string(), Vec::new()));
        } else {
            let v: f32 = tok.parse().unwrap_or_else(|_| panic!("bad number {tok}"));
            keys.last_mut().expect("number before any key").1.push(v);
        }
    }
    keys
}

/// What a line should read as: `(key, numbers)` in order.
type Expected = Vec<(String, Vec<f32>)>;

/// The analytic far field of `a` as `viewer probe` prints it, with the pdf if given.
fn expected_lobes(a: &Angles, pdf: Option<f32>) -> Expected {
    let lobes = model().model().eval_far_lobes(a);
    let mut want = vec![
        ("total".to_string(), lobes.total().0.to_vec()),
        ("lobes".to_string(), vec![]),
    ];
    want.extend(
        lobes
            .iter()
            .map(|(l, v)| (l.name().to_string(), v.0.to_vec())),
    );
    want.extend(pdf.map(|p| ("pdf".to_string(), vec![p])));
    want
}

/// The LUT's far field of `a` per family (`Bcsdf::eval`), with the pdf if given.
fn expected_families(a: &Angles, pdf: Option<f32>) -> Expected {
    let families = Bcsdf::eval(&baked(), a);
    let mut want = vec![
        ("total".to_string(), families.total().0.to_vec()),
        ("families".to_string(), vec![]),
    ];
    want.extend(
        LobeFamily::ALL
            .iter()
            .map(|&f| (f.name().to_string(), families.get(f).0.to_vec())),
    );
    want.extend(pdf.map(|p| ("pdf".to_string(), vec![p])));
    want
}

/// Bit-for-bit equality of read lines (so that 0 and −0 or NaN payloads cannot hide).
#[track_caller]
fn assert_same_bits(got: &Expected, want: &Expected, context: &str) {
    let bits = |e: &Expected| -> Vec<(String, Vec<u32>)> {
        e.iter()
            .map(|(k, v)| (k.clone(), v.iter().map(|x| x.to_bits()).collect()))
            .collect()
    };
    assert_eq!(bits(got), bits(want), "{context}");
}

fn angle_strings(a: &[f32; 3]) -> [String; 3] {
    a.map(|v| v.to_string())
}

/// `viewer probe SOURCE --theta-i … --theta-r … --phi …` plus `extra`.
fn probe(source: &[&str], a: &[f32; 3], extra: &[&str]) -> String {
    let s = angle_strings(a);
    let mut args = vec!["probe"];
    args.extend_from_slice(source);
    args.extend(["--theta-i", &s[0], "--theta-r", &s[1], "--phi", &s[2]]);
    args.extend_from_slice(extra);
    one_line(&ok(&args, None)).to_string()
}

fn angles(a: &[f32; 3]) -> Angles {
    Angles::from_degrees(a[0], a[1], a[2]).unwrap()
}

#[test]
fn probe_lut_matches_the_library_bit_for_bit() {
    let furlut = path_str(&baked_lut().furlut);
    let mut lit = 0;
    for a in &ANGLES {
        let line = probe(&["--lut", furlut], a, &[]);
        assert!(line.starts_with("{\"total\":["), "{line}");
        assert_same_bits(
            &tokens(&line),
            &expected_families(&angles(a), None),
            &format!("{a:?}: {line}"),
        );
        if Bcsdf::eval(&baked(), &angles(a)).total().max_channel() > 0.0 {
            lit += 1;
        }
    }
    assert!(lit >= 6, "the queries should mostly see light");

    // The reader goes by content, not by name: a raw blob called *.exr reads the same.
    let dir = temp_dir();
    let blob_as_exr = dir.path().join("blob.exr");
    std::fs::copy(&baked_lut().furlut, &blob_as_exr).unwrap();
    let a = &ANGLES[0];
    assert_eq!(
        probe(&["--lut", path_str(&blob_as_exr)], a, &[]),
        probe(&["--lut", furlut], a, &[])
    );
}

#[test]
fn exr_lut_reads_like_the_furlut() {
    let (furlut, exr) = (path_str(&baked_lut().furlut), path_str(exr_file()));
    for a in &ANGLES {
        for extra in [&[][..], &["--pdf"]] {
            assert_eq!(
                probe(&["--lut", exr], a, extra),
                probe(&["--lut", furlut], a, extra),
                "{a:?} {extra:?}"
            );
        }
    }
    let input = "30 -20 45\n# c\n-85 40 90\n";
    assert_eq!(
        ok(&["probe", "--lut", exr, "--stdin", "--pdf"], Some(input)),
        ok(&["probe", "--lut", furlut, "--stdin", "--pdf"], Some(input))
    );
    assert_eq!(
        sample(&["--lut", exr], "35.5", 100, &["--seed", "3"]),
        sample(&["--lut", furlut], "35.5", 100, &["--seed", "3"])
    );

    // By content, not by name: an OpenEXR file called anything reads as OpenEXR.
    let dir = temp_dir();
    let exr_elsewhere = dir.path().join("lut.data");
    std::fs::copy(exr_file(), &exr_elsewhere).unwrap();
    assert_eq!(
        probe(&["--lut", path_str(&exr_elsewhere)], &ANGLES[0], &[]),
        probe(&["--lut", furlut], &ANGLES[0], &[])
    );

    // A truncated OpenEXR file is bad input naming the file, whatever its name.
    let good = std::fs::read(exr_file()).unwrap();
    for (name, len) in [
        ("truncated.exr", good.len() / 2),
        ("cut.bin", good.len() - 100),
    ] {
        let path = dir.path().join(name);
        std::fs::write(&path, &good[..len]).unwrap();
        let p = path_str(&path);
        for argv in [
            vec!["sample", "--lut", p, "--theta-r", "0", "-n", "3"],
            vec![
                "probe",
                "--lut",
                p,
                "--theta-i",
                "0",
                "--theta-r",
                "0",
                "--phi",
                "0",
            ],
        ] {
            let o = bad_input(&argv, None, &[p]);
            assert!(o.stdout.is_empty());
        }
    }
}

#[test]
fn pdf_is_appended_to_the_unchanged_line_and_equals_the_library_pdf() {
    let analytic = model().model();
    let b = baked();
    let furlut = path_str(&baked_lut().furlut);
    let mut positive = 0;
    for a in &ANGLES {
        let q = angles(a);

        // The preset: without --pdf the line is today's format (total, then the eleven
        // lobes in order), with --pdf the same bytes and `,"pdf":p` before the last brace.
        let plain = probe(&["--preset", PRESET], a, &[]);
        assert_same_bits(&tokens(&plain), &expected_lobes(&q, None), &plain);
        assert_eq!(
            tokens(&plain)[2..].iter().map(|t| &t.0).collect::<Vec<_>>(),
            Lobe::ALL
                .map(|l| l.name().to_string())
                .iter()
                .collect::<Vec<_>>()
        );
        let with_pdf = probe(&["--preset", PRESET], a, &["--pdf"]);
        let pdf = Bcsdf::pdf(&analytic, &q);
        check_pdf_suffix(&plain, &with_pdf, pdf);
        assert_same_bits(
            &tokens(&with_pdf),
            &expected_lobes(&q, Some(pdf)),
            &with_pdf,
        );
        if pdf > 0.0 {
            positive += 1;
        }

        // The LUT, the same way.
        let plain = probe(&["--lut", furlut], a, &[]);
        let with_pdf = probe(&["--lut", furlut], a, &["--pdf"]);
        let pdf = Bcsdf::pdf(&b, &q);
        check_pdf_suffix(&plain, &with_pdf, pdf);
        assert_same_bits(
            &tokens(&with_pdf),
            &expected_families(&q, Some(pdf)),
            &with_pdf,
        );
    }
    assert!(positive >= 6, "most of the queries have a positive pdf");

    // --stdin --pdf: the same lines as the single probes.
    let input: String = ANGLES
        .iter()
        .map(|a| format!("{} {} {}\n", a[0], a[1], a[2]))
        .collect();
    for source in [["--preset", PRESET], ["--lut", furlut]] {
        let mut args = vec!["probe"];
        args.extend_from_slice(&source);
        args.extend(["--pdf", "--stdin"]);
        let out = ok(&args, Some(&input));
        let singles: Vec<String> = ANGLES
            .iter()
            .map(|a| probe(&source, a, &["--pdf"]))
            .collect();
        assert_eq!(out.lines().collect::<Vec<_>>(), singles, "{source:?}");
    }
}

/// `with_pdf` is `plain` with `,"pdf":p` inserted before its last brace, p printed so that it
/// parses back to `pdf`.
#[track_caller]
fn check_pdf_suffix(plain: &str, with_pdf: &str, pdf: f32) {
    let head = plain.strip_suffix('}').expect("line ends with }");
    let rest = with_pdf
        .strip_prefix(head)
        .unwrap_or_else(|| panic!("--pdf changed the line:\n{plain}\n{with_pdf}"));
    let number = rest
        .strip_prefix(",\"pdf\":")
        .and_then(|r| r.strip_suffix('}'))
        .unwrap_or_else(|| panic!("no pdf key last: {with_pdf}"));
    let got: f32 = number.parse().unwrap();
    assert_eq!(got.to_bits(), pdf.to_bits(), "{with_pdf}: want {pdf}");
}

#[test]
fn stdin_with_lut_answers_far_field_lines_and_rejects_h_by_line_number() {
    let furlut = path_str(&baked_lut().furlut);
    let args = ["probe", "--lut", furlut, "--stdin"];
    let input = "# theta_i theta_r phi\n30 -20 45\n\n  20\t-25 180  \n-85 40 90\n";
    let out = ok(&args, Some(input));
    let want: Vec<String> = [ANGLES[0], ANGLES[1], ANGLES[5]]
        .iter()
        .map(|a| probe(&["--lut", furlut], a, &[]))
        .collect();
    assert_eq!(out.lines().collect::<Vec<_>>(), want);

    // A fourth field (h) is the near field, which a LUT does not hold: the lines before it
    // are printed, then the error names the line.
    let o = bad_input(
        &args,
        Some("30 -20 45\n# c\n30 -20 45 0.3\n0 0 0\n"),
        &["error: line 3:", "h = 0.3", "far field"],
    );
    assert_eq!(text(&o.stdout), format!("{}\n", want[0]));
    bad_input(&args, Some("1 2 3 4\n"), &["error: line 1:"]);
    // Malformed lines are reported as for a preset.
    bad_input(&args, Some("0 0 0\n1 2\n"), &["error: line 2:", "found 2"]);

    // With a preset, h lines still give the near field, but not with --pdf.
    let near = ok(
        &["probe", "--preset", PRESET, "--stdin"],
        Some("30 -20 45 0.3\n"),
    );
    assert!(near.contains("\"lobes\""), "{near}");
    bad_input(
        &["probe", "--preset", PRESET, "--stdin", "--pdf"],
        Some("30 -20 45\n30 -20 45 0.3\n"),
        &["error: line 2:", "h = 0.3", "--pdf"],
    );
}

/// One `viewer sample` line, read exactly.
#[derive(Debug)]
struct Drawn {
    theta_i_deg: f32,
    phi_deg: f32,
    pdf: f32,
    weight: [f32; 3],
    family: String,
}

fn parse_sample(line: &str) -> Drawn {
    let fields: Vec<&str> = line.split(' ').collect();
    assert_eq!(fields.len(), 7, "seven fields: {line:?}");
    let num = |i: usize| -> f32 {
        fields[i]
            .parse()
            .unwrap_or_else(|_| panic!("field {i} of {line:?} is not a number"))
    };
    Drawn {
        theta_i_deg: num(0),
        phi_deg: num(1),
        pdf: num(2),
        weight: [num(3), num(4), num(5)],
        family: fields[6].to_string(),
    }
}

/// `viewer sample SOURCE --theta-r THETA_R -n N` plus `extra`; stdout.
fn sample(source: &[&str], theta_r: &str, n: usize, extra: &[&str]) -> String {
    let n = n.to_string();
    let mut args = vec!["sample"];
    args.extend_from_slice(source);
    args.extend(["--theta-r", theta_r, "-n", &n]);
    args.extend_from_slice(extra);
    ok(&args, None)
}

/// Checks `viewer sample` against `bcsdf` in-process: N lines; each the library's draw from
/// the documented stream (`Pcg32::new(seed, 0)`, three numbers per draw), printed so that
/// it parses back to the same bits; its pdf `Bcsdf::pdf` of the printed direction (1e-5
/// relative); weights finite and non-negative; the same seed the same output, another seed
/// another. Returns the families drawn.
fn check_sampling<B: Bcsdf>(bcsdf: &B, source: &[&str]) -> Vec<String> {
    const N: usize = 400;
    let theta_r_deg = -20.0f32;
    let out = sample(source, "-20", N, &["--seed", "7"]);
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(lines.len(), N, "{source:?}");
    assert!(out.ends_with('\n'));

    let mut rng = Pcg32::new(7, 0);
    let mut families = Vec::new();
    for line in &lines {
        let d = parse_sample(line);
        let u = [rng.uniform(), rng.uniform(), rng.uniform()];
        let s = bcsdf
            .sample(theta_r_deg.to_radians(), u)
            .expect("the library draws where the viewer printed a line");
        let printed = [
            d.theta_i_deg,
            d.phi_deg,
            d.pdf,
            d.weight[0],
            d.weight[1],
            d.weight[2],
        ];
        let library = [
            s.angles.theta_i().to_degrees(),
            s.angles.phi().to_degrees(),
            s.pdf,
            s.weight.0[0],
            s.weight.0[1],
            s.weight.0[2],
        ];
        assert_eq!(
            printed.map(f32::to_bits),
            library.map(f32::to_bits),
            "{line}: library {library:?}"
        );
        assert_eq!(d.family, s.family.name(), "{line}");

        // The library's own angles (the printed ones are their bits in degrees, above): a
        // degree round trip moves θ_i by an ulp, which a steep lobe turns into 1e-5 of pdf.
        let pdf = bcsdf.pdf(&s.angles);
        assert!(d.pdf > 0.0 && d.pdf.is_finite(), "{line}");
        assert!(
            (pdf - d.pdf).abs() <= 1e-5 * d.pdf,
            "{line}: pdf() of the printed direction is {pdf}"
        );
        assert!(
            d.weight.iter().all(|w| w.is_finite() && *w >= 0.0),
            "{line}"
        );
        assert!(
            d.theta_i_deg.abs() <= 90.0 && d.phi_deg.abs() <= 180.0,
            "{line}"
        );
        if !families.contains(&d.family) {
            families.push(d.family);
        }
    }

    // Deterministic: the same seed the same bytes; the default seed is 1; another seed
    // draws other directions.
    assert_eq!(sample(source, "-20", N, &["--seed", "7"]), out);
    assert_ne!(sample(source, "-20", N, &["--seed", "8"]), out);
    assert_eq!(
        sample(source, "-20", 50, &[]),
        sample(source, "-20", 50, &["--seed", "1"])
    );
    families.sort();
    families
}

#[test]
fn sample_preset_prints_the_library_draws_with_their_pdf() {
    let families = check_sampling(&model().model(), &["--preset", PRESET]);
    assert_eq!(
        families,
        ["R", "TRT", "TT"],
        "human-hair has no scattered lobes"
    );
}

#[test]
fn sample_lut_prints_the_library_draws_with_their_pdf() {
    let furlut = path_str(&baked_lut().furlut);
    let families = check_sampling(&baked(), &["--lut", furlut]);
    assert_eq!(families, ["R", "TRT", "TT"]);
}

#[test]
fn zero_albedo_lut_prints_nothing_and_notes_the_failed_draws() {
    // Every table zero, resealed: a valid LUT that reflects nothing.
    let mut blob = baked_lut().blob.clone();
    let header = lut::validate(&blob).unwrap();
    for t in Table::ALL {
        blob[header.res.byte_range(t)].fill(0);
    }
    lut::seal(&mut blob);
    let dir = temp_dir();
    let path = dir.path().join("black.furlut");
    lutfile::write_blob(&path, &blob).unwrap();

    let o = viewer(
        &[
            "sample",
            "--lut",
            path_str(&path),
            "--theta-r",
            "10",
            "-n",
            "5",
        ],
        None,
    );
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    assert_eq!(text(&o.stdout), "");
    assert_eq!(text(&o.stderr), "note: 5 of 5 draws failed (zero albedo)\n");
}

#[test]
fn bad_input_exits_2_with_one_error_line() {
    let furlut = path_str(&baked_lut().furlut);
    let preset = ["--preset", PRESET];
    let lut = ["--lut", furlut];
    for source in [&preset, &lut] {
        let with = |extra: &[&str]| -> Vec<String> {
            let mut a = vec!["sample".to_string()];
            a.extend(source.iter().map(|s| s.to_string()));
            a.extend(extra.iter().map(|s| s.to_string()));
            a
        };
        for (extra, needles) in [
            (&["--theta-r", "10", "-n", "0"][..], &["-n 0"][..]),
            (
                &["--theta-r", "90", "-n", "3"],
                &["theta_r = 90", "(-90, 90)"],
            ),
            (&["--theta-r", "-90", "-n", "3"], &["theta_r = -90"]),
            (&["--theta-r", "120", "-n", "3"], &["theta_r = 120"]),
            (
                &["--theta-r", "nan", "-n", "3"],
                &["theta_r = NaN", "finite"],
            ),
            (
                &["--theta-r", "inf", "-n", "3"],
                &["theta_r = inf", "finite"],
            ),
        ] {
            let args = with(extra);
            let args: Vec<&str> = args.iter().map(String::as_str).collect();
            let o = bad_input(&args, None, needles);
            assert!(o.stdout.is_empty());
        }
    }
    bad_input(
        &[
            "sample",
            "--preset",
            "no-such-fur",
            "--theta-r",
            "0",
            "-n",
            "3",
        ],
        None,
        &["no-such-fur", "human-hair"],
    );
    bad_input(
        &[
            "sample",
            "--preset",
            PRESET,
            "--set",
            "kappa=2",
            "--theta-r",
            "0",
            "-n",
            "3",
        ],
        None,
        &["kappa"],
    );

    // Missing, garbage, empty and truncated LUTs, read by probe and by sample: the message
    // names the file. (Truncated OpenEXR files: `exr_lut_reads_like_the_furlut`.)
    let dir = temp_dir();
    let blob = &baked_lut().blob;
    let mut files = vec![(dir.path().join("missing.furlut"), None)];
    for (name, bytes) in [
        (
            "garbage.furlut",
            b"this is not a LUT, just some bytes\n".to_vec(),
        ),
        (
            "garbage.exr",
            b"this is not a LUT, just some bytes\n".to_vec(),
        ),
        ("garbage", vec![0xa5; 4096]),
        ("empty.furlut", Vec::new()),
        ("truncated.furlut", blob[..blob.len() / 2].to_vec()),
        ("header-only.furlut", blob[..lut::HEADER_LEN].to_vec()),
    ] {
        let path = dir.path().join(name);
        std::fs::write(&path, bytes).unwrap();
        files.push((path, Some(())));
    }
    // One flipped table byte: the checksum no longer matches.
    let mut flipped = blob.clone();
    let at = lut::HEADER_LEN + 1000;
    flipped[at] ^= 0x10;
    let path = dir.path().join("flipped.furlut");
    std::fs::write(&path, &flipped).unwrap();
    files.push((path, Some(())));

    for (path, exists) in &files {
        let p = path_str(path);
        let mut needles = vec![p];
        if exists.is_none() {
            needles.push("no such file");
        }
        let o = bad_input(
            &["sample", "--lut", p, "--theta-r", "0", "-n", "3"],
            None,
            &needles,
        );
        assert!(o.stdout.is_empty());
        let o = bad_input(
            &[
                "probe",
                "--lut",
                p,
                "--theta-i",
                "0",
                "--theta-r",
                "0",
                "--phi",
                "0",
            ],
            None,
            &needles,
        );
        assert!(o.stdout.is_empty());
    }

    // Usage errors found by clap keep clap's format but still fail with code 2.
    for argv in [
        vec![
            "sample",
            "--preset",
            PRESET,
            "--lut",
            furlut,
            "--theta-r",
            "0",
            "-n",
            "1",
        ],
        vec![
            "sample",
            "--lut",
            furlut,
            "--theta-r",
            "0",
            "-n",
            "1",
            "--no-cache",
        ],
        vec!["sample", "--lut", furlut, "--theta-r", "0", "-n", "-1"],
        vec!["sample", "--lut", furlut, "-n", "1"],
        vec!["sample", "--theta-r", "0", "-n", "1"],
        vec![
            "probe",
            "--lut",
            furlut,
            "--set",
            "kappa=0.1",
            "--theta-i",
            "0",
            "--theta-r",
            "0",
            "--phi",
            "0",
        ],
        vec![
            "probe",
            "--lut",
            furlut,
            "--h",
            "0.3",
            "--theta-i",
            "0",
            "--theta-r",
            "0",
            "--phi",
            "0",
        ],
        vec![
            "probe",
            "--preset",
            PRESET,
            "--pdf",
            "--h",
            "0.3",
            "--theta-i",
            "0",
            "--theta-r",
            "0",
            "--phi",
            "0",
        ],
    ] {
        let o = viewer(&argv, None);
        assert_eq!(o.status.code(), Some(2), "{argv:?}: {}", text(&o.stderr));
        assert!(
            text(&o.stderr).starts_with("error:"),
            "{argv:?}: {}",
            text(&o.stderr)
        );
        assert!(o.stdout.is_empty());
    }
}

#[test]
fn help_documents_sample_lut_and_pdf() {
    let top = ok(&["--help"], None);
    for needle in ["viewer sample", "probe --lut", "--pdf"] {
        assert!(top.contains(needle), "viewer --help lacks {needle}");
    }
    let sample = ok(&["sample", "--help"], None);
    for needle in [
        "Usage:",
        "Examples:",
        "--preset",
        "--presets",
        "--set",
        "--lut",
        "--theta-r",
        "-n <N>",
        "--seed",
        "--profile-seed",
        "--photons-scale",
        "--cache-dir",
        "Pcg32::new(SEED, 0)",
        "theta_i phi pdf weight_r weight_g weight_b family",
        "zero albedo",
    ] {
        assert!(sample.contains(needle), "sample --help lacks {needle}");
    }
    let probe = ok(&["probe", "--help"], None);
    for needle in ["--lut", "--pdf", "\"families\"", "\"pdf\":p", "Examples:"] {
        assert!(probe.contains(needle), "probe --help lacks {needle}");
    }
}

/// `viewer probe --lut FILE --gpu`: the shader's answers agree with the CPU's line for line
/// (1e-5 relative to max(value, 1e-3·the line's largest)) for single queries and --stdin,
/// with and without --pdf. Skipped without an adapter unless FUR_BCSDF_REQUIRE_GPU=1.
#[test]
fn probe_gpu_agrees_with_the_cpu() {
    let lut = path_str(&baked_lut().furlut).to_string();
    let input: String = ANGLES
        .iter()
        .map(|a| format!("{} {} {}\n", a[0], a[1], a[2]))
        .collect();
    let o = viewer(
        &["probe", "--lut", &lut, "--gpu", "--pdf", "--stdin"],
        Some(&input),
    );
    if o.status.code() == Some(2) && text(&o.stderr).contains("no GPU adapter") {
        assert_ne!(
            std::env::var("FUR_BCSDF_REQUIRE_GPU").as_deref(),
            Ok("1"),
            "FUR_BCSDF_REQUIRE_GPU=1 but {}",
            text(&o.stderr)
        );
        println!("skipped: no GPU adapter");
        return;
    }
    assert!(o.status.success(), "{}", text(&o.stderr));
    let gpu = text(&o.stdout);
    let cpu = ok(&["probe", "--lut", &lut, "--pdf", "--stdin"], Some(&input));
    assert_eq!(gpu.lines().count(), ANGLES.len());
    for (g, c) in gpu.lines().zip(cpu.lines()) {
        let (g, c) = (tokens(g), tokens(c));
        assert_eq!(g.len(), c.len());
        let peak = c
            .iter()
            .flat_map(|(_, v)| v.iter().copied())
            .fold(0.0f32, f32::max);
        for ((gk, gv), (ck, cv)) in g.iter().zip(&c) {
            assert_eq!(gk, ck);
            for (x, y) in gv.iter().zip(cv) {
                let scale = y.abs().max(1e-3 * peak).max(f32::MIN_POSITIVE);
                assert!((x - y).abs() <= 1e-5 * scale, "{gk}: gpu {x} cpu {y}");
            }
        }
    }
    // A single query gives the same line as the first stdin line.
    let a = angle_strings(&ANGLES[0]);
    let single = ok(
        &[
            "probe",
            "--lut",
            &lut,
            "--gpu",
            "--pdf",
            "--theta-i",
            &a[0],
            "--theta-r",
            &a[1],
            "--phi",
            &a[2],
        ],
        None,
    );
    assert_eq!(one_line(&single), gpu.lines().next().unwrap());
    // A bad stdin line stops after the answers before it, naming the line.
    let o = bad_input(
        &["probe", "--lut", &lut, "--gpu", "--stdin"],
        Some("10 20 30\n1 2\n"),
        &["line 2:"],
    );
    assert_eq!(text(&o.stdout).lines().count(), 1);
}

/// --gpu without an adapter (the Vulkan loader pointed at no driver) exits 2 with one
/// `error:` line naming the missing driver; --gpu without --lut is a usage error.
#[test]
fn probe_gpu_without_adapter_or_lut_is_bad_input() {
    let lut = path_str(&baked_lut().furlut).to_string();
    let o = Command::new(env!("CARGO_BIN_EXE_viewer"))
        .args([
            "probe",
            "--lut",
            &lut,
            "--gpu",
            "--theta-i",
            "1",
            "--theta-r",
            "2",
            "--phi",
            "3",
        ])
        .env("VK_ICD_FILENAMES", "/nonexistent.json")
        .env("VK_DRIVER_FILES", "/nonexistent.json")
        .output()
        .unwrap();
    let err = text(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert_eq!(err.lines().count(), 1, "{err:?}");
    assert!(
        err.starts_with("error: --gpu: no GPU adapter") && err.contains("mesa-vulkan-drivers"),
        "{err}"
    );
    let o = viewer(
        &[
            "probe",
            "--preset",
            PRESET,
            "--gpu",
            "--theta-i",
            "1",
            "--theta-r",
            "2",
            "--phi",
            "3",
        ],
        None,
    );
    assert_eq!(o.status.code(), Some(2));
    assert!(text(&o.stderr).contains("--lut"), "{}", text(&o.stderr));
}

/// `viewer compare LUT.exr --gpu`: the fur render through the shader differs from the CPU's
/// baked render by at most 1e-5 (mean relative, per channel). Skipped without an adapter
/// unless FUR_BCSDF_REQUIRE_GPU=1.
#[test]
fn compare_gpu_reports_the_render_difference() {
    let exr = path_str(exr_file()).to_string();
    let o = viewer(&["compare", &exr, "--gpu", "--no-images"], None);
    let err = text(&o.stderr);
    if o.status.code() == Some(2) && err.contains("no GPU adapter") {
        assert_ne!(
            std::env::var("FUR_BCSDF_REQUIRE_GPU").as_deref(),
            Ok("1"),
            "FUR_BCSDF_REQUIRE_GPU=1 but {err}"
        );
        println!("skipped: no GPU adapter");
        return;
    }
    assert!(o.status.success(), "{err}");
    let out = text(&o.stdout);
    let line = out
        .lines()
        .find(|l| l.contains("fur render through the GPU shader"))
        .unwrap_or_else(|| panic!("no GPU line in {out}"));
    let values: Vec<f64> = ["R ", "G ", "B "]
        .iter()
        .map(|c| {
            let at = line.rfind(c).unwrap() + 2;
            line[at..]
                .split_whitespace()
                .next()
                .unwrap()
                .parse()
                .unwrap()
        })
        .collect();
    assert!(values.iter().all(|v| *v <= 1e-5), "{line}");
}
