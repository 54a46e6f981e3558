//! The `closure` setting of the model (docs/model.md §12): which energy the model keeps.

use core::fmt;

/// `closure`, a choice of the model (docs/model.md §12): [`Closure::Report`] (the default, for
/// now) evaluates the report's equations as written; [`Closure::Energy`] normalises every
/// longitudinal lobe on the sphere of directions, θ_i ∈ [−π/2, π/2]. Energy becomes the
/// default once its baked cost is within budget and its residual term exists (docs/model.md
/// §12, "Status").
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
#[repr(u8)]
pub enum Closure {
    /// The report's model, bit for bit: Gaussian M_p normalised on the whole line.
    #[default]
    Report = 0,
    /// Energy-keeping: M_p renormalised by its mass inside [−π/2, π/2] (docs/model.md §12).
    Energy = 1,
}

impl Closure {
    /// Every closure, by index (the value [`ParamValue::Choice`](super::ParamValue::Choice)
    /// carries and the LUT header stores).
    pub const ALL: [Closure; 2] = [Closure::Report, Closure::Energy];

    /// The names written in preset files, `--set`, EXR attributes, in [`Closure::ALL`] order.
    pub const NAMES: [&'static str; 2] = ["report", "energy"];

    /// The closure of index `index` ([`Closure::ALL`]); `None` past the end.
    #[must_use]
    pub const fn from_index(index: u8) -> Option<Closure> {
        match index {
            0 => Some(Closure::Report),
            1 => Some(Closure::Energy),
            _ => None,
        }
    }

    /// Its index in [`Closure::ALL`].
    #[must_use]
    pub const fn index(self) -> u8 {
        self as u8
    }

    /// Its name ([`Closure::NAMES`]).
    #[must_use]
    pub const fn name(self) -> &'static str {
        Closure::NAMES[self as usize]
    }
}

impl fmt::Display for Closure {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}
