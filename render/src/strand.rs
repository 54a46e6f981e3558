//! Per-strand colour (docs/model.md §14, "Per-strand colour"): what a fiber scatters like at
//! a hit, as a material ([`FiberMaterial`]) the integrator asks once per fiber vertex with
//! the strand and the position along it ([`StrandPoint`]).
//!
//! Any [`Scatterer`] is a material of one colour (every hit gets the scatterer itself).
//! [`Coloured`] colours each hit from a [`StrandColour`]: a linear base colour interpolated
//! from root to tip, times a per-strand factor drawn from the scene seed and the fiber id,
//! turned into σ_ca per channel through a preset's coat colour table
//! ([`Absorption::from_base_colour`]); the BCSDF is then read at that σ_ca through
//! [`Recolour`]: the baked LUT per query ([`BakedBcsdf::at`]), the analytic model as the
//! model of those parameters ([`AnalyticColours`]).
//!
//! ```
//! use bcsdf_core::colour::{coat_node, CoatColour};
//! use bcsdf_core::Rgb;
//! use render::strand::{StrandColour, StrandPoint};
//!
//! let coat = CoatColour::from_colours(core::array::from_fn(|k| {
//!     0.02 + 0.9 / (1.0 + 4.0 * coat_node(k))
//! }))
//! .unwrap();
//! let colour = StrandColour::new(Rgb([0.3, 0.15, 0.07]), Rgb([0.8, 0.7, 0.5]), 0.0, 1).unwrap();
//! let root = StrandPoint { fiber: 3, v: 0.0 };
//! let tip = StrandPoint { fiber: 3, v: 1.0 };
//! assert_eq!(colour.base_colour(&root), Rgb([0.3, 0.15, 0.07]));
//! // A darker colour absorbs more.
//! let (r, t) = (colour.absorption(&root, &coat), colour.absorption(&tip, &coat));
//! assert!(r.sigma()[0] > t.sigma()[0]);
//! ```

use crate::scatter::{Owned, Scatterer};
use bcsdf_core::baked::{BakedAt, BakedBcsdf};
use bcsdf_core::colour::{BaseColourError, CoatColour};
use bcsdf_core::rng::{cell_stream, Pcg32};
use bcsdf_core::{Absorption, Bcsdf, FurBcsdf, Math, Rgb};
use core::fmt;

/// Where a ray met a fiber: which strand, and how far along it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StrandPoint {
    /// The fiber's index (the scene's, [`crate::fiber::FiberSegment::fiber`]).
    pub fiber: u32,
    /// Position along the strand: 0 at the root, 1 at the tip.
    pub v: f32,
}

/// What a fiber scatters like at a hit: the scatterer of the strand at that point. The
/// integrator asks once per fiber vertex and uses the answer for light sampling, the
/// scattered direction and, for `dual`, the method's terms.
pub trait FiberMaterial: Sync {
    /// The scatterer at one point of a strand.
    type At<'s>: Scatterer
    where
        Self: 's;

    /// The scatterer at `point`.
    fn at(&self, point: &StrandPoint) -> Self::At<'_>;
}

/// A scatterer is a material of one colour: the same scatterer at every point.
impl<S: Scatterer> FiberMaterial for S {
    type At<'s>
        = &'s S
    where
        S: 's;

    #[inline]
    fn at(&self, _: &StrandPoint) -> &S {
        self
    }
}

/// A BCSDF that can be read at any colour (σ_ca per channel).
pub trait Recolour: Sync {
    /// The BCSDF at one colour.
    type At<'s>: Bcsdf + Sync
    where
        Self: 's;

    /// This BCSDF at colour `absorption`.
    fn recolour(&self, absorption: &Absorption) -> Self::At<'_>;
}

/// A baked LUT at a colour per query: each channel reads table `N` at its own σ_ca.
impl<'a, M: Math + Sync> Recolour for BakedBcsdf<'a, M> {
    type At<'s>
        = BakedAt<'s, 'a, M>
    where
        Self: 's;

    #[inline]
    fn recolour(&self, absorption: &Absorption) -> BakedAt<'_, 'a, M> {
        self.at(absorption)
    }
}

