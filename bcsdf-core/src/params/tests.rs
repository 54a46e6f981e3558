//! Unit tests of the parameter schema and the input setters.

extern crate std;
use super::*;
use std::string::ToString;
use std::vec::Vec;

fn human_hair() -> FurParamsInput {
    crate::presets::find("human-hair").unwrap().input
}

#[test]
fn schema_rows_follow_all_and_keys_are_unique() {
    for (i, (spec, name)) in SCHEMA.iter().zip(ParamName::ALL).enumerate() {
        assert_eq!(spec.name, name, "row {i}");
        assert_eq!(name.spec(), spec);
        assert_eq!(ParamName::from_key(spec.key), Some(name));
        assert!(
            SCHEMA[..i].iter().all(|s| s.key != spec.key),
            "{}",
            spec.key
        );
        assert!(!spec.symbol.is_empty() && !spec.meaning.is_empty());
    }
    assert_eq!(ParamName::from_key("Eta_C"), None);
    assert_eq!(ParamName::from_key(""), None);
}

#[test]
fn domain_text_is_interval_notation() {
    assert_eq!(ParamName::EtaC.domain().to_string(), "(1, 3]");
    assert_eq!(ParamName::Kappa.domain().to_string(), "[0, 0.99]");
    assert_eq!(ParamName::G.domain().to_string(), "(-1, 1)");
    assert_eq!(ParamName::AlphaDeg.domain().to_string(), "[-30, 30]");
}

#[test]
fn domains_honour_open_and_closed_ends() {
    for spec in &SCHEMA {
        let d = spec.domain;
        assert_eq!(d.contains(d.lo), d.lo_inclusive, "{}", spec.key);
        assert_eq!(d.contains(d.hi), d.hi_inclusive, "{}", spec.key);
        assert!(d.contains(0.5 * (d.lo + d.hi)), "{}", spec.key);
        for bad in [
            f32::NAN,
            f32::INFINITY,
            f32::NEG_INFINITY,
            d.lo - 1.0,
            d.hi + 1.0,
        ] {
            assert!(!d.contains(bad), "{} {bad}", spec.key);
            assert!(spec.name.check(bad).is_err());
        }
    }
}

#[test]
fn param_error_names_key_value_and_range() {
    let e = ParamName::Kappa.check(1.2).unwrap_err();
    assert_eq!(
        e.to_string(),
        "invalid kappa = 1.2: valid range is [0, 0.99]"
    );
    let mut input = human_hair();
    input.g = 1.0;
    let e = FurParams::new(&input).unwrap_err();
    assert_eq!(e.name, ParamName::G);
}

#[test]
fn set_value_then_value_round_trips_every_parameter() {
    for (i, spec) in SCHEMA.iter().enumerate() {
        let mut input = human_hair();
        let v = 0.25 + i as f32 * 0.01;
        if spec.is_choice() {
            // A choice takes whole indices only; anything else leaves it unchanged.
            for (k, name) in spec.choices.iter().enumerate() {
                input.set_value(spec.name, ParamValue::Choice(k as u8));
                assert_eq!(input.value(spec.name), Some(ParamValue::Choice(k as u8)));
                assert_eq!(spec.choice_index(name), Some(k as u8));
                assert_eq!(spec.choice_name(k as u8), Some(*name));
                input.set(spec.name, v);
                assert_eq!(input.value(spec.name), Some(ParamValue::Choice(k as u8)));
            }
            assert_eq!(spec.choice_index("neither"), None);
            assert!(ParamName::Closure.check(0.5).is_err());
            assert!(ParamName::Closure.check(2.0).is_err());
            assert_eq!(ParamName::Closure.check(1.0), Ok(1.0));
            continue;
        }
        input.set(spec.name, v);
        let expected = if spec.name.takes_rgb() {
            ParamValue::Rgb(Rgb::splat(v))
        } else {
            ParamValue::Scalar(v)
        };
        assert_eq!(input.value(spec.name), Some(expected), "{}", spec.key);
    }
    let mut input = human_hair();
    input.set_value(ParamName::SigmaCa, ParamValue::Rgb(Rgb([0.1, 0.2, 0.3])));
    assert_eq!(input.pigment, Pigment::Absorption(Rgb([0.1, 0.2, 0.3])));
    assert_eq!(input.value(ParamName::Eumelanin), None);
    input.set_value(
        ParamName::BaseColour,
        ParamValue::Rgb(Rgb([0.5, 0.25, 0.1])),
    );
    assert_eq!(input.pigment, Pigment::BaseColour(Rgb([0.5, 0.25, 0.1])));
    assert_eq!(input.value(ParamName::SigmaCa), None);
    // A base colour builds no model until the coat table has turned it into σ_ca, and the
    // error says so; a channel outside [0, 1] is refused as any other value.
    let e = FurParams::new(&input).unwrap_err();
    assert_eq!(e.name, ParamName::BaseColour);
    assert!(e.to_string().contains("coat colour table"), "{e}");
    input.set_value(ParamName::BaseColour, ParamValue::Rgb(Rgb([0.5, 1.5, 0.1])));
    let e = FurParams::new(&input).unwrap_err();
    assert_eq!(
        e.to_string(),
        "invalid base_colour = 1.5: valid range is [0, 1]"
    );
}

