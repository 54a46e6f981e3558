//! The evaluation entry points of the C ABI: the far field from angles, per family, from
//! vectors and in batches, importance sampling and its pdf, and both at one view in one call
//! (docs/model.md §8, §10).
//!
//! Every output buffer is checked against every other buffer the call reads or keeps a
//! reference into (the inputs, the `fur_lut`, the LUT bytes): an overlap is refused with
//! `FUR_ERR_OVERLAP` before anything is read or written.

use crate::args::{check_ptr, disjoint, read3, write3, Region};
use crate::handle::opened;
use crate::{fur_family, fur_lut, fur_sample, fur_status};
use bcsdf_core::{Angles, Bcsdf, Families, LobeFamily, Rgb, Sample};

fn angles(theta_i: f32, theta_r: f32, phi: f32) -> Result<Angles, fur_status> {
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

/// Importance-samples omega_i given theta_r from three uniform numbers in [0, 1) (values
/// outside are clamped) into `*out` (docs/model.md section 10). `out` must not overlap
/// `*lut` or the LUT bytes (`FUR_ERR_OVERLAP`).
///
/// # Safety
/// `lut` is NULL or points to an initialised `fur_lut`; `out` is NULL or points to a
/// writable `fur_sample`.
#[no_mangle]
pub unsafe extern "C" fn fur_sample_far(
    lut: *const fur_lut,
    theta_r: f32,
    u0: f32,
    u1: f32,
    u2: f32,
    out: *mut fur_sample,
) -> fur_status {
    // SAFETY: forwarded caller guarantee on `lut`.
    let open = tri!(unsafe { opened(lut) });
    tri!(check_ptr(out));
    tri!(disjoint(Region::of(out, 1), &open.regions));
    if !(theta_r.is_finite() && theta_r.abs() <= core::f32::consts::FRAC_PI_2) {
        return fur_status::FUR_ERR_ANGLE;
    }
    let Some(s) = open.lut.sample(theta_r, [u0, u1, u2]) else {
        return fur_status::FUR_ERR_NO_SAMPLE;
    };
    // SAFETY: non-NULL and aligned (checked); a writable fur_sample by the caller's
    // contract.
    unsafe { out.write(record(&s)) };
    fur_status::FUR_OK
}

/// The C record of a sample.
fn record(s: &Sample) -> fur_sample {
    let family = match s.family {
        LobeFamily::R => fur_family::FUR_FAMILY_R,
        LobeFamily::TT => fur_family::FUR_FAMILY_TT,
        LobeFamily::TRT => fur_family::FUR_FAMILY_TRT,
        LobeFamily::Scattered => fur_family::FUR_FAMILY_SCATTERED,
    };
    fur_sample {
        theta_i: s.angles.theta_i(),
        phi: s.angles.phi(),
        pdf: s.pdf,
        weight: s.weight.0,
        family,
    }
}

/// One bounce of a path tracer with multiple importance sampling in one call (docs/model.md
/// section 10): importance-samples omega_i given theta_r into `*out` (as `fur_sample_far`)
/// and writes into `*out_pdf` the density of another direction at the same view, (theta_i,
/// theta_r, phi) (a light's, as `fur_pdf_far`). The work that depends on theta_r alone is
/// done once for both. Bit for bit the results of `fur_sample_far` and `fur_pdf_far`.
///
/// Returns `FUR_ERR_ANGLE` (nothing written) for an invalid theta_r, theta_i or phi, and
/// `FUR_ERR_NO_SAMPLE` when nothing can be sampled (`*out_pdf` is still written; `*out` is
/// not). `out` and `out_pdf` must not overlap each other, `*lut` or the LUT bytes
/// (`FUR_ERR_OVERLAP`).
///
/// # Safety
/// `lut` is NULL or points to an initialised `fur_lut`; `out` is NULL or points to a
/// writable `fur_sample`; `out_pdf` is NULL or points to a writable float.
#[no_mangle]
#[allow(clippy::too_many_arguments)] // the C signature: three uniforms and two angles
pub unsafe extern "C" fn fur_sample_pdf_far(
    lut: *const fur_lut,
    theta_r: f32,
    u0: f32,
    u1: f32,
    u2: f32,
    theta_i: f32,
    phi: f32,
    out: *mut fur_sample,
    out_pdf: *mut f32,
) -> fur_status {
    // SAFETY: forwarded caller guarantee on `lut`.
    let open = tri!(unsafe { opened(lut) });
    tri!(check_ptr(out));
    tri!(check_ptr(out_pdf));
    tri!(disjoint(Region::of(out, 1), &open.regions));
    tri!(disjoint(Region::of(out_pdf, 1), &open.regions));
    tri!(disjoint(Region::of(out_pdf, 1), &[Region::of(out, 1)]));
    let light = tri!(angles(theta_i, theta_r, phi));
    let Some(view) = open.lut.view(theta_r) else {
        return fur_status::FUR_ERR_ANGLE;
    };
    let pdf = view.pdf(light.theta_i(), light.phi());
    // SAFETY: non-NULL and aligned (checked); a writable float by the caller's contract,
    // disjoint from every other region this call touches (checked).
    unsafe { out_pdf.write(pdf) };
    let Some(s) = view.sample([u0, u1, u2]) else {
        return fur_status::FUR_ERR_NO_SAMPLE;
    };
    // SAFETY: non-NULL and aligned (checked); a writable fur_sample by the caller's
    // contract, disjoint from `*out_pdf`, `*lut` and the LUT bytes (checked).
    unsafe { out.write(record(&s)) };
    fur_status::FUR_OK
}

/// Density per unit solid angle with which `fur_sample_far` draws omega_i given omega_r; 0
/// for invalid arguments (NULL, unopened or other-build `lut`, invalid angles).
///
/// # Safety
/// `lut` is NULL or points to an initialised `fur_lut`.
#[no_mangle]
pub unsafe extern "C" fn fur_pdf_far(
    lut: *const fur_lut,
    theta_i: f32,
    theta_r: f32,
    phi: f32,
) -> f32 {
    // SAFETY: forwarded caller guarantee on `lut`.
    match (unsafe { opened(lut) }, angles(theta_i, theta_r, phi)) {
        (Ok(open), Ok(a)) => open.lut.pdf(&a),
        _ => 0.0,
    }
}
