//! Baking: samples the analytic far field into the tables of `bcsdf_core::lut` and encodes
//! them as a half-float blob.
//!
//! Every value comes from the analytic model's own functions (`FurBcsdf::longitudinal_gaussian`,
//! `azimuthal_far`, `longitudinal_scattered`), so no formula is restated here. Table `N` has
//! one plane per node of the absorption axis (`lut::absorption_node`), each sampled from the
//! model at that σ_ca ([`OwnedModel::at_sigma`]: the same profiles, that colour's residual). Table rows are
//! sampled in parallel, each value independently, so the blob has the same bits for any
//! thread count.

use bcsdf_core::lut::{
    self, LutHeader, LutResolution, ProfileProvenance, Table, HEADER_LEN, TABLE_COUNT,
};
use bcsdf_core::medulla::GENERATOR_VERSION;
use bcsdf_core::{Absorption, Angles, FurBcsdf, FurParamsInput, Lobe, LobeFamily, LobeGroup, Rgb};
use half::f16;
use rayon::prelude::*;
use std::f32::consts::PI;

use crate::profiles::OwnedModel;

/// The tables before quantisation, [`Table::ALL`] order, each row-major with its channels
/// adjacent.
#[derive(Clone, Debug, PartialEq)]
pub struct TableValues {
    /// Node counts.
    pub res: LutResolution,
    /// The values.
    pub tables: [Vec<f32>; TABLE_COUNT],
}

/// Node `k` of `nodes` uniformly spaced nodes over [lo, lo + span] (the `lut` axes).
pub fn node(lo: f32, span: f32, k: usize, nodes: u32) -> f32 {
    lo + span * (k as f32 / (nodes - 1) as f32)
}

/// Angles with θ clamped onto [−π/2, π/2] (an f32 node may land a rounding step outside).
fn angles(theta_i: f32, theta_r: f32, phi: f32) -> Angles {
    let c = |t: f32| t.clamp(-PI / 2.0, PI / 2.0);
    Angles::new(c(theta_i), c(theta_r), phi).expect("clamped finite angles are valid")
}

/// Samples every table of `model` at its nodes, table `N`'s plane k from channel k mod 3 of
/// `planes[k / 3]`, the model whose RGB σ_ca are the nodes 3j, 3j + 1, 3j + 2 of the
/// absorption axis ([`absorption_planes`] makes them: a channel depends on its own σ_ca
/// alone, so one model gives three planes). Tables `M` and `M_s` do not depend on σ_ca.
pub fn sample(model: &FurBcsdf<'_>, planes: &[FurBcsdf<'_>], res: LutResolution) -> TableValues {
    let mut tables: [Vec<f32>; TABLE_COUNT] = Default::default();

    // M_g(x), x = θ_i + θ_r: the Gaussian G(x − α_g) evaluated as θ_i = x, θ_r = 0 (the
    // energy closure divides it by its mass on the sphere when the LUT is evaluated).
    tables[Table::M as usize] = (0..res.n_sum as usize)
        .flat_map(|k| {
            let x = node(-PI, 2.0 * PI, k, res.n_sum);
            [LobeGroup::R, LobeGroup::TT, LobeGroup::TRT]
                .map(|g| model.longitudinal_gaussian(g, x, 0.0))
        })
        .collect();

    // N_g(|θ_r|, |φ|) per absorption plane: one far-field azimuthal evaluation per node and
    // plane model gives all four families of three planes (the energy closure's residual,
    // `Lobe::Residual`, shares TRT's M: N_TRT carries it).
    assert_eq!(
        planes.len(),
        (res.n_abs as usize).div_ceil(3),
        "one model per three absorption nodes"
    );
    let model_rows: Vec<Vec<[[f32; 3]; 4]>> = (0..planes.len() * res.n_theta_r as usize)
        .into_par_iter()
        .map(|pr| {
            let model = &planes[pr / res.n_theta_r as usize];
            let r = pr % res.n_theta_r as usize;
            let theta_r = node(0.0, PI / 2.0, r, res.n_theta_r);
            (0..res.n_phi as usize)
                .map(|c| {
                    let phi = node(0.0, PI, c, res.n_phi);
                    let lobes = model.azimuthal_far(theta_r.min(PI / 2.0), phi);
                    let mut fam = [[0.0f32; 3]; 4];
                    for lobe in Lobe::ALL {
                        let f = LobeFamily::of(lobe) as usize;
                        for (acc, v) in fam[f].iter_mut().zip(lobes[lobe.index()].0) {
                            *acc += v;
                        }
                    }
                    fam
                })
                .collect()
        })
        .collect();
    // Plane k, row r: channel k mod 3 of model k / 3's row r.
    let n_rows = res.n_theta_r as usize;
    let rows: Vec<Vec<[[f32; 3]; 4]>> = (0..res.n_abs as usize * n_rows)
        .map(|pr| {
            let (k, r) = (pr / n_rows, pr % n_rows);
            model_rows[(k / 3) * n_rows + r]
                .iter()
                .map(|fam| fam.map(|rgb| [rgb[k % 3]; 3]))
                .collect()
        })
        .collect();
    // Absorption only takes light away: every plane is kept at or below the lossless plane,
    // texel by texel and family by family. The model breaks this only where the energy
    // closure's residual is evaluated at the pole row (|θ_r| = 90°, values below 1e-10);
    // the clamp keeps the sampler's density (the lossless plane) positive wherever any
    // colour's S is (docs/lut.md "The absorption axis").
    let plane_rows = res.n_theta_r as usize;
    let mut rows = rows;
    for pr in plane_rows..rows.len() {
        let (lossless, rest) = rows.split_at_mut(plane_rows);
        let row = &mut rest[pr - plane_rows];
        for (texel, top) in row.iter_mut().zip(&lossless[pr % plane_rows]) {
            for (v, t) in texel.iter_mut().zip(top) {
                v[0] = v[0].min(t[0]);
            }
        }
    }
    tables[Table::N as usize] = rows
        .iter()
        .flat_map(|row| row.iter().flat_map(|fam| fam.iter().map(|rgb| rgb[0])))
        .collect();

    // M^s_back and M^s_front: M^s at φ = 0 and φ = π, where the blend weight is exactly 0 / 1.
    tables[Table::MS as usize] = (0..res.n_ms_r as usize)
        .into_par_iter()
        .flat_map_iter(|r| {
            let theta_r = node(-PI / 2.0, PI, r, res.n_ms_r);
            (0..res.n_ms_i as usize).flat_map(move |c| {
                let theta_i = node(-PI / 2.0, PI, c, res.n_ms_i);
                [0.0, PI].map(|phi| model.longitudinal_scattered(&angles(theta_i, theta_r, phi)))
            })
        })
        .collect();

    TableValues { res, tables }
}

