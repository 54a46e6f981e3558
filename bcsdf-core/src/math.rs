//! Scalar math backends.
//!
//! Every transcendental function the model uses goes through the [`Math`] trait, so that the
//! whole model is monomorphised over one backend:
//!
//! - [`Libm`] (default): the `libm` crate, a port of musl's libm. Pure Rust, no platform
//!   intrinsics beyond IEEE arithmetic, so the same inputs give the same bits on every target.
//!   The model's exponentials, all of the form e^−x with x ≥ 0 ([`Math::exp_neg`]), use
//!   [`exp_neg_polynomial`] instead: plain f32 arithmetic as well (so just as deterministic),
//!   within 1 ulp, and about half the instructions of `libm::expf`.
//! - `FastMath` (cargo feature `micromath`): `micromath` approximations of `sin`, `cos`,
//!   `atan2` and `exp`, and the polynomial [`asin_polynomial`] (micromath's own `asin` is off
//!   by up to 0.018 rad); `sqrt` stays exact (it is not transcendental and is a single
//!   instruction on most targets). Its error against [`Libm`] is measured by the test
//!   `tests/tests/suite/fast_math.rs` and documented in `docs/accuracy.md`.
//!
//! Choosing the backend is explicit (`FurBcsdf<FastMath>`) rather than a global feature
//! switch, so that one dependency enabling the feature cannot silently change the numbers
//! of another.

/// A set of f32 scalar functions the model is evaluated with.
pub trait Math: Copy + Default + core::fmt::Debug + 'static {
    /// Sine.
    fn sin(x: f32) -> f32;
    /// Cosine.
    fn cos(x: f32) -> f32;
    /// (sin x, cos x); one argument reduction where the backend has that.
    #[inline]
    #[must_use]
    fn sin_cos(x: f32) -> (f32, f32) {
        (Self::sin(x), Self::cos(x))
    }
    /// Arc sine; the argument is clamped to `[-1, 1]` by the callers.
    fn asin(x: f32) -> f32;
    /// Four-quadrant arc tangent of `y / x`.
    fn atan2(y: f32, x: f32) -> f32;
    /// Natural exponential.
    fn exp(x: f32) -> f32;
    /// e^−x for x ≥ 0: every exponential of the model is an attenuation or a Gaussian, so
    /// this is the one the evaluation calls. Defaults to `exp(−x)`.
    #[inline]
    #[must_use]
    fn exp_neg(x: f32) -> f32 {
        Self::exp(-x)
    }
    /// Square root (exact in every backend: [`sqrt`]).
    #[inline]
    #[must_use]
    fn sqrt(x: f32) -> f32 {
        sqrt(x)
    }
}

/// The correctly rounded square root, the same bits as `libm::sqrtf` (IEEE 754 requires
/// exact rounding of both). On x86-64 it is the SSE intrinsic, which the compiler encodes for
/// the instruction set of the function it is inlined into: `vsqrtss` inside the baked
/// evaluator's AVX2 functions. `libm::sqrtf` there is inline assembly with the legacy SSE
/// encoding, which after 256-bit instructions costs an SSE/AVX state transition on Intel
/// CPUs: with three of them per query (the absorption coordinate), a batch with a colour per
/// query measured 12–23× slower than the batch at the LUT's own colour (docs/benchmarks.md,
/// "A colour per query"). Other targets, and Miri (which runs `libm`'s portable square
/// root, bcsdf-core/Cargo.toml), call `libm::sqrtf`.
#[inline(always)]
#[must_use]
pub fn sqrt(x: f32) -> f32 {
    #[cfg(all(target_arch = "x86_64", target_feature = "sse", not(miri)))]
    {
        use core::arch::x86_64::{_mm_cvtss_f32, _mm_set_ss, _mm_sqrt_ss};
        // SAFETY: the target enables SSE (the `cfg`), the intrinsics' only requirement; they
        // touch no memory.
        unsafe { _mm_cvtss_f32(_mm_sqrt_ss(_mm_set_ss(x))) }
    }
    #[cfg(not(all(target_arch = "x86_64", target_feature = "sse", not(miri))))]
    {
        libm::sqrtf(x)
    }
}

