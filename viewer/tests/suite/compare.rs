//! `viewer compare` end to end, on LUTs baked here with `bake::tables::bake` from models with a
//! tiny photon budget and written with `bake::lutfile::write_exr`:
//!
//! - a good LUT passes (exit 0), writes every image with its documented size and a page
//!   listing every parameter of the schema, and its fur renders (decoded from the PNGs and
//!   from `compare.json`) differ by less than the E1 budget;
//! - a LUT whose tables were scaled after baking (then resealed, so the file is valid) fails
//!   with exit code 3 and stderr naming the metrics, and its renders differ by more than the
//!   budget; a looser `--budget` lets it pass;
//! - `--all DIR` compares every LUT and prints one summary, with a page linking each LUT's;
//! - missing, truncated, garbage and incompatible-version files exit 2 with one `error:` line
//!   naming the file, also inside `--all`, which still reports the good LUTs first;
//! - an unwritable output folder exits 1 before any work.
//!
//! Every run has `FUR_BCSDF_CACHE` pointing at a temporary directory, so the user's profile
//! cache is never touched.

use bake::lutfile::{self, LutFile, LutMeta};
use bake::profiles::{self, ProfileOptions};
use bcsdf_core::lut::{self, LutResolution, Table};
use bcsdf_core::{FurParams, ParamDefault, PhotonBudget, SCHEMA};
use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::sync::OnceLock;

/// `heatmap.png`: three 360 × 170 panels per row, four rows, legends and labels.
const HEATMAP: (u32, u32) = (1394, 942);
/// `polar.png`: 3 × 4 polar panels.
const POLAR: (u32, u32) = (1016, 870);
/// `analytic.png`, `baked.png`, `difference.png`, `families.png`.
const RENDER: (u32, u32) = (512, 384);
/// The default E1 budget.
const E1_BUDGET: f64 = 0.01;

fn images() -> [(&'static str, (u32, u32)); 6] {
    [
        ("heatmap.png", HEATMAP),
        ("polar.png", POLAR),
        ("analytic.png", RENDER),
        ("baked.png", RENDER),
        ("difference.png", RENDER),
        ("families.png", RENDER),
    ]
}

fn temp_dir() -> tempfile::TempDir {
    tempfile::Builder::new()
        .prefix("viewer-compare-")
        .tempdir_in(env!("CARGO_TARGET_TMPDIR"))
        .unwrap()
}

/// The profile cache the viewer runs use.
fn cache() -> &'static Path {
    static DIR: OnceLock<tempfile::TempDir> = OnceLock::new();
    DIR.get_or_init(temp_dir).path()
}

/// The blob of a preset baked at the default resolution, with profiles made with 1 % of the
/// default photon budget (profiles and residual tables cached in the target folder; the
/// viewer runs use their own, [`cache`]).
fn baked_blob(preset: &str) -> Vec<u8> {
    let presets = bake::presets::builtin().unwrap();
    let p = bake::presets::find(&presets, preset).unwrap();
    let opts = ProfileOptions {
        budget: profiles::scale_budget(PhotonBudget::DEFAULT, 0.01).unwrap(),
        cache_dir: Some(PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("fur-profile-cache")),
        ..ProfileOptions::default()
    };
    let (model, _) = profiles::build_model(FurParams::new(&p.input).unwrap(), &opts).unwrap();
    bake::tables::bake(&model, &p.input, LutResolution::DEFAULT)
}

/// human-hair (needs no profiles), baked once for all tests.
fn human_hair() -> &'static [u8] {
    static BLOB: OnceLock<Vec<u8>> = OnceLock::new();
    BLOB.get_or_init(|| baked_blob("human-hair"))
}

/// Writes `blob` as `dir/name.exr`.
fn write_lut(dir: &Path, name: &str, preset: &str, blob: &[u8]) -> PathBuf {
    let path = dir.join(format!("{name}.exr"));
    let file = LutFile {
        blob: blob.to_vec(),
        meta: LutMeta {
            preset: preset.to_string(),
            errors: None,
        },
    };
    lutfile::write_exr(&path, &file).unwrap();
    path
}

