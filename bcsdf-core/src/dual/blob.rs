//! The `.furdual` blob (docs/model.md §13, "Stored tables"): what [`DualLut::eval`] reads at
//! each θ node, derived from [`DualTables`] for one [`Attenuation`], as little-endian f16.
//!
//! Layout ([`BLOB_LEN`] = 54 976 bytes):
//!
//! | bytes | content |
//! |---|---|
//! | 0..8 | [`DUAL_MAGIC`] |
//! | 8..12 | [`DUAL_FORMAT_VERSION`] (u32) |
//! | 12..16 | [`crate::MODEL_VERSION`] of the model the tables came from (u32) |
//! | 16..32 | θ nodes (64), φ nodes (32), families (4), fields per node ([`FIELDS`] = 15), u32 each |
//! | 32..36 | [`Attenuation::code`] (u32) |
//! | 36..40 | zero |
//! | 40..48 | source: the checksum of the LUT the tables were computed from, 0 if none (u64) |
//! | 48..56 | zero |
//! | 56..64 | FNV-1a 64 of every other byte (u64) |
//! | 64.. | fields, [θ node k][field f][channel c] (64 × 15 × 3 halves) |
//! | then | N^G, [family g][θ node k][φ node j][channel c] (4 × 64 × 32 × 3 halves) |
//!
//! The fields of a node ([`FIELDS`], in this order): log₂ μ (the downward flux's decay per
//! fiber, [`super::coat_decay`]), β_f (the forward spread's width per fiber, rad), the local
//! backscatter's energy toward the back half and the front half ([`super::local_backscatter`]),
//! Δ_b, σ_b0, ā_f², then each family's mean of x and its standard deviation (rad). Widths are
//! stored as standard deviations, not variances: the narrowest (0.1°) stays a normal half.

use super::coat::node_coat;
use super::{coat_decay, local_backscatter, Attenuation, DualTables, PHI_NODES, THETA_NODES};
use crate::baked::BakedBcsdf;
use crate::lobes::FAMILY_COUNT;
use crate::lut::{fnv1a64, fnv1a64_continue};
use crate::math::Math;
use core::fmt;

/// The first eight bytes of a `.furdual` blob.
pub const DUAL_MAGIC: [u8; 8] = *b"FURDUAL\0";
/// The blob format this build reads and writes.
pub const DUAL_FORMAT_VERSION: u32 = 1;
/// Quantities stored per θ node and channel.
pub const FIELDS: usize = 7 + 2 * FAMILY_COUNT;

const HEADER_LEN: usize = 64;
const CHECKSUM_AT: usize = 56;
const FIELD_HALVES: usize = THETA_NODES * FIELDS * 3;
const NG_HALVES: usize = FAMILY_COUNT * THETA_NODES * PHI_NODES * 3;
/// Length of every `.furdual` blob in bytes.
pub const BLOB_LEN: usize = HEADER_LEN + 2 * (FIELD_HALVES + NG_HALVES);
// The dual-scattering storage budget (docs/model.md §13): at most 64 KB per preset.
const _: () = assert!(BLOB_LEN <= 64 * 1024);

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
/// Indices within a node of [`DualLut`]'s derived coat quantities: ρ² and rρ.
pub(super) const RHO2: usize = 0;
pub(super) const R_RHO: usize = 1;

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

/// The quantities [`DualLut::eval`] reads (docs/model.md §13), decoded to f32, channels in
/// lanes 0–2 of four (lane 3 zero). About 146 KB; fixed size, no allocation. Only
/// [`DualLut::decode`] fills it, so every value is finite and within its field's range.
#[derive(Clone, Debug, PartialEq)]
pub struct DualLut {
    pub(super) attenuation: Attenuation,
    pub(super) source: u64,
    pub(super) nodes: [[[f32; 4]; FIELDS]; THETA_NODES],
    pub(super) n_g: [[[[f32; 4]; PHI_NODES]; THETA_NODES]; FAMILY_COUNT],
    /// (ρ², rρ) of the coat at each θ node ([`super::coat::node_coat`]), derived at decode.
    pub(super) coat: [[[f32; 4]; 2]; THETA_NODES],
}

