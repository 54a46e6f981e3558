//! Sampling the baked tables (docs/model.md §10, docs/lut.md "Sampling data").
//!
//! The baked far field is S·cos²θ_i = [Σ_g M_g(θ_i + θ_r)·N_g(|θ_r|, |φ|) + M^s(θ_i, θ_r, |φ|)·N^s]·g(θ_i),
//! every factor piecewise linear along its axis and g = min(1, cos²θ_i/10⁻⁴) the factor S's
//! pole guard 1/max(cos²θ_i, 10⁻⁴) leaves (1 except within s_c = 0.573° of θ_i = ±90°,
//! [`super::sliver`]). The sampler is a mixture of five separable parts, each drawing θ_i
//! and φ from one interpolated table row, exactly as `eval` interpolates it:
//!
//! | part c | θ_i density | φ density | weight A_c(θ_r) |
//! |---|---|---|---|
//! | g = R, TT, TRT | M_g(θ_i + θ_r)·g(θ_i)/m_g, θ_i ∈ [−π/2, π/2] | n_g(\|φ\|)/(2 ν_g) | 2·m_g·ν_g |
//! | scattered back | M^s_back(θ_i, θ_r)·g(θ_i)/s_back | (1 − \|φ\|/π)·n_s(\|φ\|)/(2 (ν_s − μ_s)) | 2·s_back·(ν_s − μ_s) |
//! | scattered front | M^s_front(θ_i, θ_r)·g(θ_i)/s_front | (\|φ\|/π)·n_s(\|φ\|)/(2 μ_s) | 2·s_front·μ_s |
//!
//! with n_f family f's N on the LUT's lossless plane (σ_ca = 0, LUT format 5: the mixture is
//! the same for every colour, and since absorption only darkens, the weight S·cos θ_i/p_ω at
//! any colour is at most the lossless one, channel by channel), ν_f = ∫₀^π n_f, μ_s = ∫₀^π (φ/π)·n_s,
//! m_g = ∫ M_g·g over the restricted range (in the energy closure M_g is multiplied by the
//! LUT's 1/Z_g, docs/model.md §12) and s_x = ∫ M^s_x·g dθ_i: exact integrals of the
//! interpolants, from the LUT's prefix sums outside the pole slivers and in closed form
//! within them (`rows::Range`, `slivers`: node weights per piece shared by the rows of an
//! axis, [`super::sliver`]). The two scattered parts are the two separable
//! products of the exact blend M^s = (1 − |φ|/π)·M^s_back + (|φ|/π)·M^s_front. The mixture
//! density per unit solid angle is then
//!
//! p_ω = [Σ_g M_g·n_g + M^s·n_s]·g(θ_i) / (W·cos θ_i),   W = Σ_c A_c,
//!
//! the mean channel of S·cos θ_i over W: for a grey fiber the weight S·cos θ_i/p_ω is W at
//! every direction, and W is the directional albedo ρ(θ_r). It costs one evaluation's lookups
//! plus seven prefix reads, and per view the slivers' pieces (one set of node weights per
//! piece for the three M_g, one for the two M^s halves).

use super::choose;
use super::sliver::pole_keep;
use crate::baked::{BakedBcsdf, Lookups};
use crate::bcsdf::{solid_angle_pdf, Bcsdf, Evaluated, Sample, SampledDirection};
use crate::frame::{AngleError, Angles, Vec3};
use crate::lobes::{Families, LobeFamily};
use crate::lut::cdf::Density;
use crate::math::{Math, PI};
use crate::model::POLE_SLIVER;
use rows::{Range, Rows};
use slivers::sliver_masses;
pub use view::BakedView;

mod at;
mod rows;
mod slivers;
mod view;

