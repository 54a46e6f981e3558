//! RGB values: absorption coefficients, attenuations and BCSDF values.

use core::ops::{Add, AddAssign, Index, IndexMut, Mul, Sub};

/// Three f32 channels (linear RGB). `repr(transparent)`: a slice of `Rgb` is a slice of
/// interleaved f32 triples (the C ABI's `out_rgb` arrays).
///
/// Channel-wise arithmetic (`+`, `-`, `*` by an `Rgb` or an `f32`), indexing by channel and
/// conversion from and to `[f32; 3]`:
///
/// ```
/// use bcsdf_core::Rgb;
///
/// let a = Rgb::from([0.5, 1.0, 2.0]);
/// let b = Rgb::splat(0.5);
/// assert_eq!(a * b, Rgb([0.25, 0.5, 1.0]));
/// assert_eq!(a - b + b, a);
/// assert_eq!(a[2], 2.0);
/// assert_eq!(<[f32; 3]>::from(a * 2.0), [1.0, 2.0, 4.0]);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[repr(transparent)]
pub struct Rgb(pub [f32; 3]);

impl Rgb {
    /// All channels zero.
    pub const ZERO: Rgb = Rgb([0.0; 3]);

    /// The same value in all three channels.
    #[inline]
    #[must_use]
    pub const fn splat(v: f32) -> Rgb {
        Rgb([v, v, v])
    }

    /// Applies `f` to each channel.
    ///
    /// ```
    /// # use bcsdf_core::Rgb;
    /// assert_eq!(Rgb([1.0, 4.0, 9.0]).map(f32::sqrt), Rgb([1.0, 2.0, 3.0]));
    /// ```
    #[inline]
    #[must_use]
    pub fn map(self, f: impl Fn(f32) -> f32) -> Rgb {
        Rgb([f(self.0[0]), f(self.0[1]), f(self.0[2])])
    }

    /// The largest channel.
    ///
    /// ```
    /// # use bcsdf_core::Rgb;
    /// assert_eq!(Rgb([0.2, 0.7, -1.0]).max_channel(), 0.7);
    /// ```
    #[inline]
    #[must_use]
    pub fn max_channel(self) -> f32 {
        self.0[0].max(self.0[1]).max(self.0[2])
    }

    /// True when every channel is finite.
    ///
    /// ```
    /// # use bcsdf_core::Rgb;
    /// assert!(Rgb([0.0, 1.0, 2.0]).is_finite());
    /// assert!(!Rgb([0.0, f32::NAN, 2.0]).is_finite());
    /// ```
    #[inline]
    #[must_use]
    pub fn is_finite(self) -> bool {
        self.0.iter().all(|c| c.is_finite())
    }

    /// Relative luminance Y = 0.2126·R + 0.7152·G + 0.0722·B: the Rec. 709 (and sRGB)
    /// weights, for linear channels with Rec. 709 primaries and a D65 white.
    ///
    /// ```
    /// # use bcsdf_core::Rgb;
    /// assert!((Rgb::splat(1.0).luminance() - 1.0).abs() < 1e-6); // the weights sum to 1
    /// assert_eq!(Rgb([0.0, 1.0, 0.0]).luminance(), 0.7152);
    /// ```
    #[inline]
    #[must_use]
    pub fn luminance(self) -> f32 {
        0.2126 * self.0[0] + 0.7152 * self.0[1] + 0.0722 * self.0[2]
    }
}

impl From<[f32; 3]> for Rgb {
    /// The channels in R, G, B order.
    ///
    /// ```
    /// # use bcsdf_core::Rgb;
    /// let c: Rgb = [0.1, 0.2, 0.3].into();
    /// assert_eq!(c, Rgb([0.1, 0.2, 0.3]));
    /// ```
    #[inline]
    fn from(c: [f32; 3]) -> Rgb {
        Rgb(c)
    }
}

impl From<Rgb> for [f32; 3] {
    /// The channels in R, G, B order.
    ///
    /// ```
    /// # use bcsdf_core::Rgb;
    /// let c: [f32; 3] = Rgb([0.1, 0.2, 0.3]).into();
    /// assert_eq!(c, [0.1, 0.2, 0.3]);
    /// ```
    #[inline]
    fn from(c: Rgb) -> [f32; 3] {
        c.0
    }
}

