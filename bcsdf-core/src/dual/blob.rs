//! The `.furdual` blob (docs/model.md §13, "Stored tables"): what [`DualLut::eval`] reads at
//! each θ node, derived from [`DualTables`] for one [`Attenuation`], as little-endian f16.
//!
//! Format 2 (the absorption axis): one grey (one-channel) set of tables per node of an
//! absorption axis of [`ABS_NODES`] nodes at σ_ca = [`axis_node`]`(k)` (the dual tables' own
//! axis, σ/(σ + 3) up to σ_ca = 1000). Layout
//! ([`BLOB_LEN`] = 292 944 bytes):
//!
//! | bytes | content |
//! |---|---|
//! | 0..8 | [`DUAL_MAGIC`] |
//! | 8..12 | [`DUAL_FORMAT_VERSION`] (u32) |
//! | 12..16 | [`crate::MODEL_VERSION`] of the model the tables came from (u32) |
//! | 16..32 | θ nodes (64), φ nodes (32), families (4), fields per node ([`FIELDS`] = 15), u32 each |
//! | 32..36 | [`Attenuation::code`] (u32) |
//! | 36..40 | absorption nodes n_abs ([`ABS_NODES`], u32) |
//! | 40..48 | source: the checksum of the LUT the tables were computed from, 0 if none (u64) |
//! | 48..56 | zero |
//! | 56..64 | FNV-1a 64 of every other byte (u64) |
//! | 64..76 | the preset's own σ_ca, RGB (f32 each): the colour [`DualLut::eval`] evaluates |
//! | 76..80 | zero |
//! | 80.. | per absorption node a: fields [θ node k][field f] (64 × 15 halves), then N^G [family g][θ node k][φ node j] (4 × 64 × 32 halves) |
//!
//! The fields of a node ([`FIELDS`], in this order): log₂ μ (the downward flux's decay per
//! fiber, [`super::coat_decay`]), β_f (the forward spread's width per fiber, rad), the local
//! backscatter's energy toward the back half and the front half ([`super::local_backscatter`]),
//! Δ_b, σ_b0, ā_f², then each family's mean of x and its standard deviation (rad). Widths are
//! stored as standard deviations, not variances: the narrowest (0.1°) stays a normal half.

use super::coat::node_coat;
use super::half_range::HalfRange;
use super::{coat_decay, local_backscatter, Attenuation, DualTables, PHI_NODES, THETA_NODES};
use crate::absorption::Absorption;
use crate::baked::BakedBcsdf;
use crate::lobes::FAMILY_COUNT;
use crate::lut::SIGMA_CA_MAX;
use crate::lut::{fnv1a64, fnv1a64_continue};
use crate::math::Math;
use crate::spectrum::Rgb;
use core::fmt;

/// The knee of the dual tables' absorption axis (per fiber radius): σ_ca sits at
/// σ/(σ + 3), normalised to 1 at σ_ca = [`SIGMA_CA_MAX`] (the WGSL's `fur_dual_locate`
/// mirrors it). The dual tables' own axis, independent of the LUT's (docs/model.md §13).
const AXIS_KNEE: f64 = 3.0;

/// The position of σ_ca on the dual tables' absorption axis, in [0, 1]: (σ/(σ + 3)) /
/// (1000/1003); NaN and negatives give 0, above 1000 gives 1.
#[must_use]
pub fn axis_coordinate(sigma: f32) -> f32 {
    #[allow(clippy::manual_clamp)]
    let s = sigma.max(0.0).min(SIGMA_CA_MAX);
    let max = SIGMA_CA_MAX / (SIGMA_CA_MAX + AXIS_KNEE as f32);
    (s / (s + AXIS_KNEE as f32) / max).min(1.0)
}

