//! Four f32 lanes for the texel kernels ([`super::texels`]): SSE2 where the target enables
//! it at compile time (every x86-64 target with a floating-point unit; not the soft-float
//! ones such as `x86_64-unknown-none`), so no runtime detection and no `target-cpu` flag;
//! plain arrays elsewhere. docs/benchmarks.md says why this is written out rather than left to the
//! auto-vectoriser (it spread the pair-wise texel reads across scalar registers).
//!
//! Every operation is a lane-wise IEEE-754 operation (add, multiply, and the exact
//! half-to-float shift of [`crate::lut::f16_biased`]), so both implementations give the same
//! bits; `tests::matches_portable` checks the SSE2 one against the portable one.

#[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
pub(crate) use sse2::F4;

#[cfg(not(all(target_arch = "x86_64", target_feature = "sse2")))]
pub(crate) use portable::F4;

/// Compiled only where the target enables SSE2 (the `cfg` below): every SAFETY comment in
/// this module rests on that, since the intrinsics require the feature.
#[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
mod sse2 {
    use core::arch::x86_64::{
        __m128, _mm_add_ps, _mm_castsi128_ps, _mm_loadl_epi64, _mm_loadu_si128, _mm_mul_ps,
        _mm_set1_ps, _mm_setzero_si128, _mm_slli_epi32, _mm_storeu_ps, _mm_unpackhi_epi16,
        _mm_unpacklo_epi16,
    };

    /// Four f32 lanes in an SSE register.
    #[derive(Clone, Copy, Debug)]
    pub(crate) struct F4(__m128);

    impl F4 {
        /// `v` in every lane.
        #[inline(always)]
        pub(crate) fn splat(v: f32) -> F4 {
            // SAFETY: the target enables SSE2 (this module's `cfg`).
            let lanes = unsafe { _mm_set1_ps(v) };
            F4(lanes)
        }

        /// Lane-wise product.
        #[inline(always)]
        pub(crate) fn mul(self, a: F4) -> F4 {
            // SAFETY: the target enables SSE2 (this module's `cfg`).
            let lanes = unsafe { _mm_mul_ps(self.0, a.0) };
            F4(lanes)
        }

        /// Lane-wise sum.
        #[inline(always)]
        pub(crate) fn add(self, a: F4) -> F4 {
            // SAFETY: the target enables SSE2 (this module's `cfg`).
            let lanes = unsafe { _mm_add_ps(self.0, a.0) };
            F4(lanes)
        }

        /// The lanes as an array.
        #[inline(always)]
        pub(crate) fn to_array(self) -> [f32; 4] {
            let mut out = [0.0; 4];
            // SAFETY: the target enables SSE2 (this module's `cfg`); `out` is 16 writable
            // bytes and `storeu` has no alignment requirement.
            unsafe { _mm_storeu_ps(out.as_mut_ptr(), self.0) };
            out
        }

        /// Four halves (eight little-endian bytes) decoded × 2^−112: zero-extended to 32
        /// bits and shifted into an f32's exponent and mantissa.
        #[inline(always)]
        pub(crate) fn halves4(b: &[u8; 8]) -> F4 {
            // SAFETY: the target enables SSE2 (this module's `cfg`); `b` is 8 readable
            // bytes and `loadl_epi64` reads 8 bytes, unaligned.
            unsafe {
                let v = _mm_loadl_epi64(b.as_ptr().cast());
                let wide = _mm_unpacklo_epi16(v, _mm_setzero_si128());
                F4(_mm_castsi128_ps(_mm_slli_epi32::<13>(wide)))
            }
        }

        /// Eight halves (sixteen bytes) decoded as [`F4::halves4`], low four first.
        #[inline(always)]
        pub(crate) fn halves8(b: &[u8; 16]) -> [F4; 2] {
            // SAFETY: the target enables SSE2 (this module's `cfg`); `b` is 16 readable
            // bytes and `loadu_si128` has no alignment requirement.
            unsafe {
                let v = _mm_loadu_si128(b.as_ptr().cast());
                let z = _mm_setzero_si128();
                let lo = _mm_slli_epi32::<13>(_mm_unpacklo_epi16(v, z));
                let hi = _mm_slli_epi32::<13>(_mm_unpackhi_epi16(v, z));
                [F4(_mm_castsi128_ps(lo)), F4(_mm_castsi128_ps(hi))]
            }
        }
    }
}

