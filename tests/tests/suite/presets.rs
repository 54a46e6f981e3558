//! Preset files (docs/model.md §9): the TOML built-ins agree bit for bit with the no_std constants,
//! and malformed files give one-line errors naming the file, the line and the field.

use bake::presets::{self, NamedPreset, PresetError};
use bcsdf_core::presets::PRESETS;
use bcsdf_core::{FurParams, FurParamsInput, Pigment, Rgb};

fn bits(v: f32) -> u32 {
    v.to_bits()
}

fn opt_bits(v: Option<f32>) -> Option<u32> {
    v.map(f32::to_bits)
}

/// Field-by-field, bit-for-bit comparison. The destructuring has no `..`, so a new field in
/// `FurParamsInput` breaks this test until it is compared too.
fn assert_same_input(toml: &FurParamsInput, core: &FurParamsInput, name: &str) {
    let FurParamsInput {
        eta_c,
        pigment,
        alpha_deg,
        beta_m_deg,
        beta_n_deg,
        l,
        kappa,
        eta_m,
        sigma_ms,
        sigma_ma,
        g,
        closure,
    } = *toml;
    assert_eq!(closure, core.closure, "{name}: closure");
    let scalars = [
        ("eta_c", eta_c, core.eta_c),
        ("alpha_deg", alpha_deg, core.alpha_deg),
        ("beta_m_deg", beta_m_deg, core.beta_m_deg),
        ("l", l, core.l),
        ("kappa", kappa, core.kappa),
        ("sigma_ms", sigma_ms, core.sigma_ms),
        ("sigma_ma", sigma_ma, core.sigma_ma),
        ("g", g, core.g),
    ];
    for (field, a, b) in scalars {
        assert_eq!(bits(a), bits(b), "{name}: {field}: toml {a} vs core {b}");
    }
    assert_eq!(
        opt_bits(beta_n_deg),
        opt_bits(core.beta_n_deg),
        "{name}: beta_n_deg: toml {beta_n_deg:?} vs core {:?}",
        core.beta_n_deg
    );
    assert_eq!(
        opt_bits(eta_m),
        opt_bits(core.eta_m),
        "{name}: eta_m: toml {eta_m:?} vs core {:?}",
        core.eta_m
    );
    match (pigment, core.pigment) {
        (Pigment::Absorption(Rgb(a)), Pigment::Absorption(Rgb(b))) => {
            assert_eq!(a.map(bits), b.map(bits), "{name}: sigma_ca: {a:?} vs {b:?}")
        }
        (
            Pigment::Melanin {
                eumelanin: ea,
                pheomelanin: pa,
            },
            Pigment::Melanin {
                eumelanin: eb,
                pheomelanin: pb,
            },
        ) => {
            assert_eq!(bits(ea), bits(eb), "{name}: eumelanin: {ea} vs {eb}");
            assert_eq!(bits(pa), bits(pb), "{name}: pheomelanin: {pa} vs {pb}");
        }
        (a, b) => panic!("{name}: colour given differently: toml {a:?} vs core {b:?}"),
    }
}

#[test]
fn toml_builtins_equal_core_constants_bit_for_bit() {
    let toml = presets::builtin().unwrap_or_else(|e| panic!("built-in presets.toml: {e}"));
    let toml_names: Vec<&str> = toml.iter().map(|p| p.name.as_str()).collect();
    let core_names: Vec<&str> = PRESETS.iter().map(|p| p.name).collect();
    assert_eq!(toml_names, core_names, "names or order differ");
    for (t, c) in toml.iter().zip(PRESETS.iter()) {
        assert_eq!(t.source, c.source, "{}: source differs", c.name);
        assert_same_input(&t.input, &c.input, c.name);
        // And the lookup helpers agree.
        assert_eq!(presets::find(&toml, c.name).map(|p| &p.name), Some(&t.name));
        assert_eq!(
            bcsdf_core::presets::find(c.name).map(|p| p.name),
            Some(c.name)
        );
    }
}

#[test]
fn builtin_text_is_the_repository_file_and_loads_from_disk() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../bcsdf-core/presets.toml");
    let on_disk = std::fs::read_to_string(path).unwrap();
    assert_eq!(presets::BUILTIN_TOML, on_disk);
    assert_eq!(
        presets::load_file(path).unwrap(),
        presets::builtin().unwrap()
    );
}

