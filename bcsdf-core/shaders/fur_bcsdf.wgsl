// fur_bcsdf.wgsl: the baked far-field fur BCSDF on the GPU (docs/model.md §8, docs/lut.md).
//
// Evaluates S(omega_i, omega_r) per lobe family from the same .furlut bytes the CPU reads
// (`bcsdf_core::baked::BakedBcsdf`), bound as a read-only storage buffer of u32 words
// (little-endian; a blob whose length is not a multiple of 4 is zero-padded). The blob must
// have been validated on the CPU (`BakedBcsdf::from_bytes`): the shader trusts its header.
//
// Every step mirrors `BakedBcsdf::eval_far` and its helpers, in the same order: the f16
// decode by shifting the half's bits into an f32 (value x 2^-112, the 2^112 folded into the
// table scale), the clamped axis location, linear / bilinear interpolation with the scale
// folded into the weights, the exact back/front blend of M^s, and 1/max(cos^2, 1e-4) with the
// same Taylor polynomial for cos. Differences to the CPU come only from the GPU's rounding of
// division and fused multiply-adds (docs/benchmarks.md gives the measured agreement).
//
// Angles are radians: theta in [-pi/2, pi/2] from the fiber's normal plane, phi = phi_r -
// phi_i. Invalid input (NaN, |theta| > pi/2, degenerate vectors) gives exactly 0, like the
// CPU's `eval_far_dirs`.
//
// Colour (LUT format 5, docs/lut.md "The absorption axis"): fur_eval_far, fur_eval_far_dirs,
// fur_pdf_far and fur_sample_far take the query's cortex absorption sigma_ca per RGB channel
// as a vec3<f32> (per fiber radius; the CPU's `BakedBcsdf::at`). Table N holds n_abs planes,
// each the four families at one sigma_ca; each channel reads three planes around its own
// sigma_ca (fur_locate_colour). The LUT's own colour (what the CPU's methods without a colour
// evaluate) is `BakedBcsdf::absorption()` on the host; validate colours there too
// (`Absorption::from_sigma`): here NaN and negative channels read as 0 (lossless) and
// channels above 1000 as 1000.
//
// Binding: group 0, binding 0 = the LUT words; binding 3 = the dual-scattering blob's words
// (`fur_eval_dual`, docs/model.md §13, its section below). The entry points at the end
// (bindings 1 and 2) serve the tests and `viewer probe --gpu`; an engine includes the
// functions and calls `fur_eval_far` / `fur_eval_far_dirs` / `fur_eval_dual` /
// `fur_eval_dual_dirs` from its own shaders.

@group(0) @binding(0) var<storage, read> fur_lut: array<u32>;

const FUR_PI: f32 = 3.14159274;
const FUR_HALF_PI: f32 = 1.57079637;
const FUR_TAU: f32 = 6.28318548;
// cos^2(theta_i) floor of the 1/cos^2 factor (model::MIN_COS2_THETA_I).
const FUR_MIN_COS2: f32 = 1e-4;
// Width of the pole slivers where that floor acts (model::POLE_SLIVER).
const FUR_POLE_SLIVER: f32 = 0.010000167;
// Halves before the first table: the 168-byte header (LUT format 5).
const FUR_HEADER_HALVES: u32 = 84u;
// Header words: n_abs (byte 36), the first table scale (byte 40), the absorption axis's
// scale s0 (byte 156, lut::absorption_scale).
const FUR_N_ABS_WORD: u32 = 9u;
const FUR_SCALE_WORD: u32 = 10u;
const FUR_ABS_SCALE_WORD: u32 = 39u;
// The largest sigma_ca of the absorption axis (lut::SIGMA_CA_MAX).
const FUR_SIGMA_CA_MAX: f32 = 1000.0;

// The far field per lobe family (R, TT, TRT, scattered), RGB each, and their sum.
struct FurFamilies {
    r: vec3<f32>,
    tt: vec3<f32>,
    trt: vec3<f32>,
    scattered: vec3<f32>,
    total: vec3<f32>,
}

// One uniform table axis: (nodes - 1)/span, the node index of x = 0, nodes - 1, nodes.
struct FurAxis {
    inv_step: f32,
    offset: f32,
    last: f32,
    nodes: u32,
}

// A location on an axis: lower node and the weight of the upper one.
struct FurLoc {
    i: u32,
    w: f32,
}

// The axis over [lo, lo + span] from 1/span (a constant), lo = 0 or -span/2 (centred):
// inv_step = (nodes - 1) * (1/span), a correctly rounded product like the CPU's (a quotient
// would not be: WGSL's division has 2.5 ulp), offset = 0 or (nodes - 1)/2, exact.
fn fur_axis(centred: bool, inv_span: f32, nodes: u32) -> FurAxis {
    let last = f32(nodes - 1u);
    return FurAxis(last * inv_span, select(0.0, 0.5 * last, centred), last, nodes);
}

// Node position u = x * inv_step + offset, as baked::Axis::locate (a compiler that fuses the
// multiply-add moves u by at most one ulp).
fn fur_locate(a: FurAxis, x: f32) -> FurLoc {
    let u = min(max(x * a.inv_step + a.offset, 0.0), a.last);
    let i = min(i32(u), i32(a.nodes) - 2);
    return FurLoc(u32(i), u - f32(i));
}

// Header word k (little-endian u32 at byte 4k).
fn fur_word(k: u32) -> u32 {
    return fur_lut[k];
}

// Half h of the blob (counted from its first byte, in halves), as f32 x 2^-112.
fn fur_half(h: u32) -> f32 {
    let word = fur_lut[h >> 1u];
    let bits = select(word & 0xffffu, word >> 16u, (h & 1u) == 1u);
    return bitcast<f32>(bits << 13u);
}

// Table scale x 2^112 of table t (0 M, 1 N, 2 M_s).
fn fur_unbias(t: u32) -> f32 {
    return bitcast<f32>(fur_word(FUR_SCALE_WORD + t)) * bitcast<f32>((127u + 112u) << 23u);
}

// Halves of one plane of table N (one absorption node): n_phi x n_theta_r texels of 4.
fn fur_n_plane_halves() -> u32 {
    return 4u * fur_word(6u) * fur_word(5u);
}

// Where a colour reads table N (BakedBcsdf::locate_colour): per RGB channel, the texel
// offset k (n_phi n_theta_r) of the first of its three planes k, k + 1, k + 2 and their
// quadratic Lagrange weights w0, w1, w2.
struct FurColour {
    plane: vec3<u32>,
    w0: vec3<f32>,
    w1: vec3<f32>,
    w2: vec3<f32>,
}

// Per channel: x = 1 - 0.4 e^(-sqrt(sigma/s_q)) - 0.6 e^(-sigma/s0) (lut::absorption_coordinate)
// as 1 - 0.4 2^(-sqrt(sigma FUR_ROOT_RATE)) - 0.6 2^(-(sigma/s0) log2 e), with fur_pow2_neg the
// CPU's math::pow2_neg (sigma kept in [0, 1000], NaN 0), u = x (n_abs - 1), k = min(floor u,
// n_abs - 3), t = u - k, weights (t - 1)(t - 2)/2, t(2 - t), t(t - 1)/2.
// lut::ROOT_RATE (log2(e)^2 / s_q) and the root term's share of the axis (lut::ROOT_SHARE).
const FUR_ROOT_RATE: f32 = 8.325475692749023;
const FUR_ROOT_SHARE: f32 = 0.4;

// 2^-y per channel, the operations of math::pow2_neg: y kept in [0, 125] (NaN 0), k = round(y)
// (ties to even), f = k - y (exact), 2^f by its Taylor polynomial of degree 7 in Estrin's
// scheme (math::estrin8, the coefficients math::POW2_TAYLOR from the highest degree), times
// 2^-k.
fn fur_pow2_neg(y_in: vec3<f32>) -> vec3<f32> {
    let y = select(min(max(y_in, vec3<f32>(0.0)), vec3<f32>(125.0)), vec3<f32>(0.0), fur_is_nan3(y_in));
    let k = round(y);
    let f = k - y;
    let f2 = f * f;
    let f4 = f2 * f2;
    let p01 = 1.5252734e-5 * f + 1.540353e-4;
    let p23 = 1.3333558e-3 * f + 9.618129e-3;
    let p45 = 5.550411e-2 * f + 0.2402265;
    let p67 = 0.6931472 * f + 1.0;
    let p = (p01 * f2 + p23) * f4 + (p45 * f2 + p67);
    return ldexp(p, -vec3<i32>(k));
}

fn fur_locate_colour(sigma_ca: vec3<f32>) -> FurColour {
    let n_abs = fur_word(FUR_N_ABS_WORD);
    let last = f32(n_abs - 1u);
    let scale = bitcast<f32>(fur_word(FUR_ABS_SCALE_WORD));
    let s = select(min(max(sigma_ca, vec3<f32>(0.0)), vec3<f32>(FUR_SIGMA_CA_MAX)), vec3<f32>(0.0), fur_is_nan3(sigma_ca));
    let e = FUR_ROOT_SHARE * fur_pow2_neg(sqrt(s * FUR_ROOT_RATE))
        + (1.0 - FUR_ROOT_SHARE) * fur_pow2_neg(s / scale * FUR_LOG2_E);
    let x = min(1.0 - e, vec3<f32>(1.0));
    let u = clamp(x * last, vec3<f32>(0.0), vec3<f32>(last));
    let k = min(vec3<u32>(u), vec3<u32>(n_abs - 3u));
    let t = u - vec3<f32>(k);
    let w0 = 0.5 * (t - 1.0) * (t - 2.0);
    let w1 = t * (2.0 - t);
    let w2 = 0.5 * t * (t - 1.0);
    return FurColour(k * (fur_word(6u) * fur_word(5u)), w0, w1, w2);
}

// cos(x) for |x| <= pi/2, the same operations as math::cos_within_half_pi: the Taylor
// polynomial of cos up to pi/4, sin(pi/2 - |x|) beyond, with pi/2 split in two floats.
fn fur_cos_within_half_pi(x: f32) -> f32 {
    let a = abs(x);
    if (a <= 0.785398185) {
        let y = a * a;
        var acc = -1.0 / 3628800.0;
        acc = acc * y + 1.0 / 40320.0;
        acc = acc * y - 1.0 / 720.0;
        acc = acc * y + 1.0 / 24.0;
        acc = acc * y - 0.5;
        return acc * y + 1.0;
    }
    // pi/2 - a = (PIO2_HI - a) + PIO2_LO, with PIO2_LO behind a select the compiler cannot
    // resolve (a <= pi/2 here): written as a constant, llvmpipe folds the two constants into
    // one float and r near the pole loses its relative precision (1/cos^2 at 89.4 deg was
    // 8e-6 off the CPU; 3e-7 with this form).
    let r = (1.57079637 - a) + select(-4.37113883e-8, 0.0, a > 4.0);
    let y = r * r;
    var acc = 1.0 / 362880.0;
    acc = acc * y - 1.0 / 5040.0;
    acc = acc * y + 1.0 / 120.0;
    acc = acc * y - 1.0 / 6.0;
    return (acc * y) * r + r;
}

// math::wrap_angle: x wrapped to (-pi, pi].
fn fur_wrap_angle(x: f32) -> f32 {
    if (x > -FUR_PI && x <= FUR_PI) {
        return x;
    }
    if (x > FUR_PI && x <= FUR_PI + FUR_TAU) {
        return x - FUR_TAU;
    }
    if (x <= -FUR_PI && x > -FUR_PI - FUR_TAU) {
        return x + FUR_TAU;
    }
    var y = x - FUR_TAU * floor((x + FUR_PI) / FUR_TAU);
    if (y <= -FUR_PI) {
        y = y + FUR_TAU;
    }
    if (y > FUR_PI) {
        y = y - FUR_TAU;
    }
    // |x| beyond about 2e8 names no direction (one ulp is over two turns): 0, as on the CPU.
    if (y > -FUR_PI && y <= FUR_PI) {
        return y;
    }
    return 0.0;
}

fn fur_zero() -> FurFamilies {
    let z = vec3<f32>(0.0);
    return FurFamilies(z, z, z, z, z);
}

