//! What a `fur_lut` stores and how it is opened, recognised and closed (docs/model.md §8:
//! the baked evaluator behind a caller-owned, fixed-size handle).
//!
//! The storage starts with five plain integers (readable whatever the bytes are): a magic
//! number the same in every build, the [`BUILD_TAG`] of the build that opened it, the
//! address and length of the borrowed LUT bytes, and a check mixing the four. Then the
//! evaluator, whose bits only this build can interpret.

use crate::args::{check_ptr, open_bytes, Region};
use crate::{fur_lut, fur_status};
use bcsdf_core::baked::BakedBcsdf;
use bcsdf_core::lut::{self, LutError};
use core::mem::{align_of, offset_of, size_of, MaybeUninit};

/// What a `fur_lut` holds.
#[repr(C)]
struct Opened {
    /// [`MAGIC`] while open, 0 once closed (or never opened: `FUR_LUT_INIT` is zeroes).
    magic: u64,
    /// [`BUILD_TAG`] of the library build that opened it.
    build: u64,
    /// Address and length of the borrowed LUT bytes.
    bytes: usize,
    len: usize,
    /// [`check_of`] the four fields above.
    check: u64,
    lut: MaybeUninit<BakedBcsdf<'static>>,
}

/// "FURLUTOK": the first word of an open `fur_lut`, in every build of this library.
const MAGIC: u64 = 0x4655_524c_5554_4f4b;

const _: () = assert!(size_of::<Opened>() <= size_of::<fur_lut>());
const _: () = assert!(align_of::<Opened>() <= align_of::<fur_lut>());

/// 64-bit FNV-1a of `bytes`, continuing from `h`.
const fn fnv1a(mut h: u64, bytes: &[u8]) -> u64 {
    let mut i = 0;
    while i < bytes.len() {
        h = (h ^ bytes[i] as u64).wrapping_mul(0x0000_0100_0000_01b3);
        i += 1;
    }
    h
}

/// The library version, the compiler (`rustc -vV`, recorded by build.rs) and the target,
/// hashed (FNV-1a), then `layout` (what a stored handle's bits mean: versions, sizes,
/// alignments, offsets), each as 8 little-endian bytes. The build tag of a handle type.
pub(crate) const fn build_tag(layout: &[usize]) -> u64 {
    let mut h = fnv1a(0xcbf2_9ce4_8422_2325, env!("CARGO_PKG_VERSION").as_bytes());
    h = fnv1a(h, env!("FUR_BCSDF_RUSTC").as_bytes());
    h = fnv1a(h, env!("FUR_BCSDF_TARGET").as_bytes());
    let mut i = 0;
    while i < layout.len() {
        h = fnv1a(h, &(layout[i] as u64).to_le_bytes());
        i += 1;
    }
    h
}

/// What a `fur_lut` means in this build, hashed ([`build_tag`]): the library version, the
/// compiler and the target, the LUT format and model versions, and the size, alignment and
/// field offsets of the stored layout. A `fur_lut` opened by another build (another version
/// of the library linked into the same process, another compiler) carries another tag and is
/// refused with `FUR_ERR_OTHER_BUILD` instead of being misread.
pub(crate) const BUILD_TAG: u64 = build_tag(&[
    lut::FORMAT_VERSION as usize,
    bcsdf_core::MODEL_VERSION as usize,
    size_of::<Opened>(),
    align_of::<Opened>(),
    offset_of!(Opened, lut),
    size_of::<BakedBcsdf<'static>>(),
    align_of::<BakedBcsdf<'static>>(),
]);

/// A 64-bit mix of the integers an open `fur_lut` carries (SplitMix64 finaliser).
fn check_of(build: u64, bytes: usize, len: usize) -> u64 {
    let mut z = MAGIC
        ^ build.rotate_left(29)
        ^ (bytes as u64).rotate_left(17)
        ^ (len as u64).wrapping_mul(0x9e37_79b9_7f4a_7c15);
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
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

/// An open `fur_lut`: its evaluator and the memory it keeps references into (its own
/// storage and the LUT bytes), which no output of a call may overlap.
pub(crate) struct Open<'a> {
    pub(crate) lut: &'a BakedBcsdf<'static>,
    pub(crate) regions: [Region; 2],
}

