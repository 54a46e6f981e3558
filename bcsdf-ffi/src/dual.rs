//! Dual scattering through the C ABI (docs/model.md §13): what a `fur_dual` stores, how it is
//! opened (decoded from a `.furdual` blob), recognised and closed, and its two evaluation
//! entry points (from angles and from world-space vectors).
//!
//! Like a `fur_lut` (`handle.rs`), a `fur_dual` is caller-owned, fixed-size storage that
//! starts with plain integers readable whatever the bytes are: a magic number the same in
//! every build, the [`DUAL_BUILD_TAG`] of the build that opened it, the source checksum the
//! blob records, and a check mixing the three. Then the decoded evaluator
//! (`bcsdf_core::dual::DualLut`, about 590 KB of f32), whose bits only this build can
//! interpret. Unlike a `fur_lut`, it owns everything it reads: the blob's bytes are decoded
//! into it and not borrowed.

use crate::args::{check_ptr, disjoint, open_bytes, read3, write3, Region};
use crate::handle::build_tag;
use crate::{fur_dual, fur_lut, fur_status};
use bcsdf_core::dual::{Density, DualColour, DualError, DualLut, Fibers, DUAL_FORMAT_VERSION};
use bcsdf_core::{Absorption, Angles, Rgb};
use core::mem::{align_of, offset_of, size_of, MaybeUninit};

/// What a `fur_dual` holds.
#[repr(C)]
struct OpenedDual {
    /// [`DUAL_MAGIC`] while open, 0 once closed (or never opened: `FUR_DUAL_INIT` is zeroes).
    magic: u64,
    /// [`DUAL_BUILD_TAG`] of the library build that opened it.
    build: u64,
    /// `DualLut::source` of the decoded blob (the checksum of the LUT it was computed from).
    source: u64,
    /// [`check_of`] the three fields above.
    check: u64,
    lut: MaybeUninit<DualLut>,
}

/// "FURDUALO": the first word of an open `fur_dual`, in every build of this library (not
/// the first word of an open `fur_lut`).
const DUAL_MAGIC: u64 = 0x4655_5244_5541_4c4f;

const _: () = assert!(size_of::<OpenedDual>() <= size_of::<fur_dual>());
const _: () = assert!(align_of::<OpenedDual>() <= align_of::<fur_dual>());
const _: () = assert!(crate::FUR_DUAL_BLOB_LEN == bcsdf_core::dual::BLOB_LEN);

/// What a `fur_dual` means in this build ([`build_tag`]: the library version, the compiler
/// and the target), with the `.furdual` format and model versions and the size, alignment
/// and field offsets of the stored layout. A `fur_dual` opened by another build carries
/// another tag and is refused with `FUR_ERR_OTHER_BUILD` instead of being misread.
pub(crate) const DUAL_BUILD_TAG: u64 = build_tag(&[
    DUAL_FORMAT_VERSION as usize,
    bcsdf_core::MODEL_VERSION as usize,
    size_of::<OpenedDual>(),
    align_of::<OpenedDual>(),
    offset_of!(OpenedDual, lut),
    size_of::<DualLut>(),
    align_of::<DualLut>(),
]);

/// The colour `sigma_ca` points to (3 floats, σ_ca per fiber radius, RGB) located on the
/// decoded tables' absorption axis; NULL is the preset's own colour. Channels above 1000 are
/// 1000 ([`Absorption::from_sigma`]).
///
/// # Safety
/// `sigma_ca` is NULL or points to 3 readable floats.
unsafe fn colour_of(lut: &DualLut, sigma_ca: *const f32) -> Result<DualColour, fur_status> {
    if sigma_ca.is_null() {
        return Ok(lut.locate(&lut.absorption()));
    }
    // SAFETY: forwarded caller guarantee (non-NULL here).
    let s = unsafe { read3(sigma_ca) }?;
    Absorption::from_sigma(Rgb(s))
        .map(|a| lut.locate(&a))
        .map_err(|_| fur_status::FUR_ERR_COLOUR)
}

