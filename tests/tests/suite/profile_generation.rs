//! Medulla profile generation in the std tools (`bake::profiles`): determinism across thread
//! counts and runs, seeds, and the cache file (round trip, damaged and foreign files, an
//! unwritable directory, atomic writes).
//!
//! Budgets are reduced (a few thousand photons per cell) so the whole file runs in seconds;
//! the bits compared are whole tables.

use bake::fsutil::{self, AtomicWriter};
use bake::profiles::{
    self, build_model, decode, encode, fnv1a64, generate_parallel, load_or_generate, CacheError,
    CacheOutcome, Error, OwnedModel, OwnedProfiles, ProfileKey, ProfileOptions,
};
use bcsdf_core::medulla::{self, PhotonBudget, ProfileError, ProfileLayout, Resolution};
use bcsdf_core::residual::{ResidualLayout, ResidualTable};
use bcsdf_core::{presets, Angles, FurBcsdf, FurParams};
use std::io::Write;
use std::path::{Path, PathBuf};

const SMALL: PhotonBudget = PhotonBudget {
    per_cn_cell: 2_000,
    per_cm_row: 4_000,
};

fn params(name: &str) -> FurParams {
    FurParams::new(&presets::find(name).unwrap().input).unwrap()
}

fn layout(name: &str) -> ProfileLayout {
    ProfileLayout::for_params(&params(name), Resolution::DEFAULT)
}

fn bits(v: &[f32]) -> Vec<u32> {
    v.iter().map(|x| x.to_bits()).collect()
}

/// Whole tables, bit for bit.
#[track_caller]
fn assert_same_bits(a: &OwnedProfiles, b: &OwnedProfiles, what: &str) {
    let (ta, tb) = (a.tables(), b.tables());
    assert_eq!(a.key(), b.key(), "{what}: key");
    assert!(bits(ta.0) == bits(tb.0), "{what}: C^N differs");
    assert!(bits(ta.1) == bits(tb.1), "{what}: C^M differs");
}

fn temp_dir() -> tempfile::TempDir {
    tempfile::Builder::new()
        .prefix("profile-generation-")
        .tempdir_in(env!("CARGO_TARGET_TMPDIR"))
        .unwrap()
}

/// The files in `dir`, but for the cache entries' lock files (`*.lock`, kept by design:
/// `bake::profiles::cache`, "Concurrent bakes").
fn files_in(dir: &Path) -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_none_or(|e| e != "lock"))
        .collect();
    v.sort();
    v
}

/// Non-trivial tables: not every cell at the "no scattered photon" fallback, so the
/// comparisons below compare real Monte Carlo output.
fn assert_nontrivial(p: &OwnedProfiles) {
    let (cn, cm) = p.tables();
    let distinct = |t: &[f32]| {
        let mut b = bits(t);
        b.sort_unstable();
        b.dedup();
        b.len()
    };
    assert!(distinct(cn) > cn.len() / 4, "C^N looks constant");
    assert!(distinct(cm) > cm.len() / 4, "C^M looks constant");
}

#[test]
fn same_bits_for_any_thread_count_and_across_runs() {
    let budget = PhotonBudget {
        per_cn_cell: 10_000,
        per_cm_row: 20_000,
    };
    for name in ["red-fox", "air-medulla"] {
        let l = layout(name);
        let one = generate_parallel(&l, &budget, 5, Some(1)).unwrap();
        assert_nontrivial(&one);
        let two = generate_parallel(&l, &budget, 5, Some(2)).unwrap();
        assert_same_bits(&one, &two, &format!("{name}: 1 vs 2 threads"));
        let again = generate_parallel(&l, &budget, 5, Some(2)).unwrap();
        assert_same_bits(&two, &again, &format!("{name}: two runs"));
        let global = generate_parallel(&l, &budget, 5, None).unwrap();
        assert_same_bits(&one, &global, &format!("{name}: global pool"));
        // And equal to the core's sequential generator.
        let (mut cn, mut cm) = (vec![0.0; l.cn_len()], vec![0.0; l.cm_len()]);
        medulla::generate(&l, &budget, 5, &mut cn, &mut cm).unwrap();
        let seq = OwnedProfiles::new(one.key(), cn, cm).unwrap();
        assert_same_bits(&one, &seq, &format!("{name}: core sequential"));
    }
}

