//! The rendered image (docs/model.md §11): per pixel the mean radiance and the variance of that mean (from the
//! samples' spread), and the statistics a reference render reports.

/// Mean radiance per pixel and its variance, RGB, row-major from the top-left.
#[derive(Clone, Debug, PartialEq)]
pub struct Image {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Mean radiance of each pixel's samples.
    pub mean: Vec<[f32; 3]>,
    /// Variance of that mean (sample variance / spp): its standard error squared.
    pub variance: Vec<[f32; 3]>,
}

/// A mean over some pixels and its standard error (per RGB channel).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Estimate {
    /// The mean.
    pub mean: [f64; 3],
    /// Its standard error.
    pub std_error: [f64; 3],
}

impl Image {
    /// Mean over the pixels x in [x0, x1), y in [y0, y1) and its standard error (pixels are
    /// independent: their variances add).
    #[must_use]
    pub fn region(&self, x0: u32, y0: u32, x1: u32, y1: u32) -> Estimate {
        let (x1, y1) = (x1.min(self.width), y1.min(self.height));
        let mut sum = [0.0f64; 3];
        let mut var = [0.0f64; 3];
        let mut n = 0.0f64;
        for y in y0..y1 {
            for x in x0..x1 {
                let i = (y * self.width + x) as usize;
                for c in 0..3 {
                    sum[c] += f64::from(self.mean[i][c]);
                    var[c] += f64::from(self.variance[i][c]);
                }
                n += 1.0;
            }
        }
        let n = n.max(1.0);
        Estimate {
            mean: sum.map(|s| s / n),
            std_error: var.map(|v| v.sqrt() / n),
        }
    }

    /// Mean over the whole image.
    #[must_use]
    pub fn whole(&self) -> Estimate {
        self.region(0, 0, self.width, self.height)
    }

    /// The image cut into `tile` × `tile` blocks (partial blocks at the edges included), row
    /// by row.
    #[must_use]
    pub fn tiles(&self, tile: u32) -> Vec<Estimate> {
        let tile = tile.max(1);
        let mut out = Vec::new();
        for y in (0..self.height).step_by(tile as usize) {
            for x in (0..self.width).step_by(tile as usize) {
                out.push(self.region(x, y, x + tile, y + tile));
            }
        }
        out
    }
}

/// A finished render.
#[derive(Clone, Debug)]
pub struct Render {
    /// The image.
    pub image: Image,
    /// Mean radiance per pixel carried by paths of each bounce order (index k: light that
    /// scattered k times; 0 is the environment seen directly). Sums to the image mean.
    pub orders: Vec<[f64; 3]>,
    /// Camera paths traced.
    pub paths: u64,
    /// Rays cast: camera and scattered rays plus shadow rays.
    pub rays: u64,
    /// Wall-clock seconds of the render (the scene's BVH build excluded).
    pub seconds: f64,
}
