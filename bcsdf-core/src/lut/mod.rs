//! The baked LUT format: the far-field BCSDF of docs/model.md §8, both components, factored
//! along the model's own structure into three half-float tables plus the data the baked
//! sampler needs (docs/model.md §10), and the little-endian byte layout
//! the core reads in place (from `include_bytes!`, a memory map or a loaded file).
//!
//! The header codec is in `header.rs`, the sampling section in [`cdf`], the energy
//! closure's 1/Z_g table in [`norms`].
//!
//! The far field is
//!
//! S(θ_i, θ_r, φ) = [Σ_g M_g(θ_i + θ_r)·N_g(|θ_r|, |φ|) + M^s(θ_i, θ_r, |φ|)·N^s(|θ_r|, |φ|)]
//! / cos²θ_i
//!
//! with g over the cuticle groups R, TT, TRT. N_g is the sum of the far-field N_p of the
//! group's paths and N^s that of the three scattered lobes; both depend on θ_r only through
//! sin²θ_r (Bravais indices, refraction) and are even in φ, so they are stored over |θ_r| and
//! |φ|. M^s = (1 − |φ|/π)·M^s_back + (|φ|/π)·M^s_front is stored as its two halves. The
//! 1/cos²θ_i factor and the back/front blend are evaluated exactly, not tabulated.
//!
//! | table | value | axes (x: columns, y: rows) | channels |
//! |---|---|---|---|
//! | `M` | M_g(x) | x = θ_i + θ_r ∈ [−π, π] | R, TT, TRT |
//! | `N` | N_R, N_TT, N_TRT, Σ N^s_p at one absorption σ_ca each plane | x = \|φ\| ∈ [0, π], y = \|θ_r\| ∈ [0, π/2], planes: σ_ca on the absorption axis | R, TT, TRT, s |
//! | `M_s` | M^s_back, M^s_front | x = θ_i, y = θ_r, both ∈ [−π/2, π/2] | back, front |
//!
//! The four azimuthal functions share their axes, so they are one 4-channel table. They are
//! tabulated against the cortex absorption σ_ca as well (LUT format 5): σ_ma, η, β, κ and l are
//! scalars of the parameter set, so each RGB channel of N is the same scalar function of that
//! channel's σ_ca alone, and table `N` holds one plane per node of the absorption axis
//! ([`absorption_coordinate`]), each plane the four families at that σ_ca. A query looks each
//! colour channel up at its own σ_ca (docs/lut.md "The absorption axis"). N_R does not depend
//! on σ_ca; it is stored in every plane so that a texel is four adjacent halves (one 8-byte
//! read). Tables `M` and `M_s` and the 1/Z_g table do not depend on σ_ca.
//!
//! Every axis has uniformly spaced nodes, the first and last on the interval ends; values are
//! point samples at the nodes, interpolated linearly (bilinearly in 2D).
//!
//! Each table stores value / scale as IEEE binary16 with one power-of-two `scale` per table,
//! chosen by the baker so that the table's largest value is stored in [2^14, 2^15): the
//! physical value is `f16 × scale`, exactly. This keeps the whole f16 range for the data
//! (values below 2^−28 of a table's peak are stored as 0) and lets the evaluator convert a
//! half with a shift and one multiply.
//!
//! Byte layout (all little-endian), [`HEADER_LEN`] bytes of header, then the tables in
//! [`Table::ALL`] order, each row-major with the channels of a texel adjacent:
//!
//! | offset | field |
//! |---|---|
//! | 0 | magic `FURLUT\0\0` |
//! | 8 | format version (u32, [`FORMAT_VERSION`]) |
//! | 12 | model version (u32, [`crate::MODEL_VERSION`]) |
//! | 16 | resolution: n_sum, n_theta_r, n_phi, n_ms_i, n_ms_r, n_abs (6 × u32) |
//! | 40 | scales (3 × f32, [`Table::ALL`] order) |
//! | 52 | parameters: η_c, pigment kind (u32: 0 σ_ca, 1 melanin), pigment (3 × f32), α°, β_m°, β_n°, l, κ, η_m, σ_ms, σ_ma, g, closure (u32: 0 report, 1 energy) |
//! | 112 | has profiles (u32 0/1), profile generator version (u32) |
//! | 120 | profile seed (u64) |
//! | 128 | photon budget: per C^N cell, per C^M row (2 × u32) |
//! | 136 | profile resolution: n_sigma, n_h, n_psi, n_in, n_out (5 × u32) |
//! | 156 | the absorption axis's scale s₀ (f32, [`absorption_scale`] of the parameters' κ) |
//! | 160 | checksum: FNV-1a 64 of every other byte of the blob (u64) |
//! | 168 | table data (u16 halves) |
//! | [`LutResolution::sampling_start`] | sampling section (f32 prefix sums, [`cdf`]) |
//! | [`LutResolution::norm_start`] | 1/Z_g(θ_r) table (f32, [`norms`]) |