#[test]
fn a_different_seed_gives_different_bits() {
    let l = layout("bobcat");
    let a = generate_parallel(&l, &SMALL, 1, None).unwrap();
    let b = generate_parallel(&l, &SMALL, 2, None).unwrap();
    let (ta, tb) = (a.tables(), b.tables());
    for (name, x, y) in [("C^N", ta.0, tb.0), ("C^M", ta.1, tb.1)] {
        let differing = x
            .iter()
            .zip(y)
            .filter(|(p, q)| p.to_bits() != q.to_bits())
            .count();
        assert!(
            differing > x.len() / 2,
            "{name}: only {differing} of {} entries differ between seeds",
            x.len()
        );
    }
}

#[test]
fn an_invalid_layout_is_an_error() {
    let mut l = layout("bobcat");
    l.res.n_h = 0;
    assert!(matches!(
        generate_parallel(&l, &SMALL, 1, Some(1)),
        Err(Error::Profile(ProfileError::BadResolution))
    ));
}

#[test]
fn cache_round_trip_is_bit_exact() {
    let dir = temp_dir();
    let p = params("raccoon");
    let (made, outcome) =
        load_or_generate(&p, Resolution::DEFAULT, SMALL, 3, Some(dir.path()), None).unwrap();
    let CacheOutcome::Generated { path: Some(path) } = outcome else {
        panic!("expected Generated with a path, got {outcome:?}");
    };
    assert_eq!(
        files_in(dir.path()),
        vec![path.clone()],
        "one file, no temporaries"
    );
    assert_eq!(std::fs::read(&path).unwrap(), encode(&made));
    let (read, outcome) =
        load_or_generate(&p, Resolution::DEFAULT, SMALL, 3, Some(dir.path()), None).unwrap();
    assert!(
        matches!(&outcome, CacheOutcome::Hit { path: hit } if *hit == path),
        "{outcome:?}"
    );
    assert_same_bits(&made, &read, "cache round trip");
    // The profiles match the generator run without any cache.
    let fresh = generate_parallel(made.layout(), &SMALL, 3, Some(2)).unwrap();
    assert_same_bits(&made, &fresh, "cached vs fresh");
    // Another seed, budget or parameter set has another file name.
    let key = made.key();
    let mut other = key;
    other.seed = 4;
    assert_ne!(key.file_name(), other.file_name());
    other = key;
    other.budget.per_cn_cell += 1;
    assert_ne!(key.file_name(), other.file_name());
    other.budget = key.budget;
    other.layout = layout("bobcat");
    assert_ne!(key.file_name(), other.file_name());
}

/// Writes `bytes` to the cache file of `params`, runs `load_or_generate`, and checks that the
/// file was rejected for a reason `expect` accepts, the profiles are the good ones, and the
/// good file is back.
#[track_caller]
fn check_rejected(
    dir: &Path,
    p: &FurParams,
    good: &OwnedProfiles,
    bytes: &[u8],
    what: &str,
    expect: impl Fn(&CacheError) -> bool,
) {
    let path = dir.join(good.key().file_name());
    std::fs::write(&path, bytes).unwrap();
    let (got, outcome) = load_or_generate(
        p,
        Resolution::DEFAULT,
        SMALL,
        good.seed(),
        Some(dir),
        Some(2),
    )
    .unwrap();
    match &outcome {
        CacheOutcome::Regenerated { path: p2, reason } => {
            assert_eq!(*p2, path, "{what}");
            assert!(expect(reason), "{what}: unexpected reason {reason:?}");
            let note = outcome.note().unwrap();
            assert_eq!(note.lines().count(), 1, "{what}: {note}");
            assert!(note.contains(&reason.to_string()), "{what}: {note}");
        }
        other => panic!("{what}: the file must be rejected, got {other:?}"),
    }
    assert_same_bits(good, &got, what);
    assert_eq!(
        std::fs::read(&path).unwrap(),
        encode(good),
        "{what}: the good file is rewritten"
    );
    assert_eq!(files_in(dir), vec![path], "{what}: no temporaries left");
}

