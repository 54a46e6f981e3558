//! The report model of `viewer compare`: what one LUT's comparison measured ([`Outcome`]),
//! its metrics against the budget with a verdict per row ([`MetricRow`]), the LUTs of a
//! `--all` run ([`IndexRow`]), the images written per LUT ([`IMAGES`]), percentages
//! ([`pct`]) and `compare.json` ([`Report`]).
//!
//! `compare` builds it; the text tables (`compare`) and the HTML pages (`summary`) present
//! it. This module imports neither (only `figures` and `render` for the image sizes and
//! `json` for ordered objects), so there is no import cycle between them.

use crate::figures::{HEATMAP_SIZE, POLAR_SIZE};
use crate::json::Ordered;
use crate::render::{RENDER_H, RENDER_W};
use bake::metrics::{ErrorBudget, ErrorSummary, Exceeded, METRIC_NAMES};
use serde::Serialize;
use std::path::{Path, PathBuf};

/// One image written per LUT.
#[derive(Clone, Copy, Debug)]
pub struct Image {
    /// File name, relative to the LUT's page.
    pub file: &'static str,
    /// Width and height in pixels.
    pub size: (usize, usize),
    /// What it shows.
    pub caption: &'static str,
}

/// The image files written per LUT, with their fixed sizes and what they show.
pub const IMAGES: [Image; 6] = [
    Image {
        file: "heatmap.png",
        size: HEATMAP_SIZE,
        caption:
            "S cos^2 theta_i over (theta_i, phi) for four theta_r: analytic | baked | relative error",
    },
    Image {
        file: "polar.png",
        size: POLAR_SIZE,
        caption:
            "S over phi per lobe family at fixed (theta_i, theta_r): analytic solid, baked dashed",
    },
    Image {
        file: "analytic.png",
        size: (RENDER_W, RENDER_H),
        caption: "fur patch lit by one directional light, analytic far field",
    },
    Image {
        file: "baked.png",
        size: (RENDER_W, RENDER_H),
        caption: "the same patch with the baked tables (same exposure)",
    },
    Image {
        file: "difference.png",
        size: (RENDER_W, RENDER_H),
        caption: "|baked - analytic|, amplified by 1 / E1 budget, same exposure",
    },
    Image {
        file: "families.png",
        size: (RENDER_W, RENDER_H),
        caption: "the analytic render split into the lobe families R, TT, TRT and scattered",
    },
];

/// A percentage with three decimals: `0.123%` (non-finite values as Rust prints them).
pub fn pct(v: f64) -> String {
    if v.is_finite() {
        format!("{:.3}%", 100.0 * v)
    } else {
        format!("{v}")
    }
}

/// The word for a verdict: `PASS` or `FAIL`.
pub fn verdict(pass: bool) -> &'static str {
    if pass {
        "PASS"
    } else {
        "FAIL"
    }
}

