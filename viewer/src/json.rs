//! The probe's JSON line, written by hand (no allocation per line).

use bcsdf_core::{Families, LobeFamily, Lobes, Rgb};
use std::io::{self, Write};

/// Writes `{"total":[r,g,b],"lobes":{"R":[r,g,b],...}}` and a newline; lobes in
/// `Lobe::ALL` order, named by `Lobe::name`. With a `pdf`, `,"pdf":p` comes before the last
/// brace.
pub fn write_lobes<W: Write>(out: &mut W, lobes: &Lobes, pdf: Option<f32>) -> io::Result<()> {
    let named = lobes.iter().map(|(lobe, value)| (lobe.name(), value));
    write_line(out, lobes.total(), "lobes", named, pdf)
}

/// Writes `{"total":[r,g,b],"families":{"R":[r,g,b],"TT":…,"TRT":…,"scattered":…}}` and a
/// newline; families in `LobeFamily::ALL` order, named by `LobeFamily::name`. With a `pdf`,
/// `,"pdf":p` comes before the last brace.
pub fn write_families<W: Write>(
    out: &mut W,
    families: &Families,
    pdf: Option<f32>,
) -> io::Result<()> {
    let named = LobeFamily::ALL.iter().map(|&f| (f.name(), families.get(f)));
    write_line(out, families.total(), "families", named, pdf)
}

/// `{"total":TOTAL,"KEY":{"NAME":[r,g,b],...}[,"pdf":p]}` and a newline.
fn write_line<W: Write>(
    out: &mut W,
    total: Rgb,
    key: &str,
    named: impl Iterator<Item = (&'static str, Rgb)>,
    pdf: Option<f32>,
) -> io::Result<()> {
    out.write_all(b"{\"total\":")?;
    write_rgb(out, total)?;
    write!(out, ",\"{key}\":{{")?;
    for (i, (name, value)) in named.enumerate() {
        if i > 0 {
            out.write_all(b",")?;
        }
        write!(out, "\"{name}\":")?;
        write_rgb(out, value)?;
    }
    out.write_all(b"}")?;
    if let Some(pdf) = pdf {
        out.write_all(b",\"pdf\":")?;
        write_number(out, pdf)?;
    }
    out.write_all(b"}\n")
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
/// NaN or infinity (the model never returns them): those print as `null`. `viewer sample`
/// prints its numbers this way too.
pub fn write_number<W: Write>(out: &mut W, v: f32) -> io::Result<()> {
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
    use bcsdf_core::FAMILY_COUNT;

    #[test]
    fn families_and_pdf_layout() {
        let families = Families::from_array(core::array::from_fn::<_, FAMILY_COUNT, _>(|f| {
            Rgb([f as f32, 0.5, 0.0])
        }));
        let mut s = Vec::new();
        write_families(&mut s, &families, None).unwrap();
        let plain = "{\"total\":[6,2,0],\"families\":{\"R\":[0,0.5,0],\"TT\":[1,0.5,0],\
                     \"TRT\":[2,0.5,0],\"scattered\":[3,0.5,0]}}\n";
        assert_eq!(String::from_utf8(s).unwrap(), plain);
        let mut s = Vec::new();
        write_families(&mut s, &families, Some(0.25)).unwrap();
        let with_pdf = plain.replace("}}\n", "},\"pdf\":0.25}\n");
        assert_eq!(String::from_utf8(s).unwrap(), with_pdf);
    }

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
