//! The sampling section of a LUT (format version 2, docs/lut.md "Sampling data",
//! docs/model.md §10): running integrals ("prefix sums") of the piecewise-linear densities
//! the baked sampler draws from, stored after the tables as little-endian f32.
//!
//! Each density is one table row read as a function of its column axis, linearly
//! interpolated between nodes exactly as the baked evaluator interpolates it:
//!
//! | density | table | row | value at a node | nodes | prefix every |
//! |---|---|---|---|---|---|
//! | [`Density::M`]`(g)` | `M` | the single row | channel g | n_sum over x = θ_i + θ_r ∈ [−π, π] | node ([`M_BLOCK`]) |
//! | [`Density::N`]`(f)` | `N` | each \|θ_r\| row of the σ_ca = 0 plane | family f | n_phi over \|φ\| ∈ [0, π] | [`N_BLOCK`] nodes |
//! | [`Density::MS`]`(x)` | `M_s` | each θ_r row | channel x (back, front) | n_ms_i over θ_i ∈ [−π/2, π/2] | [`MS_BLOCK`] nodes |
//! | [`Density::Front`] | `N` | each \|θ_r\| row of the σ_ca = 0 plane | N^s, weighted by \|φ\|/π | n_phi over \|φ\| ∈ [0, π] | [`N_BLOCK`] nodes |
//!
//! The `N` densities are read from the lossless plane (absorption node 0, LUT format 5): the
//! sampler draws from the brightest N whatever colour is evaluated, so its density is the same
//! for every colour and the weights S·cos θ_i/p are bounded by the lossless ones (absorption
//! only darkens; docs/model.md §10).
//!
//! Entry k of a row's prefix is ∫ of the density from the first node to node min(k·B, n − 1)
//! (B the block), summed segment by segment in f32 as len·(v_j + v_{j+1})/2
//! ([`Density::Front`]: the exact integral of (|φ|/π)·n_s, [`weighted_linear_mass`]), in this
//! order: `M` channels 0..3, then `N` families 0..4 × rows, then `M_s` halves 0..2 × rows,
//! then the front-weighted N^s rows (format version 4: the exact back/front blend of the
//! scattered family, docs/model.md §10). The last entry of a row is its total. The data is derived from the tables: [`super::seal`] writes
//! it and [`super::validate`] recomputes it and requires the same bits.

use super::{f16_biased, LutResolution, Table, F16_UNBIAS, HEADER_LEN, TABLE_COUNT};
use crate::math::PI;
use crate::sample1d::{linear_mass, weighted_linear_mass};
use core::ops::Range;

/// Nodes per prefix entry of the `M` densities (every node: the pdf needs the CDF at two
/// arbitrary points per query).
pub const M_BLOCK: usize = 1;
/// Nodes per prefix entry of the `N` densities.
pub const N_BLOCK: usize = 8;
/// Nodes per prefix entry of the `M_s` densities.
pub const MS_BLOCK: usize = 8;

/// One family of sampled densities.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Density {
    /// M_g over x = θ_i + θ_r, g = 0, 1, 2 (R, TT, TRT).
    M(usize),
    /// N_f over |φ| at one |θ_r| row of the lossless plane, f = 0..4 ([`crate::LobeFamily`]
    /// order).
    N(usize),
    /// M^s_back (0) or M^s_front (1) over θ_i at one θ_r row.
    MS(usize),
    /// The scattered family's N^s over |φ| at one |θ_r| row of the lossless plane,
    /// weighted by |φ|/π: the φ density of the front part of M^s's blend (the back part's is
    /// [`Density::N`]`(3)` less this).
    Front,
}

/// Number of prefix entries of a row of `nodes` nodes with blocks of `block` nodes.
#[must_use]
pub const fn entries(nodes: usize, block: usize) -> usize {
    (nodes - 1).div_ceil(block) + 1
}

impl Density {
    /// The table the density reads.
    #[must_use]
    pub const fn table(self) -> Table {
        match self {
            Density::M(_) => Table::M,
            Density::N(_) | Density::Front => Table::N,
            Density::MS(_) => Table::MS,
        }
    }

    /// Nodes per prefix entry.
    #[must_use]
    pub const fn block(self) -> usize {
        match self {
            Density::M(_) => M_BLOCK,
            Density::N(_) | Density::Front => N_BLOCK,
            Density::MS(_) => MS_BLOCK,
        }
    }

    /// The channel of a node value.
    const fn channel(self) -> usize {
        match self {
            Density::M(g) => g,
            Density::N(f) => f,
            Density::MS(x) => x,
            Density::Front => 3,
        }
    }

    /// Index of the density in section order (`M` 0..3, `N` 3..7, `M_s` 7..9, `Front` 9).
    #[must_use]
    pub const fn index(self) -> usize {
        match self {
            Density::M(g) => g,
            Density::N(f) => 3 + f,
            Density::MS(x) => 7 + x,
            Density::Front => 9,
        }
    }