fn fur_finite(x: f32) -> bool {
    // On the bits: WGSL lets a compiler assume floats are never NaN or infinite, so a float
    // comparison could be folded away.
    return (bitcast<u32>(x) & 0x7f800000u) != 0x7f800000u;
}

// The table lookups of one query (BakedBcsdf::lookups), for valid angles: M_g(theta_i +
// theta_r), M^s back and front, the 12 N channels at the query's colour (family, then RGB),
// the four families on the lossless plane (the sampler's density), |phi|/pi and
// 1/cos^2(theta_i).
struct FurLookups {
    m: array<f32, 3>,
    ms: array<f32, 2>,
    n: array<f32, 12>,
    n0: array<f32, 4>,
    front: f32,
    inv_cos2: f32,
}

fn fur_valid(theta_i: f32, theta_r: f32, phi: f32) -> bool {
    return fur_finite(theta_i) && fur_finite(theta_r) && fur_finite(phi)
        && abs(theta_i) <= FUR_HALF_PI && abs(theta_r) <= FUR_HALF_PI;
}

fn fur_lookups(theta_i: f32, theta_r: f32, phi_in: f32, sigma_ca: vec3<f32>) -> FurLookups {
    let phi = fur_wrap_angle(phi_in);
    let n_sum = fur_word(4u);
    let n_theta_r = fur_word(5u);
    let n_phi = fur_word(6u);
    let n_ms_i = fur_word(7u);
    let n_ms_r = fur_word(8u);
    let m0 = FUR_HEADER_HALVES;
    let n0 = m0 + 3u * n_sum;
    let s0 = n0 + fur_n_plane_halves() * fur_word(FUR_N_ABS_WORD);

    let abs_phi = abs(phi);
    let c = fur_cos_within_half_pi(theta_i);
    let inv_cos2 = 1.0 / max(c * c, FUR_MIN_COS2);

    // M_g(theta_i + theta_r): linear between texels i and i + 1 of table M (3 channels).
    let lm = fur_locate(fur_axis(true, 1.0 / (2.0 * FUR_PI), n_sum), theta_i + theta_r);
    let km = fur_unbias(0u);
    let wm0 = (1.0 - lm.w) * km;
    let wm1 = lm.w * km;
    var m: array<f32, 3>;
    for (var ch = 0u; ch < 3u; ch = ch + 1u) {
        let a = fur_half(m0 + 3u * lm.i + ch);
        let b = fur_half(m0 + 3u * (lm.i + 1u) + ch);
        m[ch] = wm0 * a + wm1 * b;
    }
    let norm = fur_sphere_norms(theta_r);
    for (var ch = 0u; ch < 3u; ch = ch + 1u) {
        m[ch] = m[ch] * norm[ch];
    }

    // M^s_back, M^s_front at (theta_i, theta_r): bilinear in table M_s (2 channels).
    let ly = fur_locate(fur_axis(true, 1.0 / FUR_PI, n_ms_r), theta_r);
    let lx = fur_locate(fur_axis(true, 1.0 / FUR_PI, n_ms_i), theta_i);
    let ks = fur_unbias(2u);
    var ms: array<f32, 2>;
    {
        let ky0 = (1.0 - ly.w) * ks;
        let ky1 = ly.w * ks;
        let w0 = ky0 * (1.0 - lx.w);
        let w1 = ky0 * lx.w;
        let w2 = ky1 * (1.0 - lx.w);
        let w3 = ky1 * lx.w;
        let i0 = ly.i * n_ms_i + lx.i;
        for (var ch = 0u; ch < 2u; ch = ch + 1u) {
            let t0 = fur_half(s0 + 2u * i0 + ch);
            let t1 = fur_half(s0 + 2u * (i0 + 1u) + ch);
            let b0 = fur_half(s0 + 2u * (i0 + n_ms_i) + ch);
            let b1 = fur_half(s0 + 2u * (i0 + n_ms_i + 1u) + ch);
            ms[ch] = w0 * t0 + w1 * t1 + w2 * b0 + w3 * b1;
        }
    }
    let front_w = min(abs_phi * (1.0 / FUR_PI), 1.0);

    // N (12 channels: family, then RGB) at (|theta_r|, |phi|) and the colour: per channel,
    // bilinear in each of its three planes, the planes weighted quadratically
    // (texels::n_at_colour: the six rows of the left texels in plane order, the same for the
    // right texels, then left + right, kept >= 0).
    let lr = fur_locate(fur_axis(false, 1.0 / FUR_HALF_PI, n_theta_r), abs(theta_r));
    let lp = fur_locate(fur_axis(false, 1.0 / FUR_PI, n_phi), abs_phi);
    let kn = fur_unbias(1u);
    let ny0 = (1.0 - lr.w) * kn;
    let ny1 = lr.w * kn;
    let v0 = ny0 * (1.0 - lp.w);
    let v1 = ny0 * lp.w;
    let v2 = ny1 * (1.0 - lp.w);
    let v3 = ny1 * lp.w;
    let j0 = lr.i * n_phi + lp.i;
    let col = fur_locate_colour(sigma_ca);
    let plane = fur_n_plane_halves();
    var n: array<f32, 12>;
    for (var c = 0u; c < 3u; c = c + 1u) {
        let tw = vec3<f32>(col.w0[c], col.w1[c], col.w2[c]);
        // Left and right weights of the rows (texels::plane_weights).
        let l = array<f32, 6>(tw.x * v0, tw.x * v2, tw.y * v0, tw.y * v2, tw.z * v0, tw.z * v2);
        let r = array<f32, 6>(tw.x * v1, tw.x * v3, tw.y * v1, tw.y * v3, tw.z * v1, tw.z * v3);
        // First half of each row's left texel: planes k, k + 1, k + 2, rows |theta_r| and the next.
        let h = n0 + 4u * (col.plane[c] + j0);
        let rows = array<u32, 6>(h, h + 4u * n_phi, h + plane, h + plane + 4u * n_phi, h + 2u * plane, h + 2u * plane + 4u * n_phi);
        for (var f = 0u; f < 4u; f = f + 1u) {
            var left = fur_half(rows[0] + f) * l[0];
            var right = fur_half(rows[0] + 4u + f) * r[0];
            for (var i = 1u; i < 6u; i = i + 1u) {
                left = left + fur_half(rows[i] + f) * l[i];
                right = right + fur_half(rows[i] + 4u + f) * r[i];
            }
            n[3u * f + c] = max(left + right, 0.0);
        }
    }
    // The lossless plane's four families (texels::n_lossless).
    var nl: array<f32, 4>;
    for (var f = 0u; f < 4u; f = f + 1u) {
        let t0 = fur_half(n0 + 4u * j0 + f);
        let t1 = fur_half(n0 + 4u * (j0 + 1u) + f);
        let b0 = fur_half(n0 + 4u * (j0 + n_phi) + f);
        let b1 = fur_half(n0 + 4u * (j0 + n_phi + 1u) + f);
        nl[f] = v0 * t0 + v1 * t1 + v2 * b0 + v3 * b1;
    }

    return FurLookups(m, ms, n, nl, front_w, inv_cos2);
}

// Far-field S per family from the lookups (BakedBcsdf::assemble).
fn fur_assemble(l: FurLookups) -> FurFamilies {
    let mss = l.ms[0] + l.front * (l.ms[1] - l.ms[0]);
    let lon = array<f32, 4>(l.m[0], l.m[1], l.m[2], mss);
    var f: array<vec3<f32>, 4>;
    for (var k = 0u; k < 4u; k = k + 1u) {
        let weight = lon[k] * l.inv_cos2;
        f[k] = vec3<f32>(l.n[3u * k], l.n[3u * k + 1u], l.n[3u * k + 2u]) * weight;
    }
    return FurFamilies(f[0], f[1], f[2], f[3], ((f[0] + f[1]) + f[2]) + f[3]);
}

// Far-field S per lobe family at colour sigma_ca (BakedBcsdf::at(..).eval_far). theta_i,
// theta_r in [-pi/2, pi/2], any finite phi; anything else gives 0.
fn fur_eval_far(theta_i: f32, theta_r: f32, phi: f32, sigma_ca: vec3<f32>) -> FurFamilies {
    if (!fur_valid(theta_i, theta_r, phi)) {
        return fur_zero();
    }
    return fur_assemble(fur_lookups(theta_i, theta_r, phi, sigma_ca));
}

// asin and atan2 as the baked evaluator's direction conversion computes them on the CPU
// (math::asin_polynomial, math::atan2_polynomial, frame::polynomial_angles): branch-free
// polynomials with the same operations in the same order, so that angles from vectors agree
// to an ulp or two; the GPU built-ins are far less precise (llvmpipe's moved results by 1e-2
// on a lobe's flank).
fn fur_asin(x: f32) -> f32 {
    // Abramowitz & Stegun 4.4.46, Estrin's scheme (math::estrin8) from the highest
    // coefficient.
    let ax = min(abs(x), 1.0);
    let x2 = ax * ax;
    let x4 = x2 * x2;
    let p01 = -0.001262491 * ax + 0.00667009;
    let p23 = -0.017088126 * ax + 0.03089188;
    let p45 = -0.050174303 * ax + 0.08897899;
    let p67 = -0.2145988 * ax + FUR_HALF_PI;
    let poly = (p01 * x2 + p23) * x4 + (p45 * x2 + p67);
    let r = FUR_HALF_PI - sqrt(1.0 - ax) * poly;
    // copysign(r, x), as on the CPU.
    return select(abs(r), -abs(r), (bitcast<u32>(x) & 0x80000000u) != 0u);
}

// The degree-7 polynomial c0 x^7 + ... + c7 by Estrin's scheme (math::estrin8).
fn fur_atan_poly(t: f32) -> f32 {
    let t2 = t * t;
    let t4 = t2 * t2;
    let p01 = 0.0029202348 * t + -0.016366188;
    let p23 = 0.043209206 * t + -0.07552008;
    let p45 = 0.10665919 * t + -0.14211038;
    let p67 = 0.19993772 * t + -0.33333153;
    return (p01 * t2 + p23) * t4 + (p45 * t2 + p67);
}

fn fur_atan2(y: f32, x: f32) -> f32 {
    let ax = abs(x);
    let ay = abs(y);
    let a = min(ax, ay) / max(max(ax, ay), 1.17549435e-38);
    let t = a * a;
    var r = a + a * (t * fur_atan_poly(t));
    r = select(r, FUR_HALF_PI - r, ay > ax);
    r = select(r, FUR_PI - r, x < 0.0);
    // copysign(r, y) (r >= 0 here).
    return select(r, -r, (bitcast<u32>(y) & 0x80000000u) != 0u);
}

// The angles of world-space vectors (frame::polynomial_angles): theta_i, theta_r, |phi|, and
// whether the vectors were usable (finite, none of zero length); the angles are 0 if not.
struct FurDirAngles {
    theta_i: f32,
    theta_r: f32,
    phi: f32,
    ok: bool,
}

// wi toward the light, wr toward the viewer, u the fiber tangent; none needs unit length.
// phi from unnormalised vectors: y = u.(wi x wr)/|u|, x = wi.wr - (wi.u)(wr.u)/|u|^2.
fn fur_angles_from_dirs(wi: vec3<f32>, wr: vec3<f32>, u: vec3<f32>) -> FurDirAngles {
    let none = FurDirAngles(0.0, 0.0, 0.0, false);
    let ii = dot(wi, wi);
    let rr = dot(wr, wr);
    let uu = dot(u, u);
    if (!(fur_finite(ii) && fur_finite(rr) && fur_finite(uu))) {
        return none;
    }
    let ni = sqrt(ii);
    let nr = sqrt(rr);
    let nu = sqrt(uu);
    let min_positive = 1.17549435e-38;
    if (ni < min_positive || nr < min_positive || nu < min_positive) {
        return none;
    }
    let un = u * (1.0 / nu);
    let a = dot(wi, un);
    let b = dot(wr, un);
    let theta_i = fur_asin(clamp(a * (1.0 / ni), -1.0, 1.0));
    let theta_r = fur_asin(clamp(b * (1.0 / nr), -1.0, 1.0));
    let y = dot(un, cross(wi, wr));
    let x = dot(wi, wr) - a * b;
    return FurDirAngles(theta_i, theta_r, abs(fur_atan2(y, x)), true);
}

