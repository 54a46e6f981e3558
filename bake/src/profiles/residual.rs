//! Parallel generation of the residual table (docs/model.md §12, "Residual"): the core's
//! per-row generator ([`bcsdf_core::residual::generate_row`]) on rayon, the same bits for any
//! thread count.

use super::Error;
use bcsdf_core::residual::{generate_row, ResidualLayout, RowStats};
use bcsdf_core::FurBcsdf;
use rayon::prelude::*;

/// Generates the residual table of `model` (a model without a residual: its lobes give
/// E_model) at `layout` with rayon, one θ_r row per task. `threads` as for
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
        data.par_chunks_mut(layout.row_len())
            .zip(stats.par_iter_mut())
            .enumerate()
            .for_each(|(row, (chunk, s))| {
                *s = generate_row(model, layout, row, seed, chunk);
            });
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
