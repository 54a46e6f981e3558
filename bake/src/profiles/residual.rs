//! The residual table for the std tools (docs/model.md §12, "Residual"): parallel generation
//! and a cache file beside the profiles'.
//!
//! [`generate_residual`] runs the core's per-row generator
//! ([`bcsdf_core::residual_gen::generate_row`]) on rayon, the same bits for any thread count.
//! [`load_or_generate_residual`] reuses a cache file made for exactly the same model, layout
//! and seed, through the same locked, atomic protocol as the profile cache
//! ([`super::cache`], "Concurrent bakes").
//!
//! # Cache file format (`RESIDUAL_FORMAT_VERSION` 2)
//!
//! One file per key, `residual-<16 hex digits>.furres`, the FNV-1a 64 hash of the key bytes
//! (8..120 below). The table depends on every parameter (unlike the profiles, whose key is
//! their layout), so the key holds them all. Little-endian throughout:
//!
//! | offset | type | content |
//! |---|---|---|
//! | 0 | `[u8; 8]` | magic `b"FURRES\0\0"` |
//! | 8 | u32 | cache format version ([`RESIDUAL_FORMAT_VERSION`]) |
//! | 12 | u32 | [`bcsdf_core::MODEL_VERSION`] of the model that made the table |
//! | 16 | 4 × u32 | layout: `n_theta`, `n_h`, `n_phi`, `photons` |
//! | 32 | u64 | seed |
//! | 40 | u64 | the profiles' [`ProfileKey::id`] (0: a model without profiles) |
//! | 48 | 14 × u32 | the parameters' IEEE bits: η_c, σ_ca (R, G, B), α, β_m, β_n, l, κ, η_m, σ_ms, σ_ma, g (radians and resolved values, as [`FurParams`] holds them), the closure's index |
//! | 104 | 16 bytes | zero (reserved) |
//! | 120 | u64 | number of f32 entries |
//! | 128 | f32 × … | the table, in [`ResidualLayout`]'s order (version 2: the rows, then the far field's means at the finer nodes; version 1 had the rows only) |
//! | end − 8 | u64 | FNV-1a 64 checksum of every byte before it |
//!
//! Loading checks the magic, the format version, the length, the checksum, then the key
//! bytes (the first field that differs is named: a stale file for another model version,
//! layout, seed, profiles or parameter), then the table through
//! [`ResidualTable::new`]. Each failure is a [`CacheError`] with one line.

use super::cache::entry::{load_or_make, load_or_make_many, EntryPaths};
use super::cache::{check_container, fnv1a64, CacheError, CacheOutcome};
use super::{Error, OwnedModel, ProfileKey};
use crate::fsutil::output_path;
use bcsdf_core::params::HEADER_FIELDS;
use bcsdf_core::residual::{ResidualLayout, ResidualTable};
use bcsdf_core::residual_gen::{
    fill_means, generate_row, generate_rows, mean_node_energy, RowStats,
};
use bcsdf_core::{FurBcsdf, FurParams, Libm, MODEL_VERSION};
use rayon::prelude::*;
use std::path::Path;

/// Version of the residual cache format in the module documentation.
pub const RESIDUAL_FORMAT_VERSION: u32 = 2;

/// Extension of a residual cache file.
pub const RESIDUAL_EXTENSION: &str = "furres";

/// The first eight bytes of a residual cache file.
pub const RESIDUAL_MAGIC: [u8; 8] = *b"FURRES\0\0";

/// Number of parameter words in the key: every header field, the colour as three channels.
const PARAM_WORDS: usize = HEADER_FIELDS + 2;

/// End of the key bytes (which start at 8, after the magic).
const KEY_END: usize = 120;

/// Bytes before the table: the key and its length.
const HEADER_LEN: usize = KEY_END + 8;

