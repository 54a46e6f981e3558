//! The profile cache: one checked binary file per [`ProfileKey`], [`load_or_generate`] that
//! reuses a valid file and (re)generates and atomically (re)writes a missing, stale or
//! corrupt one, and the default cache directory.
//!
//! # Cache file format (`FORMAT_VERSION` 2)
//!
//! One file per [`ProfileKey`] (generator version, layout, budget, seed), named
//! `medulla-<16 hex digits>.furprof` after the FNV-1a 64 hash of the key bytes (bytes 8..76
//! below), so different parameter sets never share a file. The path is built by
//! [`output_path`] like every output file (a valid name, directly inside the directory). Little-endian throughout:
//!
//! | offset | type | content |
//! |---|---|---|
//! | 0 | `[u8; 8]` | magic `b"FURPROF\0"` |
//! | 8 | u32 | cache format version ([`FORMAT_VERSION`]) |
//! | 12 | u32 | [`GENERATOR_VERSION`] of the generator that made the tables |
//! | 16 | 6 × f32 (IEEE bits) | layout: `g`, `sigma_n_min`, `sigma_n_max`, `sigma_m`, `theta_in_max`, `absorption` |
//! | 40 | 5 × u32 | resolution: `n_sigma`, `n_h`, `n_psi`, `n_in`, `n_out` |
//! | 60 | 2 × u32 | photon budget: `per_cn_cell`, `per_cm_row` |
//! | 68 | u64 | seed |
//! | 76 | 2 × u64 | number of f32 entries of C^N, C^M |
//! | 92 | f32 × … | C^N, then C^M, in the core's layouts ([`bcsdf_core::medulla`]) |
//! | end − 8 | u64 | FNV-1a 64 checksum of every byte before it |
//!
//! Version 1 (generator version 1) also held the mean-path table ℓ̄ and had no `absorption`;
//! such files are stale ([`CacheError::FormatVersion`]) and are regenerated.
//!
//! Loading checks, in order: the magic, the format version, that the file length is the one
//! the header announces (truncated or extended files), the checksum (any flipped bit), the
//! generator version, that the layout, budget and seed are the expected ones (bit for bit),
//! the table lengths, and finally every value through [`MedullaProfiles::new`]. The first
//! failure is a [`CacheError`] with a one-line message.
//!
//! Files are written atomically ([`crate::fsutil::AtomicWriter`]): to a temporary file in the cache
//! directory, flushed to disk, then renamed over the final name, so a reader sees the old file
//! or the new one, never a half-written one; a write that fails or is interrupted leaves any
//! existing file untouched (a crash can at worst leave a stray `.medulla-*.partial` file
//! ([`crate::fsutil`] names temporary files after their destination), which is never read).
//!
//! # Concurrent bakes
//!
//! Bakes that share a cache directory (the N shards of one job, two users, threads of one
//! process) generate each missing entry once. Each entry has a lock file beside it,
//! `medulla-<hash>.lock` (empty, created on first use and never removed: removing it would
//! let two bakes lock two different files). A bake that finds no valid file takes the
//! entry's advisory lock (`flock` on Unix, `LockFileEx` on Windows, through the `fs4` crate),
//! reads the file again (another bake may have written it while this one waited: then it is
//! a [`CacheOutcome::Hit`]), and otherwise removes any `.medulla-<hash>.furprof.*.partial`
//! file a killed writer left, generates, writes the file atomically and releases the lock.
//! A valid file is read without the lock, since it is only ever replaced whole.
//!
//! The system releases a lock when its holder exits, however it exits (`kill -9`, a crash,
//! a node reboot for a local disk): a killed holder leaves no entry locked, and at worst a
//! stray temporary file and no cache file, which the next bake of that entry regenerates
//! (and cleans). A file system without advisory locks (some NFS set-ups) gives
//! [`Error::CacheLock`], naming the lock file: use a local `--cache-dir` or `--no-cache`.
//!
//! **An unwritable cache directory is an error** ([`Error::CacheDir`], naming the directory),
//! reported before any generation work: pass no cache directory to work without a cache.
//! A read-only directory that already holds a valid file for the key is fine (a hit only
//! reads).
//!
//! [`MedullaProfiles::new`]: bcsdf_core::medulla::MedullaProfiles::new

