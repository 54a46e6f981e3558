//! The colour of a query in the C ABI (LUT format 5, docs/lut.md "The absorption axis"): the
//! cortex absorption σ_ca per RGB channel, passed as `const float sigma_ca[3]` to the `*_at`
//! entry points of `eval.rs`, checked here, and the two helpers that give one: from melanin
//! concentrations (`fur_sigma_from_melanin`) and the LUT's own (`fur_lut_sigma_ca`).
//!
//! The rule is `bcsdf_core::Absorption`'s: each channel in [0, 1000] per fiber radius; NaN
//! and negative values are refused (`FUR_ERR_COLOUR`), values above 1000 (+inf included) are
//! clamped to 1000.

use crate::args::{check_ptr, disjoint, read3, write3, Region};
use crate::handle::opened;
use crate::{fur_lut, fur_status};
use bcsdf_core::{Absorption, Rgb};

/// A colour argument: three floats at `sigma_ca`, checked for NULL and alignment
/// (`FUR_ERR_NULL`, `FUR_ERR_ALIGNMENT`), then validated (`FUR_ERR_COLOUR`).
///
/// # Safety
/// `sigma_ca` is NULL or points to 3 readable floats.
pub(crate) unsafe fn read_colour(sigma_ca: *const f32) -> Result<Absorption, fur_status> {
    // SAFETY: forwarded caller guarantee on `sigma_ca`.
    let s = unsafe { read3(sigma_ca) }?;
    colour_of(s)
}

/// Three σ_ca values as a validated colour (`FUR_ERR_COLOUR` for a NaN or negative channel).
pub(crate) fn colour_of(sigma: [f32; 3]) -> Result<Absorption, fur_status> {
    Absorption::from_sigma(Rgb(sigma)).map_err(|_| fur_status::FUR_ERR_COLOUR)
}

/// The colour of eumelanin and pheomelanin concentrations (the mix of the parameters'
/// `melanin` pigment, docs/model.md §2), as σ_ca per RGB channel into `out_sigma_ca[3]`, for
/// the `*_at` functions. A NaN or negative concentration gives `FUR_ERR_COLOUR` (nothing
/// written); channels above 1000 are clamped to 1000.
///
/// # Safety
/// `out_sigma_ca` is NULL or points to 3 writable floats.
#[no_mangle]
pub unsafe extern "C" fn fur_sigma_from_melanin(
    eumelanin: f32,
    pheomelanin: f32,
    out_sigma_ca: *mut f32,
) -> fur_status {
    tri!(check_ptr(out_sigma_ca));
    let a = match Absorption::from_melanin(eumelanin, pheomelanin) {
        Ok(a) => a,
        Err(_) => return fur_status::FUR_ERR_COLOUR,
    };
    // SAFETY: non-NULL and aligned (checked); 3 writable floats by the caller's contract.
    unsafe { write3(out_sigma_ca, a.sigma().0) };
    fur_status::FUR_OK
}

/// The LUT's own colour, the σ_ca of the parameters it was baked with (clamped to 1000), into
/// `out_sigma_ca[3]`: what every function without `_at` evaluates, bit for bit
/// (`fur_eval_far_at(lut, sigma, ...)` with this `sigma` equals `fur_eval_far(lut, ...)`).
/// `out_sigma_ca` must not overlap `*lut` or the LUT bytes (`FUR_ERR_OVERLAP`).
///
/// # Safety
/// `lut` is NULL or points to an initialised `fur_lut`; `out_sigma_ca` is NULL or points to 3
/// writable floats.
#[no_mangle]
pub unsafe extern "C" fn fur_lut_sigma_ca(
    lut: *const fur_lut,
    out_sigma_ca: *mut f32,
) -> fur_status {
    // SAFETY: forwarded caller guarantee on `lut`.
    let open = tri!(unsafe { opened(lut) });
    tri!(check_ptr(out_sigma_ca));
    tri!(disjoint(Region::of(out_sigma_ca, 3), &open.regions));
    // SAFETY: non-NULL and aligned (checked); 3 writable floats by the caller's contract,
    // outside `*lut` and the LUT bytes (checked).
    unsafe { write3(out_sigma_ca, open.lut.absorption().sigma().0) };
    fur_status::FUR_OK
}