/// Deterministic backend on top of the `libm` crate (the default).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Libm;

impl Math for Libm {
    #[inline]
    fn sin(x: f32) -> f32 {
        libm::sinf(x)
    }
    #[inline]
    fn cos(x: f32) -> f32 {
        libm::cosf(x)
    }
    #[inline]
    fn sin_cos(x: f32) -> (f32, f32) {
        libm::sincosf(x)
    }
    #[inline]
    fn asin(x: f32) -> f32 {
        libm::asinf(x)
    }
    #[inline]
    fn atan2(y: f32, x: f32) -> f32 {
        libm::atan2f(y, x)
    }
    #[inline]
    fn exp(x: f32) -> f32 {
        libm::expf(x)
    }
    #[inline]
    fn exp_neg(x: f32) -> f32 {
        exp_neg_polynomial(x)
    }
}

/// Fast approximate backend on top of `micromath` (cargo feature `micromath`).
#[cfg(feature = "micromath")]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct FastMath;

#[cfg(feature = "micromath")]
impl Math for FastMath {
    #[inline]
    fn sin(x: f32) -> f32 {
        micromath::F32Ext::sin(x)
    }
    #[inline]
    fn cos(x: f32) -> f32 {
        micromath::F32Ext::cos(x)
    }
    #[inline]
    fn asin(x: f32) -> f32 {
        // micromath's asin is off by up to 0.018 rad (measured, tests/tests/suite/fast_math.rs),
        // which moves every lobe by about a degree; this polynomial is as fast and far better.
        asin_polynomial(x)
    }
    #[inline]
    fn atan2(y: f32, x: f32) -> f32 {
        micromath::F32Ext::atan2(y, x)
    }
    #[inline]
    fn exp(x: f32) -> f32 {
        // micromath's exp is not defined for very negative arguments; absorption only ever
        // asks for exp(-x) with x >= 0, and below -87 the f32 result is 0 anyway.
        if x < -87.0 {
            0.0
        } else {
            micromath::F32Ext::exp(x)
        }
    }
}

/// Arc sine by Abramowitz & Stegun 4.4.46: asin x = π/2 − √(1 − x)·Σ a_k x^k on [0, 1]
/// (|error| ≤ 2e-8 in exact arithmetic; ≤ 3e-7 rad in f32 (Estrin's scheme), measured by
/// `tests::asin_polynomial_accuracy`), odd-extended, branch-free. Used by `FastMath` and by
/// the baked evaluator's direction conversion ([`crate::BakedBcsdf::eval_far_dirs`]).
#[inline]
#[must_use]
pub fn asin_polynomial(x: f32) -> f32 {
    const A: [f32; 8] = [
        core::f32::consts::FRAC_PI_2, // a0 = 1.5707963050 rounds to the same f32
        -0.214_598_8,
        0.088_978_99,
        -0.050_174_303,
        0.030_891_88,
        -0.017_088_126,
        0.006_670_09,
        -0.001_262_491,
    ];
    let ax = x.abs().min(1.0);
    // Estrin's scheme: the polynomial runs beside the square root instead of after it.
    let poly = estrin8(&[A[7], A[6], A[5], A[4], A[3], A[2], A[1], A[0]], ax);
    let r = PI / 2.0 - sqrt(1.0 - ax) * poly;
    // copysign rather than `if`: branch-free (−0 gives −0).
    r.copysign(x)
}

