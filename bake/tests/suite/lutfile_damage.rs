//! Damaged and edited LUT files (`bake::lutfile`): a damaged `lut_header` attribute is
//! refused naming the file and the problem, edited readable attributes change nothing, and
//! neither loader panics on or accepts corrupted bytes (every single-byte change of an EXR,
//! random truncations and flips of both forms).

use crate::common;

use bake::lutfile::{exr_from_bytes, read_blob, LutFileError};
use bcsdf_core::lut::{self, Table};
use bcsdf_core::MODEL_VERSION;
use common::*;
use exr::prelude as x;
use proptest::prelude::*;
use std::ops::Range;
use std::path::Path;

/// `air_exr()` with layer `M`'s `lut_header` attribute replaced (`None`: removed).
fn with_header_attribute(value: Option<x::AttributeValue>) -> Vec<u8> {
    rewrite_attributes(air_exr(), |layer, attrs| {
        if layer == 0 {
            match value.clone() {
                Some(v) => attrs.insert(x::Text::from("lut_header"), v),
                None => attrs.remove(b"lut_header".as_slice()),
            };
        }
    })
}

fn header_bytes_attribute(bytes: &[u8]) -> x::AttributeValue {
    x::AttributeValue::Bytes {
        type_hint: x::Text::from("furlut_header"),
        bytes: bytes.into(),
    }
}

#[test]
fn a_damaged_header_attribute_is_refused_naming_the_file_and_the_problem() {
    let path = Path::new("damaged.exr");
    // Rewritten by the exr crate unchanged: still the same LUT.
    let same = with_header_attribute(Some(header_bytes_attribute(&air()[..lut::HEADER_LEN])));
    assert_eq!(exr_from_bytes(path, &same).unwrap(), air_file());

    let header = || air()[..lut::HEADER_LEN].to_vec();
    let changed = |at: usize, value: &[u8]| {
        let mut h = header();
        h[at..at + value.len()].copy_from_slice(value);
        Some(header_bytes_attribute(&h))
    };
    let mut extended = header();
    extended.push(0);
    let model = (MODEL_VERSION + 1).to_le_bytes();
    let eta_c = f32::from_le_bytes(air()[52..56].try_into().unwrap());
    let cases: Vec<(Option<x::AttributeValue>, String)> = vec![
        (
            Some(header_bytes_attribute(&air()[..lut::HEADER_LEN - 1])),
            format!(
                "attribute lut_header holds {} bytes, expected the {} bytes of a LUT header",
                lut::HEADER_LEN - 1,
                lut::HEADER_LEN
            ),
        ),
        (
            Some(header_bytes_attribute(&extended)),
            format!("attribute lut_header holds {} bytes", lut::HEADER_LEN + 1),
        ),
        (
            Some(header_bytes_attribute(&[])),
            "attribute lut_header holds 0 bytes".into(),
        ),
        (
            Some(x::AttributeValue::Text(x::Text::from("FURLUT"))),
            "attribute lut_header of layer \"M\" has type \"string\", expected bytes".into(),
        ),
        (
            None,
            "layer \"M\" has no attribute lut_header (written by an older bake: re-bake it".into(),
        ),
        (changed(0, b"X"), "not a fur LUT (bad magic)".into()),
        (
            changed(12, &model),
            format!("model version {}", MODEL_VERSION + 1),
        ),
        (
            changed(24, &1u32.to_le_bytes()),
            "axis n_phi has 1 nodes".into(),
        ),
        (
            changed(52, &(eta_c + 0.25).to_le_bytes()),
            "LUT is corrupt: checksum".into(),
        ),
        (
            changed(52, &0.5f32.to_le_bytes()),
            "LUT parameters are invalid".into(),
        ),
        (
            changed(108, &2u32.to_le_bytes()),
            "header field closure is invalid".into(),
        ),
    ];
    for (value, expected) in cases {
        let bytes = with_header_attribute(value.clone());
        let err = exr_from_bytes(path, &bytes).unwrap_err();
        let msg = read_message(&err, path);
        assert!(msg.contains(&expected), "{value:?}: {msg}");
    }
}