/// Recomputes the trailing checksum after an edit.
fn reseal(bytes: &mut [u8]) {
    let body = bytes.len() - 8;
    let sum = fnv1a64(&bytes[..body]);
    bytes[body..].copy_from_slice(&sum.to_le_bytes());
}

#[test]
fn damaged_stale_or_foreign_cache_files_are_detected_and_regenerated() {
    let dir = temp_dir();
    let p = params("air-medulla");
    let (good, _) =
        load_or_generate(&p, Resolution::DEFAULT, SMALL, 9, Some(dir.path()), None).unwrap();
    let bytes = encode(&good);
    let n = bytes.len();

    for cut in [0, 7, 50, 96, n / 2, n - 8, n - 1] {
        check_rejected(
            dir.path(),
            &p,
            &good,
            &bytes[..cut],
            &format!("truncated to {cut}"),
            |e| {
                matches!(e, CacheError::Length { expected, found }
                    if *found == cut as u64 && found < expected)
                    || (cut < 8 && matches!(e, CacheError::BadMagic))
            },
        );
    }
    let mut longer = bytes.clone();
    longer.push(0);
    check_rejected(dir.path(), &p, &good, &longer, "one byte appended", |e| {
        matches!(e, CacheError::Length { .. })
    });

    // A flipped bit anywhere after the format version: the checksum (or, in the length
    // fields, the length check) catches it.
    for at in [13, 20, 40, 60, 66, 100, n / 2, n - 12, n - 8, n - 1] {
        let mut b = bytes.clone();
        b[at] ^= 0x04;
        check_rejected(
            dir.path(),
            &p,
            &good,
            &b,
            &format!("bit flip at {at}"),
            |e| matches!(e, CacheError::Checksum { .. }),
        );
    }
    for at in [76, 85, 90] {
        let mut b = bytes.clone();
        b[at] ^= 0x01;
        check_rejected(
            dir.path(),
            &p,
            &good,
            &b,
            &format!("length field {at}"),
            |e| matches!(e, CacheError::Length { .. }),
        );
    }
    let mut b = bytes.clone();
    b[0] = b'X';
    check_rejected(dir.path(), &p, &good, &b, "magic", |e| {
        matches!(e, CacheError::BadMagic)
    });
    let mut b = bytes.clone();
    b[8] = 99;
    check_rejected(dir.path(), &p, &good, &b, "format version", |e| {
        matches!(e, CacheError::FormatVersion(99)) && e.is_stale()
    });

    // Another generator version, with a valid checksum: stale.
    let mut b = bytes.clone();
    let v = medulla::GENERATOR_VERSION.wrapping_add(1);
    b[12..16].copy_from_slice(&v.to_le_bytes());
    reseal(&mut b);
    check_rejected(dir.path(), &p, &good, &b, "generator version", |e| {
        matches!(e, CacheError::GeneratorVersion(x) if *x == v) && e.is_stale()
    });

    // A valid file for other parameters, seed or budget under this key's name: stale.
    let foreign = generate_parallel(&layout("red-fox"), &SMALL, 9, None).unwrap();
    check_rejected(
        dir.path(),
        &p,
        &good,
        &encode(&foreign),
        "other layout",
        |e| matches!(e, CacheError::KeyMismatch("g")) && e.is_stale(),
    );
    let other_seed = generate_parallel(good.layout(), &SMALL, 10, None).unwrap();
    check_rejected(
        dir.path(),
        &p,
        &good,
        &encode(&other_seed),
        "other seed",
        |e| matches!(e, CacheError::KeyMismatch("seed")),
    );
    let half = PhotonBudget {
        per_cn_cell: SMALL.per_cn_cell / 2,
        per_cm_row: SMALL.per_cm_row,
    };
    let other_budget = generate_parallel(good.layout(), &half, 9, None).unwrap();
    check_rejected(
        dir.path(),
        &p,
        &good,
        &encode(&other_budget),
        "other budget",
        |e| matches!(e, CacheError::KeyMismatch("photon budget")),
    );
    // Another medulla absorption ratio σ_ma/σ_ms (the same axes otherwise).
    let mut absorbing = *good.layout();
    absorbing.absorption *= 2.0;
    let other_absorption = generate_parallel(&absorbing, &SMALL, 9, None).unwrap();
    check_rejected(
        dir.path(),
        &p,
        &good,
        &encode(&other_absorption),
        "other absorption",
        |e| matches!(e, CacheError::KeyMismatch("absorption")),
    );
    // Another resolution of the same parameters.
    let mut coarse_layout = *good.layout();
    coarse_layout.res.n_psi = 36;
    let coarse = generate_parallel(&coarse_layout, &SMALL, 9, None).unwrap();
    check_rejected(
        dir.path(),
        &p,
        &good,
        &encode(&coarse),
        "other resolution",
        |e| matches!(e, CacheError::KeyMismatch("resolution")),
    );

    // A table value that is not a valid profile value, sealed with a valid checksum.
    let mut b = bytes.clone();
    b[92..96].copy_from_slice(&(-1.0f32).to_bits().to_le_bytes());
    reseal(&mut b);
    check_rejected(dir.path(), &p, &good, &b, "negative C^N value", |e| {
        matches!(
            e,
            CacheError::Tables(ProfileError::BadValue {
                table: "C^N",
                index: 0
            })
        )
    });
    let mut b = bytes.clone();
    let at = n - 8 - 4; // the last C^M entry
    b[at..at + 4].copy_from_slice(&f32::NAN.to_bits().to_le_bytes());
    reseal(&mut b);
    check_rejected(dir.path(), &p, &good, &b, "NaN in C^M", |e| {
        matches!(
            e,
            CacheError::Tables(ProfileError::BadValue { table: "C^M", .. })
        )
    });

    // Finally the good file is used again.
    let (again, outcome) =
        load_or_generate(&p, Resolution::DEFAULT, SMALL, 9, Some(dir.path()), None).unwrap();
    assert!(matches!(outcome, CacheOutcome::Hit { .. }), "{outcome:?}");
    assert_same_bits(&good, &again, "after the repairs");
    // decode itself agrees.
    assert_same_bits(&good, &decode(&bytes, &good.key()).unwrap(), "decode");
}

