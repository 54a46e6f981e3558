//! A colour per fiber from where its root is on the body (docs/model.md §14, "Stripes and
//! textures"): stripes of a second colour over a base colour, or an image, looked up at the
//! root's texture coordinates ([`crate::scenes::body_uv`]). [`RootColours`] holds the colour of
//! every fiber of a scene, computed once before the render; [`Patterned`] is the material that
//! reads it at each hit and grades it to the tip as [`crate::strand::Coloured`] does.
//!
//! ```
//! use bcsdf_core::Rgb;
//! use render::pattern::BodyColour;
//!
//! let stripes = BodyColour::stripes(Rgb::splat(0.5), Rgb([0.05, 0.04, 0.03]), 0.25).unwrap();
//! // Bands of width 0.25 in u: base, stripe, base, stripe.
//! assert_eq!(stripes.at([0.1, 0.5]), Rgb::splat(0.5));
//! assert_eq!(stripes.at([0.3, 0.5]), Rgb([0.05, 0.04, 0.03]));
//! assert_eq!(stripes.at([0.6, 0.9]), Rgb::splat(0.5));
//! ```

use crate::scatter::Owned;
use crate::scene::Scene;
use crate::scenes::{body_uv, SceneKind};
use crate::strand::{FiberMaterial, Recolour, StrandColour, StrandColourError, StrandPoint};
use bcsdf_core::colour::CoatColour;
use bcsdf_core::Rgb;
use core::fmt;

/// Why a stripe pattern or a texture was refused.
#[derive(Clone, Debug, PartialEq)]
pub enum PatternError {
    /// The stripes' width is NaN or outside (0, 1].
    Width(f32),
    /// A colour channel is NaN or outside [0, 1] (which colour, the channel, its value).
    Colour(&'static str, usize, f32),
    /// The image could not be decoded, or is larger than [`Texture::MAX_SIDE`].
    Image(String),
}

impl fmt::Display for PatternError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            PatternError::Width(w) => write!(
                f,
                "stripe width {w} must be in (0, 1] (a fraction of the body's u coordinate)"
            ),
            PatternError::Colour(which, c, v) => write!(
                f,
                "{which} colour channel {} = {v} must be in [0, 1] (a linear colour)",
                ["R", "G", "B"][(*c).min(2)]
            ),
            PatternError::Image(m) => f.write_str(m),
        }
    }
}

impl std::error::Error for PatternError {}

/// The sRGB transfer function's inverse (IEC 61966-2-1): an encoded value in [0, 1] to linear.
#[inline]
#[must_use]
pub fn srgb_decode(e: f32) -> f32 {
    let e = e.clamp(0.0, 1.0);
    if e <= 0.040_45 {
        e / 12.92
    } else {
        ((e + 0.055) / 1.055).powf(2.4)
    }
}

/// A 2D image of linear colours, looked up bilinearly at (u, v) ∈ [0, 1]²: u across, from the
/// left column's centre to the right column's; v down, from the top row to the bottom row;
/// coordinates outside read the edge.
#[derive(Clone, Debug, PartialEq)]
pub struct Texture {
    width: usize,
    height: usize,
    texels: Vec<Rgb>,
}

impl Texture {
    /// The largest width or height accepted (the texels take 12 bytes each).
    pub const MAX_SIDE: u32 = 8192;

    /// A texture of `width` × `height` linear colours, row by row from the top; `None` when
    /// a side is 0 or the count does not match.
    #[must_use]
    pub fn from_linear(width: usize, height: usize, texels: Vec<Rgb>) -> Option<Texture> {
        (width > 0 && height > 0 && texels.len() == width * height).then_some(Texture {
            width,
            height,
            texels,
        })
    }

    /// Decodes a PNG (grey, grey + alpha, RGB, RGBA or palette; 1 to 16 bits): its values are
    /// sRGB-encoded and become linear through [`srgb_decode`]; alpha is ignored.
    pub fn from_png(bytes: &[u8]) -> Result<Texture, PatternError> {
        let bad = |e: &dyn fmt::Display| PatternError::Image(format!("not a readable PNG: {e}"));
        let mut decoder = png::Decoder::new(bytes);
        decoder.set_transformations(png::Transformations::EXPAND);
        let mut reader = decoder.read_info().map_err(|e| bad(&e))?;
        let (w, h) = (reader.info().width, reader.info().height);
        if w > Self::MAX_SIDE || h > Self::MAX_SIDE {
            return Err(PatternError::Image(format!(
                "a {w} x {h} image is larger than {0} x {0}",
                Self::MAX_SIDE
            )));
        }
        let mut buf = vec![0u8; reader.output_buffer_size()];
        let frame = reader.next_frame(&mut buf).map_err(|e| bad(&e))?;
        let data = &buf[..frame.buffer_size()];
        let channels = frame.color_type.samples();
        let (scale, bytes_per) = match frame.bit_depth {
            png::BitDepth::Sixteen => (65535.0f32, 2),
            // EXPAND makes 1, 2 and 4 bits 8.
            _ => (255.0f32, 1),
        };
        let sample = |i: usize| -> f32 {
            let v = if bytes_per == 2 {
                u16::from_be_bytes([data[2 * i], data[2 * i + 1]]) as f32
            } else {
                f32::from(data[i])
            };
            srgb_decode(v / scale)
        };
        let (width, height) = (frame.width as usize, frame.height as usize);
        let texels = (0..width * height)
            .map(|p| {
                let base = p * channels;
                if channels >= 3 {
                    Rgb([sample(base), sample(base + 1), sample(base + 2)])
                } else {
                    Rgb::splat(sample(base))
                }
            })
            .collect();
        Texture::from_linear(width, height, texels)
            .ok_or_else(|| PatternError::Image("an empty image".to_string()))
    }

