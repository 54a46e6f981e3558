//! A model that owns its profiles: [`build_model`] gets them from the cache or the generator
//! when the parameters scatter in the medulla, and [`OwnedModel`] lends the core's
//! [`FurBcsdf`] over them.

use super::cache::load_or_generate;
use super::residual::{load_or_generate_residual, load_or_generate_residuals};
use super::{Error, OwnedProfiles, DEFAULT_SEED};
use bcsdf_core::medulla::{PhotonBudget, ProfileError, Resolution};
use bcsdf_core::residual::{ResidualLayout, ResidualTable};
use bcsdf_core::{Absorption, Closure, FurBcsdf, FurParams, Libm, Math};
use std::path::PathBuf;

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

/// Parameters with the profiles their model needs (none when [`needs_profiles`] is false)
/// and, in the energy closure, the residual table (docs/model.md §12, "Residual").
#[derive(Clone, Debug, PartialEq)]
pub struct OwnedModel {
    params: FurParams,
    profiles: Option<OwnedProfiles>,
    residual: Option<Vec<f32>>,
    residual_note: Option<String>,
    /// Where [`OwnedModel::at_sigma`] gets the residual of another colour: the seed, cache
    /// directory and threads [`build_model`] used (none: the default seed, no cache).
    residual_source: ResidualSource,
}

/// The seed, cache directory and threads of a model's residual table.
#[derive(Clone, Debug, Default, PartialEq)]
struct ResidualSource {
    seed: Option<u64>,
    cache_dir: Option<PathBuf>,
    threads: Option<usize>,
}

impl OwnedModel {
    /// Pairs `params` with `profiles`, which must have been made for them
    /// ([`ProfileLayout::matches`]); `None` gives the unscattered model.
    ///
    /// [`ProfileLayout::matches`]: bcsdf_core::medulla::ProfileLayout::matches
    pub fn new(
        params: FurParams,
        profiles: Option<OwnedProfiles>,
    ) -> Result<OwnedModel, ProfileError> {
        if let Some(p) = &profiles {
            if !p.layout().matches(&params) {
                return Err(ProfileError::Mismatch);
            }
        }
        Ok(OwnedModel {
            params,
            profiles,
            residual: None,
            residual_note: None,
            residual_source: ResidualSource::default(),
        })
    }

    /// The model of the same parameters and profiles at colour `absorption` (σ_ca per
    /// channel; the profiles do not depend on it), in the energy closure with the residual
    /// table of that colour (docs/model.md §12: it depends on σ_ca), loaded from or generated
    /// into the cache this model's residual came from, with the same seed. What a baked LUT's
    /// absorption planes are sampled from (`tables::sample`) and what a LUT evaluated at a
    /// colour is measured against.
    pub fn at_sigma(&self, absorption: &Absorption) -> Result<OwnedModel, Error> {
        let params = self.params.with_absorption(absorption);
        let mut model = OwnedModel::new(params, self.profiles.clone())?;
        model.residual_source = self.residual_source.clone();
        if params.closure() != Closure::Energy {
            return Ok(model);
        }
        let src = &self.residual_source;
        let (data, outcome) = load_or_generate_residual(
            &model,
            ResidualLayout::DEFAULT,
            src.seed.unwrap_or(DEFAULT_SEED),
            src.cache_dir.as_deref(),
            src.threads,
        )?;
        let mut model = model.with_residual(data)?;
        model.residual_note = outcome.note();
        Ok(model)
    }

