//! Batch evaluation of the baked far field (docs/model.md §8): many queries per call, in
//! structure-of-arrays form, for wavefront renderers, per-tile shading and light lists.
//!
//! The queries go through in chunks of [`CHUNK`], in three passes:
//!
//! 1. validation and φ wrapping (exactly [`Angles::new`](crate::Angles::new));
//! 2. the axis locations, interpolation weights, |φ|/π and 1/cos²θ_i of every query
//!    ([`BakedBcsdf::place`]): pure arithmetic over arrays, which the compiler vectorises
//!    (4 queries per SSE2 instruction on x86-64), and with a colour per query each
//!    channel's coordinate on the absorption axis;
//! 3. per query, the colour's planes and weights, the texel reads and interpolation (4
//!    channels per instruction, `super::texels`) and the sum of the four families.
//!
//! Each query goes through the same operations (the families are summed without being
//! stored, `BakedBcsdf::total`) as [`BakedBcsdf::eval_far`] followed by
//! [`Families::total`], so the results equal the scalar path's bit for bit
//! (`tests/tests/suite/baked_batch.rs` checks 10⁵ queries, NaN, ∞ and edge angles included).

use super::dispatch::KernelOp;
#[cfg(target_arch = "x86_64")]
use super::texels::Avx2F16c;
use super::texels::{axis_place, ColourAt, NKernel};
use super::{BakedBcsdf, Place};
use crate::absorption::Absorption;
use crate::lut::absorption_coordinate;
use crate::math::{wrap_angle, Math, PI};
use crate::spectrum::Rgb;
use core::fmt;

/// Queries per chunk: large enough to amortise the passes, small enough for the stack
/// (about 2 KB of places).
const CHUNK: usize = 32;

/// π/2, the largest |θ| [`Angles::new`](crate::Angles::new) accepts.
const HALF_PI: f32 = PI / 2.0;

/// The instruction set the baked evaluator runs on ([`BakedBcsdf::eval_far`],
/// [`BakedBcsdf::eval_far_dirs`], [`BakedBcsdf::eval_far_batch`]), chosen once per LUT from
/// the CPU in `from_bytes` (docs/model.md §8). Every kernel gives the same bits.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kernel {
    /// Four lanes: SSE2 where the target enables it, portable arrays elsewhere.
    Baseline,
    /// AVX2 and F16C (x86-64 CPUs since about 2013), detected at run time.
    #[cfg(target_arch = "x86_64")]
    Avx2F16c,
}

impl Kernel {
    /// The fastest kernel this CPU supports.
    #[must_use]
    pub fn best() -> Kernel {
        Isa::best().kernel()
    }
}

/// The kernel a [`BakedBcsdf`] evaluates with, holding the proof of its CPU features: a
/// feature-gated kernel can only be chosen through its detecting constructor.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Isa {
    /// [`Kernel::Baseline`].
    Baseline,
    /// [`Kernel::Avx2F16c`], with the token [`Avx2F16c::detect`] returned.
    #[cfg(target_arch = "x86_64")]
    Avx2F16c(Avx2F16c),
}

impl Isa {
    /// The fastest kernel this CPU supports.
    pub(crate) fn best() -> Isa {
        #[cfg(target_arch = "x86_64")]
        if let Some(token) = Avx2F16c::detect() {
            return Isa::Avx2F16c(token);
        }
        Isa::Baseline
    }

    /// `kernel` with its proof, or `None` if this CPU lacks it.
    fn of(kernel: Kernel) -> Option<Isa> {
        match kernel {
            Kernel::Baseline => Some(Isa::Baseline),
            #[cfg(target_arch = "x86_64")]
            Kernel::Avx2F16c => Avx2F16c::detect().map(Isa::Avx2F16c),
        }
    }

    /// The public name of this kernel.
    pub(crate) fn kernel(self) -> Kernel {
        match self {
            Isa::Baseline => Kernel::Baseline,
            #[cfg(target_arch = "x86_64")]
            Isa::Avx2F16c(_) => Kernel::Avx2F16c,
        }
    }
}

/// The slices given to a batch call differ in length.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BatchLengthError {
    /// Lengths of the θ_i, θ_r and φ slices.
    pub inputs: [usize; 3],
    /// Length of the output slice.
    pub output: usize,
    /// Length of the colour slice ([`BakedBcsdf::eval_far_batch_colours`]; `None` for
    /// [`BakedBcsdf::eval_far_batch`]).
    pub colours: Option<usize>,
}

impl fmt::Display for BatchLengthError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let [a, b, c] = self.inputs;
        write!(
            f,
            "batch slices differ in length: theta_i {a}, theta_r {b}, phi {c}, output {}",
            self.output
        )?;
        match self.colours {
            Some(n) => write!(f, ", colours {n}"),
            None => Ok(()),
        }
    }
}

impl core::error::Error for BatchLengthError {}

