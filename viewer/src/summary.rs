//! The HTML summary pages of `viewer compare`: one self-contained page per LUT
//! (`index.html` beside its images: the parameters, one row per [`SCHEMA`] entry; the
//! metrics table; the render difference and every figure) and, with `--all`, one page for
//! the folder linking each LUT's page. Plain HTML with relative links and a little inline
//! CSS; no scripts. What is shown is the report model of [`crate::report`].

use crate::report::{
    self, budget_rows, named_pcts, pct, worst_rows, Image, IndexRow, Outcome, IMAGES,
};
use bake::metrics::{ErrorBudget, ErrorSummary, MetricSet, METRIC_NAMES};
use bcsdf_core::lut::LutHeader;
use bcsdf_core::{FurParamsInput, ParamDefault, ParamValue, Rgb, SCHEMA};
use std::fmt::Write as _;
use std::path::Path;

/// Everything on a LUT's page besides its images ([`IMAGES`], written beside it).
#[derive(Clone, Copy, Debug)]
pub struct PresetPage<'a> {
    /// The LUT file.
    pub lut: &'a Path,
    /// Its header (parameters, resolution, profile provenance).
    pub header: &'a LutHeader,
    /// What the comparison measured.
    pub outcome: &'a Outcome,
    /// The metrics stored at bake time, if any.
    pub stored: Option<&'a ErrorSummary>,
    /// The budget.
    pub budget: &'a ErrorBudget,
}

const STYLE: &str = "body{font-family:sans-serif;margin:1.5em;max-width:1400px}\
table{border-collapse:collapse;margin:0.5em 0 1em}\
td,th{border:1px solid #bbb;padding:3px 8px;text-align:right}\
th{background:#eee}td:first-child,th:first-child{text-align:left}\
.pass{color:#060;font-weight:bold}.fail{color:#b00;font-weight:bold}\
figure{margin:1em 0}figcaption{color:#555;font-size:90%}\
.renders img{margin-right:8px}.params td{text-align:left}\
img{max-width:100%;height:auto}";

/// Escapes text for HTML.
pub fn escape(text: &str) -> String {
    let mut s = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => s.push_str("&amp;"),
            '<' => s.push_str("&lt;"),
            '>' => s.push_str("&gt;"),
            '"' => s.push_str("&quot;"),
            '\'' => s.push_str("&#39;"),
            c => s.push(c),
        }
    }
    s
}

/// A verdict, coloured.
fn verdict(pass: bool) -> String {
    let class = if pass { "pass" } else { "fail" };
    format!("<span class=\"{class}\">{}</span>", report::verdict(pass))
}

