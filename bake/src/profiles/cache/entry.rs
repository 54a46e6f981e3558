//! One cache entry, whatever it holds: read a valid file without a lock, else take the
//! entry's advisory lock, read again, and (re)generate and atomically (re)write it. The
//! profile cache ([`super::load_or_generate`]) and the residual cache
//! ([`crate::profiles::residual::load_or_generate_residual`]) both go through
//! [`load_or_make`]; the protocol is described in the [`super`] module documentation
//! ("Concurrent bakes").

use super::{remove_stray_partials, CacheError, CacheOutcome};
use crate::fsutil::AtomicWriter;
use crate::profiles::Error;
use fs4::FileExt;
use std::fs;
use std::io::{self, Write};
use std::path::Path;

/// Where an entry lives: its directory, its file and its lock file (both directly inside
/// the directory, built by [`crate::fsutil::output_path`]).
pub(crate) struct EntryPaths<'p> {
    /// The cache directory.
    pub dir: &'p Path,
    /// The entry's file.
    pub file: std::path::PathBuf,
    /// The entry's lock file.
    pub lock: std::path::PathBuf,
}

/// Reads the file at `path` with `decode`: `Ok(Some)` for a valid entry, `Ok(None)` when
/// there is no file, `Err` with the reason a file was rejected.
fn read_entry<T>(
    path: &Path,
    decode: &impl Fn(&[u8]) -> Result<T, CacheError>,
) -> Result<Option<T>, CacheError> {
    match fs::read(path) {
        Ok(bytes) => decode(&bytes).map(Some),
        Err(e) if e.kind() == io::ErrorKind::NotFound => Ok(None),
        Err(e) => Err(CacheError::Read(e)),
    }
}

/// The entry at `paths`: `decode`d from its file when that is valid (no lock taken), else
/// made by `make` under the entry's lock and written atomically as `encode` gives it. A
/// directory that cannot be created or written is [`Error::CacheDir`], detected before
/// `make` runs; concurrent callers that miss the same entry run `make` once.
/// [`load_or_make_many`] with one entry.
pub(crate) fn load_or_make<T: Clone>(
    paths: EntryPaths<'_>,
    decode: impl Fn(&[u8]) -> Result<T, CacheError>,
    make: impl FnOnce() -> Result<T, Error>,
    encode: impl FnOnce(&T) -> Vec<u8>,
) -> Result<(T, CacheOutcome), Error> {
    let encode = std::cell::Cell::new(Some(encode));
    let mut out = load_or_make_many(
        vec![paths],
        |_, bytes| decode(bytes),
        |_| make().map(|v| vec![v]),
        |_, v| encode.take().map_or_else(Vec::new, |e| e(v)),
    )?;
    Ok(out.remove(0))
}