    /// Width and height in texels.
    #[must_use]
    pub fn size(&self) -> (usize, usize) {
        (self.width, self.height)
    }

    /// The texel in column `x`, row `y` (0 at the top), clamped to the image.
    #[must_use]
    pub fn texel(&self, x: usize, y: usize) -> Rgb {
        self.texels[y.min(self.height - 1) * self.width + x.min(self.width - 1)]
    }

    /// The colour at (u, v): bilinear between the four nearest texel centres (texel (x, y)'s
    /// centre at u = x/(width − 1), v = y/(height − 1); one texel across is that texel); NaN
    /// reads as 0.
    #[must_use]
    pub fn at(&self, uv: [f32; 2]) -> Rgb {
        let coord = |t: f32, n: usize| -> (usize, usize, f32) {
            let t = if t.is_nan() { 0.0 } else { t.clamp(0.0, 1.0) };
            let x = t * (n - 1) as f32;
            let i = (x as usize).min(n - 1);
            (i, (i + 1).min(n - 1), x - i as f32)
        };
        let (x0, x1, fx) = coord(uv[0], self.width);
        let (y0, y1, fy) = coord(uv[1], self.height);
        let mix = |a: Rgb, b: Rgb, t: f32| Rgb(core::array::from_fn(|c| a[c] + (b[c] - a[c]) * t));
        let top = mix(self.texel(x0, y0), self.texel(x1, y0), fx);
        let bottom = mix(self.texel(x0, y1), self.texel(x1, y1), fx);
        let c = mix(top, bottom, fy);
        Rgb(c.0.map(|v| v.clamp(0.0, 1.0)))
    }
}

/// A linear base colour as a function of the texture coordinates (u, v) of a fiber's root.
#[derive(Clone, Debug, PartialEq)]
pub enum BodyColour {
    /// Bands of width `width` in u, alternately `base` and `stripe`: u in [2kw, (2k + 1)w)
    /// is `base`, u in [(2k + 1)w, (2k + 2)w) `stripe`.
    Stripes {
        /// The colour between the stripes.
        base: Rgb,
        /// The stripes' colour.
        stripe: Rgb,
        /// Width of one band, as a fraction of u.
        width: f32,
    },
    /// An image ([`Texture::at`]).
    Texture(Texture),
}

impl BodyColour {
    /// The default stripe width: ten bands across the body.
    pub const STRIPE_WIDTH: f32 = 0.1;

    /// Stripes of `stripe` over `base`, `width` in (0, 1]; both colours linear, each channel
    /// in [0, 1].
    pub fn stripes(base: Rgb, stripe: Rgb, width: f32) -> Result<BodyColour, PatternError> {
        for (which, c) in [("base", base), ("stripe", stripe)] {
            for (k, &v) in c.0.iter().enumerate() {
                if !(0.0..=1.0).contains(&v) {
                    return Err(PatternError::Colour(which, k, v));
                }
            }
        }
        if !(width > 0.0 && width <= 1.0) {
            return Err(PatternError::Width(width));
        }
        Ok(BodyColour::Stripes {
            base,
            stripe,
            width,
        })
    }

    /// The colour at texture coordinates `uv` (each channel in [0, 1]).
    #[must_use]
    pub fn at(&self, uv: [f32; 2]) -> Rgb {
        match self {
            BodyColour::Stripes {
                base,
                stripe,
                width,
            } => {
                let u = if uv[0].is_nan() { 0.0 } else { uv[0] };
                let band = (u / width).floor() as i64;
                if band.rem_euclid(2) == 1 {
                    *stripe
                } else {
                    *base
                }
            }
            BodyColour::Texture(t) => t.at(uv),
        }
    }
}

/// The root colour of every fiber of a scene, by fiber index: [`BodyColour::at`] the root's
/// texture coordinates ([`body_uv`]; the root is the start of the fiber's segment at v = 0).
#[derive(Clone, Debug, PartialEq)]
pub struct RootColours {
    colours: Vec<Rgb>,
}

impl RootColours {
    /// The root colours of the fibers of `scene`, built as scene `kind`.
    #[must_use]
    pub fn new(scene: &Scene, kind: SceneKind, body: &BodyColour) -> RootColours {
        let segments = scene.fibers.segments();
        let fibers = segments
            .iter()
            .map(|s| s.fiber as usize + 1)
            .max()
            .unwrap_or(0);
        let mut colours = vec![body.at([0.0, 0.0]); fibers];
        for s in segments.iter().filter(|s| s.v0 == 0.0) {
            colours[s.fiber as usize] = body.at(body_uv(kind, &s.p0));
        }
        RootColours { colours }
    }