/// A directory this process cannot write to, when the platform lets us make one (not as
/// root, which ignores permissions): `None` otherwise.
#[cfg(unix)]
fn read_only_dir(dir: &Path) -> Option<()> {
    use std::os::unix::fs::PermissionsExt;
    std::fs::set_permissions(dir, std::fs::Permissions::from_mode(0o555)).unwrap();
    let probe = dir.join("probe");
    if std::fs::write(&probe, b"x").is_ok() {
        std::fs::remove_file(&probe).unwrap();
        std::fs::set_permissions(dir, std::fs::Permissions::from_mode(0o755)).unwrap();
        return None;
    }
    Some(())
}

#[test]
fn an_unwritable_cache_directory_is_an_error_naming_it_before_any_work() {
    let dir = temp_dir();
    let blocker = dir.path().join("a-file");
    std::fs::write(&blocker, b"not a directory").unwrap();
    let p = params("bobcat");
    for bad in [blocker.join("cache"), blocker.clone()] {
        // The full budget on one thread would take seconds: the error must come first.
        let start = std::time::Instant::now();
        let err = load_or_generate(
            &p,
            Resolution::DEFAULT,
            PhotonBudget::DEFAULT,
            1,
            Some(&bad),
            Some(1),
        )
        .unwrap_err();
        assert!(
            start.elapsed().as_secs_f64() < 1.0,
            "the directory must be checked before generating"
        );
        match &err {
            Error::CacheDir { dir, .. } => assert_eq!(*dir, bad),
            other => panic!("expected CacheDir, got {other:?}"),
        }
        let text = err.to_string();
        assert!(text.contains(bad.to_str().unwrap()), "{text}");
        assert_eq!(text.lines().count(), 1, "{text}");
    }
    // build_model reports the same error; without a cache it works.
    let opts = ProfileOptions {
        budget: SMALL,
        cache_dir: Some(blocker.join("cache")),
        ..ProfileOptions::default()
    };
    assert!(matches!(build_model(p, &opts), Err(Error::CacheDir { .. })));
    let no_cache = ProfileOptions {
        cache_dir: None,
        ..opts
    };
    assert!(build_model(p, &no_cache).unwrap().0.profiles().is_some());

    // A read-only directory: a valid file is still read; a damaged one cannot be replaced,
    // which is an error, and the file is left as it was.
    #[cfg(unix)]
    {
        let ro = temp_dir();
        let (good, _) =
            load_or_generate(&p, Resolution::DEFAULT, SMALL, 1, Some(ro.path()), None).unwrap();
        let path = ro.path().join(good.key().file_name());
        let mut damaged = encode(&good);
        damaged[200] ^= 1;
        std::fs::write(&path, &damaged).unwrap();
        if read_only_dir(ro.path()).is_some() {
            let err = load_or_generate(&p, Resolution::DEFAULT, SMALL, 1, Some(ro.path()), None)
                .unwrap_err();
            assert!(matches!(err, Error::CacheDir { .. }), "{err:?}");
            assert_eq!(std::fs::read(&path).unwrap(), damaged);
            use std::os::unix::fs::PermissionsExt;
            std::fs::set_permissions(ro.path(), std::fs::Permissions::from_mode(0o755)).unwrap();
        } else {
            eprintln!("running with permission to write anywhere: read-only case skipped");
        }
    }
}

