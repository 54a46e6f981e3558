//! The 2D cross-section seen by the view ray (docs/model.md §1, §3).
//!
//! [`ViewSlice`] holds what depends only on θ_r (Bravais indices, refracted longitudinal
//! cosines); [`Chord`] is one ray through the cross-section at offset h, with every angle the
//! exit-azimuth rule needs.

use crate::math::{asin_clamped, sqrt_pos, Math};
use crate::params::FurParams;

/// Per-θ_r quantities of the cross-section problem.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ViewSlice {
    /// η'_c = √(η_c² − sin²θ_r)/cos θ_r (Bravais index of the cortex).
    pub eta_c_prime: f32,
    /// η'_m, Bravais index of the medulla.
    pub eta_m_prime: f32,
    /// 1/cos θ_tc with sin θ_tc = sin θ_r/η_c: 2D lengths → 3D lengths in the cortex.
    pub inv_cos_tc: f32,
    /// 1/cos θ_tm with sin θ_tm = sin θ_r/η_m: 2D lengths → 3D lengths in the medulla.
    pub inv_cos_tm: f32,
    /// κ, medulla radius / fiber radius.
    pub kappa: f32,
}

/// Bravais' effective index for the normal-plane projection: √(η² − sin²θ)/cos θ.
#[inline]
#[must_use]
pub fn bravais_index<M: Math>(eta: f32, sin_theta: f32, cos_theta: f32) -> f32 {
    let cos = cos_theta.abs().max(1e-6);
    (M::sqrt((eta * eta - sin_theta * sin_theta).max(0.0)) / cos).max(1.0)
}

impl ViewSlice {
    /// The slice for a view direction at longitudinal angle `theta_r`.
    #[must_use]
    pub fn new<M: Math>(params: &FurParams, theta_r: f32) -> ViewSlice {
        let (s, c) = M::sin_cos(theta_r);
        let s = s.clamp(-1.0, 1.0);
        let inv_cos_t = |eta: f32| {
            let sin_t = s / eta;
            1.0 / sqrt_pos::<M>(1.0 - sin_t * sin_t)
        };
        ViewSlice {
            eta_c_prime: bravais_index::<M>(params.eta_c(), s, c),
            eta_m_prime: bravais_index::<M>(params.eta_m(), s, c),
            inv_cos_tc: inv_cos_t(params.eta_c()),
            inv_cos_tm: inv_cos_t(params.eta_m()),
            kappa: params.kappa(),
        }
    }

    /// |h| above which the cortex ray misses the medulla: κ·η'_c.
    #[must_use]
    pub fn h_medulla(&self) -> f32 {
        self.kappa * self.eta_c_prime
    }

    /// |h| above which the medulla reflects totally: κ·η'_m.
    #[must_use]
    pub fn h_tir(&self) -> f32 {
        self.kappa * self.eta_m_prime
    }
}

/// What the cortex ray does at the medulla.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum MedullaEvent {
    /// |b| ≥ κ: the ray misses the medulla.
    Miss,
    /// Hits at incidence `m` but is totally reflected (|h/(κη'_m)| ≥ 1).
    TotalReflection {
        /// m = asin(b/κ).
        m: f32,
        /// cos m.
        cos_m: f32,
    },
    /// Hits at incidence `m` and refracts to `μ` inside the medulla.
    Enter {
        /// m = asin(b/κ).
        m: f32,
        /// cos m.
        cos_m: f32,
        /// μ = asin(h/(κη'_m)).
        mu: f32,
        /// cos μ.
        cos_mu: f32,
    },
}

/// Which angle parameterises a far-field h-segment: h = K·sin t with t = a, m or μ.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ChordVariable {
    /// t = a, K = 1.
    A,
    /// t = m, K = κη'_c.
    M,
    /// t = μ, K = κη'_m.
    Mu,
}

/// Which of the three regions of h a chord lies in; far-field segments know theirs, so the
/// classification of a node never depends on rounding at a segment end.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Region {
    /// |h| ≥ κη'_c: misses the medulla.
    Miss,
    /// Enters the medulla.
    Enter,
    /// Hits the medulla and is totally reflected.
    TotalReflection,
}