impl Index<usize> for Rgb {
    type Output = f32;
    /// Channel `i`: 0 red, 1 green, 2 blue; panics for `i > 2`, as an array does.
    ///
    /// ```
    /// # use bcsdf_core::Rgb;
    /// let c = Rgb([0.1, 0.2, 0.3]);
    /// assert_eq!((c[0], c[1], c[2]), (0.1, 0.2, 0.3));
    /// ```
    #[inline]
    fn index(&self, i: usize) -> &f32 {
        &self.0[i]
    }
}

impl IndexMut<usize> for Rgb {
    /// Channel `i`, writable; panics for `i > 2`.
    ///
    /// ```
    /// # use bcsdf_core::Rgb;
    /// let mut c = Rgb::ZERO;
    /// c[1] = 0.5;
    /// assert_eq!(c, Rgb([0.0, 0.5, 0.0]));
    /// ```
    #[inline]
    fn index_mut(&mut self, i: usize) -> &mut f32 {
        &mut self.0[i]
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

impl Sub for Rgb {
    type Output = Rgb;
    /// Channel-wise difference (not clamped: channels can become negative).
    ///
    /// ```
    /// # use bcsdf_core::Rgb;
    /// assert_eq!(Rgb([1.0, 2.0, 3.0]) - Rgb::splat(1.5), Rgb([-0.5, 0.5, 1.5]));
    /// ```
    #[inline]
    fn sub(self, o: Rgb) -> Rgb {
        Rgb([self.0[0] - o.0[0], self.0[1] - o.0[1], self.0[2] - o.0[2]])
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arithmetic_is_channel_wise() {
        let a = Rgb([1.0, -2.0, 0.5]);
        let b = Rgb([0.25, 4.0, 8.0]);
        assert_eq!(a + b, Rgb([1.25, 2.0, 8.5]));
        assert_eq!(a - b, Rgb([0.75, -6.0, -7.5]));
        assert_eq!(a * b, Rgb([0.25, -8.0, 4.0]));
        assert_eq!(a * 2.0, Rgb([2.0, -4.0, 1.0]));
        let mut c = a;
        c += b;
        assert_eq!(c, a + b);
        for i in 0..3 {
            assert_eq!((a - b)[i], a.0[i] - b.0[i]);
        }
    }

    #[test]
    fn conversions_and_indexing_keep_channel_order() {
        let arr = [0.1f32, 0.2, 0.3];
        let c = Rgb::from(arr);
        assert_eq!(<[f32; 3]>::from(c), arr);
        assert_eq!([c[0], c[1], c[2]], arr);
        let mut d = Rgb::ZERO;
        d[2] = 7.0;
        d[0] = -1.0;
        assert_eq!(d, Rgb([-1.0, 0.0, 7.0]));
    }

    #[test]
    #[should_panic]
    fn indexing_past_blue_panics() {
        let c = Rgb::ZERO;
        let i = core::hint::black_box(3);
        let _ = c[i];
    }

    #[test]
    fn luminance_uses_the_rec709_weights() {
        assert_eq!(Rgb([1.0, 0.0, 0.0]).luminance(), 0.2126);
        assert_eq!(Rgb([0.0, 1.0, 0.0]).luminance(), 0.7152);
        assert_eq!(Rgb([0.0, 0.0, 1.0]).luminance(), 0.0722);
        assert!((Rgb::splat(0.5).luminance() - 0.5).abs() < 1e-7);
        // Linear: the luminance of a sum is the sum of the luminances.
        let (a, b) = (Rgb([0.3, 0.1, 0.9]), Rgb([0.2, 0.6, 0.05]));
        assert!(((a + b).luminance() - (a.luminance() + b.luminance())).abs() < 1e-6);
    }

    #[test]
    fn helpers() {
        assert_eq!(Rgb::splat(2.0), Rgb([2.0; 3]));
        assert_eq!(Rgb([3.0, -1.0, 2.0]).max_channel(), 3.0);
        assert_eq!(Rgb([1.0, 2.0, 3.0]).map(|c| c * c), Rgb([1.0, 4.0, 9.0]));
        assert!(Rgb::ZERO.is_finite());
        assert!(!Rgb([0.0, 0.0, f32::INFINITY]).is_finite());
    }
}
