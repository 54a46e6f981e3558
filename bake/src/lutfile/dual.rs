//! The dual-scattering tables (`.furdual`, docs/model.md §13): the `bcsdf_core::dual` blob,
//! written and read unchanged and checked with [`DualLut::decode`].

use std::io::Write;
use std::path::Path;

use bcsdf_core::dual::DualLut;

use super::{read_file, write_with, LutFileError, LutFileErrorKind};

/// Writes a `.furdual` blob to `path` atomically (temporary file, then rename). The blob is
/// decoded first; a blob [`DualLut::decode`] refuses is not written.
pub fn write_dual(path: &Path, blob: &[u8]) -> Result<(), LutFileError> {
    check(blob).map_err(|e| e.at(path))?;
    write_with(path, |w| w.write_all(blob))
}

/// Reads a `.furdual` file into a decoded evaluator (every check of [`DualLut::decode`]).
pub fn read_dual(path: &Path) -> Result<Box<DualLut>, LutFileError> {
    let bytes = read_file(path)?;
    let mut lut = Box::new(DualLut::EMPTY);
    lut.decode(&bytes)
        .map_err(|e| LutFileErrorKind::Format(e.to_string()).at(path))?;
    Ok(lut)
}

fn check(blob: &[u8]) -> Result<(), LutFileErrorKind> {
    let mut lut = Box::new(DualLut::EMPTY);
    lut.decode(blob)
        .map_err(|e| LutFileErrorKind::Format(e.to_string()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use bcsdf_core::dual::{encode, Attenuation, DualTables};

    #[test]
    fn a_dual_file_round_trips_and_a_damaged_one_is_refused_by_name() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("x.furdual");
        let blob = encode(&DualTables::ZERO, Attenuation::Coat, 5);
        write_dual(&path, &blob).unwrap();
        assert_eq!(std::fs::read(&path).unwrap(), blob.to_vec());
        assert_eq!(read_dual(&path).unwrap().source(), 5);
        let mut bad = blob.to_vec();
        bad[999] ^= 4;
        let e = write_dual(&path, &bad).unwrap_err().to_string();
        assert!(e.contains("x.furdual") && e.contains("checksum"), "{e}");
        // The good file is untouched by the refused write.
        assert_eq!(std::fs::read(&path).unwrap(), blob.to_vec());
        std::fs::write(&path, &bad).unwrap();
        let e = read_dual(&path).unwrap_err().to_string();
        assert!(e.contains("checksum"), "{e}");
    }
}
