//! The HTML summary pages of `viewer compare`: one self-contained page per LUT
//! (`index.html` beside its images: parameters, the metrics table, the render difference
//! and every figure) and, with `--all`, one page for the folder linking each LUT's page.
//! Plain HTML with relative links and a little inline CSS; no scripts.

use crate::report::{
    self, budget_rows, named_pcts, pct, worst_rows, Image, IndexRow, Outcome, IMAGES,
};
use bake::metrics::{ErrorBudget, ErrorSummary, MetricSet, METRIC_NAMES};
use bcsdf_core::lut::LutHeader;
use bcsdf_core::Pigment;
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
.renders img{margin-right:8px}";

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

    s.push_str("<h2>Parameters</h2>\n<table>\n");
    for (k, v) in parameters(p.header) {
        let _ = writeln!(s, "<tr><td>{}</td><td>{}</td></tr>", escape(&k), escape(&v));
    }
    s.push_str("</table>\n");

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

/// The header as (name, value) rows.
fn parameters(h: &LutHeader) -> Vec<(String, String)> {
    let p = &h.params;
    let mut rows = vec![("eta_c".to_string(), format!("{}", p.eta_c))];
    match p.pigment {
        Pigment::Absorption(rgb) => rows.push((
            "sigma_ca".into(),
            format!("{}, {}, {}", rgb.0[0], rgb.0[1], rgb.0[2]),
        )),
        Pigment::Melanin {
            eumelanin,
            pheomelanin,
        } => rows.push((
            "melanin".into(),
            format!("eumelanin {eumelanin}, pheomelanin {pheomelanin}"),
        )),
    }
    let opt = |v: Option<f32>, default: &str| v.map_or(default.to_string(), |x| x.to_string());
    rows.extend([
        ("alpha (deg)".into(), format!("{}", p.alpha_deg)),
        ("beta_m (deg)".into(), format!("{}", p.beta_m_deg)),
        ("beta_n (deg)".into(), opt(p.beta_n_deg, "= beta_m")),
        ("l".into(), format!("{}", p.l)),
        ("kappa".into(), format!("{}", p.kappa)),
        ("eta_m".into(), opt(p.eta_m, "= eta_c")),
        ("sigma_ms".into(), format!("{}", p.sigma_ms)),
        ("sigma_ma".into(), format!("{}", p.sigma_ma)),
        ("g".into(), format!("{}", p.g)),
    ]);
    let res: Vec<String> = h
        .res
        .axes()
        .iter()
        .map(|(n, v)| format!("{n} {v}"))
        .collect();
    rows.push(("LUT resolution".into(), res.join(", ")));
    rows.push((
        "medulla profiles".into(),
        match &h.profiles {
            None => "none (no medulla scattering)".into(),
            Some(pr) => format!(
                "generator v{}, seed {}, {} photons per C^N cell, {} per C^M row",
                pr.generator_version, pr.seed, pr.budget.per_cn_cell, pr.budget.per_cm_row
            ),
        },
    ));
    rows
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

    #[test]
    fn text_is_escaped() {
        assert_eq!(escape("a<b & \"c\""), "a&lt;b &amp; &quot;c&quot;");
    }
}