/// σ_ca of node `k` of the dual tables' axis ([`ABS_NODES`] nodes): the inverse of
/// [`axis_coordinate`] at k/(n − 1) in f64; node 0 is 0, the last node exactly 1000.
#[must_use]
pub fn axis_node(k: usize) -> f32 {
    let last = ABS_NODES - 1;
    if k >= last {
        return SIGMA_CA_MAX;
    }
    let max = f64::from(SIGMA_CA_MAX) / (f64::from(SIGMA_CA_MAX) + AXIS_KNEE);
    let v = k as f64 / last as f64 * max;
    (AXIS_KNEE * v / (1.0 - v)) as f32
}

/// The first eight bytes of a `.furdual` blob.
pub const DUAL_MAGIC: [u8; 8] = *b"FURDUAL\0";
/// The blob format this build reads and writes.
pub const DUAL_FORMAT_VERSION: u32 = 2;
/// Nodes of the absorption axis of a `.furdual` blob: σ_ca = [`axis_node`]`(k)`, the dual
/// tables' own axis (independent of the LUT's).
pub const ABS_NODES: usize = 16;
/// Quantities stored per θ node and channel.
pub const FIELDS: usize = 7 + 2 * FAMILY_COUNT;

const HEADER_LEN: usize = 80;
const CHECKSUM_AT: usize = 56;
const COLOUR_AT: usize = 64;
/// Halves of one absorption node's fields and N^G (one channel).
const FIELD_HALVES: usize = THETA_NODES * FIELDS;
const NG_HALVES: usize = FAMILY_COUNT * THETA_NODES * PHI_NODES;
const NODE_HALVES: usize = FIELD_HALVES + NG_HALVES;
/// Length of every `.furdual` blob in bytes.
pub const BLOB_LEN: usize = HEADER_LEN + 2 * ABS_NODES * NODE_HALVES;
// The dual-scattering storage budget with the absorption axis: at most 512 KB per preset.
const _: () = assert!(BLOB_LEN <= 512 * 1024);

/// Field indices within a node.
pub(super) const LOG2_DECAY: usize = 0;
pub(super) const BETA_F: usize = 1;
pub(super) const BACK: usize = 2;
pub(super) const FRONT: usize = 3;
pub(super) const DELTA_B: usize = 4;
pub(super) const SIGMA_B0: usize = 5;
pub(super) const A_F2: usize = 6;
pub(super) const MEAN: usize = 7;
pub(super) const SD: usize = 7 + FAMILY_COUNT;

/// Smallest stored log₂ μ: a fiber letting through less than 2⁻²⁴ of the light.
const MIN_LOG2_DECAY: f32 = -24.0;

/// Why a `.furdual` blob was refused.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DualError {
    /// The blob is not [`BLOB_LEN`] bytes long (its length).
    Length(usize),
    /// The first eight bytes are not [`DUAL_MAGIC`].
    Magic,
    /// Another blob format version (the blob's).
    FormatVersion(u32),
    /// Tables of another model version (the blob's).
    ModelVersion(u32),
    /// Table dimensions other than this build's, or non-zero reserved bytes.
    Layout,
    /// An unknown attenuation code (the blob's).
    Attenuation(u32),
    /// The checksum does not match the bytes.
    Checksum,
    /// The recorded preset colour (σ_ca) is NaN, negative or above [`SIGMA_CA_MAX`].
    Colour,
    /// A stored value is infinite, NaN or outside its field's range (the half's index).
    Value(usize),
    /// The blob was not computed from the LUT it is paired with ([`DualLut::check_lut`]):
    /// the source checksum it records (0: none recorded) and the LUT's.
    Source {
        /// The blob's source checksum.
        recorded: u64,
        /// The LUT's checksum.
        lut: u64,
    },
}