#[cfg(test)]
mod tests {
    //! The `_at` entry points called from Rust on a small synthetic LUT, against
    //! `BakedBcsdf::at` bit for bit, and their refusals (also run under Miri:
    //! `cargo +nightly miri test -p bcsdf-ffi --lib colour`).
    use crate::eval::*;
    use crate::sample::*;
    use crate::{fur_lut, fur_sample, fur_status, FUR_LUT_INIT};
    use bcsdf_core::lut::{self, LutHeader, LutResolution, HEADER_LEN, TABLE_COUNT};
    use bcsdf_core::rng::Pcg32;
    use bcsdf_core::{presets, Absorption, Angles, BakedBcsdf, Bcsdf, Closure, FurParamsInput};
    use bcsdf_core::{Rgb, Sample};
    use core::ptr::null;

    /// A valid LUT of random tables, 4 absorption planes, small enough for Miri.
    fn blob() -> Vec<u8> {
        let res = LutResolution {
            n_sum: 8,
            n_theta_r: 3,
            n_phi: 5,
            n_ms_i: 3,
            n_ms_r: 3,
            n_abs: 4,
        };
        let header = LutHeader {
            res,
            scales: [1.0; TABLE_COUNT],
            params: FurParamsInput {
                closure: Closure::Report,
                ..presets::find("bobcat").unwrap().input
            },
            profiles: None,
        };
        let mut blob = vec![0u8; res.blob_len()];
        blob[..HEADER_LEN].copy_from_slice(&header.encode());
        let mut rng = Pcg32::new(5, 9);
        for half in blob[HEADER_LEN..res.sampling_start()].chunks_exact_mut(2) {
            // Halves in [0.125, 1): every texel of every plane differs.
            let bits = 0x3000u16 + (rng.uniform() * 3072.0) as u16;
            half.copy_from_slice(&bits.to_le_bytes());
        }
        lut::seal(&mut blob);
        blob
    }

    /// Random colours: channels 0, within the axis's knee, ≥ 100, and above 1000 (clamped).
    fn colours(n: usize) -> Vec<[f32; 3]> {
        let mut rng = Pcg32::new(77, 1);
        let mut channel = |k: usize| match k % 4 {
            0 => 0.0,
            1 => rng.uniform() * 4.0,
            2 => 100.0 + rng.uniform() * 900.0,
            _ => 1000.0 + rng.uniform() * 5.0e4,
        };
        (0..n)
            .map(|i| [channel(i), channel(i / 4 + 1), channel(i / 16 + 2)])
            .collect()
    }

    fn bits3(v: [f32; 3]) -> [u32; 3] {
        v.map(f32::to_bits)
    }

    fn same_sample(c: &fur_sample, s: &Sample) {
        assert_eq!(c.theta_i.to_bits(), s.angles.theta_i().to_bits());
        assert_eq!(c.phi.to_bits(), s.angles.phi().to_bits());
        assert_eq!(c.pdf.to_bits(), s.pdf.to_bits());
        assert_eq!(bits3(c.weight), bits3(s.weight.0));
        assert_eq!(c.family as usize, s.family as usize);
    }