use super::generate::generate_parallel;
use super::{Error, OwnedProfiles};
use crate::fsutil::{output_path, OutputNameError, TEMP_SUFFIX};
use bcsdf_core::medulla::{
    PhotonBudget, ProfileError, ProfileLayout, Resolution, GENERATOR_VERSION,
};
use bcsdf_core::FurParams;
use entry::{load_or_make, EntryPaths};
use std::fmt;
use std::fs;
use std::io;
use std::path::{Path, PathBuf};

/// Version of the cache file format described in the module documentation.
pub const FORMAT_VERSION: u32 = 2;

/// Extension of a cache file.
pub const CACHE_EXTENSION: &str = "furprof";

/// Extension of a cache entry's lock file.
pub const LOCK_EXTENSION: &str = "lock";

/// The first eight bytes of a cache file.
pub const MAGIC: [u8; 8] = *b"FURPROF\0";

/// End of the key bytes (which start at 8, after the magic).
const KEY_END: usize = 76;

/// Bytes before the tables: the key, then two table lengths.
const HEADER_LEN: usize = KEY_END + 16;

/// Bytes of the trailing checksum.
const CHECKSUM_LEN: usize = 8;

/// FNV-1a 64 of `bytes` (the cache checksum and file-name hash).
pub fn fnv1a64(bytes: &[u8]) -> u64 {
    bcsdf_core::lut::fnv1a64(bytes)
}

/// Everything that determines the tables' bits: the generator ([`GENERATOR_VERSION`]) aside,
/// the layout, the photon budget and the seed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ProfileKey {
    /// Axes and resolution.
    pub layout: ProfileLayout,
    /// Photons per cell.
    pub budget: PhotonBudget,
    /// Seed of the random streams.
    pub seed: u64,
}

impl ProfileKey {
    /// Bytes 8..76 of a cache file for this key (format and generator versions included).
    fn to_bytes(self) -> [u8; KEY_END - 8] {
        let mut b = [0u8; KEY_END - 8];
        let mut w = 0;
        let mut put = |bytes: &[u8]| {
            b[w..w + bytes.len()].copy_from_slice(bytes);
            w += bytes.len();
        };
        put(&FORMAT_VERSION.to_le_bytes());
        put(&GENERATOR_VERSION.to_le_bytes());
        let l = &self.layout;
        let axes = [
            l.g,
            l.sigma_n_min,
            l.sigma_n_max,
            l.sigma_m,
            l.theta_in_max,
            l.absorption,
        ];
        for v in axes {
            put(&v.to_bits().to_le_bytes());
        }
        let r = l.res;
        for n in [r.n_sigma, r.n_h, r.n_psi, r.n_in, r.n_out] {
            // Validated resolutions are at most 4096; saturate anything else (it never
            // validates, so it is never written).
            put(&u32::try_from(n).unwrap_or(u32::MAX).to_le_bytes());
        }
        put(&self.budget.per_cn_cell.to_le_bytes());
        put(&self.budget.per_cm_row.to_le_bytes());
        put(&self.seed.to_le_bytes());
        debug_assert_eq!(w, b.len());
        b
    }

    /// The name of this key's cache entry: `medulla-<hash>` (16 hex digits), a valid name
    /// ([`bcsdf_core::params::check_name`]); the cache file and its lock add an extension.
    pub fn stem(&self) -> String {
        format!("medulla-{:016x}", self.id())
    }

    /// FNV-1a 64 of the key bytes (format and generator versions included): the hash in
    /// [`ProfileKey::stem`], and what a cache entry derived from these profiles (the residual
    /// table's, [`crate::profiles::residual`]) records of them.
    pub fn id(&self) -> u64 {
        fnv1a64(&self.to_bytes())
    }

    /// The cache file name of this key: `medulla-<hash>.furprof`.
    pub fn file_name(&self) -> String {
        format!("{}.{CACHE_EXTENSION}", self.stem())
    }

