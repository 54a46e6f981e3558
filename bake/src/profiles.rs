//! Medulla profiles for the std tools (MODEL.md §7): parallel generation, a cache file, and
//! a model that owns its profiles.
//!
//! Over 600 lines: generation, the cache format and model building; the split into
//! `profiles/{generate, cache, model}` is issue 13 (maintainability), not done yet.
//!
//! - [`generate_parallel`] runs the core's per-cell generators
//!   ([`bcsdf_core::medulla::generate_cn_cell`], [`bcsdf_core::medulla::generate_cm_row`]) on
//!   rayon, each cell into its own disjoint chunk of the tables. Every cell draws from its own
//!   random stream, so the tables are the same bits for any thread count and across runs with
//!   the same seed.
//! - [`load_or_generate`] reuses a cache file when it was made for exactly the same
//!   generator version, layout, photon budget and seed, and otherwise (re)generates and
//!   (re)writes it. A stale or corrupt file is never used: the [`CacheOutcome`] says why it
//!   was replaced.
//! - [`build_model`] / [`OwnedModel`]: a [`FurBcsdf`] for any valid parameter set, with the
//!   profiles when the parameters scatter in the medulla (σ_ms > 0 and κ > 0) and without them
//!   otherwise (the unscattered model is then exact).
//!
//! ```no_run
//! use bake::profiles::{build_model, ProfileOptions};
//! use bcsdf_core::{presets, Angles, FurParams};
//!
//! let params = FurParams::new(&presets::find("yan-row-a").unwrap().input).unwrap();
//! let opts = ProfileOptions {
//!     cache_dir: bake::profiles::default_cache_dir(),
//!     ..ProfileOptions::default()
//! };
//! let (owned, _outcome) = build_model(params, &opts).unwrap();
//! let fur = owned.model();
//! let s = fur.eval_far(&Angles::from_degrees(30.0, -20.0, 45.0).unwrap());
//! # let _ = s;
//! ```
//!
//! # Cache file format (`FORMAT_VERSION` 1)
//!
//! One file per [`ProfileKey`] (generator version, layout, budget, seed), named
//! `medulla-<16 hex digits>.furprof` after the FNV-1a 64 hash of the key bytes (bytes 8..72
//! below), so different parameter sets never share a file. Little-endian throughout:
//!
//! | offset | type | content |
//! |---|---|---|
//! | 0 | `[u8; 8]` | magic `b"FURPROF\0"` |
//! | 8 | u32 | cache format version ([`FORMAT_VERSION`]) |
//! | 12 | u32 | [`GENERATOR_VERSION`] of the generator that made the tables |
//! | 16 | 5 × f32 (IEEE bits) | layout: `g`, `sigma_n_min`, `sigma_n_max`, `sigma_m`, `theta_in_max` |
//! | 36 | 5 × u32 | resolution: `n_sigma`, `n_h`, `n_psi`, `n_in`, `n_out` |
//! | 56 | 2 × u32 | photon budget: `per_cn_cell`, `per_cm_row` |
//! | 64 | u64 | seed |
//! | 72 | 3 × u64 | number of f32 entries of C^N, ℓ̄, C^M |
//! | 96 | f32 × … | C^N, then ℓ̄, then C^M, in the core's layouts ([`bcsdf_core::medulla`]) |
//! | end − 8 | u64 | FNV-1a 64 checksum of every byte before it |
//!
//! Loading checks, in order: the magic, the format version, that the file length is the one
//! the header announces (truncated or extended files), the checksum (any flipped bit), the
//! generator version, that the layout, budget and seed are the expected ones (bit for bit),
//! the table lengths, and finally every value through [`MedullaProfiles::new`]. The first
//! failure is a [`CacheError`] with a one-line message.
//!
//! Files are written atomically ([`AtomicWriter`]): to a temporary file in the cache
//! directory, flushed to disk, then renamed over the final name, so a reader sees the old file
//! or the new one, never a half-written one; a write that fails or is interrupted leaves any
//! existing file untouched (a crash can at worst leave a stray `.medulla-*.partial` file,
//! which is never read).
//!
//! **An unwritable cache directory is an error** ([`Error::CacheDir`], naming the directory),
//! reported before any generation work: pass no cache directory to work without a cache.
//! A read-only directory that already holds a valid file for the key is fine (a hit only
//! reads).

