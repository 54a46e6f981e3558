//! Unit tests of the residual cache (`super`).

use super::*;
use crate::profiles::cache::{u32_at, u64_at};
use bcsdf_core::{presets, Closure, FurParamsInput, Rgb};

/// Human hair in the energy closure: no profiles, so its residual (beams only) is quick.
fn model(sigma_ca: Option<f32>) -> OwnedModel {
    let mut input = FurParamsInput {
        closure: Closure::Energy,
        ..presets::find("human-hair").unwrap().input
    };
    if let Some(s) = sigma_ca {
        input.pigment = bcsdf_core::Pigment::Absorption(Rgb([s; 3]));
    }
    OwnedModel::new(FurParams::new(&input).unwrap(), None).unwrap()
}

fn temp_dir(name: &str) -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!("fur-residual-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    d
}

#[test]
fn encode_decode_round_trip_and_header_offsets() {
    let m = model(None);
    let key = ResidualKey::of(&m, ResidualLayout::DEFAULT, 9);
    let data: Vec<f32> = (0..ResidualLayout::DEFAULT.len())
        .map(|i| i as f32 * 0.25)
        .collect();
    let bytes = encode_residual(&key, &data);
    assert_eq!(&bytes[..8], b"FURRES\0\0");
    assert_eq!(u32_at(&bytes, 8), RESIDUAL_FORMAT_VERSION);
    assert_eq!(u32_at(&bytes, 12), MODEL_VERSION);
    assert_eq!(u32_at(&bytes, 16) as usize, ResidualLayout::DEFAULT.n_theta);
    assert_eq!(u32_at(&bytes, 28), ResidualLayout::DEFAULT.photons);
    assert_eq!(u64_at(&bytes, 32), 9);
    assert_eq!(u64_at(&bytes, 40), 0, "no profiles");
    assert_eq!(u32_at(&bytes, 48), m.params().eta_c().to_bits());
    assert_eq!(u32_at(&bytes, 100), 1, "closure index (energy)");
    assert_eq!(u64_at(&bytes, KEY_END) as usize, data.len());
    assert_eq!(bytes.len(), HEADER_LEN + 4 * data.len() + 8);
    let back = decode_residual(&bytes, &key).unwrap();
    assert!(back
        .iter()
        .zip(&data)
        .all(|(a, b)| a.to_bits() == b.to_bits()));
}

#[test]
fn every_parameter_is_in_the_key() {
    // One word per header field, the colour as three: a parameter added to the schema
    // without a word here fails this test instead of sharing another set's cache file.
    assert_eq!(param_words(model(None).params()).len(), HEADER_FIELDS + 2);
    let base = ResidualKey::of(&model(None), ResidualLayout::DEFAULT, 1);
    let other = ResidualKey::of(&model(Some(0.2)), ResidualLayout::DEFAULT, 1);
    assert_ne!(base.stem(), other.stem());
    let bytes = encode_residual(&base, &vec![0.0; ResidualLayout::DEFAULT.len()]);
    let named = |k: &ResidualKey| match decode_residual(&bytes, k) {
        Err(CacheError::KeyMismatch(field)) => field,
        other => panic!("{other:?}"),
    };
    assert_eq!(named(&other), "sigma_ca");
    assert_eq!(named(&ResidualKey { seed: 2, ..base }), "seed");
    let layout = ResidualLayout {
        n_phi: 24,
        ..ResidualLayout::DEFAULT
    };
    assert_eq!(named(&ResidualKey { layout, ..base }), "residual layout");
    let params = base.params.with_closure(Closure::Report);
    assert_eq!(named(&ResidualKey { params, ..base }), "closure");
}