    /// The cache file of this key in `dir`, built by [`output_path`] (always directly inside
    /// `dir`).
    pub fn path_in(&self, dir: &Path) -> Result<PathBuf, OutputNameError> {
        output_path(dir, &self.stem(), CACHE_EXTENSION)
    }

    /// The lock file of this key's entry in `dir` (module documentation, "Concurrent bakes").
    pub fn lock_path_in(&self, dir: &Path) -> Result<PathBuf, OutputNameError> {
        output_path(dir, &self.stem(), LOCK_EXTENSION)
    }
}

/// Why a cache file was not used. [`Display`](fmt::Display) gives one line.
#[derive(Debug)]
pub enum CacheError {
    /// The file exists but cannot be read.
    Read(io::Error),
    /// The file is not a cache file of the expected kind (wrong magic).
    BadMagic,
    /// The file is shorter (truncated) or longer than its header announces.
    Length {
        /// Bytes the header announces (at least the header and checksum).
        expected: u64,
        /// Bytes found.
        found: u64,
    },
    /// The checksum does not match the contents.
    Checksum {
        /// Checksum stored in the file.
        stored: u64,
        /// Checksum of the contents.
        computed: u64,
    },
    /// Written in another cache format version.
    FormatVersion(u32),
    /// Made by another profile generator version.
    GeneratorVersion(u32),
    /// Made for another layout, budget or seed (the named field differs).
    KeyMismatch(&'static str),
    /// A table has the wrong length or holds a negative or non-finite value.
    Tables(ProfileError),
}

impl CacheError {
    /// True when the file is intact but was made by another version or for another key (as
    /// opposed to damaged).
    pub fn is_stale(&self) -> bool {
        matches!(
            self,
            CacheError::FormatVersion(_)
                | CacheError::GeneratorVersion(_)
                | CacheError::KeyMismatch(_)
        )
    }
}

impl fmt::Display for CacheError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            CacheError::Read(e) => write!(f, "unreadable: {e}"),
            CacheError::BadMagic => {
                f.write_str("corrupt: not a cache file of this kind (bad magic)")
            }
            CacheError::Length { expected, found } if found < expected => write!(
                f,
                "corrupt: truncated ({found} bytes, the header announces {expected})"
            ),
            CacheError::Length { expected, found } => write!(
                f,
                "corrupt: {} trailing bytes ({found} bytes, the header announces {expected})",
                found - expected
            ),
            CacheError::Checksum { stored, computed } => write!(
                f,
                "corrupt: checksum mismatch (stored {stored:016x}, contents {computed:016x})"
            ),
            CacheError::FormatVersion(v) => {
                write!(
                    f,
                    "stale: cache format version {v}, not the one this build reads"
                )
            }
            CacheError::GeneratorVersion(v) => write!(
                f,
                "stale: made by profile generator version {v}, this build is version \
                 {GENERATOR_VERSION}"
            ),
            CacheError::KeyMismatch(field) => {
                write!(f, "stale: made for other parameters ({field} differs)")
            }
            CacheError::Tables(e) => write!(f, "corrupt: {e}"),
        }
    }
}

impl std::error::Error for CacheError {}

/// Serialises `profiles` in the cache format (module documentation).
pub fn encode(profiles: &OwnedProfiles) -> Vec<u8> {
    let (cn, cm) = profiles.tables();
    let total = HEADER_LEN + 4 * (cn.len() + cm.len()) + CHECKSUM_LEN;
    let mut out = Vec::with_capacity(total);
    out.extend_from_slice(&MAGIC);
    out.extend_from_slice(&profiles.key().to_bytes());
    for t in [cn, cm] {
        out.extend_from_slice(&(t.len() as u64).to_le_bytes());
    }
    for t in [cn, cm] {
        for v in t {
            out.extend_from_slice(&v.to_bits().to_le_bytes());
        }
    }
    let sum = fnv1a64(&out);
    out.extend_from_slice(&sum.to_le_bytes());
    debug_assert_eq!(out.len(), total);
    out
}

pub(crate) fn u32_at(b: &[u8], at: usize) -> u32 {
    u32::from_le_bytes(b[at..at + 4].try_into().expect("4 bytes"))
}