// Far-field S from world-space vectors at colour sigma_ca (BakedAt::eval_far_dirs), at the
// angles of fur_angles_from_dirs; 0 for unusable vectors.
fn fur_eval_far_dirs(wi: vec3<f32>, wr: vec3<f32>, u: vec3<f32>, sigma_ca: vec3<f32>) -> FurFamilies {
    let a = fur_angles_from_dirs(wi, wr, u);
    if (!a.ok) {
        return fur_zero();
    }
    return fur_eval_far(a.theta_i, a.theta_r, a.phi, sigma_ca);
}

// ---- Sampling and pdf (sampling::baked, docs/model.md §10) ----
//
// The mixture of five separable parts (R, TT, TRT, scattered back, front), each row inverted
// exactly from the LUT's sampling section (prefix sums, docs/lut.md "Sampling data"), as
// `BakedBcsdf::sample` / `pdf` do it.

// A sampled direction: theta_i, phi, pdf (per unit solid angle), weight S cos(theta_i)/pdf,
// family (0 R, 1 TT, 2 TRT, 3 scattered); ok is false when nothing could be sampled.
struct FurSample {
    theta_i: f32,
    phi: f32,
    pdf: f32,
    weight: vec3<f32>,
    family: u32,
    ok: bool,
}

// Where one density's prefix entries are (lut::cdf::DensityLayout).
struct FurDensity {
    prefix_at: u32,   // byte offset
    entries: u32,
    nodes: u32,
    rows: u32,
    step: f32,
    block: u32,
    table: u32,       // 0 M, 1 N (its lossless plane), 2 M_s
    channel: u32,
}

// f32 at an even byte offset of the blob.
fn fur_f32_at(byte: u32) -> f32 {
    let w = byte >> 2u;
    if ((byte & 3u) == 0u) {
        return bitcast<f32>(fur_lut[w]);
    }
    return bitcast<f32>((fur_lut[w] >> 16u) | (fur_lut[w + 1u] << 16u));
}

fn fur_entries(nodes: u32, block: u32) -> u32 {
    return (nodes - 1u + block - 1u) / block + 1u;
}

// Density d in section order: 0..2 M_g, 3..6 N_f, 7..8 M^s_x, 9 the front-weighted N^s
// (lut::cdf::Density::Front).
fn fur_density(d: u32) -> FurDensity {
    let n_sum = fur_word(4u);
    let n_theta_r = fur_word(5u);
    let n_phi = fur_word(6u);
    let n_ms_i = fur_word(7u);
    let n_ms_r = fur_word(8u);
    let values = 3u * n_sum + fur_n_plane_halves() * fur_word(FUR_N_ABS_WORD) + 2u * n_ms_i * n_ms_r;
    var at = 2u * FUR_HEADER_HALVES + 2u * values;
    let e_m = fur_entries(n_sum, 1u);
    let e_n = fur_entries(n_phi, 8u);
    let e_s = fur_entries(n_ms_i, 8u);
    if (d < 3u) {
        return FurDensity(at + 4u * d * e_m, e_m, n_sum, 1u, 2.0 * FUR_PI / f32(n_sum - 1u), 1u, 0u, d);
    }
    at = at + 4u * 3u * e_m;
    if (d < 7u) {
        let f = d - 3u;
        return FurDensity(at + 4u * f * n_theta_r * e_n, e_n, n_phi, n_theta_r, FUR_PI / f32(n_phi - 1u), 8u, 1u, f);
    }
    at = at + 4u * 4u * n_theta_r * e_n;
    if (d < 9u) {
        let x = d - 7u;
        return FurDensity(at + 4u * x * n_ms_r * e_s, e_s, n_ms_i, n_ms_r, FUR_PI / f32(n_ms_i - 1u), 8u, 2u, x);
    }
    at = at + 4u * 2u * n_ms_r * e_s;
    return FurDensity(at, e_n, n_phi, n_theta_r, FUR_PI / f32(n_phi - 1u), 8u, 1u, 3u);
}

// lut::cdf::Nodes::value: density node value at (row, j) (table N: its lossless plane).
fn fur_node(d: FurDensity, row: u32, j: u32) -> f32 {
    let m0 = FUR_HEADER_HALVES;
    let n0 = m0 + 3u * fur_word(4u);
    let s0 = n0 + fur_n_plane_halves() * fur_word(FUR_N_ABS_WORD);
    let starts = array<u32, 3>(m0, n0, s0);
    let chans = array<u32, 3>(3u, 4u, 2u);
    let base = starts[d.table] + (row * d.nodes + j) * chans[d.table] + d.channel;
    return fur_half(base) * fur_unbias(d.table);
}

// Two rows of a density blended with weights (1 - w, w), weighted along |phi| by the
// scattered blend (sampling::baked::rows::Weighting): 0 one, 1 back (1 - |phi|/pi; prefix
// sums N^s's less density 9's), 2 front (|phi|/pi; density 9).
struct FurRows {
    d: FurDensity,
    r0: u32,
    r1: u32,
    w: f32,
    origin: f32,
    weighting: u32,
}

fn fur_rows(d: FurDensity, row: u32, w: f32, origin: f32) -> FurRows {
    return FurRows(d, min(row, d.rows - 1u), min(row + 1u, d.rows - 1u), w, origin, 0u);
}

// The scattered |phi| rows weighted by 1 - |phi|/pi (weighting 1, Rows::back) or |phi|/pi
// (weighting 2, density 9, Rows::new of Density::Front).
fn fur_rows_weighted(weighting: u32, row: u32, w: f32) -> FurRows {
    let d = fur_density(select(6u, 9u, weighting == 2u));
    return FurRows(d, min(row, d.rows - 1u), min(row + 1u, d.rows - 1u), w, 0.0, weighting);
}

fn fur_rows_value(r: FurRows, j: u32) -> f32 {
    let v0 = fur_node(r.d, r.r0, j);
    if (r.w == 0.0) {
        return v0;
    }
    let v1 = fur_node(r.d, r.r1, j);
    return (1.0 - r.w) * v0 + r.w * v1;
}

fn fur_blended_prefix(r: FurRows, d: FurDensity, k: u32) -> f32 {
    let p0 = fur_f32_at(d.prefix_at + 4u * (r.r0 * d.entries + k));
    if (r.w == 0.0) {
        return p0;
    }
    let p1 = fur_f32_at(d.prefix_at + 4u * (r.r1 * d.entries + k));
    return (1.0 - r.w) * p0 + r.w * p1;
}

fn fur_rows_prefix(r: FurRows, k: u32) -> f32 {
    let p = fur_blended_prefix(r, r.d, k);
    if (r.weighting == 1u) {
        return p - fur_blended_prefix(r, fur_density(9u), k);
    }
    return p;
}

fn fur_rows_total(r: FurRows) -> f32 {
    return fur_rows_prefix(r, r.d.entries - 1u);
}

fn fur_linear_mass(v0: f32, v1: f32, len: f32) -> f32 {
    return 0.5 * len * (v0 + v1);
}

// sampling::invert_linear.
fn fur_invert_linear(v0: f32, v1: f32, len: f32, t: f32) -> f32 {
    if (!(len > 0.0)) {
        return 0.0;
    }
    var s = 0.0;
    if (t > 0.0) {
        let disc = max(v0 * v0 + 2.0 * (v1 - v0) * t / len, 0.0);
        let den = v0 + sqrt(disc);
        if (den > 0.0) {
            s = clamp(2.0 * t / den, 0.0, len);
        } else {
            s = len;
        }
    }
    let inset = len * (1.0 / 1048576.0);
    if (v0 <= 0.0 && s < inset) {
        return inset;
    }
    if (v1 <= 0.0 && s > len - inset) {
        return len - inset;
    }
    return s;
}

// sampling::weighted_linear_mass.
fn fur_weighted_linear_mass(v0: f32, v1: f32, a: f32, b: f32, len: f32) -> f32 {
    return len * (a * v0 + 0.5 * (a * v1 + b * v0) + b * v1) * (1.0 / 3.0);
}

// sampling::invert_weighted_linear: Newton steps on the cubic inside a shrinking bracket.
fn fur_invert_weighted_linear(v0: f32, v1: f32, a: f32, b: f32, len: f32, t: f32) -> f32 {
    if (!(len > 0.0)) {
        return 0.0;
    }
    let ca = a * v0;
    let cb = a * (v1 - v0) + v0 * (b - a);
    let cc = (b - a) * (v1 - v0);
    let q0 = ca;
    let q1 = b * v1;
    let goal = t / len;
    let total = ca + 0.5 * cb + (1.0 / 3.0) * cc;
    let lin = 0.5 * (q0 + q1);
    var x = 0.5;
    if (total > 0.0 && lin > 0.0) {
        x = fur_invert_linear(q0, q1, 1.0, goal * (lin / total));
    }
    var lo = 0.0;
    var hi = 1.0;
    for (var k = 0u; k < 8u; k = k + 1u) {
        let fx = x * (ca + x * (0.5 * cb + x * (1.0 / 3.0) * cc)) - goal;
        if (fx > 0.0) {
            hi = x;
        } else {
            lo = x;
        }
        let d = ca + x * (cb + x * cc);
        var next = 0.5 * (lo + hi);
        if (d > 0.0) {
            let n = x - fx / d;
            if (n >= lo && n <= hi) {
                next = n;
            }
        }
        let done = abs(next - x) <= 1.2e-7;
        x = next;
        if (done) {
            break;
        }
    }
    let s = clamp(x * len, 0.0, len);
    let inset = len * (1.0 / 1048576.0);
    if (q0 <= 0.0 && s < inset) {
        return inset;
    }
    if (q1 <= 0.0 && s > len - inset) {
        return len - inset;
    }
    return s;
}

// The weights at nodes j and j + 1 of a weighted row (Rows::weights).
fn fur_rows_weights(r: FurRows, j: u32) -> vec2<f32> {
    let inv = 1.0 / f32(r.d.nodes - 1u);
    let ab = vec2<f32>(f32(j) * inv, f32(j + 1u) * inv);
    if (r.weighting == 1u) {
        return vec2<f32>(1.0 - ab.x, 1.0 - ab.y);
    }
    return ab;
}

// Rows::segment_mass.
fn fur_rows_segment_mass(r: FurRows, j: u32, v0: f32, v1: f32) -> f32 {
    if (r.weighting == 0u) {
        return fur_linear_mass(v0, v1, r.d.step);
    }
    let ab = fur_rows_weights(r, j);
    return fur_weighted_linear_mass(v0, v1, ab.x, ab.y, r.d.step);
}

// Rows::invert_segment.
fn fur_rows_invert_segment(r: FurRows, j: u32, v0: f32, v1: f32, t: f32) -> f32 {
    if (r.weighting == 0u) {
        return fur_invert_linear(v0, v1, r.d.step, t);
    }
    let ab = fur_rows_weights(r, j);
    return fur_invert_weighted_linear(v0, v1, ab.x, ab.y, r.d.step, t);
}

fn fur_unit(u: f32) -> f32 {
    if (u > 0.0) {
        return min(u, 0.99999994);
    }
    return 0.0;
}

// Rows::invert: the axis position where the running integral reaches t.
fn fur_rows_invert(r: FurRows, t: f32) -> f32 {
    var lo = 0u;
    var len = r.d.entries - 1u;
    loop {
        if (len <= 1u) {
            break;
        }
        let half = len / 2u;
        lo = select(lo, lo + half, fur_rows_prefix(r, lo + half) < t);
        len = len - half;
    }
    let first = lo * r.d.block;
    let end = min(first + r.d.block, r.d.nodes - 1u);
    var acc = fur_rows_prefix(r, lo);
    var prev = fur_rows_value(r, first);
    var have_last = false;
    var last_j = 0u;
    var last_v0 = 0.0;
    var last_v1 = 0.0;
    var last_m = 0.0;
    for (var j = first; j < end; j = j + 1u) {
        let v = fur_rows_value(r, j + 1u);
        let m = fur_rows_segment_mass(r, j, prev, v);
        if (m > 0.0) {
            if (t - acc <= m) {
                let s = fur_rows_invert_segment(r, j, prev, v, t - acc);
                return r.origin + f32(j) * r.d.step + s;
            }
            have_last = true;
            last_j = j;
            last_v0 = prev;
            last_v1 = v;
            last_m = m;
        }
        acc = acc + m;
        prev = v;
    }
    if (have_last) {
        let whole = select(last_m, r.d.step * (last_v0 + last_v1), r.weighting == 0u);
        let s = fur_rows_invert_segment(r, last_j, last_v0, last_v1, whole);
        return r.origin + f32(last_j) * r.d.step + s;
    }
    return r.origin + f32(end) * r.d.step;
}

