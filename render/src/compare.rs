//! An approximation's image judged against the reference (docs/model.md §13, the dual-scattering
//! metrics), and the side-by-side pictures `viewer render --compare` writes.
//!
//! Both metrics are on luminance L (Rec. 709: 0.2126 R + 0.7152 G + 0.0722 B):
//! - mean error = mean(L_approx)/mean(L_reference) − 1 over the pixels compared;
//! - tile RMSE = √(mean over tiles of (L̄_approx − L̄_reference)²) / mean over tiles of
//!   L̄_reference, L̄ a tile's mean luminance, the image cut into a `grid` × `grid`
//!   arrangement of tiles (tile i spans pixels ⌊i·W/grid⌋ to ⌊(i + 1)·W/grid⌋, so every pixel
//!   is in one tile however W divides).

use crate::film::Image;
use crate::scene::{HitKind, Scene};

/// Tiles per side of the tile RMSE (a 16 × 16 arrangement of tiles, docs/accuracy.md).
pub const TILE_GRID: u32 = 16;

/// Rec. 709 luminance of an RGB radiance.
#[must_use]
pub fn luminance(rgb: &[f32; 3]) -> f64 {
    0.2126 * f64::from(rgb[0]) + 0.7152 * f64::from(rgb[1]) + 0.0722 * f64::from(rgb[2])
}

/// How far an image is from the reference (module docs).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Metrics {
    /// mean(L)/mean(L_reference) − 1 (0 when the reference is black).
    pub mean: f64,
    /// Tile RMSE relative to the reference's mean tile luminance (0 when it is black).
    pub tiles: f64,
    /// The tile RMSE that the two images' sampling noise alone would give if it were
    /// independent (from their per-pixel variances, channels taken as fully correlated), on
    /// the same scale as `tiles`. An upper estimate for `render`'s methods, which draw the
    /// same random numbers per vertex, so that much of their noise cancels in the difference.
    pub noise: f64,
}

/// [`Metrics`] of `image` against `reference` (same size) over a `grid` × `grid`
/// arrangement of tiles (`grid` clamped to 1..=the smaller side), counting only the pixels
/// `mask` keeps (all of them when `None`; a tile without a kept pixel is left out).
///
/// # Panics
/// When the two images (or the mask) differ in size.
#[must_use]
pub fn metrics(image: &Image, reference: &Image, grid: u32, mask: Option<&[bool]>) -> Metrics {
    assert_eq!(
        (image.width, image.height),
        (reference.width, reference.height),
        "images of different sizes"
    );
    let (w, h) = (image.width, image.height);
    if let Some(m) = mask {
        assert_eq!(m.len(), (w * h) as usize, "mask of another size");
    }
    let grid = grid.clamp(1, w.min(h).max(1));
    let keep = |i: usize| mask.is_none_or(|m| m[i]);
    let (mut sum_a, mut sum_r) = (0.0f64, 0.0f64);
    let (mut sq, mut ref_tiles, mut tiles) = (0.0f64, 0.0f64, 0.0f64);
    let mut noise_sq = 0.0f64;
    let sigma = |v: &[f32; 3]| luminance(&v.map(|x| x.max(0.0).sqrt()));
    for ty in 0..grid {
        let (y0, y1) = (ty * h / grid, (ty + 1) * h / grid);
        for tx in 0..grid {
            let (x0, x1) = (tx * w / grid, (tx + 1) * w / grid);
            let (mut a, mut r, mut n, mut var) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
            for y in y0..y1 {
                for x in x0..x1 {
                    let i = (y * w + x) as usize;
                    if keep(i) {
                        a += luminance(&image.mean[i]);
                        r += luminance(&reference.mean[i]);
                        var += sigma(&image.variance[i]).powi(2)
                            + sigma(&reference.variance[i]).powi(2);
                        n += 1.0;
                    }
                }
            }
            sum_a += a;
            sum_r += r;
            if n > 0.0 {
                sq += (a / n - r / n).powi(2);
                noise_sq += var / (n * n);
                ref_tiles += r / n;
                tiles += 1.0;
            }
        }
    }
    let ratio = |x: f64, y: f64| if y > 0.0 { x / y } else { 0.0 };
    Metrics {
        mean: if sum_r > 0.0 {
            sum_a / sum_r - 1.0
        } else {
            0.0
        },
        tiles: ratio((sq / tiles.max(1.0)).sqrt(), ref_tiles / tiles.max(1.0)),
        noise: ratio(
            (noise_sq / tiles.max(1.0)).sqrt(),
            ref_tiles / tiles.max(1.0),
        ),
    }
}

/// The pixels of a `width` × `height` image of `scene` whose centre's camera ray first meets
/// a fiber (the fur, for [`metrics`]' mask).
#[must_use]
pub fn fur_mask(scene: &Scene, width: u32, height: u32) -> Vec<bool> {
    (0..width * height)
        .map(|i| {
            let (x, y) = (i % width, i / width);
            let (o, d) = scene
                .camera
                .ray(x as f32 + 0.5, y as f32 + 0.5, width, height);
            matches!(
                scene.intersect(&o, &d, None).map(|h| h.kind),
                Some(HitKind::Fiber { .. })
            )
        })
        .collect()
}

