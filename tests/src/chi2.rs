//! A χ² goodness-of-fit test of a direction sampler against its claimed density, in the
//! manner of Mitsuba's: bin the sampled directions over the sphere of ω_i, integrate the
//! density over every bin for the expected counts, pool the bins expecting fewer than
//! [`MIN_EXPECTED`] samples, and compare with the χ² distribution.
//!
//! The bins are uniform in θ_i ∈ [−π/2, π/2] and φ ∈ (−π, π]; the expected count of a bin
//! is N·∫∫ p_ω(θ_i, φ)·cos θ_i dθ_i dφ (dω = cos θ dθ dφ), integrated with a tensor
//! Gauss–Legendre rule in each bin. Nothing here knows how the density is built: it only
//! calls the two closures it is given.
//!
//! The statistic is computed twice from the same counts: on the fine bins (sensitive to
//! errors in narrow structure) and on coarse bins that merge [`COARSE`] × [`COARSE`] fine
//! ones (sensitive to smooth errors: with 10⁶ samples the fine statistic's own spread,
//! √(2·dof) ≈ 130, hides a 2 % tilt, which adds only ~N·(0.02)²/3 ≈ 130 to it; on 128 coarse
//! bins the spread is 16). A sampler fails when either rejects.

use rayon::prelude::*;
use statrs::distribution::{ChiSquared, ContinuousCDF};

/// Bins expecting fewer samples than this are pooled into one.
pub const MIN_EXPECTED: f64 = 5.0;

/// Fine bins per coarse bin along each axis.
pub const COARSE: usize = 8;

/// Bin layout and sample count of one test.
#[derive(Clone, Copy, Debug)]
pub struct Chi2Setup {
    /// Bins over θ_i ∈ [−π/2, π/2].
    pub n_theta: usize,
    /// Bins over φ ∈ (−π, π].
    pub n_phi: usize,
    /// Gauss–Legendre nodes per bin and axis.
    pub nodes: usize,
    /// Samples drawn.
    pub samples: usize,
}

impl Chi2Setup {
    /// 64 θ × 128 φ bins, 4 × 4 nodes per bin, 10⁶ samples.
    pub const DEFAULT: Chi2Setup = Chi2Setup {
        n_theta: 64,
        n_phi: 128,
        nodes: 4,
        samples: 1_000_000,
    };
}

/// One χ² statistic.
#[derive(Clone, Copy, Debug)]
pub struct Statistic {
    /// The χ² statistic.
    pub value: f64,
    /// Degrees of freedom (bins after pooling − 1).
    pub dof: usize,
    /// P(χ²_dof ≥ value).
    pub p_value: f64,
}

/// The outcome of one test.
#[derive(Clone, Debug)]
pub struct Chi2Outcome {
    /// On the fine bins.
    pub fine: Statistic,
    /// On the coarse bins ([`COARSE`]² fine bins each).
    pub coarse: Statistic,
    /// Samples that fell in a bin whose expected count is 0 (a sampler producing directions
    /// its density says are impossible).
    pub impossible: u64,
    /// Samples the sampler failed to produce (None).
    pub failed: u64,
    /// Σ of the expected counts / N: the density's integral over the sphere.
    pub integral: f64,
}

impl Chi2Outcome {
    /// True when the test rejects the sampler at significance `alpha` (per statistic; the
    /// caller's Šidák correction counts two statistics per test).
    pub fn rejects(&self, alpha: f64) -> bool {
        self.impossible > 0 || self.fine.p_value < alpha || self.coarse.p_value < alpha
    }
}

/// Šidák-corrected per-test significance for `tests` tests at overall significance
/// `alpha`: 1 − (1 − α)^{1/tests}.
pub fn sidak(alpha: f64, tests: usize) -> f64 {
    1.0 - (1.0 - alpha).powf(1.0 / tests as f64)
}

