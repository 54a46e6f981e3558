//! The finite coat's closed forms ([`crate::dual::coat`]) against the adding recursion of
//! two-stream layers, and the reachable-range normalisation of the term's Gaussians.

use super::super::coat::{backscatter_factor, downward_flux, reflectance_squared};
use super::super::eval::gauss_reachable;
use super::*;

/// (R_k, T_k) of k layers (t, r) by the adding recursion, in f64.
fn stack(t: f64, r: f64, k: u32) -> (f64, f64) {
    let (mut rk, mut tk) = (0.0f64, 1.0f64);
    for _ in 0..k {
        let den = 1.0 - rk * r;
        (rk, tk) = (rk + tk * tk * r / den, tk * t / den);
    }
    (rk, tk)
}

const LAYERS: [(f32, f32); 5] = [
    (0.537, 0.455),
    (0.66, 0.25),
    (0.3, 0.28),
    (0.9, 0.0999),
    (0.5, 0.0),
];

#[test]
fn the_closed_forms_are_the_adding_recursion() {
    for (t, r) in LAYERS {
        let mu = coat_decay(Attenuation::Coat, t, r);
        let rho2 = reflectance_squared(mu, t);
        let (r_inf, _) = stack(f64::from(t), f64::from(r), 100_000);
        // f32 and nearly lossless layers (0.9, 0.0999): μ − t cancels, so 1e-4.
        assert!(
            (f64::from(rho2) - r_inf * r_inf).abs() < 1e-4,
            "(t, r) = ({t}, {r}): ρ² {rho2} vs {}",
            r_inf * r_inf
        );
        let up = |rr: f64| rr * f64::from(t) / (1.0 - f64::from(r) * rr);
        for n in 0..12u32 {
            for m in [0u32, 1, 2, 5, 11, 40] {
                let (r_n, t_n) = stack(f64::from(t), f64::from(r), n);
                let (r_m, _) = stack(f64::from(t), f64::from(r), m);
                let want = t_n / (1.0 - r_n * r_m);
                let mu_n = mu.powi(n as i32);
                let mu_2m = mu.powi(2 * m as i32);
                let got = downward_flux(mu_n, mu_2m, rho2);
                assert!(
                    (f64::from(got) - want).abs() < 1e-5 + 1e-4 * want,
                    "(t, r) = ({t}, {r}), n = {n}, m = {m}: D {got} vs {want}"
                );
                if r > 0.0 {
                    // The coat below the neighbourhood returns R_m per unit of the downward
                    // flux; the stored energy holds the stack's U_∞ (through the fiber).
                    let want = r_m / up(r_inf);
                    let got = backscatter_factor(rho2, mu, mu_2m);
                    assert!(
                        (f64::from(got) - want).abs() < 1e-4,
                        "(t, r) = ({t}, {r}), m = {m}: factor {got} vs {want}"
                    );
                }
            }
        }
    }
}

#[test]
fn the_limits_are_the_deep_coat_and_the_bare_skin() {
    for (t, r) in LAYERS {
        let mu = coat_decay(Attenuation::Coat, t, r);
        let rho2 = reflectance_squared(mu, t);
        for n in [0.0f32, 0.5, 3.0, 20.0] {
            let mu_n = mu.powf(n);
            // m = ∞: the semi-infinite coat's μⁿ; more fibers below never darken.
            assert_eq!(downward_flux(mu_n, 0.0, rho2), mu_n);
            let mut last = 0.0;
            for m in [0.0f32, 0.5, 1.0, 4.0, 30.0] {
                let d = downward_flux(mu_n, mu.powf(2.0 * m), rho2);
                assert!(
                    d >= last && d <= mu_n,
                    "n {n} m {m}: {d} after {last}, μⁿ {mu_n}"
                );
                last = d;
            }
        }
        // m = ∞: the semi-infinite coat's R_∞ over U_∞ = R_∞μ; m = 0: nothing below.
        assert_eq!(backscatter_factor(rho2, mu, 0.0), 1.0 / mu);
        assert_eq!(backscatter_factor(rho2, mu, 1.0), 0.0);
    }
    // Degenerate layers: lossless (μ = 1), opaque (t = 0), NaN: finite, in range.
    for (mu, t) in [
        (1.0f32, 0.6f32),
        (1.0, 1.0),
        (0.0, 0.0),
        (f32::NAN, 0.5),
        (0.5, f32::NAN),
    ] {
        let rho2 = reflectance_squared(mu, t);
        assert!((0.0..=1.0).contains(&rho2), "ρ² {rho2}");
        for q in [0.0f32, 0.5, 1.0] {
            let mu_n = if mu.is_nan() { 0.0 } else { mu.clamp(0.0, 1.0) };
            let d = downward_flux(mu_n, q, rho2);
            let k = backscatter_factor(rho2, mu, q);
            assert!(
                d.is_finite() && (0.0..=1.0e6).contains(&k) && (mu.is_nan() || k * mu <= 1.0),
                "μ {mu} t {t} q {q}: {d} {k}"
            );
        }
    }
}

