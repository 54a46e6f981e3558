//! Writing files whole or not at all, and checking an output folder before any work. Used by
//! bake (the LUT files, the profile cache) and by the viewer (PNG images, pages).
//!
//! - [`AtomicWriter`] / [`write_atomic`]: the bytes go to a temporary file in the
//!   destination's folder, which is flushed to disk and renamed over the destination, so a
//!   reader sees the old file or the new one, never a half-written one, and a write that fails
//!   or is interrupted leaves any existing file untouched. The temporary file is named after
//!   the destination, `.<file name>.<random>.partial` (the file name cut to
//!   [`TEMP_NAME_MAX`] bytes), so a stray one left by a crash says what it was for; no
//!   reader ever opens a `.partial` file.
//! - [`output_path`]: the one place a file name made from a preset name is joined to its
//!   folder (`<out>/<name>.furlut`, `<out>/<name>.exr`, `<cache>/medulla-<hash>.furprof`): the
//!   name must pass [`bcsdf_core::params::check_name`], and the result is checked to be a
//!   file directly inside the folder, so no name can write outside `--out` or the cache.
//! - [`prepare_dir`]: creates an output folder if needed and checks that a file can be
//!   created in it, so that an unwritable folder is reported (naming it) before the work.
//!
//! ```
//! let dir = tempfile::tempdir().unwrap();
//! let out = dir.path().join("out");
//! bake::fsutil::prepare_dir(&out).unwrap();
//! bake::fsutil::write_atomic(&out.join("a.txt"), b"whole").unwrap();
//! assert_eq!(std::fs::read(out.join("a.txt")).unwrap(), b"whole");
//! ```

use bcsdf_core::params::{check_name, NameError};
use std::ffi::OsStr;
use std::fmt;
use std::fs::File;
use std::io::{self, Write};
use std::path::{Component, Path, PathBuf};

/// Longest part of the destination's file name (in bytes) that goes into a temporary file's
/// name, so that the temporary name stays well within file-name limits (255 bytes).
pub const TEMP_NAME_MAX: usize = 64;

/// Suffix of every temporary file.
pub const TEMP_SUFFIX: &str = ".partial";

/// The folder a file at `path` goes in (`.` for a bare file name).
pub fn parent_dir(path: &Path) -> &Path {
    match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    }
}

/// `.<file name>.` with the file name cut to [`TEMP_NAME_MAX`] bytes (at a character
/// boundary): the start of the temporary file names for `path`.
fn temp_prefix(path: &Path) -> String {
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    let mut end = name.len().min(TEMP_NAME_MAX);
    while !name.is_char_boundary(end) {
        end -= 1;
    }
    format!(".{}.", &name[..end])
}

/// A file written atomically: the bytes go to a temporary file in the destination's
/// folder, and [`AtomicWriter::commit`] flushes it to disk and renames it over the
/// destination. Dropping the writer without committing removes the temporary file and
/// leaves the destination untouched.
#[derive(Debug)]
pub struct AtomicWriter {
    tmp: tempfile::NamedTempFile,
    path: PathBuf,
}

impl AtomicWriter {
    /// Creates the temporary file next to `path` (its folder must exist).
    pub fn new(path: &Path) -> io::Result<AtomicWriter> {
        let tmp = tempfile::Builder::new()
            .prefix(&temp_prefix(path))
            .suffix(TEMP_SUFFIX)
            .tempfile_in(parent_dir(path))?;
        Ok(AtomicWriter {
            tmp,
            path: path.to_path_buf(),
        })
    }

    /// The temporary file, to write to.
    pub fn file(&mut self) -> &mut File {
        self.tmp.as_file_mut()
    }

    /// The temporary file's path (for messages and tests; it is removed or renamed).
    pub fn temp_path(&self) -> &Path {
        self.tmp.path()
    }

    /// The destination.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// Flushes the temporary file to disk and renames it to the destination (replacing any
    /// file there).
    pub fn commit(mut self) -> io::Result<()> {
        // A temporary file is private (0600); the result is an ordinary readable file.
        #[cfg(unix)]
        {
            use std::os::unix::fs::PermissionsExt;
            self.tmp
                .as_file()
                .set_permissions(std::fs::Permissions::from_mode(0o644))?;
        }
        self.tmp.as_file_mut().flush()?;
        self.tmp.as_file().sync_all()?;
        self.tmp.persist(&self.path).map_err(|e| e.error)?;
        // Make the rename itself durable where the platform allows it (best effort).
        #[cfg(unix)]
        if let Ok(d) = File::open(parent_dir(&self.path)) {
            let _ = d.sync_all();
        }
        Ok(())
    }
}

impl Write for AtomicWriter {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        self.tmp.write(buf)
    }

    fn flush(&mut self) -> io::Result<()> {
        self.tmp.flush()
    }
}

/// Writes `bytes` to `path` atomically ([`AtomicWriter`]).
pub fn write_atomic(path: &Path, bytes: &[u8]) -> io::Result<()> {
    let mut w = AtomicWriter::new(path)?;
    w.write_all(bytes)?;
    w.commit()
}