fn fur_rows_invert_between(r: FurRows, t0: f32, t1: f32, u: f32) -> f32 {
    let inset = (t1 - t0) * (1.0 / 1048576.0);
    let t = clamp(t0 + fur_unit(u) * (t1 - t0), t0 + inset, t1 - inset);
    return fur_rows_invert(r, t);
}

// ---- The pole slivers (sampling::sliver, docs/model.md §10) ----

// sampling::sliver::pole_keep: g = min(1, cos^2/1e-4), cos kept at or above 1e-6.
fn fur_pole_keep(cos_theta_i: f32) -> f32 {
    let c = max(cos_theta_i, 1e-6);
    return min(c * c * (1.0 / FUR_MIN_COS2), 1.0);
}

// sampling::sliver::sliver_keep: (s^2 - s^4/3)/1e-4 within a sliver, 1 beyond.
fn fur_sliver_keep(s_in: f32) -> f32 {
    let s = abs(s_in);
    if (!(s < FUR_POLE_SLIVER)) {
        return 1.0;
    }
    let s2 = s * s;
    return min(s2 * (1.0 - s2 * (1.0 / 3.0)) * (1.0 / FUR_MIN_COS2), 1.0);
}

// sampling::sliver::sliver_piece_mass: three-point Gauss-Legendre of v * keep over the first
// len of a linear piece of length len0 starting at x0.
fn fur_sliver_piece_mass(v0: f32, v1: f32, len0: f32, x0: f32, pole: f32, len: f32) -> f32 {
    if (!(len > 0.0 && len0 > 0.0)) {
        return 0.0;
    }
    let slope = (v1 - v0) / len0;
    let t = array<f32, 3>(0.11270166, 0.5, 0.8872983);
    let w = array<f32, 3>(5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0);
    var acc = 0.0;
    for (var k = 0u; k < 3u; k = k + 1u) {
        let d = t[k] * len;
        acc = acc + w[k] * (v0 + slope * d) * fur_sliver_keep((x0 - pole) + d);
    }
    return acc * len;
}

// sampling::sliver::invert_sliver_piece: bracketed Newton steps, at most sixteen.
fn fur_invert_sliver_piece(v0: f32, v1: f32, len: f32, x0: f32, pole: f32, t: f32) -> f32 {
    let total = fur_sliver_piece_mass(v0, v1, len, x0, pole, len);
    if (!(total > 0.0) || !(t > 0.0)) {
        return 0.0;
    }
    if (!(t < total)) {
        return len;
    }
    let slope = (v1 - v0) / len;
    var lo = 0.0;
    var hi = len;
    var d = len * (t / total);
    for (var k = 0u; k < 16u; k = k + 1u) {
        let f = fur_sliver_piece_mass(v0, v1, len, x0, pole, d) - t;
        if (f > 0.0) {
            hi = d;
        } else {
            lo = d;
        }
        let dens = (v0 + slope * d) * fur_sliver_keep((x0 - pole) + d);
        var next = 0.5 * (lo + hi);
        if (dens > 0.0) {
            let n = d - f / dens;
            if (n >= lo && n <= hi) {
                next = n;
            }
        }
        let done = abs(next - d) <= 1.2e-7 * len;
        d = next;
        if (done) {
            break;
        }
    }
    return clamp(d, 0.0, len);
}

// Rows::sliver: (raw mass, mass times g) of the sliver [a, b] with a pole at a or b, or, with
// t >= 0 (Rows::invert_sliver), in .z the position where the mass times g from a reaches t
// (b past its mass). The pieces between the nodes as Rows::pieces finds them: by the axis's
// location of a and b, lengths from node weights times the spacing.
fn fur_rows_sliver(r: FurRows, ax: FurAxis, a: f32, b: f32, pole: f32, t: f32) -> vec3<f32> {
    let la = fur_locate(ax, a);
    let lb = fur_locate(ax, b);
    let at = a - pole;
    var off = 0.0;
    var out = vec3<f32>(0.0, 0.0, b);
    for (var j = la.i; j <= lb.i; j = j + 1u) {
        let w0 = select(0.0, la.w, j == la.i);
        let w1 = select(1.0, lb.w, j == lb.i);
        if (w1 > w0) {
            let n0 = fur_rows_value(r, j);
            let n1 = fur_rows_value(r, j + 1u);
            let len = (w1 - w0) * r.d.step;
            let v0 = n0 + (n1 - n0) * w0;
            let v1 = n0 + (n1 - n0) * w1;
            let m = fur_sliver_piece_mass(v0, v1, len, at + off, 0.0, len);
            if (t >= 0.0 && m > 0.0 && t - out.y <= m) {
                out.z = a + (off + fur_invert_sliver_piece(v0, v1, len, at + off, 0.0, t - out.y));
                return out;
            }
            out.x = out.x + fur_linear_mass(v0, v1, len);
            out.y = out.y + m;
            off = off + len;
        }
    }
    return out;
}

// Rows::range: a part's theta_i range [lo, hi] and its masses; slivers (raw, kept) at lo
// (.xy of s) and hi (.zw).
struct FurRange {
    lo: f32,
    hi: f32,
    start: f32,
    raw: f32,
    s: vec4<f32>,
}

fn fur_rows_range(r: FurRows, ax: FurAxis, lo: f32, hi: f32, start: f32, raw: f32) -> FurRange {
    let a = fur_rows_sliver(r, ax, lo, lo + FUR_POLE_SLIVER, lo, -1.0);
    let b = fur_rows_sliver(r, ax, hi - FUR_POLE_SLIVER, hi, hi, -1.0);
    return FurRange(lo, hi, start, raw, vec4<f32>(a.x, a.y, b.x, b.y));
}

// Range::kept.
fn fur_range_kept(g: FurRange) -> f32 {
    return max(g.raw - g.s.x - g.s.z, 0.0) + g.s.y + g.s.w;
}

// Rows::invert_kept.
fn fur_rows_invert_kept(r: FurRows, ax: FurAxis, g: FurRange, u: f32) -> f32 {
    let total = fur_range_kept(g);
    let inset = total * (1.0 / 1048576.0);
    let t0 = clamp(fur_unit(u) * total, inset, total - inset);
    if (t0 < g.s.y) {
        return fur_rows_sliver(r, ax, g.lo, g.lo + FUR_POLE_SLIVER, g.lo, t0).z;
    }
    let mid = max(g.raw - g.s.x - g.s.z, 0.0);
    let t = t0 - g.s.y;
    if (t <= mid || !(g.s.w > 0.0)) {
        return fur_rows_invert(r, g.start + g.s.x + min(t, mid));
    }
    return fur_rows_sliver(r, ax, g.hi - FUR_POLE_SLIVER, g.hi, g.hi, t - mid).z;
}

// The three M CDFs and interpolated values at a location on the sum axis, from one texel
// pair (BakedBcsdf::m_cdf_and_value).
struct FurMAt {
    cdf: vec3<f32>,
    value: vec3<f32>,
}

fn fur_sum_axis() -> FurAxis {
    return fur_axis(true, 1.0 / (2.0 * FUR_PI), fur_word(4u));
}

fn fur_m_at(l: FurLoc) -> FurMAt {
    let d0 = fur_density(0u);
    let off = l.w * d0.step;
    var out = FurMAt(vec3<f32>(0.0), vec3<f32>(0.0));
    for (var g = 0u; g < 3u; g = g + 1u) {
        let d = fur_density(g);
        let v0 = fur_node(d, 0u, l.i);
        let v1 = fur_node(d, 0u, l.i + 1u);
        let at = v0 + (v1 - v0) * l.w;
        out.cdf[g] = fur_f32_at(d.prefix_at + 4u * l.i) + fur_linear_mass(v0, at, off);
        out.value[g] = at;
    }
    return out;
}

// The three M CDFs at x (BakedBcsdf::m_cdf).
fn fur_m_cdf(x: f32) -> vec3<f32> {
    return fur_m_at(fur_locate(fur_sum_axis(), x)).cdf;
}

// Header word of the closure (byte 108, after g): 0 report, 1 energy (docs/model.md §12).
const FUR_CLOSURE_WORD: u32 = 27u;

// Byte offset of the 1/Z_g table (lut::LutResolution::norm_start): the end of the sampling
// section, i.e. of its last density (the front-weighted N^s).
fn fur_norm_start() -> u32 {
    let d = fur_density(9u);
    return d.prefix_at + 4u * d.rows * d.entries;
}

// The energy closure's factor M_g / (tabulated M_g) at theta_r (BakedBcsdf::sphere_norms):
// 1/Z_g(theta_r) interpolated linearly in the LUT's 1/Z_g table (lut::norms, n_sum nodes over
// theta_r in [-pi/2, pi/2], the three groups adjacent); 1 in the report closure.
fn fur_sphere_norms(theta_r: f32) -> vec3<f32> {
    if (fur_word(FUR_CLOSURE_WORD) != 1u) {
        return vec3<f32>(1.0);
    }
    let l = fur_locate(fur_axis(true, 1.0 / FUR_PI, fur_word(4u)), theta_r);
    let at = fur_norm_start() + 12u * l.i;
    var out = vec3<f32>(0.0);
    for (var g = 0u; g < 3u; g = g + 1u) {
        let z0 = fur_f32_at(at + 4u * g);
        out[g] = z0 + (fur_f32_at(at + 12u + 4u * g) - z0) * l.w;
    }
    return out;
}

fn fur_row_total(d: FurDensity, l: FurLoc) -> f32 {
    let t0 = fur_f32_at(d.prefix_at + 4u * (min(l.i, d.rows - 1u) * d.entries + d.entries - 1u));
    let t1 = fur_f32_at(d.prefix_at + 4u * (min(l.i + 1u, d.rows - 1u) * d.entries + d.entries - 1u));
    return t0 + (t1 - t0) * l.w;
}

fn fur_positive(v: f32) -> f32 {
    return select(0.0, v, fur_finite(v) && v > 0.0);
}

// Mixture weights A_c(theta_r) and the parts' theta_i ranges, every mass with S's pole factor
// g (BakedBcsdf::parts).
struct FurParts {
    a: array<f32, 5>,
    ranges: array<FurRange, 5>,
}

// The M^s theta_i axis (baked::BakedBcsdf's ms_i).
fn fur_ms_i_axis() -> FurAxis {
    return fur_axis(true, 1.0 / FUR_PI, fur_word(7u));
}

fn fur_ms_rows(half: u32, theta_r: f32) -> FurRows {
    let sr = fur_locate(fur_axis(true, 1.0 / FUR_PI, fur_word(8u)), theta_r);
    return fur_rows(fur_density(7u + half), sr.i, sr.w, -FUR_HALF_PI);
}