#[test]
fn edited_readable_attributes_read_to_the_same_blob() {
    use x::AttributeValue::{FloatVec3, Text, F32, I32};
    let edited = rewrite_attributes(air_exr(), |layer, attrs| {
        let mut put = |k: &str, v| {
            attrs.insert(x::Text::from(k), v);
        };
        put("scale", F32(1e9));
        if layer == 0 {
            put("kappa", F32(0.123));
            put("eumelanin", F32(7.0));
            put("sigma_ca", FloatVec3((1.0, 2.0, 3.0)));
            put("params", Text(x::Text::from("eta_c=9 anything")));
            put("n_phi", I32(17));
            put("has_profiles", I32(0));
            put("profile_seed", Text(x::Text::from("not a number")));
            put("lut_checksum", Text(x::Text::from("0000000000000000")));
            put("axes", Text(x::Text::from("")));
            attrs.remove(b"eta_c".as_slice());
            attrs.remove(b"profile_n_h".as_slice());
        }
    });
    assert_ne!(edited, air_exr());
    let back = exr_from_bytes(Path::new("edited.exr"), &edited).unwrap();
    assert_eq!(back.blob, air(), "the same blob bytes");
    assert_eq!(back, air_file());
}

/// 256 cases per property, or `PROPTEST_CASES` when set (for a deeper run).
fn fuzz_config() -> ProptestConfig {
    let default = ProptestConfig::default();
    ProptestConfig {
        cases: if std::env::var_os("PROPTEST_CASES").is_some() {
            default.cases
        } else {
            256
        },
        failure_persistence: None,
        ..default
    }
}

/// Writes `bytes` to a fresh file and reads it as a blob.
fn read_blob_bytes(bytes: &[u8]) -> Result<Vec<u8>, LutFileError> {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("fuzz.lut");
    std::fs::write(&path, bytes).unwrap();
    read_blob(&path)
}

proptest! {
    #![proptest_config(fuzz_config())]

    #[test]
    fn blob_truncated_anywhere_is_rejected(len in 0usize..RES.blob_len()) {
        let blob = air();
        prop_assert_eq!(blob.len(), RES.blob_len());
        prop_assert!(read_blob_bytes(&blob[..len]).is_err());
    }

    #[test]
    fn blob_with_any_byte_changed_is_rejected(at in 0usize..RES.blob_len(), xor in 1u8..=255) {
        let mut blob = air().to_vec();
        blob[at] ^= xor;
        prop_assert!(read_blob_bytes(&blob).is_err());
    }

    #[test]
    fn blob_with_any_bit_flipped_is_rejected(bit in 0usize..RES.blob_len() * 8) {
        let mut blob = air().to_vec();
        blob[bit / 8] ^= 1 << (bit % 8);
        prop_assert!(read_blob_bytes(&blob).is_err());
    }

    #[test]
    fn blob_with_bytes_appended_is_rejected(tail in prop::collection::vec(any::<u8>(), 1..64)) {
        let mut blob = air().to_vec();
        blob.extend_from_slice(&tail);
        prop_assert!(read_blob_bytes(&blob).is_err());
    }

    #[test]
    fn exr_truncated_anywhere_is_rejected(frac in 0.0f64..1.0) {
        let bytes = air_exr();
        let len = (frac * bytes.len() as f64) as usize;
        prop_assert!(exr_from_bytes(Path::new("fuzz.exr"), &bytes[..len]).is_err());
    }

    #[test]
    fn exr_with_bytes_changed_is_rejected_or_reads_identically(
        flips in prop::collection::vec((0.0f64..1.0, 1u8..=255), 1..6)
    ) {
        let mut bytes = air_exr().to_vec();
        for (frac, xor) in flips {
            let at = (frac * bytes.len() as f64) as usize;
            bytes[at] ^= xor;
        }
        if let Ok(back) = exr_from_bytes(Path::new("fuzz.exr"), &bytes) {
            // The flips hit bytes that do not matter (e.g. the `comments` text).
            prop_assert_eq!(back, air_file());
        }
    }
}

