//! Raster drawing for the comparison figures: an 8-bit RGB canvas, text in the embedded
//! public-domain 8×8 bitmap font of `font8x8` (no system fonts needed), antialiased lines
//! (solid or dashed), the two colour maps with their legends, and PNG output.
//!
//! Coordinates are pixels, x to the right and y down, (0, 0) the top-left corner; drawing
//! outside the canvas is clipped. Everything is deterministic: the same calls give the same
//! bytes.

use std::io;
use std::path::Path;

/// An sRGB colour, 8 bits per channel.
pub type Rgb8 = [u8; 3];

/// A point in pixel coordinates.
pub type Point = (f32, f32);

/// Plot background.
pub const WHITE: Rgb8 = [255, 255, 255];
/// Text and axes.
pub const BLACK: Rgb8 = [0, 0, 0];
/// Secondary text (notes, tick labels of minor importance).
pub const GREY: Rgb8 = [110, 110, 110];
/// Grid lines.
pub const LIGHT_GREY: Rgb8 = [215, 215, 215];
/// Analytic curves.
pub const ANALYTIC_COLOUR: Rgb8 = [20, 60, 170];
/// Baked curves.
pub const BAKED_COLOUR: Rgb8 = [235, 110, 0];

/// Width and height of one glyph at scale 1.
pub const GLYPH: usize = 8;

/// An RGB image being drawn.
#[derive(Clone, Debug, PartialEq)]
pub struct Canvas {
    width: usize,
    height: usize,
    pixels: Vec<Rgb8>,
}

impl Canvas {
    /// A `width` × `height` canvas filled with `background`.
    pub fn new(width: usize, height: usize, background: Rgb8) -> Canvas {
        Canvas {
            width,
            height,
            pixels: vec![background; width * height],
        }
    }

    /// Width in pixels.
    pub fn width(&self) -> usize {
        self.width
    }

    /// Height in pixels.
    pub fn height(&self) -> usize {
        self.height
    }

    /// The pixel at (x, y) (black outside the canvas).
    #[cfg(test)]
    pub fn get(&self, x: usize, y: usize) -> Rgb8 {
        if x < self.width && y < self.height {
            self.pixels[y * self.width + x]
        } else {
            BLACK
        }
    }

    /// Sets one pixel (clipped).
    pub fn set(&mut self, x: i64, y: i64, c: Rgb8) {
        if x >= 0 && y >= 0 && (x as usize) < self.width && (y as usize) < self.height {
            self.pixels[y as usize * self.width + x as usize] = c;
        }
    }

    /// Mixes `c` into one pixel with opacity `alpha` ∈ [0, 1] (clipped).
    pub fn blend(&mut self, x: i64, y: i64, c: Rgb8, alpha: f32) {
        if x < 0 || y < 0 || x as usize >= self.width || y as usize >= self.height {
            return;
        }
        let a = alpha.clamp(0.0, 1.0);
        let p = &mut self.pixels[y as usize * self.width + x as usize];
        for k in 0..3 {
            let v = f32::from(p[k]) + a * (f32::from(c[k]) - f32::from(p[k]));
            p[k] = v.round().clamp(0.0, 255.0) as u8;
        }
    }

    /// Fills a rectangle (clipped).
    pub fn fill_rect(&mut self, x: i64, y: i64, w: i64, h: i64, c: Rgb8) {
        for yy in y.max(0)..(y + h).min(self.height as i64) {
            for xx in x.max(0)..(x + w).min(self.width as i64) {
                self.pixels[yy as usize * self.width + xx as usize] = c;
            }
        }
    }

    /// A one-pixel rectangle outline enclosing the `w` × `h` area at (x, y).
    pub fn outline(&mut self, x: i64, y: i64, w: i64, h: i64, c: Rgb8) {
        self.fill_rect(x - 1, y - 1, w + 2, 1, c);
        self.fill_rect(x - 1, y + h, w + 2, 1, c);
        self.fill_rect(x - 1, y, 1, h, c);
        self.fill_rect(x + w, y, 1, h, c);
    }

    /// Copies `other` with its top-left corner at (x, y) (clipped).
    pub fn paste(&mut self, other: &Canvas, x: i64, y: i64) {
        for yy in 0..other.height {
            for xx in 0..other.width {
                self.set(
                    x + xx as i64,
                    y + yy as i64,
                    other.pixels[yy * other.width + xx],
                );
            }
        }
    }

    /// Draws `text` with its top-left corner at (x, y), each glyph `scale` × 8 pixels square;
    /// returns the width drawn. Characters outside ASCII print as `?`.
    pub fn text(&mut self, x: i64, y: i64, text: &str, c: Rgb8, scale: usize) -> i64 {
        let s = scale.max(1) as i64;
        let mut pen = x;
        for ch in text.chars() {
            let glyph = glyph(ch);
            for (row, bits) in glyph.iter().enumerate() {
                for col in 0..8 {
                    if bits >> col & 1 == 1 {
                        self.fill_rect(pen + col * s, y + row as i64 * s, s, s, c);
                    }
                }
            }
            pen += 8 * s;
        }
        pen - x
    }

