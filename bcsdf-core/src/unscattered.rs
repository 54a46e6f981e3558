//! The eight unscattered paths: exit azimuths Φ_p(h) and attenuations A_p(h) (docs/model.md §3).

use crate::fresnel;
use crate::geometry::{Chord, MedullaEvent, ViewSlice};
use crate::lobes::UNSCATTERED_COUNT;
use crate::math::{Math, PI};
use crate::spectrum::Rgb;

/// Exit azimuth Φ_p and attenuation A_p of one path at one chord (A_p = 0 where the path
/// does not exist).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PathSample {
    /// Φ_p(h), not wrapped (the azimuthal distribution wraps it).
    pub exit_azimuth: f32,
    /// A_p(h), RGB.
    pub attenuation: Rgb,
}

/// Absorption and scattering coefficients along the chord, already divided by the refracted
/// longitudinal cosines (2D length → 3D length).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Extinction {
    /// σ_ca / cos θ_tc.
    pub cortex: Rgb,
    /// (σ_ms + σ_ma) / cos θ_tm: unscattered light leaves the medulla at full extinction.
    pub medulla: f32,
    /// σ_ms / cos θ_tm: the chance of scattering on a medulla chord (docs/model.md §6, P).
    pub medulla_scattering: f32,
}

impl Extinction {
    /// The coefficients for `params` at the view slice `slice`.
    #[must_use]
    pub fn new(params: &crate::params::FurParams, slice: &ViewSlice) -> Extinction {
        Extinction {
            cortex: params.sigma_ca() * slice.inv_cos_tc,
            medulla: (params.sigma_ms() + params.sigma_ma()) * slice.inv_cos_tm,
            medulla_scattering: params.sigma_ms() * slice.inv_cos_tm,
        }
    }
}

/// Transmittance exp(−σ·L) per channel (one exponential when the channels are equal).
#[inline]
pub(crate) fn transmittance<M: Math>(sigma: Rgb, length: f32) -> Rgb {
    let [r, g, b] = sigma.0;
    if r == g && g == b {
        Rgb::splat(M::exp_neg(r * length))
    } else {
        sigma.map(|s| M::exp_neg(s * length))
    }
}

/// Exit azimuths Φ_p(h) of all eight paths at `chord` (docs/model.md §3 table), in
/// [`crate::Lobe::UNSCATTERED`] order; 0 for a path that does not exist at this chord.
///
/// Each follows the event rule Φ = π + Σ events with outer refraction (c − a), internal
/// reflection at the cuticle (π + 2c), medulla refraction (μ − m), reflection off the medulla
/// from the cortex (π − 2m) and reflection inside the medulla (π + 2μ); R is Φ_R = −2a.
#[inline]
#[must_use]
pub fn exit_azimuths(chord: &Chord) -> [f32; UNSCATTERED_COUNT] {
    let (a, c) = (chord.a, chord.c);
    let mut phi = [0.0; UNSCATTERED_COUNT];
    phi[0] = -2.0 * a;
    match chord.medulla {
        MedullaEvent::Miss => {
            phi[1] = 2.0 * c - 2.0 * a + PI;
            phi[2] = 4.0 * c - 2.0 * a;
        }
        MedullaEvent::TotalReflection { m, .. } => {
            phi[3] = 2.0 * c - 2.0 * a - 2.0 * m;
            phi[6] = 4.0 * c - 2.0 * a - 4.0 * m;
        }
        MedullaEvent::Enter { m, mu, .. } => {
            phi[3] = 2.0 * c - 2.0 * a - 2.0 * m;
            phi[4] = 2.0 * c - 2.0 * a - 2.0 * m + 2.0 * mu + PI;
            phi[5] = 2.0 * c - 2.0 * a - 2.0 * m + 4.0 * mu;
            phi[6] = 4.0 * c - 2.0 * a - 4.0 * m;
            phi[7] = 4.0 * c - 2.0 * a - 4.0 * m + 4.0 * mu;
        }
    }
    phi
}

/// Attenuations A_p(h) of all eight paths at `chord` (report eq. 5): the Fresnel product of
/// the docs/model.md §3 table times exp(−σ_ca·L_c/cos θ_tc)·exp(−(σ_ms+σ_ma)·L_m/cos θ_tm), in
/// [`crate::Lobe::UNSCATTERED`] order; zero for a path that does not exist. `l` is the number of
/// cuticle layers.
#[inline]
#[must_use]
pub fn attenuations<M: Math>(
    slice: &ViewSlice,
    chord: &Chord,
    ext: &Extinction,
    l: f32,
) -> [Rgb; UNSCATTERED_COUNT] {
    let mut out = [Rgb::ZERO; UNSCATTERED_COUNT];
    let f = fresnel::cuticle::<M>(chord.cos_a, slice.eta_c_prime, l);
    let t = 1.0 - f;
    let base = t * t;
    out[0] = Rgb::splat(f);
    match chord.medulla {
        MedullaEvent::Miss => {
            // TT: one cortex chord of length 2 cos c; TRT: two of them.
            let t1 = transmittance::<M>(ext.cortex, 2.0 * chord.cos_c);
            out[1] = t1 * base;
            out[2] = t1 * t1 * (base * f);
        }
        MedullaEvent::TotalReflection { cos_m, .. } => {
            // f_m = 1 under total internal reflection.
            let tc = transmittance::<M>(ext.cortex, 2.0 * cortex_leg(slice, chord, cos_m));
            out[3] = tc * base;
            out[6] = tc * tc * (base * f);
        }
        MedullaEvent::Enter { cos_m, cos_mu, .. } => {
            let eta_rel = slice.eta_m_prime / slice.eta_c_prime;
            let fm = fresnel::medulla::<M>(cos_m, eta_rel);
            let tm = 1.0 - fm;
            let tc = transmittance::<M>(ext.cortex, 2.0 * cortex_leg(slice, chord, cos_m));
            // One medulla chord ℓ_m = 2κ cos μ at full extinction.
            let um = M::exp_neg(ext.medulla * 2.0 * slice.kappa * cos_mu);
            let tm2 = tm * tm;
            out[3] = tc * (base * fm);
            out[4] = tc * (base * tm2 * um);
            out[5] = tc * (base * tm2 * fm * um * um);
            out[6] = tc * tc * (base * f * fm * fm);
            out[7] = tc * tc * (base * f * tm2 * tm2 * um * um);
        }
    }
    out
}

/// ℓ_c = cos c − κ cos m: the cortex leg between the outer circle and the medulla.
#[inline]
pub(crate) fn cortex_leg(slice: &ViewSlice, chord: &Chord, cos_m: f32) -> f32 {
    (chord.cos_c - slice.kappa * cos_m).max(0.0)
}

/// Φ_p and A_p of all eight paths at `chord`, in [`crate::Lobe::UNSCATTERED`] order.
#[inline]
#[must_use]
pub fn paths_at<M: Math>(
    slice: &ViewSlice,
    chord: &Chord,
    ext: &Extinction,
    l: f32,
) -> [PathSample; UNSCATTERED_COUNT] {
    let phi = exit_azimuths(chord);
    let att = attenuations::<M>(slice, chord, ext, l);
    let mut out = [PathSample::default(); UNSCATTERED_COUNT];
    for i in 0..UNSCATTERED_COUNT {
        out[i] = PathSample {
            exit_azimuth: phi[i],
            attenuation: att[i],
        };
    }
    out
}