#[test]
fn each_gaussian_keeps_its_mass_over_the_reachable_range() {
    // ∫ Ĝ(θ_i + θ_r − mean; v) dθ_i over θ_i ∈ [−π/2, π/2] is 1 (midpoint rule), wherever
    // the lobe's mass in range is above the 0.05 floor; below it, the floor.
    let steps = 20_000;
    for (tr, mean, v) in [
        (0.0f32, 0.1f32, 0.01f32),
        (1.2, 0.3, 0.2),
        (-1.4, -0.2, 0.5),
        (0.4, 2.4, 0.05),
        (0.0, 0.0, 2.0),
    ] {
        let h = PI / steps as f32;
        let total: f64 = (0..steps)
            .map(|i| {
                let ti = -0.5 * PI + (i as f32 + 0.5) * h;
                let d = ti + tr - mean;
                f64::from(gauss_reachable(&[d], &[v], ti)[0]) * f64::from(h)
            })
            .sum();
        let g = |x: f64| libm::erf(x / f64::from(2.0 * v).sqrt());
        let mass = 0.5
            * (g(f64::from(tr - mean) + std::f64::consts::FRAC_PI_2)
                - g(f64::from(tr - mean) - std::f64::consts::FRAC_PI_2));
        let want = if mass >= 0.05 { 1.0 } else { mass / 0.05 };
        assert!(
            (total - want).abs() < 2e-4,
            "θ_r {tr} mean {mean} v {v}: {total} (mass {mass})"
        );
    }
}

#[test]
fn the_coat_below_lights_the_point() {
    // Through the evaluator: on bare skin (a negative count below: no coat) nothing comes
    // back up, so unoccluded light gets no local backscatter; a line that crosses no fiber
    // below a point in the coat (m = 0) sees the neighbourhood's coat, m + 1 layers
    // (`coat::coat_below_layers`), exactly what one layer below gives; more fibers below
    // give more.
    let t = absorbing_tables();
    let lut = lut_of(&t, Attenuation::Coat);
    let a = Angles::new(0.3, -0.2, 0.4).unwrap();
    let d = Density::DEFAULT;
    assert_eq!(lut.eval(&a, Fibers::new(0.0, -1.0), d), Rgb::ZERO);
    let line_clear = lut.eval(&a, Fibers::new(0.0, 0.0), d);
    assert!(line_clear.0.iter().all(|&v| v > 0.0), "{line_clear:?}");
    assert_eq!(line_clear, lut.eval(&a, Fibers::new(0.0, -0.0), d));
    assert!(line_clear[0] < lut.eval(&a, Fibers::new(0.0, 1.0), d)[0]);
    assert_eq!(crate::dual::coat::coat_below_layers(0.0), 1.0);
    assert_eq!(crate::dual::coat::coat_below_layers(2.5), 3.5);
    assert_eq!(crate::dual::coat::coat_below_layers(-3.0), 0.0);
    assert_eq!(crate::dual::coat::coat_below_layers(f32::NAN), 1.0e6);
    assert_eq!(crate::dual::coat::coat_below_layers(f32::INFINITY), 1.0e6);
    for n in [0.0f32, 2.0] {
        let first = lut.eval(&a, Fibers::new(n, 0.5), d);
        assert!(first.0.iter().all(|&v| v > 0.0), "{first:?}");
        let mut last = first;
        for m in [2.0f32, 8.0, f32::INFINITY] {
            let v = lut.eval(&a, Fibers::new(n, m), d);
            for c in 0..3 {
                assert!(v[c] >= last[c], "n {n} m {m}: {v:?} after {last:?}");
            }
            last = v;
        }
        // Against bare skin (no coat below: 0 layers) the deep coat is far brighter.
        let skin = lut.eval(&a, Fibers::new(n, -1.0), d);
        assert!(
            last[0] > 1.2 * skin[0] && last[0] > 0.0,
            "{last:?} vs {skin:?}"
        );
        // NaN below is the deep coat.
        assert_eq!(lut.eval(&a, Fibers::new(n, f32::NAN), d), last);
        assert_eq!(lut.eval(&a, Fibers::deep(n), d), last);
    }
}