pub mod cdf;
mod header;
pub mod norms;

use crate::medulla::{PhotonBudget, Resolution};
use crate::params::{FurParamsInput, ParamError};
use core::fmt;
use core::ops::Range;

/// First eight bytes of every LUT blob.
pub const MAGIC: [u8; 8] = *b"FURLUT\0\0";

/// Version of this layout; a blob of another version is rejected. Version 2 added the
/// sampling section ([`cdf`]); version 3 the `closure` parameter (docs/model.md §12); version
/// 4 the energy closure's 1/Z_g table ([`norms`]); version 5 the absorption axis of table `N`
/// (one plane per σ_ca node, [`absorption_coordinate`]; the resolution's `n_abs`).
pub const FORMAT_VERSION: u32 = 5;

/// Length of the fixed header in bytes.
pub const HEADER_LEN: usize = 168;

/// Byte offset of the profile provenance block.
const PROFILES: usize = 112;

/// Byte offset of the absorption axis's scale, the word before the checksum.
const RESERVED: usize = 156;

/// Byte range of the checksum field.
pub const CHECKSUM: Range<usize> = 160..168;

pub use crate::absorption::SIGMA_CA_MAX;

mod axis;
pub use axis::{
    absorption_coordinate, absorption_node, absorption_scale, ABSORPTION_SCALE_HAIR,
    ABSORPTION_SCALE_ROOT, MIN_ABSORPTION_NODES, ROOT_RATE, ROOT_SHARE,
};

/// Largest node count accepted on any axis.
pub const MAX_NODES: u32 = 8192;

/// Largest number of f16 values (all tables together) accepted: 64 Mi values, 128 MiB.
pub const MAX_VALUES: usize = 1 << 26;

/// Smallest and largest accepted table scale (powers of two); the bounds keep every product
/// the evaluator forms finite.
pub const SCALE_RANGE: (f32, f32) = (1.0 / (1u64 << 60) as f32, (1u32 << 15) as f32);

/// FNV-1a 64 (the LUT checksum; also used by the profile cache).
#[must_use]
pub fn fnv1a64(bytes: &[u8]) -> u64 {
    fnv1a64_continue(0xcbf2_9ce4_8422_2325, bytes)
}

/// FNV-1a 64 of `bytes`, continuing from the hash `h`.
pub(crate) fn fnv1a64_continue(mut h: u64, bytes: &[u8]) -> u64 {
    for &b in bytes {
        h ^= u64::from(b);
        h = h.wrapping_mul(0x0000_0100_0000_01b3);
    }
    h
}

/// One of the three tables.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Table {
    /// M_g(θ_i + θ_r) for the three cuticle groups.
    M = 0,
    /// N_g(|θ_r|, |φ|) of the R, TT and TRT groups (each the sum of its paths' far-field
    /// N_p) and Σ N^s_p of the scattered lobes, in [`LobeFamily`](crate::LobeFamily) order,
    /// one plane of n_theta_r rows per node of the absorption axis (format 5).
    N = 1,
    /// M^s_back(θ_i, θ_r) and M^s_front(θ_i, θ_r).
    MS = 2,
}

/// Number of tables.
pub const TABLE_COUNT: usize = 3;

/// Channels of table `N`: the four families at the plane's σ_ca.
const N_CHANNELS: [&str; 4] = ["R", "TT", "TRT", "s"];

impl Table {
    /// All tables in blob order.
    pub const ALL: [Table; TABLE_COUNT] = [Table::M, Table::N, Table::MS];

    /// Layer name in the EXR file and in messages.
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            Table::M => "M",
            Table::N => "N",
            Table::MS => "M_s",
        }
    }

    /// Channel names, in texel order.
    #[must_use]
    pub const fn channel_names(self) -> &'static [&'static str] {
        match self {
            Table::M => &["R", "TT", "TRT"],
            Table::N => &N_CHANNELS,
            Table::MS => &["back", "front"],
        }
    }

    /// Channels per texel.
    #[must_use]
    pub const fn channels(self) -> usize {
        self.channel_names().len()
    }
}

