//! The probe's JSON line, written by hand (no allocation per line).

use bcsdf_core::{Lobes, Rgb};
use std::io::{self, Write};

/// Writes `{"total":[r,g,b],"lobes":{"R":[r,g,b],...}}` and a newline; lobes in
/// `Lobe::ALL` order, named by `Lobe::name`.
pub fn write_lobes<W: Write>(out: &mut W, lobes: &Lobes) -> io::Result<()> {
    out.write_all(b"{\"total\":")?;
    write_rgb(out, lobes.total())?;
    out.write_all(b",\"lobes\":{")?;
    for (i, (lobe, value)) in lobes.iter().enumerate() {
        if i > 0 {
            out.write_all(b",")?;
        }
        write!(out, "\"{}\":", lobe.name())?;
        write_rgb(out, value)?;
    }
    out.write_all(b"}}\n")
}

fn write_rgb<W: Write>(out: &mut W, rgb: Rgb) -> io::Result<()> {
    let [r, g, b] = rgb.0;
    out.write_all(b"[")?;
    write_number(out, r)?;
    out.write_all(b",")?;
    write_number(out, g)?;
    out.write_all(b",")?;
    write_number(out, b)?;
    out.write_all(b"]")
}

/// A JSON number that parses back to the same f32: Rust prints the shortest round-tripping
/// decimal; very small or large magnitudes use exponent notation to stay short. JSON has no
/// NaN or infinity (the model never returns them): those print as `null`.
fn write_number<W: Write>(out: &mut W, v: f32) -> io::Result<()> {
    let a = v.abs();
    if !v.is_finite() {
        out.write_all(b"null")
    } else if a == 0.0 || (1e-5..1e16).contains(&a) {
        write!(out, "{v}")
    } else {
        write!(out, "{v:e}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_round_trip_and_are_json() {
        for v in [
            0.0f32,
            -0.0,
            1.0,
            0.1,
            1e-5,
            9.99e-6,
            1e-30,
            f32::MIN_POSITIVE,
            1e-45,
            3.4e38,
            12345.678,
        ] {
            let mut s = Vec::new();
            write_number(&mut s, v).unwrap();
            let s = String::from_utf8(s).unwrap();
            assert_eq!(s.parse::<f32>().unwrap().to_bits(), v.to_bits(), "{s}");
            assert!(
                !s.contains("inf") && !s.contains("NaN") && !s.starts_with('.'),
                "{s}"
            );
        }
    }
}