#[test]
fn the_light_s_incidence_turns_the_line_into_the_coat_s_normal_depth() {
    use crate::dual::coat::{below_at_incidence, coat_below_layers, DIFFUSIVITY};
    // The layers the term uses: DIFFUSIVITY·|cos ι|·(m + 1), at least 1, whatever the sign
    // of cos ι; at |cos ι| = 1/DIFFUSIVITY the line's count is the coat's.
    for m in [0.0f32, 0.5, 2.0, 7.0, 40.0] {
        for c in [1.0f32, 0.8, 0.5, 0.3, 0.1, 0.0] {
            let want = (2.0 * c * (m + 1.0)).max(1.0);
            for s in [c, -c] {
                let got = coat_below_layers(below_at_incidence(m, s));
                assert!(
                    (got - want).abs() <= 1e-5 * want,
                    "m {m} cos {s}: {got} layers, want {want}"
                );
            }
        }
        assert_eq!(below_at_incidence(m, 1.0 / DIFFUSIVITY), m);
        // |cos ι| above 1 (a caller's rounding) is 1.
        assert_eq!(below_at_incidence(m, 1.5), below_at_incidence(m, 1.0));
    }
    // The normal unknown (NaN), the skin (negative), the semi-infinite coat (NaN, ∞, ≥ 10⁶):
    // the count as given, bit for bit.
    for m in [0.0f32, 3.0, -1.0, -0.0, f32::INFINITY, 2.0e6] {
        assert_eq!(below_at_incidence(m, f32::NAN).to_bits(), m.to_bits());
    }
    for m in [-1.0f32, f32::INFINITY, 2.0e6] {
        assert_eq!(below_at_incidence(m, 0.7).to_bits(), m.to_bits());
    }
    // −0 is a count of 0 (coat_below_layers: a point in the coat), not the skin.
    assert_eq!(below_at_incidence(-0.0, 0.7), below_at_incidence(0.0, 0.7));
    assert!(below_at_incidence(f32::NAN, 0.7).is_nan());
    // Through the evaluator: at normal incidence the unoccluded point sees a deeper coat
    // below than the line's (more local backscatter), at grazing incidence a shallower one.
    let t = absorbing_tables();
    let lut = lut_of(&t, Attenuation::Coat);
    let a = Angles::new(0.3, -0.2, 0.4).unwrap();
    let d = Density::DEFAULT;
    let line = lut.eval(&a, Fibers::new(0.0, 2.0), d);
    let normal = lut.eval(&a, Fibers::new(0.0, below_at_incidence(2.0, 1.0)), d);
    let grazing = lut.eval(&a, Fibers::new(0.0, below_at_incidence(2.0, 0.1)), d);
    for c in 0..3 {
        assert!(
            normal[c] > line[c] && grazing[c] < line[c],
            "{normal:?} {line:?} {grazing:?}"
        );
    }
    assert_eq!(normal, lut.eval(&a, Fibers::new(0.0, 5.0), d));
}

#[test]
fn the_light_s_incidence_sets_the_scattered_flux_through_the_fibers_above() {
    use crate::dual::coat::{forward_density_at_incidence, DIFFUSIVITY};
    // d_f·DIFFUSIVITY·|cos ι|: the diffuse flux per unit of coat area, intercepted along
    // twice the normal depth; |cos ι| clamped to 1, the sign ignored, NaN d_f unchanged.
    for d in [1.0f32, 0.7, 2.5] {
        for c in [1.0f32, 0.8, 0.5, 0.3, 0.1, 0.0] {
            let want = d * 2.0 * c;
            for s in [c, -c] {
                let got = forward_density_at_incidence(d, s);
                assert!(
                    (got - want).abs() <= 1e-6 * want,
                    "d {d} cos {s}: {got}, want {want}"
                );
            }
        }
        assert_eq!(forward_density_at_incidence(d, 1.0 / DIFFUSIVITY), d);
        assert_eq!(
            forward_density_at_incidence(d, 1.5),
            forward_density_at_incidence(d, 1.0)
        );
        assert_eq!(
            forward_density_at_incidence(d, f32::NAN).to_bits(),
            d.to_bits()
        );
    }
    // Through the evaluator: behind fibers, the light falling along the normal gives more
    // than the line's count alone, grazing light less; the unoccluded point (no spread term)
    // is unchanged.
    let t = absorbing_tables();
    let lut = lut_of(&t, Attenuation::Coat);
    let a = Angles::new(0.3, -0.2, 0.4).unwrap();
    let at = |n: f32, c: f32| {
        let d = Density {
            d_f: forward_density_at_incidence(Density::DEFAULT.d_f, c),
            ..Density::DEFAULT
        };
        lut.eval(&a, Fibers::new(n, 2.0), d)
    };
    let (line, normal, grazing) = (at(2.0, f32::NAN), at(2.0, 1.0), at(2.0, 0.1));
    for c in 0..3 {
        assert!(
            normal[c] > 1.5 * line[c] && grazing[c] < 0.5 * line[c],
            "{normal:?} {line:?} {grazing:?}"
        );
    }
    assert_eq!(at(0.0, 1.0), at(0.0, f32::NAN));
}
