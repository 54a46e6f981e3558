//! Running the `bake` binary in tests (Cargo builds it for them, `CARGO_BIN_EXE_bake`): the
//! command, its output as text, the files it left, and the rows of its summary table.
#![allow(dead_code)] // each test file uses some of them

use std::collections::BTreeMap;
use std::fs;
use std::path::Path;
use std::process::{Command, Output};

/// The cheapest bake the CLI offers: tiny tables, the fewest absorption planes (three: one
/// residual simulation in the energy closure instead of eight), few photons, no error check,
/// a 16 × 16 quadrature for the dual-scattering tables (the default's 128 × 96 costs seconds
/// per preset), one thread. (Add `--no-cache` or `--cache-dir`.)
pub const CHEAP: [&str; 16] = [
    "--res-sum",
    "64",
    "--res-theta-r",
    "8",
    "--res-phi",
    "16",
    "--res-ms",
    "12",
    "--res-abs",
    "3",
    "--photons-scale",
    "0.005",
    "--res-dual",
    "16,16",
    "--no-check",
    "--threads=1",
];

/// `bake ARGS`, with the default profile cache pointed at `FUR_BCSDF_CACHE` when the caller
/// sets it (tests never touch the user's cache: they pass `--no-cache` or `--cache-dir`).
pub fn bake(args: &[&str]) -> Command {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_bake"));
    cmd.args(args);
    cmd
}

pub fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

pub fn check_success(o: &Output, what: &str) {
    assert!(
        o.status.success(),
        "{what}: {:?}\nstdout:\n{}\nstderr:\n{}",
        o.status,
        text(&o.stdout),
        text(&o.stderr)
    );
}

/// Every file in `dir` (no subfolders expected), by name.
pub fn files(dir: &Path) -> BTreeMap<String, Vec<u8>> {
    fs::read_dir(dir)
        .unwrap()
        .map(|e| {
            let e = e.unwrap();
            assert!(e.file_type().unwrap().is_file(), "{:?}", e.path());
            (
                e.file_name().into_string().unwrap(),
                fs::read(e.path()).unwrap(),
            )
        })
        .collect()
}

/// Every file and folder under `root`, as paths relative to it (folders end in `/`).
pub fn tree(root: &Path) -> Vec<String> {
    let mut out = Vec::new();
    let mut stack = vec![root.to_path_buf()];
    while let Some(dir) = stack.pop() {
        for e in fs::read_dir(&dir).unwrap() {
            let e = e.unwrap();
            let rel = e.path().strip_prefix(root).unwrap().display().to_string();
            if e.file_type().unwrap().is_dir() {
                out.push(format!("{rel}/"));
                stack.push(e.path());
            } else {
                out.push(rel);
            }
        }
    }
    out.sort();
    out
}

/// The rows of the summary table (between the header and the "wrote" line), split into
/// columns: preset, f16 KB, LUT KB, EXR KB, dual KB, dual s, profiles, …
pub fn summary_rows(stdout: &str) -> Vec<Vec<String>> {
    stdout
        .lines()
        .skip_while(|l| !l.starts_with("preset "))
        .skip(1)
        .take_while(|l| !l.starts_with("wrote "))
        .map(|l| l.split_whitespace().map(str::to_string).collect())
        .collect()
}

/// The preset names of the summary table's rows.
pub fn summary_presets(stdout: &str) -> Vec<String> {
    summary_rows(stdout)
        .into_iter()
        .map(|r| r[0].clone())
        .collect()
}
