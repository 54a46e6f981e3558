//! Parallel generation of the medulla profiles: the core's per-cell generators on rayon, the
//! same bits for any thread count; and scaling a photon budget.

use super::{Error, OwnedProfiles, ProfileKey};
use bcsdf_core::medulla::{generate_cm_row, generate_cn_cell, PhotonBudget, ProfileLayout};
use rayon::prelude::*;

/// Generates every table of `layout` with rayon: C^N cells and C^M rows in parallel,
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
                cn.par_chunks_mut(n_psi).enumerate().for_each(|(cell, c)| {
                    generate_cn_cell(layout, cell, budget, seed, c);
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
    Ok(OwnedProfiles::new(key, cn, cm)?)
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

#[cfg(test)]
mod tests {
    use super::*;

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
