//! The attributes of a LUT EXR file: their names, writing them, reading back the few that
//! are read, and sorting them so that the file bytes are reproducible.
//!
//! Layer `M` holds the attributes listed in the [`exr`](super) module documentation that are
//! read back ([`FORMAT`], [`MODEL`], [`HEADER`], [`PRESET`], the error summary,
//! [`META_CHECKSUM`]) and these readable ones, which are **written but never read back**:
//!
//! | attribute | type | value |
//! |---|---|---|
//! | `params` | string | every parameter as `key=value`, separated by spaces, in schema order ([`bcsdf_core::params::SCHEMA`]; σ_ca as `r,g,b`) |
//! | one per parameter, named by its schema key (`eta_c`, `sigma_ca` or `eumelanin` and `pheomelanin`, `alpha_deg`, …) | float (`sigma_ca`: v3f) | the value the header stores (β_n and η_m resolved; the colour form not in use is absent) |
//! | `n_sum`, `n_theta_r`, `n_phi`, `n_ms_i`, `n_ms_r` | int | node counts of the five axes |
//! | `axes` | string | each axis's range |
//! | `has_profiles` | int | 1 if the scattered tables were baked from medulla profiles, else 0 |
//! | `profile_generator`, `photons_per_cn_cell`, `photons_per_cm_row`, `profile_n_sigma`, `profile_n_h`, `profile_n_psi`, `profile_n_in`, `profile_n_out` | int | profile generator version, photon budget and profile resolution (only with profiles) |
//! | `profile_seed` | string | the profiles' seed, decimal u64 (only with profiles) |
//! | `lut_checksum` | string | the blob's checksum, 16 hex digits |
//!
//! Every layer also has `scale` (float): the table's scale, so that a generic EXR viewer can
//! show physical values (the blob's scales are in `lut_header`).

use std::collections::HashMap;

use bcsdf_core::lut::{self, LutHeader, LutResolution, HEADER_LEN};
use bcsdf_core::params::{ParamValue, SCHEMA};
use bcsdf_core::MODEL_VERSION;
use exr::meta::header::Header;
use exr::prelude as x;

use crate::lutfile::{LutFileErrorKind as Kind, LutMeta};
use crate::metrics::{ErrorSummary, METRIC_NAMES};

/// `lut_format_version` (int, read back): [`lut::FORMAT_VERSION`].
pub const FORMAT: &str = "lut_format_version";
/// `model_version` (int, read back): [`bcsdf_core::MODEL_VERSION`].
pub const MODEL: &str = "model_version";
/// `lut_header` (bytes, read back): the blob's first [`HEADER_LEN`] bytes.
pub const HEADER: &str = "lut_header";
/// The type hint of the [`HEADER`] attribute.
pub const HEADER_TYPE_HINT: &str = "furlut_header";
/// `preset` (string, read back): the preset name.
pub const PRESET: &str = "preset";
/// `meta_checksum` (string, read back): FNV-1a 64 of the preset name and error summary.
pub const META_CHECKSUM: &str = "meta_checksum";
/// `scale` (float, every layer, informative): the table's scale.
pub const SCALE: &str = "scale";
/// `params` (string, informative): every parameter as `key=value`.
pub const PARAMS: &str = "params";
/// `axes` (string, informative): the axes' ranges.
pub const AXES: &str = "axes";
/// `lut_checksum` (string, informative): the blob's checksum in hex.
pub const CHECKSUM: &str = "lut_checksum";

const HAS_PROFILES: &str = "has_profiles";
const GENERATOR: &str = "profile_generator";
const SEED: &str = "profile_seed";
const BUDGET: [&str; 2] = ["photons_per_cn_cell", "photons_per_cm_row"];
const PROFILE_RES: [&str; 5] = [
    "profile_n_sigma",
    "profile_n_h",
    "profile_n_psi",
    "profile_n_in",
    "profile_n_out",
];
const CHANNEL_SUFFIXES: [&str; 3] = ["R", "G", "B"];

/// The nine error-summary attribute names (`E1_R` … `E_peak_B`, read back),
/// [`ErrorSummary::rows`] order × R, G, B.
pub fn error_names() -> [String; 9] {
    std::array::from_fn(|i| format!("{}_{}", METRIC_NAMES[i / 3], CHANNEL_SUFFIXES[i % 3]))
}

fn error_values(e: &ErrorSummary) -> [f64; 9] {
    let rows = [e.e1, e.e_albedo, e.e_peak];
    std::array::from_fn(|i| rows[i / 3][i % 3])
}

