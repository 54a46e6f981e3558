//! `BakedBcsdf::eval_far_batch` (and the scalar path of every kernel) against the scalar
//! path of the baseline kernel, bit for bit: for every query,
//! `eval_far(&Angles::new(θ_i, θ_r, φ)?).total()`, or zero where `Angles::new` rejects the
//! angles. 10⁵ queries per LUT, in batches of irregular sizes (so that every chunk boundary
//! and remainder is crossed), mixing random angles with NaN, ±∞, φ far outside (−π, π],
//! θ just beyond ±π/2, ±0, subnormals and the axis ends. Every kernel this CPU has
//! (SSE2, and AVX2 + F16C where present) is checked.

use bake::profiles::{build_model, scale_budget, ProfileOptions};
use bake::tables;
use bcsdf_core::baked::{BakedBcsdf, BatchLengthError, Kernel};
use bcsdf_core::lut::LutResolution;
use bcsdf_core::medulla::PhotonBudget;
use bcsdf_core::{presets, Angles, FurParams, Rgb};
use std::f32::consts::{FRAC_PI_2, PI};

/// A preset's LUT at the default resolution (small photon budget: the values need not be
/// converged, only realistic; profiles and residual tables cached in the target folder, as
/// the other tests of this crate cache theirs).
fn lut_blob(preset: &str) -> Vec<u8> {
    let input = presets::find(preset).unwrap().input;
    let opts = ProfileOptions {
        budget: scale_budget(PhotonBudget::DEFAULT, 0.01).unwrap(),
        cache_dir: Some(
            std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("fur-profile-cache"),
        ),
        ..ProfileOptions::default()
    };
    let (model, _) = build_model(FurParams::new(&input).unwrap(), &opts).unwrap();
    tables::bake(&model, &input, LutResolution::DEFAULT)
}

/// A small deterministic generator (SplitMix64).
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }
    fn unit(&mut self) -> f32 {
        (self.next() >> 40) as f32 / (1u64 << 24) as f32
    }
    fn range(&mut self, lo: f32, hi: f32) -> f32 {
        lo + (hi - lo) * self.unit()
    }
}

/// One angle: mostly in range, sometimes a special value.
fn angle(rng: &mut Rng, half_range: f32) -> f32 {
    const SPECIAL: [f32; 14] = [
        f32::NAN,
        f32::INFINITY,
        f32::NEG_INFINITY,
        0.0,
        -0.0,
        f32::MIN_POSITIVE / 4.0,
        FRAC_PI_2,
        -FRAC_PI_2,
        PI,
        -PI,
        f32::MAX,
        -f32::MAX,
        1e-30,
        -1e-30,
    ];
    match rng.next() % 16 {
        0 => SPECIAL[(rng.next() % SPECIAL.len() as u64) as usize],
        // Just beyond the domain: θ slightly past ±π/2, φ several turns away.
        1 => rng.range(-1.0, 1.0) * half_range * if half_range < 2.0 { 1.001 } else { 20.0 },
        _ => rng.range(-half_range, half_range),
    }
}

#[test]
fn batch_equals_scalar_bit_for_bit() {
    use rayon::prelude::*;
    let presets = ["bobcat", "air-medulla", "human-hair"];
    // The three bakes side by side, then each preset's checks.
    let blobs: Vec<Vec<u8>> = presets.par_iter().map(|p| lut_blob(p)).collect();
    for (preset, blob) in presets.into_iter().zip(blobs) {
        // The reference: the scalar path on the baseline kernel.
        let scalar_lut = BakedBcsdf::from_bytes(&blob)
            .unwrap()
            .with_kernel(Kernel::Baseline)
            .unwrap();
        let mut kernels = vec![Kernel::Baseline];
        if Kernel::best() != Kernel::Baseline {
            kernels.push(Kernel::best());
        }
        for kernel in kernels {
            let lut = scalar_lut.with_kernel(kernel).unwrap();
            check(preset, &scalar_lut, &lut);
        }
    }
}

/// The batch and the scalar path of `lut` against the scalar path of `scalar_lut` on 10⁵
/// queries.
fn check(preset: &str, scalar_lut: &BakedBcsdf, lut: &BakedBcsdf) {
    let kernel = lut.kernel();
    let mut rng = Rng(0x5eed ^ preset.len() as u64);
    let n = 100_000;
    let ti: Vec<f32> = (0..n).map(|_| angle(&mut rng, FRAC_PI_2)).collect();
    let tr: Vec<f32> = (0..n).map(|_| angle(&mut rng, FRAC_PI_2)).collect();
    let ph: Vec<f32> = (0..n).map(|_| angle(&mut rng, PI)).collect();
    let mut out = vec![Rgb::splat(-1.0); n];

    // Irregular batch sizes: 1, 31, 32, 33, 64, 257 … and whatever remains.
    const SIZES: [usize; 9] = [1, 31, 32, 33, 64, 257, 1000, 7, 4096];
    let (mut start, mut s, mut rejected) = (0, 0, 0);
    while start < n {
        let end = (start + SIZES[s % SIZES.len()]).min(n);
        rejected += lut
            .eval_far_batch(
                &ti[start..end],
                &tr[start..end],
                &ph[start..end],
                &mut out[start..end],
            )
            .unwrap();
        start = end;
        s += 1;
    }

    let mut expected_rejected = 0;
    for k in 0..n {
        let scalar = match Angles::new(ti[k], tr[k], ph[k]) {
            Ok(a) => scalar_lut.eval_far(&a).total(),
            Err(_) => {
                expected_rejected += 1;
                Rgb::ZERO
            }
        };
        if let Ok(a) = Angles::new(ti[k], tr[k], ph[k]) {
            let own = lut.eval_far(&a).total();
            assert_eq!(
                own.0.map(f32::to_bits),
                scalar.0.map(f32::to_bits),
                "{preset}, {kernel:?}: scalar path, query {k}"
            );
        }
        assert_eq!(
            out[k].0.map(f32::to_bits),
            scalar.0.map(f32::to_bits),
            "{preset}, {kernel:?}: query {k} (θ_i {}, θ_r {}, φ {}): batch {:?}, scalar {:?}",
            ti[k],
            tr[k],
            ph[k],
            out[k],
            scalar
        );
    }
    assert_eq!(
        rejected, expected_rejected,
        "{preset}, {kernel:?}: rejected count"
    );
    // The mix exercises both outcomes substantially.
    assert!(
        expected_rejected > n / 50 && expected_rejected < n / 5,
        "{expected_rejected}"
    );
}

#[test]
fn mismatched_lengths_are_refused_without_writing() {
    let blob = lut_blob("human-hair");
    let lut = BakedBcsdf::from_bytes(&blob).unwrap();
    let a = [0.1f32; 4];
    let mut out = [Rgb::splat(7.0); 4];
    let err = lut.eval_far_batch(&a, &a[..3], &a, &mut out).unwrap_err();
    assert_eq!(
        err,
        BatchLengthError {
            inputs: [4, 3, 4],
            output: 4,
            colours: None,
        }
    );
    assert!(err.to_string().contains("theta_r 3"), "{err}");
    assert_eq!(out, [Rgb::splat(7.0); 4]);
    // An empty batch is fine.
    assert_eq!(lut.eval_far_batch(&[], &[], &[], &mut []), Ok(0));
}
