//! Exercises the core from a `#![no_std]` staticlib: every public evaluation path with both
//! math backends, so that the linker sees all of it.
#![no_std]
#![deny(clippy::undocumented_unsafe_blocks)]

/// The panic handler (a trap instruction, never a spin loop) and the unwinding personality
/// stub, shared with bcsdf-ffi's no_std build.
#[path = "../../../bcsdf-ffi/src/nostd.rs"]
mod nostd;

use bcsdf_core::medulla::{generate, MedullaProfiles, PhotonBudget, ProfileLayout, Resolution};
use bcsdf_core::baked::BakedBcsdf;
use bcsdf_core::lut::{self, LutHeader, LutResolution};
use bcsdf_core::{presets, Angles, Bcsdf, FastMath, FurBcsdf, FurParams, Libm, Math};

fn eval<M: Math>(preset: usize, ti: f32, tr: f32, phi: f32, h: f32) -> f32 {
    let Some(p) = presets::PRESETS.get(preset) else {
        return -1.0;
    };
    let Ok(params) = FurParams::new(&p.input) else {
        return -1.0;
    };
    let model = FurBcsdf::<M>::unscattered(params);
    let Ok(angles) = Angles::new(ti, tr, phi) else {
        return -1.0;
    };
    let far = model.eval_far(&angles).total();
    let near = model.eval_near(&angles, h).total();
    let dirs = model
        .eval_far_dirs([1.0, 0.0, 0.2], [0.0, 1.0, -0.1], [0.0, 0.0, 1.0])
        .total();
    far.0[0] + near.0[1] + dirs.0[2]
}

/// C entry point: far + near + direction-based evaluation with the libm backend.
#[no_mangle]
pub extern "C" fn fur_eval_libm(preset: usize, ti: f32, tr: f32, phi: f32, h: f32) -> f32 {
    eval::<Libm>(preset, ti, tr, phi, h)
}

/// C entry point: the same with the micromath backend.
#[no_mangle]
pub extern "C" fn fur_eval_fast(preset: usize, ti: f32, tr: f32, phi: f32, h: f32) -> f32 {
    eval::<FastMath>(preset, ti, tr, phi, h)
}

/// Small profile tables, generated in caller (stack) memory, then the full model.
const RES: Resolution = Resolution {
    n_sigma: 2,
    n_h: 4,
    n_psi: 16,
    n_in: 2,
    n_out: 8,
};

fn eval_full<M: Math>(preset: usize, ti: f32, tr: f32, phi: f32, h: f32) -> f32 {
    let Some(p) = presets::PRESETS.get(preset) else {
        return -1.0;
    };
    let Ok(params) = FurParams::new(&p.input) else {
        return -1.0;
    };
    let layout = ProfileLayout::for_params(&params, RES);
    let mut cn = [0.0f32; 2 * 4 * 16];
    let mut cm = [0.0f32; 2 * 2 * 8];
    let budget = PhotonBudget {
        per_cn_cell: 64,
        per_cm_row: 64,
    };
    if generate(&layout, &budget, 1, &mut cn, &mut cm).is_err() {
        return -1.0;
    }
    let Ok(profiles) = MedullaProfiles::new(layout, &cn, &cm) else {
        return -1.0;
    };
    let Ok(model) = FurBcsdf::<M>::new(params, profiles) else {
        return -1.0;
    };
    let Ok(angles) = Angles::new(ti, tr, phi) else {
        return -1.0;
    };
    let sampled = sample_sum(&model, tr, [0.3, 0.6, 0.9], [0.0, 1.0, -0.1], [0.0, 0.0, 1.0]);
    model.eval_far(&angles).total().0[0] + model.eval_near(&angles, h).total().0[1] + sampled
}

/// Exercises the `Bcsdf` trait: sample, pdf, from angles and from vectors.
fn sample_sum<B: Bcsdf>(m: &B, tr: f32, u: [f32; 3], wr: [f32; 3], t: [f32; 3]) -> f32 {
    let mut acc = 0.0;
    if let Some(s) = m.sample(tr, u) {
        acc += s.pdf + s.weight.0[0] + m.pdf(&s.angles);
    }
    if let Some(s) = m.sample_dirs(wr, t, u) {
        acc += s.pdf + s.weight.0[1] + s.wi.map_or(0.0, |w| w[0]);
    }
    acc
}

