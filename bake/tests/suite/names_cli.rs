//! Preset names cannot escape `--out` (docs/model.md §9, "Preset names"):
//!
//! - through the binary, every form of bad name (in a preset file, or given to `--preset`)
//!   exits 2 with one `error:` line naming the file, the line and the field, and writes
//!   nothing anywhere: not `--out`, not beside it, not the profile cache;
//! - a property test over random names: writing a bake under any name (the library's
//!   `write_bake`, the step of `bake_preset` that names files, which does not go through the
//!   preset-file check) either refuses the name and writes nothing, or writes exactly
//!   `<out>/<name>.exr`, `.furlut` and `.furdual`; the bake itself is computed once (its
//!   tables do not depend on the name), and `bake_preset` is checked to refuse a bad name
//!   before any work.

use crate::cli_support;

use bake::pipeline::{self, BakeError, BakeOptions};
use bake::presets::NamedPreset;
use bake::profiles::ProfileOptions;
use bcsdf_core::lut::LutResolution;
use cli_support::{bake, text, tree};
use proptest::prelude::*;
use std::fs;
use std::path::Path;
use std::sync::OnceLock;

/// A valid preset without medulla profiles (κ = 0), then a second one whose name line
/// (line 16) the tests replace.
const FILE: &str = r#"# line 1
[[preset]]
name = "good"
source = "test"
eta_c = 1.55
eumelanin = 0.2
alpha_deg = 3.0
beta_m_deg = 6.0
l = 0.5
kappa = 0.0
sigma_ms = 0.0
g = 0.0

[[preset]]
source = "test"
name = "NAME"
eta_c = 1.55
eumelanin = 0.4
alpha_deg = 3.0
beta_m_deg = 6.0
l = 0.5
kappa = 0.0
sigma_ms = 0.0
g = 0.0
"#;

