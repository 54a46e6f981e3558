//! Unit tests of the math helpers: the polynomials against libm, wrap_angle's range on any
//! input, and the backends.

extern crate std;
use super::*;

/// Distance in units in the last place of `got` from the f64 value `want`.
fn ulps(got: f32, want: f64) -> f64 {
    let ulp = (f32::from_bits(got.to_bits() + 1) - got) as f64;
    (got as f64 - want).abs() / ulp
}

#[test]
fn pow2_neg_is_within_two_ulp_and_safe_outside() {
    // Every 64th float in [0, 125] plus the ends: within 2 ulp of 2^−y.
    let mut worst = 0.0f64;
    let (lo, hi) = (0.0f32.to_bits(), 125.0f32.to_bits());
    for bits in (lo..=hi).step_by(64).chain([hi]) {
        let y = f32::from_bits(bits);
        worst = worst.max(ulps(pow2_neg(y), libm::exp2(-(y as f64))));
    }
    std::eprintln!("pow2_neg: worst {worst:.2} ulp");
    assert!(worst <= 2.0, "worst {worst} ulp");
    // Exact at the integers (f = 0, p = 1).
    for k in 0..=125 {
        assert_eq!(pow2_neg(k as f32), libm::exp2f(-(k as f32)), "y = {k}");
    }
    // Clamped: above 125 the value at 125, NaN and negatives the value at 0.
    assert_eq!(pow2_neg(1e30), pow2_neg(125.0));
    assert_eq!(pow2_neg(f32::INFINITY), pow2_neg(125.0));
    assert_eq!(pow2_neg(f32::NAN), 1.0);
    assert_eq!(pow2_neg(-3.0), 1.0);
}

#[test]
fn exp_neg_polynomial_is_within_one_ulp() {
    // Every 256th float in [0, 87] plus the ends; the result is normal there.
    let mut worst = 0.0f64;
    let (lo, hi) = (0.0f32.to_bits(), 87.0f32.to_bits());
    for bits in (lo..=hi).step_by(256).chain([hi]) {
        let x = f32::from_bits(bits);
        let e = exp_neg_polynomial(x);
        let want = libm::exp(-(x as f64));
        if want >= f32::MIN_POSITIVE as f64 {
            worst = worst.max(ulps(e, want));
        }
    }
    std::eprintln!("exp_neg_polynomial: worst {worst:.2} ulp");
    assert!(worst <= 1.0, "worst {worst} ulp");
    assert_eq!(exp_neg_polynomial(0.0), 1.0);
    assert_eq!(exp_neg_polynomial(100.0), 0.0);
    assert_eq!(exp_neg_polynomial(f32::INFINITY), 0.0);
    assert!(exp_neg_polynomial(f32::NAN).is_nan());
    assert_eq!(exp_neg_polynomial(-1.0), libm::expf(1.0));
}

#[test]
fn exp_neg_saturating_is_the_polynomial_on_its_range_and_safe_outside() {
    let (lo, hi) = (0.0f32.to_bits(), 87.0f32.to_bits());
    for bits in (lo..=hi).step_by(4099).chain([hi]) {
        let x = f32::from_bits(bits);
        assert_eq!(exp_neg_saturating(x), exp_neg_polynomial(x), "x = {x}");
    }
    assert_eq!(exp_neg_saturating(87.001), 0.0);
    assert_eq!(exp_neg_saturating(f32::INFINITY), 0.0);
    assert_eq!(exp_neg_saturating(f32::MAX), 0.0);
    assert_eq!(exp_neg_saturating(-5.0), 1.0);
    assert_eq!(exp_neg_saturating(f32::NEG_INFINITY), 1.0);
    assert_eq!(exp_neg_saturating(f32::NAN), 1.0);
}

/// Every `n`-th f32 in [lo, hi].
fn grid(lo: f32, hi: f32, n: usize) -> impl Iterator<Item = f32> {
    (0..=n).map(move |k| lo + (hi - lo) * (k as f32 / n as f32))
}

