//! LUT files on disk: the OpenEXR form (one f16 layer per table, metadata attributes) and the
//! raw little-endian blob, both written atomically.
//!
//! Over 600 lines: it mixes error plumbing, EXR attributes and blob I/O; the split into
//! `lutfile/{exr, blob, error}` is issue 13 (maintainability), not done yet.
//!
//! # The raw blob
//!
//! Exactly the bytes of `bcsdf_core::lut` (header, tables, checksum): [`write_blob`] writes
//! them, [`read_blob`] reads them back and checks them with [`lut::validate`].
//!
//! # The OpenEXR form
//!
//! A multi-part scan-line file, ZIP-compressed (lossless), with one part ("layer") per
//! [`Table`], in [`Table::ALL`] order, named [`Table::name`], of size
//! [`LutResolution::dims`] (width = columns, height = rows; `M` has one row), with one
//! `half` channel per [`Table::channel_names`] holding exactly the blob's f16 bits (the
//! physical value is the half × the layer's `scale`). Every layer has the attribute
//!
//! | attribute | type | value |
//! |---|---|---|
//! | `scale` | float | the table's scale (`LutHeader::scales`) |
//!
//! and the first layer, `M`, carries the metadata:
//!
//! | attribute | type | value |
//! |---|---|---|
//! | `lut_format_version` | int | [`lut::FORMAT_VERSION`] |
//! | `model_version` | int | [`bcsdf_core::MODEL_VERSION`] |
//! | `preset` | string | preset name (UTF-8) |
//! | `params` | string | the parameters, human-readable (informative only) |
//! | `eta_c` | float | η_c |
//! | `pigment` | string | `sigma_ca` (`pigment_0..2` = σ_ca R, G, B) or `melanin` (`pigment_0` = eumelanin, `pigment_1` = pheomelanin, `pigment_2` = 0) |
//! | `pigment_0`, `pigment_1`, `pigment_2` | float | the pigment's values |
//! | `alpha_deg`, `beta_m_deg`, `beta_n_deg`, `l`, `kappa`, `eta_m`, `sigma_ms`, `sigma_ma`, `g` | float | the other parameters (β_n and η_m resolved) |
//! | `n_sum`, `n_theta_r`, `n_phi`, `n_ms_i`, `n_ms_r` | int | node counts of the five axes |
//! | `axes` | string | each axis's range, human-readable (informative only) |
//! | `has_profiles` | int | 1 if the scattered tables were baked from medulla profiles, else 0 |
//! | `profile_generator` | int | profile generator version (only with profiles) |
//! | `profile_seed` | string | the profiles' seed, decimal u64 (only with profiles) |
//! | `photons_per_cn_cell`, `photons_per_cm_row` | int | the photon budget (only with profiles) |
//! | `profile_n_sigma`, `profile_n_h`, `profile_n_psi`, `profile_n_in`, `profile_n_out` | int | the profile resolution (only with profiles) |
//! | `lut_checksum` | string | the blob's stored checksum, 16 hex digits |
//! | `E1_R` … `E_peak_B` | double | the measured error summary (nine values: `E1`, `E_albedo`, `E_peak` × `R`, `G`, `B`; all or none) |
//! | `meta_checksum` | string | FNV-1a 64 of the preset name and error summary, 16 hex digits |
//!
//! Floats are stored as `float` (f32) attributes, so they round-trip bit for bit; u32 fields
//! are stored as `int` (the same 32 bits). [`read_exr`] rebuilds the exact blob from these
//! attributes and the layers, puts `lut_checksum` back in its field and runs
//! [`lut::validate`]: any change to the tables, the parameters, the axes or the scales is
//! detected by the blob checksum, and any change to the preset name or error summary by
//! `meta_checksum`. The attributes of each part are written sorted by name, so the same LUT
//! always gives the same file bytes.

use std::collections::HashMap;
use std::fmt;
use std::io::{self, Cursor, Write};
use std::path::{Path, PathBuf};

use bcsdf_core::baked::BakedBcsdf;
use bcsdf_core::lut::{
    self, LutError, LutHeader, LutResolution, ProfileProvenance, Table, HEADER_LEN, TABLE_COUNT,
};
use bcsdf_core::medulla::{PhotonBudget, Resolution};
use bcsdf_core::{FurParamsInput, Pigment, Rgb, MODEL_VERSION};
use exr::prelude as x;
use exr::prelude::traits::*;

use crate::fsutil::AtomicWriter;
use crate::metrics::{ErrorSummary, METRIC_NAMES};

/// Metadata beside the tables (the tables' own header is inside the blob).
#[derive(Clone, Debug, PartialEq)]
pub struct LutMeta {
    /// Name of the preset the LUT was baked from.
    pub preset: String,
    /// The error summary measured at bake time, if any.
    pub errors: Option<ErrorSummary>,
}

/// A LUT with its metadata: the contents of a LUT EXR file.
#[derive(Clone, Debug, PartialEq)]
pub struct LutFile {
    /// The sealed blob (`bcsdf_core::lut` layout).
    pub blob: Vec<u8>,
    /// Metadata that is not part of the blob.
    pub meta: LutMeta,
}

impl LutFile {
    /// The validated evaluator over the blob.
    pub fn baked(&self) -> Result<BakedBcsdf<'_>, LutError> {
        BakedBcsdf::from_bytes(&self.blob)
    }

    /// The decoded header (after validating the whole blob with [`lut::validate`]).
    pub fn header(&self) -> Result<LutHeader, LutError> {
        lut::validate(&self.blob)
    }
}

