//! The analytic double-cylinder BCSDF (docs/model.md §8, report eq. 1):
//! S = [Σ_p M_p·N_p + M^s·Σ_p N^s_p] / cos²θ_i, near field (at offset h) and far field
//! (h integrated).

use crate::far_field::FarFieldQuery;
use crate::frame::{Angles, Vec3};
use crate::geometry::{Chord, MedullaEvent, ViewSlice};
use crate::lobes::{Families, Lobe, LobeGroup, Lobes, LOBE_COUNT, UNSCATTERED_COUNT};
use crate::longitudinal::GroupLobes;
use crate::math::{Libm, Math};
use crate::medulla::{MedullaProfiles, ProfileError};
use crate::params::{Closure, FurParams};
use crate::residual::ResidualTable;
use crate::scattered::{
    azimuthal_at, exit_transmittance, scattered_paths, ScatteredLongitudinal, SCATTERED_COUNT,
};
use crate::spectrum::Rgb;
use crate::unscattered::{paths_at, Extinction};
use core::marker::PhantomData;

/// S's pole guard (docs/model.md §8, §12), defined with the longitudinal lobes whose
/// normalisation accounts for it; re-exported here, where tools and tests name it.
pub use crate::longitudinal::{inv_cos2_theta_i, MIN_COS2_THETA_I, POLE_SLIVER};

/// Version of the model's formulas: any change to what S evaluates to bumps it, so baked
/// tables made by an older model are recognised (`lut` header).
pub const MODEL_VERSION: u32 = 6;

/// The medulla-scattering part of a model: borrowed profiles and the precomputed M^s.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Scattering<'a> {
    pub(crate) profiles: MedullaProfiles<'a>,
    pub(crate) longitudinal: ScatteredLongitudinal,
}

/// The analytic fur BCSDF for one parameter set, evaluated with the math backend `M`.
///
/// Built with [`FurBcsdf::new`] from medulla profiles (the full model), or with
/// [`FurBcsdf::unscattered`] (the eight unscattered paths only; the scattered lobes are then
/// zero — exact when σ_ms = 0 or κ = 0). Construction precomputes the lobe constants;
/// evaluation allocates nothing. The crate documentation shows the full model; here,
/// human hair, which has no medulla:
///
/// ```
/// use bcsdf_core::{presets, Angles, FurBcsdf, FurParams, Lobe, LobeFamily, Rgb};
///
/// let params = FurParams::new(&presets::find("human-hair").unwrap().input).unwrap();
/// let model: FurBcsdf = FurBcsdf::unscattered(params); // κ = 0: this is the whole model
/// let angles = Angles::from_degrees(20.0, -15.0, 160.0).unwrap();
///
/// let lobes = model.eval_far_lobes(&angles); // the eleven paths
/// let families = model.eval_far(&angles); // the same, summed per family
/// assert_eq!(families, lobes.families());
/// assert!(lobes.get(Lobe::TT).max_channel() > 0.0); // through the fiber, forward
/// assert_eq!(lobes.get(Lobe::TrT), Rgb::ZERO); // no medulla to reflect off
/// assert_eq!(families.get(LobeFamily::Scattered), Rgb::ZERO);
/// // The far field is even in φ.
/// assert_eq!(model.eval_far(&angles.mirrored()), families);
/// ```
#[derive(Clone, Copy, Debug)]
pub struct FurBcsdf<'a, M: Math = Libm> {
    params: FurParams,
    pub(crate) groups: GroupLobes,
    pub(crate) scattering: Option<Scattering<'a>>,
    /// The residual table (docs/model.md §12, "Residual"); used in the energy closure only.
    pub(crate) residual: Option<ResidualTable<'a>>,
    _math: PhantomData<M>,
}

/// The azimuthal parts M multiplies: the unscattered lobes' N_p in breakdown order, the
/// scattered ones' N^s_p, and the energy closure's N_res (docs/model.md §12).
pub(crate) type Azimuthal = ([Rgb; UNSCATTERED_COUNT], [Rgb; SCATTERED_COUNT], Rgb);

