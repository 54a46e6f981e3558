//! The LUT header codec: [`LutHeader::encode`] and [`LutHeader::decode`] (byte layout in
//! the [`super`] module docs and docs/lut.md). The parameter block follows the parameter
//! schema ([`crate::params::SCHEMA`]): the decoder iterates [`ParamName::ALL`], the encoder
//! [`crate::params::ResolvedParams::fields`] (every default written out, so no parameter
//! can be missing; `params::tests` checks that the two orders agree).

use super::{
    is_valid_scale, LutError, LutHeader, LutResolution, ProfileProvenance, Table, CHECKSUM,
    FORMAT_VERSION, HEADER_LEN, MAGIC, PROFILES, RESERVED, TABLE_COUNT,
};
use crate::medulla::{PhotonBudget, Resolution};
use crate::params::{FurParams, FurParamsInput, HeaderField, ParamName, ParamValue};
use crate::pigment::Pigment;
use crate::spectrum::Rgb;

struct Writer<'a> {
    out: &'a mut [u8; HEADER_LEN],
    at: usize,
}

impl Writer<'_> {
    fn bytes(&mut self, b: &[u8]) {
        self.out[self.at..self.at + b.len()].copy_from_slice(b);
        self.at += b.len();
    }
    fn u32(&mut self, v: u32) {
        self.bytes(&v.to_le_bytes());
    }
    fn u64(&mut self, v: u64) {
        self.bytes(&v.to_le_bytes());
    }
    fn f32(&mut self, v: f32) {
        self.bytes(&v.to_le_bytes());
    }
}

struct Reader<'a> {
    bytes: &'a [u8],
    at: usize,
}

impl Reader<'_> {
    fn take<const N: usize>(&mut self) -> [u8; N] {
        let mut b = [0u8; N];
        // The caller checked the header length; a short read would leave zeros, never panic.
        if let Some(src) = self.bytes.get(self.at..self.at + N) {
            b.copy_from_slice(src);
        }
        self.at += N;
        b
    }
    fn u32(&mut self) -> u32 {
        u32::from_le_bytes(self.take())
    }
    fn u64(&mut self) -> u64 {
        u64::from_le_bytes(self.take())
    }
    fn f32(&mut self) -> f32 {
        f32::from_le_bytes(self.take())
    }
}

/// The header's pigment record: kind (0 = σ_ca RGB, 1 = melanin, 2 = base colour) and three
/// values (melanin: eumelanin, pheomelanin, 0). A LUT never holds kind 2 (`bake` records the
/// σ_ca a base colour resolves to, docs/model.md §14); the decoder reads it and then refuses
/// it through [`FurParams::new`], as it refuses any parameters that build no model.
fn pigment_record(pigment: &Pigment) -> (u32, [f32; 3]) {
    match *pigment {
        Pigment::Absorption(s) => (0, s.0),
        Pigment::Melanin {
            eumelanin,
            pheomelanin,
        } => (1, [eumelanin, pheomelanin, 0.0]),
        Pigment::BaseColour(c) => (2, c.0),
    }
}

impl LutHeader {
    /// The scale s₀ of this LUT's absorption axis ([`super::absorption_scale`] of the
    /// parameters' κ; header byte 156).
    #[must_use]
    pub fn absorption_scale(&self) -> f32 {
        super::absorption_scale(self.params.kappa)
    }

    /// The header as bytes, checksum field zero (see [`seal`](super::seal)).
    #[must_use]
    pub fn encode(&self) -> [u8; HEADER_LEN] {
        let mut out = [0u8; HEADER_LEN];
        let mut w = Writer {
            out: &mut out,
            at: 0,
        };
        w.bytes(&MAGIC);
        w.u32(FORMAT_VERSION);
        w.u32(crate::model::MODEL_VERSION);
        for (_, n) in self.res.axes() {
            w.u32(n);
        }
        for s in self.scales {
            w.f32(s);
        }
        // The parameter block: every parameter in schema order, the three colour parameters
        // as one pigment record (kind, three values) at the first colour position.
        for field in self.params.resolve().fields() {
            match field {
                HeaderField::Pigment(pigment) => {
                    let (kind, pig) = pigment_record(&pigment);
                    w.u32(kind);
                    for v in pig {
                        w.f32(v);
                    }
                }
                HeaderField::Scalar(_, v) => w.f32(v),
                HeaderField::Choice(_, i) => w.u32(u32::from(i)),
            }
        }
        match &self.profiles {
            Some(pr) => {
                w.u32(1);
                w.u32(pr.generator_version);
                w.u64(pr.seed);
                w.u32(pr.budget.per_cn_cell);
                w.u32(pr.budget.per_cm_row);
                for n in [
                    pr.res.n_sigma,
                    pr.res.n_h,
                    pr.res.n_psi,
                    pr.res.n_in,
                    pr.res.n_out,
                ] {
                    w.u32(n as u32);
                }
            }
            None => w.bytes(&[0u8; RESERVED - PROFILES]),
        }
        w.f32(self.absorption_scale());
        debug_assert_eq!(w.at, CHECKSUM.start);
        out
    }