/// `blob` with every value of table `N` (the azimuthal functions of every family) multiplied
/// by `factor`, resealed so that it is a valid LUT.
fn perturbed(blob: &[u8], factor: f32) -> Vec<u8> {
    let mut blob = blob.to_vec();
    let header = lut::validate(&blob).unwrap();
    // Table N: in the energy closure M_g is divided by its own mass, so a scaled table M
    // would not change S there (docs/model.md §12); a scaled N changes S in both closures.
    let range = header.res.byte_range(Table::N);
    for pair in blob[range].chunks_exact_mut(2) {
        let v = half::f16::from_bits(u16::from_le_bytes([pair[0], pair[1]]));
        let scaled = half::f16::from_f32(v.to_f32() * factor);
        pair.copy_from_slice(&scaled.to_bits().to_le_bytes());
    }
    lut::seal(&mut blob);
    lut::validate(&blob).expect("the perturbed blob is valid");
    blob
}

fn viewer(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_viewer"))
        .args(args)
        .env("FUR_BCSDF_CACHE", cache())
        .output()
        .expect("spawning viewer")
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8(bytes.to_vec()).expect("UTF-8 output")
}

/// Runs `viewer compare ARGS` and checks the exit code; returns (stdout, stderr).
#[track_caller]
fn compare(args: &[&str], code: i32) -> (String, String) {
    let mut all = vec!["compare"];
    all.extend_from_slice(args);
    let o = viewer(&all);
    let (out, err) = (text(&o.stdout), text(&o.stderr));
    assert_eq!(
        o.status.code(),
        Some(code),
        "viewer {all:?}\nstdout:\n{out}\nstderr:\n{err}"
    );
    (out, err)
}

/// Exit code 2 and a single `error:` line naming `file` and containing every needle.
#[track_caller]
fn bad_input(args: &[&str], file: &Path, needles: &[&str]) {
    let (out, err) = compare(args, 2);
    assert!(out.is_empty(), "{out}");
    assert!(err.starts_with("error: "), "{err:?}");
    assert_eq!(err.lines().count(), 1, "one line expected: {err:?}");
    assert!(
        err.contains(&file.display().to_string()),
        "{err:?} should name {}",
        file.display()
    );
    for needle in needles {
        assert!(err.contains(needle), "{err:?} should contain {needle:?}");
    }
}

