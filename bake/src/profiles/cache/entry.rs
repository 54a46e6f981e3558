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
pub(crate) fn load_or_make<T>(
    paths: EntryPaths<'_>,
    decode: impl Fn(&[u8]) -> Result<T, CacheError>,
    make: impl FnOnce() -> Result<T, Error>,
    encode: impl FnOnce(&T) -> Vec<u8>,
) -> Result<(T, CacheOutcome), Error> {
    let EntryPaths { dir, file, lock } = paths;
    // A valid file needs no lock: it is only ever replaced whole (renamed over).
    if let Ok(Some(v)) = read_entry(&file, &decode) {
        return Ok((v, CacheOutcome::Hit { path: file }));
    }
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
        .open(&lock)
        .map_err(dir_error)?;
    // Blocks while another bake generates this entry; the system releases the lock when its
    // holder exits, however it exits. Released when `lock_file` is dropped, on every path
    // below.
    FileExt::lock(&lock_file).map_err(|source| Error::CacheLock {
        path: lock.clone(),
        source,
    })?;
    // Another bake may have written the file while this one waited.
    let rejected = match read_entry(&file, &decode) {
        Ok(Some(v)) => return Ok((v, CacheOutcome::Hit { path: file })),
        Ok(None) => None,
        Err(e) => Some(e),
    };
    remove_stray_partials(dir, &file);
    let mut writer = AtomicWriter::new(&file).map_err(dir_error)?;
    let value = make()?;
    let write_error = |source| Error::CacheWrite {
        path: file.clone(),
        source,
    };
    writer.write_all(&encode(&value)).map_err(write_error)?;
    writer.commit().map_err(write_error)?;
    drop(lock_file);
    let outcome = match rejected {
        Some(reason) => CacheOutcome::Regenerated { path: file, reason },
        None => CacheOutcome::Generated { path: Some(file) },
    };
    Ok((value, outcome))
}