/// A 64-bit mix of the integers an open `fur_dual` carries (SplitMix64 finaliser).
fn check_of(build: u64, source: u64) -> u64 {
    let mut z = DUAL_MAGIC ^ build.rotate_left(29) ^ source.wrapping_mul(0x9e37_79b9_7f4a_7c15);
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

/// The status of a refused `.furdual` blob.
fn status_of(e: &DualError) -> fur_status {
    match e {
        DualError::Length(_) => fur_status::FUR_ERR_DUAL_LENGTH,
        DualError::Magic => fur_status::FUR_ERR_DUAL_FORMAT,
        DualError::FormatVersion(_) | DualError::ModelVersion(_) => {
            fur_status::FUR_ERR_DUAL_VERSION
        }
        DualError::Checksum => fur_status::FUR_ERR_DUAL_CHECKSUM,
        DualError::Layout | DualError::Attenuation(_) | DualError::Value(_) | DualError::Colour => {
            fur_status::FUR_ERR_DUAL_INVALID
        }
        DualError::Source { .. } => fur_status::FUR_ERR_DUAL_SOURCE,
    }
}

/// An open `fur_dual`: its evaluator and its storage, which no output of a call may overlap.
struct Open<'a> {
    lut: &'a DualLut,
    region: Region,
}

/// The evaluator inside an open `fur_dual`, after checking the pointer, the magic, the tag
/// and the check word.
///
/// # Safety
/// `dual` is NULL or points to `size_of::<fur_dual>()` readable, initialised bytes (the
/// header's contract: `FUR_DUAL_INIT` or zeroed memory, then `fur_dual_open`,
/// `fur_dual_close`) that no other thread writes while the reference lives.
unsafe fn opened<'a>(dual: *const fur_dual) -> Result<Open<'a>, fur_status> {
    check_ptr(dual)?;
    let o = dual.cast::<OpenedDual>();
    // SAFETY: `dual` is non-NULL, 8-aligned (checked) and, by the caller's contract, points
    // to an initialised fur_dual; the first four words are plain integers, valid for any
    // bits.
    let (magic, build, source, check) = unsafe {
        (
            (&raw const (*o).magic).read(),
            (&raw const (*o).build).read(),
            (&raw const (*o).source).read(),
            (&raw const (*o).check).read(),
        )
    };
    if magic != DUAL_MAGIC {
        return Err(fur_status::FUR_ERR_NOT_OPEN);
    }
    if build != DUAL_BUILD_TAG {
        return Err(fur_status::FUR_ERR_OTHER_BUILD);
    }
    if check != check_of(build, source) {
        return Err(fur_status::FUR_ERR_NOT_OPEN);
    }
    // SAFETY: magic, build and check are written together only by fur_dual_open of this
    // build (the tag says so), after `lut` was initialised with a valid DualLut and decoded
    // into, and cleared by fur_dual_close; a random match of the 128 bits is a 2^-128 event.
    // The storage is owned by the caller and, by the contract, not written while in use.
    let lut = unsafe { (*o).lut.assume_init_ref() };
    Ok(Open {
        lut,
        region: Region::of(dual, 1),
    })
}

/// Zeroes the whole storage: closed, and equal to `FUR_DUAL_INIT`.
///
/// # Safety
/// `dual` is non-NULL, aligned and points to a writable `fur_dual`.
unsafe fn close(dual: *mut fur_dual) {
    // SAFETY: the caller guarantees a writable, aligned fur_dual; zero is a valid u64.
    unsafe { dual.write_bytes(0, 1) };
}

