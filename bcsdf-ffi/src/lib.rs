//! # bcsdf-ffi
//!
//! The C ABI of the baked fur BCSDF (`bcsdf_core::baked::BakedBcsdf`): open a LUT from
//! borrowed bytes, evaluate the far field (one direction, per family, from vectors, in
//! batches), importance-sample it and query its pdf (docs/model.md §8, §10), at the LUT's own
//! colour or, through the `_at` functions, at any cortex absorption σ_ca per RGB channel
//! (LUT format 5, docs/lut.md "The absorption axis"; `eval.rs`, `colour.rs`). The header
//! `include/fur_bcsdf.h` is generated from this file by cbindgen (`tests/header.rs` checks it
//! is current). A `fur_dual`, decoded from a `.furdual` blob, evaluates the dual-scattering
//! term added to single scattering behind other fibers (docs/model.md §13, `dual.rs`).
//!
//! Rules every exported function keeps:
//! - no allocation, no global state, thread-safe for concurrent reads of one `fur_lut`;
//! - every pointer is checked (NULL, alignment) and every length; an output buffer that
//!   overlaps another argument's buffer, the `fur_lut` or the LUT bytes is refused with
//!   `FUR_ERR_OVERLAP` (so that the Rust side never holds a shared and a mutable reference
//!   to the same memory); a zeroed (`FUR_LUT_INIT`) or closed `fur_lut`, or one whose open
//!   failed, is refused with `FUR_ERR_NOT_OPEN`, one opened by another build of this library
//!   with `FUR_ERR_OTHER_BUILD`; corrupt LUT bytes are refused by `fur_lut_open` with a
//!   status naming the problem;
//! - no panic can cross the boundary: the paths below are written without panicking
//!   operations (checked conversions, `get` instead of indexing), a panic that reached an
//!   `extern "C"` function would abort (Rust ≥ 1.81), the no_std build (the workspace's
//!   `nostd` profile, `panic = "abort"`) has no unwinding and its panic handler traps
//!   (`nostd.rs`), and the C tests drive every function with bad input.
//!
//! The contract the caller keeps (the header says it at `fur_lut`): a `fur_lut` is
//! initialised (`FUR_LUT_INIT`, or opened) before any call reads it; the LUT bytes stay alive
//! and unchanged until `fur_lut_close` (the `fur_lut` borrows them, like
//! `BakedBcsdf::from_bytes`). No check can tell uninitialised storage, or storage whose bytes
//! were freed without a close, from an open `fur_lut`: those are the caller's errors, as with
//! any C handle.
#![deny(clippy::undocumented_unsafe_blocks)]
#![cfg_attr(not(feature = "std"), no_std)]
#![allow(non_camel_case_types)]
#![deny(missing_docs)]

/// `return` the status of an `Err`.
macro_rules! tri {
    ($e:expr) => {
        match $e {
            Ok(v) => v,
            Err(s) => return s,
        }
    };
}

// cbindgen writes the functions file by file in path order: colour, dual, eval, handle, info.
mod args;
mod coat;
mod colour;
mod dual;
mod eval;
mod handle;
mod info;
mod nostd;
mod sample;

pub use coat::{fur_absorption_from_colour, fur_coat, fur_coat_measure, FUR_COAT_NODES};
pub use colour::{fur_lut_sigma_ca, fur_sigma_from_melanin};
pub use dual::{
    fur_dual_below_at_incidence, fur_dual_close, fur_dual_forward_density_at_incidence,
    fur_dual_open, fur_eval_dual, fur_eval_dual_dirs,
};
pub use eval::{
    fur_eval_far, fur_eval_far_at, fur_eval_far_batch, fur_eval_far_batch_at, fur_eval_far_dirs,
    fur_eval_far_dirs_at, fur_eval_far_families, fur_eval_far_families_at,
};
pub use handle::{fur_lut_close, fur_lut_open};
pub use info::{fur_lut_format_version, fur_model_version, fur_status_str, fur_version};
pub use sample::{
    fur_pdf_far, fur_pdf_far_at, fur_sample_far, fur_sample_far_at, fur_sample_pdf_far,
    fur_sample_pdf_far_at,
};