/// FNV-1a 64 of the metadata that the blob checksum does not cover.
pub(super) fn meta_checksum(meta: &LutMeta) -> u64 {
    let mut bytes = Vec::with_capacity(meta.preset.len() + 81);
    bytes.extend_from_slice(&(meta.preset.len() as u64).to_le_bytes());
    bytes.extend_from_slice(meta.preset.as_bytes());
    match &meta.errors {
        None => bytes.push(0),
        Some(e) => {
            bytes.push(1);
            for v in error_values(e) {
                bytes.extend_from_slice(&v.to_bits().to_le_bytes());
            }
        }
    }
    lut::fnv1a64(&bytes)
}

/// Text attribute contents: raw bytes (UTF-8), not Latin-1, so any string round-trips.
pub(super) fn text(s: &str) -> x::Text {
    x::Text::from_slice_unchecked(s.as_bytes())
}

/// A name from the file, quoted and escaped for messages.
pub(super) fn shown(bytes: &[u8]) -> String {
    format!("{:?}", String::from_utf8_lossy(bytes))
}

fn axes_text(res: &LutResolution) -> String {
    format!(
        "n_sum = {}: theta_i + theta_r in [-pi, pi]; n_theta_r = {}: |theta_r| in [0, pi/2]; \
         n_phi = {}: |phi| in [0, pi]; n_ms_i = {}: theta_i in [-pi/2, pi/2]; \
         n_ms_r = {}: theta_r in [-pi/2, pi/2] (uniform nodes, first and last on the ends)",
        res.n_sum, res.n_theta_r, res.n_phi, res.n_ms_i, res.n_ms_r
    )
}

// ---------------------------------------------------------------------------------------------
// Writing

/// Inserts the attributes of layer `M` (module documentation) for the sealed `blob`, whose
/// decoded header is `header`.
pub(super) fn insert_metadata(
    other: &mut HashMap<x::Text, x::AttributeValue>,
    header: &LutHeader,
    blob: &[u8],
    meta: &LutMeta,
) {
    use x::AttributeValue::{FloatVec3, Text as T, F32, F64, I32};
    let mut put = |name: &str, v: x::AttributeValue| {
        other.insert(text(name), v);
    };
    // u32 values are stored as the i32 with the same bits.
    let int = |v: u32| I32(v as i32);

    // Read back.
    put(FORMAT, int(lut::FORMAT_VERSION));
    put(MODEL, int(MODEL_VERSION));
    put(
        HEADER,
        x::AttributeValue::Bytes {
            type_hint: text(HEADER_TYPE_HINT),
            bytes: blob[..HEADER_LEN].into(),
        },
    );
    put(PRESET, T(text(&meta.preset)));
    if let Some(e) = &meta.errors {
        for (name, v) in error_names().iter().zip(error_values(e)) {
            put(name, F64(v));
        }
    }
    put(
        META_CHECKSUM,
        T(text(&format!("{:016x}", meta_checksum(meta)))),
    );

    // Readable only: the parameters as the header stores them, by the schema.
    let p = header.params.resolved();
    let mut readable = Vec::with_capacity(SCHEMA.len());
    for spec in &SCHEMA {
        match p.value(spec.name) {
            Some(ParamValue::Scalar(v)) => {
                put(spec.key, F32(v));
                readable.push(format!("{}={v}", spec.key));
            }
            Some(ParamValue::Rgb(c)) => {
                let [r, g, b] = c.0;
                put(spec.key, FloatVec3((r, g, b)));
                readable.push(format!("{}={r},{g},{b}", spec.key));
            }
            Some(ParamValue::Choice(i)) => {
                let name = spec.choice_name(i).unwrap_or("?");
                put(spec.key, T(text(name)));
                readable.push(format!("{}={name}", spec.key));
            }
            None => {}
        }
    }
    put(PARAMS, T(text(&readable.join(" "))));
    for (name, n) in header.res.axes() {
        put(name, int(n));
    }
    put(AXES, T(text(&axes_text(&header.res))));
    match &header.profiles {
        None => put(HAS_PROFILES, int(0)),
        Some(pr) => {
            put(HAS_PROFILES, int(1));
            put(GENERATOR, int(pr.generator_version));
            put(SEED, T(text(&pr.seed.to_string())));
            put(BUDGET[0], int(pr.budget.per_cn_cell));
            put(BUDGET[1], int(pr.budget.per_cm_row));
            let r = pr.res;
            for (name, n) in PROFILE_RES
                .iter()
                .zip([r.n_sigma, r.n_h, r.n_psi, r.n_in, r.n_out])
            {
                put(name, int(n as u32));
            }
        }
    }
    let sum = u64::from_le_bytes(blob[lut::CHECKSUM].try_into().unwrap_or([0; 8]));
    put(CHECKSUM, T(text(&format!("{sum:016x}"))));
}