pub(crate) fn u64_at(b: &[u8], at: usize) -> u64 {
    u64::from_le_bytes(b[at..at + 8].try_into().expect("8 bytes"))
}

/// The checks every cache file kind shares, in the order of the module documentation: the
/// kind's magic, its format version, the length the header announces (`header_len`, then as
/// many f32 as the u64 counts at byte offsets `count_at` say, then the checksum), and the
/// FNV-1a checksum of everything before it. Returns the length of the checksummed body.
pub(crate) fn check_container(
    bytes: &[u8],
    magic: &[u8; 8],
    format_version: u32,
    header_len: usize,
    count_at: &[usize],
) -> Result<usize, CacheError> {
    let min = (header_len + CHECKSUM_LEN) as u64;
    let found = bytes.len() as u64;
    if bytes.len() < magic.len() || bytes[..magic.len()] != *magic {
        return Err(CacheError::BadMagic);
    }
    if bytes.len() < 12 {
        return Err(CacheError::Length {
            expected: min,
            found,
        });
    }
    let format = u32_at(bytes, 8);
    if format != format_version {
        return Err(CacheError::FormatVersion(format));
    }
    if found < min {
        return Err(CacheError::Length {
            expected: min,
            found,
        });
    }
    let announced = count_at
        .iter()
        .try_fold(min, |acc, &at| {
            u64_at(bytes, at)
                .checked_mul(4)
                .and_then(|b| acc.checked_add(b))
        })
        .unwrap_or(u64::MAX);
    if announced != found {
        return Err(CacheError::Length {
            expected: announced,
            found,
        });
    }
    let body = bytes.len() - CHECKSUM_LEN;
    let (stored, computed) = (u64_at(bytes, body), fnv1a64(&bytes[..body]));
    if stored != computed {
        return Err(CacheError::Checksum { stored, computed });
    }
    Ok(body)
}

/// Reads a cache file's bytes, accepting them only if they hold profiles for exactly
/// `expected` made by this generator (checks in the order of the module documentation).
pub fn decode(bytes: &[u8], expected: &ProfileKey) -> Result<OwnedProfiles, CacheError> {
    check_container(
        bytes,
        &MAGIC,
        FORMAT_VERSION,
        HEADER_LEN,
        &[KEY_END, KEY_END + 8],
    )?;
    let lens = [u64_at(bytes, KEY_END), u64_at(bytes, KEY_END + 8)];
    let generator = u32_at(bytes, 12);
    if generator != GENERATOR_VERSION {
        return Err(CacheError::GeneratorVersion(generator));
    }
    let want = expected.to_bytes();
    let got = &bytes[8..KEY_END];
    const FIELDS: [(usize, &str); 9] = [
        (16, "g"),
        (20, "sigma_n_min"),
        (24, "sigma_n_max"),
        (28, "sigma_m"),
        (32, "theta_in_max"),
        (36, "absorption"),
        (40, "resolution"),
        (60, "photon budget"),
        (68, "seed"),
    ];
    if let Some(i) = (0..want.len()).find(|&i| want[i] != got[i]) {
        let field = FIELDS
            .iter()
            .rev()
            .find(|(start, _)| *start <= i + 8)
            .map_or("header", |(_, name)| name);
        return Err(CacheError::KeyMismatch(field));
    }
    let table = |start: usize, n: usize| -> Vec<f32> {
        bytes[start..start + 4 * n]
            .chunks_exact(4)
            .map(|c| f32::from_bits(u32::from_le_bytes(c.try_into().expect("4 bytes"))))
            .collect()
    };
    // The lengths fit in memory: they add up to the file's length.
    let [n_cn, n_cm] = lens.map(|n| n as usize);
    let cn = table(HEADER_LEN, n_cn);
    let cm = table(HEADER_LEN + 4 * n_cn, n_cm);
    OwnedProfiles::new(*expected, cn, cm).map_err(CacheError::Tables)
}

