//! The OpenEXR form of a LUT: I/O, the layers, and the attributes.
//!
//! A multi-part scan-line file, ZIP-compressed (lossless), with one part ("layer") per
//! [`Table`], in [`Table::ALL`] order, named [`Table::name`], of size
//! [`LutResolution::dims`] (width = columns, height = rows; `M` has one row), with one
//! `half` channel per [`Table::channel_names`] holding exactly the blob's f16 bits (the
//! physical value is the half × the table's scale).
//!
//! The first layer, `M`, carries the attributes that are **read back**:
//!
//! | attribute | type | value |
//! |---|---|---|
//! | `lut_format_version` | int | [`lut::FORMAT_VERSION`] (checked first: a LUT of another format is refused by its version, whatever else changed) |
//! | `model_version` | int | [`bcsdf_core::MODEL_VERSION`] (checked first, likewise) |
//! | `lut_header` | bytes (type hint `furlut_header`, not checked) | the blob's first [`HEADER_LEN`] bytes, verbatim: magic, versions, resolution, scales, parameters, profile provenance, checksum |
//! | `preset` | string | preset name (UTF-8) |
//! | `E1_R` … `E_peak_B` | double | the measured error summary (nine values: `E1`, `E_albedo`, `E_peak` × `R`, `G`, `B`; all or none) |
//! | `meta_checksum` | string | FNV-1a 64 of the preset name and error summary, 16 hex digits |
//!
//! and readable copies of what the header holds, **written for people and other tools but
//! never read back** (editing them changes nothing; see [`attributes`] for the list): every
//! parameter, the node counts and axes, the profile provenance, the blob checksum, and on
//! every layer its `scale`.
//!
//! [`read_exr`] checks the two versions, takes `lut_header` (exactly [`HEADER_LEN`] bytes
//! that the core's [`LutHeader::decode`] accepts), checks every layer's name, size, channels
//! and compression against the header's resolution before any pixel is decoded, copies the
//! halves into the blob, recomputes the sampling section ([`lut::write_sampling`], as
//! [`lut::seal`] does) and runs [`lut::validate`], which requires the header's checksum to be
//! the one [`lut::seal`] computes over the rebuilt blob: any change to the header or to a
//! table value is detected. The preset name and error summary are checked against
//! `meta_checksum`. The attributes of each part are written sorted by name, so the same LUT
//! always gives the same file bytes.

pub mod attributes;

use std::io::{Cursor, Write};
use std::path::Path;

use bcsdf_core::lut::{self, LutError, LutHeader, LutResolution, Table, HEADER_LEN, TABLE_COUNT};
use bcsdf_core::MODEL_VERSION;
use exr::prelude as x;
use exr::prelude::traits::*;

use self::attributes::{
    check_version, insert_metadata, meta_checksum, parse_meta, shown, sort_attributes, text, Attrs,
};
use super::{read_file, write_with, LutFile, LutFileError, LutFileErrorKind};

/// The first four bytes of every OpenEXR file.
pub(super) const EXR_MAGIC: [u8; 4] = [0x76, 0x2f, 0x31, 0x01];

type Kind = LutFileErrorKind;

/// Writes a LUT as OpenEXR (module docs) to `path` atomically: the file is encoded in
/// memory, read back and compared, then written to a temporary file in the same directory
/// and renamed over `path`.
pub fn write_exr(path: &Path, file: &LutFile) -> Result<(), LutFileError> {
    let bytes = encode_exr(path, file)?;
    write_with(path, |w| w.write_all(&bytes))
}

/// Reads a LUT EXR file written by [`write_exr`]: rebuilds the exact blob and validates it.
pub fn read_exr(path: &Path) -> Result<LutFile, LutFileError> {
    let bytes = read_file(path)?;
    exr_from_bytes(path, &bytes)
}

/// [`write_exr`] without the file: the EXR file's bytes. `path` is only named in errors.
pub fn encode_exr(path: &Path, file: &LutFile) -> Result<Vec<u8>, LutFileError> {
    encode(file).map_err(|k| k.at(path))
}

