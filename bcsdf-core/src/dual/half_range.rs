//! The value sets of the `.furdual` blob's stored halves ([`super::blob`]'s decode, docs/lut.md),
//! checked on the f16 bits without converting them.

/// The set a stored half must lie in, checked on its bits: finite (exponent field not all
/// ones), and for the signed sets compared as its value compares (±0 belongs to both sides).
#[derive(Clone, Copy)]
pub(super) enum HalfRange {
    Finite,
    NonNegative,
    NonPositive,
    /// [0, 1].
    Unit,
}

impl HalfRange {
    pub(super) fn holds(self, h: u16) -> bool {
        const EXPONENT: u16 = 0x7c00;
        const SIGN: u16 = 0x8000;
        const ONE: u16 = 0x3c00;
        let magnitude = h & !SIGN;
        let finite = h & EXPONENT != EXPONENT;
        let non_negative = h & SIGN == 0 || magnitude == 0;
        finite
            && match self {
                HalfRange::Finite => true,
                HalfRange::NonNegative => non_negative,
                HalfRange::NonPositive => h & SIGN != 0 || magnitude == 0,
                HalfRange::Unit => non_negative && magnitude <= ONE,
            }
    }
}