impl fmt::Display for DualError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            DualError::Length(n) => write!(
                f,
                "dual-scattering blob is {n} bytes long, expected {BLOB_LEN}"
            ),
            DualError::Magic => f.write_str("not a dual-scattering blob (bad magic)"),
            DualError::FormatVersion(v) => write!(
                f,
                "dual-scattering blob format {v}, this build reads {DUAL_FORMAT_VERSION}"
            ),
            DualError::ModelVersion(v) => write!(
                f,
                "dual-scattering tables of model version {v}, this build is {}",
                crate::MODEL_VERSION
            ),
            DualError::Layout => f.write_str("dual-scattering blob has another table layout"),
            DualError::Attenuation(c) => {
                write!(f, "dual-scattering blob has unknown attenuation {c}")
            }
            DualError::Checksum => {
                f.write_str("dual-scattering blob is corrupt (checksum mismatch)")
            }
            DualError::Colour => f.write_str(
                "dual-scattering blob records an invalid preset colour (sigma_ca outside [0, 1000])",
            ),
            DualError::Value(i) => write!(
                f,
                "dual-scattering blob holds an invalid value (half {i}: infinite, NaN or out of range)"
            ),
            DualError::Source { recorded: 0, lut } => write!(
                f,
                "dual-scattering blob records no source LUT, so it cannot be paired with LUT {lut:016x}"
            ),
            DualError::Source { recorded, lut } => write!(
                f,
                "dual-scattering blob was computed from LUT {recorded:016x}, not from this LUT {lut:016x}"
            ),
        }
    }
}

/// The quantities [`DualLut::eval`] reads (docs/model.md §13), decoded to f32: one grey set
/// per absorption node ([`ABS_NODES`]). About 590 KB; fixed size, no allocation. Only
/// [`DualLut::decode`] fills it, so every value is finite and within its field's range.
#[derive(Clone, Debug, PartialEq)]
pub struct DualLut {
    pub(super) attenuation: Attenuation,
    pub(super) source: u64,
    /// The preset's own σ_ca (the blob's header) and its place on the axis.
    pub(super) default: Absorption,
    pub(super) default_at: DualColour,
    /// √σ_ca of the absorption nodes (the interpolation variable).
    pub(super) sqrt_nodes: [f32; ABS_NODES],
    /// [absorption node][θ node][field].
    pub(super) nodes: [[[f32; FIELDS]; THETA_NODES]; ABS_NODES],
    /// [absorption node][family][θ node][φ node].
    pub(super) n_g: [[[[f32; PHI_NODES]; THETA_NODES]; FAMILY_COUNT]; ABS_NODES],
    /// ρ² of the coat at each absorption and θ node ([`super::coat::node_coat`]),
    /// derived at decode.
    pub(super) coat: [[f32; THETA_NODES]; ABS_NODES],
}

/// A colour located on a `.furdual` blob's absorption axis ([`DualLut::locate`]): per RGB
/// channel the lower absorption node and the weight of the upper one. Cheap to copy.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct DualColour {
    pub(super) node: [usize; 3],
    pub(super) w: [f32; 3],
}

/// Weights within this distance of 0 or 1 read the node itself: a colour computed at a node
/// (σ = [`absorption_node`], whose coordinate is an integer up to rounding) reads that node's
/// tables exactly.
const NODE_SNAP: f32 = 1e-4;

/// √σ_ca of each absorption node ([`absorption_node`]), the interpolation variable.
fn sqrt_nodes() -> [f32; ABS_NODES] {
    core::array::from_fn(|k| libm::sqrtf(axis_node(k)))
}