/// [`read_exr`] without the file: decodes EXR file bytes. `path` is only named in errors.
pub fn exr_from_bytes(path: &Path, bytes: &[u8]) -> Result<LutFile, LutFileError> {
    decode(bytes).map_err(|k| k.at(path))
}

fn table_named(name: &[u8]) -> Option<Table> {
    Table::ALL.into_iter().find(|t| t.name().as_bytes() == name)
}

fn layer_name(attrs: &x::LayerAttributes) -> &[u8] {
    attrs.layer_name.as_ref().map(|t| t.bytes()).unwrap_or(b"")
}

// ---------------------------------------------------------------------------------------------
// Encoding

fn encode(file: &LutFile) -> Result<Vec<u8>, Kind> {
    let blob = &file.blob;
    let header = lut::validate(blob)?;
    let res = header.res;

    let mut layers = Vec::with_capacity(TABLE_COUNT);
    let (mut max_w, mut max_h) = (1, 1);
    for t in Table::ALL {
        let (w, h) = res.dims(t);
        max_w = max_w.max(w);
        max_h = max_h.max(h);
        let data = &blob[res.byte_range(t)];
        let nc = t.channels();
        let list = t
            .channel_names()
            .iter()
            .enumerate()
            .map(|(c, name)| {
                let samples: Vec<x::f16> = (0..w * h)
                    .map(|i| {
                        let at = 2 * (i * nc + c);
                        x::f16::from_bits(u16::from_le_bytes([data[at], data[at + 1]]))
                    })
                    .collect();
                x::AnyChannel::new(*name, x::FlatSamples::F16(samples))
            })
            .collect();
        let mut attrs = x::LayerAttributes::named(t.name());
        attrs.software_name = Some(text(concat!("bake ", env!("CARGO_PKG_VERSION"))));
        attrs.comments = Some(text(
            "fur BCSDF LUT table: physical value = stored half x scale attribute",
        ));
        attrs.other.insert(
            text(attributes::SCALE),
            x::AttributeValue::F32(header.scales[t as usize]),
        );
        if t == Table::M {
            insert_metadata(&mut attrs.other, &header, blob, &file.meta);
        }
        layers.push(x::Layer::new(
            (w, h),
            attrs,
            x::Encoding::SMALL_LOSSLESS,
            x::AnyChannels::sort(list),
        ));
    }
    let image = x::Image::from_layers(x::ImageAttributes::with_size((max_w, max_h)), layers);
    let mut out = Vec::new();
    image
        .write()
        .non_parallel()
        .to_buffered(Cursor::new(&mut out))
        .map_err(|e| Kind::Encode(e.to_string()))?;
    sort_attributes(&mut out);

    // Read it back: a file this function writes always reads back as the same LUT.
    let back = decode(&out).map_err(|k| {
        Kind::Encode(format!(
            "the encoded file does not read back: {}",
            k.at(Path::new("(encoded)"))
        ))
    })?;
    if back.blob != file.blob || meta_checksum(&back.meta) != meta_checksum(&file.meta) {
        return Err(Kind::Encode(
            "the encoded file reads back as a different LUT".into(),
        ));
    }
    Ok(out)
}

// ---------------------------------------------------------------------------------------------
// Decoding

/// A blob of the length `header` (the `lut_header` bytes) announces, holding the header and
/// zeros, with the header decoded by the core.
fn blob_from_header(header: &[u8]) -> Result<(Vec<u8>, LutHeader), Kind> {
    // The core's decoder checks the magic, versions and resolution before the length, and
    // reports the length that the resolution asks for.
    let len = match LutHeader::decode(header) {
        Err(LutError::Length { expected, .. }) => expected,
        Err(e) => return Err(e.into()),
        Ok(_) => {
            return Err(Kind::Format(format!(
                "attribute {} describes a LUT without tables",
                attributes::HEADER
            )))
        }
    };
    let mut blob = vec![0u8; len];
    blob[..HEADER_LEN].copy_from_slice(header);
    let decoded = LutHeader::decode(&blob)?;
    Ok((blob, decoded))
}

