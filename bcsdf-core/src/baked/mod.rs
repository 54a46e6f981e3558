//! The baked far-field evaluator: reads the half-float tables of [`crate::lut`] in place
//! (borrowed bytes, no allocation, no std) and evaluates (docs/model.md §8)
//!
//! S = [Σ_g M_g(θ_i + θ_r)·N_g(|θ_r|, |φ|) + M^s(θ_i, θ_r, |φ|)·N^s(|θ_r|, |φ|)] / cos²θ_i
//!
//! with linear interpolation in every table axis. The data is validated once, in
//! [`BakedBcsdf::from_bytes`]; evaluation then never fails, never panics and never returns NaN.
//! Sampling and pdf ([`crate::Bcsdf`]) are in the crate's `sampling::baked` module.
//!
//! Loading, placing a query and gathering its reads are one hot path, kept in this file; the
//! table axes, kernels, batch, colour view and sampler are split out.

use crate::frame::{polynomial_angles, AngleError, Angles, Vec3};
use crate::lobes::{Families, FAMILY_COUNT};
use crate::lut::cdf::{Density, DensityLayout, Nodes};
use crate::lut::{self, f16_biased, LutError, LutHeader, Table, F16_UNBIAS, TABLE_COUNT};
use dispatch::KernelOp;
pub(crate) use grid::Axis;
pub use texels::ColourAt;
use texels::{corner_weights, locate_colour, m_linear, ms_bilinear, n_lossless, Baseline, NKernel};

mod at;
mod batch;
mod dispatch;
mod grid;
mod simd;
mod sphere;
mod texels;

pub use at::BakedAt;

use crate::math::{cos_within_half_pi, Libm, Math, PI};
use crate::model::inv_cos2_theta_i;
use crate::params::{Closure, FurParams};
use crate::spectrum::Rgb;
use batch::Isa;
pub use batch::{BatchLengthError, Kernel};
use core::marker::PhantomData;