#[test]
fn every_builtin_validates_and_spec_requirements_hold() {
    let list = presets::builtin().unwrap();
    for p in &list {
        FurParams::new(&p.input).unwrap_or_else(|e| panic!("{}: {e}", p.name));
        assert!(!p.source.trim().is_empty(), "{}: no source", p.name);
    }
    // docs/model.md §9: a kappa = 0 preset and one with eta_m != eta_c.
    assert!(list.iter().any(|p| p.input.kappa == 0.0));
    assert!(list
        .iter()
        .any(|p| p.input.eta_m.is_some_and(|m| m != p.input.eta_c)));
}

// ---------------------------------------------------------------------------------------------
// The species table of docs/model.md §9: one source of truth for the species presets.

/// The rows between the `species-table` markers of docs/model.md §9: the preset name and the
/// ten cells as written (`—` where the table has no value).
fn species_table() -> Vec<(String, Vec<String>)> {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../docs/model.md");
    let text = std::fs::read_to_string(path).unwrap();
    let start = text
        .find("<!-- species-table")
        .expect("docs/model.md §9 has the species-table marker");
    let end = text[start..]
        .find("<!-- end species-table -->")
        .expect("the species table is closed")
        + start;
    let rows: Vec<(String, Vec<String>)> = text[start..end]
        .lines()
        .filter(|l| l.starts_with('|') && !l.starts_with("|---") && !l.starts_with("| preset"))
        .map(|l| {
            let cells: Vec<String> = l
                .trim_matches('|')
                .split('|')
                .map(|c| c.trim().to_string())
                .collect();
            assert_eq!(cells.len(), 11, "row {l:?}: a name and ten values");
            (cells[0].clone(), cells[1..].to_vec())
        })
        .collect();
    rows
}

fn number(cell: &str, what: &str) -> f32 {
    cell.parse()
        .unwrap_or_else(|e| panic!("{what}: {cell:?} is not a number: {e}"))
}

#[test]
fn species_presets_are_the_table_of_docs_model_value_by_value() {
    let table = species_table();
    assert_eq!(table.len(), 10, "ten fitted species");
    let toml = presets::builtin().unwrap();
    for (name, cells) in &table {
        let core = bcsdf_core::presets::PRESETS
            .iter()
            .find(|p| p.name == name)
            .unwrap_or_else(|| panic!("species {name} has no built-in preset"));
        // The TOML equals the constants (toml_builtins_equal_core_constants_bit_for_bit), so
        // checking the constants checks both; the file is checked too, cheaply.
        let file = presets::find(&toml, name).unwrap();
        assert_eq!(file.input, core.input, "{name}: file and constants differ");
        let p = core.input.resolved();
        let col = |i: usize, key: &str| number(&cells[i], &format!("{name} {key}"));
        let check = |got: f32, i: usize, key: &str| {
            assert_eq!(
                got.to_bits(),
                col(i, key).to_bits(),
                "{name}: {key} = {got}, table {}",
                cells[i]
            );
        };
        check(p.kappa, 0, "kappa");
        check(p.eta_c, 1, "eta_c");
        check(p.eta_m.unwrap(), 1, "eta_m (the table's one eta)");
        check(p.alpha_deg, 2, "alpha_deg");
        check(p.beta_m_deg, 3, "beta_m_deg");
        check(p.beta_n_deg.unwrap(), 4, "beta_n_deg");
        match p.pigment {
            Pigment::Absorption(rgb) => {
                for c in rgb.0 {
                    check(c, 5, "sigma_ca (grey: every channel)");
                }
            }
            other => panic!("{name}: colour {other:?}, the table gives sigma_ca"),
        }
        check(p.sigma_ms, 6, "sigma_ms");
        check(p.sigma_ma, 7, "sigma_ma");
        check(p.g, 8, "g");
        if cells[9] == "—" {
            assert_eq!(
                p.l, 0.5,
                "{name}: l not published takes the documented default 0.5"
            );
            assert!(
                core.source.contains("l not published"),
                "{name}: {}",
                core.source
            );
        } else {
            check(p.l, 9, "l");
            assert!(!core.source.contains("l not published"), "{name}");
        }
        assert!(
            core.source.contains("Table 4"),
            "{name}: source names the table"
        );
    }
}

#[test]
fn former_names_select_the_species_presets() {
    let list = presets::builtin().unwrap();
    for (old, new) in [
        ("yan-row-a", "bobcat"),
        ("yan-row-b", "red-fox"),
        ("yan-row-c", "raccoon"),
    ] {
        let (p, alias) = presets::lookup(&list, old).unwrap();
        assert_eq!(p.name, new);
        let note = alias.unwrap().to_string();
        assert!(note.contains(old) && note.contains(new), "{note}");
        assert_eq!(bcsdf_core::presets::find(old).unwrap().name, new);
        // A real name is found as itself, with no note.
        assert!(presets::lookup(&list, new).unwrap().1.is_none());
    }
    assert!(presets::lookup(&list, "yan-row-d").is_none());
}

