//! Unit tests of the baked evaluator on small synthetic LUTs: axis location, interpolation
//! in every table, the exact factors, the direction and batch paths, and rejection.

extern crate std;

use super::*;
use crate::lobes::LobeFamily;
use crate::lut::{LutResolution, HEADER_LEN};
use crate::math::wrap_angle;
use crate::params::FurParamsInput;
use crate::presets;
use crate::Absorption;
use std::sync::OnceLock;
use std::vec;
use std::vec::Vec;

/// A small resolution with a different node count on every axis.
pub(crate) const RES: LutResolution = LutResolution {
    n_sum: 33,
    n_theta_r: 5,
    n_phi: 27,
    n_ms_i: 19,
    n_ms_r: 7,
    n_abs: 4,
};

/// A sealed LUT at `res` for the first preset's parameters in the report closure (the
/// tables read as stored), every stored half from `half(table, x, y, channel)`.
pub(crate) fn blob(
    res: LutResolution,
    half: impl Fn(Table, usize, usize, usize) -> u16,
) -> Vec<u8> {
    blob_with(res, Closure::Report, half)
}

/// [`blob`] in the closure `closure`.
pub(crate) fn blob_with(
    res: LutResolution,
    closure: Closure,
    half: impl Fn(Table, usize, usize, usize) -> u16,
) -> Vec<u8> {
    let header = LutHeader {
        res,
        scales: [1.0; TABLE_COUNT],
        params: FurParamsInput {
            closure,
            ..presets::PRESETS[0].input
        },
        profiles: None,
    };
    let mut b = vec![0u8; res.blob_len()];
    b[..HEADER_LEN].copy_from_slice(&header.encode());
    for t in Table::ALL {
        let (w, h) = res.dims(t);
        let start = res.byte_range(t).start;
        for y in 0..h {
            for x in 0..w {
                for c in 0..t.channels() {
                    let at = start + 2 * ((y * w + x) * t.channels() + c);
                    b[at..at + 2].copy_from_slice(&half(t, x, y, c).to_le_bytes());
                }
            }
        }
    }
    lut::seal(&mut b);
    b
}

/// The f16 bits of `v`, which must be 0 or a normal half exactly (small integers are).
fn half(v: f32) -> u16 {
    if v == 0.0 {
        return 0;
    }
    let bits = v.to_bits();
    let exp = ((bits >> 23) & 0xff) as i32 - 127 + 15;
    assert!(
        bits & 0x1fff == 0 && (1..31).contains(&exp) && v > 0.0,
        "{v}"
    );
    ((exp as u16) << 10) | ((bits >> 13) & 0x3ff) as u16
}

/// Every table affine in its node indices: M = x + c, N = x + 2y + 5k + c (y the |θ_r| row
/// within absorption plane k), M_s = x + 3y + c. Built once per test process and shared, as
/// [`random_with`]'s LUTs are: under Miri one build of a LUT costs seconds.
fn affine() -> &'static [u8] {
    static AFFINE: OnceLock<Vec<u8>> = OnceLock::new();
    AFFINE.get_or_init(|| {
        blob(RES, |t, x, y, c| {
            let v = match t {
                Table::M => x as f32,
                Table::N => {
                    let (plane, row) = (y / RES.n_theta_r as usize, y % RES.n_theta_r as usize);
                    x as f32 + 2.0 * row as f32 + 5.0 * plane as f32
                }
                Table::MS => x as f32 + 3.0 * y as f32,
            };
            half(v + c as f32)
        })
    })
}

fn close(a: f32, b: f32, tol: f32) -> bool {
    (a - b).abs() <= tol
}