#[test]
fn writes_are_atomic() {
    let dir = temp_dir();
    let path = dir.path().join("medulla-target.furprof");
    let old = b"the old, good contents".repeat(100);
    std::fs::write(&path, &old).unwrap();

    // A write that fails halfway (the writer is dropped without commit): the old file is
    // intact and the temporary file is gone.
    {
        let mut w = AtomicWriter::new(&path).unwrap();
        w.write_all(b"half of the new con").unwrap();
        assert_eq!(
            files_in(dir.path()).len(),
            2,
            "the temporary file is in the same directory"
        );
        assert_eq!(
            std::fs::read(&path).unwrap(),
            old,
            "nothing visible before commit"
        );
        // ... and here the write fails: `w` is dropped without `commit`.
    }
    assert_eq!(std::fs::read(&path).unwrap(), old);
    assert_eq!(files_in(dir.path()), vec![path.clone()]);

    // A committed write replaces the file whole.
    let new = b"new".repeat(1000);
    fsutil::write_atomic(&path, &new).unwrap();
    assert_eq!(std::fs::read(&path).unwrap(), new);
    assert_eq!(files_in(dir.path()), vec![path.clone()]);

    // A rename that cannot happen (the destination is a non-empty directory) fails without
    // leaving a temporary file.
    let blocked = dir.path().join("blocked");
    std::fs::create_dir(&blocked).unwrap();
    std::fs::write(blocked.join("inside"), b"x").unwrap();
    assert!(fsutil::write_atomic(&blocked, b"data").is_err());
    assert_eq!(files_in(dir.path()), vec![blocked.clone(), path.clone()]);

    // Concurrent writers of the same key: every reader sees a complete file.
    let cache = temp_dir();
    let p = params("bobcat");
    let results: Vec<(OwnedProfiles, CacheOutcome)> = std::thread::scope(|s| {
        let handles: Vec<_> = (0..3)
            .map(|_| {
                s.spawn(|| {
                    load_or_generate(
                        &p,
                        Resolution::DEFAULT,
                        SMALL,
                        2,
                        Some(cache.path()),
                        Some(1),
                    )
                    .unwrap()
                })
            })
            .collect();
        handles.into_iter().map(|h| h.join().unwrap()).collect()
    });
    for (r, _) in &results[1..] {
        assert_same_bits(&results[0].0, r, "concurrent writers");
    }
    // The entry's lock: one thread generated, the two others waited and read its file.
    let generated = results
        .iter()
        .filter(|(_, o)| matches!(o, CacheOutcome::Generated { .. }))
        .count();
    let hits = results
        .iter()
        .filter(|(_, o)| matches!(o, CacheOutcome::Hit { .. }))
        .count();
    assert_eq!(
        (generated, hits),
        (1, 2),
        "{:?}",
        results.iter().map(|(_, o)| o).collect::<Vec<_>>()
    );
    let files = files_in(cache.path());
    assert_eq!(files.len(), 1, "{files:?}");
    assert_eq!(std::fs::read(&files[0]).unwrap(), encode(&results[0].0));
    let lock = files[0].with_extension("lock");
    assert!(lock.is_file(), "the entry's lock file {}", lock.display());
}

