//! Reading and interpolating the half-float texels of the three tables (docs/lut.md): the
//! inner kernel of every baked evaluation, scalar or batched.
//!
//! Each kernel reads whole runs of adjacent halves (a texel pair is contiguous in a row-major
//! table; table `N`'s is 16 bytes, the four families of two texels) and works on four channels
//! at a time ([`F4`]), so that the half-to-float decode
//! (a zero-extension and one shift, [`crate::lut::f16_biased`]) and the weighted sums map
//! onto 4-wide SIMD registers (SSE2, NEON) without shuffles. Every channel is still computed
//! by the same sequence of IEEE operations as the scalar formula
//! ((w₀·t₀ + w₁·t₁) + w₂·b₀) + w₃·b₁, so the results do not depend on how the compiler maps
//! the lanes.
//!
//! A read that would fall outside the data is clamped to its end (validation makes this
//! unreachable; it keeps the kernels free of panics and of out-of-bounds reads).

use super::simd::F4;
use crate::lut::absorption_coordinate;
use crate::spectrum::Rgb;

/// How an evaluation reads table `N` (`BakedBcsdf::kernel`). A kernel is a value: a kernel
/// that needs CPU features is a token that only their detection constructs, so holding one
/// is the proof that its instructions may run.
pub(crate) trait NKernel: Copy {
    /// Whether the kernel decodes true half values (F16C), so that the weights carry the
    /// table scale itself, not scale × 2^112 (`BakedBcsdf::place`).
    const TRUE_HALVES: bool;

    /// Table `N` at one colour, as [`n_at_colour`].
    fn n_at_colour(
        self,
        data: &[u8],
        width: usize,
        index: usize,
        w: [f32; 4],
        at: &ColourAt,
    ) -> [f32; 12];
}

/// Where a colour reads table `N` (docs/lut.md "The absorption axis"): per RGB channel, the
/// first texel of the first of its three absorption planes and the three planes' weights
/// (`BakedBcsdf::locate_colour`).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ColourAt {
    /// Texel offset k·(n_phi·n_theta_r) of plane k, the first of each channel's three nodes.
    pub(crate) plane: [usize; 3],
    /// Weights of planes k, k + 1, k + 2, plane-major: `w[j][c]` is plane k + j's weight for
    /// channel c (quadratic Lagrange weights; a channel's three sum to 1); lane 3 is unused.
    /// Plane-major, so that the lane loop that computes them stores them without a
    /// transposition.
    pub(crate) w: [[f32; 4]; 3],
    /// Texels per plane (the distance from plane k to plane k + 1).
    pub(crate) stride: usize,
}

/// [`BakedBcsdf::locate_colour`]: per channel, the coordinate
/// x = [`absorption_coordinate`]`(σ, s₀)`, then [`ColourAt::from_coordinates`]. The three
/// coordinates are computed in one lane loop over four lanes (the third channel twice), which
/// the compiler turns into 4-wide SIMD: the two exponentials, the square root and the
/// division of each channel cost about what one channel's did.
#[inline(always)]
pub(crate) fn locate_colour(
    sigma: Rgb,
    scale: f32,
    last: f32,
    first_of_last: f32,
    plane: usize,
) -> ColourAt {
    let [r, g, b] = sigma.0;
    let lanes = [r, g, b, b];
    let mut x = [0.0f32; 4];
    for c in 0..4 {
        x[c] = absorption_coordinate(lanes[c], scale);
    }
    ColourAt::from_coordinates(x, last, first_of_last, plane)
}

impl ColourAt {
    /// The colour whose channels 0, 1, 2 sit at absorption coordinates `x[0..3]`
    /// ([`absorption_coordinate`], in [0, 1]; lane 3 is ignored) on an axis of n nodes
    /// (`last` = n − 1, `first_of_last` = n − 3, [`first_of_last`]) whose planes are `plane`
    /// texels apart: each channel placed by [`axis_place`]. A lane loop without branches: 4-wide SIMD.
    #[inline(always)]
    pub(crate) fn from_coordinates(
        x: [f32; 4],
        last: f32,
        first_of_last: f32,
        plane: usize,
    ) -> ColourAt {
        let mut k = [0u32; 4];
        let mut w = [[0.0f32; 4]; 3];
        for c in 0..4 {
            let (kc, wc) = axis_place(x[c], last, first_of_last);
            k[c] = kc;
            for j in 0..3 {
                w[j][c] = wc[j];
            }
        }
        ColourAt {
            plane: core::array::from_fn(|c| k[c] as usize * plane),
            w,
            stride: plane,
        }
    }