fn fur_parts(theta_r: f32) -> FurParts {
    let lo_x = theta_r - FUR_HALF_PI;
    let hi_x = theta_r + FUR_HALF_PI;
    let lo = fur_m_cdf(lo_x);
    let hi = fur_m_cdf(hi_x);
    let mass = max(hi - lo, vec3<f32>(0.0));
    let nr = fur_locate(fur_axis(false, 1.0 / FUR_HALF_PI, fur_word(5u)), abs(theta_r));
    let nu_s = fur_row_total(fur_density(6u), nr);
    let mu_s = fur_row_total(fur_density(9u), nr);
    var ranges: array<FurRange, 5>;
    for (var g = 0u; g < 3u; g = g + 1u) {
        let rows = fur_rows(fur_density(g), 0u, 0.0, -FUR_PI);
        ranges[g] = fur_rows_range(rows, fur_sum_axis(), lo_x, hi_x, lo[g], mass[g]);
    }
    for (var x = 0u; x < 2u; x = x + 1u) {
        let rows = fur_ms_rows(x, theta_r);
        ranges[3u + x] = fur_rows_range(rows, fur_ms_i_axis(), -FUR_HALF_PI, FUR_HALF_PI, 0.0, fur_rows_total(rows));
    }
    // The mass of the evaluated M_g: the tabulated one times the closure's factor.
    let kept = vec3<f32>(fur_range_kept(ranges[0]), fur_range_kept(ranges[1]), fur_range_kept(ranges[2])) * fur_sphere_norms(theta_r);
    let a = array<f32, 5>(
        fur_positive(2.0 * kept.x * fur_row_total(fur_density(3u), nr)),
        fur_positive(2.0 * kept.y * fur_row_total(fur_density(4u), nr)),
        fur_positive(2.0 * kept.z * fur_row_total(fur_density(5u), nr)),
        fur_positive(2.0 * fur_range_kept(ranges[3]) * (nu_s - mu_s)),
        fur_positive(2.0 * fur_range_kept(ranges[4]) * mu_s),
    );
    return FurParts(a, ranges);
}

// The mixture density per unit solid angle from the lookups and W (BakedBcsdf::density): the
// lossless plane's N, the same for every colour.
fn fur_density_of(l: FurLookups, w: f32, cos_theta_i: f32) -> f32 {
    if (!(w > 0.0)) {
        return 0.0;
    }
    // M^s's blend exactly as fur_assemble forms it.
    let ms = l.ms[0] + l.front * (l.ms[1] - l.ms[0]);
    let p = l.m[0] * l.n0[0] + l.m[1] * l.n0[1] + l.m[2] * l.n0[2] + ms * l.n0[3];
    // S's pole factor g (exactly 1 outside the slivers).
    let pg = p * fur_pole_keep(cos_theta_i);
    return fur_positive((pg / w) / max(cos_theta_i, 1e-6));
}

// Density per unit solid angle with which fur_sample_far draws omega_i (Bcsdf::pdf); 0 for
// invalid angles. The sampler draws from the lossless plane, so the density is the same at
// every colour: sigma_ca is taken for the same call shape as the other functions (and
// BakedAt::pdf), and does not change the result.
fn fur_pdf_far(theta_i: f32, theta_r: f32, phi: f32, sigma_ca: vec3<f32>) -> f32 {
    if (!fur_valid(theta_i, theta_r, phi)) {
        return 0.0;
    }
    let p = fur_parts(theta_r);
    let w = ((p.a[0] + p.a[1]) + p.a[2] + p.a[3]) + p.a[4];
    return fur_density_of(fur_lookups(theta_i, theta_r, phi, sigma_ca), w, fur_cos_within_half_pi(theta_i));
}

// Importance-samples omega_i given theta_r from three uniforms in [0, 1) at colour sigma_ca
// (BakedAt::sample): the direction and pdf are the lossless plane's, the weight
// S cos(theta_i)/pdf this colour's.
fn fur_sample_far(theta_r: f32, u: vec3<f32>, sigma_ca: vec3<f32>) -> FurSample {
    var out = FurSample(0.0, 0.0, 0.0, vec3<f32>(0.0), 0u, false);
    if (!(fur_finite(theta_r) && abs(theta_r) <= FUR_HALF_PI)) {
        return out;
    }
    let p = fur_parts(theta_r);
    // sampling::choose over the five parts.
    var total = 0.0;
    for (var k = 0u; k < 5u; k = k + 1u) {
        total = total + p.a[k];
    }
    if (!(total > 0.0)) {
        return out;
    }
    let target_mass = fur_unit(u.x) * total;
    var acc = 0.0;
    var c = 5u;
    var u0 = 0.0;
    var last = 5u;
    for (var k = 0u; k < 5u; k = k + 1u) {
        let wk = p.a[k];
        if (!(wk > 0.0)) {
            continue;
        }
        last = k;
        if (target_mass < acc + wk) {
            c = k;
            u0 = fur_unit((target_mass - acc) / wk);
            break;
        }
        acc = acc + wk;
    }
    if (c == 5u) {
        c = last;
        u0 = 0.99999994;
    }
    let total_weight = ((p.a[0] + p.a[1]) + p.a[2] + p.a[3]) + p.a[4];
    let negative = u0 < 0.5;
    var theta_i = 0.0;
    if (c < 3u) {
        let rows = fur_rows(fur_density(c), 0u, 0.0, -FUR_PI);
        let x = fur_rows_invert_kept(rows, fur_sum_axis(), p.ranges[c], u.y);
        theta_i = clamp(x - theta_r, -FUR_HALF_PI, FUR_HALF_PI);
    } else {
        let rows = fur_ms_rows(c - 3u, theta_r);
        theta_i = clamp(fur_rows_invert_kept(rows, fur_ms_i_axis(), p.ranges[c], u.y), -FUR_HALF_PI, FUR_HALF_PI);
    }
    let family = min(c, 3u);
    let nr = fur_locate(fur_axis(false, 1.0 / FUR_HALF_PI, fur_word(5u)), abs(theta_r));
    var nrows = fur_rows(fur_density(3u + family), nr.i, nr.w, 0.0);
    if (c >= 3u) {
        nrows = fur_rows_weighted(c - 2u, nr.i, nr.w);
    }
    let abs_phi = clamp(fur_rows_invert_between(nrows, 0.0, fur_rows_total(nrows), u.z), 0.0, FUR_PI);
    let phi = fur_wrap_angle(select(abs_phi, -abs_phi, negative));
    let l = fur_lookups(theta_i, theta_r, phi, sigma_ca);
    let pdf = fur_density_of(l, total_weight, fur_cos_within_half_pi(theta_i));
    if (!(pdf > 0.0 && fur_finite(pdf))) {
        return out;
    }
    let s = fur_assemble(l);
    let k = max(cos(theta_i), 0.0) / pdf;
    out = FurSample(theta_i, phi, pdf, max(s.total * k, vec3<f32>(0.0)), family, true);
    return out;
}

// ---- Dual scattering (bcsdf_core::dual::DualLut::eval, docs/model.md §13) ----
//
// The term an engine adds to single scattering for the light that reaches a fiber through
// other fibers, from a .furdual blob (bcsdf_core::dual, blob.rs) bound as its own read-only
// storage buffer of u32 words (group 0, binding 3), validated on the CPU first
// (`DualLut::decode`): the shader trusts it. After the 64-byte header (16 words) come
// little-endian f16 halves, read with unpack2x16float (exact, as the CPU's f16 -> f32):
// - the node fields, [theta node k (64)][field f (15)][channel c (3)];
// - N^G, [family g (4)][theta node k (64)][phi node j (32)][channel c (3)].
// Every step mirrors `DualLut::eval` in the same order, with the CPU's lane functions ported
// operation for operation: rsqrt_newton (fur_rsqrt_newton), exp_neg_saturating
// (fur_exp_neg), erf_polynomial (fur_erf) and the finite coat's closed forms of
// dual/coat.rs (fur_reflectance_squared, fur_downward_flux, fur_backscatter_factor). What
// remains between the two is the GPU's rounding of division and fused multiply-adds.

@group(0) @binding(3) var<storage, read> fur_dual: array<u32>;

// Words of the .furdual header before the first half (format 2).
const FUR_DUAL_HEADER_WORDS: u32 = 20u;
// The absorption axis (dual::ABS_NODES nodes at dual::axis_node): per node one grey
// set of tables, its fields (64 x 15 halves) then its N^G (4 x 64 x 32 halves).
const FUR_DUAL_ABS_NODES: u32 = 16u;
const FUR_DUAL_NODE_HALVES: u32 = 9152u;
// The dual tables' own absorption axis (dual::axis_coordinate): knee 3, up to SIGMA_CA_MAX.
const FUR_DUAL_KNEE: f32 = 3.0;
const FUR_DUAL_SIGMA_MAX: f32 = 1000.0;
// Fields per theta node (dual::FIELDS) and their indices (blob.rs): log2 mu (the downward
// flux's decay per fiber), beta_f (rad), the local backscatter's back-half and front-half
// energy, Delta_b, sigma_b0, a_f^2, then each family's mean of x and its standard deviation.
const FUR_DUAL_FIELDS: u32 = 15u;
const FUR_DUAL_LOG2_DECAY: u32 = 0u;
const FUR_DUAL_BETA_F: u32 = 1u;
const FUR_DUAL_BACK: u32 = 2u;
const FUR_DUAL_FRONT: u32 = 3u;
const FUR_DUAL_DELTA_B: u32 = 4u;
const FUR_DUAL_SIGMA_B0: u32 = 5u;
const FUR_DUAL_A_F2: u32 = 6u;
const FUR_DUAL_MEAN: u32 = 7u;
const FUR_DUAL_SD: u32 = 11u;
// Table nodes: theta (cell centres over [-pi/2, pi/2]), |phi| (j pi/31, ends included).
const FUR_DUAL_THETA_NODES: u32 = 64u;
const FUR_DUAL_PHI_NODES: u32 = 32u;
// Halves of one absorption node's fields, before its N^G: 64 x 15.
const FUR_DUAL_NG_START: u32 = 960u;
// 64/pi and 31/pi as the CPU's f32 quotients (dual::theta_position, the phi position).
const FUR_DUAL_THETA_SCALE: f32 = 20.3718319;
const FUR_DUAL_PHI_SCALE: f32 = 9.86760616;
// dual::MAX_FIBERS, dual::MAX_DENSITY, dual::MIN_VARIANCE (rad^2).
const FUR_DUAL_MAX_FIBERS: f32 = 1.0e6;
const FUR_DUAL_MAX_DENSITY: f32 = 4.0;
const FUR_DUAL_MIN_VARIANCE: f32 = 3.0e-6;
// dual::coat::LINE_SAMPLE_OFFSET: the coat below a point is its line's count + 1 layers.
const FUR_DUAL_LINE_SAMPLE_OFFSET: f32 = 1.0;
// The smallest mass a Gaussian is divided by (dual::eval's MIN_REACHABLE_MASS): a lobe
// centred far outside the reachable range is not blown up.
const FUR_DUAL_MIN_MASS: f32 = 0.05;
// The smallest denominator the finite coat's closed forms divide by (dual::coat's TINY).
const FUR_DUAL_TINY: f32 = 1e-6;
// ln 2 as an f32 (core::f32::consts::LN_2).
const FUR_LN2: f32 = 0.693147182;
// log2 e, ln 2 in two parts (math::exp_neg_saturating's reduction) and 1/sqrt(2 pi).
const FUR_LOG2_E: f32 = 1.44269502;
const FUR_LN2_HI: f32 = 0.693359375;
const FUR_LN2_LO: f32 = -2.1219444e-4;
const FUR_INV_SQRT_TAU: f32 = 0.3989423;
// 1/sqrt(2) as an f32 (core::f32::consts::FRAC_1_SQRT_2).
const FUR_FRAC_1_SQRT_2: f32 = 0.707106769;
// math::erf_polynomial's constants (Abramowitz and Stegun 7.1.28): a1 ... a6.
const FUR_ERF_A1: f32 = 0.07052308;
const FUR_ERF_A2: f32 = 0.04228201;
const FUR_ERF_A3: f32 = 0.009270527;
const FUR_ERF_A4: f32 = 0.0001520143;
const FUR_ERF_A5: f32 = 0.0002765672;
const FUR_ERF_A6: f32 = 0.0000430638;

// Half h of the blob's tables (counted from the first half after the header).
fn fur_dual_half(h: u32) -> f32 {
    let pair = unpack2x16float(fur_dual[FUR_DUAL_HEADER_WORDS + (h >> 1u)]);
    return select(pair.x, pair.y, (h & 1u) == 1u);
}

// Half h within absorption node a[c] per channel c: the RGB of one stored value at each
// channel's own node.
fn fur_dual_rgb(a: vec3<u32>, h: u32) -> vec3<f32> {
    let n = a * FUR_DUAL_NODE_HALVES + vec3<u32>(h);
    return vec3<f32>(fur_dual_half(n.x), fur_dual_half(n.y), fur_dual_half(n.z));
}

