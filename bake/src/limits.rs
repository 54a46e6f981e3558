//! Resource bounds of the tools' numeric options (`bake`, `viewer`): thread counts and the
//! profile generator's photon scale are checked, and what they would cost estimated, before
//! anything runs, so that no option value makes a command run for hours or exhaust memory
//! without saying so. A value past a hard bound is bad input (the tools exit with code 2).

use bcsdf_core::medulla::PhotonBudget;

/// Threads a `--threads` request is capped at, per unit of the machine's available
/// parallelism: more only adds scheduling overhead.
pub const THREADS_PER_CORE: usize = 8;

/// The largest `--threads` accepted at all: above it the request is refused as bad input
/// (spawning 100 000 OS threads takes minutes and gigabytes of stacks).
pub const MAX_THREADS: usize = 4096;

/// The largest `--photons-scale`: the medulla profiles' generation time grows linearly with
/// it (see [`profile_seconds`]).
pub const MAX_PHOTONS_SCALE: f64 = 16.0;

/// Core-seconds to generate one preset's medulla profiles at `--photons-scale 1` (the
/// default resolution, release build; docs/model.md §12 measures ~10 s per preset on two
/// cores): the base of [`profile_seconds`].
pub const PROFILE_CORE_SECONDS: f64 = 20.0;

/// The machine's available parallelism (1 when it cannot be told).
#[must_use]
pub fn cores() -> usize {
    std::thread::available_parallelism().map_or(1, std::num::NonZeroUsize::get)
}

/// A checked `--threads` request: `None` (or 0, which the tools document as the default)
/// stays the default, a count above [`THREADS_PER_CORE`] × [`cores`] is capped there with a
/// note, and one above [`MAX_THREADS`] is refused with the reason.
pub fn threads(
    flag: &str,
    requested: Option<usize>,
) -> Result<(Option<usize>, Option<String>), String> {
    let Some(n) = requested else {
        return Ok((None, None));
    };
    if n == 0 {
        return Ok((None, None));
    }
    if n > MAX_THREADS {
        return Err(format!(
            "{flag} {n} is more than {MAX_THREADS} threads (this machine has {} cores; \
             more than {THREADS_PER_CORE} per core only adds overhead)",
            cores()
        ));
    }
    let cap = THREADS_PER_CORE * cores();
    if n > cap {
        return Ok((
            Some(cap),
            Some(format!(
                "{flag} {n}: using {cap} threads ({THREADS_PER_CORE} per core on this machine's {} cores)",
                cores()
            )),
        ));
    }
    Ok((Some(n), None))
}

/// Estimated core-seconds to generate one medullated preset's profiles at `scale`
/// ([`PROFILE_CORE_SECONDS`] × scale, the photon counts being proportional to it; presets
/// without a scattering medulla need no profiles).
#[must_use]
pub fn profile_seconds(scale: f64) -> f64 {
    PROFILE_CORE_SECONDS * scale
}

/// `budget` scaled by a checked `--photons-scale` (finite, positive, at most
/// [`MAX_PHOTONS_SCALE`]), with a note estimating the generation time when it is above 1.
pub fn photon_budget(
    budget: PhotonBudget,
    scale: f64,
) -> Result<(PhotonBudget, Option<String>), String> {
    if !(scale.is_finite() && scale > 0.0) {
        return Err(format!(
            "--photons-scale {scale} must be a positive finite number"
        ));
    }
    let per_core = |s: f64| profile_seconds(s) / cores() as f64;
    if scale > MAX_PHOTONS_SCALE {
        return Err(format!(
            "--photons-scale {scale} is above {MAX_PHOTONS_SCALE}: the medulla profiles would take \
             about {} per medullated preset on this machine's {} cores (1 takes about {})",
            duration(per_core(scale)),
            cores(),
            duration(per_core(1.0)),
        ));
    }
    let scaled = crate::profiles::scale_budget(budget, scale)
        .ok_or_else(|| format!("--photons-scale {scale} must be a positive finite number"))?;
    let note = (scale > 1.0).then(|| {
        format!(
            "--photons-scale {scale}: generating the medulla profiles takes about {} per \
             medullated preset on {} cores (none when they are cached)",
            duration(per_core(scale)),
            cores()
        )
    });
    Ok((scaled, note))
}