#[test]
fn cos_within_half_pi_is_the_two_taylor_branches_bit_for_bit() {
    // The formulas the branch-free form selects between, written with a branch.
    fn branches(x: f32) -> f32 {
        let a = x.abs();
        if a <= core::f32::consts::FRAC_PI_4 {
            let y = a * a;
            let mut acc = -1.0 / 3_628_800.0;
            for c in [1.0 / 40_320.0, -1.0 / 720.0, 1.0 / 24.0, -0.5] {
                acc = acc * y + c;
            }
            acc * y + 1.0
        } else {
            let r = (1.570_796_4 - a) + -4.371_139e-8;
            let y = r * r;
            let mut acc = 1.0 / 362_880.0;
            for c in [-1.0 / 5_040.0, 1.0 / 120.0, -1.0 / 6.0] {
                acc = acc * y + c;
            }
            (acc * y) * r + r
        }
    }
    for x in grid(-PI / 2.0, PI / 2.0, 200_000) {
        assert_eq!(
            cos_within_half_pi(x).to_bits(),
            branches(x).to_bits(),
            "{x}"
        );
        let exact = libm::cos(f64::from(x));
        let err = (f64::from(cos_within_half_pi(x)) - exact).abs();
        assert!(
            err <= 1.2e-7 * exact.max(1e-7) + 1e-14,
            "cos {x}: error {err}"
        );
    }
}

#[test]
fn asin_polynomial_accuracy() {
    let mut worst = 0.0f64;
    for x in grid(-1.0, 1.0, 400_000) {
        let err = (f64::from(asin_polynomial(x)) - libm::asin(f64::from(x))).abs();
        worst = worst.max(err);
    }
    assert!(worst < 3e-7, "asin: worst absolute error {worst}");
}

#[test]
fn atan2_polynomial_accuracy() {
    let mut worst = 0.0f64;
    for y in grid(-2.0, 2.0, 400) {
        for x in grid(-2.0, 2.0, 400) {
            let exact = libm::atan2(f64::from(y), f64::from(x));
            // The cut along the negative x axis: ±π are the same direction.
            let mut err = (f64::from(atan2_polynomial(y, x)) - exact).abs();
            if err > 6.0 {
                err = (err - 2.0 * core::f64::consts::PI).abs();
            }
            worst = worst.max(err);
        }
    }
    assert!(worst < 3e-7, "atan2: worst absolute error {worst}");
    assert_eq!(atan2_polynomial(0.0, 0.0), 0.0);
    assert_eq!(atan2_polynomial(0.0, -1.0), PI);
    assert_eq!(atan2_polynomial(1.0, 0.0), PI / 2.0);
    assert_eq!(atan2_polynomial(-1.0, 0.0), -PI / 2.0);
}

#[test]
fn wrap_angle_lands_in_the_half_open_interval() {
    for x in grid(-50.0, 50.0, 100_000).chain([PI, -PI, TAU, -TAU, 3.0 * PI]) {
        let y = wrap_angle(x);
        assert!(y > -PI && y <= PI, "{x} → {y}");
        // The same direction: x − y is a whole number of turns (to f32 rounding).
        let turns = (f64::from(x) - f64::from(y)) / core::f64::consts::TAU;
        assert!((turns - libm::round(turns)).abs() < 1e-5, "{x} → {y}");
    }
    assert_eq!(wrap_angle(-PI), PI);
    assert_eq!(wrap_angle(f32::NAN), 0.0);
    assert_eq!(wrap_angle(f32::INFINITY), 0.0);
}

