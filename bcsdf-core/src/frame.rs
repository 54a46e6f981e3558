//! The fiber frame and the angles the model is written in (docs/model.md §1).
//!
//! Directions point away from the fiber: ω_i toward the light, ω_r toward the viewer.
//! θ = asin(ω·u) is measured from the normal plane, and φ = φ_r − φ_i is the azimuth
//! from ω_i to ω_r around u, for the right-handed frame (v, w, u), i.e. u = v × w.

use crate::math::{asin_clamped, asin_polynomial, atan2_polynomial, wrap_angle, Math, PI};
use core::fmt;

/// A 3-vector (not necessarily unit length).
pub type Vec3 = [f32; 3];

#[inline]
fn dot(a: Vec3, b: Vec3) -> f32 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

#[inline]
fn cross(a: Vec3, b: Vec3) -> Vec3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// Why a set of angles or directions was rejected.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AngleError {
    /// An angle or vector component is NaN or infinite.
    NonFinite,
    /// θ outside [−π/2, π/2].
    ThetaOutOfRange,
    /// A direction or the tangent has zero (or denormal) length.
    Degenerate,
}

impl fmt::Display for AngleError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            AngleError::NonFinite => "angle or direction is not finite",
            AngleError::ThetaOutOfRange => "theta must lie in [-90, 90] degrees",
            AngleError::Degenerate => "direction or fiber tangent has zero length",
        })
    }
}

impl core::error::Error for AngleError {}

/// Validated query angles: θ_i, θ_r ∈ [−π/2, π/2] and φ = φ_r − φ_i ∈ (−π, π], radians.
///
/// Directions point away from the fiber, ω_i toward the light and ω_r toward the viewer;
/// θ = asin(ω·u) is measured from the normal plane of the fiber tangent u, and φ is the
/// azimuth from ω_i to ω_r around u, in the right-handed frame (v, w, u) (docs/model.md §1).
///
/// ```
/// use bcsdf_core::{AngleError, Angles, Libm};
///
/// let a = Angles::from_degrees(30.0, -20.0, 270.0).unwrap();
/// assert!((a.phi().to_degrees() + 90.0).abs() < 1e-4); // φ wrapped into (−180°, 180°]
///
/// // From world-space vectors (tangent along z here; none needs unit length).
/// let b = Angles::from_directions::<Libm>([0.0, 2.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 5.0])
///     .unwrap();
/// assert_eq!((b.theta_i(), b.theta_r()), (0.0, 0.0));
/// assert!((b.phi().to_degrees() + 90.0).abs() < 1e-4);
///
/// assert_eq!(Angles::new(f32::NAN, 0.0, 0.0), Err(AngleError::NonFinite));
/// assert_eq!(Angles::from_degrees(95.0, 0.0, 0.0), Err(AngleError::ThetaOutOfRange));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Angles {
    theta_i: f32,
    theta_r: f32,
    phi: f32,
}

impl Angles {
    /// From radians; φ is wrapped to (−π, π].
    #[inline]
    pub fn new(theta_i: f32, theta_r: f32, phi: f32) -> Result<Angles, AngleError> {
        if !(theta_i.is_finite() && theta_r.is_finite() && phi.is_finite()) {
            return Err(AngleError::NonFinite);
        }
        let half = PI / 2.0;
        if theta_i.abs() > half || theta_r.abs() > half {
            return Err(AngleError::ThetaOutOfRange);
        }
        Ok(Angles {
            theta_i,
            theta_r,
            phi: wrap_angle(phi),
        })
    }

    /// From degrees; φ is wrapped to (−180°, 180°].
    pub fn from_degrees(theta_i: f32, theta_r: f32, phi: f32) -> Result<Angles, AngleError> {
        // θ a hair past ±90° after the degree conversion is clamped, not rejected.
        let conv = |d: f32| {
            let r = d.to_radians();
            if d.abs() <= 90.0 {
                r.clamp(-PI / 2.0, PI / 2.0)
            } else {
                r
            }
        };
        Angles::new(conv(theta_i), conv(theta_r), phi.to_radians())
    }