use bcsdf_core::medulla::{
    generate_cm_row, generate_cn_cell, MedullaProfiles, PhotonBudget, ProfileError, ProfileLayout,
    Resolution, GENERATOR_VERSION,
};
use bcsdf_core::{FurBcsdf, FurParams, Libm, Math};
use rayon::prelude::*;
use std::fmt;
use std::fs::{self, File};
use std::io::{self, Write};
use std::path::{Path, PathBuf};

/// Version of the cache file format described in the module documentation.
pub const FORMAT_VERSION: u32 = 1;

/// The first eight bytes of a cache file.
pub const MAGIC: [u8; 8] = *b"FURPROF\0";

/// Bytes before the tables.
const HEADER_LEN: usize = 96;

/// Bytes of the trailing checksum.
const CHECKSUM_LEN: usize = 8;

/// The seed used when none is given (`viewer probe --seed` defaults to it).
pub const DEFAULT_SEED: u64 = 1;

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
    /// Bytes 8..72 of a cache file for this key (format and generator versions included).
    fn to_bytes(self) -> [u8; 64] {
        let mut b = [0u8; 64];
        let mut w = 0;
        let mut put = |bytes: &[u8]| {
            b[w..w + bytes.len()].copy_from_slice(bytes);
            w += bytes.len();
        };
        put(&FORMAT_VERSION.to_le_bytes());
        put(&GENERATOR_VERSION.to_le_bytes());
        let l = &self.layout;
        for v in [l.g, l.sigma_n_min, l.sigma_n_max, l.sigma_m, l.theta_in_max] {
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
        b
    }

    /// The cache file name of this key: `medulla-<hash>.furprof`.
    pub fn file_name(&self) -> String {
        format!("medulla-{:016x}.furprof", fnv1a64(&self.to_bytes()))
    }
}

/// Medulla profiles in owned memory, with the key they were generated for. The tables are
/// validated at construction, so [`OwnedProfiles::view`] cannot fail.
#[derive(Clone, Debug, PartialEq)]
pub struct OwnedProfiles {
    layout: ProfileLayout,
    budget: PhotonBudget,
    seed: u64,
    cn: Vec<f32>,
    lbar: Vec<f32>,
    cm: Vec<f32>,
}

impl OwnedProfiles {
    /// Wraps tables in the core's layouts; checks them like [`MedullaProfiles::new`].
    pub fn new(
        key: ProfileKey,
        cn: Vec<f32>,
        lbar: Vec<f32>,
        cm: Vec<f32>,
    ) -> Result<OwnedProfiles, ProfileError> {
        MedullaProfiles::new(key.layout, &cn, &lbar, &cm)?;
        Ok(OwnedProfiles {
            layout: key.layout,
            budget: key.budget,
            seed: key.seed,
            cn,
            lbar,
            cm,
        })
    }

    /// The borrowed, validated view the model takes.
    pub fn view(&self) -> MedullaProfiles<'_> {
        MedullaProfiles::new(self.layout, &self.cn, &self.lbar, &self.cm)
            .expect("OwnedProfiles are validated at construction and immutable")
    }

    /// The layout.
    pub fn layout(&self) -> &ProfileLayout {
        &self.layout
    }

    /// The photon budget they were generated with.
    pub fn budget(&self) -> PhotonBudget {
        self.budget
    }

    /// The seed they were generated with.
    pub fn seed(&self) -> u64 {
        self.seed
    }

    /// Layout, budget and seed.
    pub fn key(&self) -> ProfileKey {
        ProfileKey {
            layout: self.layout,
            budget: self.budget,
            seed: self.seed,
        }
    }

    /// The tables `(C^N, ℓ̄, C^M)`.
    pub fn tables(&self) -> (&[f32], &[f32], &[f32]) {
        (&self.cn, &self.lbar, &self.cm)
    }
}

/// Why profiles could not be made or cached.
#[derive(Debug)]
pub enum Error {
    /// The layout is invalid, or the generated tables failed validation.
    Profile(ProfileError),
    /// The local thread pool could not be built.
    ThreadPool(String),
    /// The cache directory cannot be created or written to.
    CacheDir {
        /// The directory.
        dir: PathBuf,
        /// What the system said.
        source: io::Error,
    },
    /// Writing or renaming the cache file failed.
    CacheWrite {
        /// The cache file.
        path: PathBuf,
        /// What the system said.
        source: io::Error,
    },
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::Profile(e) => write!(f, "medulla profiles: {e}"),
            Error::ThreadPool(e) => write!(f, "cannot start the profile generator threads: {e}"),
            Error::CacheDir { dir, source } => write!(
                f,
                "profile cache directory {} is not writable: {source}",
                dir.display()
            ),
            Error::CacheWrite { path, source } => {
                write!(f, "cannot write profile cache {}: {source}", path.display())
            }
        }
    }
}