#[test]
fn axis_locates_nodes_interpolates_and_clamps() {
    // [0, π] on 5 nodes: π/4 apart.
    let a = Axis::new(0.0, 1.0 / PI, 5);
    assert_eq!(a.locate(0.0), (0, 0.0));
    assert_eq!(a.locate(PI / 2.0).0, 2);
    let (i, w) = a.locate(PI / 8.0);
    assert!(i == 0 && close(w, 0.5, 1e-6), "{i} {w}");
    let (i, w) = a.locate(3.0 * PI / 4.0 + PI / 16.0);
    assert!(i == 3 && close(w, 0.25, 1e-5), "{i} {w}");
    // The last node is reached as the upper end of the last interval.
    let (i, w) = a.locate(PI);
    assert!(i == 3 && close(w, 1.0, 1e-6), "{i} {w}");
    // Outside the axis (and NaN): clamped to the ends.
    assert_eq!(a.locate(-1.0), (0, 0.0));
    assert_eq!(a.locate(f32::NEG_INFINITY), (0, 0.0));
    assert_eq!(a.locate(f32::NAN), (0, 0.0));
    assert_eq!(a.locate(10.0), (3, 1.0));
    assert_eq!(a.locate(f32::INFINITY), (3, 1.0));
    // Centred on 0: [−π, π] on 33 nodes, x = 0 on node 16.
    let c = Axis::new(-PI, 1.0 / (2.0 * PI), 33);
    assert_eq!(c.locate(0.0), (16, 0.0));
    let (i, w) = c.locate(-PI);
    assert!(i == 0 && w < 1e-5, "{i} {w}");
    let (i, w) = c.locate(PI);
    assert!(i == 31 && close(w, 1.0, 1e-5), "{i} {w}");
    // Node positions: lo + (i + w)·step recovers x everywhere inside.
    for k in 0..=1000 {
        let x = -PI + 2.0 * PI * k as f32 / 1000.0;
        let (i, w) = c.locate(x);
        assert!(i <= 31 && (0.0..=1.0).contains(&w));
        let back = -PI + (i as f32 + w) * (2.0 * PI / 32.0);
        assert!(close(back, x, 2e-6), "{x}: {i} {w}");
    }
    // Two nodes: a single interval.
    let two = Axis::new(0.0, 1.0 / PI, 2);
    assert_eq!(two.locate(PI / 2.0), (0, 0.5));
}

#[test]
fn lookups_interpolate_every_table_linearly() {
    let b = affine();
    let lut = BakedBcsdf::from_bytes(b).unwrap();
    let r = RES;
    // Under Miri (CI's unsafe-code check, ~10⁴ times slower): both ends and two inside.
    let (thetas, phis) = if cfg!(miri) {
        (
            vec![-PI / 2.0, -0.4, 0.05, PI / 2.0],
            vec![-PI, -0.1, 0.7, PI],
        )
    } else {
        (
            vec![-PI / 2.0, -1.3, -0.4, 0.0, 0.05, 0.9, PI / 2.0],
            vec![-PI, -2.0, -0.1, 0.0, 0.7, 3.0, PI],
        )
    };
    // Colours: the preset's, lossless, fully absorbing, and one channel per plane interval.
    let colours = [
        lut.absorption().sigma(),
        Rgb::ZERO,
        Rgb::splat(1000.0),
        Rgb([0.05, 1.7, 60.0]),
    ];
    for (ci, sigma) in colours.into_iter().enumerate() {
        let colour = lut.locate_colour(sigma);
        let scale = lut.header().absorption_scale();
        let plane_u = sigma
            .0
            .map(|s| lut::absorption_coordinate(s, scale) * (r.n_abs - 1) as f32);
        for &ti in &thetas {
            for &tr in &thetas {
                for &phi in &phis {
                    let l = lut.lookups(&Angles::new(ti, tr, phi).unwrap(), &colour);
                    // The node coordinates of the query on each axis.
                    let sum = (ti + tr + PI) * (r.n_sum - 1) as f32 / (2.0 * PI);
                    let col_n = phi.abs() * (r.n_phi - 1) as f32 / PI;
                    let row_n = tr.abs() * (r.n_theta_r - 1) as f32 / (PI / 2.0);
                    let col_ms = (ti + PI / 2.0) * (r.n_ms_i - 1) as f32 / PI;
                    let row_ms = (tr + PI / 2.0) * (r.n_ms_r - 1) as f32 / PI;
                    let tol = 1e-4 * (r.n_sum + r.n_phi) as f32;
                    for c in 0..3 {
                        assert!(close(l.m[c], sum + c as f32, tol), "M {ti} {tr}: {l:?}");
                    }
                    for c in 0..12 {
                        let (family, rgb) = (c / 3, c % 3);
                        let want = col_n + 2.0 * row_n + 5.0 * plane_u[rgb] + family as f32;
                        assert!(
                            close(l.n[c], want, tol),
                            "N {tr} {phi} colour {ci}: {} vs {want}",
                            l.n[c]
                        );
                    }
                    // The sampler's densities: the lossless plane.
                    for f in 0..4 {
                        let want = col_n + 2.0 * row_n + f as f32;
                        assert!(close(l.n0[f], want, tol), "N0 {tr} {phi}");
                    }
                    for c in 0..2 {
                        let want = col_ms + 3.0 * row_ms + c as f32;
                        assert!(
                            close(l.ms[c], want, tol),
                            "M_s {ti} {tr}: {} vs {want}",
                            l.ms[c]
                        );
                    }
                    assert!(close(l.front, phi.abs() / PI, 1e-6));
                }
            }
        }
    }
}