/// Node counts of the table axes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LutResolution {
    /// Nodes of x = θ_i + θ_r ∈ [−π, π] (table `M`).
    pub n_sum: u32,
    /// Nodes of |θ_r| ∈ [0, π/2] (the N tables' rows).
    pub n_theta_r: u32,
    /// Nodes of |φ| ∈ [0, π] (the N tables' columns).
    pub n_phi: u32,
    /// Nodes of θ_i ∈ [−π/2, π/2] (table `M_s` columns).
    pub n_ms_i: u32,
    /// Nodes of θ_r ∈ [−π/2, π/2] (table `M_s` rows).
    pub n_ms_r: u32,
    /// Nodes of the absorption axis σ_ca ∈ [0, [`SIGMA_CA_MAX`]] (table `N`'s planes,
    /// [`absorption_coordinate`]).
    pub n_abs: u32,
}

impl LutResolution {
    /// The default resolution (docs/lut.md gives the error it was chosen by).
    pub const DEFAULT: LutResolution = LutResolution {
        n_sum: 2048,
        n_theta_r: 64,
        n_phi: 128,
        n_ms_i: 96,
        n_ms_r: 96,
        n_abs: 22,
    };

    /// The node counts with their names, in header order, for messages and metadata.
    #[must_use]
    pub fn axes(&self) -> [(&'static str, u32); 6] {
        [
            ("n_sum", self.n_sum),
            ("n_theta_r", self.n_theta_r),
            ("n_phi", self.n_phi),
            ("n_ms_i", self.n_ms_i),
            ("n_ms_r", self.n_ms_r),
            ("n_abs", self.n_abs),
        ]
    }

    /// Texels of one plane of table `N` (one absorption node): n_phi × n_theta_r.
    #[must_use]
    pub fn n_plane(&self) -> usize {
        self.n_phi as usize * self.n_theta_r as usize
    }

    /// The fewest nodes axis `axis` may have: [`MIN_ABSORPTION_NODES`] for `n_abs`, else 2.
    #[must_use]
    pub fn fewest_nodes(axis: &str) -> u32 {
        if axis == "n_abs" {
            MIN_ABSORPTION_NODES
        } else {
            2
        }
    }

    /// Checks every axis has 2 ..= [`MAX_NODES`] nodes (the absorption axis at least
    /// [`MIN_ABSORPTION_NODES`]) and the tables hold at most
    /// [`MAX_VALUES`] values.
    pub fn validate(&self) -> Result<(), LutError> {
        for (axis, nodes) in self.axes() {
            if !(Self::fewest_nodes(axis)..=MAX_NODES).contains(&nodes) {
                return Err(LutError::Resolution { axis, nodes });
            }
        }
        if self.total_values() > MAX_VALUES {
            return Err(LutError::TooLarge {
                values: self.total_values(),
            });
        }
        Ok(())
    }

    /// (width, height) of a table in texels (table `N`: its planes stacked, n_abs ×
    /// n_theta_r rows).
    #[must_use]
    pub fn dims(&self, table: Table) -> (usize, usize) {
        match table {
            Table::M => (self.n_sum as usize, 1),
            Table::N => (
                self.n_phi as usize,
                self.n_theta_r as usize * self.n_abs as usize,
            ),
            Table::MS => (self.n_ms_i as usize, self.n_ms_r as usize),
        }
    }

    /// Number of f16 values in a table.
    #[must_use]
    pub fn values(&self, table: Table) -> usize {
        let (w, h) = self.dims(table);
        w * h * table.channels()
    }

    /// Number of f16 values in all tables.
    #[must_use]
    pub fn total_values(&self) -> usize {
        Table::ALL.iter().map(|&t| self.values(t)).sum()
    }

    /// Byte range of a table inside the blob.
    #[must_use]
    pub fn byte_range(&self, table: Table) -> Range<usize> {
        let start = HEADER_LEN
            + Table::ALL[..table as usize]
                .iter()
                .map(|&t| 2 * self.values(t))
                .sum::<usize>();
        start..start + 2 * self.values(table)
    }

    /// Length of the whole blob in bytes: header, tables, sampling section and 1/Z_g table.
    #[must_use]
    pub fn blob_len(&self) -> usize {
        self.norm_start() + 4 * self.norm_values()
    }
}

/// How the medulla profiles behind the scattered tables were made, so that the analytic
/// model the tables were baked from can be rebuilt bit for bit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ProfileProvenance {
    /// Profile generator version ([`crate::medulla::GENERATOR_VERSION`]).
    pub generator_version: u32,
    /// Seed of the random streams.
    pub seed: u64,
    /// Photons per cell.
    pub budget: PhotonBudget,
    /// Table resolution.
    pub res: Resolution,
}

