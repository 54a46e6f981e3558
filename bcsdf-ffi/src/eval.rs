//! The evaluation entry points of the C ABI: the far field from angles, per family, from
//! vectors and in batches (docs/model.md §8); sampling and its pdf are in `sample.rs`.
//!
//! Each has an `_at` sibling that takes the query's colour (LUT format 5, docs/lut.md "The
//! absorption axis"): σ_ca per RGB channel as `const float sigma_ca[3]` right after the
//! `fur_lut` (the batch: `3n` floats, one colour per query), validated by `colour.rs`
//! (`FUR_ERR_COLOUR` for a NaN or negative channel). The functions without `_at` evaluate the
//! LUT's own colour (`fur_lut_sigma_ca`), bit for bit as their `_at` siblings do at it.
//!
//! Every output buffer is checked against every other buffer the call reads or keeps a
//! reference into (the inputs, the colour, the `fur_lut`, the LUT bytes): an overlap is
//! refused with `FUR_ERR_OVERLAP` before anything is read or written.

use crate::args::{check_ptr, disjoint, read3, write3, Region};
use crate::colour::{colour_of, read_colour};
use crate::handle::opened;
use crate::{fur_lut, fur_status};
use bcsdf_core::{Absorption, Angles, Families, Rgb};

pub(crate) fn angles(theta_i: f32, theta_r: f32, phi: f32) -> Result<Angles, fur_status> {
    Angles::new(theta_i, theta_r, phi).map_err(|_| fur_status::FUR_ERR_ANGLE)
}

/// Far-field S(omega_i, omega_r), RGB, into `out_rgb[3]` (0 and `FUR_ERR_ANGLE` for invalid
/// angles). `out_rgb` must not overlap `*lut` or the LUT bytes (`FUR_ERR_OVERLAP`).
///
/// # Safety
/// `lut` is NULL or points to an initialised `fur_lut`; `out_rgb` is NULL or points to 3
/// writable floats.
#[no_mangle]
pub unsafe extern "C" fn fur_eval_far(
    lut: *const fur_lut,
    theta_i: f32,
    theta_r: f32,
    phi: f32,
    out_rgb: *mut f32,
) -> fur_status {
    // SAFETY: forwarded caller guarantee on `lut`.
    let open = tri!(unsafe { opened(lut) });
    tri!(check_ptr(out_rgb));
    tri!(disjoint(Region::of(out_rgb, 3), &open.regions));
    let (v, status) = match angles(theta_i, theta_r, phi) {
        Ok(a) => (open.lut.eval_far(&a).total().0, fur_status::FUR_OK),
        Err(s) => ([0.0; 3], s),
    };
    // SAFETY: non-NULL and aligned (checked); 3 writable floats by the caller's contract.
    unsafe { write3(out_rgb, v) };
    status
}

/// Far-field S per lobe family into `out[12]`: R, TT, TRT, scattered, RGB each. `out` must
/// not overlap `*lut` or the LUT bytes (`FUR_ERR_OVERLAP`).
///
/// # Safety
/// `lut` is NULL or points to an initialised `fur_lut`; `out` is NULL or points to 12
/// writable floats.
#[no_mangle]
pub unsafe extern "C" fn fur_eval_far_families(
    lut: *const fur_lut,
    theta_i: f32,
    theta_r: f32,
    phi: f32,
    out: *mut f32,
) -> fur_status {
    // SAFETY: forwarded caller guarantee on `lut`.
    let open = tri!(unsafe { opened(lut) });
    tri!(check_ptr(out));
    tri!(disjoint(Region::of(out, 12), &open.regions));
    let (f, status) = match angles(theta_i, theta_r, phi) {
        Ok(a) => (open.lut.eval_far(&a), fur_status::FUR_OK),
        Err(s) => (Families::ZERO, s),
    };
    // SAFETY: non-NULL and aligned (checked); 12 writable floats, 4 families × 3 channels,
    // by the caller's contract.
    unsafe { out.cast::<[[f32; 3]; 4]>().write(f.as_array().map(|c| c.0)) };
    status
}