impl<'a, M: Math> BakedBcsdf<'a, M> {
    /// M_g restricted to θ_i ∈ [−π/2, π/2], i.e. x = θ_i + θ_r ∈ [θ_r − π/2, θ_r + π/2].
    fn m_rows(&self, g: usize) -> Rows<'a> {
        Rows::new(self, Density::M(g), &self.sum, (0, 0.0))
    }

    /// ∫ M_g from the first node to x, for the three groups at once (one texel pair).
    #[inline(always)]
    fn m_cdf(&self, x: f32) -> [f32; 3] {
        self.m_cdf_at(self.sum.locate(x))
    }

    /// (∫ M_g over θ_i ∈ [−π/2, π/2], CDF at the range start) for the three groups.
    #[inline(always)]
    fn m_masses(&self, theta_r: f32) -> [(f32, f32); 3] {
        let lo = self.m_cdf(theta_r - PI / 2.0);
        let hi = self.m_cdf(theta_r + PI / 2.0);
        [
            ((hi[0] - lo[0]).max(0.0), lo[0]),
            ((hi[1] - lo[1]).max(0.0), lo[1]),
            ((hi[2] - lo[2]).max(0.0), lo[2]),
        ]
    }

    /// Total of density `d` (the last prefix entry) blended between rows `row` and `row + 1`.
    #[inline(always)]
    fn row_total(&self, d: Density, (row, w): (usize, f32)) -> f32 {
        let l = &self.densities[d.index()];
        let at = |r: usize| l.prefix_at + 4 * (r.min(l.rows - 1) * l.entries + l.entries - 1);
        let t0 = self.f32_at(at(row));
        t0 + (self.f32_at(at(row + 1)) - t0) * w
    }

    fn ms_rows(&self, half: usize, theta_r: f32) -> Rows<'a> {
        let at = self.ms_r.locate(theta_r);
        Rows::new(self, Density::MS(half), &self.ms_i, at)
    }

    /// Mixture weights A_c(θ_r) of the five parts (R, TT, TRT, scattered back, front) and
    /// their θ_i ranges, every mass with S's pole factor g (docs/model.md §10).
    #[inline(always)]
    fn parts(&self, theta_r: f32) -> ([f32; 5], [Range; 5]) {
        let m = self.m_masses(theta_r);
        let nr = self.theta_r.locate(theta_r.abs());
        let nu_s = self.row_total(Density::N(3), nr);
        let mu_s = self.row_total(Density::Front, nr);
        // The θ_i ranges: M_g over x = θ_i + θ_r ∈ [θ_r − π/2, θ_r + π/2], M^s_x over θ_i.
        let (lo, hi) = (theta_r - PI / 2.0, theta_r + PI / 2.0);
        let n = [
            self.row_total(Density::N(0), nr),
            self.row_total(Density::N(1), nr),
            self.row_total(Density::N(2), nr),
            nu_s - mu_s,
            mu_s,
        ];
        // The pole slivers at both ends of every range (docs/model.md §10): the three M_g
        // from one texel pair per node, the two halves of M^s from their blended rows, each
        // piece's node weights computed once for the rows of its axis.
        let m_step = self.densities[0].step;
        let pair = |j: usize| {
            let v = self.nodes.m_pair(j);
            ([v[0], v[1], v[2]], [v[3], v[4], v[5]])
        };
        let m_low = sliver_masses(&self.sum, m_step, (lo, lo + POLE_SLIVER), lo, pair);
        let m_high = sliver_masses(&self.sum, m_step, (hi - POLE_SLIVER, hi), hi, pair);
        let ms = [self.ms_rows(0, theta_r), self.ms_rows(1, theta_r)];
        let halves = |j: usize| {
            (
                [ms[0].value(j), ms[1].value(j)],
                [ms[0].value(j + 1), ms[1].value(j + 1)],
            )
        };
        let (p0, p1) = (-PI / 2.0, PI / 2.0);
        let ms_low = sliver_masses(&self.ms_i, ms[0].step, (p0, p0 + POLE_SLIVER), p0, halves);
        let ms_high = sliver_masses(&self.ms_i, ms[0].step, (p1 - POLE_SLIVER, p1), p1, halves);
        // Written out (not `array::from_fn`, whose closure stayed a call per part).
        let m_range = |g: usize| Range {
            lo,
            hi,
            start: m[g].1,
            raw: m[g].0,
            slivers: [m_low[g], m_high[g]],
        };
        let ms_range = |x: usize| Range {
            lo: p0,
            hi: p1,
            start: 0.0,
            raw: ms[x].total(),
            slivers: [ms_low[x], ms_high[x]],
        };
        let ranges = [m_range(0), m_range(1), m_range(2), ms_range(0), ms_range(1)];
        // The mass of the evaluated M_g: the tabulated one times the closure's factor.
        let norm = self.sphere_norms(self.norm.locate(theta_r));
        let mass = |g: usize| ranges[g].kept() * norm[g];
        let a = [
            2.0 * mass(0) * n[0],
            2.0 * mass(1) * n[1],
            2.0 * mass(2) * n[2],
            2.0 * ranges[3].kept() * n[3],
            2.0 * ranges[4].kept() * n[4],
        ];
        (
            a.map(|v| if v.is_finite() && v > 0.0 { v } else { 0.0 }),
            ranges,
        )
    }

    /// The mixture density of the lookups per unit solid angle, given W.
    fn density(l: &Lookups, total_weight: f32, cos_theta_i: f32) -> f32 {
        if !(total_weight > 0.0) {
            return 0.0;
        }
        let n = l.n0;
        // M^s's blend exactly as `assemble` forms it.
        let [back, front] = l.ms;
        let ms = back + l.front * (front - back);
        let p = l.m[0] * n[0] + l.m[1] * n[1] + l.m[2] * n[2] + ms * n[3];
        // S's pole factor g: S·cos²θ_i = (Σ M·N)·g (exactly 1 outside the slivers).
        let p = p * pole_keep(cos_theta_i);
        let v = solid_angle_pdf(p / total_weight, cos_theta_i);
        if v.is_finite() && v > 0.0 {
            v
        } else {
            0.0
        }
    }

    /// Draws (θ_i, φ) given a valid θ_r and its [`BakedBcsdf::parts`] `(a, ranges)` from
    /// three uniform numbers (docs/model.md §10).
    fn draw(
        &self,
        theta_r: f32,
        (a, ranges): ([f32; 5], [Range; 5]),
        u: [f32; 3],
    ) -> Option<SampledDirection> {
        let (c, u0) = choose(&a, u[0])?;
        let negative = u0 < 0.5;
        let theta_i = if c < 3 {
            let x = self.m_rows(c).invert_kept(&ranges[c], u[1]);
            (x - theta_r).clamp(-PI / 2.0, PI / 2.0)
        } else {
            self.ms_rows(c - 3, theta_r)
                .invert_kept(&ranges[c], u[1])
                .clamp(-PI / 2.0, PI / 2.0)
        };
        let family = if c < 3 { c } else { 3 };
        let at = self.theta_r.locate(theta_r.abs());
        let rows = match c {
            3 => Rows::back(self, &self.phi, at),
            4 => Rows::new(self, Density::Front, &self.phi, at),
            _ => Rows::new(self, Density::N(family), &self.phi, at),
        };
        let abs_phi = rows.invert_between(0.0, rows.total(), u[2]).clamp(0.0, PI);
        let phi = if negative { -abs_phi } else { abs_phi };
        let angles = Angles::new(theta_i, theta_r, phi).ok()?;
        Some(SampledDirection {
            angles,
            family: LobeFamily::ALL[family],
        })
    }
}

