//! `bake --shard K/N` through the binary (Cargo builds it for this test, `CARGO_BIN_EXE_bake`):
//!
//! - the 3 shards of a 4-preset file (two presets in the first, one in each other), run
//!   concurrently into one output folder, write exactly
//!   the files of one unsharded bake, byte for byte, and nothing else;
//! - shard K bakes the presets at positions i ≡ K (mod N), so each preset comes from exactly
//!   one shard;
//! - a shard with no presets succeeds and writes nothing;
//! - malformed `--shard` values and `--shard` with `--preset` exit with 2 and an `error:` line.
//!
//! Every bake is small (tiny tables, 0.5 % of the photon budget, no error check) and bypasses
//! the profile cache, so the unsharded and sharded runs generate their profiles independently.

use crate::cli_support;

use cli_support::{bake, check_success, files, summary_presets, text, CHEAP};
use std::collections::BTreeMap;
use std::fs;
use std::path::PathBuf;

/// Four presets: three with medulla profiles (σ_ms > 0, κ > 0, different g; one an air
/// medulla, η_m ≠ η_c), in the report closure, and one without a medulla in the energy
/// closure, whose residual table is simulated too (a medullated preset's residual
/// simulation costs seconds even in a cheap bake; one preset's shows that it shards).
const PRESETS: &str = r#"
[[preset]]
name = "p0-medulla"
source = "test"
closure = "report"
eta_c = 1.55
sigma_ca = 0.64
alpha_deg = 5.48
beta_m_deg = 11.64
beta_n_deg = 7.49
l = 0.47
kappa = 0.88
sigma_ms = 1.69
sigma_ma = 0.17
g = 0.44

[[preset]]
name = "p1-hair"
source = "test"
eta_c = 1.55
eumelanin = 1.3
pheomelanin = 0.1
alpha_deg = 2.0
beta_m_deg = 7.0
l = 0.5
kappa = 0.0
sigma_ms = 0.0
g = 0.0

[[preset]]
name = "p2-medulla"
source = "test"
closure = "report"
eta_c = 1.49
sigma_ca = [0.2, 0.3, 0.6]
alpha_deg = 2.64
beta_m_deg = 9.45
beta_n_deg = 17.63
l = 0.68
kappa = 0.86
sigma_ms = 3.15
sigma_ma = 0.21
g = 0.79

[[preset]]
name = "p3-air-medulla"
source = "test"
closure = "report"
eta_c = 1.55
eta_m = 1.2
eumelanin = 0.5
alpha_deg = 3.0
beta_m_deg = 8.0
l = 1.0
kappa = 0.5
sigma_ms = 1.0
g = 0.3
"#;

const NAMES: [&str; 4] = ["p0-medulla", "p1-hair", "p2-medulla", "p3-air-medulla"];

struct Setup {
    _dir: tempfile::TempDir,
    root: PathBuf,
    presets: String,
}

fn setup() -> Setup {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path().to_path_buf();
    let presets = root.join("variants.toml");
    fs::write(&presets, PRESETS).unwrap();
    Setup {
        _dir: dir,
        presets: presets.to_str().unwrap().to_string(),
        root,
    }
}

#[test]
fn shards_reproduce_the_unsharded_bake_byte_for_byte() {
    let s = setup();
    let a = s.root.join("a");
    let b = s.root.join("b");
    let (a_str, b_str) = (a.to_str().unwrap(), b.to_str().unwrap());

    // One unsharded bake (all threads) into A.
    let mut args = vec![
        "--presets",
        &s.presets,
        "--all",
        "--out",
        a_str,
        "--no-cache",
    ];
    args.extend(&CHEAP[..CHEAP.len() - 1]);
    let o = bake(&args).output().unwrap();
    check_success(&o, "unsharded bake");
    assert_eq!(summary_presets(&text(&o.stdout)), NAMES);

    // The three shards, concurrently, into one folder B (one thread each).
    let n = 3;
    let children: Vec<_> = (0..n)
        .map(|k| {
            let shard = format!("{k}/{n}");
            let mut args = vec![
                "--presets",
                &s.presets,
                "--shard",
                &shard,
                "--out",
                b_str,
                "--no-cache",
            ];
            args.extend(CHEAP);
            bake(&args)
                .stdout(std::process::Stdio::piped())
                .stderr(std::process::Stdio::piped())
                .spawn()
                .unwrap()
        })
        .collect();
    let mut from_shard: BTreeMap<String, usize> = BTreeMap::new();
    for (k, child) in children.into_iter().enumerate() {
        let o = child.wait_with_output().unwrap();
        check_success(&o, &format!("shard {k}/{n}"));
        let expected: Vec<&str> = NAMES.iter().copied().skip(k).step_by(n).collect();
        let baked = summary_presets(&text(&o.stdout));
        assert_eq!(baked, expected, "shard {k}/{n} baked the wrong presets");
        let stderr = text(&o.stderr);
        assert!(
            stderr.contains(&format!(
                "shard {k}/{n}: {} of {} presets ({})",
                expected.len(),
                NAMES.len(),
                expected.join(", ")
            )),
            "{stderr}"
        );
        for name in baked {
            if let Some(other) = from_shard.insert(name.clone(), k) {
                panic!("{name} baked by shards {other} and {k}");
            }
        }
    }
    // Each preset from exactly one shard.
    assert_eq!(from_shard.keys().collect::<Vec<_>>(), {
        let mut sorted = NAMES.to_vec();
        sorted.sort();
        sorted
    });

    // Same file names (no temporary or shared file left behind), same bytes.
    let (fa, fb) = (files(&a), files(&b));
    let expected_names: Vec<String> = NAMES
        .iter()
        .flat_map(|p| {
            [
                format!("{p}.exr"),
                format!("{p}.furdual"),
                format!("{p}.furlut"),
            ]
        })
        .collect::<std::collections::BTreeSet<_>>()
        .into_iter()
        .collect();
    assert_eq!(fa.keys().cloned().collect::<Vec<_>>(), expected_names);
    assert_eq!(fb.keys().cloned().collect::<Vec<_>>(), expected_names);
    for (name, bytes) in &fa {
        assert!(fb[name] == *bytes, "{name} differs between A and B");
    }
}