// ---------------------------------------------------------------------------------------------
// User files and malformed files.

/// A valid user file; the comments give the line numbers the tests below rely on.
const GOOD: &str = r#"# my presets
[[preset]]
name = "cat"
source = "test data"
eta_c = 1.55
sigma_ca = [0.2, 0.3, 0.5]
alpha_deg = 3
beta_m_deg = 8
l = 1
kappa = 0.5
sigma_ms = 2
g = 0.6
"#;
// line 2: [[preset]], 3: name, 6: sigma_ca, 10: kappa, 12: g

const FILE: &str = "user.toml";

fn parse(text: &str) -> Result<Vec<NamedPreset>, PresetError> {
    presets::parse(text, FILE)
}

/// `GOOD` with line `line` (1-based) replaced by `with` (which may hold several lines or none).
fn edit(line: usize, with: &str) -> String {
    let mut lines: Vec<&str> = GOOD.lines().collect();
    assert!(line >= 1 && line <= lines.len());
    if with.is_empty() {
        lines.remove(line - 1);
    } else {
        lines[line - 1] = with;
    }
    lines.join("\n") + "\n"
}

/// Parses `text`, expects an error at `line`, and checks its one-line message holds `needles`.
#[track_caller]
fn expect_error(text: &str, line: usize, needles: &[&str]) -> String {
    let err = match parse(text) {
        Ok(list) => panic!("expected an error, parsed {list:?}"),
        Err(e) => e,
    };
    let msg = err.to_string();
    assert_eq!(err.file, FILE, "{msg}");
    assert_eq!(err.line, Some(line), "{msg}");
    assert!(
        msg.starts_with(&format!("{FILE}:{line}: ")),
        "message should start with file:line: {msg}"
    );
    assert!(!msg.contains('\n'), "message should be one line: {msg:?}");
    for needle in needles {
        assert!(msg.contains(needle), "{msg:?} should contain {needle:?}");
    }
    msg
}

#[test]
fn good_user_file_parses_with_defaults() {
    let list = parse(GOOD).unwrap();
    assert_eq!(list.len(), 1);
    let p = &list[0];
    assert_eq!((p.name.as_str(), p.source.as_str()), ("cat", "test data"));
    assert_eq!(p.input.pigment, Pigment::Absorption(Rgb([0.2, 0.3, 0.5])));
    // Integers are accepted for numbers; omitted keys take their documented defaults.
    assert_eq!(p.input.alpha_deg, 3.0);
    assert_eq!(p.input.beta_n_deg, None);
    assert_eq!(p.input.eta_m, None);
    assert_eq!(p.input.sigma_ma, 0.0);

    let scalar = parse(&edit(6, "sigma_ca = 0.25")).unwrap();
    assert_eq!(
        scalar[0].input.pigment,
        Pigment::Absorption(Rgb::splat(0.25))
    );
    let eu_only = parse(&edit(6, "eumelanin = 0.5")).unwrap();
    assert_eq!(
        eu_only[0].input.pigment,
        Pigment::Melanin {
            eumelanin: 0.5,
            pheomelanin: 0.0
        }
    );
    let pheo_only = parse(&edit(6, "pheomelanin = 0.7")).unwrap();
    assert_eq!(
        pheo_only[0].input.pigment,
        Pigment::Melanin {
            eumelanin: 0.0,
            pheomelanin: 0.7
        }
    );
}

#[test]
fn unknown_field_names_field_and_line() {
    expect_error(
        &edit(10, "kappa = 0.5\ncolour = 1"),
        11,
        &["colour", "unknown field"],
    );
}

#[test]
fn unknown_top_level_table_is_an_error() {
    expect_error(&GOOD.replace("[[preset]]", "[[presets]]"), 2, &["presets"]);
    expect_error(&GOOD.replace("[[preset]]", "[preset]"), 2, &["[[preset]]"]);
}

#[test]
fn wrong_value_type_names_field_preset_and_line() {
    expect_error(
        &edit(10, "kappa = \"half\""),
        10,
        &["kappa", "preset \"cat\""],
    );
    expect_error(&edit(3, "name = 7"), 3, &["name"]);
}