/// Generates the residual table of `model` (a model without a residual: its lobes give
/// E_model) at `layout` with rayon, one θ_r row per task, then one mean node per task. `threads` as for
/// [`super::generate_parallel`]. Returns the table and each row's statistics.
pub fn generate_residual(
    model: &FurBcsdf<'_>,
    layout: &ResidualLayout,
    seed: u64,
    threads: Option<usize>,
) -> Result<(Vec<f32>, Vec<RowStats>), Error> {
    layout.validate()?;
    let mut data = vec![0.0f32; layout.len()];
    let mut stats = vec![RowStats::default(); layout.n_theta];
    let mut work = || {
        data[..layout.means_offset()]
            .par_chunks_mut(layout.row_len())
            .zip(stats.par_iter_mut())
            .enumerate()
            .for_each(|(row, (chunk, s))| {
                *s = generate_row(model, layout, row, seed, chunk);
            });
        let energies: Vec<_> = (0..layout.n_mean())
            .into_par_iter()
            .map(|i| mean_node_energy(model, layout, i))
            .collect();
        fill_means(layout, |i| energies[i], &mut data);
    };
    match threads {
        None => work(),
        Some(n) => rayon::ThreadPoolBuilder::new()
            .num_threads(n)
            .build()
            .map_err(|e| Error::ThreadPool(e.to_string()))?
            .install(work),
    }
    Ok((data, stats))
}

/// Most colours one photon walk carries ([`generate_residuals`]): a default LUT's 22
/// absorption nodes are eight models of three channels, one walk.
pub const COLOURS_PER_WALK: usize = 8;