/// Far-field S from world-space vectors: `wi` toward the light, `wr` toward the viewer,
/// `tangent` the fiber direction (none needs unit length), into `out_rgb[3]`. `out_rgb`
/// must not overlap the three vectors, `*lut` or the LUT bytes (`FUR_ERR_OVERLAP`).
///
/// # Safety
/// `lut` is NULL or points to an initialised `fur_lut`; each vector is NULL or points to 3
/// readable floats; `out_rgb` is NULL or points to 3 writable floats.
#[no_mangle]
pub unsafe extern "C" fn fur_eval_far_dirs(
    lut: *const fur_lut,
    wi: *const f32,
    wr: *const f32,
    tangent: *const f32,
    out_rgb: *mut f32,
) -> fur_status {
    // SAFETY: forwarded caller guarantee on `lut`.
    let open = tri!(unsafe { opened(lut) });
    tri!(check_ptr(out_rgb));
    // SAFETY: forwarded caller guarantee on `wi`.
    let wi_v = tri!(unsafe { read3(wi) });
    // SAFETY: forwarded caller guarantee on `wr`.
    let wr_v = tri!(unsafe { read3(wr) });
    // SAFETY: forwarded caller guarantee on `tangent`.
    let t_v = tri!(unsafe { read3(tangent) });
    let [a, b] = open.regions;
    let inputs = [
        a,
        b,
        Region::of(wi, 3),
        Region::of(wr, 3),
        Region::of(tangent, 3),
    ];
    tri!(disjoint(Region::of(out_rgb, 3), &inputs));
    let (v, status) = match open.lut.try_eval_far_dirs(wi_v, wr_v, t_v) {
        Ok(f) => (f.total().0, fur_status::FUR_OK),
        Err(_) => ([0.0; 3], fur_status::FUR_ERR_DIRECTION),
    };
    // SAFETY: non-NULL and aligned (checked); 3 writable floats by the caller's contract.
    unsafe { write3(out_rgb, v) };
    status
}

/// `n` far-field evaluations, structure of arrays in (`theta_i[n]`, `theta_r[n]`, `phi[n]`),
/// `out_rgb[3n]` out. `n` = 0 does nothing (any pointers). An invalid angle gives 0 for its
/// entry and the call returns `FUR_ERR_ANGLE` after evaluating every other entry. The inputs
/// may share memory with each other; `out_rgb` must not overlap them, `*lut` or the LUT bytes
/// (`FUR_ERR_OVERLAP`, nothing written). `n` above `PTRDIFF_MAX / 12` gives `FUR_ERR_LENGTH`.
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
    // SAFETY: forwarded caller guarantee on `lut`.
    let open = tri!(unsafe { opened(lut) });
    if n == 0 {
        return fur_status::FUR_OK;
    }
    // The output is 12n bytes, and a slice may span at most isize::MAX bytes.
    if n > isize::MAX as usize / size_of::<Rgb>() {
        return fur_status::FUR_ERR_LENGTH;
    }
    for p in [theta_i, theta_r, phi] {
        tri!(check_ptr(p));
    }
    tri!(check_ptr(out_rgb));
    let [a, b] = open.regions;
    let inputs = [
        a,
        b,
        Region::of(theta_i, n),
        Region::of(theta_r, n),
        Region::of(phi, n),
    ];
    tri!(disjoint(Region::of(out_rgb.cast::<Rgb>(), n), &inputs));
    // SAFETY: non-NULL and 4-aligned (checked); the caller guarantees n readable floats
    // each; 4n ≤ 12n ≤ isize::MAX bytes (checked); none of them overlaps the output
    // (checked), the only memory written while these slices live.
    let (ti, tr, ph) = unsafe {
        (
            core::slice::from_raw_parts(theta_i, n),
            core::slice::from_raw_parts(theta_r, n),
            core::slice::from_raw_parts(phi, n),
        )
    };
    // SAFETY: as above for 3n writable floats, which are n `Rgb`s (`repr(transparent)` over
    // `[f32; 3]`, alignment 4); 12n ≤ isize::MAX bytes (checked); disjoint from the three
    // input slices, `*lut` and the LUT bytes (checked), so this is the only reference to it.
    let out = unsafe { core::slice::from_raw_parts_mut(out_rgb.cast::<Rgb>(), n) };
    // The batch path (SIMD over the queries, bit-identical to fur_eval_far per entry).
    match open.lut.eval_far_batch(ti, tr, ph, out) {
        Ok(0) => fur_status::FUR_OK,
        Ok(_) => fur_status::FUR_ERR_ANGLE,
        // Unreachable: all four slices have length n.
        Err(_) => fur_status::FUR_ERR_LENGTH,
    }
}

