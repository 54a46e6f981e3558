//! Robustness (docs/model.md §2, §8): S ≥ 0 and finite for every input; invalid parameters are
//! rejected with an error that names the parameter and its value.
//!
//! Inputs are arbitrary f32 (NaN, ±inf, subnormals, huge values, zero or unnormalised
//! vectors, h outside [−1, 1], θ beyond ±90° through the direction API), for every preset and
//! for random valid parameters across the whole valid domain. Case counts are modest: a far
//! field evaluation costs 10–40 µs, and up to ~1 ms for the narrowest roughness.

use bcsdf_core::{
    presets, Angles, FurBcsdf, FurParams, FurParamsInput, Lobes, ParamName, ParamValue, Pigment,
    Rgb, Vec3, LOBE_COUNT,
};
use proptest::prelude::*;

fn assert_valid(l: &Lobes, what: &str) {
    for (lobe, v) in l.iter() {
        for c in v.0 {
            assert!(c.is_finite() && c >= 0.0, "{what}: {} = {c}", lobe.name());
        }
    }
}

fn assert_valid_n(n: &[Rgb; LOBE_COUNT], what: &str) {
    for (i, v) in n.iter().enumerate() {
        for c in v.0 {
            assert!(c.is_finite() && c >= 0.0, "{what}: lobe {i} = {c}");
        }
    }
}

/// Any f32, with the special values made frequent.
fn any_f32() -> impl Strategy<Value = f32> {
    prop_oneof![
        3 => proptest::num::f32::ANY,
        2 => -4.0f32..4.0,
        1 => prop::sample::select(vec![
            f32::NAN,
            f32::INFINITY,
            f32::NEG_INFINITY,
            0.0,
            -0.0,
            1.0,
            -1.0,
            f32::MAX,
            f32::MIN,
            f32::MIN_POSITIVE,
            1e-40,
            core::f32::consts::FRAC_PI_2,
            -core::f32::consts::FRAC_PI_2,
            core::f32::consts::PI,
            1.000_000_1,
        ]),
    ]
}

fn any_vec() -> impl Strategy<Value = Vec3> {
    prop_oneof![
        3 => [any_f32(), any_f32(), any_f32()],
        3 => [-2.0f32..2.0, -2.0f32..2.0, -2.0f32..2.0],
        1 => Just([0.0, 0.0, 0.0]),
        1 => [-1e-30f32..1e-30, -1e-30f32..1e-30, -1e-30f32..1e-30],
        1 => [-1e30f32..1e30, -1e30f32..1e30, -1e30f32..1e30],
    ]
}

/// Valid parameters over the whole valid domain (including its closed ends).
fn valid_input() -> impl Strategy<Value = FurParamsInput> {
    let eta = prop_oneof![4 => 1.0001f32..=3.0, 1 => Just(3.0f32), 1 => Just(1.000_001f32)];
    let sigma = prop_oneof![3 => 0.0f32..=10.0, 1 => 0.0f32..=1000.0, 1 => Just(0.0f32)];
    let beta = prop_oneof![3 => 0.5f32..=45.0, 1 => Just(0.5f32), 1 => Just(45.0f32)];
    let pigment = prop_oneof![
        (sigma.clone(), sigma.clone(), sigma.clone())
            .prop_map(|(r, g, b)| Pigment::Absorption(Rgb([r, g, b]))),
        (0.0f32..=100.0, 0.0f32..=100.0).prop_map(|(e, p)| Pigment::Melanin {
            eumelanin: e,
            pheomelanin: p
        }),
    ];
    (
        (eta.clone(), pigment, -30.0f32..=30.0, beta.clone()),
        (
            prop::option::of(beta),
            prop_oneof![0.0f32..=64.0, Just(0.0f32), Just(0.5f32)],
            prop_oneof![0.0f32..=0.99, Just(0.0f32), Just(0.99f32)],
            prop::option::of(eta),
        ),
        (0.0f32..=100.0, 0.0f32..=100.0, -0.999f32..=0.999),
    )
        .prop_map(
            |(
                (eta_c, pigment, alpha_deg, beta_m_deg),
                (beta_n_deg, l, kappa, eta_m),
                (sms, sma, g),
            )| {
                FurParamsInput {
                    eta_c,
                    pigment,
                    alpha_deg,
                    beta_m_deg,
                    beta_n_deg,
                    l,
                    kappa,
                    eta_m,
                    sigma_ms: sms,
                    sigma_ma: sma,
                    g,
                    closure: bcsdf_core::Closure::Energy,
                }
            },
        )
}

