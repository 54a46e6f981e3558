//! The sampling entry points of the C ABI: importance sampling of omega_i given theta_r, its
//! pdf, and both at one view in one call (docs/model.md section 10), each with an `_at`
//! sibling that takes the query's colour as the evaluation entry points do (`eval.rs`).

use crate::args::{check_ptr, disjoint, Region};
use crate::colour::read_colour;
use crate::eval::{angles, with_colour};
use crate::handle::opened;
use crate::{fur_family, fur_lut, fur_sample, fur_status};
use bcsdf_core::{Bcsdf, LobeFamily, Sample};

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

/// `fur_sample_far` at colour `sigma_ca[3]` (as `fur_eval_far_at`): importance-samples
/// omega_i given theta_r into `*out`. The sampled direction and its pdf do not depend on the
/// colour (the sampler draws from the LUT's lossless plane, docs/model.md section 10); the
/// weight S cos(theta_i)/pdf is this colour's. `FUR_ERR_COLOUR` (nothing written) for a NaN
/// or negative channel. `out` must not overlap `sigma_ca`, `*lut` or the LUT bytes
/// (`FUR_ERR_OVERLAP`).
///
/// # Safety
/// `lut` is NULL or points to an initialised `fur_lut`; `sigma_ca` is NULL or points to 3
/// readable floats; `out` is NULL or points to a writable `fur_sample`.
#[no_mangle]
pub unsafe extern "C" fn fur_sample_far_at(
    lut: *const fur_lut,
    sigma_ca: *const f32,
    theta_r: f32,
    u0: f32,
    u1: f32,
    u2: f32,
    out: *mut fur_sample,
) -> fur_status {
    // SAFETY: forwarded caller guarantee on `lut`.
    let open = tri!(unsafe { opened(lut) });
    tri!(check_ptr(out));
    tri!(check_ptr(sigma_ca));
    tri!(disjoint(
        Region::of(out, 1),
        &with_colour(open.regions, sigma_ca)
    ));
    // SAFETY: forwarded caller guarantee on `sigma_ca` (non-NULL and aligned, checked).
    let colour = tri!(unsafe { read_colour(sigma_ca) });
    if !(theta_r.is_finite() && theta_r.abs() <= core::f32::consts::FRAC_PI_2) {
        return fur_status::FUR_ERR_ANGLE;
    }
    let Some(s) = open.lut.at(&colour).sample(theta_r, [u0, u1, u2]) else {
        return fur_status::FUR_ERR_NO_SAMPLE;
    };
    // SAFETY: non-NULL and aligned (checked); a writable fur_sample by the caller's
    // contract.
    unsafe { out.write(record(&s)) };
    fur_status::FUR_OK
}

/// `fur_sample_pdf_far` at colour `sigma_ca[3]` (as `fur_eval_far_at`): a sample (its
/// weight at this colour) and the density of another direction at the same view, bit for
/// bit the results of `fur_sample_far_at` and `fur_pdf_far_at`. `FUR_ERR_COLOUR` (nothing
/// written) for a NaN or negative channel; otherwise as `fur_sample_pdf_far`. `out` and
/// `out_pdf` must not overlap each other, `sigma_ca`, `*lut` or the LUT bytes
/// (`FUR_ERR_OVERLAP`).
///
/// # Safety
/// `lut` is NULL or points to an initialised `fur_lut`; `sigma_ca` is NULL or points to 3
/// readable floats; `out` is NULL or points to a writable `fur_sample`; `out_pdf` is NULL or
/// points to a writable float.
#[no_mangle]
#[allow(clippy::too_many_arguments)] // the C signature: a colour, three uniforms, two angles
pub unsafe extern "C" fn fur_sample_pdf_far_at(
    lut: *const fur_lut,
    sigma_ca: *const f32,
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
    tri!(check_ptr(sigma_ca));
    let inputs = with_colour(open.regions, sigma_ca);
    tri!(disjoint(Region::of(out, 1), &inputs));
    tri!(disjoint(Region::of(out_pdf, 1), &inputs));
    tri!(disjoint(Region::of(out_pdf, 1), &[Region::of(out, 1)]));
    // SAFETY: forwarded caller guarantee on `sigma_ca` (non-NULL and aligned, checked).
    let colour = tri!(unsafe { read_colour(sigma_ca) });
    let light = tri!(angles(theta_i, theta_r, phi));
    let Some(view) = open.lut.at(&colour).view(theta_r) else {
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
    // contract, disjoint from `*out_pdf`, `sigma_ca`, `*lut` and the LUT bytes (checked).
    unsafe { out.write(record(&s)) };
    fur_status::FUR_OK
}

/// `fur_pdf_far` at colour `sigma_ca[3]`: the density with which `fur_sample_far_at` draws
/// omega_i. The sampler draws from the LUT's lossless plane whatever the colour, so this
/// equals `fur_pdf_far` for every valid colour; the colour is taken (and checked) so that a
/// caller passes one set of arguments to every `_at` call. 0 for invalid arguments (NULL,
/// unopened or other-build `lut`, NULL or misaligned `sigma_ca`, a NaN or negative channel,
/// invalid angles).
///
/// # Safety
/// `lut` is NULL or points to an initialised `fur_lut`; `sigma_ca` is NULL or points to 3
/// readable floats.
#[no_mangle]
pub unsafe extern "C" fn fur_pdf_far_at(
    lut: *const fur_lut,
    sigma_ca: *const f32,
    theta_i: f32,
    theta_r: f32,
    phi: f32,
) -> f32 {
    // SAFETY: forwarded caller guarantees on `lut` and `sigma_ca`.
    let (open, colour) = unsafe { (opened(lut), read_colour(sigma_ca)) };
    match (open, colour, angles(theta_i, theta_r, phi)) {
        (Ok(open), Ok(c), Ok(a)) => open.lut.at(&c).pdf(&a),
        _ => 0.0,
    }
}