impl std::error::Error for Error {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            Error::CacheDir { source, .. } | Error::CacheWrite { source, .. } => Some(source),
            _ => None,
        }
    }
}

impl From<ProfileError> for Error {
    fn from(e: ProfileError) -> Error {
        Error::Profile(e)
    }
}

/// Generates every table of `layout` with rayon: C^N / ℓ̄ cells and C^M rows in parallel,
/// each into its own chunk. `threads`: a local pool of that many threads (`Some(0)` means
/// rayon's default count), or `None` for rayon's global pool. The result is the same bits for
/// any thread count, and equal to [`bcsdf_core::medulla::generate`].
pub fn generate_parallel(
    layout: &ProfileLayout,
    budget: &PhotonBudget,
    seed: u64,
    threads: Option<usize>,
) -> Result<OwnedProfiles, Error> {
    layout.validate()?;
    let mut cn = vec![0.0f32; layout.cn_len()];
    let mut lbar = vec![0.0f32; layout.cn_len()];
    let mut cm = vec![0.0f32; layout.cm_len()];
    let mut work = || {
        let n_psi = layout.res.n_psi;
        let n_out = layout.res.n_out;
        let (back, front) = cm.split_at_mut(layout.res.n_in * n_out);
        // The C^M rows are the longest tasks: start them alongside the C^N cells.
        rayon::join(
            || {
                back.par_chunks_mut(n_out)
                    .zip(front.par_chunks_mut(n_out))
                    .enumerate()
                    .for_each(|(row, (b, f))| {
                        generate_cm_row(layout, row, budget, seed, b, f);
                    })
            },
            || {
                cn.par_chunks_mut(n_psi)
                    .zip(lbar.par_chunks_mut(n_psi))
                    .enumerate()
                    .for_each(|(cell, (c, l))| {
                        generate_cn_cell(layout, cell, budget, seed, c, l);
                    })
            },
        );
    };
    match threads {
        None => work(),
        Some(n) => rayon::ThreadPoolBuilder::new()
            .num_threads(n)
            .build()
            .map_err(|e| Error::ThreadPool(e.to_string()))?
            .install(work),
    }
    let key = ProfileKey {
        layout: *layout,
        budget: *budget,
        seed,
    };
    Ok(OwnedProfiles::new(key, cn, lbar, cm)?)
}

/// Why a cache file was not used. [`Display`](fmt::Display) gives one line.
#[derive(Debug)]
pub enum CacheError {
    /// The file exists but cannot be read.
    Read(io::Error),
    /// The file is not a profile cache (wrong magic).
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
            CacheError::BadMagic => f.write_str("corrupt: not a profile cache file (bad magic)"),
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
            CacheError::FormatVersion(v) => write!(
                f,
                "stale: cache format version {v}, this build reads version {FORMAT_VERSION}"
            ),
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
    let (cn, lbar, cm) = profiles.tables();
    let total = HEADER_LEN + 4 * (cn.len() + lbar.len() + cm.len()) + CHECKSUM_LEN;
    let mut out = Vec::with_capacity(total);
    out.extend_from_slice(&MAGIC);
    out.extend_from_slice(&profiles.key().to_bytes());
    for t in [cn, lbar, cm] {
        out.extend_from_slice(&(t.len() as u64).to_le_bytes());
    }
    for t in [cn, lbar, cm] {
        for v in t {
            out.extend_from_slice(&v.to_bits().to_le_bytes());
        }
    }
    let sum = fnv1a64(&out);
    out.extend_from_slice(&sum.to_le_bytes());
    debug_assert_eq!(out.len(), total);
    out
}

fn u32_at(b: &[u8], at: usize) -> u32 {
    u32::from_le_bytes(b[at..at + 4].try_into().expect("4 bytes"))
}

fn u64_at(b: &[u8], at: usize) -> u64 {
    u64::from_le_bytes(b[at..at + 8].try_into().expect("8 bytes"))
}

