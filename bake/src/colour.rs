//! A base colour as a LUT's default colour (docs/model.md §14, "In files"): the tables of a
//! LUT do not depend on its parameters' σ_ca (the absorption axis covers every colour), so a
//! preset given as `base_colour = [r, g, b]` is baked at any σ_ca, the coat colour table is
//! measured from the baked LUT ([`CoatColour::measure`]), the colour inverted
//! ([`Absorption::from_base_colour`]), and the σ_ca found written into the header as the
//! LUT's default colour.

use bcsdf_core::colour::{BaseColour, CoatColour, CoatWalk};
use bcsdf_core::lut::{self, LutError, LutHeader, HEADER_LEN};
use bcsdf_core::{Absorption, BakedBcsdf, BaseColourError, Pigment, Rgb};
use std::fmt;

/// Why a base colour could not become a LUT's default colour.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ResolveError {
    /// The blob is not a valid LUT.
    Lut(LutError),
    /// A channel of the colour is NaN or outside [0, 1].
    Colour(BaseColourError),
}

impl fmt::Display for ResolveError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ResolveError::Lut(e) => write!(f, "{e}"),
            ResolveError::Colour(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for ResolveError {}

/// The σ_ca whose thick coat shows `colour`, from the coat colour table of `blob`
/// ([`CoatColour::measure`] with [`CoatWalk::DEFAULT`]: 1–7 s on one core).
pub fn base_colour_of(blob: &[u8], colour: Rgb) -> Result<BaseColour, ResolveError> {
    let lut = BakedBcsdf::from_bytes(blob).map_err(ResolveError::Lut)?;
    let coat = CoatColour::measure(&lut, &CoatWalk::DEFAULT);
    Absorption::from_base_colour(colour, &coat).map_err(ResolveError::Colour)
}

/// Writes `absorption` into `blob`'s header as its default colour (pigment σ_ca) and seals
/// the blob again (sampling section and checksum, [`lut::seal`]); the tables are untouched.
pub fn set_default_colour(blob: &mut [u8], absorption: &Absorption) -> Result<(), LutError> {
    let mut header = LutHeader::decode(blob)?;
    header.params.pigment = Pigment::Absorption(absorption.sigma());
    blob[..HEADER_LEN].copy_from_slice(&header.encode());
    lut::seal(blob);
    lut::validate(blob).map(|_| ())
}

/// [`base_colour_of`] then [`set_default_colour`]: the LUT baked from a base-colour preset
/// (at any σ_ca) gets the σ_ca that shows `colour` as its default; returns what the inversion
/// found (clamped channels included, for the caller to report).
pub fn resolve_into(blob: &mut [u8], colour: Rgb) -> Result<BaseColour, ResolveError> {
    let found = base_colour_of(blob, colour)?;
    set_default_colour(blob, &found.absorption).map_err(ResolveError::Lut)?;
    Ok(found)
}

#[cfg(test)]
mod tests {
    use crate::overrides::Override;
    use crate::presets::parse;
    use bcsdf_core::{FurParamsInput, ParamName, ParamValue, Pigment, Rgb, SCHEMA};

    const HEAD: &str = "[[preset]]\nname = \"pick\"\nsource = \"chosen\"\neta_c = 1.55\n\
        alpha_deg = 3\nbeta_m_deg = 10\nl = 0.5\nkappa = 0\nsigma_ms = 0\ng = 0\n";

    #[test]
    fn a_preset_file_takes_base_colour_and_its_values_round_trip_bit_exactly() {
        let text = format!("{HEAD}base_colour = [0.7, 0.55, 0.35]\n");
        let list = parse(&text, "t.toml").unwrap();
        let input = list[0].input;
        let want = Rgb([0.7f32, 0.55, 0.35]);
        assert_eq!(input.pigment, Pigment::BaseColour(want));
        assert!(input.check().is_ok());
        // Every serialisation walks SCHEMA through `value`; reading them back is `from_values`.
        let back = FurParamsInput::from_values(|n| input.value(n)).unwrap();
        assert_eq!(back, input);
        for spec in &SCHEMA {
            let v = input.resolved().value(spec.name);
            assert_eq!(
                v.is_some(),
                spec.name == ParamName::BaseColour || !spec.name.is_colour()
            );
        }
        match input.value(ParamName::BaseColour) {
            Some(ParamValue::Rgb(c)) => {
                assert_eq!(c.0.map(f32::to_bits), want.0.map(f32::to_bits));
            }
            other => panic!("{other:?}"),
        }
        // A grey as one number.
        let grey = parse(&format!("{HEAD}base_colour = 0.18\n"), "t.toml").unwrap();
        assert_eq!(grey[0].input.pigment, Pigment::BaseColour(Rgb::splat(0.18)));
    }

    #[test]
    fn bad_base_colours_give_one_error_naming_the_key() {
        let cases = [
            (
                "base_colour = [0.5, 1.2, 0.1]",
                "invalid base_colour = 1.2: valid range is [0, 1]",
            ),
            (
                "base_colour = [0.5, -0.1, 0.1]",
                "invalid base_colour = -0.1: valid range is [0, 1]",
            ),
            (
                "base_colour = [0.5, nan, 0.1]",
                "invalid base_colour = NaN: valid range is [0, 1]",
            ),
            (
                "base_colour = [0.5, 0.1]",
                "base_colour: invalid value: an array of 2 elements",
            ),
            ("base_colour = \"red\"", "base_colour: invalid type: string"),
            (
                "base_colour = 0.5\nsigma_ca = 0.2",
                "sigma_ca and base_colour both given: give exactly one colour form",
            ),
            (
                "base_colour = 0.5\neumelanin = 0.2",
                "eumelanin and base_colour both given",
            ),
        ];
        for (line, want) in cases {
            let e = parse(&format!("{HEAD}{line}\n"), "t.toml").unwrap_err();
            let msg = e.to_string();
            assert!(msg.contains(want), "{line}: {msg}");
            assert_eq!(msg.lines().count(), 1, "{msg}");
        }
    }

    #[test]
    fn set_takes_base_colour_as_one_or_three_numbers() {
        let o = Override::parse("base_colour=0.5,0.3,0.1").unwrap();
        assert_eq!(o.value, ParamValue::Rgb(Rgb([0.5, 0.3, 0.1])));
        let o = Override::parse("base_colour = 0.18").unwrap();
        assert_eq!(o.value, ParamValue::Scalar(0.18));
        for (spec, want) in [
            (
                "base_colour=0.5,1.5,0.1",
                "`base_colour=0.5,1.5,0.1`: invalid base_colour = 1.5: valid range is [0, 1]",
            ),
            (
                "base_colour=0.5,0.1",
                "`base_colour=0.5,0.1`: base_colour takes one value or three (r,g,b), got 2",
            ),
            ("base_colour=x", "`base_colour=x`: `x` is not a number"),
            (
                "base_colour=NaN",
                "`base_colour=NaN`: invalid base_colour = NaN: valid range is [0, 1]",
            ),
        ] {
            assert_eq!(Override::parse(spec).unwrap_err().to_string(), want);
        }
        // Over a preset given as sigma_ca, base_colour replaces it (and the other way round).
        let mut input = parse(&format!("{HEAD}sigma_ca = 0.3\n"), "t.toml").unwrap()[0].input;
        Override::parse("base_colour=0.5,0.3,0.1")
            .unwrap()
            .apply(&mut input);
        assert_eq!(input.pigment, Pigment::BaseColour(Rgb([0.5, 0.3, 0.1])));
        assert_eq!(input.value(ParamName::SigmaCa), None);
        Override::parse("sigma_ca=0.2").unwrap().apply(&mut input);
        assert_eq!(input.pigment, Pigment::Absorption(Rgb::splat(0.2)));
    }
}
