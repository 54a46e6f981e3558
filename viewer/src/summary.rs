//! The HTML summary pages of `viewer compare`: one self-contained page per LUT
//! (`index.html` beside its images: parameters, the metrics table, the render difference
//! and every figure) and, with `--all`, one page for the folder linking each LUT's page.
//! Plain HTML with relative links and a little inline CSS; no scripts.

use crate::compare::{pct, Outcome};
use bake::metrics::{ErrorBudget, ErrorSummary, Exceeded, MetricSet};
use bcsdf_core::lut::LutHeader;
use bcsdf_core::Pigment;
use std::fmt::Write as _;
use std::path::Path;

/// One image on a page.
#[derive(Clone, Copy, Debug)]
pub struct Image {
    /// File name, relative to the page.
    pub file: &'static str,
    /// Width and height in pixels.
    pub size: (usize, usize),
    /// What it shows.
    pub caption: &'static str,
}

/// Everything on a LUT's page.
#[derive(Clone, Copy, Debug)]
pub struct PresetPage<'a> {
    /// Preset name stored in the LUT.
    pub preset: &'a str,
    /// The LUT file.
    pub lut: &'a Path,
    /// Its header (parameters, resolution, profile provenance).
    pub header: &'a LutHeader,
    /// The metrics measured now.
    pub errors: &'a ErrorSummary,
    /// The metrics stored at bake time, if any.
    pub stored: Option<&'a ErrorSummary>,
    /// The budget.
    pub budget: &'a ErrorBudget,
    /// Metrics above the budget.
    pub exceeded: &'a [Exceeded],
    /// Mean relative difference of the renders per channel.
    pub render: [f64; 3],
    /// The figures.
    pub images: &'a [Image],
}

/// One LUT of a `--all` run: its file name and what came of it (the error message when it
/// could not be read).
#[derive(Clone, Debug)]
pub struct IndexRow {
    /// File name within the folder.
    pub file: String,
    /// The comparison, or why there is none.
    pub outcome: Result<Outcome, String>,
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

/// A JSON string literal.
pub fn json_string(text: &str) -> String {
    let mut s = String::from("\"");
    for c in text.chars() {
        match c {
            '"' => s.push_str("\\\""),
            '\\' => s.push_str("\\\\"),
            c if (c as u32) < 0x20 => {
                let _ = write!(s, "\\u{:04x}", c as u32);
            }
            c => s.push(c),
        }
    }
    s.push('"');
    s
}

fn verdict(pass: bool) -> &'static str {
    if pass {
        "<span class=\"pass\">PASS</span>"
    } else {
        "<span class=\"fail\">FAIL</span>"
    }
}

/// The page of one LUT.
pub fn preset_page(p: &PresetPage<'_>) -> String {
    let mut s = String::new();
    let title = format!("{}: baked vs analytic", p.preset);
    let _ = write!(
        s,
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>{}</title><style>{STYLE}</style></head><body>\n",
        escape(&title)
    );
    let _ = writeln!(
        s,
        "<h1>{} {}</h1>\n<p>LUT <code>{}</code>, compared with the analytic model rebuilt from the parameters stored in it.</p>",
        escape(&title),
        verdict(p.exceeded.is_empty()),
        escape(&p.lut.display().to_string())
    );

    s.push_str("<h2>Error metrics</h2>\n<table><tr><th>metric</th><th>R</th><th>G</th><th>B</th><th>budget</th><th>result</th></tr>\n");
    let bounds = [p.budget.e1, p.budget.e_albedo, p.budget.e_peak];
    for ((name, v), bound) in p.errors.rows().into_iter().zip(bounds) {
        let fail = p.exceeded.iter().any(|e| e.metric == name);
        let _ = writeln!(
            s,
            "<tr><td>{name}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td></tr>",
            pct(v[0]),
            pct(v[1]),
            pct(v[2]),
            pct(bound),
            verdict(!fail)
        );
    }
    let _ = writeln!(
        s,
        "<tr><td>render</td><td>{}</td><td>{}</td><td>{}</td><td></td><td></td></tr>\n</table>",
        pct(p.render[0]),
        pct(p.render[1]),
        pct(p.render[2])
    );
    let _ = writeln!(
        s,
        "<p>E1: energy-weighted relative L1 (weight cos&sup2;&theta;<sub>i</sub>); E_albedo: worst \
         relative error of the directional albedo over &theta;<sub>r</sub>; E_peak: worst weighted \
         difference over the weighted peak (bake::metrics, {} stratified directions over \
         &plusmn;{}&deg;). render: mean |baked &minus; analytic| / analytic over the fur picture below.</p>",
        MetricSet::DEFAULT.len(),
        MetricSet::DEFAULT.max_theta_deg
    );
    if let Some(st) = p.stored {
        let w = st.worst();
        let _ = writeln!(
            s,
            "<p>Stored in the LUT at bake time (worst channel): E1 {}, E_albedo {}, E_peak {}.</p>",
            pct(w[0]),
            pct(w[1]),
            pct(w[2])
        );
    }
    if !p.exceeded.is_empty() {
        s.push_str("<ul>\n");
        for e in p.exceeded {
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
    for img in p
        .images
        .iter()
        .filter(|i| !is_render(i) && i.file != "families.png")
    {
        figure(&mut s, img);
    }
    let renders: Vec<&Image> = p.images.iter().filter(is_render).collect();
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
    for img in p.images.iter().filter(|i| i.file == "families.png") {
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
        .filter(|r| matches!(&r.outcome, Ok(o) if o.exceeded.is_empty()))
        .count();
    let _ = writeln!(
        s,
        "<p>{pass} of {} LUTs within the budget E1 {}, E_albedo {}, E_peak {} (worst channel shown).</p>",
        rows.len(),
        pct(budget.e1),
        pct(budget.e_albedo),
        pct(budget.e_peak)
    );
    s.push_str("<table><tr><th>LUT</th><th>preset</th><th>E1</th><th>E_albedo</th><th>E_peak</th><th>render</th><th>result</th><th>render</th></tr>\n");
    for row in rows {
        let stem = Path::new(&row.file)
            .file_stem()
            .map(|x| x.to_string_lossy().into_owned())
            .unwrap_or_default();
        let folder = format!("{stem}-compare");
        match &row.outcome {
            Ok(o) => {
                let w = o.errors.worst();
                let render = o
                    .render
                    .map(|r| pct(r[0].max(r[1]).max(r[2])))
                    .unwrap_or_default();
                let _ = writeln!(
                    s,
                    "<tr><td><a href=\"{folder}/index.html\">{}</a></td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td><a href=\"{folder}/index.html\"><img src=\"{folder}/analytic.png\" width=\"192\" height=\"144\" alt=\"render\"></a></td></tr>",
                    escape(&row.file),
                    escape(&o.preset),
                    pct(w[0]),
                    pct(w[1]),
                    pct(w[2]),
                    render,
                    verdict(o.exceeded.is_empty())
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
        assert_eq!(json_string("a\"b\\c\n"), "\"a\\\"b\\\\c\\u000a\"");
    }
}