/// Gauss–Legendre nodes and weights on [−1, 1] (Newton on the Legendre recurrence).
pub fn gauss_legendre(n: usize) -> Vec<(f64, f64)> {
    (0..n)
        .map(|i| {
            let mut x = (std::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
            let mut dp = 1.0;
            for _ in 0..100 {
                let (mut p0, mut p1) = (1.0, x);
                for k in 2..=n {
                    let p2 = ((2 * k - 1) as f64 * x * p1 - (k - 1) as f64 * p0) / k as f64;
                    p0 = p1;
                    p1 = p2;
                }
                let pn = if n == 0 { 1.0 } else { p1 };
                dp = n as f64 * (x * pn - p0) / (x * x - 1.0);
                let dx = pn / dp;
                x -= dx;
                if dx.abs() < 1e-15 {
                    break;
                }
            }
            (x, 2.0 / ((1.0 - x * x) * dp * dp))
        })
        .collect()
}

/// Runs the test. `sample(i)` returns the i-th sampled (θ_i, φ) in radians (or `None` for
/// a failed draw); it must be a pure function of i so that the outcome does not depend on
/// the thread count. `pdf(θ_i, φ)` is the claimed density per unit solid angle.
pub fn chi2_test(
    setup: Chi2Setup,
    sample: impl Fn(usize) -> Option<(f32, f32)> + Sync,
    pdf: impl Fn(f32, f32) -> f64 + Sync,
) -> Chi2Outcome {
    use std::f64::consts::PI;
    let (nt, np) = (setup.n_theta, setup.n_phi);
    let (dt, dp) = (PI / nt as f64, 2.0 * PI / np as f64);
    let bin_of = |theta: f32, phi: f32| -> usize {
        let t = (((theta as f64 + PI / 2.0) / dt) as usize).min(nt - 1);
        let p = (((phi as f64 + PI) / dp) as usize).min(np - 1);
        t * np + p
    };

    // Observed counts, in fixed chunks so that the sum is the same for any thread count.
    const CHUNK: usize = 1 << 14;
    let chunks = setup.samples.div_ceil(CHUNK);
    let (observed, failed) = (0..chunks)
        .into_par_iter()
        .map(|c| {
            let mut counts = vec![0u64; nt * np];
            let mut failed = 0u64;
            for i in c * CHUNK..((c + 1) * CHUNK).min(setup.samples) {
                match sample(i) {
                    Some((t, p)) => counts[bin_of(t, p)] += 1,
                    None => failed += 1,
                }
            }
            (counts, failed)
        })
        .reduce(
            || (vec![0u64; nt * np], 0),
            |(mut a, fa), (b, fb)| {
                for (x, y) in a.iter_mut().zip(b) {
                    *x += y;
                }
                (a, fa + fb)
            },
        );

    // Expected counts: N ∫∫ p cos θ dθ dφ per bin.
    let gl = gauss_legendre(setup.nodes);
    let expected: Vec<f64> = (0..nt * np)
        .into_par_iter()
        .map(|b| {
            let (t, p) = (b / np, b % np);
            let (t0, p0) = (-PI / 2.0 + t as f64 * dt, -PI + p as f64 * dp);
            let mut sum = 0.0;
            for &(xt, wt) in &gl {
                let theta = t0 + 0.5 * dt * (xt + 1.0);
                let c = theta.cos();
                for &(xp, wp) in &gl {
                    let phi = p0 + 0.5 * dp * (xp + 1.0);
                    sum += wt * wp * pdf(theta as f32, phi as f32) * c;
                }
            }
            sum * 0.25 * dt * dp * setup.samples as f64
        })
        .collect();

    let impossible = observed
        .iter()
        .zip(&expected)
        .filter(|(_, &e)| e <= 0.0)
        .map(|(&o, _)| o)
        .sum();
    let fine = statistic(
        observed
            .iter()
            .map(|&o| o as f64)
            .zip(expected.iter().copied()),
    );
    let (ct, cp) = (nt.div_ceil(COARSE), np.div_ceil(COARSE));
    let mut coarse = vec![(0.0, 0.0); ct * cp];
    for (b, (&o, &e)) in observed.iter().zip(&expected).enumerate() {
        let (t, p) = (b / np, b % np);
        let c = &mut coarse[(t / COARSE) * cp + p / COARSE];
        c.0 += o as f64;
        c.1 += e;
    }
    Chi2Outcome {
        fine,
        coarse: statistic(coarse.into_iter()),
        impossible,
        failed,
        integral: expected.iter().sum::<f64>() / setup.samples as f64,
    }
}

/// χ² of (observed, expected) bins, pooling those expecting fewer than [`MIN_EXPECTED`]
/// (Mitsuba's rule: all of them into one bin); bins expecting 0 are left out (their samples
/// are counted as impossible by the caller).
fn statistic(bins: impl Iterator<Item = (f64, f64)>) -> Statistic {
    let (mut value, mut n) = (0.0, 0usize);
    let (mut pool_o, mut pool_e) = (0.0, 0.0);
    for (o, e) in bins {
        if e <= 0.0 {
            continue;
        }
        if e < MIN_EXPECTED {
            pool_o += o;
            pool_e += e;
            continue;
        }
        value += (o - e).powi(2) / e;
        n += 1;
    }
    if pool_e > 0.0 {
        value += (pool_o - pool_e).powi(2) / pool_e;
        n += 1;
    }
    let dof = n.saturating_sub(1).max(1);
    let p_value = ChiSquared::new(dof as f64)
        .map(|d| 1.0 - d.cdf(value))
        .unwrap_or(0.0);
    Statistic {
        value,
        dof,
        p_value,
    }
}