    /// Reads and checks the header of `bytes` (magic, versions, resolution, total length,
    /// scales, parameters, flags); the table values and checksum are checked by
    /// [`validate`](super::validate).
    pub fn decode(bytes: &[u8]) -> Result<LutHeader, LutError> {
        if bytes.len() < HEADER_LEN {
            return Err(LutError::TooShort { len: bytes.len() });
        }
        if bytes[..8] != MAGIC {
            return Err(LutError::BadMagic);
        }
        let mut r = Reader { bytes, at: 8 };
        let format = r.u32();
        if format != FORMAT_VERSION {
            return Err(LutError::FormatVersion { found: format });
        }
        let model = r.u32();
        if model != crate::model::MODEL_VERSION {
            return Err(LutError::ModelVersion { found: model });
        }
        let res = LutResolution {
            n_sum: r.u32(),
            n_theta_r: r.u32(),
            n_phi: r.u32(),
            n_ms_i: r.u32(),
            n_ms_r: r.u32(),
            n_abs: r.u32(),
        };
        res.validate()?;
        if bytes.len() != res.blob_len() {
            return Err(LutError::Length {
                expected: res.blob_len(),
                found: bytes.len(),
            });
        }
        let mut scales = [0.0; TABLE_COUNT];
        for (t, s) in Table::ALL.iter().zip(scales.iter_mut()) {
            *s = r.f32();
            if !is_valid_scale(*s) {
                return Err(LutError::Scale {
                    table: *t,
                    value: *s,
                });
            }
        }
        let mut params = FurParamsInput::zeroed();
        for name in ParamName::ALL {
            if name == ParamName::SigmaCa {
                let kind = r.u32();
                let pig = [r.f32(), r.f32(), r.f32()];
                params.pigment = match kind {
                    0 => Pigment::Absorption(Rgb(pig)),
                    1 if pig[2] == 0.0 => Pigment::Melanin {
                        eumelanin: pig[0],
                        pheomelanin: pig[1],
                    },
                    2 => Pigment::BaseColour(Rgb(pig)),
                    _ => return Err(LutError::Field { field: "pigment" }),
                };
            } else if name.spec().is_choice() {
                let index = r.u32();
                if usize::try_from(index).map_or(true, |i| i >= name.spec().choices.len()) {
                    return Err(LutError::Field { field: name.key() });
                }
                params.set_value(name, ParamValue::Choice(index as u8));
            } else if !name.is_colour() {
                params.set(name, r.f32());
            }
        }
        FurParams::new(&params).map_err(LutError::Params)?;
        let has_profiles = r.u32();
        let generator_version = r.u32();
        let seed = r.u64();
        let budget = PhotonBudget {
            per_cn_cell: r.u32(),
            per_cm_row: r.u32(),
        };
        let pres = Resolution {
            n_sigma: r.u32() as usize,
            n_h: r.u32() as usize,
            n_psi: r.u32() as usize,
            n_in: r.u32() as usize,
            n_out: r.u32() as usize,
        };
        let profiles = match has_profiles {
            0 => {
                if bytes[PROFILES..RESERVED].iter().any(|&b| b != 0) {
                    return Err(LutError::Field { field: "profiles" });
                }
                None
            }
            1 => Some(ProfileProvenance {
                generator_version,
                seed,
                budget,
                res: pres,
            }),
            _ => {
                return Err(LutError::Field {
                    field: "has_profiles",
                })
            }
        };
        let stored = f32::from_le_bytes([
            bytes[RESERVED],
            bytes[RESERVED + 1],
            bytes[RESERVED + 2],
            bytes[RESERVED + 3],
        ]);
        if stored.to_bits() != super::absorption_scale(params.kappa).to_bits() {
            return Err(LutError::Field {
                field: "absorption_scale",
            });
        }
        Ok(LutHeader {
            res,
            scales,
            params,
            profiles,
        })
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use crate::lut::{seal, validate};
    use crate::params::{ParamValue, SCHEMA};
    use std::vec;
    use std::vec::Vec;

    pub(super) fn header(preset: &str) -> LutHeader {
        LutHeader {
            res: LutResolution {
                n_sum: 3,
                n_theta_r: 2,
                n_phi: 4,
                n_ms_i: 2,
                n_ms_r: 3,
                n_abs: 3,
            },
            scales: [1.0, 0.5, 2.0],
            params: crate::presets::find(preset).unwrap().input,
            profiles: Some(ProfileProvenance {
                generator_version: 7,
                seed: 0x0123_4567_89ab_cdef,
                budget: PhotonBudget {
                    per_cn_cell: 11,
                    per_cm_row: 13,
                },
                res: Resolution {
                    n_sigma: 2,
                    n_h: 3,
                    n_psi: 4,
                    n_in: 5,
                    n_out: 6,
                },
            }),
        }
    }

    /// A whole blob around `h`: zero tables, sealed (sampling section and checksum).
    pub(super) fn blob(h: &LutHeader) -> Vec<u8> {
        let mut bytes = vec![0u8; h.res.blob_len()];
        bytes[..HEADER_LEN].copy_from_slice(&h.encode());
        seal(&mut bytes);
        bytes
    }

    #[test]
    fn header_round_trips_through_a_sealed_blob() {
        for preset in ["human-hair", "bobcat", "air-medulla"] {
            let mut h = header(preset);
            let back = validate(&blob(&h)).unwrap();
            // Decoding writes the SameAs defaults out, as the encoder stores them.
            h.params = h.params.resolved();
            assert_eq!(back, h, "{preset}");
            assert_eq!(back.encode(), h.encode());
        }
        let mut h = header("human-hair");
        h.profiles = None;
        assert_eq!(validate(&blob(&h)).unwrap().profiles, None);
    }

    #[test]
    fn every_parameter_has_its_own_bytes_in_the_header() {
        let base = header("bobcat");
        let reference = base.encode();
        for spec in &SCHEMA {
            let mut h = base;
            let nudged = match base.params.resolved().value(spec.name) {
                Some(ParamValue::Scalar(v)) => {
                    // A quarter of the way into the domain (or three quarters, if v is there).
                    let d = spec.domain;
                    let q1 = d.lo + 0.25 * (d.hi - d.lo);
                    ParamValue::Scalar(if v == q1 {
                        d.hi - 0.25 * (d.hi - d.lo)
                    } else {
                        q1
                    })
                }
                Some(ParamValue::Rgb(c)) => ParamValue::Rgb(c * 0.5),
                // The other choice.
                Some(ParamValue::Choice(i)) => ParamValue::Choice(1 - i),
                None => ParamValue::Scalar(0.5), // the colour form not in use: switch to it
            };
            h.params.set_value(spec.name, nudged);
            let bytes = h.encode();
            assert_ne!(bytes, reference, "{} changes no header byte", spec.key);
            if spec.name == ParamName::BaseColour {
                // Recorded as pigment kind 2, and refused: a LUT holds the σ_ca it resolved to.
                assert!(matches!(
                    LutHeader::decode(&blob(&h)),
                    Err(LutError::Params(e)) if e.name == ParamName::BaseColour
                ));
                continue;
            }
            let back = LutHeader::decode(&blob(&h)).unwrap();
            assert_eq!(back.params.value(spec.name), Some(nudged), "{}", spec.key);
        }
    }

    #[test]
    fn corrupt_parameter_blocks_are_refused() {
        let h = header("human-hair");
        let mut bytes = blob(&h);
        // Pigment kind 3 does not exist.
        bytes[56..60].copy_from_slice(&3u32.to_le_bytes());
        assert_eq!(
            LutHeader::decode(&bytes),
            Err(LutError::Field { field: "pigment" })
        );
        // κ = 1.5 is outside its domain.
        let mut bytes = blob(&h);
        let kappa_at = 52 + 4 + 4 + 12 + 4 * 4;
        bytes[kappa_at..kappa_at + 4].copy_from_slice(&1.5f32.to_le_bytes());
        assert!(matches!(
            LutHeader::decode(&bytes),
            Err(LutError::Params(e)) if e.name == ParamName::Kappa && e.value == 1.5
        ));
        // Closure 2 does not exist (0 report, 1 energy, after g).
        let mut bytes = blob(&h);
        bytes[108..112].copy_from_slice(&2u32.to_le_bytes());
        assert_eq!(
            LutHeader::decode(&bytes),
            Err(LutError::Field { field: "closure" })
        );
    }
}

#[cfg(test)]
mod version_tests {
    extern crate std;
    use crate::baked::BakedBcsdf;
    use crate::lut::{seal, LutError};
    use crate::MODEL_VERSION;
    use std::string::ToString;

    /// A LUT baked by the previous model version (its tables were computed with other
    /// formulas) is refused, and the message names both versions and says to re-bake.
    #[test]
    fn a_lut_of_the_previous_model_version_is_refused_with_a_rebake_message() {
        let h = super::tests::header("bobcat");
        let mut bytes = super::tests::blob(&h);
        bytes[12..16].copy_from_slice(&(MODEL_VERSION - 1).to_le_bytes());
        seal(&mut bytes);
        let err = BakedBcsdf::from_bytes(&bytes).unwrap_err();
        assert_eq!(
            err,
            LutError::ModelVersion {
                found: MODEL_VERSION - 1
            }
        );
        let msg = err.to_string();
        for needle in [
            std::format!("model version {}", MODEL_VERSION - 1),
            std::format!("model version {MODEL_VERSION}"),
            "re-bake".to_string(),
        ] {
            assert!(msg.contains(&needle), "{msg:?} should name {needle:?}");
        }
    }
}