/// |image − reference| per pixel and channel, with the two images' variances added.
///
/// # Panics
/// When the two images differ in size.
#[must_use]
pub fn difference(image: &Image, reference: &Image) -> Image {
    assert_eq!(
        (image.width, image.height),
        (reference.width, reference.height),
        "images of different sizes"
    );
    let zip = |a: &[[f32; 3]], b: &[[f32; 3]], f: fn(f32, f32) -> f32| -> Vec<[f32; 3]> {
        a.iter()
            .zip(b)
            .map(|(p, q)| core::array::from_fn(|c| f(p[c], q[c])))
            .collect()
    };
    Image {
        width: image.width,
        height: image.height,
        mean: zip(&image.mean, &reference.mean, |a, b| (a - b).abs()),
        variance: zip(&image.variance, &reference.variance, |a, b| a + b),
    }
}

/// The images placed left to right (all of the first one's height; each image's own width).
///
/// # Panics
/// When the images differ in height.
#[must_use]
pub fn side_by_side(images: &[&Image]) -> Image {
    let height = images.first().map_or(0, |i| i.height);
    assert!(
        images.iter().all(|i| i.height == height),
        "images of different heights"
    );
    let width: u32 = images.iter().map(|i| i.width).sum();
    let mut mean = Vec::with_capacity((width * height) as usize);
    let mut variance = Vec::with_capacity((width * height) as usize);
    for y in 0..height {
        for img in images {
            let row = (y * img.width) as usize..((y + 1) * img.width) as usize;
            mean.extend_from_slice(&img.mean[row.clone()]);
            variance.extend_from_slice(&img.variance[row]);
        }
    }
    Image {
        width,
        height,
        mean,
        variance,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn flat(w: u32, h: u32, v: impl Fn(u32, u32) -> f32) -> Image {
        let mut mean = Vec::new();
        for y in 0..h {
            for x in 0..w {
                mean.push([v(x, y); 3]);
            }
        }
        Image {
            width: w,
            height: h,
            variance: vec![[0.0; 3]; mean.len()],
            mean,
        }
    }

    #[test]
    fn metrics_of_known_images() {
        let r = flat(32, 32, |_, _| 2.0);
        // 10 % brighter everywhere: mean +0.1, every tile off by 0.2 of 2.
        let a = flat(32, 32, |_, _| 2.2);
        let m = metrics(&a, &r, TILE_GRID, None);
        assert!(
            (m.mean - 0.1).abs() < 1e-6 && (m.tiles - 0.1).abs() < 1e-6,
            "{m:?}"
        );
        // Left half +20 %, right half −20 %: the mean is right, the tiles are 20 % off.
        let b = flat(32, 32, |x, _| if x < 16 { 2.4 } else { 1.6 });
        let m = metrics(&b, &r, TILE_GRID, None);
        assert!(m.mean.abs() < 1e-6 && (m.tiles - 0.2).abs() < 1e-6, "{m:?}");
        // One grid tile: the halves cancel there.
        assert!(metrics(&b, &r, 1, None).tiles < 1e-6);
        // A mask keeping the left half sees only the +20 %.
        let mask: Vec<bool> = (0..32 * 32).map(|i| i % 32 < 16).collect();
        let m = metrics(&b, &r, TILE_GRID, Some(&mask));
        assert!(
            (m.mean - 0.2).abs() < 1e-6 && (m.tiles - 0.2).abs() < 1e-6,
            "{m:?}"
        );
        // A side that the grid does not divide: every pixel still counts once.
        let (r7, a7) = (
            flat(7, 5, |_, _| 1.0),
            flat(7, 5, |x, y| 1.0 + (x + y) as f32),
        );
        let m = metrics(&a7, &r7, 3, None);
        let want: f64 = (0..5)
            .flat_map(|y| (0..7).map(move |x| f64::from(x + y)))
            .sum::<f64>()
            / 35.0;
        assert!((m.mean - want).abs() < 1e-9, "{m:?} vs {want}");
        // Noise: every pixel of both images with variance 0.04 (σ 0.2 per channel, so 0.2 in
        // luminance), 2 × 2 pixels per tile: σ of a tile's difference √(2·0.04/4) = 0.1414,
        // against a mean tile of 2.
        let mut noisy = a.clone();
        noisy.variance = vec![[0.04; 3]; 32 * 32];
        let mut noisy_r = r.clone();
        noisy_r.variance = noisy.variance.clone();
        let m = metrics(&noisy, &noisy_r, TILE_GRID, None);
        assert!((m.noise - 0.02f64.sqrt() / 2.0).abs() < 1e-6, "{m:?}");
        assert_eq!(metrics(&a, &r, TILE_GRID, None).noise, 0.0);
        // A black reference gives 0, not NaN.
        let m = metrics(&a, &flat(32, 32, |_, _| 0.0), TILE_GRID, None);
        assert_eq!((m.mean, m.tiles, m.noise), (0.0, 0.0, 0.0));
    }

    #[test]
    fn pictures_are_placed_and_differenced() {
        let a = flat(3, 2, |x, y| (x + 10 * y) as f32);
        let b = flat(2, 2, |x, _| -(x as f32));
        let s = side_by_side(&[&a, &b]);
        assert_eq!((s.width, s.height), (5, 2));
        let row1: Vec<f32> = s.mean[5..10].iter().map(|p| p[0]).collect();
        assert_eq!(row1, [10.0, 11.0, 12.0, 0.0, -1.0]);
        let d = difference(&a, &flat(3, 2, |_, _| 5.0));
        assert_eq!(d.mean[0], [5.0; 3]);
        assert_eq!(d.mean[5], [7.0; 3]);
    }
}