/// Width and height from a PNG's IHDR chunk.
fn png_size(path: &Path) -> (u32, u32) {
    let bytes = std::fs::read(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    assert_eq!(
        &bytes[..8],
        b"\x89PNG\r\n\x1a\n",
        "{} is not a PNG",
        path.display()
    );
    assert_eq!(&bytes[12..16], b"IHDR");
    let be = |at: usize| u32::from_be_bytes(bytes[at..at + 4].try_into().unwrap());
    (be(16), be(20))
}

/// Decodes an 8-bit RGB PNG: (width, height, pixels).
fn decode_png(path: &Path) -> (u32, u32, Vec<[u8; 3]>) {
    let decoder = png::Decoder::new(std::fs::File::open(path).unwrap());
    let mut reader = decoder.read_info().unwrap();
    let mut buf = vec![0; reader.output_buffer_size()];
    let info = reader.next_frame(&mut buf).unwrap();
    assert_eq!(info.color_type, png::ColorType::Rgb);
    assert_eq!(info.bit_depth, png::BitDepth::Eight);
    buf.truncate(info.buffer_size());
    let px = buf.chunks_exact(3).map(|c| [c[0], c[1], c[2]]).collect();
    (info.width, info.height, px)
}

fn srgb_to_linear(v: u8) -> f64 {
    let s = f64::from(v) / 255.0;
    if s <= 0.04045 {
        s / 12.92
    } else {
        ((s + 0.055) / 1.055).powf(2.4)
    }
}

/// Compares the two decoded renders: (fraction of pixels showing fur, mean display
/// brightness of the analytic render, Σ|b − a| / Σ a over the linearised pixels).
fn render_difference(dir: &Path) -> (f64, f64, f64) {
    let (wa, ha, a) = decode_png(&dir.join("analytic.png"));
    let (wb, hb, b) = decode_png(&dir.join("baked.png"));
    assert_eq!((wa, ha), (wb, hb));
    let background = a[0].min(b[0]);
    let mut fur = 0usize;
    let (mut diff, mut total, mut bright) = (0.0, 0.0, 0.0);
    for (pa, pb) in a.iter().zip(&b) {
        if pa
            .iter()
            .zip(&background)
            .any(|(&v, &bg)| v > bg.saturating_add(8))
        {
            fur += 1;
        }
        for c in 0..3 {
            let (la, lb) = (srgb_to_linear(pa[c]), srgb_to_linear(pb[c]));
            diff += (lb - la).abs();
            total += la;
            bright += f64::from(pa[c]) / 255.0;
        }
    }
    let n = a.len() as f64;
    (fur as f64 / n, bright / (3.0 * n), diff / total)
}

fn report(dir: &Path) -> serde_json::Value {
    let path = dir.join("compare.json");
    let s = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    serde_json::from_str(&s).unwrap_or_else(|e| panic!("{}: {e}\n{s}", path.display()))
}

fn triple(v: &serde_json::Value) -> [f64; 3] {
    let a = v.as_array().expect("an array of three numbers");
    assert_eq!(a.len(), 3);
    std::array::from_fn(|i| a[i].as_f64().expect("a number"))
}

/// Every image exists with its documented size, the page links them all and lists every
/// parameter of the schema that is not a colour form (those depend on the preset).
#[track_caller]
fn check_outputs(dir: &Path) {
    for (name, size) in images() {
        assert_eq!(png_size(&dir.join(name)), size, "{name}");
    }
    let page = std::fs::read_to_string(dir.join("index.html")).unwrap();
    for (name, _) in images() {
        assert!(
            page.contains(&format!("src=\"{name}\"")),
            "page lacks {name}"
        );
    }
    for spec in SCHEMA.iter().filter(|s| s.default != ParamDefault::Colour) {
        let cell = format!("<td>{}</td><td><code>{}</code></td>", spec.symbol, spec.key);
        assert!(page.contains(&cell), "page lacks the {} row", spec.key);
    }
}

#[test]
fn a_good_lut_passes_with_every_image_and_renders_within_budget() {
    let tmp = temp_dir();
    let lut = write_lut(tmp.path(), "human-hair", "human-hair", human_hair());
    let (out, err) = compare(&[lut.to_str().unwrap()], 0);
    assert!(err.is_empty(), "{err}");
    // The table: one row per metric, three channels, the budget and the verdict.
    for metric in ["E1", "E_albedo", "E_peak"] {
        let row = out
            .lines()
            .find(|l| l.split_whitespace().next() == Some(metric))
            .unwrap_or_else(|| panic!("no {metric} row in\n{out}"));
        assert!(row.ends_with("PASS"), "{row}");
        assert_eq!(row.matches('%').count(), 4, "R, G, B and the budget: {row}");
    }
    assert!(!out.contains("FAIL"), "{out}");
    // The default three random colours, each against the analytic model at that colour.
    // (The other tests pass `--colours 0`: each colour costs a residual simulation.)
    for k in 0..3 {
        let line = out
            .lines()
            .find(|l| {
                l.trim_start()
                    .starts_with(&format!("at random {k} (sigma_ca"))
            })
            .unwrap_or_else(|| panic!("no line for random colour {k} in\n{out}"));
        assert!(line.ends_with(" ok"), "{line}");
    }
    assert!(!out.contains("at random 3"), "{out}");

    // Default output folder: `<stem>-compare/` beside the LUT.
    let dir = tmp.path().join("human-hair-compare");
    check_outputs(&dir);
    let json = report(&dir);
    assert_eq!(json["preset"], "human-hair");
    assert_eq!(json["pass"], true);
    for m in ["E1", "E_albedo", "E_peak"] {
        let v = triple(&json["metrics"][m]);
        let budget = json["budget"][m].as_f64().unwrap();
        assert!(v.iter().all(|&x| x <= budget), "{m} {v:?} over {budget}");
    }
    // The render, from the numbers and from the pictures themselves.
    let render = triple(&json["render_difference"]);
    assert!(
        render.iter().all(|&d| d < E1_BUDGET),
        "render difference {render:?}"
    );
    let (fur, brightness, png_diff) = render_difference(&dir);
    assert!(fur > 0.3, "only {fur} of the picture shows fur");
    assert!(
        brightness > 0.05,
        "the render is nearly black: {brightness}"
    );
    assert!(png_diff < E1_BUDGET, "PNG renders differ by {png_diff}");
}

#[test]
fn perturbed_tables_fail_naming_the_metrics() {
    let tmp = temp_dir();
    let lut = write_lut(
        tmp.path(),
        "perturbed",
        "human-hair",
        &perturbed(human_hair(), 1.06),
    );
    let out_dir = tmp.path().join("out");
    let (out, err) = compare(
        &[lut.to_str().unwrap(), "--out", out_dir.to_str().unwrap()],
        3,
    );
    assert!(err.starts_with("error: "), "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    for needle in [
        lut.to_str().unwrap(),
        "over budget",
        "E1 (R)",
        "E1 (G)",
        "E1 (B)",
        "E_albedo",
        "E_peak",
    ] {
        assert!(err.contains(needle), "{err:?} should name {needle:?}");
    }
    assert!(out.contains("FAIL"), "{out}");
    // Still a complete report, and the renders show the error.
    check_outputs(&out_dir);
    let json = report(&out_dir);
    assert_eq!(json["pass"], false);
    let e1 = triple(&json["metrics"]["E1"]);
    assert!(e1.iter().all(|&v| v > 0.03), "E1 {e1:?}");
    let render = triple(&json["render_difference"]);
    assert!(
        render.iter().all(|&d| d > E1_BUDGET),
        "render difference {render:?}"
    );
    let (_, _, png_diff) = render_difference(&out_dir);
    assert!(png_diff > E1_BUDGET, "PNG renders differ by {png_diff}");

    // A budget loose enough lets it pass; nothing is written with --no-images.
    let quiet = tmp.path().join("quiet");
    let (out, err) = compare(
        &[
            lut.to_str().unwrap(),
            "--budget",
            "10%,10%,10%",
            "--no-images",
            "--colours",
            "0",
            "--out",
            quiet.to_str().unwrap(),
        ],
        0,
    );
    assert!(err.is_empty(), "{err}");
    assert!(out.contains("10.000%") && !out.contains("FAIL"), "{out}");
    assert!(!quiet.exists());
}

#[test]
fn all_compares_a_folder_with_one_summary() {
    let tmp = temp_dir();
    let luts = tmp.path().join("luts");
    std::fs::create_dir(&luts).unwrap();
    write_lut(&luts, "human-hair", "human-hair", human_hair());
    write_lut(&luts, "bobcat", "bobcat", &baked_blob("bobcat"));
    // Not a LUT: ignored.
    std::fs::write(luts.join("notes.txt"), "not a LUT").unwrap();

    let (out, err) = compare(
        &[
            "--all",
            luts.to_str().unwrap(),
            "--threads",
            "2",
            "--colours",
            "0",
        ],
        0,
    );
    assert!(err.is_empty(), "{err}");
    assert_eq!(out.matches("summary of 2 LUTs").count(), 1, "{out}");
    let summary = &out[out.find("summary of").unwrap()..];
    for name in ["human-hair.exr", "bobcat.exr"] {
        let row = summary
            .lines()
            .find(|l| l.trim_start().starts_with(name))
            .unwrap_or_else(|| panic!("no row for {name} in\n{summary}"));
        assert!(row.ends_with("PASS"), "{row}");
    }
    // Sorted by name: bobcat's table comes first.
    assert!(out.find("bobcat (").unwrap() < out.find("human-hair (").unwrap());
    // The gallery: one panel per LUT (half-size renders, 4 per row), one light, one exposure.
    let gallery = luts.join("gallery.png");
    assert!(
        out.contains(&format!(
            "gallery (every LUT's baked render, one light, one exposure): {}",
            gallery.display()
        )),
        "{out}"
    );
    let decoder = png::Decoder::new(std::fs::File::open(&gallery).unwrap());
    let info = decoder.read_info().unwrap();
    assert_eq!(
        (info.info().width, info.info().height),
        (2 * 256, 192),
        "two panels side by side"
    );

    let index = std::fs::read_to_string(luts.join("index.html")).unwrap();
    for stem in ["human-hair", "bobcat"] {
        assert!(index.contains(&format!("href=\"{stem}-compare/index.html\"")));
        let dir = luts.join(format!("{stem}-compare"));
        check_outputs(&dir);
        let render = triple(&report(&dir)["render_difference"]);
        assert!(
            render.iter().all(|&d| d < E1_BUDGET),
            "{stem}: render difference {render:?}"
        );
        let (fur, _, png_diff) = render_difference(&dir);
        assert!(
            fur > 0.3 && png_diff < E1_BUDGET,
            "{stem}: {fur} {png_diff}"
        );
    }
}

#[test]
fn all_reports_every_lut_before_failing() {
    let tmp = temp_dir();
    let good = write_lut(tmp.path(), "good", "human-hair", human_hair());
    let bytes = std::fs::read(&good).unwrap();
    let luts = tmp.path().join("luts");
    std::fs::create_dir(&luts).unwrap();
    let broken = luts.join("a-broken.exr");
    std::fs::write(&broken, &bytes[..bytes.len() / 2]).unwrap();
    let over = write_lut(
        &luts,
        "b-over",
        "human-hair",
        &perturbed(human_hair(), 1.06),
    );

    let (out, err) = compare(
        &[
            "--all",
            luts.to_str().unwrap(),
            "--no-images",
            "--colours",
            "0",
        ],
        2,
    );
    let lines: Vec<&str> = err.lines().collect();
    assert_eq!(lines.len(), 3, "{err}");
    assert!(lines.iter().all(|l| l.starts_with("error: ")), "{err}");
    assert!(lines[0].contains(broken.to_str().unwrap()), "{err}");
    assert!(
        lines[1].contains(over.to_str().unwrap()) && lines[1].contains("E1 (R)"),
        "{err}"
    );
    assert!(
        lines[2].contains("1 of 2 LUTs") && lines[2].contains("a-broken.exr"),
        "{err}"
    );
    assert!(lines[2].contains("1 over budget (b-over.exr)"), "{err}");
    let summary = &out[out.find("summary of 2 LUTs").expect("a summary")..];
    let verdict = |name: &str| {
        summary
            .lines()
            .find(|l| l.trim_start().starts_with(name))
            .unwrap_or_else(|| panic!("no row for {name} in\n{summary}"))
            .to_string()
    };
    assert!(verdict("a-broken.exr").contains("ERROR"));
    assert!(verdict("b-over.exr").ends_with("FAIL"));

    // Without the broken file, the budget failure decides: exit 3.
    std::fs::remove_file(&broken).unwrap();
    let (_, err) = compare(
        &[
            "--all",
            luts.to_str().unwrap(),
            "--no-images",
            "--colours",
            "0",
        ],
        3,
    );
    assert!(err.lines().last().unwrap().contains("1 of 1 LUTs"), "{err}");
}

#[test]
fn missing_corrupt_and_incompatible_luts_are_bad_input() {
    let tmp = temp_dir();
    let good = write_lut(tmp.path(), "good", "human-hair", human_hair());
    let bytes = std::fs::read(&good).unwrap();

    let missing = tmp.path().join("missing.exr");
    bad_input(&[missing.to_str().unwrap()], &missing, &["no such file"]);

    let truncated = tmp.path().join("truncated.exr");
    std::fs::write(&truncated, &bytes[..bytes.len() - 100]).unwrap();
    bad_input(&[truncated.to_str().unwrap()], &truncated, &[]);

    let garbage = tmp.path().join("garbage.exr");
    std::fs::write(&garbage, b"this is not an OpenEXR file at all\n").unwrap();
    bad_input(
        &[garbage.to_str().unwrap()],
        &garbage,
        &["not an OpenEXR file"],
    );

    // A LUT of another format version: the `lut_format_version` int attribute set to 99.
    let key = b"lut_format_version\0int\0\x04\0\0\0";
    let at = bytes
        .windows(key.len())
        .position(|w| w == key)
        .expect("the format version attribute")
        + key.len();
    let mut other = bytes.clone();
    other[at..at + 4].copy_from_slice(&99u32.to_le_bytes());
    let old = tmp.path().join("old-format.exr");
    std::fs::write(&old, &other).unwrap();
    bad_input(
        &[old.to_str().unwrap()],
        &old,
        &["version 99", "not supported"],
    );

    // Nothing was written for any of them.
    for stem in ["missing", "truncated", "garbage", "old-format"] {
        assert!(!tmp.path().join(format!("{stem}-compare")).exists());
    }

    // Other bad input: a malformed budget, a folder without LUTs.
    let (_, err) = compare(&[good.to_str().unwrap(), "--budget", "1%,2%"], 2);
    assert!(
        err.starts_with("error: invalid --budget") && err.lines().count() == 1,
        "{err}"
    );
    let empty = temp_dir();
    bad_input(
        &["--all", empty.path().to_str().unwrap()],
        empty.path(),
        &["no *.exr"],
    );
}

#[test]
fn an_unwritable_output_folder_fails_before_any_work() {
    let tmp = temp_dir();
    let lut = write_lut(tmp.path(), "human-hair", "human-hair", human_hair());
    let file = tmp.path().join("a-file");
    std::fs::write(&file, "").unwrap();
    let under_file = file.join("out");
    for args in [
        vec![lut.to_str().unwrap(), "--out", under_file.to_str().unwrap()],
        vec![
            "--all",
            tmp.path().to_str().unwrap(),
            "--out",
            file.to_str().unwrap(),
        ],
    ] {
        let (out, err) = compare(&args, 1);
        // Nothing measured or printed: the folder is checked first.
        assert!(out.is_empty(), "{out}");
        assert!(err.starts_with("error: output folder "), "{err}");
        assert!(err.contains("not writable"), "{err}");
        assert_eq!(err.lines().count(), 1, "{err}");
    }
}
