//! LUT files on disk (`bake::lutfile`): the EXR and raw-blob forms round-trip bit for bit,
//! the EXR holds the blob's halves and header with readable metadata, writes are atomic and
//! fail cleanly, and bad input gives errors naming the file. Damaged and edited files:
//! `lutfile_damage.rs`.

use crate::common;

use bake::lutfile::{
    encode_exr, exr_from_bytes, read_blob, read_exr, write_blob, write_exr,
    LutFileErrorKind as Kind,
};
use bcsdf_core::lut::{self, LutError, Table};
use bcsdf_core::params::{ParamValue, SCHEMA};
use bcsdf_core::{ParamName, Pigment, Rgb, MODEL_VERSION};
use common::*;
use exr::prelude as x;
use exr::prelude::traits::*;
use std::path::{Path, PathBuf};

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
        lut_file(human(), "A.b_c-9", None),
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
            Some(ParamValue::Choice(i)) => {
                let name = spec.choices[usize::from(i)];
                assert_eq!(text(spec.key), name, "{}", spec.key);
                let kv = format!("{}={name}", spec.key);
                assert!(text("params").split(' ').any(|t| t == kv), "{}", spec.key);
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

    // A preset name that breaks the name rule (docs/model.md §9) is refused on reading (the
    // file is made by patching a valid name of the same length), and so on writing, which
    // reads its encoding back.
    for bad in ["../escaped", "a b", "con"] {
        let good = "x".repeat(bad.len());
        let path = p("bad-name.exr");
        write_exr(&path, &lut_file(human(), &good, None)).unwrap();
        let mut bytes = std::fs::read(&path).unwrap();
        let at = find(&bytes, good.as_bytes()).unwrap();
        bytes[at..at + bad.len()].copy_from_slice(bad.as_bytes());
        assert_eq!(find(&bytes, good.as_bytes()), None, "one occurrence");
        std::fs::write(&path, &bytes).unwrap();
        let err = read_exr(&path).unwrap_err();
        assert!(matches!(err.kind(), Kind::Format(_)), "{err:?}");
        let msg = read_message(&err, &path);
        assert!(
            msg.contains(&format!("attribute preset: name {bad:?} ")),
            "{msg}"
        );
        std::fs::remove_file(&path).unwrap();
        assert!(write_exr(&path, &lut_file(human(), bad, None)).is_err());
        assert!(!path.exists());
    }

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