    /// The colour whose channel c reads planes `k[c]`, `k[c]` + 1, `k[c]` + 2 with weights
    /// `w(c, 0..3)` ([`axis_place`]), planes `plane` texels apart.
    #[inline(always)]
    pub(crate) fn from_nodes(
        k: [u32; 3],
        w: impl Fn(usize, usize) -> f32,
        plane: usize,
    ) -> ColourAt {
        ColourAt {
            plane: core::array::from_fn(|c| k[c] as usize * plane),
            w: core::array::from_fn(|j| [w(0, j), w(1, j), w(2, j), 0.0]),
            stride: plane,
        }
    }
}

impl ColourAt {
    /// Channel `c`'s weights of its planes k, k + 1, k + 2.
    #[inline(always)]
    pub(crate) fn weights(&self, c: usize) -> [f32; 3] {
        [self.w[0][c], self.w[1][c], self.w[2][c]]
    }
}

/// n − 3 of an absorption axis of `nodes` nodes, the last first node of a channel's three
/// (as f32, exact: `nodes` ∈ [3, 8192], `lut::validate`).
#[inline(always)]
pub(crate) fn first_of_last(nodes: usize) -> f32 {
    nodes.saturating_sub(3) as f32
}

/// One channel's place on the absorption axis (docs/lut.md "The absorption axis"): at
/// coordinate `x` ([`absorption_coordinate`], in [0, 1]) on an axis with `last` = n − 1 and
/// `first_of_last` = n − 3 ([`first_of_last`]), u = x·(n − 1), the first of three nodes
/// k = min(⌊u⌋, n − 3) and the quadratic Lagrange weights of nodes k, k + 1, k + 2 at
/// t = u − k: (t − 1)(t − 2)/2, t(2 − t), t(t − 1)/2. The interpolant passes through every
/// node, so it is continuous where k changes. Branch-free, so that a lane loop over channels
/// or queries vectorises ([`ColourAt::from_coordinates`], the batch).
#[inline(always)]
pub(crate) fn axis_place(x: f32, last: f32, first_of_last: f32) -> (u32, [f32; 3]) {
    // The clamps as compare-and-select (`minps`/`maxps` per lane; `f32::min` would add a
    // NaN test per clamp): NaN fails `u > 0` and becomes 0.
    let u = x * last;
    let u = if u > 0.0 { u } else { 0.0 };
    let u = if u < last { u } else { last };
    // min(⌊u⌋, n − 3) = ⌊min(u, n − 3)⌋: the clamp in f32, so that a lane loop's
    // truncations are one SSE2 instruction (an i32 `min` is SSE4.1).
    let lower = if u < first_of_last { u } else { first_of_last };
    // SAFETY: `lower` ∈ [0, n − 3] and never NaN (the first select maps NaN to 0), and the
    // axis has at most MAX_NODES = 8192 nodes, so the truncation to i32 is in range;
    // unchecked, it is one instruction instead of a saturating sequence (as `Axis::locate`).
    let k = unsafe { lower.to_int_unchecked::<i32>() };
    let t = u - k as f32;
    // k ∈ [0, n − 3]: non-negative.
    (
        k as u32,
        [
            0.5 * (t - 1.0) * (t - 2.0),
            t * (2.0 - t),
            0.5 * t * (t - 1.0),
        ],
    )
}

/// [`n_bilinear`]: four lanes (SSE2 where the target has it, portable arrays elsewhere).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Baseline;

impl NKernel for Baseline {
    const TRUE_HALVES: bool = false;
    #[inline(always)]
    fn n_at_colour(
        self,
        data: &[u8],
        width: usize,
        index: usize,
        w: [f32; 4],
        at: &ColourAt,
    ) -> [f32; 12] {
        n_at_colour(data, width, index, w, at)
    }
}

/// `B` bytes from `start`, clamped so that the read stays inside `data` (zeros if `data`
/// is shorter than `B`). Validation and the axis clamping make the clamp a no-op; it makes
/// the read safe whatever the index, at one compare per read.
#[inline(always)]
fn bytes<const B: usize>(data: &[u8], start: usize) -> &[u8; B] {
    let start = start.min(data.len().saturating_sub(B));
    data.get(start..)
        .and_then(<[u8]>::first_chunk)
        .unwrap_or(&[0; B])
}

