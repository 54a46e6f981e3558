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
// Binding: group 0, binding 0 = the LUT words. The entry points at the end (bindings 1 and 2)
// serve the tests and `viewer probe --gpu`; an engine includes the functions and calls
// `fur_eval_far` / `fur_eval_far_dirs` from its own shaders.

@group(0) @binding(0) var<storage, read> fur_lut: array<u32>;

const FUR_PI: f32 = 3.14159274;
const FUR_HALF_PI: f32 = 1.57079637;
const FUR_TAU: f32 = 6.28318548;
// cos^2(theta_i) floor of the 1/cos^2 factor (model::MIN_COS2_THETA_I).
const FUR_MIN_COS2: f32 = 1e-4;
// Halves before the first table: the 160-byte header.
const FUR_HEADER_HALVES: u32 = 80u;

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
    return bitcast<f32>(fur_word(9u + t)) * bitcast<f32>((127u + 112u) << 23u);
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
    let r = (1.57079637 - a) + -4.37113883e-8;
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
    return y;
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

// Far-field S per lobe family (BakedBcsdf::eval_far). theta_i, theta_r in [-pi/2, pi/2], any
// finite phi; anything else gives 0.
fn fur_eval_far(theta_i: f32, theta_r: f32, phi_in: f32) -> FurFamilies {
    if (!(fur_finite(theta_i) && fur_finite(theta_r) && fur_finite(phi_in))
        || abs(theta_i) > FUR_HALF_PI || abs(theta_r) > FUR_HALF_PI) {
        return fur_zero();
    }
    let phi = fur_wrap_angle(phi_in);
    let n_sum = fur_word(4u);
    let n_theta_r = fur_word(5u);
    let n_phi = fur_word(6u);
    let n_ms_i = fur_word(7u);
    let n_ms_r = fur_word(8u);
    let m0 = FUR_HEADER_HALVES;
    let n0 = m0 + 3u * n_sum;
    let s0 = n0 + 12u * n_phi * n_theta_r;

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
    let mss = ms[0] + front_w * (ms[1] - ms[0]);

    // N (12 channels: family, then RGB) at (|theta_r|, |phi|): bilinear in table N.
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
    var n: array<f32, 12>;
    for (var ch = 0u; ch < 12u; ch = ch + 1u) {
        let t0 = fur_half(n0 + 12u * j0 + ch);
        let t1 = fur_half(n0 + 12u * (j0 + 1u) + ch);
        let b0 = fur_half(n0 + 12u * (j0 + n_phi) + ch);
        let b1 = fur_half(n0 + 12u * (j0 + n_phi + 1u) + ch);
        n[ch] = v0 * t0 + v1 * t1 + v2 * b0 + v3 * b1;
    }

    let lon = array<f32, 4>(m[0], m[1], m[2], mss);
    var f: array<vec3<f32>, 4>;
    for (var k = 0u; k < 4u; k = k + 1u) {
        let weight = lon[k] * inv_cos2;
        f[k] = vec3<f32>(n[3u * k], n[3u * k + 1u], n[3u * k + 2u]) * weight;
    }
    return FurFamilies(f[0], f[1], f[2], f[3], ((f[0] + f[1]) + f[2]) + f[3]);
}

// asin and atan2 as the CPU's default math backend computes them (the libm crate's asinf and
// atan2f, i.e. musl's algorithms: argument reduction and the same minimax polynomials), so
// that angles from vectors agree to an ulp or two; the GPU built-ins are far less precise
// (llvmpipe's moved results by 1e-2 on a lobe's flank). asinf's last branch runs in f64 on
// the CPU and in f32 here.
fn fur_asin_r(z: f32) -> f32 {
    let p = z * (1.6666586697e-01 + z * (-4.2743422091e-02 + z * -8.6563630030e-03));
    let q = 1.0 + z * -7.0662963390e-01;
    return p / q;
}

fn fur_asin(x: f32) -> f32 {
    let ix = bitcast<u32>(x) & 0x7fffffffu;
    if (ix >= 0x3f800000u) {
        return sign(x) * FUR_HALF_PI;
    }
    if (ix < 0x3f000000u) {
        if (ix < 0x39800000u) {
            return x;
        }
        return x + x * fur_asin_r(x * x);
    }
    let z = (1.0 - abs(x)) * 0.5;
    let s = sqrt(z);
    let a = FUR_HALF_PI - 2.0 * (s + s * fur_asin_r(z));
    return select(a, -a, x < 0.0);
}