/// Several entries at once, made together: each is `decode`d from its file when that is
/// valid (no lock taken); the others are locked (in the order of their lock files' paths,
/// so that two callers with overlapping entries cannot deadlock), read again, and those
/// still missing are made by one call of `make` (given their indices in `entries`, it
/// returns their values in that order) and written atomically as `encode` gives them. The
/// same protocol as one entry's, and the same errors; what a bake's absorption planes use,
/// whose residual tables one photon walk makes together. Entries with the same file are
/// made once.
pub(crate) fn load_or_make_many<T: Clone>(
    entries: Vec<EntryPaths<'_>>,
    decode: impl Fn(usize, &[u8]) -> Result<T, CacheError>,
    make: impl FnOnce(&[usize]) -> Result<Vec<T>, Error>,
    encode: impl Fn(usize, &T) -> Vec<u8>,
) -> Result<Vec<(T, CacheOutcome)>, Error> {
    let mut found: Vec<Option<(T, CacheOutcome)>> = entries.iter().map(|_| None).collect();
    // A valid file needs no lock: it is only ever replaced whole (renamed over).
    for (i, e) in entries.iter().enumerate() {
        if let Ok(Some(v)) = read_entry(&e.file, &|b: &[u8]| decode(i, b)) {
            found[i] = Some((
                v,
                CacheOutcome::Hit {
                    path: e.file.clone(),
                },
            ));
        }
    }
    // The missing entries, one per file, in the order of their lock files.
    let mut missing: Vec<usize> = (0..entries.len()).filter(|&i| found[i].is_none()).collect();
    missing.sort_by(|&i, &j| entries[i].lock.cmp(&entries[j].lock).then(i.cmp(&j)));
    missing.dedup_by(|j, i| entries[*i].file == entries[*j].file);
    let mut locks = Vec::with_capacity(missing.len());
    let mut todo = Vec::new();
    let mut rejected = Vec::new();
    for &i in &missing {
        let EntryPaths { dir, file, lock } = &entries[i];
        // Creating the lock file also checks, before the work, that the directory is writable.
        let dir_error = |source| Error::CacheDir {
            dir: dir.to_path_buf(),
            source,
        };
        fs::create_dir_all(dir).map_err(dir_error)?;
        let lock_file = fs::OpenOptions::new()
            .read(true)
            .write(true)
            .create(true)
            .truncate(false)
            .open(lock)
            .map_err(dir_error)?;
        // Blocks while another bake generates this entry; the system releases the lock when
        // its holder exits, however it exits. Released when `locks` is dropped, on every
        // path below.
        FileExt::lock(&lock_file).map_err(|source| Error::CacheLock {
            path: lock.clone(),
            source,
        })?;
        locks.push(lock_file);
        // Another bake may have written the file while this one waited.
        match read_entry(file, &|b: &[u8]| decode(i, b)) {
            Ok(Some(v)) => found[i] = Some((v, CacheOutcome::Hit { path: file.clone() })),
            Ok(None) => {
                todo.push(i);
                rejected.push(None);
            }
            Err(e) => {
                todo.push(i);
                rejected.push(Some(e));
            }
        }
    }
    let mut writers = Vec::with_capacity(todo.len());
    for &i in &todo {
        let EntryPaths { dir, file, .. } = &entries[i];
        remove_stray_partials(dir, file);
        writers.push(AtomicWriter::new(file).map_err(|source| Error::CacheDir {
            dir: dir.to_path_buf(),
            source,
        })?);
    }
    if !todo.is_empty() {
        let values = make(&todo)?;
        for (((&i, value), mut writer), reason) in
            todo.iter().zip(values).zip(writers).zip(rejected)
        {
            let file = &entries[i].file;
            let write_error = |source| Error::CacheWrite {
                path: file.clone(),
                source,
            };
            writer.write_all(&encode(i, &value)).map_err(write_error)?;
            writer.commit().map_err(write_error)?;
            let outcome = match reason {
                Some(reason) => CacheOutcome::Regenerated {
                    path: file.clone(),
                    reason,
                },
                None => CacheOutcome::Generated {
                    path: Some(file.clone()),
                },
            };
            found[i] = Some((value, outcome));
        }
    }
    drop(locks);
    // Entries that share a file take its value.
    let shared: Vec<Option<T>> = (0..entries.len())
        .map(|i| {
            let same = |j: &usize| found[*j].is_some() && entries[*j].file == entries[i].file;
            match found[i] {
                Some(_) => None,
                None => (0..entries.len())
                    .find(same)
                    .and_then(|j| found[j].as_ref().map(|(v, _)| v.clone())),
            }
        })
        .collect();
    found
        .into_iter()
        .zip(shared)
        .zip(&entries)
        .map(|((mine, shared), e)| match (mine, shared) {
            (Some(done), _) => Ok(done),
            (None, Some(v)) => Ok((
                v,
                CacheOutcome::Hit {
                    path: e.file.clone(),
                },
            )),
            (None, None) => Err(Error::CacheWrite {
                path: e.file.clone(),
                source: io::Error::other("the entry was not made"),
            }),
        })
        .collect()
}
