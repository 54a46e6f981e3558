//! Preset files (docs/model.md §9): named parameter sets in TOML.
//!
//! The format is the one of `bcsdf-core/presets.toml` (see its header comment): one
//! `[[preset]]` table per preset with
//!
//! - `name`, `source`: text; `source` records where the numbers come from;
//! - one number per parameter of the schema ([`bcsdf_core::SCHEMA`]: key, domain, default),
//!   e.g. `eta_c`, `alpha_deg`, `kappa`; a parameter with a default may be left out
//!   (`beta_n_deg` follows `beta_m_deg`, `eta_m` follows `eta_c`, `sigma_ma` is 0);
//! - the colour, exactly one of: `sigma_ca = value` or `sigma_ca = [r, g, b]`, or
//!   `eumelanin` and/or `pheomelanin` (concentrations, the missing one is 0), or
//!   `base_colour = [r, g, b]` (linear, each in [0, 1]: the colour the coat shows,
//!   docs/model.md §14; `bake` turns it into σ_ca with the coat colour table of the LUT it
//!   bakes).
//!
//! Unknown keys are errors, and every preset is validated with [`FurParamsInput::check`] when
//! the file is loaded, so a loaded preset always builds a model ([`bcsdf_core::FurParams::new`]) once a
//! base colour has been turned into σ_ca. Every error is one line that names
//! the file, the line, the preset and the field, e.g.
//! `presets.toml:12: preset "foo": invalid kappa = 1.2: valid range is [0, 0.99]`.

use bcsdf_core::presets::Alias;
use bcsdf_core::{FurParamsInput, InputError, ParamDefault, ParamName, ParamValue, Rgb, SCHEMA};
use serde::Deserialize;
use std::collections::BTreeMap;
use std::fmt;
use std::ops::Range;
use std::path::Path;
use toml::Spanned;

/// The text of the built-in preset file, `bcsdf-core/presets.toml`
/// ([`bcsdf_core::presets::PRESETS_TOML`]: the file ships in the core's crate, so this crate
/// reads no file outside its own when packaged).
pub const BUILTIN_TOML: &str = bcsdf_core::presets::PRESETS_TOML;

/// The file name used in error messages about [`BUILTIN_TOML`].
pub const BUILTIN_FILE: &str = "bcsdf-core/presets.toml";

/// One preset read from a file: its name, its provenance and its (validated) parameters.
#[derive(Clone, Debug, PartialEq)]
pub struct NamedPreset {
    /// The preset's name (`viewer probe --preset NAME`); unique within its file.
    pub name: String,
    /// Where the numbers come from.
    pub source: String,
    /// The parameters; [`FurParamsInput::check`] accepts them (checked at load).
    pub input: FurParamsInput,
}

/// Why a preset file could not be loaded. [`Display`](fmt::Display) gives one line:
/// `FILE:LINE: preset "NAME": MESSAGE` (the line and the preset when known).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PresetError {
    /// The file, as given to [`load_file`] or [`parse`].
    pub file: String,
    /// 1-based line of the offending key, value or `[[preset]]` header, when known.
    pub line: Option<usize>,
    /// Name of the preset the error is in, when known.
    pub preset: Option<String>,
    /// What is wrong (one line, names the field).
    pub message: String,
}

impl fmt::Display for PresetError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.file)?;
        if let Some(line) = self.line {
            write!(f, ":{line}")?;
        }
        f.write_str(": ")?;
        if let Some(name) = &self.preset {
            // Quoted with escapes: a name with a newline still gives one line.
            write!(f, "preset {name:?}: ")?;
        }
        f.write_str(&self.message)
    }
}

impl std::error::Error for PresetError {}

/// The built-in presets, parsed from [`BUILTIN_TOML`] (the same data as
/// `bcsdf_core::presets::PRESETS`, which a test keeps in agreement).
///
/// An error here means the repository's `presets.toml` is broken.
pub fn builtin() -> Result<Vec<NamedPreset>, PresetError> {
    parse(BUILTIN_TOML, BUILTIN_FILE)
}

