//! Preset names (docs/model.md §9, "Preset names"): the one rule every reader of a name
//! applies — preset files, `bake --preset`, the LUT metadata read back, the profile cache's
//! file names — because a name becomes a file name (`<out>/<name>.furlut`).
//!
//! A valid name is 1 to [`NAME_MAX_BYTES`] bytes of ASCII letters, digits, `-`, `_` and `.`,
//! does not start with `.` or `-` (hidden files, `..`, command-line options), and is not a
//! Windows device name (`CON`, `PRN`, `AUX`, `NUL`, `COM0`–`COM9`, `LPT0`–`LPT9`, in any
//! case, alone or before a `.`: Windows opens the device for `nul.exr` too). Such a name has
//! no path separator, no `..` component and no control character, so `<dir>/<name>.<ext>` is
//! always a file directly inside `<dir>` on every platform.
//!
//! ```
//! use bcsdf_core::params::{check_name, NameError};
//! assert!(check_name("bobcat").is_ok());
//! assert_eq!(check_name("../x"), Err(NameError::BadChar { ch: '/', at: 2 }));
//! assert_eq!(check_name(".x"), Err(NameError::BadStart('.')));
//! assert_eq!(check_name("Nul.v2"), Err(NameError::DeviceName("NUL")));
//! ```

use core::fmt;

/// Longest valid name, in bytes (ASCII: also in characters).
pub const NAME_MAX_BYTES: usize = 64;

/// Windows' reserved device names (matched case-insensitively against the part of a name
/// before its first `.`).
pub const DEVICE_NAMES: [&str; 24] = [
    "CON", "PRN", "AUX", "NUL", "COM0", "COM1", "COM2", "COM3", "COM4", "COM5", "COM6", "COM7",
    "COM8", "COM9", "LPT0", "LPT1", "LPT2", "LPT3", "LPT4", "LPT5", "LPT6", "LPT7", "LPT8", "LPT9",
];

/// Why a text is not a valid preset name ([`check_name`]). [`Display`](fmt::Display) gives one
/// line naming the problem (the caller names the field and quotes the name).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NameError {
    /// The name is empty.
    Empty,
    /// The name is longer than [`NAME_MAX_BYTES`] (its length in bytes).
    TooLong(usize),
    /// The name starts with `.` or `-`.
    BadStart(char),
    /// A character other than an ASCII letter, digit, `-`, `_` or `.`, at this byte offset.
    BadChar {
        /// The character.
        ch: char,
        /// Its byte offset in the name.
        at: usize,
    },
    /// The name is (or starts with, before a `.`) this Windows device name.
    DeviceName(&'static str),
}

impl core::error::Error for NameError {}

/// The predicate of a sentence whose subject is the quoted name: callers write
/// `name "<name>" <error>`, e.g. `name "../x" contains '/' at byte 2; only ASCII letters,
/// digits, '-', '_' and '.' are allowed` (quote the name with `{:?}`, which escapes control
/// characters, so the line stays one line).
impl fmt::Display for NameError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        const ALLOWED: &str = "ASCII letters, digits, '-', '_' and '.'";
        match *self {
            NameError::Empty => write!(f, "is empty; a name is 1 to {NAME_MAX_BYTES} {ALLOWED}"),
            NameError::TooLong(n) => {
                write!(f, "is {n} bytes long; at most {NAME_MAX_BYTES} are allowed")
            }
            NameError::BadStart(c) => {
                write!(
                    f,
                    "starts with {c:?}; a name starts with a letter, a digit or '_'"
                )
            }
            NameError::BadChar { ch, at } => {
                write!(
                    f,
                    "contains {ch:?} at byte {at}; only {ALLOWED} are allowed"
                )
            }
            NameError::DeviceName(d) => {
                write!(
                    f,
                    "is the Windows device name {d}, which cannot be a file name"
                )
            }
        }
    }
}

/// Whether byte `b` may appear in a name.
fn allowed(b: u8) -> bool {
    b.is_ascii_alphanumeric() || matches!(b, b'-' | b'_' | b'.')
}

