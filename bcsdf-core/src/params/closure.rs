//! The `closure` setting of the model (docs/model.md §12): which energy the model keeps.

use core::fmt;

/// `closure`, a choice of the model (docs/model.md §12): [`Closure::Energy`] (the default)
/// normalises every longitudinal lobe on the sphere of directions, θ_i ∈ [−π/2, π/2], and adds
/// the residual of the paths the report leaves out, so that a lossless fiber keeps all the
/// light; [`Closure::Report`] evaluates the report's equations as written (kept bit for bit,
/// for checking against the report and the authors' code).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
#[repr(u8)]
pub enum Closure {
    /// The report's model, bit for bit: Gaussian M_p normalised on the whole line.
    Report = 0,
    /// Energy-keeping, the default: M_p renormalised by its mass inside [−π/2, π/2] and the
    /// residual lobe (docs/model.md §12).
    #[default]
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