/// A validated LUT, borrowed: the baked far field of one parameter set, evaluated, sampled
/// and given a pdf ([`Bcsdf`](crate::Bcsdf)) straight from the bytes, without allocating.
///
/// The math backend `M` serves only the direction-to-angle conversion of
/// [`BakedBcsdf::eval_far_dirs`]; cos θ_i comes from a libm-free polynomial that the WGSL
/// evaluator shares (`math::cos_within_half_pi`).
///
/// A `.furlut` blob normally comes from the `bake` tool, as a file, a memory map or
/// `include_bytes!`. Here, the smallest one, written with the format's own encoder, every
/// table value 1, in the report closure (which reads `M` as stored; the energy closure would
/// divide it by its mass on the sphere, docs/model.md §12):
///
/// ```
/// use bcsdf_core::lut::{self, HEADER_LEN, TABLE_COUNT};
/// use bcsdf_core::{presets, Angles, BakedBcsdf, Bcsdf, Closure, FurParamsInput};
/// use bcsdf_core::{LutError, LutHeader, LutResolution};
///
/// let res = LutResolution { n_sum: 2, n_theta_r: 2, n_phi: 2, n_ms_i: 2, n_ms_r: 2, n_abs: 3 };
/// let header = LutHeader {
///     res,
///     scales: [1.0; TABLE_COUNT],
///     params: FurParamsInput {
///         closure: Closure::Report,
///         ..presets::find("human-hair").unwrap().input
///     },
///     profiles: None,
/// };
/// let mut blob = vec![0u8; res.blob_len()];
/// blob[..HEADER_LEN].copy_from_slice(&header.encode());
/// for half in blob[HEADER_LEN..res.sampling_start()].chunks_exact_mut(2) {
///     half.copy_from_slice(&0x3c00u16.to_le_bytes()); // 1.0 as an IEEE binary16
/// }
/// lut::seal(&mut blob); // the sampling section and the checksum
///
/// let baked = BakedBcsdf::from_bytes(&blob).unwrap();
/// let angles = Angles::from_degrees(60.0, -10.0, 90.0).unwrap();
/// // M = N = M^s = 1: each of the four families is 1/cos²θ_i = 4.
/// let s = baked.eval_far(&angles).total();
/// assert!((s.0[0] - 16.0).abs() < 1e-3);
/// // Importance sampling through the engine-facing trait.
/// let sample = baked.sample(angles.theta_r(), [0.2, 0.7, 0.4]).unwrap();
/// assert_eq!(sample.pdf, baked.pdf(&sample.angles));
///
/// // Damaged or foreign bytes are rejected with the reason.
/// blob[HEADER_LEN] ^= 1;
/// assert!(matches!(BakedBcsdf::from_bytes(&blob), Err(LutError::Checksum { .. })));
/// assert_eq!(BakedBcsdf::from_bytes(b"FURLUT").unwrap_err(), LutError::TooShort { len: 6 });
/// ```
#[derive(Clone, Copy, Debug)]
pub struct BakedBcsdf<'a, M: Math = Libm> {
    pub(crate) header: LutHeader,
    params: FurParams,
    tables: [&'a [u8]; TABLE_COUNT],
    /// Table scale × 2^112 (see [`lut::f16_biased`]).
    unbias: [f32; TABLE_COUNT],
    /// Node values as the sampling section sees them.
    pub(crate) nodes: Nodes<'a>,
    /// The whole blob (the sampling section is read from it).
    pub(crate) blob: &'a [u8],
    /// Byte offset of table `M` in the blob.
    m_start: usize,
    /// The 1/Z_g table ([`lut::norms`]): little-endian f32, three per node (empty unless the
    /// blob holds the whole section, which `lut::validate` checks).
    norms: &'a [u8],
    /// The instruction set of the evaluation ([`Kernel`]), with the proof of its features.
    kernel: Isa,
    /// Table `N`'s scale for a kernel that decodes true half values (F16C), computed at
    /// load: the baseline decodes halves × 2^−112 and folds `unbias` (scale × 2^112) into the
    /// weights; F16C's `vcvtph2ps` gives true values, so its weights carry the scale itself
    /// ([`NKernel::TRUE_HALVES`]), a power-of-two rescaling: the same products bit for bit.
    n_scale_true: f32,
    /// Where each sampled density lives ([`Density::index`] order).
    pub(crate) densities: [DensityLayout; 10],
    pub(crate) sum: Axis,
    pub(crate) theta_r: Axis,
    pub(crate) phi: Axis,
    pub(crate) ms_i: Axis,
    pub(crate) ms_r: Axis,
    /// θ_r ∈ [−π/2, π/2], the 1/Z_g table's axis.
    pub(crate) norm: Axis,
    /// The energy closure (docs/model.md §12): M_g is divided by its mass on the sphere,
    /// read from the LUT's 1/Z_g table.
    pub(crate) energy: bool,
    /// The absorption axis: n_abs − 1 (as f32) and the texels of one plane of table `N`.
    abs_last: f32,
    /// n_abs − 3 (as f32): the last first node of a channel's three.
    abs_first_of_last: f32,
    abs_scale: f32,
    plane: usize,
    /// The colour the LUT's own parameters give (the preset's σ_ca), located on the
    /// absorption axis: what the methods without a colour evaluate.
    colour: ColourAt,
    _math: PhantomData<M>,
}

/// Where one query reads the tables: lower texel indices and interpolation weights (table
/// scale folded in), plus the two factors evaluated exactly.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Place {
    /// Table `M`: texel index, weights of texels m and m + 1.
    m: usize,
    m_w: [f32; 2],
    /// Table `M_s`: texel index (row-major), corner weights.
    ms: usize,
    ms_w: [f32; 4],
    /// Table `N`: texel index (row-major), corner weights.
    n: usize,
    n_w: [f32; 4],
    /// |φ|/π.
    front: f32,
    /// 1/cos²θ_i, guarded.
    inv_cos2: f32,
    /// θ_r on the 1/Z_g table's axis (node, weight), for the energy closure's factor
    /// (docs/model.md §12).
    norm: (usize, f32),
}

impl Place {
    /// The texel indices (`M`, `M_s`, `N`, the 1/Z_g node) and the thirteen floats, for
    /// storage by field.
    #[inline(always)]
    fn into_parts(self) -> ([u32; 4], [f32; 13]) {
        let [a, b] = self.m_w;
        let [c, d, e, f] = self.ms_w;
        let [g, h, i, j] = self.n_w;
        let (norm, norm_w) = self.norm;
        (
            [self.m as u32, self.ms as u32, self.n as u32, norm as u32],
            [
                a,
                b,
                c,
                d,
                e,
                f,
                g,
                h,
                i,
                j,
                self.front,
                self.inv_cos2,
                norm_w,
            ],
        )
    }