/// A preset or random valid parameters.
fn model_input() -> impl Strategy<Value = FurParamsInput> {
    prop_oneof![
        1 => (0..presets::PRESETS.len()).prop_map(|i| presets::PRESETS[i].input),
        2 => valid_input(),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 1024, failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn near_field_is_finite_and_non_negative(
        input in model_input(),
        ti in any_f32(), tr in any_f32(), phi in any_f32(), h in any_f32(),
        wi in any_vec(), wr in any_vec(), u in any_vec(),
    ) {
        let model: FurBcsdf = FurBcsdf::unscattered(FurParams::new(&input).expect("valid input"));
        // Angles: raw radians (rejected unless valid), degrees, and clamped into range.
        let half = core::f32::consts::FRAC_PI_2;
        let clamp = |x: f32| if x.is_finite() { x.clamp(-half, half) } else { 0.3 };
        let angles = [
            Angles::new(ti, tr, phi).ok(),
            Angles::from_degrees(ti, tr, phi).ok(),
            Angles::new(clamp(ti), clamp(tr), if phi.is_finite() { phi } else { 1.0 }).ok(),
        ];
        for a in angles.iter().flatten() {
            assert_valid(&model.eval_near(a, h), "eval_near");
            assert_valid(&model.eval_near(a, 0.5), "eval_near h=0.5");
        }
        assert_valid(&model.eval_near_dirs(wi, wr, u, h), "eval_near_dirs");
        assert_valid_n(&model.azimuthal_near(tr, phi, h), "azimuthal_near");
        // An offset outside [−1, 1] (or NaN) misses the fiber: exactly zero.
        if !(-1.0..=1.0).contains(&h) {
            for a in angles.iter().flatten() {
                prop_assert_eq!(model.eval_near(a, h), Lobes::ZERO);
            }
        }
    }

    #[test]
    fn invalid_directions_give_zero_or_valid_values(
        wi in any_vec(), wr in any_vec(), u in any_vec(), h in -1.0f32..=1.0,
    ) {
        let model: FurBcsdf = FurBcsdf::unscattered(FurParams::new(&presets::find("air-medulla").unwrap().input).unwrap());
        let near = model.eval_near_dirs(wi, wr, u, h);
        assert_valid(&near, "eval_near_dirs");
        let non_finite = wi.iter().chain(&wr).chain(&u).any(|c| !c.is_finite());
        if non_finite || [wi, wr, u].contains(&[0.0; 3]) {
            prop_assert_eq!(near, Lobes::ZERO);
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn far_field_is_finite_and_non_negative(
        input in model_input(),
        ti in any_f32(), tr in any_f32(), phi in any_f32(),
        wi in any_vec(), wr in any_vec(), u in any_vec(),
    ) {
        let model: FurBcsdf = FurBcsdf::unscattered(FurParams::new(&input).expect("valid input"));
        if let Ok(a) = Angles::new(ti, tr, phi) {
            assert_valid(&model.eval_far_lobes(&a), "eval_far");
        }
        let half = core::f32::consts::FRAC_PI_2;
        let clamp = |x: f32| if x.is_finite() { x.clamp(-half, half) } else { -0.7 };
        let a = Angles::new(clamp(ti), clamp(tr), if phi.is_finite() { phi } else { 2.0 }).unwrap();
        assert_valid(&model.eval_far_lobes(&a), "eval_far (clamped)");
        if let Ok(a) = Angles::from_degrees(ti, tr, phi) {
            assert_valid(&model.eval_far_lobes(&a), "eval_far (degrees)");
        }
        assert_valid(&model.eval_far_dirs(wi, wr, u), "eval_far_dirs");
        assert_valid_n(&model.azimuthal_far(tr, phi), "azimuthal_far");
        // Directions along the tangent, where ω·u/(|ω||u|) can round past ±1 (θ beyond ±90°
        // before clamping), with unnormalised lengths.
        for (d, t) in [([0.0, 0.0, 3.0], [0.0, 0.0, 1e-3]), ([1e-7, 1e-7, -7.0], [0.1, 0.1, 1e3])] {
            assert_valid(&model.eval_far_dirs(d, wr, t), "far along the tangent");
            assert_valid(&model.eval_near_dirs(wi, d, t, 0.3), "near along the tangent");
        }
    }
}

/// The number parameters: every schema row but the choices (`closure`, whose field is typed).
fn numbers() -> Vec<ParamName> {
    ParamName::ALL
        .into_iter()
        .filter(|n| !n.spec().is_choice())
        .collect()
}

/// One parameter set to an invalid value (σ_ca, the base colour: in the green channel only).
fn set_invalid(input: &mut FurParamsInput, name: ParamName, v: f32) {
    match name {
        ParamName::SigmaCa | ParamName::BaseColour => {
            input.set_value(name, ParamValue::Rgb(Rgb([0.5, v, 0.5])));
        }
        _ => input.set(name, v),
    }
}

/// Invalid values per docs/model.md §2: non-finite anything; η ≤ 1; negative σ and melanin; κ ≥ 1
/// or negative; g ∉ (−1, 1); non-positive roughness; negative layers.
fn invalid_value(name: ParamName) -> BoxedStrategy<f32> {
    let non_finite = prop::sample::select(vec![f32::NAN, f32::INFINITY, f32::NEG_INFINITY]);
    let negative = prop_oneof![-1e30f32..-1e-30, Just(-f32::MIN_POSITIVE), Just(-1.0)];
    let class = match name {
        ParamName::EtaC | ParamName::EtaM => {
            prop_oneof![-1e30f32..=1.0, Just(1.0f32), Just(0.999_999_9)].boxed()
        }
        ParamName::SigmaCa
        | ParamName::Eumelanin
        | ParamName::Pheomelanin
        | ParamName::SigmaMs
        | ParamName::SigmaMa
        | ParamName::L => negative.boxed(),
        ParamName::Kappa => prop_oneof![1.0f32..1e30, Just(1.0f32), negative].boxed(),
        ParamName::G => {
            prop_oneof![1.0f32..1e30, -1e30f32..=-1.0, Just(1.0f32), Just(-1.0f32)].boxed()
        }
        ParamName::BetaMDeg | ParamName::BetaNDeg => {
            prop_oneof![-1e30f32..=0.0, Just(0.0f32)].boxed()
        }
        ParamName::AlphaDeg => prop_oneof![90.0f32..1e30, -1e30f32..-90.0].boxed(),
        // A linear colour channel: outside [0, 1].
        ParamName::BaseColour => prop_oneof![1.0001f32..1e30, negative].boxed(),
        // Not a whole index of a choice (`closure`); not drawn below, since the typed field
        // cannot hold it (its parsers' errors are tested in bake).
        ParamName::Closure => prop_oneof![Just(0.5f32), Just(2.0f32)].boxed(),
    };
    prop_oneof![1 => non_finite, 3 => class].boxed()
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 1024, failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn invalid_parameters_are_rejected_by_name(
        (name, v) in proptest::sample::select(numbers())
            .prop_flat_map(|n| (Just(n), invalid_value(n))),
        base in 0..presets::PRESETS.len(),
    ) {
        let mut input = presets::PRESETS[base].input;
        set_invalid(&mut input, name, v);
        let err = FurParams::new(&input).expect_err("invalid parameter accepted");
        prop_assert_eq!(err.name, name);
        let msg = err.to_string();
        prop_assert!(msg.contains(name.key()), "{msg:?} does not name {}", name.key());
        prop_assert!(msg.contains(&v.to_string()), "{msg:?} does not show the value {v}");
    }
}

#[test]
fn every_preset_is_valid() {
    for p in presets::PRESETS.iter() {
        FurParams::new(&p.input).unwrap_or_else(|e| panic!("{}: {e}", p.name));
    }
}
