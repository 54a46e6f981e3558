//! The LUT format and the baked evaluator, independently of the analytic model:
//!
//! - the shift-and-multiply f16 decoding equals `half`'s conversion for every valid half;
//! - the header round-trips and every malformed blob is rejected with the right error;
//! - on tables filled from known functions that bilinear interpolation reproduces exactly,
//!   the evaluator returns S = [Σ M_g·N_g + M^s·N^s]/cos²θ_i to f16 precision, which pins
//!   down axis orientation, |θ_r| and |φ| folding, channel order and the back/front blend;
//! - random and degenerate input never gives NaN, negative values or a panic.

use bake::tables::{encode, node, TableValues};
use bcsdf_core::baked::BakedBcsdf;
use bcsdf_core::lut::{
    self, f16_biased, LutError, LutHeader, LutResolution, ProfileProvenance, Table, F16_UNBIAS,
    TABLE_COUNT,
};
use bcsdf_core::medulla::{PhotonBudget, Resolution, GENERATOR_VERSION};
use bcsdf_core::{presets, Absorption, Angles, LobeFamily, Pigment, Rgb};
use half::f16;
use proptest::prelude::*;
use std::f32::consts::PI;

const RES: LutResolution = LutResolution {
    n_sum: 33,
    n_theta_r: 9,
    n_phi: 17,
    n_ms_i: 13,
    n_ms_r: 11,
    n_abs: 3,
};

/// Bobcat in the report closure: the tables are read as stored (the energy closure's factor
/// is checked in bcsdf-core's baked tests).
fn input() -> bcsdf_core::FurParamsInput {
    bcsdf_core::FurParamsInput {
        closure: bcsdf_core::Closure::Report,
        ..presets::find("bobcat").unwrap().input
    }
}

/// Test functions, each linear in every table axis (so bilinear interpolation is exact):
/// M_g(x) = 1 + g + 0.1·(g+1)·(x + π); N_f = (1 + f + c)·(1 + |φ|)·(2 + |θ_r|) per channel c;
/// M^s_back = 1 + θ_i + 2 (θ_r + 2), M^s_front = 3 + 0.5 θ_i − 0.25 θ_r.
fn m_fn(g: usize, x: f32) -> f32 {
    1.0 + g as f32 + 0.1 * (g as f32 + 1.0) * (x + PI)
}
fn n_fn(f: usize, c: usize, theta_r: f32, phi: f32) -> f32 {
    (1.0 + f as f32 + c as f32) * (1.0 + phi.abs()) * (2.0 + theta_r.abs())
}
fn ms_fn(front: bool, ti: f32, tr: f32) -> f32 {
    if front {
        3.0 + 0.5 * ti - 0.25 * tr
    } else {
        1.0 + ti + 2.0 * (tr + 2.0)
    }
}

fn linear_tables() -> TableValues {
    let mut t: [Vec<f32>; TABLE_COUNT] = Default::default();
    t[Table::M as usize] = (0..RES.n_sum as usize)
        .flat_map(|k| {
            let x = node(-PI, 2.0 * PI, k, RES.n_sum);
            [0, 1, 2].map(|g| m_fn(g, x))
        })
        .collect();
    // Table N: plane k (absorption node k) holds n_fn(f, k, ..), so that a colour whose
    // channel c sits on node c reads n_fn(f, c, ..) in channel c.
    let mut v = Vec::new();
    for k in 0..RES.n_abs as usize {
        for r in 0..RES.n_theta_r as usize {
            for c in 0..RES.n_phi as usize {
                let tr = node(0.0, PI / 2.0, r, RES.n_theta_r);
                let phi = node(0.0, PI, c, RES.n_phi);
                v.extend((0..4).map(|f| n_fn(f, k, tr, phi)));
            }
        }
    }
    t[Table::N as usize] = v;
    let mut ms = Vec::new();
    for r in 0..RES.n_ms_r as usize {
        for c in 0..RES.n_ms_i as usize {
            let tr = node(-PI / 2.0, PI, r, RES.n_ms_r);
            let ti = node(-PI / 2.0, PI, c, RES.n_ms_i);
            ms.extend([ms_fn(false, ti, tr), ms_fn(true, ti, tr)]);
        }
    }
    t[Table::MS as usize] = ms;
    TableValues {
        res: RES,
        tables: t,
    }
}

fn linear_blob() -> Vec<u8> {
    encode(&linear_tables(), &input(), None)
}

fn shared_blob() -> &'static [u8] {
    static BLOB: std::sync::OnceLock<Vec<u8>> = std::sync::OnceLock::new();
    BLOB.get_or_init(linear_blob)
}

#[test]
fn f16_decoding_is_exact_for_every_valid_half() {
    let mut checked = 0;
    for bits in 0..=u16::MAX {
        if !lut::is_valid_value(bits) {
            let h = f16::from_bits(bits);
            assert!(
                h.is_sign_negative() || !h.is_finite(),
                "{bits:#x} wrongly invalid"
            );
            continue;
        }
        let expected = f16::from_bits(bits).to_f32();
        assert_eq!(
            (f16_biased(bits) * F16_UNBIAS).to_bits(),
            expected.to_bits(),
            "bits {bits:#06x}"
        );
        checked += 1;
    }
    assert_eq!(checked, 0x7c00, "every non-negative finite half");
}