#[test]
fn colours_are_located_on_the_absorption_axis() {
    let b = affine();
    let lut = BakedBcsdf::from_bytes(b).unwrap();
    let plane = RES.n_plane();
    let scale = lut.header().absorption_scale();
    // Every node is reached exactly: its own weight 1 (to rounding), the others 0.
    for k in 0..RES.n_abs as usize {
        let s = lut::absorption_node(k, RES.n_abs, scale);
        let at = lut.locate_colour(Rgb::splat(s));
        let first = at.plane[0] / plane;
        for (j, &w) in at.weights(0).iter().enumerate() {
            let want = if first + j == k { 1.0 } else { 0.0 };
            assert!(
                (w - want).abs() < 1e-5,
                "node {k} (σ {s}): first plane {first}, weights {:?}",
                at.weights(0)
            );
        }
        assert!((at.weights(0).iter().sum::<f32>() - 1.0).abs() < 1e-6);
    }
    assert_eq!(lut::absorption_node(0, RES.n_abs, scale), 0.0);
    assert_eq!(lut::absorption_node(3, RES.n_abs, scale), lut::SIGMA_CA_MAX);
    // Out of the domain: NaN and negatives at the lossless node, beyond 1000 at the last.
    let at = lut.locate_colour(Rgb([f32::NAN, -3.0, f32::INFINITY]));
    assert_eq!((at.plane[0], at.weights(0)), (0, [1.0, 0.0, 0.0]));
    assert_eq!((at.plane[1], at.weights(1)), (0, [1.0, 0.0, 0.0]));
    assert_eq!((at.plane[2], at.weights(2)), (plane, [0.0, 0.0, 1.0]));
    // The coordinate is monotone and maps [0, 1000] onto [0, 1].
    let mut prev = -1.0;
    for k in 0..=2000 {
        let s = 1000.0 * (k as f32 / 2000.0).powi(4);
        let u = lut::absorption_coordinate(s, scale);
        assert!(u >= prev && (0.0..=1.0).contains(&u), "{s}: {u}");
        prev = u;
    }
    assert_eq!(lut::absorption_coordinate(1000.0, scale), 1.0);
    // The default colour is the preset's, and `at` with it evaluates as the LUT does.
    assert_eq!(
        lut.default_colour(),
        lut.locate_colour(lut.params().sigma_ca())
    );
    let a = Angles::new(0.3, -0.4, 1.1).unwrap();
    assert_eq!(lut.at(&lut.absorption()).eval_far(&a), lut.eval_far(&a));
}