    /// Draws `text` centred horizontally on `cx`, top at `y`.
    pub fn text_centred(&mut self, cx: i64, y: i64, text: &str, c: Rgb8, scale: usize) {
        let w = text_width(text, scale) as i64;
        self.text(cx - w / 2, y, text, c, scale);
    }

    /// Draws `text` ending at `right` (exclusive), top at `y`.
    pub fn text_right(&mut self, right: i64, y: i64, text: &str, c: Rgb8, scale: usize) {
        let w = text_width(text, scale) as i64;
        self.text(right - w, y, text, c, scale);
    }

    /// Draws `text` rotated a quarter turn counter-clockwise (reading bottom to top), its
    /// left edge at `x` and centred vertically on `cy`.
    pub fn text_vertical(&mut self, x: i64, cy: i64, text: &str, c: Rgb8) {
        let len = text_width(text, 1) as i64;
        let bottom = cy + len / 2;
        for (i, ch) in text.chars().enumerate() {
            let glyph = glyph(ch);
            for (row, bits) in glyph.iter().enumerate() {
                for col in 0..8i64 {
                    if bits >> col & 1 == 1 {
                        // Glyph column → up the page, glyph row → right.
                        self.set(x + row as i64, bottom - (8 * i as i64 + col), c);
                    }
                }
            }
        }
    }

    /// An antialiased polyline of the given width; with `dash = Some((on, off))` only the
    /// "on" stretches (lengths in pixels along the line) are drawn.
    pub fn polyline(
        &mut self,
        points: &[(f32, f32)],
        c: Rgb8,
        width: f32,
        dash: Option<(f32, f32)>,
    ) {
        let mut segments = Vec::new();
        let mut travelled = 0.0f32;
        for pair in points.windows(2) {
            let (p, q) = (pair[0], pair[1]);
            let len = ((q.0 - p.0).powi(2) + (q.1 - p.1).powi(2)).sqrt();
            if !(len.is_finite()) {
                continue;
            }
            match dash {
                None => segments.push((p, q)),
                Some((on, off)) => {
                    let period = on + off;
                    let mut t = 0.0f32;
                    while t < len {
                        let phase = (travelled + t) % period;
                        let step = if phase < on {
                            on - phase
                        } else {
                            period - phase
                        };
                        let t1 = (t + step).min(len);
                        if phase < on {
                            let at =
                                |s: f32| (p.0 + (q.0 - p.0) * s / len, p.1 + (q.1 - p.1) * s / len);
                            segments.push((at(t), at(t1)));
                        }
                        t = t1;
                    }
                }
            }
            travelled += len;
        }
        self.stroke(&segments, c, width);
    }

    /// A straight antialiased line.
    pub fn line(&mut self, p: (f32, f32), q: (f32, f32), c: Rgb8, width: f32) {
        self.stroke(&[(p, q)], c, width);
    }

    /// An antialiased circle outline.
    pub fn circle(&mut self, centre: (f32, f32), radius: f32, c: Rgb8, width: f32) {
        let n = ((radius * 0.8) as usize).clamp(24, 720);
        let pts: Vec<(f32, f32)> = (0..=n)
            .map(|k| {
                let a = std::f32::consts::TAU * k as f32 / n as f32;
                (centre.0 + radius * a.cos(), centre.1 + radius * a.sin())
            })
            .collect();
        self.polyline(&pts, c, width, None);
    }

