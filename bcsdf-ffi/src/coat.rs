//! Base colour → absorption in the C ABI (docs/model.md §14): a preset's coat colour table
//! (`fur_coat`, measured from an open LUT by `fur_coat_measure`) and its inverse per channel,
//! `fur_absorption_from_colour`, whose σ_ca goes to the `*_at` entry points.

use crate::args::{check_ptr, disjoint, read3, write3, Region};
use crate::handle::opened;
use crate::{fur_lut, fur_status};
use bcsdf_core::colour::{CoatColour, CoatWalk, COAT_NODES};
use bcsdf_core::{Absorption, Rgb};

/// Nodes of a coat colour table (`fur_coat`; `bcsdf_core::colour::COAT_NODES`).
pub const FUR_COAT_NODES: usize = 24;
const _: () = assert!(FUR_COAT_NODES == COAT_NODES);

/// A preset's coat colour table (docs/model.md §14): the colour a thick coat of its fibers
/// shows, one channel's value at each node of the absorption axis of `bcsdf_core::colour`
/// (node 0 lossless, the last sigma_ca = 1000), non-increasing. Filled by
/// `fur_coat_measure`; plain data, so it may be stored and copied.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct fur_coat {
    /// The coat colour at each node, in node order.
    pub colour: [f32; FUR_COAT_NODES],
}

/// Measures the coat colour table of an open LUT (docs/model.md §14: a random walk through a
/// thick coat of its fibers, `CoatColour::measure`) into `*out`, with `photons` photons per
/// walk (0: the default, 8192; at most 1 048 576). Slow: about 1–4 s on one core with the
/// default, so measure once per LUT and keep the table. `out` must not overlap `*lut` or the
/// LUT bytes (`FUR_ERR_OVERLAP`).
///
/// # Safety
/// `lut` is NULL or points to an initialised `fur_lut`; `out` is NULL or points to a
/// writable `fur_coat`.
#[no_mangle]
pub unsafe extern "C" fn fur_coat_measure(
    lut: *const fur_lut,
    photons: u32,
    out: *mut fur_coat,
) -> fur_status {
    // SAFETY: forwarded caller guarantee on `lut`.
    let open = tri!(unsafe { opened(lut) });
    tri!(check_ptr(out));
    tri!(disjoint(Region::of(out, 1), &open.regions));
    let walk = CoatWalk {
        photons: if photons == 0 {
            CoatWalk::DEFAULT.photons
        } else {
            photons.min(1 << 20)
        },
        ..CoatWalk::DEFAULT
    };
    let table = CoatColour::measure(open.lut, &walk);
    // SAFETY: non-NULL and aligned (checked); a writable fur_coat by the caller's contract,
    // outside `*lut` and the LUT bytes (checked).
    unsafe {
        out.write(fur_coat {
            colour: *table.colours(),
        });
    }
    fur_status::FUR_OK
}

/// The cortex absorption sigma_ca per RGB channel whose thick coat shows the linear colour
/// `colour[3]` (docs/model.md §14; `Absorption::from_base_colour`), into `out_sigma_ca[3]`,
/// from a table of `fur_coat_measure`. A channel NaN or outside [0, 1] gives
/// `FUR_ERR_BASE_COLOUR`, an invalid table `FUR_ERR_COAT_TABLE` (nothing written). A channel
/// the coat cannot show (brighter than its lossless coat, darker than its fully absorbing
/// one) is clamped to the nearest colour it can show, and reported: bit c of
/// `*out_clamped` (0 red, 1 green, 2 blue) is set for each clamped channel, 0 when none was.
/// The outputs must not overlap each other or the inputs (`FUR_ERR_OVERLAP`).
///
/// # Safety
/// `coat` is NULL or points to a `fur_coat`; `colour` is NULL or points to 3 readable floats;
/// `out_sigma_ca` is NULL or points to 3 writable floats; `out_clamped` is NULL or points to
/// a writable `uint32_t`.
#[no_mangle]
pub unsafe extern "C" fn fur_absorption_from_colour(
    coat: *const fur_coat,
    colour: *const f32,
    out_sigma_ca: *mut f32,
    out_clamped: *mut u32,
) -> fur_status {
    tri!(check_ptr(coat));
    tri!(check_ptr(out_sigma_ca));
    tri!(check_ptr(out_clamped));
    let inputs = [Region::of(coat, 1), Region::of(colour, 3)];
    let sigma_out = Region::of(out_sigma_ca, 3);
    let clamped_out = Region::of(out_clamped, 1);
    tri!(disjoint(sigma_out, &[inputs[0], inputs[1], clamped_out]));
    tri!(disjoint(clamped_out, &inputs));
    // SAFETY: forwarded caller guarantee on `colour`.
    let c = tri!(unsafe { read3(colour) });
    // SAFETY: non-NULL and aligned (checked); a readable fur_coat by the caller's contract
    // (plain floats: any bits are a value, validated next).
    let table = unsafe { coat.read() };
    let Ok(table) = CoatColour::from_colours(table.colour) else {
        return fur_status::FUR_ERR_COAT_TABLE;
    };
    let Ok(b) = Absorption::from_base_colour(Rgb(c), &table) else {
        return fur_status::FUR_ERR_BASE_COLOUR;
    };
    let bits = (0..3).fold(0u32, |m, k| m | (u32::from(b.clamped[k]) << k));
    // SAFETY: both non-NULL and aligned (checked), writable by the caller's contract, and
    // disjoint from each other and from the inputs (checked).
    unsafe {
        write3(out_sigma_ca, b.absorption.sigma().0);
        out_clamped.write(bits);
    }
    fur_status::FUR_OK
}

