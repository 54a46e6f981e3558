//! # bcsdf-ffi
//!
//! The C ABI of the baked fur BCSDF (`bcsdf_core::baked::BakedBcsdf`): open a LUT from
//! borrowed bytes, evaluate the far field (one direction, per family, from vectors, in
//! batches), importance-sample it and query its pdf (docs/model.md §8, §10). The header
//! `include/fur_bcsdf.h` is generated from this file by cbindgen (`tests/header.rs` checks it
//! is current).
//!
//! Rules every exported function keeps:
//! - no allocation, no global state, thread-safe for concurrent reads of one `fur_lut`;
//! - every pointer is checked (NULL, alignment) and every length; a `fur_lut` that was never
//!   opened (or was closed, or whose bytes failed validation) is refused with
//!   `FUR_ERR_NOT_OPEN`; corrupt LUT bytes are refused by `fur_lut_open` with a status naming
//!   the problem;
//! - no panic can cross the boundary: the paths below are written without panicking
//!   operations (checked conversions, `get` instead of indexing), release builds use
//!   `panic = "abort"` (workspace profile), and the C tests drive every function with bad
//!   input.
//!
//! The caller keeps the LUT bytes alive and unchanged while a `fur_lut` opened on them is in
//! use (the `fur_lut` borrows them, like `BakedBcsdf::from_bytes`).
#![cfg_attr(not(feature = "std"), no_std)]
#![allow(non_camel_case_types)]
#![deny(missing_docs)]

use bcsdf_core::baked::BakedBcsdf;
use bcsdf_core::lut::{self, LutError};
use bcsdf_core::{Angles, Bcsdf, Families, LobeFamily, Rgb, Vec3};
use core::ffi::c_char;
use core::mem::{align_of, size_of, MaybeUninit};

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
    /// The fur_lut was never opened with fur_lut_open, was closed, or its open failed.
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