/// Checks one part's name, size, compression and channels against the resolution; returns
/// its table.
fn check_part(
    h: &exr::meta::header::Header,
    res: &LutResolution,
    seen: &mut [bool],
) -> Result<Table, Kind> {
    let name = layer_name(&h.own_attributes);
    let Some(t) = table_named(name) else {
        return Err(Kind::Format(format!(
            "unexpected layer {} (a LUT has the layers {})",
            shown(name),
            Table::ALL.map(Table::name).join(", ")
        )));
    };
    let problem = |what: String| Err(Kind::Format(format!("layer {} {what}", t.name())));
    if std::mem::replace(&mut seen[t as usize], true) {
        return problem("appears twice".into());
    }
    if h.deep {
        return problem("holds deep data, expected flat data".into());
    }
    // Lossy compression would change the halves; B44 would also be fed to a decoder that
    // panics on some corrupt data.
    if !h.compression.is_lossless_for(x::SampleType::F16) {
        return problem(format!(
            "uses lossy compression {}, a LUT must be stored losslessly",
            h.compression
        ));
    }
    let (w, h_rows) = res.dims(t);
    let size = h.layer_size;
    if size.0 != w {
        return problem(format!("has {} columns, expected {w}", size.0));
    }
    if size.1 != h_rows {
        return problem(format!("has {} rows, expected {h_rows}", size.1));
    }
    let list = &h.channels.list;
    for want in t.channel_names() {
        let Some(c) = list.iter().find(|c| c.name.bytes() == want.as_bytes()) else {
            return problem(format!("has no channel {want}"));
        };
        if c.sample_type != x::SampleType::F16 {
            return Err(Kind::Format(format!(
                "channel {want} of layer {} has {:?} samples, expected F16 (half)",
                t.name(),
                c.sample_type
            )));
        }
        if c.sampling != x::Vec2(1, 1) {
            return Err(Kind::Format(format!(
                "channel {want} of layer {} is subsampled",
                t.name()
            )));
        }
    }
    if list.len() != t.channels() {
        let extra = list
            .iter()
            .find(|c| {
                !t.channel_names()
                    .iter()
                    .any(|n| n.as_bytes() == c.name.bytes())
            })
            .map(|c| shown(c.name.bytes()))
            .unwrap_or_default();
        return problem(format!(
            "has {} channels, expected {} (unexpected channel {extra})",
            list.len(),
            t.channels()
        ));
    }
    Ok(t)
}

/// Runs the exr crate's reader on this thread, turning its errors, and any panic inside it
/// (its decompressors have panicked on corrupt data, e.g. B44 on an integer overflow), into
/// a "corrupt OpenEXR file" problem. A caught panic still prints the panic hook's message.
fn guarded<T>(read: impl FnOnce() -> x::Result<T>) -> Result<T, Kind> {
    match std::panic::catch_unwind(std::panic::AssertUnwindSafe(read)) {
        Ok(Ok(v)) => Ok(v),
        Ok(Err(e)) => Err(Kind::NotExr(format!("corrupt OpenEXR file: {e}"))),
        Err(_) => Err(Kind::NotExr(
            "corrupt OpenEXR file: the decoder failed on its contents".into(),
        )),
    }
}

/// Copies the halves of one decoded layer into the blob.
fn fill_table(
    layer: &x::Layer<x::AnyChannels<x::FlatSamples>>,
    t: Table,
    res: &LutResolution,
    blob: &mut [u8],
) -> Result<(), Kind> {
    let (w, h) = res.dims(t);
    if layer.size != x::Vec2(w, h) {
        return Err(Kind::Format(format!(
            "layer {} changed between header and data",
            t.name()
        )));
    }
    let nc = t.channels();
    let data = &mut blob[res.byte_range(t)];
    for (c, want) in t.channel_names().iter().enumerate() {
        let samples = layer
            .channel_data
            .list
            .iter()
            .find(|ch| ch.name.bytes() == want.as_bytes())
            .map(|ch| &ch.sample_data);
        let Some(x::FlatSamples::F16(v)) = samples else {
            return Err(Kind::Format(format!(
                "layer {} has no half channel {want}",
                t.name()
            )));
        };
        if v.len() != w * h {
            return Err(Kind::Format(format!(
                "channel {want} of layer {} has {} samples, expected {}",
                t.name(),
                v.len(),
                w * h
            )));
        }
        for (i, s) in v.iter().enumerate() {
            let at = 2 * (i * nc + c);
            data[at..at + 2].copy_from_slice(&s.to_bits().to_le_bytes());
        }
    }
    Ok(())
}

