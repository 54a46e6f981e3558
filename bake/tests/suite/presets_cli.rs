//! Built-in preset names through the `bake` binary (docs/model.md §9):
//!
//! - a former name (`yan-row-c`) prints one `note:` line naming the new preset and bakes the
//!   same bytes, under the new name, as the new name (`raccoon`);
//! - an unknown name exits with 2 and one `error:` line listing the known names, and writes
//!   nothing.
//!
//! The bakes are the cheapest the CLI offers (tiny tables, few photons, no cache, no check).

use crate::cli_support;

use cli_support::{bake as command, text, CHEAP};
use std::fs;
use std::path::PathBuf;
use std::process::Output;

/// The cheapest bake of `args` into `out`, without the profile cache.
fn bake(args: &[&str], out: &PathBuf) -> Output {
    command(args)
        .args(CHEAP)
        .arg("--no-cache")
        .arg("--out")
        .arg(out)
        .output()
        .unwrap()
}

fn fresh_dir(tag: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("presets-cli-{tag}-{}", std::process::id()));
    let _ = fs::remove_dir_all(&dir);
    dir
}

fn stderr(o: &Output) -> String {
    text(&o.stderr)
}

#[test]
fn former_name_prints_a_note_and_bakes_the_new_presets_bytes() {
    let (old_dir, new_dir) = (fresh_dir("old"), fresh_dir("new"));
    let old = bake(&["--preset", "yan-row-c"], &old_dir);
    assert!(old.status.success(), "{}", stderr(&old));
    let notes: Vec<String> = stderr(&old)
        .lines()
        .filter(|l| l.starts_with("note: preset"))
        .map(str::to_owned)
        .collect();
    assert_eq!(
        notes,
        ["note: preset 'yan-row-c' is now called 'raccoon' (docs/model.md §9); using 'raccoon'"]
    );
    let new = bake(&["--preset", "raccoon"], &new_dir);
    assert!(new.status.success(), "{}", stderr(&new));
    assert!(!stderr(&new).contains("note: preset"), "{}", stderr(&new));
    for file in ["raccoon.furlut", "raccoon.exr", "raccoon.furdual"] {
        let (a, b) = (
            fs::read(old_dir.join(file)).unwrap(),
            fs::read(new_dir.join(file)).unwrap(),
        );
        assert!(a == b, "{file} differs between yan-row-c and raccoon");
    }
    assert!(!old_dir.join("yan-row-c.furlut").exists());
    for d in [old_dir, new_dir] {
        fs::remove_dir_all(d).unwrap();
    }
}

#[test]
fn unknown_preset_exits_2_with_one_error_line_listing_the_names() {
    let dir = fresh_dir("unknown");
    let o = bake(&["--preset", "no-such-fur"], &dir);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    let err = stderr(&o);
    let lines: Vec<&str> = err.lines().filter(|l| !l.trim().is_empty()).collect();
    assert_eq!(lines.len(), 1, "{err}");
    assert!(lines[0].starts_with("error:"), "{err}");
    for name in bcsdf_core::presets::PRESETS.iter().map(|p| p.name) {
        assert!(lines[0].contains(name), "{name} missing from {err}");
    }
    assert!(!dir.exists() || fs::read_dir(&dir).unwrap().next().is_none());
}