// A colour located on the absorption axis (dual::DualColour): per channel the lower node and
// the weight of the upper one. Set by fur_eval_dual for the functions below.
struct FurDualColour {
    node: vec3<u32>,
    w: vec3<f32>,
}
var<private> fur_dual_at: FurDualColour;

// sigma_ca of absorption node k (lut::absorption_node, here in f32): the inverse of the
// coordinate at k/15.
fn fur_dual_sigma_node(k: vec3<u32>) -> vec3<f32> {
    let v = vec3<f32>(k) / f32(FUR_DUAL_ABS_NODES - 1u) * (FUR_DUAL_SIGMA_MAX / (FUR_DUAL_SIGMA_MAX + FUR_DUAL_KNEE));
    return select(FUR_DUAL_KNEE * v / (1.0 - v), vec3<f32>(FUR_DUAL_SIGMA_MAX), k >= vec3<u32>(FUR_DUAL_ABS_NODES - 1u));
}

// DualColour::locate: the cell by the LUT's coordinate (sigma/(sigma + s0))/(max/(max + s0)),
// the weight linear in sqrt(sigma) within it, weights within 1e-4 of a node snapped to it.
fn fur_dual_locate(sigma_in: vec3<f32>) -> FurDualColour {
    let s = select(min(max(sigma_in, vec3<f32>(0.0)), vec3<f32>(FUR_DUAL_SIGMA_MAX)), vec3<f32>(0.0), fur_is_nan3(sigma_in));
    let last = f32(FUR_DUAL_ABS_NODES - 1u);
    let coord = min(s / (s + FUR_DUAL_KNEE) / (FUR_DUAL_SIGMA_MAX / (FUR_DUAL_SIGMA_MAX + FUR_DUAL_KNEE)), vec3<f32>(1.0));
    let u = clamp(coord * last, vec3<f32>(0.0), vec3<f32>(last));
    var k = min(vec3<u32>(u), vec3<u32>(FUR_DUAL_ABS_NODES - 2u));
    let lo = sqrt(fur_dual_sigma_node(k));
    let hi = sqrt(fur_dual_sigma_node(k + 1u));
    var w = clamp((sqrt(s) - lo) / (hi - lo), vec3<f32>(0.0), vec3<f32>(1.0));
    w = select(w, vec3<f32>(0.0), fur_is_nan3(w) | (w < vec3<f32>(1e-4)));
    let up = (w > vec3<f32>(1.0 - 1e-4)) & (k + 2u < vec3<u32>(FUR_DUAL_ABS_NODES));
    k = select(k, k + 1u, up);
    w = select(w, vec3<f32>(0.0), up);
    w = select(w, vec3<f32>(1.0), w > vec3<f32>(1.0 - 1e-4));
    return FurDualColour(k, w);
}

// True for NaN, on the bits (see fur_finite).
fn fur_is_nan(x: f32) -> bool {
    return (bitcast<u32>(x) & 0x7fffffffu) > 0x7f800000u;
}

// fur_is_nan per channel.
fn fur_is_nan3(x: vec3<f32>) -> vec3<bool> {
    return (bitcast<vec3<u32>>(x) & vec3<u32>(0x7fffffffu)) > vec3<u32>(0x7f800000u);
}

// Linear interpolation position of theta on the theta axis (dual::theta_position):
// t = (theta + pi/2) 64/pi - 1/2 clamped to [0, 63], lower node k = min(floor t, 62) and the
// weight t - k of the upper one.
fn fur_dual_theta(theta: f32) -> FurLoc {
    var t = (theta + FUR_HALF_PI) * FUR_DUAL_THETA_SCALE - 0.5;
    t = select(0.0, t, t > 0.0);
    t = min(t, f32(FUR_DUAL_THETA_NODES - 1u));
    let k = min(u32(t), FUR_DUAL_THETA_NODES - 2u);
    return FurLoc(k, t - f32(k));
}

// Field f at theta node k as stored at absorption node a[c] per channel
// (DualLut::nodes[a][k][f]).
fn fur_dual_node(a: vec3<u32>, k: u32, f: u32) -> vec3<f32> {
    return fur_dual_rgb(a, k * FUR_DUAL_FIELDS + f);
}

// Field f at theta and the located colour (DualLut::field): linear between theta nodes k
// and k + 1 at each channel's two absorption nodes, a + (b - a) w, then between those.
fn fur_dual_field(l: FurLoc, f: u32) -> vec3<f32> {
    let lo = fur_dual_at.node;
    let a0 = fur_dual_node(lo, l.i, f);
    let b0 = fur_dual_node(lo, l.i + 1u, f);
    let a1 = fur_dual_node(lo + 1u, l.i, f);
    let b1 = fur_dual_node(lo + 1u, l.i + 1u, f);
    let v0 = a0 + (b0 - a0) * l.w;
    let v1 = a1 + (b1 - a1) * l.w;
    return v0 + (v1 - v0) * fur_dual_at.w;
}

// N^G of family g at the theta and |phi| positions (DualLut::n_g): bilinear, the four
// corners weighted as dual's bilinear_weights does, summed in the same order.
// At each channel's two absorption nodes, then linear between them.
fn fur_dual_ng_at(a: vec3<u32>, g: u32, l: FurLoc, p: FurLoc) -> vec3<f32> {
    let row0 = (g * FUR_DUAL_THETA_NODES + l.i) * FUR_DUAL_PHI_NODES + p.i;
    let row1 = row0 + FUR_DUAL_PHI_NODES;
    let t00 = fur_dual_rgb(a, FUR_DUAL_NG_START + row0);
    let t01 = fur_dual_rgb(a, FUR_DUAL_NG_START + row0 + 1u);
    let t10 = fur_dual_rgb(a, FUR_DUAL_NG_START + row1);
    let t11 = fur_dual_rgb(a, FUR_DUAL_NG_START + row1 + 1u);
    let w = l.w;
    let v = p.w;
    return (1.0 - w) * (1.0 - v) * t00 + (1.0 - w) * v * t01 + w * (1.0 - v) * t10 + w * v * t11;
}

fn fur_dual_ng(g: u32, l: FurLoc, p: FurLoc) -> vec3<f32> {
    let v0 = fur_dual_ng_at(fur_dual_at.node, g, l, p);
    let v1 = fur_dual_ng_at(fur_dual_at.node + 1u, g, l, p);
    return v0 + (v1 - v0) * fur_dual_at.w;
}

// 1/sqrt(v) for normal v > 0, the operations of math::rsqrt_newton on the CPU: the
// bit-level first guess 0x5f375a86 - bits/2, then three Newton steps y(1.5 - v y^2/2).
fn fur_rsqrt_newton(v: vec3<f32>) -> vec3<f32> {
    var y = bitcast<vec3<f32>>(vec3<u32>(0x5f375a86u) - (bitcast<vec3<u32>>(v) >> vec3<u32>(1u)));
    let h = 0.5 * v;
    y = y * (1.5 - h * y * y);
    y = y * (1.5 - h * y * y);
    return y * (1.5 - h * y * y);
}

// e^-x for x >= 0, the operations of math::exp_neg_saturating on the CPU: x = k ln 2 - r with
// k = round(x log2 e) and ln 2 in two parts (exact products), Cephes' polynomial for e^r, and
// 2^-k by ldexp; 0 above 87. Not the built-in exp, whose error grows with |x| (3 + 2|x| ulp
// allowed): the Gaussians' exponents reach tens at grazing angles.
fn fur_exp_neg(x_in: vec3<f32>) -> vec3<f32> {
    let x = min(max(x_in, vec3<f32>(0.0)), vec3<f32>(87.0));
    let k = round(x * FUR_LOG2_E);
    let r = (k * FUR_LN2_HI - x) + k * FUR_LN2_LO;
    let z = r * r;
    var p = vec3<f32>(1.9875692e-4);
    p = p * r + 1.3981999e-3;
    p = p * r + 8.333452e-3;
    p = p * r + 4.1665796e-2;
    p = p * r + 0.16666665;
    p = p * r + 0.5;
    let e = p * z + r + 1.0;
    return select(ldexp(e, -vec3<i32>(k)), vec3<f32>(0.0), x_in > vec3<f32>(87.0));
}

// erf x per channel, the operations of math::erf_polynomial on the CPU (Abramowitz and
// Stegun 7.1.28, error at most 3e-7): with a = |x| kept in [0, 10] (NaN gives 0; erf 10 is 1
// in f32),
//   erf a = 1 - 1/(1 + a1 a + a2 a^2 + ... + a6 a^6)^16
// (Horner from a6; the 16th power by four squarings), and the sign bit of x put back onto
// it (erf is odd).
fn fur_erf(x: vec3<f32>) -> vec3<f32> {
    let a = select(min(abs(x), vec3<f32>(10.0)), vec3<f32>(0.0), fur_is_nan3(x));
    let p = (((((FUR_ERF_A6 * a + FUR_ERF_A5) * a + FUR_ERF_A4) * a + FUR_ERF_A3) * a + FUR_ERF_A2) * a + FUR_ERF_A1) * a + 1.0;
    let p2 = p * p;
    let p4 = p2 * p2;
    let p8 = p4 * p4;
    let e = 1.0 - 1.0 / (p8 * p8);
    let sign = bitcast<vec3<u32>>(x) & vec3<u32>(0x80000000u);
    return bitcast<vec3<f32>>(bitcast<vec3<u32>>(e) | sign);
}

// x per channel kept in [0, top] by max then min, NaN giving 0 (the CPU's
// x.max(0.0).min(top), which a GPU's max need not reproduce for NaN).
fn fur_dual_between(x: vec3<f32>, top: vec3<f32>) -> vec3<f32> {
    return select(min(max(x, vec3<f32>(0.0)), top), vec3<f32>(0.0), fur_is_nan3(x));
}

// The normalised Gaussian G(d; sqrt(v)) = e^(-d^2/2v)/sqrt(2 pi v) per channel, divided by
// its mass over the x = theta_i + theta_r the caller can reach (theta_i in [-pi/2, pi/2]),
// given d = x - mean (dual::eval's gauss_reachable). v is kept in [dual::MIN_VARIANCE,
// 1e30]; with s = 1/sqrt(v) (fur_rsqrt_newton) and z = d s:
//   G = e^(-z^2/2) s/sqrt(2 pi),
//   mass = (erf z+ - erf z-)/2, z+- = (d - theta_i +- pi/2) s/sqrt(2) (fur_erf),
// the mass kept at or above 0.05, so that each lobe returns its stored energy.
fn fur_dual_gauss(d: vec3<f32>, v_in: vec3<f32>, theta_i: f32) -> vec3<f32> {
    let v = clamp(v_in, vec3<f32>(FUR_DUAL_MIN_VARIANCE), vec3<f32>(1e30));
    let s = fur_rsqrt_newton(v);
    let z = d * s;
    let g = fur_exp_neg(0.5 * z * z) * s * FUR_INV_SQRT_TAU;
    let centre = (d - theta_i) * s * FUR_FRAC_1_SQRT_2;
    let half_range = FUR_HALF_PI * s * FUR_FRAC_1_SQRT_2;
    let mass = 0.5 * (fur_erf(centre + half_range) - fur_erf(centre - half_range));
    return g / max(mass, vec3<f32>(FUR_DUAL_MIN_MASS));
}

// mu^k = e^(-k ln 2 (-log2 mu)) per channel for k >= 0 (log2 mu <= 0), from the stored
// log2 mu (dual::eval's power_of_decay).
fn fur_dual_power(log2_mu: vec3<f32>, k: f32) -> vec3<f32> {
    return fur_exp_neg(-k * FUR_LN2 * log2_mu);
}

// The finite coat (docs/model.md §13, "The coat below"; dual/coat.rs): the fibers around a
// shading point as identical two-stream layers, n above it toward the light and m below it
// over a black floor. Per channel from the stored decay mu of the semi-infinite stack and
// the layer's forward fraction t; rho = R_inf, the semi-infinite stack's reflectance.

