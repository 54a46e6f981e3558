//! A picture of a fur patch rendered with the far-field BCSDF: [`FIBER_COUNT`] roughly
//! parallel, slightly curved, tapering fibers (thin cylinders whose tangent turns along their length,
//! in the image plane and towards or away from the viewer), seen orthographically against a
//! dark background and lit by one directional light ([`LIGHT`], a rim light from the left).
//!
//! In the far field the radiance leaving a fiber depends only on the directions and the
//! local tangent, so each centre-line segment gets one value,
//! L = S(ω_i, ω_r; tangent)·cos θ_i·E with E = 1, and is drawn as an antialiased band as wide
//! as the fiber; fibers are composited back to front. Both evaluators see exactly the same
//! geometry, so their pictures differ only by the BCSDF. Everything (the fiber layout comes
//! from a fixed-seed generator) is deterministic.
//!
//! Images: `analytic.png`, `baked.png` and `difference.png` ([`RENDER_W`] × [`RENDER_H`]), and
//! `families.png` (the same size: a 2 × 2 grid of half-size analytic renders, one per lobe
//! family, at the exposure of the full picture).

use crate::plot::Canvas;
use bcsdf_core::{Angles, Bcsdf, Libm, LobeFamily, Rgb, Vec3, FAMILY_COUNT};
use rayon::prelude::*;

/// Width of the rendered pictures.
pub const RENDER_W: usize = 512;
/// Height of the rendered pictures.
pub const RENDER_H: usize = 384;
/// Number of fibers in the patch.
pub const FIBER_COUNT: usize = 500;
/// Direction towards the light: from the left, slightly above and behind the fur (φ ≈ 120°
/// for a vertical fiber), so that reflection (R), transmission (TT) and the medulla-scattered
/// lobes all show; not normalised.
pub const LIGHT: Vec3 = [-0.8, 0.25, -0.45];
/// Direction towards the viewer (orthographic camera on the +z axis).
pub const VIEW: Vec3 = [0.0, 0.0, 1.0];
/// Display colour of the background, linear.
const BACKGROUND: [f32; 3] = [0.006, 0.007, 0.010];
/// Centre-line step, pixels.
const STEP: f32 = 2.0;

/// One fiber: centre-line points (x right, y up, z towards the viewer; pixels) and the
/// radius at each.
#[derive(Clone, Debug)]
struct Fiber {
    points: Vec<[f32; 3]>,
    radii: Vec<f32>,
}

impl Fiber {
    /// Mean depth (for back-to-front order).
    fn depth(&self) -> f32 {
        self.points.iter().map(|p| p[2]).sum::<f32>() / self.points.len().max(1) as f32
    }
}

/// SplitMix64 stream: uniform numbers in [0, 1).
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> f32 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^= z >> 31;
        (z >> 40) as f32 / (1u64 << 24) as f32
    }

    /// Uniform in [lo, hi).
    fn range(&mut self, lo: f32, hi: f32) -> f32 {
        lo + (hi - lo) * self.next()
    }
}

/// The fixed fiber layout.
fn scene() -> Vec<Fiber> {
    let mut rng = Rng(0x00f0_7ba7_c4e5);
    let mut fibers: Vec<Fiber> = (0..FIBER_COUNT)
        .map(|_| {
            let x0 = rng.range(-60.0, RENDER_W as f32 + 20.0);
            let z0 = rng.range(-60.0, 60.0);
            let length = rng.range(260.0, 440.0);
            let lean = 0.12 + rng.range(-0.16, 0.16);
            let bend = rng.range(-0.45, 0.45);
            let tz0 = rng.range(-0.6, 0.3);
            let tz1 = rng.range(-0.4, 0.4);
            let r0 = rng.range(0.8, 1.3);
            let n = (length / STEP) as usize;
            let mut p = [x0, -30.0, z0];
            let mut points = Vec::with_capacity(n + 1);
            let mut radii = Vec::with_capacity(n + 1);
            for k in 0..=n {
                let s = k as f32 / n as f32;
                points.push(p);
                radii.push(r0 * (1.0 - 0.65 * s * s));
                let a = lean + bend * s;
                p = [
                    p[0] + STEP * a.sin(),
                    p[1] + STEP * a.cos(),
                    p[2] + STEP * (tz0 + tz1 * s),
                ];
            }
            Fiber { points, radii }
        })
        .collect();
    fibers.sort_by(|a, b| a.depth().total_cmp(&b.depth()));
    fibers
}