/// Decodes the `.furdual` blob of `len` bytes at `bytes` (docs/model.md §13) into `*out`
/// after checking all of it (length `FUR_DUAL_BLOB_LEN`, magic, format and model versions,
/// table layout, attenuation, checksum, every value), and opens `*out`. Nothing is borrowed:
/// the bytes may be freed or changed as soon as this returns. `*out` may be uninitialised.
///
/// Statuses of a refused blob (`*out` is then left closed, equal to `FUR_DUAL_INIT`):
/// `FUR_ERR_DUAL_LENGTH`, `FUR_ERR_DUAL_FORMAT`, `FUR_ERR_DUAL_VERSION`,
/// `FUR_ERR_DUAL_CHECKSUM`, `FUR_ERR_DUAL_INVALID`; NULL `bytes` gives `FUR_ERR_NULL`, `len`
/// 0 `FUR_ERR_LENGTH` (also closed). `FUR_ERR_NULL`/`FUR_ERR_ALIGNMENT` on `out` itself and
/// `FUR_ERR_OVERLAP` (`*out` overlaps the bytes) leave `*out` untouched.
///
/// # Safety
/// `bytes` is NULL or points to `len` readable bytes; `out` is NULL or points to a writable
/// `fur_dual` no other thread is using.
#[no_mangle]
pub unsafe extern "C" fn fur_dual_open(
    bytes: *const u8,
    len: usize,
    out: *mut fur_dual,
) -> fur_status {
    // SAFETY: the caller's contract (this function's) on `bytes`, `len` and `out`, for the
    // duration of this call; `close` zeroes a fur_dual.
    let slice: &[u8] = tri!(unsafe { open_bytes(bytes, len, out, close) });
    let o = out.cast::<OpenedDual>();
    // `DualLut::EMPTY` is promoted to a static (no Drop, no interior mutability): copying
    // it from there puts no 590 KB temporary on the caller's stack.
    let empty: &'static DualLut = &DualLut::EMPTY;
    // SAFETY: `o` is aligned and writable for an `OpenedDual` (`out` is checked, and
    // `OpenedDual` fits in `fur_dual` with no stricter alignment: static assertions); the
    // bitwise copy of a valid `DualLut` into its field makes that field a valid `DualLut`
    // (the zeroed storage need not be one: its attenuation is an enum), which `decode` then
    // fills through the only reference to it. `empty` is a static, disjoint from `*out`.
    let decoded = unsafe {
        let lut = (&raw mut (*o).lut).cast::<DualLut>();
        lut.copy_from_nonoverlapping(empty, 1);
        (*lut).decode(slice).map(|()| (*lut).source())
    };
    let source = match decoded {
        Ok(s) => s,
        Err(e) => {
            // SAFETY: as above: `out` is writable and aligned.
            unsafe { close(out) };
            return status_of(&e);
        }
    };
    let build = DUAL_BUILD_TAG;
    // SAFETY: `o` is aligned and writable (above); these four plain integers are written
    // last, after `lut` holds a valid, decoded evaluator.
    unsafe {
        (&raw mut (*o).source).write(source);
        (&raw mut (*o).check).write(check_of(build, source));
        (&raw mut (*o).build).write(build);
        (&raw mut (*o).magic).write(DUAL_MAGIC);
    }
    fur_status::FUR_OK
}

/// Closes `*dual`: zeroes it (it becomes equal to `FUR_DUAL_INIT`), so that every later call
/// with it returns `FUR_ERR_NOT_OPEN`. It holds no other resources (the caller frees the
/// storage itself, before or after closing).
///
/// # Safety
/// `dual` is NULL or points to a writable `fur_dual` no other thread is using.
#[no_mangle]
pub unsafe extern "C" fn fur_dual_close(dual: *mut fur_dual) -> fur_status {
    tri!(check_ptr(dual));
    // SAFETY: non-NULL and aligned (checked); writable by the caller's contract.
    unsafe { close(dual) };
    fur_status::FUR_OK
}

