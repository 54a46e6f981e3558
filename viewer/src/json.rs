//! The viewer's one JSON writer: small `Serialize` structs written by serde_json.
//!
//! - `viewer probe`: one line per query, [`write_lobes`] / [`write_families`];
//! - `viewer sample`: the numbers of its text lines, [`write_number`];
//! - `viewer compare`: `compare.json`, [`pretty`] on the report model's `Report`.
//!
//! Numbers are serde_json's (ryu): the shortest decimal that parses back to the same value
//! in the type written (f32 for the model's answers, f64 for the metrics), so `1` prints as
//! `1.0`. JSON has no NaN or infinity: serde_json writes those as `null`. The model never
//! returns them; a metric that is NaN (which the budget counts as exceeded) reads back as
//! `null` in `compare.json`.

use bcsdf_core::{Families, LobeFamily, Lobes, Rgb, FAMILY_COUNT, LOBE_COUNT};
use serde::ser::{Serialize, Serializer};
use std::io::{self, Write};

/// A JSON object whose keys keep the order of the array (`{"R":…,"TT":…}`).
#[derive(Clone, Copy, Debug)]
pub struct Ordered<V, const N: usize>(pub [(&'static str, V); N]);

impl<V: Serialize, const N: usize> Serialize for Ordered<V, N> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_map(self.0.iter().map(|(k, v)| (k, v)))
    }
}

/// The probe's line for the analytic model: `{"total":[r,g,b],"lobes":{…}[,"pdf":p]}`.
#[derive(serde::Serialize)]
struct LobesLine {
    total: [f32; 3],
    lobes: Ordered<[f32; 3], LOBE_COUNT>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pdf: Option<f32>,
}

/// The probe's line for a LUT: `{"total":[r,g,b],"families":{…}[,"pdf":p]}`.
#[derive(serde::Serialize)]
struct FamiliesLine {
    total: [f32; 3],
    families: Ordered<[f32; 3], FAMILY_COUNT>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pdf: Option<f32>,
}

/// Writes `{"total":[r,g,b],"lobes":{"R":[r,g,b],...}}` and a newline; lobes in
/// `Lobe::ALL` order, named by `Lobe::name`. With a `pdf`, `,"pdf":p` comes before the last
/// brace.
pub fn write_lobes<W: Write>(out: &mut W, lobes: &Lobes, pdf: Option<f32>) -> io::Result<()> {
    let mut named = [("", [0.0f32; 3]); LOBE_COUNT];
    for (slot, (lobe, value)) in named.iter_mut().zip(lobes.iter()) {
        *slot = (lobe.name(), rgb(value));
    }
    let line = LobesLine {
        total: rgb(lobes.total()),
        lobes: Ordered(named),
        pdf,
    };
    write_line(out, &line)
}

/// Writes `{"total":[r,g,b],"families":{"R":[r,g,b],"TT":…,"TRT":…,"scattered":…}}` and a
/// newline; families in `LobeFamily::ALL` order, named by `LobeFamily::name`. With a `pdf`,
/// `,"pdf":p` comes before the last brace.
pub fn write_families<W: Write>(
    out: &mut W,
    families: &Families,
    pdf: Option<f32>,
) -> io::Result<()> {
    let line = FamiliesLine {
        total: rgb(families.total()),
        families: Ordered(LobeFamily::ALL.map(|f| (f.name(), rgb(families.get(f))))),
        pdf,
    };
    write_line(out, &line)
}

fn rgb(v: Rgb) -> [f32; 3] {
    v.0
}

/// `value` as one line of JSON and a newline.
pub fn write_line<W: Write, T: Serialize>(out: &mut W, value: &T) -> io::Result<()> {
    serde_json::to_writer(&mut *out, value)?;
    out.write_all(b"\n")
}

/// One JSON number (`null` if not finite) that parses back to the same f32; `viewer sample`
/// prints its numbers this way.
pub fn write_number<W: Write>(out: &mut W, v: f32) -> io::Result<()> {
    serde_json::to_writer(out, &v)?;
    Ok(())
}

/// `value` as indented JSON and a newline (`compare.json`).
pub fn pretty<T: Serialize>(value: &T) -> String {
    // Serialising these structs cannot fail: every map key is a string.
    let mut s = serde_json::to_string_pretty(value).expect("string keys only");
    s.push('\n');
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn families_and_pdf_layout() {
        let families = Families::from_array(core::array::from_fn::<_, FAMILY_COUNT, _>(|f| {
            Rgb([f as f32, 0.5, 0.0])
        }));
        let mut s = Vec::new();
        write_families(&mut s, &families, None).unwrap();
        let plain = "{\"total\":[6.0,2.0,0.0],\"families\":{\"R\":[0.0,0.5,0.0],\
                     \"TT\":[1.0,0.5,0.0],\"TRT\":[2.0,0.5,0.0],\"scattered\":[3.0,0.5,0.0]}}\n";
        assert_eq!(String::from_utf8(s).unwrap(), plain);
        let mut s = Vec::new();
        write_families(&mut s, &families, Some(0.25)).unwrap();
        let with_pdf = plain.replace("}}\n", "},\"pdf\":0.25}\n");
        assert_eq!(String::from_utf8(s).unwrap(), with_pdf);
    }

    #[test]
    fn lobes_in_order_with_their_names() {
        let lobes = Lobes::from_array(core::array::from_fn::<_, LOBE_COUNT, _>(|k| {
            Rgb([k as f32, 1.0, 0.25])
        }));
        let mut s = Vec::new();
        write_lobes(&mut s, &lobes, Some(1.5)).unwrap();
        let text = String::from_utf8(s).unwrap();
        assert!(text.ends_with("},\"pdf\":1.5}\n"), "{text}");
        let json: serde_json::Value = serde_json::from_str(&text).unwrap();
        let map = json["lobes"].as_object().unwrap();
        assert_eq!(map.len(), LOBE_COUNT);
        let mut at = 0;
        for (k, (lobe, value)) in lobes.iter().enumerate() {
            let key = format!("\"{}\":[{}.0,1.0,0.25]", lobe.name(), k);
            let found = text[at..]
                .find(&key)
                .unwrap_or_else(|| panic!("{key} in {text}"));
            at += found + key.len();
            assert_eq!(
                json["lobes"][lobe.name()][0].as_f64(),
                Some(value.0[0].into())
            );
        }
        let total = lobes.total().0.map(f64::from);
        let read: Vec<f64> = json["total"]
            .as_array()
            .unwrap()
            .iter()
            .map(|v| v.as_f64().unwrap())
            .collect();
        assert_eq!(read, total);
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
            assert!(serde_json::from_str::<serde_json::Value>(&s).is_ok(), "{s}");
            assert!(
                !s.contains("inf") && !s.contains("NaN") && !s.starts_with('.'),
                "{s}"
            );
        }
        for v in [f32::NAN, f32::INFINITY, f32::NEG_INFINITY] {
            let mut s = Vec::new();
            write_number(&mut s, v).unwrap();
            assert_eq!(s, b"null");
        }
    }
}