    #[test]
    fn the_at_functions_equal_the_core_at_random_colours() {
        let bytes = blob();
        let want = BakedBcsdf::from_bytes(&bytes).unwrap();
        let mut l: Box<fur_lut> = Box::new(FUR_LUT_INIT);
        let lut: *mut fur_lut = &mut *l;
        let qs = [(0.5f32, -0.35f32, 0.785f32), (-1.2, 0.9, -2.9)];
        let n = if cfg!(miri) { 6 } else { 64 };
        let cs = colours(n);
        let mut distinct = 0;
        // SAFETY: `lut` is a live fur_lut opened on `bytes`, which outlive it (closed at the
        // end); every pointer below is a live array of the length the call reads or writes.
        unsafe {
            assert_eq!(
                crate::fur_lut_open(bytes.as_ptr(), bytes.len(), lut),
                fur_status::FUR_OK
            );
            let lut = lut.cast_const();
            for c in &cs {
                let at = want.at(&Absorption::from_sigma(Rgb(*c)).unwrap());
                for &(ti, tr, ph) in &qs {
                    let a = Angles::new(ti, tr, ph).unwrap();
                    let mut rgb = [-1.0f32; 3];
                    let st = fur_eval_far_at(lut, c.as_ptr(), ti, tr, ph, rgb.as_mut_ptr());
                    assert_eq!(st, fur_status::FUR_OK);
                    assert_eq!(bits3(rgb), bits3(at.eval(&a).total().0), "{c:?}");
                    distinct += usize::from(rgb != want.eval(&a).total().0);
                    let mut fam = [-1.0f32; 12];
                    let st =
                        fur_eval_far_families_at(lut, c.as_ptr(), ti, tr, ph, fam.as_mut_ptr());
                    assert_eq!(st, fur_status::FUR_OK);
                    let f: Vec<f32> = at.eval(&a).as_array().iter().flat_map(|x| x.0).collect();
                    assert_eq!(
                        fam.map(f32::to_bits).to_vec(),
                        f.iter().map(|x| x.to_bits()).collect::<Vec<_>>()
                    );
                    let p = fur_pdf_far_at(lut, c.as_ptr(), ti, tr, ph);
                    assert_eq!(p.to_bits(), at.pdf(&a).to_bits());
                    // The pdf is the lossless plane's: the same at every colour.
                    assert_eq!(p.to_bits(), want.pdf(&a).to_bits());
                    let u = [0.3, 0.6, 0.2];
                    let mut s = core::mem::zeroed::<fur_sample>();
                    let st = fur_sample_far_at(lut, c.as_ptr(), tr, u[0], u[1], u[2], &mut s);
                    assert_eq!(st, fur_status::FUR_OK);
                    same_sample(&s, &at.sample(tr, u).unwrap());
                    let mut pl = -1.0f32;
                    let st = fur_sample_pdf_far_at(
                        lut,
                        c.as_ptr(),
                        tr,
                        u[0],
                        u[1],
                        u[2],
                        -ti,
                        ph,
                        &mut s,
                        &mut pl,
                    );
                    assert_eq!(st, fur_status::FUR_OK);
                    same_sample(&s, &at.sample(tr, u).unwrap());
                    let light = Angles::new(-ti, tr, ph).unwrap();
                    assert_eq!(pl.to_bits(), at.pdf(&light).to_bits());
                }
                let (wi, wr, t) = ([0.3f32, 0.8, 0.2], [-0.6f32, 0.7, -0.1], [0.0f32, 0.2, 1.0]);
                let mut rgb = [-1.0f32; 3];
                let st = fur_eval_far_dirs_at(
                    lut,
                    c.as_ptr(),
                    wi.as_ptr(),
                    wr.as_ptr(),
                    t.as_ptr(),
                    rgb.as_mut_ptr(),
                );
                assert_eq!(st, fur_status::FUR_OK);
                assert_eq!(bits3(rgb), bits3(at.eval_dirs(wi, wr, t).total().0));
            }
            // The colour changes the values (a test of the colour, not of the preset's).
            assert!(distinct * 2 > cs.len() * qs.len(), "{distinct}");

            // The batch, across its 32-query passes: each entry as fur_eval_far_at.
            let m = if cfg!(miri) { 35 } else { 100 };
            let cs = colours(m);
            let mut rng = Pcg32::new(3, 4);
            let mut ang = || (rng.uniform() - 0.5) * 3.1;
            let ti: Vec<f32> = (0..m).map(|_| ang()).collect();
            let tr: Vec<f32> = (0..m).map(|_| ang()).collect();
            let ph: Vec<f32> = (0..m).map(|_| 2.0 * ang()).collect();
            let flat: Vec<f32> = cs.iter().flatten().copied().collect();
            let mut out = vec![-1.0f32; 3 * m];
            let st = fur_eval_far_batch_at(
                lut,
                m,
                flat.as_ptr(),
                ti.as_ptr(),
                tr.as_ptr(),
                ph.as_ptr(),
                out.as_mut_ptr(),
            );
            assert_eq!(st, fur_status::FUR_OK);
            for k in 0..m {
                let mut one = [0.0f32; 3];
                fur_eval_far_at(lut, cs[k].as_ptr(), ti[k], tr[k], ph[k], one.as_mut_ptr());
                assert_eq!(
                    bits3(one),
                    bits3([out[3 * k], out[3 * k + 1], out[3 * k + 2]]),
                    "{k}"
                );
            }
            // One refused colour (entry 33) and one invalid angle (entry 2): zeros there,
            // every other entry unchanged, the colour's status first.
            let mut bad = flat.clone();
            bad[3 * 33 + 1] = f32::NAN;
            let mut ti_bad = ti.clone();
            ti_bad[2] = 2.0;
            let mut out2 = vec![-1.0f32; 3 * m];
            let st = fur_eval_far_batch_at(
                lut,
                m,
                bad.as_ptr(),
                ti_bad.as_ptr(),
                tr.as_ptr(),
                ph.as_ptr(),
                out2.as_mut_ptr(),
            );
            assert_eq!(st, fur_status::FUR_ERR_COLOUR);
            for k in 0..m {
                let got = &out2[3 * k..3 * k + 3];
                if k == 33 || k == 2 {
                    assert_eq!(got, [0.0; 3]);
                } else {
                    assert_eq!(got, &out[3 * k..3 * k + 3], "{k}");
                }
            }
            let st = fur_eval_far_batch_at(
                lut,
                m,
                flat.as_ptr(),
                ti_bad.as_ptr(),
                tr.as_ptr(),
                ph.as_ptr(),
                out2.as_mut_ptr(),
            );
            assert_eq!(st, fur_status::FUR_ERR_ANGLE);
            let close = crate::fur_lut_close(lut.cast_mut());
            assert_eq!(close, fur_status::FUR_OK);
        }
    }

