//! The `.furdual` blob and its evaluator: round trip, refusals, and the term recomputed in
//! f64 from the decoded node values.

use super::*;

#[test]
fn the_blob_round_trips_to_half_precision() {
    let t = absorbing_tables();
    let blob = encode(&t, Attenuation::Coat, 0xfeed);
    assert_eq!(blob.len(), BLOB_LEN);
    let mut lut = Box::new(DualLut::EMPTY);
    lut.decode(&blob).unwrap();
    assert_eq!(
        (lut.attenuation(), lut.source()),
        (Attenuation::Coat, 0xfeed)
    );
    // Encoding what was decoded gives the same bytes (f16 values are exact in f32).
    for k in [0usize, 17, 63] {
        let f = &t.fiber[k];
        for c in 0..3 {
            let mu = coat_decay(Attenuation::Coat, f.a_f[c], f.a_b[c]);
            let got = libm::exp2f(lut.nodes[c][k][blob::LOG2_DECAY]);
            assert!((got - mu).abs() < 1e-3 * mu, "μ {got} vs {mu}");
            let (back, front) =
                local_backscatter(Attenuation::Coat, f.big_a_b[c], f.a_f[c], f.a_b[c]);
            assert!((lut.nodes[c][k][blob::BACK] - back).abs() <= 5e-4 * back);
            assert!((lut.nodes[c][k][blob::FRONT] - front).abs() <= 5e-4 * front);
        }
        let ng = t.n_g[0][k][5][1];
        assert!((lut.n_g[1][0][k][5] - ng).abs() <= 5e-4 * ng);
        // Nodes 3 and up repeat channel 2.
        assert_eq!(lut.n_g[ABS_NODES - 1][0][k][5], lut.n_g[2][0][k][5]);
    }
    // Forward stores μ = ā_f.
    let fwd = lut_of(&t, Attenuation::Forward);
    assert!((libm::exp2f(fwd.nodes[0][3][blob::LOG2_DECAY]) - 0.6).abs() < 1e-3);
}

#[test]
fn a_damaged_blob_is_refused_and_leaves_the_evaluator_alone() {
    let good = encode(&absorbing_tables(), Attenuation::Coat, 1);
    let mut lut = Box::new(DualLut::EMPTY);
    lut.decode(&good).unwrap();
    let before = lut.clone();
    let reseal = |b: &mut [u8]| {
        let sum = blob::checksum_of(b);
        b[56..64].copy_from_slice(&sum.to_le_bytes());
    };
    let mut cases: std::vec::Vec<(std::vec::Vec<u8>, DualError)> = std::vec::Vec::new();
    cases.push((good[..100].to_vec(), DualError::Length(100)));
    let mut b = good.to_vec();
    b.push(0);
    cases.push((b, DualError::Length(BLOB_LEN + 1)));
    let mut b = good.to_vec();
    b[0] = b'X';
    cases.push((b, DualError::Magic));
    let mut b = good.to_vec();
    b[8] = 9;
    cases.push((b, DualError::FormatVersion(9)));
    let mut b = good.to_vec();
    b[12] = 99;
    cases.push((b, DualError::ModelVersion(99)));
    let mut b = good.to_vec();
    b[16] = 65;
    cases.push((b, DualError::Layout));
    let mut b = good.to_vec();
    b[50] = 1;
    cases.push((b, DualError::Layout));
    let mut b = good.to_vec();
    b[36] = 17; // n_abs
    cases.push((b, DualError::Layout));
    let mut b = good.to_vec();
    b[77] = 1;
    cases.push((b, DualError::Layout));
    let mut b = good.to_vec();
    b[32] = 3;
    cases.push((b, DualError::Attenuation(3)));
    // Sealed but a hostile preset colour: NaN, negative, above the axis.
    for v in [f32::NAN, -1.0, 1000.5] {
        let mut b = good.to_vec();
        b[68..72].copy_from_slice(&v.to_le_bytes());
        reseal(&mut b);
        cases.push((b, DualError::Colour));
    }
    let mut b = good.to_vec();
    b[1000] ^= 1;
    cases.push((b, DualError::Checksum));
    // Sealed but hostile values: a NaN, an infinity, a negative width, ā_f² above 1, a
    // positive log₂ μ, a negative N^G.
    // Channel c is absorption node c ([`encode`]); a node is its fields, then its N^G.
    let node = THETA_NODES * FIELDS + FAMILY_COUNT * THETA_NODES * PHI_NODES;
    let field = |k: usize, f: usize, c: usize| c * node + k * FIELDS + f;
    let ng0 = (ABS_NODES - 1) * node + THETA_NODES * FIELDS;
    for (i, bits) in [
        (field(4, blob::MEAN, 1), 0x7e00u16),
        (field(4, blob::DELTA_B, 0), 0x7c00),
        (field(9, blob::SD + 2, 2), 0xbc00),
        (field(9, blob::A_F2, 0), 0x3c01),
        (field(0, blob::LOG2_DECAY, 0), 0x3c00),
        (ng0 + 77, 0x8001),
    ] {
        let mut b = good.to_vec();
        b[80 + 2 * i..82 + 2 * i].copy_from_slice(&bits.to_le_bytes());
        reseal(&mut b);
        cases.push((b, DualError::Value(i)));
    }
    for (bytes, want) in cases {
        assert_eq!(lut.decode(&bytes), Err(want));
        assert_eq!(lut, before, "{want:?} changed the evaluator");
        assert!(!std::format!("{want}").is_empty());
    }
}