/// Whether the open `*dual` was computed from the LUT the open `*lut` reads
/// (`DualLut::check_lut`, docs/model.md §13 "Stored tables"): `FUR_OK` when the `.furdual`
/// blob's recorded source is the LUT's checksum, `FUR_ERR_DUAL_SOURCE` when it is another
/// LUT's or the blob records none. Check once after opening a `.furdual` and a `.furlut` as a
/// pair: tables left over from another bake or another preset open and evaluate without
/// complaint, but shade with another fur. Either handle not open gives `FUR_ERR_NOT_OPEN`
/// (or `FUR_ERR_NULL`, `FUR_ERR_ALIGNMENT`, `FUR_ERR_OTHER_BUILD`, as for its other calls).
/// Reads only: O(1), the LUT's checksum is read from its validated header.
///
/// # Safety
/// `dual` is NULL or points to an initialised `fur_dual`; `lut` is NULL or points to an
/// initialised `fur_lut` whose LUT bytes are alive (the contract of its other calls).
#[no_mangle]
pub unsafe extern "C" fn fur_dual_check_lut(
    dual: *const fur_dual,
    lut: *const fur_lut,
) -> fur_status {
    // SAFETY: forwarded caller guarantee on `dual`.
    let open = tri!(unsafe { opened(dual) });
    // SAFETY: forwarded caller guarantee on `lut`.
    let baked = tri!(unsafe { crate::handle::opened(lut) });
    match open.lut.check_lut(baked.lut) {
        Ok(()) => fur_status::FUR_OK,
        Err(e) => status_of(&e),
    }
}

/// The density factors as the core takes them (NaN and negative values are 0 there, values
/// above `MAX_DENSITY` = 4 are 4).
fn density(d_f: f32, d_b: f32) -> Density {
    Density { d_f, d_b }
}

/// The dual-scattering term (docs/model.md §13), RGB, into `out_rgb[3]`, from angles
/// (radians, as `fur_eval_far`): the light that reaches the shading point through `fibers`
/// other fibers, in a coat `fibers_below` fibers deep beneath the point.
///
/// `fibers` is n, the number of fibers between the shading point and the light (a shadow
/// ray's count, or a deep opacity map's / voxel density's estimate; fractional values are
/// fine): NaN or negative is 0 (unoccluded), above 10^6 (or +infinity) is 10^6.
/// `fibers_below` is m, the number of fibers beyond the shading point on the line from the
/// light through it (along -wi, away from the light), up to the skin or out of the coat: the
/// coat below, which sends light back up (fractional values are fine). Pass it as counted:
/// the term takes a count m >= 0 as the coat around the point, m + 1 layers (one line's
/// count is a sample of it, docs/model.md §13 "The coat below"). Negative is no coat (the
/// point lies on the skin); NaN, +infinity and anything above 10^6 is 10^6, a semi-infinite coat: pass
/// INFINITY when the depth is not known. That is the coat of the previous version of this
/// function, which had no `fibers_below`; its values changed anyway, since every Gaussian
/// is now normalised over the angles the caller can reach. `d_f` and `d_b` are the forward
/// and backward density factors (1 and 0.8 is the shipped default, `Density::DEFAULT`; with
/// the skin normal, pass `d_f` through `fur_dual_forward_density_at_incidence`; NaN or
/// negative is 0; above 4 is 4). The result is the term to ADD to single scattering: shade with S * V + result,
/// where S is `fur_eval_far`'s value and V = clamp(1 - fibers, 0, 1) the fraction of direct
/// light; the result is in S's units (multiply it, like S, by cos(theta_i) and the light's
/// radiance). Finite and >= 0. The value is `DualLut::eval` with
/// `Fibers::new(fibers, fibers_below)`, bit for bit, at the colour `sigma_ca` (3 floats:
/// the cortex absorption per fiber radius, RGB; each channel reads the tables' absorption
/// axis at its own value, `DualLut::eval_at`), or at the preset's own colour when
/// `sigma_ca` is NULL (`DualLut::eval`). A NaN or negative channel writes 0 and returns
/// `FUR_ERR_COLOUR`; channels above 1000 are 1000.
///
/// Invalid angles write 0 and return `FUR_ERR_ANGLE`. `out_rgb` must not overlap `*dual`
/// or `sigma_ca` (`FUR_ERR_OVERLAP`, nothing written).
///
/// # Safety
/// `dual` is NULL or points to an initialised `fur_dual`; `sigma_ca` is NULL or points to 3
/// readable floats; `out_rgb` is NULL or points to 3 writable floats.
#[no_mangle]
#[allow(clippy::too_many_arguments)] // the C signature: three angles, two counts, two factors
pub unsafe extern "C" fn fur_eval_dual(
    dual: *const fur_dual,
    theta_i: f32,
    theta_r: f32,
    phi: f32,
    fibers: f32,
    fibers_below: f32,
    d_f: f32,
    d_b: f32,
    sigma_ca: *const f32,
    out_rgb: *mut f32,
) -> fur_status {
    // SAFETY: forwarded caller guarantee on `dual`.
    let open = tri!(unsafe { opened(dual) });
    tri!(check_ptr(out_rgb));
    if !sigma_ca.is_null() {
        tri!(check_ptr(sigma_ca));
    }
    tri!(disjoint(
        Region::of(out_rgb, 3),
        &[open.region, Region::of(sigma_ca, 3)]
    ));
    // SAFETY: forwarded caller guarantee on `sigma_ca`.
    let (v, status) = match unsafe { colour_of(open.lut, sigma_ca) } {
        Err(e) => ([0.0; 3], e),
        Ok(colour) => match Angles::new(theta_i, theta_r, phi) {
            Ok(a) => (
                open.lut
                    .eval_located(
                        &a,
                        Fibers::new(fibers, fibers_below),
                        density(d_f, d_b),
                        &colour,
                    )
                    .0,
                fur_status::FUR_OK,
            ),
            Err(_) => ([0.0; 3], fur_status::FUR_ERR_ANGLE),
        },
    };
    // SAFETY: non-NULL and aligned (checked); 3 writable floats by the caller's contract,
    // disjoint from `*dual` (checked).
    unsafe { write3(out_rgb, v) };
    status
}