/// The bad forms: (TOML string literal, the name it holds, what the message says).
const BAD: [(&str, &str, &str); 17] = [
    (r#""../escaped""#, "../escaped", "contains '/' at byte 2"),
    (
        r#""../../home/x/.bashrc""#,
        "../../home/x/.bashrc",
        "contains '/'",
    ),
    (r#""/tmp/abs""#, "/tmp/abs", "contains '/' at byte 0"),
    (r#""sub/dir""#, "sub/dir", "contains '/' at byte 3"),
    (r#""..\\win""#, "..\\win", "contains '\\\\' at byte 2"),
    (r#""c:drive""#, "c:drive", "contains ':' at byte 1"),
    (r#""..""#, "..", "starts with '.'"),
    (r#"".hidden""#, ".hidden", "starts with '.'"),
    (r#""-rf""#, "-rf", "starts with '-'"),
    (r#""""#, "", "is empty"),
    (r#""two words""#, "two words", "contains ' ' at byte 3"),
    (r#""tab\there""#, "tab\there", "contains '\\t' at byte 3"),
    (r#""new\nline""#, "new\nline", "contains '\\n' at byte 3"),
    (r#""fourrure-é""#, "fourrure-é", "contains 'é' at byte 9"),
    (r#""NUL""#, "NUL", "is the Windows device name NUL"),
    (
        r#""com1.fur""#,
        "com1.fur",
        "is the Windows device name COM1",
    ),
    (
        r#""a123456789a123456789a123456789a123456789a123456789a123456789abcde""#,
        "a123456789a123456789a123456789a123456789a123456789a123456789abcde",
        "is 65 bytes long; at most 64 are allowed",
    ),
];

#[test]
fn every_bad_name_exits_2_naming_file_line_and_field_and_writes_nothing() {
    let dir = tempfile::tempdir().unwrap();
    // --out two levels down, so that `..` and `../..` land inside the temporary folder.
    let root = dir.path();
    let out = root.join("a").join("b").join("out");
    let cache = root.join("cache");
    fs::create_dir_all(root.join("a").join("b")).unwrap();
    let presets = root.join("p.toml");
    let out_s = out.to_str().unwrap();
    for (literal, name, why) in BAD {
        fs::write(&presets, FILE.replace("\"NAME\"", literal)).unwrap();
        let before = tree(root);
        let o = bake(&[
            "--presets",
            presets.to_str().unwrap(),
            "--all",
            "--out",
            out_s,
            "--no-check",
        ])
        .env("FUR_BCSDF_CACHE", &cache)
        .output()
        .unwrap();
        let stderr = text(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{name:?}: {stderr}");
        assert!(
            stderr.starts_with(&format!(
                "error: {}:16: name {name:?} {why}",
                presets.display()
            )),
            "{name:?}: {stderr}"
        );
        assert_eq!(stderr.lines().count(), 1, "{stderr}");
        assert!(o.stdout.is_empty(), "{name:?}");
        assert_eq!(tree(root), before, "{name:?} wrote something");
        // Nothing at the absolute destinations either.
        for ext in ["exr", "furlut", "furdual"] {
            assert!(!Path::new(&format!("/tmp/abs.{ext}")).exists());
        }
    }

    // `--preset NAME` with a bad name: the same rule, before the lookup.
    for (_, name, why) in BAD {
        let before = tree(root);
        let o = bake(&["--preset", name, "--out", out_s, "--no-check"])
            .env("FUR_BCSDF_CACHE", &cache)
            .output()
            .unwrap();
        let stderr = text(&o.stderr);
        // clap takes a leading '-' for an option (its own exit 2); the rest are ours.
        assert_eq!(o.status.code(), Some(2), "--preset {name:?}: {stderr}");
        if !name.starts_with('-') {
            assert!(
                stderr.starts_with(&format!("error: --preset: name {name:?} {why}")),
                "{stderr}"
            );
            assert_eq!(stderr.lines().count(), 1, "{stderr}");
        }
        assert_eq!(tree(root), before, "--preset {name:?} wrote something");
    }
}

fn cheap_options(out: &Path) -> BakeOptions {
    BakeOptions {
        res: LutResolution {
            n_sum: 16,
            n_theta_r: 4,
            n_phi: 8,
            n_ms_i: 4,
            n_ms_r: 4,
            n_abs: 3,
        },
        profiles: ProfileOptions {
            cache_dir: None,
            ..ProfileOptions::default()
        },
        out_dir: out.to_path_buf(),
        metrics: None,
        dual: bcsdf_core::dual::Quadrature {
            theta_steps: 16,
            phi_steps: 16,
        },
    }
}

/// Names a careless or hostile preset file could hold: path-like strings, dots, separators,
/// device names, control characters, any Unicode, and valid names.
fn names() -> impl Strategy<Value = String> {
    prop_oneof![
        "[A-Za-z0-9_][A-Za-z0-9._-]{0,20}",
        "(\\.\\./){1,3}[a-z.]{0,6}",
        "[a-z./\\\\:-]{1,12}",
        "(con|NUL|Aux|com[0-9]|lpt[0-9])(\\.[a-z]{1,3})?",
        "[a-z]{0,3}[\\x00-\\x1f\\x7f ][a-z]{0,3}",
        "[^/]{0,70}",
    ]
}

/// human-hair at [`cheap_options`]' resolution, computed once for every name.
fn computed() -> &'static pipeline::Computed {
    static C: OnceLock<pipeline::Computed> = OnceLock::new();
    C.get_or_init(|| {
        let dir = tempfile::tempdir().unwrap();
        pipeline::compute(
            &human_hair("human-hair"),
            &cheap_options(dir.path()),
            &|_| {},
        )
        .unwrap()
    })
}

fn human_hair(name: &str) -> NamedPreset {
    let input = bake::presets::find(&bake::presets::builtin().unwrap(), "human-hair")
        .unwrap()
        .input;
    NamedPreset {
        name: name.to_owned(),
        source: "test".into(),
        input,
    }
}

/// `bake_preset` checks the name before it computes anything: a bad name is refused at once
/// (no step reported) and nothing is written.
#[test]
fn bake_preset_refuses_a_bad_name_before_any_step() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    fs::create_dir_all(&out).unwrap();
    let steps = std::cell::Cell::new(0);
    let r = pipeline::bake_preset(&human_hair("../x"), &cheap_options(&out), &|_| {
        steps.set(steps.get() + 1)
    });
    assert!(matches!(r, Err(BakeError::Name(_))), "{r:?}");
    assert_eq!(steps.get(), 0);
    assert_eq!(tree(dir.path()), ["out/"]);
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

    #[test]
    fn no_name_writes_outside_out(name in names()) {
        let dir = tempfile::tempdir().unwrap();
        let root = dir.path();
        let out = root.join("a").join("b").join("out");
        fs::create_dir_all(&out).unwrap();
        let valid = bcsdf_core::params::check_name(&name).is_ok();
        match pipeline::write_bake(&out, &name, computed()) {
            Ok(paths) => {
                prop_assert!(valid, "{name:?} was written");
                prop_assert_eq!(paths.exr, out.join(format!("{name}.exr")));
                let mut want = vec![
                    "a/".to_string(),
                    "a/b/".to_string(),
                    "a/b/out/".to_string(),
                    format!("a/b/out/{name}.exr"),
                    format!("a/b/out/{name}.furdual"),
                    format!("a/b/out/{name}.furlut"),
                ];
                want.sort();
                prop_assert_eq!(tree(root), want);
            }
            Err(BakeError::Name(e)) => {
                prop_assert!(!valid, "{name:?} refused: {e}");
                prop_assert_eq!(tree(root), ["a/", "a/b/", "a/b/out/"]);
            }
            Err(e) => prop_assert!(false, "{name:?}: {e}"),
        }
    }
}