/// The residual tables of `models` (models without a residual that differ in σ_ca only,
/// [`FurParams::same_but_absorption`]: a LUT's absorption planes) at `layout`: each table bit
/// for bit what [`generate_residual`] gives for its model alone, made by one photon walk per
/// [`COLOURS_PER_WALK`] models ([`generate_rows`]: the walk does not depend on the colour, so
/// its geometry is computed once for all of them). Models that differ in more than σ_ca are
/// generated one by one. `threads` as for [`generate_residual`].
pub fn generate_residuals(
    models: &[&FurBcsdf<'_>],
    layout: &ResidualLayout,
    seed: u64,
    threads: Option<usize>,
) -> Result<Vec<Vec<f32>>, Error> {
    layout.validate()?;
    let Some(first) = models.first() else {
        return Ok(Vec::new());
    };
    if !models
        .iter()
        .all(|m| m.params().same_but_absorption(first.params()))
    {
        return models
            .iter()
            .map(|m| generate_residual(m, layout, seed, threads).map(|(data, _)| data))
            .collect();
    }
    let work = || -> Vec<Vec<f32>> {
        let mut tables: Vec<Vec<f32>> = models
            .chunks(COLOURS_PER_WALK)
            .flat_map(|chunk| match chunk.len() {
                1 => walk::<1>(chunk, layout, seed),
                2 => walk::<2>(chunk, layout, seed),
                3 | 4 => walk::<4>(chunk, layout, seed),
                _ => walk::<COLOURS_PER_WALK>(chunk, layout, seed),
            })
            .collect();
        for (data, model) in tables.iter_mut().zip(models) {
            let energies: Vec<_> = (0..layout.n_mean())
                .into_par_iter()
                .map(|i| mean_node_energy(model, layout, i))
                .collect();
            fill_means(layout, |i| energies[i], data);
        }
        tables
    };
    match threads {
        None => Ok(work()),
        Some(n) => Ok(rayon::ThreadPoolBuilder::new()
            .num_threads(n)
            .build()
            .map_err(|e| Error::ThreadPool(e.to_string()))?
            .install(work)),
    }
}

/// The rows of the tables of `chunk` (at most `P` models), one walk of `P` colours per θ_r
/// row on rayon (a short chunk repeats its last model; the copies are dropped).
fn walk<const P: usize>(
    chunk: &[&FurBcsdf<'_>],
    layout: &ResidualLayout,
    seed: u64,
) -> Vec<Vec<f32>> {
    let n = chunk.len();
    let models: [&FurBcsdf<'_>; P] = core::array::from_fn(|k| chunk[k.min(n - 1)]);
    let row_len = layout.row_len();
    let rows: Vec<[Vec<f32>; P]> = (0..layout.n_theta)
        .into_par_iter()
        .map(|row| {
            let mut out: [Vec<f32>; P] = core::array::from_fn(|_| vec![0.0; row_len]);
            let mut hist = vec![[0.0f64; 3]; P * layout.n_phi];
            generate_rows(
                &models,
                layout,
                row,
                seed,
                out.each_mut().map(Vec::as_mut_slice),
                &mut hist,
            );
            out
        })
        .collect();
    (0..n)
        .map(|k| {
            let mut data = vec![0.0f32; layout.len()];
            for (chunk, row) in data[..layout.means_offset()]
                .chunks_exact_mut(row_len)
                .zip(&rows)
            {
                chunk.copy_from_slice(&row[k]);
            }
            data
        })
        .collect()
}

/// Everything that determines a residual table's bits besides the model's code
/// ([`MODEL_VERSION`]): the parameters, the profiles behind the scattered lobes, the layout
/// and the seed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ResidualKey {
    /// The model's parameters.
    pub params: FurParams,
    /// The profiles' key (`None`: a model without profiles).
    pub profiles: Option<ProfileKey>,
    /// The table's layout.
    pub layout: ResidualLayout,
    /// Seed of the photon walks.
    pub seed: u64,
}

/// The parameters' words of the key, in the order of the module documentation.
fn param_words(p: &FurParams) -> [u32; PARAM_WORDS] {
    let [r, g, b] = p.sigma_ca().0;
    [
        p.eta_c().to_bits(),
        r.to_bits(),
        g.to_bits(),
        b.to_bits(),
        p.alpha().to_bits(),
        p.beta_m().to_bits(),
        p.beta_n().to_bits(),
        p.l().to_bits(),
        p.kappa().to_bits(),
        p.eta_m().to_bits(),
        p.sigma_ms().to_bits(),
        p.sigma_ma().to_bits(),
        p.g().to_bits(),
        u32::from(p.closure().index()),
    ]
}

impl ResidualKey {
    /// The key of `model`'s residual at `layout` and `seed`.
    pub fn of(model: &OwnedModel, layout: ResidualLayout, seed: u64) -> ResidualKey {
        ResidualKey {
            params: *model.params(),
            profiles: model.profiles().map(|p| p.key()),
            layout,
            seed,
        }
    }

    /// Bytes 8..[`KEY_END`] of a cache file for this key.
    fn to_bytes(self) -> [u8; KEY_END - 8] {
        let l = self.layout;
        // Validated layouts are small; anything else never validates, so is never written.
        let count = |n: usize| u32::try_from(n).unwrap_or(u32::MAX);
        let words = [RESIDUAL_FORMAT_VERSION, MODEL_VERSION].into_iter().chain([
            count(l.n_theta),
            count(l.n_h),
            count(l.n_phi),
            l.photons,
        ]);
        let mut v: Vec<u8> = words.flat_map(u32::to_le_bytes).collect();
        v.extend(self.seed.to_le_bytes());
        v.extend(self.profiles.map_or(0, |k| k.id()).to_le_bytes());
        v.extend(
            param_words(&self.params)
                .into_iter()
                .flat_map(u32::to_le_bytes),
        );
        // Then the reserved zeros.
        let mut b = [0u8; KEY_END - 8];
        b[..v.len()].copy_from_slice(&v);
        b
    }

    /// The entry's name: `residual-<hash>` (16 hex digits).
    pub fn stem(&self) -> String {
        format!("residual-{:016x}", fnv1a64(&self.to_bytes()))
    }
}

/// Serialises the table `data` of `key` in the cache format (module documentation).
pub fn encode_residual(key: &ResidualKey, data: &[f32]) -> Vec<u8> {
    let mut out = Vec::with_capacity(HEADER_LEN + 4 * data.len() + 8);
    out.extend_from_slice(&RESIDUAL_MAGIC);
    out.extend_from_slice(&key.to_bytes());
    out.extend_from_slice(&(data.len() as u64).to_le_bytes());
    for v in data {
        out.extend_from_slice(&v.to_bits().to_le_bytes());
    }
    let sum = fnv1a64(&out);
    out.extend_from_slice(&sum.to_le_bytes());
    out
}

/// The name of the key field that byte `at` (an offset in the file) belongs to.
fn field_at(at: usize) -> &'static str {
    const PARAMS: [&str; PARAM_WORDS] = [
        "eta_c", "sigma_ca", "sigma_ca", "sigma_ca", "alpha", "beta_m", "beta_n", "l", "kappa",
        "eta_m", "sigma_ms", "sigma_ma", "g", "closure",
    ];
    match at {
        12..=15 => "model version",
        16..=31 => "residual layout",
        32..=39 => "seed",
        40..=47 => "profiles",
        48..=103 => PARAMS[(at - 48) / 4],
        _ => "reserved",
    }
}

/// Reads a residual cache file's bytes, accepting them only if they hold the table of exactly
/// `expected` (checks in the order of the module documentation).
pub fn decode_residual(bytes: &[u8], expected: &ResidualKey) -> Result<Vec<f32>, CacheError> {
    let body = check_container(
        bytes,
        &RESIDUAL_MAGIC,
        RESIDUAL_FORMAT_VERSION,
        HEADER_LEN,
        &[KEY_END],
    )?;
    let want = expected.to_bytes();
    if let Some(i) = (0..want.len()).find(|&i| want[i] != bytes[8 + i]) {
        return Err(CacheError::KeyMismatch(field_at(8 + i)));
    }
    let data: Vec<f32> = bytes[HEADER_LEN..body]
        .chunks_exact(4)
        .map(|c| f32::from_bits(u32::from_le_bytes(c.try_into().expect("4 bytes"))))
        .collect();
    ResidualTable::new(expected.params, expected.layout, &data).map_err(CacheError::Tables)?;
    Ok(data)
}

/// The residual table of `model` (which must not have one yet: its lobes give E_model) at
/// `layout` and `seed`: read from `cache_dir` when it holds a valid file for this key, else
/// generated with [`generate_residual`] and written there atomically, under the entry's lock
/// (so concurrent bakes generate it once). Without a cache directory it is always generated.
pub fn load_or_generate_residual(
    model: &OwnedModel,
    layout: ResidualLayout,
    seed: u64,
    cache_dir: Option<&Path>,
    threads: Option<usize>,
) -> Result<(Vec<f32>, CacheOutcome), Error> {
    layout.validate()?;
    let make = || {
        generate_residual(
            &model.model_without_residual::<Libm>(),
            &layout,
            seed,
            threads,
        )
        .map(|(data, _)| data)
    };
    let Some(dir) = cache_dir else {
        return Ok((make()?, CacheOutcome::Generated { path: None }));
    };
    let key = ResidualKey::of(model, layout, seed);
    let stem = key.stem();
    let paths = EntryPaths {
        dir,
        file: output_path(dir, &stem, RESIDUAL_EXTENSION).map_err(Error::CacheName)?,
        lock: output_path(dir, &stem, super::LOCK_EXTENSION).map_err(Error::CacheName)?,
    };
    load_or_make(
        paths,
        |bytes| decode_residual(bytes, &key),
        make,
        |data| encode_residual(&key, data),
    )
}

/// [`load_or_generate_residual`] for several models that differ in σ_ca only (a LUT's
/// absorption planes): each table read from `cache_dir` when it holds a valid file for its
/// key, the others generated together ([`generate_residuals`]) under their entries' locks and
/// written atomically, each to its own file (the same files [`load_or_generate_residual`]
/// reads and writes). Without a cache directory they are always generated.
pub fn load_or_generate_residuals(
    models: &[&OwnedModel],
    layout: ResidualLayout,
    seed: u64,
    cache_dir: Option<&Path>,
    threads: Option<usize>,
) -> Result<Vec<(Vec<f32>, CacheOutcome)>, Error> {
    layout.validate()?;
    let views: Vec<FurBcsdf<'_>> = models
        .iter()
        .map(|m| m.model_without_residual::<Libm>())
        .collect();
    let make = |which: &[usize]| {
        let chosen: Vec<&FurBcsdf<'_>> = which.iter().map(|&i| &views[i]).collect();
        generate_residuals(&chosen, &layout, seed, threads)
    };
    let Some(dir) = cache_dir else {
        let all: Vec<usize> = (0..models.len()).collect();
        return Ok(make(&all)?
            .into_iter()
            .map(|data| (data, CacheOutcome::Generated { path: None }))
            .collect());
    };
    let keys: Vec<ResidualKey> = models
        .iter()
        .map(|m| ResidualKey::of(m, layout, seed))
        .collect();
    let entries = keys
        .iter()
        .map(|key| {
            let stem = key.stem();
            Ok(EntryPaths {
                dir,
                file: output_path(dir, &stem, RESIDUAL_EXTENSION).map_err(Error::CacheName)?,
                lock: output_path(dir, &stem, super::LOCK_EXTENSION).map_err(Error::CacheName)?,
            })
        })
        .collect::<Result<Vec<_>, Error>>()?;
    load_or_make_many(
        entries,
        |i, bytes| decode_residual(bytes, &keys[i]),
        make,
        |i, data| encode_residual(&keys[i], data),
    )
}

#[cfg(test)]
mod tests;