/// Why reading or writing a LUT file failed. Every variant names the file; the
/// [`Display`](fmt::Display) form is one line, `path: problem`.
#[derive(Debug)]
pub enum LutFileError {
    /// The file does not exist.
    Missing {
        /// The file.
        path: PathBuf,
    },
    /// The file exists but could not be read.
    Read {
        /// The file.
        path: PathBuf,
        /// The I/O error.
        source: io::Error,
    },
    /// The file is not an OpenEXR file, or a corrupt one.
    NotExr {
        /// The file.
        path: PathBuf,
        /// What is wrong.
        problem: String,
    },
    /// The LUT was made by another format version or model version.
    Version {
        /// The file.
        path: PathBuf,
        /// `"format"` (the file layout) or `"model"` (the BCSDF model).
        what: &'static str,
        /// Version found in the file.
        found: u32,
        /// Version this build reads.
        expected: u32,
    },
    /// The EXR file is readable but does not describe a LUT: a layer or attribute is
    /// missing, has the wrong type or size, or the metadata is inconsistent.
    Format {
        /// The file.
        path: PathBuf,
        /// What is wrong.
        problem: String,
    },
    /// The LUT data is invalid ([`lut::validate`] rejected it).
    Invalid {
        /// The file.
        path: PathBuf,
        /// The validation error.
        error: LutError,
    },
    /// The LUT could not be encoded as OpenEXR.
    Encode {
        /// The file.
        path: PathBuf,
        /// What went wrong.
        problem: String,
    },
    /// The output directory is missing, not a directory, or no file can be created in it.
    Directory {
        /// The file to be written.
        path: PathBuf,
        /// Its directory.
        dir: PathBuf,
        /// What is wrong with the directory.
        problem: String,
    },
    /// Writing the file failed (e.g. the disk is full); any existing file at the path is
    /// unchanged.
    Write {
        /// The file.
        path: PathBuf,
        /// The I/O error.
        source: io::Error,
    },
}

impl LutFileError {
    /// The file the error is about.
    pub fn path(&self) -> &Path {
        match self {
            LutFileError::Missing { path }
            | LutFileError::Read { path, .. }
            | LutFileError::NotExr { path, .. }
            | LutFileError::Version { path, .. }
            | LutFileError::Format { path, .. }
            | LutFileError::Invalid { path, .. }
            | LutFileError::Encode { path, .. }
            | LutFileError::Directory { path, .. }
            | LutFileError::Write { path, .. } => path,
        }
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
        let path = one_line(&self.path().display().to_string());
        match self {
            LutFileError::Missing { .. } => write!(f, "{path}: no such file"),
            LutFileError::Read { source, .. } => {
                write!(f, "{path}: cannot read: {}", one_line(&source.to_string()))
            }
            LutFileError::NotExr { problem, .. } => write!(f, "{path}: {}", one_line(problem)),
            LutFileError::Version {
                what: "model",
                found,
                expected,
                ..
            } => write!(
                f,
                "{path}: LUT was baked by model version {found}; this build is model version {expected}: re-bake it with this version's `bake`"
            ),
            LutFileError::Version {
                what,
                found,
                expected,
                ..
            } => write!(
                f,
                "{path}: LUT {what} version {found} is not supported (this build reads version {expected}): re-bake it with this version's `bake`"
            ),
            LutFileError::Format { problem, .. } => {
                write!(f, "{path}: not a valid LUT file: {}", one_line(problem))
            }
            LutFileError::Invalid { error, .. } => write!(f, "{path}: {error}"),
            LutFileError::Encode { problem, .. } => write!(
                f,
                "{path}: cannot encode the LUT as OpenEXR: {}",
                one_line(problem)
            ),
            LutFileError::Directory { dir, problem, .. } => write!(
                f,
                "{path}: cannot write: directory {} {}",
                one_line(&dir.display().to_string()),
                one_line(problem)
            ),
            LutFileError::Write { source, .. } => write!(
                f,
                "{path}: write failed: {} (any existing file there is unchanged)",
                one_line(&source.to_string())
            ),
        }
    }
}

impl std::error::Error for LutFileError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            LutFileError::Read { source, .. } | LutFileError::Write { source, .. } => Some(source),
            _ => None,
        }
    }
}

/// A problem found in bytes, before the path is attached.
#[derive(Debug)]
enum Problem {
    NotExr(String),
    Version {
        what: &'static str,
        found: u32,
        expected: u32,
    },
    Format(String),
    Invalid(LutError),
    Encode(String),
}

impl Problem {
    fn at(self, path: &Path) -> LutFileError {
        let path = path.to_path_buf();
        match self {
            Problem::NotExr(problem) => LutFileError::NotExr { path, problem },
            Problem::Version {
                what,
                found,
                expected,
            } => LutFileError::Version {
                path,
                what,
                found,
                expected,
            },
            Problem::Format(problem) => LutFileError::Format { path, problem },
            Problem::Invalid(error) => LutFileError::Invalid { path, error },
            Problem::Encode(problem) => LutFileError::Encode { path, problem },
        }
    }
}