/// Sorts the attributes of every part header by name, in place (the headers keep their
/// length, so the offset tables stay valid). The exr crate writes them in hash-map order,
/// which changes from run to run; sorted (as the OpenEXR library writes them) the same LUT
/// always gives the same bytes. Leaves `bytes` unchanged if the headers do not parse.
pub(super) fn sort_attributes(bytes: &mut [u8]) {
    fn cstr(bytes: &[u8], at: usize) -> Option<usize> {
        // Index just past the terminating zero of the string starting at `at`.
        let len = bytes.get(at..)?.iter().position(|&b| b == 0)?;
        Some(at + len + 1)
    }
    fn header_end(bytes: &[u8], mut at: usize, attrs: &mut Vec<(usize, usize)>) -> Option<usize> {
        loop {
            if *bytes.get(at)? == 0 {
                return Some(at);
            }
            let start = at;
            let name_end = cstr(bytes, at)?;
            let type_end = cstr(bytes, name_end)?;
            let size = i32::from_le_bytes(bytes.get(type_end..type_end + 4)?.try_into().ok()?);
            let end = type_end + 4 + usize::try_from(size).ok()?;
            if end > bytes.len() {
                return None;
            }
            attrs.push((start, end));
            at = end;
        }
    }
    if bytes.len() < 8 || bytes[..4] != super::EXR_MAGIC {
        return;
    }
    let multipart = bytes[5] & 0x10 != 0;
    let mut headers = Vec::new();
    let mut at = 8;
    loop {
        let mut attrs = Vec::new();
        let Some(end) = header_end(bytes, at, &mut attrs) else {
            return;
        };
        headers.push((at, end, attrs));
        at = end + 1;
        if !multipart || bytes.get(at).is_none_or(|&b| b == 0) {
            break;
        }
    }
    for (start, end, mut attrs) in headers {
        let name = |&(s, _): &(usize, usize)| {
            let e = bytes[s..].iter().position(|&b| b == 0).unwrap_or(0);
            bytes[s..s + e].to_vec()
        };
        attrs.sort_by_key(name);
        let sorted: Vec<u8> = attrs
            .iter()
            .flat_map(|&(s, e)| bytes[s..e].iter().copied())
            .collect();
        if sorted.len() == end - start {
            bytes[start..end].copy_from_slice(&sorted);
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Reading

/// Typed access to one part's attributes.
pub(super) struct Attrs<'a> {
    /// The part's attributes.
    pub map: &'a HashMap<x::Text, x::AttributeValue>,
    /// The part's name, for messages.
    pub layer: &'a str,
}

impl Attrs<'_> {
    fn get(&self, name: &str) -> Result<&x::AttributeValue, Kind> {
        self.map.get(name.as_bytes()).ok_or_else(|| {
            Kind::Format(format!(
                "layer {} has no attribute {name}",
                shown(self.layer.as_bytes())
            ))
        })
    }

    fn mistyped(&self, name: &str, v: &x::AttributeValue, expected: &str) -> Kind {
        Kind::Format(format!(
            "attribute {name} of layer {} has type {}, expected {expected}",
            shown(self.layer.as_bytes()),
            shown(v.kind_name())
        ))
    }

    fn f64(&self, name: &str) -> Result<f64, Kind> {
        match self.get(name)? {
            x::AttributeValue::F64(v) => Ok(*v),
            v => Err(self.mistyped(name, v, "double")),
        }
    }

    fn text(&self, name: &str) -> Result<String, Kind> {
        match self.get(name)? {
            x::AttributeValue::Text(t) => String::from_utf8(t.bytes().to_vec())
                .map_err(|_| Kind::Format(format!("attribute {name} is not valid UTF-8 text"))),
            v => Err(self.mistyped(name, v, "string")),
        }
    }

    fn hex64(&self, name: &str) -> Result<u64, Kind> {
        let s = self.text(name)?;
        let bad = || {
            Kind::Format(format!(
                "attribute {name} is {}, not 16 hex digits",
                shown(s.as_bytes())
            ))
        };
        if s.len() != 16 {
            return Err(bad());
        }
        u64::from_str_radix(&s, 16).map_err(|_| bad())
    }

    /// The [`HEADER`] attribute's bytes: exactly [`HEADER_LEN`] of them (not yet decoded).
    pub(super) fn header_bytes(&self) -> Result<&[u8], Kind> {
        let Some(value) = self.map.get(HEADER.as_bytes()) else {
            // LUT EXR files written before the header was stored verbatim lack it.
            return Err(Kind::Format(format!(
                "layer {} has no attribute {HEADER} (written by an older bake: re-bake it, or \
                 read the .furlut written beside it)",
                shown(self.layer.as_bytes())
            )));
        };
        match value {
            x::AttributeValue::Bytes { bytes, .. } if bytes.len() == HEADER_LEN => Ok(bytes),
            x::AttributeValue::Bytes { bytes, .. } => Err(Kind::Format(format!(
                "attribute {HEADER} holds {} bytes, expected the {HEADER_LEN} bytes of a LUT header",
                bytes.len()
            ))),
            v => Err(self.mistyped(HEADER, v, "bytes")),
        }
    }
}

/// Checks the version attribute `name` (an int, in any part) against `expected`.
pub(super) fn check_version(
    headers: &[Header],
    name: &str,
    what: &'static str,
    expected: u32,
) -> Result<(), Kind> {
    let found = headers
        .iter()
        .find_map(|h| h.own_attributes.other.get(name.as_bytes()));
    match found {
        None => Err(Kind::Format(format!(
            "no attribute {name}: this OpenEXR file is not a fur LUT"
        ))),
        Some(x::AttributeValue::I32(v)) if *v as u32 == expected => Ok(()),
        Some(x::AttributeValue::I32(v)) => Err(Kind::Version {
            what,
            found: *v as u32,
            expected,
        }),
        Some(v) => Err(Kind::Format(format!(
            "attribute {name} has type {}, expected int",
            shown(v.kind_name())
        ))),
    }
}

/// The preset name and error summary of layer `M`, and the stored [`META_CHECKSUM`].
pub(super) fn parse_meta(a: &Attrs<'_>) -> Result<(LutMeta, u64), Kind> {
    let names = error_names();
    let present = names
        .iter()
        .filter(|n| a.map.contains_key(n.as_bytes()))
        .count();
    let errors = match present {
        0 => None,
        9 => {
            let mut v = [0.0f64; 9];
            for (slot, name) in v.iter_mut().zip(&names) {
                *slot = a.f64(name)?;
            }
            Some(ErrorSummary {
                e1: [v[0], v[1], v[2]],
                e_albedo: [v[3], v[4], v[5]],
                e_peak: [v[6], v[7], v[8]],
            })
        }
        _ => {
            let missing = names
                .iter()
                .find(|n| !a.map.contains_key(n.as_bytes()))
                .cloned()
                .unwrap_or_default();
            return Err(Kind::Format(format!(
                "incomplete error summary: attribute {missing} is missing"
            )));
        }
    };
    let preset = a.text(PRESET)?;
    // The name a LUT was baked under follows the preset-name rule (docs/model.md §9).
    bcsdf_core::params::check_name(&preset)
        .map_err(|e| Kind::Format(format!("attribute {PRESET}: name {preset:?} {e}")))?;
    let meta = LutMeta { preset, errors };
    Ok((meta, a.hex64(META_CHECKSUM)?))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sorting_attributes_leaves_other_bytes_alone() {
        let mut junk = vec![0x76, 0x2f, 0x31, 0x01, 2, 0x10, 0, 0, b'a'];
        let copy = junk.clone();
        sort_attributes(&mut junk); // header does not parse: unchanged
        assert_eq!(junk, copy);
        let mut header = vec![0x76, 0x2f, 0x31, 0x01, 2, 0, 0, 0];
        for (name, v) in [("b", 2u8), ("a", 1u8)] {
            header.extend_from_slice(name.as_bytes());
            header.extend_from_slice(b"\0int\0");
            header.extend_from_slice(&4i32.to_le_bytes());
            header.extend_from_slice(&[v, 0, 0, 0]);
        }
        header.push(0);
        header.extend_from_slice(&[9, 9, 9]);
        let mut sorted = header.clone();
        sort_attributes(&mut sorted);
        assert_eq!(sorted.len(), header.len());
        assert_eq!(&sorted[8..16], b"a\0int\0\x04\0");
        assert_eq!(&sorted[sorted.len() - 4..], &[0, 9, 9, 9]);
    }

    #[test]
    fn error_attribute_names() {
        let names = error_names();
        assert_eq!(names[0], "E1_R");
        assert_eq!(names[4], "E_albedo_G");
        assert_eq!(names[8], "E_peak_B");
    }
}