/// Everything in a LUT besides the table data.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LutHeader {
    /// Node counts.
    pub res: LutResolution,
    /// Per-table scale (value = f16 × scale), [`Table::ALL`] order.
    pub scales: [f32; TABLE_COUNT],
    /// The parameters the tables were baked from.
    pub params: FurParamsInput,
    /// The profiles the scattered tables were baked from (`None`: the model had none, the
    /// scattered tables are zero).
    pub profiles: Option<ProfileProvenance>,
}

/// Why a LUT blob was rejected.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LutError {
    /// Shorter than the header.
    TooShort {
        /// Bytes given.
        len: usize,
    },
    /// Does not start with [`MAGIC`].
    BadMagic,
    /// Made for another layout version.
    FormatVersion {
        /// Version found.
        found: u32,
    },
    /// Made by another model version.
    ModelVersion {
        /// Version found.
        found: u32,
    },
    /// An axis has too few or too many nodes.
    Resolution {
        /// Axis name.
        axis: &'static str,
        /// Nodes found.
        nodes: u32,
    },
    /// The tables would be larger than [`MAX_VALUES`].
    TooLarge {
        /// Values the header asks for.
        values: usize,
    },
    /// The blob length does not match the header's resolution (truncated or padded).
    Length {
        /// Bytes the header implies.
        expected: usize,
        /// Bytes given.
        found: usize,
    },
    /// A table scale is not a power of two within [`SCALE_RANGE`].
    Scale {
        /// Table.
        table: Table,
        /// Value found.
        value: f32,
    },
    /// A stored value is negative, infinite or NaN.
    Value {
        /// Table.
        table: Table,
        /// Index of the value within the table.
        index: usize,
        /// Its bits.
        bits: u16,
    },
    /// The stored parameters are invalid.
    Params(ParamError),
    /// A field that must be 0/1 or zero is not.
    Field {
        /// Field name.
        field: &'static str,
    },
    /// The derived data (the sampling section's prefix sums, then the 1/Z_g table) does not
    /// match the tables.
    Sampling {
        /// Index of the first wrong f32 entry, counted from the start of the sampling
        /// section (the 1/Z_g table's entries follow the prefix sums').
        entry: usize,
    },
    /// The checksum does not match: the data was changed after baking.
    Checksum {
        /// Checksum stored.
        stored: u64,
        /// Checksum of the bytes given.
        computed: u64,
    },
}

impl core::error::Error for LutError {
    fn source(&self) -> Option<&(dyn core::error::Error + 'static)> {
        match self {
            LutError::Params(e) => Some(e),
            _ => None,
        }
    }
}

impl fmt::Display for LutError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            LutError::TooShort { len } => write!(
                f,
                "LUT is truncated: {len} bytes, shorter than the {HEADER_LEN}-byte header"
            ),
            LutError::BadMagic => f.write_str("not a fur LUT (bad magic)"),
            LutError::FormatVersion { found } => write!(
                f,
                "LUT format version {found} is not supported (this build reads version {FORMAT_VERSION}): re-bake it with this version's `bake`"
            ),
            LutError::ModelVersion { found } => write!(
                f,
                "LUT was baked by model version {found}; this build is model version {}: re-bake it with this version's `bake`",
                crate::model::MODEL_VERSION
            ),
            LutError::Resolution { axis, nodes } => write!(
                f,
                "LUT axis {axis} has {nodes} nodes (valid: {} to {MAX_NODES})",
                LutResolution::fewest_nodes(axis)
            ),
            LutError::TooLarge { values } => write!(
                f,
                "LUT asks for {values} values, more than the limit of {MAX_VALUES}"
            ),
            LutError::Length { expected, found } => write!(
                f,
                "LUT is {found} bytes but its header describes {expected} bytes ({})",
                if found < expected { "truncated" } else { "trailing data" }
            ),
            LutError::Scale { table, value } => write!(
                f,
                "LUT table {} has scale {value}, not a power of two in [2^-60, 2^15]",
                table.name()
            ),
            LutError::Value { table, index, bits } => write!(
                f,
                "LUT table {} value {index} is negative or not finite (f16 bits {bits:#06x})",
                table.name()
            ),
            LutError::Params(e) => write!(f, "LUT parameters are invalid: {e}"),
            LutError::Field { field } => write!(f, "LUT header field {field} is invalid"),
            LutError::Sampling { entry } => write!(
                f,
                "LUT sampling data entry {entry} does not match its tables: the file is corrupt, re-bake it"
            ),
            LutError::Checksum { stored, computed } => write!(
                f,
                "LUT is corrupt: checksum {computed:016x} does not match the stored {stored:016x}"
            ),
        }
    }
}

