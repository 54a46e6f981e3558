//! LUT files on disk (`bake::lutfile`): the EXR and raw-blob forms round-trip bit for bit,
//! writes are atomic and fail cleanly, bad input gives errors naming the file, and neither
//! loader panics on corrupted bytes.

use bake::lutfile::{
    encode_exr, exr_from_bytes, read_blob, read_exr, write_blob, write_exr, LutFile, LutFileError,
    LutFileErrorKind as Kind, LutMeta,
};
use bake::metrics::ErrorSummary;
use bake::profiles::{build_model, scale_budget, ProfileOptions};
use bcsdf_core::lut::{self, LutError, LutResolution, Table};
use bcsdf_core::params::{ParamValue, SCHEMA};
use bcsdf_core::{FurParams, ParamName, PhotonBudget, Pigment, Rgb, MODEL_VERSION};
use exr::prelude as x;
use exr::prelude::traits::*;
use proptest::prelude::*;
use std::collections::HashMap;
use std::io::Cursor;
use std::ops::Range;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

const RES: LutResolution = LutResolution {
    n_sum: 64,
    n_theta_r: 8,
    n_phi: 16,
    n_ms_i: 12,
    n_ms_r: 12,
};

fn bake_preset(name: &str) -> Vec<u8> {
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
fn air() -> &'static [u8] {
    static BLOB: OnceLock<Vec<u8>> = OnceLock::new();
    BLOB.get_or_init(|| bake_preset("air-medulla"))
}

/// "human-hair": no profiles.
fn human() -> &'static [u8] {
    static BLOB: OnceLock<Vec<u8>> = OnceLock::new();
    BLOB.get_or_init(|| bake_preset("human-hair"))
}

/// Values that are not short decimals, so that any rounding on the way shows.
fn summary() -> ErrorSummary {
    ErrorSummary {
        e1: [1.0 / 3.0, 0.1, 2.5e-3],
        e_albedo: [1.0 / 7.0, 1e-300, 0.0],
        e_peak: [std::f64::consts::PI * 1e-3, 0.02, 5e-324],
    }
}

fn lut_file(blob: &[u8], preset: &str, errors: Option<ErrorSummary>) -> LutFile {
    LutFile {
        blob: blob.to_vec(),
        meta: LutMeta {
            preset: preset.to_string(),
            errors,
        },
    }
}

fn air_file() -> LutFile {
    lut_file(air(), "air-medulla", Some(summary()))
}

fn air_exr() -> &'static [u8] {
    static BYTES: OnceLock<Vec<u8>> = OnceLock::new();
    BYTES.get_or_init(|| encode_exr(Path::new("air.exr"), &air_file()).unwrap())
}