#[test]
fn wrap_angle_handles_huge_and_non_finite_input() {
    for x in [f32::NEG_INFINITY, f32::INFINITY, f32::NAN, -f32::NAN] {
        assert_eq!(wrap_angle(x), 0.0, "{x}");
    }
    // Far outside: still in (−π, π] and the same direction as the f64 reduction of the
    // same f32 (up to the f32 rounding of x − 2πk, which grows with |x|); beyond about
    // 2e8, where x names no direction, 0.
    for x in [
        1e4f32,
        -1e4,
        123_456.7,
        -7.5e6,
        1e8,
        3e8,
        -1e9,
        1e30,
        f32::MAX,
        -f32::MAX,
    ] {
        let y = wrap_angle(x);
        assert!(y > -PI && y <= PI, "{x} → {y}");
    }
    assert_eq!(wrap_angle(1e30), 0.0);
    assert_eq!(wrap_angle(-f32::MAX), 0.0);
    for x in [1e4f32, -1e4, 123_456.7, -7.5e6] {
        let want = (f64::from(x) + core::f64::consts::PI).rem_euclid(core::f64::consts::TAU)
            - core::f64::consts::PI;
        let got = f64::from(wrap_angle(x));
        // Compare on the circle: ±π are the same point.
        let d = (got - want).rem_euclid(core::f64::consts::TAU);
        let d = d.min(core::f64::consts::TAU - d);
        assert!(
            d < 1e-6 * f64::from(x.abs()).max(1.0),
            "{x}: {got} vs {want}"
        );
    }
    // The ends of the one-period fast paths.
    assert_eq!(wrap_angle(PI), PI);
    assert_eq!(wrap_angle(PI + TAU), PI + TAU - TAU);
    assert!(wrap_angle(-PI - TAU) > -PI);
    // Wrapping twice changes nothing.
    for x in grid(-1e3, 1e3, 10_000) {
        assert_eq!(wrap_angle(wrap_angle(x)), wrap_angle(x), "{x}");
    }
}

#[test]
fn asin_polynomial_ends_and_symmetry() {
    assert_eq!(asin_polynomial(0.0), 0.0);
    assert!(asin_polynomial(-0.0).is_sign_negative());
    assert_eq!(asin_polynomial(1.0), PI / 2.0);
    assert_eq!(asin_polynomial(-1.0), -PI / 2.0);
    // Beyond ±1 the argument is clamped (callers clamp anyway).
    assert_eq!(asin_polynomial(1.5), PI / 2.0);
    for x in grid(0.0, 1.0, 10_000) {
        assert_eq!(asin_polynomial(-x), -asin_polynomial(x), "odd at {x}");
    }
    // Monotone: a sampler inverting it must not see it turn back.
    let mut prev = -PI;
    for x in grid(-1.0, 1.0, 100_000) {
        let y = asin_polynomial(x);
        assert!(y >= prev, "not monotone at {x}");
        prev = y;
    }
}

#[test]
fn cos_within_half_pi_ends_symmetry_and_monotonicity() {
    assert_eq!(cos_within_half_pi(0.0), 1.0);
    let pole = cos_within_half_pi(PI / 2.0);
    // cos of the f32 nearest π/2 is −4.37e-8 in exact arithmetic.
    assert!(
        (f64::from(pole) - libm::cos(f64::from(PI / 2.0))).abs() < 1e-12,
        "{pole}"
    );
    let mut prev = 1.0f32;
    for x in grid(0.0, PI / 2.0, 50_000) {
        let c = cos_within_half_pi(x);
        assert_eq!(c.to_bits(), cos_within_half_pi(-x).to_bits(), "even at {x}");
        assert!(c <= prev, "not decreasing at {x}");
        prev = c;
    }
    // Relative accuracy near the pole, where 1/cos²θ magnifies errors.
    for k in 1..=1000 {
        let x = PI / 2.0 - k as f32 * 1e-6;
        let exact = libm::cos(f64::from(x));
        let rel = (f64::from(cos_within_half_pi(x)) - exact).abs() / exact;
        assert!(rel < 2e-6, "{x}: relative error {rel}");
    }
}

#[test]
fn clamped_helpers_never_give_nan() {
    assert_eq!(asin_clamped::<Libm>(1.000_001), PI / 2.0);
    assert_eq!(asin_clamped::<Libm>(-1.5), -PI / 2.0);
    assert_eq!(sqrt_pos::<Libm>(-1e-9), 0.0);
    assert_eq!(sqrt_pos::<Libm>(4.0), 2.0);
}

