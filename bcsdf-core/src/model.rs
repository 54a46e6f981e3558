//! The analytic double-cylinder BCSDF (MODEL.md §8, report eq. 1), unscattered part:
//! S = Σ_p M_p·N_p / cos²θ_i, near field (at offset h) and far field (h integrated).

use crate::far_field::FarFieldQuery;
use crate::frame::{Angles, Vec3};
use crate::geometry::{Chord, ViewSlice};
use crate::lobes::{Lobe, LobeGroup, Lobes, LOBE_COUNT};
use crate::longitudinal::GroupLobes;
use crate::math::{Libm, Math};
use crate::params::FurParams;
use crate::spectrum::Rgb;
use crate::unscattered::{paths_at, Extinction};
use core::marker::PhantomData;

/// Smallest cos²θ_i the 1/cos²θ_i factor of eq. 1 divides by (θ_i ≈ ±89.4°): keeps S finite
/// for grazing light.
pub const MIN_COS2_THETA_I: f32 = 1e-4;

/// The analytic fur BCSDF for one parameter set, evaluated with the math backend `M`.
///
/// Construction precomputes the per-group lobe constants; evaluation allocates nothing.
#[derive(Clone, Copy, Debug)]
pub struct FurBcsdf<M: Math = Libm> {
    params: FurParams,
    groups: GroupLobes,
    _math: PhantomData<M>,
}

impl<M: Math> FurBcsdf<M> {
    /// The model for validated `params`.
    pub fn new(params: FurParams) -> FurBcsdf<M> {
        FurBcsdf {
            params,
            groups: GroupLobes::new(&params),
            _math: PhantomData,
        }
    }

    /// The parameters this model was built from.
    pub fn params(&self) -> &FurParams {
        &self.params
    }

    fn slice_and_extinction(&self, theta_r: f32) -> (ViewSlice, Extinction) {
        let slice = ViewSlice::new::<M>(&self.params, theta_r);
        let ext = Extinction {
            cortex: self.params.sigma_ca() * slice.inv_cos_tc,
            medulla: (self.params.sigma_ms() + self.params.sigma_ma()) * slice.inv_cos_tm,
        };
        (slice, ext)
    }

    /// Multiplies N_p by M_p and divides by cos²θ_i (report eq. 1).
    fn assemble(&self, angles: &Angles, n: &[Rgb; LOBE_COUNT]) -> Lobes {
        let (ti, tr) = (angles.theta_i(), angles.theta_r());
        let cos_i = M::cos(ti);
        let inv_cos2 = 1.0 / (cos_i * cos_i).max(MIN_COS2_THETA_I);
        let m = [
            self.groups.m::<M>(LobeGroup::R, ti, tr),
            self.groups.m::<M>(LobeGroup::TT, ti, tr),
            self.groups.m::<M>(LobeGroup::TRT, ti, tr),
        ];
        let mut out = [Rgb::ZERO; LOBE_COUNT];
        for lobe in Lobe::ALL {
            let v = n[lobe.index()] * (m[lobe.group() as usize] * inv_cos2);
            // Never hand NaN or a negative value to a renderer.
            out[lobe.index()] = v.map(|c| if c.is_finite() && c > 0.0 { c } else { 0.0 });
        }
        Lobes::from_array(out)
    }

    /// Near-field azimuthal lobes N_p(h, φ) = A_p(h)·D_p(φ − Φ_p(h)) (report eq. 4).
    pub fn azimuthal_near(&self, theta_r: f32, phi: f32, h: f32) -> [Rgb; LOBE_COUNT] {
        let mut n = [Rgb::ZERO; LOBE_COUNT];
        if !(h.is_finite() && (-1.0..=1.0).contains(&h) && theta_r.is_finite()) {
            return n;
        }
        let (slice, ext) = self.slice_and_extinction(theta_r);
        let chord = Chord::at_offset::<M>(&slice, h);
        let paths = paths_at::<M>(&slice, &chord, &ext, self.params.l());
        for lobe in Lobe::ALL {
            let p = paths[lobe.index()];
            // Paths that do not exist at this h (or carry no energy) need no D_p.
            if p.attenuation.max_channel() > 0.0 {
                let d = self.groups.d(lobe.group());
                n[lobe.index()] = p.attenuation * d.eval::<M>(phi - p.exit_azimuth);
            }
        }
        n
    }

    /// Far-field azimuthal lobes N_p(φ) = ½ ∫ N_p(h, φ) dh (MODEL.md §5).
    pub fn azimuthal_far(&self, theta_r: f32, phi: f32) -> [Rgb; LOBE_COUNT] {
        if !(theta_r.is_finite() && phi.is_finite()) {
            return [Rgb::ZERO; LOBE_COUNT];
        }
        let (slice, ext) = self.slice_and_extinction(theta_r);
        FarFieldQuery {
            slice: &slice,
            extinction: &ext,
            layers: self.params.l(),
            groups: &self.groups,
            index_matched: self.params.eta_m() == self.params.eta_c(),
        }
        .azimuthal::<M>(phi)
    }

    /// Near-field S(ω_i, ω_r, h) per lobe. An offset outside [−1, 1] (or NaN) misses the
    /// fiber and gives zero.
    pub fn eval_near(&self, angles: &Angles, h: f32) -> Lobes {
        let n = self.azimuthal_near(angles.theta_r(), angles.phi(), h);
        self.assemble(angles, &n)
    }

    /// Far-field S(ω_i, ω_r) per lobe.
    pub fn eval_far(&self, angles: &Angles) -> Lobes {
        let n = self.azimuthal_far(angles.theta_r(), angles.phi());
        self.assemble(angles, &n)
    }

    /// Near-field S from world-space directions (see [`Angles::from_directions`]); invalid
    /// directions give zero.
    pub fn eval_near_dirs(&self, wi: Vec3, wr: Vec3, tangent: Vec3, h: f32) -> Lobes {
        match Angles::from_directions::<M>(wi, wr, tangent) {
            Ok(a) => self.eval_near(&a, h),
            Err(_) => Lobes::ZERO,
        }
    }

    /// Far-field S from world-space directions; invalid directions give zero.
    pub fn eval_far_dirs(&self, wi: Vec3, wr: Vec3, tangent: Vec3) -> Lobes {
        match Angles::from_directions::<M>(wi, wr, tangent) {
            Ok(a) => self.eval_far(&a),
            Err(_) => Lobes::ZERO,
        }
    }
}
