//! Unit tests of the coat colour table, its inverse and the random walk (docs/model.md §14).

extern crate std;
use super::*;
use crate::bcsdf::{Bcsdf, SampledDirection};
use crate::frame::Angles;
use crate::lobes::{Families, LobeFamily};
use crate::math::Libm;
use core::f32::consts::PI;

/// A made-up table: c(σ) = dark + (bright − dark)/(1 + 4σ).
fn table(dark: f32, bright: f32) -> CoatColour {
    CoatColour::from_colours(core::array::from_fn(|k| {
        dark + (bright - dark) / (1.0 + 4.0 * coat_node(k))
    }))
    .unwrap()
}

#[test]
fn nodes_run_from_lossless_to_sigma_max_and_increase() {
    assert_eq!(coat_node(0), 0.0);
    assert_eq!(coat_node(COAT_NODES - 1), SIGMA_CA_MAX);
    assert_eq!(coat_node(COAT_NODES + 5), SIGMA_CA_MAX);
    for k in 1..COAT_NODES {
        assert!(coat_node(k) > coat_node(k - 1), "node {k}");
    }
    // The first cell is narrow: the steep √σ start of a nearly lossless coat.
    assert!(coat_node(1) < 0.005, "{}", coat_node(1));
}

#[test]
fn the_inverse_undoes_the_table_and_is_monotone() {
    let coat = table(0.02, 0.92);
    for k in 0..COAT_NODES {
        let s = coat_node(k);
        assert!((coat.colour_at(s) - coat.colours()[k]).abs() < 1e-6);
    }
    let mut last_sigma = -1.0f32;
    for i in 0..=400 {
        // From bright to dark: σ must not decrease.
        let c = (coat.brightest() - (coat.brightest() - coat.darkest()) * i as f32 / 400.0)
            .max(coat.darkest());
        let b = Absorption::from_base_colour(Rgb::splat(c), &coat).unwrap();
        assert!(!b.is_clamped(), "{c}");
        let s = b.absorption.sigma()[0];
        assert!(s >= last_sigma, "{c}: {s} < {last_sigma}");
        last_sigma = s;
        // Forward through the table again: the colour asked for.
        let back = coat.colour_at(s);
        assert!((back - c).abs() < 2e-5, "{c} -> {s} -> {back}");
        assert_eq!(b.shown, Rgb::splat(c));
    }
}

#[test]
fn unreachable_colours_are_clamped_and_reported_bad_ones_refused() {
    let coat = table(0.04, 0.8);
    let b = Absorption::from_base_colour(Rgb([0.9, 0.5, 0.01]), &coat).unwrap();
    assert_eq!(b.clamped, [true, false, true]);
    assert_eq!(b.absorption.sigma()[0], 0.0);
    assert_eq!(b.absorption.sigma()[2], SIGMA_CA_MAX);
    assert_eq!(b.shown, Rgb([coat.brightest(), 0.5, coat.darkest()]));
    let text = std::format!("{b}");
    assert!(text.contains("out of this fur's reach in R B"), "{text}");
    for (c, bad) in [(0, f32::NAN), (1, -0.01), (2, 1.5), (0, f32::INFINITY)] {
        let mut v = [0.5; 3];
        v[c] = bad;
        let e = Absorption::from_base_colour(Rgb(v), &coat).unwrap_err();
        assert_eq!(e.channel, c);
        assert!(std::format!("{e}").contains("base_colour channel"));
    }
}