/// A file name [`output_path`] refused: the folder, the name, and why.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct OutputNameError {
    /// The folder the file was to go in.
    pub dir: PathBuf,
    /// The name as given.
    pub name: String,
    /// Why it is refused: the name breaks the rule (`Some`), or (`None`) the joined path is
    /// not directly inside the folder, which the rule excludes (a broken invariant).
    pub reason: Option<NameError>,
}

impl fmt::Display for OutputNameError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "refusing to write in {}: name {:?} ",
            self.dir.display(),
            self.name
        )?;
        match &self.reason {
            Some(reason) => write!(f, "{reason}"),
            None => f.write_str("would not make a file directly inside the folder"),
        }
    }
}

impl std::error::Error for OutputNameError {}

/// The path of the file `<name>.<extension>` directly inside `dir`: the name must pass
/// [`check_name`] (docs/model.md §9), the extension is ASCII letters and digits, and the
/// joined path must have `dir` as its parent and `<name>.<extension>` as its only new
/// component. Every output file
/// of bake (the LUTs and the profile cache) gets its path here.
pub fn output_path(dir: &Path, name: &str, extension: &str) -> Result<PathBuf, OutputNameError> {
    let err = |reason| OutputNameError {
        dir: dir.to_path_buf(),
        name: name.to_string(),
        reason,
    };
    let file_name = format!("{name}.{extension}");
    check_name(name).map_err(|e| err(Some(e)))?;
    let path = dir.join(&file_name);
    let inside = !extension.is_empty()
        && extension.bytes().all(|b| b.is_ascii_alphanumeric())
        && path.parent() == Some(dir)
        && matches!(
            path.strip_prefix(dir).map(|rest| rest.components().collect::<Vec<_>>()),
            Ok(c) if c == [Component::Normal(OsStr::new(&file_name))]
        );
    if inside {
        Ok(path)
    } else {
        Err(err(None))
    }
}

/// A folder that cannot be created or written to. [`Display`](fmt::Display) gives one line,
/// `<dir> is not writable: <reason>`, for the caller to prefix with what the folder is for.
#[derive(Debug)]
pub struct DirError {
    /// The folder.
    pub dir: PathBuf,
    /// What the system said.
    pub source: io::Error,
}

impl fmt::Display for DirError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} is not writable: {}", self.dir.display(), self.source)
    }
}

impl std::error::Error for DirError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        Some(&self.source)
    }
}

