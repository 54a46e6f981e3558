//! RGB values: absorption coefficients, attenuations and BCSDF values.

use core::ops::{Add, AddAssign, Mul};

/// Three f32 channels (linear RGB). `repr(transparent)`: a slice of `Rgb` is a slice of
/// interleaved f32 triples (the C ABI's `out_rgb` arrays).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[repr(transparent)]
pub struct Rgb(pub [f32; 3]);

impl Rgb {
    /// All channels zero.
    pub const ZERO: Rgb = Rgb([0.0; 3]);

    /// The same value in all three channels.
    #[inline]
    pub const fn splat(v: f32) -> Rgb {
        Rgb([v, v, v])
    }

    /// Applies `f` to each channel.
    #[inline]
    pub fn map(self, f: impl Fn(f32) -> f32) -> Rgb {
        Rgb([f(self.0[0]), f(self.0[1]), f(self.0[2])])
    }

    /// The largest channel.
    #[inline]
    pub fn max_channel(self) -> f32 {
        self.0[0].max(self.0[1]).max(self.0[2])
    }

    /// True when every channel is finite.
    #[inline]
    pub fn is_finite(self) -> bool {
        self.0.iter().all(|c| c.is_finite())
    }
}

impl Add for Rgb {
    type Output = Rgb;
    #[inline]
    fn add(self, o: Rgb) -> Rgb {
        Rgb([self.0[0] + o.0[0], self.0[1] + o.0[1], self.0[2] + o.0[2]])
    }
}

impl AddAssign for Rgb {
    #[inline]
    fn add_assign(&mut self, o: Rgb) {
        *self = *self + o;
    }
}

impl Mul for Rgb {
    type Output = Rgb;
    #[inline]
    fn mul(self, o: Rgb) -> Rgb {
        Rgb([self.0[0] * o.0[0], self.0[1] * o.0[1], self.0[2] * o.0[2]])
    }
}

impl Mul<f32> for Rgb {
    type Output = Rgb;
    #[inline]
    fn mul(self, s: f32) -> Rgb {
        Rgb([self.0[0] * s, self.0[1] * s, self.0[2] * s])
    }
}