/// The memory an `_at` call reads besides its own inputs: `*lut`, the LUT bytes and the
/// colour's 3 floats.
pub(crate) fn with_colour(regions: [Region; 2], sigma_ca: *const f32) -> [Region; 3] {
    let [a, b] = regions;
    [a, b, Region::of(sigma_ca, 3)]
}

/// `fur_eval_far` at colour `sigma_ca[3]` (σ_ca per RGB channel, per fiber radius, in
/// [0, 1000]; larger values are clamped to 1000): far-field S(omega_i, omega_r), RGB, into
/// `out_rgb[3]`. A NaN or negative channel writes 0 and returns `FUR_ERR_COLOUR`; invalid
/// angles write 0 and return `FUR_ERR_ANGLE`. `out_rgb` must not overlap `sigma_ca`, `*lut`
/// or the LUT bytes (`FUR_ERR_OVERLAP`).
///
/// ```c
/// float sigma[3], rgb[3];
/// fur_sigma_from_melanin(0.4f, 1.5f, sigma); // a ginger strand
/// fur_eval_far_at(&lut, sigma, 0.5f, -0.35f, 0.785f, rgb);
/// ```
///
/// # Safety
/// `lut` is NULL or points to an initialised `fur_lut`; `sigma_ca` is NULL or points to 3
/// readable floats; `out_rgb` is NULL or points to 3 writable floats.
#[no_mangle]
pub unsafe extern "C" fn fur_eval_far_at(
    lut: *const fur_lut,
    sigma_ca: *const f32,
    theta_i: f32,
    theta_r: f32,
    phi: f32,
    out_rgb: *mut f32,
) -> fur_status {
    // SAFETY: forwarded caller guarantee on `lut`.
    let open = tri!(unsafe { opened(lut) });
    tri!(check_ptr(out_rgb));
    tri!(check_ptr(sigma_ca));
    tri!(disjoint(
        Region::of(out_rgb, 3),
        &with_colour(open.regions, sigma_ca)
    ));
    // SAFETY: forwarded caller guarantee on `sigma_ca` (non-NULL and aligned, checked).
    let colour = unsafe { read_colour(sigma_ca) };
    let (v, status) = match (colour, angles(theta_i, theta_r, phi)) {
        (Ok(c), Ok(a)) => (open.lut.at(&c).eval_far(&a).total().0, fur_status::FUR_OK),
        (Err(s), _) | (Ok(_), Err(s)) => ([0.0; 3], s),
    };
    // SAFETY: non-NULL and aligned (checked); 3 writable floats by the caller's contract.
    unsafe { write3(out_rgb, v) };
    status
}

/// `fur_eval_far_families` at colour `sigma_ca[3]` (as `fur_eval_far_at`): S per lobe family
/// into `out[12]` (R, TT, TRT, scattered, RGB each; 0 with `FUR_ERR_COLOUR` or
/// `FUR_ERR_ANGLE`). `out` must not overlap `sigma_ca`, `*lut` or the LUT bytes
/// (`FUR_ERR_OVERLAP`).
///
/// # Safety
/// `lut` is NULL or points to an initialised `fur_lut`; `sigma_ca` is NULL or points to 3
/// readable floats; `out` is NULL or points to 12 writable floats.
#[no_mangle]
pub unsafe extern "C" fn fur_eval_far_families_at(
    lut: *const fur_lut,
    sigma_ca: *const f32,
    theta_i: f32,
    theta_r: f32,
    phi: f32,
    out: *mut f32,
) -> fur_status {
    // SAFETY: forwarded caller guarantee on `lut`.
    let open = tri!(unsafe { opened(lut) });
    tri!(check_ptr(out));
    tri!(check_ptr(sigma_ca));
    tri!(disjoint(
        Region::of(out, 12),
        &with_colour(open.regions, sigma_ca)
    ));
    // SAFETY: forwarded caller guarantee on `sigma_ca` (non-NULL and aligned, checked).
    let colour = unsafe { read_colour(sigma_ca) };
    let (f, status) = match (colour, angles(theta_i, theta_r, phi)) {
        (Ok(c), Ok(a)) => (open.lut.at(&c).eval_far(&a), fur_status::FUR_OK),
        (Err(s), _) | (Ok(_), Err(s)) => (Families::ZERO, s),
    };
    // SAFETY: non-NULL and aligned (checked); 12 writable floats, 4 families × 3 channels,
    // by the caller's contract.
    unsafe { out.cast::<[[f32; 3]; 4]>().write(f.as_array().map(|c| c.0)) };
    status
}