/// One ray of the cross-section at offset h (docs/model.md §3).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Chord {
    /// Offset h ∈ [−1, 1].
    pub h: f32,
    /// a = asin h, incidence at the cuticle.
    pub a: f32,
    /// cos a.
    pub cos_a: f32,
    /// c = asin(h/η'_c), refracted angle in the cortex.
    pub c: f32,
    /// cos c.
    pub cos_c: f32,
    /// The event at the medulla.
    pub medulla: MedullaEvent,
}

impl Chord {
    /// cos t of the segment variable t this chord was built from (see [`ChordVariable`]);
    /// 0 when that angle is not defined at this chord.
    #[inline]
    #[must_use]
    pub fn variable_cos(&self, var: ChordVariable) -> f32 {
        match (var, self.medulla) {
            (ChordVariable::A, _) => self.cos_a,
            (ChordVariable::M, MedullaEvent::Enter { cos_m, .. })
            | (ChordVariable::M, MedullaEvent::TotalReflection { cos_m, .. }) => cos_m,
            (ChordVariable::Mu, MedullaEvent::Enter { cos_mu, .. }) => cos_mu,
            _ => 0.0,
        }
    }

    /// The chord at offset `h` (clamped to [−1, 1]).
    #[must_use]
    pub fn at_offset<M: Math>(slice: &ViewSlice, h: f32) -> Chord {
        let h = h.clamp(-1.0, 1.0);
        Chord::build::<M>(slice, h, None, None)
    }

    /// The chord at h = K·sin t for the segment variable `var`, known to lie in `region`; the
    /// variable's own angle and cosine are taken from `t` directly, which keeps them exact
    /// where asin is singular.
    #[must_use]
    pub fn at_variable<M: Math>(
        slice: &ViewSlice,
        var: ChordVariable,
        t: f32,
        region: Region,
    ) -> Chord {
        let (s, c) = M::sin_cos(t);
        let c = c.max(0.0);
        let k = match var {
            ChordVariable::A => 1.0,
            ChordVariable::M => slice.h_medulla(),
            ChordVariable::Mu => slice.h_tir(),
        };
        let h = (k * s).clamp(-1.0, 1.0);
        Chord::build::<M>(slice, h, Some((var, t, c)), Some(region))
    }

