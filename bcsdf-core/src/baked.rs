//! The baked far-field evaluator: reads the half-float tables of [`crate::lut`] in place
//! (borrowed bytes, no allocation, no std) and evaluates (docs/model.md §8)
//!
//! S = [Σ_g M_g(θ_i + θ_r)·N_g(|θ_r|, |φ|) + M^s(θ_i, θ_r, |φ|)·N^s(|θ_r|, |φ|)] / cos²θ_i
//!
//! with linear interpolation in every table axis. The data is validated once, in
//! [`BakedBcsdf::from_bytes`]; evaluation then never fails, never panics and never returns NaN.
//! Sampling and pdf ([`crate::Bcsdf`]) are in [`crate::sampling::baked`].

use crate::frame::{Angles, Vec3};
use crate::lobes::{Families, FAMILY_COUNT};
use crate::lut::cdf::{Density, DensityLayout, Nodes};
use crate::lut::{self, f16_biased, LutError, LutHeader, Table, F16_UNBIAS, TABLE_COUNT};
use crate::math::{cos_within_half_pi, Libm, Math, PI};
use crate::model::inv_cos2_theta_i;
use crate::params::FurParams;
use crate::spectrum::Rgb;
use core::marker::PhantomData;

/// One uniform table axis over [lo, lo + span] with `nodes` nodes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Axis {
    pub(crate) lo: f32,
    inv_step: f32,
    /// Node index of x = 0: 0, or (nodes − 1)/2 for an axis centred on 0.
    offset: f32,
    last: f32,
    pub(crate) nodes: usize,
}

impl Axis {
    /// The axis over [lo, lo + span] given 1/span, with lo = 0 or lo = −span/2. The node
    /// position of x is u = x·inv_step + offset, inv_step = (nodes − 1)·(1/span) and offset =
    /// 0 or (nodes − 1)/2: only correctly rounded products and sums of constants, no division
    /// (WGSL's is not correctly rounded), so that the WGSL evaluator forms the same u. A shader
    /// compiler that fuses x·inv_step + offset into one rounding moves u by at most one ulp
    /// (docs/lut.md, "On the GPU").
    fn new(lo: f32, inv_span: f32, nodes: u32) -> Axis {
        let last = (nodes - 1) as f32;
        Axis {
            lo,
            inv_step: last * inv_span,
            offset: if lo == 0.0 { 0.0 } else { 0.5 * last },
            last,
            nodes: nodes as usize,
        }
    }

    /// Lower node index and weight of the upper node for `x` (clamped to the axis ends).
    #[inline(always)]
    pub(crate) fn locate(&self, x: f32) -> (usize, f32) {
        // `max` first: NaN becomes 0 (the callers pass finite angles anyway).
        let u = (x * self.inv_step + self.offset).max(0.0).min(self.last);
        // u ∈ [0, nodes − 1] here; the i32 conversions are the cheap ones on every target.
        let i = (u as i32).min(self.nodes as i32 - 2);
        (i as u32 as usize, u - i as f32)
    }
}

/// A validated LUT, borrowed. The math backend `M` serves only the direction-to-angle
/// conversion of [`BakedBcsdf::eval_far_dirs`]; cos θ_i comes from
/// [`cos_within_half_pi`].
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
    /// Where each sampled density lives ([`Density::index`] order).
    pub(crate) densities: [DensityLayout; 9],
    pub(crate) sum: Axis,
    pub(crate) theta_r: Axis,
    pub(crate) phi: Axis,
    pub(crate) ms_i: Axis,
    pub(crate) ms_r: Axis,
    _math: PhantomData<M>,
}

/// The table lookups of one query, shared by evaluation and pdf.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Lookups {
    /// M_g(θ_i + θ_r), g = R, TT, TRT.
    pub(crate) m: [f32; 3],
    /// M^s_back(θ_i, θ_r), M^s_front(θ_i, θ_r).
    pub(crate) ms: [f32; 2],
    /// N (12 channels: family, then RGB) at (|θ_r|, |φ|).
    pub(crate) n: [f32; 12],
    /// |φ|/π, the front weight of M^s.
    pub(crate) front: f32,
    /// 1/cos²θ_i, guarded.
    pub(crate) inv_cos2: f32,
}

/// The `B` bytes of texels `index` and `index + 1` of a table with `C` channels
/// (`B` = 4·C), as a fixed-size array so that the per-channel loops below carry no bounds
/// checks.
#[inline(always)]
fn texel_pair<const C: usize, const B: usize>(data: &[u8], index: usize) -> &[u8; B] {
    let start = 2 * C * index;
    // Validation guarantees the range; a miss would read zeros (a pointer select, so the
    // decoding below stays branch- and blend-free), never panic.
    match data.get(start..).and_then(|s| s.get(..B)) {
        Some(s) => s.try_into().unwrap_or(&[0; B]),
        None => &[0; B],
    }
}

/// The `H` = 2·C halves of a texel pair, converted (× 2^−112, see [`lut::f16_biased`]).
#[inline(always)]
fn decode<const B: usize, const H: usize>(bytes: &[u8; B]) -> [f32; H] {
    let mut out = [0.0; H];
    for (o, pair) in out.iter_mut().zip(bytes.chunks_exact(2)) {
        *o = f16_biased(u16::from_le_bytes([pair[0], pair[1]]));
    }
    out
}