impl<M: Math> FurBcsdf<'static, M> {
    /// The unscattered part of the model only (R … TttRttT); the scattered lobes are zero.
    /// This is the whole model when σ_ms = 0 or κ = 0.
    #[must_use]
    pub fn unscattered(params: FurParams) -> FurBcsdf<'static, M> {
        FurBcsdf {
            params,
            groups: GroupLobes::new(&params),
            scattering: None,
            residual: None,
            _math: PhantomData,
        }
    }
}

impl<'a, M: Math> FurBcsdf<'a, M> {
    /// The full model with the medulla profiles `profiles`, which must have been made for
    /// these parameters ([`crate::medulla::ProfileLayout::for_params`]).
    pub fn new(
        params: FurParams,
        profiles: MedullaProfiles<'a>,
    ) -> Result<FurBcsdf<'a, M>, ProfileError> {
        if !profiles.layout().matches(&params) {
            return Err(ProfileError::Mismatch);
        }
        Ok(FurBcsdf {
            params,
            groups: GroupLobes::new(&params),
            scattering: Some(Scattering {
                profiles,
                longitudinal: ScatteredLongitudinal::new::<M>(&params, &profiles),
            }),
            residual: None,
            _math: PhantomData,
        })
    }

    /// This model with the residual table `table` (docs/model.md §12, "Residual"), which must
    /// have been made for these parameters ([`crate::residual_gen::generate`] from this model
    /// without a residual). In the energy closure S gains M_TRT·N_res/cos²θ_i, the
    /// [`Lobe::Residual`] entry of every evaluation ([`FurBcsdf::eval_far_lobes`],
    /// [`FurBcsdf::eval_near`] with A_res's own h-profile, the `*_dirs` variants, and the TRT
    /// family of [`FurBcsdf::eval_far`]); the report closure ignores it.
    pub fn with_residual(self, table: ResidualTable<'a>) -> Result<FurBcsdf<'a, M>, ProfileError> {
        if !table.matches(&self.params) {
            return Err(ProfileError::Mismatch);
        }
        Ok(FurBcsdf {
            residual: Some(table),
            ..self
        })
    }

    /// The residual table, when the model has one.
    #[must_use]
    pub fn residual(&self) -> Option<&ResidualTable<'a>> {
        self.residual.as_ref()
    }

    /// The residual table the evaluation uses: the model's, in the energy closure only.
    pub(crate) fn active_residual(&self) -> Option<&ResidualTable<'a>> {
        match self.params.closure() {
            Closure::Energy => self.residual.as_ref(),
            Closure::Report => None,
        }
    }

    /// Far-field N_res(θ_r, φ) = ⟨A_res⟩_h·D_res(θ_r, |φ|) (docs/model.md §12, "Residual"); zero
    /// in the report closure or without a residual table.
    #[must_use]
    pub fn residual_azimuthal_far(&self, theta_r: f32, phi: f32) -> Rgb {
        self.residual_azimuthal(theta_r, phi, None)
    }

    /// N_res(θ_r, h, φ) = A_res(θ_r, |h|)·D_res(θ_r, |φ|) at offset `h` (A_res linear in |h|
    /// between the table's offsets, whose h-mean is exactly the far field's ⟨A_res⟩_h), or the
    /// far field ⟨A_res⟩_h·D_res with `None` (docs/model.md §12, "Residual"). Zero in the
    /// report closure, without a residual table, or for an offset off the fiber.
    fn residual_azimuthal(&self, theta_r: f32, phi: f32, h: Option<f32>) -> Rgb {
        let Some(t) = self.active_residual() else {
            return Rgb::ZERO;
        };
        if !(theta_r.is_finite() && phi.is_finite()) {
            return Rgb::ZERO;
        }
        match h {
            None => t.far(theta_r, phi),
            Some(h) if h.is_finite() && (-1.0..=1.0).contains(&h) => t.near(theta_r, h, phi),
            Some(_) => Rgb::ZERO,
        }
    }

    /// The residual's S: M_TRT(θ_i, θ_r)·N_res/cos²θ_i, with the near-field N_res at `h`
    /// when given, the far field otherwise (docs/model.md §12, "Residual"): the
    /// [`Lobe::Residual`] entry of [`FurBcsdf::eval_near`] / [`FurBcsdf::eval_far_lobes`].
    #[must_use]
    pub fn eval_residual(&self, angles: &Angles, h: Option<f32>) -> Rgb {
        let n = self.residual_azimuthal(angles.theta_r(), angles.phi(), h);
        let m = self
            .groups
            .m::<M>(ResidualTable::GROUP, angles.theta_i(), angles.theta_r());
        finite_non_negative(n * (m * inv_cos2_theta_i(M::cos(angles.theta_i()))))
    }

    /// The parameters this model was built from.
    #[must_use]
    pub fn params(&self) -> &FurParams {
        &self.params
    }

    /// This model at another colour: the σ_ca of `absorption`, every other parameter
    /// unchanged (`FurParams::with_absorption`). The longitudinal constants and the medulla's
    /// precomputed M^s do not depend on σ_ca, so this is a copy, cheap enough per query
    /// (a renderer colouring each strand). `None` when the model carries a residual table:
    /// that table was generated for the model's own σ_ca (docs/model.md §12), and the model
    /// at another colour needs its own.
    #[must_use]
    pub fn at_absorption(
        &self,
        absorption: &crate::absorption::Absorption,
    ) -> Option<FurBcsdf<'a, M>> {
        if self.residual.is_some() {
            return None;
        }
        Some(FurBcsdf {
            params: self.params.with_absorption(absorption),
            ..*self
        })
    }

    /// The medulla profiles, when the model has them.
    #[must_use]
    pub fn profiles(&self) -> Option<&MedullaProfiles<'a>> {
        self.scattering.as_ref().map(|s| &s.profiles)
    }

    pub(crate) fn slice_and_extinction(&self, theta_r: f32) -> (ViewSlice, Extinction) {
        let slice = ViewSlice::new::<M>(&self.params, theta_r);
        let ext = Extinction::new(&self.params, &slice);
        (slice, ext)
    }

    /// σ_N = σ_ms·κ/cos θ_tm, the medulla's 2D optical radius at this slice.
    pub(crate) fn sigma_n(&self, slice: &ViewSlice) -> f32 {
        self.params.sigma_ms() * self.params.kappa() * slice.inv_cos_tm
    }

    /// Multiplies N_p by M_p, N^s_p by M^s, N_res by M_TRT (docs/model.md §12), and divides
    /// by cos²θ_i (report eq. 1).
    pub(crate) fn assemble(&self, angles: &Angles, n: &Azimuthal) -> Lobes {
        let (ti, tr) = (angles.theta_i(), angles.theta_r());
        let inv_cos2 = inv_cos2_theta_i(M::cos(ti));
        let m = [
            self.groups.m::<M>(LobeGroup::R, ti, tr),
            self.groups.m::<M>(LobeGroup::TT, ti, tr),
            self.groups.m::<M>(LobeGroup::TRT, ti, tr),
        ];
        let ms = match &self.scattering {
            Some(s) if n.1.iter().any(|v| v.max_channel() > 0.0) => {
                s.longitudinal.eval::<M>(&s.profiles, ti, tr, angles.phi())
            }
            _ => 0.0,
        };
        let mut out = [Rgb::ZERO; LOBE_COUNT];
        for (p, v) in n.0.iter().enumerate() {
            out[p] = *v * (m[Lobe::unscattered_group(p) as usize] * inv_cos2);
        }
        for (k, v) in n.1.iter().enumerate() {
            out[UNSCATTERED_COUNT + k] = *v * (ms * inv_cos2);
        }
        out[Lobe::Residual.index()] = n.2 * (m[ResidualTable::GROUP as usize] * inv_cos2);
        // Never hand NaN or a negative value to a renderer.
        Lobes::from_array(out.map(finite_non_negative))
    }

    /// Near-field azimuthal lobes: N_p(h, φ) = A_p(h)·D_p(φ − Φ_p(h)) (report eq. 4), the
    /// scattered N^s_p(h, φ) (report eq. 6) and the residual's N_res(θ_r, h, φ)
    /// (docs/model.md §12), in [`Lobe::ALL`] order.
    #[must_use]
    pub fn azimuthal_near(&self, theta_r: f32, phi: f32, h: f32) -> [Rgb; LOBE_COUNT] {
        join(&self.azimuthal_near_parts(theta_r, phi, h))
    }

    fn azimuthal_near_parts(&self, theta_r: f32, phi: f32, h: f32) -> Azimuthal {
        let mut n = [Rgb::ZERO; UNSCATTERED_COUNT];
        let mut ns = [Rgb::ZERO; SCATTERED_COUNT];
        if !(h.is_finite() && (-1.0..=1.0).contains(&h) && theta_r.is_finite() && phi.is_finite()) {
            return (n, ns, Rgb::ZERO);
        }
        let (slice, ext) = self.slice_and_extinction(theta_r);
        let chord = Chord::at_offset::<M>(&slice, h);
        let paths = paths_at::<M>(&slice, &chord, &ext, self.params.l());
        for (p, path) in paths.iter().enumerate() {
            // Paths that do not exist at this h (or carry no energy) need no D_p.
            if path.attenuation.max_channel() > 0.0 {
                let d = self.groups.d(Lobe::unscattered_group(p));
                n[p] = path.attenuation * d.eval::<M>(phi - path.exit_azimuth);
            }
        }
        let enters = matches!(chord.medulla, MedullaEvent::Enter { .. });
        if let (Some(s), true) = (&self.scattering, enters) {
            let exit = exit_transmittance::<M>(&slice, &ext);
            if let Some(sp) = scattered_paths::<M>(&slice, &chord, &ext, self.params.l(), exit) {
                ns = azimuthal_at(&s.profiles, &sp, self.sigma_n(&slice), phi);
                if let Some(t) = self.active_residual() {
                    let k = t.scattered_scale_near(theta_r, h);
                    ns = ns.map(|v| v * k);
                }
            }
        }
        (n, ns, self.residual_azimuthal(theta_r, phi, Some(h)))
    }

    /// Far-field azimuthal lobes N_p(φ) = ½ ∫ N_p(h, φ) dh (docs/model.md §5, §6) and the
    /// residual's ⟨A_res⟩_h·D_res (§12), in [`Lobe::ALL`] order.
    #[must_use]
    pub fn azimuthal_far(&self, theta_r: f32, phi: f32) -> [Rgb; LOBE_COUNT] {
        join(&self.azimuthal_far_parts(theta_r, phi))
    }

    fn azimuthal_far_parts(&self, theta_r: f32, phi: f32) -> Azimuthal {
        let zero = ([0.0; UNSCATTERED_COUNT], [0.0; SCATTERED_COUNT]);
        self.azimuthal_far_with_density(theta_r, phi, &zero).0
    }

    /// True when η_m = η_c (f_m ≡ 0: the medulla-reflection paths vanish).
    pub(crate) fn index_matched(&self) -> bool {
        self.params.eta_m() == self.params.eta_c()
    }

    /// The far-field azimuthal parts and, with the same quadrature nodes, the analytic
    /// sampler's φ density for per-path constants `coeffs` (unscattered, scattered); see
    /// [`FarFieldQuery::azimuthal_with_density`].
    pub(crate) fn azimuthal_far_with_density(
        &self,
        theta_r: f32,
        phi: f32,
        coeffs: &([f32; UNSCATTERED_COUNT], [f32; SCATTERED_COUNT]),
    ) -> (Azimuthal, f32) {
        if !(theta_r.is_finite() && phi.is_finite()) {
            let zero = [Rgb::ZERO; UNSCATTERED_COUNT];
            return ((zero, [Rgb::ZERO; SCATTERED_COUNT], Rgb::ZERO), 0.0);
        }
        let (slice, ext) = self.slice_and_extinction(theta_r);
        let query = FarFieldQuery {
            slice: &slice,
            extinction: &ext,
            layers: self.params.l(),
            groups: &self.groups,
            index_matched: self.index_matched(),
        };
        let (n, dens) = query.azimuthal_with_density::<M>(phi, &coeffs.0);
        let (mut ns, dens_s) = match &self.scattering {
            Some(s) if ext.medulla_scattering > 0.0 => query.azimuthal_scattered_with_density::<M>(
                &s.profiles,
                self.sigma_n(&slice),
                phi,
                &coeffs.1,
            ),
            _ => ([Rgb::ZERO; SCATTERED_COUNT], 0.0),
        };
        // The energy closure's residual table scales the scattered lobes down where they
        // carry more than the cross-section lets out (docs/model.md §12, "Residual").
        if let Some(t) = self.active_residual() {
            let k = t.scattered_scale(theta_r);
            ns = ns.map(|v| v * k);
        }
        let res = self.residual_azimuthal(theta_r, phi, None);
        ((n, ns, res), dens + dens_s)
    }

    /// M_p(θ_i, θ_r) of one cuticle group: G(θ_r + θ_i − α_p; β_M) (report eq. 2–3), in the
    /// energy closure divided by its mass on the sphere (docs/model.md §12).
    #[must_use]
    pub fn longitudinal(&self, group: LobeGroup, theta_i: f32, theta_r: f32) -> f32 {
        self.groups.m::<M>(group, theta_i, theta_r)
    }

    /// G(θ_r + θ_i − α_p; β_M) of one cuticle group, the report's M_p (docs/model.md §5):
    /// what the baked table `M` stores, a function of θ_i + θ_r alone (the energy closure's
    /// factor is applied when a LUT is evaluated, §12).
    #[must_use]
    pub fn longitudinal_gaussian(&self, group: LobeGroup, theta_i: f32, theta_r: f32) -> f32 {
        self.groups.gaussian::<M>(group, theta_i, theta_r)
    }

    /// M^s(θ_i, θ_r, φ), the longitudinal scattered lobe (0 without profiles).
    #[must_use]
    pub fn longitudinal_scattered(&self, angles: &Angles) -> f32 {
        match &self.scattering {
            Some(s) => s.longitudinal.eval::<M>(
                &s.profiles,
                angles.theta_i(),
                angles.theta_r(),
                angles.phi(),
            ),
            None => 0.0,
        }
    }

    /// Near-field S(ω_i, ω_r, h) per lobe, the residual at offset h included (its own
    /// h-profile A_res(θ_r, |h|), docs/model.md §12). An offset outside [−1, 1] (or NaN)
    /// misses the fiber and gives zero.
    pub fn eval_near(&self, angles: &Angles, h: f32) -> Lobes {
        let n = self.azimuthal_near_parts(angles.theta_r(), angles.phi(), h);
        self.assemble(angles, &n)
    }

    /// Far-field S(ω_i, ω_r) per lobe: the breakdown of [`FurBcsdf::eval_far`], eleven paths
    /// and the energy closure's residual (docs/model.md §8, §12); its total is S.
    pub fn eval_far_lobes(&self, angles: &Angles) -> Lobes {
        let n = self.azimuthal_far_parts(angles.theta_r(), angles.phi());
        self.assemble(angles, &n)
    }

    /// Far-field S(ω_i, ω_r) per lobe family, the type both evaluators return
    /// (docs/model.md §8); [`FurBcsdf::eval_far_lobes`] has the per-lobe breakdown.
    pub fn eval_far(&self, angles: &Angles) -> Families {
        self.eval_far_lobes(angles).families()
    }

    /// Near-field S from world-space directions (see [`Angles::from_directions`]); invalid
    /// directions give zero.
    pub fn eval_near_dirs(&self, wi: Vec3, wr: Vec3, tangent: Vec3, h: f32) -> Lobes {
        match Angles::from_directions::<M>(wi, wr, tangent) {
            Ok(a) => self.eval_near(&a, h),
            Err(_) => Lobes::ZERO,
        }
    }

    /// Far-field S per lobe from world-space directions; invalid directions give zero.
    pub fn eval_far_dirs(&self, wi: Vec3, wr: Vec3, tangent: Vec3) -> Lobes {
        match Angles::from_directions::<M>(wi, wr, tangent) {
            Ok(a) => self.eval_far_lobes(&a),
            Err(_) => Lobes::ZERO,
        }
    }
}