/// atan2(y, x) without libm and without branches, for the baked evaluator's directions
/// (docs/model.md §1): a = min(|x|, |y|)/max(|x|, |y|) ∈ [0, 1], atan a = a + a·t·P(t) with
/// t = a² and P a degree-7 polynomial (Estrin's scheme) fitted for this crate (minimax in
/// relative error on [0, 1];
/// |error| ≤ 7e-8 rad in f32, measured by `tests::atan2_polynomial_accuracy`), then the
/// octant: π/2 − · where |y| > |x|, π − · where x < 0, and the sign of y. atan2(±0, ±0) = ±0
/// (libm gives ±π for x = −0, which the callers never need).
#[inline]
#[must_use]
pub fn atan2_polynomial(y: f32, x: f32) -> f32 {
    const P: [f32; 8] = [
        0.002_920_234_8,
        -0.016_366_188,
        0.043_209_206,
        -0.075_520_08,
        0.106_659_19,
        -0.142_110_38,
        0.199_937_72,
        -0.333_331_53,
    ];
    let (ax, ay) = (x.abs(), y.abs());
    let (lo, hi) = (ax.min(ay), ax.max(ay));
    // 0/0 becomes 0/MIN_POSITIVE = 0.
    let a = lo / hi.max(f32::MIN_POSITIVE);
    let t = a * a;
    let r = a + a * (t * estrin8(&P, t));
    // Bit-mask selects (an `if` becomes a branch that random directions mispredict).
    let select = |cond: bool, then: f32, otherwise: f32| {
        let mask = 0u32.wrapping_sub(u32::from(cond));
        f32::from_bits((then.to_bits() & mask) | (otherwise.to_bits() & !mask))
    };
    let r = select(ay > ax, PI / 2.0 - r, r);
    let r = select(x < 0.0, PI - r, r);
    r.copysign(y)
}

/// The degree-7 polynomial c₀x⁷ + c₁x⁶ + … + c₇ by Estrin's scheme: pairs, then pairs of
/// pairs (x², x⁴), three multiply-add levels deep instead of Horner's seven, so that the
/// polynomials of [`asin_polynomial`] and [`atan2_polynomial`] do not lengthen the
/// dependency chain of an evaluation from directions.
#[inline(always)]
fn estrin8(c: &[f32; 8], x: f32) -> f32 {
    let x2 = x * x;
    let x4 = x2 * x2;
    let p01 = c[0] * x + c[1];
    let p23 = c[2] * x + c[3];
    let p45 = c[4] * x + c[5];
    let p67 = c[6] * x + c[7];
    (p01 * x2 + p23) * x4 + (p45 * x2 + p67)
}

/// e^−x for x ≥ 0 in plain f32 arithmetic, for [`Libm`]: x = k·ln 2 + r with |r| ≤ ln 2/2
/// (ln 2 split in two floats, as in libm), e^−r by Cephes' degree-7 `expf` polynomial, and 2^−k
/// put into the exponent bits. Within 1 ulp of e^−x (0.98 ulp measured against f64 by the
/// crate's unit test); no division and no call, about half of `libm::expf`'s instructions. Results
/// below 2^−126 (x > 87.3) are flushed to 0; x < 0 or NaN goes to `libm::expf`.
#[inline]
#[must_use]
pub fn exp_neg_polynomial(x: f32) -> f32 {
    if !(0.0..=87.0).contains(&x) {
        return if x > 87.0 { 0.0 } else { libm::expf(-x) };
    }
    exp_neg_reduced(x)
}

/// e^−x for x ≥ 0 without a branch, for lane loops ([`crate::dual`]): x is clamped to
/// [0, 87] for [`exp_neg_polynomial`]'s polynomial and the result selected to 0 above 87, so
/// that a loop over lanes compiles to straight-line (vectorisable) code. Same accuracy as
/// [`exp_neg_polynomial`] on [0, 87]; x < 0 and NaN give 1 (never a panic or NaN).
#[inline(always)]
#[must_use]
pub fn exp_neg_saturating(x: f32) -> f32 {
    // max/min, not clamp: NaN becomes 0 here (clamp would pass it on); the result kept or
    // zeroed by a bit mask: no branch.
    #[allow(clippy::manual_clamp)]
    let e = exp_neg_reduced(x.max(0.0).min(87.0));
    let keep = u32::from(x > 87.0).wrapping_sub(1);
    f32::from_bits(e.to_bits() & keep)
}