/// Creates the folder `dir` (and its parents) if needed and checks that a file can be
/// created in it (a temporary `.write-check-*.partial` file, removed at once). Call it
/// before the work whose results go there.
pub fn prepare_dir(dir: &Path) -> Result<(), DirError> {
    let err = |source| DirError {
        dir: dir.to_path_buf(),
        source,
    };
    std::fs::create_dir_all(dir).map_err(err)?;
    tempfile::Builder::new()
        .prefix(".write-check-")
        .suffix(TEMP_SUFFIX)
        .tempfile_in(dir)
        .map(drop)
        .map_err(err)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn names(dir: &Path) -> Vec<String> {
        let mut v: Vec<String> = std::fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        v.sort();
        v
    }

    #[test]
    fn output_paths_stay_directly_inside_their_folder() {
        let dir = Path::new("some/out");
        assert_eq!(
            output_path(dir, "bobcat", "furlut").unwrap(),
            Path::new("some/out/bobcat.furlut")
        );
        assert_eq!(
            output_path(Path::new("."), "x.v2", "exr").unwrap(),
            Path::new("./x.v2.exr")
        );
        for bad in [
            "../escaped",
            "..",
            "/etc/passwd",
            "a/b",
            "a\\b",
            ".x",
            "-x",
            "",
            "nul",
            "a\nb",
        ] {
            let e = output_path(dir, bad, "exr").unwrap_err();
            assert_eq!((e.dir.as_path(), e.name.as_str()), (dir, bad));
            assert!(e.reason.is_some(), "{bad:?}");
            let msg = e.to_string();
            assert!(
                msg.starts_with(&format!("refusing to write in some/out: name {bad:?} ")),
                "{msg}"
            );
            assert_eq!(msg.lines().count(), 1, "{msg}");
        }
        // The longest name is fine; an extension that is not letters and digits is refused.
        let long = "a".repeat(bcsdf_core::params::NAME_MAX_BYTES);
        assert!(output_path(dir, &long, "furlut").is_ok());
        for ext in ["", "x/y", "..", "e x"] {
            let e = output_path(dir, "ok", ext).unwrap_err();
            assert_eq!(e.reason, None, "{ext:?}");
            assert!(e
                .to_string()
                .ends_with("would not make a file directly inside the folder"));
        }
    }

    #[test]
    fn commit_replaces_the_destination_whole() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("out.bin");
        std::fs::write(&path, b"old").unwrap();
        let mut w = AtomicWriter::new(&path).unwrap();
        w.write_all(b"new contents").unwrap();
        // Before the commit: the temporary file sits beside the old, unchanged file.
        assert_eq!(std::fs::read(&path).unwrap(), b"old");
        let tmp = w.temp_path().to_path_buf();
        assert_eq!(tmp.parent(), Some(dir.path()));
        let tmp_name = tmp.file_name().unwrap().to_string_lossy().into_owned();
        assert!(
            tmp_name.starts_with(".out.bin.") && tmp_name.ends_with(".partial"),
            "{tmp_name}"
        );
        assert_eq!(names(dir.path()).len(), 2);
        w.commit().unwrap();
        assert_eq!(std::fs::read(&path).unwrap(), b"new contents");
        assert!(!tmp.exists());
        assert_eq!(names(dir.path()), ["out.bin"]);
        #[cfg(unix)]
        {
            use std::os::unix::fs::PermissionsExt;
            let mode = std::fs::metadata(&path).unwrap().permissions().mode();
            assert_eq!(mode & 0o777, 0o644, "an ordinary readable file");
        }
        // A new file where there was none.
        write_atomic(&dir.path().join("fresh"), b"x").unwrap();
        assert_eq!(names(dir.path()), ["fresh", "out.bin"]);
    }

    #[test]
    fn a_writer_dropped_without_commit_leaves_the_existing_file_untouched() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("keep.txt");
        std::fs::write(&path, b"the good file").unwrap();
        {
            let mut w = AtomicWriter::new(&path).unwrap();
            w.write_all(b"half of a new ").unwrap();
            w.flush().unwrap();
        }
        assert_eq!(std::fs::read(&path).unwrap(), b"the good file");
        assert_eq!(names(dir.path()), ["keep.txt"], "no temporary file left");
    }

    #[test]
    fn a_rename_onto_a_directory_fails_and_cleans_up() {
        let dir = tempfile::tempdir().unwrap();
        let blocked = dir.path().join("blocked");
        std::fs::create_dir(&blocked).unwrap();
        std::fs::write(blocked.join("inside"), b"x").unwrap();
        assert!(write_atomic(&blocked, b"data").is_err());
        assert_eq!(names(dir.path()), ["blocked"]);
        assert_eq!(std::fs::read(blocked.join("inside")).unwrap(), b"x");
    }

    #[test]
    fn long_and_bare_file_names_make_valid_temporary_names() {
        let long = "é".repeat(100); // 200 bytes: cut at a character boundary
        let prefix = temp_prefix(Path::new(&long));
        assert!(prefix.len() <= TEMP_NAME_MAX + 2, "{prefix}");
        assert!(prefix.starts_with(".é") && prefix.ends_with('.'));
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join(&long);
        write_atomic(&path, b"long").unwrap();
        assert_eq!(std::fs::read(&path).unwrap(), b"long");
        assert_eq!(parent_dir(Path::new("bare.txt")), Path::new("."));
        assert_eq!(parent_dir(Path::new("a/b.txt")), Path::new("a"));
    }

    #[test]
    fn prepare_dir_creates_folders_and_names_an_unwritable_one() {
        let dir = tempfile::tempdir().unwrap();
        let nested = dir.path().join("a").join("b");
        prepare_dir(&nested).unwrap();
        assert!(nested.is_dir());
        assert!(names(&nested).is_empty(), "the write check leaves nothing");
        prepare_dir(&nested).unwrap(); // already there: fine

        // A file in the way: the folder cannot be created, whoever runs the test.
        let blocker = dir.path().join("a-file");
        std::fs::write(&blocker, b"not a folder").unwrap();
        for bad in [blocker.join("out"), blocker.clone()] {
            let err = prepare_dir(&bad).unwrap_err();
            assert_eq!(err.dir, bad);
            let msg = err.to_string();
            assert!(
                msg.starts_with(&bad.display().to_string()) && msg.contains("is not writable"),
                "{msg}"
            );
            assert_eq!(msg.lines().count(), 1, "{msg}");
        }
        assert_eq!(std::fs::read(&blocker).unwrap(), b"not a folder");

        // A read-only folder, when the platform enforces it (not for root).
        #[cfg(unix)]
        {
            use std::os::unix::fs::PermissionsExt;
            let ro = dir.path().join("read-only");
            std::fs::create_dir(&ro).unwrap();
            std::fs::set_permissions(&ro, std::fs::Permissions::from_mode(0o555)).unwrap();
            let enforced = std::fs::write(ro.join("probe"), b"x").is_err();
            let result = prepare_dir(&ro);
            let write = write_atomic(&ro.join("f"), b"x");
            std::fs::set_permissions(&ro, std::fs::Permissions::from_mode(0o755)).unwrap();
            if enforced {
                let err = result.unwrap_err();
                assert_eq!(err.dir, ro);
                assert_eq!(err.source.kind(), io::ErrorKind::PermissionDenied);
                assert!(write.is_err());
            } else {
                eprintln!("running with permission to write anywhere: read-only case skipped");
            }
        }
    }
}