/// The power-of-two scale that stores a table whose largest value is `max` in [2^14, 2^15)
/// (1 for an all-zero table).
pub fn scale_for(max: f32) -> f32 {
    if !(max > 0.0 && max.is_finite()) {
        return 1.0;
    }
    let e = max.log2().floor() as i32 - 14;
    let (lo, hi) = lut::SCALE_RANGE;
    2f32.powi(e).clamp(lo, hi)
}

/// f32 → f16 bits of `v / scale`, round to nearest even; values that would be subnormal
/// halves (below 2^−14, i.e. 2^−28 of the table's peak) become 0, negative or non-finite
/// values become 0.
pub fn quantise(v: f32, scale: f32) -> u16 {
    let x = v / scale;
    if !(x.is_finite() && x > 0.0) {
        return 0;
    }
    let h = f16::from_f32(x);
    if h.is_infinite() {
        f16::MAX.to_bits()
    } else if !h.is_normal() {
        0 // subnormal (or rounded to zero)
    } else {
        h.to_bits()
    }
}

/// Encodes sampled tables with their parameters and profile provenance as a sealed blob.
pub fn encode(
    values: &TableValues,
    params: &FurParamsInput,
    profiles: Option<ProfileProvenance>,
) -> Vec<u8> {
    let res = values.res;
    let mut scales = [1.0f32; TABLE_COUNT];
    for t in Table::ALL {
        let max =
            values.tables[t as usize]
                .iter()
                .fold(0.0f32, |m, &v| if v.is_finite() { m.max(v) } else { m });
        scales[t as usize] = scale_for(max);
    }
    let header = LutHeader {
        res,
        scales,
        params: *params,
        profiles,
    };
    let mut blob = vec![0u8; res.blob_len()];
    blob[..HEADER_LEN].copy_from_slice(&header.encode());
    for t in Table::ALL {
        let range = res.byte_range(t);
        let src = &values.tables[t as usize];
        assert_eq!(src.len() * 2, range.len(), "table {} size", t.name());
        for (dst, &v) in blob[range].chunks_exact_mut(2).zip(src) {
            dst.copy_from_slice(&quantise(v, scales[t as usize]).to_le_bytes());
        }
    }
    lut::seal(&mut blob);
    blob
}

/// Where the profiles of a model came from, for the LUT header.
pub fn provenance(model: &OwnedModel) -> Option<ProfileProvenance> {
    model.profiles().map(|p| ProfileProvenance {
        generator_version: GENERATOR_VERSION,
        seed: p.seed(),
        budget: p.budget(),
        res: p.layout().res,
    })
}

/// Why the analytic model behind a LUT could not be rebuilt.
#[derive(Debug)]
pub enum RebuildError {
    /// The LUT's profiles came from another profile generator version.
    GeneratorVersion {
        /// Version in the LUT.
        found: u32,
    },
    /// Making or loading the profiles failed.
    Profiles(crate::profiles::Error),
    /// The stored parameters are invalid.
    Params(bcsdf_core::ParamError),
}