impl DualColour {
    /// σ_ca per channel on the axis of [`ABS_NODES`] nodes whose √σ are `sqrt_nodes`: the
    /// cell by [`axis_coordinate`], the weight linear in √σ within
    /// the cell (measured against linear in the coordinate: the dual quantities of a nearly
    /// lossless fiber go as √σ, docs in the module's tests). NaN and negative channels read
    /// node 0, large ones the last node.
    fn locate(sigma: Rgb, sqrt_nodes: &[f32; ABS_NODES]) -> DualColour {
        let last = (ABS_NODES - 1) as f32;
        let mut at = DualColour::default();
        for c in 0..3 {
            let u = (axis_coordinate(sigma.0[c]) * last).clamp(0.0, last);
            let mut k = (u as usize).min(ABS_NODES - 2);
            #[allow(clippy::manual_clamp)] // NaN → 0
            let s = libm::sqrtf(sigma.0[c].max(0.0).min(SIGMA_CA_MAX));
            let (lo, hi) = (sqrt_nodes[k], sqrt_nodes[k + 1]);
            let mut w = ((s - lo) / (hi - lo)).clamp(0.0, 1.0);
            if !w.is_finite() {
                w = 0.0;
            }
            if w < NODE_SNAP {
                w = 0.0;
            } else if w > 1.0 - NODE_SNAP {
                if k + 2 < ABS_NODES {
                    k += 1;
                    w = 0.0;
                } else {
                    w = 1.0;
                }
            }
            at.node[c] = k;
            at.w[c] = w;
        }
        at
    }
}

/// Finite, saturated to the f16 range, rounded to the nearest half.
fn half_bits(v: f32) -> u16 {
    let v = if v.is_finite() {
        v.clamp(-65504.0, 65504.0)
    } else {
        0.0
    };
    // The portable conversion (same bits as `from_f32`): no per-value CPU-feature check,
    // which costs an interpreter such as Miri more than the conversion itself.
    half::f16::from_f32_const(v).to_bits()
}

/// Finite and ≥ 0, else 0.
fn non_negative(v: f32) -> f32 {
    if v.is_finite() && v > 0.0 {
        v
    } else {
        0.0
    }
}

/// The node fields of `tables` at node `k`, channel `c`, for `attenuation` (unrounded).
fn node_fields(tables: &DualTables, attenuation: Attenuation, k: usize, c: usize) -> [f32; FIELDS] {
    let f = &tables.fiber[k];
    let mut out = [0.0f32; FIELDS];
    let mu = coat_decay(attenuation, f.a_f[c], f.a_b[c]);
    out[LOG2_DECAY] = if mu > 0.0 {
        libm::log2f(mu).clamp(MIN_LOG2_DECAY, 0.0)
    } else {
        MIN_LOG2_DECAY
    };
    out[BETA_F] = libm::sqrtf(non_negative(f.beta2_f[c]));
    let (back, front) = local_backscatter(attenuation, f.big_a_b[c], f.a_f[c], f.a_b[c]);
    out[BACK] = back;
    out[FRONT] = front;
    out[DELTA_B] = f.delta_b[c];
    out[SIGMA_B0] = non_negative(f.sigma_b0[c]);
    let af = non_negative(f.a_f[c]).min(1.0);
    out[A_F2] = af * af;
    for g in 0..FAMILY_COUNT {
        let m = &tables.moments[k][g];
        out[MEAN + g] = m.mean[c];
        out[SD + g] = libm::sqrtf(non_negative(m.variance[c]));
    }
    out
}

/// Writes channel `c` of `tables` as absorption node `a` of `blob` (rounded to halves).
fn put_node(
    blob: &mut [u8; BLOB_LEN],
    a: usize,
    tables: &DualTables,
    attenuation: Attenuation,
    c: usize,
) {
    let mut at = HEADER_LEN + 2 * a * NODE_HALVES;
    let mut put = |v: f32| {
        blob[at..at + 2].copy_from_slice(&half_bits(v).to_le_bytes());
        at += 2;
    };
    for k in 0..THETA_NODES {
        for v in node_fields(tables, attenuation, k, c) {
            put(v);
        }
    }
    for g in 0..FAMILY_COUNT {
        for k in 0..THETA_NODES {
            for j in 0..PHI_NODES {
                put(non_negative(tables.n_g[g][k][j][c]));
            }
        }
    }
}

