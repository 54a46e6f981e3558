//! The profile cache under concurrent and interrupted bakes, through the binary
//! (`bake::profiles::cache`, "Concurrent bakes"):
//!
//! - three shards run at once on an empty shared cache, each baking one preset of three that
//!   need the same medulla profiles: exactly one generates them (the summary's `profiles`
//!   column says `generated` once and `cached` twice), the cache holds one file, its lock and
//!   no temporary file, and the three LUTs are byte-identical to a serial, uncached bake;
//! - a bake killed (SIGKILL) while it generates an entry leaves no cache file and the entry
//!   unlocked: the next bake regenerates it (removing the killed one's temporary file), and
//!   the one after reads it.

use crate::cli_support;

use cli_support::{bake, check_success, files, summary_rows, text, tree, CHEAP};
use std::fs;
use std::path::Path;
use std::process::{Child, Stdio};
use std::time::{Duration, Instant};

/// Three presets with the same medulla (η_c, κ, σ_ms, σ_ma, g): one profile set for all.
/// They differ in colour and tilt, which the profiles do not depend on.
const SHARED: &str = r#"
[[preset]]
name = "v0"
source = "test"
eta_c = 1.55
eumelanin = 0.5
alpha_deg = 3.0
beta_m_deg = 8.0
l = 1.0
kappa = 0.5
sigma_ms = 1.0
g = 0.3

[[preset]]
name = "v1"
source = "test"
eta_c = 1.55
sigma_ca = [0.2, 0.3, 0.6]
alpha_deg = 2.0
beta_m_deg = 8.0
l = 1.0
kappa = 0.5
sigma_ms = 1.0
g = 0.3

[[preset]]
name = "v2"
source = "test"
eta_c = 1.55
eumelanin = 1.2
pheomelanin = 0.3
alpha_deg = 4.0
beta_m_deg = 8.0
l = 1.0
kappa = 0.5
sigma_ms = 1.0
g = 0.3
"#;

/// The `profiles` column (the seventh) of each summary row.
fn profile_column(stdout: &str) -> Vec<String> {
    summary_rows(stdout)
        .into_iter()
        .map(|r| r[6].clone())
        .collect()
}

/// Cache folder entries by kind: (.furprof files, .lock files, anything else).
fn cache_entries(dir: &Path) -> (Vec<String>, Vec<String>, Vec<String>) {
    let (mut prof, mut lock, mut other) = (vec![], vec![], vec![]);
    for name in tree(dir) {
        // The energy closure's residual tables (one per parameter set, with their own locks)
        // share the directory; these tests count the medulla profiles' entries.
        if name.starts_with("residual-") {
            continue;
        }
        if name.ends_with(".furprof") {
            prof.push(name);
        } else if name.ends_with(".lock") {
            lock.push(name);
        } else {
            other.push(name);
        }
    }
    (prof, lock, other)
}

#[test]
fn concurrent_shards_generate_a_shared_profile_once() {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path();
    let presets = root.join("shared.toml");
    fs::write(&presets, SHARED).unwrap();
    let p = presets.to_str().unwrap();
    let (serial, sharded, cache) = (
        root.join("serial"),
        root.join("sharded"),
        root.join("cache"),
    );

    let mut args = vec!["--presets", p, "--all", "--no-cache"];
    args.extend(["--out", serial.to_str().unwrap()]);
    args.extend(CHEAP);
    let o = bake(&args).output().unwrap();
    check_success(&o, "serial bake");
    assert_eq!(profile_column(&text(&o.stdout)), ["generated"; 3]);

    let n = 3;
    let children: Vec<Child> = (0..n)
        .map(|k| {
            let shard = format!("{k}/{n}");
            let mut args = vec!["--presets", p, "--shard", &shard];
            args.extend(["--out", sharded.to_str().unwrap()]);
            args.extend(["--cache-dir", cache.to_str().unwrap()]);
            args.extend(CHEAP);
            bake(&args)
                .stdout(Stdio::piped())
                .stderr(Stdio::piped())
                .spawn()
                .unwrap()
        })
        .collect();
    let mut column = Vec::new();
    for (k, child) in children.into_iter().enumerate() {
        let o = child.wait_with_output().unwrap();
        check_success(&o, &format!("shard {k}/{n}"));
        column.extend(profile_column(&text(&o.stdout)));
    }
    column.sort();
    assert_eq!(
        column,
        ["cached", "cached", "generated"],
        "one generation in all"
    );

    let (prof, lock, other) = cache_entries(&cache);
    assert_eq!((prof.len(), lock.len()), (1, 1), "{prof:?} {lock:?}");
    assert!(other.is_empty(), "left in the cache: {other:?}");
    assert_eq!(
        prof[0].trim_end_matches(".furprof"),
        lock[0].trim_end_matches(".lock")
    );

    let (a, b) = (files(&serial), files(&sharded));
    assert_eq!(a.len(), 9, "three presets × .exr, .furlut, .furdual");
    assert_eq!(a.keys().collect::<Vec<_>>(), b.keys().collect::<Vec<_>>());
    for (name, bytes) in &a {
        assert!(b[name] == *bytes, "{name} differs from the serial bake");
    }
}

