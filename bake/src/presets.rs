//! Preset files (MODEL.md §9): named parameter sets in TOML.
//!
//! The format is the one of `bcsdf-core/presets.toml` (see its header comment): one
//! `[[preset]]` table per preset with
//!
//! - `name`, `source`: text; `source` records where the numbers come from;
//! - `eta_c`, `alpha_deg`, `beta_m_deg`, `l`, `kappa`, `sigma_ms`, `g`: required numbers;
//! - `beta_n_deg` (default `beta_m_deg`), `eta_m` (default `eta_c`), `sigma_ma` (default 0);
//! - the colour, exactly one of: `sigma_ca = value` or `sigma_ca = [r, g, b]`, or
//!   `eumelanin` and/or `pheomelanin` (concentrations, the missing one is 0).
//!
//! Unknown keys are errors, and every preset is validated with [`FurParams::new`] when the
//! file is loaded, so a loaded preset always builds a model. Every error is one line that names
//! the file, the line, the preset and the field, e.g.
//! `presets.toml:12: preset "foo": invalid kappa = 1.2: valid range is [0, 0.99]`.

use bcsdf_core::{FurParams, FurParamsInput, ParamName, Pigment, Rgb};
use serde::de::{self, Deserializer, SeqAccess, Visitor};
use serde::Deserialize;
use std::collections::BTreeMap;
use std::fmt;
use std::ops::Range;
use std::path::Path;
use toml::Spanned;

/// The text of the built-in preset file, `bcsdf-core/presets.toml`.
pub const BUILTIN_TOML: &str = include_str!("../../bcsdf-core/presets.toml");

/// The file name used in error messages about [`BUILTIN_TOML`].
pub const BUILTIN_FILE: &str = "bcsdf-core/presets.toml";