#[test]
fn header_round_trips_with_and_without_profiles() {
    let mut params = input();
    for (pigment, profiles) in [
        (Pigment::Absorption(Rgb([0.1, 0.2, 0.3])), None),
        (
            Pigment::Melanin {
                eumelanin: 0.7,
                pheomelanin: 0.2,
            },
            Some(ProfileProvenance {
                generator_version: GENERATOR_VERSION,
                seed: 0x0123_4567_89ab_cdef,
                budget: PhotonBudget {
                    per_cn_cell: 12345,
                    per_cm_row: 678,
                },
                res: Resolution::DEFAULT,
            }),
        ),
    ] {
        params.pigment = pigment;
        let tables = linear_tables();
        let blob = encode(&tables, &params, profiles);
        let header = lut::validate(&blob).unwrap();
        assert_eq!(header.params.pigment, pigment);
        assert_eq!(header.profiles, profiles);
        assert_eq!(header.res, RES);
        assert_eq!(
            bcsdf_core::FurParams::new(&header.params).unwrap(),
            bcsdf_core::FurParams::new(&params).unwrap()
        );
        // Re-encoding the decoded header gives the same bytes.
        assert_eq!(
            header.encode()[..lut::CHECKSUM.start],
            blob[..lut::CHECKSUM.start]
        );
    }
}

/// Re-seals a modified blob so that only the intended defect remains.
fn sealed(mut blob: Vec<u8>) -> Vec<u8> {
    lut::seal(&mut blob);
    blob
}

#[test]
fn malformed_blobs_are_rejected_with_the_right_error() {
    let good = linear_blob();
    assert!(BakedBcsdf::from_bytes(&good).is_ok());
    let err = |b: &[u8]| BakedBcsdf::from_bytes(b).unwrap_err();

    assert!(matches!(err(&good[..100]), LutError::TooShort { len: 100 }));
    assert!(matches!(
        err(&good[..good.len() - 2]),
        LutError::Length { .. }
    ));
    let mut longer = good.clone();
    longer.push(0);
    assert!(matches!(err(&longer), LutError::Length { .. }));

    let mut b = good.clone();
    b[0] = b'X';
    assert_eq!(err(&b), LutError::BadMagic);

    // The previous format (1, without the sampling section) asks for a re-bake.
    let mut b = good.clone();
    b[8..12].copy_from_slice(&1u32.to_le_bytes());
    assert_eq!(err(&sealed(b)), LutError::FormatVersion { found: 1 });
    assert!(LutError::FormatVersion { found: 1 }
        .to_string()
        .contains("re-bake"));

    // A sampling section that does not match the tables, checksum recomputed over it.
    let mut b = good.clone();
    let at = RES.sampling_start() + 4 * 5;
    let v = f32::from_le_bytes(b[at..at + 4].try_into().unwrap());
    b[at..at + 4].copy_from_slice(&(v * 1.5 + 1.0).to_le_bytes());
    let sum = lut::checksum(&b);
    b[lut::CHECKSUM].copy_from_slice(&sum.to_le_bytes());
    assert_eq!(err(&b), LutError::Sampling { entry: 5 });

    let mut b = good.clone();
    b[12..16].copy_from_slice(&99u32.to_le_bytes());
    assert_eq!(err(&sealed(b)), LutError::ModelVersion { found: 99 });

    let mut b = good.clone();
    b[20..24].copy_from_slice(&1u32.to_le_bytes()); // n_theta_r = 1
    assert!(matches!(
        err(&sealed(b)),
        LutError::Resolution {
            axis: "n_theta_r",
            nodes: 1
        }
    ));

    let mut b = good.clone();
    b[44..48].copy_from_slice(&3.0f32.to_le_bytes()); // scale of N, not a power of two
    assert!(matches!(
        err(&sealed(b)),
        LutError::Scale {
            table: Table::N,
            ..
        }
    ));

    let mut b = good.clone();
    b[52..56].copy_from_slice(&0.5f32.to_le_bytes()); // eta_c < 1
    assert!(matches!(err(&sealed(b)), LutError::Params(_)));

    // The first TT channel of table N.
    let first_n_tt = RES.byte_range(Table::N).start + 2 * 3;
    for bad in [0xbc00u16, 0x7c00, 0x7e00] {
        // −1.0, +∞, NaN
        let mut b = good.clone();
        b[first_n_tt..first_n_tt + 2].copy_from_slice(&bad.to_le_bytes());
        assert_eq!(
            err(&sealed(b)),
            LutError::Value {
                table: Table::N,
                index: 3,
                bits: bad
            }
        );
    }

    let mut b = good.clone();
    *b.last_mut().unwrap() ^= 0x01; // a still-valid half, changed after sealing
    assert!(matches!(err(&b), LutError::Checksum { .. }));

    // Closure 2 names nothing (0 report, 1 energy: the word after g).
    let mut b = good.clone();
    b[108..112].copy_from_slice(&2u32.to_le_bytes());
    assert_eq!(err(&sealed(b)), LutError::Field { field: "closure" });

    // Every message is one line.
    for e in [
        LutError::BadMagic,
        LutError::TooShort { len: 3 },
        LutError::Length {
            expected: 10,
            found: 5,
        },
    ] {
        assert!(!e.to_string().contains('\n'));
    }
}