/// Reads and parses the preset file at `path`.
pub fn load_file(path: impl AsRef<Path>) -> Result<Vec<NamedPreset>, PresetError> {
    let path = path.as_ref();
    let file = path.display().to_string();
    let text = std::fs::read_to_string(path).map_err(|e| PresetError {
        file: file.clone(),
        line: None,
        preset: None,
        message: format!("cannot read preset file: {e}"),
    })?;
    parse(&text, &file)
}

/// The preset called `name` in `list`.
pub fn find<'a>(list: &'a [NamedPreset], name: &str) -> Option<&'a NamedPreset> {
    list.iter().find(|p| p.name == name)
}

/// The preset called `name` in `list`, or, when `name` is a former name
/// ([`bcsdf_core::presets::ALIASES`]) that `list` does not define, the preset it now
/// selects together with the alias, whose `Display` is the one-line note the tools print.
pub fn lookup<'a>(
    list: &'a [NamedPreset],
    name: &str,
) -> Option<(&'a NamedPreset, Option<&'static Alias>)> {
    find(list, name).map(|p| (p, None)).or_else(|| {
        let alias = bcsdf_core::presets::alias(name)?;
        find(list, alias.preset).map(|p| (p, Some(alias)))
    })
}

/// Parses preset-file text; `file` is only used in error messages.
///
/// Checks, in this order: TOML syntax, unknown keys and value types, the name
/// ([`bcsdf_core::params::check_name`]), the colour (exactly one form), [`FurParamsInput::check`]
/// for every preset, and that names are unique.
pub fn parse(text: &str, file: &str) -> Result<Vec<NamedPreset>, PresetError> {
    let raw: RawFile = toml::from_str(text).map_err(|e| toml_error(text, file, &e))?;
    if raw.preset.is_empty() {
        return Err(PresetError {
            file: file.to_string(),
            line: None,
            preset: None,
            message: "no presets: expected at least one [[preset]] table".to_string(),
        });
    }
    let mut out: Vec<NamedPreset> = Vec::with_capacity(raw.preset.len());
    let mut first_line: BTreeMap<String, usize> = BTreeMap::new();
    for entry in &raw.preset {
        let preset = RawPreset::read(entry).map_err(|(span, preset, message)| PresetError {
            file: file.to_string(),
            line: Some(line_of(text, span.start)),
            preset,
            message,
        })?;
        let err = |span: Range<usize>, message: String| PresetError {
            file: file.to_string(),
            line: Some(line_of(text, span.start)),
            preset: Some(preset.name.get_ref().clone()),
            message,
        };
        // The name first: it is the file name of everything made from this preset.
        check_name(preset.name.get_ref()).map_err(|message| PresetError {
            file: file.to_string(),
            line: Some(line_of(text, preset.name.span().start)),
            preset: None,
            message,
        })?;
        let input = preset
            .to_input(entry.span())
            .map_err(|(span, m)| err(span, m))?;
        input
            .check()
            .map_err(|e| err(preset.span_of(e.name, entry.span()), e.to_string()))?;
        let name = preset.name.get_ref().clone();
        let line = line_of(text, preset.name.span().start);
        if let Some(first) = first_line.get(&name) {
            return Err(err(
                preset.name.span(),
                format!("duplicate preset name (first defined at line {first})"),
            ));
        }
        first_line.insert(name.clone(), line);
        out.push(NamedPreset {
            name,
            source: preset.source.get_ref().clone(),
            input,
        });
    }
    Ok(out)
}

/// A preset name becomes a file name (`<out>/<name>.furlut`): it must follow
/// [`bcsdf_core::params::check_name`] (docs/model.md §9). The message quotes the name
/// escaped, so it stays one line.
fn check_name(name: &str) -> Result<(), String> {
    bcsdf_core::params::check_name(name).map_err(|e| format!("name {name:?} {e}"))
}