#[test]
fn colour_forms_exclude_each_other() {
    let mut input = human_hair();
    input.set(ParamName::SigmaCa, 0.7);
    input.set(ParamName::Eumelanin, 1.5);
    assert_eq!(input.value(ParamName::SigmaCa), None);
    assert_eq!(
        input.value(ParamName::Pheomelanin),
        Some(ParamValue::Scalar(0.0))
    );
    input.set(ParamName::Pheomelanin, 0.5);
    assert_eq!(
        input.pigment,
        Pigment::Melanin {
            eumelanin: 1.5,
            pheomelanin: 0.5
        }
    );
    input.set(ParamName::SigmaCa, 2.0);
    assert_eq!(input.value(ParamName::Eumelanin), None);
    assert_eq!(
        input.value(ParamName::SigmaCa),
        Some(ParamValue::Rgb(Rgb::splat(2.0)))
    );
}

#[test]
fn resolved_fills_same_as_defaults_only() {
    let mut input = human_hair();
    input.beta_n_deg = None;
    input.eta_m = None;
    let r = input.resolved();
    assert_eq!(r.beta_n_deg, Some(input.beta_m_deg));
    assert_eq!(r.eta_m, Some(input.eta_c));
    assert_eq!(r.resolved(), r);
    input.eta_m = Some(1.4);
    assert_eq!(input.resolved().eta_m, Some(1.4));
    // Validation gives the same parameters either way.
    assert_eq!(FurParams::new(&input), FurParams::new(&input.resolved()));
}

#[test]
fn header_fields_follow_the_schema_order() {
    // The encoder writes `fields`, the decoder reads `ParamName::ALL`: the same order, the
    // colour as one record at σ_ca's position (eumelanin and pheomelanin inside it).
    let fields = human_hair().resolve().fields();
    let names: Vec<ParamName> = fields
        .iter()
        .map(|f| match f {
            HeaderField::Pigment(_) => ParamName::SigmaCa,
            HeaderField::Scalar(name, _) | HeaderField::Choice(name, _) => *name,
        })
        .collect();
    let want: Vec<ParamName> = ParamName::ALL
        .into_iter()
        .filter(|n| !n.is_colour() || *n == ParamName::SigmaCa)
        .collect();
    assert_eq!(names, want);
    assert_eq!(fields.len(), HEADER_FIELDS);
    // Each scalar field carries the resolved value of its parameter.
    let r = human_hair().resolved();
    for f in fields {
        match f {
            HeaderField::Scalar(name, v) => {
                assert_eq!(r.value(name), Some(ParamValue::Scalar(v)), "{name}");
            }
            HeaderField::Choice(name, i) => {
                assert_eq!(r.value(name), Some(ParamValue::Choice(i)), "{name}");
            }
            HeaderField::Pigment(p) => assert_eq!(p, r.pigment),
        }
    }
}

#[test]
fn resolve_applies_every_same_as_row_of_the_schema() {
    // Walks SCHEMA, so a new `SameAs` row that `resolve` does not apply fails here.
    let mut same_as = 0;
    for spec in &SCHEMA {
        if let ParamDefault::SameAs(source) = spec.default {
            same_as += 1;
            let mut input = human_hair();
            input.beta_n_deg = None;
            input.eta_m = None;
            // A distinct source value, so that a default from the wrong source shows.
            input.set(source, 1.234);
            let r = input.resolved();
            assert_eq!(
                r.value(spec.name),
                Some(ParamValue::Scalar(1.234)),
                "{}",
                spec.name
            );
            let fields = input.resolve().fields();
            assert!(
                fields.contains(&HeaderField::Scalar(spec.name, 1.234)),
                "{}",
                spec.name
            );
        }
    }
    assert_eq!(same_as, 2);
}