    /// The mass of segment j of a row of `nodes` nodes, node values `v0`, `v1`, spacing
    /// `step`: len·(v0 + v1)/2, or for [`Density::Front`] the exact integral of the
    /// |φ|/π-weighted linear interpolant.
    #[inline(always)]
    #[must_use]
    pub fn segment_mass(self, j: usize, nodes: usize, v0: f32, v1: f32, step: f32) -> f32 {
        match self {
            Density::Front => {
                let (a, b) = front_weights(j, nodes);
                weighted_linear_mass(v0, v1, a, b, step)
            }
            _ => linear_mass(v0, v1, step),
        }
    }

    /// All densities in section order.
    pub const ALL: [Density; 10] = [
        Density::M(0),
        Density::M(1),
        Density::M(2),
        Density::N(0),
        Density::N(1),
        Density::N(2),
        Density::N(3),
        Density::MS(0),
        Density::MS(1),
        Density::Front,
    ];
}

/// The front weight |φ|/π at nodes j and j + 1 of an |φ| ∈ [0, π] row of `nodes` nodes.
#[inline(always)]
#[must_use]
pub fn front_weights(j: usize, nodes: usize) -> (f32, f32) {
    let inv = 1.0 / (nodes - 1) as f32;
    (j as f32 * inv, (j + 1) as f32 * inv)
}

impl LutResolution {
    /// (rows, nodes per row) of a density's table (table `N`: its first plane, σ_ca = 0).
    #[must_use]
    pub fn density_dims(&self, d: Density) -> (usize, usize) {
        let (w, h) = self.dims(d.table());
        match d.table() {
            Table::N => (self.n_theta_r as usize, w),
            _ => (h, w),
        }
    }

    /// Node spacing along a density's axis (radians).
    #[must_use]
    pub fn density_step(&self, d: Density) -> f32 {
        let (_, nodes) = self.density_dims(d);
        let span = match d {
            Density::M(_) => 2.0 * PI,
            Density::N(_) | Density::MS(_) | Density::Front => PI,
        };
        span / (nodes - 1) as f32
    }

    /// Prefix entries per row of a density.
    #[must_use]
    pub fn prefix_entries(&self, d: Density) -> usize {
        entries(self.density_dims(d).1, d.block())
    }

    /// f32 values of one density (all its rows).
    fn density_values(&self, d: Density) -> usize {
        self.density_dims(d).0 * self.prefix_entries(d)
    }

    /// Number of f32 values in the sampling section.
    #[must_use]
    pub fn sampling_values(&self) -> usize {
        Density::ALL.iter().map(|&d| self.density_values(d)).sum()
    }

    /// Byte offset of the sampling section in the blob.
    #[must_use]
    pub fn sampling_start(&self) -> usize {
        HEADER_LEN + 2 * self.total_values()
    }

    /// Byte range of one density's prefix entries (all rows, row-major).
    #[must_use]
    pub fn prefix_range(&self, d: Density) -> Range<usize> {
        let before: usize = Density::ALL[..d.index()]
            .iter()
            .map(|&e| self.density_values(e))
            .sum();
        let start = self.sampling_start() + 4 * before;
        start..start + 4 * self.density_values(d)
    }
}

/// Where one density's rows and prefix entries are, precomputed once per LUT.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DensityLayout {
    /// Byte offset of the first prefix entry in the blob.
    pub prefix_at: usize,
    /// Prefix entries per row.
    pub entries: usize,
    /// Nodes per row.
    pub nodes: usize,
    /// Rows.
    pub rows: usize,
    /// Node spacing (radians).
    pub step: f32,
    /// Nodes per prefix entry.
    pub block: usize,
}

impl LutResolution {
    /// The layout of one density.
    #[must_use]
    pub fn density_layout(&self, d: Density) -> DensityLayout {
        let (rows, nodes) = self.density_dims(d);
        DensityLayout {
            prefix_at: self.prefix_range(d).start,
            entries: self.prefix_entries(d),
            nodes,
            rows,
            step: self.density_step(d),
            block: d.block(),
        }
    }
}

/// Read access to the node values of the tables, as the evaluator decodes them.
#[derive(Clone, Copy, Debug)]
pub struct Nodes<'a> {
    tables: [&'a [u8]; TABLE_COUNT],
    /// Table scale × 2^112 (see [`f16_biased`]).
    unbias: [f32; TABLE_COUNT],
    /// Texels per row of each table.
    width: [usize; TABLE_COUNT],
    res: LutResolution,
}