#[cfg_attr(all(target_arch = "x86_64", target_feature = "sse2"), allow(dead_code))]
mod portable {
    /// Four f32 lanes in an array.
    #[derive(Clone, Copy, Debug)]
    pub(crate) struct F4([f32; 4]);

    impl F4 {
        #[inline(always)]
        fn zip(self, a: F4, f: impl Fn(f32, f32) -> f32) -> F4 {
            F4([
                f(self.0[0], a.0[0]),
                f(self.0[1], a.0[1]),
                f(self.0[2], a.0[2]),
                f(self.0[3], a.0[3]),
            ])
        }

        /// `v` in every lane.
        #[inline(always)]
        pub(crate) fn splat(v: f32) -> F4 {
            F4([v; 4])
        }

        /// Lane-wise product.
        #[inline(always)]
        pub(crate) fn mul(self, a: F4) -> F4 {
            self.zip(a, |x, y| x * y)
        }

        /// Lane-wise sum.
        #[inline(always)]
        pub(crate) fn add(self, a: F4) -> F4 {
            self.zip(a, |x, y| x + y)
        }

        /// The lanes as an array.
        #[inline(always)]
        pub(crate) fn to_array(self) -> [f32; 4] {
            self.0
        }

        /// Four halves (eight little-endian bytes) decoded × 2^−112.
        #[inline(always)]
        pub(crate) fn halves4(b: &[u8; 8]) -> F4 {
            let h = |i: usize| crate::lut::f16_biased(u16::from_le_bytes([b[2 * i], b[2 * i + 1]]));
            F4([h(0), h(1), h(2), h(3)])
        }

        /// Eight halves (sixteen bytes), low four first.
        #[inline(always)]
        pub(crate) fn halves8(b: &[u8; 16]) -> [F4; 2] {
            let (lo, hi) = b.split_at(8);
            [
                F4::halves4(lo.try_into().unwrap_or(&[0; 8])),
                F4::halves4(hi.try_into().unwrap_or(&[0; 8])),
            ]
        }
    }
}

#[cfg(all(test, target_arch = "x86_64", target_feature = "sse2"))]
mod tests {
    use super::{portable, sse2};

    #[test]
    fn matches_portable() {
        // Every half bit pattern through both decoders, and the arithmetic on the results.
        let mut bytes = [0u8; 16];
        for start in (0..=u16::MAX).step_by(8) {
            for (i, pair) in bytes.chunks_exact_mut(2).enumerate() {
                pair.copy_from_slice(&start.wrapping_add(i as u16).to_le_bytes());
            }
            let [a, b] = sse2::F4::halves8(&bytes);
            let [c, d] = portable::F4::halves8(&bytes);
            let w = 0.3_f32 * (start as f32 + 1.0);
            let x = a.mul(sse2::F4::splat(w)).add(b);
            let y = c.mul(portable::F4::splat(w)).add(d);
            for (p, q) in [(a.to_array(), c.to_array()), (x.to_array(), y.to_array())] {
                assert_eq!(
                    p.map(f32::to_bits),
                    q.map(f32::to_bits),
                    "halves from {start}"
                );
            }
        }
    }
}

/// Whether this x86-64 CPU and its OS support AVX2 and F16C (CPUID, and XGETBV for the
/// AVX register state). No std: read from CPUID directly, once per [`super::BakedBcsdf`].
/// Under Miri, which cannot execute CPUID, the answer is what the build enables statically
/// (`-C target-feature`): the interpreted CPU has exactly those features.
#[cfg(target_arch = "x86_64")]
pub(crate) fn avx2_f16c() -> bool {
    use core::arch::x86_64::{__cpuid, __cpuid_count, _xgetbv};
    if cfg!(miri) {
        return cfg!(all(
            target_feature = "avx",
            target_feature = "avx2",
            target_feature = "f16c"
        ));
    }
    // SAFETY: CPUID exists on every x86-64 CPU; leaf 7 is read only when leaf 0 says it
    // exists; XGETBV is executed only when CPUID reports OSXSAVE (the OS enabled it).
    unsafe {
        if __cpuid(0).eax < 7 {
            return false;
        }
        let ecx = __cpuid(1).ecx;
        let (osxsave, avx, f16c) = (ecx & 1 << 27 != 0, ecx & 1 << 28 != 0, ecx & 1 << 29 != 0);
        if !(osxsave && avx && f16c) {
            return false;
        }
        // XMM and YMM state enabled by the OS.
        if _xgetbv(0) & 0b110 != 0b110 {
            return false;
        }
        __cpuid_count(7, 0).ebx & 1 << 5 != 0
    }
}
