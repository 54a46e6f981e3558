//! Base colour → absorption (docs/model.md §14): the colour a thick coat of a preset's fibers
//! shows at each cortex absorption σ_ca ([`CoatColour`], measured by the random walk of
//! [`walk`] from a baked LUT), and its inverse per channel, [`Absorption::from_base_colour`]:
//! the σ_ca whose coat shows the colour an artist picked.
//!
//! A channel of the far field depends on its own σ_ca alone, and light transport is linear
//! per channel, so the coat's colour in a channel is one function c(σ) of that channel's σ_ca,
//! the same for R, G and B. [`CoatColour`] holds c at [`COAT_NODES`] values of σ_ca
//! ([`coat_node`]), made non-increasing; the inverse interpolates it linearly in the axis
//! coordinate √(σ/(σ + 1)), in which c is close to linear near σ = 0 (c(0) − c(σ) grows as √σ
//! in a thick, nearly lossless coat).

pub mod walk;

use crate::absorption::{Absorption, SIGMA_CA_MAX};
use crate::baked::BakedBcsdf;
use crate::math::Math;
use crate::spectrum::Rgb;
use core::fmt;
pub use walk::{coat_reflectance, CoatEstimate, CoatWalk, COAT_TANGENT_MAX_SIN};

/// Nodes of the coat colour table (docs/model.md §14).
pub const COAT_NODES: usize = 24;

/// The axis coordinate of σ_ca: √(σ/(σ + 1)).
#[must_use]
fn axis_coordinate(sigma: f32) -> f32 {
    libm::sqrtf(sigma / (sigma + 1.0))
}

/// The coordinate of [`SIGMA_CA_MAX`], the last node.
fn axis_end() -> f32 {
    axis_coordinate(SIGMA_CA_MAX)
}

/// σ_ca at axis coordinate `x` (the inverse of √(σ/(σ + 1))), clamped to [0, σ_max].
fn sigma_at(x: f32) -> f32 {
    let x2 = x * x;
    (x2 / (1.0 - x2).max(1e-12)).clamp(0.0, SIGMA_CA_MAX)
}

/// σ_ca of node `k` of the coat colour table: the coordinate √(σ/(σ + 1)) uniform from 0
/// (node 0, lossless) to that of σ_max = 1000 (the last node); `k` past the end is the last.
#[must_use]
pub fn coat_node(k: usize) -> f32 {
    let k = k.min(COAT_NODES - 1);
    if k == COAT_NODES - 1 {
        return SIGMA_CA_MAX;
    }
    sigma_at(axis_end() * k as f32 / (COAT_NODES - 1) as f32)
}

/// The colour of a thick coat at each node σ_ca ([`coat_node`]), one channel's function of its
/// own σ_ca (docs/model.md §14), non-increasing from the lossless coat (node 0, the brightest
/// colour the preset can show) to the fully absorbing one (the darkest).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CoatColour {
    colour: [f32; COAT_NODES],
}

/// Why a coat colour table was refused ([`CoatColour::from_colours`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CoatTableError {
    /// The first offending node.
    pub node: usize,
    /// Its colour.
    pub value: f32,
}

impl fmt::Display for CoatTableError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "invalid coat colour table: node {} = {} must be in [0, 1] and not above the node before it",
            self.node, self.value
        )
    }
}

impl core::error::Error for CoatTableError {}

impl CoatColour {
    /// A table from its node colours ([`coat_node`] order): each finite, in [0, 1] and not
    /// above the one before it.
    pub fn from_colours(colour: [f32; COAT_NODES]) -> Result<CoatColour, CoatTableError> {
        let mut prev = 1.0f32;
        for (node, &value) in colour.iter().enumerate() {
            if !(0.0..=prev).contains(&value) {
                return Err(CoatTableError { node, value });
            }
            prev = value;
        }
        Ok(CoatColour { colour })
    }