/// `fur_eval_far_dirs` at colour `sigma_ca[3]` (as `fur_eval_far_at`): far-field S from
/// world-space vectors into `out_rgb[3]` (0 with `FUR_ERR_COLOUR` or `FUR_ERR_DIRECTION`).
/// `out_rgb` must not overlap the three vectors, `sigma_ca`, `*lut` or the LUT bytes
/// (`FUR_ERR_OVERLAP`).
///
/// # Safety
/// `lut` is NULL or points to an initialised `fur_lut`; `sigma_ca` and each vector are NULL
/// or point to 3 readable floats; `out_rgb` is NULL or points to 3 writable floats.
#[no_mangle]
pub unsafe extern "C" fn fur_eval_far_dirs_at(
    lut: *const fur_lut,
    sigma_ca: *const f32,
    wi: *const f32,
    wr: *const f32,
    tangent: *const f32,
    out_rgb: *mut f32,
) -> fur_status {
    // SAFETY: forwarded caller guarantee on `lut`.
    let open = tri!(unsafe { opened(lut) });
    tri!(check_ptr(out_rgb));
    tri!(check_ptr(sigma_ca));
    // SAFETY: forwarded caller guarantee on `wi`.
    let wi_v = tri!(unsafe { read3(wi) });
    // SAFETY: forwarded caller guarantee on `wr`.
    let wr_v = tri!(unsafe { read3(wr) });
    // SAFETY: forwarded caller guarantee on `tangent`.
    let t_v = tri!(unsafe { read3(tangent) });
    let [a, b, c] = with_colour(open.regions, sigma_ca);
    let inputs = [
        a,
        b,
        c,
        Region::of(wi, 3),
        Region::of(wr, 3),
        Region::of(tangent, 3),
    ];
    tri!(disjoint(Region::of(out_rgb, 3), &inputs));
    // SAFETY: forwarded caller guarantee on `sigma_ca` (non-NULL and aligned, checked).
    let (v, status) = match unsafe { read_colour(sigma_ca) } {
        Ok(c) => match open.lut.at(&c).try_eval_far_dirs(wi_v, wr_v, t_v) {
            Ok(f) => (f.total().0, fur_status::FUR_OK),
            Err(_) => ([0.0; 3], fur_status::FUR_ERR_DIRECTION),
        },
        Err(s) => ([0.0; 3], s),
    };
    // SAFETY: non-NULL and aligned (checked); 3 writable floats by the caller's contract.
    unsafe { write3(out_rgb, v) };
    status
}

/// Queries per pass of `fur_eval_far_batch_at` (its validated colours live on the stack: 384
/// bytes).
const COLOUR_CHUNK: usize = 32;