    /// The inverse of [`Place::into_parts`].
    #[inline(always)]
    fn from_parts(index: [u32; 4], w: [f32; 13]) -> Place {
        Place {
            m: index[0] as usize,
            m_w: [w[0], w[1]],
            ms: index[1] as usize,
            ms_w: [w[2], w[3], w[4], w[5]],
            n: index[2] as usize,
            n_w: [w[6], w[7], w[8], w[9]],
            front: w[10],
            inv_cos2: w[11],
            norm: (index[3] as usize, w[12]),
        }
    }
}

/// The table lookups of one query, shared by evaluation and pdf.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Lookups {
    /// M_g(θ_i + θ_r), g = R, TT, TRT (in the energy closure divided by its mass on the
    /// sphere, docs/model.md §12).
    pub(crate) m: [f32; 3],
    /// M^s_back(θ_i, θ_r), M^s_front(θ_i, θ_r).
    pub(crate) ms: [f32; 2],
    /// N (12 channels: family, then RGB) at (|θ_r|, |φ|) and the query's colour.
    pub(crate) n: [f32; 12],
    /// N of the four families on the lossless plane (the sampler's densities; zero where
    /// only the value is wanted).
    pub(crate) n0: [f32; 4],
    /// |φ|/π, the front weight of M^s.
    pub(crate) front: f32,
    /// 1/cos²θ_i, guarded.
    pub(crate) inv_cos2: f32,
}

