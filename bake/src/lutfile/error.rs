//! The one error type of [`lutfile`](super): the file it is about and what went wrong.

use std::fmt;
use std::io;
use std::path::{Path, PathBuf};

use bcsdf_core::lut::{self, LutError};
use bcsdf_core::MODEL_VERSION;

/// Why reading or writing a LUT file failed: the file ([`LutFileError::path`]) and the
/// problem ([`LutFileError::kind`]). The [`Display`](fmt::Display) form is one line,
/// `path: problem`.
#[derive(Debug)]
pub struct LutFileError {
    path: PathBuf,
    kind: LutFileErrorKind,
}

/// What went wrong with a LUT file (see [`LutFileError`]).
#[derive(Debug)]
pub enum LutFileErrorKind {
    /// The file does not exist.
    Missing,
    /// The file exists but could not be read.
    Read(io::Error),
    /// The file is not an OpenEXR file, or a corrupt one (the text says what is wrong).
    NotExr(String),
    /// The LUT was made by another format version or model version.
    Version {
        /// `"format"` (the file layout) or `"model"` (the BCSDF model).
        what: &'static str,
        /// Version found in the file.
        found: u32,
        /// Version this build reads.
        expected: u32,
    },
    /// The EXR file is readable but does not describe a LUT: a layer or attribute is
    /// missing, has the wrong type or size, or the metadata is inconsistent (the text says
    /// what).
    Format(String),
    /// The LUT data is invalid ([`lut::validate`] rejected it).
    Invalid(LutError),
    /// The LUT could not be encoded as OpenEXR (the text says why).
    Encode(String),
    /// The output directory is missing, not a directory, or no file can be created in it.
    Directory {
        /// The file's directory.
        dir: PathBuf,
        /// What is wrong with it.
        problem: String,
    },
    /// Writing the file failed (e.g. the disk is full); any existing file at the path is
    /// unchanged.
    Write(io::Error),
}

impl LutFileErrorKind {
    /// This problem with the file at `path`.
    pub fn at(self, path: &Path) -> LutFileError {
        LutFileError {
            path: path.to_path_buf(),
            kind: self,
        }
    }
}

impl From<LutError> for LutFileErrorKind {
    /// A version mismatch is [`LutFileErrorKind::Version`], anything else
    /// [`LutFileErrorKind::Invalid`].
    fn from(e: LutError) -> LutFileErrorKind {
        match e {
            LutError::FormatVersion { found } => LutFileErrorKind::Version {
                what: "format",
                found,
                expected: lut::FORMAT_VERSION,
            },
            LutError::ModelVersion { found } => LutFileErrorKind::Version {
                what: "model",
                found,
                expected: MODEL_VERSION,
            },
            e => LutFileErrorKind::Invalid(e),
        }
    }
}

impl LutFileError {
    /// The file the error is about.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// What went wrong.
    pub fn kind(&self) -> &LutFileErrorKind {
        &self.kind
    }
}

/// `s` on one line (control characters escaped).
fn one_line(s: &str) -> String {
    s.chars()
        .flat_map(|c| {
            if c.is_control() {
                c.escape_default().collect::<Vec<_>>()
            } else {
                vec![c]
            }
        })
        .collect()
}

impl fmt::Display for LutFileError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use LutFileErrorKind as K;
        let path = one_line(&self.path.display().to_string());
        match &self.kind {
            K::Missing => write!(f, "{path}: no such file"),
            K::Read(source) => {
                write!(f, "{path}: cannot read: {}", one_line(&source.to_string()))
            }
            K::NotExr(problem) => write!(f, "{path}: {}", one_line(problem)),
            K::Version {
                what: "model",
                found,
                expected,
            } => write!(
                f,
                "{path}: LUT was baked by model version {found}; this build is model version {expected}: re-bake it with this version's `bake`"
            ),
            K::Version {
                what,
                found,
                expected,
            } => write!(
                f,
                "{path}: LUT {what} version {found} is not supported (this build reads version {expected}): re-bake it with this version's `bake`"
            ),
            K::Format(problem) => {
                write!(f, "{path}: not a valid LUT file: {}", one_line(problem))
            }
            K::Invalid(error) => write!(f, "{path}: {error}"),
            K::Encode(problem) => write!(
                f,
                "{path}: cannot encode the LUT as OpenEXR: {}",
                one_line(problem)
            ),
            K::Directory { dir, problem } => write!(
                f,
                "{path}: cannot write: directory {} {}",
                one_line(&dir.display().to_string()),
                one_line(problem)
            ),
            K::Write(source) => write!(
                f,
                "{path}: write failed: {} (any existing file there is unchanged)",
                one_line(&source.to_string())
            ),
        }
    }
}

impl std::error::Error for LutFileError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match &self.kind {
            LutFileErrorKind::Read(source) | LutFileErrorKind::Write(source) => Some(source),
            _ => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn messages_are_one_line_and_name_the_file() {
        let path = Path::new("dir/bad\nname.exr");
        let cases = [
            LutFileErrorKind::Missing,
            LutFileErrorKind::Format("two\nlines".into()),
            LutFileErrorKind::from(LutError::ModelVersion { found: 99 }),
            LutFileErrorKind::from(LutError::FormatVersion { found: 1 }),
            LutFileErrorKind::from(LutError::BadMagic),
            LutFileErrorKind::Write(io::Error::from_raw_os_error(28)),
        ];
        for kind in cases {
            let err = kind.at(path);
            assert_eq!(err.path(), path);
            let msg = err.to_string();
            assert!(!msg.contains('\n'), "{msg}");
            assert!(msg.starts_with("dir/bad\\nname.exr: "), "{msg}");
        }
        let err = LutFileErrorKind::from(LutError::FormatVersion { found: 1 }).at(path);
        assert!(matches!(
            err.kind(),
            LutFileErrorKind::Version {
                what: "format",
                found: 1,
                ..
            }
        ));
        assert!(err.to_string().contains("re-bake"), "{err}");
        let err = LutFileErrorKind::from(LutError::BadMagic).at(path);
        assert!(matches!(
            err.kind(),
            LutFileErrorKind::Invalid(LutError::BadMagic)
        ));
    }
}