fn dir_entries(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

fn find(haystack: &[u8], needle: &[u8]) -> Option<usize> {
    haystack.windows(needle.len()).position(|w| w == needle)
}

/// Overwrites the value of the `int` attribute `name` in EXR file bytes.
fn patch_int(bytes: &mut [u8], name: &str, value: i32) {
    let key = [name.as_bytes(), b"\0int\0", &4i32.to_le_bytes()].concat();
    let at = find(bytes, &key).unwrap_or_else(|| panic!("attribute {name}")) + key.len();
    bytes[at..at + 4].copy_from_slice(&value.to_le_bytes());
}

/// Offset in EXR file bytes of the LUT header held by the `lut_header` attribute.
fn header_at(bytes: &[u8]) -> usize {
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

fn half_at(blob: &[u8], t: Table, texel: usize, channel: usize) -> u16 {
    let at = RES.byte_range(t).start + 2 * (texel * t.channels() + channel);
    u16::from_le_bytes([blob[at], blob[at + 1]])
}

#[test]
fn exr_round_trip_is_bit_exact() {
    let dir = tempfile::tempdir().unwrap();
    assert!(lut::validate(air()).unwrap().profiles.is_some());
    assert!(lut::validate(human()).unwrap().profiles.is_none());
    let cases = [
        lut_file(air(), "air-medulla", Some(summary())),
        lut_file(air(), "air-medulla", None),
        lut_file(human(), "human-hair", None),
        lut_file(human(), "human-hair", Some(summary())),
        lut_file(human(), "ümlaut «preset» with spaces", None),
    ];
    for (i, file) in cases.iter().enumerate() {
        let path = dir.path().join(format!("{i}.exr"));
        write_exr(&path, file).unwrap();
        let back = read_exr(&path).unwrap();
        assert_eq!(back.blob, file.blob, "case {i}: blob");
        assert_eq!(back.meta, file.meta, "case {i}: meta");
        assert_eq!(back.header().unwrap(), lut::validate(&file.blob).unwrap());
        assert!(back.baked().is_ok());
    }
}

#[test]
fn exr_layers_hold_the_blob_halves_and_the_metadata() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("air.exr");
    let file = air_file();
    write_exr(&path, &file).unwrap();
    let header = lut::validate(air()).unwrap();

    // Read with the exr crate directly, not through `read_exr`.
    let image = x::read_all_flat_layers_from_file(&path).unwrap();
    let names: Vec<String> = image
        .layer_data
        .iter()
        .map(|l| l.attributes.layer_name.as_ref().unwrap().to_string())
        .collect();
    assert_eq!(names, Table::ALL.map(|t| t.name().to_string()));
    for (layer, t) in image.layer_data.iter().zip(Table::ALL) {
        let (w, h) = RES.dims(t);
        assert_eq!(layer.size, x::Vec2(w, h), "{}", t.name());
        assert_eq!(layer.encoding.compression, x::Compression::ZIP16);
        assert_eq!(
            layer.attributes.other.get(b"scale".as_slice()),
            Some(&x::AttributeValue::F32(header.scales[t as usize]))
        );
        assert_eq!(layer.channel_data.list.len(), t.channels());
        for (c, name) in t.channel_names().iter().enumerate() {
            let ch = layer
                .channel_data
                .list
                .iter()
                .find(|ch| ch.name.to_string() == *name)
                .unwrap_or_else(|| panic!("{} channel {name}", t.name()));
            let x::FlatSamples::F16(v) = &ch.sample_data else {
                panic!("{} channel {name} is not half", t.name());
            };
            assert_eq!(v.len(), w * h);
            for yy in 0..h {
                for xx in 0..w {
                    let i = yy * w + xx;
                    assert_eq!(
                        v[i].to_bits(),
                        half_at(air(), t, i, c),
                        "{} {name} at ({xx}, {yy})",
                        t.name()
                    );
                }
            }
        }
    }
    // Some data is non-zero, so the comparison above means something.
    assert!((0..RES.values(Table::MS) / 2).any(|i| half_at(air(), Table::MS, i, 1) != 0));

    let m = &image.layer_data[0].attributes.other;
    let get = |name: &str| m.get(name.as_bytes()).unwrap_or_else(|| panic!("{name}"));
    let int = |v: u32| x::AttributeValue::I32(v as i32);
    assert_eq!(get("lut_format_version"), &int(lut::FORMAT_VERSION));
    assert_eq!(get("model_version"), &int(MODEL_VERSION));
    assert_eq!(get("n_phi"), &int(RES.n_phi));
    assert_eq!(get("n_sum"), &int(RES.n_sum));
    assert_eq!(get("has_profiles"), &int(1));
    assert_eq!(
        get("eta_c"),
        &x::AttributeValue::F32(header.params.eta_c),
        "float attributes hold the exact value"
    );
    assert_eq!(get("g"), &x::AttributeValue::F32(header.params.g));
    assert_eq!(get("E_albedo_R"), &x::AttributeValue::F64(1.0 / 7.0));
    let text = |name: &str| match get(name) {
        x::AttributeValue::Text(t) => t.to_string(),
        v => panic!("{name}: {v:?}"),
    };
    assert_eq!(text("preset"), "air-medulla");
    // The header, verbatim.
    match get("lut_header") {
        x::AttributeValue::Bytes { type_hint, bytes } => {
            assert_eq!(type_hint.to_string(), "furlut_header");
            assert_eq!(bytes.as_slice(), &air()[..lut::HEADER_LEN]);
        }
        v => panic!("lut_header: {v:?}"),
    }
    // The readable parameters: the melanin form, not sigma_ca.
    let Some(ParamValue::Scalar(eumelanin)) = header.params.value(ParamName::Eumelanin) else {
        panic!("air-medulla is coloured by melanin: {:?}", header.params);
    };
    assert_eq!(get("eumelanin"), &x::AttributeValue::F32(eumelanin));
    assert!(m.get(b"sigma_ca".as_slice()).is_none());
    assert!(m.get(b"pigment".as_slice()).is_none());
    // Every schema row: an attribute named by its key with the header's value (and a
    // `key=` entry in `params`), or, for the colour form not in use, no attribute.
    let resolved = header.params.resolved();
    for spec in &SCHEMA {
        let attr = m.get(spec.key.as_bytes());
        let in_text = text("params")
            .split(' ')
            .any(|kv| kv.starts_with(&format!("{}=", spec.key)));
        match resolved.value(spec.name) {
            Some(ParamValue::Scalar(v)) => {
                assert_eq!(attr, Some(&x::AttributeValue::F32(v)), "{}", spec.key);
                assert!(in_text, "{}", spec.key);
            }
            Some(ParamValue::Rgb(c)) => {
                let [r, g, b] = c.0;
                let v3 = x::AttributeValue::FloatVec3((r, g, b));
                assert_eq!(attr, Some(&v3), "{}", spec.key);
                assert!(in_text, "{}", spec.key);
            }
            None => assert!(attr.is_none() && !in_text, "{}", spec.key),
        }
    }
    let stored = u64::from_le_bytes(air()[lut::CHECKSUM].try_into().unwrap());
    assert_eq!(text("lut_checksum"), format!("{stored:016x}"));
    let seed = header.profiles.unwrap().seed;
    assert_eq!(text("profile_seed"), seed.to_string());
    assert!(
        text("axes").contains("n_phi = 16: |phi| in [0, pi]"),
        "{}",
        text("axes")
    );
    assert!(text("params").starts_with("eta_c=1.55 eumelanin=0.5"));
}

#[test]
fn an_rgb_colour_is_a_v3f_attribute_and_round_trips() {
    // human-hair recoloured with an RGB sigma_ca (a header the core encodes, resealed).
    let mut header = lut::validate(human()).unwrap();
    header.params.pigment = Pigment::Absorption(Rgb([0.25, 0.5, 1.5]));
    let mut blob = human().to_vec();
    blob[..lut::HEADER_LEN].copy_from_slice(&header.encode());
    lut::seal(&mut blob);
    let file = lut_file(&blob, "rgb", None);
    let bytes = encode_exr(Path::new("rgb.exr"), &file).unwrap();
    assert_eq!(exr_from_bytes(Path::new("rgb.exr"), &bytes).unwrap(), file);
    let mut seen = false;
    rewrite_attributes(&bytes, |layer, attrs| {
        if layer == 0 {
            let get = |k: &str| attrs.get(k.as_bytes()).cloned();
            assert_eq!(
                get("sigma_ca"),
                Some(x::AttributeValue::FloatVec3((0.25, 0.5, 1.5)))
            );
            assert_eq!(get("eumelanin"), None);
            assert_eq!(get("pheomelanin"), None);
            let Some(x::AttributeValue::Text(params)) = get("params") else {
                panic!("params");
            };
            assert!(
                params
                    .to_string()
                    .starts_with("eta_c=1.55 sigma_ca=0.25,0.5,1.5 alpha_deg=2"),
                "{params}"
            );
            seen = true;
        }
    });
    assert!(seen);
}

/// `bytes` (an EXR file) read with the exr crate, each layer's attributes passed to `edit`
/// (with the layer's index), and written again by the exr crate (not by `bake`).
fn rewrite_attributes(
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
    let eta_c = f32::from_le_bytes(air()[48..52].try_into().unwrap());
    let cases: Vec<(Option<x::AttributeValue>, String)> = vec![
        (
            Some(header_bytes_attribute(&air()[..lut::HEADER_LEN - 1])),
            "attribute lut_header holds 159 bytes, expected the 160 bytes of a LUT header".into(),
        ),
        (
            Some(header_bytes_attribute(&extended)),
            "attribute lut_header holds 161 bytes".into(),
        ),
        (
            Some(header_bytes_attribute(&[])),
            "attribute lut_header holds 0 bytes".into(),
        ),
        (
            Some(x::AttributeValue::Text(x::Text::from("FURLUT"))),
            "attribute lut_header of layer \"M\" has type \"string\", expected bytes".into(),
        ),
        (None, "layer \"M\" has no attribute lut_header".into()),
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
            changed(48, &(eta_c + 0.25).to_le_bytes()),
            "LUT is corrupt: checksum".into(),
        ),
        (
            changed(48, &0.5f32.to_le_bytes()),
            "LUT parameters are invalid".into(),
        ),
        (
            changed(157, &[1]),
            "header field reserved is invalid".into(),
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

#[test]
fn exr_files_are_byte_for_byte_reproducible() {
    let dir = tempfile::tempdir().unwrap();
    let (a, b) = (dir.path().join("a.exr"), dir.path().join("b.exr"));
    write_exr(&a, &air_file()).unwrap();
    write_exr(&b, &air_file()).unwrap();
    // Each write builds fresh hash maps (new random order); the attributes are sorted.
    assert_eq!(std::fs::read(&a).unwrap(), std::fs::read(&b).unwrap());
    assert_eq!(std::fs::read(&a).unwrap(), air_exr());
}

#[test]
fn blob_round_trip_is_bit_exact() {
    let dir = tempfile::tempdir().unwrap();
    for (name, blob) in [("air.lut", air()), ("human.lut", human())] {
        let path = dir.path().join(name);
        write_blob(&path, blob).unwrap();
        assert_eq!(std::fs::read(&path).unwrap(), blob, "the file is the blob");
        assert_eq!(read_blob(&path).unwrap(), blob);
    }
}

#[test]
fn writes_into_a_missing_or_non_directory_fail_cleanly() {
    let dir = tempfile::tempdir().unwrap();
    let missing = dir.path().join("no-such-dir");
    let not_dir = dir.path().join("plain-file");
    std::fs::write(&not_dir, b"keep me").unwrap();
    for (parent, problem) in [
        (&missing, "does not exist"),
        (&not_dir, "is not a directory"),
    ] {
        let exr_path = parent.join("x.exr");
        let blob_path = parent.join("x.lut");
        let errors = [
            write_exr(&exr_path, &air_file()).unwrap_err(),
            write_blob(&blob_path, air()).unwrap_err(),
        ];
        for err in errors {
            assert!(matches!(err.kind(), Kind::Directory { .. }), "{err:?}");
            let msg = err.to_string();
            assert!(!msg.contains('\n'), "{msg}");
            assert!(
                msg.contains(&parent.display().to_string()) && msg.contains(problem),
                "{msg}"
            );
        }
    }
    assert!(!missing.exists(), "nothing created");
    assert_eq!(std::fs::read(&not_dir).unwrap(), b"keep me");
    assert_eq!(dir_entries(dir.path()), ["plain-file"]);
}

#[test]
fn a_directory_in_the_way_is_left_alone() {
    // The destination is an existing directory: the rename cannot replace it (even as root).
    let dir = tempfile::tempdir().unwrap();
    let target = dir.path().join("x.exr");
    std::fs::create_dir(&target).unwrap();
    std::fs::write(target.join("inside"), b"data").unwrap();
    let err = write_exr(&target, &air_file()).unwrap_err();
    assert!(matches!(err.kind(), Kind::Write(_)), "{err:?}");
    assert!(err.to_string().contains("x.exr"), "{err}");
    let err = write_blob(&target, air()).unwrap_err();
    assert!(matches!(err.kind(), Kind::Write(_)), "{err:?}");
    assert_eq!(dir_entries(dir.path()), ["x.exr"], "no temporary file left");
    assert_eq!(std::fs::read(target.join("inside")).unwrap(), b"data");
}

#[test]
fn a_new_lut_replaces_an_old_one_and_a_rejected_write_keeps_it() {
    let dir = tempfile::tempdir().unwrap();
    let exr_path = dir.path().join("x.exr");
    let blob_path = dir.path().join("x.lut");
    write_exr(&exr_path, &lut_file(human(), "human-hair", None)).unwrap();
    write_blob(&blob_path, human()).unwrap();
    write_exr(&exr_path, &air_file()).unwrap();
    write_blob(&blob_path, air()).unwrap();
    assert_eq!(read_exr(&exr_path).unwrap(), air_file(), "replaced");
    assert_eq!(read_blob(&blob_path).unwrap(), air());

    // A write that fails (here: the LUT is invalid, so nothing is encoded) does not touch
    // the existing files. A write failing part-way through (disk full) is covered by the
    // unit test `failed_write_keeps_the_existing_file` in src/lutfile/mod.rs.
    let before_exr = std::fs::read(&exr_path).unwrap();
    let mut bad = air_file();
    let last = bad.blob.len() - 1;
    bad.blob[last] ^= 1;
    let err = write_exr(&exr_path, &bad).unwrap_err();
    assert!(
        matches!(err.kind(), Kind::Invalid(LutError::Checksum { .. })),
        "{err:?}"
    );
    let err = write_blob(&blob_path, &bad.blob).unwrap_err();
    assert!(matches!(err.kind(), Kind::Invalid(_)), "{err:?}");
    assert_eq!(std::fs::read(&exr_path).unwrap(), before_exr);
    assert_eq!(std::fs::read(&blob_path).unwrap(), air());
    assert_eq!(dir_entries(dir.path()), ["x.exr", "x.lut"]);
}

/// The message of a read error: one line, naming the file.
fn read_message(err: &LutFileError, path: &Path) -> String {
    let msg = err.to_string();
    assert!(!msg.contains('\n'), "{msg}");
    assert!(msg.starts_with(&path.display().to_string()), "{msg}");
    assert_eq!(err.path(), path);
    msg
}

#[test]
fn read_errors_name_the_file_and_the_problem() {
    let dir = tempfile::tempdir().unwrap();
    let p = |name: &str| -> PathBuf { dir.path().join(name) };

    for read in [
        |p: &Path| read_exr(p).map(|_| ()),
        |p: &Path| read_blob(p).map(|_| ()),
    ] {
        let err = read(&p("missing")).unwrap_err();
        assert!(matches!(err.kind(), Kind::Missing), "{err:?}");
        assert!(read_message(&err, &p("missing")).contains("no such file"));

        let err = read(dir.path()).unwrap_err();
        assert!(matches!(err.kind(), Kind::Read(_)), "{err:?}");
        read_message(&err, dir.path());
    }

    std::fs::write(p("text.exr"), b"hello, not an image\n").unwrap();
    let err = read_exr(&p("text.exr")).unwrap_err();
    assert!(matches!(err.kind(), Kind::NotExr(_)), "{err:?}");
    assert!(read_message(&err, &p("text.exr")).contains("not an OpenEXR file"));
    std::fs::write(p("empty.exr"), b"").unwrap();
    assert!(matches!(
        read_exr(&p("empty.exr")).unwrap_err().kind(),
        Kind::NotExr(_)
    ));

    write_blob(&p("x.lut"), air()).unwrap();
    let err = read_exr(&p("x.lut")).unwrap_err();
    assert!(read_message(&err, &p("x.lut")).contains("raw LUT blob"));
    write_exr(&p("x.exr"), &air_file()).unwrap();
    let err = read_blob(&p("x.exr")).unwrap_err();
    assert!(read_message(&err, &p("x.exr")).contains("OpenEXR"));

    let truncated = &air_exr()[..air_exr().len() - 100];
    std::fs::write(p("truncated.exr"), truncated).unwrap();
    let err = read_exr(&p("truncated.exr")).unwrap_err();
    assert!(matches!(err.kind(), Kind::NotExr(_)), "{err:?}");
    assert!(read_message(&err, &p("truncated.exr")).contains("corrupt OpenEXR"));

    // An EXR that is not a LUT.
    let plain = x::Image::from_channels(
        (4, 2),
        x::AnyChannels::sort(
            [x::AnyChannel::new(
                "R",
                x::FlatSamples::F16(vec![x::f16::ONE; 8]),
            )]
            .into_iter()
            .collect(),
        ),
    );
    plain.write().to_file(p("plain.exr")).unwrap();
    let err = read_exr(&p("plain.exr")).unwrap_err();
    assert!(matches!(err.kind(), Kind::Format(_)), "{err:?}");
    assert!(read_message(&err, &p("plain.exr")).contains("lut_format_version"));

    // The header says 17 columns, the (first) layer over |phi| has 16.
    let phi_table = Table::ALL
        .into_iter()
        .find(|&t| RES.dims(t).0 == RES.n_phi as usize)
        .unwrap();
    let mut bytes = air_exr().to_vec();
    let at = header_at(&bytes) + 24; // n_phi, the third node count
    bytes[at..at + 4].copy_from_slice(&17u32.to_le_bytes());
    std::fs::write(p("size.exr"), &bytes).unwrap();
    let err = read_exr(&p("size.exr")).unwrap_err();
    let msg = read_message(&err, &p("size.exr"));
    let expected = format!("layer {} has 16 columns, expected 17", phi_table.name());
    assert!(msg.contains(&expected), "{msg}");

    // Lossy compression is refused (B44 is lossy for halves, and its decoder panicked on
    // fuzzed data before this check).
    let mut bytes = air_exr().to_vec();
    let key = b"compression\0compression\0\x01\0\0\0";
    let at = find(&bytes, key).unwrap() + key.len();
    bytes[at] = 6; // B44
    let err = exr_from_bytes(Path::new("b44.exr"), &bytes).unwrap_err();
    assert!(matches!(err.kind(), Kind::Format(_)), "{err:?}");
    assert!(err.to_string().contains("lossy compression"), "{err}");

    // Another stored checksum in the header: the rebuilt blob no longer validates.
    let mut bytes = air_exr().to_vec();
    let at = header_at(&bytes) + lut::CHECKSUM.start;
    bytes[at] ^= 1;
    let err = exr_from_bytes(Path::new("sum.exr"), &bytes).unwrap_err();
    assert!(
        matches!(err.kind(), Kind::Invalid(LutError::Checksum { .. })),
        "{err:?}"
    );
    assert!(err.to_string().contains("checksum"), "{err}");
}

#[test]
fn another_format_or_model_version_is_rejected_naming_the_version() {
    let dir = tempfile::tempdir().unwrap();

    // A LUT of the previous format (version 1, before the sampling section) is refused with a
    // message that says to re-bake.
    let mut bytes = air_exr().to_vec();
    patch_int(&mut bytes, "lut_format_version", 1);
    let path = dir.path().join("v1.exr");
    std::fs::write(&path, &bytes).unwrap();
    let err = read_exr(&path).unwrap_err();
    assert!(
        matches!(
            err.kind(),
            Kind::Version {
                what: "format",
                found: 1,
                ..
            }
        ),
        "{err:?}"
    );
    let msg = read_message(&err, &path);
    assert!(
        msg.contains("format version 1") && msg.contains("re-bake"),
        "{msg}"
    );

    let mut bytes = air_exr().to_vec();
    patch_int(&mut bytes, "model_version", MODEL_VERSION as i32 + 1);
    let err = exr_from_bytes(&path, &bytes).unwrap_err();
    let msg = read_message(&err, &path);
    assert!(
        msg.contains(&format!("model version {}", MODEL_VERSION + 1)),
        "{msg}"
    );

    let mut blob = air().to_vec();
    blob[8..12].copy_from_slice(&1u32.to_le_bytes());
    let path = dir.path().join("v1.lut");
    std::fs::write(&path, &blob).unwrap();
    let err = read_blob(&path).unwrap_err();
    assert!(
        matches!(
            err.kind(),
            Kind::Version {
                what: "format",
                found: 1,
                ..
            }
        ),
        "{err:?}"
    );
    let msg = read_message(&err, &path);
    assert!(
        msg.contains("format version 1") && msg.contains("re-bake"),
        "{msg}"
    );
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