/// 1/√x for normal x > 0 in plain f32 arithmetic, for lane loops ([`crate::dual`]): the
/// bit-level first guess 0x5f37_5a86 − bits/2 (relative error ≤ 3.5e-2) and three Newton
/// steps y ← y(1.5 − x y²/2) (each squares the error and multiplies it by 1.5: ≤ 1.8e-3,
/// ≤ 5e-6, then rounding), so within 4 ulp of 1/√x (measured by the crate's unit test); no division, no square root, no call,
/// so a loop over lanes vectorises. Not for 0, subnormals, infinities or NaN (the caller
/// keeps x in a normal range).
#[inline(always)]
#[must_use]
pub fn rsqrt_newton(x: f32) -> f32 {
    let y = f32::from_bits(0x5f37_5a86u32.wrapping_sub(x.to_bits() >> 1));
    let half = 0.5 * x;
    let y = y * (1.5 - half * y * y);
    let y = y * (1.5 - half * y * y);
    y * (1.5 - half * y * y)
}

/// a₁ … a₆ of [`erf_polynomial`] (Abramowitz and Stegun 7.1.28); the shader's `FUR_ERF_A1` …
/// `FUR_ERF_A6`.
pub(crate) const ERF_A: [f32; 6] = [
    0.070_523_08,
    0.042_282_01,
    0.009_270_527,
    0.000_152_014_3,
    0.000_276_567_2,
    0.000_043_063_8,
];
/// ln 2 split in two floats for [`exp_neg_polynomial`]'s reduction; the shader's
/// `FUR_LN2_HI`, `FUR_LN2_LO`.
pub(crate) const LN2_SPLIT: [f32; 2] = [0.693_359_4, -2.121_944_4e-4];
/// [`exp_neg_polynomial`]'s polynomial in r, Horner from the highest degree (then
/// e = p·r² + r + 1); the literals of the shader's `fur_exp_neg`, in this order.
pub(crate) const EXP_NEG_POLY: [f32; 6] = [
    1.987_569_2e-4,
    1.398_199_9e-3,
    8.333_452e-3,
    4.166_579_6e-2,
    0.166_666_65,
    0.5,
];

/// erf x in plain f32 arithmetic, for lane loops ([`crate::dual`]) and its WGSL twin
/// (`shaders/fur_bcsdf.wgsl`, `fur_erf`): Abramowitz and Stegun 7.1.28,
/// erf |x| = 1 − 1/(1 + a₁x + a₂x² + … + a₆x⁶)¹⁶, whose error is at most 3e-7 (the 16th power
/// by four squarings; no exponential), and the sign of x put back (erf is odd). Within 2e-6
/// of erf x in f32 (1.6e-6 measured by the crate's unit test: the 16th power multiplies the
/// rounding of the polynomial by 16); one division and no branch. NaN gives a value in
/// [−1, 1], never NaN.
#[inline(always)]
#[must_use]
pub fn erf_polynomial(x: f32) -> f32 {
    const A: [f32; 6] = ERF_A;
    // max/min, not clamp or abs: NaN becomes 0 here. |x| ≤ 10 loses nothing (erf 10 = 1 in
    // f32) and keeps p¹⁶ finite (p(10) ≈ 87).
    #[allow(clippy::manual_clamp)]
    let a = x.max(-x).max(0.0).min(10.0);
    let p = (((((A[5] * a + A[4]) * a + A[3]) * a + A[2]) * a + A[1]) * a + A[0]) * a + 1.0;
    let p2 = p * p;
    let p4 = p2 * p2;
    let p8 = p4 * p4;
    let e = 1.0 - 1.0 / (p8 * p8);
    // The sign bit of x onto e ≥ 0.
    f32::from_bits(e.to_bits() | (x.to_bits() & 0x8000_0000))
}

/// The Taylor coefficients of 2^f = e^(f·ln 2), (ln 2)ⁿ/n! for n = 7, 6, …, 0 (highest degree
/// first, [`estrin8`]'s order); the literals of the shader's `fur_pow2_neg`, in this order.
pub(crate) const POW2_TAYLOR: [f32; 8] = [
    1.525_273_4e-5,
    1.540_353e-4,
    1.333_355_8e-3,
    9.618_129e-3,
    5.550_411e-2,
    0.240_226_5,
    core::f32::consts::LN_2,
    1.0,
];

