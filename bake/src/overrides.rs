//! `key=value` parameter overrides (`viewer probe --set`).
//!
//! The key is a [`ParamName::key`] (`eta_c`, `sigma_ca`, `kappa`, …). The value is one number;
//! `sigma_ca` and `base_colour` also take three, `r,g,b`. Each value is checked against its parameter's valid
//! range when parsed. Overrides apply left to right with [`FurParamsInput::set_value`]'s meaning:
//! `sigma_ca` replaces any melanin colour, and `eumelanin` / `pheomelanin` replace an RGB
//! `sigma_ca` (the other concentration then starts from 0).

use bcsdf_core::{FurParamsInput, ParamError, ParamName, ParamValue, Rgb};
use std::fmt;
use std::str::FromStr;

/// One parsed `key=value` override.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Override {
    /// The parameter to set.
    pub name: ParamName,
    /// Its new value (already range-checked).
    pub value: ParamValue,
}

/// What is wrong with an override.
#[non_exhaustive]
#[derive(Clone, Debug, PartialEq)]
pub enum OverrideErrorKind {
    /// No `=` in the text, or nothing before it.
    NotKeyValue,
    /// The key names no parameter (the unknown key).
    UnknownKey(String),
    /// A value component is not a number (the offending text).
    NotANumber(String),
    /// The value of a choice parameter (`closure`) is none of its names (the text).
    NotAChoice(String),
    /// The wrong number of comma-separated components (how many were given).
    WrongArity(usize),
    /// A value outside the parameter's valid range.
    OutOfRange(ParamError),
}

/// An override that could not be parsed. [`Display`](fmt::Display) gives one line starting
/// with the override in backquotes, e.g.
/// ``"`kappa=1.2`: invalid kappa = 1.2: valid range is [0, 0.99]"``.
#[derive(Clone, Debug, PartialEq)]
pub struct OverrideError {
    /// The override as given.
    pub spec: String,
    /// What is wrong.
    pub kind: OverrideErrorKind,
}

/// All valid keys, comma-separated, in schema order ([`bcsdf_core::SCHEMA`]).
pub fn valid_keys() -> String {
    bcsdf_core::SCHEMA
        .iter()
        .map(|s| s.key)
        .collect::<Vec<_>>()
        .join(", ")
}

impl fmt::Display for OverrideError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "`{}`: ", self.spec)?;
        match &self.kind {
            OverrideErrorKind::NotKeyValue => {
                write!(f, "expected KEY=VALUE (valid keys: {})", valid_keys())
            }
            OverrideErrorKind::UnknownKey(key) => write!(
                f,
                "unknown parameter key `{key}` (valid keys: {})",
                valid_keys()
            ),
            OverrideErrorKind::NotANumber(text) => write!(f, "`{text}` is not a number"),
            OverrideErrorKind::NotAChoice(text) => {
                let key = self.spec.split('=').next().unwrap_or("").trim();
                let choices = ParamName::from_key(key).map_or(&[][..], |n| n.spec().choices);
                write!(
                    f,
                    "`{text}` is not a {key}: valid values are {}",
                    choices.join(", ")
                )
            }
            OverrideErrorKind::WrongArity(n) => {
                let key = self.spec.split('=').next().unwrap_or("").trim();
                if ParamName::from_key(key).is_some_and(ParamName::takes_rgb) {
                    write!(f, "{key} takes one value or three (r,g,b), got {n}")
                } else {
                    write!(f, "{key} takes one value, got {n}")
                }
            }
            OverrideErrorKind::OutOfRange(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for OverrideError {}

impl Override {
    /// Parses `key=value` (spaces around the key and the values are ignored).
    pub fn parse(spec: &str) -> Result<Override, OverrideError> {
        let fail = |kind| OverrideError {
            spec: spec.to_string(),
            kind,
        };
        let (key, value) = spec
            .split_once('=')
            .filter(|(k, _)| !k.trim().is_empty())
            .ok_or_else(|| fail(OverrideErrorKind::NotKeyValue))?;
        let key = key.trim();
        let name = ParamName::from_key(key)
            .ok_or_else(|| fail(OverrideErrorKind::UnknownKey(key.to_string())))?;
        let spec = name.spec();
        if spec.is_choice() {
            let text = value.trim();
            let index = spec
                .choice_index(text)
                .ok_or_else(|| fail(OverrideErrorKind::NotAChoice(text.to_string())))?;
            return Ok(Override {
                name,
                value: ParamValue::Choice(index),
            });
        }
        let parts: Vec<&str> = value.split(',').map(str::trim).collect();
        let rgb_ok = name.takes_rgb();
        if !(parts.len() == 1 || rgb_ok && parts.len() == 3) {
            return Err(fail(OverrideErrorKind::WrongArity(parts.len())));
        }
        let mut numbers = [0.0f32; 3];
        for (slot, text) in numbers.iter_mut().zip(&parts) {
            let v: f32 = text
                .parse()
                .map_err(|_| fail(OverrideErrorKind::NotANumber(text.to_string())))?;
            *slot = name
                .check(v)
                .map_err(|e| fail(OverrideErrorKind::OutOfRange(e)))?;
        }
        let value = if parts.len() == 3 {
            ParamValue::Rgb(Rgb(numbers))
        } else {
            ParamValue::Scalar(numbers[0])
        };
        Ok(Override { name, value })
    }

    /// Applies this override to `input`.
    pub fn apply(&self, input: &mut FurParamsInput) {
        input.set_value(self.name, self.value);
    }
}

impl FromStr for Override {
    type Err = OverrideError;
    fn from_str(s: &str) -> Result<Override, OverrideError> {
        Override::parse(s)
    }
}

/// Parses and applies every override in `specs`, left to right. On error `input` is left
/// unchanged.
///
/// Every value is range-checked on its own; the combination still has to pass
/// [`bcsdf_core::FurParams::new`].
pub fn apply_overrides<I>(input: &mut FurParamsInput, specs: I) -> Result<(), OverrideError>
where
    I: IntoIterator,
    I::Item: AsRef<str>,
{
    let parsed = specs
        .into_iter()
        .map(|s| Override::parse(s.as_ref()))
        .collect::<Result<Vec<_>, _>>()?;
    for o in &parsed {
        o.apply(input);
    }
    Ok(())
}