/// Radiance per lobe family of one segment seen through both evaluators.
type SegmentRadiance = ([Rgb; FAMILY_COUNT], [Rgb; FAMILY_COUNT]);

/// Linear radiance pictures of both evaluators, per lobe family, and the coverage.
#[derive(Clone, Debug)]
pub struct Renders {
    /// Coverage (opacity) per pixel, row-major from the top-left.
    pub alpha: Vec<f32>,
    /// Analytic radiance per family per pixel.
    pub analytic: Vec<[Rgb; FAMILY_COUNT]>,
    /// Baked radiance per family per pixel.
    pub baked: Vec<[Rgb; FAMILY_COUNT]>,
}

fn sum(f: &[Rgb; FAMILY_COUNT]) -> Rgb {
    f.iter().fold(Rgb::ZERO, |acc, &v| acc + v)
}

fn scale(f: &[Rgb; FAMILY_COUNT], k: f32) -> [Rgb; FAMILY_COUNT] {
    f.map(|v| v * k)
}

/// The far-field queries the render makes: one per fiber segment with a valid direction
/// (the GPU check evaluates exactly these in one batch).
pub fn segment_angles() -> Vec<Angles> {
    scene()
        .iter()
        .flat_map(|fiber| {
            fiber
                .points
                .windows(2)
                .filter_map(|w| {
                    let t = [w[1][0] - w[0][0], w[1][1] - w[0][1], w[1][2] - w[0][2]];
                    Angles::from_directions::<Libm>(LIGHT, VIEW, t).ok()
                })
                .collect::<Vec<_>>()
        })
        .collect()
}

/// Renders the patch with both evaluators (segments evaluated in parallel, compositing in a
/// fixed order: the same bits for any thread count).
pub fn render<A, B>(analytic: &A, baked: &B) -> Renders
where
    A: Bcsdf + Sync,
    B: Bcsdf + Sync,
{
    let fibers = scene();
    let radiance: Vec<Vec<SegmentRadiance>> = fibers
        .par_iter()
        .map(|fiber| {
            fiber
                .points
                .windows(2)
                .map(|w| {
                    let t = [w[1][0] - w[0][0], w[1][1] - w[0][1], w[1][2] - w[0][2]];
                    match Angles::from_directions::<Libm>(LIGHT, VIEW, t) {
                        Ok(angles) => {
                            let cos_i = angles.theta_i().cos();
                            (
                                scale(analytic.eval(&angles).as_array(), cos_i),
                                scale(baked.eval(&angles).as_array(), cos_i),
                            )
                        }
                        Err(_) => ([Rgb::ZERO; FAMILY_COUNT], [Rgb::ZERO; FAMILY_COUNT]),
                    }
                })
                .collect()
        })
        .collect();

    let n = RENDER_W * RENDER_H;
    let mut out = Renders {
        alpha: vec![0.0; n],
        analytic: vec![[Rgb::ZERO; FAMILY_COUNT]; n],
        baked: vec![[Rgb::ZERO; FAMILY_COUNT]; n],
    };
    for (fiber, values) in fibers.iter().zip(&radiance) {
        composite(&mut out, fiber, values);
    }
    out
}