#[test]
fn evaluator_reproduces_tables_of_linear_functions() {
    let blob = linear_blob();
    let lut = BakedBcsdf::from_bytes(&blob).unwrap();
    let header: &LutHeader = lut.header();
    assert_eq!(header.res, RES);
    let mut worst = 0.0f32;
    // Channel c on absorption node c.
    let scale = header.absorption_scale();
    let colour = Absorption::from_sigma(Rgb(
        [0, 1, 2].map(|k| lut::absorption_node(k, RES.n_abs, scale))
    ))
    .unwrap();
    let at = lut.at(&colour);
    for ti_deg in (-88..=88).step_by(8) {
        for tr_deg in (-89..=89).step_by(7) {
            for phi_deg in (-180..=180).step_by(15) {
                let a = Angles::from_degrees(ti_deg as f32, tr_deg as f32, phi_deg as f32).unwrap();
                let (ti, tr, phi) = (a.theta_i(), a.theta_r(), a.phi());
                let inv_cos2 = 1.0 / (ti.cos() * ti.cos()).max(1e-4);
                let w = phi.abs() / PI;
                let ms = (1.0 - w) * ms_fn(false, ti, tr) + w * ms_fn(true, ti, tr);
                let got = at.eval_far(&a);
                for f in LobeFamily::ALL {
                    let fi = f as usize;
                    let m = if fi < 3 { m_fn(fi, ti + tr) } else { ms };
                    for c in 0..3 {
                        let expect = m * n_fn(fi, c, tr, phi) * inv_cos2;
                        let v = got.get(f).0[c];
                        let rel = (v - expect).abs() / expect;
                        worst = worst.max(rel);
                        assert!(
                            rel < 2e-3,
                            "{f:?} ch {c} at ({ti_deg}, {tr_deg}, {phi_deg}): {v} vs {expect}"
                        );
                    }
                }
            }
        }
    }
    // f16 rounding of two factors (2^-11 each) and f32 interpolation.
    assert!(worst < 2e-3, "worst {worst}");
    // Reading single stored values back: plane 2's first row (the planes are stacked), family 3.
    let v = lut.value(Table::N, 0, 2 * RES.n_theta_r as usize, 3);
    assert!((v - n_fn(3, 2, 0.0, 0.0)).abs() < 1e-2, "{v}");
    assert_eq!(lut.value(Table::N, 99, 0, 0), 0.0);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    #[test]
    fn baked_values_are_finite_and_non_negative(
        ti in -1.6f32..1.6, tr in -1.6f32..1.6, phi in -10.0f32..10.0,
        wi in prop::array::uniform3(-1e3f32..1e3), wr in prop::array::uniform3(-1e3f32..1e3),
    ) {
        let lut = BakedBcsdf::from_bytes(shared_blob()).unwrap();
        if let Ok(a) = Angles::new(ti, tr, phi) {
            for f in lut.eval_far(&a).as_array() {
                prop_assert!(f.0.iter().all(|v| v.is_finite() && *v >= 0.0));
            }
        }
        let d = lut.eval_far_dirs(wi, wr, [0.0, 0.0, 1.0]).total();
        prop_assert!(d.0.iter().all(|v| v.is_finite() && *v >= 0.0));
        let z = lut.eval_far_dirs([0.0; 3], wr, [f32::NAN, 0.0, 1.0]).total();
        prop_assert_eq!(z, Rgb::ZERO);
    }
}

#[test]
fn polynomial_cosine_is_accurate_within_half_pi() {
    let (mut worst, mut worst_rel) = (0.0f64, 0.0f64);
    let n = 200_000;
    let near_pole = (0..=2000).map(|k| PI / 2.0 - k as f32 * 1e-6);
    let grid = (0..=n).map(|k| -PI / 2.0 + PI * (k as f32 / n as f32));
    for x in grid.chain(near_pole) {
        let x = x.clamp(-PI / 2.0, PI / 2.0);
        let got = f64::from(bcsdf_core::math::cos_within_half_pi(x));
        let exact = f64::from(x).cos();
        worst = worst.max((got - exact).abs());
        if exact > 0.0 {
            // Relative accuracy matters near the poles, where 1/cos²θ_i magnifies errors.
            worst_rel = worst_rel.max((got - exact).abs() / exact);
        }
    }
    assert!(worst < 1.5e-7, "worst absolute error {worst:e}");
    assert!(worst_rel < 2e-6, "worst relative error {worst_rel:e}");
}