/// f16 bits → f32 for non-negative finite halves (the only ones a valid LUT holds), exact:
/// shifting the bits into place gives the value times 2^−112 (normal and subnormal halves
/// alike), which the caller multiplies back, usually folded into the table scale
/// ([`F16_UNBIAS`]).
#[inline(always)]
#[must_use]
pub fn f16_biased(bits: u16) -> f32 {
    f32::from_bits(u32::from(bits) << 13)
}

/// 2^112: [`f16_biased`]`(bits) × F16_UNBIAS` is the half's value.
pub const F16_UNBIAS: f32 = f32::from_bits((127 + 112) << 23);

/// Checks that the bits are a non-negative finite half (sign bit clear, exponent not all
/// ones).
#[inline]
#[must_use]
pub fn is_valid_value(bits: u16) -> bool {
    bits & 0x8000 == 0 && bits & 0x7c00 != 0x7c00
}

fn is_valid_scale(s: f32) -> bool {
    s.is_finite() && (SCALE_RANGE.0..=SCALE_RANGE.1).contains(&s) && s.to_bits() & 0x007f_ffff == 0
}

/// The checksum of a blob: FNV-1a 64 over every byte except the checksum field.
#[must_use]
pub fn checksum(blob: &[u8]) -> u64 {
    let head = blob.get(..CHECKSUM.start).unwrap_or(blob);
    let tail = blob.get(CHECKSUM.end..).unwrap_or(&[]);
    fnv1a64_continue(fnv1a64(head), tail)
}

/// Writes the derived data of a blob whose header and tables are filled in: the sampling
/// section ([`cdf`]), then the 1/Z_g table ([`norms`], which reads the former); the checksum
/// is left as it is. A blob whose header does not decode is left alone.
pub fn write_sampling(blob: &mut [u8]) {
    if let Ok(header) = LutHeader::decode(blob) {
        cdf::write(blob, header.res, header.scales);
        norms::write(blob, header.res, header.scales);
    }
}

/// Completes a blob whose header and tables are filled in: writes the sampling section
/// ([`write_sampling`]), then the checksum. Blobs shorter than the header are left alone; a
/// blob whose header does not decode gets only its checksum.
pub fn seal(blob: &mut [u8]) {
    if blob.len() >= HEADER_LEN {
        write_sampling(blob);
        let sum = checksum(blob);
        blob[CHECKSUM].copy_from_slice(&sum.to_le_bytes());
    }
}

/// Checks a whole blob: header ([`LutHeader::decode`]), checksum, that every stored value
/// is a non-negative finite half, that the sampling section holds exactly the prefix sums of
/// the tables and the 1/Z_g table exactly the values they give.
pub fn validate(bytes: &[u8]) -> Result<LutHeader, LutError> {
    let header = LutHeader::decode(bytes)?;
    let stored = u64::from_le_bytes(bytes[CHECKSUM].try_into().unwrap_or([0; 8]));
    let computed = checksum(bytes);
    if stored != computed {
        return Err(LutError::Checksum { stored, computed });
    }
    for t in Table::ALL {
        let data = &bytes[header.res.byte_range(t)];
        for (index, pair) in data.chunks_exact(2).enumerate() {
            let bits = u16::from_le_bytes([pair[0], pair[1]]);
            if !is_valid_value(bits) {
                return Err(LutError::Value {
                    table: t,
                    index,
                    bits,
                });
            }
        }
    }
    cdf::check(bytes, header.res, header.scales).map_err(|entry| LutError::Sampling { entry })?;
    norms::check(bytes, header.res, header.scales).map_err(|i| LutError::Sampling {
        entry: header.res.sampling_values() + i,
    })?;
    Ok(header)
}
