//! Tests of the C ABI's dual-scattering entry points.

//! The entry points called from Rust on small synthetic tables (also run under Miri:
//! `cargo +nightly miri test -p bcsdf-ffi --lib dual`).
use super::*;
use crate::FUR_DUAL_INIT;
use bcsdf_core::dual::{encode, Attenuation, DualTables, BLOB_LEN};
use bcsdf_core::Rgb;

/// A `.furdual` blob of uniform, non-zero tables.
fn blob() -> Vec<u8> {
    let mut t = Box::new(DualTables::ZERO);
    for f in t.fiber.iter_mut() {
        f.a_f = Rgb([0.6, 0.5, 0.4]);
        f.a_b = Rgb([0.2, 0.2, 0.1]);
        f.beta2_f = Rgb([0.01; 3]);
        f.big_a_b = Rgb([0.1; 3]);
        f.sigma_b0 = Rgb([0.1; 3]);
    }
    for row in t.moments.iter_mut() {
        for m in row.iter_mut() {
            m.variance = Rgb([0.02; 3]);
        }
    }
    for g in t.n_g.iter_mut() {
        for row in g.iter_mut() {
            row.fill(Rgb([0.1; 3]));
        }
    }
    encode(&t, Attenuation::Coat, 42).to_vec()
}

