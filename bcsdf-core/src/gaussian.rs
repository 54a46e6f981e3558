//! The normalised Gaussian G(x; β) = exp(−x²/2β²)/(√(2π)·β) (report eq. 3) and its wrapped
//! version on the circle, the shapes of M_p and D_p (docs/model.md §5).

use crate::math::{Math, PI, TAU};

/// 1/√(2π).
const INV_SQRT_TAU: f32 = 0.398_942_3;

/// Beyond this many standard deviations a Gaussian term is dropped (e^{−0.5·6.2²} ≈ 4.5e-9
/// of the peak).
pub const CUTOFF_SIGMAS: f32 = 6.2;

/// ∫ₐᵇ of the standard Gaussian shape e^{−z²} in units of √π/2, i.e. (erf b − erf a), computed
/// on the tail side that keeps its precision (erfc when both ends are on one side).
pub(crate) fn erf_mass(a: f64, b: f64) -> f64 {
    if a >= 0.0 {
        libm::erfc(a) - libm::erfc(b)
    } else if b <= 0.0 {
        libm::erfc(-b) - libm::erfc(-a)
    } else {
        libm::erf(b) - libm::erf(a)
    }
}

/// Mass of the normalised Gaussian G(x; β) (docs/model.md §5) over [lo, hi] (0 for an empty
/// interval or a β that is not positive, NaN included: hence the negated comparisons).
#[must_use]
#[allow(clippy::neg_cmp_op_on_partial_ord)]
pub fn gaussian_mass(beta: f32, lo: f32, hi: f32) -> f32 {
    if !(hi > lo) || !(beta > 0.0) {
        return 0.0;
    }
    let k = 1.0 / (core::f64::consts::SQRT_2 * f64::from(beta));
    (0.5 * erf_mass(f64::from(lo) * k, f64::from(hi) * k)) as f32
}

/// A normalised Gaussian of standard deviation β.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Gaussian {
    beta: f32,
    norm: f32,
    inv_two_beta2: f32,
}

impl Gaussian {
    /// G(·; β); β > 0 is guaranteed by parameter validation.
    #[must_use]
    pub fn new(beta: f32) -> Gaussian {
        Gaussian {
            beta,
            norm: INV_SQRT_TAU / beta,
            inv_two_beta2: 0.5 / (beta * beta),
        }
    }

    /// Standard deviation β.
    #[must_use]
    pub fn beta(&self) -> f32 {
        self.beta
    }

    /// G(x; β); exactly zero beyond [`CUTOFF_SIGMAS`]·β.
    #[inline]
    #[must_use]
    pub fn eval<M: Math>(&self, x: f32) -> f32 {
        let e = x * x * self.inv_two_beta2;
        if e > 0.5 * CUTOFF_SIGMAS * CUTOFF_SIGMAS {
            0.0
        } else {
            self.norm * M::exp_neg(e)
        }
    }
}

/// The Gaussian G(·; β) wrapped onto the circle: D(x) = Σ_k G(x + 2πk; β), summed over every
/// period within [`CUTOFF_SIGMAS`]·β, so the truncation error is below 1e-6 (docs/model.md §5).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WrappedGaussian {
    gaussian: Gaussian,
    periods: i32,
}

impl WrappedGaussian {
    /// D(·; β).
    #[must_use]
    pub fn new(beta: f32) -> WrappedGaussian {
        // After wrapping x to (−π, π], term k is at least 2π|k| − π away from 0.
        let reach = CUTOFF_SIGMAS * beta;
        let mut periods = 0;
        while TAU * (periods as f32 + 1.0) - PI < reach {
            periods += 1;
        }
        WrappedGaussian {
            gaussian: Gaussian::new(beta),
            periods,
        }
    }

    /// Standard deviation β of the underlying Gaussian.
    #[must_use]
    pub fn beta(&self) -> f32 {
        self.gaussian.beta()
    }

    /// Distance beyond which a single period contributes nothing: [`CUTOFF_SIGMAS`]·β.
    #[must_use]
    pub fn reach(&self) -> f32 {
        CUTOFF_SIGMAS * self.gaussian.beta()
    }