    /// From world-space directions `wi` (toward the light), `wr` (toward the viewer) and the
    /// fiber tangent `u`; none needs to be normalised.
    pub fn from_directions<M: Math>(wi: Vec3, wr: Vec3, u: Vec3) -> Result<Angles, AngleError> {
        if !(wi.iter().chain(wr.iter()).chain(u.iter())).all(|c| c.is_finite()) {
            return Err(AngleError::NonFinite);
        }
        let norm = |v: Vec3| M::sqrt(dot(v, v));
        let (ni, nr, nu) = (norm(wi), norm(wr), norm(u));
        // Components up to f32::MAX can overflow the squared norm: treat as non-finite.
        if !(ni.is_finite() && nr.is_finite() && nu.is_finite()) {
            return Err(AngleError::NonFinite);
        }
        if ni < f32::MIN_POSITIVE || nr < f32::MIN_POSITIVE || nu < f32::MIN_POSITIVE {
            return Err(AngleError::Degenerate);
        }
        let un = [u[0] / nu, u[1] / nu, u[2] / nu];
        let (si, sr) = (dot(wi, un) / ni, dot(wr, un) / nr);
        let theta_i = asin_clamped::<M>(si);
        let theta_r = asin_clamped::<M>(sr);
        // Azimuth from the projections onto the normal plane (atan2(0, 0) = 0 when one of
        // them is parallel to the fiber, where φ carries no meaning).
        let project = |v: Vec3, s: f32, n: f32| {
            [
                v[0] / n - s * un[0],
                v[1] / n - s * un[1],
                v[2] / n - s * un[2],
            ]
        };
        let (pi, pr) = (project(wi, si, ni), project(wr, sr, nr));
        let phi = M::atan2(dot(un, cross(pi, pr)), dot(pi, pr));
        Angles::new(theta_i, theta_r, phi)
    }

    /// θ_i, longitudinal angle of the light direction (radians).
    #[must_use]
    pub fn theta_i(&self) -> f32 {
        self.theta_i
    }
    /// θ_r, longitudinal angle of the view direction (radians).
    #[must_use]
    pub fn theta_r(&self) -> f32 {
        self.theta_r
    }
    /// φ = φ_r − φ_i in (−π, π] (radians).
    #[must_use]
    pub fn phi(&self) -> f32 {
        self.phi
    }
    /// The same query with φ → −φ.
    #[must_use]
    pub fn mirrored(&self) -> Angles {
        Angles {
            phi: wrap_angle(-self.phi),
            ..*self
        }
    }
}

/// θ_i, θ_r and φ of world-space directions, as [`Angles::from_directions`] defines them
/// (same validation and errors), computed for speed: with
/// reciprocals of the three lengths, the branch-free polynomials [`asin_polynomial`] and
/// [`atan2_polynomial`] instead of libm's asin and atan2, and φ from unnormalised vectors
/// (atan2 is scale-invariant):
///
/// - sin θ = (ω·û)/|ω| with û = u/|u|;
/// - tan φ = y/x with y = û·(ω_i × ω_r) and x = ω_i·ω_r − (ω_i·û)(ω_r·û), |ω_i||ω_r| times
///   the sine and cosine of φ (the components along û drop out of the triple product).
///
/// Every intermediate is bounded by a product of at most two of the lengths, so nothing
/// overflows where the lengths are finite. The angles are within about 3e-7 rad of the libm
/// ones away from the poles (docs/lut.md); φ lies in [−π, π] (−π only where `Angles::new`
/// wraps it to π). This is the baked evaluator's one direction conversion
/// ([`crate::Bcsdf::angles_from_dirs`], used by `eval_dirs`, `pdf_dirs` and `sample_dirs`);
/// its WGSL twin (`shaders/fur_bcsdf.wgsl`, `fur_eval_far_dirs`) does the same operations.
#[inline]
pub(crate) fn polynomial_angles<M: Math>(
    wi: Vec3,
    wr: Vec3,
    u: Vec3,
) -> Result<[f32; 3], AngleError> {
    // A NaN or infinite component, or an overflowing square, makes its dot non-finite.
    let (ii, rr, uu) = (dot(wi, wi), dot(wr, wr), dot(u, u));
    if !(ii.is_finite() && rr.is_finite() && uu.is_finite()) {
        return Err(AngleError::NonFinite);
    }
    let (ni, nr, nu) = (M::sqrt(ii), M::sqrt(rr), M::sqrt(uu));
    if ni < f32::MIN_POSITIVE || nr < f32::MIN_POSITIVE || nu < f32::MIN_POSITIVE {
        return Err(AngleError::Degenerate);
    }
    let k = 1.0 / nu;
    let un = [u[0] * k, u[1] * k, u[2] * k];
    let (a, b) = (dot(wi, un), dot(wr, un));
    let theta_i = asin_polynomial((a * (1.0 / ni)).clamp(-1.0, 1.0));
    let theta_r = asin_polynomial((b * (1.0 / nr)).clamp(-1.0, 1.0));
    let y = dot(un, cross(wi, wr));
    let x = dot(wi, wr) - a * b;
    Ok([theta_i, theta_r, atan2_polynomial(y, x)])
}