/// 1-based line number of byte offset `pos` in `text`.
fn line_of(text: &str, pos: usize) -> usize {
    let end = pos.min(text.len());
    text.as_bytes()[..end]
        .iter()
        .filter(|&&b| b == b'\n')
        .count()
        + 1
}

/// Turns a serde/TOML error into a one-line [`PresetError`], adding the preset's name and the
/// key whose value was rejected when they can be found.
fn toml_error(text: &str, file: &str, e: &toml::de::Error) -> PresetError {
    let mut message = e
        .message()
        .trim()
        .replace("expected f32", "expected a number")
        .replace('\n', "; ");
    // The only sequence besides `sigma_ca` (which has its own message) is the preset list.
    if message.starts_with("invalid type: map, expected a sequence") {
        message = "presets are an array of tables: write [[preset]], not [preset]".to_string();
    }
    let mut preset = None;
    let line = e.span().map(|span| {
        if let Ok(lenient) = toml::from_str::<RawFile>(text) {
            if let Some(table) = lenient
                .preset
                .iter()
                .find(|t| contains(&t.span(), span.start))
            {
                let entries = table.get_ref();
                preset = entries
                    .iter()
                    .find(|(k, _)| k.get_ref() == "name")
                    .and_then(|(_, v)| v.get_ref().as_str().map(str::to_string));
                // A rejected value (not a rejected key): say which key it belongs to.
                if let Some((key, _)) = entries
                    .iter()
                    .find(|(_, v)| contains(&v.span(), span.start))
                {
                    message = format!("{}: {message}", key.get_ref());
                }
            }
        }
        line_of(text, span.start)
    });
    PresetError {
        file: file.to_string(),
        line,
        preset,
        message,
    }
}

fn contains(span: &Range<usize>, pos: usize) -> bool {
    span.start <= pos && (pos < span.end || span.is_empty() && pos == span.start)
}

/// A preset table as written: every key and value with its span.
type RawTable = BTreeMap<Spanned<String>, Spanned<toml::Value>>;

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawFile {
    #[serde(default)]
    preset: Vec<Spanned<RawTable>>,
}

/// One preset table, its keys checked against the parameter schema
/// ([`bcsdf_core::SCHEMA`]): `name`, `source` and one value per given parameter.
struct RawPreset {
    name: Spanned<String>,
    source: Spanned<String>,
    values: Vec<(ParamName, ParamValue, Range<usize>)>,
}

/// The keys of a preset table besides the parameters.
const TEXT_KEYS: [&str; 2] = ["name", "source"];

impl RawPreset {
    /// Reads the table's keys: unknown keys and values of the wrong type are errors at
    /// their span; a missing `name` or `source` is an error at the table.
    fn read(
        table: &Spanned<RawTable>,
    ) -> Result<RawPreset, (Range<usize>, Option<String>, String)> {
        let entries = table.get_ref();
        let text_of = |key: &str| {
            entries
                .iter()
                .find(|(k, _)| k.get_ref() == key)
                .map(|(_, v)| v)
        };
        let name_value = text_of("name").and_then(|v| v.get_ref().as_str());
        let preset_name = name_value.map(str::to_string);
        let fail = |span: Range<usize>, message: String| (span, preset_name.clone(), message);
        let text = |key: &str| match text_of(key) {
            None => Err(fail(table.span(), format!("missing field `{key}`"))),
            Some(v) => match v.get_ref().as_str() {
                Some(t) => Ok(Spanned::new(v.span(), t.to_string())),
                None => Err(fail(
                    v.span(),
                    format!(
                        "{key}: invalid type: {}, expected a string",
                        v.get_ref().type_str()
                    ),
                )),
            },
        };
        let (name, source) = (text("name")?, text("source")?);
        let mut values = Vec::new();
        for (key, value) in entries {
            let key_text = key.get_ref().as_str();
            if TEXT_KEYS.contains(&key_text) {
                continue;
            }
            let Some(param) = ParamName::from_key(key_text) else {
                return Err(fail(
                    key.span(),
                    format!(
                        "unknown field `{key_text}`, expected one of {}",
                        TEXT_KEYS
                            .iter()
                            .copied()
                            .chain(SCHEMA.iter().map(|s| s.key))
                            .map(|k| format!("`{k}`"))
                            .collect::<Vec<_>>()
                            .join(", ")
                    ),
                ));
            };
            let parsed = param_value(param, value.get_ref())
                .map_err(|expected| fail(value.span(), format!("{key_text}: {expected}")))?;
            values.push((param, parsed, value.span()));
        }
        Ok(RawPreset {
            name,
            source,
            values,
        })
    }