    #[test]
    fn the_preset_colour_and_refusals() {
        let bytes = blob();
        let want = BakedBcsdf::from_bytes(&bytes).unwrap();
        let mut l: Box<fur_lut> = Box::new(FUR_LUT_INIT);
        let lut: *mut fur_lut = &mut *l;
        // SAFETY: as in the test above; the misaligned pointer is only checked, never read.
        unsafe {
            assert_eq!(
                crate::fur_lut_open(bytes.as_ptr(), bytes.len(), lut),
                fur_status::FUR_OK
            );
            let lut = lut.cast_const();
            // The LUT's own colour: the functions without `_at`, bit for bit.
            let mut own = [-1.0f32; 3];
            assert_eq!(
                super::fur_lut_sigma_ca(lut, own.as_mut_ptr()),
                fur_status::FUR_OK
            );
            assert_eq!(own, want.absorption().sigma().0);
            assert!(own.iter().all(|&s| s > 0.0));
            let (ti, tr, ph) = (0.4f32, -0.2f32, 2.2f32);
            let (mut a, mut b) = ([0.0f32; 3], [0.0f32; 3]);
            fur_eval_far(lut, ti, tr, ph, a.as_mut_ptr());
            fur_eval_far_at(lut, own.as_ptr(), ti, tr, ph, b.as_mut_ptr());
            assert_eq!(bits3(a), bits3(b));

            // Melanin: Absorption::from_melanin's colour; NaN and negative refused.
            let mut m = [-1.0f32; 3];
            assert_eq!(
                super::fur_sigma_from_melanin(0.4, 1.5, m.as_mut_ptr()),
                fur_status::FUR_OK
            );
            assert_eq!(m, Absorption::from_melanin(0.4, 1.5).unwrap().sigma().0);
            let mut m2 = [-1.0f32; 3];
            for (e, p) in [(f32::NAN, 0.0), (0.0, -1.0)] {
                let st = super::fur_sigma_from_melanin(e, p, m2.as_mut_ptr());
                assert_eq!(st, fur_status::FUR_ERR_COLOUR);
            }
            assert_eq!(m2, [-1.0; 3]);
            assert_eq!(
                super::fur_sigma_from_melanin(0.4, 1.5, core::ptr::null_mut()),
                fur_status::FUR_ERR_NULL
            );

            // Refused colours: 0 written, FUR_ERR_COLOUR; NULL and misaligned colours.
            for bad in [
                [f32::NAN, 0.0, 0.0],
                [0.5, -1e-9, 0.0],
                [0.5, 0.5, f32::NEG_INFINITY],
            ] {
                let mut rgb = [-1.0f32; 3];
                let st = fur_eval_far_at(lut, bad.as_ptr(), ti, tr, ph, rgb.as_mut_ptr());
                assert_eq!((st, rgb), (fur_status::FUR_ERR_COLOUR, [0.0; 3]));
                let mut fam = [-1.0f32; 12];
                let st = fur_eval_far_families_at(lut, bad.as_ptr(), ti, tr, ph, fam.as_mut_ptr());
                assert_eq!((st, fam), (fur_status::FUR_ERR_COLOUR, [0.0; 12]));
                let v = [0.3f32, 0.8, 0.2];
                let st = fur_eval_far_dirs_at(
                    lut,
                    bad.as_ptr(),
                    v.as_ptr(),
                    v.as_ptr(),
                    v.as_ptr(),
                    rgb.as_mut_ptr(),
                );
                assert_eq!(st, fur_status::FUR_ERR_COLOUR);
                assert_eq!(fur_pdf_far_at(lut, bad.as_ptr(), ti, tr, ph), 0.0);
                let mut s = core::mem::zeroed::<fur_sample>();
                s.pdf = -1.0;
                let st = fur_sample_far_at(lut, bad.as_ptr(), tr, 0.5, 0.5, 0.5, &mut s);
                assert_eq!(st, fur_status::FUR_ERR_COLOUR);
                let mut p = -1.0f32;
                let st = fur_sample_pdf_far_at(
                    lut,
                    bad.as_ptr(),
                    tr,
                    0.5,
                    0.5,
                    0.5,
                    ti,
                    ph,
                    &mut s,
                    &mut p,
                );
                assert_eq!((st, p, s.pdf), (fur_status::FUR_ERR_COLOUR, -1.0, -1.0));
            }
            let mut rgb = [0.0f32; 4];
            let good = [0.1f32, 0.2, 0.3, 0.0];
            assert_eq!(
                fur_eval_far_at(lut, null(), ti, tr, ph, rgb.as_mut_ptr()),
                fur_status::FUR_ERR_NULL
            );
            let misaligned = good.as_ptr().cast::<u8>().add(1).cast::<f32>();
            assert_eq!(
                fur_eval_far_at(lut, misaligned, ti, tr, ph, rgb.as_mut_ptr()),
                fur_status::FUR_ERR_ALIGNMENT
            );
            assert_eq!(fur_pdf_far_at(lut, null(), ti, tr, ph), 0.0);
            // The output overlapping the colour: refused, nothing written.
            let mut shared = [0.1f32, 0.2, 0.3, 0.4];
            let p = shared.as_mut_ptr();
            assert_eq!(
                fur_eval_far_at(lut, p, ti, tr, ph, p.add(1)),
                fur_status::FUR_ERR_OVERLAP
            );
            assert_eq!(shared, [0.1, 0.2, 0.3, 0.4]);
            let st = fur_eval_far_batch_at(
                lut,
                1,
                p,
                [ti].as_ptr(),
                [tr].as_ptr(),
                [ph].as_ptr(),
                p.add(2),
            );
            assert_eq!(st, fur_status::FUR_ERR_OVERLAP);
            let st = fur_eval_far_batch_at(
                lut,
                1,
                null(),
                [ti].as_ptr(),
                [tr].as_ptr(),
                [ph].as_ptr(),
                p,
            );
            assert_eq!(st, fur_status::FUR_ERR_NULL);
            assert_eq!(
                super::fur_lut_sigma_ca(lut, lut.cast::<f32>().cast_mut().add(4)),
                fur_status::FUR_ERR_OVERLAP
            );
            let close = crate::fur_lut_close(lut.cast_mut());
            assert_eq!(close, fur_status::FUR_OK);
            let mut rgb = [-1.0f32; 3];
            assert_eq!(
                fur_eval_far_at(lut, good.as_ptr(), ti, tr, ph, rgb.as_mut_ptr()),
                fur_status::FUR_ERR_NOT_OPEN
            );
        }
    }
}