    /// Draws segments as one shape: the coverage of every pixel is the largest over the
    /// segments (so joints are not drawn twice), then blended once.
    fn stroke(&mut self, segments: &[(Point, Point)], c: Rgb8, width: f32) {
        if segments.is_empty() {
            return;
        }
        let half = 0.5 * width;
        let pad = half + 1.0;
        let (mut x0, mut y0, mut x1, mut y1) = (f32::MAX, f32::MAX, f32::MIN, f32::MIN);
        for &(p, q) in segments {
            x0 = x0.min(p.0.min(q.0));
            y0 = y0.min(p.1.min(q.1));
            x1 = x1.max(p.0.max(q.0));
            y1 = y1.max(p.1.max(q.1));
        }
        let bx0 = ((x0 - pad).floor() as i64).max(0);
        let by0 = ((y0 - pad).floor() as i64).max(0);
        let bx1 = ((x1 + pad).ceil() as i64).min(self.width as i64 - 1);
        let by1 = ((y1 + pad).ceil() as i64).min(self.height as i64 - 1);
        if bx1 < bx0 || by1 < by0 {
            return;
        }
        let bw = (bx1 - bx0 + 1) as usize;
        let mut mask = vec![0.0f32; bw * (by1 - by0 + 1) as usize];
        for &(p, q) in segments {
            let sx0 = ((p.0.min(q.0) - pad).floor() as i64).max(bx0);
            let sx1 = ((p.0.max(q.0) + pad).ceil() as i64).min(bx1);
            let sy0 = ((p.1.min(q.1) - pad).floor() as i64).max(by0);
            let sy1 = ((p.1.max(q.1) + pad).ceil() as i64).min(by1);
            for y in sy0..=sy1 {
                for x in sx0..=sx1 {
                    let d = segment_distance((x as f32 + 0.5, y as f32 + 0.5), p, q);
                    let cov = (half + 0.5 - d).clamp(0.0, 1.0);
                    let m = &mut mask[(y - by0) as usize * bw + (x - bx0) as usize];
                    *m = m.max(cov);
                }
            }
        }
        for (i, &cov) in mask.iter().enumerate() {
            if cov > 0.0 {
                self.blend(bx0 + (i % bw) as i64, by0 + (i / bw) as i64, c, cov);
            }
        }
    }

    /// Encodes the canvas as an 8-bit RGB PNG.
    pub fn png_bytes(&self) -> Vec<u8> {
        let mut out = Vec::new();
        {
            let mut enc = png::Encoder::new(&mut out, self.width as u32, self.height as u32);
            enc.set_color(png::ColorType::Rgb);
            enc.set_depth(png::BitDepth::Eight);
            let data: Vec<u8> = self.pixels.iter().flatten().copied().collect();
            // Writing into a Vec cannot fail.
            let mut w = enc.write_header().expect("PNG header into memory");
            w.write_image_data(&data).expect("PNG data into memory");
        }
        out
    }

    /// Writes the canvas to `path` as PNG, atomically ([`write_file`]).
    pub fn write_png(&self, path: &Path) -> io::Result<()> {
        write_file(path, &self.png_bytes())
    }
}

/// Writes `bytes` to `path` atomically with [`bake::fsutil::write_atomic`]: a temporary file
/// in the same folder, flushed to disk and renamed into place, so a reader never sees half a
/// file and a failed write leaves any existing file untouched.
pub fn write_file(path: &Path, bytes: &[u8]) -> io::Result<()> {
    bake::fsutil::write_atomic(path, bytes)
}

/// Width in pixels of `text` at `scale`.
pub fn text_width(text: &str, scale: usize) -> usize {
    text.chars().count() * GLYPH * scale.max(1)
}

/// The 8×8 bitmap of a character: one byte per row, bit 0 the leftmost pixel.
fn glyph(ch: char) -> [u8; 8] {
    let code = if ch.is_ascii() {
        ch as usize
    } else {
        '?' as usize
    };
    font8x8::legacy::BASIC_LEGACY[code]
}