/// Waits for `child` at most `limit`; kills it and fails if it is still running.
fn wait_with_limit(mut child: Child, limit: Duration, what: &str) -> std::process::Output {
    let start = Instant::now();
    while child.try_wait().unwrap().is_none() {
        if start.elapsed() > limit {
            child.kill().unwrap();
            panic!("{what} still running after {limit:?}: a lock was left held?");
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    child.wait_with_output().unwrap()
}

#[test]
fn a_holder_killed_mid_generation_leaves_a_cache_the_next_bake_repairs() {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path();
    let presets = root.join("one.toml");
    // The first preset alone.
    let one = SHARED.split("\n[[preset]]").nth(1).unwrap();
    fs::write(&presets, format!("[[preset]]{one}")).unwrap();
    let cache = root.join("cache");
    let out = root.join("out");
    let mut args = vec!["--presets", presets.to_str().unwrap(), "--all"];
    args.extend(["--out", out.to_str().unwrap()]);
    args.extend(["--cache-dir", cache.to_str().unwrap()]);
    // CHEAP's table sizes and planes with ten times its photons: generation lasts long
    // enough to be interrupted.
    args.extend(&CHEAP[..10]);
    args.extend([
        "--photons-scale",
        "0.05",
        "--res-dual",
        "16,16",
        "--no-check",
        "--threads=1",
    ]);

    // Start a bake and kill it once it holds the lock and is generating: its temporary
    // cache file exists from the moment it takes the lock until it renames it.
    let mut child = bake(&args)
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let start = Instant::now();
    let partial = loop {
        let found = cache
            .is_dir()
            .then(|| cache_entries(&cache).2)
            .and_then(|other| other.into_iter().find(|n| n.ends_with(".partial")));
        if let Some(name) = found {
            break name;
        }
        assert!(
            child.try_wait().unwrap().is_none(),
            "the bake ended before it was killed"
        );
        assert!(
            start.elapsed() < Duration::from_secs(60),
            "no generation started"
        );
        std::thread::sleep(Duration::from_millis(2));
    };
    child.kill().unwrap(); // SIGKILL on Unix
    child.wait().unwrap();
    let (prof, lock, other) = cache_entries(&cache);
    assert!(
        prof.is_empty(),
        "a killed bake wrote a cache file: {prof:?}"
    );
    assert_eq!(lock.len(), 1);
    assert_eq!(other, [partial], "the killed bake's temporary file");

    // The next bake takes the (released) lock, regenerates and cleans up.
    let spawn = || {
        bake(&args)
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap()
    };
    let o = wait_with_limit(spawn(), Duration::from_secs(120), "the bake after the kill");
    check_success(&o, "the bake after the kill");
    assert_eq!(profile_column(&text(&o.stdout)), ["generated"]);
    let (prof, lock, other) = cache_entries(&cache);
    assert_eq!((prof.len(), lock.len()), (1, 1));
    assert!(other.is_empty(), "left in the cache: {other:?}");
    let repaired = files(&out);

    // And the one after reads the repaired file, giving the same LUTs.
    let o = wait_with_limit(spawn(), Duration::from_secs(120), "the third bake");
    check_success(&o, "the third bake");
    assert_eq!(profile_column(&text(&o.stdout)), ["cached"]);
    assert_eq!(files(&out), repaired);
}
