//! Reading and interpolating the half-float texels of the three tables (docs/lut.md): the
//! inner kernel of every baked evaluation, scalar or batched.
//!
//! Each kernel reads whole runs of adjacent halves (a texel pair is contiguous in a row-major
//! table) and works on four channels at a time ([`F4`]), so that the half-to-float decode
//! (a zero-extension and one shift, [`crate::lut::f16_biased`]) and the weighted sums map
//! onto 4-wide SIMD registers (SSE2, NEON) without shuffles. Every channel is still computed
//! by the same sequence of IEEE operations as the scalar formula
//! ((w₀·t₀ + w₁·t₁) + w₂·b₀) + w₃·b₁, so the results do not depend on how the compiler maps
//! the lanes.
//!
//! A read that would fall outside the data is clamped to its end (validation makes this
//! unreachable; it keeps the kernels free of panics and of out-of-bounds reads).

use super::simd::F4;

/// How an evaluation reads table `N` (`BakedBcsdf::kernel`). A kernel is a value: a kernel
/// that needs CPU features is a token that only their detection constructs, so holding one
/// is the proof that its instructions may run.
pub(crate) trait NKernel: Copy {
    /// Whether the kernel decodes true half values (F16C), so that the weights carry the
    /// table scale itself, not scale × 2^112 (`BakedBcsdf::place`).
    const TRUE_HALVES: bool;

    /// Table `N` bilinearly, as [`n_bilinear`].
    fn n_bilinear(self, data: &[u8], width: usize, index: usize, w: [f32; 4]) -> [f32; 12];
}

/// [`n_bilinear`]: four lanes (SSE2 where the target has it, portable arrays elsewhere).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Baseline;

impl NKernel for Baseline {
    const TRUE_HALVES: bool = false;
    #[inline(always)]
    fn n_bilinear(self, data: &[u8], width: usize, index: usize, w: [f32; 4]) -> [f32; 12] {
        n_bilinear(data, width, index, w)
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

/// The 24 halves of a 12-channel texel pair: texel `i` in groups 0–2, texel `i + 1` in 3–5.
#[inline(always)]
fn decode24(b: &[u8; 48]) -> [F4; 6] {
    let (a, rest) = b.split_at(16);
    let (c, d) = rest.split_at(16);
    let [g0, g1] = F4::halves8(a.try_into().unwrap_or(&[0; 16]));
    let [g2, g3] = F4::halves8(c.try_into().unwrap_or(&[0; 16]));
    let [g4, g5] = F4::halves8(d.try_into().unwrap_or(&[0; 16]));
    [g0, g1, g2, g3, g4, g5]
}

/// The four bilinear corner weights for row weight `wy` and column weight `wx`, with the
/// table's scale `k` folded in: (1−wy)(1−wx), (1−wy)wx, wy(1−wx), wy·wx, each × k.
#[inline(always)]
pub(crate) fn corner_weights(wy: f32, wx: f32, k: f32) -> [f32; 4] {
    let (ky0, ky1) = ((1.0 - wy) * k, wy * k);
    [ky0 * (1.0 - wx), ky0 * wx, ky1 * (1.0 - wx), ky1 * wx]
}

/// Table `N` (12 channels) bilinearly: corner weights `w` ([`corner_weights`]) at texel
/// `index` (row-major, row `width` texels long) and its right and lower neighbours.
#[inline(always)]
pub(crate) fn n_bilinear(data: &[u8], width: usize, index: usize, w: [f32; 4]) -> [f32; 12] {
    let top = decode24(bytes::<48>(data, 24 * index));
    let bottom = decode24(bytes::<48>(data, 24 * (index + width)));
    let [w0, w1, w2, w3] = w.map(F4::splat);
    let mut out = [0.0; 12];
    for g in 0..3 {
        // ((w0·t0 + w1·t1) + w2·b0) + w3·b1, lane-wise.
        let s = w0.mul(top[g]).add(w1.mul(top[g + 3]));
        let s = s.add(w2.mul(bottom[g])).add(w3.mul(bottom[g + 3]));
        out[4 * g..4 * g + 4].copy_from_slice(&s.to_array());
    }
    out
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

/// Table `M_s` (2 channels) bilinearly, as [`n_bilinear`].
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
/// and sum bit for bit those of [`n_bilinear`]: a power-of-two rescaling, exact in the normal
/// range the weights stay in), eight channels in a 256-bit register and four in a 128-bit
/// one.
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
    fn n_bilinear(self, data: &[u8], width: usize, index: usize, w: [f32; 4]) -> [f32; 12] {
        use core::arch::x86_64::{
            __m128, __m256, _mm256_add_ps, _mm256_cvtph_ps, _mm256_mul_ps, _mm256_set1_ps,
            _mm256_storeu_ps, _mm_add_ps, _mm_cvtph_ps, _mm_loadl_epi64, _mm_loadu_si128,
            _mm_mul_ps, _mm_set1_ps, _mm_storeu_ps,
        };
        let top = bytes::<48>(data, 24 * index);
        let bottom = bytes::<48>(data, 24 * (index + width));
        let mut out = [0.0; 12];
        // SAFETY: `self` exists, so `detect` found AVX, AVX2 and F16C on this CPU and OS
        // (the intrinsics' target features); every load reads inside a 48-byte texel pair
        // (offsets 0 and 24: 16 bytes; 16 and 40: 8 bytes); the stores write inside `out`
        // (8 floats at 0, 4 at 8 of 12).
        unsafe {
            // Channels 0–7 of texels i and i + 1 (halves 0–7 and 12–19), channels 8–11
            // (halves 8–11 and 20–23).
            let wide = |b: &[u8; 48], at: usize| -> __m256 {
                _mm256_cvtph_ps(_mm_loadu_si128(b.as_ptr().add(at).cast()))
            };
            let narrow = |b: &[u8; 48], at: usize| -> __m128 {
                _mm_cvtph_ps(_mm_loadl_epi64(b.as_ptr().add(at).cast()))
            };
            let [w0, w1, w2, w3] = w.map(|x| _mm256_set1_ps(x));
            let lo = _mm256_add_ps(
                _mm256_mul_ps(w0, wide(top, 0)),
                _mm256_mul_ps(w1, wide(top, 24)),
            );
            let lo = _mm256_add_ps(lo, _mm256_mul_ps(w2, wide(bottom, 0)));
            let lo = _mm256_add_ps(lo, _mm256_mul_ps(w3, wide(bottom, 24)));
            let [v0, v1, v2, v3] = w.map(|x| _mm_set1_ps(x));
            let hi = _mm_add_ps(
                _mm_mul_ps(v0, narrow(top, 16)),
                _mm_mul_ps(v1, narrow(top, 40)),
            );
            let hi = _mm_add_ps(hi, _mm_mul_ps(v2, narrow(bottom, 16)));
            let hi = _mm_add_ps(hi, _mm_mul_ps(v3, narrow(bottom, 40)));
            _mm256_storeu_ps(out.as_mut_ptr(), lo);
            _mm_storeu_ps(out.as_mut_ptr().add(8), hi);
        }
        out
    }
}
