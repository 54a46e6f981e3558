//! What light paths a render includes (docs/model.md §13): the reference `path`, and the
//! two engine approximations judged against it, `single` and `dual`.
//!
//! - [`Method::Path`]: full path tracing (docs/model.md §11).
//! - [`Method::Single`]: no fiber→fiber step. At a fiber, next-event estimation with a binary
//!   shadow ray (any fiber or surface blocks); the path then goes on, by sampling the fiber,
//!   only to the first surface behind the fibers on its way, and only if it crosses none
//!   (V = 1): light from skin and ground reaches a fiber as it does in `path` (an engine's
//!   indirect lighting), light from other fibers never does. Skin and ground are path traced
//!   as in `path` (a ray bounced off them that meets a fiber is shaded the same way).
//! - [`Method::Dual`]: `single`, but every ray toward a fiber's light — the shadow ray to a
//!   light and the sampled ray to a surface — counts the fibers it crosses (n; a surface
//!   still blocks a shadow ray) and the fiber's weight is S·V + D(n), the dual-scattering
//!   term of [`bcsdf_core::dual::DualLut::eval`] with V = 1 when n = 0 and 0 otherwise: the
//!   fiber→fiber steps `single` leaves out, stood in for by D, for direct and indirect light
//!   alike.
//!
//! At a fiber both approximations use light sampling alone for lights (weight 1, whatever
//! the [`crate::Strategy`]; a sampled ray that escapes adds nothing); the random numbers
//! drawn per vertex are those of `path`, so a render is the same bits for any thread count.

use crate::scatter::Scatterer;
use crate::scene::CoatBelow;
use bcsdf_core::dual::{coat, Density, DualLut, Fibers};
use bcsdf_core::{Angles, Libm};
use core::fmt;
use core::str::FromStr;
use nalgebra::Vector3;

/// Which light paths a render includes, with what the `dual` method needs.
#[derive(Clone, Copy, Debug)]
pub enum Method<'a> {
    /// Full path tracing, the reference.
    Path,
    /// Single scattering at fibers (binary shadow rays).
    Single,
    /// Single scattering with counted shadow rays plus the dual-scattering term.
    Dual {
        /// The fiber's dual-scattering evaluator (the decoded `.furdual` blob of the rendered
        /// BCSDF's tables, the attenuation in it).
        lut: &'a DualLut,
        /// d_f, d_b.
        density: Density,
    },
}

/// The method's name without its data (the command line's `--method`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MethodKind {
    /// [`Method::Path`].
    Path,
    /// [`Method::Single`].
    Single,
    /// [`Method::Dual`].
    Dual,
}

impl MethodKind {
    /// Every method, in the order `--help` lists them.
    pub const ALL: [MethodKind; 3] = [MethodKind::Path, MethodKind::Dual, MethodKind::Single];

    /// The name on the command line.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            MethodKind::Path => "path",
            MethodKind::Single => "single",
            MethodKind::Dual => "dual",
        }
    }
}

impl fmt::Display for MethodKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for MethodKind {
    type Err = String;

    fn from_str(s: &str) -> Result<MethodKind, String> {
        MethodKind::ALL
            .into_iter()
            .find(|k| k.name() == s)
            .ok_or_else(|| format!("unknown method `{s}` (expected path, dual or single)"))
    }
}

impl Method<'_> {
    /// The kind of this method.
    #[must_use]
    pub fn kind(&self) -> MethodKind {
        match self {
            Method::Path => MethodKind::Path,
            Method::Single => MethodKind::Single,
            Method::Dual { .. } => MethodKind::Dual,
        }
    }

    /// What a fiber returns toward `wr` for unit radiance from `wi` when the ray toward the
    /// light (or surface) crossed `fibers` fibers: S·cos θ_i·V, plus D·cos θ_i for `dual`
    /// (RGB, ≥ 0, finite), whose coat below the point `below` finds (called for `dual`
    /// only: [`crate::scene::Scene::fibers_below`] casts one more ray): its count along the
    /// light's line and the light's incidence on the skin under the fiber, turned into the
    /// term's count by [`bcsdf_core::dual::coat::below_at_incidence`] (docs/model.md §13,
    /// "The light's incidence on the coat").
    pub(crate) fn fiber_light<S: Scatterer>(
        &self,
        fiber: &S,
        wi: &Vector3<f32>,
        wr: &Vector3<f32>,
        tangent: &Vector3<f32>,
        fibers: u32,
        below: impl FnOnce() -> CoatBelow,
    ) -> [f32; 3] {
        let mut value = if fibers == 0 {
            fiber.eval(wi, wr, tangent).0
        } else {
            [0.0; 3]
        };
        if let Method::Dual { lut, density } = self {
            if let Ok(a) =
                Angles::from_directions::<Libm>((*wi).into(), (*wr).into(), (*tangent).into())
            {
                let cos = a.theta_i().cos().max(0.0);
                // The coat below as the light scattered inside the coat sees it: the count
                // along the light's line, rescaled by the light's incidence on the skin under
                // the fiber where the scene knows it (docs/model.md §13).
                let below = below();
                let m = coat::below_at_incidence(below.count as f32, below.incidence);
                let counts = Fibers::new(fibers as f32, m);
                let density = Density {
                    d_f: coat::forward_density_at_incidence(density.d_f, below.incidence),
                    ..*density
                };
                let d = lut.eval(&a, counts, density);
                for c in 0..3 {
                    let v = d[c] * cos;
                    if v.is_finite() && v > 0.0 {
                        value[c] += v;
                    }
                }
            }
        }
        value
    }
}
