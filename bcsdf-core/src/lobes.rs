//! Lobe names and the per-lobe breakdown of an evaluation.

use crate::spectrum::Rgb;

/// One light path of the model (docs/model.md §3, §6). Uppercase events happen at the cuticle,
/// lowercase at the medulla boundary.
///
/// The first eight are the unscattered paths (docs/model.md §3); the next three carry the light
/// scattered inside the medulla (docs/model.md §6); the last, [`Lobe::Residual`], every path the
/// eleven leave out (the energy closure's residual, docs/model.md §12; zero in the report
/// closure). Code matching on it should use `Lobe::ALL` and [`Lobe::name`].
#[non_exhaustive]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Lobe {
    /// Reflection off the cuticle.
    R = 0,
    /// Through the cortex, missing the medulla.
    TT = 1,
    /// Through the cortex with one internal reflection, missing the medulla.
    TRT = 2,
    /// Reflected off the medulla from the cortex side.
    TrT = 3,
    /// Straight through the medulla.
    TttT = 4,
    /// Into the medulla, reflected inside it, out.
    TtrtT = 5,
    /// Reflected off the medulla, the cuticle and the medulla again.
    TrRrT = 6,
    /// Through the medulla, reflected at the cuticle, through the medulla again.
    TttRttT = 7,
    /// Scattered inside the medulla on the first medulla chord (TttT^s).
    TttTs = 8,
    /// Scattered on the chord after a reflection inside the medulla (TtrtT^s).
    TtrtTs = 9,
    /// Scattered on the medulla chord after the cuticle reflection (TttRttT^s).
    TttRttTs = 10,
    /// The energy closure's residual S_res = M_TRT·N_res/cos²θ_i: every path the eleven lobes
    /// leave out (docs/model.md §12, "Residual"); in the TRT family, zero in the report closure.
    Residual = 11,
}

/// Number of lobes in a [`Lobes`] breakdown.
pub const LOBE_COUNT: usize = 12;

/// Number of unscattered lobes (the first ones in [`Lobe::ALL`]).
pub const UNSCATTERED_COUNT: usize = 8;

/// The three cuticle groups that share tilt and roughness (docs/model.md §5).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum LobeGroup {
    /// R: touches the cuticle once from outside.
    R = 0,
    /// TT, TrT, TttT, TtrtT: crosses the cuticle twice.
    TT = 1,
    /// TRT, TrRrT, TttRttT: crosses twice and reflects inside once.
    TRT = 2,
}

impl Lobe {
    /// All lobes in breakdown order.
    pub const ALL: [Lobe; LOBE_COUNT] = [
        Lobe::R,
        Lobe::TT,
        Lobe::TRT,
        Lobe::TrT,
        Lobe::TttT,
        Lobe::TtrtT,
        Lobe::TrRrT,
        Lobe::TttRttT,
        Lobe::TttTs,
        Lobe::TtrtTs,
        Lobe::TttRttTs,
        Lobe::Residual,
    ];

    /// The path's name as written in docs/model.md (`"TttRttT"`).
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            Lobe::R => "R",
            Lobe::TT => "TT",
            Lobe::TRT => "TRT",
            Lobe::TrT => "TrT",
            Lobe::TttT => "TttT",
            Lobe::TtrtT => "TtrtT",
            Lobe::TrRrT => "TrRrT",
            Lobe::TttRttT => "TttRttT",
            Lobe::TttTs => "TttT_s",
            Lobe::TtrtTs => "TtrtT_s",
            Lobe::TttRttTs => "TttRttT_s",
            Lobe::Residual => "residual",
        }
    }

    /// The eight unscattered paths, in breakdown order.
    pub const UNSCATTERED: [Lobe; UNSCATTERED_COUNT] = [
        Lobe::R,
        Lobe::TT,
        Lobe::TRT,
        Lobe::TrT,
        Lobe::TttT,
        Lobe::TtrtT,
        Lobe::TrRrT,
        Lobe::TttRttT,
    ];

    /// The three scattered lobes, in breakdown order.
    pub const SCATTERED: [Lobe; 3] = [Lobe::TttTs, Lobe::TtrtTs, Lobe::TttRttTs];

    /// Index into [`Lobes`].
    #[must_use]
    pub const fn index(self) -> usize {
        self as usize
    }

    /// The cuticle group whose M_p an unscattered path (or the residual, which uses TRT's M,
    /// docs/model.md §12) uses; `None` for the scattered lobes, which share M^s.
    #[must_use]
    pub const fn group(self) -> Option<LobeGroup> {
        match self {
            Lobe::R => Some(LobeGroup::R),
            Lobe::TT | Lobe::TrT | Lobe::TttT | Lobe::TtrtT => Some(LobeGroup::TT),
            Lobe::TRT | Lobe::TrRrT | Lobe::TttRttT | Lobe::Residual => Some(LobeGroup::TRT),
            Lobe::TttTs | Lobe::TtrtTs | Lobe::TttRttTs => None,
        }
    }

    /// The cuticle group of unscattered path `index` (< [`UNSCATTERED_COUNT`]).
    #[must_use]
    pub const fn unscattered_group(index: usize) -> LobeGroup {
        match index {
            0 => LobeGroup::R,
            1 | 3 | 4 | 5 => LobeGroup::TT,
            _ => LobeGroup::TRT,
        }
    }

    /// True for the lobes scattered inside the medulla.
    #[must_use]
    pub const fn is_scattered(self) -> bool {
        self.group().is_none()
    }
}

