//! The error metrics between a baked and an analytic far field — the one definition that
//! `bake`, `viewer compare` and the tests share.
//!
//! Both evaluators are sampled on a deterministic stratified set of directions: θ_r on
//! `n_theta_r` strata of [−85°, 85°] (one jittered value per stratum), and for each θ_r a
//! jittered sample in every cell of an `n_theta_i` × `n_phi` grid over θ_i ∈ [−85°, 85°],
//! φ ∈ (−180°, 180°]. All cells have the same (θ_i, φ) area, so with the weight cos²θ_i
//! (one cos θ_i for the projected solid angle, one for dω_i = cos θ_i dθ_i dφ) the sums below
//! are stratified estimates of the integrals. Per RGB channel:
//!
//! - E1 = Σ|S_b − S_a|·cos²θ_i / Σ S_a·cos²θ_i (energy-weighted relative L1);
//! - E_albedo = max over θ_r of |ρ_b − ρ_a| / ρ_a, with ρ(θ_r) = ∫ S cos θ_i dω_i the
//!   directional albedo of docs/model.md §8, integrated over |θ_i| ≤ 85°;
//! - E_peak = max |S_b − S_a|·cos²θ_i / max S_a·cos²θ_i.
//!
//! Rows are evaluated in parallel and merged in row order, so the result has the same bits
//! for any thread count.

use bcsdf_core::rng::Pcg32;
use bcsdf_core::{Absorption, Angles, Bcsdf, Rgb};
use rayon::prelude::*;
use std::fmt;

/// The stratified sample set of the metrics.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MetricSet {
    /// θ_r strata (one albedo value each).
    pub n_theta_r: usize,
    /// θ_i strata per θ_r.
    pub n_theta_i: usize,
    /// φ strata per θ_r.
    pub n_phi: usize,
    /// Largest |θ_i|, |θ_r| in degrees.
    pub max_theta_deg: f32,
    /// Seed of the jitter.
    pub seed: u64,
}

impl MetricSet {
    /// The set the budgets apply to: 36 × 72 × 72 = 186 624 directions over ±85°.
    pub const DEFAULT: MetricSet = MetricSet {
        n_theta_r: 36,
        n_theta_i: 72,
        n_phi: 72,
        max_theta_deg: 85.0,
        seed: 0x5eed,
    };

    /// Number of directions.
    pub fn len(&self) -> usize {
        self.n_theta_r * self.n_theta_i * self.n_phi
    }

    /// True when the set has no directions.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// θ_r of stratum `j`, radians.
    pub fn theta_r(&self, j: usize) -> f32 {
        self.stratum(j, self.n_theta_r, 0, 0, 0)
    }

    /// The direction of cell (`i`, `k`) of θ_r stratum `j`.
    pub fn point(&self, j: usize, i: usize, k: usize) -> Angles {
        let theta_i = self.stratum(i, self.n_theta_i, j + 1, k + 1, 1);
        let u = jitter(self.seed, [j as u64, i as u64, k as u64, 2]);
        let phi =
            -std::f32::consts::PI + std::f32::consts::TAU * ((k as f32 + u) / self.n_phi as f32);
        // Every value is in range by construction.
        Angles::new(theta_i, self.theta_r(j), phi)
            .unwrap_or_else(|_| Angles::new(0.0, 0.0, 0.0).expect("zero angles are valid"))
    }

    fn stratum(&self, s: usize, n: usize, a: usize, b: usize, axis: u64) -> f32 {
        let max = self.max_theta_deg.to_radians();
        let u = jitter(self.seed, [s as u64, a as u64, b as u64, axis]);
        -max + 2.0 * max * ((s as f32 + u) / n as f32)
    }
}

/// A deterministic uniform number in [0, 1) from a seed and four indices (SplitMix64).
fn jitter(seed: u64, idx: [u64; 4]) -> f32 {
    let mut h = seed;
    for v in idx {
        h = splitmix64(h ^ v.wrapping_mul(0x9e37_79b9_7f4a_7c15));
    }
    (h >> 40) as f32 / (1u64 << 24) as f32
}