/// Writes the header of a blob recording `attenuation`, `source` and the preset colour
/// `default`, then its checksum (the nodes must be written before).
fn seal(blob: &mut [u8; BLOB_LEN], attenuation: Attenuation, source: u64, default: Absorption) {
    blob[..8].copy_from_slice(&DUAL_MAGIC);
    let words = [
        DUAL_FORMAT_VERSION,
        crate::MODEL_VERSION,
        THETA_NODES as u32,
        PHI_NODES as u32,
        FAMILY_COUNT as u32,
        FIELDS as u32,
        attenuation.code(),
        ABS_NODES as u32,
    ];
    for (i, w) in words.iter().enumerate() {
        blob[8 + 4 * i..12 + 4 * i].copy_from_slice(&w.to_le_bytes());
    }
    blob[40..48].copy_from_slice(&source.to_le_bytes());
    blob[48..56].fill(0);
    for (c, v) in default.sigma().0.iter().enumerate() {
        blob[COLOUR_AT + 4 * c..COLOUR_AT + 4 * c + 4].copy_from_slice(&v.to_le_bytes());
    }
    blob[COLOUR_AT + 12..HEADER_LEN].fill(0);
    let sum = checksum_of(&blob[..]);
    blob[CHECKSUM_AT..CHECKSUM_AT + 8].copy_from_slice(&sum.to_le_bytes());
}

/// The `.furdual` blob of a BCSDF over the absorption axis (docs/model.md §13): for each node
/// a, `tables_at(σ_a, tables)` fills `tables` (a scratch buffer) with the tables of the
/// BCSDF at the grey colour σ_ca = σ_a ([`axis_node`]`(a)`), of which
/// channel 0 is stored (the node fields and N^G rounded to the nearest half, non-finite values
/// as 0, magnitudes saturated at 65504). `source` is the checksum of the LUT the tables were
/// computed from (0 for none), `default` the preset's own colour. No allocation.
pub fn encode_axis<F: FnMut(f32, &mut DualTables)>(
    blob: &mut [u8; BLOB_LEN],
    tables: &mut DualTables,
    mut tables_at: F,
    attenuation: Attenuation,
    source: u64,
    default: Absorption,
) {
    for a in 0..ABS_NODES {
        tables_at(axis_node(a), tables);
        put_node(blob, a, tables, attenuation, 0);
    }
    seal(blob, attenuation, source, default);
}

/// The preset colour [`encode`] records: channel c at absorption node c.
fn channel_nodes() -> Absorption {
    let s = Rgb([0, 1, 2].map(axis_node));
    Absorption::from_sigma(s).unwrap_or(Absorption::LOSSLESS)
}

/// A blob of one colour's RGB `tables` (computed at one fixed σ_ca, e.g. a BCSDF without a
/// LUT): channel c is stored at absorption node c (nodes 3 and up repeat channel 2), and the
/// recorded preset colour is σ_ca = ([`axis_node`] 0, 1, 2), so that [`DualLut::eval`]
/// evaluates exactly these tables per channel. Evaluating such a blob at another colour reads
/// the other channels' tables: for per-colour evaluation use [`encode_axis`]. Otherwise as
/// [`encode_axis`]. The blob is returned by value (no allocation).
#[must_use]
pub fn encode(tables: &DualTables, attenuation: Attenuation, source: u64) -> [u8; BLOB_LEN] {
    let mut blob = [0u8; BLOB_LEN];
    for a in 0..3 {
        put_node(&mut blob, a, tables, attenuation, a);
    }
    let node = |a: usize| HEADER_LEN + 2 * a * NODE_HALVES;
    for a in 3..ABS_NODES {
        blob.copy_within(node(2)..node(3), node(a));
    }
    seal(&mut blob, attenuation, source, channel_nodes());
    blob
}