    /// Measures the table of a baked LUT (docs/model.md §14): the coat colour by
    /// [`coat_reflectance`] at the LUT read at each node (three nodes per walk, one per RGB
    /// channel, every walk with the same photon streams), then made non-increasing (each node
    /// at most the one before it; the walk's noise is shared between nodes, so this moves
    /// a node by about its standard error at most).
    ///
    /// Cost: [`COAT_NODES`]/3 walks; with [`CoatWalk::DEFAULT`] about 1–4 s on one core (0.9 s deer, 3.8 s human hair),
    /// longest for lossless fibers (long paths in a nearly lossless coat).
    #[must_use]
    pub fn measure<M: Math>(lut: &BakedBcsdf<'_, M>, walk: &CoatWalk) -> CoatColour {
        let mut colour = [0.0f32; COAT_NODES];
        for group in 0..COAT_NODES / 3 {
            let sigma = Rgb([
                coat_node(3 * group),
                coat_node(3 * group + 1),
                coat_node(3 * group + 2),
            ]);
            let at = Absorption::from_sigma(sigma).unwrap_or(Absorption::LOSSLESS);
            let est = coat_reflectance(&lut.at(&at), walk);
            for c in 0..3 {
                colour[3 * group + c] = est.colour[c];
            }
        }
        CoatColour::monotone(colour)
    }

    /// `colour` clamped to [0, 1] (NaN to 0) and made non-increasing.
    fn monotone(mut colour: [f32; COAT_NODES]) -> CoatColour {
        let mut prev = 1.0f32;
        for c in &mut colour {
            let v = if c.is_nan() { 0.0 } else { c.clamp(0.0, 1.0) };
            *c = v.min(prev);
            prev = *c;
        }
        CoatColour { colour }
    }

    /// The node colours, in [`coat_node`] order.
    #[must_use]
    pub fn colours(&self) -> &[f32; COAT_NODES] {
        &self.colour
    }

    /// The brightest colour a channel can show (the lossless coat, σ_ca = 0).
    #[must_use]
    pub fn brightest(&self) -> f32 {
        self.colour[0]
    }

    /// The darkest colour a channel can show (σ_ca = σ_max: the light the coat's surfaces
    /// reflect before any enters a cortex).
    #[must_use]
    pub fn darkest(&self) -> f32 {
        self.colour[COAT_NODES - 1]
    }

    /// The coat colour of one channel at σ_ca (the table, linear in √(σ/(σ + 1))); NaN or
    /// negative σ read as 0, above σ_max as σ_max.
    #[must_use]
    pub fn colour_at(&self, sigma: f32) -> f32 {
        let sigma = if sigma.is_nan() {
            0.0
        } else {
            sigma.clamp(0.0, SIGMA_CA_MAX)
        };
        let x = axis_coordinate(sigma) / axis_end() * (COAT_NODES - 1) as f32;
        let k = (x as usize).min(COAT_NODES - 2);
        let t = (x - k as f32).clamp(0.0, 1.0);
        self.colour[k] + t * (self.colour[k + 1] - self.colour[k])
    }

    /// The coat colour of an absorption, per channel ([`CoatColour::colour_at`]).
    #[must_use]
    pub fn colour_of(&self, absorption: &Absorption) -> Rgb {
        absorption.sigma().map(|s| self.colour_at(s))
    }

    /// The σ_ca whose coat shows `c` in one channel: the smallest σ_ca of the table's
    /// interpolant with colour `c`, for `c` within [`CoatColour::darkest`],
    /// [`CoatColour::brightest`]; outside, the nearest end (σ_max, 0).
    #[must_use]
    fn sigma_for(&self, c: f32) -> f32 {
        if c >= self.colour[0] {
            return 0.0;
        }
        for k in 0..COAT_NODES - 1 {
            let (hi, lo) = (self.colour[k], self.colour[k + 1]);
            if c >= lo {
                let t = if hi > lo { (hi - c) / (hi - lo) } else { 0.0 };
                let x = (k as f32 + t) / (COAT_NODES - 1) as f32 * axis_end();
                return sigma_at(x);
            }
        }
        SIGMA_CA_MAX
    }
}

/// A colour's absorption ([`Absorption::from_base_colour`]) and what the coat will show.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BaseColour {
    /// The σ_ca per channel.
    pub absorption: Absorption,
    /// The colour asked for.
    pub requested: Rgb,
    /// The colour the coat shows at `absorption` (the table's): `requested` where it was
    /// reachable, the nearest reachable colour in a clamped channel.
    pub shown: Rgb,
    /// Per channel: whether the requested colour was out of reach (brighter than the lossless
    /// coat or darker than the fully absorbing one) and was clamped.
    pub clamped: [bool; 3],
}