/// The LUT at the preset's own colour: [`BakedBcsdf::at`] its [`BakedBcsdf::absorption`].
impl<M: Math> Bcsdf for BakedBcsdf<'_, M> {
    type Math = M;

    #[inline]
    fn eval(&self, angles: &Angles) -> Families {
        self.eval_far(angles)
    }

    /// [`BakedBcsdf::angles_from_dirs`]: the polynomial direction conversion (within about
    /// 3e-7 rad of [`Angles::from_directions`]), which the WGSL evaluator shares.
    #[inline]
    fn angles_from_dirs(&self, wi: Vec3, wr: Vec3, tangent: Vec3) -> Result<Angles, AngleError> {
        BakedBcsdf::angles_from_dirs(self, wi, wr, tangent)
    }

    /// [`BakedBcsdf::eval_far_dirs`]: the same angles as [`BakedBcsdf::angles_from_dirs`],
    /// on the AVX2 + F16C kernel where the CPU has it.
    #[inline]
    fn eval_dirs(&self, wi: Vec3, wr: Vec3, tangent: Vec3) -> Families {
        self.eval_far_dirs(wi, wr, tangent)
    }

    /// [`BakedView::pdf`] at a view made for this call; [`BakedBcsdf::view`] keeps it for
    /// several calls at one θ_r.
    fn pdf(&self, angles: &Angles) -> f32 {
        self.view(angles.theta_r())
            .map_or(0.0, |v| v.pdf_at(angles))
    }

    fn eval_with_pdf(&self, angles: &Angles) -> (Families, f32) {
        self.view(angles.theta_r())
            .map_or((Families::ZERO, 0.0), |v| v.eval_with_pdf_at(angles))
    }

    fn sample_direction(&self, theta_r: f32, u: [f32; 3]) -> Option<SampledDirection> {
        self.view(theta_r)?.sample_direction(u)
    }

    /// [`BakedView::sample`]: the mixture weights of the draw serve the density too.
    fn sample(&self, theta_r: f32, u: [f32; 3]) -> Option<Sample> {
        self.view(theta_r)?.sample(u)
    }

    /// One [`BakedView`] for the light's direction and the sample.
    fn eval_and_sample_dirs(
        &self,
        wl: Vec3,
        wr: Vec3,
        tangent: Vec3,
        u: [f32; 3],
    ) -> (Option<Evaluated>, Option<Sample>) {
        self.eval_and_sample_dirs_with(self.default_colour(), wl, wr, tangent, u)
    }
}