#[cfg(test)]
mod tests {
    use super::*;
    use bcsdf_core::colour::coat_node;
    use core::ptr::{null, null_mut};

    fn table() -> fur_coat {
        fur_coat {
            colour: core::array::from_fn(|k| 0.02 + 0.9 / (1.0 + 4.0 * coat_node(k))),
        }
    }

    #[test]
    fn the_c_inverse_is_the_rust_one_and_reports_clamping() {
        let coat = table();
        let rust = CoatColour::from_colours(coat.colour).unwrap();
        let colour = [0.3f32, 0.95, 0.01];
        let (mut sigma, mut clamped) = ([-1.0f32; 3], 99u32);
        // SAFETY: every pointer is a live local of the length the call reads or writes.
        let st = unsafe {
            fur_absorption_from_colour(&coat, colour.as_ptr(), sigma.as_mut_ptr(), &mut clamped)
        };
        assert_eq!(st, fur_status::FUR_OK);
        let want = Absorption::from_base_colour(Rgb(colour), &rust).unwrap();
        assert_eq!(sigma, want.absorption.sigma().0);
        assert_eq!(clamped, 0b110);
        for bad in [[f32::NAN, 0.5, 0.5], [0.5, -0.1, 0.5], [0.5, 0.5, 1.01]] {
            // SAFETY: as above.
            let st = unsafe {
                fur_absorption_from_colour(&coat, bad.as_ptr(), sigma.as_mut_ptr(), &mut clamped)
            };
            assert_eq!(st, fur_status::FUR_ERR_BASE_COLOUR);
        }
        let mut broken = coat;
        broken.colour[3] = 2.0;
        // SAFETY: as above.
        let st = unsafe {
            fur_absorption_from_colour(&broken, colour.as_ptr(), sigma.as_mut_ptr(), &mut clamped)
        };
        assert_eq!(st, fur_status::FUR_ERR_COAT_TABLE);
        // SAFETY: NULL arguments are refused before anything is read.
        let st = unsafe {
            fur_absorption_from_colour(null(), colour.as_ptr(), sigma.as_mut_ptr(), null_mut())
        };
        assert_eq!(st, fur_status::FUR_ERR_NULL);
        let mut buf = [0.5f32; 4];
        let p = buf.as_mut_ptr();
        // SAFETY: `p` holds 4 floats: the colour at p[0..3], the output at p[1..4] overlaps it.
        let st = unsafe { fur_absorption_from_colour(&coat, p, p.add(1), &mut clamped) };
        assert_eq!(st, fur_status::FUR_ERR_OVERLAP);
    }

    #[test]
    fn measuring_needs_an_open_lut() {
        let mut out = table();
        let l = crate::FUR_LUT_INIT;
        // SAFETY: a live, never opened fur_lut and a live fur_coat.
        let st = unsafe { fur_coat_measure(&l, 16, &mut out) };
        assert_eq!(st, fur_status::FUR_ERR_NOT_OPEN);
        assert_eq!(out, table());
    }
}