/// One preset read from a file: its name, its provenance and its (validated) parameters.
#[derive(Clone, Debug, PartialEq)]
pub struct NamedPreset {
    /// The preset's name (`viewer probe --preset NAME`); unique within its file.
    pub name: String,
    /// Where the numbers come from.
    pub source: String,
    /// The parameters; [`FurParams::new`] accepts them (checked at load).
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
            write!(f, "preset \"{name}\": ")?;
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

/// Parses preset-file text; `file` is only used in error messages.
///
/// Checks, in this order: TOML syntax, unknown keys and value types, the colour (exactly one
/// form), the name, [`FurParams::new`] for every preset, and that names are unique.
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
        let preset = entry.get_ref();
        let err = |span: Range<usize>, message: String| PresetError {
            file: file.to_string(),
            line: Some(line_of(text, span.start)),
            preset: Some(preset.name.get_ref().clone()),
            message,
        };
        let input = preset
            .to_input(entry.span())
            .map_err(|(span, m)| err(span, m))?;
        check_name(preset.name.get_ref()).map_err(|m| err(preset.name.span(), m))?;
        FurParams::new(&input)
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

/// Names are typed on command lines and listed one per line: no empty names and no control
/// characters (tabs, newlines).
fn check_name(name: &str) -> Result<(), String> {
    if name.trim().is_empty() {
        Err("name must not be empty".to_string())
    } else if name.chars().any(char::is_control) {
        Err(format!(
            "name {name:?} must not contain control characters (tabs, newlines)"
        ))
    } else {
        Ok(())
    }
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
        if let Ok(lenient) = toml::from_str::<LenientFile>(text) {
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

/// Only used to give context to an error of the strict parse.
#[derive(Deserialize)]
struct LenientFile {
    #[serde(default)]
    #[allow(clippy::type_complexity)]
    preset: Vec<Spanned<BTreeMap<Spanned<String>, Spanned<toml::Value>>>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawFile {
    #[serde(default)]
    preset: Vec<Spanned<RawPreset>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawPreset {
    name: Spanned<String>,
    source: Spanned<String>,
    eta_c: Spanned<f32>,
    sigma_ca: Option<Spanned<SigmaCa>>,
    eumelanin: Option<Spanned<f32>>,
    pheomelanin: Option<Spanned<f32>>,
    alpha_deg: Spanned<f32>,
    beta_m_deg: Spanned<f32>,
    beta_n_deg: Option<Spanned<f32>>,
    l: Spanned<f32>,
    kappa: Spanned<f32>,
    eta_m: Option<Spanned<f32>>,
    sigma_ms: Spanned<f32>,
    sigma_ma: Option<Spanned<f32>>,
    g: Spanned<f32>,
}

impl RawPreset {
    /// The unvalidated input; fails only on the colour rule (`table`: the preset's span).
    fn to_input(&self, table: Range<usize>) -> Result<FurParamsInput, (Range<usize>, String)> {
        let value = |s: &Spanned<f32>| *s.get_ref();
        let opt = |s: &Option<Spanned<f32>>| s.as_ref().map(value);
        let pigment =
            match (&self.sigma_ca, &self.eumelanin, &self.pheomelanin) {
                (Some(s), None, None) => Pigment::Absorption(s.get_ref().0),
                (None, None, None) => return Err((
                    table,
                    "no colour: give sigma_ca = value | [r, g, b], or eumelanin and/or pheomelanin"
                        .to_string(),
                )),
                (None, eu, pheo) => Pigment::Melanin {
                    eumelanin: opt(eu).unwrap_or(0.0),
                    pheomelanin: opt(pheo).unwrap_or(0.0),
                },
                (Some(s), eu, _) => {
                    let other = if eu.is_some() {
                        "eumelanin"
                    } else {
                        "pheomelanin"
                    };
                    return Err((
                        s.span(),
                        format!(
                            "sigma_ca and {other} both given: give exactly one colour form, \
                         sigma_ca or eumelanin/pheomelanin"
                        ),
                    ));
                }
            };
        Ok(FurParamsInput {
            eta_c: value(&self.eta_c),
            pigment,
            alpha_deg: value(&self.alpha_deg),
            beta_m_deg: value(&self.beta_m_deg),
            beta_n_deg: opt(&self.beta_n_deg),
            l: value(&self.l),
            kappa: value(&self.kappa),
            eta_m: opt(&self.eta_m),
            sigma_ms: value(&self.sigma_ms),
            sigma_ma: opt(&self.sigma_ma).unwrap_or(0.0),
            g: value(&self.g),
        })
    }

    /// Where the value of parameter `name` is written (the table when it is defaulted).
    fn span_of(&self, name: ParamName, table: Range<usize>) -> Range<usize> {
        let opt = |s: &Option<Spanned<f32>>| s.as_ref().map(Spanned::span);
        let span = match name {
            ParamName::EtaC => Some(self.eta_c.span()),
            ParamName::SigmaCa => self.sigma_ca.as_ref().map(Spanned::span),
            ParamName::Eumelanin => opt(&self.eumelanin),
            ParamName::Pheomelanin => opt(&self.pheomelanin),
            ParamName::AlphaDeg => Some(self.alpha_deg.span()),
            ParamName::BetaMDeg => Some(self.beta_m_deg.span()),
            ParamName::BetaNDeg => opt(&self.beta_n_deg).or(Some(self.beta_m_deg.span())),
            ParamName::L => Some(self.l.span()),
            ParamName::Kappa => Some(self.kappa.span()),
            ParamName::EtaM => opt(&self.eta_m).or(Some(self.eta_c.span())),
            ParamName::SigmaMs => Some(self.sigma_ms.span()),
            ParamName::SigmaMa => opt(&self.sigma_ma),
            ParamName::G => Some(self.g.span()),
        };
        span.unwrap_or(table)
    }
}

/// `sigma_ca = value` (all channels) or `sigma_ca = [r, g, b]`.
struct SigmaCa(Rgb);

impl<'de> Deserialize<'de> for SigmaCa {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = SigmaCa;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("a number or an array of three numbers [r, g, b]")
            }
            fn visit_f64<E: de::Error>(self, v: f64) -> Result<SigmaCa, E> {
                Ok(SigmaCa(Rgb::splat(v as f32)))
            }
            fn visit_i64<E: de::Error>(self, v: i64) -> Result<SigmaCa, E> {
                Ok(SigmaCa(Rgb::splat(v as f32)))
            }
            fn visit_u64<E: de::Error>(self, v: u64) -> Result<SigmaCa, E> {
                Ok(SigmaCa(Rgb::splat(v as f32)))
            }
            fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<SigmaCa, A::Error> {
                let mut rgb = [0.0f32; 3];
                for (i, c) in rgb.iter_mut().enumerate() {
                    *c = seq
                        .next_element::<f32>()?
                        .ok_or_else(|| de::Error::invalid_length(i, &self))?;
                }
                if seq.next_element::<de::IgnoredAny>()?.is_some() {
                    return Err(de::Error::invalid_length(4, &self));
                }
                Ok(SigmaCa(Rgb(rgb)))
            }
        }
        d.deserialize_any(V)
    }
}