/// What [`load_or_generate`] did with the cache.
#[derive(Debug)]
pub enum CacheOutcome {
    /// A valid cache file was read.
    Hit {
        /// The file.
        path: PathBuf,
    },
    /// There was no cache file (or no cache): the profiles were generated, and written to
    /// `path` when there is one.
    Generated {
        /// The file written, `None` without a cache directory.
        path: Option<PathBuf>,
    },
    /// A cache file existed but was stale or corrupt: it was not used; the profiles were
    /// generated and the file rewritten.
    Regenerated {
        /// The file rewritten.
        path: PathBuf,
        /// Why the old file was rejected.
        reason: CacheError,
    },
}

impl CacheOutcome {
    /// A one-line note for a user when the outcome deserves one (a rejected cache file).
    pub fn note(&self) -> Option<String> {
        match self {
            CacheOutcome::Regenerated { path, reason } => Some(format!(
                "cache file {} was {reason}; regenerated and rewritten",
                path.display()
            )),
            _ => None,
        }
    }
}

/// Removes the temporary files a killed writer of the cache file `path` left behind
/// (`.<file name>.*.partial`, [`AtomicWriter`]'s names). Call only with the entry's lock held:
/// then no other bake is writing one. Best effort (a file that cannot be removed is left; it
/// is never read).
pub(crate) fn remove_stray_partials(dir: &Path, path: &Path) {
    let Some(name) = path.file_name().and_then(|n| n.to_str()) else {
        return;
    };
    let prefix = format!(".{name}.");
    let Ok(entries) = fs::read_dir(dir) else {
        return;
    };
    for entry in entries.flatten() {
        let file = entry.file_name();
        let Some(file) = file.to_str() else { continue };
        if file.starts_with(&prefix) && file.ends_with(TEMP_SUFFIX) {
            let _ = fs::remove_file(entry.path());
        }
    }
}

/// Profiles for `params` at resolution `res`: read from `cache_dir` when it holds a valid
/// file for this (generator version, layout, budget, seed), else generated with
/// [`generate_parallel`] and written there atomically. Without a cache directory they are
/// always generated. A directory that cannot be created or written is [`Error::CacheDir`],
/// detected before generating.
///
/// Concurrent callers (threads or processes) that miss the same entry generate it once: the
/// one holding the entry's lock generates and writes it, the others wait for the lock and
/// then read the file (module documentation, "Concurrent bakes").
pub fn load_or_generate(
    params: &FurParams,
    res: Resolution,
    budget: PhotonBudget,
    seed: u64,
    cache_dir: Option<&Path>,
    threads: Option<usize>,
) -> Result<(OwnedProfiles, CacheOutcome), Error> {
    let layout = ProfileLayout::for_params(params, res);
    layout.validate()?;
    let Some(dir) = cache_dir else {
        let p = generate_parallel(&layout, &budget, seed, threads)?;
        return Ok((p, CacheOutcome::Generated { path: None }));
    };
    let key = ProfileKey {
        layout,
        budget,
        seed,
    };
    let paths = EntryPaths {
        dir,
        file: key.path_in(dir).map_err(Error::CacheName)?,
        lock: key.lock_path_in(dir).map_err(Error::CacheName)?,
    };
    load_or_make(
        paths,
        |bytes| decode(bytes, &key),
        || generate_parallel(&layout, &budget, seed, threads),
        encode,
    )
}

/// The default cache directory: `$FUR_BCSDF_CACHE` if set (and not empty), else
/// `$XDG_CACHE_HOME/fur-bcsdf` (when absolute), else `$HOME/.cache/fur-bcsdf`; `None` when
/// none of these is set.
pub fn default_cache_dir() -> Option<PathBuf> {
    let var = |name: &str| std::env::var_os(name).filter(|v| !v.is_empty());
    if let Some(dir) = var("FUR_BCSDF_CACHE") {
        return Some(PathBuf::from(dir));
    }
    if let Some(xdg) = var("XDG_CACHE_HOME").map(PathBuf::from) {
        if xdg.is_absolute() {
            return Some(xdg.join("fur-bcsdf"));
        }
    }
    var("HOME").map(|home| PathBuf::from(home).join(".cache").join("fur-bcsdf"))
}

pub(crate) mod entry;

#[cfg(test)]
mod tests;