impl std::fmt::Display for RebuildError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            RebuildError::GeneratorVersion { found } => write!(
                f,
                "the LUT's medulla profiles come from generator version {found}, this build has version {GENERATOR_VERSION}: re-bake it"
            ),
            RebuildError::Profiles(e) => write!(f, "{e}"),
            RebuildError::Params(e) => write!(f, "LUT parameters: {e}"),
        }
    }
}

impl std::error::Error for RebuildError {}

/// Rebuilds the analytic model a LUT was baked from: its parameters, and profiles
/// regenerated (or loaded from `cache_dir`) with the stored seed, budget and resolution, so
/// the model is the same bits as at bake time.
pub fn rebuild_model(
    header: &LutHeader,
    cache_dir: Option<std::path::PathBuf>,
    threads: Option<usize>,
) -> Result<OwnedModel, RebuildError> {
    let params = bcsdf_core::FurParams::new(&header.params).map_err(RebuildError::Params)?;
    match header.profiles {
        // No profiles; in the energy closure the residual is regenerated (default seed).
        None => crate::profiles::build_model(
            params,
            &crate::profiles::ProfileOptions {
                cache_dir,
                threads,
                ..crate::profiles::ProfileOptions::default()
            },
        )
        .map(|(m, _)| m)
        .map_err(RebuildError::Profiles),
        Some(p) => {
            if p.generator_version != GENERATOR_VERSION {
                return Err(RebuildError::GeneratorVersion {
                    found: p.generator_version,
                });
            }
            let opts = crate::profiles::ProfileOptions {
                res: p.res,
                budget: p.budget,
                seed: p.seed,
                cache_dir,
                threads,
            };
            crate::profiles::build_model(params, &opts)
                .map(|(m, _)| m)
                .map_err(RebuildError::Profiles)
        }
    }
}

/// The models of table `N`'s absorption planes: model j is `model` at the RGB σ_ca of nodes
/// 3j, 3j + 1, 3j + 2 (`lut::absorption_node(k, n_abs, s₀)`, s₀ = `lut::absorption_scale(κ)`;
/// past the last node, the last node again), ⌈n_abs/3⌉ models ([`OwnedModel::at_sigmas`]: the
/// residual of each colour from `model`'s cache, or generated: one photon walk gives up to
/// eight models, 24 planes).
pub fn absorption_planes(
    model: &OwnedModel,
    n_abs: u32,
) -> Result<Vec<OwnedModel>, crate::profiles::Error> {
    let scale = lut::absorption_scale(model.model().params().kappa());
    let colours: Vec<Absorption> = (0..(n_abs as usize).div_ceil(3))
        .map(|j| {
            let sigma = Rgb([0, 1, 2].map(|c| lut::absorption_node(3 * j + c, n_abs, scale)));
            Absorption::from_sigma(sigma).expect("absorption nodes lie in [0, 1000]")
        })
        .collect();
    model.at_sigmas(&colours)
}

/// Samples and encodes `model` (made from `input`) at resolution `res`: the LUT blob, or why
/// an absorption plane's model could not be made ([`absorption_planes`]).
pub fn try_bake(
    model: &OwnedModel,
    input: &FurParamsInput,
    res: LutResolution,
) -> Result<Vec<u8>, crate::profiles::Error> {
    let planes = absorption_planes(model, res.n_abs)?;
    let views: Vec<FurBcsdf<'_>> = planes.iter().map(OwnedModel::model).collect();
    let values = sample(&model.model(), &views, res);
    Ok(encode(&values, input, provenance(model)))
}

/// [`try_bake`] for tests, benches and examples, which cannot go on without the LUT.
///
/// # Panics
/// When an absorption plane's residual cannot be cached ([`try_bake`]'s error).
pub fn bake(model: &OwnedModel, input: &FurParamsInput, res: LutResolution) -> Vec<u8> {
    try_bake(model, input, res).unwrap_or_else(|e| panic!("baking the LUT: {e}"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scales_put_the_peak_in_the_top_binade() {
        for max in [1e-6f32, 0.3, 1.0, 7.5, 4000.0] {
            let s = scale_for(max);
            let x = max / s;
            assert!((16384.0..32768.0).contains(&x), "{max} -> {x}");
            assert_eq!(s.to_bits() & 0x007f_ffff, 0, "power of two");
        }
        assert_eq!(scale_for(0.0), 1.0);
    }

    #[test]
    fn quantise_rounds_flushes_and_never_goes_negative() {
        assert_eq!(quantise(1.0, 1.0), f16::ONE.to_bits());
        assert_eq!(quantise(-1.0, 1.0), 0);
        assert_eq!(quantise(f32::NAN, 1.0), 0);
        assert_eq!(quantise(1e-6, 1.0), 0, "subnormal half flushed");
        assert_eq!(quantise(1e9, 1.0), f16::MAX.to_bits());
    }
}
