//! The `viewer` binary end to end: JSON output, far/near switching, `--set`, `--stdin`,
//! `viewer presets`, one-line `error:` messages with exit code 2 for bad input, and the
//! medulla profile cache (`--cache-dir`, `--no-cache`, `--seed`, `--photons-scale`, the
//! default directory, stale and corrupt files).
//! (Over 600 lines: fourteen end-to-end cases sharing one harness that runs the binary.)
//!
//! Cargo builds the binary for this test (`CARGO_BIN_EXE_viewer`), so it is never stale.
//! Every probe runs with a small photon budget (`--photons-scale`, added by [`viewer`]) and
//! with `FUR_BCSDF_CACHE` pointing at a temporary directory, so the tests stay fast and never
//! touch the user's cache.

use bake::profiles::{self, OwnedModel, ProfileOptions};
use bcsdf_core::{presets, Angles, FurParams, Lobe, Lobes, PhotonBudget, Pigment, Rgb};
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::sync::OnceLock;

/// The photon scale every probe of these tests runs with (2 000 photons per C^N cell).
const SCALE: &str = "0.01";

/// Path of the `viewer` binary Cargo built for this test.
fn viewer_path() -> &'static Path {
    Path::new(env!("CARGO_BIN_EXE_viewer"))
}

/// The profile cache shared by the tests that do not set their own: a fresh directory under
/// Cargo's per-target temporary directory.
fn shared_cache() -> &'static Path {
    static DIR: OnceLock<tempfile::TempDir> = OnceLock::new();
    DIR.get_or_init(|| {
        tempfile::Builder::new()
            .prefix("viewer-cli-cache-")
            .tempdir_in(env!("CARGO_TARGET_TMPDIR"))
            .unwrap()
    })
    .path()
}

/// A fresh temporary directory (removed when dropped).
fn temp_dir() -> tempfile::TempDir {
    tempfile::Builder::new()
        .prefix("viewer-cli-")
        .tempdir_in(env!("CARGO_TARGET_TMPDIR"))
        .unwrap()
}

