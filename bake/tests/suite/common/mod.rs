//! Fixtures shared by the LUT file tests: two small baked LUTs (with and without medulla
//! profiles), their EXR form, and helpers to look into EXR file bytes.
#![allow(dead_code)] // each test file uses some of them

use bake::lutfile::{encode_exr, LutFile, LutFileError, LutMeta};
use bake::metrics::ErrorSummary;
use bake::profiles::{build_model, scale_budget, ProfileOptions};
use bcsdf_core::lut::{self, LutResolution, Table};
use bcsdf_core::{FurParams, PhotonBudget};
use exr::prelude as x;
use exr::prelude::traits::*;
use std::collections::HashMap;
use std::io::Cursor;
use std::path::Path;
use std::sync::OnceLock;

pub const RES: LutResolution = LutResolution {
    n_sum: 64,
    n_theta_r: 8,
    n_phi: 16,
    n_ms_i: 12,
    n_ms_r: 12,
    n_abs: 3,
};

pub fn bake_preset(name: &str) -> Vec<u8> {
    let presets = bake::presets::builtin().unwrap();
    let input = bake::presets::find(&presets, name).unwrap().input;
    let params = FurParams::new(&input).unwrap();
    let opts = ProfileOptions {
        budget: scale_budget(PhotonBudget::DEFAULT, 0.002).unwrap(),
        cache_dir: None,
        ..Default::default()
    };
    let (model, _) = build_model(params, &opts).unwrap();
    bake::tables::bake(&model, &input, RES)
}

/// "air-medulla": with medulla profiles.
pub fn air() -> &'static [u8] {
    static BLOB: OnceLock<Vec<u8>> = OnceLock::new();
    BLOB.get_or_init(|| bake_preset("air-medulla"))
}

/// "human-hair": no profiles.
pub fn human() -> &'static [u8] {
    static BLOB: OnceLock<Vec<u8>> = OnceLock::new();
    BLOB.get_or_init(|| bake_preset("human-hair"))
}

/// Values that are not short decimals, so that any rounding on the way shows.
pub fn summary() -> ErrorSummary {
    ErrorSummary {
        e1: [1.0 / 3.0, 0.1, 2.5e-3],
        e_albedo: [1.0 / 7.0, 1e-300, 0.0],
        e_peak: [std::f64::consts::PI * 1e-3, 0.02, 5e-324],
    }
}

pub fn lut_file(blob: &[u8], preset: &str, errors: Option<ErrorSummary>) -> LutFile {
    LutFile {
        blob: blob.to_vec(),
        meta: LutMeta {
            preset: preset.to_string(),
            errors,
        },
    }
}

pub fn air_file() -> LutFile {
    lut_file(air(), "air-medulla", Some(summary()))
}

pub fn air_exr() -> &'static [u8] {
    static BYTES: OnceLock<Vec<u8>> = OnceLock::new();
    BYTES.get_or_init(|| encode_exr(Path::new("air.exr"), &air_file()).unwrap())
}

pub fn dir_entries(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

pub fn find(haystack: &[u8], needle: &[u8]) -> Option<usize> {
    haystack.windows(needle.len()).position(|w| w == needle)
}

/// Overwrites the value of the `int` attribute `name` in EXR file bytes.
pub fn patch_int(bytes: &mut [u8], name: &str, value: i32) {
    let key = [name.as_bytes(), b"\0int\0", &4i32.to_le_bytes()].concat();
    let at = find(bytes, &key).unwrap_or_else(|| panic!("attribute {name}")) + key.len();
    bytes[at..at + 4].copy_from_slice(&value.to_le_bytes());
}

/// Offset in EXR file bytes of the LUT header held by the `lut_header` attribute.
pub fn header_at(bytes: &[u8]) -> usize {
    let key = b"lut_header\0bytes\0";
    let hint = b"furlut_header";
    let at = find(bytes, key).expect("attribute lut_header") + key.len();
    let size = i32::from_le_bytes(bytes[at..at + 4].try_into().unwrap());
    assert_eq!(size as usize, 4 + hint.len() + lut::HEADER_LEN);
    let hint_len = u32::from_le_bytes(bytes[at + 4..at + 8].try_into().unwrap());
    assert_eq!(hint_len as usize, hint.len());
    assert_eq!(&bytes[at + 8..at + 8 + hint.len()], hint);
    at + 8 + hint.len()
}

pub fn half_at(blob: &[u8], t: Table, texel: usize, channel: usize) -> u16 {
    let at = RES.byte_range(t).start + 2 * (texel * t.channels() + channel);
    u16::from_le_bytes([blob[at], blob[at + 1]])
}

/// The message of a read error: one line, naming the file.
pub fn read_message(err: &LutFileError, path: &Path) -> String {
    let msg = err.to_string();
    assert!(!msg.contains('\n'), "{msg}");
    assert!(msg.starts_with(&path.display().to_string()), "{msg}");
    assert_eq!(err.path(), path);
    msg
}

/// `bytes` (an EXR file) read with the exr crate, each layer's attributes passed to `edit`
/// (with the layer's index), and written again by the exr crate (not by `bake`).
pub fn rewrite_attributes(
    bytes: &[u8],
    mut edit: impl FnMut(usize, &mut HashMap<x::Text, x::AttributeValue>),
) -> Vec<u8> {
    let mut image = x::read()
        .no_deep_data()
        .largest_resolution_level()
        .all_channels()
        .all_layers()
        .all_attributes()
        .from_buffered(Cursor::new(bytes))
        .unwrap();
    for (i, layer) in image.layer_data.iter_mut().enumerate() {
        edit(i, &mut layer.attributes.other);
    }
    let mut out = Vec::new();
    image.write().to_buffered(Cursor::new(&mut out)).unwrap();
    out
}
