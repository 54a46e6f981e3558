//! The attenuation through the counted fibers: Coat's closed form μⁿ against the adding
//! method and a random walk through the layers, and the local backscatter's halves.

use super::*;

/// The adding method, one layer at a time (T_{k+1} = t T_k/(1 − r R_k),
/// R_{k+1} = r + t² R_k/(1 − r R_k)), in f64: the stack's (T_n, R_n).
fn adding(t: f64, r: f64, n: u32) -> (f64, f64) {
    let (mut tk, mut rk) = (1.0f64, 0.0f64);
    for _ in 0..n {
        let d = 1.0 - rk * r;
        (tk, rk) = (tk * t / d, r + t * t * rk / d);
    }
    (tk, rk)
}

#[test]
fn the_coat_decay_is_the_adding_method_on_a_semi_infinite_stack() {
    for (t, r) in [
        (0.537f32, 0.40f32),
        (0.30, 0.28),
        (0.8, 0.1),
        (0.2, 0.05),
        (0.9, 0.0999),
    ] {
        let (t64, r64) = (f64::from(t), f64::from(r));
        let (_, r_inf) = adding(t64, r64, 100_000);
        for n in [1u32, 2, 5, 17] {
            // D_n = T_n/(1 − R_n R_∞), the adding method with the coat below.
            let (tn, rn) = adding(t64, r64, n);
            let want = tn / (1.0 - rn * r_inf);
            let got = f64::from(transmittance(Attenuation::Coat, t, r, n as f32));
            assert!(
                (got - want).abs() < 2e-5 + 1e-4 * want,
                "t {t} r {r} n {n}: {got} vs {want}"
            );
        }
        // Fractional n: geometric between the integers (D_n is geometric).
        let (a, b) = (
            transmittance(Attenuation::Coat, t, r, 2.0),
            transmittance(Attenuation::Coat, t, r, 3.0),
        );
        let mid = transmittance(Attenuation::Coat, t, r, 2.5);
        assert!(
            (mid - (a * b).sqrt()).abs() < 1e-5,
            "{mid} vs {}",
            (a * b).sqrt()
        );
        // The semi-infinite stack's reflectance is the limit of the recursion's R_n.
        let closed = semi_infinite_reflectance(t, r);
        assert!(
            (f64::from(closed) - r_inf).abs() < 1e-4,
            "t {t} r {r}: {closed} vs {r_inf}"
        );
    }
    // Lossless layers: D_n = 1 at every depth; no reflection: t^n; Forward: ā_f^n.
    for (t, r) in [(0.54f32, 0.46f32), (0.9, 0.1), (0.3, 0.7)] {
        assert_eq!(coat_decay(Attenuation::Coat, t, r), 1.0, "t {t}");
    }
    for n in [1.0f32, 3.0, 7.0] {
        let a = transmittance(Attenuation::Coat, 0.6, 0.0, n);
        assert!((a - 0.6f32.powf(n)).abs() < 1e-6, "{a}");
        assert_eq!(
            transmittance(Attenuation::Forward, 0.6, 0.3, n),
            0.6f32.powf(n)
        );
    }
    for n in [0.0, -1.0, f32::NAN] {
        assert_eq!(transmittance(Attenuation::Coat, 0.5, 0.3, n), 1.0);
    }
    for bad in [f32::NAN, -1.0, f32::INFINITY, 0.0] {
        let mu = coat_decay(Attenuation::Coat, bad, 0.3);
        assert!((0.0..=1.0).contains(&mu), "{bad}: {mu}");
    }
    assert!(transmittance(Attenuation::Coat, 1.0, 0.0, f32::INFINITY) <= 1.0);
    assert_eq!(semi_infinite_reflectance(0.5, 0.0), 0.0);
}

/// A random walk through the layered coat, independent of the adding method's closed forms:
/// a photon enters at the top going down; each layer it meets passes it on (probability t),
/// turns it round (r) or absorbs it. Returns the mean number of downward crossings of the
/// boundary under `depth` layers (the downward flux there, D) and of upward crossings of the
/// boundary under `depth + 1` layers (the flux the coat below sends up to layer depth + 1,
/// U), for a stack of `total` layers (deep enough to stand for the semi-infinite coat).
fn walk_fluxes(t: f32, r: f32, depth: u32, total: u32, photons: u32) -> (f64, f64) {
    let mut rng = crate::rng::Pcg32::new(23, u64::from(depth));
    let (mut down, mut up) = (0u64, 0u64);
    for _ in 0..photons {
        // Position: the boundary index (0 = top), direction: +1 down, −1 up.
        let (mut at, mut dir) = (0i64, 1i64);
        loop {
            if dir > 0 && at == i64::from(depth) {
                down += 1;
            }
            if dir < 0 && at == i64::from(depth) + 1 {
                up += 1;
            }
            // The layer crossed next: at (going down) or at − 1 (going up).
            let layer = if dir > 0 { at } else { at - 1 };
            if layer < 0 || layer >= i64::from(total) {
                break; // left by the top, or out of the bottom of the deep stack
            }
            let u = rng.uniform();
            if u < t {
                at += dir;
            } else if u < t + r {
                dir = -dir;
            } else {
                break;
            }
        }
    }
    let p = f64::from(photons);
    (down as f64 / p, up as f64 / p)
}