fn decode(bytes: &[u8]) -> Result<LutFile, Kind> {
    if !bytes.starts_with(&EXR_MAGIC) {
        return Err(Kind::NotExr(if bytes.starts_with(&lut::MAGIC) {
            "not an OpenEXR file: this is a raw LUT blob (read it as a blob)".into()
        } else {
            "not an OpenEXR file (no EXR magic number)".into()
        }));
    }
    // The headers first: check the layers' sizes before any pixel memory is allocated.
    let meta = guarded(|| x::MetaData::read_from_buffered(Cursor::new(bytes), true))?;
    let headers = &meta.headers;
    check_version(headers, attributes::FORMAT, "format", lut::FORMAT_VERSION)?;
    check_version(headers, attributes::MODEL, "model", MODEL_VERSION)?;
    let m = headers
        .iter()
        .find(|h| layer_name(&h.own_attributes) == Table::M.name().as_bytes())
        .ok_or_else(|| Kind::Format("no layer M".into()))?;
    let attrs = Attrs {
        map: &m.own_attributes.other,
        layer: Table::M.name(),
    };
    let (mut blob, header) = blob_from_header(attrs.header_bytes()?)?;
    let (meta, stored_meta_checksum) = parse_meta(&attrs)?;
    let res = header.res;
    let mut seen = [false; TABLE_COUNT];
    for h in headers.iter() {
        check_part(h, &res, &mut seen)?;
    }
    if let Some(t) = Table::ALL.into_iter().find(|&t| !seen[t as usize]) {
        return Err(Kind::Format(format!("no layer {}", t.name())));
    }

    // Now the pixels (sizes checked above, so the allocation is bounded by the resolution).
    let image = guarded(|| {
        x::read()
            .no_deep_data()
            .largest_resolution_level()
            .all_channels()
            .all_layers()
            .all_attributes()
            .non_parallel()
            .pedantic()
            .from_buffered(Cursor::new(bytes))
    })?;
    let mut filled = [false; TABLE_COUNT];
    for layer in image.layer_data.iter() {
        let name = layer_name(&layer.attributes);
        let t = table_named(name)
            .ok_or_else(|| Kind::Format(format!("unexpected layer {}", shown(name))))?;
        if std::mem::replace(&mut filled[t as usize], true) {
            return Err(Kind::Format(format!(
                "layer {} changed between header and data",
                t.name()
            )));
        }
        fill_table(layer, t, &res, &mut blob)?;
    }
    if let Some(t) = Table::ALL.into_iter().find(|&t| !filled[t as usize]) {
        return Err(Kind::Format(format!("no data for layer {}", t.name())));
    }
    // The sampling section is derived from the tables, so the EXR does not carry it; the
    // header's checksum covers it and catches any change to the header or the layers.
    lut::write_sampling(&mut blob);
    lut::validate(&blob)?;
    if meta_checksum(&meta) != stored_meta_checksum {
        return Err(Kind::Format(format!(
            "metadata is corrupt: {} does not match the preset name and error summary",
            attributes::META_CHECKSUM
        )));
    }
    Ok(LutFile { blob, meta })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_panic_in_the_exr_reader_becomes_an_error() {
        let r: Result<(), Kind> = guarded(|| panic!("decoder bug (expected in this test)"));
        assert!(matches!(r, Err(Kind::NotExr(_))), "{r:?}");
        let r: Result<(), Kind> = guarded(|| Err(x::Error::Aborted));
        assert!(matches!(r, Err(Kind::NotExr(_))), "{r:?}");
    }

    #[test]
    fn a_header_that_announces_no_valid_blob_is_refused() {
        // Too short, and not a LUT header at all.
        let r = blob_from_header(&[0u8; 10]);
        assert!(
            matches!(r, Err(Kind::Invalid(LutError::TooShort { len: 10 }))),
            "{r:?}"
        );
        let r = blob_from_header(&[0u8; HEADER_LEN]);
        assert!(matches!(r, Err(Kind::Invalid(LutError::BadMagic))), "{r:?}");
    }
}