impl<M: Math> BakedBcsdf<'_, M> {
    /// The far-field S(ω_i, ω_r) (all families summed, RGB) of many queries: `out[k]` gets
    /// the value at (θ_i, θ_r, φ) = (`theta_i[k]`, `theta_r[k]`, `phi[k]`) in radians.
    ///
    /// Equal bit for bit to `eval_far(&Angles::new(θ_i, θ_r, φ)?).total()` per query; a
    /// query that [`Angles::new`](crate::Angles::new) rejects (non-finite, |θ| > π/2) gives zero. Returns the
    /// number of rejected queries, or an error (and writes nothing) when the four slices
    /// differ in length. No allocation; about 2 KB of stack.
    ///
    /// ```
    /// # fn demo(lut: &bcsdf_core::baked::BakedBcsdf) {
    /// let theta_i = [0.3, -0.2, f32::NAN];
    /// let theta_r = [0.1, 0.4, 0.0];
    /// let phi = [2.0, -3.0, 0.0];
    /// let mut out = [bcsdf_core::Rgb::ZERO; 3];
    /// let rejected = lut.eval_far_batch(&theta_i, &theta_r, &phi, &mut out).unwrap();
    /// assert_eq!(rejected, 1); // the NaN query, whose value is zero
    /// # }
    /// ```
    pub fn eval_far_batch(
        &self,
        theta_i: &[f32],
        theta_r: &[f32],
        phi: &[f32],
        out: &mut [Rgb],
    ) -> Result<usize, BatchLengthError> {
        let n = out.len();
        if theta_i.len() != n || theta_r.len() != n || phi.len() != n {
            return Err(BatchLengthError {
                inputs: [theta_i.len(), theta_r.len(), phi.len()],
                output: n,
                colours: None,
            });
        }
        Ok(self.dispatch(Batch {
            theta_i,
            theta_r,
            phi,
            colours: None,
            out,
        }))
    }

    /// [`BakedBcsdf::eval_far_batch`] with a colour per query: `out[k]` gets S at
    /// (`theta_i[k]`, `theta_r[k]`, `phi[k]`) and colour `colours[k]` (docs/lut.md "The
    /// absorption axis"), equal bit for bit to `self.at(&colours[k]).eval_far(..).total()`.
    /// An error (nothing written) when the five slices differ in length.
    ///
    /// ```
    /// # fn demo(lut: &bcsdf_core::baked::BakedBcsdf) {
    /// use bcsdf_core::{Absorption, Rgb};
    /// let colours = [
    ///     Absorption::from_melanin(0.3, 0.0).unwrap(),
    ///     Absorption::from_sigma(Rgb([0.1, 0.5, 2.0])).unwrap(),
    /// ];
    /// let mut out = [Rgb::ZERO; 2];
    /// lut.eval_far_batch_colours(&[0.3, -0.2], &[0.1, 0.4], &[2.0, -3.0], &colours, &mut out)
    ///     .unwrap();
    /// # }
    /// ```
    pub fn eval_far_batch_colours(
        &self,
        theta_i: &[f32],
        theta_r: &[f32],
        phi: &[f32],
        colours: &[Absorption],
        out: &mut [Rgb],
    ) -> Result<usize, BatchLengthError> {
        let n = out.len();
        if theta_i.len() != n || theta_r.len() != n || phi.len() != n || colours.len() != n {
            return Err(BatchLengthError {
                inputs: [theta_i.len(), theta_r.len(), phi.len()],
                output: n,
                colours: Some(colours.len()),
            });
        }
        Ok(self.dispatch(Batch {
            theta_i,
            theta_r,
            phi,
            colours: Some(colours),
            out,
        }))
    }

    /// The kernel the evaluator uses on this CPU.
    #[must_use]
    pub fn kernel(&self) -> Kernel {
        self.kernel.kernel()
    }

    /// The same LUT evaluated with `kernel`, or `None` if this CPU lacks it. The kernels give
    /// the same bits; this is for tests and benchmarks.
    #[must_use]
    pub fn with_kernel(mut self, kernel: Kernel) -> Option<Self> {
        self.kernel = Isa::of(kernel)?;
        Some(self)
    }

    /// Every chunk of equally long slices, table `N` read by `kernel`; returns the rejected
    /// count.
    #[inline(always)]
    fn eval_chunks<K: NKernel>(&self, kernel: K, batch: Batch<'_>) -> usize {
        let Batch {
            theta_i,
            theta_r,
            phi,
            colours,
            out,
        } = batch;
        let mut rejected = 0;
        let chunks = theta_i
            .chunks(CHUNK)
            .zip(theta_r.chunks(CHUNK))
            .zip(phi.chunks(CHUNK))
            .zip(out.chunks_mut(CHUNK))
            .enumerate();
        for (i, (((ti, tr), ph), out)) in chunks {
            let c = colours.map(|c| c.get(i * CHUNK..).unwrap_or(&[]));
            rejected += self.eval_chunk(kernel, ti, tr, ph, c, out);
        }
        rejected
    }

    /// One chunk (all slices of one length ≤ [`CHUNK`]); returns the rejected count.
    #[inline(always)]
    fn eval_chunk<K: NKernel>(
        &self,
        kernel: K,
        ti: &[f32],
        tr: &[f32],
        ph: &[f32],
        colours: Option<&[Absorption]>,
        out: &mut [Rgb],
    ) -> usize {
        // Pass 1: validation, as `Angles::new` but branch-free over the chunk; φ outside
        // (−π, π] (rare) is wrapped by `wrap_angle` in a second loop. Rejected lanes get
        // angles 0 (placed, never read).
        let mut angles = [[0.0f32; CHUNK]; 3];
        let mut valid = [false; CHUNK];
        let mut wrap = false;
        for k in 0..ti.len().min(CHUNK) {
            let (a, b, c) = (ti[k], tr[k], ph[k]);
            let ok = a.is_finite()
                & b.is_finite()
                & c.is_finite()
                & (a.abs() <= HALF_PI)
                & (b.abs() <= HALF_PI);
            let keep = |x: f32| if ok { x } else { 0.0 };
            angles[0][k] = keep(a);
            angles[1][k] = keep(b);
            angles[2][k] = keep(c);
            valid[k] = ok;
            wrap |= ok & !(c > -PI && c <= PI);
        }
        if wrap {
            for phi in &mut angles[2] {
                *phi = wrap_angle(*phi);
            }
        }
        let rejected = ti.len().min(CHUNK) - valid.iter().filter(|&&v| v).count();
        for phi in &mut angles[2] {
            *phi = phi.abs();
        }
        // Pass 2: arithmetic only, over the whole chunk, into one array per field (a fixed
        // trip count and unit-stride stores vectorise).
        let mut places = Places::default();
        let [a, b, c] = &angles;
        for (k, ((&a, &b), &c)) in a.iter().zip(b).zip(c).enumerate() {
            places.set(k, self.place(kernel, a, b, c));
        }
        // The colours' places on the absorption axis (`locate_colour`'s lane loops), channel
        // by channel over the chunk, 8 queries per AVX2 instruction: the coordinate, then
        // the first node and the three weights.
        let mut node = [[0u32; CHUNK]; 3];
        let mut weight = [[[0.0f32; CHUNK]; 3]; 3];
        if let Some(colours) = colours {
            let mut sigma = [[0.0f32; CHUNK]; 3];
            for (k, a) in colours.iter().take(CHUNK).enumerate() {
                let [r, g, b] = a.sigma().0;
                (sigma[0][k], sigma[1][k], sigma[2][k]) = (r, g, b);
            }
            for c in 0..3 {
                for k in 0..CHUNK {
                    let x = absorption_coordinate(sigma[c][k], self.abs_scale);
                    let (n, w) = axis_place(x, self.abs_last, self.abs_first_of_last);
                    node[c][k] = n;
                    for j in 0..3 {
                        weight[c][j][k] = w[j];
                    }
                }
            }
        }
        // Pass 3: the colour's planes and weights, texel reads and the family sum.
        for (k, (o, ok)) in out.iter_mut().zip(valid).enumerate() {
            let colour = match colours {
                Some(_) => ColourAt::from_nodes(
                    [node[0][k], node[1][k], node[2][k]],
                    |c, j| weight[c][j][k],
                    self.plane,
                ),
                None => self.default_colour(),
            };
            *o = if ok {
                Self::total(&self.gather_with(kernel, &places.get(k), &colour))
            } else {
                Rgb::ZERO
            };
        }
        rejected
    }
}