/// Named byte ranges of a file.
type Spans = Vec<(String, Range<usize>)>;

/// The layout of a multi-part EXR file: every attribute of every part header (name and the
/// byte range of the whole attribute: name, type, size, value), and the byte ranges of the
/// compressed pixel data of every chunk.
fn exr_layout(bytes: &[u8]) -> (Spans, Vec<Range<usize>>) {
    let cstr_end = |at: usize| at + bytes[at..].iter().position(|&b| b == 0).unwrap() + 1;
    let i32_at = |at: usize| i32::from_le_bytes(bytes[at..at + 4].try_into().unwrap());
    let mut spans = Vec::new();
    let mut at = 8;
    loop {
        // One header: attributes up to a zero byte.
        while bytes[at] != 0 {
            let name_end = cstr_end(at);
            let type_end = cstr_end(name_end);
            let end = type_end + 4 + i32_at(type_end) as usize;
            let name = String::from_utf8_lossy(&bytes[at..name_end - 1]).into_owned();
            spans.push((name, at..end));
            at = end;
        }
        at += 1;
        if bytes[at] == 0 {
            break; // the empty header that ends a multi-part header list
        }
    }
    let chunks: usize = spans
        .iter()
        .filter(|(n, _)| n == "chunkCount")
        .map(|(_, r)| i32_at(r.end - 4) as usize)
        .sum();
    // The offset tables (one u64 per chunk), then the chunks: part, y, size, data.
    let mut at = at + 1 + 8 * chunks;
    let mut data = Vec::new();
    for _ in 0..chunks {
        let size = i32_at(at + 8) as usize;
        data.push(at + 12..at + 12 + size);
        at += 12 + size;
    }
    assert_eq!(at, bytes.len(), "the chunks end the file");
    (spans, data)
}

/// Every single-byte change of the EXR file, at every offset: never a panic, never a
/// different LUT, and a change that reads back unnoticed is never in the pixel data or in a
/// LUT attribute that is read back (only in the readable attributes, or in bytes of the file
/// structure that do not matter).
#[test]
fn exr_every_byte_changed_is_rejected_or_reads_identically() {
    let bytes = air_exr();
    let (spans, chunks) = exr_layout(bytes);
    assert!(spans.iter().any(|(n, _)| n == "lut_header"));
    let rows_per_chunk = 16; // ZIP16
    let expected: usize = Table::ALL
        .iter()
        .map(|&t| RES.dims(t).1.div_ceil(rows_per_chunk))
        .sum();
    assert_eq!(chunks.len(), expected);
    // The LUT attributes that are read back (and the error summary, `E…`).
    let read_back = [
        "lut_format_version",
        "model_version",
        "preset",
        "meta_checksum",
    ];
    let mut accepted = 0;
    let mut unnoticed: Vec<&str> = Vec::new();
    for at in 0..bytes.len() {
        let mut b = bytes.to_vec();
        b[at] ^= 0x41;
        if let Ok(back) = exr_from_bytes(Path::new("fuzz.exr"), &b) {
            assert_eq!(back, air_file(), "byte {at}");
            accepted += 1;
            assert!(
                !chunks.iter().any(|r| r.contains(&at)),
                "byte {at}, in the pixel data, changed unnoticed"
            );
            let Some((name, span)) = spans.iter().find(|(_, r)| r.contains(&at)) else {
                continue; // structure (e.g. the offset tables, which the reader does not need)
            };
            assert!(
                !read_back.contains(&name.as_str()) && !name.starts_with('E'),
                "byte {at} of attribute {name} changed unnoticed"
            );
            if name == "lut_header" {
                // Only the type hint, never the header itself.
                assert!(at < span.end - lut::HEADER_LEN, "lut_header byte {at}");
            }
            if !unnoticed.contains(&name.as_str()) {
                unnoticed.push(name);
            }
        }
    }
    println!(
        "{accepted} of {} single-byte changes read back identically, in the attributes {unnoticed:?} and the file structure",
        bytes.len()
    );
}