// rho^2 = (mu - t)/(mu (1 - t mu)), from mu(1 - r rho) = t and rho(1 - t mu) = r, kept in
// [0, 1] (NaN 0); 0 when mu (1 - t mu) is at or below 1e-6 (dual::coat::reflectance_squared).
fn fur_reflectance_squared(mu: vec3<f32>, t: vec3<f32>) -> vec3<f32> {
    let den = mu * (1.0 - t * mu);
    let v = fur_dual_between((mu - t) / max(den, vec3<f32>(FUR_DUAL_TINY)), vec3<f32>(1.0));
    return select(vec3<f32>(0.0), v, den > vec3<f32>(FUR_DUAL_TINY));
}

// The downward flux under n layers with m below over a black floor,
//   D = T_n/(1 - R_n R_m) = mu^n (1 - rho^2 mu^2m)/(1 - rho^2 mu^2(n+m)),
// from mu^n, mu^2m and rho^2, kept in [0, mu^n] (NaN 0); mu^n when the denominator is at or
// below 1e-6 (dual::coat::downward_flux). mu^n for an infinite m, T_n for m = 0.
fn fur_downward_flux(mu_n: vec3<f32>, mu_2m: vec3<f32>, rho2: vec3<f32>) -> vec3<f32> {
    let num = 1.0 - rho2 * mu_2m;
    let den = 1.0 - rho2 * mu_n * mu_n * mu_2m;
    let d = mu_n * (num / max(den, vec3<f32>(FUR_DUAL_TINY)));
    return select(mu_n, fur_dual_between(d, mu_n), den > vec3<f32>(FUR_DUAL_TINY));
}

// The local backscatter's energy with m layers below, as a factor on the stored energy (the
// deep stack's light through one more layer, U_inf = rho mu): the coat below the point's
// neighbourhood returns R_m = rho g, g = (1 - mu^2m)/(1 - rho^2 mu^2m) kept in [0, 1] (NaN 0;
// 1 when its denominator is at or below 1e-6), so k_m = g/mu, mu kept at or above 1e-6
// (dual::coat::backscatter_factor). 1/mu for an infinite m, 0 for m = 0.
fn fur_backscatter_factor(rho2: vec3<f32>, mu: vec3<f32>, mu_2m: vec3<f32>) -> vec3<f32> {
    let tiny = vec3<f32>(FUR_DUAL_TINY);
    let g_den = 1.0 - rho2 * mu_2m;
    let g = fur_dual_between((1.0 - mu_2m) / max(g_den, tiny), vec3<f32>(1.0));
    return select(vec3<f32>(1.0), g, g_den > tiny) / max(mu, tiny);
}

// rho^2 of the coat at theta node k (dual::coat::node_coat, what DualLut::decode derives per
// node): mu = 2^(log2 mu) (fur_dual_power) and t = a_f = a_f^2/sqrt(a_f^2) (a_f^2 kept in
// [0, 1], fur_rsqrt_newton), then fur_reflectance_squared.
fn fur_dual_coat_node(n: vec3<u32>, k: u32) -> vec3<f32> {
    let log2_mu = fur_dual_node(n, k, FUR_DUAL_LOG2_DECAY);
    let a = clamp(fur_dual_node(n, k, FUR_DUAL_A_F2), vec3<f32>(0.0), vec3<f32>(1.0));
    let mu = fur_dual_power(log2_mu, 1.0);
    let t = a * fur_rsqrt_newton(max(a, vec3<f32>(1e-30)));
    return fur_reflectance_squared(mu, t);
}

// rho^2 at theta: derived at the two nodes, then linear between them, a + (b - a) w
// (DualLut::eval's coat lookup).
// (At each channel's two absorption nodes, then linear between them, as DualLut::rho2.)
fn fur_dual_coat(l: FurLoc) -> vec3<f32> {
    let lo = fur_dual_at.node;
    let a0 = fur_dual_coat_node(lo, l.i);
    let b0 = fur_dual_coat_node(lo, l.i + 1u);
    let a1 = fur_dual_coat_node(lo + 1u, l.i);
    let b1 = fur_dual_coat_node(lo + 1u, l.i + 1u);
    let rho0 = a0 + (b0 - a0) * l.w;
    let rho1 = a1 + (b1 - a1) * l.w;
    return rho0 + (rho1 - rho0) * fur_dual_at.w;
}

// A fiber count or density factor as the CPU's contract takes it: NaN and values <= 0 give
// 0, values above `top` (+inf included) give `top`.
fn fur_dual_clean(x: f32, top: f32) -> f32 {
    return select(0.0, min(x, top), !fur_is_nan(x) && x > 0.0);
}

// The layers of the coat below the term uses (dual::coat::coat_below_layers): a count
// x >= 0 along the light's line is one sample of the neighbourhood's coat, x + 1 layers
// (FUR_DUAL_LINE_SAMPLE_OFFSET), at most 1e6; values < 0 give 0 (the point lies on the skin);
// NaN and +inf give 1e6 (a semi-infinite coat).
fn fur_dual_below(x: f32) -> f32 {
    let deep = select(0.0, FUR_DUAL_MAX_FIBERS, fur_is_nan(x));
    return select(deep, min(x + FUR_DUAL_LINE_SAMPLE_OFFSET, FUR_DUAL_MAX_FIBERS), !fur_is_nan(x) && x >= 0.0);
}

// The two-stream diffusivity factor (dual::coat::DIFFUSIVITY, docs/model.md §13 "The light's
// incidence on the coat").
const FUR_DUAL_DIFFUSIVITY: f32 = 2.0;

// The count of the coat below to pass as fur_eval_dual's fibers_below when the skin normal
// under the strand is known (dual::coat::below_at_incidence): count_on_line counted along the
// light's line, cos_to_skin the cosine between the direction toward the light and the skin
// normal; the term then uses 2 |cos_to_skin| (count_on_line + 1) layers, at least 1.
// count_on_line < 0, NaN or >= 1e6 (the skin, a semi-infinite coat) and a NaN cos_to_skin
// (the normal unknown) return count_on_line unchanged.
fn fur_dual_below_at_incidence(count_on_line: f32, cos_to_skin: f32) -> f32 {
    let skin_layers = FUR_DUAL_DIFFUSIVITY * min(abs(cos_to_skin), 1.0) * (count_on_line + FUR_DUAL_LINE_SAMPLE_OFFSET);
    let as_count = max(skin_layers - FUR_DUAL_LINE_SAMPLE_OFFSET, 0.0);
    let known = !fur_is_nan(count_on_line) && count_on_line >= 0.0 && count_on_line < FUR_DUAL_MAX_FIBERS && !fur_is_nan(cos_to_skin);
    return select(count_on_line, as_count, known);
}

// The forward density factor to pass as fur_eval_dual's d_f when the skin normal under the
// strand is known (dual::coat::forward_density_at_incidence): d_f 2 |cos_to_skin|
// (|cos_to_skin| clamped to 1), the diffuse flux the light scattered through the fibers above
// brings per unit of coat area; a NaN cos_to_skin (the normal unknown) returns d_f unchanged.
fn fur_dual_forward_density_at_incidence(d_f: f32, cos_to_skin: f32) -> f32 {
    let scaled = d_f * FUR_DUAL_DIFFUSIVITY * min(abs(cos_to_skin), 1.0);
    return select(scaled, d_f, fur_is_nan(cos_to_skin));
}

// The dual-scattering term to add to single scattering (DualLut::eval, docs/model.md §13),
// RGB, in S's units (the caller multiplies by cos theta_i and the light's radiance like S).
// `fibers` is n, the number of fibers between the shading point and the light (fractional
// allowed); `fibers_below` is m, the fibers beyond the point along -omega_i, down to the skin
// or out of the coat (the coat below, which sends light back up; +inf for a semi-infinite
// coat); d_f, d_b the density factors (dual::Density; 1 and 0.8 by default). With
// V = clamp(1 - n, 0, 1) the direct fraction (what a shadow ray gives), the shading is
// S V + this term:
//
//   D = V d_b f_back(0) + (T_f - V) d_f (f_s^scatter(sigma_f^2) + d_b f_back(sigma_f^2)),
//
// - the light that reaches the point through n fibers above, m below over a black floor:
//   T_f = mu^n (1 - rho^2 mu^2m)/(1 - rho^2 mu^2(n+m)) (fur_downward_flux), mu the stored
//   decay and rho^2 derived from mu and a_f at the nodes and interpolated (fur_dual_coat),
//   both at -theta_i (the light's path leaves the fibers above at theta ~ -theta_i); its
//   spread sigma_f^2 = n beta_f^2(-theta_i);
// - the fibers' scattering of it:
//   f_s^scatter(s^2) = sum_g N^G_g(theta_r, |phi|) G^(x - mean_g; sd_g^2 + s^2)/cos^2 theta_i;
// - the local backscatter:
//   f_back(s^2) = A k_m G^(x - Delta_b; sigma_b^2 + s^2)/(pi cos^2 theta_i),
//   sigma_b = (1 + d_b a_f^2) sigma_b0, x = theta_i + theta_r, A the stored back-half energy
//   for |phi| < pi/2, the front-half one otherwise, and k_m its factor for m fibers below
//   (fur_backscatter_factor), at theta_r;
// - G^ a Gaussian divided by its mass over the x reachable at this theta_r (fur_dual_gauss).
//
// Invalid angles (as fur_eval_far) give 0; n NaN or < 0 is 0, n > 1e6 (or +inf) is 1e6;
// m < 0 is 0, m NaN, +inf or > 1e6 is 1e6; densities NaN or < 0 are 0, clamped to 4. The
// result is finite and >= 0.
fn fur_eval_dual(theta_i: f32, theta_r: f32, phi_in: f32, fibers: f32, fibers_below: f32, d_f_in: f32, d_b_in: f32, sigma_ca: vec3<f32>) -> vec3<f32> {
    // The colour: each channel reads the absorption axis at its own sigma_ca.
    fur_dual_at = fur_dual_locate(sigma_ca);
    let zero = vec3<f32>(0.0);
    if (!fur_valid(theta_i, theta_r, phi_in)) {
        return zero;
    }
    let n = fur_dual_clean(fibers, FUR_DUAL_MAX_FIBERS);
    let m = fur_dual_below(fibers_below);
    let d_f = fur_dual_clean(d_f_in, FUR_DUAL_MAX_DENSITY);
    let d_b = fur_dual_clean(d_b_in, FUR_DUAL_MAX_DENSITY);
    let x = theta_i + theta_r;
    // S's guarded 1/cos^2(theta_i) (model::inv_cos2_theta_i, docs/model.md §8).
    let c = fur_cos_within_half_pi(theta_i);
    let inv_cos2 = 1.0 / max(c * c, FUR_MIN_COS2);
    let direct = clamp(1.0 - n, 0.0, 1.0);
    let here = fur_dual_theta(theta_r);
    let abs_phi = abs(fur_wrap_angle(phi_in));
    // The local backscatter at theta_r: the stored energy (back half for |phi| < pi/2, else
    // front) times k_m for the m layers below instead of the semi-infinite stack, from the
    // interpolated rho^2 (fur_dual_coat), mu and mu^2m.
    let stored = fur_dual_field(here, select(FUR_DUAL_FRONT, FUR_DUAL_BACK, abs_phi < FUR_HALF_PI));
    let log2_mu_here = fur_dual_field(here, FUR_DUAL_LOG2_DECAY);
    let a_f2 = fur_dual_field(here, FUR_DUAL_A_F2);
    let mu_here = fur_dual_power(log2_mu_here, 1.0);
    let mu_2m_here = fur_dual_power(log2_mu_here, 2.0 * m);
    let half_energy = stored * fur_backscatter_factor(fur_dual_coat(here), mu_here, mu_2m_here);
    // Delta_b and sigma_b^2 = ((1 + d_b a_f^2) sigma_b0)^2.
    let sigma_b0 = fur_dual_field(here, FUR_DUAL_SIGMA_B0);
    let delta = fur_dual_field(here, FUR_DUAL_DELTA_B);
    let d_back = x - delta;
    let s_b = (1.0 + d_b * a_f2) * sigma_b0;
    let v_back = s_b * s_b;
    // f_back without its variance increase, times pi cos^2 theta_i.
    let back_scale = d_b * inv_cos2 / FUR_PI;
    var out = zero;
    // V d_b f_back(0).
    if (direct > 0.0) {
        out = direct * back_scale * half_energy * fur_dual_gauss(d_back, v_back, theta_i);
    }
    if (n > 0.0) {
        // T_f through n layers above and m below (fur_downward_flux) and
        // sigma_f^2 = n beta_f^2, both at -theta_i.
        let along = fur_dual_theta(-theta_i);
        let log2_mu = fur_dual_field(along, FUR_DUAL_LOG2_DECAY);
        let beta_f = fur_dual_field(along, FUR_DUAL_BETA_F);
        let mu_n = fur_dual_power(log2_mu, n);
        let mu_2m = fur_dual_power(log2_mu, 2.0 * m);
        let t_f = fur_downward_flux(mu_n, mu_2m, fur_dual_coat(along));
        let spread = max(t_f - direct, zero) * d_f;
        if (any(spread > zero)) {
            let s2f = n * beta_f * beta_f;
            // |phi| position on the N^G axis: p = |phi| 31/pi in [0, 31], j = min(floor p, 30).
            var p = abs_phi * FUR_DUAL_PHI_SCALE;
            p = select(0.0, min(p, f32(FUR_DUAL_PHI_NODES - 1u)), p > 0.0);
            let j = min(u32(p), FUR_DUAL_PHI_NODES - 2u);
            let at_phi = FurLoc(j, p - f32(j));
            // f_s^scatter(sigma_f^2) cos^2 theta_i: each family's N^G times its Gaussian.
            var f_s = zero;
            for (var g = 0u; g < 4u; g = g + 1u) {
                let mean = fur_dual_field(here, FUR_DUAL_MEAN + g);
                let sd = fur_dual_field(here, FUR_DUAL_SD + g);
                let ng = fur_dual_ng(g, here, at_phi);
                let v = sd * sd + s2f;
                f_s = f_s + ng * fur_dual_gauss(x - mean, v, theta_i);
            }
            // (T_f - V) d_f (f_s^scatter(sigma_f^2) + d_b f_back(sigma_f^2)).
            let gb = fur_dual_gauss(d_back, v_back + s2f, theta_i);
            out = out + spread * (f_s * inv_cos2 + back_scale * half_energy * gb);
        }
    }
    // Finite and >= 0 per channel, else 0 (on the bits, like fur_finite).
    let finite = vec3<bool>(fur_finite(out.x), fur_finite(out.y), fur_finite(out.z));
    return select(zero, out, finite & (out > zero));
}