/// Status of a call; `FUR_OK` (0) is success. `fur_status_str` describes each.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum fur_status {
    /// Success.
    FUR_OK = 0,
    /// A required pointer argument is NULL.
    FUR_ERR_NULL = 1,
    /// A pointer argument is not aligned for its type (fur_lut: 8 bytes, float: 4).
    FUR_ERR_ALIGNMENT = 2,
    /// A length is zero where data is required, or 3*n overflows size_t.
    FUR_ERR_LENGTH = 3,
    /// The fur_lut (or fur_dual) is not open: zeroed (`FUR_LUT_INIT`, `FUR_DUAL_INIT`),
    /// closed, or its open failed.
    FUR_ERR_NOT_OPEN = 4,
    /// The LUT bytes are shorter than their header says (or than a header).
    FUR_ERR_LUT_TRUNCATED = 5,
    /// The bytes are not a fur LUT (bad magic) or have trailing data.
    FUR_ERR_LUT_FORMAT = 6,
    /// The LUT was made by another format or model version: re-bake it.
    FUR_ERR_LUT_VERSION = 7,
    /// The LUT checksum does not match its bytes: the data was changed after baking.
    FUR_ERR_LUT_CHECKSUM = 8,
    /// The LUT header or data is invalid (axes, scales, parameters, values, sampling data).
    FUR_ERR_LUT_INVALID = 9,
    /// An angle is NaN, infinite, or theta is outside [-pi/2, pi/2]; the outputs for it are 0.
    FUR_ERR_ANGLE = 10,
    /// A direction or the tangent is NaN, infinite or of zero length; the output is 0.
    FUR_ERR_DIRECTION = 11,
    /// Nothing can be sampled at this view angle (the BCSDF is zero there).
    FUR_ERR_NO_SAMPLE = 12,
    /// The fur_lut (or fur_dual) was opened by another build of this library (another
    /// version, compiler or target): it is only meaningful in the process and build that
    /// opened it.
    FUR_ERR_OTHER_BUILD = 13,
    /// An output buffer overlaps an input buffer, the fur_lut or the LUT bytes (or the
    /// fur_dual, or the .furdual bytes being opened); nothing was written.
    FUR_ERR_OVERLAP = 14,
    /// The .furdual bytes are not `FUR_DUAL_BLOB_LEN` long (truncated, or trailing data).
    FUR_ERR_DUAL_LENGTH = 15,
    /// The bytes are not a .furdual blob (bad magic).
    FUR_ERR_DUAL_FORMAT = 16,
    /// The .furdual blob was made by another format or model version: recompute it (bake).
    FUR_ERR_DUAL_VERSION = 17,
    /// The .furdual checksum does not match its bytes: the data was changed after baking.
    FUR_ERR_DUAL_CHECKSUM = 18,
    /// The .furdual blob has another table layout, an unknown attenuation, or an invalid
    /// value (infinite, NaN or out of its range).
    FUR_ERR_DUAL_INVALID = 19,
    /// The fur_dual was not computed from the LUT it is checked against
    /// (`fur_dual_check_lut`): its .furdual blob records another LUT's checksum, or none.
    FUR_ERR_DUAL_SOURCE = 20,
    /// A colour is invalid: a sigma_ca channel (or a melanin concentration) is NaN or
    /// negative (valid sigma_ca: [0, 1000] per fiber radius; larger values are clamped to
    /// 1000); the outputs for it are 0.
    FUR_ERR_COLOUR = 21,
    /// A base colour is invalid (`fur_absorption_from_colour`): a channel is NaN or outside
    /// [0, 1] (linear RGB); the outputs are not written.
    FUR_ERR_BASE_COLOUR = 22,
    /// A `fur_coat` table is invalid: a value is NaN, outside [0, 1] or above the one before
    /// it; the outputs are not written.
    FUR_ERR_COAT_TABLE = 23,
}

/// The lobe family a sample was drawn from (docs/model.md sections 5, 6).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum fur_family {
    /// R: reflection off the cuticle.
    FUR_FAMILY_R = 0,
    /// TT and the medulla paths that cross the cuticle twice (TrT, TttT, TtrtT).
    FUR_FAMILY_TT = 1,
    /// TRT and the medulla paths with one internal cuticle reflection (TrRrT, TttRttT).
    FUR_FAMILY_TRT = 2,
    /// The light scattered inside the medulla.
    FUR_FAMILY_SCATTERED = 3,
}

/// 64-bit words of storage in a `fur_lut`.
pub const FUR_LUT_WORDS: usize = 256;

