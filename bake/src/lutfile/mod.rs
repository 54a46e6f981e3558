//! LUT files on disk: the raw little-endian blob ([`blob`], `.furlut`), the OpenEXR form
//! ([`exr`]: one f16 layer per table, the blob's header verbatim in one attribute, readable
//! metadata beside it) and the dual-scattering tables ([`dual`], `.furdual`), all written
//! atomically ([`crate::fsutil::AtomicWriter`]). Every
//! failure is one [`LutFileError`] naming the file, with a [`LutFileErrorKind`] ([`error`]).
//!
//! Everything public in the submodules is re-exported here (`bake::lutfile::read_exr`).

pub mod blob;
pub mod dual;
pub mod error;
pub mod exr;

pub use blob::{read_blob, write_blob};
pub use dual::{read_dual, write_dual};
pub use error::{LutFileError, LutFileErrorKind};
pub use exr::{encode_exr, exr_from_bytes, read_exr, write_exr};

use std::io;
use std::path::Path;

use bcsdf_core::baked::BakedBcsdf;
use bcsdf_core::lut::{self, LutError, LutHeader};

use crate::fsutil::{self, AtomicWriter};
use crate::metrics::ErrorSummary;

/// Metadata beside the tables (the tables' own header is inside the blob).
#[derive(Clone, Debug, PartialEq)]
pub struct LutMeta {
    /// Name of the preset the LUT was baked from.
    pub preset: String,
    /// The error summary measured at bake time, if any.
    pub errors: Option<ErrorSummary>,
}

/// A LUT with its metadata: the contents of a LUT EXR file.
#[derive(Clone, Debug, PartialEq)]
pub struct LutFile {
    /// The sealed blob (`bcsdf_core::lut` layout).
    pub blob: Vec<u8>,
    /// Metadata that is not part of the blob.
    pub meta: LutMeta,
}

impl LutFile {
    /// The validated evaluator over the blob.
    pub fn baked(&self) -> Result<BakedBcsdf<'_>, LutError> {
        BakedBcsdf::from_bytes(&self.blob)
    }

    /// The decoded header (after validating the whole blob with [`lut::validate`]).
    pub fn header(&self) -> Result<LutHeader, LutError> {
        lut::validate(&self.blob)
    }
}

/// The whole file, or [`LutFileErrorKind::Missing`] / [`LutFileErrorKind::Read`].
fn read_file(path: &Path) -> Result<Vec<u8>, LutFileError> {
    std::fs::read(path).map_err(|source| {
        if source.kind() == io::ErrorKind::NotFound {
            LutFileErrorKind::Missing.at(path)
        } else {
            LutFileErrorKind::Read(source).at(path)
        }
    })
}

/// Writes a file atomically: checks the directory (which must exist: a LUT write never
/// creates folders), fills a temporary file in it with `fill`, then renames it over `path`.
/// On any failure the temporary file is removed and an existing file at `path` is untouched.
fn write_with(
    path: &Path,
    fill: impl FnOnce(&mut AtomicWriter) -> io::Result<()>,
) -> Result<(), LutFileError> {
    let dir = fsutil::parent_dir(path);
    let dir_error = |problem: String| {
        LutFileErrorKind::Directory {
            dir: dir.to_path_buf(),
            problem,
        }
        .at(path)
    };
    match std::fs::metadata(dir) {
        Err(e) if e.kind() == io::ErrorKind::NotFound => {
            return Err(dir_error("does not exist".into()))
        }
        Err(e) => return Err(dir_error(format!("is not accessible: {e}"))),
        Ok(m) if !m.is_dir() => return Err(dir_error("is not a directory".into())),
        Ok(_) => {}
    }
    if path.is_dir() {
        return Err(
            LutFileErrorKind::Write(io::Error::other("the destination is a directory")).at(path),
        );
    }
    let mut w = AtomicWriter::new(path)
        .map_err(|e| dir_error(format!("does not accept a new file: {e}")))?;
    let write_error = |source| LutFileErrorKind::Write(source).at(path);
    // On error `w` is dropped, which removes the temporary file.
    fill(&mut w).map_err(write_error)?;
    w.commit().map_err(write_error)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::io::Write;

    /// A write that fails part-way (as on a full disk) reports the error, leaves the
    /// existing file as it was and leaves no temporary file behind.
    #[test]
    fn failed_write_keeps_the_existing_file() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("x.lut");
        std::fs::write(&path, b"old contents").unwrap();
        let err = write_with(&path, |w| {
            w.write_all(b"new partial data")?;
            Err(io::Error::from_raw_os_error(28)) // ENOSPC
        })
        .unwrap_err();
        assert!(matches!(err.kind(), LutFileErrorKind::Write(_)), "{err:?}");
        let msg = err.to_string();
        assert!(
            msg.contains("x.lut") && msg.contains("No space left"),
            "{msg}"
        );
        assert_eq!(std::fs::read(&path).unwrap(), b"old contents");
        let names: Vec<_> = std::fs::read_dir(dir.path())
            .unwrap()
            .map(|e| e.unwrap().file_name())
            .collect();
        assert_eq!(names, [std::ffi::OsString::from("x.lut")]);
    }
}