/// Linear lookup between texels `index` and `index + 1` (`C` channels each, `B` = 4·C bytes,
/// `H` = 2·C halves) with weight `w` of the upper one; `k` (table scale × 2^112) is folded
/// into the weights.
#[inline(always)]
fn linear<const C: usize, const B: usize, const H: usize>(
    data: &[u8],
    (index, w): (usize, f32),
    k: f32,
) -> [f32; C] {
    let (w0, w1) = ((1.0 - w) * k, w * k);
    let t: [f32; H] = decode(texel_pair::<C, B>(data, index));
    let mut out = [0.0; C];
    for c in 0..C {
        out[c] = w0 * t[c] + w1 * t[C + c];
    }
    out
}

/// Bilinear lookup in a row-major table of width `width` (`C` channels, `B` = 4·C bytes and
/// `H` = 2·C halves per texel pair), rows by `row`, columns by `col`; `k` (table scale ×
/// 2^112) is folded into the four corner weights.
#[inline(always)]
fn bilinear<const C: usize, const B: usize, const H: usize>(
    data: &[u8],
    width: usize,
    (row, wy): (usize, f32),
    (col, wx): (usize, f32),
    k: f32,
) -> [f32; C] {
    let (ky0, ky1) = ((1.0 - wy) * k, wy * k);
    let w = [ky0 * (1.0 - wx), ky0 * wx, ky1 * (1.0 - wx), ky1 * wx];
    let i0 = row * width + col;
    let t: [f32; H] = decode(texel_pair::<C, B>(data, i0));
    let b: [f32; H] = decode(texel_pair::<C, B>(data, i0 + width));
    let mut out = [0.0; C];
    for c in 0..C {
        out[c] = w[0] * t[c] + w[1] * t[C + c] + w[2] * b[c] + w[3] * b[C + c];
    }
    out
}

impl<'a> BakedBcsdf<'a, Libm> {
    /// Validates `bytes` (header, lengths, versions, checksum, every value) and borrows it.
    /// With the default `Libm` backend; see [`BakedBcsdf::from_bytes_with`] for another.
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
            densities: Density::ALL.map(|d| res.density_layout(d)),
            sum: Axis::new(-PI, 1.0 / (2.0 * PI), res.n_sum),
            theta_r: Axis::new(0.0, 1.0 / (PI / 2.0), res.n_theta_r),
            phi: Axis::new(0.0, 1.0 / PI, res.n_phi),
            ms_i: Axis::new(-PI / 2.0, 1.0 / PI, res.n_ms_i),
            ms_r: Axis::new(-PI / 2.0, 1.0 / PI, res.n_ms_r),
            _math: PhantomData,
        })
    }

    /// The header: resolution, scales, parameters, profile provenance.
    pub fn header(&self) -> &LutHeader {
        &self.header
    }

    /// The validated parameters the tables were baked from.
    pub fn params(&self) -> &FurParams {
        &self.params
    }

    /// One stored value (× its table scale) at texel (x, y), channel c; 0 outside the table.
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

    /// The table lookups of one query.
    #[inline]
    pub(crate) fn lookups(&self, angles: &Angles) -> Lookups {
        let (ti, tr, phi) = (angles.theta_i(), angles.theta_r(), angles.phi());
        let abs_phi = phi.abs();
        let res = &self.header.res;

        // M_g(θ_i + θ_r), the three cuticle groups side by side.
        let (i, w) = self.sum.locate(ti + tr);
        let km = self.unbias[Table::M as usize];
        let m = linear::<3, 12, 6>(self.tables[Table::M as usize], (i, w), km);

        // M^s_back and M^s_front at (θ_i, θ_r).
        let kms = self.unbias[Table::MS as usize];
        let ms = bilinear::<2, 8, 4>(
            self.tables[Table::MS as usize],
            res.n_ms_i as usize,
            self.ms_r.locate(tr),
            self.ms_i.locate(ti),
            kms,
        );

        // N_g(|θ_r|, |φ|) for the three groups and the scattered lobes, one 12-channel table.
        let n = bilinear::<12, 48, 24>(
            self.tables[Table::N as usize],
            res.n_phi as usize,
            self.theta_r.locate(tr.abs()),
            self.phi.locate(abs_phi),
            self.unbias[Table::N as usize],
        );
        Lookups {
            m,
            ms,
            n,
            front: (abs_phi * (1.0 / PI)).min(1.0),
            inv_cos2: inv_cos2_theta_i(cos_within_half_pi(ti)),
        }
    }

    /// Far-field S(ω_i, ω_r) per lobe family from the lookups: M_g·N_g and
    /// M^s·N^s with M^s = (1 − |φ|/π)·back + (|φ|/π)·front, each over cos²θ_i.
    #[inline]
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

    /// Far-field S(ω_i, ω_r) per lobe family, from the tables (docs/model.md §8).
    #[inline]
    #[must_use]
    pub fn eval_far(&self, angles: &Angles) -> Families {
        Self::assemble(&self.lookups(angles))
    }

    /// Far-field S from world-space directions (see [`Angles::from_directions`]); invalid
    /// directions give zero.
    pub fn eval_far_dirs(&self, wi: Vec3, wr: Vec3, tangent: Vec3) -> Families {
        match Angles::from_directions::<M>(wi, wr, tangent) {
            Ok(a) => self.eval_far(&a),
            Err(_) => Families::ZERO,
        }
    }
}