#[test]
fn empty_shard_succeeds_and_writes_nothing() {
    let s = setup();
    // The file has 4 presets: shard 4 of 5 is empty.
    let out = s.root.join("empty");
    let mut args = vec![
        "--presets",
        &s.presets,
        "--shard",
        "4/5",
        "--out",
        out.to_str().unwrap(),
        "--no-cache",
    ];
    args.extend(CHEAP);
    let o = bake(&args).output().unwrap();
    check_success(&o, "empty shard");
    assert!(
        text(&o.stderr).contains("shard 4/5: no presets (the list has 4), nothing to bake"),
        "{}",
        text(&o.stderr)
    );
    assert!(
        text(&o.stdout).contains("wrote 0 LUTs"),
        "{}",
        text(&o.stdout)
    );
    assert!(files(&out).is_empty());

    // The built-in presets without --presets: shard n of n + 1 is empty too.
    let n = bcsdf_core::presets::PRESETS.len();
    let shard = format!("{n}/{}", n + 1);
    let out = s.root.join("builtin");
    let o = bake(&["--shard", &shard, "--out", out.to_str().unwrap()])
        .output()
        .unwrap();
    check_success(&o, "empty built-in shard");
    assert!(
        text(&o.stderr).contains(&format!("shard {shard}: no presets (the list has {n})")),
        "{}",
        text(&o.stderr)
    );
    assert!(files(&out).is_empty());
}

#[test]
fn bad_shards_exit_2_with_one_error_line() {
    let s = setup();
    let out = s.root.join("never");
    for (value, message) in [
        (
            "3",
            "error: --shard '3': expected K/N, shard K of N with K counting from 0 (e.g. 0/4 to 3/4)",
        ),
        (
            "a/b",
            "error: --shard 'a/b': K 'a' is not a whole number (expected K/N, e.g. 0/4)",
        ),
        ("0/0", "error: --shard '0/0': N must be at least 1"),
        (
            "5/4",
            "error: --shard '5/4': K must be 0 to 3 for N = 4 (K counts from 0)",
        ),
        (
            "3/3",
            "error: --shard '3/3': K must be 0 to 2 for N = 3 (K counts from 0)",
        ),
    ] {
        let o = bake(&[
            "--presets",
            &s.presets,
            "--shard",
            value,
            "--out",
            out.to_str().unwrap(),
        ])
        .output()
        .unwrap();
        assert_eq!(o.status.code(), Some(2), "--shard {value}");
        assert_eq!(text(&o.stderr), format!("{message}\n"), "--shard {value}");
        assert!(o.stdout.is_empty());
    }
    assert!(!out.exists(), "bad input created the output folder");

    // --shard selects from all presets: with --preset it is rejected (by clap, exit 2).
    let o = bake(&[
        "--shard",
        "0/2",
        "--preset",
        "human-hair",
        "--out",
        out.to_str().unwrap(),
    ])
    .output()
    .unwrap();
    assert_eq!(o.status.code(), Some(2));
    let stderr = text(&o.stderr);
    assert!(
        stderr.starts_with(
            "error: the argument '--shard <K/N>' cannot be used with '--preset <NAME>'"
        ),
        "{stderr}"
    );
}