    /// The unvalidated input; fails only on a missing parameter or the colour rule
    /// (`table`: the preset's span).
    fn to_input(&self, table: Range<usize>) -> Result<FurParamsInput, (Range<usize>, String)> {
        FurParamsInput::from_values(|name| self.value_of(name).map(|(v, _)| v)).map_err(|e| {
            let span = match e {
                InputError::TwoColours { first, .. } => self.span_of(first, table),
                InputError::Missing(_) | InputError::NoColour => table,
            };
            (span, e.to_string())
        })
    }

    fn value_of(&self, name: ParamName) -> Option<(ParamValue, Range<usize>)> {
        self.values
            .iter()
            .find(|(n, _, _)| *n == name)
            .map(|(_, v, span)| (*v, span.clone()))
    }

    /// Where the value of parameter `name` is written: its own value, else (a defaulted
    /// parameter) the value it defaults to, else the table.
    fn span_of(&self, name: ParamName, table: Range<usize>) -> Range<usize> {
        let own = self.value_of(name).map(|(_, span)| span);
        let source = match name.spec().default {
            ParamDefault::SameAs(source) => self.value_of(source).map(|(_, span)| span),
            _ => None,
        };
        own.or(source).unwrap_or(table)
    }
}

/// A parameter's value from TOML: a number (integers accepted), or for `sigma_ca` and
/// `base_colour` also `[r, g, b]`, or for a choice (`closure`) one of its names as a string. The error says
/// what was expected.
fn param_value(name: ParamName, value: &toml::Value) -> Result<ParamValue, String> {
    let spec = name.spec();
    if spec.is_choice() {
        let names = spec
            .choices
            .iter()
            .map(|c| format!("\"{c}\""))
            .collect::<Vec<_>>()
            .join(" or ");
        return match value {
            toml::Value::String(text) => spec
                .choice_index(text)
                .map(ParamValue::Choice)
                .ok_or_else(|| format!("invalid value: \"{text}\", expected {names}")),
            v => Err(format!("invalid type: {}, expected {names}", v.type_str())),
        };
    }
    let number = |v: &toml::Value| match v {
        toml::Value::Float(f) => Some(*f as f32),
        toml::Value::Integer(i) => Some(*i as f32),
        _ => None,
    };
    let rgb_ok = name.takes_rgb();
    let expected = if rgb_ok {
        "a number or an array of three numbers [r, g, b]"
    } else {
        "a number"
    };
    match value {
        toml::Value::Array(items) if rgb_ok => {
            let numbers: Option<Vec<f32>> = items.iter().map(number).collect();
            match numbers.as_deref() {
                Some(&[r, g, b]) => Ok(ParamValue::Rgb(Rgb([r, g, b]))),
                _ => Err(format!(
                    "invalid value: an array of {} elements, expected {expected}",
                    items.len()
                )),
            }
        }
        v => number(v)
            .map(ParamValue::Scalar)
            .ok_or_else(|| format!("invalid type: {}, expected {expected}", v.type_str())),
    }
}