/// The analytic model at a colour per query ([`FurBcsdf::at_absorption`]): a model without
/// a residual table (the report closure, or the energy closure without its residual), since
/// a residual table belongs to one σ_ca (docs/model.md §12).
#[derive(Clone, Copy, Debug)]
pub struct AnalyticColours<'a, M: Math>(FurBcsdf<'a, M>);

impl<'a, M: Math> AnalyticColours<'a, M> {
    /// `model` at any colour, or `None` when it carries a residual table.
    #[must_use]
    pub fn new(model: FurBcsdf<'a, M>) -> Option<AnalyticColours<'a, M>> {
        model
            .at_absorption(&Absorption::LOSSLESS)
            .map(|_| AnalyticColours(model))
    }
}

impl<'a, M: Math + Sync> Recolour for AnalyticColours<'a, M> {
    type At<'s>
        = FurBcsdf<'a, M>
    where
        Self: 's;

    #[inline]
    fn recolour(&self, absorption: &Absorption) -> FurBcsdf<'a, M> {
        // `new` checked that the model has no residual, the only refusal.
        self.0.at_absorption(absorption).unwrap_or(self.0)
    }
}

/// Why a [`StrandColour`] was refused.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum StrandColourError {
    /// The root colour: a channel NaN or outside [0, 1].
    Root(BaseColourError),
    /// The tip colour: a channel NaN or outside [0, 1].
    Tip(BaseColourError),
    /// The per-strand variation is NaN or outside [0, [`StrandColour::MAX_JITTER`]].
    Jitter(f32),
}

impl fmt::Display for StrandColourError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            StrandColourError::Root(e) => write!(f, "root colour: {e}"),
            StrandColourError::Tip(e) => write!(f, "tip colour: {e}"),
            StrandColourError::Jitter(j) => write!(
                f,
                "per-strand variation {j} must be in [0, {}]",
                StrandColour::MAX_JITTER
            ),
        }
    }
}

impl std::error::Error for StrandColourError {}

/// The base colour of every point of every strand: linear RGB from `root` (v = 0) to `tip`
/// (v = 1), times a per-strand factor 1 + j·(2u − 1) with u uniform in [0, 1) drawn from the
/// seed and the fiber id alone (the same on any thread count, in any order), each channel
/// then clamped to [0, 1]. One factor for all three channels: the variation is in lightness,
/// not hue.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StrandColour {
    root: Rgb,
    tip: Rgb,
    jitter: f32,
    seed: u64,
}

/// The stream table of the per-strand factor ([`cell_stream`]'s `table`): "strand".
const STRAND_TABLE: u64 = 0x7374_7261_6e64;

impl StrandColour {
    /// The largest per-strand variation: ±100 %.
    pub const MAX_JITTER: f32 = 1.0;

    /// Root and tip colours (linear, each channel in [0, 1]), the per-strand variation `jitter`
    /// (a fraction: 0.1 is ±10 %) and the seed of the per-strand factors (a scene's seed).
    pub fn new(root: Rgb, tip: Rgb, jitter: f32, seed: u64) -> Result<Self, StrandColourError> {
        check(root).map_err(StrandColourError::Root)?;
        check(tip).map_err(StrandColourError::Tip)?;
        if !(0.0..=Self::MAX_JITTER).contains(&jitter) {
            return Err(StrandColourError::Jitter(jitter));
        }
        Ok(StrandColour {
            root,
            tip,
            jitter,
            seed,
        })
    }

    /// A strand colour from parts its caller has checked (channels in [0, 1], `jitter` in
    /// [0, [`StrandColour::MAX_JITTER`]]): [`crate::pattern::Patterned`]'s per-fiber roots.
    pub(crate) fn checked_parts(root: Rgb, tip: Rgb, jitter: f32, seed: u64) -> Self {
        StrandColour {
            root,
            tip,
            jitter,
            seed,
        }
    }

    /// The per-strand factor of fiber `fiber`: exactly 1 without variation.
    #[must_use]
    pub fn factor(&self, fiber: u32) -> f32 {
        if self.jitter == 0.0 {
            return 1.0;
        }
        let stream = cell_stream(self.seed, STRAND_TABLE, u64::from(fiber));
        let u = Pcg32::new(self.seed, stream).uniform();
        1.0 + self.jitter * (2.0 * u - 1.0)
    }