/// A closed `fur_lut` (all zeroes), for Rust callers; C and C++ use the header's
/// `FUR_LUT_INIT` initialiser, the same bits.
pub const FUR_LUT_INIT: fur_lut = fur_lut {
    _opaque: [0; FUR_LUT_WORDS],
};

/// An opened LUT (docs/model.md §8): fixed-size, caller-owned storage (stack, arena, struct
/// member), no heap. Its contents are private, and only meaningful in the process and the
/// build of this library that opened it (another build's is refused with
/// `FUR_ERR_OTHER_BUILD`).
///
/// The contract, as for any C handle:
/// 1. Initialise before use: `fur_lut l = FUR_LUT_INIT;` (zeroes), or open it at once.
///    `fur_lut_open` accepts uninitialised storage; every other function reads it, and
///    refuses a zeroed one with `FUR_ERR_NOT_OPEN`.
/// 2. Open before use: `fur_lut_open(bytes, len, &l)` borrows the bytes.
/// 3. Close before you free (or change) the bytes: `fur_lut_close(&l)` zeroes `l`, after which
///    every call with it returns `FUR_ERR_NOT_OPEN` without reading anything else. A copy
///    made by value is another open handle on the same bytes: close it too.
///
/// A `fur_lut` whose bytes were freed without a close, or uninitialised storage, is the
/// caller's error: no check can tell either from an open `fur_lut`, and using it reads freed
/// or arbitrary memory.
#[repr(C)]
pub struct fur_lut {
    /// Opaque storage (8-byte aligned).
    pub _opaque: [u64; FUR_LUT_WORDS],
}

/// 64-bit words of storage in a `fur_dual` (600 000 bytes, about 586 KiB: the tables of the
/// 16 nodes of the absorption axis).
pub const FUR_DUAL_WORDS: usize = 75_000;

/// Length in bytes of every `.furdual` blob `fur_dual_open` accepts.
pub const FUR_DUAL_BLOB_LEN: usize = 292_944;

/// A closed `fur_dual` (all zeroes), for Rust callers; C and C++ use the header's
/// `FUR_DUAL_INIT` initialiser (or zeroed memory: `calloc`), the same bits.
pub const FUR_DUAL_INIT: fur_dual = fur_dual {
    _opaque: [0; FUR_DUAL_WORDS],
};

/// Decoded dual-scattering tables (docs/model.md §13): fixed-size, caller-owned storage of
/// `FUR_DUAL_WORDS` 64-bit words (600 000 bytes, about 586 KiB: allocate it on the heap, e.g.
/// `calloc(1, sizeof(fur_dual))`, or in static storage, rather than on a thread's stack).
/// Its contents are private, and only meaningful in the process and the build of this
/// library that opened it (another build's is refused with `FUR_ERR_OTHER_BUILD`).
///
/// The contract:
/// 1. Initialise before use: zeroed memory (`calloc`, or `FUR_DUAL_INIT`), or open it at once.
///    `fur_dual_open` accepts uninitialised storage; every other function reads it, and
///    refuses a zeroed one with `FUR_ERR_NOT_OPEN`.
/// 2. Open: `fur_dual_open(bytes, len, d)` decodes the `.furdual` blob into `*d`. Unlike
///    `fur_lut_open`, nothing is borrowed: the bytes may be freed as soon as it returns.
/// 3. Close when done: `fur_dual_close(d)` zeroes it, after which every call with it returns
///    `FUR_ERR_NOT_OPEN`; then free the storage. A copy made by value (memcpy) is another
///    open `fur_dual`, independent of the first.
///
/// Do not write to a `fur_dual` (open, close, or otherwise) while another thread evaluates
/// with it; concurrent evaluations with one open `fur_dual` are fine.
#[repr(C)]
pub struct fur_dual {
    /// Opaque storage (8-byte aligned).
    pub _opaque: [u64; FUR_DUAL_WORDS],
}

/// One importance sample (docs/model.md section 10), written by `fur_sample_far`.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct fur_sample {
    /// Sampled theta_i (radians).
    pub theta_i: f32,
    /// Sampled phi = phi_r - phi_i (radians, in (-pi, pi]).
    pub phi: f32,
    /// Density of omega_i per unit solid angle (what fur_pdf_far returns for it).
    pub pdf: f32,
    /// S * cos(theta_i) / pdf, RGB.
    pub weight: [f32; 3],
    /// The lobe family the sample was drawn from.
    pub family: fur_family,
}