#[test]
fn tables_must_be_in_range_and_non_increasing() {
    let mut c = *table(0.02, 0.9).colours();
    c[5] = c[4] + 0.01;
    assert_eq!(CoatColour::from_colours(c).unwrap_err().node, 5);
    c = *table(0.02, 0.9).colours();
    c[0] = f32::NAN;
    assert_eq!(CoatColour::from_colours(c).unwrap_err().node, 0);
    let m = CoatColour::monotone([
        0.5,
        0.6,
        f32::NAN,
        0.3,
        0.31,
        0.2,
        2.0,
        -1.0,
        0.1,
        0.1,
        0.1,
        0.1,
        0.1,
        0.1,
        0.1,
        0.1,
        0.1,
        0.1,
        0.1,
        0.1,
        0.1,
        0.1,
        0.1,
        0.05,
    ]);
    assert_eq!(CoatColour::from_colours(*m.colours()), Ok(m));
    assert_eq!(&m.colours()[..8], &[0.5, 0.5, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]);
}

/// An ideal fiber of albedo `a`: S = a/π² (∫ S cos θ_i dω_i = a), sampled uniformly on the
/// sphere (p_ω = 1/(4π), weight 4a·cos θ_i/π, of mean a).
struct Ideal(f32);

impl Bcsdf for Ideal {
    type Math = Libm;
    fn eval(&self, _a: &Angles) -> Families {
        let mut v = [Rgb::ZERO; 4];
        v[LobeFamily::R as usize] = Rgb::splat(self.0 / (PI * PI));
        Families::from_array(v)
    }
    fn pdf(&self, _a: &Angles) -> f32 {
        1.0 / (4.0 * PI)
    }
    fn sample_direction(&self, _t: f32, u: [f32; 3]) -> Option<SampledDirection> {
        // sin θ_i uniform in [−1, 1], φ uniform: uniform on the sphere.
        let theta_i = libm::asinf(2.0 * u[0] - 1.0);
        let phi = PI * (2.0 * u[1] - 1.0);
        Some(SampledDirection {
            angles: Angles::new(theta_i, 0.0, phi).ok()?,
            family: LobeFamily::R,
        })
    }
}

#[test]
fn a_lossless_coat_returns_its_light_and_absorption_darkens_it() {
    let walk = CoatWalk {
        photons: 4000,
        max_bounces: 4000,
        seed: 3,
        depth: f32::INFINITY,
    };
    let lossless = coat_reflectance(&Ideal(1.0), &walk);
    // Energy: every photon leaves (or is still inside at the end), within the noise.
    let total = lossless.colour[0] + lossless.unfinished[0];
    assert!(
        (total - 1.0).abs() < 4.0 * lossless.std_error[0] + 0.01,
        "{lossless:?}"
    );
    assert!(lossless.colour[0] > 0.9, "{lossless:?}");
    let mut last = 1.0;
    for a in [0.99, 0.9, 0.5] {
        let e = coat_reflectance(&Ideal(a), &walk);
        assert!(e.colour[0] < last && e.colour[0].is_finite());
        assert!(e.colour == Rgb::splat(e.colour[0]));
        last = e.colour[0];
    }
}