#[test]
fn the_coat_fluxes_match_a_random_walk_through_the_layers() {
    // Absorbing layers (the walk ends: a deep stack is semi-infinite) and lossless ones
    // (the walk on a lossless stack is a recurrent random walk: it would not end, so only the
    // closed form's limit, D_n = 1, is checked there).
    for (t, r) in [(0.537f32, 0.40f32), (0.30, 0.28), (0.8, 0.1), (0.5, 0.0)] {
        for depth in [0u32, 1, 2, 5] {
            let (d, u) = walk_fluxes(t, r, depth, 400, 200_000);
            let got_d = f64::from(transmittance(Attenuation::Coat, t, r, depth as f32));
            // U per unit of D: the light through the fiber at `depth`, reflected back by the
            // coat below, with the inter-reflections (what `local_backscatter` divides by ā_f).
            let (back, front) = local_backscatter(Attenuation::Coat, 0.0, t, r);
            let got_u = if t > 0.0 { f64::from(back / t) } else { 0.0 } * got_d;
            let tol_d = 4.0 * (d / 200_000.0).sqrt() + 2e-3 * d;
            assert!(
                (got_d - d).abs() <= tol_d,
                "t {t} r {r} n {depth}: D {got_d} vs walk {d}"
            );
            let tol_u = 4.0 * (u.max(1e-3) / 200_000.0).sqrt() + 2e-3 * u;
            assert!(
                (got_u - u).abs() <= tol_u,
                "t {t} r {r} n {depth}: U {got_u} vs walk {u}"
            );
            // The fiber scatters U forward (back half) and back (front half).
            assert!((f64::from(front) - f64::from(r) * got_u / got_d.max(1e-12)).abs() < 1e-5);
        }
    }
    // Lossless layers: the coat below returns everything, the downward flux is 1 at every
    // depth (a finite stack alone gives 1/(1 + n r/t)), and the fiber scatters all of U.
    // In f32, R_∞'s square root of a vanishing discriminant is off by ~1e-3, which the
    // denominator 1 − R_n R_∞ feels more as T_n falls: 2.7e-3 at n = 40 for t = 0.9.
    for (t, r) in [(0.54f32, 0.46f32), (0.9, 0.1)] {
        for n in [1.0f32, 2.0, 7.5, 40.0] {
            let d = transmittance(Attenuation::Coat, t, r, n);
            assert!((d - 1.0).abs() < 4e-3, "t {t} n {n}: {d}");
            let (tn, _) = adding(f64::from(t), f64::from(r), n as u32);
            assert!(
                f64::from(d) > tn,
                "the finite stack alone lets less through"
            );
        }
        let (back, front) = local_backscatter(Attenuation::Coat, 0.0, t, r);
        assert!((back + front - 1.0).abs() < 2e-3, "{back} + {front}");
    }
    for n in [0.0, -1.0, f32::NAN] {
        assert_eq!(transmittance(Attenuation::Coat, 0.5, 0.3, n), 1.0);
    }
    // Coat's back-half energy is R_∞ − ā_b (= ā_f U); Zinke's is its own.
    let (b_c, _) = local_backscatter(Attenuation::Coat, 0.7, 0.5, 0.3);
    let r_inf = semi_infinite_reflectance(0.5, 0.3);
    assert!(
        (b_c - (r_inf - 0.3)).abs() < 1e-6,
        "{b_c} vs {}",
        r_inf - 0.3
    );
    assert_eq!(
        local_backscatter(Attenuation::Forward, 0.7, 0.5, 0.3),
        (0.7, 0.0)
    );
    for bad in [f32::NAN, -1.0, f32::INFINITY] {
        let (b, f) = local_backscatter(Attenuation::Coat, bad, bad, bad);
        assert!(b.is_finite() && f.is_finite() && b >= 0.0 && f >= 0.0);
    }
}