/// C entry point: the full model (profiles generated in place) with the libm backend.
#[no_mangle]
pub extern "C" fn fur_eval_full_libm(preset: usize, ti: f32, tr: f32, phi: f32, h: f32) -> f32 {
    eval_full::<Libm>(preset, ti, tr, phi, h)
}

/// C entry point: the full model with the micromath backend.
#[no_mangle]
pub extern "C" fn fur_eval_full_fast(preset: usize, ti: f32, tr: f32, phi: f32, h: f32) -> f32 {
    eval_full::<FastMath>(preset, ti, tr, phi, h)
}

/// A baked LUT borrowed from caller memory (an engine's memory-mapped file or
/// `include_bytes!`): validated, then evaluated. −1 for a rejected blob.
///
/// # Safety
/// `data` must point to `len` readable bytes.
#[no_mangle]
pub unsafe extern "C" fn fur_eval_baked(
    data: *const u8,
    len: usize,
    ti: f32,
    tr: f32,
    phi: f32,
) -> f32 {
    if data.is_null() {
        return -1.0;
    }
    // SAFETY: the caller promises `len` readable bytes at `data`.
    let bytes = unsafe { core::slice::from_raw_parts(data, len) };
    eval_baked(bytes, ti, tr, phi)
}

fn eval_baked(bytes: &[u8], ti: f32, tr: f32, phi: f32) -> f32 {
    let Ok(lut) = BakedBcsdf::from_bytes(bytes) else {
        return -1.0;
    };
    let Ok(angles) = Angles::new(ti, tr, phi) else {
        return -1.0;
    };
    let dirs = lut
        .eval_far_dirs([1.0, 0.0, 0.2], [0.0, 1.0, -0.1], [0.0, 0.0, 1.0])
        .total();
    let sampled = sample_sum(&lut, tr, [0.3, 0.6, 0.9], [0.0, 1.0, -0.1], [0.0, 0.0, 1.0]);
    lut.eval_far(&angles).total().0[0] + dirs.0[1] + sampled
}

/// The smallest LUT (two nodes per axis), written into a stack buffer with the core's own
/// header encoder and checksum, every value 1.0, then evaluated.
#[no_mangle]
pub extern "C" fn fur_eval_baked_small(preset: usize, ti: f32, tr: f32, phi: f32) -> f32 {
    const RES: LutResolution = LutResolution {
        n_sum: 2,
        n_theta_r: 2,
        n_phi: 2,
        n_ms_i: 2,
        n_ms_r: 2,
        n_abs: 3,
    };
    // Header, the three tables (f16), the sampling section (f32 prefix sums: M 3 × 2,
    // N 4 families × 2 rows × 2, M_s 2 halves × 2 rows × 2), the 1/Z_g table (f32: 2 nodes
    // × 3 groups).
    const TABLES: usize = 2 * (2 * 3 + 4 * (2 * 2 * 3) + 2 * 2 * 2);
    const LEN: usize =
        lut::HEADER_LEN + TABLES + 4 * (3 * 2 + 4 * 2 * 2 + 2 * 2 * 2) + 4 * (2 * 3);
    let Some(p) = presets::PRESETS.get(preset) else {
        return -1.0;
    };
    if RES.blob_len() != LEN {
        return -1.0;
    }
    let header = LutHeader {
        res: RES,
        scales: [1.0; lut::TABLE_COUNT],
        params: p.input,
        profiles: None,
    };
    let mut blob = [0u8; LEN];
    blob[..lut::HEADER_LEN].copy_from_slice(&header.encode());
    for pair in blob[lut::HEADER_LEN..lut::HEADER_LEN + TABLES].chunks_exact_mut(2) {
        pair.copy_from_slice(&0x3c00u16.to_le_bytes()); // 1.0 as f16
    }
    lut::seal(&mut blob);
    eval_baked(&blob, ti, tr, phi)
}