    fn build<M: Math>(
        slice: &ViewSlice,
        h: f32,
        exact: Option<(ChordVariable, f32, f32)>,
        region: Option<Region>,
    ) -> Chord {
        let pick = |v: ChordVariable, sin: f32| match exact {
            Some((var, t, cos_t)) if var == v => (t, cos_t),
            // (1 − s)(1 + s) keeps cos accurate where s → 1 (grazing rays).
            _ => (
                asin_clamped::<M>(sin),
                sqrt_pos::<M>((1.0 - sin) * (1.0 + sin)),
            ),
        };
        let (a, cos_a) = pick(ChordVariable::A, h);
        let sin_c = (h / slice.eta_c_prime).clamp(-1.0, 1.0);
        let c = asin_clamped::<M>(sin_c);
        let cos_c = sqrt_pos::<M>((1.0 - sin_c) * (1.0 + sin_c));
        let kappa = slice.kappa;
        // sin μ = h/(κη'_m), written as sin m · η'_c/η'_m so that μ = m to the bit when the
        // medulla is index-matched.
        let sin_m = sin_c / kappa;
        let sin_mu = sin_m * (slice.eta_c_prime / slice.eta_m_prime);
        let region = region.unwrap_or(if !(kappa > 0.0 && sin_c.abs() < kappa) {
            Region::Miss
        } else if sin_mu.abs() < 1.0 {
            Region::Enter
        } else {
            Region::TotalReflection
        });
        let medulla = if region != Region::Miss {
            let (m, cos_m) = pick(ChordVariable::M, sin_m.clamp(-1.0, 1.0));
            if region == Region::Enter {
                // An index-matched medulla does not bend the ray: μ = m.
                let (mu, cos_mu) = if slice.eta_m_prime == slice.eta_c_prime {
                    match exact {
                        Some((ChordVariable::Mu, t, cos_t)) => (t, cos_t),
                        _ => (m, cos_m),
                    }
                } else {
                    pick(ChordVariable::Mu, sin_mu.clamp(-1.0, 1.0))
                };
                MedullaEvent::Enter {
                    m,
                    cos_m,
                    mu,
                    cos_mu,
                }
            } else {
                MedullaEvent::TotalReflection { m, cos_m }
            }
        } else {
            MedullaEvent::Miss
        };
        Chord {
            h,
            a,
            cos_a,
            c,
            cos_c,
            medulla,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::Libm;
    use crate::presets;

    fn slice(name: &str, theta_r: f32) -> ViewSlice {
        let params = FurParams::new(&presets::find(name).unwrap().input).unwrap();
        ViewSlice::new::<Libm>(&params, theta_r)
    }

    #[test]
    fn bravais_indices_grow_with_the_view_angle() {
        // In the normal plane (θ_r = 0) the effective index is the index itself.
        assert!((bravais_index::<Libm>(1.55, 0.0, 1.0) - 1.55).abs() < 1e-7);
        let mut prev = 1.55;
        for k in 1..10 {
            let t = 0.15 * k as f32;
            let eta = bravais_index::<Libm>(1.55, libm::sinf(t), libm::cosf(t));
            // η' = √(η² − sin²θ)/cos θ, and η'² − 1 = (η² − 1)/cos²θ.
            let want = libm::sqrtf(1.55 * 1.55 - libm::sinf(t).powi(2)) / libm::cosf(t);
            assert!((eta - want).abs() < 1e-5 * want && eta > prev, "{t}");
            prev = eta;
        }
        // Never below 1 (no total internal reflection appears from rounding).
        assert_eq!(bravais_index::<Libm>(1.0, 0.3, 0.96), 1.0);
    }

    #[test]
    fn slices_hold_the_medulla_thresholds() {
        let s = slice("air-medulla", 0.0);
        assert!((s.eta_c_prime - 1.55).abs() < 1e-6 && (s.eta_m_prime - 1.2).abs() < 1e-6);
        assert_eq!((s.inv_cos_tc, s.inv_cos_tm), (1.0, 1.0));
        assert!((s.h_medulla() - 0.5 * 1.55).abs() < 1e-6);
        assert!((s.h_tir() - 0.5 * 1.2).abs() < 1e-6);
        let tilted = slice("air-medulla", 0.8);
        let want = 1.0 / libm::sqrtf(1.0 - (libm::sinf(0.8) / 1.55).powi(2));
        assert!((tilted.inv_cos_tc - want).abs() < 1e-6);
    }

    #[test]
    fn chords_classify_the_medulla_event() {
        // η_m < η_c: misses above κη'_c, total reflection between κη'_m and κη'_c.
        let s = slice("air-medulla", 0.0);
        let at = |h: f32| Chord::at_offset::<Libm>(&s, h);
        assert!(matches!(at(0.1).medulla, MedullaEvent::Enter { .. }));
        assert!(matches!(
            at(-0.7).medulla,
            MedullaEvent::TotalReflection { .. }
        ));
        assert_eq!(at(0.9).medulla, MedullaEvent::Miss);
        // Snell in the cross-section: sin a = h, sin c = h/η'_c, and at the medulla
        // sin m = sin c/κ, sin μ = (η'_c/η'_m) sin m.
        let c = at(0.2);
        assert!((libm::sinf(c.a) - 0.2).abs() < 1e-6);
        assert!((libm::sinf(c.c) * s.eta_c_prime - 0.2).abs() < 1e-6);
        match c.medulla {
            MedullaEvent::Enter { m, cos_m, mu, .. } => {
                assert!((libm::sinf(m) - libm::sinf(c.c) / 0.5).abs() < 1e-6);
                assert!((libm::sinf(mu) * 1.2 - libm::sinf(m) * 1.55).abs() < 1e-5);
                assert!((cos_m - libm::cosf(m)).abs() < 1e-6);
                assert_eq!(c.variable_cos(ChordVariable::M), cos_m);
            }
            other => panic!("{other:?}"),
        }
        assert_eq!(at(0.9).variable_cos(ChordVariable::Mu), 0.0);
        // Offsets beyond the fiber are clamped to its edge.
        assert_eq!(at(3.0), at(1.0));
        // Built from the segment variable: the same chord, the variable's angle exact.
        let t = 0.3f32;
        let v = Chord::at_variable::<Libm>(&s, ChordVariable::A, t, Region::Enter);
        assert_eq!(v.a, t);
        assert!((v.h - libm::sinf(t)).abs() < 1e-7);
        // Without a medulla every chord misses it.
        let hair = slice("human-hair", 0.4);
        assert_eq!(
            Chord::at_offset::<Libm>(&hair, 0.0).medulla,
            MedullaEvent::Miss
        );
    }
}