#[cfg(test)]
mod tests {
    extern crate std;

    use super::*;
    use crate::baked::tests::random as blob;

    /// ∫ of the rows' interpolant times `weight` (a function of the axis position) from the
    /// first node to x, segment by segment by Simpson's rule (exact for the product of two
    /// linear functions), written independently of `Rows`.
    fn integral(rows: &Rows<'_>, x: f32, weight: impl Fn(f64) -> f64) -> f64 {
        let u = f64::from((x - rows.origin) / rows.step);
        let h = f64::from(rows.step);
        let mut acc = 0.0f64;
        for j in 0..rows.nodes - 1 {
            let (v0, v1) = (f64::from(rows.value(j)), f64::from(rows.value(j + 1)));
            let len = (u - j as f64).clamp(0.0, 1.0);
            if len <= 0.0 {
                break;
            }
            let at = |t: f64| {
                let pos = f64::from(rows.origin) + (j as f64 + t) * h;
                (v0 + (v1 - v0) * t) * weight(pos)
            };
            acc += len * h / 6.0 * (at(0.0) + 4.0 * at(0.5 * len) + at(len));
        }
        acc
    }

    /// Target masses per row: under Miri (CI's unsafe-code check, ~10⁴ times slower) a
    /// tenth, the same rows and both ends.
    const TARGETS: usize = if cfg!(miri) { 4 } else { 40 };

