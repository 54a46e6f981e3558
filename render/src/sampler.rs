//! Per-pixel random streams: the image is the same bits for any thread count (docs/model.md §11).
//!
//! Every pixel owns one PCG32 stream, chosen by mixing the seed and the pixel index
//! (`bcsdf_core::rng::cell_stream`), and draws all its samples from it in order. No number
//! depends on which thread renders the pixel or in what order pixels are rendered.

use bcsdf_core::rng::{cell_stream, Pcg32};

/// Table id mixed into the stream id, so the renderer's streams differ from the profile
/// generator's for the same seed.
const RENDER_TABLE: u64 = 0x7265_6e64; // "rend"

/// The uniform numbers of one pixel.
#[derive(Clone, Debug)]
pub struct Sampler {
    rng: Pcg32,
}

impl Sampler {
    /// The stream of pixel `index` (row-major) for `seed`.
    #[must_use]
    pub fn for_pixel(seed: u64, index: u64) -> Sampler {
        Sampler {
            rng: Pcg32::new(seed, cell_stream(seed, RENDER_TABLE, index)),
        }
    }

    /// One uniform number in [0, 1).
    #[inline]
    pub fn next_1d(&mut self) -> f32 {
        self.rng.uniform()
    }

    /// Two uniform numbers in [0, 1).
    #[inline]
    pub fn next_2d(&mut self) -> [f32; 2] {
        [self.next_1d(), self.next_1d()]
    }

    /// Three uniform numbers in [0, 1).
    #[inline]
    pub fn next_3d(&mut self) -> [f32; 3] {
        [self.next_1d(), self.next_1d(), self.next_1d()]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pixels_have_distinct_reproducible_streams() {
        let a: Vec<f32> = (0..8)
            .map({
                let mut s = Sampler::for_pixel(3, 10);
                move |_| s.next_1d()
            })
            .collect();
        let mut again = Sampler::for_pixel(3, 10);
        assert!(a.iter().all(|&x| x == again.next_1d()));
        let mut other = Sampler::for_pixel(3, 11);
        assert!(a.iter().any(|&x| x != other.next_1d()));
        let mut seeded = Sampler::for_pixel(4, 10);
        assert!(a.iter().any(|&x| x != seeded.next_1d()));
    }
}