#[test]
fn libm_backend_is_libm() {
    for x in grid(-10.0, 10.0, 1_000) {
        let (s, c) = Libm::sin_cos(x);
        assert_eq!(s.to_bits(), libm::sinf(x).to_bits());
        assert_eq!(c.to_bits(), libm::cosf(x).to_bits());
        assert_eq!(Libm::atan2(x, 1.5), libm::atan2f(x, 1.5));
        assert_eq!(Libm::exp(x), libm::expf(x));
        if x >= 0.0 {
            assert_eq!(Libm::exp_neg(x), exp_neg_polynomial(x));
        }
    }
    assert_eq!(Libm::sqrt(2.0), libm::sqrtf(2.0));
}

/// Within the errors docs/accuracy.md reports for micromath (sin, cos 1.1e-3 absolute,
/// atan2 2.8e-3, exp 2.4e-3 relative); asin is this crate's polynomial.
#[cfg(feature = "micromath")]
#[test]
fn fast_math_backend_is_within_its_documented_error() {
    for x in grid(-4.0, 4.0, 4_000) {
        assert_eq!(FastMath::asin(x / 4.0), asin_polynomial(x / 4.0));
        assert!((FastMath::sin(x) - libm::sinf(x)).abs() < 1.2e-3, "sin {x}");
        assert!((FastMath::cos(x) - libm::cosf(x)).abs() < 1.2e-3, "cos {x}");
        assert!(
            (FastMath::atan2(x, 1.3) - libm::atan2f(x, 1.3)).abs() < 3e-3,
            "atan2 {x}"
        );
    }
    for x in grid(0.0, 87.0, 8_700) {
        let (e, want) = (FastMath::exp_neg(x), libm::expf(-x));
        assert!(
            (e - want).abs() <= 2.5e-3 * want,
            "exp(−{x}): {e} vs {want}"
        );
    }
    assert_eq!(FastMath::exp(-100.0), 0.0);
    assert_eq!(FastMath::sqrt(2.0), libm::sqrtf(2.0));
}

#[test]
fn sqrt_is_libm_sqrtf_bit_for_bit() {
    // Every 997th bit pattern (under Miri, where `sqrt` is `libm::sqrtf` itself, every
    // 997 · 4099th): positives, negatives, subnormals, infinities and NaNs.
    let step = if cfg!(miri) { 997 * 4099 } else { 997 };
    for bits in (0..=u32::MAX)
        .step_by(step)
        .chain([0x7f80_0000, 0xff80_0000, 0x8000_0000])
    {
        let x = f32::from_bits(bits);
        let (a, b) = (sqrt(x), libm::sqrtf(x));
        assert!(
            a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan()),
            "x = {x:e}"
        );
    }
}

#[test]
fn rsqrt_newton_is_within_four_ulp() {
    // Every 1021st float from 1e-7 to 1e7 (the variances and widths the dual term feeds it).
    let mut worst = 0.0f64;
    let (lo, hi) = (1e-7f32.to_bits(), 1e7f32.to_bits());
    for bits in (lo..=hi).step_by(1021).chain([hi]) {
        let x = f32::from_bits(bits);
        let want = 1.0 / f64::from(x).sqrt();
        worst = worst.max(ulps(rsqrt_newton(x), want));
    }
    std::eprintln!("rsqrt_newton: worst {worst:.2} ulp");
    assert!(worst <= 4.0, "worst {worst} ulp");
}

#[test]
fn erf_polynomial_is_within_2e_6() {
    // Every 257th float from 1e-6 to 12, both signs, against f64's erf; 0, NaN, ±∞ too.
    let mut worst = 0.0f64;
    let (lo, hi) = (1e-6f32.to_bits(), 12f32.to_bits());
    for bits in (lo..=hi).step_by(257).chain([hi]) {
        for x in [f32::from_bits(bits), -f32::from_bits(bits)] {
            let want = libm::erf(f64::from(x));
            worst = worst.max((f64::from(erf_polynomial(x)) - want).abs());
        }
    }
    std::eprintln!("erf_polynomial: worst {worst:.2e}");
    assert!(worst <= 2e-6, "worst {worst:e}");
    assert!(erf_polynomial(0.0).abs() <= 1e-7);
    assert_eq!(erf_polynomial(-0.7), -erf_polynomial(0.7));
    assert_eq!(erf_polynomial(f32::INFINITY), 1.0);
    assert_eq!(erf_polynomial(f32::NEG_INFINITY), -1.0);
    assert!(erf_polynomial(f32::NAN).abs() <= 1.0);
}