/// The page of one LUT.
pub fn preset_page(p: &PresetPage<'_>) -> String {
    let mut s = String::new();
    let o = p.outcome;
    let title = format!("{}: baked vs analytic", o.preset);
    let _ = write!(
        s,
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>{}</title><style>{STYLE}</style></head><body>\n",
        escape(&title)
    );
    let _ = writeln!(
        s,
        "<h1>{} {}</h1>\n<p>LUT <code>{}</code>, compared with the analytic model rebuilt from the parameters stored in it.</p>",
        escape(&title),
        verdict(o.pass()),
        escape(&p.lut.display().to_string())
    );

    s.push_str("<h2>Error metrics</h2>\n<table><tr><th>metric</th><th>R</th><th>G</th><th>B</th><th>budget</th><th>result</th></tr>\n");
    for row in o.metric_rows(p.budget) {
        let v = row.values;
        let _ = writeln!(
            s,
            "<tr><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td></tr>",
            row.name,
            pct(v[0]),
            pct(v[1]),
            pct(v[2]),
            pct(row.budget),
            verdict(row.pass)
        );
    }
    if let Some(r) = o.render {
        let _ = writeln!(
            s,
            "<tr><td>render</td><td>{}</td><td>{}</td><td>{}</td><td></td><td></td></tr>",
            pct(r[0]),
            pct(r[1]),
            pct(r[2])
        );
    }
    s.push_str("</table>\n");
    let _ = writeln!(
        s,
        "<p>E1: energy-weighted relative L1 (weight cos&sup2;&theta;<sub>i</sub>); E_albedo: worst \
         relative error of the directional albedo over &theta;<sub>r</sub>; E_peak: worst weighted \
         difference over the weighted peak (bake::metrics, {} stratified directions over \
         &plusmn;{}&deg;). render: mean |baked &minus; analytic| / analytic over the fur picture below.</p>",
        MetricSet::DEFAULT.len(),
        MetricSet::DEFAULT.max_theta_deg
    );
    if let Some(stored) = p.stored {
        let _ = writeln!(
            s,
            "<p>Stored in the LUT at bake time (worst channel): {}.</p>",
            named_pcts(&worst_rows(stored))
        );
    }
    if !o.pass() {
        s.push_str("<ul>\n");
        for e in &o.exceeded {
            let _ = writeln!(s, "<li class=\"fail\">{}</li>", escape(&e.to_string()));
        }
        s.push_str("</ul>\n");
    }

    s.push_str("<h2>Parameters</h2>\n");
    parameter_table(&mut s, p.header);

    s.push_str("<h2>Figures</h2>\n");
    let is_render = |i: &&Image| matches!(i.file, "analytic.png" | "baked.png" | "difference.png");
    for img in IMAGES
        .iter()
        .filter(|i| !is_render(i) && i.file != "families.png")
    {
        figure(&mut s, img);
    }
    let renders: Vec<&Image> = IMAGES.iter().filter(is_render).collect();
    s.push_str("<figure class=\"renders\">");
    for img in &renders {
        let _ = write!(
            s,
            "<img src=\"{}\" width=\"{}\" height=\"{}\" alt=\"{}\">",
            img.file, img.size.0, img.size.1, img.file
        );
    }
    s.push_str("<figcaption>Fur patch, one directional light: analytic | baked | difference (");
    s.push_str(
        &renders
            .iter()
            .map(|i| escape(i.caption))
            .collect::<Vec<_>>()
            .join("; "),
    );
    s.push_str(")</figcaption></figure>\n");
    for img in IMAGES.iter().filter(|i| i.file == "families.png") {
        figure(&mut s, img);
    }
    s.push_str("</body></html>\n");
    s
}

fn figure(s: &mut String, img: &Image) {
    let _ = writeln!(
        s,
        "<figure><img src=\"{}\" width=\"{}\" height=\"{}\" alt=\"{}\"><figcaption>{} ({} &times; {} px)</figcaption></figure>",
        img.file,
        img.size.0,
        img.size.1,
        img.file,
        escape(img.caption),
        img.size.0,
        img.size.1
    );
}

/// One parameter on a LUT's page: its [`SCHEMA`] row and its value in the header.
#[derive(Clone, Debug, PartialEq)]
struct ParamRow {
    symbol: &'static str,
    key: &'static str,
    value: String,
    unit: &'static str,
    meaning: &'static str,
}

/// The parameters of `params` in [`SCHEMA`] order, one row per parameter given. The colour
/// forms not in use (σ_ca, eumelanin and pheomelanin, the base colour) have no row; a [`ParamDefault::SameAs`]
/// parameter left absent reads `= β_m` (the header stores them resolved, so only hand-made
/// inputs show this).
fn parameter_rows(params: &FurParamsInput) -> Vec<ParamRow> {
    SCHEMA
        .iter()
        .filter_map(|spec| {
            let value = match (params.value(spec.name), spec.default) {
                (Some(ParamValue::Scalar(v)), _) => format!("{v}"),
                (Some(ParamValue::Rgb(Rgb([r, g, b]))), _) => format!("{r}, {g}, {b}"),
                (Some(ParamValue::Choice(i)), _) => spec.choice_name(i)?.to_string(),
                (None, ParamDefault::SameAs(source)) => format!("= {}", source.spec().symbol),
                (None, _) => return None,
            };
            Some(ParamRow {
                symbol: spec.symbol,
                key: spec.key,
                value,
                unit: spec.unit,
                meaning: spec.meaning,
            })
        })
        .collect()
}