    /// The base colour at `point` (v outside [0, 1] read as the nearest end, NaN as the root).
    #[must_use]
    pub fn base_colour(&self, point: &StrandPoint) -> Rgb {
        let v = if point.v.is_nan() {
            0.0
        } else {
            point.v.clamp(0.0, 1.0)
        };
        let f = self.factor(point.fiber);
        let mut c = self.root;
        for k in 0..3 {
            c[k] = ((self.root[k] + (self.tip[k] - self.root[k]) * v) * f).clamp(0.0, 1.0);
        }
        c
    }

    /// σ_ca at `point`: its base colour through the coat colour table `coat`
    /// ([`Absorption::from_base_colour`]; a colour out of the fur's reach gets the nearest it
    /// can show, as a uniform colour does).
    #[must_use]
    pub fn absorption(&self, point: &StrandPoint, coat: &CoatColour) -> Absorption {
        // The base colour is in [0, 1] per channel, never NaN: never refused.
        Absorption::from_base_colour(self.base_colour(point), coat)
            .map_or(Absorption::LOSSLESS, |b| b.absorption)
    }
}

fn check(c: Rgb) -> Result<(), BaseColourError> {
    for (channel, &value) in c.0.iter().enumerate() {
        if !(0.0..=1.0).contains(&value) {
            return Err(BaseColourError { channel, value });
        }
    }
    Ok(())
}

/// A BCSDF coloured per hit: the colour of [`StrandColour`] at the hit, through the preset's
/// coat colour table, read by [`Recolour`].
#[derive(Clone, Copy, Debug)]
pub struct Coloured<'c, R> {
    /// The BCSDF (a baked LUT, or [`AnalyticColours`]).
    pub fur: &'c R,
    /// The coat colour table of the BCSDF's preset (`CoatColour::measure` for a LUT).
    pub coat: &'c CoatColour,
    /// The colour of every point of every strand.
    pub colour: StrandColour,
}

impl<'c, R: Recolour> FiberMaterial for Coloured<'c, R> {
    type At<'s>
        = Owned<R::At<'c>>
    where
        Self: 's;

    #[inline]
    fn at(&self, point: &StrandPoint) -> Owned<R::At<'c>> {
        Owned(self.fur.recolour(&self.colour.absorption(point, self.coat)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn colours_grade_from_root_to_tip_and_vary_per_strand() {
        let (root, tip) = (Rgb([0.2, 0.1, 0.05]), Rgb([0.8, 0.6, 0.4]));
        let c = StrandColour::new(root, tip, 0.0, 7).unwrap();
        let at = |fiber, v| c.base_colour(&StrandPoint { fiber, v });
        assert_eq!(at(0, 0.0), root);
        assert_eq!(at(0, 1.0), tip);
        assert_eq!(at(0, 2.0), tip);
        assert_eq!(at(0, f32::NAN), root);
        assert!((at(5, 0.5)[1] - 0.35).abs() < 1e-6);
        let j = StrandColour::new(root, tip, 0.3, 7).unwrap();
        let factors: Vec<f32> = (0..1000).map(|f| j.factor(f)).collect();
        assert!(factors.iter().all(|f| (0.7..1.3).contains(f)));
        let mean = factors.iter().sum::<f32>() / 1000.0;
        assert!((mean - 1.0).abs() < 0.02, "{mean}");
        assert_eq!(j.factor(12), j.factor(12));
        assert_ne!(j.factor(12), j.factor(13));
        assert_ne!(
            j.factor(12),
            StrandColour::new(root, tip, 0.3, 8).unwrap().factor(12)
        );
    }

    #[test]
    fn bad_colours_are_refused_by_name() {
        let ok = Rgb::splat(0.5);
        let e = StrandColour::new(Rgb([0.5, 1.5, 0.5]), ok, 0.0, 1).unwrap_err();
        assert!(e.to_string().starts_with("root colour") && e.to_string().contains('G'));
        let e = StrandColour::new(ok, Rgb([f32::NAN, 0.5, 0.5]), 0.0, 1).unwrap_err();
        assert!(e.to_string().starts_with("tip colour"));
        for j in [-0.1, 1.5, f32::NAN] {
            assert!(StrandColour::new(ok, ok, j, 1).is_err());
        }
    }
}