/// An opened LUT: fixed-size, caller-owned storage (stack, arena, struct member), no heap.
/// Zero-initialise it or leave it uninitialised; only `fur_lut_open` makes it usable. It
/// may be copied by value once opened. Its contents are private.
#[repr(C)]
pub struct fur_lut {
    /// Opaque storage (8-byte aligned).
    pub _opaque: [u64; FUR_LUT_WORDS],
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

/// What a `fur_lut` holds: a check of the borrowed bytes' address and length, then the
/// evaluator. Plain integers come first, so an unopened `fur_lut` is recognised by reading
/// integers only.
#[repr(C)]
struct Opened {
    magic: u64,
    bytes: usize,
    len: usize,
    check: u64,
    lut: MaybeUninit<BakedBcsdf<'static>>,
}

const MAGIC: u64 = 0x4655_524c_5554_4f4b; // "FURLUTOK"

const _: () = assert!(size_of::<Opened>() <= size_of::<fur_lut>());
const _: () = assert!(align_of::<Opened>() <= align_of::<fur_lut>());

/// A 64-bit mix of the fields an opened `fur_lut` carries (SplitMix64 finaliser).
fn check_of(bytes: usize, len: usize) -> u64 {
    let mut z =
        MAGIC ^ (bytes as u64).rotate_left(17) ^ (len as u64).wrapping_mul(0x9e37_79b9_7f4a_7c15);
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

fn aligned<T>(p: *const T) -> bool {
    (p as usize).is_multiple_of(align_of::<T>())
}

fn status_of(e: &LutError) -> fur_status {
    match e {
        LutError::TooShort { .. } => fur_status::FUR_ERR_LUT_TRUNCATED,
        LutError::Length { expected, found } if found < expected => {
            fur_status::FUR_ERR_LUT_TRUNCATED
        }
        LutError::Length { .. } | LutError::BadMagic => fur_status::FUR_ERR_LUT_FORMAT,
        LutError::FormatVersion { .. } | LutError::ModelVersion { .. } => {
            fur_status::FUR_ERR_LUT_VERSION
        }
        LutError::Checksum { .. } => fur_status::FUR_ERR_LUT_CHECKSUM,
        _ => fur_status::FUR_ERR_LUT_INVALID,
    }
}

/// The evaluator inside an opened `fur_lut`, after checking the pointer and the tag.
///
/// # Safety
/// `lut` is NULL or points to `size_of::<fur_lut>()` readable bytes.
unsafe fn opened<'a>(lut: *const fur_lut) -> Result<&'a BakedBcsdf<'static>, fur_status> {
    if lut.is_null() {
        return Err(fur_status::FUR_ERR_NULL);
    }
    if !aligned(lut) {
        return Err(fur_status::FUR_ERR_ALIGNMENT);
    }
    let o = lut as *const Opened;
    // SAFETY: the caller provides a readable fur_lut, 8-aligned (checked); the first four
    // words are plain integers for any bit pattern.
    let (magic, bytes, len, check) = unsafe {
        (
            core::ptr::addr_of!((*o).magic).read(),
            core::ptr::addr_of!((*o).bytes).read(),
            core::ptr::addr_of!((*o).len).read(),
            core::ptr::addr_of!((*o).check).read(),
        )
    };
    if magic != MAGIC || check != check_of(bytes, len) {
        return Err(fur_status::FUR_ERR_NOT_OPEN);
    }
    // SAFETY: magic and check are only written together with `lut`, by fur_lut_open, after a
    // successful BakedBcsdf::from_bytes (a random match is a 2^-128 event).
    Ok(unsafe { (*core::ptr::addr_of!((*o).lut)).assume_init_ref() })
}

/// Writes `v` to `out` (3 floats).
///
/// # Safety
/// `out` is non-NULL, 4-aligned and points to 3 writable floats.
unsafe fn write3(out: *mut f32, v: [f32; 3]) {
    for (i, c) in v.into_iter().enumerate() {
        // SAFETY: the caller guarantees 3 writable floats.
        unsafe { out.add(i).write(c) };
    }
}

fn check_out(out: *mut f32) -> Result<(), fur_status> {
    if out.is_null() {
        Err(fur_status::FUR_ERR_NULL)
    } else if !aligned(out) {
        Err(fur_status::FUR_ERR_ALIGNMENT)
    } else {
        Ok(())
    }
}

/// Reads 3 floats from `p`, checking NULL and alignment.
///
/// # Safety
/// `p` is NULL or points to 3 readable floats.
unsafe fn read3(p: *const f32) -> Result<Vec3, fur_status> {
    if p.is_null() {
        return Err(fur_status::FUR_ERR_NULL);
    }
    if !aligned(p) {
        return Err(fur_status::FUR_ERR_ALIGNMENT);
    }
    // SAFETY: the caller guarantees 3 readable floats.
    Ok(unsafe { [p.read(), p.add(1).read(), p.add(2).read()] })
}

macro_rules! tri {
    ($e:expr) => {
        match $e {
            Ok(v) => v,
            Err(s) => return s,
        }
    };
}

/// Validates `len` bytes at `bytes` as a baked LUT (header, versions, lengths, checksum,
/// every value, the sampling data: one pass over the bytes) and opens `*out` on them. The bytes are
/// borrowed: keep them alive and unchanged while `*out` is used. On failure `*out` is left
/// closed and the status names the problem.
///
/// # Safety
/// `bytes` is NULL or points to `len` readable bytes; `out` is NULL or points to a writable
/// `fur_lut`.
#[no_mangle]
pub unsafe extern "C" fn fur_lut_open(
    bytes: *const u8,
    len: usize,
    out: *mut fur_lut,
) -> fur_status {
    if out.is_null() {
        return fur_status::FUR_ERR_NULL;
    }
    if !aligned(out) {
        return fur_status::FUR_ERR_ALIGNMENT;
    }
    let o = out as *mut Opened;
    // SAFETY: out is a writable, aligned fur_lut; closing it first means a failed open never
    // leaves a previously opened fur_lut pointing at other bytes.
    unsafe { core::ptr::addr_of_mut!((*o).magic).write(0) };
    if bytes.is_null() {
        return fur_status::FUR_ERR_NULL;
    }
    if len == 0 {
        return fur_status::FUR_ERR_LENGTH;
    }
    // SAFETY: the caller guarantees `len` readable bytes that outlive the fur_lut.
    let slice: &'static [u8] = unsafe { core::slice::from_raw_parts(bytes, len) };
    let lut = match BakedBcsdf::from_bytes(slice) {
        Ok(l) => l,
        Err(e) => return status_of(&e),
    };
    // SAFETY: out is writable and aligned (checked above); Opened fits in fur_lut (static
    // assertions).
    unsafe {
        o.write(Opened {
            magic: MAGIC,
            bytes: bytes as usize,
            len,
            check: check_of(bytes as usize, len),
            lut: MaybeUninit::new(lut),
        });
    }
    fur_status::FUR_OK
}

/// Closes `*lut` (it holds no resources; later calls with it return `FUR_ERR_NOT_OPEN`).
///
/// # Safety
/// `lut` is NULL or points to a writable `fur_lut`.
#[no_mangle]
pub unsafe extern "C" fn fur_lut_close(lut: *mut fur_lut) -> fur_status {
    if lut.is_null() {
        return fur_status::FUR_ERR_NULL;
    }
    if !aligned(lut) {
        return fur_status::FUR_ERR_ALIGNMENT;
    }
    // SAFETY: writable and aligned (checked).
    unsafe { core::ptr::addr_of_mut!((*(lut as *mut Opened)).magic).write(0) };
    fur_status::FUR_OK
}

fn angles(theta_i: f32, theta_r: f32, phi: f32) -> Result<Angles, fur_status> {
    Angles::new(theta_i, theta_r, phi).map_err(|_| fur_status::FUR_ERR_ANGLE)
}

/// Far-field S(omega_i, omega_r), RGB, into `out_rgb[3]` (0 and `FUR_ERR_ANGLE` for invalid
/// angles).
///
/// # Safety
/// `lut` is NULL or points to a `fur_lut`; `out_rgb` is NULL or points to 3 writable floats.
#[no_mangle]
pub unsafe extern "C" fn fur_eval_far(
    lut: *const fur_lut,
    theta_i: f32,
    theta_r: f32,
    phi: f32,
    out_rgb: *mut f32,
) -> fur_status {
    // SAFETY: forwarded caller guarantees.
    let l = tri!(unsafe { opened(lut) });
    tri!(check_out(out_rgb));
    let (v, status) = match angles(theta_i, theta_r, phi) {
        Ok(a) => (l.eval_far(&a).total().0, fur_status::FUR_OK),
        Err(s) => ([0.0; 3], s),
    };
    // SAFETY: checked non-NULL and aligned; the caller provides 3 floats.
    unsafe { write3(out_rgb, v) };
    status
}

/// Far-field S per lobe family into `out[12]`: R, TT, TRT, scattered, RGB each.
///
/// # Safety
/// `lut` is NULL or points to a `fur_lut`; `out` is NULL or points to 12 writable floats.
#[no_mangle]
pub unsafe extern "C" fn fur_eval_far_families(
    lut: *const fur_lut,
    theta_i: f32,
    theta_r: f32,
    phi: f32,
    out: *mut f32,
) -> fur_status {
    // SAFETY: forwarded caller guarantees.
    let l = tri!(unsafe { opened(lut) });
    tri!(check_out(out));
    let (f, status) = match angles(theta_i, theta_r, phi) {
        Ok(a) => (l.eval_far(&a), fur_status::FUR_OK),
        Err(s) => (Families::ZERO, s),
    };
    for (k, v) in f.as_array().iter().enumerate() {
        // SAFETY: 12 floats: 4 families × 3 channels.
        unsafe { write3(out.add(3 * k), v.0) };
    }
    status
}

/// Far-field S from world-space vectors: `wi` toward the light, `wr` toward the viewer,
/// `tangent` the fiber direction (none needs unit length), into `out_rgb[3]`.
///
/// # Safety
/// `lut` is NULL or points to a `fur_lut`; each vector is NULL or points to 3 readable
/// floats; `out_rgb` is NULL or points to 3 writable floats.
#[no_mangle]
pub unsafe extern "C" fn fur_eval_far_dirs(
    lut: *const fur_lut,
    wi: *const f32,
    wr: *const f32,
    tangent: *const f32,
    out_rgb: *mut f32,
) -> fur_status {
    // SAFETY: forwarded caller guarantees.
    let l = tri!(unsafe { opened(lut) });
    tri!(check_out(out_rgb));
    // SAFETY (three blocks): forwarded caller guarantees.
    let wi = tri!(unsafe { read3(wi) });
    let wr = tri!(unsafe { read3(wr) });
    let t = tri!(unsafe { read3(tangent) });
    let (v, status) = match l.try_eval_far_dirs(wi, wr, t) {
        Ok(f) => (f.total().0, fur_status::FUR_OK),
        Err(_) => ([0.0; 3], fur_status::FUR_ERR_DIRECTION),
    };
    // SAFETY: checked non-NULL and aligned.
    unsafe { write3(out_rgb, v) };
    status
}

/// `n` far-field evaluations, structure of arrays in (`theta_i[n]`, `theta_r[n]`, `phi[n]`),
/// `out_rgb[3n]` out. `n` = 0 does nothing (any pointers). An invalid angle gives 0 for its
/// entry and the call returns `FUR_ERR_ANGLE` after evaluating every other entry.
///
/// # Safety
/// For n > 0: the three input pointers are NULL or point to `n` readable floats each, and
/// `out_rgb` is NULL or points to `3n` writable floats.
#[no_mangle]
pub unsafe extern "C" fn fur_eval_far_batch(
    lut: *const fur_lut,
    n: usize,
    theta_i: *const f32,
    theta_r: *const f32,
    phi: *const f32,
    out_rgb: *mut f32,
) -> fur_status {
    // SAFETY: forwarded caller guarantees.
    let l = tri!(unsafe { opened(lut) });
    if n == 0 {
        return fur_status::FUR_OK;
    }
    if n.checked_mul(3).is_none() {
        return fur_status::FUR_ERR_LENGTH;
    }
    for p in [theta_i, theta_r, phi] {
        if p.is_null() {
            return fur_status::FUR_ERR_NULL;
        }
        if !aligned(p) {
            return fur_status::FUR_ERR_ALIGNMENT;
        }
    }
    tri!(check_out(out_rgb));
    // SAFETY: the caller guarantees n readable floats each and 3n writable ones; the
    // pointers are non-NULL and aligned (checked).
    let (ti, tr, ph) = unsafe {
        (
            core::slice::from_raw_parts(theta_i, n),
            core::slice::from_raw_parts(theta_r, n),
            core::slice::from_raw_parts(phi, n),
        )
    };
    // SAFETY: as above; `Rgb` is `repr(transparent)` over `[f32; 3]`, so 3n floats are n
    // `Rgb`s (alignment 4, checked).
    let out = unsafe { core::slice::from_raw_parts_mut(out_rgb.cast::<Rgb>(), n) };
    // The batch path (SIMD over the queries, bit-identical to fur_eval_far per entry).
    match l.eval_far_batch(ti, tr, ph, out) {
        Ok(0) => fur_status::FUR_OK,
        Ok(_) => fur_status::FUR_ERR_ANGLE,
        // Unreachable: all four slices have length n.
        Err(_) => fur_status::FUR_ERR_LENGTH,
    }
}

/// Importance-samples omega_i given theta_r from three uniform numbers in [0, 1) (values
/// outside are clamped) into `*out` (docs/model.md section 10).
///
/// # Safety
/// `lut` is NULL or points to a `fur_lut`; `out` is NULL or points to a writable
/// `fur_sample`.
#[no_mangle]
pub unsafe extern "C" fn fur_sample_far(
    lut: *const fur_lut,
    theta_r: f32,
    u0: f32,
    u1: f32,
    u2: f32,
    out: *mut fur_sample,
) -> fur_status {
    // SAFETY: forwarded caller guarantees.
    let l = tri!(unsafe { opened(lut) });
    if out.is_null() {
        return fur_status::FUR_ERR_NULL;
    }
    if !aligned(out) {
        return fur_status::FUR_ERR_ALIGNMENT;
    }
    if !(theta_r.is_finite() && theta_r.abs() <= core::f32::consts::FRAC_PI_2) {
        return fur_status::FUR_ERR_ANGLE;
    }
    let Some(s) = l.sample(theta_r, [u0, u1, u2]) else {
        return fur_status::FUR_ERR_NO_SAMPLE;
    };
    let family = match s.family {
        LobeFamily::R => fur_family::FUR_FAMILY_R,
        LobeFamily::TT => fur_family::FUR_FAMILY_TT,
        LobeFamily::TRT => fur_family::FUR_FAMILY_TRT,
        LobeFamily::Scattered => fur_family::FUR_FAMILY_SCATTERED,
    };
    // SAFETY: writable and aligned (checked).
    unsafe {
        out.write(fur_sample {
            theta_i: s.angles.theta_i(),
            phi: s.angles.phi(),
            pdf: s.pdf,
            weight: s.weight.0,
            family,
        })
    };
    fur_status::FUR_OK
}

/// Density per unit solid angle with which `fur_sample_far` draws omega_i given omega_r; 0
/// for invalid arguments (NULL or unopened `lut`, invalid angles).
///
/// # Safety
/// `lut` is NULL or points to a `fur_lut`.
#[no_mangle]
pub unsafe extern "C" fn fur_pdf_far(
    lut: *const fur_lut,
    theta_i: f32,
    theta_r: f32,
    phi: f32,
) -> f32 {
    // SAFETY: forwarded caller guarantees.
    match (unsafe { opened(lut) }, angles(theta_i, theta_r, phi)) {
        (Ok(l), Ok(a)) => l.pdf(&a),
        _ => 0.0,
    }
}

/// A static, NUL-terminated English description of a status (any value: unknown ones get
/// "unknown status"). Takes the status as an integer so that any value is safe to pass.
#[no_mangle]
pub extern "C" fn fur_status_str(status: i32) -> *const c_char {
    let s: &'static [u8] = match status {
        0 => b"ok\0",
        1 => b"a required pointer argument is NULL\0",
        2 => b"a pointer argument is misaligned for its type\0",
        3 => b"a length is zero where data is required, or too large\0",
        4 => b"the fur_lut is not open (never opened, closed, or its open failed)\0",
        5 => b"the LUT bytes are truncated\0",
        6 => b"the bytes are not a fur LUT (bad magic or trailing data)\0",
        7 => b"the LUT was baked by another format or model version: re-bake it\0",
        8 => b"the LUT checksum does not match: the data was changed after baking\0",
        9 => b"the LUT header or data is invalid\0",
        10 => b"an angle is not finite or theta is outside [-pi/2, pi/2]\0",
        11 => b"a direction or the tangent is not finite or has zero length\0",
        12 => b"nothing can be sampled at this view angle (zero BCSDF)\0",
        _ => b"unknown status\0",
    };
    s.as_ptr().cast()
}

/// This library's version as a static NUL-terminated string, e.g. "0.1.0".
#[no_mangle]
pub extern "C" fn fur_version() -> *const c_char {
    concat!(env!("CARGO_PKG_VERSION"), "\0").as_ptr().cast()
}

/// The LUT format version this library reads (a LUT of another version is refused with
/// `FUR_ERR_LUT_VERSION`).
#[no_mangle]
pub extern "C" fn fur_lut_format_version() -> u32 {
    lut::FORMAT_VERSION
}

/// The model version this library's LUTs must be baked with.
#[no_mangle]
pub extern "C" fn fur_model_version() -> u32 {
    bcsdf_core::MODEL_VERSION
}

/// The unwinding personality the precompiled `core` refers to. Without std nothing unwinds
/// (release builds abort on panic), so it is never called; it only lets a C linker resolve
/// the reference.
#[cfg(all(not(feature = "std"), not(test)))]
#[no_mangle]
pub extern "C" fn rust_eh_personality() {}

#[cfg(all(not(feature = "std"), not(test)))]
#[panic_handler]
fn panic(_: &core::panic::PanicInfo<'_>) -> ! {
    // Unreachable by construction (see the crate documentation); spinning rather than
    // returning keeps the signature honest without std's abort.
    loop {}
}
