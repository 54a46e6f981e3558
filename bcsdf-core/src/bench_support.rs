//! The query generators of the benchmarks and profiling loops, defined once so that every
//! one of them times the same queries: `bcsdf-core/benches/eval.rs`,
//! `bcsdf-core/examples/far_loop.rs`, `bake/benches/{baked,sampling}.rs`,
//! `bake/examples/{baked_loop,sampling_loop}.rs` and `bcsdf-ffi/benches/ffi.rs` draw from
//! [`QueryStream`]; `bcsdf-gpu`'s benchmark and throughput example use [`indexed_radians`].
//!
//! Not a stable interface (hidden from the docs); no allocation, so usable from `no_std`.

use crate::frame::Angles;
use crate::math::PI;
use crate::rng::{cell_stream, Pcg32};

/// Length of the benchmarks' fixed query lists.
pub const QUERY_COUNT: usize = 256;

/// A deterministic stream of uniform numbers and far-field queries: a 64-bit linear
/// congruential generator (Knuth's MMIX multiplier and increment), each number the top 24
/// bits of the state. Cheap, dependency-free and the same on every target; its quality is
/// only meant to spread queries over the domain.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct QueryStream {
    state: u64,
}

impl Default for QueryStream {
    fn default() -> QueryStream {
        QueryStream::new()
    }
}

impl QueryStream {
    /// The seed every benchmark starts from.
    pub const SEED: u64 = 0x2545_f491_4f6c_dd1d;

    /// The stream from [`QueryStream::SEED`].
    #[must_use]
    pub const fn new() -> QueryStream {
        QueryStream { state: Self::SEED }
    }

    /// The next number, uniform in [0, 1) on a grid of 2^−24.
    #[inline]
    pub fn uniform(&mut self) -> f32 {
        self.state = self
            .state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (self.state >> 40) as f32 / (1u64 << 24) as f32
    }

    /// θ_i and θ_r uniform in [−80°, 80°) and φ in [−180°, 180°), in degrees, drawn in
    /// that order (three numbers).
    pub fn degrees(&mut self) -> [f32; 3] {
        let theta_i = -80.0 + 160.0 * self.uniform();
        let theta_r = -80.0 + 160.0 * self.uniform();
        let phi = -180.0 + 360.0 * self.uniform();
        [theta_i, theta_r, phi]
    }

    /// [`QueryStream::degrees`] as [`Angles`] (three numbers).
    pub fn angles(&mut self) -> Angles {
        let [ti, tr, phi] = self.degrees();
        Angles::from_degrees(ti, tr, phi).expect("θ within ±80° and a finite φ are valid")
    }

    /// A query and a near-field offset h uniform in [−1, 1) (four numbers).
    pub fn angles_and_offset(&mut self) -> (Angles, f32) {
        let angles = self.angles();
        (angles, -1.0 + 2.0 * self.uniform())
    }

    /// A sampler's input: θ_r (radians) uniform in [−80°, 80°), then three uniform numbers
    /// (four numbers).
    pub fn sample_input(&mut self) -> (f32, [f32; 3]) {
        let theta_r = (-80.0 + 160.0 * self.uniform()).to_radians();
        (theta_r, [self.uniform(), self.uniform(), self.uniform()])
    }
}

/// Query `i` of the GPU benchmarks: θ_i and θ_r uniform in [−π/2, π/2) and φ in [−π, π),
/// radians, from PCG32 stream `(cell_stream(3, 1, i), cell_stream(3, 2, i))`, so that any
/// index is generated independently of the others.
#[must_use]
pub fn indexed_radians(i: u64) -> [f32; 3] {
    let mut r = Pcg32::new(cell_stream(3, 1, i), cell_stream(3, 2, i));
    let theta_i = (r.uniform() - 0.5) * PI;
    let theta_r = (r.uniform() - 0.5) * PI;
    let phi = (r.uniform() - 0.5) * 2.0 * PI;
    [theta_i, theta_r, phi]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_stream_is_the_benchmarks_lcg() {
        // The generator the benchmarks were written with, inline.
        let mut state = 0x2545_f491_4f6c_dd1du64;
        let mut next = move || {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((state >> 40) as f32) / (1u64 << 24) as f32
        };
        let mut s = QueryStream::new();
        for _ in 0..1000 {
            assert_eq!(s.uniform().to_bits(), next().to_bits());
        }
    }

    #[test]
    fn queries_cover_their_ranges() {
        let mut s = QueryStream::new();
        let (mut lo, mut hi) = ([f32::MAX; 3], [f32::MIN; 3]);
        for _ in 0..QUERY_COUNT * 4 {
            let d = s.degrees();
            for k in 0..3 {
                lo[k] = lo[k].min(d[k]);
                hi[k] = hi[k].max(d[k]);
            }
            let (a, h) = s.angles_and_offset();
            assert!(a.theta_i().abs() <= 80f32.to_radians() + 1e-6);
            assert!((-1.0..1.0).contains(&h));
            let (tr, u) = s.sample_input();
            assert!(tr.abs() <= 80f32.to_radians() + 1e-6);
            assert!(u.iter().all(|u| (0.0..1.0).contains(u)));
        }
        // Spread over (nearly) the whole range, not stuck in a corner.
        for (k, half) in [80.0, 80.0, 180.0].into_iter().enumerate() {
            assert!(lo[k] >= -half && lo[k] < -0.95 * half, "{k}: {lo:?}");
            assert!(hi[k] < half && hi[k] > 0.95 * half, "{k}: {hi:?}");
        }
    }

    #[test]
    fn indexed_queries_are_independent_of_order() {
        let a = indexed_radians(7);
        assert_eq!(a, indexed_radians(7));
        assert_ne!(a, indexed_radians(8));
        for i in 0..1000 {
            let [ti, tr, phi] = indexed_radians(i);
            assert!((-PI / 2.0..PI / 2.0).contains(&ti) && (-PI / 2.0..PI / 2.0).contains(&tr));
            assert!((-PI..PI).contains(&phi));
        }
    }
}