/// `fur_eval_dual` from world-space vectors (as `fur_eval_far_dirs`): `wi` toward the light,
/// `wr` toward the viewer, `tangent` the fiber direction (none needs unit length), into
/// `out_rgb[3]`; `fibers` (n, toward the light), `fibers_below` (m, beyond the point along
/// -wi; INFINITY or NaN for a semi-infinite coat), `d_f`, `d_b` and the result as in
/// `fur_eval_dual`, with the same contract (add it to S * V, multiply by cos(theta_i) and
/// the light's radiance), the colour `sigma_ca` too (NULL: the preset's own; a NaN or
/// negative channel writes 0 and returns `FUR_ERR_COLOUR`). The angles are those `DualLut::eval_dirs` converts to (the baked
/// evaluator's conversion). A vector with a component that is not finite, or of zero (below
/// the smallest normal float) or overflowing length, writes 0 and returns
/// `FUR_ERR_DIRECTION`. `out_rgb` must not overlap the three vectors, `sigma_ca` or `*dual`
/// (`FUR_ERR_OVERLAP`, nothing written).
///
/// # Safety
/// `dual` is NULL or points to an initialised `fur_dual`; each vector and `sigma_ca` is NULL
/// or points to 3 readable floats; `out_rgb` is NULL or points to 3 writable floats.
#[no_mangle]
#[allow(clippy::too_many_arguments)] // the C signature: three vectors, two counts, two factors
pub unsafe extern "C" fn fur_eval_dual_dirs(
    dual: *const fur_dual,
    wi: *const f32,
    wr: *const f32,
    tangent: *const f32,
    fibers: f32,
    fibers_below: f32,
    d_f: f32,
    d_b: f32,
    sigma_ca: *const f32,
    out_rgb: *mut f32,
) -> fur_status {
    // SAFETY: forwarded caller guarantee on `dual`.
    let open = tri!(unsafe { opened(dual) });
    tri!(check_ptr(out_rgb));
    if !sigma_ca.is_null() {
        tri!(check_ptr(sigma_ca));
    }
    // SAFETY: forwarded caller guarantee on `wi`.
    let wi_v = tri!(unsafe { read3(wi) });
    // SAFETY: forwarded caller guarantee on `wr`.
    let wr_v = tri!(unsafe { read3(wr) });
    // SAFETY: forwarded caller guarantee on `tangent`.
    let t_v = tri!(unsafe { read3(tangent) });
    let inputs = [
        open.region,
        Region::of(wi, 3),
        Region::of(wr, 3),
        Region::of(tangent, 3),
        Region::of(sigma_ca, 3),
    ];
    tri!(disjoint(Region::of(out_rgb, 3), &inputs));
    // SAFETY: forwarded caller guarantee on `sigma_ca`.
    let colour = match unsafe { colour_of(open.lut, sigma_ca) } {
        Ok(c) => c,
        Err(e) => {
            // SAFETY: non-NULL and aligned (checked); 3 writable floats, disjoint (checked).
            unsafe { write3(out_rgb, [0.0; 3]) };
            return e;
        }
    };
    // `DualLut::try_eval_dirs`: the Rust API's value bit for bit, and its verdict on the
    // directions from the same conversion (0 written for rejected ones).
    let counts = Fibers::new(fibers, fibers_below);
    let (v, status) =
        match open
            .lut
            .try_eval_dirs_located(wi_v, wr_v, t_v, counts, density(d_f, d_b), &colour)
        {
            Ok(v) => (v.0, fur_status::FUR_OK),
            Err(_) => ([0.0; 3], fur_status::FUR_ERR_DIRECTION),
        };
    // SAFETY: non-NULL and aligned (checked); 3 writable floats by the caller's contract,
    // disjoint from the inputs and `*dual` (checked).
    unsafe { write3(out_rgb, v) };
    status
}