/// Finite, saturated to the f16 range, rounded to the nearest half.
fn half_bits(v: f32) -> u16 {
    let v = if v.is_finite() {
        v.clamp(-65504.0, 65504.0)
    } else {
        0.0
    };
    half::f16::from_f32(v).to_bits()
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

/// The `.furdual` blob of `tables` for `attenuation` (docs/model.md §13): the node fields and
/// N^G rounded to the nearest half (non-finite values as 0, magnitudes saturated at 65504),
/// `source` the checksum of the LUT the tables were computed from (0 for none). No
/// allocation (the blob is returned by value).
#[must_use]
pub fn encode(tables: &DualTables, attenuation: Attenuation, source: u64) -> [u8; BLOB_LEN] {
    let mut blob = [0u8; BLOB_LEN];
    blob[..8].copy_from_slice(&DUAL_MAGIC);
    let words = [
        DUAL_FORMAT_VERSION,
        crate::MODEL_VERSION,
        THETA_NODES as u32,
        PHI_NODES as u32,
        FAMILY_COUNT as u32,
        FIELDS as u32,
        attenuation.code(),
    ];
    for (i, w) in words.iter().enumerate() {
        blob[8 + 4 * i..12 + 4 * i].copy_from_slice(&w.to_le_bytes());
    }
    blob[40..48].copy_from_slice(&source.to_le_bytes());
    let mut at = HEADER_LEN;
    let mut put = |v: f32| {
        blob[at..at + 2].copy_from_slice(&half_bits(v).to_le_bytes());
        at += 2;
    };
    for k in 0..THETA_NODES {
        let per_channel = [0, 1, 2].map(|c| node_fields(tables, attenuation, k, c));
        for f in 0..FIELDS {
            for fields in &per_channel {
                put(fields[f]);
            }
        }
    }
    for g in 0..FAMILY_COUNT {
        for k in 0..THETA_NODES {
            for j in 0..PHI_NODES {
                for c in 0..3 {
                    put(non_negative(tables.n_g[g][k][j][c]));
                }
            }
        }
    }
    let sum = checksum_of(&blob);
    blob[CHECKSUM_AT..HEADER_LEN].copy_from_slice(&sum.to_le_bytes());
    blob
}

/// FNV-1a 64 over every byte but the checksum field.
pub(super) fn checksum_of(blob: &[u8]) -> u64 {
    let mut copy = [0u8; HEADER_LEN];
    copy.copy_from_slice(&blob[..HEADER_LEN]);
    copy[CHECKSUM_AT..].fill(0);
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
        nodes: [[[0.0; 4]; FIELDS]; THETA_NODES],
        n_g: [[[[0.0; 4]; PHI_NODES]; THETA_NODES]; FAMILY_COUNT],
        coat: [[[0.0; 4]; 2]; THETA_NODES],
    };

    /// Reads a `.furdual` blob into `self` after checking all of it: length, magic, format and
    /// model versions, layout, attenuation, checksum, and every value (finite; log₂ μ ≤ 0;
    /// widths, energies, ā_f² ∈ [0, 1] and N^G ≥ 0). On error `self` is left as it was.
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
        ];
        let expected = [THETA_NODES, PHI_NODES, FAMILY_COUNT, FIELDS].map(|v| v as u32);
        if dims != expected || word(bytes, 36) != 0 || bytes[48..56].iter().any(|&b| b != 0) {
            return Err(DualError::Layout);
        }
        let code = word(bytes, 32);
        let Some(attenuation) = Attenuation::from_code(code) else {
            return Err(DualError::Attenuation(code));
        };
        let stored =
            u64::from_le_bytes(bytes[CHECKSUM_AT..HEADER_LEN].try_into().unwrap_or([0; 8]));
        if stored != checksum_of(bytes) {
            return Err(DualError::Checksum);
        }
        let half = |i: usize| {
            let at = HEADER_LEN + 2 * i;
            half::f16::from_bits(u16::from_le_bytes([bytes[at], bytes[at + 1]])).to_f32()
        };
        // Check every value before writing any.
        for i in 0..FIELD_HALVES + NG_HALVES {
            let v = half(i);
            let ok = v.is_finite()
                && if i >= FIELD_HALVES {
                    v >= 0.0
                } else {
                    match (i / 3) % FIELDS {
                        LOG2_DECAY => v <= 0.0,
                        A_F2 => (0.0..=1.0).contains(&v),
                        BETA_F | BACK | FRONT | SIGMA_B0 => v >= 0.0,
                        f if f >= SD => v >= 0.0,
                        _ => true,
                    }
                };
            if !ok {
                return Err(DualError::Value(i));
            }
        }
        self.attenuation = attenuation;
        self.source = u64::from_le_bytes(bytes[40..48].try_into().unwrap_or([0; 8]));
        let mut i = 0;
        for node in self.nodes.iter_mut() {
            for field in node.iter_mut() {
                for lane in field.iter_mut().take(3) {
                    *lane = half(i);
                    i += 1;
                }
                field[3] = 0.0;
            }
        }
        for (node, coat) in self.nodes.iter().zip(self.coat.iter_mut()) {
            for c in 0..4 {
                let (rho2, r_rho) = node_coat(node[LOG2_DECAY][c], node[A_F2][c]);
                coat[RHO2][c] = rho2;
                coat[R_RHO][c] = r_rho;
            }
        }
        for family in self.n_g.iter_mut() {
            for row in family.iter_mut() {
                for texel in row.iter_mut() {
                    for lane in texel.iter_mut().take(3) {
                        *lane = half(i);
                        i += 1;
                    }
                    texel[3] = 0.0;
                }
            }
        }
        Ok(())
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