/// The fiber frame (v, w, u) of one view direction (docs/model.md §1): u the unit tangent,
/// v the unit projection of ω_r onto the normal plane (so that φ_r = 0), w = u × v. It turns
/// sampled angles back into a world-space direction.
///
/// ```
/// use bcsdf_core::{Angles, Frame, Libm};
///
/// let (wr, tangent) = ([0.3, -1.0, 0.4], [0.0, 0.2, 1.0]);
/// let frame = Frame::from_view::<Libm>(wr, tangent).unwrap();
/// let angles = Angles::new(0.4, frame.theta_r(), -2.0).unwrap();
/// let wi = frame.to_world(&angles);
/// // The direction has the angles it was made from.
/// let back = Angles::from_directions::<Libm>(wi, wr, tangent).unwrap();
/// assert!((back.theta_i() - 0.4).abs() < 1e-5 && (back.phi() + 2.0).abs() < 1e-5);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame {
    v: Vec3,
    w: Vec3,
    u: Vec3,
    theta_r: f32,
}

impl Frame {
    /// The frame whose axes are the coordinate axes (v = x, w = y, u = z), θ_r = 0: vectors
    /// in it are fiber-frame components.
    #[must_use]
    pub const fn canonical() -> Frame {
        Frame {
            v: [1.0, 0.0, 0.0],
            w: [0.0, 1.0, 0.0],
            u: [0.0, 0.0, 1.0],
            theta_r: 0.0,
        }
    }

    /// The frame of view direction `wr` around the fiber tangent `tangent` (neither needs to
    /// be unit length). When `wr` is parallel to the fiber, v is any unit normal. `None` for
    /// non-finite or zero-length input.
    #[must_use]
    pub fn from_view<M: Math>(wr: Vec3, tangent: Vec3) -> Option<Frame> {
        if !wr.iter().chain(tangent.iter()).all(|c| c.is_finite()) {
            return None;
        }
        let norm = |v: Vec3| M::sqrt(dot(v, v));
        let (nr, nu) = (norm(wr), norm(tangent));
        if !(nr.is_finite() && nu.is_finite() && nr >= f32::MIN_POSITIVE && nu >= f32::MIN_POSITIVE)
        {
            return None;
        }
        let u = [tangent[0] / nu, tangent[1] / nu, tangent[2] / nu];
        let wr = [wr[0] / nr, wr[1] / nr, wr[2] / nr];
        let s = dot(wr, u).clamp(-1.0, 1.0);
        let p = [wr[0] - s * u[0], wr[1] - s * u[1], wr[2] - s * u[2]];
        let np = norm(p);
        let v = if np > 1e-6 {
            [p[0] / np, p[1] / np, p[2] / np]
        } else {
            // ω_r along the fiber: any normal will do; take the axis least aligned with u.
            let a = if u[0].abs() < 0.6 {
                [1.0, 0.0, 0.0]
            } else {
                [0.0, 1.0, 0.0]
            };
            let q = cross(cross(u, a), u);
            let nq = norm(q);
            [q[0] / nq, q[1] / nq, q[2] / nq]
        };
        Some(Frame {
            v,
            w: cross(u, v),
            u,
            theta_r: asin_clamped::<M>(s),
        })
    }

    /// θ_r of the view direction the frame was built from.
    #[must_use]
    pub fn theta_r(&self) -> f32 {
        self.theta_r
    }