/// `fur_eval_far_batch` with a colour per query: `sigma_ca[3n]` holds query k's σ_ca at
/// `sigma_ca[3k .. 3k + 3]` (as `fur_eval_far_at`), the angles `theta_i[n]`, `theta_r[n]`,
/// `phi[n]`, the results `out_rgb[3n]`; each entry equal bit for bit to `fur_eval_far_at`'s.
/// `n` = 0 does nothing (any pointers). An entry with a NaN or negative colour channel, or an
/// invalid angle, gives 0; the call evaluates every other entry and returns `FUR_ERR_COLOUR`
/// if any colour was refused, else `FUR_ERR_ANGLE` if any angle was. The inputs may share
/// memory with each other; `out_rgb` must not overlap them, `*lut` or the LUT bytes
/// (`FUR_ERR_OVERLAP`, nothing written). `n` above `PTRDIFF_MAX / 12` gives `FUR_ERR_LENGTH`.
///
/// # Safety
/// For n > 0: `sigma_ca` is NULL or points to `3n` readable floats, the three angle pointers
/// are NULL or point to `n` readable floats each, and `out_rgb` is NULL or points to `3n`
/// writable floats.
#[no_mangle]
pub unsafe extern "C" fn fur_eval_far_batch_at(
    lut: *const fur_lut,
    n: usize,
    sigma_ca: *const f32,
    theta_i: *const f32,
    theta_r: *const f32,
    phi: *const f32,
    out_rgb: *mut f32,
) -> fur_status {
    // SAFETY: forwarded caller guarantee on `lut`.
    let open = tri!(unsafe { opened(lut) });
    if n == 0 {
        return fur_status::FUR_OK;
    }
    // The output and the colours are 12n bytes each, and a slice may span at most
    // isize::MAX bytes.
    if n > isize::MAX as usize / size_of::<Rgb>() {
        return fur_status::FUR_ERR_LENGTH;
    }
    for p in [sigma_ca, theta_i, theta_r, phi] {
        tri!(check_ptr(p));
    }
    tri!(check_ptr(out_rgb));
    let [a, b] = open.regions;
    let inputs = [
        a,
        b,
        Region::of(sigma_ca.cast::<Rgb>(), n),
        Region::of(theta_i, n),
        Region::of(theta_r, n),
        Region::of(phi, n),
    ];
    tri!(disjoint(Region::of(out_rgb.cast::<Rgb>(), n), &inputs));
    // SAFETY: non-NULL and 4-aligned (checked); the caller guarantees n readable floats
    // each (3n for the colours, n `Rgb`s: `repr(transparent)` over `[f32; 3]`, alignment 4);
    // 12n ≤ isize::MAX bytes (checked); none of them overlaps the output (checked), the only
    // memory written while these slices live.
    let (sigma, ti, tr, ph) = unsafe {
        (
            core::slice::from_raw_parts(sigma_ca.cast::<Rgb>(), n),
            core::slice::from_raw_parts(theta_i, n),
            core::slice::from_raw_parts(theta_r, n),
            core::slice::from_raw_parts(phi, n),
        )
    };
    // SAFETY: as above for 3n writable floats, n `Rgb`s; disjoint from the input slices,
    // `*lut` and the LUT bytes (checked), so this is the only reference to it.
    let out = unsafe { core::slice::from_raw_parts_mut(out_rgb.cast::<Rgb>(), n) };
    let (mut bad_colour, mut bad_angle) = (false, false);
    let chunks = sigma
        .chunks(COLOUR_CHUNK)
        .zip(ti.chunks(COLOUR_CHUNK))
        .zip(tr.chunks(COLOUR_CHUNK))
        .zip(ph.chunks(COLOUR_CHUNK))
        .zip(out.chunks_mut(COLOUR_CHUNK));
    for ((((s, ti), tr), ph), out) in chunks {
        // The chunk's colours validated (a refused one evaluated as lossless, then zeroed).
        let mut colours = [Absorption::LOSSLESS; COLOUR_CHUNK];
        let mut refused = [false; COLOUR_CHUNK];
        for ((c, r), s) in colours.iter_mut().zip(&mut refused).zip(s) {
            match colour_of(s.0) {
                Ok(v) => *c = v,
                Err(_) => *r = true,
            }
        }
        let colours = colours.get(..s.len()).unwrap_or(&[]);
        // The core's batch path (SIMD over the queries, bit-identical to the scalar one).
        match open.lut.eval_far_batch_colours(ti, tr, ph, colours, out) {
            Ok(rejected) => bad_angle |= rejected > 0,
            // Unreachable: all five slices have the chunk's length.
            Err(_) => return fur_status::FUR_ERR_LENGTH,
        }
        for (o, r) in out.iter_mut().zip(refused) {
            if r {
                *o = Rgb::ZERO;
                bad_colour = true;
            }
        }
    }
    if bad_colour {
        fur_status::FUR_ERR_COLOUR
    } else if bad_angle {
        fur_status::FUR_ERR_ANGLE
    } else {
        fur_status::FUR_OK
    }
}