/// Reads a cache file's bytes, accepting them only if they hold profiles for exactly
/// `expected` made by this generator (checks in the order of the module documentation).
pub fn decode(bytes: &[u8], expected: &ProfileKey) -> Result<OwnedProfiles, CacheError> {
    let min = (HEADER_LEN + CHECKSUM_LEN) as u64;
    let found = bytes.len() as u64;
    if bytes.len() < MAGIC.len() || bytes[..MAGIC.len()] != MAGIC {
        return Err(CacheError::BadMagic);
    }
    if bytes.len() < 12 {
        return Err(CacheError::Length {
            expected: min,
            found,
        });
    }
    let format = u32_at(bytes, 8);
    if format != FORMAT_VERSION {
        return Err(CacheError::FormatVersion(format));
    }
    if found < min {
        return Err(CacheError::Length {
            expected: min,
            found,
        });
    }
    let lens = [u64_at(bytes, 72), u64_at(bytes, 80), u64_at(bytes, 88)];
    let announced = lens
        .iter()
        .try_fold(min, |acc, n| {
            n.checked_mul(4).and_then(|b| acc.checked_add(b))
        })
        .unwrap_or(u64::MAX);
    if announced != found {
        return Err(CacheError::Length {
            expected: announced,
            found,
        });
    }
    let body = bytes.len() - CHECKSUM_LEN;
    let stored = u64_at(bytes, body);
    let computed = fnv1a64(&bytes[..body]);
    if stored != computed {
        return Err(CacheError::Checksum { stored, computed });
    }
    let generator = u32_at(bytes, 12);
    if generator != GENERATOR_VERSION {
        return Err(CacheError::GeneratorVersion(generator));
    }
    let want = expected.to_bytes();
    let got = &bytes[8..72];
    const FIELDS: [(usize, &str); 8] = [
        (16, "g"),
        (20, "sigma_n_min"),
        (24, "sigma_n_max"),
        (28, "sigma_m"),
        (32, "theta_in_max"),
        (36, "resolution"),
        (56, "photon budget"),
        (64, "seed"),
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
    let [n_cn, n_lbar, n_cm] = lens.map(|n| n as usize);
    let cn = table(HEADER_LEN, n_cn);
    let lbar = table(HEADER_LEN + 4 * n_cn, n_lbar);
    let cm = table(HEADER_LEN + 4 * (n_cn + n_lbar), n_cm);
    OwnedProfiles::new(*expected, cn, lbar, cm).map_err(CacheError::Tables)
}

/// A file written atomically: the bytes go to a temporary file in the destination's
/// directory, and [`AtomicWriter::commit`] flushes it to disk and renames it over the
/// destination. Dropping the writer without committing removes the temporary file and leaves
/// the destination untouched.
#[derive(Debug)]
pub struct AtomicWriter {
    tmp: tempfile::NamedTempFile,
    path: PathBuf,
}

impl AtomicWriter {
    /// Creates the temporary file next to `path` (its directory must exist).
    pub fn new(path: &Path) -> io::Result<AtomicWriter> {
        let dir = match path.parent() {
            Some(p) if !p.as_os_str().is_empty() => p,
            _ => Path::new("."),
        };
        let tmp = tempfile::Builder::new()
            .prefix(".medulla-")
            .suffix(".partial")
            .tempfile_in(dir)?;
        Ok(AtomicWriter {
            tmp,
            path: path.to_path_buf(),
        })
    }

    /// The temporary file, to write to.
    pub fn file(&mut self) -> &mut File {
        self.tmp.as_file_mut()
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
        if let Some(dir) = self.path.parent() {
            let dir = if dir.as_os_str().is_empty() {
                Path::new(".")
            } else {
                dir
            };
            if let Ok(d) = File::open(dir) {
                let _ = d.sync_all();
            }
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
                "medulla profile cache {} was {reason}; regenerated and rewritten",
                path.display()
            )),
            _ => None,
        }
    }
}

