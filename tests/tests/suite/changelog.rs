//! CHANGELOG.md against the code: every value `lut::FORMAT_VERSION`, `MODEL_VERSION` and
//! `dual::DUAL_FORMAT_VERSION` have taken has an entry (a list item
//! `- **LUT format N** (DATE; re-bake: yes|no) ...`, `- **Model version N** ...` or
//! `- **Dual format N** ...`, its layout described at the top of the changelog), and the
//! latest release heading is the version of every crate of the workspace (which is what
//! `fur_version()`, `bake --version` and `viewer --version` print: their own tests check that).

use bcsdf_core::dual::DUAL_FORMAT_VERSION;
use bcsdf_core::lut::FORMAT_VERSION;
use bcsdf_core::MODEL_VERSION;
use std::path::PathBuf;
use std::process::Command;

fn repo_root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..")
}

fn changelog() -> String {
    let path = repo_root().join("CHANGELOG.md");
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// The version entries for `kind` (`"LUT format"`, `"Model version"` or `"Dual format"`): the number of each
/// list item that starts with `- **{kind} N**`, with the rest of its first line.
fn entries<'a>(text: &'a str, kind: &str) -> Vec<(u32, &'a str)> {
    let prefix = format!("- **{kind} ");
    text.lines()
        .filter_map(|line| {
            let rest = line.strip_prefix(&prefix)?;
            let (number, after) = rest.split_once("**")?;
            Some((number.trim().parse().ok()?, after))
        })
        .collect()
}

/// `Ok` when the entries for `kind` are exactly versions 1 to `current`, once each, each with
/// `(YYYY-MM-DD; re-bake: yes` or `...; re-bake: no`; else the problem, in one line.
fn check(text: &str, kind: &str, constant: &str, current: u32) -> Result<(), String> {
    let found = entries(text, kind);
    for v in 1..=current {
        let n = found.iter().filter(|(n, _)| *n == v).count();
        if n != 1 {
            return Err(format!(
                "CHANGELOG.md has {n} entries for {kind} {v} ({constant} is {current}): \
                 add one `- **{kind} {v}** (YYYY-MM-DD; re-bake: yes|no) what changed`"
            ));
        }
    }
    if let Some((v, _)) = found.iter().find(|(v, _)| *v == 0 || *v > current) {
        return Err(format!(
            "CHANGELOG.md has an entry for {kind} {v}, but {constant} is {current}"
        ));
    }
    for (v, after) in &found {
        let ok = after.strip_prefix(" (").is_some_and(|s| {
            let (date, rest) = s.split_at(s.len().min(10));
            is_date(date)
                && (rest.starts_with("; re-bake: yes") || rest.starts_with("; re-bake: no"))
        });
        if !ok {
            return Err(format!(
                "CHANGELOG.md's entry for {kind} {v} lacks `(YYYY-MM-DD; re-bake: yes|no)`"
            ));
        }
    }
    Ok(())
}

fn is_date(s: &str) -> bool {
    let b = s.as_bytes();
    b.len() == 10
        && b[4] == b'-'
        && b[7] == b'-'
        && b.iter()
            .enumerate()
            .all(|(i, c)| i == 4 || i == 7 || c.is_ascii_digit())
}

/// The version of the latest release heading, `## [X.Y.Z] - YYYY-MM-DD` (`[Unreleased]` is
/// skipped).
fn latest_release(text: &str) -> Option<&str> {
    text.lines().find_map(|line| {
        let rest = line.strip_prefix("## [")?;
        let (version, date) = rest.split_once("] - ")?;
        (version != "Unreleased" && is_date(date.trim())).then_some(version)
    })
}

#[test]
fn every_lut_format_and_model_version_has_an_entry() {
    let text = changelog();
    check(&text, "LUT format", "lut::FORMAT_VERSION", FORMAT_VERSION)
        .unwrap_or_else(|e| panic!("{e}"));
    check(&text, "Model version", "MODEL_VERSION", MODEL_VERSION).unwrap_or_else(|e| panic!("{e}"));
    check(
        &text,
        "Dual format",
        "dual::DUAL_FORMAT_VERSION",
        DUAL_FORMAT_VERSION,
    )
    .unwrap_or_else(|e| panic!("{e}"));
}

/// The checker itself, on a made-up changelog: complete, missing the next version, ahead of
/// the constant, an entry without its date and re-bake, an entry twice.
#[test]
fn a_version_without_an_entry_or_with_a_malformed_one_is_refused() {
    let two = "- **LUT format 1** (2026-11-22; re-bake: no) first\n\
               - **LUT format 2** (2026-12-01; re-bake: yes) sampling section\n";
    assert_eq!(check(two, "LUT format", "FORMAT_VERSION", 2), Ok(()));
    let e = check(two, "LUT format", "FORMAT_VERSION", 3).unwrap_err();
    assert!(e.contains("0 entries for LUT format 3"), "{e}");
    let e = check(two, "LUT format", "FORMAT_VERSION", 1).unwrap_err();
    assert!(
        e.contains("entry for LUT format 2, but FORMAT_VERSION is 1"),
        "{e}"
    );
    let e = check(two, "Model version", "MODEL_VERSION", 1).unwrap_err();
    assert!(e.contains("0 entries for Model version 1"), "{e}");
    let undated = "- **LUT format 1** (2026-11-22; re-bake: no)\n- **LUT format 2** re-bake\n";
    let e = check(undated, "LUT format", "FORMAT_VERSION", 2).unwrap_err();
    assert!(e.contains("entry for LUT format 2 lacks"), "{e}");
    let twice = "- **LUT format 1** (2026-11-22; re-bake: no)\n".repeat(2);
    let e = check(&twice, "LUT format", "FORMAT_VERSION", 1).unwrap_err();
    assert!(e.contains("2 entries for LUT format 1"), "{e}");
}

/// The latest release heading is this crate's version, and every package of the workspace has
/// the same version (`cargo metadata`).
#[test]
fn the_latest_release_is_every_crates_version() {
    let text = changelog();
    let latest = latest_release(&text).expect("CHANGELOG.md has no `## [X.Y.Z] - YYYY-MM-DD`");
    assert_eq!(
        latest,
        env!("CARGO_PKG_VERSION"),
        "CHANGELOG.md's latest release"
    );
    let out = Command::new(env!("CARGO"))
        .args([
            "metadata",
            "--no-deps",
            "--offline",
            "--format-version",
            "1",
        ])
        .arg("--manifest-path")
        .arg(repo_root().join("Cargo.toml"))
        .output()
        .expect("cargo metadata runs");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let meta: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let packages = meta["packages"].as_array().unwrap();
    assert!(packages.len() >= 6, "{} packages", packages.len());
    for p in packages {
        assert_eq!(
            p["version"].as_str(),
            Some(latest),
            "{} has another version than CHANGELOG.md's latest release",
            p["name"]
        );
    }
}