fn join((u, s, r): &Azimuthal) -> [Rgb; LOBE_COUNT] {
    let mut out = [Rgb::ZERO; LOBE_COUNT];
    out[..UNSCATTERED_COUNT].copy_from_slice(u);
    out[UNSCATTERED_COUNT..UNSCATTERED_COUNT + SCATTERED_COUNT].copy_from_slice(s);
    out[Lobe::Residual.index()] = *r;
    out
}

/// `v` with every channel that is not a finite positive number set to 0: the model never
/// hands NaN or a negative value to a renderer.
fn finite_non_negative(v: Rgb) -> Rgb {
    v.map(|c| if c.is_finite() && c > 0.0 { c } else { 0.0 })
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use crate::math::PI;
    use crate::medulla::{generate, PhotonBudget, ProfileLayout, Resolution};
    use crate::presets;
    use std::vec;

    fn params(name: &str) -> FurParams {
        FurParams::new(&presets::find(name).unwrap().input).unwrap()
    }

    #[test]
    fn the_pole_sliver_is_where_the_guard_acts() {
        let want = libm::asin(libm::sqrt(f64::from(MIN_COS2_THETA_I)));
        assert!((f64::from(POLE_SLIVER) - want).abs() < 1e-9, "{want}");
        let edge = |s: f32| libm::cosf(PI / 2.0 - s).powi(2);
        assert!(edge(POLE_SLIVER * 0.999) < MIN_COS2_THETA_I);
        assert!(edge(POLE_SLIVER * 1.001) > MIN_COS2_THETA_I);
    }

    #[test]
    fn a_model_at_another_colour_is_the_model_of_those_parameters() {
        let base = params("human-hair");
        let red = crate::absorption::Absorption::from_sigma(Rgb([0.2, 1.5, 4.0])).unwrap();
        let model: FurBcsdf = FurBcsdf::unscattered(base);
        let at = model.at_absorption(&red).unwrap();
        let want: FurBcsdf = FurBcsdf::unscattered(base.with_absorption(&red));
        let a = Angles::from_degrees(30.0, -20.0, 150.0).unwrap();
        assert_eq!(at.eval_far(&a), want.eval_far(&a));
        assert_eq!(at.params().sigma_ca(), Rgb([0.2, 1.5, 4.0]));
    }

    #[test]
    fn the_cos2_factor_is_guarded_at_grazing_light() {
        assert_eq!(inv_cos2_theta_i(1.0), 1.0);
        assert_eq!(inv_cos2_theta_i(0.5), 4.0);
        assert_eq!(inv_cos2_theta_i(0.0), 1.0 / MIN_COS2_THETA_I);
        assert_eq!(inv_cos2_theta_i(-1e-9), 1.0 / MIN_COS2_THETA_I);
    }

    #[test]
    fn evaluations_are_finite_non_negative_and_zero_off_the_fiber() {
        let model: FurBcsdf = FurBcsdf::unscattered(params("air-medulla"));
        assert!(model.profiles().is_none());
        let thetas = [-PI / 2.0, -1.0, -0.2, 0.0, 0.4, 1.3, PI / 2.0];
        for ti in thetas {
            for tr in thetas {
                for phi in [-3.0, -0.5, 0.0, 1.0, PI] {
                    let a = Angles::new(ti, tr, phi).unwrap();
                    for lobes in [model.eval_far_lobes(&a), model.eval_near(&a, 0.37)] {
                        for (lobe, v) in lobes.iter() {
                            assert!(
                                v.0.iter().all(|c| c.is_finite() && *c >= 0.0),
                                "{lobe:?} {a:?}"
                            );
                        }
                    }
                    // Off the fiber (|h| > 1) or NaN: nothing.
                    assert_eq!(model.eval_near(&a, 1.01), Lobes::ZERO);
                    assert_eq!(model.eval_near(&a, f32::NAN), Lobes::ZERO);
                }
            }
        }
    }

    #[test]
    fn direction_paths_are_the_angle_paths() {
        let model: FurBcsdf = FurBcsdf::unscattered(params("human-hair"));
        let (wi, wr, u) = ([0.2, 0.9, -0.3], [-1.0, 0.4, 0.5], [0.1, 0.0, 2.0]);
        let a = Angles::from_directions::<Libm>(wi, wr, u).unwrap();
        assert_eq!(model.eval_far_dirs(wi, wr, u), model.eval_far_lobes(&a));
        assert_eq!(
            model.eval_near_dirs(wi, wr, u, 0.2),
            model.eval_near(&a, 0.2)
        );
        assert_eq!(model.eval_far_dirs([0.0; 3], wr, u), Lobes::ZERO);
        assert_eq!(
            model.eval_near_dirs(wi, wr, [f32::NAN; 3], 0.2),
            Lobes::ZERO
        );
        // The lobe products: each unscattered lobe is N_p·M_p/cos²θ_i.
        let n = model.azimuthal_far(a.theta_r(), a.phi());
        let lobes = model.eval_far_lobes(&a);
        let inv = inv_cos2_theta_i(libm::cosf(a.theta_i()));
        for (p, lobe) in Lobe::UNSCATTERED.iter().enumerate() {
            let m = model.longitudinal(lobe.group().unwrap(), a.theta_i(), a.theta_r());
            let want = n[p] * (m * inv);
            for c in 0..3 {
                assert!((lobes.get(*lobe).0[c] - want.0[c]).abs() <= 1e-6 * want.0[c].max(1e-6));
            }
        }
        assert_eq!(model.longitudinal_scattered(&a), 0.0);
    }

    #[test]
    fn profiles_must_match_the_parameters() {
        let p = params("air-medulla");
        let res = Resolution {
            n_sigma: 2,
            n_h: 2,
            n_psi: 8,
            n_in: 2,
            n_out: 4,
        };
        let layout = ProfileLayout::for_params(&p, res);
        let (mut cn, mut cm) = (vec![0.0; layout.cn_len()], vec![0.0; layout.cm_len()]);
        let budget = PhotonBudget {
            per_cn_cell: 200,
            per_cm_row: 200,
        };
        generate(&layout, &budget, 1, &mut cn, &mut cm).unwrap();
        let profiles = MedullaProfiles::new(layout, &cn, &cm).unwrap();
        let other = FurBcsdf::<Libm>::new(params("bobcat"), profiles);
        assert_eq!(other.err(), Some(ProfileError::Mismatch));
        let model = FurBcsdf::<Libm>::new(p, profiles).unwrap();
        assert_eq!(model.params(), &p);
        assert!(model.profiles().is_some());
        let a = Angles::new(0.2, -0.1, 2.5).unwrap();
        assert!(model.longitudinal_scattered(&a) > 0.0);
    }
}