/// The budget's bound of each metric, in [`METRIC_NAMES`] order.
pub fn budget_rows(budget: &ErrorBudget) -> [(&'static str, f64); 3] {
    [
        (METRIC_NAMES[0], budget.e1),
        (METRIC_NAMES[1], budget.e_albedo),
        (METRIC_NAMES[2], budget.e_peak),
    ]
}

/// Each metric's worst channel, in [`METRIC_NAMES`] order.
pub fn worst_rows(errors: &ErrorSummary) -> [(&'static str, f64); 3] {
    let w = errors.worst();
    [
        (METRIC_NAMES[0], w[0]),
        (METRIC_NAMES[1], w[1]),
        (METRIC_NAMES[2], w[2]),
    ]
}

/// `E1 0.100%, E_albedo 1.000%, E_peak 5.000%`.
pub fn named_pcts(rows: &[(&str, f64)]) -> String {
    let parts: Vec<String> = rows
        .iter()
        .map(|(name, v)| format!("{name} {}", pct(*v)))
        .collect();
    parts.join(", ")
}

/// A file's stem (`lut` if it has none).
pub fn stem(path: &Path) -> String {
    path.file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_else(|| "lut".into())
}

/// The folder of a LUT's page and images: `<lut-stem>-compare`.
pub fn compare_folder(lut: &Path) -> String {
    format!("{}-compare", stem(lut))
}

/// One metric of one LUT against the budget.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MetricRow {
    /// Metric name (`E1`, `E_albedo`, `E_peak`).
    pub name: &'static str,
    /// Measured per channel (R, G, B).
    pub values: [f64; 3],
    /// The budget's bound.
    pub budget: f64,
    /// No channel exceeds the bound ([`ErrorBudget::check`] decides).
    pub pass: bool,
}

/// The metrics of `errors` against `budget`, one row per metric in [`METRIC_NAMES`] order;
/// a row fails when `exceeded` (from [`ErrorBudget::check`]) names its metric.
pub fn metric_rows(
    errors: &ErrorSummary,
    exceeded: &[Exceeded],
    budget: &ErrorBudget,
) -> [MetricRow; 3] {
    let bounds = budget_rows(budget);
    let rows = errors.rows();
    std::array::from_fn(|k| {
        let (name, values) = rows[k];
        debug_assert_eq!(name, bounds[k].0);
        MetricRow {
            name,
            values,
            budget: bounds[k].1,
            pass: !exceeded.iter().any(|e| e.metric == name),
        }
    })
}

/// What one LUT's comparison measured.
#[derive(Clone, Debug)]
pub struct Outcome {
    /// Preset name stored in the LUT.
    pub preset: String,
    /// The metrics.
    pub errors: ErrorSummary,
    /// Metrics above the budget.
    pub exceeded: Vec<Exceeded>,
    /// Mean relative difference of the renders per channel (when images were made).
    pub render: Option<[f64; 3]>,
    /// The page written (when images were made).
    pub page: Option<PathBuf>,
}

impl Outcome {
    /// Within the budget: no metric exceeded.
    pub fn pass(&self) -> bool {
        self.exceeded.is_empty()
    }

    /// The metrics against `budget`, one row each.
    pub fn metric_rows(&self, budget: &ErrorBudget) -> [MetricRow; 3] {
        metric_rows(&self.errors, &self.exceeded, budget)
    }

    /// The render difference's worst channel (when images were made).
    pub fn render_worst(&self) -> Option<f64> {
        self.render.map(|r| r[0].max(r[1]).max(r[2]))
    }
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

/// A metric over budget in `compare.json`: `{"metric": "E1", "channel": "R"}`.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct ExceededEntry {
    /// Metric name.
    pub metric: &'static str,
    /// Channel name.
    pub channel: &'static str,
}

/// `compare.json`: the numbers of a LUT's page, for scripts and tests. Objects keep the
/// key order below; metrics and budget are keyed by [`METRIC_NAMES`], images by file name
/// with `[width, height]`; non-finite numbers are `null` (see [`crate::json`]).
#[derive(Clone, Debug, Serialize)]
pub struct Report<'a> {
    /// The LUT file.
    pub lut: String,
    /// Its preset.
    pub preset: &'a str,
    /// `{"E1": b, "E_albedo": b, "E_peak": b}`.
    pub budget: Ordered<f64, 3>,
    /// `{"E1": [r, g, b], …}`.
    pub metrics: Ordered<[f64; 3], 3>,
    /// The metrics and channels over budget.
    pub exceeded: Vec<ExceededEntry>,
    /// No metric over budget.
    pub pass: bool,
    /// Mean relative difference of the renders per channel, or `null`.
    pub render_difference: Option<[f64; 3]>,
    /// `{"heatmap.png": [w, h], …}`.
    pub images: Ordered<(usize, usize), { IMAGES.len() }>,
}