/// 2^−y for y ≥ 0 without a branch, for the absorption axis's coordinate
/// ([`crate::lut::absorption_coordinate`]): y kept in [0, 125] (NaN gives 0), k = y rounded to
/// the nearest integer (ties to even, as WGSL's `round`), f = k − y ∈ [−½, ½] (exact), 2^f by
/// its Taylor polynomial of degree 7 (`POW2_TAYLOR`, truncation error ≤ 5.2e-9 relative)
/// in Estrin's scheme (three multiply-add levels: a short dependency chain), and 2^−k put into
/// the exponent bits. Within 2 ulp of 2^−y (measured by the crate's unit test); above 125 the
/// result stays 2^−125·2^f, not 0 (the axis's coordinate is 1 there either way).
#[inline(always)]
#[must_use]
pub fn pow2_neg(y: f32) -> f32 {
    // 1.5·2²³: adding it rounds y ∈ [0, 125] to an integer, which then sits in the low
    // mantissa bits.
    const ROUND: f32 = 12_582_912.0;
    #[allow(clippy::manual_clamp)]
    let y = y.max(0.0).min(125.0);
    let shifted = y + ROUND;
    let k = shifted - ROUND;
    // Exact (Sterbenz: k and y within a factor 2, or k = 0).
    let f = k - y;
    let p = estrin8(&POW2_TAYLOR, f);
    // p ∈ [0.70, 1.42] has biased exponent 126 or 127 and k ≤ 125: the result stays normal.
    let k_bits = shifted.to_bits().wrapping_sub(ROUND.to_bits());
    f32::from_bits(p.to_bits().wrapping_sub(k_bits << 23))
}

/// The polynomial of [`exp_neg_polynomial`] for x ∈ [0, 87].
#[inline(always)]
fn exp_neg_reduced(x: f32) -> f32 {
    const LN2_HI: f32 = LN2_SPLIT[0];
    const LN2_LO: f32 = LN2_SPLIT[1];
    const LOG2_E: f32 = core::f32::consts::LOG2_E;
    // k = round(x / ln 2) ∈ [0, 126]: adding 1.5·2²³ rounds to an integer, which then sits
    // in the low mantissa bits (cheaper than a saturating float-to-int conversion).
    const ROUND: f32 = 12_582_912.0;
    let shifted = x * LOG2_E + ROUND;
    let kf = shifted - ROUND;
    let k = shifted.to_bits().wrapping_sub(ROUND.to_bits());
    let r = (kf * LN2_HI - x) + kf * LN2_LO;
    let z = r * r;
    let c = EXP_NEG_POLY;
    let mut p = c[0];
    p = p * r + c[1];
    p = p * r + c[2];
    p = p * r + c[3];
    p = p * r + c[4];
    p = p * r + c[5];
    let e = p * z + r + 1.0;
    e * f32::from_bits((127 - k) << 23)
}

/// `π` in f32.
pub const PI: f32 = core::f32::consts::PI;
/// `2π` in f32.
pub const TAU: f32 = core::f32::consts::TAU;