    /// ω_i for `angles` (θ_i and φ = φ_r − φ_i with φ_r = 0), as a unit vector in the frame's
    /// space: sin θ_i·u + cos θ_i·(cos φ·v − sin φ·w).
    #[must_use]
    pub fn to_world(&self, angles: &Angles) -> Vec3 {
        let (st, ct) = (libm::sinf(angles.theta_i), libm::cosf(angles.theta_i));
        let (sp, cp) = (libm::sinf(angles.phi), libm::cosf(angles.phi));
        let (a, b) = (ct * cp, -ct * sp);
        [
            st * self.u[0] + a * self.v[0] + b * self.w[0],
            st * self.u[1] + a * self.v[1] + b * self.w[1],
            st * self.u[2] + a * self.v[2] + b * self.w[2],
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::Libm;

    const HALF_PI: f32 = PI / 2.0;

    fn close(a: f32, b: f32, tol: f32) -> bool {
        (a - b).abs() <= tol
    }

    /// Angles on a grid covering the domain, poles and φ = π included.
    fn grid() -> impl Iterator<Item = Angles> {
        let thetas = [-HALF_PI, -1.2, -0.5, 0.0, 0.3, 1.0, 1.5, HALF_PI];
        let phis = [-3.0, -1.6, -0.2, 0.0, 0.7, 2.0, PI];
        thetas.into_iter().flat_map(move |ti| {
            thetas.into_iter().flat_map(move |tr| {
                phis.into_iter()
                    .map(move |phi| Angles::new(ti, tr, phi).unwrap())
            })
        })
    }

    #[test]
    fn new_validates_and_wraps() {
        assert_eq!(Angles::new(f32::NAN, 0.0, 0.0), Err(AngleError::NonFinite));
        assert_eq!(
            Angles::new(0.0, f32::INFINITY, 0.0),
            Err(AngleError::NonFinite)
        );
        assert_eq!(
            Angles::new(0.0, 0.0, f32::NEG_INFINITY),
            Err(AngleError::NonFinite)
        );
        assert_eq!(Angles::new(1.6, 0.0, 0.0), Err(AngleError::ThetaOutOfRange));
        assert_eq!(
            Angles::new(0.0, -1.6, 0.0),
            Err(AngleError::ThetaOutOfRange)
        );
        // The poles themselves are valid.
        let a = Angles::new(HALF_PI, -HALF_PI, 0.0).unwrap();
        assert_eq!((a.theta_i(), a.theta_r()), (HALF_PI, -HALF_PI));
        // φ is wrapped to (−π, π]: −π becomes π, 3π/2 becomes −π/2.
        assert_eq!(Angles::new(0.0, 0.0, -PI).unwrap().phi(), PI);
        assert!(close(
            Angles::new(0.0, 0.0, 1.5 * PI).unwrap().phi(),
            -HALF_PI,
            1e-6
        ));
        let far = Angles::new(0.0, 0.0, 1e4).unwrap().phi();
        let want = (1e4f64 + core::f64::consts::PI).rem_euclid(core::f64::consts::TAU)
            - core::f64::consts::PI;
        assert!((f64::from(far) - want).abs() < 2e-3, "{far} {want}");
        // So large that it names no direction: treated like a non-finite φ would be wrapped.
        assert_eq!(Angles::new(0.0, 0.0, 1e30).unwrap().phi(), 0.0);
    }

    #[test]
    fn from_degrees_clamps_the_poles_and_rejects_beyond() {
        let a = Angles::from_degrees(90.0, -90.0, 180.0).unwrap();
        assert_eq!((a.theta_i(), a.theta_r(), a.phi()), (HALF_PI, -HALF_PI, PI));
        assert_eq!(
            Angles::from_degrees(90.01, 0.0, 0.0),
            Err(AngleError::ThetaOutOfRange)
        );
        assert_eq!(
            Angles::from_degrees(0.0, 0.0, f32::NAN),
            Err(AngleError::NonFinite)
        );
        let b = Angles::from_degrees(45.0, 10.0, -190.0).unwrap();
        assert!(close(b.theta_i(), PI / 4.0, 1e-7));
        assert!(close(b.phi(), 170f32.to_radians(), 1e-5));
    }

    #[test]
    fn mirrored_negates_phi_only() {
        let a = Angles::new(0.3, -0.2, 1.0).unwrap();
        let m = a.mirrored();
        assert_eq!((m.theta_i(), m.theta_r(), m.phi()), (0.3, -0.2, -1.0));
        // φ = π is its own mirror image (−π wraps back to π).
        assert_eq!(Angles::new(0.0, 0.0, PI).unwrap().mirrored().phi(), PI);
    }

    #[test]
    fn frame_round_trips_through_directions() {
        let views: [(Vec3, Vec3); 4] = [
            ([1.0, 0.0, 0.0], [0.0, 0.0, 1.0]),
            ([0.3, -1.0, 0.4], [0.0, 0.2, 1.0]),
            ([-2.0, 0.5, -3.0], [1.0, 1.0, 1.0]),
            ([0.0, 0.0, 4.0], [0.1, -3.0, 0.2]),
        ];
        for (wr, tangent) in views {
            let frame = Frame::from_view::<Libm>(wr, tangent).unwrap();
            let want_tr = Angles::from_directions::<Libm>(wr, wr, tangent)
                .unwrap()
                .theta_r();
            assert!(close(frame.theta_r(), want_tr, 1e-6));
            for a in grid() {
                let a = Angles::new(a.theta_i(), frame.theta_r(), a.phi()).unwrap();
                let wi = frame.to_world(&a);
                let len = libm::sqrtf(dot(wi, wi));
                assert!(close(len, 1.0, 1e-6), "|ω_i| = {len}");
                let back = Angles::from_directions::<Libm>(wi, wr, tangent).unwrap();
                assert!(close(back.theta_i(), a.theta_i(), 2e-3), "{a:?} {back:?}");
                assert!(close(back.theta_r(), a.theta_r(), 1e-6), "{a:?} {back:?}");
                // φ is meaningless at the poles; elsewhere it comes back (mod 2π).
                if a.theta_i().abs() < 1.5 && a.theta_r().abs() < 1.5 {
                    let d = crate::math::wrap_angle(back.phi() - a.phi());
                    assert!(d.abs() < 1e-4, "{a:?} {back:?}");
                }
            }
        }
    }

    #[test]
    fn frame_along_the_fiber_is_still_orthonormal() {
        let frame = Frame::from_view::<Libm>([0.0, 0.0, 2.0], [0.0, 0.0, 1.0]).unwrap();
        assert!(close(frame.theta_r(), HALF_PI, 1e-6));
        for a in grid() {
            let wi = frame.to_world(&a);
            assert!(close(dot(wi, wi), 1.0, 1e-5));
            // θ_i is still the angle to the normal plane.
            assert!(close(
                libm::asinf(wi[2].clamp(-1.0, 1.0)),
                a.theta_i(),
                2e-3
            ));
        }
        assert_eq!(Frame::from_view::<Libm>([0.0; 3], [0.0, 0.0, 1.0]), None);
        assert_eq!(
            Frame::from_view::<Libm>([1.0, 0.0, 0.0], [f32::NAN; 3]),
            None
        );
    }

    #[test]
    fn canonical_frame_is_the_fiber_frame() {
        let f = Frame::canonical();
        let wi = f.to_world(&Angles::new(0.0, 0.0, HALF_PI).unwrap());
        // φ = φ_r − φ_i = π/2 with φ_r = 0: ω_i at azimuth −π/2, i.e. along −w = −y.
        assert!(close(wi[0], 0.0, 1e-6) && close(wi[1], -1.0, 1e-6) && wi[2] == 0.0);
        let wi = f.to_world(&Angles::new(HALF_PI, 0.0, 0.0).unwrap());
        assert!(close(wi[2], 1.0, 1e-6));
    }

    #[test]
    fn directions_are_validated() {
        let (x, z) = ([1.0, 0.0, 0.0], [0.0, 0.0, 1.0]);
        let from = Angles::from_directions::<Libm>;
        assert_eq!(from([0.0; 3], x, z), Err(AngleError::Degenerate));
        assert_eq!(from(x, x, [1e-30, 0.0, 0.0]), Err(AngleError::Degenerate));
        assert_eq!(from([f32::NAN, 0.0, 0.0], x, z), Err(AngleError::NonFinite));
        // Finite components whose squared length overflows.
        assert_eq!(from([f32::MAX, 0.0, 0.0], x, z), Err(AngleError::NonFinite));
        // Lengths do not matter.
        let a = from([0.2, 0.5, 0.1], [-1.0, 0.3, 0.6], z).unwrap();
        let b = from([2e3, 5e3, 1e3], [-1e-3, 0.3e-3, 0.6e-3], [0.0, 0.0, 7.0]).unwrap();
        assert!(close(a.theta_i(), b.theta_i(), 1e-6));
        assert!(close(a.theta_r(), b.theta_r(), 1e-6));
        assert!(close(a.phi(), b.phi(), 1e-6));
    }

    #[test]
    fn polynomial_angles_agree_with_libm() {
        let frame = Frame::from_view::<Libm>([0.3, -1.0, 0.4], [0.0, 0.2, 1.0]).unwrap();
        let (wr, tangent) = ([0.3, -1.0, 0.4], [0.0, 0.2, 1.0]);
        for a in grid() {
            let a = Angles::new(a.theta_i(), frame.theta_r(), a.phi()).unwrap();
            let wi = frame.to_world(&a);
            let exact = Angles::from_directions::<Libm>(wi, wr, tangent).unwrap();
            let [ti, tr, phi] = polynomial_angles::<Libm>(wi, wr, tangent).unwrap();
            let phi = phi.abs();
            assert!(close(ti, exact.theta_i(), 1e-6), "{a:?}");
            assert!(close(tr, exact.theta_r(), 1e-6), "{a:?}");
            if exact.theta_i().abs() < 1.5 {
                assert!(close(phi, exact.phi().abs(), 1e-5), "{a:?}");
            }
        }
        assert_eq!(
            polynomial_angles::<Libm>([0.0; 3], wr, tangent),
            Err(AngleError::Degenerate)
        );
        assert_eq!(
            polynomial_angles::<Libm>([f32::NAN; 3], wr, tangent),
            Err(AngleError::NonFinite)
        );
    }
}
