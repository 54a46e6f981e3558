//! What a status means and which versions this library is (docs/model.md §8: the format
//! and model versions a LUT must carry).

use bcsdf_core::lut;
use core::ffi::c_char;

/// A static, NUL-terminated English description of a status (any value: unknown ones get
/// "unknown status"). Takes the status as an integer so that any value is safe to pass.
/// Never NULL (a reference on the Rust side, so the header's pointer carries no
/// `FUR_RESTRICT`).
#[no_mangle]
pub extern "C" fn fur_status_str(status: i32) -> &'static c_char {
    let s: &'static [u8] = match status {
        0 => b"ok\0",
        1 => b"a required pointer argument is NULL\0",
        2 => b"a pointer argument is misaligned for its type\0",
        3 => b"a length is zero where data is required, or too large\0",
        4 => b"the fur_lut or fur_dual is not open (never opened, closed, or its open failed)\0",
        5 => b"the LUT bytes are truncated\0",
        6 => b"the bytes are not a fur LUT (bad magic or trailing data)\0",
        7 => b"the LUT was baked by another format or model version: re-bake it\0",
        8 => b"the LUT checksum does not match: the data was changed after baking\0",
        9 => b"the LUT header or data is invalid\0",
        10 => b"an angle is not finite or theta is outside [-pi/2, pi/2]\0",
        11 => b"a direction or the tangent is not finite or has zero length\0",
        12 => b"nothing can be sampled at this view angle (zero BCSDF)\0",
        13 => b"the fur_lut or fur_dual was opened by another build of this library\0",
        14 => b"an output buffer overlaps an input buffer, the fur_lut, the fur_dual or the bytes\0",
        15 => b"the dual-scattering (.furdual) bytes are not 292944 bytes long (truncated or trailing data)\0",
        16 => b"the bytes are not a dual-scattering (.furdual) blob (bad magic)\0",
        17 => b"the dual-scattering blob was made by another format or model version: re-bake it\0",
        18 => b"the dual-scattering blob checksum does not match: the data was changed after baking\0",
        19 => b"the dual-scattering blob has another layout, an unknown attenuation or an invalid value\0",
        20 => b"the dual-scattering blob was not computed from this LUT (another LUT's checksum, or none recorded)\0",
        21 => b"a colour is invalid: a sigma_ca channel or melanin concentration is NaN or negative (valid sigma_ca: [0, 1000], larger values are clamped)\0",
        22 => b"a base colour is invalid: a channel is NaN or outside [0, 1] (linear RGB)\0",
        23 => b"the fur_coat table is invalid: a value is NaN, outside [0, 1] or above the one before it\0",
        _ => b"unknown status\0",
    };
    as_c_char(s.first().unwrap_or(&0))
}

/// The first byte of a NUL-terminated literal as a `c_char` (`c_char` is `i8` or `u8`, both
/// one byte: the same address, read as a C string by the caller).
fn as_c_char(b: &'static u8) -> &'static c_char {
    // SAFETY: `c_char` and `u8` have the same size and alignment (1), every bit pattern is
    // valid for both, and the reference keeps its 'static provenance over the literal.
    unsafe { &*core::ptr::from_ref(b).cast::<c_char>() }
}

/// This library's version as a static NUL-terminated string, e.g. "0.1.0". Never NULL.
#[no_mangle]
pub extern "C" fn fur_version() -> &'static c_char {
    as_c_char(
        concat!(env!("CARGO_PKG_VERSION"), "\0")
            .as_bytes()
            .first()
            .unwrap_or(&0),
    )
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