fn fur_atan(x_in: f32) -> f32 {
    var x = x_in;
    let ix = bitcast<u32>(x) & 0x7fffffffu;
    let negative = x < 0.0;
    if (ix >= 0x4c800000u) {
        return select(1.5707962513, -1.5707962513, negative);
    }
    var id = -1;
    if (ix < 0x3ee00000u) {
        if (ix < 0x39800000u) {
            return x;
        }
    } else {
        x = abs(x);
        if (ix < 0x3f980000u) {
            if (ix < 0x3f300000u) {
                x = (2.0 * x - 1.0) / (2.0 + x);
                id = 0;
            } else {
                x = (x - 1.0) / (x + 1.0);
                id = 1;
            }
        } else if (ix < 0x401c0000u) {
            x = (x - 1.5) / (1.0 + 1.5 * x);
            id = 2;
        } else {
            x = -1.0 / x;
            id = 3;
        }
    }
    let z = x * x;
    let w = z * z;
    let s1 = z * (3.3333328366e-01 + w * (1.4253635705e-01 + w * 6.1687607318e-02));
    let s2 = w * (-1.9999158382e-01 + w * -1.0648017377e-01);
    if (id < 0) {
        return x - x * (s1 + s2);
    }
    let hi = array<f32, 4>(4.6364760399e-01, 7.8539812565e-01, 9.8279368877e-01, 1.5707962513e+00);
    let lo = array<f32, 4>(5.0121582440e-09, 3.7748947079e-08, 3.4473217170e-08, 7.5497894159e-08);
    let r = hi[id] - ((x * (s1 + s2) - lo[id]) - x);
    return select(r, -r, negative);
}

fn fur_atan2(y: f32, x: f32) -> f32 {
    let bx = bitcast<u32>(x);
    let by = bitcast<u32>(y);
    if (bx == 0x3f800000u) {
        return fur_atan(y);
    }
    let m = ((by >> 31u) & 1u) | ((bx >> 30u) & 2u);
    let ix = bx & 0x7fffffffu;
    let iy = by & 0x7fffffffu;
    if (iy == 0u) {
        if (m < 2u) {
            return y;
        }
        return select(FUR_PI, -FUR_PI, m == 3u);
    }
    if (ix == 0u) {
        return select(FUR_HALF_PI, -FUR_HALF_PI, (m & 1u) != 0u);
    }
    if (ix + (26u << 23u) < iy) {
        return select(FUR_HALF_PI, -FUR_HALF_PI, (m & 1u) != 0u);
    }
    var z = 0.0;
    if (!((m & 2u) != 0u && iy + (26u << 23u) < ix)) {
        z = fur_atan(abs(y / x));
    }
    let pi_lo = -8.7422776573e-08;
    switch m {
        case 0u: { return z; }
        case 1u: { return -z; }
        case 2u: { return FUR_PI - (z - pi_lo); }
        default: { return (z - pi_lo) - FUR_PI; }
    }
}

// Far-field S from world-space vectors (BakedBcsdf::eval_far_dirs, Angles::from_directions):
// wi toward the light, wr toward the viewer, u the fiber tangent; none needs unit length.
fn fur_eval_far_dirs(wi: vec3<f32>, wr: vec3<f32>, u: vec3<f32>) -> FurFamilies {
    for (var k = 0u; k < 3u; k = k + 1u) {
        if (!(fur_finite(wi[k]) && fur_finite(wr[k]) && fur_finite(u[k]))) {
            return fur_zero();
        }
    }
    let ni = sqrt(dot(wi, wi));
    let nr = sqrt(dot(wr, wr));
    let nu = sqrt(dot(u, u));
    if (!(fur_finite(ni) && fur_finite(nr) && fur_finite(nu))) {
        return fur_zero();
    }
    let min_positive = 1.17549435e-38;
    if (ni < min_positive || nr < min_positive || nu < min_positive) {
        return fur_zero();
    }
    let un = u / nu;
    let si = dot(wi, un) / ni;
    let sr = dot(wr, un) / nr;
    let theta_i = fur_asin(clamp(si, -1.0, 1.0));
    let theta_r = fur_asin(clamp(sr, -1.0, 1.0));
    let pi = wi / ni - si * un;
    let pr = wr / nr - sr * un;
    let phi = fur_atan2(dot(un, cross(pi, pr)), dot(pi, pr));
    return fur_eval_far(theta_i, theta_r, phi);
}

// ---- Entry points for the tests and `viewer probe --gpu` (bindings 1 and 2) ----

// Queries: (theta_i, theta_r, phi, unused) per evaluation; or, for fur_eval_dirs_main,
// three vec4 per evaluation (wi, wr, tangent; w unused).
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

@compute @workgroup_size(64)
fn fur_eval_main(@builtin(global_invocation_id) id: vec3<u32>) {
    let q = id.x;
    if (q >= arrayLength(&fur_queries)) {
        return;
    }
    let a = fur_queries[q];
    fur_store(q, fur_eval_far(a.x, a.y, a.z));
}

@compute @workgroup_size(64)
fn fur_eval_dirs_main(@builtin(global_invocation_id) id: vec3<u32>) {
    let q = id.x;
    if (3u * q + 2u >= arrayLength(&fur_queries)) {
        return;
    }
    let f = fur_eval_far_dirs(
        fur_queries[3u * q].xyz,
        fur_queries[3u * q + 1u].xyz,
        fur_queries[3u * q + 2u].xyz,
    );
    fur_store(q, f);
}