/// Draws one fiber over the picture: each pixel takes the segment covering it most, then
/// blends once with that coverage.
fn composite(out: &mut Renders, fiber: &Fiber, values: &[SegmentRadiance]) {
    let to_screen = |p: [f32; 3]| (p[0], RENDER_H as f32 - p[1]);
    let (mut x0, mut y0, mut x1, mut y1) = (f32::MAX, f32::MAX, f32::MIN, f32::MIN);
    for &p in &fiber.points {
        let (x, y) = to_screen(p);
        x0 = x0.min(x);
        x1 = x1.max(x);
        y0 = y0.min(y);
        y1 = y1.max(y);
    }
    let pad = 3.0;
    let bx0 = ((x0 - pad).floor() as i64).max(0);
    let by0 = ((y0 - pad).floor() as i64).max(0);
    let bx1 = ((x1 + pad).ceil() as i64).min(RENDER_W as i64 - 1);
    let by1 = ((y1 + pad).ceil() as i64).min(RENDER_H as i64 - 1);
    if bx1 < bx0 || by1 < by0 {
        return;
    }
    let bw = (bx1 - bx0 + 1) as usize;
    let mut mask = vec![(0.0f32, 0usize); bw * (by1 - by0 + 1) as usize];
    for (k, w) in fiber.points.windows(2).enumerate() {
        let (p, q) = (to_screen(w[0]), to_screen(w[1]));
        let r = 0.5 * (fiber.radii[k] + fiber.radii[k + 1]);
        let sx0 = ((p.0.min(q.0) - r - 1.0).floor() as i64).max(bx0);
        let sx1 = ((p.0.max(q.0) + r + 1.0).ceil() as i64).min(bx1);
        let sy0 = ((p.1.min(q.1) - r - 1.0).floor() as i64).max(by0);
        let sy1 = ((p.1.max(q.1) + r + 1.0).ceil() as i64).min(by1);
        for y in sy0..=sy1 {
            for x in sx0..=sx1 {
                let d = distance((x as f32 + 0.5, y as f32 + 0.5), p, q);
                let cov = (r + 0.5 - d).clamp(0.0, 1.0);
                let m = &mut mask[(y - by0) as usize * bw + (x - bx0) as usize];
                if cov > m.0 {
                    *m = (cov, k);
                }
            }
        }
    }
    for (i, &(cov, k)) in mask.iter().enumerate() {
        if cov <= 0.0 {
            continue;
        }
        let (x, y) = (bx0 as usize + i % bw, by0 as usize + i / bw);
        let pix = y * RENDER_W + x;
        let keep = 1.0 - cov;
        out.alpha[pix] = out.alpha[pix] * keep + cov;
        let (a, b) = &values[k];
        for f in 0..FAMILY_COUNT {
            out.analytic[pix][f] = out.analytic[pix][f] * keep + a[f] * cov;
            out.baked[pix][f] = out.baked[pix][f] * keep + b[f] * cov;
        }
    }
}

