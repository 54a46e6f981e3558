//! The residual (docs/model.md §12, "Residual"): the energy of every path the eight
//! unscattered and three scattered lobes leave out, from the model's own simulation of the
//! cross-section ([`sim`]), as a term of S in the energy closure.
//!
//! Per view angle θ_r (node) and offset h (node), the simulation gives the energy leaving
//! the fiber, E_sim, and the energy on unmodelled paths by exit azimuth; the model's own
//! lobes carry E_model(θ_r, h) (computed by calling them: Σ_p A_p(h), the M_p having mass 1
//! on the sphere in the energy closure, plus per scattered lobe A^s_k(h) times the ψ-integral
//! of C^N against the back/front blend of ∫ M^s_x dθ_i). The residual's magnitude is
//! A_res = max(0, E_sim − E_model) per channel; its shape D_res(θ_r, |φ|) is the unmodelled
//! energy's exit-azimuth histogram, normalised to unit integral over φ ∈ (−π, π]:
//!
//! N_res(θ_r, h, φ) = A_res(θ_r, h)·D_res(θ_r, |φ|), far field ⟨A_res⟩_h·D_res(θ_r, |φ|),
//!
//! and S gains M_TRT(θ_i, θ_r)·N_res/cos²θ_i (folded into the TRT family).
//!
//! # Layout
//! Flat f32 in caller memory, per θ_r node (`n_theta` nodes θ_k = (π/2)·(1 − (1 − x_k)²),
//! x_k = k/(n_theta − 1): graded toward grazing view, where the Bravais index grows as
//! 1/cos θ_r and the residual changes fastest) one row
//! of [`ResidualLayout::row_len`] values: A_res at the `n_h` offsets h_j = (j + ½)/n_h (RGB
//! interleaved), then the row's ⟨A_res⟩_h (RGB, the mean of those offsets' values, which is
//! exactly the h-mean of the near field's piecewise-linear interpolant), then D_res in `n_phi`
//! bins of |φ| ∈ [0, π] (RGB), then the scattered lobes' scale at the offsets and its far-field
//! value (RGB), then the far field's ⟨A_res⟩_h at the row (RGB: the offsets' mean completed to
//! the lobes' exact h-means, `residual_gen::generate_row`). After the rows, the far field's ⟨A_res⟩_h at [`ResidualLayout::n_mean`] finer
//! θ_r nodes (RGB; [`MEAN_SUBDIVISION`] per row interval, the same grading, so every row is
//! one of them): E_model(θ_r) has kinks between the rows (where h = κη'_c or the medulla's
//! total reflection reaches h = 1) that a mean interpolated between rows misses by up to
//! 1.2e-3 of ρ (lossless air-medulla at 67.25°); these means are deterministic (the row's
//! ⟨E_sim⟩_h interpolated, less the lobes' exact h-means at the node), so they cost no photons.
//! Every cell draws from its own PCG32 stream (`rng::cell_stream`), so a table is the same bits
//! for any thread count.
//!
//! This module holds what the model reads (the layout, [`ResidualTable`]'s lookups) and the
//! cross-section simulation ([`sim`]), below `model`; the generation of a table, which calls a
//! model's lobes for E_model, is `crate::residual_gen`, above it.

mod events;
mod flatland;
pub mod sim;
mod table;

pub use table::ResidualTable;

use crate::math::PI;
use crate::medulla::ProfileError;

/// Finer θ_r nodes of the far field's ⟨A_res⟩_h per interval between two rows.
pub const MEAN_SUBDIVISION: usize = 8;

/// Axes and photon budget of a residual table.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ResidualLayout {
    /// θ_r nodes over [0, π/2].
    pub n_theta: usize,
    /// h nodes (midpoints) over [0, 1].
    pub n_h: usize,
    /// |φ| bins over [0, π].
    pub n_phi: usize,
    /// Photons per unit of scattered weight in a cell (K).
    pub photons: u32,
}