fn splitmix64(mut z: u64) -> u64 {
    z = z.wrapping_add(0x9e37_79b9_7f4a_7c15);
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

/// The three metrics per RGB channel.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ErrorSummary {
    /// E1, energy-weighted relative L1.
    pub e1: [f64; 3],
    /// E_albedo, worst relative directional-albedo error over θ_r.
    pub e_albedo: [f64; 3],
    /// E_peak, worst weighted difference relative to the weighted peak.
    pub e_peak: [f64; 3],
}

/// Names of the metrics, in [`ErrorSummary::worst`] order.
pub const METRIC_NAMES: [&str; 3] = ["E1", "E_albedo", "E_peak"];

impl ErrorSummary {
    /// Each metric's worst channel: [E1, E_albedo, E_peak].
    pub fn worst(&self) -> [f64; 3] {
        let m = |v: [f64; 3]| v[0].max(v[1]).max(v[2]);
        [m(self.e1), m(self.e_albedo), m(self.e_peak)]
    }

    /// The metrics as rows `[name, R, G, B]`.
    pub fn rows(&self) -> [(&'static str, [f64; 3]); 3] {
        [
            (METRIC_NAMES[0], self.e1),
            (METRIC_NAMES[1], self.e_albedo),
            (METRIC_NAMES[2], self.e_peak),
        ]
    }
}

/// Largest acceptable value of each metric (fractions, not percent).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ErrorBudget {
    /// E1 bound.
    pub e1: f64,
    /// E_albedo bound.
    pub e_albedo: f64,
    /// E_peak bound.
    pub e_peak: f64,
}

/// A metric above its budget.
#[derive(Clone, Debug, PartialEq)]
pub struct Exceeded {
    /// Metric name (`E1`, `E_albedo`, `E_peak`).
    pub metric: &'static str,
    /// Channel name (`R`, `G`, `B`).
    pub channel: &'static str,
    /// Measured value.
    pub value: f64,
    /// Budget.
    pub budget: f64,
    /// The colour it was measured at, when not the preset's own ([`colour_set`] labels).
    pub colour: Option<String>,
}

impl fmt::Display for Exceeded {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} ({}) = {:.3}% exceeds the budget of {:.3}%",
            self.metric,
            self.channel,
            100.0 * self.value,
            100.0 * self.budget
        )?;
        match &self.colour {
            Some(c) => write!(f, " at colour {c}"),
            None => Ok(()),
        }
    }
}

impl ErrorBudget {
    /// The budget of the bake issue: E1 ≤ 1 %, E_albedo ≤ 0.5 %, E_peak ≤ 2 %.
    pub const DEFAULT: ErrorBudget = ErrorBudget {
        e1: 0.01,
        e_albedo: 0.005,
        e_peak: 0.02,
    };

    /// Parses `E1,E_albedo,E_peak` as three fractions (`0.01,0.005,0.02`) or percentages
    /// (`1%,0.5%,2%`).
    pub fn parse(text: &str) -> Result<ErrorBudget, String> {
        let parts: Vec<&str> = text.split(',').map(str::trim).collect();
        if parts.len() != 3 {
            return Err(format!(
                "budget '{text}' must be three values E1,E_albedo,E_peak (e.g. 0.01,0.005,0.02 or 1%,0.5%,2%)"
            ));
        }
        let mut v = [0.0; 3];
        for (slot, (part, name)) in v.iter_mut().zip(parts.iter().zip(METRIC_NAMES)) {
            let (num, scale) = match part.strip_suffix('%') {
                Some(p) => (p, 0.01),
                None => (*part, 1.0),
            };
            let x: f64 = num
                .trim()
                .parse()
                .map_err(|_| format!("budget for {name} '{part}' is not a number"))?;
            if !(x.is_finite() && x >= 0.0) {
                return Err(format!(
                    "budget for {name} '{part}' must be finite and non-negative"
                ));
            }
            *slot = x * scale;
        }
        Ok(ErrorBudget {
            e1: v[0],
            e_albedo: v[1],
            e_peak: v[2],
        })
    }