impl<'a> BakedBcsdf<'a, Libm> {
    /// Validates `bytes` (header, lengths, versions, checksum, every value) and borrows it.
    /// With the default `Libm` backend; see [`BakedBcsdf::from_bytes_with`] for another.
    ///
    /// ```
    /// use bcsdf_core::{BakedBcsdf, LutError};
    ///
    /// let mut bytes = vec![0u8; 4096];
    /// assert_eq!(BakedBcsdf::from_bytes(&bytes).unwrap_err(), LutError::BadMagic);
    /// bytes[..8].copy_from_slice(b"FURLUT\0\0");
    /// let e = BakedBcsdf::from_bytes(&bytes).unwrap_err();
    /// assert_eq!(e, LutError::FormatVersion { found: 0 });
    /// assert!(e.to_string().contains("re-bake"));
    /// ```
    pub fn from_bytes(bytes: &'a [u8]) -> Result<BakedBcsdf<'a, Libm>, LutError> {
        Self::from_bytes_with(bytes)
    }
}

impl<'a, M: Math> BakedBcsdf<'a, M> {
    /// Validates `bytes` and borrows it, evaluating with math backend `M`.
    pub fn from_bytes_with(bytes: &'a [u8]) -> Result<BakedBcsdf<'a, M>, LutError> {
        let header = lut::validate(bytes)?;
        let params = FurParams::new(&header.params).map_err(LutError::Params)?;
        let res = header.res;
        let plane = res.n_plane();
        let abs_last = (res.n_abs - 1) as f32;
        let abs_first_of_last = texels::first_of_last(res.n_abs as usize);
        let abs_scale = header.absorption_scale();
        let mut tables: [&'a [u8]; TABLE_COUNT] = [&[]; TABLE_COUNT];
        let mut unbias = [0.0; TABLE_COUNT];
        for t in Table::ALL {
            tables[t as usize] = &bytes[res.byte_range(t)];
            unbias[t as usize] = header.scales[t as usize] * F16_UNBIAS;
        }
        Ok(BakedBcsdf {
            header,
            params,
            tables,
            unbias,
            nodes: Nodes::new(bytes, res, header.scales),
            blob: bytes,
            m_start: res.byte_range(Table::M).start,
            norms: bytes
                .get(res.norm_start()..res.norm_start() + 4 * res.norm_values())
                .unwrap_or(&[]),
            kernel: Isa::best(),
            n_scale_true: unbias[Table::N as usize] * f32::from_bits((127 - 112) << 23),
            densities: Density::ALL.map(|d| res.density_layout(d)),
            sum: Axis::new(-PI, 1.0 / (2.0 * PI), res.n_sum),
            theta_r: Axis::new(0.0, 1.0 / (PI / 2.0), res.n_theta_r),
            phi: Axis::new(0.0, 1.0 / PI, res.n_phi),
            ms_i: Axis::new(-PI / 2.0, 1.0 / PI, res.n_ms_i),
            ms_r: Axis::new(-PI / 2.0, 1.0 / PI, res.n_ms_r),
            norm: Axis::new(-PI / 2.0, 1.0 / PI, res.n_norm() as u32),
            energy: params.closure() == Closure::Energy,
            abs_last,
            abs_first_of_last,
            abs_scale,
            plane,
            colour: locate_colour(
                params.sigma_ca(),
                abs_scale,
                abs_last,
                abs_first_of_last,
                plane,
            ),
            _math: PhantomData,
        })
    }

    /// Where colour `sigma` (σ_ca per channel, validated: [`crate::Absorption`]) reads table
    /// `N`: each channel's three planes and their weights on the absorption axis
    /// ([`lut::absorption_coordinate`], docs/lut.md "The absorption axis").
    #[inline(always)]
    #[must_use]
    pub fn locate_colour(&self, sigma: Rgb) -> ColourAt {
        locate_colour(
            sigma,
            self.abs_scale,
            self.abs_last,
            self.abs_first_of_last,
            self.plane,
        )
    }

    /// The preset's own colour (the σ_ca the LUT's parameters give), located: what
    /// [`BakedBcsdf::eval_far`] and the [`Bcsdf`](crate::Bcsdf) methods evaluate.
    #[must_use]
    pub fn default_colour(&self) -> ColourAt {
        self.colour
    }

    /// The header: resolution, scales, parameters, profile provenance.
    #[must_use]
    pub fn header(&self) -> &LutHeader {
        &self.header
    }

    /// The LUT's checksum ([`lut::checksum`], docs/lut.md "Byte layout and validation"):
    /// FNV-1a 64 of every byte but the checksum field, read from the header, which
    /// [`BakedBcsdf::from_bytes`] checked against the bytes. What a `.furdual` blob records as
    /// its source ([`crate::dual::DualLut::check_lut`]).
    #[must_use]
    pub fn checksum(&self) -> u64 {
        let field = self.blob.get(lut::CHECKSUM).unwrap_or(&[]);
        u64::from_le_bytes(field.try_into().unwrap_or([0; 8]))
    }

    /// The validated parameters the tables were baked from.
    #[must_use]
    pub fn params(&self) -> &FurParams {
        &self.params
    }

    /// One stored value (× its table scale) at texel (x, y), channel c; 0 outside the table.
    #[must_use]
    pub fn value(&self, table: Table, x: usize, y: usize, c: usize) -> f32 {
        let (w, h) = self.header.res.dims(table);
        let ch = table.channels();
        if x >= w || y >= h || c >= ch {
            return 0.0;
        }
        let i = 2 * ((y * w + x) * ch + c);
        match self.tables[table as usize].get(i..i + 2) {
            Some(b) => f16_biased(u16::from_le_bytes([b[0], b[1]])) * self.unbias[table as usize],
            None => 0.0,
        }
    }

    /// Where one query reads the tables (θ_i, θ_r and |φ| of validated angles). Pure
    /// arithmetic, no memory reads besides `self`: the batch evaluator runs it over many
    /// queries in one loop, which the compiler vectorises.
    #[inline(always)]
    pub(crate) fn place<K: NKernel>(&self, _kernel: K, ti: f32, tr: f32, abs_phi: f32) -> Place {
        let res = &self.header.res;
        // M_g(θ_i + θ_r): linear.
        let (m, w) = self.sum.locate(ti + tr);
        let km = self.unbias[Table::M as usize];
        // M^s_back and M^s_front at (θ_i, θ_r): bilinear.
        let (row, wy) = self.ms_r.locate(tr);
        let (col, wx) = self.ms_i.locate(ti);
        let ms = row * res.n_ms_i as usize + col;
        let ms_w = corner_weights(wy, wx, self.unbias[Table::MS as usize]);
        // N_g(|θ_r|, |φ|), one 4-channel table per absorption plane: bilinear in each.
        let (row, wy) = self.theta_r.locate(tr.abs());
        let (col, wx) = self.phi.locate(abs_phi);
        let n = row * res.n_phi as usize + col;
        let n_scale = if K::TRUE_HALVES {
            self.n_scale_true
        } else {
            self.unbias[Table::N as usize]
        };
        let n_w = corner_weights(wy, wx, n_scale);
        Place {
            m,
            m_w: [(1.0 - w) * km, w * km],
            ms,
            ms_w,
            n,
            n_w,
            front: (abs_phi * (1.0 / PI)).min(1.0),
            inv_cos2: inv_cos2_theta_i(cos_within_half_pi(ti)),
            // Only the energy closure reads the 1/Z_g table (`sphere_norms`).
            norm: if self.energy {
                self.norm.locate(tr)
            } else {
                (0, 0.0)
            },
        }
    }

    /// f32 at byte offset `at` of the blob (0 past its end).
    #[inline(always)]
    pub(crate) fn f32_at(&self, at: usize) -> f32 {
        match self.blob.get(at..at + 4) {
            Some(b) => f32::from_le_bytes([b[0], b[1], b[2], b[3]]),
            None => 0.0,
        }
    }

    /// The table reads of one query at `p` ([`BakedBcsdf::place`] for the same kernel),
    /// table `N` read by `kernel`.
    #[inline(always)]
    pub(crate) fn gather_with<K: NKernel>(
        &self,
        kernel: K,
        p: &Place,
        colour: &ColourAt,
    ) -> Lookups {
        let res = &self.header.res;
        // Read from the blob: a pair is read as eight halves (table N follows M).
        let m = m_linear(self.blob, self.m_start, p.m, p.m_w[0], p.m_w[1]);
        let norm = self.sphere_norms(p.norm);
        Lookups {
            m: core::array::from_fn(|g| m[g] * norm[g]),
            ms: ms_bilinear(
                self.tables[Table::MS as usize],
                res.n_ms_i as usize,
                p.ms,
                p.ms_w,
            ),
            n: kernel.n_at_colour(
                self.tables[Table::N as usize],
                res.n_phi as usize,
                p.n,
                p.n_w,
                colour,
            ),
            n0: [0.0; 4],
            front: p.front,
            inv_cos2: p.inv_cos2,
        }
    }

    /// The table lookups of one query at `colour` (the samplers' pdf), with the lossless
    /// plane's N for the sampler's density ([`Lookups::n0`]), with the baseline kernel,
    /// inlined into the sampler: through the AVX2 function (a call, the lookups returned in
    /// memory) the pdf measured slower (docs/benchmarks.md, "Sampling and evaluation speed").
    #[inline]
    pub(crate) fn lookups(&self, angles: &Angles, colour: &ColourAt) -> Lookups {
        let (ti, tr, abs_phi) = (angles.theta_i(), angles.theta_r(), angles.phi().abs());
        let p = self.place(Baseline, ti, tr, abs_phi);
        let mut l = self.gather_with(Baseline, &p, colour);
        l.n0 = n_lossless(
            self.tables[Table::N as usize],
            self.header.res.n_phi as usize,
            p.n,
            p.n_w,
        );
        l
    }

    /// Far-field S(ω_i, ω_r) per lobe family from the lookups: M_g·N_g and
    /// M^s·N^s with M^s = (1 − |φ|/π)·back + (|φ|/π)·front, each over cos²θ_i.
    #[inline(always)]
    pub(crate) fn assemble(l: &Lookups) -> Families {
        let [back, front] = l.ms;
        let ms = back + l.front * (front - back);
        let longitudinal = [l.m[0], l.m[1], l.m[2], ms];
        let mut out = [Rgb::ZERO; FAMILY_COUNT];
        for (f, o) in out.iter_mut().enumerate() {
            let weight = longitudinal[f] * l.inv_cos2;
            *o = Rgb([l.n[3 * f], l.n[3 * f + 1], l.n[3 * f + 2]]) * weight;
        }
        Families::from_array(out)
    }

    /// S, all families summed: [`Self::assemble`] followed by [`Families::total`] (inlined,
    /// so the families are not stored; the batch path's per-query sum).
    #[inline(always)]
    pub(crate) fn total(l: &Lookups) -> Rgb {
        Self::assemble(l).total()
    }

    /// Far-field S(ω_i, ω_r) per lobe family, from the tables (docs/model.md §8), with the
    /// kernel chosen at load (the same bits with either).
    #[inline]
    pub fn eval_far(&self, angles: &Angles) -> Families {
        self.dispatch(EvalAt(angles, &self.colour))
    }

    /// Far-field S from world-space directions: `wi` toward the light, `wr` toward the viewer,
    /// `tangent` the fiber direction, none necessarily of unit length. Invalid directions
    /// (non-finite, zero length) give zero; [`BakedBcsdf::try_eval_far_dirs`] says why.
    ///
    /// The angles come from a branch-free polynomial conversion (within about 3e-7 rad of
    /// [`Angles::from_directions`], docs/lut.md), so the result can differ from
    /// `eval_far(&Angles::from_directions(..)?)` in the last bits; it equals
    /// `eval_far(&self.angles_from_dirs(..)?)` bit for bit.
    #[inline]
    pub fn eval_far_dirs(&self, wi: Vec3, wr: Vec3, tangent: Vec3) -> Families {
        self.try_eval_far_dirs(wi, wr, tangent)
            .unwrap_or(Families::ZERO)
    }

    /// [`BakedBcsdf::eval_far_dirs`], or why the directions were rejected.
    #[inline]
    pub fn try_eval_far_dirs(
        &self,
        wi: Vec3,
        wr: Vec3,
        tangent: Vec3,
    ) -> Result<Families, AngleError> {
        self.dispatch(EvalDirs(&wi, &wr, &tangent, &self.colour))
    }

    /// The baked evaluator's one direction-to-angle conversion (docs/model.md §1), behind
    /// [`Bcsdf::angles_from_dirs`](crate::Bcsdf::angles_from_dirs) and so behind every
    /// `*_dirs` method: the branch-free polynomials of [`BakedBcsdf::eval_far_dirs`] (within
    /// about 3e-7 rad of [`Angles::from_directions`]), which the WGSL evaluator shares.
    /// `eval_far_dirs` evaluates exactly these angles.
    #[inline]
    pub fn angles_from_dirs(
        &self,
        wi: Vec3,
        wr: Vec3,
        tangent: Vec3,
    ) -> Result<Angles, AngleError> {
        let [ti, tr, phi] = polynomial_angles::<M>(wi, wr, tangent)?;
        Angles::new(ti, tr, phi)
    }
}

/// [`BakedBcsdf::eval_far`]'s work. It carries a reference to the angles, not θ_i, θ_r,
/// |φ| by value: the dispatcher's AVX2 side is a separate function, the op reaches it in
/// memory, and the caller's three 4-byte stores read back as one 8-byte load stalled store
/// forwarding (it nearly doubled `eval_far`'s time, at the same instruction count).
pub(crate) struct EvalAt<'s>(pub(crate) &'s Angles, pub(crate) &'s ColourAt);

impl<M: Math> KernelOp<M> for EvalAt<'_> {
    type Output = Families;
    #[inline(always)]
    fn run<K: NKernel>(self, lut: &BakedBcsdf<'_, M>, kernel: K) -> Families {
        let a = self.0;
        families_at(lut, kernel, a.theta_i(), a.theta_r(), a.phi().abs(), self.1)
    }
}

/// The families at validated θ_i, θ_r and |φ| and a located colour, table `N` read by
/// `kernel`.
#[inline(always)]
fn families_at<M: Math, K: NKernel>(
    lut: &BakedBcsdf<'_, M>,
    kernel: K,
    ti: f32,
    tr: f32,
    abs_phi: f32,
    colour: &ColourAt,
) -> Families {
    let place = lut.place(kernel, ti, tr, abs_phi);
    BakedBcsdf::<M>::assemble(&lut.gather_with(kernel, &place, colour))
}

/// [`BakedBcsdf::try_eval_far_dirs`]'s work: ω_i, ω_r, tangent, colour. By reference, as
/// [`EvalAt`]: by value, the op's nine floats reached the AVX2 side copied in wider moves,
/// which stalled store forwarding (docs/benchmarks.md "Baked evaluation").
pub(crate) struct EvalDirs<'s>(
    pub(crate) &'s Vec3,
    pub(crate) &'s Vec3,
    pub(crate) &'s Vec3,
    pub(crate) &'s ColourAt,
);

impl<M: Math> KernelOp<M> for EvalDirs<'_> {
    type Output = Result<Families, AngleError>;
    #[inline(always)]
    fn run<K: NKernel>(self, lut: &BakedBcsdf<'_, M>, kernel: K) -> Self::Output {
        let EvalDirs(wi, wr, tangent, colour) = self;
        let [ti, tr, phi] = polynomial_angles::<M>(*wi, *wr, *tangent)?;
        Ok(families_at(lut, kernel, ti, tr, phi.abs(), colour))
    }
}

#[cfg(test)]
pub(crate) mod tests;