/// The parameter table of a LUT's page: symbol, key, value, unit and meaning per
/// [`SCHEMA`] row, then the LUT's resolution and profile provenance.
fn parameter_table(s: &mut String, h: &LutHeader) {
    s.push_str(
        "<table class=\"params\"><tr><th>parameter</th><th>key</th><th>value</th><th>unit</th><th>meaning</th></tr>\n",
    );
    for row in parameter_rows(&h.params) {
        let _ = writeln!(
            s,
            "<tr><td>{}</td><td><code>{}</code></td><td>{}</td><td>{}</td><td>{}</td></tr>",
            escape(row.symbol),
            escape(row.key),
            escape(&row.value),
            escape(row.unit),
            escape(row.meaning)
        );
    }
    s.push_str("</table>\n<table class=\"params\">\n");
    let res: Vec<String> = h
        .res
        .axes()
        .iter()
        .map(|(n, v)| format!("{n} {v}"))
        .collect();
    let profiles = match &h.profiles {
        None => "none (no medulla scattering)".into(),
        Some(pr) => format!(
            "generator v{}, seed {}, {} photons per C^N cell, {} per C^M row",
            pr.generator_version, pr.seed, pr.budget.per_cn_cell, pr.budget.per_cm_row
        ),
    };
    for (k, v) in [
        ("LUT resolution", res.join(", ")),
        ("medulla profiles", profiles),
    ] {
        let _ = writeln!(s, "<tr><td>{k}</td><td>{}</td></tr>", escape(&v));
    }
    s.push_str("</table>\n");
}

/// The `--all` page: one row per LUT linking its page, with each metric's worst channel and
/// a thumbnail of the analytic render.
pub fn index_page(dir: &Path, budget: &ErrorBudget, rows: &[IndexRow]) -> String {
    let mut s = String::new();
    let title = format!("Baked vs analytic: {}", dir.display());
    let _ = write!(
        s,
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>{}</title><style>{STYLE}</style></head><body>\n<h1>{}</h1>\n",
        escape(&title),
        escape(&title)
    );
    let pass = rows
        .iter()
        .filter(|r| matches!(&r.outcome, Ok(o) if o.pass()))
        .count();
    let _ = writeln!(
        s,
        "<p>{pass} of {} LUTs within the budget {} (worst channel shown).</p>",
        rows.len(),
        named_pcts(&budget_rows(budget))
    );
    s.push_str("<table><tr><th>LUT</th><th>preset</th>");
    for name in METRIC_NAMES {
        let _ = write!(s, "<th>{name}</th>");
    }
    s.push_str("<th>render</th><th>result</th><th>render</th></tr>\n");
    for row in rows {
        let folder = report::compare_folder(Path::new(&row.file));
        match &row.outcome {
            Ok(o) => {
                let w = o.errors.worst();
                let render = o.render_worst().map(pct).unwrap_or_default();
                let _ = writeln!(
                    s,
                    "<tr><td><a href=\"{folder}/index.html\">{}</a></td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td><a href=\"{folder}/index.html\"><img src=\"{folder}/analytic.png\" width=\"192\" height=\"144\" alt=\"render\"></a></td></tr>",
                    escape(&row.file),
                    escape(&o.preset),
                    pct(w[0]),
                    pct(w[1]),
                    pct(w[2]),
                    render,
                    verdict(o.pass())
                );
            }
            Err(message) => {
                let _ = writeln!(
                    s,
                    "<tr><td>{}</td><td colspan=\"5\" style=\"text-align:left\">{}</td><td><span class=\"fail\">ERROR</span></td><td></td></tr>",
                    escape(&row.file),
                    escape(message)
                );
            }
        }
    }
    s.push_str("</table>\n</body></html>\n");
    s
}