/// cos x for |x| ≤ π/2 (larger |x| is not meaningful), without libm: for |x| ≤ π/4 the
/// Taylor polynomial of cos (first omitted term (π/4)^12/12! ≈ 1.1e-10), beyond it sin(π/2 − |x|)
/// by the Taylor polynomial of sin (first omitted term (π/4)^11/11! ≈ 1.8e-9), with π/2 split
/// in two floats so that π/2 − |x| keeps its relative precision near the poles (where
/// 1/cos²θ_i magnifies any absolute error). The baked evaluator and its WGSL twin
/// (`shaders/fur_bcsdf.wgsl`) use this same sequence of operations.
#[inline]
#[must_use]
pub fn cos_within_half_pi(x: f32) -> f32 {
    /// π/2 rounded to f32, and the remainder π/2 − PIO2_HI.
    const PIO2_HI: f32 = 1.570_796_4;
    const PIO2_LO: f32 = -4.371_139e-8;
    /// Horner coefficients per branch: cos up to π/4 ((−1)^k/(2k)!, k = 5 … 1), then
    /// sin(π/2 − |x|) ((−1)^k/(2k+1)!, k = 4 … 1, after a leading 0, which the first
    /// Horner step turns back into the k = 4 coefficient exactly).
    const NEAR: [f32; 5] = [
        -1.0 / 3_628_800.0,
        1.0 / 40_320.0,
        -1.0 / 720.0,
        1.0 / 24.0,
        -0.5,
    ];
    const FAR: [f32; 5] = [
        0.0,
        1.0 / 362_880.0,
        -1.0 / 5_040.0,
        1.0 / 120.0,
        -1.0 / 6.0,
    ];
    let a = x.abs();
    // One polynomial on selected inputs instead of a branch, which random angles would
    // mispredict half the time: the near branch is 1 + y·C(y) with y = a², the far one
    // r + (y·S(y))·r with r = π/2 − a (PIO2_HI − a is exact by Sterbenz for a ∈ [π/4, π/2];
    // one rounding adds PIO2_LO) and y = r². For the near branch the multiplier m = 1 and
    // (y·C(y))·1 is exact, so each branch is computed exactly as its own formula. The selects
    // are bit masks (compilers turn `if` into a branch), which also lets a loop over many
    // angles vectorise.
    let r = (PIO2_HI - a) + PIO2_LO;
    let mask = 0u32.wrapping_sub(u32::from(a > core::f32::consts::FRAC_PI_4));
    let pick =
        |near: f32, far: f32| f32::from_bits((near.to_bits() & !mask) | (far.to_bits() & mask));
    let t = pick(a, r);
    let m = pick(1.0, r);
    let y = t * t;
    let mut acc = pick(NEAR[0], FAR[0]);
    for k in 1..5 {
        acc = acc * y + pick(NEAR[k], FAR[k]);
    }
    (acc * y) * m + m
}

/// Wraps an angle to `(-π, π]`. Non-finite input gives 0, and so does finite input too
/// large for the f32 reduction to place (|x| beyond about 2e8, where one ulp of x exceeds
/// two turns, so that x names no direction).
#[inline]
#[must_use]
pub fn wrap_angle(x: f32) -> f32 {
    // Fast paths (inlined): at most one period away, the common case for sums of a few
    // angles. The rest is not inlined.
    if x > -PI && x <= PI {
        return x;
    }
    wrap_angle_outside(x)
}

/// [`wrap_angle`] for x outside (−π, π].
#[inline(never)]
fn wrap_angle_outside(x: f32) -> f32 {
    if x > PI && x <= PI + TAU {
        return x - TAU;
    }
    if x <= -PI && x > -PI - TAU {
        return x + TAU;
    }
    wrap_angle_far(x)
}

/// [`wrap_angle`] for x more than one period outside (−π, π].
fn wrap_angle_far(x: f32) -> f32 {
    if !x.is_finite() {
        return 0.0;
    }
    let mut y = x - TAU * libm::floorf((x + PI) / TAU);
    // floor-based wrap yields [-π, π); move the closed end to +π.
    if y <= -PI {
        y += TAU;
    }
    if y > PI {
        y -= TAU;
    }
    // |x| beyond about 2e8 (one ulp of x is then 16, over two turns), where the f32 product
    // above can be off by more than a turn: such an angle names no direction, so it is
    // treated like non-finite input (a WGSL twin can do the same; it has no f64 to reduce in).
    if y > -PI && y <= PI {
        y
    } else {
        0.0
    }
}

/// `asin` with its argument clamped to `[-1, 1]` (rounding can push `sin` values just past 1).
#[inline]
#[must_use]
pub fn asin_clamped<M: Math>(x: f32) -> f32 {
    M::asin(x.clamp(-1.0, 1.0))
}

/// `sqrt(max(x, 0))`: a cosine from a sine without NaN from rounding.
#[inline]
#[must_use]
pub fn sqrt_pos<M: Math>(x: f32) -> f32 {
    M::sqrt(x.max(0.0))
}

#[cfg(test)]
mod tests;