#[test]
fn a_constant_lut_leaves_the_exact_cos2_factor() {
    // Every table 1: each family is 1/cos²θ_i (the blend of two equal halves is 1 too).
    let b = blob(RES, |_, _, _, _| half(1.0));
    let lut = BakedBcsdf::from_bytes(&b).unwrap();
    for deg in [-90.0f32, -89.5, -60.0, -10.0, 0.0, 25.0, 80.0, 90.0] {
        let a = Angles::from_degrees(deg, 33.0, 100.0).unwrap();
        let want = inv_cos2_theta_i(libm::cosf(a.theta_i()));
        let got = lut.eval_far(&a);
        for f in got.as_array() {
            for c in f.0 {
                assert!(close(c, want, 2e-6 * want), "θ_i {deg}: {c} vs {want}");
            }
        }
        assert!(close(got.total().0[0], 4.0 * want, 8e-6 * want));
    }
    // The grazing guard: at the pole 1/cos² is held at 1/MIN_COS2_THETA_I.
    let pole = lut.eval_far(&Angles::new(PI / 2.0, 0.0, 0.0).unwrap());
    assert!(close(pole.total().0[1], 4.0e4, 1.0));
}

#[test]
fn value_reads_texels_and_is_zero_outside() {
    let b = affine();
    let lut = BakedBcsdf::from_bytes(b).unwrap();
    assert_eq!(lut.value(Table::M, 7, 0, 2), 9.0);
    assert_eq!(lut.value(Table::N, 3, 4, 3), 3.0 + 8.0 + 3.0);
    assert_eq!(lut.value(Table::N, 3, 6, 2), 3.0 + 2.0 + 5.0 + 2.0);
    assert_eq!(lut.value(Table::MS, 18, 6, 1), 18.0 + 18.0 + 1.0);
    assert_eq!(lut.value(Table::M, 33, 0, 0), 0.0);
    assert_eq!(lut.value(Table::N, 0, 20, 0), 0.0);
    assert_eq!(lut.value(Table::N, 0, 0, 4), 0.0);
    assert_eq!(lut.value(Table::MS, 0, 0, 2), 0.0);
    assert_eq!(lut.header().res, RES);
    assert_eq!(lut.params().eta_c(), presets::PRESETS[0].input.eta_c);
}

/// A LUT at [`RES`] with pseudo-random halves in [0, 2), one in eight zero.
pub(crate) fn random() -> &'static [u8] {
    random_with(Closure::Report)
}

/// [`random`] in the closure `closure`, built once per test process and shared by every test
/// that reads it (under Miri one build and seal of a LUT costs seconds).
pub(crate) fn random_with(closure: Closure) -> &'static [u8] {
    static LUTS: [OnceLock<Vec<u8>>; 2] = [OnceLock::new(), OnceLock::new()];
    let cell = match closure {
        Closure::Report => &LUTS[0],
        Closure::Energy => &LUTS[1],
    };
    cell.get_or_init(|| random_blob(closure))
}

fn random_blob(closure: Closure) -> Vec<u8> {
    blob_with(RES, closure, |t, x, y, c| {
        let mut z = (t as u64) << 48 ^ (x as u64) << 32 ^ (y as u64) << 16 ^ c as u64;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        let r = (z ^ (z >> 31)) as u32;
        if r.is_multiple_of(8) {
            0
        } else {
            (r % 0x4000) as u16
        }
    })
}

#[test]
fn directions_agree_with_angles_and_reject_like_angles() {
    let b = random();
    let lut = BakedBcsdf::from_bytes(b).unwrap();
    let (wr, tangent) = ([0.3, -1.0, 0.4], [0.0, 0.2, 1.0]);
    let frame = crate::Frame::from_view::<Libm>(wr, tangent).unwrap();
    // Under Miri (CI's unsafe-code check) a fifth of the queries.
    let n = if cfg!(miri) { 40 } else { 200 };
    for k in 0..n {
        let ti = -1.4 + 2.8 * (k as f32 / (n - 1) as f32);
        let phi = wrap_angle(0.37 * k as f32);
        let a = Angles::new(ti, frame.theta_r(), phi).unwrap();
        let wi = frame.to_world(&a);
        let exact = Angles::from_directions::<Libm>(wi, wr, tangent).unwrap();
        let (got, want) = (lut.eval_far_dirs(wi, wr, tangent), lut.eval_far(&exact));
        for (g, w) in got.total().0.iter().zip(want.total().0) {
            // The polynomial angles differ by ~3e-7 rad; the tables are smooth at that scale.
            assert!(close(*g, w, 1e-3 * w.max(1.0)), "{a:?}: {g} vs {w}");
        }
    }
    assert_eq!(lut.eval_far_dirs([0.0; 3], wr, tangent), Families::ZERO);
    assert_eq!(
        lut.try_eval_far_dirs([f32::NAN, 0.0, 0.0], wr, tangent),
        Err(AngleError::NonFinite)
    );
    assert_eq!(
        lut.try_eval_far_dirs(wr, wr, [0.0; 3]),
        Err(AngleError::Degenerate)
    );
}

