//! The parameter schema ([`bcsdf_core::SCHEMA`]) walked through every serialisation of the
//! parameter set: for each row a distinctive value is set, written in the format and read
//! back. A parameter added to the schema that some format does not carry fails here; the
//! viewer's summary page has the same walk in `viewer/tests/suite/compare.rs`.

use bake::presets;
use bake::tables::{encode, TableValues};
use bake::Override;
use bcsdf_core::lut::{LutHeader, LutResolution, Table, TABLE_COUNT};
use bcsdf_core::{FurParamsInput, ParamName, ParamValue, Rgb, SCHEMA};

/// A value a quarter of the way into `name`'s domain: valid, and unlike any preset's.
fn quarter(name: ParamName) -> f32 {
    let d = name.domain();
    d.lo + 0.25 * (d.hi - d.lo)
}

/// For every schema row: a valid input (bobcat, or human-hair for the melanin rows) with
/// that row set to a distinctive value, and the value.
fn one_per_row() -> Vec<(ParamName, FurParamsInput, ParamValue)> {
    SCHEMA
        .iter()
        .map(|spec| {
            let mut input = bcsdf_core::presets::find("bobcat").unwrap().input;
            let value = match spec.name {
                ParamName::SigmaCa | ParamName::BaseColour => {
                    let q = quarter(spec.name);
                    ParamValue::Rgb(Rgb([q, 0.5 * q, 0.25 * q]))
                }
                // A choice: the one that is not the default.
                _ if spec.is_choice() => match input.value(spec.name) {
                    Some(ParamValue::Choice(i)) => ParamValue::Choice(1 - i),
                    other => panic!("{}: {other:?}", spec.key),
                },
                n => ParamValue::Scalar(quarter(n)),
            };
            input.set_value(spec.name, value);
            // What preset files and overrides are checked with (a base colour becomes σ_ca
            // through a LUT's coat colour table, docs/model.md §14).
            input
                .check()
                .unwrap_or_else(|e| panic!("{}: {e}", spec.key));
            (spec.name, input, value)
        })
        .collect()
}

fn toml_of(name: &str, input: &FurParamsInput) -> String {
    let mut text = format!("[[preset]]\nname = \"{name}\"\nsource = \"schema walk\"\n");
    for spec in &SCHEMA {
        match input.value(spec.name) {
            Some(ParamValue::Scalar(v)) => text += &format!("{} = {v:?}\n", spec.key),
            Some(ParamValue::Rgb(c)) => {
                text += &format!(
                    "{} = [{:?}, {:?}, {:?}]\n",
                    spec.key, c.0[0], c.0[1], c.0[2]
                )
            }
            Some(ParamValue::Choice(i)) => {
                text += &format!("{} = \"{}\"\n", spec.key, spec.choices[usize::from(i)])
            }
            None => {}
        }
    }
    text
}

#[test]
fn lut_header_carries_every_parameter() {
    let res = LutResolution {
        n_sum: 2,
        n_theta_r: 2,
        n_phi: 2,
        n_ms_i: 2,
        n_ms_r: 2,
        n_abs: 3,
    };
    let mut tables: [Vec<f32>; TABLE_COUNT] = Default::default();
    for t in Table::ALL {
        tables[t as usize] = vec![1.0; res.values(t)];
    }
    let values = TableValues { res, tables };
    for (name, input, value) in one_per_row() {
        let blob = encode(&values, &input, None);
        if name == ParamName::BaseColour {
            // A LUT records the σ_ca its base colour resolves to (`bake::colour`), never the
            // colour: a header holding one is refused, by name.
            let e = LutHeader::decode(&blob).unwrap_err().to_string();
            assert!(e.contains("base_colour"), "{e}");
            continue;
        }
        let header = LutHeader::decode(&blob).unwrap();
        assert_eq!(header.params.value(name), Some(value), "{name}");
        assert_eq!(header.params, input.resolved(), "{name}");
    }
}

#[test]
fn preset_toml_carries_every_parameter() {
    for (name, input, value) in one_per_row() {
        let text = toml_of("walk", &input);
        let parsed = presets::parse(&text, "walk.toml").unwrap_or_else(|e| panic!("{e}\n{text}"));
        assert_eq!(parsed[0].input.value(name), Some(value), "{name}\n{text}");
        assert_eq!(parsed[0].input, input, "{name}\n{text}");
    }
}

#[test]
fn set_overrides_reach_every_parameter() {
    for (name, _, value) in one_per_row() {
        let text = match value {
            ParamValue::Scalar(v) => format!("{}={v}", name.key()),
            ParamValue::Rgb(c) => format!("{}={},{},{}", name.key(), c.0[0], c.0[1], c.0[2]),
            ParamValue::Choice(i) => {
                format!("{}={}", name.key(), name.spec().choices[usize::from(i)])
            }
        };
        let mut input = bcsdf_core::presets::find("human-hair").unwrap().input;
        Override::parse(&text).unwrap().apply(&mut input);
        assert_eq!(input.value(name), Some(value), "{text}");
    }
}

#[test]
fn closure_takes_its_names_and_nothing_else() {
    // --set: the names, and one clear error for anything else.
    for (text, want) in [("closure=report", 0u8), ("closure = energy", 1)] {
        let o = Override::parse(text).unwrap();
        assert_eq!(o.value, ParamValue::Choice(want), "{text}");
    }
    for text in ["closure=1", "closure=Energy", "closure="] {
        let e = Override::parse(text).unwrap_err().to_string();
        assert!(e.contains("valid values are report, energy"), "{text}: {e}");
    }
    // Preset files: a string naming one of them.
    let base = "[[preset]]\nname = \"c\"\nsource = \"s\"\neta_c = 1.5\nsigma_ca = 0.1\n\
                alpha_deg = 2\nbeta_m_deg = 5\nl = 0.5\nkappa = 0\nsigma_ms = 0\ng = 0\n";
    let parsed = presets::parse(&format!("{base}closure = \"energy\"\n"), "c.toml").unwrap();
    assert_eq!(parsed[0].input.closure, bcsdf_core::Closure::Energy);
    let parsed = presets::parse(base, "c.toml").unwrap();
    assert_eq!(
        parsed[0].input.closure,
        bcsdf_core::Closure::Energy,
        "the default (docs/model.md §12 Status)"
    );
    for bad in ["closure = \"both\"", "closure = 1"] {
        let e = presets::parse(&format!("{base}{bad}\n"), "c.toml")
            .unwrap_err()
            .to_string();
        assert!(e.contains("\"report\" or \"energy\""), "{bad}: {e}");
    }
}