/// The four bilinear corner weights for row weight `wy` and column weight `wx`, with the
/// table's scale `k` folded in: (1−wy)(1−wx), (1−wy)wx, wy(1−wx), wy·wx, each × k.
#[inline(always)]
pub(crate) fn corner_weights(wy: f32, wx: f32, k: f32) -> [f32; 4] {
    let (ky0, ky1) = ((1.0 - wy) * k, wy * k);
    [ky0 * (1.0 - wx), ky0 * wx, ky1 * (1.0 - wx), ky1 * wx]
}

/// The twelve weights of one colour channel's read, in the order the kernels sum them: for
/// the left texels and for the right texels, the two |θ_r| rows of plane k, then of plane
/// k + 1, then of plane k + 2; `t` holds the three planes' weights.
#[inline(always)]
pub(crate) fn plane_weights(w: [f32; 4], t: [f32; 3]) -> ([f32; 6], [f32; 6]) {
    (
        [
            t[0] * w[0],
            t[0] * w[2],
            t[1] * w[0],
            t[1] * w[2],
            t[2] * w[0],
            t[2] * w[2],
        ],
        [
            t[0] * w[1],
            t[0] * w[3],
            t[1] * w[1],
            t[1] * w[3],
            t[2] * w[1],
            t[2] * w[3],
        ],
    )
}

/// Table `N` (4 channels: R, TT, TRT, s per plane) at one colour: for each RGB channel c,
/// bilinearly in (|θ_r|, |φ|) with corner weights `w` ([`corner_weights`]) at texel `index`
/// of the three planes of `at` around that channel's σ_ca, combined with the planes'
/// quadratic weights. Per channel and family the sum runs over the six rows of the left
/// texels in [`plane_weights`] order, the same over the right texels, then left + right;
/// the result is kept ≥ 0 (the quadratic can undershoot where a family falls to 0).
/// Returns the families' RGB, family-major (R.R, R.G, R.B, TT.R, …).
#[inline(always)]
pub(crate) fn n_at_colour(
    data: &[u8],
    width: usize,
    index: usize,
    w: [f32; 4],
    at: &ColourAt,
) -> [f32; 12] {
    let mut out = [0.0; 12];
    for c in 0..3 {
        let t0 = at.plane[c] + index;
        let rows = [
            t0,
            t0 + width,
            t0 + at.stride,
            t0 + at.stride + width,
            t0 + 2 * at.stride,
            t0 + 2 * at.stride + width,
        ]
        .map(|t| F4::halves8(bytes::<16>(data, 8 * t)));
        let (l, r) = plane_weights(w, at.weights(c));
        let side = |s: usize, k: [f32; 6]| {
            let mut acc = rows[0][s].mul(F4::splat(k[0]));
            for i in 1..6 {
                acc = acc.add(rows[i][s].mul(F4::splat(k[i])));
            }
            acc
        };
        let v = side(0, l).add(side(1, r)).to_array();
        for f in 0..4 {
            out[3 * f + c] = v[f].max(0.0);
        }
    }
    out
}

/// Table `N`'s lossless plane (σ_ca = 0, the sampler's densities, docs/lut.md "Sampling
/// data") bilinearly at texel `index`: the four families.
#[inline(always)]
pub(crate) fn n_lossless(data: &[u8], width: usize, index: usize, w: [f32; 4]) -> [f32; 4] {
    let a = F4::halves8(bytes::<16>(data, 8 * index));
    let b = F4::halves8(bytes::<16>(data, 8 * (index + width)));
    let [w0, w1, w2, w3] = w.map(F4::splat);
    a[0].mul(w0)
        .add(a[1].mul(w1))
        .add(b[0].mul(w2))
        .add(b[1].mul(w3))
        .to_array()
}

/// Table `M` (3 channels) linearly between texels `index` and `index + 1` with weights
/// `w0`, `w1` (scale folded in). `data` must continue past the table (the blob does: table
/// `N` follows), so that the pair is read as one run of eight halves.
#[inline(always)]
pub(crate) fn m_linear(data: &[u8], start: usize, index: usize, w0: f32, w1: f32) -> [f32; 3] {
    let [a, b] = F4::halves8(bytes::<16>(data, start + 6 * index));
    let (a, b) = (a.to_array(), b.to_array());
    // Texel `index` is a[0..3], texel `index + 1` is a[3], b[0], b[1].
    [
        w0 * a[0] + w1 * a[3],
        w0 * a[1] + w1 * b[0],
        w0 * a[2] + w1 * b[1],
    ]
}