    /// Every (metric, channel) of `summary` above this budget.
    pub fn check(&self, summary: &ErrorSummary) -> Vec<Exceeded> {
        let bounds = [self.e1, self.e_albedo, self.e_peak];
        let mut out = Vec::new();
        for ((metric, values), budget) in summary.rows().into_iter().zip(bounds) {
            for (c, channel) in ["R", "G", "B"].into_iter().enumerate() {
                // NaN counts as exceeded.
                if values[c].is_nan() || values[c] > budget {
                    out.push(Exceeded {
                        colour: None,
                        metric,
                        channel,
                        value: values[c],
                        budget,
                    });
                }
            }
        }
        out
    }
}

/// Sums of one θ_r row.
#[derive(Clone, Copy, Debug, Default)]
struct Row {
    abs_diff: [f64; 3],
    reference: [f64; 3],
    baked: [f64; 3],
    max_diff: [f64; 3],
    max_reference: [f64; 3],
}

fn eval_row<A: Bcsdf, B: Bcsdf>(reference: &A, baked: &B, set: &MetricSet, j: usize) -> Row {
    let mut row = Row::default();
    for i in 0..set.n_theta_i {
        for k in 0..set.n_phi {
            let angles = set.point(j, i, k);
            let w = f64::from(angles.theta_i().cos()).powi(2);
            let a: Rgb = reference.eval(&angles).total();
            let b: Rgb = baked.eval(&angles).total();
            for c in 0..3 {
                let (sa, sb) = (f64::from(a.0[c]) * w, f64::from(b.0[c]) * w);
                let d = (sb - sa).abs();
                row.abs_diff[c] += d;
                row.reference[c] += sa;
                row.baked[c] += sb;
                row.max_diff[c] = row.max_diff[c].max(d);
                row.max_reference[c] = row.max_reference[c].max(sa);
            }
        }
    }
    row
}

/// Compares `baked` against `reference` on `set` (rows in parallel on the current rayon
/// pool; the result does not depend on the thread count).
pub fn compare<A, B>(reference: &A, baked: &B, set: &MetricSet) -> ErrorSummary
where
    A: Bcsdf + Sync,
    B: Bcsdf + Sync,
{
    let rows: Vec<Row> = (0..set.n_theta_r)
        .into_par_iter()
        .map(|j| eval_row(reference, baked, set, j))
        .collect();
    summarise(&rows)
}

fn summarise(rows: &[Row]) -> ErrorSummary {
    let mut out = ErrorSummary::default();
    for c in 0..3 {
        let (mut diff, mut total, mut peak_diff, mut peak) = (0.0, 0.0, 0.0f64, 0.0f64);
        let mut albedo = 0.0f64;
        for r in rows {
            diff += r.abs_diff[c];
            total += r.reference[c];
            peak_diff = peak_diff.max(r.max_diff[c]);
            peak = peak.max(r.max_reference[c]);
            let rel = if r.reference[c] > 0.0 {
                (r.baked[c] - r.reference[c]).abs() / r.reference[c]
            } else if r.baked[c] > 0.0 {
                f64::INFINITY
            } else {
                0.0
            };
            albedo = albedo.max(rel);
        }
        out.e1[c] = ratio(diff, total);
        out.e_albedo[c] = albedo;
        out.e_peak[c] = ratio(peak_diff, peak);
    }
    out
}

/// a/b, with 0/0 = 0 (both evaluators zero) and x/0 = ∞.
fn ratio(a: f64, b: f64) -> f64 {
    if b > 0.0 {
        a / b
    } else if a > 0.0 {
        f64::INFINITY
    } else {
        0.0
    }
}

/// `n` random colours (at most 16; labels `random k`): each channel log-uniform over
/// [0.01, 1000], a lossless channel in every fourth colour and a channel ≥ 100 in the next;
/// fixed seed, so every run measures the same colours ([`colour_set`]).
pub fn random_colours(n: usize) -> Vec<(String, Absorption)> {
    let mut rng = Pcg32::new(2026, 12);
    (0..n.min(16))
        .map(|k| {
            let mut s = [0.0f32; 3];
            for c in &mut s {
                *c = 10f32.powf(-2.0 + 5.0 * rng.uniform());
            }
            if k % 4 == 0 {
                s[k / 4 % 3] = 0.0;
            }
            if k % 4 == 1 {
                s[(k / 4 + 1) % 3] = 100.0 + 900.0 * rng.uniform();
            }
            (
                format!("random {k}"),
                Absorption::from_sigma(Rgb(s)).unwrap_or(Absorption::LOSSLESS),
            )
        })
        .collect()
}