/// Distance from `p` to the segment a–b.
fn segment_distance(p: (f32, f32), a: (f32, f32), b: (f32, f32)) -> f32 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let len2 = dx * dx + dy * dy;
    let t = if len2 > 0.0 {
        (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let (ex, ey) = (a.0 + t * dx - p.0, a.1 + t * dy - p.1);
    (ex * ex + ey * ey).sqrt()
}

/// Linear interpolation through evenly spaced colour stops, `t` ∈ [0, 1] (clamped).
fn through(stops: &[Rgb8], t: f32) -> Rgb8 {
    let t = if t.is_nan() { 0.0 } else { t.clamp(0.0, 1.0) };
    let x = t * (stops.len() - 1) as f32;
    let i = (x.floor() as usize).min(stops.len() - 2);
    let w = x - i as f32;
    let (a, b) = (stops[i], stops[i + 1]);
    let mut out = [0u8; 3];
    for k in 0..3 {
        out[k] = (f32::from(a[k]) + w * (f32::from(b[k]) - f32::from(a[k])))
            .round()
            .clamp(0.0, 255.0) as u8;
    }
    out
}

/// The sequential colour map (an approximation of matplotlib's "inferno": black → purple →
/// orange → pale yellow, perceptually ordered), `t` ∈ [0, 1].
pub fn sequential(t: f32) -> Rgb8 {
    const STOPS: [Rgb8; 9] = [
        [0, 0, 4],
        [31, 12, 72],
        [85, 15, 109],
        [136, 34, 106],
        [186, 54, 85],
        [227, 89, 51],
        [249, 140, 10],
        [249, 201, 50],
        [252, 255, 164],
    ];
    through(&STOPS, t)
}

/// The diverging colour map (blue → white → red, like matplotlib's "RdBu_r"), `t` ∈ [−1, 1]:
/// negative blue, zero white, positive red.
pub fn diverging(t: f32) -> Rgb8 {
    const STOPS: [Rgb8; 5] = [
        [5, 48, 97],
        [67, 147, 195],
        [247, 247, 247],
        [214, 96, 77],
        [103, 0, 31],
    ];
    through(&STOPS, 0.5 * (t + 1.0))
}

/// A vertical colour bar `w` × `h` at (x, y): `map(t)` with t = 1 at the top and 0 at the
/// bottom, outlined, with `ticks` (t, label) drawn to its right.
pub fn colour_bar(
    canvas: &mut Canvas,
    (x, y, w, h): (i64, i64, i64, i64),
    map: &dyn Fn(f32) -> Rgb8,
    ticks: &[(f32, String)],
) {
    for row in 0..h {
        let t = 1.0 - (row as f32 + 0.5) / h as f32;
        canvas.fill_rect(x, y + row, w, 1, map(t));
    }
    canvas.outline(x, y, w, h, BLACK);
    for (t, label) in ticks {
        let ty = y + ((1.0 - t) * (h - 1) as f32).round() as i64;
        canvas.fill_rect(x + w, ty, 4, 1, BLACK);
        canvas.text(x + w + 6, ty - 3, label, BLACK, 1);
    }
}

/// A decade 10^k as a short label: `0.01`, `0.1`, `1`, `10`, `100`, else `1e-3`, `1e3`.
pub fn decade_label(k: i32) -> String {
    match k {
        -2 => "0.01".into(),
        -1 => "0.1".into(),
        0 => "1".into(),
        1 => "10".into(),
        2 => "100".into(),
        _ => format!("1e{k}"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn text_draws_ink_inside_its_box() {
        let mut c = Canvas::new(40, 12, WHITE);
        let w = c.text(2, 2, "E1", BLACK, 1);
        assert_eq!(w, 16);
        let ink: Vec<(usize, usize)> = (0..12)
            .flat_map(|y| (0..40).map(move |x| (x, y)))
            .filter(|&(x, y)| c.get(x, y) == BLACK)
            .collect();
        assert!(ink.len() > 10);
        assert!(ink
            .iter()
            .all(|&(x, y)| (2..18).contains(&x) && (2..10).contains(&y)));
    }

    #[test]
    fn colour_maps_run_end_to_end() {
        assert_eq!(sequential(0.0), [0, 0, 4]);
        assert_eq!(sequential(1.0), [252, 255, 164]);
        assert_eq!(diverging(0.0), [247, 247, 247]);
        assert_eq!(diverging(-5.0), [5, 48, 97]);
        assert_eq!(diverging(f32::NAN), [5, 48, 97]);
        // Brightness rises monotonically along the sequential map.
        let lum = |c: Rgb8| {
            0.2126 * f32::from(c[0]) + 0.7152 * f32::from(c[1]) + 0.0722 * f32::from(c[2])
        };
        for k in 0..20 {
            assert!(lum(sequential(k as f32 / 20.0)) < lum(sequential((k + 1) as f32 / 20.0)));
        }
    }

    #[test]
    fn dashed_lines_leave_gaps_and_png_round_trips() {
        let mut c = Canvas::new(64, 8, WHITE);
        c.polyline(&[(0.0, 4.0), (64.0, 4.0)], BLACK, 2.0, Some((6.0, 4.0)));
        let row: Vec<bool> = (0..64).map(|x| c.get(x, 4) != WHITE).collect();
        assert!(row.iter().filter(|&&on| on).count() > 30);
        assert!(row.iter().filter(|&&on| !on).count() >= 6, "{row:?}");
        let bytes = c.png_bytes();
        assert_eq!(&bytes[1..4], b"PNG");
        assert_eq!(u32::from_be_bytes(bytes[16..20].try_into().unwrap()), 64);
        assert_eq!(u32::from_be_bytes(bytes[20..24].try_into().unwrap()), 8);
    }

    #[test]
    fn png_files_are_written_whole_and_failures_keep_the_old_file() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("c.png");
        let c = Canvas::new(4, 2, WHITE);
        c.write_png(&path).unwrap();
        assert_eq!(std::fs::read(&path).unwrap(), c.png_bytes());
        // A folder in the way of the rename: an error, and nothing else in the folder.
        let blocked = dir.path().join("blocked.png");
        std::fs::create_dir(&blocked).unwrap();
        std::fs::write(blocked.join("inside"), b"x").unwrap();
        assert!(c.write_png(&blocked).is_err());
        let mut names: Vec<_> = std::fs::read_dir(dir.path())
            .unwrap()
            .map(|e| e.unwrap().file_name())
            .collect();
        names.sort();
        assert_eq!(names, ["blocked.png", "c.png"]);
        assert_eq!(std::fs::read(blocked.join("inside")).unwrap(), b"x");
    }
}