/// The smallest f32 σ_ca in [0, σ_max] whose table colour `coat.colour_at(σ)` is at most `c`,
/// by bisection on the bit patterns of the non-negative floats (to one f32 step): the
/// brute-force root of the same interpolant [`Absorption::from_base_colour`] inverts; 0 for
/// a colour at or above the lossless coat's, σ_max below the darkest.
fn brute_force_sigma(coat: &CoatColour, c: f32) -> f32 {
    if coat.colour_at(0.0) <= c {
        return 0.0;
    }
    if coat.colour_at(SIGMA_CA_MAX) > c {
        return SIGMA_CA_MAX;
    }
    // colour_at(lo) > c >= colour_at(hi).
    let (mut lo, mut hi) = (0u32, SIGMA_CA_MAX.to_bits());
    while hi - lo > 1 {
        let mid = lo + (hi - lo) / 2;
        if coat.colour_at(f32::from_bits(mid)) <= c {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    f32::from_bits(hi)
}

/// The worst disagreement of the inverse with [`brute_force_sigma`] over `colours`: the
/// largest |σ − σ_bf| / max(σ_bf, 1e-3), the largest colour residual |c(σ) − c| of the
/// inverse's σ (against the clamped colour at the ends), and that of the brute force's σ.
fn worst_against_brute_force(coat: &CoatColour, colours: &[f32]) -> (f32, f32, f32) {
    let (mut sigma_err, mut colour_err, mut bf_err) = (0.0f32, 0.0f32, 0.0f32);
    for &c in colours {
        let b = Absorption::from_base_colour(Rgb::splat(c), coat).unwrap();
        let sigma = b.absorption.sigma()[0];
        let bf = brute_force_sigma(coat, c);
        let target = c.clamp(coat.darkest(), coat.brightest());
        assert_eq!(b.shown[0], target, "{c}");
        sigma_err = sigma_err.max((sigma - bf).abs() / bf.max(1e-3));
        colour_err = colour_err.max((coat.colour_at(sigma) - target).abs());
        bf_err = bf_err.max((coat.colour_at(bf) - target).abs());
    }
    (sigma_err, colour_err, bf_err)
}

/// The inverse against a brute-force root find on the same table (docs/model.md §14,
/// "Inverse"): 20 001 colours evenly over [0, 1] (the clamped ends beyond the darkest and the
/// brightest colour included), every node colour and every cell's midpoint, on a smooth table,
/// one with flat cells (where the smallest σ is the answer) and the human-hair table as
/// measured. The worst σ error and colour residual are printed (docs/benchmarks.md "Base
/// colour inversion").
#[test]
fn the_inverse_matches_a_brute_force_root_find_on_the_same_table() {
    let mut flat = *table(0.03, 0.6).colours();
    for k in 5..9 {
        flat[k] = flat[4];
    }
    for k in 15..COAT_NODES {
        flat[k] = flat[14];
    }
    let tables = [
        ("smooth", table(0.02, 0.92)),
        ("flat cells", CoatColour::from_colours(flat).unwrap()),
        ("human hair", CoatColour::from_colours(HUMAN_HAIR).unwrap()),
    ];
    for (name, coat) in tables {
        let mut colours: std::vec::Vec<f32> = (0..=20_000).map(|i| i as f32 / 20_000.0).collect();
        let nodes = coat.colours();
        colours.extend(nodes.iter().copied());
        colours.extend(nodes.windows(2).map(|w| 0.5 * (w[0] + w[1])));
        colours.extend([
            (coat.darkest() - 1e-4).max(0.0),
            coat.brightest() + 1e-4,
            0.0,
            1.0,
        ]);
        let (sigma_err, colour_err, bf_err) = worst_against_brute_force(&coat, &colours);
        std::println!(
            "{name}: {} colours, worst sigma error {sigma_err:.2e} (relative, or absolute \
             below 1e-3), worst colour residual {colour_err:.2e} (brute force {bf_err:.2e})",
            colours.len()
        );
        assert!(sigma_err < 2e-4, "{name}: sigma error {sigma_err}");
        assert!(colour_err < 2e-6, "{name}: colour residual {colour_err}");
    }
}

/// Human hair's coat colour table as measured (`CoatColour::measure`, `CoatWalk::DEFAULT`,
/// its LUT baked with the shipped budget; printed by the test
/// `base_colour::a_picked_colour_is_the_colour_the_coat_shows`, 2026-12-07): its last three
/// nodes are equal (made non-increasing), flat cells at the dark end.
const HUMAN_HAIR: [f32; COAT_NODES] = [
    0.987_292_9,
    0.778_039_63,
    0.585_170_8,
    0.442_182_1,
    0.336_811_27,
    0.256_772_82,
    0.196_196_87,
    0.150_884_8,
    0.115_661_1,
    0.088_859_47,
    0.068_062_45,
    0.052_314_308,
    0.040_565_83,
    0.031_613_313,
    0.025_129_395,
    0.020_566_378,
    0.017_502_695,
    0.015_589_191,
    0.014_507_53,
    0.013_986_28,
    0.013_796_063,
    0.013_768_798,
    0.013_768_798,
    0.013_768_798,
];