#[test]
fn the_cache_returns_the_generated_bits_and_replaces_a_damaged_file() {
    let dir = temp_dir("cache");
    let m = model(None);
    let layout = ResidualLayout::DEFAULT;
    let (fresh, _) =
        generate_residual(&m.model_without_residual::<Libm>(), &layout, 3, Some(1)).unwrap();
    let (first, outcome) = load_or_generate_residual(&m, layout, 3, Some(&dir), Some(2)).unwrap();
    let CacheOutcome::Generated { path: Some(path) } = outcome else {
        panic!("{outcome:?}")
    };
    assert!(path.starts_with(&dir));
    assert_eq!(path.extension().unwrap(), RESIDUAL_EXTENSION);
    let (second, outcome) = load_or_generate_residual(&m, layout, 3, Some(&dir), None).unwrap();
    assert!(matches!(&outcome, CacheOutcome::Hit { path: p } if *p == path));
    for t in [&first, &second] {
        assert!(t
            .iter()
            .zip(&fresh)
            .all(|(a, b)| a.to_bits() == b.to_bits()));
    }
    // One flipped bit in the table: rejected by the checksum, regenerated, rewritten.
    let mut bytes = std::fs::read(&path).unwrap();
    bytes[HEADER_LEN + 40] ^= 0x10;
    std::fs::write(&path, &bytes).unwrap();
    let (third, outcome) = load_or_generate_residual(&m, layout, 3, Some(&dir), None).unwrap();
    match &outcome {
        CacheOutcome::Regenerated { reason, .. } => {
            assert!(matches!(reason, CacheError::Checksum { .. }), "{reason}");
            assert!(outcome.note().unwrap().contains("residual-"));
        }
        other => panic!("{other:?}"),
    }
    assert!(third
        .iter()
        .zip(&fresh)
        .all(|(a, b)| a.to_bits() == b.to_bits()));
    assert!(decode_residual(
        &std::fs::read(&path).unwrap(),
        &ResidualKey::of(&m, layout, 3)
    )
    .is_ok());
    // Truncated: a length error, never a panic.
    let cut = &bytes[..bytes.len() - 5];
    assert!(matches!(
        decode_residual(cut, &ResidualKey::of(&m, layout, 3)),
        Err(CacheError::Length { .. })
    ));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn colours_made_together_are_each_colours_own_table_and_cache_file() {
    // A LUT's absorption planes: one walk for several colours (and a colour given twice),
    // each table the bits of its own generation, each cached in its own file, which the
    // one-colour path then reads; a damaged file among them is remade alone.
    let dir = temp_dir("together");
    let layout = ResidualLayout {
        n_theta: 6,
        ..ResidualLayout::DEFAULT
    };
    let models = [
        model(Some(0.0)),
        model(Some(0.4)),
        model(Some(7.0)),
        model(Some(0.4)),
    ];
    let own: Vec<Vec<f32>> = models[..3]
        .iter()
        .map(|m| {
            generate_residual(&m.model_without_residual::<Libm>(), &layout, 5, None)
                .unwrap()
                .0
        })
        .collect();
    let own = [&own[0], &own[1], &own[2], &own[1]];
    let same = |a: &[f32], b: &[f32]| {
        a.len() == b.len() && a.iter().zip(b).all(|(x, y)| x.to_bits() == y.to_bits())
    };
    let refs: Vec<&OwnedModel> = models.iter().collect();
    let first = load_or_generate_residuals(&refs, layout, 5, Some(&dir), None).unwrap();
    for (k, (t, outcome)) in first.iter().enumerate() {
        assert!(same(t, own[k]), "colour {k}");
        match (k, outcome) {
            (3, CacheOutcome::Hit { .. }) | (0..=2, CacheOutcome::Generated { path: Some(_) }) => {}
            other => panic!("{other:?}"),
        }
    }
    for (k, m) in models.iter().enumerate() {
        let (t, outcome) = load_or_generate_residual(m, layout, 5, Some(&dir), None).unwrap();
        assert!(matches!(outcome, CacheOutcome::Hit { .. }), "{outcome:?}");
        assert!(same(&t, own[k]));
    }
    // Damage the second colour's file: it alone is regenerated.
    let path = dir.join(format!(
        "{}.{RESIDUAL_EXTENSION}",
        ResidualKey::of(&models[1], layout, 5).stem()
    ));
    let mut bytes = std::fs::read(&path).unwrap();
    bytes[HEADER_LEN + 12] ^= 0x01;
    std::fs::write(&path, &bytes).unwrap();
    let again = load_or_generate_residuals(&refs, layout, 5, Some(&dir), None).unwrap();
    for (k, (t, outcome)) in again.iter().enumerate() {
        assert!(same(t, own[k]), "colour {k}");
        match (k, outcome) {
            (1, CacheOutcome::Regenerated { .. }) | (0 | 2 | 3, CacheOutcome::Hit { .. }) => {}
            other => panic!("{other:?}"),
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}