#[test]
fn check_lut_pairs_a_blob_with_the_lut_it_records_and_no_other() {
    use crate::baked::{tests as luts, BakedBcsdf};
    use std::string::ToString;
    let bytes = luts::random();
    let lut = BakedBcsdf::from_bytes(bytes).unwrap();
    // The header's checksum is the bytes' (from_bytes checked it; read, not recomputed).
    assert_eq!(lut.checksum(), crate::lut::checksum(bytes));
    let other_bytes = luts::random_with(Closure::Energy);
    let other = BakedBcsdf::from_bytes(other_bytes).unwrap();
    assert_ne!(other.checksum(), lut.checksum());

    let t = absorbing_tables();
    let decoded = |source: u64| {
        let mut d = Box::new(DualLut::EMPTY);
        d.decode(&encode(&t, Attenuation::Coat, source)).unwrap();
        d
    };
    let paired = decoded(lut.checksum());
    assert_eq!(paired.check_lut(&lut), Ok(()));
    let e = paired.check_lut(&other).unwrap_err();
    assert_eq!(
        e,
        DualError::Source {
            recorded: lut.checksum(),
            lut: other.checksum()
        }
    );
    assert!(e.to_string().contains("not from this LUT"), "{e}");
    // A blob that records no source (0) pairs with no LUT.
    let e = decoded(0).check_lut(&lut).unwrap_err();
    assert_eq!(
        e,
        DualError::Source {
            recorded: 0,
            lut: lut.checksum()
        }
    );
    assert!(e.to_string().contains("records no source"), "{e}");
}