impl<'a> Nodes<'a> {
    /// Over the table bytes of a blob whose header gave `res` and `scales` (lengths are
    /// checked by the caller; a short table reads as zeros).
    #[must_use]
    pub fn new(blob: &'a [u8], res: LutResolution, scales: [f32; TABLE_COUNT]) -> Nodes<'a> {
        let mut tables: [&'a [u8]; TABLE_COUNT] = [&[]; TABLE_COUNT];
        let mut unbias = [0.0; TABLE_COUNT];
        for t in Table::ALL {
            tables[t as usize] = blob.get(res.byte_range(t)).unwrap_or(&[]);
            unbias[t as usize] = scales[t as usize] * F16_UNBIAS;
        }
        Nodes {
            tables,
            unbias,
            width: Table::ALL.map(|t| res.dims(t).0),
            res,
        }
    }

    /// The value of density `d` at node `j` of row `row` (0 outside the table).
    #[inline]
    #[must_use]
    pub fn value(&self, d: Density, row: usize, j: usize) -> f32 {
        self.row(d, row).value(j)
    }

    /// One row of density `d`, for reading many of its nodes ([`NodeRow::value`]).
    #[inline]
    #[must_use]
    pub fn row(&self, d: Density, row: usize) -> NodeRow<'a> {
        let t = d.table() as usize;
        let channels = Table::ALL[t].channels();
        let start = 2 * (row * self.width[t] * channels + d.channel());
        NodeRow {
            data: self.tables[t].get(start..).unwrap_or(&[]),
            stride: 2 * channels,
            scale: self.unbias[t],
        }
    }

    /// The three `M` channels at nodes j and j + 1 (R, TT, TRT, then the same at j + 1), as
    /// [`Nodes::value`] gives them; zeros past the table.
    #[inline]
    #[must_use]
    pub fn m_pair(&self, j: usize) -> [f32; 6] {
        let k = self.unbias[Table::M as usize];
        match self.tables[Table::M as usize].get(6 * j..6 * j + 12) {
            Some(b) => core::array::from_fn(|i| {
                f16_biased(u16::from_le_bytes([b[2 * i], b[2 * i + 1]])) * k
            }),
            None => [0.0; 6],
        }
    }

    /// Computes every prefix entry in section order and hands it to `sink` with its index in
    /// the section.
    fn for_each_prefix(&self, mut sink: impl FnMut(usize, f32)) {
        let mut index = 0;
        for d in Density::ALL {
            let (rows, nodes) = self.res.density_dims(d);
            let step = self.res.density_step(d);
            let block = d.block();
            for row in 0..rows {
                let mut acc = 0.0f32;
                sink(index, acc);
                index += 1;
                let mut prev = self.value(d, row, 0);
                for j in 1..nodes {
                    let v = self.value(d, row, j);
                    acc += d.segment_mass(j - 1, nodes, prev, v, step);
                    prev = v;
                    if j % block == 0 || j == nodes - 1 {
                        sink(index, acc);
                        index += 1;
                    }
                }
            }
        }
    }
}

/// The nodes of one row of one density ([`Nodes::row`]): the value at a node is a half (× the
/// table scale; docs/lut.md "Sampling data").
#[derive(Clone, Copy, Debug)]
pub struct NodeRow<'a> {
    /// The table from the row's first node's first channel on.
    data: &'a [u8],
    /// Bytes from one node to the next.
    stride: usize,
    /// Table scale × 2^112.
    scale: f32,
}

impl NodeRow<'_> {
    /// The value at node `j` (0 outside the table): the one formula of a node's value, for
    /// the prefix sums and the sampler alike.
    #[inline(always)]
    #[must_use]
    pub fn value(&self, j: usize) -> f32 {
        let at = j * self.stride;
        match self.data.get(at..at + 2) {
            Some(b) => f16_biased(u16::from_le_bytes([b[0], b[1]])) * self.scale,
            None => 0.0,
        }
    }
}

/// Writes the sampling section of `blob` (header and tables filled in) from its tables.
pub(super) fn write(blob: &mut [u8], res: LutResolution, scales: [f32; TABLE_COUNT]) {
    let start = res.sampling_start();
    // The tables lie entirely before the section: read them while writing the section.
    let (tables, section) = blob.split_at_mut(start.min(blob.len()));
    let nodes = Nodes::new(tables, res, scales);
    nodes.for_each_prefix(|i, v| {
        if let Some(dst) = section.get_mut(4 * i..4 * i + 4) {
            dst.copy_from_slice(&v.to_le_bytes());
        }
    });
}

/// Checks that the sampling section of `blob` holds exactly the prefix sums of its tables;
/// returns the index of the first entry that differs.
pub(super) fn check(
    blob: &[u8],
    res: LutResolution,
    scales: [f32; TABLE_COUNT],
) -> Result<(), usize> {
    let start = res.sampling_start();
    let nodes = Nodes::new(blob, res, scales);
    let mut bad = None;
    nodes.for_each_prefix(|i, v| {
        if bad.is_some() {
            return;
        }
        let at = start + 4 * i;
        let stored = blob
            .get(at..at + 4)
            .map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]));
        if stored != Some(v.to_bits()) {
            bad = Some(i);
        }
    });
    match bad {
        Some(i) => Err(i),
        None => Ok(()),
    }
}