impl BaseColour {
    /// Whether any channel was clamped (the coat cannot show the requested colour).
    #[must_use]
    pub fn is_clamped(&self) -> bool {
        self.clamped.iter().any(|&c| c)
    }
}

impl fmt::Display for BaseColour {
    /// `base colour [r, g, b] -> sigma_ca [..]`, and when clamped what the coat shows instead.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let [r, g, b] = self.requested.0;
        let [sr, sg, sb] = self.absorption.sigma().0;
        write!(
            f,
            "base colour [{r}, {g}, {b}] -> sigma_ca [{sr:.4}, {sg:.4}, {sb:.4}]"
        )?;
        if self.is_clamped() {
            let [cr, cg, cb] = self.shown.0;
            let names: [&str; 3] = ["R", "G", "B"];
            write!(f, "; out of this fur's reach in")?;
            for (c, name) in names.iter().enumerate() {
                if self.clamped[c] {
                    write!(f, " {name}")?;
                }
            }
            write!(f, ", the coat shows [{cr:.4}, {cg:.4}, {cb:.4}] instead")?;
        }
        Ok(())
    }
}

/// Why a base colour was refused: a channel is NaN or outside [0, 1].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BaseColourError {
    /// The first offending channel, 0–2 (R, G, B).
    pub channel: usize,
    /// Its value.
    pub value: f32,
}

impl fmt::Display for BaseColourError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "invalid base_colour channel {} = {}: a linear colour channel must be in [0, 1]",
            ["R", "G", "B"][self.channel.min(2)],
            self.value
        )
    }
}

impl core::error::Error for BaseColourError {}

impl Absorption {
    /// The σ_ca per channel whose thick coat shows the linear RGB colour `colour`
    /// (docs/model.md §14), from a preset's [`CoatColour`] table. A channel NaN or outside
    /// [0, 1] is refused ([`BaseColourError`]); a channel the coat cannot show (brighter than
    /// its lossless coat, or darker than its fully absorbing one) is clamped to the nearest
    /// reachable colour and reported in [`BaseColour::clamped`].
    ///
    /// ```
    /// use bcsdf_core::colour::{coat_node, CoatColour, COAT_NODES};
    /// use bcsdf_core::{Absorption, Rgb};
    ///
    /// // A made-up table: c(σ) = 0.02 + 0.9/(1 + 4σ).
    /// let coat = CoatColour::from_colours(core::array::from_fn(|k| {
    ///     0.02 + 0.9 / (1.0 + 4.0 * coat_node(k))
    /// }))
    /// .unwrap();
    /// let brown = Absorption::from_base_colour(Rgb([0.3, 0.15, 0.06]), &coat).unwrap();
    /// assert!(!brown.is_clamped());
    /// let s = brown.absorption.sigma();
    /// assert!(s[0] < s[1] && s[1] < s[2]);
    /// // Whiter than the lossless coat: clamped to it, and said so.
    /// let white = Absorption::from_base_colour(Rgb::splat(0.95), &coat).unwrap();
    /// assert_eq!(white.clamped, [true; 3]);
    /// assert_eq!(white.absorption.sigma(), Rgb::ZERO);
    /// assert!(Absorption::from_base_colour(Rgb([0.5, f32::NAN, 0.5]), &coat).is_err());
    /// # let _ = COAT_NODES;
    /// ```
    pub fn from_base_colour(colour: Rgb, coat: &CoatColour) -> Result<BaseColour, BaseColourError> {
        for (channel, &value) in colour.0.iter().enumerate() {
            if !(0.0..=1.0).contains(&value) {
                return Err(BaseColourError { channel, value });
            }
        }
        let sigma = colour.map(|c| coat.sigma_for(c));
        let absorption = Absorption::from_sigma(sigma).unwrap_or(Absorption::LOSSLESS);
        let clamped = colour.0.map(|c| c > coat.brightest() || c < coat.darkest());
        let mut shown = colour;
        for c in 0..3 {
            if clamped[c] {
                shown[c] = colour[c].clamp(coat.darkest(), coat.brightest());
            }
        }
        Ok(BaseColour {
            absorption,
            requested: colour,
            shown,
            clamped,
        })
    }
}

#[cfg(test)]
mod tests;