#[cfg(test)]
mod tests {
    use super::*;
    use bcsdf_core::lut::{LutResolution, TABLE_COUNT};
    use bcsdf_core::Pigment;

    fn input(pigment: Pigment) -> FurParamsInput {
        FurParamsInput {
            eta_c: 1.55,
            pigment,
            alpha_deg: 3.0,
            beta_m_deg: 10.0,
            beta_n_deg: None,
            l: 0.5,
            kappa: 0.25,
            eta_m: Some(1.4),
            sigma_ms: 2.5,
            sigma_ma: 0.0,
            g: 0.8,
            closure: bcsdf_core::Closure::Energy,
        }
    }

    #[test]
    fn the_parameter_table_walks_the_schema() {
        let rgb = input(Pigment::Absorption(Rgb([0.25, 0.5, 1.0])));
        let rows = parameter_rows(&rgb);
        // Every schema row but the melanin pair and the base colour, in schema order.
        let keys: Vec<&str> = rows.iter().map(|r| r.key).collect();
        let expected: Vec<&str> = SCHEMA
            .iter()
            .map(|s| s.key)
            .filter(|k| !matches!(*k, "eumelanin" | "pheomelanin" | "base_colour"))
            .collect();
        assert_eq!(keys, expected);
        for row in &rows {
            let spec = SCHEMA.iter().find(|s| s.key == row.key).unwrap();
            assert_eq!(
                (row.symbol, row.unit, row.meaning),
                (spec.symbol, spec.unit, spec.meaning)
            );
        }
        let value = |key: &str| rows.iter().find(|r| r.key == key).unwrap().value.clone();
        assert_eq!(value("sigma_ca"), "0.25, 0.5, 1");
        assert_eq!(value("eta_c"), "1.55");
        assert_eq!(value("beta_n_deg"), "= β_m");
        assert_eq!(value("eta_m"), "1.4");
        assert_eq!(value("g"), "0.8");
        assert_eq!(value("closure"), "energy");

        let melanin = input(Pigment::Melanin {
            eumelanin: 1.5,
            pheomelanin: 0.0,
        });
        let rows = parameter_rows(&melanin.resolved());
        assert_eq!(
            rows.len(),
            SCHEMA.len() - 2,
            "no sigma_ca or base_colour row"
        );
        assert!(rows.iter().all(|r| r.key != "sigma_ca"));
        let value = |key: &str| rows.iter().find(|r| r.key == key).unwrap().value.clone();
        assert_eq!(value("eumelanin"), "1.5");
        assert_eq!(value("pheomelanin"), "0");
        assert_eq!(value("beta_n_deg"), "10", "resolved: beta_n = beta_m");

        let header = LutHeader {
            res: LutResolution::DEFAULT,
            scales: [1.0; TABLE_COUNT],
            params: rgb,
            profiles: None,
        };
        let mut html = String::new();
        parameter_table(&mut html, &header);
        for spec in SCHEMA
            .iter()
            .filter(|s| !matches!(s.key, "eumelanin" | "pheomelanin" | "base_colour"))
        {
            let cell = format!(
                "<tr><td>{}</td><td><code>{}</code></td>",
                spec.symbol, spec.key
            );
            assert!(html.contains(&cell), "{cell} in {html}");
            assert!(html.contains(spec.meaning), "{}", spec.meaning);
        }
        assert!(!html.contains("eumelanin"));
        assert!(html.contains("none (no medulla scattering)"));
    }

    #[test]
    fn text_is_escaped() {
        assert_eq!(escape("a<b & \"c\""), "a&lt;b &amp; &quot;c&quot;");
    }
}