impl<'a> Report<'a> {
    /// The report of `outcome` for `lut` against `budget`.
    pub fn new(lut: &Path, outcome: &'a Outcome, budget: &ErrorBudget) -> Report<'a> {
        Report {
            lut: lut.display().to_string(),
            preset: &outcome.preset,
            budget: Ordered(budget_rows(budget)),
            metrics: Ordered(outcome.errors.rows()),
            exceeded: outcome
                .exceeded
                .iter()
                .map(|e| ExceededEntry {
                    metric: e.metric,
                    channel: e.channel,
                })
                .collect(),
            pass: outcome.pass(),
            render_difference: outcome.render,
            images: Ordered(IMAGES.map(|i| (i.file, i.size))),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn outcome() -> Outcome {
        let errors = ErrorSummary {
            e1: [0.001, 0.02, 0.003],
            e_albedo: [0.0, 0.0, f64::NAN],
            e_peak: [0.01, 0.01, 0.01],
        };
        let budget = budget();
        Outcome {
            preset: "p \"q\"".into(),
            exceeded: budget.check(&errors),
            errors,
            render: Some([0.001, 0.002, 0.0005]),
            page: None,
        }
    }

    fn budget() -> ErrorBudget {
        ErrorBudget {
            e1: 0.01,
            e_albedo: 0.01,
            e_peak: 0.05,
        }
    }

    #[test]
    fn rows_and_verdicts() {
        let o = outcome();
        let rows = o.metric_rows(&budget());
        assert_eq!(rows.map(|r| r.name), METRIC_NAMES);
        assert_eq!(rows.map(|r| r.pass), [false, false, true]);
        assert_eq!(rows.map(|r| r.budget), [0.01, 0.01, 0.05]);
        assert_eq!(rows[0].values, o.errors.e1);
        assert!(!o.pass());
        assert_eq!(o.render_worst(), Some(0.002));
        assert_eq!(pct(0.00123), "0.123%");
        assert_eq!(pct(f64::NAN), "NaN");
        assert_eq!((verdict(true), verdict(false)), ("PASS", "FAIL"));
        assert_eq!(
            named_pcts(&budget_rows(&budget())),
            "E1 1.000%, E_albedo 1.000%, E_peak 5.000%"
        );
        assert_eq!(worst_rows(&o.errors)[0], ("E1", 0.02));
        assert_eq!(compare_folder(Path::new("d/x.exr")), "x-compare");
    }

    #[test]
    fn report_schema() {
        let o = outcome();
        let report = Report::new(Path::new("dir/a.exr"), &o, &budget());
        let text = crate::json::pretty(&report);
        let json: serde_json::Value = serde_json::from_str(&text).unwrap();
        let keys: Vec<&str> = json
            .as_object()
            .unwrap()
            .keys()
            .map(String::as_str)
            .collect();
        let mut sorted = keys.clone();
        sorted.sort_unstable();
        let mut expected = [
            "lut",
            "preset",
            "budget",
            "metrics",
            "exceeded",
            "pass",
            "render_difference",
            "images",
        ];
        expected.sort_unstable();
        assert_eq!(sorted, expected);
        assert_eq!(json["lut"], "dir/a.exr");
        assert_eq!(json["preset"], "p \"q\"");
        assert_eq!(json["budget"]["E_peak"], 0.05);
        assert_eq!(json["metrics"]["E1"][1], 0.02);
        assert!(json["metrics"]["E_albedo"][2].is_null(), "NaN is null");
        assert_eq!(json["pass"], false);
        assert_eq!(
            json["exceeded"],
            serde_json::json!([
                {"metric": "E1", "channel": "G"},
                {"metric": "E_albedo", "channel": "B"}
            ])
        );
        assert_eq!(json["render_difference"][2], 0.0005);
        assert_eq!(json["images"]["heatmap.png"][0], HEATMAP_SIZE.0);
        assert_eq!(json["images"].as_object().unwrap().len(), IMAGES.len());
        // Keys in the documented order.
        let at = |k: &str| text.find(&format!("\"{k}\"")).unwrap();
        assert!(at("lut") < at("preset") && at("preset") < at("budget"));
        assert!(at("E1") < at("E_albedo") && at("E_albedo") < at("E_peak"));
        assert!(at("heatmap.png") < at("polar.png") && at("baked.png") < at("families.png"));
        assert!(text.ends_with("}\n"));
    }
}