/// Runs the viewer. `probe` commands get `--photons-scale SCALE`; the environment has
/// `FUR_BCSDF_CACHE` = [`shared_cache`] unless `env` says otherwise (`None` removes a
/// variable).
fn viewer_env(args: &[&str], stdin: Option<&str>, env: &[(&str, Option<&Path>)]) -> Output {
    let mut cmd = Command::new(viewer_path());
    cmd.args(args);
    if args.first() == Some(&"probe") && !args.contains(&"--photons-scale") {
        cmd.args(["--photons-scale", SCALE]);
    }
    cmd.env("FUR_BCSDF_CACHE", shared_cache());
    for (name, value) in env {
        match value {
            Some(v) => cmd.env(name, v),
            None => cmd.env_remove(name),
        };
    }
    let mut child = cmd
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

fn viewer(args: &[&str], stdin: Option<&str>) -> Output {
    viewer_env(args, stdin, &[])
}

fn stdout(o: &Output) -> String {
    String::from_utf8(o.stdout.clone()).expect("stdout is UTF-8")
}

fn stderr(o: &Output) -> String {
    String::from_utf8(o.stderr.clone()).expect("stderr is UTF-8")
}

/// Runs successfully and returns stdout.
#[track_caller]
fn ok(args: &[&str], stdin: Option<&str>) -> String {
    let o = viewer(args, stdin);
    assert!(
        o.status.success(),
        "viewer {args:?} failed: {}\n{}",
        o.status,
        stderr(&o)
    );
    assert!(o.stderr.is_empty(), "unexpected stderr: {}", stderr(&o));
    stdout(&o)
}

/// Fails with exit code 2 and one `error:` line on stderr holding every needle; returns it.
#[track_caller]
fn bad_input(args: &[&str], stdin: Option<&str>, needles: &[&str]) -> Output {
    let o = viewer(args, stdin);
    crate::assert_refused(&o, &args, needles);
    o
}

/// One probe line: validated as JSON, then read exactly (each number parsed straight to f32).
#[derive(Debug, PartialEq)]
struct Probe {
    total: [f32; 3],
    lobes: Vec<(String, [f32; 3])>,
}

fn parse_probe(line: &str) -> Probe {
    let json: serde_json::Value =
        serde_json::from_str(line).unwrap_or_else(|e| panic!("not JSON ({e}): {line}"));
    let obj = json.as_object().expect("an object");
    assert_eq!(obj.len(), 2, "{line}");
    assert_eq!(obj["total"].as_array().map(Vec::len), Some(3), "{line}");
    let lobes = obj["lobes"].as_object().expect("lobes object");
    assert_eq!(lobes.len(), Lobe::ALL.len(), "{line}");
    // Fixed format: the tokens between the punctuation are "name" or a number.
    let cleaned: String = line
        .chars()
        .map(|c| if "{}[]:,".contains(c) { ' ' } else { c })
        .collect();
    let mut names = Vec::new();
    let mut numbers: Vec<Vec<f32>> = Vec::new();
    for tok in cleaned.split_whitespace() {
        if let Some(name) = tok.strip_prefix('"').and_then(|t| t.strip_suffix('"')) {
            names.push(name.to_string());
            numbers.push(Vec::new());
        } else {
            let v: f32 = tok.parse().unwrap_or_else(|_| panic!("bad number {tok}"));
            numbers.last_mut().expect("number before any key").push(v);
        }
    }
    assert_eq!(names[0], "total");
    assert_eq!(names[1], "lobes");
    assert!(numbers[1].is_empty());
    let rgb = |v: &Vec<f32>| -> [f32; 3] { v.as_slice().try_into().expect("three numbers") };
    Probe {
        total: rgb(&numbers[0]),
        lobes: names[2..]
            .iter()
            .cloned()
            .zip(numbers[2..].iter().map(rgb))
            .collect(),
    }
}

fn lobe_names() -> Vec<String> {
    Lobe::ALL.iter().map(|l| l.name().to_string()).collect()
}

/// The options the viewer uses under [`viewer`]: default resolution and seed, the photon
/// budget scaled by [`SCALE`]; no cache (the library generates its own copy, so the binary's
/// cached profiles are checked against an independent generation).
fn options(seed: u64) -> ProfileOptions {
    ProfileOptions {
        budget: profiles::scale_budget(PhotonBudget::DEFAULT, SCALE.parse().unwrap()).unwrap(),
        seed,
        ..ProfileOptions::default()
    }
}

/// The full model for `params`, built like the viewer builds it.
fn build(params: FurParams, seed: u64) -> OwnedModel {
    profiles::build_model(params, &options(seed)).unwrap().0
}

fn model(preset: &str) -> OwnedModel {
    let p = presets::find(preset).unwrap();
    build(FurParams::new(&p.input).unwrap(), 1)
}

/// The library's answer, for exact comparison (the model is deterministic f32 code with a
/// pure-Rust libm, so the binary and this test compute the same bits).
fn expected(lobes: &Lobes) -> Probe {
    Probe {
        total: lobes.total().0,
        lobes: lobes
            .iter()
            .map(|(l, v)| (l.name().to_string(), v.0))
            .collect(),
    }
}

fn probe_args<'a>(preset: &'a str, angles: &[&'a str; 3]) -> Vec<&'a str> {
    vec![
        "probe",
        "--preset",
        preset,
        "--theta-i",
        angles[0],
        "--theta-r",
        angles[1],
        "--phi",
        angles[2],
    ]
}

fn one_line(out: &str) -> &str {
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(lines.len(), 1, "one line expected: {out:?}");
    assert!(out.ends_with('\n'));
    lines[0]
}

/// The probe's JSON for `presets`: every lobe in `Lobe::ALL` order, the total their sum, the
/// library's numbers bit for bit; the medulla-scattered lobes lit exactly for the presets that
/// scatter (of `scatter`, each must be in `presets`), and dark for human hair if it is there.
fn check_probe_json(presets: &[&'static str], scatter: &[&str]) {
    let mut multi_lobe = 0;
    let mut lit_scattered = Vec::new();
    for &preset in presets {
        // Generated once per preset (no cache: see `options`), not once per query.
        let owned = model(preset);
        for angles in [
            ["30", "-20", "45"],
            ["20", "-25", "180"],
            ["10", "-10", "30"],
        ] {
            let out = ok(&probe_args(preset, &angles), None);
            let p = parse_probe(one_line(&out));
            let names: Vec<String> = p.lobes.iter().map(|(n, _)| n.clone()).collect();
            assert_eq!(names, lobe_names(), "lobes in Lobe::ALL order");
            for ch in 0..3 {
                let sum: f32 = p.lobes.iter().map(|(_, v)| v[ch]).sum();
                let scale: f32 = p.lobes.iter().map(|(_, v)| v[ch].abs()).sum();
                assert!(
                    (p.total[ch] - sum).abs() <= 8.0 * f32::EPSILON * scale,
                    "{preset} {angles:?}: total {} vs lobe sum {sum}",
                    p.total[ch]
                );
            }
            if p.lobes.iter().filter(|(_, v)| v[0] > 0.0).count() >= 3 {
                multi_lobe += 1;
            }
            // The three scattered lobes (the residual, after them, is in every preset).
            let scattered = p
                .lobes
                .iter()
                .filter(|(name, _)| Lobe::SCATTERED.iter().any(|l| l.name() == name))
                .any(|(_, v)| v[0] > 0.0);
            if scattered {
                lit_scattered.push(preset);
            }
            // And the numbers are the library's, bit for bit (round-trip printing).
            let a: Vec<f32> = angles.iter().map(|s| s.parse().unwrap()).collect();
            let lib = owned
                .model()
                .eval_far_lobes(&Angles::from_degrees(a[0], a[1], a[2]).unwrap());
            assert_eq!(p, expected(&lib), "{preset} {angles:?}");
        }
    }
    assert!(
        multi_lobe > 0,
        "no query had several non-zero lobes: the sum check is vacuous"
    );
    // Every preset that scatters in the medulla shows it in at least one query; the one that
    // does not (human-hair: kappa = 0) never does.
    for preset in scatter {
        assert!(presets.contains(preset));
        assert!(
            lit_scattered.contains(preset),
            "{preset}: {lit_scattered:?}"
        );
    }
    assert!(!lit_scattered.contains(&"human-hair"));
}

/// The core presets (`fur_tests::per_preset::CORE_PRESETS`) in the everyday run.
#[test]
fn probe_prints_json_with_every_lobe_and_total_is_their_sum() {
    let core = fur_tests::per_preset::CORE_PRESETS;
    assert!(core.contains(&"human-hair"));
    check_probe_json(&core, &["raccoon", "air-medulla"]);
}

/// The other species: part of the full sweep.
mod probe_json_other_species {
    #[test]
    #[ignore = "full sweep: cargo test --workspace -- --ignored full_sweep"]
    fn full_sweep() {
        let core = fur_tests::per_preset::CORE_PRESETS;
        let others: Vec<&'static str> = bcsdf_core::presets::PRESETS
            .iter()
            .map(|p| p.name)
            .filter(|n| !core.contains(n))
            .collect();
        super::check_probe_json(&others, &["bobcat", "red-fox"]);
    }
}

#[test]
fn h_switches_from_far_to_near_field() {
    let angles = ["10", "-10", "30"];
    let args = probe_args("air-medulla", &angles);
    let far = parse_probe(one_line(&ok(&args, None)));
    let a = Angles::from_degrees(10.0, -10.0, 30.0).unwrap();
    let owned = model("air-medulla");
    let m = owned.model();
    assert_eq!(far, expected(&m.eval_far_lobes(&a)));
    for h in ["0.2", "-0.7", "1", "-1", "0"] {
        let mut near_args = args.clone();
        near_args.extend(["--h", h]);
        let near = parse_probe(one_line(&ok(&near_args, None)));
        assert_eq!(
            near,
            expected(&m.eval_near(&a, h.parse().unwrap())),
            "h = {h}"
        );
        if h == "0.2" {
            assert_ne!(near, far, "--h must switch to the near field");
        }
    }
    for h in ["1.5", "-1.01"] {
        let mut near_args = args.clone();
        near_args.extend(["--h", h]);
        bad_input(&near_args, None, &["h = ", "[-1, 1]"]);
    }
}

#[test]
fn set_overrides_change_the_result() {
    let angles = ["20", "-25", "180"];
    let base_args = probe_args("human-hair", &angles);
    let tt = |p: &Probe| p.lobes.iter().find(|(n, _)| n == "TT").unwrap().1;
    let base = parse_probe(one_line(&ok(&base_args, None)));
    assert!(
        tt(&base)[0] > 0.0,
        "TT should be lit at these angles: {base:?}"
    );

    let mut clear = base_args.clone();
    clear.extend(["--set", "sigma_ca=0"]);
    let clear = parse_probe(one_line(&ok(&clear, None)));
    for ch in 0..3 {
        assert!(
            tt(&clear)[ch] > tt(&base)[ch],
            "sigma_ca=0 must raise TT in every channel: {:?} vs {:?}",
            tt(&clear),
            tt(&base)
        );
    }

    // Several overrides, including an RGB sigma_ca, equal the library with the same input.
    let mut args = base_args.clone();
    args.extend([
        "--set",
        "sigma_ca=0.1,0.2,0.4",
        "--set",
        "kappa=0.3",
        "--set=eta_m=1.3",
        "--set",
        "sigma_ms=1.5",
    ]);
    let got = parse_probe(one_line(&ok(&args, None)));
    let mut input = presets::find("human-hair").unwrap().input;
    input.pigment = Pigment::Absorption(Rgb([0.1, 0.2, 0.4]));
    input.kappa = 0.3;
    input.eta_m = Some(1.3);
    input.sigma_ms = 1.5;
    let m = build(FurParams::new(&input).unwrap(), 1);
    assert!(m.profiles().is_some(), "kappa and sigma_ms > 0 scatter");
    let ts = got.lobes.iter().find(|(n, _)| n == "TttT_s").unwrap().1;
    assert!(ts[0] > 0.0, "the scattered lobe is lit here: {got:?}");
    let a = Angles::from_degrees(20.0, -25.0, 180.0).unwrap();
    assert_eq!(got, expected(&m.model().eval_far_lobes(&a)));
}

#[test]
fn stdin_answers_each_line_in_order_like_single_probes() {
    let queries = [
        ["30", "-20", "45", ""],
        ["10", "-10", "30", "0.2"],
        ["20", "-25", "180", ""],
    ];
    let mut singles = Vec::new();
    for q in &queries {
        let mut args = probe_args("air-medulla", &[q[0], q[1], q[2]]);
        if !q[3].is_empty() {
            args.extend(["--h", q[3]]);
        }
        singles.push(one_line(&ok(&args, None)).to_string());
    }
    let input = format!(
        "# theta_i theta_r phi [h]\n{} {} {}\n\n   \t\n{}\t{}  {} {}\n  # more\n{} {} {}",
        queries[0][0],
        queries[0][1],
        queries[0][2],
        queries[1][0],
        queries[1][1],
        queries[1][2],
        queries[1][3],
        queries[2][0],
        queries[2][1],
        queries[2][2],
    );
    let out = ok(
        &["probe", "--preset", "air-medulla", "--stdin"],
        Some(&input),
    );
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(lines, singles);
    assert_ne!(lines[0], lines[2]);
    // CRLF input works too.
    let crlf = input.replace('\n', "\r\n");
    let out = ok(
        &["probe", "--preset", "air-medulla", "--stdin"],
        Some(&crlf),
    );
    assert_eq!(out.lines().collect::<Vec<_>>(), singles);
    // Empty input: no output, success.
    assert_eq!(
        ok(&["probe", "--preset", "air-medulla", "--stdin"], Some("")),
        ""
    );
}

#[test]
fn malformed_stdin_line_is_reported_by_number_after_the_earlier_output() {
    let args = ["probe", "--preset", "bobcat", "--stdin"];
    let first = one_line(&ok(&probe_args("bobcat", &["30", "-20", "45"]), None)).to_string();
    let o = bad_input(
        &args,
        Some("30 -20 45\n30 oops 45\n10 10 10\n"),
        &["line 2", "oops"],
    );
    assert_eq!(
        stdout(&o),
        format!("{first}\n"),
        "lines before the bad one are printed"
    );
    // Comment and blank lines count in the numbering.
    bad_input(
        &args,
        Some("# c\n30 -20 45\n\n1 2\n"),
        &["line 4:", "found 2"],
    );
    bad_input(&args, Some("30 -20 45 0.5 9\n"), &["line 1:", "found 5"]);
    bad_input(
        &args,
        Some("0 0 0\n95 0 0\n"),
        &["line 2:", "theta_i = 95", "[-90, 90]"],
    );
    bad_input(&args, Some("0 0 0 2\n"), &["line 1:", "h = 2"]);
}

#[test]
fn bad_input_exits_2_with_one_error_line() {
    let mut args = probe_args("no-such-fur", &["30", "-20", "45"]);
    bad_input(
        &args,
        None,
        &["no-such-fur", "bobcat", "human-hair", "air-medulla"],
    );

    args = probe_args("bobcat", &["30", "-20", "45"]);
    let with = |extra: &[&'static str]| {
        let mut a = args.clone();
        a.extend_from_slice(extra);
        a
    };
    bad_input(
        &with(&["--set", "colour=1"]),
        None,
        &["colour", "eta_c", "kappa", "sigma_ca"],
    );
    bad_input(
        &with(&["--set", "kappa=1.2"]),
        None,
        &["kappa", "1.2", "[0, 0.99]"],
    );
    bad_input(&with(&["--set", "kappa=abc"]), None, &["kappa", "abc"]);
    bad_input(&with(&["--set", "sigma_ca=1,2"]), None, &["sigma_ca"]);
    bad_input(
        &probe_args("bobcat", &["91", "0", "0"]),
        None,
        &["theta_i = 91"],
    );
    bad_input(
        &probe_args("bobcat", &["0", "-90.5", "0"]),
        None,
        &["theta_r = -90.5"],
    );
    bad_input(&probe_args("bobcat", &["0", "0", "nan"]), None, &["phi"]);

    // Usage errors found by clap keep clap's format but still fail with code 2.
    for argv in [
        probe_args("bobcat", &["abc", "0", "0"]),
        vec!["probe", "--preset", "bobcat", "--theta-i", "0"],
        vec!["probe", "--preset", "bobcat", "--stdin", "--h", "0.5"],
        vec!["probe", "--theta-i", "0", "--theta-r", "0", "--phi", "0"],
        vec!["frobnicate"],
    ] {
        let o = viewer(&argv, None);
        assert_eq!(o.status.code(), Some(2), "{argv:?}: {}", stderr(&o));
        assert!(stderr(&o).starts_with("error:"), "{argv:?}: {}", stderr(&o));
    }
}

#[test]
fn presets_lists_every_builtin_with_its_parameters_and_source() {
    let out = ok(&["presets"], None);
    let lines: Vec<&str> = out.lines().collect();
    let n = presets::PRESETS.len();
    // The header walks the schema: one column per row but the melanin keys and the base
    // colour (they share σ_ca's column).
    let header: Vec<&str> = lines[0].split_whitespace().collect();
    assert_eq!(header[0], "name");
    assert_eq!(header.len(), 1 + bcsdf_core::SCHEMA.len() - 3, "{header:?}");
    for (p, line) in presets::PRESETS.iter().zip(&lines[1..=n]) {
        let cells: Vec<&str> = line.split_whitespace().collect();
        assert_eq!(cells[0], p.name, "{line}");
        let kappa = header.iter().position(|h| *h == "κ").unwrap();
        assert_eq!(
            cells[kappa].parse::<f32>().unwrap(),
            p.input.kappa,
            "{line}"
        );
    }
    assert!(out.contains("bobcat  "), "{out}");
    assert_eq!(lines[n + 2], "sources:");
    for (p, line) in presets::PRESETS.iter().zip(&lines[n + 3..]) {
        assert_eq!(*line, format!("  {}: {}", p.name, p.source));
    }
    assert!(
        out.contains("former names: yan-row-a → bobcat, yan-row-b → red-fox, yan-row-c → raccoon"),
        "{out}"
    );
}

#[test]
fn presets_json_has_every_preset_and_parameter_as_resolved() {
    let out = ok(&["presets", "--json"], None);
    let v: serde_json::Value = serde_json::from_str(one_line(&out)).unwrap();
    let list = v["presets"].as_array().unwrap();
    assert_eq!(list.len(), presets::PRESETS.len());
    for (p, j) in presets::PRESETS.iter().zip(list) {
        assert_eq!(j["name"], p.name);
        assert_eq!(j["source"], p.source);
        let params = j["parameters"].as_object().unwrap();
        let r = p.input.resolved();
        assert_eq!(
            params["kappa"].as_f64().unwrap() as f32,
            r.kappa,
            "{}",
            p.name
        );
        assert_eq!(
            params["eta_m"].as_f64().unwrap() as f32,
            r.eta_m.unwrap(),
            "{}",
            p.name
        );
        assert_eq!(
            params["beta_n_deg"].as_f64().unwrap() as f32,
            r.beta_n_deg.unwrap()
        );
        match p.input.pigment {
            Pigment::Absorption(c) => {
                let got: Vec<f32> = params["sigma_ca"]
                    .as_array()
                    .unwrap()
                    .iter()
                    .map(|x| x.as_f64().unwrap() as f32)
                    .collect();
                assert_eq!(got, c.0, "{}", p.name);
                assert!(!params.contains_key("eumelanin"));
            }
            Pigment::Melanin { eumelanin, .. } => {
                assert_eq!(params["eumelanin"].as_f64().unwrap() as f32, eumelanin);
                assert!(!params.contains_key("sigma_ca"));
            }
            Pigment::BaseColour(c) => {
                let got: Vec<f32> = params["base_colour"]
                    .as_array()
                    .unwrap()
                    .iter()
                    .map(|x| x.as_f64().unwrap() as f32)
                    .collect();
                assert_eq!(got, c.0, "{}", p.name);
                assert!(!params.contains_key("sigma_ca"));
            }
        }
    }
    assert_eq!(v["aliases"][0]["name"], "yan-row-a");
    assert_eq!(v["aliases"][0]["preset"], "bobcat");
}

#[test]
fn former_preset_names_print_a_note_and_evaluate_the_new_preset() {
    let old = viewer(&probe_args("yan-row-b", &["30", "-20", "45"]), None);
    assert_eq!(old.status.code(), Some(0), "{}", stderr(&old));
    assert_eq!(
        stderr(&old).trim_end(),
        "note: preset 'yan-row-b' is now called 'red-fox' (docs/model.md §9); using 'red-fox'"
    );
    let new = viewer(&probe_args("red-fox", &["30", "-20", "45"]), None);
    assert_eq!(stderr(&new), "");
    assert_eq!(old.stdout, new.stdout);
}

#[test]
fn user_preset_file_is_listed_probed_and_checked() {
    let path = format!(
        "{}/cli-user-presets-{}.toml",
        env!("CARGO_TARGET_TMPDIR"),
        std::process::id()
    );
    let text = "[[preset]]\nname = \"my-fur\"\nsource = \"a test\"\neta_c = 1.5\n\
                eumelanin = 0.4\nalpha_deg = 2\nbeta_m_deg = 9\nl = 0.5\nkappa = 0.6\n\
                sigma_ms = 1\ng = 0.3\n";
    std::fs::write(&path, text).unwrap();
    let listed = ok(&["presets", "--presets", &path], None);
    assert!(
        listed.lines().nth(1).unwrap().starts_with("my-fur  "),
        "{listed}"
    );
    assert!(listed.ends_with("sources:\n  my-fur: a test\n"), "{listed}");
    let mut args = probe_args("my-fur", &["30", "-20", "45"]);
    args.extend(["--presets", &path]);
    let got = parse_probe(one_line(&ok(&args, None)));
    let list = bake::presets::load_file(&path).unwrap();
    let m = build(FurParams::new(&list[0].input).unwrap(), 1);
    let a = Angles::from_degrees(30.0, -20.0, 45.0).unwrap();
    assert_eq!(got, expected(&m.model().eval_far_lobes(&a)));
    // The built-ins are not in a user file.
    let mut args = probe_args("bobcat", &["30", "-20", "45"]);
    args.extend(["--presets", &path]);
    bad_input(&args, None, &["bobcat", "my-fur"]);

    std::fs::write(&path, text.replace("kappa = 0.6", "kappa = 1.6")).unwrap();
    let line9 = format!("{path}:9: preset \"my-fur\": invalid kappa = 1.6");
    bad_input(&["presets", "--presets", &path], None, &[&line9]);
    bad_input(&args, None, &[&line9]);
    std::fs::remove_file(&path).unwrap();
    bad_input(&["presets", "--presets", &path], None, &[&path]);
}

#[test]
fn help_shows_usage_and_examples() {
    for argv in [
        vec!["--help"],
        vec!["probe", "--help"],
        vec!["presets", "--help"],
    ] {
        let out = ok(&argv, None);
        assert!(out.contains("Usage:"), "{argv:?}: {out}");
        assert!(out.contains("Examples:"), "{argv:?}: {out}");
    }
    let probe = ok(&["probe", "--help"], None);
    for flag in [
        "--preset",
        "--presets",
        "--set",
        "--theta-i",
        "--theta-r",
        "--phi",
        "--h",
        "--stdin",
        "--cache-dir",
        "--no-cache",
        "--seed",
        "--photons-scale",
        "--threads",
        "FUR_BCSDF_CACHE",
    ] {
        assert!(probe.contains(flag), "probe --help lacks {flag}");
    }
}

/// The cache files in `dir` (sorted), but for the entries' lock files (`*.lock`).
/// The medulla profile entries of a cache directory (no locks; the energy closure's residual
/// tables, which share the directory, are [`residual_files`]).
fn cache_files(dir: &Path) -> Vec<PathBuf> {
    entries(dir, false)
}

/// The residual table entries (`residual-<hash>.furres`) of a cache directory.
fn residual_files(dir: &Path) -> Vec<PathBuf> {
    entries(dir, true)
}

fn entries(dir: &Path, residual: bool) -> Vec<PathBuf> {
    let mut files: Vec<PathBuf> = match std::fs::read_dir(dir) {
        Ok(rd) => rd
            .map(|e| e.unwrap().path())
            .filter(|p| p.extension().is_none_or(|e| e != "lock"))
            .filter(|p| {
                let name = p.file_name().and_then(|n| n.to_str()).unwrap_or("");
                name.starts_with("residual-") == residual
            })
            .collect(),
        Err(_) => Vec::new(),
    };
    files.sort();
    files
}

fn lobe<'a>(p: &'a Probe, name: &str) -> &'a [f32; 3] {
    &p.lobes.iter().find(|(n, _)| n == name).unwrap().1
}

#[test]
fn profiles_are_cached_per_parameter_set_and_reused() {
    let dir = temp_dir();
    let d = dir.path().to_str().unwrap();
    let angles = ["30", "-20", "45"];
    let mut args = probe_args("bobcat", &angles);
    args.extend(["--cache-dir", d]);
    let first = ok(&args, None);
    let p = parse_probe(one_line(&first));
    assert!(lobe(&p, "TttT_s")[0] > 0.0, "{p:?}");
    let files = cache_files(dir.path());
    assert_eq!(files.len(), 1, "{files:?}");
    let name = files[0].file_name().unwrap().to_str().unwrap();
    assert!(
        name.starts_with("medulla-") && name.ends_with(".furprof"),
        "{name}"
    );
    let bytes = std::fs::read(&files[0]).unwrap();
    // A hit: same answer, file untouched, nothing on stderr.
    assert_eq!(ok(&args, None), first);
    assert_eq!(std::fs::read(&files[0]).unwrap(), bytes);
    // Another parameter set, or another seed, gets its own file.
    let mut other = args.clone();
    other.extend(["--set", "g=0.5"]);
    ok(&other, None);
    let mut seeded = args.clone();
    seeded.extend(["--seed", "2"]);
    ok(&seeded, None);
    assert_eq!(cache_files(dir.path()).len(), 3);
    assert_eq!(std::fs::read(&files[0]).unwrap(), bytes);
    // Each parameter set's residual table is cached beside its profiles.
    assert_eq!(residual_files(dir.path()).len(), 3);
    // A preset that needs no profiles (kappa = 0) writes no profile, only its residual.
    let hair = temp_dir();
    let mut args = probe_args("human-hair", &angles);
    args.extend(["--cache-dir", hair.path().to_str().unwrap()]);
    ok(&args, None);
    assert!(cache_files(hair.path()).is_empty());
    assert_eq!(residual_files(hair.path()).len(), 1);
}

#[test]
fn stale_or_corrupt_cache_is_noted_regenerated_and_rewritten() {
    let dir = temp_dir();
    let mut args = probe_args("air-medulla", &["10", "-10", "30"]);
    args.extend(["--cache-dir", dir.path().to_str().unwrap()]);
    let good_out = ok(&args, None);
    let file = cache_files(dir.path()).pop().unwrap();
    let good = std::fs::read(&file).unwrap();
    let mut flipped = good.clone();
    flipped[200] ^= 0x10;
    let mut stale = good.clone();
    stale[12] = stale[12].wrapping_add(1); // generator version, with a valid checksum
    let body = stale.len() - 8;
    let sum = profiles::fnv1a64(&stale[..body]);
    stale[body..].copy_from_slice(&sum.to_le_bytes());
    let cases: [(&str, Vec<u8>); 4] = [
        ("truncated", good[..good.len() / 2].to_vec()),
        ("checksum", flipped),
        ("generator version", stale),
        ("bad magic", b"not a cache".to_vec()),
    ];
    for (needle, bytes) in cases {
        std::fs::write(&file, &bytes).unwrap();
        let o = viewer(&args, None);
        assert!(o.status.success(), "{needle}: {}", stderr(&o));
        assert_eq!(
            stdout(&o),
            good_out,
            "{needle}: stdout stays the pure JSON answer"
        );
        let err = stderr(&o);
        assert_eq!(err.lines().count(), 1, "{needle}: one note line: {err:?}");
        assert!(err.starts_with("note: "), "{err:?}");
        for want in [needle, "regenerated", file.to_str().unwrap()] {
            assert!(err.contains(want), "{err:?} should contain {want:?}");
        }
        assert_eq!(
            std::fs::read(&file).unwrap(),
            good,
            "{needle}: the good file is rewritten"
        );
        // And it is used quietly from then on.
        assert_eq!(ok(&args, None), good_out);
    }
    assert_eq!(
        cache_files(dir.path()),
        vec![file],
        "no stray temporary files"
    );
}

#[test]
fn no_cache_env_var_and_default_directories() {
    let args = probe_args("raccoon", &["20", "-25", "180"]);
    let reference = ok(&args, None);

    // --no-cache: same bits, nothing written anywhere.
    let env_dir = temp_dir();
    let mut no_cache = args.clone();
    no_cache.push("--no-cache");
    let o = viewer_env(
        &no_cache,
        None,
        &[("FUR_BCSDF_CACHE", Some(env_dir.path()))],
    );
    assert!(o.status.success() && o.stderr.is_empty(), "{}", stderr(&o));
    assert_eq!(stdout(&o), reference);
    assert!(cache_files(env_dir.path()).is_empty());

    // $FUR_BCSDF_CACHE.
    let o = viewer_env(&args, None, &[("FUR_BCSDF_CACHE", Some(env_dir.path()))]);
    assert!(o.status.success() && o.stderr.is_empty(), "{}", stderr(&o));
    assert_eq!(stdout(&o), reference);
    assert_eq!(cache_files(env_dir.path()).len(), 1);

    // --cache-dir wins over the variable.
    let flag_dir = temp_dir();
    let mut flagged = args.clone();
    flagged.extend(["--cache-dir", flag_dir.path().to_str().unwrap()]);
    let o = viewer_env(&flagged, None, &[("FUR_BCSDF_CACHE", Some(env_dir.path()))]);
    assert_eq!(stdout(&o), reference);
    assert_eq!(cache_files(flag_dir.path()).len(), 1);
    assert_eq!(cache_files(env_dir.path()).len(), 1);

    // ${XDG_CACHE_HOME}/fur-bcsdf, else $HOME/.cache/fur-bcsdf.
    let xdg = temp_dir();
    let o = viewer_env(
        &args,
        None,
        &[
            ("FUR_BCSDF_CACHE", None),
            ("XDG_CACHE_HOME", Some(xdg.path())),
        ],
    );
    assert_eq!(stdout(&o), reference, "{}", stderr(&o));
    assert_eq!(cache_files(&xdg.path().join("fur-bcsdf")).len(), 1);
    let home = temp_dir();
    let o = viewer_env(
        &args,
        None,
        &[
            ("FUR_BCSDF_CACHE", None),
            ("XDG_CACHE_HOME", None),
            ("HOME", Some(home.path())),
        ],
    );
    assert_eq!(stdout(&o), reference, "{}", stderr(&o));
    assert_eq!(
        cache_files(&home.path().join(".cache").join("fur-bcsdf")).len(),
        1
    );
}

#[test]
fn seed_threads_and_photon_scale() {
    let angles = ["30", "-20", "45"];
    let args = probe_args("red-fox", &angles);
    let base = parse_probe(one_line(&ok(&args, None)));
    let mut seeded = args.clone();
    seeded.extend(["--seed", "2", "--threads", "1"]);
    let two = parse_probe(one_line(&ok(&seeded, None)));
    // Another seed: other scattered lobes, the same unscattered ones.
    assert_eq!(
        base.lobes[..bcsdf_core::UNSCATTERED_COUNT],
        two.lobes[..bcsdf_core::UNSCATTERED_COUNT]
    );
    assert_ne!(lobe(&base, "TttT_s"), lobe(&two, "TttT_s"));
    let params = FurParams::new(&presets::find("red-fox").unwrap().input).unwrap();
    let a = Angles::from_degrees(30.0, -20.0, 45.0).unwrap();
    assert_eq!(two, expected(&build(params, 2).model().eval_far_lobes(&a)));
    // The thread count does not change the bits.
    let mut threads = args.clone();
    threads.extend(["--threads", "2", "--no-cache"]);
    assert_eq!(parse_probe(one_line(&ok(&threads, None))), base);
    // Another photon count: other profiles.
    let mut scaled = args.clone();
    scaled.extend(["--photons-scale", "0.02", "--no-cache"]);
    let scaled = parse_probe(one_line(&ok(&scaled, None)));
    assert_ne!(lobe(&base, "TttT_s"), lobe(&scaled, "TttT_s"));
    for bad in ["0", "-1", "nan", "inf"] {
        let mut a = args.clone();
        a.extend(["--photons-scale", bad]);
        let o = viewer(&a, None);
        assert_eq!(o.status.code(), Some(2), "{bad}: {}", stderr(&o));
        assert!(stderr(&o).starts_with("error:"), "{}", stderr(&o));
    }
    let mut both = args.clone();
    both.extend(["--no-cache", "--cache-dir", "/tmp"]);
    assert_eq!(viewer(&both, None).status.code(), Some(2));
}

#[test]
fn unwritable_cache_directory_is_an_error_naming_it() {
    let dir = temp_dir();
    let blocker = dir.path().join("a-file");
    std::fs::write(&blocker, "not a directory").unwrap();
    let bad = blocker.join("cache");
    let mut args = probe_args("bobcat", &["30", "-20", "45"]);
    args.extend(["--cache-dir", bad.to_str().unwrap()]);
    let o = viewer(&args, None);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(o.stdout.is_empty());
    assert_eq!(err.lines().count(), 1, "{err:?}");
    assert!(err.starts_with("error: "), "{err:?}");
    assert!(err.contains(bad.to_str().unwrap()), "{err:?}");
    assert!(err.contains("not writable"), "{err:?}");
    // A preset that needs no profiles still caches its energy closure's residual table: the
    // same error. In the report closure (no residual) it does not touch the cache and works.
    let mut hair = probe_args("human-hair", &["30", "-20", "45"]);
    hair.extend(["--cache-dir", bad.to_str().unwrap()]);
    let o = viewer(&hair, None);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(stderr(&o).contains("not writable"), "{}", stderr(&o));
    hair.extend(["--set", "closure=report"]);
    ok(&hair, None);
}