#[test]
fn opens_evaluates_like_the_core_refuses_and_closes() {
    let bytes = blob();
    // The core's own decode, to compare bit for bit. Under Miri, which is here for the
    // unsafe code of the entry points, it is skipped: a decode of the 55 KB blob takes the
    // interpreter about a minute, and the comparison is the same in the plain test run.
    let want = (!cfg!(miri)).then(|| {
        let mut w = Box::new(DualLut::EMPTY);
        w.decode(&bytes).unwrap();
        w
    });
    let mut d: Box<fur_dual> = Box::new(FUR_DUAL_INIT);
    let p: *mut fur_dual = &mut *d;
    let mut rgb = [-1.0f32; 3];
    let out = rgb.as_mut_ptr();
    // SAFETY: for every call below, `p` is a live, aligned fur_dual, `bytes` a live buffer of
    // its length, `out` 3 writable floats; the vectors are live arrays.
    unsafe {
        assert_eq!(
            fur_eval_dual(
                p,
                0.1,
                0.2,
                0.3,
                1.0,
                f32::INFINITY,
                1.0,
                1.0,
                core::ptr::null(),
                out
            ),
            fur_status::FUR_ERR_NOT_OPEN
        );
        assert_eq!(
            fur_dual_open(bytes.as_ptr(), bytes.len(), p),
            fur_status::FUR_OK
        );
        // Pairing needs an open fur_lut (the C clients pair real files): a never-opened
        // one and NULL are refused without reading further.
        let never = Box::new(crate::FUR_LUT_INIT);
        assert_eq!(fur_dual_check_lut(p, &*never), fur_status::FUR_ERR_NOT_OPEN);
        assert_eq!(
            fur_dual_check_lut(p, core::ptr::null()),
            fur_status::FUR_ERR_NULL
        );
        assert_eq!(
            fur_dual_check_lut(core::ptr::null(), &*never),
            fur_status::FUR_ERR_NULL
        );
        let a = Angles::new(0.3, -0.2, 2.5).unwrap();
        for n in [0.0, 0.5, 2.0, f32::NAN] {
            for m in [0.0, 2.5, f32::INFINITY, f32::NAN] {
                assert_eq!(
                    fur_eval_dual(p, 0.3, -0.2, 2.5, n, m, 1.0, 1.0, core::ptr::null(), out),
                    fur_status::FUR_OK
                );
                if let Some(want) = &want {
                    let w = want
                        .eval(&a, Fibers::new(n, m), Density { d_f: 1.0, d_b: 1.0 })
                        .0;
                    assert_eq!(rgb.map(f32::to_bits), w.map(f32::to_bits));
                }
            }
        }
        // A colour: each channel at its own σ_ca, `DualLut::eval_at` bit for bit; NaN or
        // negative channels refused with zeros written.
        for sigma in [[0.0f32, 0.2, 0.4], [0.05, 3.0, 700.0], [2.0e3, 0.3, 1.0]] {
            assert_eq!(
                fur_eval_dual(p, 0.3, -0.2, 2.5, 2.0, 1.5, 1.0, 1.0, sigma.as_ptr(), out),
                fur_status::FUR_OK
            );
            if let Some(want) = &want {
                let colour = Absorption::from_sigma(Rgb(sigma)).unwrap();
                let w = want
                    .eval_at(
                        &a,
                        Fibers::new(2.0, 1.5),
                        Density { d_f: 1.0, d_b: 1.0 },
                        &colour,
                    )
                    .0;
                assert_eq!(rgb.map(f32::to_bits), w.map(f32::to_bits));
            }
        }
        for bad in [[f32::NAN, 0.2, 0.4], [0.1, -1.0, 0.4]] {
            out.cast::<[f32; 3]>().write([-1.0; 3]); // through `out`: a direct write to `rgb` would retire it
            assert_eq!(
                fur_eval_dual(p, 0.3, -0.2, 2.5, 2.0, 1.5, 1.0, 1.0, bad.as_ptr(), out),
                fur_status::FUR_ERR_COLOUR
            );
            assert_eq!(rgb, [0.0; 3]);
            out.cast::<[f32; 3]>().write([-1.0; 3]);
            let (wi, wr, t) = ([0.3f32, 0.8, 0.2], [-0.6f32, 0.7, -0.1], [0.0f32, 0.2, 1.0]);
            assert_eq!(
                fur_eval_dual_dirs(
                    p,
                    wi.as_ptr(),
                    wr.as_ptr(),
                    t.as_ptr(),
                    2.0,
                    1.5,
                    1.0,
                    1.0,
                    bad.as_ptr(),
                    out
                ),
                fur_status::FUR_ERR_COLOUR
            );
            assert_eq!(rgb, [0.0; 3]);
        }
        // The count below matters: no fibers below reflect less than the deep coat.
        let mut deep = [0.0f32; 3];
        assert_eq!(
            fur_eval_dual(
                p,
                0.3,
                -0.2,
                2.5,
                2.0,
                f32::INFINITY,
                1.0,
                1.0,
                core::ptr::null(),
                deep.as_mut_ptr()
            ),
            fur_status::FUR_OK
        );
        assert!(deep.iter().any(|&v| v > 0.0));
        assert_eq!(
            fur_eval_dual(
                p,
                0.3,
                -0.2,
                2.5,
                2.0,
                0.0,
                1.0,
                1.0,
                core::ptr::null(),
                out
            ),
            fur_status::FUR_OK
        );
        assert!(rgb.iter().zip(&deep).all(|(s, d)| s < d));
        let (wi, wr, t) = ([0.3f32, 0.8, 0.2], [-0.6f32, 0.7, -0.1], [0.0f32, 0.2, 1.0]);
        for m in [0.0, 2.5, f32::INFINITY] {
            assert_eq!(
                fur_eval_dual_dirs(
                    p,
                    wi.as_ptr(),
                    wr.as_ptr(),
                    t.as_ptr(),
                    2.0,
                    m,
                    0.5,
                    2.0,
                    core::ptr::null(),
                    out
                ),
                fur_status::FUR_OK
            );
            if let Some(want) = &want {
                let w = want
                    .eval_dirs(
                        wi,
                        wr,
                        t,
                        Fibers::new(2.0, m),
                        Density { d_f: 0.5, d_b: 2.0 },
                    )
                    .0;
                assert_eq!(rgb.map(f32::to_bits), w.map(f32::to_bits));
            }
        }
        assert_eq!(
            fur_eval_dual(
                p,
                0.3,
                -0.2,
                2.5,
                2.0,
                0.0,
                1.0,
                1.0,
                core::ptr::null(),
                p.cast::<f32>().add(8)
            ),
            fur_status::FUR_ERR_OVERLAP
        );

        // Another build's tag is refused. (The handle stays open for the refusals below, so
        // the blob is decoded once: under Miri a decode of it takes minutes.)
        (*p)._opaque[1] ^= 1;
        assert_eq!(
            fur_eval_dual(
                p,
                0.1,
                0.2,
                0.3,
                1.0,
                f32::INFINITY,
                1.0,
                1.0,
                core::ptr::null(),
                out
            ),
            fur_status::FUR_ERR_OTHER_BUILD
        );
        (*p)._opaque[1] ^= 1;

        // A refused blob closes the open handle (zeroes it); later refusals leave it so.
        assert_eq!(
            fur_dual_open(bytes.as_ptr(), BLOB_LEN - 1, p),
            fur_status::FUR_ERR_DUAL_LENGTH
        );
        assert!(d._opaque.iter().all(|&w| w == 0));
        let mut bad = bytes.clone();
        // A damaged byte: the checksum (a pass over the whole blob, which the interpreter
        // is spared: the refusal path's unsafe code is the length refusal's above).
        if !cfg!(miri) {
            bad[1000] ^= 1;
            assert_eq!(
                fur_dual_open(bad.as_ptr(), bad.len(), p),
                fur_status::FUR_ERR_DUAL_CHECKSUM
            );
            bad.copy_from_slice(&bytes);
        }
        bad[0] = b'X';
        assert_eq!(
            fur_dual_open(bad.as_ptr(), bad.len(), p),
            fur_status::FUR_ERR_DUAL_FORMAT
        );
        assert_eq!(
            fur_eval_dual(
                p,
                0.1,
                0.2,
                0.3,
                1.0,
                f32::INFINITY,
                1.0,
                1.0,
                core::ptr::null(),
                out
            ),
            fur_status::FUR_ERR_NOT_OPEN
        );
        // Closing a closed handle is allowed and keeps it zeroed.
        assert_eq!(fur_dual_close(p), fur_status::FUR_OK);
    }
    assert!(d._opaque.iter().all(|&w| w == 0));
}