    /// Checks one row's total and `r.invert` at [`TARGETS`] + 1 target masses against
    /// [`integral`]; returns 1 (the caller counts rows).
    fn check_inversion(r: &Rows<'_>, what: &str, weight: impl Fn(f64) -> f64 + Copy) -> usize {
        let total = r.total();
        let end = r.origin + r.step * (r.nodes - 1) as f32;
        let exact = integral(r, end, weight);
        assert!(
            (f64::from(total) - exact).abs() <= 1e-5 * exact + 1e-12,
            "{what}: total {total} vs {exact}"
        );
        for k in 0..=TARGETS {
            let t = total * k as f32 / TARGETS as f32;
            let x = r.invert(t);
            let got = integral(r, x, weight);
            assert!(
                (got - f64::from(t)).abs() <= 2e-5 * exact + 1e-12,
                "{what}: ∫ to {x} = {got}, wanted {t}"
            );
        }
        1
    }

    #[test]
    fn row_inversion_hits_the_target_mass() {
        let b = blob();
        let lut = BakedBcsdf::from_bytes(b).unwrap();
        let mut checked = 0;
        let n_theta_r = lut.header.res.n_theta_r as usize;
        let front = |phi: f64| phi / core::f64::consts::PI;
        for d in Density::ALL {
            let (axis, rows) = match d {
                Density::M(_) => (&lut.sum, 1),
                Density::N(_) | Density::Front => (&lut.phi, n_theta_r),
                Density::MS(_) => (&lut.ms_i, lut.header.res.n_ms_r as usize),
            };
            for row in 0..rows {
                for w in [0.0f32, 0.3, 0.77] {
                    let r = Rows::new(&lut, d, axis, (row, w));
                    let what = std::format!("{d:?} row {row} w {w}");
                    checked += if d == Density::Front {
                        check_inversion(&r, &what, front)
                    } else {
                        check_inversion(&r, &what, |_| 1.0)
                    };
                }
            }
        }
        // The back part of the scattered blend: weighted by 1 − |φ|/π.
        for row in 0..n_theta_r {
            for w in [0.0f32, 0.3, 0.77] {
                let r = Rows::back(&lut, &lut.phi, (row, w));
                checked += check_inversion(&r, &std::format!("back row {row} w {w}"), |phi| {
                    1.0 - front(phi)
                });
            }
        }
        assert!(checked >= 25, "{checked} rows");
    }

    #[test]
    fn samples_carry_the_pdf_and_the_weight_of_their_direction() {
        let b = blob();
        let lut = BakedBcsdf::from_bytes(b).unwrap();
        let mut drawn = 0;
        // Under Miri (CI's unsafe-code check) a tenth of the draws: every θ_r still.
        let draws = if cfg!(miri) { 40 } else { 400 };
        for k in 0..draws {
            let theta_r = -1.5 + 3.0 * (k % 20) as f32 / 19.0;
            let u = [
                (k as f32 * 0.618_034) % 1.0,
                (k as f32 * 0.414_214) % 1.0,
                0.37,
            ];
            let Some(s) = lut.sample(theta_r, u) else {
                continue;
            };
            drawn += 1;
            assert_eq!(s.angles.theta_r(), theta_r);
            // The density is the one `pdf` gives for that direction, bit for bit.
            assert_eq!(s.pdf.to_bits(), lut.pdf(&s.angles).to_bits(), "{s:?}");
            assert_eq!(
                lut.sample_direction(theta_r, u).map(|d| d.angles),
                Some(s.angles)
            );
            // weight = S·cos θ_i / pdf.
            let value = lut.eval(&s.angles).total();
            let k = libm::cosf(s.angles.theta_i()) / s.pdf;
            for (w, v) in s.weight.0.iter().zip(value.0) {
                assert!((w - v * k).abs() <= 1e-5 * (v * k).max(1e-6), "{s:?}");
            }
        }
        assert!(drawn > draws * 3 / 4, "{drawn} of {draws}");
        // Invalid θ_r: nothing drawn.
        assert!(lut.sample(f32::NAN, [0.5; 3]).is_none());
        assert!(lut.sample(1.6, [0.5; 3]).is_none());
    }
}
