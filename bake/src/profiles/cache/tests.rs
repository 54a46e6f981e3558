//! Unit tests of the profile cache (`super`).

use super::*;
use bcsdf_core::presets;

fn key(seed: u64) -> ProfileKey {
    let params = FurParams::new(&presets::find("bobcat").unwrap().input).unwrap();
    ProfileKey {
        layout: ProfileLayout::for_params(&params, Resolution::DEFAULT),
        budget: PhotonBudget {
            per_cn_cell: 300,
            per_cm_row: 300,
        },
        seed,
    }
}

#[test]
fn encode_decode_round_trip_and_header_offsets() {
    let k = key(7);
    let p = generate_parallel(&k.layout, &k.budget, k.seed, Some(1)).unwrap();
    let bytes = encode(&p);
    assert_eq!(&bytes[..8], b"FURPROF\0");
    assert_eq!(u32_at(&bytes, 8), FORMAT_VERSION);
    assert_eq!(u32_at(&bytes, 12), GENERATOR_VERSION);
    assert_eq!(u32_at(&bytes, 16), k.layout.g.to_bits());
    assert_eq!(u32_at(&bytes, 32), k.layout.theta_in_max.to_bits());
    assert!(k.layout.absorption > 0.0);
    assert_eq!(u32_at(&bytes, 36), k.layout.absorption.to_bits());
    assert_eq!(u32_at(&bytes, 40) as usize, k.layout.res.n_sigma);
    assert_eq!(u32_at(&bytes, 60), 300);
    assert_eq!(u64_at(&bytes, 68), 7);
    assert_eq!(u64_at(&bytes, 76) as usize, k.layout.cn_len());
    assert_eq!(u64_at(&bytes, 84) as usize, k.layout.cm_len());
    assert_eq!(
        bytes.len(),
        92 + 4 * (k.layout.cn_len() + k.layout.cm_len()) + 8
    );
    assert_eq!(decode(&bytes, &k).unwrap(), p);
    // Each key field is named when it differs.
    let mut other = k;
    other.seed = 8;
    assert!(matches!(
        decode(&bytes, &other),
        Err(CacheError::KeyMismatch("seed"))
    ));
    other = k;
    other.budget.per_cm_row += 1;
    assert!(matches!(
        decode(&bytes, &other),
        Err(CacheError::KeyMismatch("photon budget"))
    ));
    other = k;
    other.layout.sigma_n_max += 0.5;
    assert!(matches!(
        decode(&bytes, &other),
        Err(CacheError::KeyMismatch("sigma_n_max"))
    ));
    other = k;
    other.layout.absorption *= 2.0;
    assert!(matches!(
        decode(&bytes, &other),
        Err(CacheError::KeyMismatch("absorption"))
    ));
    assert_ne!(other.file_name(), k.file_name());
    other = k;
    other.layout.res.n_out += 1;
    assert!(matches!(
        decode(&bytes, &other),
        Err(CacheError::KeyMismatch("resolution"))
    ));
}

#[test]
fn file_names_differ_by_key() {
    assert_ne!(key(1).file_name(), key(2).file_name());
    assert_eq!(key(1).file_name(), key(1).file_name());
    assert!(key(1).file_name().starts_with("medulla-"));
}

#[test]
fn fnv_known_values() {
    assert_eq!(fnv1a64(b""), 0xcbf2_9ce4_8422_2325);
    assert_eq!(fnv1a64(b"a"), 0xaf63_dc4c_8601_ec8c);
    assert_eq!(fnv1a64(b"foobar"), 0x8594_4171_f739_67e8);
}