#[test]
fn the_evaluator_is_allocation_free_and_matches_the_stored_formula() {
    // The term recomputed from the decoded node values in f64, independent of the lane
    // code: Gaussians normalised over the reachable x by f64 erf, and the finite coat by the
    // adding recursion of layers (t, r), r recovered from μ + 1/μ = (1 + t² − r²)/t. Back
    // half, n = 3 above (and n = 0), m = 2 below, default density. The evaluator
    // interpolates the coat's ρ² between θ nodes where this recovers the layer from
    // interpolated fields: at these angles the two differ by 2e-7 (relative), far inside
    // the bound.
    let t = absorbing_tables();
    let lut = lut_of(&t, Attenuation::Coat);
    let (ti, tr, phi, n, m) = (0.31f32, -0.22f32, 0.7f32, 3u32, 2u32);
    let fibers = Fibers::new(n as f32, m as f32);
    let angles = Angles::new(ti, tr, phi).unwrap();
    let got = lut.eval(&angles, fibers, Density::DEFAULT);
    let direct = lut.eval(&angles, Fibers::new(0.0, m as f32), Density::DEFAULT);
    let pi = std::f64::consts::PI;
    let g = |d: f64, v: f64| (-d * d / (2.0 * v)).exp() / (2.0 * pi * v).sqrt();
    // g divided by its mass over x ∈ [θ_r − π/2, θ_r + π/2].
    let g_hat = |d: f64, v: f64| {
        let v = v.max(f64::from(MIN_VARIANCE));
        let mean = f64::from(ti + tr) - d;
        let z = |x: f64| (x - mean) / (2.0 * v).sqrt();
        let mass =
            0.5 * (libm::erf(z(f64::from(tr) + pi / 2.0)) - libm::erf(z(f64::from(tr) - pi / 2.0)));
        g(d, v) / mass.max(0.05)
    };
    let lerp_at = |theta: f32, f: usize, c: usize| {
        let (k, w) = theta_position(theta);
        f64::from(lut.nodes[c][k][f]) * f64::from(1.0 - w)
            + f64::from(lut.nodes[c][k + 1][f]) * f64::from(w)
    };
    // (R_k, T_k) of k layers by the adding recursion.
    let stack = |t: f64, r: f64, k: u32| {
        let (mut rk, mut tk) = (0.0f64, 1.0f64);
        for _ in 0..k {
            let den = 1.0 - rk * r;
            (rk, tk) = (rk + tk * tk * r / den, tk * t / den);
        }
        (rk, tk)
    };
    let layer = |theta: f32, c: usize| {
        let mu = lerp_at(theta, blob::LOG2_DECAY, c).exp2();
        let t = lerp_at(theta, blob::A_F2, c).sqrt();
        let r = (1.0 + t * t - t * (mu + 1.0 / mu)).max(0.0).sqrt();
        (t, r)
    };
    for c in 0..3 {
        let x = f64::from(ti + tr);
        let inv = 1.0 / f64::from(ti).cos().powi(2);
        // Light reaching the point: n layers above, and below it over a black floor the
        // neighbourhood's coat, one layer more than the line's count m
        // (`coat::coat_below_layers`).
        let m = m + 1;
        let (t_a, r_a) = layer(-ti, c);
        let (r_n, t_n) = stack(t_a, r_a, n);
        let (r_m, _) = stack(t_a, r_a, m);
        let d_flux = t_n / (1.0 - r_n * r_m);
        // The local backscatter's energy: the stored one is the deep stack's light through
        // one more layer, U_∞ = R_∞t/(1 − rR_∞); the point gets the m layers' R_m.
        let (t_h, r_h) = layer(tr, c);
        let up = |rr: f64| rr * t_h / (1.0 - r_h * rr);
        let factor = stack(t_h, r_h, m).0 / up(stack(t_h, r_h, 20_000).0);
        let s2 = f64::from(n) * lerp_at(-ti, blob::BETA_F, c).powi(2);
        let (d_f, d_b) = (
            f64::from(Density::DEFAULT.d_f),
            f64::from(Density::DEFAULT.d_b),
        );
        let sb = (1.0 + d_b * lerp_at(tr, blob::A_F2, c)) * lerp_at(tr, blob::SIGMA_B0, c);
        let back = d_b * lerp_at(tr, blob::BACK, c) * factor;
        let db = x - lerp_at(tr, blob::DELTA_B, c);
        let mut fs = 0.0;
        for fam in 0..FAMILY_COUNT {
            let (k, w) = theta_position(tr);
            let p = f64::from(phi) * (PHI_NODES - 1) as f64 / pi;
            let (j, v) = (p as usize, p - p.floor());
            let tab = &lut.n_g[c][fam];
            let at = |kk: usize, jj: usize| f64::from(tab[kk][jj]);
            let ng = (at(k, j) * (1.0 - v) + at(k, j + 1) * v) * f64::from(1.0 - w)
                + (at(k + 1, j) * (1.0 - v) + at(k + 1, j + 1) * v) * f64::from(w);
            let mean = lerp_at(tr, blob::MEAN + fam, c);
            let sd = lerp_at(tr, blob::SD + fam, c);
            fs += ng * g_hat(x - mean, sd * sd + s2);
        }
        let want = d_f * d_flux * (fs * inv + back * g_hat(db, sb * sb + s2) * inv / pi);
        let err = (f64::from(got[c]) - want).abs() / want;
        assert!(err < 1e-4, "channel {c}: {} vs {want} ({err:e})", got[c]);
        // Unoccluded (n = 0): the local backscatter alone, its k_m for the m layers below.
        let want = back * g_hat(db, sb * sb) * inv / pi;
        let err = (f64::from(direct[c]) - want).abs() / want;
        assert!(
            err < 1e-4,
            "n = 0, channel {c}: {} vs {want} ({err:e})",
            direct[c]
        );
    }
}

#[test]
fn value_checks_on_the_bits_are_the_float_comparisons() {
    use crate::dual::half_range::HalfRange;
    // Every one of the 65 536 halves, against the comparison on its value.
    for h in 0..=u16::MAX {
        let v = half::f16::from_bits(h).to_f32();
        let cases = [
            (HalfRange::Finite, v.is_finite()),
            (HalfRange::NonNegative, v.is_finite() && v >= 0.0),
            (HalfRange::NonPositive, v.is_finite() && v <= 0.0),
            (HalfRange::Unit, v.is_finite() && (0.0..=1.0).contains(&v)),
        ];
        for (i, (range, want)) in cases.into_iter().enumerate() {
            assert_eq!(range.holds(h), want, "range {i}, bits {h:#06x} ({v})");
        }
    }
}