/// Distance from `p` to the segment a–b.
fn distance(p: (f32, f32), a: (f32, f32), b: (f32, f32)) -> f32 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let len2 = dx * dx + dy * dy;
    let t = if len2 > 0.0 {
        (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    ((a.0 + t * dx - p.0).powi(2) + (a.1 + t * dy - p.1).powi(2)).sqrt()
}

impl Renders {
    /// Mean relative difference per channel, Σ|baked − analytic| / Σ analytic over all
    /// pixels (the background adds nothing to either sum).
    pub fn mean_relative_difference(&self) -> [f64; 3] {
        let mut diff = [0.0f64; 3];
        let mut total = [0.0f64; 3];
        for (a, b) in self.analytic.iter().zip(&self.baked) {
            let (a, b) = (sum(a), sum(b));
            for c in 0..3 {
                diff[c] += f64::from((b.0[c] - a.0[c]).abs());
                total[c] += f64::from(a.0[c]);
            }
        }
        std::array::from_fn(|c| {
            if total[c] > 0.0 {
                diff[c] / total[c]
            } else if diff[c] > 0.0 {
                f64::INFINITY
            } else {
                0.0
            }
        })
    }

    /// Fraction of the picture covered by fibers (sum of coverage / pixel count).
    #[cfg(test)]
    pub fn coverage(&self) -> f64 {
        self.alpha.iter().map(|&a| f64::from(a)).sum::<f64>() / self.alpha.len() as f64
    }

    /// The exposure k of every picture (display value 1 − e^(−k·L)): the median analytic
    /// luminance over the covered pixels maps to at most 1 − e^(−0.5) ≈ 0.39 of white and the
    /// 99th percentile to at most 1 − e^(−3) ≈ 0.95.
    pub fn exposure(&self) -> f32 {
        let mut lum: Vec<f32> = self
            .analytic
            .iter()
            .zip(&self.alpha)
            .filter(|(_, &a)| a > 0.5)
            .map(|(v, _)| crate::figures::luminance(sum(v)) as f32)
            .filter(|v| *v > 0.0)
            .collect();
        if lum.is_empty() {
            return 1.0;
        }
        lum.sort_by(f32::total_cmp);
        let at = |q: usize| lum[(lum.len() * q / 100).min(lum.len() - 1)];
        (0.5 / at(50)).min(3.0 / at(99))
    }

    /// The analytic (or baked) picture.
    pub fn picture(&self, baked: bool) -> Canvas {
        let k = self.exposure();
        let src = if baked { &self.baked } else { &self.analytic };
        self.tone_map(|i| sum(&src[i]), k, RENDER_W, RENDER_H, 1)
    }

    /// |baked − analytic| × `gain` at the pictures' exposure, with a line of text saying so.
    pub fn difference(&self, gain: f32, caption: &[String]) -> Canvas {
        let k = self.exposure();
        let mut c = self.tone_map(
            |i| {
                let (a, b) = (sum(&self.analytic[i]), sum(&self.baked[i]));
                Rgb(std::array::from_fn(|ch| (b.0[ch] - a.0[ch]).abs() * gain))
            },
            k,
            RENDER_W,
            RENDER_H,
            1,
        );
        let height = 12 * caption.len() as i64 + 6;
        c.fill_rect(0, 0, RENDER_W as i64, height, [0, 0, 0]);
        for (i, line) in caption.iter().enumerate() {
            c.text(4, 4 + 12 * i as i64, line, [255, 255, 255], 1);
        }
        c
    }

    /// The analytic picture split by lobe family: a 2 × 2 grid of half-size pictures, labelled.
    pub fn families(&self) -> Canvas {
        let k = self.exposure();
        let mut c = Canvas::new(RENDER_W, RENDER_H, [0, 0, 0]);
        for (f, family) in LobeFamily::ALL.iter().enumerate() {
            let cell = self.tone_map(|i| self.analytic[i][f], k, RENDER_W / 2, RENDER_H / 2, 2);
            let (x, y) = ((f % 2) * RENDER_W / 2, (f / 2) * RENDER_H / 2);
            c.paste(&cell, x as i64, y as i64);
            let label = format!("{} (analytic)", family.name());
            c.fill_rect(
                x as i64,
                y as i64,
                8 * label.len() as i64 + 8,
                14,
                [0, 0, 0],
            );
            c.text(x as i64 + 4, y as i64 + 3, &label, [255, 255, 255], 1);
        }
        // Thin separators between the cells.
        c.fill_rect(RENDER_W as i64 / 2 - 1, 0, 2, RENDER_H as i64, [90, 90, 90]);
        c.fill_rect(0, RENDER_H as i64 / 2 - 1, RENDER_W as i64, 2, [90, 90, 90]);
        c
    }

    /// Tone-maps radiance `value(pixel)` of the full-size pictures ([`tone_map`]).
    fn tone_map(
        &self,
        value: impl Fn(usize) -> Rgb,
        k: f32,
        w: usize,
        h: usize,
        step: usize,
    ) -> Canvas {
        tone_map(value, &self.alpha, RENDER_W, k, (w, h), step)
    }

    /// The baked picture at half size, linear, with its coverage and exposure: one panel of
    /// the species gallery ([`gallery`]).
    pub fn thumbnail(&self) -> Thumbnail {
        let (w, h) = (RENDER_W / 2, RENDER_H / 2);
        let mut radiance = vec![Rgb::ZERO; w * h];
        let mut alpha = vec![0.0f32; w * h];
        for y in 0..h {
            for x in 0..w {
                for (dy, dx) in [(0, 0), (0, 1), (1, 0), (1, 1)] {
                    let i = (2 * y + dy) * RENDER_W + 2 * x + dx;
                    radiance[y * w + x] += sum(&self.baked[i]) * 0.25;
                    alpha[y * w + x] += 0.25 * self.alpha[i];
                }
            }
        }
        Thumbnail {
            radiance,
            alpha,
            exposure: self.exposure(),
        }
    }
}

/// A half-size linear picture of one LUT's baked render ([`Renders::thumbnail`]).
#[derive(Clone, Debug)]
pub struct Thumbnail {
    radiance: Vec<Rgb>,
    alpha: Vec<f32>,
    /// The exposure [`Renders::exposure`] chose for this LUT alone.
    pub exposure: f32,
}

/// Panels per row of the gallery.
const GALLERY_COLUMNS: usize = 4;

/// The species gallery (`viewer compare --all`): one labelled half-size panel per LUT, all
/// under the same light and the same exposure — the median of the LUTs' own exposures — so
/// that the panels compare the furs themselves.
pub fn gallery(panels: &[(String, Thumbnail)]) -> Canvas {
    let (w, h) = (RENDER_W / 2, RENDER_H / 2);
    let mut ks: Vec<f32> = panels.iter().map(|(_, t)| t.exposure).collect();
    ks.sort_by(f32::total_cmp);
    let k = ks.get(ks.len() / 2).copied().unwrap_or(1.0);
    let cols = GALLERY_COLUMNS.min(panels.len().max(1));
    let rows = panels.len().div_ceil(cols).max(1);
    let mut c = Canvas::new(cols * w, rows * h, [0, 0, 0]);
    for (n, (name, t)) in panels.iter().enumerate() {
        let cell = tone_map(|i| t.radiance[i], &t.alpha, w, k, (w, h), 1);
        let (x, y) = (((n % cols) * w) as i64, ((n / cols) * h) as i64);
        c.paste(&cell, x, y);
        c.fill_rect(x, y, 8 * name.chars().count() as i64 + 8, 14, [0, 0, 0]);
        c.text(x + 4, y + 3, name, [255, 255, 255], 1);
        c.outline(x, y, w as i64, h as i64, [60, 60, 60]);
    }
    c
}

/// Tone-maps radiance `value(pixel)` of a picture `src_w` pixels wide with coverage `alpha`
/// (1 − e^(−k·L) per channel, over the background, sRGB) into a `w` × `h` canvas, each output
/// pixel the mean of `step` × `step` input pixels.
fn tone_map(
    value: impl Fn(usize) -> Rgb,
    alpha: &[f32],
    src_w: usize,
    k: f32,
    (w, h): (usize, usize),
    step: usize,
) -> Canvas {
    let mut c = Canvas::new(w, h, [0, 0, 0]);
    let n = (step * step) as f32;
    for y in 0..h {
        for x in 0..w {
            let mut acc = [0.0f32; 3];
            let mut cover = 0.0;
            for dy in 0..step {
                for dx in 0..step {
                    let i = (y * step + dy) * src_w + x * step + dx;
                    let v = value(i);
                    for (a, c) in acc.iter_mut().zip(v.0) {
                        *a += c;
                    }
                    cover += alpha[i];
                }
            }
            let cover = cover / n;
            let px = std::array::from_fn(|ch| {
                let lin = 1.0 - (-k * acc[ch] / n).exp() + (1.0 - cover) * BACKGROUND[ch];
                srgb(lin)
            });
            c.set(x as i64, y as i64, px);
        }
    }
    c
}

/// Linear [0, 1] → 8-bit sRGB.
fn srgb(v: f32) -> u8 {
    let v = if v.is_nan() { 0.0 } else { v.clamp(0.0, 1.0) };
    let s = if v <= 0.003_130_8 {
        12.92 * v
    } else {
        1.055 * v.powf(1.0 / 2.4) - 0.055
    };
    (255.0 * s).round() as u8
}

#[cfg(test)]
mod tests {
    use super::*;
    use bcsdf_core::Families;

    /// S = `k` in the R family everywhere.
    struct Flat(f32);
    impl Bcsdf for Flat {
        type Math = bcsdf_core::Libm;
        fn eval(&self, _: &Angles) -> Families {
            Families::from_array([Rgb::splat(self.0), Rgb::ZERO, Rgb::ZERO, Rgb::ZERO])
        }
        fn pdf(&self, _: &Angles) -> f32 {
            0.0
        }
        fn sample_direction(&self, _: f32, _: [f32; 3]) -> Option<bcsdf_core::SampledDirection> {
            None
        }
    }

    #[test]
    fn the_patch_covers_the_picture_and_differences_are_measured() {
        let r = render(&Flat(1.0), &Flat(1.03));
        let cov = r.coverage();
        assert!((0.4..0.99).contains(&cov), "coverage {cov}");
        for d in r.mean_relative_difference() {
            assert!((d - 0.03).abs() < 1e-4, "{d}");
        }
        let same = render(&Flat(1.0), &Flat(1.0));
        assert_eq!(same.mean_relative_difference(), [0.0; 3]);
        let pic = r.picture(false);
        assert_eq!((pic.width(), pic.height()), (RENDER_W, RENDER_H));
        assert_eq!(
            (r.families().width(), r.families().height()),
            (RENDER_W, RENDER_H)
        );
    }
}