/// [`BakedBcsdf::eval_far_batch`]'s work: equally long slices (colours: per query, or the
/// preset's).
struct Batch<'s> {
    theta_i: &'s [f32],
    theta_r: &'s [f32],
    phi: &'s [f32],
    colours: Option<&'s [Absorption]>,
    out: &'s mut [Rgb],
}

impl<M: Math> KernelOp<M> for Batch<'_> {
    type Output = usize;
    #[inline(always)]
    fn run<K: NKernel>(self, lut: &BakedBcsdf<'_, M>, kernel: K) -> usize {
        lut.eval_chunks(kernel, self)
    }
}

/// [`Place`]s of one chunk, one array per field.
struct Places {
    index: [[u32; CHUNK]; 4],
    weight: [[f32; CHUNK]; 13],
}

impl Default for Places {
    fn default() -> Places {
        Places {
            index: [[0; CHUNK]; 4],
            weight: [[0.0; CHUNK]; 13],
        }
    }
}

impl Places {
    #[inline(always)]
    fn set(&mut self, k: usize, p: Place) {
        let (index, weight) = p.into_parts();
        for (field, v) in self.index.iter_mut().zip(index) {
            field[k] = v;
        }
        for (field, v) in self.weight.iter_mut().zip(weight) {
            field[k] = v;
        }
    }

    #[inline(always)]
    fn get(&self, k: usize) -> Place {
        // `from_fn`, not `map`: `map` would copy the whole arrays.
        Place::from_parts(
            core::array::from_fn(|f| self.index[f][k]),
            core::array::from_fn(|f| self.weight[f][k]),
        )
    }
}