    /// D(x) for any finite x.
    #[inline(always)]
    #[must_use]
    pub fn eval<M: Math>(&self, x: f32) -> f32 {
        let x = crate::math::wrap_angle(x);
        let mut sum = self.gaussian.eval::<M>(x);
        for k in 1..=self.periods {
            let shift = TAU * k as f32;
            sum += self.gaussian.eval::<M>(x + shift) + self.gaussian.eval::<M>(x - shift);
        }
        sum
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::Libm;

    /// ∫ f over [lo, hi] by the composite Simpson rule on `n` (even) panels, in f64.
    fn simpson(f: impl Fn(f32) -> f32, lo: f64, hi: f64, n: usize) -> f64 {
        let h = (hi - lo) / n as f64;
        let mut acc = f64::from(f(lo as f32)) + f64::from(f(hi as f32));
        for k in 1..n {
            let w = if k % 2 == 1 { 4.0 } else { 2.0 };
            acc += w * f64::from(f((lo + k as f64 * h) as f32));
        }
        acc * h / 3.0
    }

    #[test]
    fn gaussian_integrates_to_one() {
        for beta in [0.5f32.to_radians(), 0.05, 0.2, 0.8] {
            let g = Gaussian::new(beta);
            let reach = f64::from(CUTOFF_SIGMAS * beta);
            let mass = simpson(|x| g.eval::<Libm>(x), -reach, reach, 4_000);
            // The cut-off tails hold 5.6e-10 of the mass.
            assert!((mass - 1.0).abs() < 2e-6, "β {beta}: mass {mass}");
            assert_eq!(g.beta(), beta);
        }
    }

    #[test]
    fn gaussian_peak_symmetry_and_cutoff() {
        let beta = 0.1f32;
        let g = Gaussian::new(beta);
        let peak = 1.0 / (beta * libm::sqrtf(2.0 * PI));
        assert!((g.eval::<Libm>(0.0) - peak).abs() < 1e-6 * peak);
        // One standard deviation down: e^{−1/2} of the peak.
        assert!((g.eval::<Libm>(beta) / peak - libm::expf(-0.5)).abs() < 1e-6);
        for k in 0..100 {
            let x = k as f32 * 0.007;
            assert_eq!(g.eval::<Libm>(x), g.eval::<Libm>(-x));
        }
        assert!(g.eval::<Libm>(6.1 * beta) > 0.0);
        assert_eq!(g.eval::<Libm>(6.3 * beta), 0.0);
        assert_eq!(g.eval::<Libm>(-1e3), 0.0);
    }

    #[test]
    fn wrapped_gaussian_integrates_to_one_over_the_circle() {
        // Narrow lobes need no wrapping; wide ones sum several periods.
        for beta in [0.02f32, 0.3, 1.0, 2.5] {
            let d = WrappedGaussian::new(beta);
            let mass = simpson(
                |x| d.eval::<Libm>(x),
                -core::f64::consts::PI,
                core::f64::consts::PI,
                20_000,
            );
            assert!((mass - 1.0).abs() < 1e-5, "β {beta}: mass {mass}");
            assert_eq!(d.beta(), beta);
            assert_eq!(d.reach(), CUTOFF_SIGMAS * beta);
        }
        // Against the Fourier series of the wrapped normal (Jacobi's identity),
        // D(x) = (1 + 2 Σ_n e^{−n²β²/2} cos nx)/2π, which converges fast for wide lobes.
        for beta in [1.0f64, 2.0, 3.0] {
            let d = WrappedGaussian::new(beta as f32);
            for k in 0..=40 {
                let x = -core::f64::consts::PI + core::f64::consts::TAU * f64::from(k) / 40.0;
                let series: f64 = (1..=12)
                    .map(|n| {
                        let n = f64::from(n);
                        libm::exp(-0.5 * n * n * beta * beta) * libm::cos(n * x)
                    })
                    .sum();
                let want = (1.0 + 2.0 * series) / core::f64::consts::TAU;
                let got = f64::from(d.eval::<Libm>(x as f32));
                assert!(
                    (got - want).abs() < 1e-6,
                    "β {beta}, x {x}: {got} vs {want}"
                );
            }
        }
    }

    #[test]
    fn wrapped_gaussian_is_periodic_and_even() {
        let d = WrappedGaussian::new(0.7);
        for k in 0..50 {
            let x = -3.0 + 0.12 * k as f32;
            let here = d.eval::<Libm>(x);
            assert!(
                (d.eval::<Libm>(x + TAU) - here).abs() < 1e-5 * here.max(1e-3),
                "{x}"
            );
            assert!((d.eval::<Libm>(-x) - here).abs() < 1e-6, "{x}");
        }
    }
}
