//! Computing [`DualTables`] from any [`Bcsdf`] by quadrature (docs/model.md §13): at each θ_r
//! node, S·cos²θ_i over a midpoint grid in θ_i ∈ [−π/2, π/2] and |φ| ∈ [0, π], per family.
//! No allocation: the per-node buffer is a fixed array.

use super::{
    backscatter, phi_node, theta_node, DualTables, FamilyMoments, FiberAverages, PHI_NODES,
    THETA_NODES,
};
use crate::bcsdf::Bcsdf;
use crate::frame::Angles;
use crate::lobes::FAMILY_COUNT;
use crate::math::{Libm, Math, PI};
use crate::spectrum::Rgb;

/// Largest number of |φ| quadrature nodes.
pub const MAX_PHI_STEPS: usize = 256;

/// Quadrature resolution of [`DualTables::compute`]: midpoint nodes in θ_i over
/// [−π/2, π/2] and in |φ| over [0, π] (even in φ: each node stands for ±φ).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Quadrature {
    /// θ_i nodes (at least 8).
    pub theta_steps: usize,
    /// |φ| nodes (8 to [`MAX_PHI_STEPS`], rounded to even so the front/back split falls on a
    /// cell edge).
    pub phi_steps: usize,
}

impl Quadrature {
    /// 128 × 96: lobes of β ≥ 3° are resolved to well under 1 % (docs/model.md §13).
    pub const DEFAULT: Quadrature = Quadrature {
        theta_steps: 128,
        phi_steps: 96,
    };

    fn clamped(self) -> (usize, usize) {
        let t = self.theta_steps.max(8);
        let p = self.phi_steps.clamp(8, MAX_PHI_STEPS) & !1;
        (t, p)
    }
}

/// Energy and first two moments of x = θ_i + θ_r, per channel.
#[derive(Clone, Copy, Default)]
struct Moments {
    e: [f64; 3],
    m1: [f64; 3],
    m2: [f64; 3],
}

impl Moments {
    fn add(&mut self, v: Rgb, x: f32, w: f64) {
        let x = f64::from(x);
        for c in 0..3 {
            let e = f64::from(v[c]) * w;
            self.e[c] += e;
            self.m1[c] += e * x;
            self.m2[c] += e * x * x;
        }
    }

    fn energy(&self) -> Rgb {
        Rgb(self.e.map(|v| v as f32))
    }

    /// Mean and variance (0 where there is no energy).
    fn mean_variance(&self) -> (Rgb, Rgb) {
        let mut mean = [0.0f32; 3];
        let mut var = [0.0f32; 3];
        for c in 0..3 {
            if self.e[c] > 0.0 {
                let m = self.m1[c] / self.e[c];
                mean[c] = m as f32;
                var[c] = (self.m2[c] / self.e[c] - m * m).max(0.0) as f32;
            }
        }
        (Rgb(mean), Rgb(var))
    }
}

impl DualTables {
    /// Fills `self` from `bcsdf` (every family it returns, the residual included when it is
    /// folded into them) at resolution `q` (docs/model.md §13). Allocation-free; cost
    /// 64·θ_steps·phi_steps evaluations.
    pub fn compute<B: Bcsdf>(&mut self, bcsdf: &B, q: Quadrature) {
        let (nt, np) = q.clamped();
        let dt = PI / nt as f32;
        let dp = PI / np as f32;
        for k in 0..THETA_NODES {
            let tr = theta_node(k);
            // n_g(θ_r, φ) at the |φ| midpoints: energy per unit φ (one sign of φ).
            let mut per_phi = [[Rgb::ZERO; FAMILY_COUNT]; MAX_PHI_STEPS];
            let mut front = Moments::default();
            let mut back = Moments::default();
            let mut family = [Moments::default(); FAMILY_COUNT];
            for (j, slot) in per_phi.iter_mut().enumerate().take(np) {
                let phi = (j as f32 + 0.5) * dp;
                let is_front = 2 * j >= np;
                for i in 0..nt {
                    let ti = -0.5 * PI + (i as f32 + 0.5) * dt;
                    let Ok(a) = Angles::new(ti, tr, phi) else {
                        continue;
                    };
                    let c2 = Libm::cos(ti);
                    let c2 = c2 * c2;
                    let f = bcsdf.eval(&a);
                    let x = ti + tr;
                    // ±φ: the weight of both signs of φ.
                    let w = f64::from(2.0 * dt * dp * c2);
                    for (g, fam) in family.iter_mut().enumerate() {
                        let v = clean(f.as_array()[g]);
                        fam.add(v, x, w);
                        slot[g] += v * (dt * c2);
                    }
                    let total = clean(f.total());
                    if is_front {
                        front.add(total, x, w);
                    } else {
                        back.add(total, x, w);
                    }
                }
            }
            let (alpha_f, beta2_f) = front.mean_variance();
            let (alpha_b, beta2_b) = back.mean_variance();
            let (a_f, a_b) = (front.energy(), back.energy());
            let mut big_a_b = Rgb::ZERO;
            let mut delta_b = Rgb::ZERO;
            let mut sigma_b0 = Rgb::ZERO;
            for c in 0..3 {
                let [a, d, s] = backscatter(
                    a_f[c], a_b[c], alpha_f[c], alpha_b[c], beta2_f[c], beta2_b[c],
                );
                big_a_b[c] = a;
                delta_b[c] = d;
                sigma_b0[c] = s;
            }
            self.fiber[k] = FiberAverages {
                a_f,
                a_b,
                alpha_f,
                alpha_b,
                beta2_f,
                beta2_b,
                big_a_b,
                delta_b,
                sigma_b0,
            };
            for (g, fam) in family.iter().enumerate() {
                let (mean, variance) = fam.mean_variance();
                self.moments[k][g] = FamilyMoments { mean, variance };
            }
            // N^G(φ_j) = (1/π)∫_{φ_j−π/2}^{φ_j+π/2} n_g(φ') dφ' over the whole circle, n_g even.
            for g in 0..FAMILY_COUNT {
                for jj in 0..PHI_NODES {
                    let centre = phi_node(jj);
                    let mut sum = Rgb::ZERO;
                    for (j, slot) in per_phi.iter().enumerate().take(np) {
                        let phi = (j as f32 + 0.5) * dp;
                        // Both signs of φ', each at its distance from the centre on the circle.
                        for p in [phi, -phi] {
                            let d = crate::math::wrap_angle(p - centre).abs();
                            if d < 0.5 * PI {
                                sum += slot[g] * dp;
                            }
                        }
                    }
                    self.n_g[g][k][jj] = sum * (1.0 / PI);
                }
            }
        }
    }
}

/// Non-finite or negative channels as 0.
fn clean(v: Rgb) -> Rgb {
    v.map(|c| if c.is_finite() && c > 0.0 { c } else { 0.0 })
}