impl From<LutError> for Problem {
    fn from(e: LutError) -> Problem {
        match e {
            LutError::FormatVersion { found } => Problem::Version {
                what: "format",
                found,
                expected: lut::FORMAT_VERSION,
            },
            LutError::ModelVersion { found } => Problem::Version {
                what: "model",
                found,
                expected: MODEL_VERSION,
            },
            e => Problem::Invalid(e),
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Files

fn read_file(path: &Path) -> Result<Vec<u8>, LutFileError> {
    std::fs::read(path).map_err(|source| {
        if source.kind() == io::ErrorKind::NotFound {
            LutFileError::Missing {
                path: path.to_path_buf(),
            }
        } else {
            LutFileError::Read {
                path: path.to_path_buf(),
                source,
            }
        }
    })
}

/// Writes a file atomically: checks the directory, fills a temporary file in it with `fill`,
/// then renames it over `path`. On any failure the temporary file is removed and an existing
/// file at `path` is untouched.
fn write_with(
    path: &Path,
    fill: impl FnOnce(&mut AtomicWriter) -> io::Result<()>,
) -> Result<(), LutFileError> {
    let dir = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    let dir_error = |problem: String| LutFileError::Directory {
        path: path.to_path_buf(),
        dir: dir.to_path_buf(),
        problem,
    };
    match std::fs::metadata(dir) {
        Err(e) if e.kind() == io::ErrorKind::NotFound => {
            return Err(dir_error("does not exist".into()))
        }
        Err(e) => return Err(dir_error(format!("is not accessible: {e}"))),
        Ok(m) if !m.is_dir() => return Err(dir_error("is not a directory".into())),
        Ok(_) => {}
    }
    if path.is_dir() {
        return Err(LutFileError::Write {
            path: path.to_path_buf(),
            source: io::Error::other("the destination is a directory"),
        });
    }
    let mut w = AtomicWriter::new(path)
        .map_err(|e| dir_error(format!("does not accept a new file: {e}")))?;
    let write_error = |source| LutFileError::Write {
        path: path.to_path_buf(),
        source,
    };
    // On error `w` is dropped, which removes the temporary file.
    fill(&mut w).map_err(write_error)?;
    w.commit().map_err(write_error)
}

/// Writes a raw LUT blob to `path` atomically (temporary file in the same directory, then
/// rename). The blob is validated first; an invalid blob is not written.
pub fn write_blob(path: &Path, blob: &[u8]) -> Result<(), LutFileError> {
    lut::validate(blob).map_err(|e| Problem::from(e).at(path))?;
    write_with(path, |w| w.write_all(blob))
}

/// Reads a raw LUT blob and validates it with [`lut::validate`].
pub fn read_blob(path: &Path) -> Result<Vec<u8>, LutFileError> {
    let bytes = read_file(path)?;
    if bytes.starts_with(&EXR_MAGIC) {
        return Err(Problem::Format(
            "this is an OpenEXR file, not a raw LUT blob (read it as EXR)".into(),
        )
        .at(path));
    }
    lut::validate(&bytes).map_err(|e| Problem::from(e).at(path))?;
    Ok(bytes)
}

/// Writes a LUT as OpenEXR (module docs) to `path` atomically: the file is encoded in
/// memory, read back and compared, then written to a temporary file in the same directory
/// and renamed over `path`.
pub fn write_exr(path: &Path, file: &LutFile) -> Result<(), LutFileError> {
    let bytes = exr_to_bytes(file).map_err(|p| p.at(path))?;
    write_with(path, |w| w.write_all(&bytes))
}

/// Reads a LUT EXR file written by [`write_exr`]: rebuilds the exact blob and validates it.
pub fn read_exr(path: &Path) -> Result<LutFile, LutFileError> {
    let bytes = read_file(path)?;
    exr_from_bytes(path, &bytes)
}

/// [`write_exr`] without the file: the EXR file's bytes. `path` is only named in errors.
pub fn encode_exr(path: &Path, file: &LutFile) -> Result<Vec<u8>, LutFileError> {
    exr_to_bytes(file).map_err(|p| p.at(path))
}

/// [`read_exr`] without the file: decodes EXR file bytes. `path` is only named in errors.
pub fn exr_from_bytes(path: &Path, bytes: &[u8]) -> Result<LutFile, LutFileError> {
    decode(bytes).map_err(|p| p.at(path))
}

// ---------------------------------------------------------------------------------------------
// Attribute names

const EXR_MAGIC: [u8; 4] = [0x76, 0x2f, 0x31, 0x01];

const A_FORMAT: &str = "lut_format_version";
const A_MODEL: &str = "model_version";
const A_PRESET: &str = "preset";
const A_PARAMS: &str = "params";
const A_ETA_C: &str = "eta_c";
const A_PIGMENT: &str = "pigment";
const A_PIGMENT_VALUES: [&str; 3] = ["pigment_0", "pigment_1", "pigment_2"];
const A_FLOATS: [&str; 9] = [
    "alpha_deg",
    "beta_m_deg",
    "beta_n_deg",
    "l",
    "kappa",
    "eta_m",
    "sigma_ms",
    "sigma_ma",
    "g",
];
const A_AXES: &str = "axes";
const A_HAS_PROFILES: &str = "has_profiles";
const A_GENERATOR: &str = "profile_generator";
const A_SEED: &str = "profile_seed";
const A_BUDGET: [&str; 2] = ["photons_per_cn_cell", "photons_per_cm_row"];
const A_PROFILE_RES: [&str; 5] = [
    "profile_n_sigma",
    "profile_n_h",
    "profile_n_psi",
    "profile_n_in",
    "profile_n_out",
];
const A_CHECKSUM: &str = "lut_checksum";
const A_META_CHECKSUM: &str = "meta_checksum";
const A_SCALE: &str = "scale";
const CHANNEL_SUFFIXES: [&str; 3] = ["R", "G", "B"];

const PIGMENT_SIGMA_CA: &str = "sigma_ca";
const PIGMENT_MELANIN: &str = "melanin";

/// The nine error-summary attribute names, [`ErrorSummary::rows`] order × R, G, B.
fn error_names() -> [String; 9] {
    std::array::from_fn(|i| format!("{}_{}", METRIC_NAMES[i / 3], CHANNEL_SUFFIXES[i % 3]))
}

fn error_values(e: &ErrorSummary) -> [f64; 9] {
    let rows = [e.e1, e.e_albedo, e.e_peak];
    std::array::from_fn(|i| rows[i / 3][i % 3])
}

/// FNV-1a 64 of the metadata that the blob checksum does not cover.
fn meta_checksum(meta: &LutMeta) -> u64 {
    let mut bytes = Vec::with_capacity(meta.preset.len() + 81);
    bytes.extend_from_slice(&(meta.preset.len() as u64).to_le_bytes());
    bytes.extend_from_slice(meta.preset.as_bytes());
    match &meta.errors {
        None => bytes.push(0),
        Some(e) => {
            bytes.push(1);
            for v in error_values(e) {
                bytes.extend_from_slice(&v.to_bits().to_le_bytes());
            }
        }
    }
    lut::fnv1a64(&bytes)
}

fn pigment_values(p: &Pigment) -> (&'static str, [f32; 3]) {
    match *p {
        Pigment::Absorption(s) => (PIGMENT_SIGMA_CA, s.0),
        Pigment::Melanin {
            eumelanin,
            pheomelanin,
        } => (PIGMENT_MELANIN, [eumelanin, pheomelanin, 0.0]),
    }
}

/// The nine trailing parameters, [`A_FLOATS`] order, as the blob header stores them.
fn param_floats(p: &FurParamsInput) -> [f32; 9] {
    [
        p.alpha_deg,
        p.beta_m_deg,
        p.beta_n_deg.unwrap_or(p.beta_m_deg),
        p.l,
        p.kappa,
        p.eta_m.unwrap_or(p.eta_c),
        p.sigma_ms,
        p.sigma_ma,
        p.g,
    ]
}

fn params_text(p: &FurParamsInput) -> String {
    let (kind, v) = pigment_values(&p.pigment);
    let pigment = match kind {
        PIGMENT_SIGMA_CA => format!("sigma_ca={},{},{}", v[0], v[1], v[2]),
        _ => format!("eumelanin={} pheomelanin={}", v[0], v[1]),
    };
    let rest: Vec<String> = A_FLOATS
        .iter()
        .zip(param_floats(p))
        .map(|(n, v)| format!("{n}={v}"))
        .collect();
    format!("eta_c={} {pigment} {}", p.eta_c, rest.join(" "))
}

fn axes_text(res: &LutResolution) -> String {
    format!(
        "n_sum = {}: theta_i + theta_r in [-pi, pi]; n_theta_r = {}: |theta_r| in [0, pi/2]; \
         n_phi = {}: |phi| in [0, pi]; n_ms_i = {}: theta_i in [-pi/2, pi/2]; \
         n_ms_r = {}: theta_r in [-pi/2, pi/2] (uniform nodes, first and last on the ends)",
        res.n_sum, res.n_theta_r, res.n_phi, res.n_ms_i, res.n_ms_r
    )
}

fn text(s: &str) -> x::Text {
    // Raw bytes (UTF-8), not Latin-1: any string round-trips.
    x::Text::from_slice_unchecked(s.as_bytes())
}

fn table_named(name: &[u8]) -> Option<Table> {
    Table::ALL.into_iter().find(|t| t.name().as_bytes() == name)
}

/// A name from the file, quoted and escaped for messages.
fn shown(bytes: &[u8]) -> String {
    format!("{:?}", String::from_utf8_lossy(bytes))
}

// ---------------------------------------------------------------------------------------------
// Encoding

fn exr_to_bytes(file: &LutFile) -> Result<Vec<u8>, Problem> {
    let blob = &file.blob;
    let header = lut::validate(blob)?;
    // The reader rebuilds the header from its fields; refuse a blob it would not rebuild.
    if header.encode()[..lut::CHECKSUM.start] != blob[..lut::CHECKSUM.start] {
        return Err(Problem::Encode(
            "the blob's header is not in canonical form (it would not re-encode identically)"
                .into(),
        ));
    }
    let res = header.res;

    let mut layers = Vec::with_capacity(TABLE_COUNT);
    let (mut max_w, mut max_h) = (1, 1);
    for t in Table::ALL {
        let (w, h) = res.dims(t);
        max_w = max_w.max(w);
        max_h = max_h.max(h);
        let data = &blob[res.byte_range(t)];
        let nc = t.channels();
        let list = t
            .channel_names()
            .iter()
            .enumerate()
            .map(|(c, name)| {
                let samples: Vec<x::f16> = (0..w * h)
                    .map(|i| {
                        let at = 2 * (i * nc + c);
                        x::f16::from_bits(u16::from_le_bytes([data[at], data[at + 1]]))
                    })
                    .collect();
                x::AnyChannel::new(*name, x::FlatSamples::F16(samples))
            })
            .collect();
        let mut attrs = x::LayerAttributes::named(t.name());
        attrs.software_name = Some(text(concat!("bake ", env!("CARGO_PKG_VERSION"))));
        attrs.comments = Some(text(
            "fur BCSDF LUT table: physical value = stored half x scale attribute",
        ));
        attrs.other.insert(
            text(A_SCALE),
            x::AttributeValue::F32(header.scales[t as usize]),
        );
        if t == Table::M {
            insert_metadata(&mut attrs.other, &header, blob, &file.meta);
        }
        layers.push(x::Layer::new(
            (w, h),
            attrs,
            x::Encoding::SMALL_LOSSLESS,
            x::AnyChannels::sort(list),
        ));
    }
    let image = x::Image::from_layers(x::ImageAttributes::with_size((max_w, max_h)), layers);
    let mut out = Vec::new();
    image
        .write()
        .non_parallel()
        .to_buffered(Cursor::new(&mut out))
        .map_err(|e| Problem::Encode(e.to_string()))?;
    sort_attributes(&mut out);

    // Read it back: a file this function writes always reads back as the same LUT.
    let back = decode(&out).map_err(|p| {
        Problem::Encode(format!(
            "the encoded file does not read back: {}",
            p.at(Path::new("(encoded)"))
        ))
    })?;
    if back.blob != file.blob || meta_checksum(&back.meta) != meta_checksum(&file.meta) {
        return Err(Problem::Encode(
            "the encoded file reads back as a different LUT".into(),
        ));
    }
    Ok(out)
}

fn insert_metadata(
    other: &mut HashMap<x::Text, x::AttributeValue>,
    header: &LutHeader,
    blob: &[u8],
    meta: &LutMeta,
) {
    use x::AttributeValue::{Text as T, F32, F64, I32};
    let mut put = |name: &str, v: x::AttributeValue| {
        other.insert(text(name), v);
    };
    // u32 values are stored as the i32 with the same bits.
    let int = |v: u32| I32(v as i32);
    put(A_FORMAT, int(lut::FORMAT_VERSION));
    put(A_MODEL, int(MODEL_VERSION));
    put(A_PRESET, T(text(&meta.preset)));
    let p = &header.params;
    put(A_PARAMS, T(text(&params_text(p))));
    put(A_ETA_C, F32(p.eta_c));
    let (kind, pig) = pigment_values(&p.pigment);
    put(A_PIGMENT, T(text(kind)));
    for (name, v) in A_PIGMENT_VALUES.iter().zip(pig) {
        put(name, F32(v));
    }
    for (name, v) in A_FLOATS.iter().zip(param_floats(p)) {
        put(name, F32(v));
    }
    for (name, n) in header.res.axes() {
        put(name, int(n));
    }
    put(A_AXES, T(text(&axes_text(&header.res))));
    match &header.profiles {
        None => put(A_HAS_PROFILES, int(0)),
        Some(pr) => {
            put(A_HAS_PROFILES, int(1));
            put(A_GENERATOR, int(pr.generator_version));
            put(A_SEED, T(text(&pr.seed.to_string())));
            put(A_BUDGET[0], int(pr.budget.per_cn_cell));
            put(A_BUDGET[1], int(pr.budget.per_cm_row));
            let r = pr.res;
            for (name, n) in A_PROFILE_RES
                .iter()
                .zip([r.n_sigma, r.n_h, r.n_psi, r.n_in, r.n_out])
            {
                put(name, int(n as u32));
            }
        }
    }
    let sum = u64::from_le_bytes(blob[lut::CHECKSUM].try_into().unwrap_or([0; 8]));
    put(A_CHECKSUM, T(text(&format!("{sum:016x}"))));
    if let Some(e) = &meta.errors {
        for (name, v) in error_names().iter().zip(error_values(e)) {
            put(name, F64(v));
        }
    }
    put(
        A_META_CHECKSUM,
        T(text(&format!("{:016x}", meta_checksum(meta)))),
    );
}

/// Sorts the attributes of every part header by name, in place (the headers keep their
/// length, so the offset tables stay valid). The exr crate writes them in hash-map order,
/// which changes from run to run; sorted (as the OpenEXR library writes them) the same LUT
/// always gives the same bytes. Leaves `bytes` unchanged if the headers do not parse.
fn sort_attributes(bytes: &mut [u8]) {
    fn cstr(bytes: &[u8], at: usize) -> Option<usize> {
        // Index just past the terminating zero of the string starting at `at`.
        let len = bytes.get(at..)?.iter().position(|&b| b == 0)?;
        Some(at + len + 1)
    }
    fn header_end(bytes: &[u8], mut at: usize, attrs: &mut Vec<(usize, usize)>) -> Option<usize> {
        loop {
            if *bytes.get(at)? == 0 {
                return Some(at);
            }
            let start = at;
            let name_end = cstr(bytes, at)?;
            let type_end = cstr(bytes, name_end)?;
            let size = i32::from_le_bytes(bytes.get(type_end..type_end + 4)?.try_into().ok()?);
            let end = type_end + 4 + usize::try_from(size).ok()?;
            if end > bytes.len() {
                return None;
            }
            attrs.push((start, end));
            at = end;
        }
    }
    if bytes.len() < 8 || bytes[..4] != EXR_MAGIC {
        return;
    }
    let multipart = bytes[5] & 0x10 != 0;
    let mut headers = Vec::new();
    let mut at = 8;
    loop {
        let mut attrs = Vec::new();
        let Some(end) = header_end(bytes, at, &mut attrs) else {
            return;
        };
        headers.push((at, end, attrs));
        at = end + 1;
        if !multipart || bytes.get(at).is_none_or(|&b| b == 0) {
            break;
        }
    }
    for (start, end, mut attrs) in headers {
        let name = |&(s, _): &(usize, usize)| {
            let e = bytes[s..].iter().position(|&b| b == 0).unwrap_or(0);
            bytes[s..s + e].to_vec()
        };
        attrs.sort_by_key(name);
        let sorted: Vec<u8> = attrs
            .iter()
            .flat_map(|&(s, e)| bytes[s..e].iter().copied())
            .collect();
        if sorted.len() == end - start {
            bytes[start..end].copy_from_slice(&sorted);
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Decoding

/// Typed access to one part's attributes.
struct Attrs<'a> {
    map: &'a HashMap<x::Text, x::AttributeValue>,
    layer: &'a str,
}

impl Attrs<'_> {
    fn get(&self, name: &str) -> Result<&x::AttributeValue, Problem> {
        self.map.get(name.as_bytes()).ok_or_else(|| {
            Problem::Format(format!(
                "layer {} has no attribute {name}",
                shown(self.layer.as_bytes())
            ))
        })
    }

    fn mistyped(&self, name: &str, v: &x::AttributeValue, expected: &str) -> Problem {
        Problem::Format(format!(
            "attribute {name} of layer {} has type {}, expected {expected}",
            shown(self.layer.as_bytes()),
            shown(v.kind_name())
        ))
    }

    fn f32(&self, name: &str) -> Result<f32, Problem> {
        match self.get(name)? {
            x::AttributeValue::F32(v) => Ok(*v),
            v => Err(self.mistyped(name, v, "float")),
        }
    }

    fn f64(&self, name: &str) -> Result<f64, Problem> {
        match self.get(name)? {
            x::AttributeValue::F64(v) => Ok(*v),
            v => Err(self.mistyped(name, v, "double")),
        }
    }

    /// An `int` attribute as the u32 with the same bits.
    fn u32(&self, name: &str) -> Result<u32, Problem> {
        match self.get(name)? {
            x::AttributeValue::I32(v) => Ok(*v as u32),
            v => Err(self.mistyped(name, v, "int")),
        }
    }

    fn text(&self, name: &str) -> Result<String, Problem> {
        match self.get(name)? {
            x::AttributeValue::Text(t) => String::from_utf8(t.bytes().to_vec())
                .map_err(|_| Problem::Format(format!("attribute {name} is not valid UTF-8 text"))),
            v => Err(self.mistyped(name, v, "string")),
        }
    }

    fn hex64(&self, name: &str) -> Result<u64, Problem> {
        let s = self.text(name)?;
        if s.len() != 16 {
            return Err(Problem::Format(format!(
                "attribute {name} is {}, not 16 hex digits",
                shown(s.as_bytes())
            )));
        }
        u64::from_str_radix(&s, 16).map_err(|_| {
            Problem::Format(format!(
                "attribute {name} is {}, not 16 hex digits",
                shown(s.as_bytes())
            ))
        })
    }
}

/// Everything the attributes of layer `M` say.
struct Parsed {
    header: LutHeader,
    checksum: u64,
    meta: LutMeta,
    meta_checksum: u64,
}

fn check_version(
    headers: &[exr::meta::header::Header],
    name: &str,
    what: &'static str,
    expected: u32,
) -> Result<(), Problem> {
    let found = headers
        .iter()
        .find_map(|h| h.own_attributes.other.get(name.as_bytes()));
    match found {
        None => Err(Problem::Format(format!(
            "no attribute {name}: this OpenEXR file is not a fur LUT"
        ))),
        Some(x::AttributeValue::I32(v)) if *v as u32 == expected => Ok(()),
        Some(x::AttributeValue::I32(v)) => Err(Problem::Version {
            what,
            found: *v as u32,
            expected,
        }),
        Some(v) => Err(Problem::Format(format!(
            "attribute {name} has type {}, expected int",
            shown(v.kind_name())
        ))),
    }
}

fn parse_metadata(a: &Attrs<'_>) -> Result<Parsed, Problem> {
    let res = LutResolution {
        n_sum: a.u32("n_sum")?,
        n_theta_r: a.u32("n_theta_r")?,
        n_phi: a.u32("n_phi")?,
        n_ms_i: a.u32("n_ms_i")?,
        n_ms_r: a.u32("n_ms_r")?,
    };
    res.validate()?;

    let eta_c = a.f32(A_ETA_C)?;
    let pig = [
        a.f32(A_PIGMENT_VALUES[0])?,
        a.f32(A_PIGMENT_VALUES[1])?,
        a.f32(A_PIGMENT_VALUES[2])?,
    ];
    let pigment = match a.text(A_PIGMENT)?.as_str() {
        PIGMENT_SIGMA_CA => Pigment::Absorption(Rgb(pig)),
        PIGMENT_MELANIN => Pigment::Melanin {
            eumelanin: pig[0],
            pheomelanin: pig[1],
        },
        other => {
            return Err(Problem::Format(format!(
            "attribute {A_PIGMENT} is {}, expected \"{PIGMENT_SIGMA_CA}\" or \"{PIGMENT_MELANIN}\"",
            shown(other.as_bytes())
        )))
        }
    };
    if matches!(pigment, Pigment::Melanin { .. }) && pig[2].to_bits() != 0 {
        return Err(Problem::Format(format!(
            "attribute {} must be 0 for melanin",
            A_PIGMENT_VALUES[2]
        )));
    }
    let mut v = [0.0f32; 9];
    for (slot, name) in v.iter_mut().zip(A_FLOATS) {
        *slot = a.f32(name)?;
    }
    let params = FurParamsInput {
        eta_c,
        pigment,
        alpha_deg: v[0],
        beta_m_deg: v[1],
        beta_n_deg: Some(v[2]),
        l: v[3],
        kappa: v[4],
        eta_m: Some(v[5]),
        sigma_ms: v[6],
        sigma_ma: v[7],
        g: v[8],
    };

    let profiles = match a.u32(A_HAS_PROFILES)? {
        0 => None,
        1 => {
            let seed_text = a.text(A_SEED)?;
            let seed = seed_text.parse::<u64>().map_err(|_| {
                Problem::Format(format!(
                    "attribute {A_SEED} is {}, not a decimal u64",
                    shown(seed_text.as_bytes())
                ))
            })?;
            let mut r = [0usize; 5];
            for (slot, name) in r.iter_mut().zip(A_PROFILE_RES) {
                *slot = a.u32(name)? as usize;
            }
            Some(ProfileProvenance {
                generator_version: a.u32(A_GENERATOR)?,
                seed,
                budget: PhotonBudget {
                    per_cn_cell: a.u32(A_BUDGET[0])?,
                    per_cm_row: a.u32(A_BUDGET[1])?,
                },
                res: Resolution {
                    n_sigma: r[0],
                    n_h: r[1],
                    n_psi: r[2],
                    n_in: r[3],
                    n_out: r[4],
                },
            })
        }
        n => {
            return Err(Problem::Format(format!(
                "attribute {A_HAS_PROFILES} is {n}, expected 0 or 1"
            )))
        }
    };

    let names = error_names();
    let present = names
        .iter()
        .filter(|n| a.map.contains_key(n.as_bytes()))
        .count();
    let errors = match present {
        0 => None,
        9 => {
            let mut v = [0.0f64; 9];
            for (slot, name) in v.iter_mut().zip(&names) {
                *slot = a.f64(name)?;
            }
            Some(ErrorSummary {
                e1: [v[0], v[1], v[2]],
                e_albedo: [v[3], v[4], v[5]],
                e_peak: [v[6], v[7], v[8]],
            })
        }
        _ => {
            let missing = names
                .iter()
                .find(|n| !a.map.contains_key(n.as_bytes()))
                .cloned()
                .unwrap_or_default();
            return Err(Problem::Format(format!(
                "incomplete error summary: attribute {missing} is missing"
            )));
        }
    };

    Ok(Parsed {
        header: LutHeader {
            res,
            // Filled in from each layer's `scale`.
            scales: [1.0; TABLE_COUNT],
            params,
            profiles,
        },
        checksum: a.hex64(A_CHECKSUM)?,
        meta: LutMeta {
            preset: a.text(A_PRESET)?,
            errors,
        },
        meta_checksum: a.hex64(A_META_CHECKSUM)?,
    })
}

/// Checks one part's name, size and channels against the resolution; returns its table.
fn check_part(
    h: &exr::meta::header::Header,
    res: &LutResolution,
    seen: &mut [bool],
) -> Result<Table, Problem> {
    let name = h
        .own_attributes
        .layer_name
        .as_ref()
        .map(|t| t.bytes())
        .unwrap_or(b"");
    let Some(t) = table_named(name) else {
        return Err(Problem::Format(format!(
            "unexpected layer {} (a LUT has the layers {})",
            shown(name),
            Table::ALL.map(Table::name).join(", ")
        )));
    };
    if std::mem::replace(&mut seen[t as usize], true) {
        return Err(Problem::Format(format!("layer {} appears twice", t.name())));
    }
    if h.deep {
        return Err(Problem::Format(format!(
            "layer {} holds deep data, expected flat data",
            t.name()
        )));
    }
    // Lossy compression would change the halves; B44 would also be fed to a decoder that
    // panics on some corrupt data.
    if !h.compression.is_lossless_for(x::SampleType::F16) {
        return Err(Problem::Format(format!(
            "layer {} uses lossy compression {}, a LUT must be stored losslessly",
            t.name(),
            h.compression
        )));
    }
    let (w, h_rows) = res.dims(t);
    let size = h.layer_size;
    if size.0 != w {
        return Err(Problem::Format(format!(
            "layer {} has {} columns, expected {w}",
            t.name(),
            size.0
        )));
    }
    if size.1 != h_rows {
        return Err(Problem::Format(format!(
            "layer {} has {} rows, expected {h_rows}",
            t.name(),
            size.1
        )));
    }
    let list = &h.channels.list;
    for want in t.channel_names() {
        let Some(c) = list.iter().find(|c| c.name.bytes() == want.as_bytes()) else {
            return Err(Problem::Format(format!(
                "layer {} has no channel {want}",
                t.name()
            )));
        };
        if c.sample_type != x::SampleType::F16 {
            return Err(Problem::Format(format!(
                "channel {want} of layer {} has {:?} samples, expected F16 (half)",
                t.name(),
                c.sample_type
            )));
        }
        if c.sampling != x::Vec2(1, 1) {
            return Err(Problem::Format(format!(
                "channel {want} of layer {} is subsampled",
                t.name()
            )));
        }
    }
    if list.len() != t.channels() {
        let extra = list
            .iter()
            .find(|c| {
                !t.channel_names()
                    .iter()
                    .any(|n| n.as_bytes() == c.name.bytes())
            })
            .map(|c| shown(c.name.bytes()))
            .unwrap_or_default();
        return Err(Problem::Format(format!(
            "layer {} has {} channels, expected {} (unexpected channel {extra})",
            t.name(),
            list.len(),
            t.channels()
        )));
    }
    Ok(t)
}

/// Runs the exr crate's reader on this thread, turning its errors, and any panic inside it
/// (its decompressors have panicked on corrupt data, e.g. B44 on an integer overflow), into
/// a "corrupt OpenEXR file" problem. A caught panic still prints the panic hook's message.
fn guarded<T>(read: impl FnOnce() -> x::Result<T>) -> Result<T, Problem> {
    match std::panic::catch_unwind(std::panic::AssertUnwindSafe(read)) {
        Ok(Ok(v)) => Ok(v),
        Ok(Err(e)) => Err(Problem::NotExr(format!("corrupt OpenEXR file: {e}"))),
        Err(_) => Err(Problem::NotExr(
            "corrupt OpenEXR file: the decoder failed on its contents".into(),
        )),
    }
}

fn decode(bytes: &[u8]) -> Result<LutFile, Problem> {
    if !bytes.starts_with(&EXR_MAGIC) {
        return Err(Problem::NotExr(if bytes.starts_with(&lut::MAGIC) {
            "not an OpenEXR file: this is a raw LUT blob (read it as a blob)".into()
        } else {
            "not an OpenEXR file (no EXR magic number)".into()
        }));
    }
    // The headers first: check the layers' sizes before any pixel memory is allocated.
    let meta = guarded(|| x::MetaData::read_from_buffered(Cursor::new(bytes), true))?;
    let headers = &meta.headers;
    check_version(headers, A_FORMAT, "format", lut::FORMAT_VERSION)?;
    check_version(headers, A_MODEL, "model", MODEL_VERSION)?;
    let m = headers
        .iter()
        .find(|h| {
            h.own_attributes
                .layer_name
                .as_ref()
                .is_some_and(|n| n.bytes() == Table::M.name().as_bytes())
        })
        .ok_or_else(|| Problem::Format("no layer M".into()))?;
    let mut parsed = parse_metadata(&Attrs {
        map: &m.own_attributes.other,
        layer: Table::M.name(),
    })?;
    let res = parsed.header.res;
    let mut seen = [false; TABLE_COUNT];
    for h in headers.iter() {
        let t = check_part(h, &res, &mut seen)?;
        parsed.header.scales[t as usize] = Attrs {
            map: &h.own_attributes.other,
            layer: t.name(),
        }
        .f32(A_SCALE)?;
    }
    if let Some(t) = Table::ALL.into_iter().find(|&t| !seen[t as usize]) {
        return Err(Problem::Format(format!("no layer {}", t.name())));
    }

    // Now the pixels (sizes checked above, so the allocation is bounded by the resolution).
    let image = guarded(|| {
        x::read()
            .no_deep_data()
            .largest_resolution_level()
            .all_channels()
            .all_layers()
            .all_attributes()
            .non_parallel()
            .pedantic()
            .from_buffered(Cursor::new(bytes))
    })?;

    let mut blob = vec![0u8; res.blob_len()];
    blob[..HEADER_LEN].copy_from_slice(&parsed.header.encode());
    blob[lut::CHECKSUM].copy_from_slice(&parsed.checksum.to_le_bytes());
    let mut filled = [false; TABLE_COUNT];
    for layer in image.layer_data.iter() {
        let name = layer
            .attributes
            .layer_name
            .as_ref()
            .map(|t| t.bytes())
            .unwrap_or(b"");
        let t = table_named(name)
            .ok_or_else(|| Problem::Format(format!("unexpected layer {}", shown(name))))?;
        let (w, h) = res.dims(t);
        if layer.size != x::Vec2(w, h) || std::mem::replace(&mut filled[t as usize], true) {
            return Err(Problem::Format(format!(
                "layer {} changed between header and data",
                t.name()
            )));
        }
        let nc = t.channels();
        let range = res.byte_range(t);
        let data = &mut blob[range];
        for (c, want) in t.channel_names().iter().enumerate() {
            let samples = layer
                .channel_data
                .list
                .iter()
                .find(|ch| ch.name.bytes() == want.as_bytes())
                .map(|ch| &ch.sample_data);
            let Some(x::FlatSamples::F16(v)) = samples else {
                return Err(Problem::Format(format!(
                    "layer {} has no half channel {want}",
                    t.name()
                )));
            };
            if v.len() != w * h {
                return Err(Problem::Format(format!(
                    "channel {want} of layer {} has {} samples, expected {}",
                    t.name(),
                    v.len(),
                    w * h
                )));
            }
            for (i, s) in v.iter().enumerate() {
                let at = 2 * (i * nc + c);
                data[at..at + 2].copy_from_slice(&s.to_bits().to_le_bytes());
            }
        }
    }
    if let Some(t) = Table::ALL.into_iter().find(|&t| !filled[t as usize]) {
        return Err(Problem::Format(format!("no data for layer {}", t.name())));
    }
    // The sampling section is derived from the tables, so the EXR does not carry it; the
    // stored checksum covers it and still catches any change to the layers.
    lut::write_sampling(&mut blob);
    lut::validate(&blob)?;
    if meta_checksum(&parsed.meta) != parsed.meta_checksum {
        return Err(Problem::Format(format!(
            "metadata is corrupt: {A_META_CHECKSUM} does not match the preset name and error summary"
        )));
    }
    Ok(LutFile {
        blob,
        meta: parsed.meta,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A write that fails part-way (as on a full disk) reports the error, leaves the
    /// existing file as it was and leaves no temporary file behind.
    #[test]
    fn failed_write_keeps_the_existing_file() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("x.lut");
        std::fs::write(&path, b"old contents").unwrap();
        let err = write_with(&path, |w| {
            w.write_all(b"new partial data")?;
            Err(io::Error::from_raw_os_error(28)) // ENOSPC
        })
        .unwrap_err();
        assert!(matches!(err, LutFileError::Write { .. }), "{err:?}");
        let msg = err.to_string();
        assert!(
            msg.contains("x.lut") && msg.contains("No space left"),
            "{msg}"
        );
        assert_eq!(std::fs::read(&path).unwrap(), b"old contents");
        let names: Vec<_> = std::fs::read_dir(dir.path())
            .unwrap()
            .map(|e| e.unwrap().file_name())
            .collect();
        assert_eq!(names, [std::ffi::OsString::from("x.lut")]);
    }

    #[test]
    fn a_panic_in_the_exr_reader_becomes_an_error() {
        let r: Result<(), Problem> = guarded(|| panic!("decoder bug (expected in this test)"));
        assert!(matches!(r, Err(Problem::NotExr(_))), "{r:?}");
        let r: Result<(), Problem> = guarded(|| Err(x::Error::Aborted));
        assert!(matches!(r, Err(Problem::NotExr(_))), "{r:?}");
    }

    #[test]
    fn sorting_attributes_leaves_other_bytes_alone() {
        let mut junk = vec![0x76, 0x2f, 0x31, 0x01, 2, 0x10, 0, 0, b'a'];
        let copy = junk.clone();
        sort_attributes(&mut junk); // header does not parse: unchanged
        assert_eq!(junk, copy);
        let mut header = vec![0x76, 0x2f, 0x31, 0x01, 2, 0, 0, 0];
        for (name, v) in [("b", 2u8), ("a", 1u8)] {
            header.extend_from_slice(name.as_bytes());
            header.extend_from_slice(b"\0int\0");
            header.extend_from_slice(&4i32.to_le_bytes());
            header.extend_from_slice(&[v, 0, 0, 0]);
        }
        header.push(0);
        header.extend_from_slice(&[9, 9, 9]);
        let mut sorted = header.clone();
        sort_attributes(&mut sorted);
        assert_eq!(sorted.len(), header.len());
        assert_eq!(&sorted[8..16], b"a\0int\0\x04\0");
        assert_eq!(&sorted[sorted.len() - 4..], &[0, 9, 9, 9]);
    }
}