impl ResidualLayout {
    /// The default: 32 θ_r nodes, 32 offsets, 36 azimuth bins, K = 500 (docs/model.md §12).
    pub const DEFAULT: ResidualLayout = ResidualLayout {
        n_theta: 32,
        n_h: 32,
        n_phi: 36,
        photons: 500,
    };

    /// Values per θ_r row: 3·(2·(n_h + 1) + n_phi + 1).
    #[must_use]
    pub fn row_len(&self) -> usize {
        3 * (2 * (self.n_h + 1) + self.n_phi + 1)
    }

    /// Where the far field's ⟨A_res⟩_h at the row is in a row (its last three values).
    #[must_use]
    pub fn far_mean_offset(&self) -> usize {
        self.row_len() - 3
    }

    /// Where the scattered lobes' scale factors start in a row: 3·(n_h + 1 + n_phi).
    #[must_use]
    pub fn scale_offset(&self) -> usize {
        3 * (self.n_h + 1 + self.n_phi)
    }

    /// Nodes of the far field's ⟨A_res⟩_h: [`MEAN_SUBDIVISION`]·(n_theta − 1) + 1.
    #[must_use]
    pub fn n_mean(&self) -> usize {
        MEAN_SUBDIVISION * (self.n_theta.max(1) - 1) + 1
    }

    /// Where the far field's ⟨A_res⟩_h start: after the rows.
    #[must_use]
    pub fn means_offset(&self) -> usize {
        self.n_theta * self.row_len()
    }

    /// Values of the whole table: the rows, then 3·[`ResidualLayout::n_mean`] means.
    #[must_use]
    pub fn len(&self) -> usize {
        self.means_offset() + 3 * self.n_mean()
    }

    /// True when the table has no values.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// θ_r of node `k`: (π/2)·(1 − (1 − x)²), x = k/(n_theta − 1).
    #[must_use]
    pub fn theta_node(&self, k: usize) -> f32 {
        graded_node(k, self.n_theta)
    }

    /// The fractional node position of |θ_r| (the inverse of [`ResidualLayout::theta_node`]),
    /// clamped to [0, n_theta − 1].
    #[must_use]
    pub fn theta_position(&self, theta_r: f32) -> f32 {
        graded_position(theta_r, self.n_theta)
    }

    /// θ_r of mean node `i`, on the rows' grading: row k is mean node
    /// [`MEAN_SUBDIVISION`]·k, at the same θ_r bits.
    #[must_use]
    pub fn mean_node(&self, i: usize) -> f32 {
        graded_node(i, self.n_mean())
    }

    /// The fractional mean-node position of |θ_r|, clamped to [0, n_mean − 1].
    #[must_use]
    pub fn mean_position(&self, theta_r: f32) -> f32 {
        graded_position(theta_r, self.n_mean())
    }

    /// h of node `j`: (j + ½)/n_h.
    #[must_use]
    pub fn h_node(&self, j: usize) -> f32 {
        (j as f32 + 0.5) / self.n_h as f32
    }

    /// Checks the sizes.
    pub fn validate(&self) -> Result<(), ProfileError> {
        let ok = |n: usize| (2..=4096).contains(&n);
        if ok(self.n_theta) && ok(self.n_h) && ok(self.n_phi) && self.photons > 0 {
            Ok(())
        } else {
            Err(ProfileError::BadResolution)
        }
    }
}

/// Node `k` of `n` graded nodes over [0, π/2]: (π/2)·(1 − (1 − x)²), x = k/(n − 1).
fn graded_node(k: usize, n: usize) -> f32 {
    let x = 1.0 - k as f32 / (n - 1) as f32;
    (PI / 2.0) * (1.0 - x * x)
}

/// The fractional position of |θ_r| among `n` graded nodes, clamped to [0, n − 1].
fn graded_position(theta_r: f32, n: usize) -> f32 {
    let t = (theta_r.abs() / (PI / 2.0)).min(1.0);
    let x = 1.0 - libm::sqrtf(1.0 - t);
    (x * (n - 1) as f32).clamp(0.0, (n - 1) as f32)
}

#[cfg(test)]
mod tests;