/// Profiles for `params` at resolution `res`: read from `cache_dir` when it holds a valid
/// file for this (generator version, layout, budget, seed), else generated with
/// [`generate_parallel`] and written there atomically. Without a cache directory they are
/// always generated. A directory that cannot be created or written is [`Error::CacheDir`],
/// detected before generating.
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
    let path = dir.join(key.file_name());
    let rejected = match fs::read(&path) {
        Ok(bytes) => match decode(&bytes, &key) {
            Ok(p) => return Ok((p, CacheOutcome::Hit { path })),
            Err(e) => Some(e),
        },
        Err(e) if e.kind() == io::ErrorKind::NotFound => None,
        Err(e) => Some(CacheError::Read(e)),
    };
    // Open the temporary file first: an unwritable directory fails before the work.
    let dir_error = |source| Error::CacheDir {
        dir: dir.to_path_buf(),
        source,
    };
    fs::create_dir_all(dir).map_err(dir_error)?;
    let mut writer = AtomicWriter::new(&path).map_err(dir_error)?;
    let profiles = generate_parallel(&layout, &budget, seed, threads)?;
    let write_error = |source| Error::CacheWrite {
        path: path.clone(),
        source,
    };
    writer.write_all(&encode(&profiles)).map_err(write_error)?;
    writer.commit().map_err(write_error)?;
    let outcome = match rejected {
        Some(reason) => CacheOutcome::Regenerated { path, reason },
        None => CacheOutcome::Generated { path: Some(path) },
    };
    Ok((profiles, outcome))
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

/// `budget` with both photon counts multiplied by `scale` (rounded, at least 1, at most
/// 2^24, the core's per-cell limit); `None` unless `scale` is finite and positive.
pub fn scale_budget(budget: PhotonBudget, scale: f64) -> Option<PhotonBudget> {
    if !(scale.is_finite() && scale > 0.0) {
        return None;
    }
    let s = |n: u32| {
        (f64::from(n) * scale)
            .round()
            .clamp(1.0, f64::from(1u32 << 24)) as u32
    };
    Some(PhotonBudget {
        per_cn_cell: s(budget.per_cn_cell),
        per_cm_row: s(budget.per_cm_row),
    })
}

/// How [`build_model`] gets its profiles.
#[derive(Clone, Debug, PartialEq)]
pub struct ProfileOptions {
    /// Table resolution.
    pub res: Resolution,
    /// Photons per cell.
    pub budget: PhotonBudget,
    /// Seed of the random streams.
    pub seed: u64,
    /// Cache directory (`None`: always generate, write nothing).
    pub cache_dir: Option<PathBuf>,
    /// Generator threads (`None`: rayon's global pool).
    pub threads: Option<usize>,
}

impl Default for ProfileOptions {
    /// Default resolution and budget, [`DEFAULT_SEED`], no cache, rayon's global pool.
    fn default() -> ProfileOptions {
        ProfileOptions {
            res: Resolution::DEFAULT,
            budget: PhotonBudget::DEFAULT,
            seed: DEFAULT_SEED,
            cache_dir: None,
            threads: None,
        }
    }
}

/// True when `params` scatter in the medulla (σ_ms > 0 and κ > 0), i.e. the full model
/// needs profiles; otherwise the unscattered model is exact.
pub fn needs_profiles(params: &FurParams) -> bool {
    params.sigma_ms() > 0.0 && params.kappa() > 0.0
}

/// Parameters with the profiles their model needs (none when [`needs_profiles`] is false).
#[derive(Clone, Debug, PartialEq)]
pub struct OwnedModel {
    params: FurParams,
    profiles: Option<OwnedProfiles>,
}

impl OwnedModel {
    /// Pairs `params` with `profiles`, which must have been made for them
    /// ([`ProfileLayout::matches`]); `None` gives the unscattered model.
    pub fn new(
        params: FurParams,
        profiles: Option<OwnedProfiles>,
    ) -> Result<OwnedModel, ProfileError> {
        if let Some(p) = &profiles {
            if !p.layout().matches(&params) {
                return Err(ProfileError::Mismatch);
            }
        }
        Ok(OwnedModel { params, profiles })
    }

    /// The parameters.
    pub fn params(&self) -> &FurParams {
        &self.params
    }

    /// The profiles, when the parameters need them.
    pub fn profiles(&self) -> Option<&OwnedProfiles> {
        self.profiles.as_ref()
    }

    /// The model with the default `Libm` backend: the full model with profiles, the
    /// unscattered one without.
    pub fn model(&self) -> FurBcsdf<'_> {
        self.model_with::<Libm>()
    }

    /// The model with math backend `M`.
    pub fn model_with<M: Math>(&self) -> FurBcsdf<'_, M> {
        match &self.profiles {
            Some(p) => FurBcsdf::new(self.params, p.view())
                .expect("OwnedModel checks that the profiles match the parameters"),
            None => FurBcsdf::unscattered(self.params),
        }
    }
}