#[test]
fn out_of_range_value_names_field_value_range_and_line() {
    let msg = expect_error(&edit(10, "kappa = 1.2"), 10, &["preset \"cat\""]);
    assert_eq!(
        msg,
        "user.toml:10: preset \"cat\": invalid kappa = 1.2: valid range is [0, 0.99]"
    );
    expect_error(&edit(12, "g = 1"), 12, &["invalid g = 1", "(-1, 1)"]);
    expect_error(&edit(5, "eta_c = 0.9"), 5, &["invalid eta_c = 0.9"]);
    expect_error(
        &edit(6, "sigma_ca = [0.2, -1, 0.5]"),
        6,
        &["invalid sigma_ca = -1"],
    );
    expect_error(
        &edit(6, "eumelanin = -0.5"),
        6,
        &["invalid eumelanin = -0.5"],
    );
    expect_error(&edit(10, "kappa = nan"), 10, &["invalid kappa = NaN"]);
    // An optional field, when present, is checked where it is written.
    expect_error(
        &edit(10, "kappa = 0.5\neta_m = 1"),
        11,
        &["invalid eta_m = 1"],
    );
}

#[test]
fn missing_colour_is_an_error_at_the_preset() {
    expect_error(
        &edit(6, ""),
        2,
        &["preset \"cat\"", "no colour", "sigma_ca", "eumelanin"],
    );
}

#[test]
fn both_colour_forms_are_an_error() {
    expect_error(
        &edit(6, "sigma_ca = 0.3\neumelanin = 0.5"),
        6,
        &["sigma_ca", "eumelanin", "exactly one"],
    );
    expect_error(
        &edit(6, "pheomelanin = 0.1\nsigma_ca = 0.3"),
        7,
        &["sigma_ca", "pheomelanin"],
    );
}

#[test]
fn sigma_ca_array_needs_three_numbers() {
    expect_error(&edit(6, "sigma_ca = [0.2, 0.3]"), 6, &["sigma_ca", "three"]);
    expect_error(
        &edit(6, "sigma_ca = [0.2, 0.3, 0.4, 0.5]"),
        6,
        &["sigma_ca"],
    );
    expect_error(&edit(6, "sigma_ca = \"red\""), 6, &["sigma_ca"]);
}

#[test]
fn missing_required_field_is_an_error_at_the_preset() {
    expect_error(&edit(12, ""), 2, &["missing field", "g"]);
    expect_error(&edit(4, ""), 2, &["missing field", "source"]);
}

#[test]
fn duplicate_name_is_an_error_at_the_second_definition() {
    let text = format!("{GOOD}\n{}", GOOD.replace("# my presets\n", ""));
    // The second copy starts after GOOD's 12 lines and a blank line: header 14, name 15.
    expect_error(&text, 15, &["preset \"cat\"", "duplicate", "line 3"]);
}

#[test]
fn toml_syntax_error_gives_the_line() {
    expect_error(&edit(10, "kappa = 0.5 x"), 10, &[]);
    expect_error(&edit(10, "kappa = 0.5\nkappa = 0.6"), 11, &["kappa"]);
}

#[test]
fn error_in_a_later_preset_names_that_preset() {
    let second = GOOD
        .replace("# my presets\n", "")
        .replace("\"cat\"", "\"dog\"")
        .replace("kappa = 0.5", "kappa = \"x\"");
    let text = format!("{GOOD}{second}");
    // GOOD is 12 lines; in the second copy kappa is its 9th line.
    expect_error(&text, 21, &["preset \"dog\"", "kappa"]);
}