/// FNV-1a 64 over every byte but the checksum field.
pub(super) fn checksum_of(blob: &[u8]) -> u64 {
    let mut copy = [0u8; HEADER_LEN];
    copy.copy_from_slice(&blob[..HEADER_LEN]);
    copy[CHECKSUM_AT..CHECKSUM_AT + 8].fill(0);
    // The header with its checksum field zeroed, then the body.
    fnv1a64_continue(fnv1a64(&copy), &blob[HEADER_LEN..])
}

fn word(bytes: &[u8], at: usize) -> u32 {
    u32::from_le_bytes([bytes[at], bytes[at + 1], bytes[at + 2], bytes[at + 3]])
}

impl DualLut {
    /// An empty evaluator (every value zero: the term is zero everywhere), to decode into.
    pub const EMPTY: DualLut = DualLut {
        attenuation: Attenuation::Coat,
        source: 0,
        default: Absorption::LOSSLESS,
        default_at: DualColour {
            node: [0; 3],
            w: [0.0; 3],
        },
        sqrt_nodes: [0.0; ABS_NODES],
        nodes: [[[0.0; FIELDS]; THETA_NODES]; ABS_NODES],
        n_g: [[[[0.0; PHI_NODES]; THETA_NODES]; FAMILY_COUNT]; ABS_NODES],
        coat: [[0.0; THETA_NODES]; ABS_NODES],
    };

    /// Reads a `.furdual` blob into `self` after checking all of it: length, magic, format and
    /// model versions, layout (the absorption axis's node count included), attenuation,
    /// checksum, the preset colour (σ_ca in [0, [`SIGMA_CA_MAX`]]), and every value (finite;
    /// log₂ μ ≤ 0; widths, energies, ā_f² ∈ [0, 1] and N^G ≥ 0). On error `self` is left as it
    /// was.
    ///
    /// # Errors
    /// The first check that fails, as a [`DualError`].
    pub fn decode(&mut self, bytes: &[u8]) -> Result<(), DualError> {
        if bytes.len() != BLOB_LEN {
            return Err(DualError::Length(bytes.len()));
        }
        if bytes[..8] != DUAL_MAGIC {
            return Err(DualError::Magic);
        }
        let version = word(bytes, 8);
        if version != DUAL_FORMAT_VERSION {
            return Err(DualError::FormatVersion(version));
        }
        let model = word(bytes, 12);
        if model != crate::MODEL_VERSION {
            return Err(DualError::ModelVersion(model));
        }
        let dims = [
            word(bytes, 16),
            word(bytes, 20),
            word(bytes, 24),
            word(bytes, 28),
            word(bytes, 36),
        ];
        let expected = [THETA_NODES, PHI_NODES, FAMILY_COUNT, FIELDS, ABS_NODES].map(|v| v as u32);
        if dims != expected
            || bytes[48..56].iter().any(|&b| b != 0)
            || bytes[COLOUR_AT + 12..HEADER_LEN].iter().any(|&b| b != 0)
        {
            return Err(DualError::Layout);
        }
        let code = word(bytes, 32);
        let Some(attenuation) = Attenuation::from_code(code) else {
            return Err(DualError::Attenuation(code));
        };
        let stored = u64::from_le_bytes(
            bytes[CHECKSUM_AT..CHECKSUM_AT + 8]
                .try_into()
                .unwrap_or([0; 8]),
        );
        if stored != checksum_of(bytes) {
            return Err(DualError::Checksum);
        }
        let colour = Rgb([0, 1, 2].map(|c| f32::from_bits(word(bytes, COLOUR_AT + 4 * c))));
        if colour
            .0
            .iter()
            .any(|&v| !(v.is_finite() && (0.0..=SIGMA_CA_MAX).contains(&v)))
        {
            return Err(DualError::Colour);
        }
        let Ok(default) = Absorption::from_sigma(colour) else {
            return Err(DualError::Colour);
        };
        let bits = |i: usize| {
            let at = HEADER_LEN + 2 * i;
            u16::from_le_bytes([bytes[at], bytes[at + 1]])
        };
        let half = |i: usize| {
            // Portable, as in `half_bits`: a blob is decoded once, not per query.
            half::f16::from_bits(bits(i)).to_f32_const()
        };
        // Check every value before writing any, on the bits (the same sets as the float
        // comparisons, without a conversion per value).
        for i in 0..ABS_NODES * NODE_HALVES {
            let within = i % NODE_HALVES;
            let range = match within % FIELDS {
                _ if within >= FIELD_HALVES => HalfRange::NonNegative,
                LOG2_DECAY => HalfRange::NonPositive,
                A_F2 => HalfRange::Unit,
                BETA_F | BACK | FRONT | SIGMA_B0 => HalfRange::NonNegative,
                f if f >= SD => HalfRange::NonNegative,
                _ => HalfRange::Finite,
            };
            if !range.holds(bits(i)) {
                return Err(DualError::Value(i));
            }
        }
        self.attenuation = attenuation;
        self.source = u64::from_le_bytes(bytes[40..48].try_into().unwrap_or([0; 8]));
        self.default = default;
        self.sqrt_nodes = sqrt_nodes();
        self.default_at = DualColour::locate(colour, &self.sqrt_nodes);
        let mut i = 0;
        for a in 0..ABS_NODES {
            for node in self.nodes[a].iter_mut() {
                for field in node.iter_mut() {
                    *field = half(i);
                    i += 1;
                }
            }
            for (node, coat) in self.nodes[a].iter().zip(self.coat[a].iter_mut()) {
                *coat = node_coat(node[LOG2_DECAY], node[A_F2]);
            }
            for family in self.n_g[a].iter_mut() {
                for row in family.iter_mut() {
                    for texel in row.iter_mut() {
                        *texel = half(i);
                        i += 1;
                    }
                }
            }
        }
        Ok(())
    }