#[test]
fn energy_closure_divides_m_by_its_mass_on_the_sphere() {
    // Every table 1: the interpolated M_g has mass π over θ_i ∈ [−π/2, π/2] at every θ_r,
    // less (2/3)·s_c in each pole sliver (the weight 1 − s²/s_c² of the 1/cos² guard), so the
    // energy closure's M_g is 1/(π − 4/3·s_c); M^s is left as it is (docs/model.md §12).
    let report = blob(RES, |_, _, _, _| half(1.0));
    let energy = blob_with(RES, Closure::Energy, |_, _, _, _| half(1.0));
    let (report, energy) = (
        BakedBcsdf::from_bytes(&report).unwrap(),
        BakedBcsdf::from_bytes(&energy).unwrap(),
    );
    assert_eq!(energy.params().closure(), Closure::Energy);
    for tr in [-90.0f32, -61.0, -3.0, 0.0, 44.0, 89.0, 90.0] {
        for ti in [-80.0f32, -10.0, 0.0, 35.0, 89.9] {
            let a = Angles::from_degrees(ti, tr, 120.0).unwrap();
            let (r, e) = (report.eval_far(&a), energy.eval_far(&a));
            for f in [LobeFamily::R, LobeFamily::TT, LobeFamily::TRT] {
                let mass = PI - (4.0 / 3.0) * crate::model::POLE_SLIVER;
                let (want, got) = (r.get(f).0[0] / mass, e.get(f).0[0]);
                assert!(
                    close(got, want, 2e-5 * want),
                    "{f:?} {ti} {tr}: {got} vs {want}"
                );
            }
            assert_eq!(e.get(LobeFamily::Scattered), r.get(LobeFamily::Scattered));
        }
    }
}

#[test]
fn batch_equals_the_scalar_path_bit_for_bit() {
    for closure in Closure::ALL {
        batch_equals_the_scalar_path_in(closure);
    }
}