/// Per-lobe RGB values of one evaluation; [`Lobes::total`] is the BCSDF value.
///
/// ```
/// use bcsdf_core::{Lobe, LobeFamily, LobeGroup, Lobes, Rgb, LOBE_COUNT};
///
/// let mut values = [Rgb::ZERO; LOBE_COUNT];
/// values[Lobe::R.index()] = Rgb::splat(0.125);
/// values[Lobe::TrT.index()] = Rgb::splat(0.25);
/// values[Lobe::TttTs.index()] = Rgb::splat(0.5);
/// let lobes = Lobes::from_array(values);
///
/// assert_eq!(lobes.get(Lobe::TrT), Rgb::splat(0.25));
/// assert_eq!(lobes.total(), Rgb::splat(0.875));
/// // TrT crosses the cuticle twice: it shares the TT group's tilt and roughness.
/// assert_eq!(Lobe::TrT.group(), Some(LobeGroup::TT));
/// assert_eq!(lobes.families().get(LobeFamily::TT), Rgb::splat(0.25));
/// assert_eq!(LobeFamily::of(Lobe::TttTs), LobeFamily::Scattered);
/// assert_eq!(Lobe::TttTs.name(), "TttT_s");
/// assert_eq!(lobes.iter().filter(|(_, v)| v.max_channel() > 0.0).count(), 3);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[must_use]
pub struct Lobes {
    values: [Rgb; LOBE_COUNT],
}

impl Lobes {
    /// All lobes zero.
    pub const ZERO: Lobes = Lobes {
        values: [Rgb::ZERO; LOBE_COUNT],
    };

    /// From values in [`Lobe::ALL`] order.
    pub const fn from_array(values: [Rgb; LOBE_COUNT]) -> Lobes {
        Lobes { values }
    }

    /// One lobe's value.
    #[must_use]
    pub fn get(&self, lobe: Lobe) -> Rgb {
        self.values[lobe.index()]
    }

    /// All values in [`Lobe::ALL`] order.
    #[must_use]
    pub fn as_array(&self) -> &[Rgb; LOBE_COUNT] {
        &self.values
    }

    /// `(lobe, value)` pairs in [`Lobe::ALL`] order.
    pub fn iter(&self) -> impl Iterator<Item = (Lobe, Rgb)> + '_ {
        Lobe::ALL.iter().map(move |&l| (l, self.values[l.index()]))
    }

    /// The sum over all lobes: S.
    #[must_use]
    pub fn total(&self) -> Rgb {
        self.values.iter().fold(Rgb::ZERO, |acc, &v| acc + v)
    }
}

/// Number of lobe families ([`LobeFamily`]).
pub const FAMILY_COUNT: usize = 4;

/// The four families a baked table keeps apart: the three cuticle groups of the unscattered
/// paths (each shares one M_p, docs/model.md §5) and the medulla-scattered lobes (which share M^s,
/// docs/model.md §6).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum LobeFamily {
    /// R.
    R = 0,
    /// TT, TrT, TttT, TtrtT.
    TT = 1,
    /// TRT, TrRrT, TttRttT and the energy closure's residual (docs/model.md §12).
    TRT = 2,
    /// TttT^s, TtrtT^s, TttRttT^s.
    Scattered = 3,
}

impl LobeFamily {
    /// All families in order.
    pub const ALL: [LobeFamily; FAMILY_COUNT] = [
        LobeFamily::R,
        LobeFamily::TT,
        LobeFamily::TRT,
        LobeFamily::Scattered,
    ];

    /// Short name: `R`, `TT`, `TRT`, `scattered`.
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            LobeFamily::R => "R",
            LobeFamily::TT => "TT",
            LobeFamily::TRT => "TRT",
            LobeFamily::Scattered => "scattered",
        }
    }

    /// The family a lobe belongs to.
    #[must_use]
    pub const fn of(lobe: Lobe) -> LobeFamily {
        match lobe.group() {
            Some(LobeGroup::R) => LobeFamily::R,
            Some(LobeGroup::TT) => LobeFamily::TT,
            Some(LobeGroup::TRT) => LobeFamily::TRT,
            None => LobeFamily::Scattered,
        }
    }
}