/// The evaluator inside an open `fur_lut`, after checking the pointer and the tag.
///
/// # Safety
/// `lut` is NULL or points to `size_of::<fur_lut>()` readable, initialised bytes (the
/// header's contract: `FUR_LUT_INIT`, then `fur_lut_open`, `fur_lut_close`).
pub(crate) unsafe fn opened<'a>(lut: *const fur_lut) -> Result<Open<'a>, fur_status> {
    check_ptr(lut)?;
    let o = lut.cast::<Opened>();
    // SAFETY: `lut` is non-NULL, 8-aligned (checked) and, by the caller's contract, points
    // to an initialised fur_lut; the first five words are plain integers, valid for any
    // bits.
    let (magic, build, bytes, len, check) = unsafe {
        (
            (&raw const (*o).magic).read(),
            (&raw const (*o).build).read(),
            (&raw const (*o).bytes).read(),
            (&raw const (*o).len).read(),
            (&raw const (*o).check).read(),
        )
    };
    if magic != MAGIC {
        return Err(fur_status::FUR_ERR_NOT_OPEN);
    }
    if build != BUILD_TAG {
        return Err(fur_status::FUR_ERR_OTHER_BUILD);
    }
    if check != check_of(build, bytes, len) {
        return Err(fur_status::FUR_ERR_NOT_OPEN);
    }
    // SAFETY: magic, build and check are written together with `lut` only by
    // fur_lut_open of this build (the tag says so), after a successful
    // BakedBcsdf::from_bytes, and cleared by fur_lut_close; a random match of the 128 bits
    // is a 2^-128 event. The bytes it borrows are alive by the caller's contract (close
    // before freeing them).
    let l = unsafe { (*o).lut.assume_init_ref() };
    Ok(Open {
        lut: l,
        regions: [Region::of(lut, 1), Region::at(bytes, len)],
    })
}

/// Validates `len` bytes at `bytes` as a baked LUT (header, versions, lengths, checksum,
/// every value, the sampling data: one pass over the bytes) and opens `*out` on them
/// (docs/model.md §8). The bytes are borrowed: keep them alive and unchanged until
/// `fur_lut_close(out)`. `*out` may be uninitialised; on failure it is left closed (equal to
/// `FUR_LUT_INIT`), except for `FUR_ERR_NULL`/`FUR_ERR_ALIGNMENT` on `out` itself and
/// `FUR_ERR_OVERLAP` (`*out` lies inside the bytes), which leave it untouched.
///
/// # Safety
/// `bytes` is NULL or points to `len` readable bytes; `out` is NULL or points to a writable
/// `fur_lut` no other thread is using.
#[no_mangle]
pub unsafe extern "C" fn fur_lut_open(
    bytes: *const u8,
    len: usize,
    out: *mut fur_lut,
) -> fur_status {
    // SAFETY: the caller's contract (this function's) on `bytes`, `len` and `out`: the bytes
    // stay alive and unchanged until the fur_lut is closed (the header's contract), hence
    // 'static here; `close` zeroes a fur_lut.
    let slice: &'static [u8] = tri!(unsafe { open_bytes(bytes, len, out, close) });
    let lut = match BakedBcsdf::from_bytes(slice) {
        Ok(l) => l,
        Err(e) => return status_of(&e),
    };
    let (bytes, build) = (bytes.addr(), BUILD_TAG);
    // SAFETY: `out` is writable and aligned (checked above); `Opened` fits in `fur_lut`
    // with no stricter alignment (static assertions).
    unsafe {
        out.cast::<Opened>().write(Opened {
            magic: MAGIC,
            build,
            bytes,
            len,
            check: check_of(build, bytes, len),
            lut: MaybeUninit::new(lut),
        });
    }
    fur_status::FUR_OK
}

/// Zeroes the whole storage: closed, and equal to `FUR_LUT_INIT`.
///
/// # Safety
/// `lut` is non-NULL, aligned and points to a writable `fur_lut`.
unsafe fn close(lut: *mut fur_lut) {
    // SAFETY: the caller guarantees a writable, aligned fur_lut; zero is a valid u64.
    unsafe { lut.write_bytes(0, 1) };
}

/// Closes `*lut`: zeroes it (it becomes equal to `FUR_LUT_INIT`), so that every later call
/// with it returns `FUR_ERR_NOT_OPEN` and reads nothing else. Close every `fur_lut` (and every
/// copy of one) before freeing or changing its LUT bytes. It holds no other resources.
///
/// # Safety
/// `lut` is NULL or points to a writable `fur_lut` no other thread is using.
#[no_mangle]
pub unsafe extern "C" fn fur_lut_close(lut: *mut fur_lut) -> fur_status {
    tri!(check_ptr(lut));
    // SAFETY: non-NULL and aligned (checked); writable by the caller's contract.
    unsafe { close(lut) };
    fur_status::FUR_OK
}