#[test]
fn empty_or_bad_names_and_empty_files_are_errors() {
    // Every form the name rule (docs/model.md §9) refuses: file, line 3 and the field named.
    for (toml_name, shown, why) in [
        (r#""""#, r#""""#, "is empty"),
        (r#""a\tb""#, r#""a\tb""#, "contains '\\t' at byte 1"),
        (r#""a\nb""#, r#""a\nb""#, "contains '\\n' at byte 1"),
        (
            r#""../escaped""#,
            r#""../escaped""#,
            "contains '/' at byte 2",
        ),
        (
            r#""../../home/x/.bashrc""#,
            r#""../../home/x/.bashrc""#,
            "contains '/'",
        ),
        (r#""/abs""#, r#""/abs""#, "contains '/' at byte 0"),
        (r#""a\\b""#, r#""a\\b""#, "contains '\\\\' at byte 1"),
        (r#""c:x""#, r#""c:x""#, "contains ':'"),
        (r#""my fur""#, r#""my fur""#, "contains ' '"),
        (
            r#""fourrure-é""#,
            r#""fourrure-é""#,
            "contains 'é' at byte 9",
        ),
        (r#"".hidden""#, r#"".hidden""#, "starts with '.'"),
        (r#""..""#, r#""..""#, "starts with '.'"),
        (r#""-rf""#, r#""-rf""#, "starts with '-'"),
        (r#""NUL""#, r#""NUL""#, "Windows device name NUL"),
        (r#""com1.fur""#, r#""com1.fur""#, "Windows device name COM1"),
        (
            r#""aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa""#,
            "\"aaaa",
            "is 65 bytes long; at most 64",
        ),
    ] {
        let msg = expect_error(
            &edit(3, &format!("name = {toml_name}")),
            3,
            &[&format!("name {shown}"), why],
        );
        assert!(msg.starts_with(&format!("{FILE}:3: name ")), "{msg}");
    }
    // A bad name in a later preset names that preset's line.
    let second = GOOD.replace("\"cat\"", "\"../dog\"");
    expect_error(
        &format!("{GOOD}{second}"),
        15,
        &["name \"../dog\" contains '/'"],
    );
    let err = parse("# nothing here\n").unwrap_err();
    assert!(err.to_string().contains("no presets"), "{err}");
}

#[test]
fn load_file_names_the_path() {
    let dir = env!("CARGO_TARGET_TMPDIR");
    let path = format!("{dir}/presets-test-{}.toml", std::process::id());
    std::fs::write(&path, edit(10, "kappa = 2")).unwrap();
    let err = presets::load_file(&path).unwrap_err().to_string();
    std::fs::remove_file(&path).unwrap();
    assert!(err.starts_with(&format!("{path}:10: ")), "{err}");
    assert!(err.contains("invalid kappa = 2"), "{err}");

    let missing = format!("{dir}/no-such-presets.toml");
    let err = presets::load_file(&missing).unwrap_err().to_string();
    assert!(
        err.starts_with(&missing) && err.contains("cannot read"),
        "{err}"
    );
}

// ---------------------------------------------------------------------------------------------
// `--set key=value` overrides.

#[test]
fn overrides_apply_in_order() {
    let mut input = presets::builtin().unwrap()[0].input;
    bake::apply_overrides(
        &mut input,
        ["kappa=0.25", "sigma_ca=0.1,0.2,0.3", "g = -0.5"],
    )
    .unwrap();
    assert_eq!(input.kappa, 0.25);
    assert_eq!(input.g, -0.5);
    assert_eq!(input.pigment, Pigment::Absorption(Rgb([0.1, 0.2, 0.3])));
    bake::apply_overrides(
        &mut input,
        ["sigma_ca=0", "eumelanin=2", "beta_n_deg=3", "eta_m=1.3"],
    )
    .unwrap();
    assert_eq!(
        input.pigment,
        Pigment::Melanin {
            eumelanin: 2.0,
            pheomelanin: 0.0
        }
    );
    assert_eq!((input.beta_n_deg, input.eta_m), (Some(3.0), Some(1.3)));
    FurParams::new(&input).unwrap();
}

#[test]
fn bad_overrides_name_the_problem_and_leave_input_unchanged() {
    let original = presets::builtin().unwrap()[0].input;
    let cases: [(&str, &[&str]); 7] = [
        (
            "colour=1",
            &[
                "unknown parameter key `colour`",
                "eta_c",
                "sigma_ca",
                "kappa",
                "g",
            ],
        ),
        ("kappa", &["`kappa`", "KEY=VALUE"]),
        ("kappa=abc", &["`abc` is not a number"]),
        ("kappa=1.2", &["invalid kappa = 1.2", "[0, 0.99]"]),
        ("kappa=0.1,0.2,0.3", &["kappa takes one value"]),
        ("sigma_ca=0.1,0.2", &["sigma_ca takes one value or three"]),
        ("sigma_ca=0.1,-2,0.3", &["invalid sigma_ca = -2"]),
    ];
    for (spec, needles) in cases {
        let mut input = original;
        let err = bake::apply_overrides(&mut input, ["kappa=0.3", spec]).unwrap_err();
        let msg = err.to_string();
        assert_eq!(err.spec, spec);
        for needle in needles {
            assert!(
                msg.contains(needle),
                "{spec}: {msg:?} should contain {needle:?}"
            );
        }
        assert_eq!(input, original, "{spec}: input changed on error");
    }
}