fn batch_equals_the_scalar_path_in(closure: Closure) {
    let b = random_with(closure);
    let lut = BakedBcsdf::from_bytes(b).unwrap();
    // More than three chunks, the last one partial; under Miri (CI's unsafe-code check, ~10⁴
    // times slower) one full chunk and a partial one.
    let n = if cfg!(miri) { 40 } else { 100 };
    let step = 100.0 / n as f32;
    let mut ti: Vec<f32> = (0..n).map(|k| -1.5 + 0.03 * step * k as f32).collect();
    let tr: Vec<f32> = (0..n).map(|k| 1.2 - 0.024 * step * k as f32).collect();
    let mut phi: Vec<f32> = (0..n).map(|k| -7.0 + 0.14 * step * k as f32).collect();
    ti[5] = f32::NAN;
    ti[n * 2 / 5] = 2.0;
    phi[n - 3] = f32::INFINITY;
    phi[n - 2] = 1e30;
    let mut out = vec![Rgb([9.0; 3]); n];
    let rejected = lut.eval_far_batch(&ti, &tr, &phi, &mut out).unwrap();
    assert_eq!(rejected, 3);
    for k in 0..n {
        let want =
            Angles::new(ti[k], tr[k], phi[k]).map_or(Rgb::ZERO, |a| lut.eval_far(&a).total());
        assert_eq!(
            out[k].0.map(f32::to_bits),
            want.0.map(f32::to_bits),
            "query {k}"
        );
    }
    // Every kernel this CPU has gives the same bits.
    let base = lut.with_kernel(Kernel::Baseline).unwrap();
    let mut again = vec![Rgb::ZERO; n];
    base.eval_far_batch(&ti, &tr, &phi, &mut again).unwrap();
    assert_eq!(again, out);
    let a = Angles::new(0.3, -0.2, 1.0).unwrap();
    assert_eq!(base.eval_far(&a), lut.eval_far(&a));
    assert_eq!(base.kernel(), Kernel::Baseline);
    // A colour per query: each equal to `at(colour)`, bit for bit, with every kernel.
    let mut rng = crate::rng::Pcg32::new(5, 9);
    let colours: Vec<Absorption> = (0..n)
        .map(|_| {
            let s = [0; 3].map(|_| 1000.0 * rng.uniform().powi(6));
            Absorption::from_sigma(Rgb(s)).unwrap()
        })
        .collect();
    let mut coloured = vec![Rgb::ZERO; n];
    lut.eval_far_batch_colours(&ti, &tr, &phi, &colours, &mut coloured)
        .unwrap();
    let mut coloured_base = vec![Rgb::ZERO; n];
    base.eval_far_batch_colours(&ti, &tr, &phi, &colours, &mut coloured_base)
        .unwrap();
    assert_eq!(coloured, coloured_base);
    let mut differs = 0;
    for k in 0..n {
        let want = match Angles::new(ti[k], tr[k], phi[k]) {
            Ok(a) => lut.at(&colours[k]).eval_far(&a).total(),
            Err(_) => Rgb::ZERO,
        };
        assert_eq!(coloured[k], want, "query {k}");
        differs += usize::from(coloured[k] != out[k]);
    }
    assert!(
        differs > n / 2,
        "the colours change the values ({differs} of {n})"
    );
    let e = lut
        .eval_far_batch_colours(&ti, &tr, &phi, &colours[1..], &mut coloured)
        .unwrap_err();
    assert_eq!(e.colours, Some(n - 1));
    assert!(std::format!("{e}").contains("colours"));
}

#[test]
fn batch_rejects_slices_of_different_lengths() {
    let b = random();
    let lut = BakedBcsdf::from_bytes(b).unwrap();
    let mut out = [Rgb([5.0; 3]); 2];
    let e = lut
        .eval_far_batch(&[0.0; 2], &[0.0; 3], &[0.0; 2], &mut out)
        .unwrap_err();
    assert_eq!(
        e,
        BatchLengthError {
            inputs: [2, 3, 2],
            output: 2,
            colours: None,
        }
    );
    assert_eq!(out, [Rgb([5.0; 3]); 2], "nothing written");
    let text = std::format!("{e}");
    assert!(
        text.contains("theta_r 3") && text.contains("output 2"),
        "{text}"
    );
    let _: &dyn core::error::Error = &e;
    assert_eq!(lut.eval_far_batch(&[], &[], &[], &mut []), Ok(0));
}

#[test]
fn from_bytes_rejects_damaged_blobs() {
    let good = random().to_vec();
    assert!(BakedBcsdf::from_bytes(&good).is_ok());
    assert_eq!(
        BakedBcsdf::from_bytes(&good[..100]).unwrap_err(),
        LutError::TooShort { len: 100 }
    );
    let mut magic = good.clone();
    magic[0] = b'X';
    assert_eq!(
        BakedBcsdf::from_bytes(&magic).unwrap_err(),
        LutError::BadMagic
    );
    let mut long = good.clone();
    long.push(0);
    assert!(matches!(
        BakedBcsdf::from_bytes(&long),
        Err(LutError::Length { .. })
    ));
    // A changed table byte fails the checksum.
    let mut flipped = good.clone();
    flipped[HEADER_LEN + 10] ^= 1;
    assert!(matches!(
        BakedBcsdf::from_bytes(&flipped),
        Err(LutError::Checksum { .. })
    ));
    // A negative half is caught even when the checksum is made to match.
    let mut negative = good;
    negative[HEADER_LEN + 1] |= 0x80;
    lut::seal(&mut negative);
    assert!(matches!(
        BakedBcsdf::from_bytes(&negative),
        Err(LutError::Value {
            table: Table::M,
            index: 0,
            ..
        })
    ));
}
