//! The preset list: built-in or from `--presets FILE`; `viewer presets`.

use crate::cli::{PresetsArgs, PresetsListArgs};
use crate::error::Error;
use crate::json;
use bake::presets::{self, NamedPreset};
use bcsdf_core::presets::{Alias, ALIASES};
use bcsdf_core::{FurParamsInput, ParamName, ParamSpec, ParamValue, Pigment, Rgb, SCHEMA};
use std::io::{self, BufWriter, Write};

/// The presets `args` selects: the file's with `--presets FILE`, else the built-in ones.
pub fn load(args: &PresetsArgs) -> Result<Vec<NamedPreset>, Error> {
    match &args.presets {
        Some(path) => presets::load_file(path),
        None => presets::builtin(),
    }
    .map_err(Error::input)
}

/// The preset called `name` (or the one a former name selects, with a one-line note on
/// stderr); the error lists the known names.
pub fn find<'a>(list: &'a [NamedPreset], name: &str) -> Result<&'a NamedPreset, Error> {
    let (preset, alias) = presets::lookup(list, name).ok_or_else(|| {
        let known: Vec<&str> = list.iter().map(|p| p.name.as_str()).collect();
        Error::input(format!(
            "unknown preset `{name}` (known presets: {})",
            known.join(", ")
        ))
    })?;
    if let Some(alias) = alias {
        eprintln!("note: {alias}");
    }
    Ok(preset)
}

/// `viewer presets`: the parameter table (one column per [`SCHEMA`] row, the colour keys
/// as one σ_ca column; values as resolved, so defaults show), the provenance of each preset,
/// and the former names; or, with `--json`, the same as one JSON document.
pub fn list(args: &PresetsListArgs) -> Result<(), Error> {
    let list = load(&args.presets)?;
    let mut out = BufWriter::new(io::stdout().lock());
    if args.json {
        json::write_line(&mut out, &PresetsJson::new(&list))?;
    } else {
        write_table(&mut out, &list)?;
    }
    out.flush()?;
    Ok(())
}

/// The schema rows that get a column: every row but the melanin concentrations and the base
/// colour, which share σ_ca's column.
fn columns() -> impl Iterator<Item = &'static ParamSpec> {
    SCHEMA.iter().filter(|s| {
        !matches!(
            s.name,
            ParamName::Eumelanin | ParamName::Pheomelanin | ParamName::BaseColour
        )
    })
}

/// One cell: a number as the shortest text that reads back the same; an RGB σ_ca as one
/// number when grey; a melanin colour as its concentrations.
fn cell(input: &FurParamsInput, spec: &ParamSpec) -> String {
    if spec.name == ParamName::SigmaCa {
        if let Pigment::Melanin {
            eumelanin,
            pheomelanin,
        } = input.pigment
        {
            return format!("eu={eumelanin},pheo={pheomelanin}");
        }
        if let Pigment::BaseColour(Rgb([r, g, b])) = input.pigment {
            return format!("base={r},{g},{b}");
        }
    }
    match input.resolved().value(spec.name) {
        Some(ParamValue::Scalar(v)) => format!("{v}"),
        Some(ParamValue::Rgb(Rgb([r, g, b]))) if r == g && g == b => format!("{r}"),
        Some(ParamValue::Rgb(Rgb([r, g, b]))) => format!("{r},{g},{b}"),
        Some(ParamValue::Choice(i)) => spec.choice_name(i).unwrap_or("?").to_string(),
        None => String::from("-"),
    }
}

/// The former names that select a preset of `list` ([`presets::lookup`]).
fn live_aliases(list: &[NamedPreset]) -> impl Iterator<Item = &'static Alias> + '_ {
    ALIASES.iter().filter(|a| {
        presets::find(list, a.preset).is_some() && presets::find(list, a.name).is_none()
    })
}

fn header(spec: &ParamSpec) -> String {
    match spec.unit {
        "deg" => format!("{}°", spec.symbol),
        _ => spec.symbol.to_string(),
    }
}

fn write_table(out: &mut impl Write, list: &[NamedPreset]) -> io::Result<()> {
    let mut rows: Vec<Vec<String>> = vec![std::iter::once(String::from("name"))
        .chain(columns().map(header))
        .collect()];
    for p in list {
        rows.push(
            std::iter::once(p.name.clone())
                .chain(columns().map(|s| cell(&p.input, s)))
                .collect(),
        );
    }
    let n = rows[0].len();
    let width: Vec<usize> = (0..n)
        .map(|c| rows.iter().map(|r| r[c].chars().count()).max().unwrap_or(0))
        .collect();
    for r in &rows {
        let line: Vec<String> = r
            .iter()
            .zip(&width)
            .map(|(t, w)| format!("{t}{}", " ".repeat(w - t.chars().count())))
            .collect();
        writeln!(out, "{}", line.join("  ").trim_end())?;
    }
    writeln!(out)?;
    writeln!(out, "sources:")?;
    for p in list {
        // Keep one preset per line even if a user's source spans several.
        let source: String = p
            .source
            .chars()
            .map(|c| if c.is_control() { ' ' } else { c })
            .collect();
        writeln!(out, "  {}: {source}", p.name)?;
    }
    let aliases: Vec<String> = live_aliases(list)
        .map(|a| format!("{} → {}", a.name, a.preset))
        .collect();
    if !aliases.is_empty() {
        writeln!(out)?;
        writeln!(out, "former names: {}", aliases.join(", "))?;
    }
    Ok(())
}

/// `viewer presets --json`: `{"presets":[{"name","source","parameters":{key: value}}],
/// "aliases":[{"name","preset"}]}`, the parameters resolved, in [`SCHEMA`] order, each
/// colour form under its own keys (σ_ca as `[r, g, b]`).
#[derive(serde::Serialize)]
struct PresetsJson<'a> {
    presets: Vec<PresetJson<'a>>,
    aliases: Vec<AliasJson>,
}

#[derive(serde::Serialize)]
struct AliasJson {
    name: &'static str,
    preset: &'static str,
}

#[derive(serde::Serialize)]
struct PresetJson<'a> {
    name: &'a str,
    source: &'a str,
    parameters: serde_json::Map<String, serde_json::Value>,
}

impl<'a> PresetsJson<'a> {
    fn new(list: &'a [NamedPreset]) -> Self {
        let presets = list
            .iter()
            .map(|p| {
                let resolved = p.input.resolved();
                let parameters = SCHEMA
                    .iter()
                    .filter_map(|s| {
                        let v = match resolved.value(s.name)? {
                            ParamValue::Scalar(v) => serde_json::json!(v),
                            ParamValue::Rgb(Rgb(c)) => serde_json::json!(c),
                            ParamValue::Choice(i) => serde_json::json!(s.choice_name(i)?),
                        };
                        Some((s.key.to_string(), v))
                    })
                    .collect();
                PresetJson {
                    name: &p.name,
                    source: &p.source,
                    parameters,
                }
            })
            .collect();
        let aliases = live_aliases(list)
            .map(|a| AliasJson {
                name: a.name,
                preset: a.preset,
            })
            .collect();
        PresetsJson { presets, aliases }
    }
}