/// The colours a LUT is measured at (docs/lut.md "The absorption axis"): for a preset whose
/// own σ_ca is `own`, that colour, the 16 [`random_colours`] and eight melanin mixes
/// (eumelanin 0–8, pheomelanin 0–2), with labels.
pub fn colour_set(own: Rgb) -> Vec<(String, Absorption)> {
    let mut out = vec![(
        "own".to_string(),
        Absorption::from_sigma(own).unwrap_or(Absorption::LOSSLESS),
    )];
    out.extend(random_colours(16));
    for (eu, pheo) in [
        (0.0, 0.0),
        (0.2, 0.0),
        (0.5, 1.0),
        (1.0, 0.3),
        (2.0, 2.0),
        (4.0, 0.5),
        (8.0, 0.0),
        (8.0, 2.0),
    ] {
        out.push((
            format!("melanin {eu}/{pheo}"),
            Absorption::from_melanin(eu, pheo).unwrap_or(Absorption::LOSSLESS),
        ));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use bcsdf_core::{Families, LobeFamily};

    struct Constant(f32);
    impl Bcsdf for Constant {
        type Math = bcsdf_core::Libm;
        fn eval(&self, _: &Angles) -> Families {
            let mut v = [Rgb::ZERO; 4];
            v[LobeFamily::R as usize] = Rgb::splat(self.0);
            Families::from_array(v)
        }
        fn pdf(&self, _: &Angles) -> f32 {
            0.0
        }
        fn sample_direction(&self, _: f32, _: [f32; 3]) -> Option<bcsdf_core::SampledDirection> {
            None
        }
    }

    const SMALL: MetricSet = MetricSet {
        n_theta_r: 4,
        n_theta_i: 6,
        n_phi: 5,
        max_theta_deg: 85.0,
        seed: 1,
    };

    #[test]
    fn a_uniform_relative_error_shows_in_every_metric() {
        let s = compare(&Constant(2.0), &Constant(2.02), &SMALL);
        for m in [s.e1, s.e_albedo, s.e_peak] {
            for c in m {
                assert!((c - 0.01).abs() < 1e-6, "{s:?}");
            }
        }
        assert_eq!(
            compare(&Constant(2.0), &Constant(2.0), &SMALL).worst(),
            [0.0; 3]
        );
    }

    #[test]
    fn points_stay_inside_the_strata() {
        let max = 85f32.to_radians();
        for j in 0..SMALL.n_theta_r {
            for i in 0..SMALL.n_theta_i {
                for k in 0..SMALL.n_phi {
                    let a = SMALL.point(j, i, k);
                    let lo = -max + 2.0 * max * i as f32 / SMALL.n_theta_i as f32;
                    let hi = -max + 2.0 * max * (i + 1) as f32 / SMALL.n_theta_i as f32;
                    assert!(a.theta_i() >= lo - 1e-6 && a.theta_i() <= hi + 1e-6);
                    assert_eq!(a.theta_r(), SMALL.theta_r(j));
                }
            }
        }
    }

    #[test]
    fn budget_parses_fractions_and_percentages_and_flags_excess() {
        assert_eq!(
            ErrorBudget::parse("1%,0.5%,2%").unwrap(),
            ErrorBudget::DEFAULT
        );
        assert_eq!(
            ErrorBudget::parse("0.01, 0.005, 0.02").unwrap(),
            ErrorBudget::DEFAULT
        );
        assert!(ErrorBudget::parse("0.01,0.005").is_err());
        assert!(ErrorBudget::parse("a,b,c").is_err());
        assert!(ErrorBudget::parse("-1,0,0").is_err());
        let s = ErrorSummary {
            e1: [0.0, 0.02, 0.0],
            e_albedo: [0.0; 3],
            e_peak: [f64::NAN, 0.0, 0.0],
        };
        let ex = ErrorBudget::DEFAULT.check(&s);
        assert_eq!(ex.len(), 2);
        assert_eq!((ex[0].metric, ex[0].channel), ("E1", "G"));
        assert_eq!((ex[1].metric, ex[1].channel), ("E_peak", "R"));
    }
}