/// Checks `name` against the rule of the module documentation; the first violation, in the
/// order empty, too long, bad character, bad first character, device name.
pub fn check_name(name: &str) -> Result<(), NameError> {
    if name.is_empty() {
        return Err(NameError::Empty);
    }
    if name.len() > NAME_MAX_BYTES {
        return Err(NameError::TooLong(name.len()));
    }
    if let Some((at, ch)) = name.char_indices().find(|&(_, c)| {
        let mut buf = [0u8; 4];
        c.len_utf8() > 1 || !allowed(c.encode_utf8(&mut buf).as_bytes()[0])
    }) {
        return Err(NameError::BadChar { ch, at });
    }
    let first = name.as_bytes()[0];
    if first == b'.' || first == b'-' {
        return Err(NameError::BadStart(char::from(first)));
    }
    let stem = name.split('.').next().unwrap_or(name);
    match DEVICE_NAMES.iter().find(|d| d.eq_ignore_ascii_case(stem)) {
        Some(d) => Err(NameError::DeviceName(d)),
        None => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn accepts_the_allowed_alphabet() {
        for ok in [
            "a",
            "bobcat",
            "human_hair.v2",
            "0",
            "_x",
            "A.b-c_d",
            "x..y",
            "trailing.",
            "CONSOLE",
            "com10",
            "nul_x",
            "LPT",
        ] {
            assert_eq!(check_name(ok), Ok(()), "{ok}");
        }
        assert_eq!(check_name(&"a".repeat(NAME_MAX_BYTES)), Ok(()));
    }

    #[test]
    fn the_built_in_presets_have_valid_names() {
        for p in crate::presets::PRESETS {
            assert_eq!(check_name(p.name), Ok(()), "{}", p.name);
        }
    }

    #[test]
    fn refuses_every_bad_form_with_its_reason() {
        let cases: [(&str, NameError); 16] = [
            ("", NameError::Empty),
            (".hidden", NameError::BadStart('.')),
            ("..", NameError::BadStart('.')),
            ("-rf", NameError::BadStart('-')),
            ("../escaped", NameError::BadChar { ch: '/', at: 2 }),
            ("a/b", NameError::BadChar { ch: '/', at: 1 }),
            ("a\\b", NameError::BadChar { ch: '\\', at: 1 }),
            ("/abs", NameError::BadChar { ch: '/', at: 0 }),
            ("C:x", NameError::BadChar { ch: ':', at: 1 }),
            ("tab\there", NameError::BadChar { ch: '\t', at: 3 }),
            ("nl\n", NameError::BadChar { ch: '\n', at: 2 }),
            ("a b", NameError::BadChar { ch: ' ', at: 1 }),
            ("fourrure-é", NameError::BadChar { ch: 'é', at: 9 }),
            ("nul\0", NameError::BadChar { ch: '\0', at: 3 }),
            ("con", NameError::DeviceName("CON")),
            ("Com7.exr", NameError::DeviceName("COM7")),
        ];
        for (name, want) in cases {
            assert_eq!(check_name(name), Err(want), "{name:?}");
        }
        for d in DEVICE_NAMES {
            assert_eq!(check_name(d), Err(NameError::DeviceName(d)));
        }
        let long = "a".repeat(NAME_MAX_BYTES + 1);
        assert_eq!(check_name(&long), Err(NameError::TooLong(65)));
    }

    #[test]
    fn messages_are_one_line_and_name_the_problem() {
        extern crate std;
        use std::format;
        let msg = |n: &str| format!("name {n:?} {}", check_name(n).unwrap_err());
        assert_eq!(
            msg("a/b"),
            "name \"a/b\" contains '/' at byte 1; only ASCII letters, digits, '-', '_' and '.' \
             are allowed"
        );
        assert_eq!(
            msg("\n"),
            "name \"\\n\" contains '\\n' at byte 0; only ASCII letters, digits, '-', '_' and \
             '.' are allowed"
        );
        assert!(msg(".x").contains("starts with '.'"));
        assert!(msg("aux").ends_with("is the Windows device name AUX, which cannot be a file name"));
        assert!(msg(&"x".repeat(70)).ends_with("is 70 bytes long; at most 64 are allowed"));
        assert!(msg("").starts_with("name \"\" is empty"));
    }
}