/// The model for `params`: profiles from [`load_or_generate`] with `opts` when
/// [`needs_profiles`], none otherwise (the outcome is then `None` and nothing is generated
/// or cached).
pub fn build_model(
    params: FurParams,
    opts: &ProfileOptions,
) -> Result<(OwnedModel, Option<CacheOutcome>), Error> {
    if !needs_profiles(&params) {
        return Ok((
            OwnedModel {
                params,
                profiles: None,
            },
            None,
        ));
    }
    let (profiles, outcome) = load_or_generate(
        &params,
        opts.res,
        opts.budget,
        opts.seed,
        opts.cache_dir.as_deref(),
        opts.threads,
    )?;
    let model = OwnedModel::new(params, Some(profiles))?;
    Ok((model, Some(outcome)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use bcsdf_core::presets;

    fn key(seed: u64) -> ProfileKey {
        let params = FurParams::new(&presets::find("yan-row-a").unwrap().input).unwrap();
        ProfileKey {
            layout: ProfileLayout::for_params(&params, Resolution::DEFAULT),
            budget: PhotonBudget {
                per_cn_cell: 300,
                per_cm_row: 300,
            },
            seed,
        }
    }

    #[test]
    fn encode_decode_round_trip_and_header_offsets() {
        let k = key(7);
        let p = generate_parallel(&k.layout, &k.budget, k.seed, Some(1)).unwrap();
        let bytes = encode(&p);
        assert_eq!(&bytes[..8], b"FURPROF\0");
        assert_eq!(u32_at(&bytes, 8), FORMAT_VERSION);
        assert_eq!(u32_at(&bytes, 12), GENERATOR_VERSION);
        assert_eq!(u32_at(&bytes, 16), k.layout.g.to_bits());
        assert_eq!(u32_at(&bytes, 36) as usize, k.layout.res.n_sigma);
        assert_eq!(u32_at(&bytes, 56), 300);
        assert_eq!(u64_at(&bytes, 64), 7);
        assert_eq!(u64_at(&bytes, 72) as usize, k.layout.cn_len());
        assert_eq!(u64_at(&bytes, 88) as usize, k.layout.cm_len());
        assert_eq!(decode(&bytes, &k).unwrap(), p);
        // Each key field is named when it differs.
        let mut other = k;
        other.seed = 8;
        assert!(matches!(
            decode(&bytes, &other),
            Err(CacheError::KeyMismatch("seed"))
        ));
        other = k;
        other.budget.per_cm_row += 1;
        assert!(matches!(
            decode(&bytes, &other),
            Err(CacheError::KeyMismatch("photon budget"))
        ));
        other = k;
        other.layout.sigma_n_max += 0.5;
        assert!(matches!(
            decode(&bytes, &other),
            Err(CacheError::KeyMismatch("sigma_n_max"))
        ));
        other = k;
        other.layout.res.n_out += 1;
        assert!(matches!(
            decode(&bytes, &other),
            Err(CacheError::KeyMismatch("resolution"))
        ));
    }

    #[test]
    fn file_names_differ_by_key() {
        assert_ne!(key(1).file_name(), key(2).file_name());
        assert_eq!(key(1).file_name(), key(1).file_name());
        assert!(key(1).file_name().starts_with("medulla-"));
    }

    #[test]
    fn fnv_known_values() {
        assert_eq!(fnv1a64(b""), 0xcbf2_9ce4_8422_2325);
        assert_eq!(fnv1a64(b"a"), 0xaf63_dc4c_8601_ec8c);
        assert_eq!(fnv1a64(b"foobar"), 0x8594_4171_f739_67e8);
    }

    #[test]
    fn budget_scaling() {
        let b = scale_budget(PhotonBudget::DEFAULT, 0.01).unwrap();
        assert_eq!(b.per_cn_cell, PhotonBudget::DEFAULT.per_cn_cell / 100);
        assert_eq!(
            scale_budget(PhotonBudget::DEFAULT, 1e-12)
                .unwrap()
                .per_cm_row,
            1
        );
        assert_eq!(
            scale_budget(PhotonBudget::DEFAULT, 1e12)
                .unwrap()
                .per_cm_row,
            1 << 24
        );
        assert!(scale_budget(PhotonBudget::DEFAULT, 0.0).is_none());
        assert!(scale_budget(PhotonBudget::DEFAULT, f64::NAN).is_none());
    }
}