/// The f32 value of `const NAME: f32 = literal;` in the shader.
fn wgsl_const(name: &str) -> f32 {
    let src = crate::shader::FUR_BCSDF_WGSL;
    let key = std::format!("const {name}: f32 = ");
    let at = src
        .find(&key)
        .unwrap_or_else(|| panic!("{name} not in the shader"))
        + key.len();
    let end = at + src[at..].find(';').unwrap();
    src[at..end].trim().parse().unwrap()
}

/// The float literals (digits with a '.', an optional exponent) in the body of the shader
/// function `name`, in order.
fn wgsl_literals(name: &str) -> std::vec::Vec<f32> {
    let src = crate::shader::FUR_BCSDF_WGSL;
    let at = src
        .find(&std::format!("fn {name}("))
        .unwrap_or_else(|| panic!("{name} not in the shader"));
    let body = &src[at..at + src[at..].find("\n}").unwrap()];
    let b = body.as_bytes();
    let mut out = std::vec::Vec::new();
    let mut i = 0;
    while i < b.len() {
        let word_start = i == 0 || !(b[i - 1].is_ascii_alphanumeric() || b[i - 1] == b'_');
        if b[i].is_ascii_digit() && word_start {
            let mut j = i;
            while j < b.len()
                && (b[j].is_ascii_digit()
                    || b[j] == b'.'
                    || b[j] == b'e'
                    || (b[j] == b'-' && b[j - 1] == b'e'))
            {
                j += 1;
            }
            if body[i..j].contains('.') {
                out.push(body[i..j].parse().unwrap());
            }
            i = j;
        } else {
            i += 1;
        }
    }
    out
}

#[test]
fn the_shader_twins_use_the_same_coefficients() {
    // The WGSL `fur_exp_neg` and `fur_erf` repeat exp_neg_reduced's and erf_polynomial's
    // operations on purpose (the GPU = CPU parity rests on it); their constants must be
    // these to the bit, so a coefficient edited on one side only fails here, not only when
    // the drift exceeds the GPU test's 1e-5.
    assert_eq!(wgsl_const("FUR_LN2_HI"), LN2_SPLIT[0]);
    assert_eq!(wgsl_const("FUR_LN2_LO"), LN2_SPLIT[1]);
    assert_eq!(wgsl_const("FUR_LOG2_E"), core::f32::consts::LOG2_E);
    // fur_exp_neg's literals: the clamp bounds 0.0 and 87.0, the polynomial, then 1.0,
    // 0.0 and 87.0 of the result's select.
    let exp = wgsl_literals("fur_exp_neg");
    let poly: std::vec::Vec<f32> = exp
        .iter()
        .copied()
        .filter(|v| *v > 0.0 && *v < 1.0)
        .collect();
    assert_eq!(poly, EXP_NEG_POLY, "fur_exp_neg's literals {exp:?}");
    // fur_pow2_neg's literals: the clamp bounds 0.0 and 125.0, then the Taylor
    // coefficients from the highest degree (the constant 1.0 last).
    let pow2 = wgsl_literals("fur_pow2_neg");
    assert_eq!(
        pow2[..3],
        [0.0, 125.0, 0.0],
        "fur_pow2_neg's literals {pow2:?}"
    );
    assert_eq!(pow2[3..], POW2_TAYLOR, "fur_pow2_neg's literals {pow2:?}");
    assert_eq!(wgsl_const("FUR_ROOT_RATE"), crate::lut::ROOT_RATE);
    assert_eq!(wgsl_const("FUR_ROOT_SHARE"), crate::lut::ROOT_SHARE);
    for (k, a) in ERF_A.iter().enumerate() {
        assert_eq!(
            wgsl_const(&std::format!("FUR_ERF_A{}", k + 1)),
            *a,
            "a{}",
            k + 1
        );
    }
}