#[test]
fn build_model_uses_profiles_only_when_the_medulla_scatters() {
    let opts = ProfileOptions {
        budget: SMALL,
        ..ProfileOptions::default()
    };
    let a = Angles::from_degrees(30.0, -20.0, 45.0).unwrap();

    // kappa = 0, or sigma_ms = 0: no profiles, no cache, the unscattered model exactly.
    let hair = params("human-hair");
    let mut input = presets::find("bobcat").unwrap().input;
    input.sigma_ms = 0.0;
    let clear = FurParams::new(&input).unwrap();
    for p in [hair, clear] {
        assert!(!profiles::needs_profiles(&p));
        let (m, outcome) = build_model(p, &opts).unwrap();
        assert!(m.profiles().is_none() && outcome.is_none());
        // Both are in the energy closure: the direct model gets the same residual table.
        let residual = m.residual().expect("energy closure: a residual table");
        let table = ResidualTable::new(p, ResidualLayout::DEFAULT, residual).unwrap();
        let direct: FurBcsdf = FurBcsdf::unscattered(p).with_residual(table).unwrap();
        assert_eq!(m.model().eval_far_lobes(&a), direct.eval_far_lobes(&a));
    }

    // bobcat scatters: profiles for its layout, and the same model as FurBcsdf::new.
    let p = params("bobcat");
    let (m, outcome) = build_model(p, &opts).unwrap();
    assert!(matches!(
        outcome,
        Some(CacheOutcome::Generated { path: None })
    ));
    let prof = m.profiles().unwrap();
    assert!(prof.layout().matches(&p));
    // bobcat is in the energy closure: the direct model carries the same residual table.
    let residual = m.residual().expect("energy closure: a residual table");
    let table = ResidualTable::new(p, ResidualLayout::DEFAULT, residual).unwrap();
    let direct: FurBcsdf = FurBcsdf::new(p, prof.view())
        .unwrap()
        .with_residual(table)
        .unwrap();
    let got = m.model().eval_far_lobes(&a);
    assert_eq!(got, direct.eval_far_lobes(&a));
    assert!(got.get(bcsdf_core::Lobe::TttTs).max_channel() > 0.0);

    // Profiles for other parameters are refused.
    let other = generate_parallel(&layout("red-fox"), &SMALL, 1, None).unwrap();
    assert_eq!(
        OwnedModel::new(p, Some(other)).unwrap_err(),
        ProfileError::Mismatch
    );
    // An OwnedProfiles is validated when built.
    let key = ProfileKey {
        layout: layout("bobcat"),
        budget: SMALL,
        seed: 1,
    };
    let l = key.layout;
    assert!(matches!(
        OwnedProfiles::new(key, vec![0.0; 3], vec![0.0; l.cm_len()]),
        Err(ProfileError::WrongLength { table: "C^N", .. })
    ));
}
