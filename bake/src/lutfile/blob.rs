//! The raw blob (`.furlut`): exactly the bytes of `bcsdf_core::lut` (header, tables, sampling
//! section, checksum), written and read unchanged and checked with [`lut::validate`].

use std::io::Write;
use std::path::Path;

use bcsdf_core::lut;

use super::exr::EXR_MAGIC;
use super::{read_file, write_with, LutFileError, LutFileErrorKind};

/// Writes a raw LUT blob to `path` atomically (temporary file in the same directory, then
/// rename). The blob is validated first; an invalid blob is not written.
pub fn write_blob(path: &Path, blob: &[u8]) -> Result<(), LutFileError> {
    lut::validate(blob).map_err(|e| LutFileErrorKind::from(e).at(path))?;
    write_with(path, |w| w.write_all(blob))
}

/// Reads a raw LUT blob and validates it with [`lut::validate`].
pub fn read_blob(path: &Path) -> Result<Vec<u8>, LutFileError> {
    let bytes = read_file(path)?;
    if bytes.starts_with(&EXR_MAGIC) {
        return Err(LutFileErrorKind::Format(
            "this is an OpenEXR file, not a raw LUT blob (read it as EXR)".into(),
        )
        .at(path));
    }
    lut::validate(&bytes).map_err(|e| LutFileErrorKind::from(e).at(path))?;
    Ok(bytes)
}
