//! The event strings of docs/model.md §3 (which interfaces a path met, in order), and the
//! strings the model's lobes carry: what the residual simulation ([`super::sim`]) tallies as
//! modelled and what it counts as the residual.

/// The event letters of docs/model.md §3: uppercase at the cuticle, lowercase at the medulla.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(u32)]
pub enum Event {
    /// Transmission through the cuticle (in or out).
    T = 0,
    /// Reflection at the cuticle (outside or inside).
    R = 1,
    /// Transmission through the medulla boundary (either way).
    Tm = 2,
    /// Reflection at the medulla boundary (either side, total reflection included).
    Rm = 3,
}

/// An event string, two bits per event; strings longer than 15 events are only "long".
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct Events {
    code: u32,
    len: u8,
}

impl Events {
    /// The empty string.
    pub const EMPTY: Events = Events { code: 0, len: 0 };

    /// The string of `s`, written with T, R, t, r (docs/model.md §3).
    #[must_use]
    pub const fn parse(s: &[u8]) -> Events {
        let mut e = Events::EMPTY;
        let mut k = 0;
        while k < s.len() {
            let ev = match s[k] {
                b'T' => Event::T,
                b'R' => Event::R,
                b't' => Event::Tm,
                _ => Event::Rm,
            };
            e = e.push(ev);
            k += 1;
        }
        e
    }

    /// This string followed by `event`.
    #[must_use]
    pub const fn push(self, event: Event) -> Events {
        if self.len >= 15 {
            return Events {
                code: self.code,
                len: 16,
            };
        }
        Events {
            code: self.code | ((event as u32) << (2 * self.len as u32)),
            len: self.len + 1,
        }
    }
}

/// The eight unscattered paths of docs/model.md §3.
pub const MODELLED_UNSCATTERED: [Events; 8] = [
    Events::parse(b"R"),
    Events::parse(b"TT"),
    Events::parse(b"TRT"),
    Events::parse(b"TrT"),
    Events::parse(b"TttT"),
    Events::parse(b"TtrtT"),
    Events::parse(b"TrRrT"),
    Events::parse(b"TttRttT"),
];

/// The strings before the scattering chord of the three scattered lobes (docs/model.md §6).
pub const MODELLED_BEFORE_SCATTERING: [Events; 3] = [
    Events::parse(b"Tt"),
    Events::parse(b"Ttr"),
    Events::parse(b"TttRt"),
];

/// The only string after the last… first scattering the model's scattered lobes carry: leave
/// the medulla, leave the cuticle.
pub const MODELLED_AFTER_SCATTERING: Events = Events::parse(b"tT");