// fur_eval_dual from world-space vectors: wi toward the light, wr toward the viewer, u the
// fiber tangent (any lengths), at the angles of fur_angles_from_dirs (the baked
// evaluator's polynomial conversion, `BakedBcsdf::angles_from_dirs`); 0 for unusable vectors.
fn fur_eval_dual_dirs(wi: vec3<f32>, wr: vec3<f32>, u: vec3<f32>, fibers: f32, fibers_below: f32, d_f: f32, d_b: f32, sigma_ca: vec3<f32>) -> vec3<f32> {
    let a = fur_angles_from_dirs(wi, wr, u);
    if (!a.ok) {
        return vec3<f32>(0.0);
    }
    return fur_eval_dual(a.theta_i, a.theta_r, a.phi, fibers, fibers_below, d_f, d_b, sigma_ca);
}

// Base colour -> absorption (docs/model.md §14, "Inverse"): the sigma_ca per channel whose
// thick coat shows the linear colour `colour`, from a preset's coat colour table, as the CPU's
// `Absorption::from_base_colour` does: per channel the smallest sigma_ca of the table's
// interpolant (linear in the axis coordinate sqrt(sigma/(sigma + 1)) between nodes) with that
// colour; a channel at or above the table's first node gives 0, below its last node 1000.
// `table` is `CoatColour::colours()` (24 nodes, non-increasing), packed four to a vec4 (node k
// in table[k / 4][k % 4]) so that the caller can keep it in a uniform or a storage buffer and
// pass it by value. Validate colours on the host (`Absorption::from_base_colour` refuses NaN
// and channels outside [0, 1]); here a NaN channel gives 1000.
const FUR_COAT_NODES: u32 = 24u;
// sqrt(1000 / 1001) rounded to f32: the axis coordinate of sigma_ca = 1000, bit for bit the
// CPU's (computed there by libm's correctly rounded sqrtf).
const FUR_COAT_AXIS_END: f32 = 0.999500394;

// sigma_ca at axis coordinate x: x^2/(1 - x^2), in [0, 1000].
fn fur_coat_sigma_at(x: f32) -> f32 {
    let x2 = x * x;
    return clamp(x2 / max(1.0 - x2, 1e-12), 0.0, FUR_SIGMA_CA_MAX);
}

fn fur_coat_sigma_for(table: array<vec4<f32>, 6>, c: f32) -> f32 {
    // A function variable: indexed by a loop counter in every shading language.
    var nodes = table;
    if (c >= nodes[0].x) {
        return 0.0;
    }
    for (var k = 0u; k < FUR_COAT_NODES - 1u; k = k + 1u) {
        let hi = nodes[k / 4u][k % 4u];
        let lo = nodes[(k + 1u) / 4u][(k + 1u) % 4u];
        if (c >= lo) {
            var t = 0.0;
            if (hi > lo) {
                t = (hi - c) / (hi - lo);
            }
            let x = (f32(k) + t) / f32(FUR_COAT_NODES - 1u) * FUR_COAT_AXIS_END;
            return fur_coat_sigma_at(x);
        }
    }
    return FUR_SIGMA_CA_MAX;
}

fn fur_absorption_from_colour(table: array<vec4<f32>, 6>, colour: vec3<f32>) -> vec3<f32> {
    return vec3<f32>(
        fur_coat_sigma_for(table, colour.x),
        fur_coat_sigma_for(table, colour.y),
        fur_coat_sigma_for(table, colour.z),
    );
}

// ---- Entry points for the tests and `viewer probe --gpu` (bindings 1 and 2; 3 for dual) ----

// Queries: two vec4 per evaluation, (theta_i, theta_r, phi, unused) and (sigma_ca, unused);
// or, for fur_eval_dirs_main, three vec4 per evaluation (wi, sigma_ca.r), (wr, sigma_ca.g),
// (tangent, sigma_ca.b); the sampling, pdf and dual-scattering layouts at their entry points.
@group(0) @binding(1) var<storage, read> fur_queries: array<vec4<f32>>;
// Results: 16 floats per evaluation: R, TT, TRT, scattered (RGB each), total (RGB), 0.
@group(0) @binding(2) var<storage, read_write> fur_results: array<f32>;

fn fur_store(q: u32, f: FurFamilies) {
    let base = 16u * q;
    let parts = array<vec3<f32>, 5>(f.r, f.tt, f.trt, f.scattered, f.total);
    for (var k = 0u; k < 5u; k = k + 1u) {
        fur_results[base + 3u * k] = parts[k].x;
        fur_results[base + 3u * k + 1u] = parts[k].y;
        fur_results[base + 3u * k + 2u] = parts[k].z;
    }
    fur_results[base + 15u] = 0.0;
}

// One RGB result in the first three of the query's 16 floats, the rest 0.
fn fur_store_rgb(q: u32, v: vec3<f32>) {
    let base = 16u * q;
    fur_results[base] = v.x;
    fur_results[base + 1u] = v.y;
    fur_results[base + 2u] = v.z;
    for (var k = 3u; k < 16u; k = k + 1u) {
        fur_results[base + k] = 0.0;
    }
}

@compute @workgroup_size(64)
fn fur_eval_main(@builtin(global_invocation_id) id: vec3<u32>) {
    let q = id.x;
    if (2u * q + 1u >= arrayLength(&fur_queries)) {
        return;
    }
    let a = fur_queries[2u * q];
    fur_store(q, fur_eval_far(a.x, a.y, a.z, fur_queries[2u * q + 1u].xyz));
}

@compute @workgroup_size(64)
fn fur_eval_dirs_main(@builtin(global_invocation_id) id: vec3<u32>) {
    let q = id.x;
    if (3u * q + 2u >= arrayLength(&fur_queries)) {
        return;
    }
    let wi = fur_queries[3u * q];
    let wr = fur_queries[3u * q + 1u];
    let u = fur_queries[3u * q + 2u];
    fur_store(q, fur_eval_far_dirs(wi.xyz, wr.xyz, u.xyz, vec3<f32>(wi.w, wr.w, u.w)));
}

// Sampling queries: two vec4, (theta_r, u0, u1, u2) and (sigma_ca, unused); results 8 floats:
// theta_i, phi, pdf, weight RGB, family, ok (1 or 0).
@compute @workgroup_size(64)
fn fur_sample_main(@builtin(global_invocation_id) id: vec3<u32>) {
    let q = id.x;
    if (2u * q + 1u >= arrayLength(&fur_queries)) {
        return;
    }
    let a = fur_queries[2u * q];
    let s = fur_sample_far(a.x, a.yzw, fur_queries[2u * q + 1u].xyz);
    let base = 16u * q;
    fur_results[base] = s.theta_i;
    fur_results[base + 1u] = s.phi;
    fur_results[base + 2u] = s.pdf;
    fur_results[base + 3u] = s.weight.x;
    fur_results[base + 4u] = s.weight.y;
    fur_results[base + 5u] = s.weight.z;
    fur_results[base + 6u] = f32(s.family);
    fur_results[base + 7u] = select(0.0, 1.0, s.ok);
}

// Pdf queries: two vec4, (theta_i, theta_r, phi, unused) and (sigma_ca, unused); result: the
// pdf in the first float.
@compute @workgroup_size(64)
fn fur_pdf_main(@builtin(global_invocation_id) id: vec3<u32>) {
    let q = id.x;
    if (2u * q + 1u >= arrayLength(&fur_queries)) {
        return;
    }
    let a = fur_queries[2u * q];
    fur_results[16u * q] = fur_pdf_far(a.x, a.y, a.z, fur_queries[2u * q + 1u].xyz);
}

// Dual-scattering queries (bindings 1, 2 and 3): three vec4 per evaluation,
// (theta_i, theta_r, phi, fibers), (d_f, d_b, fibers_below, unused) and (sigma_ca RGB,
// unused); results: RGB in the
// first three of 16 floats, the rest 0.
@compute @workgroup_size(64)
fn fur_dual_main(@builtin(global_invocation_id) id: vec3<u32>) {
    let q = id.x;
    if (3u * q + 2u >= arrayLength(&fur_queries)) {
        return;
    }
    let a = fur_queries[3u * q];
    let d = fur_queries[3u * q + 1u];
    let sigma = fur_queries[3u * q + 2u];
    fur_store_rgb(q, fur_eval_dual(a.x, a.y, a.z, a.w, d.z, d.x, d.y, sigma.xyz));
}

// Dual-scattering vector queries (bindings 1, 2 and 3): four vec4 per evaluation,
// (wi, fibers), (wr, d_f), (tangent, d_b), (fibers_below, sigma_ca RGB); results
// as fur_dual_main.
@compute @workgroup_size(64)
fn fur_dual_dirs_main(@builtin(global_invocation_id) id: vec3<u32>) {
    let q = id.x;
    if (4u * q + 3u >= arrayLength(&fur_queries)) {
        return;
    }
    let wi = fur_queries[4u * q];
    let wr = fur_queries[4u * q + 1u];
    let u = fur_queries[4u * q + 2u];
    let below = fur_queries[4u * q + 3u];
    fur_store_rgb(q, fur_eval_dual_dirs(wi.xyz, wr.xyz, u.xyz, wi.w, below.x, wr.w, u.w, below.yzw));
}

// Base colour queries (bindings 1 and 2): six vec4, the coat colour table (node k in
// component k % 4 of vec4 k / 4), then one vec4 per colour (linear RGB, unused); results:
// sigma_ca RGB in the first three of 16 floats, the rest 0.
@compute @workgroup_size(64)
fn fur_absorption_main(@builtin(global_invocation_id) id: vec3<u32>) {
    let q = id.x;
    if (6u + q >= arrayLength(&fur_queries)) {
        return;
    }
    let table = array<vec4<f32>, 6>(
        fur_queries[0],
        fur_queries[1],
        fur_queries[2],
        fur_queries[3],
        fur_queries[4],
        fur_queries[5],
    );
    fur_store_rgb(q, fur_absorption_from_colour(table, fur_queries[6u + q].xyz));
}