/// Table `M_s` (2 channels) bilinearly, as [`n_lossless`].
#[inline(always)]
pub(crate) fn ms_bilinear(data: &[u8], width: usize, index: usize, w: [f32; 4]) -> [f32; 2] {
    let t = F4::halves4(bytes::<8>(data, 4 * index)).to_array();
    let b = F4::halves4(bytes::<8>(data, 4 * (index + width))).to_array();
    let mut out = [0.0; 2];
    for c in 0..2 {
        out[c] = w[0] * t[c] + w[1] * t[2 + c] + w[2] * b[c] + w[3] * b[2 + c];
    }
    out
}

/// Table `N` with AVX and F16C: `vcvtph2ps` converts eight halves per instruction (true
/// values, so the weights `w` must not carry the 2^112 of the biased decode: the evaluator
/// takes it off the table scale once, at load ([`NKernel::TRUE_HALVES`]), which keeps every product
/// and sum bit for bit those of [`n_at_colour`]: a power-of-two rescaling, exact in the normal
/// range the weights stay in), a texel pair (both texels' four families) in one 256-bit
/// register.
///
/// A value of this type is the proof that the CPU and its OS support AVX, AVX2 and F16C:
/// its field is private to this module and [`Avx2F16c::detect`] is its only constructor.
/// The kernel runs correctly anywhere it is called; it is fast where it is inlined into a
/// function compiled with those features (`BakedBcsdf`'s `*_avx2` functions, which take
/// the token too).
#[cfg(target_arch = "x86_64")]
#[derive(Clone, Copy, Debug)]
pub(crate) struct Avx2F16c {
    _proof: (),
}

#[cfg(target_arch = "x86_64")]
impl Avx2F16c {
    /// The token, if this CPU and its OS support AVX, AVX2 and F16C (CPUID and XGETBV).
    pub(crate) fn detect() -> Option<Avx2F16c> {
        super::simd::avx2_f16c().then_some(Avx2F16c { _proof: () })
    }
}

#[cfg(target_arch = "x86_64")]
impl NKernel for Avx2F16c {
    const TRUE_HALVES: bool = true;
    #[inline(always)]
    fn n_at_colour(
        self,
        data: &[u8],
        width: usize,
        index: usize,
        w: [f32; 4],
        at: &ColourAt,
    ) -> [f32; 12] {
        use core::arch::x86_64::{
            __m256, _mm256_add_ps, _mm256_castps256_ps128, _mm256_cvtph_ps, _mm256_extractf128_ps,
            _mm256_mul_ps, _mm256_setr_ps, _mm_add_ps, _mm_loadu_si128, _mm_storeu_ps,
        };
        let mut out = [0.0; 12];
        for c in 0..3 {
            let t0 = at.plane[c] + index;
            let rows = [
                t0,
                t0 + width,
                t0 + at.stride,
                t0 + at.stride + width,
                t0 + 2 * at.stride,
                t0 + 2 * at.stride + width,
            ]
            .map(|t| bytes::<16>(data, 8 * t));
            let (l, r) = plane_weights(w, at.weights(c));
            let mut v = [0.0f32; 4];
            // SAFETY: `self` exists, so `detect` found AVX, AVX2 and F16C on this CPU and OS
            // (the intrinsics' target features); each load reads one 16-byte texel pair
            // (`bytes` keeps it inside `data`); the store writes the 4 floats of `v`.
            unsafe {
                // A texel pair: the left texel's four families in lanes 0–3, the right's in
                // 4–7, each lane the same products and sums as `n_at_colour`.
                let pair = |b: &[u8; 16]| -> __m256 {
                    _mm256_cvtph_ps(_mm_loadu_si128(b.as_ptr().cast()))
                };
                let k = |i: usize| _mm256_setr_ps(l[i], l[i], l[i], l[i], r[i], r[i], r[i], r[i]);
                let mut acc = _mm256_mul_ps(pair(rows[0]), k(0));
                for (i, row) in rows.iter().enumerate().skip(1) {
                    acc = _mm256_add_ps(acc, _mm256_mul_ps(pair(row), k(i)));
                }
                let sum = _mm_add_ps(_mm256_castps256_ps128(acc), _mm256_extractf128_ps::<1>(acc));
                _mm_storeu_ps(v.as_mut_ptr(), sum);
            }
            for f in 0..4 {
                out[3 * f + c] = v[f].max(0.0);
            }
        }
        out
    }
}