    /// The preset's own colour recorded in the blob: what [`DualLut::eval`] evaluates.
    #[must_use]
    pub fn absorption(&self) -> Absorption {
        self.default
    }

    /// Makes `absorption` the colour [`DualLut::eval`] evaluates (a renderer that shades a
    /// whole coat at one colour other than the preset's; per query, use
    /// [`DualLut::eval_at`]).
    pub fn set_absorption(&mut self, absorption: &Absorption) {
        self.default = *absorption;
        self.default_at = self.locate(absorption);
    }

    /// `absorption` located on the blob's absorption axis, for [`DualLut::eval_located`].
    #[must_use]
    pub fn locate(&self, absorption: &Absorption) -> DualColour {
        DualColour::locate(absorption.sigma(), &self.sqrt_nodes)
    }

    /// The attenuation the blob was made for.
    #[must_use]
    pub fn attenuation(&self) -> Attenuation {
        self.attenuation
    }

    /// The checksum of the LUT the tables were computed from (0 if none was recorded): compare
    /// it with the LUT's header checksum to check a `.furdual` belongs to a `.furlut`.
    #[must_use]
    pub fn source(&self) -> u64 {
        self.source
    }

    /// Whether these tables were computed from `lut` ([`DualLut::source`] equal to
    /// [`BakedBcsdf::checksum`]): what an engine checks once after loading a `.furdual` and a
    /// `.furlut` as a pair (docs/model.md §13 "Stored tables"), so that tables left over from
    /// another bake or another preset are refused instead of shading with the wrong fur.
    ///
    /// # Errors
    /// [`DualError::Source`] when the checksums differ or the blob records no source (0).
    pub fn check_lut<M: Math>(&self, lut: &BakedBcsdf<'_, M>) -> Result<(), DualError> {
        let sum = lut.checksum();
        if self.source != 0 && self.source == sum {
            Ok(())
        } else {
            Err(DualError::Source {
                recorded: self.source,
                lut: sum,
            })
        }
    }
}
