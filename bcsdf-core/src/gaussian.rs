//! The normalised Gaussian G(x; β) = exp(−x²/2β²)/(√(2π)·β) (report eq. 3) and its wrapped
//! version on the circle, the shapes of M_p and D_p (MODEL.md §5).

use crate::math::{Math, PI, TAU};

/// 1/√(2π).
const INV_SQRT_TAU: f32 = 0.398_942_3;

/// Beyond this many standard deviations a Gaussian term is dropped (e^{−0.5·6.2²} ≈ 4.5e-9
/// of the peak).
pub const CUTOFF_SIGMAS: f32 = 6.2;

/// A normalised Gaussian of standard deviation β.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Gaussian {
    beta: f32,
    norm: f32,
    inv_two_beta2: f32,
}

impl Gaussian {
    /// G(·; β); β > 0 is guaranteed by parameter validation.
    pub fn new(beta: f32) -> Gaussian {
        Gaussian {
            beta,
            norm: INV_SQRT_TAU / beta,
            inv_two_beta2: 0.5 / (beta * beta),
        }
    }

    /// Standard deviation β.
    pub fn beta(&self) -> f32 {
        self.beta
    }

    /// G(x; β); exactly zero beyond [`CUTOFF_SIGMAS`]·β.
    #[inline]
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
/// period within [`CUTOFF_SIGMAS`]·β, so the truncation error is below 1e-6 (MODEL.md §5).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WrappedGaussian {
    gaussian: Gaussian,
    periods: i32,
}

impl WrappedGaussian {
    /// D(·; β).
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
    pub fn beta(&self) -> f32 {
        self.gaussian.beta()
    }

    /// Distance beyond which a single period contributes nothing: [`CUTOFF_SIGMAS`]·β.
    pub fn reach(&self) -> f32 {
        CUTOFF_SIGMAS * self.gaussian.beta()
    }

    /// D(x) for any finite x.
    #[inline(always)]
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
