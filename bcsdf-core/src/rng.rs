//! A small deterministic PRNG for the profile simulations: PCG32 (O'Neill 2014, XSH RR).

/// PCG32: 64-bit state, 32-bit output; the stream is fixed by `(seed, stream)`.
#[derive(Clone, Debug)]
pub struct Pcg32 {
    state: u64,
    inc: u64,
}

const MULTIPLIER: u64 = 6_364_136_223_846_793_005;

impl Pcg32 {
    /// A generator for `seed` on stream `stream` (distinct streams are independent).
    #[must_use]
    pub fn new(seed: u64, stream: u64) -> Pcg32 {
        let mut rng = Pcg32 {
            state: 0,
            inc: (stream << 1) | 1,
        };
        rng.next_u32();
        rng.state = rng.state.wrapping_add(seed);
        rng.next_u32();
        rng
    }

    /// The next 32 random bits.
    #[inline]
    pub fn next_u32(&mut self) -> u32 {
        let old = self.state;
        self.state = old.wrapping_mul(MULTIPLIER).wrapping_add(self.inc);
        let xorshifted = (((old >> 18) ^ old) >> 27) as u32;
        let rot = (old >> 59) as u32;
        xorshifted.rotate_right(rot)
    }

    /// Uniform in [0, 1) with 24 random bits.
    #[inline]
    pub fn uniform(&mut self) -> f32 {
        (self.next_u32() >> 8) as f32 * (1.0 / 16_777_216.0)
    }

    /// Uniform in (0, 1]: safe for −ln u.
    #[inline]
    pub fn uniform_open0(&mut self) -> f32 {
        ((self.next_u32() >> 8) + 1) as f32 * (1.0 / 16_777_216.0)
    }
}

/// Mixes `(seed, table, cell)` into one 64-bit stream id (SplitMix64 finaliser), so every
/// table cell has its own stream and results do not depend on the order cells are computed in.
#[must_use]
pub fn cell_stream(seed: u64, table: u64, cell: u64) -> u64 {
    let mut z =
        seed ^ table.wrapping_mul(0x9e37_79b9_7f4a_7c15) ^ cell.wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pcg32_matches_the_reference_implementation() {
        // pcg32_srandom_r(&rng, 42, 54) of O'Neill's pcg32-demo, then pcg32_random_r.
        let mut rng = Pcg32::new(42, 54);
        let want = [
            0xa15c_02b7u32,
            0x7b47_f409,
            0xba1d_3330,
            0x83d2_f293,
            0xbfa4_784b,
            0xcbed_606e,
        ];
        for w in want {
            assert_eq!(rng.next_u32(), w);
        }
    }

    #[test]
    fn uniforms_stay_in_their_intervals_and_streams_differ() {
        let mut a = Pcg32::new(1, 2);
        let mut b = Pcg32::new(1, 3);
        let (mut same, mut sum) = (0, 0.0f64);
        for _ in 0..10_000 {
            let u = a.uniform();
            assert!((0.0..1.0).contains(&u));
            let v = a.uniform_open0();
            assert!(v > 0.0 && v <= 1.0);
            sum += f64::from(u);
            same += usize::from(a.next_u32() == b.next_u32());
        }
        assert!(
            (sum / 10_000.0 - 0.5).abs() < 0.01,
            "mean {}",
            sum / 10_000.0
        );
        assert!(same < 5, "streams 2 and 3 agree {same} times");
        // The extremes of the 24-bit grid.
        let mut z = Pcg32::new(0, 0);
        for _ in 0..1000 {
            let u = z.uniform_open0();
            assert!(-libm::logf(u) >= 0.0 && (-libm::logf(u)).is_finite());
        }
    }

    #[test]
    fn cell_streams_are_distinct_and_order_free() {
        let mut seen = [0u64; 64];
        for (k, s) in seen.iter_mut().enumerate() {
            *s = cell_stream(7, 1 + (k as u64 & 1), k as u64 >> 1);
        }
        for i in 0..64 {
            for j in 0..i {
                assert_ne!(seen[i], seen[j], "{i} {j}");
            }
        }
        assert_eq!(cell_stream(7, 2, 5), cell_stream(7, 2, 5));
        assert_ne!(cell_stream(7, 2, 5), cell_stream(8, 2, 5));
    }
}