    /// [`OwnedModel::at_sigma`] at several colours: the residual tables of those colours
    /// that the cache lacks are generated together, one photon walk for up to
    /// [`super::residual::COLOURS_PER_WALK`] colours ([`load_or_generate_residuals`]), each
    /// the same bits as [`OwnedModel::at_sigma`]'s. What a baked LUT's absorption planes are
    /// made with.
    pub fn at_sigmas(&self, colours: &[Absorption]) -> Result<Vec<OwnedModel>, Error> {
        let models = colours
            .iter()
            .map(|a| {
                let mut model =
                    OwnedModel::new(self.params.with_absorption(a), self.profiles.clone())?;
                model.residual_source = self.residual_source.clone();
                Ok(model)
            })
            .collect::<Result<Vec<_>, Error>>()?;
        if self.params.closure() != Closure::Energy {
            return Ok(models);
        }
        let src = &self.residual_source;
        let refs: Vec<&OwnedModel> = models.iter().collect();
        let tables = load_or_generate_residuals(
            &refs,
            ResidualLayout::DEFAULT,
            src.seed.unwrap_or(DEFAULT_SEED),
            src.cache_dir.as_deref(),
            src.threads,
        )?;
        models
            .into_iter()
            .zip(tables)
            .map(|(model, (data, outcome))| {
                let mut model = model.with_residual(data)?;
                model.residual_note = outcome.note();
                Ok(model)
            })
            .collect()
    }

    /// This model with the residual table `data` ([`ResidualLayout::DEFAULT`], generated for
    /// these parameters by [`super::residual::generate_residual`]); checked like [`ResidualTable::new`].
    pub fn with_residual(self, data: Vec<f32>) -> Result<OwnedModel, ProfileError> {
        ResidualTable::new(self.params, ResidualLayout::DEFAULT, &data)?;
        Ok(OwnedModel {
            residual: Some(data),
            ..self
        })
    }

    /// Why [`build_model`] did not use the residual's cache file, when it rejected one
    /// ([`super::CacheOutcome::note`]).
    pub fn residual_cache_note(&self) -> Option<&str> {
        self.residual_note.as_deref()
    }

    /// The residual table, when the model has one.
    pub fn residual(&self) -> Option<&[f32]> {
        self.residual.as_deref()
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
        let model = self.model_without_residual::<M>();
        match &self.residual {
            Some(data) => ResidualTable::new(self.params, ResidualLayout::DEFAULT, data)
                .and_then(|t| model.with_residual(t))
                .expect("OwnedModel checks the residual table at construction"),
            None => model,
        }
    }

    /// The model without its residual (what the residual's E_model is computed from).
    pub fn model_without_residual<M: Math>(&self) -> FurBcsdf<'_, M> {
        match &self.profiles {
            Some(p) => FurBcsdf::new(self.params, p.view())
                .expect("OwnedModel checks that the profiles match the parameters"),
            None => FurBcsdf::unscattered(self.params),
        }
    }
}

/// The model for `params`: profiles from [`load_or_generate`] with `opts` when
/// [`needs_profiles`], none otherwise (the outcome is then `None` and nothing is generated
/// or cached); in the energy closure also the residual table ([`load_or_generate_residual`]
/// at [`ResidualLayout::DEFAULT`] with `opts.seed`, cached in `opts.cache_dir` beside the
/// profiles), for every parameter set. The profiles' cache outcome is returned; a rejected
/// residual cache file leaves its note in [`OwnedModel::residual_cache_note`].
pub fn build_model(
    params: FurParams,
    opts: &ProfileOptions,
) -> Result<(OwnedModel, Option<super::CacheOutcome>), Error> {
    let (model, outcome) = if needs_profiles(&params) {
        let (profiles, outcome) = load_or_generate(
            &params,
            opts.res,
            opts.budget,
            opts.seed,
            opts.cache_dir.as_deref(),
            opts.threads,
        )?;
        (OwnedModel::new(params, Some(profiles))?, Some(outcome))
    } else {
        (OwnedModel::new(params, None)?, None)
    };
    let mut model = model;
    model.residual_source = ResidualSource {
        seed: Some(opts.seed),
        cache_dir: opts.cache_dir.clone(),
        threads: opts.threads,
    };
    if params.closure() != Closure::Energy {
        return Ok((model, outcome));
    }
    let (data, residual_outcome) = load_or_generate_residual(
        &model,
        ResidualLayout::DEFAULT,
        opts.seed,
        opts.cache_dir.as_deref(),
        opts.threads,
    )?;
    let mut model = model.with_residual(data)?;
    model.residual_note = residual_outcome.note();
    model.residual_source = ResidualSource {
        seed: Some(opts.seed),
        cache_dir: opts.cache_dir.clone(),
        threads: opts.threads,
    };
    Ok((model, outcome))
}