/// Per-family RGB values of one far-field evaluation; [`Families::total`] is S.
///
/// ```
/// use bcsdf_core::{Families, LobeFamily, Rgb};
///
/// let f = Families::from_array([Rgb::splat(1.0), Rgb::splat(2.0), Rgb::ZERO, Rgb::splat(0.5)]);
/// assert_eq!(f.get(LobeFamily::TT), Rgb::splat(2.0));
/// assert_eq!(f.total(), Rgb::splat(3.5));
/// assert_eq!(LobeFamily::ALL.map(LobeFamily::name), ["R", "TT", "TRT", "scattered"]);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[must_use]
pub struct Families {
    values: [Rgb; FAMILY_COUNT],
}

impl Families {
    /// All families zero.
    pub const ZERO: Families = Families {
        values: [Rgb::ZERO; FAMILY_COUNT],
    };

    /// From values in [`LobeFamily::ALL`] order.
    #[inline]
    pub const fn from_array(values: [Rgb; FAMILY_COUNT]) -> Families {
        Families { values }
    }

    /// One family's value.
    #[inline]
    #[must_use]
    pub fn get(&self, family: LobeFamily) -> Rgb {
        self.values[family as usize]
    }

    /// All values in [`LobeFamily::ALL`] order.
    #[must_use]
    pub fn as_array(&self) -> &[Rgb; FAMILY_COUNT] {
        &self.values
    }

    /// The sum over all families: S.
    #[inline]
    #[must_use]
    pub fn total(&self) -> Rgb {
        self.values.iter().fold(Rgb::ZERO, |acc, &v| acc + v)
    }
}

impl Lobes {
    /// The lobes summed per [`LobeFamily`].
    pub fn families(&self) -> Families {
        let mut out = [Rgb::ZERO; FAMILY_COUNT];
        for (lobe, v) in self.iter() {
            out[LobeFamily::of(lobe) as usize] += v;
        }
        Families::from_array(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lobe_order_indices_and_names_agree() {
        for (i, lobe) in Lobe::ALL.iter().enumerate() {
            assert_eq!(lobe.index(), i);
            for other in &Lobe::ALL[..i] {
                assert_ne!(lobe.name(), other.name());
            }
        }
        // The unscattered and scattered lists split ALL in order.
        assert_eq!(Lobe::UNSCATTERED[..], Lobe::ALL[..UNSCATTERED_COUNT]);
        assert_eq!(
            Lobe::SCATTERED[..],
            Lobe::ALL[UNSCATTERED_COUNT..UNSCATTERED_COUNT + 3]
        );
        assert_eq!(Lobe::ALL[LOBE_COUNT - 1], Lobe::Residual);
        for (i, lobe) in Lobe::UNSCATTERED.iter().enumerate() {
            assert_eq!(lobe.group(), Some(Lobe::unscattered_group(i)));
            assert!(!lobe.is_scattered());
        }
        assert!(Lobe::SCATTERED.iter().all(|l| l.is_scattered()));
    }

    #[test]
    fn groups_follow_the_cuticle_crossings() {
        // R touches the cuticle once; the TT group crosses it twice; TRT reflects inside.
        let group = |g| Lobe::ALL.iter().filter(move |l| l.group() == Some(g));
        assert_eq!(group(LobeGroup::R).count(), 1);
        assert!(group(LobeGroup::TT).all(|l| !l.name().contains('R')));
        assert!(group(LobeGroup::TRT).all(|l| l.name().contains('R') || l == &Lobe::Residual));
        assert_eq!(group(LobeGroup::TRT).count(), 4);
        for lobe in Lobe::ALL {
            let fam = LobeFamily::of(lobe);
            match lobe.group() {
                Some(g) => assert_eq!(fam as usize, g as usize),
                None => assert_eq!(fam, LobeFamily::Scattered),
            }
        }
    }

    #[test]
    fn families_sum_their_lobes() {
        let mut values = [Rgb::ZERO; LOBE_COUNT];
        for (i, v) in values.iter_mut().enumerate() {
            *v = Rgb([1.0, 2.0, 4.0]) * (1u32 << i) as f32;
        }
        let lobes = Lobes::from_array(values);
        let fam = lobes.families();
        // Bit masks of the lobes in each family: R {0}, TT {1,3,4,5}, TRT {2,6,7,11},
        // s {8,9,10}.
        let masks = [0b1u32, 0b11_1010, 0b1000_1100_0100, 0b111_0000_0000];
        for (f, mask) in LobeFamily::ALL.iter().zip(masks) {
            assert_eq!(fam.get(*f), Rgb([1.0, 2.0, 4.0]) * mask as f32, "{f:?}");
        }
        assert_eq!(fam.total(), lobes.total());
        assert_eq!(lobes.total(), Rgb([4095.0, 8190.0, 16380.0]));
        assert_eq!(lobes.as_array(), &values);
        assert_eq!(Lobes::ZERO.total(), Rgb::ZERO);
        assert_eq!(Families::ZERO, Lobes::ZERO.families());
    }
}