/// A duration in seconds as `12 s`, `3.4 min`, `2.1 h` or `5.0 days`.
#[must_use]
pub fn duration(seconds: f64) -> String {
    if !seconds.is_finite() {
        return "forever".to_string();
    }
    if seconds > 100.0 * 365.0 * 86_400.0 {
        return "more than a century".to_string();
    }
    if seconds < 90.0 {
        format!("{seconds:.0} s")
    } else if seconds < 5400.0 {
        format!("{:.1} min", seconds / 60.0)
    } else if seconds < 172_800.0 {
        format!("{:.1} h", seconds / 3600.0)
    } else {
        format!("{:.1} days", seconds / 86_400.0)
    }
}

/// The largest `--res-dual` node count along θ_i: the dual-scattering tables' cost grows with
/// the product of the two counts (the default, 128 × 96, takes seconds per preset).
pub const MAX_DUAL_THETA_STEPS: usize = 1024;

/// A checked `bake --res-dual THETA,PHI`: θ_i nodes in [8, [`MAX_DUAL_THETA_STEPS`]], |φ|
/// nodes in [8, [`bcsdf_core::dual::MAX_PHI_STEPS`]] and even (the front/back split falls on a
/// cell edge); anything else is refused with the reason.
pub fn dual_quadrature(value: &str) -> Result<bcsdf_core::dual::Quadrature, String> {
    let max_phi = bcsdf_core::dual::MAX_PHI_STEPS;
    let bad = || {
        format!(
            "--res-dual {value:?}: expected THETA,PHI (θ_i nodes 8 to {MAX_DUAL_THETA_STEPS}, \
             |φ| nodes 8 to {max_phi} and even)"
        )
    };
    let (t, p) = value.split_once(',').ok_or_else(bad)?;
    let t: usize = t.trim().parse().map_err(|_| bad())?;
    let p: usize = p.trim().parse().map_err(|_| bad())?;
    if !(8..=MAX_DUAL_THETA_STEPS).contains(&t)
        || !(8..=max_phi).contains(&p)
        || !p.is_multiple_of(2)
    {
        return Err(bad());
    }
    Ok(bcsdf_core::dual::Quadrature {
        theta_steps: t,
        phi_steps: p,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn threads_are_capped_and_refused_past_the_hard_bound() {
        assert_eq!(threads("--threads", None).unwrap(), (None, None));
        assert_eq!(threads("--threads", Some(0)).unwrap(), (None, None));
        assert_eq!(threads("--threads", Some(1)).unwrap(), (Some(1), None));
        let cap = THREADS_PER_CORE * cores();
        if cap < MAX_THREADS {
            let (n, note) = threads("--threads", Some(cap + 1)).unwrap();
            assert_eq!(n, Some(cap));
            assert!(note.unwrap().contains("using"));
        }
        let e = threads("--threads", Some(100_000)).unwrap_err();
        assert!(e.contains("100000") && e.contains("4096"), "{e}");
    }

    #[test]
    fn photon_scales_are_bounded_with_an_estimate() {
        let d = PhotonBudget::DEFAULT;
        for bad in [0.0, -1.0, f64::NAN, f64::INFINITY, 1e30, 17.0] {
            assert!(photon_budget(d, bad).is_err(), "{bad}");
        }
        assert!(photon_budget(d, 1e30)
            .unwrap_err()
            .contains("would take about"));
        assert_eq!(photon_budget(d, 1.0).unwrap(), (d, None));
        let (b, note) = photon_budget(d, 2.0).unwrap();
        assert_eq!(b.per_cn_cell, 2 * d.per_cn_cell);
        assert!(note.unwrap().contains("takes about"));
        assert_eq!(photon_budget(d, 1e-9).unwrap().0.per_cn_cell, 1);
    }

    #[test]
    fn dual_quadratures_are_bounded() {
        let q = dual_quadrature("128,96").unwrap();
        assert_eq!((q.theta_steps, q.phi_steps), (128, 96));
        assert_eq!(dual_quadrature(" 8, 256").unwrap().phi_steps, 256);
        for bad in [
            "", "128", "7,96", "1025,96", "128,6", "128,258", "128,95", "a,b", "-8,8", "8,8,8",
        ] {
            let e = dual_quadrature(bad).unwrap_err();
            assert!(e.contains("--res-dual") && e.contains("1024"), "{bad}: {e}");
        }
    }

    #[test]
    fn durations_read_in_sensible_units() {
        assert_eq!(duration(12.0), "12 s");
        assert_eq!(duration(600.0), "10.0 min");
        assert_eq!(duration(7200.0), "2.0 h");
        assert_eq!(duration(864_000.0), "10.0 days");
        assert_eq!(duration(f64::INFINITY), "forever");
        assert_eq!(duration(1e30), "more than a century");
    }
}
