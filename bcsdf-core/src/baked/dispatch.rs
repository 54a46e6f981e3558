//! The one kernel dispatcher of the baked evaluator (docs/model.md §8): every entry point
//! that reads the tables (`eval_far`, `eval_far_dirs`, the samplers' lookups, the batch) is
//! a [`KernelOp`], run by [`BakedBcsdf::dispatch`] with the kernel chosen at load: inlined
//! into a function compiled for AVX2 and F16C where the CPU has them, into a baseline one
//! elsewhere. A new entry point is a new op, not a new `#[target_feature]` copy.

#[cfg(target_arch = "x86_64")]
use super::texels::Avx2F16c;
use super::texels::{Baseline, NKernel};
use super::{BakedBcsdf, Isa};
use crate::math::Math;

/// Work that reads the tables with a table-`N` kernel `K` (always inlined into the
/// dispatcher's per-kernel functions, so that it is compiled with the kernel's features).
pub(crate) trait KernelOp<M: Math> {
    /// What the work returns.
    type Output;
    /// Does the work with `kernel`.
    fn run<K: NKernel>(self, lut: &BakedBcsdf<'_, M>, kernel: K) -> Self::Output;
}

impl<M: Math> BakedBcsdf<'_, M> {
    /// Runs `op` with the kernel chosen at load (`Isa::best`, or `with_kernel`).
    #[inline(always)]
    pub(crate) fn dispatch<O: KernelOp<M>>(&self, op: O) -> O::Output {
        match self.kernel {
            Isa::Baseline => op.run(self, Baseline),
            #[cfg(target_arch = "x86_64")]
            // SAFETY: `token` exists, so `Avx2F16c::detect` found AVX, AVX2 and F16C on this
            // CPU and OS: the target features `dispatch_avx2` is compiled with.
            Isa::Avx2F16c(token) => unsafe { self.dispatch_avx2(token, op) },
        }
    }

    /// [`BakedBcsdf::dispatch`]'s AVX2 + F16C side: `op` compiled for those features
    /// (`token` proves the CPU has them).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx,avx2,f16c")]
    fn dispatch_avx2<O: KernelOp<M>>(&self, token: Avx2F16c, op: O) -> O::Output {
        op.run(self, token)
    }
}