    /// The root colour of fiber `fiber` (black past the scene's fibers).
    #[must_use]
    pub fn colour(&self, fiber: u32) -> Rgb {
        self.colours
            .get(fiber as usize)
            .copied()
            .unwrap_or(Rgb::ZERO)
    }

    /// Every fiber's root colour, by fiber index.
    #[must_use]
    pub fn colours(&self) -> &[Rgb] {
        &self.colours
    }
}

/// A BCSDF coloured per hit from each fiber's root colour ([`RootColours`]), graded to a tip
/// colour and varied per strand exactly as [`crate::strand::Coloured`] does with one root
/// colour (the same [`StrandColour`] with that fiber's root).
#[derive(Clone, Copy, Debug)]
pub struct Patterned<'c, R> {
    fur: &'c R,
    coat: &'c CoatColour,
    roots: &'c RootColours,
    tip: Option<Rgb>,
    jitter: f32,
    seed: u64,
}

impl<'c, R> Patterned<'c, R> {
    /// `fur` (a baked LUT, or [`crate::strand::AnalyticColours`]) coloured by `roots` through
    /// the coat colour table `coat`; `tip` the colour at the tips (`None`: each fiber's root
    /// colour along the whole strand), `jitter` and `seed` the per-strand variation of
    /// [`StrandColour::new`] (checked there, as is `tip`).
    pub fn new(
        fur: &'c R,
        coat: &'c CoatColour,
        roots: &'c RootColours,
        tip: Option<Rgb>,
        jitter: f32,
        seed: u64,
    ) -> Result<Self, StrandColourError> {
        let grey = Rgb::splat(0.5);
        StrandColour::new(grey, tip.unwrap_or(grey), jitter, seed)?;
        Ok(Patterned {
            fur,
            coat,
            roots,
            tip,
            jitter,
            seed,
        })
    }

    /// The strand colour of fiber `fiber`: its root colour, the tip colour, the variation.
    #[must_use]
    pub fn strand(&self, fiber: u32) -> StrandColour {
        let root = self.roots.colour(fiber);
        // Root colours are in [0, 1] (`BodyColour::at`); the tip and jitter were checked.
        StrandColour::checked_parts(root, self.tip.unwrap_or(root), self.jitter, self.seed)
    }
}

impl<'c, R: Recolour> FiberMaterial for Patterned<'c, R> {
    type At<'s>
        = Owned<R::At<'c>>
    where
        Self: 's;

    #[inline]
    fn at(&self, point: &StrandPoint) -> Owned<R::At<'c>> {
        let strand = self.strand(point.fiber);
        Owned(self.fur.recolour(&strand.absorption(point, self.coat)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn srgb_decode_inverts_the_encoding() {
        for i in 0..=100 {
            let v = i as f32 / 100.0;
            let back = srgb_decode(crate::output::srgb_encode(v));
            assert!((back - v).abs() < 1e-5, "{v} -> {back}");
        }
        assert_eq!(srgb_decode(0.0), 0.0);
        assert_eq!(srgb_decode(1.0), 1.0);
    }

    #[test]
    fn stripes_alternate_and_bad_ones_are_refused() {
        let (a, b) = (Rgb::splat(0.6), Rgb::splat(0.1));
        let s = BodyColour::stripes(a, b, 0.1).unwrap();
        let bands: Vec<bool> = (0..10)
            .map(|k| s.at([k as f32 / 10.0 + 0.05, 0.3]) == b)
            .collect();
        assert_eq!(
            bands,
            [false, true, false, true, false, true, false, true, false, true]
        );
        for w in [0.0, -0.1, 1.5, f32::NAN] {
            assert!(matches!(
                BodyColour::stripes(a, b, w),
                Err(PatternError::Width(_))
            ));
        }
        assert!(matches!(
            BodyColour::stripes(a, Rgb([0.1, 2.0, 0.1]), 0.1),
            Err(PatternError::Colour("stripe", 1, _))
        ));
    }

    #[test]
    fn textures_interpolate_between_texel_centres() {
        let t = Texture::from_linear(
            2,
            2,
            vec![
                Rgb::splat(0.0),
                Rgb::splat(1.0),
                Rgb::splat(0.5),
                Rgb::splat(0.25),
            ],
        )
        .unwrap();
        assert_eq!(t.at([0.0, 0.0]), Rgb::splat(0.0));
        assert_eq!(t.at([1.0, 0.0]), Rgb::splat(1.0));
        assert_eq!(t.at([0.0, 1.0]), Rgb::splat(0.5));
        assert_eq!(t.at([0.5, 0.0]), Rgb::splat(0.5));
        assert_eq!(t.at([2.0, f32::NAN]), Rgb::splat(1.0));
        assert!(Texture::from_linear(0, 1, Vec::new()).is_none());
        assert!(Texture::from_png(b"not a png").is_err());
    }
}