/// The `fibers_below` to pass to `fur_eval_dual` / `fur_eval_dual_dirs` when the engine
/// knows the skin normal under the strand (the groom's root normal; docs/model.md §13 "The
/// light's incidence on the coat", docs/engines.md): `fibers_below` is m as counted along the
/// light's line (as those functions take it without the normal) and `cos_to_normal` the
/// cosine between the direction toward the light and that normal. The term then uses
/// 2 |cos| (m + 1) layers of coat below, at least 1: the coat's normal depth crossed twice by
/// the diffuse light it returns, not the light's chord. A negative, NaN or infinite
/// `fibers_below` (or one of 10^6 and more) and a NaN `cos_to_normal` (the normal unknown)
/// are returned unchanged. `bcsdf_core::dual::coat::below_at_incidence`, bit for bit.
#[no_mangle]
pub extern "C" fn fur_dual_below_at_incidence(fibers_below: f32, cos_to_normal: f32) -> f32 {
    bcsdf_core::dual::coat::below_at_incidence(fibers_below, cos_to_normal)
}

/// The `d_f` to pass to `fur_eval_dual` / `fur_eval_dual_dirs` when the engine knows the
/// skin normal under the strand (docs/model.md §13 "The light's incidence on the coat",
/// docs/engines.md): `d_f` times 2 |cos_to_normal| (clamped to 1), `cos_to_normal` the cosine
/// between the direction toward the light and that normal. The light that reaches the point
/// through fibers is a diffuse flux set by the light the coat takes in per unit of its area.
/// A NaN `cos_to_normal` (the normal unknown) returns `d_f` unchanged.
/// `bcsdf_core::dual::coat::forward_density_at_incidence`, bit for bit.
#[no_mangle]
pub extern "C" fn fur_dual_forward_density_at_incidence(d_f: f32, cos_to_normal: f32) -> f32 {
    bcsdf_core::dual::coat::forward_density_at_incidence(d_f, cos_to_normal)
}

#[cfg(test)]
#[path = "dual_tests.rs"]
mod tests;
