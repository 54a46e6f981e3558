//! `viewer compare`: a baked LUT against the analytic model it was baked from.
//!
//! For each LUT: read it (`bake::lutfile::read_exr`) and validate its tables, rebuild the
//! analytic model from the parameters and profile provenance in its header
//! (`bake::tables::rebuild_model`, profiles from the cache when present), measure both with
//! the shared metrics (`bake::metrics::compare` on `MetricSet::DEFAULT`), print a table per
//! RGB channel against the budget, and (unless `--no-images`) write the figures
//! ([`crate::figures`]), the fur renders ([`crate::render`]), `compare.json`
//! ([`crate::report::Report`]) and an `index.html` page ([`crate::summary`]). What was
//! measured is the report model of [`crate::report`]; this module runs the comparison and
//! prints its text tables.
//!
//! Exit codes: 0 within budget; 3 when a metric exceeds the budget (stderr names each
//! metric and channel); 2 for bad input (missing, corrupt or incompatible LUT, bad
//! `--budget`, a folder without LUTs); 1 for I/O failures such as an unwritable output
//! folder. With `--all`, every LUT is reported before the run ends: 2 if any could not be
//! read, else 3 if any exceeded the budget.

use crate::cli::CompareArgs;
use crate::error::Error;
use crate::figures::{self, HEATMAP_SIZE, POLAR_SIZE};
use crate::json;
use crate::plot::write_file;
use crate::render;
use crate::report::{
    budget_rows, compare_folder, named_pcts, pct, stem, verdict, worst_rows, IndexRow, Outcome,
    Report,
};
use crate::summary::{self, PresetPage};
use bake::lutfile::{self, LutFile};
use bake::metrics::{self, ErrorBudget, ErrorSummary, Exceeded, MetricSet, METRIC_NAMES};
use bake::profiles::{self, OwnedModel};
use bake::tables::{rebuild_model, RebuildError};
use bcsdf_core::baked::BakedBcsdf;
use bcsdf_core::lut::LutHeader;
use std::fmt::Write as _;
use std::fs;
use std::io::{self, Write};
use std::path::{Path, PathBuf};
use std::time::Instant;

/// Why one LUT could not be compared.
#[derive(Debug)]
enum Failure {
    /// The LUT is missing, corrupt or incompatible (exit 2, other LUTs go on).
    Input(String),
    /// Anything else (exit 1, the run stops).
    Fatal(Error),
}

impl From<io::Error> for Failure {
    fn from(e: io::Error) -> Failure {
        Failure::Fatal(Error::Io(e))
    }
}

/// `viewer compare`.
pub fn run(args: &CompareArgs) -> Result<(), Error> {
    let budget = ErrorBudget::parse(&args.budget)
        .map_err(|e| Error::input(format!("invalid --budget: {e}")))?;
    let mut builder = rayon::ThreadPoolBuilder::new();
    let (threads, note) = bake::limits::threads("--threads", args.threads).map_err(Error::input)?;
    if let Some(note) = note {
        eprintln!("note: {note}");
    }
    if let Some(n) = threads {
        builder = builder.num_threads(n);
    }
    let pool = builder
        .build()
        .map_err(|e| Error::Failure(format!("cannot start the worker threads: {e}")))?;
    pool.install(|| match (&args.all, &args.lut) {
        (Some(dir), _) => run_all(dir, args, &budget),
        (None, Some(lut)) => run_one(lut, args, &budget),
        (None, None) => Err(Error::input("give a LUT file or --all DIR")),
    })
}

/// One LUT: table on stdout, files in `--out` or `<lut-stem>-compare/` beside it.
fn run_one(lut: &Path, args: &CompareArgs, budget: &ErrorBudget) -> Result<(), Error> {
    let file = load(lut).map_err(Error::Input)?;
    let out = (!args.no_images).then(|| match &args.out {
        Some(dir) => dir.clone(),
        None => default_out(lut),
    });
    if let Some(dir) = &out {
        prepare_out_dir(dir)?;
    }
    let outcome = match compare_file(lut, &file, out.as_deref(), args, budget) {
        Ok((o, _)) => o,
        Err(Failure::Input(m)) => return Err(Error::Input(m)),
        Err(Failure::Fatal(e)) => return Err(e),
    };
    if outcome.pass() {
        Ok(())
    } else {
        Err(Error::Budget(over_budget_message(lut, &outcome.exceeded)))
    }
}

/// `--all DIR`: every `*.exr` in DIR by name, then one summary table and `index.html`.
fn run_all(dir: &Path, args: &CompareArgs, budget: &ErrorBudget) -> Result<(), Error> {
    let luts = list_luts(dir)?;
    let root = args.out.clone().unwrap_or_else(|| dir.to_path_buf());
    if !args.no_images {
        prepare_out_dir(&root)?;
    }
    let mut rows = Vec::new();
    let mut unreadable = Vec::new();
    let mut over = Vec::new();
    let mut panels = Vec::new();
    for lut in &luts {
        let name = lut
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        let out = (!args.no_images).then(|| root.join(compare_folder(lut)));
        let result = load(lut).map_err(Failure::Input).and_then(|file| {
            if let Some(dir) = &out {
                prepare_out_dir(dir).map_err(Failure::Fatal)?;
            }
            compare_file(lut, &file, out.as_deref(), args, budget)
        });
        match result {
            Ok((outcome, thumbnail)) => {
                if let Some(t) = thumbnail {
                    panels.push((outcome.preset.clone(), t));
                }
                if !outcome.pass() {
                    eprintln_line(&format!(
                        "error: {}",
                        over_budget_message(lut, &outcome.exceeded)
                    ));
                    over.push(name.clone());
                }
                rows.push(IndexRow {
                    file: name,
                    outcome: Ok(outcome),
                });
            }
            Err(Failure::Input(message)) => {
                eprintln_line(&format!("error: {message}"));
                unreadable.push(name.clone());
                rows.push(IndexRow {
                    file: name,
                    outcome: Err(message),
                });
            }
            Err(Failure::Fatal(e)) => return Err(e),
        }
    }

    let mut text = String::new();
    summary_table(&mut text, &rows, budget);
    print(&text)?;
    if !args.no_images {
        let html = summary::index_page(dir, budget, &rows);
        write_file(&root.join("index.html"), html.as_bytes()).map_err(|e| out_error(&root, &e))?;
        if !panels.is_empty() {
            let gallery = root.join("gallery.png");
            render::gallery(&panels)
                .write_png(&gallery)
                .map_err(|e| out_error(&root, &e))?;
            print(&format!(
                "gallery (every LUT's baked render, one light, one exposure): {}\n",
                gallery.display()
            ))?;
        }
        print(&format!(
            "summary page: {}\n",
            root.join("index.html").display()
        ))?;
    }

    let total = luts.len();
    match (unreadable.is_empty(), over.is_empty()) {
        (true, true) => Ok(()),
        (false, _) => Err(Error::Input(format!(
            "{} of {total} LUTs in {} could not be read ({}){}",
            unreadable.len(),
            dir.display(),
            unreadable.join(", "),
            if over.is_empty() {
                String::new()
            } else {
                format!("; {} over budget ({})", over.len(), over.join(", "))
            }
        ))),
        (true, false) => Err(Error::Budget(format!(
            "{} of {total} LUTs in {} over budget: {}",
            over.len(),
            dir.display(),
            over.join(", ")
        ))),
    }
}

/// The `*.exr` files of `dir`, sorted by name.
fn list_luts(dir: &Path) -> Result<Vec<PathBuf>, Error> {
    let entries = fs::read_dir(dir)
        .map_err(|e| Error::input(format!("cannot read LUT folder {}: {e}", dir.display())))?;
    let mut luts = Vec::new();
    for entry in entries {
        let entry = entry.map_err(|e| Error::input(format!("{}: {e}", dir.display())))?;
        let path = entry.path();
        let is_exr = path
            .extension()
            .is_some_and(|x| x.eq_ignore_ascii_case("exr"));
        if is_exr && path.is_file() {
            luts.push(path);
        }
    }
    luts.sort();
    if luts.is_empty() {
        return Err(Error::input(format!("no *.exr LUTs in {}", dir.display())));
    }
    Ok(luts)
}

/// Reads a LUT file and checks its tables; the message names the file.
fn load(path: &Path) -> Result<LutFile, String> {
    let file = lutfile::read_exr(path).map_err(|e| e.to_string())?;
    file.baked()
        .map_err(|e| format!("{}: {e}", path.display()))?;
    Ok(file)
}

/// `<lut-stem>-compare/` beside the LUT.
fn default_out(lut: &Path) -> PathBuf {
    lut.with_file_name(compare_folder(lut))
}

/// Creates `dir` if needed and checks a file can be written in it (before any work).
pub fn prepare_out_dir(dir: &Path) -> Result<(), Error> {
    bake::fsutil::prepare_dir(dir).map_err(|e| out_error(&e.dir, &e.source))
}

fn out_error(dir: &Path, e: &io::Error) -> Error {
    Error::Failure(format!(
        "output folder {} is not writable: {e}",
        dir.display()
    ))
}

/// `FILE: over budget: E1 (R) = … exceeds …; …`
fn over_budget_message(lut: &Path, exceeded: &[Exceeded]) -> String {
    let list: Vec<String> = exceeded.iter().map(ToString::to_string).collect();
    format!("{}: over budget: {}", lut.display(), list.join("; "))
}

/// Rebuilds the analytic model behind `header`; the default cache directory falls back to
/// no cache (with a note) when it cannot be used, like `viewer probe`.
fn analytic_model(
    header: &LutHeader,
    lut: &Path,
    args: &CompareArgs,
) -> Result<OwnedModel, Failure> {
    let cache_dir = if args.no_cache {
        None
    } else {
        args.cache_dir.clone().or_else(profiles::default_cache_dir)
    };
    let explicit = args.cache_dir.is_some();
    let result = match rebuild_model(header, cache_dir, args.threads) {
        Err(RebuildError::Profiles(e @ profiles::Error::CacheDir { .. })) if !explicit => {
            eprintln_line(&format!("note: {e}; continuing without a cache"));
            rebuild_model(header, None, args.threads)
        }
        r => r,
    };
    result.map_err(|e| match e {
        RebuildError::GeneratorVersion { .. } | RebuildError::Params(_) => {
            Failure::Input(format!("{}: {e}", lut.display()))
        }
        RebuildError::Profiles(e) => Failure::Fatal(Error::Failure(e.to_string())),
    })
}

/// Compares one loaded LUT, prints its table and writes its files into `out`.
fn compare_file(
    lut: &Path,
    file: &LutFile,
    out: Option<&Path>,
    args: &CompareArgs,
    budget: &ErrorBudget,
) -> Result<(Outcome, Option<render::Thumbnail>), Failure> {
    let bad = |e: bcsdf_core::lut::LutError| Failure::Input(format!("{}: {e}", lut.display()));
    let baked: BakedBcsdf<'_> = file.baked().map_err(bad)?;
    let header = file.header().map_err(bad)?;
    let owned = analytic_model(&header, lut, args)?;
    let analytic = owned.model();

    if args.gpu {
        let (adapter, diff) = crate::gpu::render_difference(&file.blob, &baked)
            .map_err(|e| Failure::Input(format!("--gpu: {e}")))?;
        print(&format!(
            "{}: fur render through the GPU shader on {adapter}: mean relative difference to the CPU's baked render R {:.2e} G {:.2e} B {:.2e}\n",
            lut.display(),
            diff[0],
            diff[1],
            diff[2]
        ))
        .map_err(|e| Failure::Fatal(e.into()))?;
    }

    let t = Instant::now();
    let errors = metrics::compare(&analytic, &baked, &MetricSet::DEFAULT);
    let mut exceeded = budget.check(&errors);
    // The same budget at other colours: the LUT read at each against the analytic model
    // with that σ_ca (docs/lut.md "The absorption axis").
    let mut colour_lines = String::new();
    let colours = metrics::random_colours(usize::from(args.colours));
    // The analytic models at those colours, their residual tables made together.
    let references = owned
        .at_sigmas(&colours.iter().map(|(_, c)| *c).collect::<Vec<_>>())
        .map_err(|e| Failure::Fatal(Error::Failure(e.to_string())))?;
    for ((label, colour), reference) in colours.into_iter().zip(&references) {
        let e = metrics::compare(&reference.model(), &baked.at(&colour), &MetricSet::DEFAULT);
        let over = budget.check(&e);
        let [r, g, b] = colour.sigma().0;
        let w = e.worst();
        let _ = writeln!(
            colour_lines,
            "  at {label} (sigma_ca {r:.3}, {g:.3}, {b:.3}): E1 {:.3}%  E_albedo {:.3}%  E_peak {:.3}%  {}",
            100.0 * w[0],
            100.0 * w[1],
            100.0 * w[2],
            if over.is_empty() { "ok" } else { "OVER BUDGET" }
        );
        exceeded.extend(over.into_iter().map(|x| metrics::Exceeded {
            colour: Some(label.clone()),
            ..x
        }));
    }
    let metric_seconds = t.elapsed().as_secs_f64();
    let preset = if file.meta.preset.is_empty() {
        stem(lut)
    } else {
        file.meta.preset.clone()
    };

    let mut outcome = Outcome {
        preset,
        errors,
        exceeded,
        render: None,
        page: None,
    };
    let mut image_seconds = 0.0;
    let mut thumbnail = None;
    if let Some(dir) = out {
        let t = Instant::now();
        let thumb = write_images(
            lut,
            file,
            &header,
            &analytic,
            &baked,
            dir,
            budget,
            &mut outcome,
        )
        .map_err(|e| Failure::Fatal(out_error(dir, &e)))?;
        thumbnail = Some(thumb);
        image_seconds = t.elapsed().as_secs_f64();
    }

    let mut text = String::new();
    preset_table(&mut text, lut, &outcome, file.meta.errors.as_ref(), budget);
    text.push_str(&colour_lines);
    let _ = writeln!(
        text,
        "  time: metrics {metric_seconds:.1} s{}",
        if out.is_some() {
            format!(", images {image_seconds:.1} s")
        } else {
            String::new()
        }
    );
    if let Some(page) = &outcome.page {
        let _ = writeln!(text, "  page: {}", page.display());
    }
    print(&text)?;
    Ok((outcome, thumbnail))
}

/// Draws and writes every image, `compare.json` and `index.html` into `dir`.
#[allow(clippy::too_many_arguments)]
fn write_images(
    lut: &Path,
    file: &LutFile,
    header: &LutHeader,
    analytic: &bcsdf_core::FurBcsdf<'_>,
    baked: &BakedBcsdf<'_>,
    dir: &Path,
    budget: &ErrorBudget,
    outcome: &mut Outcome,
) -> io::Result<render::Thumbnail> {
    let preset = outcome.preset.clone();
    let heat = figures::heat_maps(
        analytic,
        baked,
        &format!("{preset}: analytic vs baked far field"),
        budget.e_peak,
    );
    debug_assert_eq!((heat.width(), heat.height()), HEATMAP_SIZE);
    heat.write_png(&dir.join("heatmap.png"))?;
    let polar = figures::polar_plots(analytic, baked, &format!("{preset}: lobes over phi"));
    debug_assert_eq!((polar.width(), polar.height()), POLAR_SIZE);
    polar.write_png(&dir.join("polar.png"))?;

    let renders = render::render(analytic, baked);
    let diff = renders.mean_relative_difference();
    renders
        .picture(false)
        .write_png(&dir.join("analytic.png"))?;
    renders.picture(true).write_png(&dir.join("baked.png"))?;
    let gain = if budget.e1 > 0.0 {
        (1.0 / budget.e1) as f32
    } else {
        100.0
    };
    let caption = [
        format!("|baked - analytic| x {gain} (1 / E1 budget), same exposure"),
        format!(
            "mean relative difference: R {} G {} B {}",
            pct(diff[0]),
            pct(diff[1]),
            pct(diff[2])
        ),
    ];
    renders
        .difference(gain, &caption)
        .write_png(&dir.join("difference.png"))?;
    renders.families().write_png(&dir.join("families.png"))?;
    outcome.render = Some(diff);

    let page = PresetPage {
        lut,
        header,
        outcome,
        stored: file.meta.errors.as_ref(),
        budget,
    };
    write_file(
        &dir.join("index.html"),
        summary::preset_page(&page).as_bytes(),
    )?;
    write_file(
        &dir.join("compare.json"),
        json::pretty(&Report::new(lut, outcome, budget)).as_bytes(),
    )?;
    outcome.page = Some(dir.join("index.html"));
    Ok(renders.thumbnail())
}

/// The per-LUT table: one row per metric, R G B columns in percent, budget and result.
fn preset_table(
    out: &mut String,
    lut: &Path,
    o: &Outcome,
    stored: Option<&ErrorSummary>,
    budget: &ErrorBudget,
) {
    let _ = writeln!(out, "{} ({})", o.preset, lut.display());
    let _ = writeln!(
        out,
        "  {:<9} {:>9} {:>9} {:>9} {:>9}  result",
        "metric", "R", "G", "B", "budget"
    );
    for row in o.metric_rows(budget) {
        let v = row.values;
        let _ = writeln!(
            out,
            "  {:<9} {:>9} {:>9} {:>9} {:>9}  {}",
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
            out,
            "  {:<9} {:>9} {:>9} {:>9}            (mean |baked - analytic| / analytic over the fur render)",
            "render",
            pct(r[0]),
            pct(r[1]),
            pct(r[2])
        );
    }
    if let Some(s) = stored {
        let _ = writeln!(
            out,
            "  stored at bake time (worst channel): {}",
            named_pcts(&worst_rows(s))
        );
    }
}

/// The `--all` summary: one row per LUT with each metric's worst channel.
fn summary_table(out: &mut String, rows: &[IndexRow], budget: &ErrorBudget) {
    let _ = writeln!(
        out,
        "\nsummary of {} LUTs (worst channel; budget {}):",
        rows.len(),
        named_pcts(&budget_rows(budget))
    );
    let [m0, m1, m2] = METRIC_NAMES;
    let _ = writeln!(
        out,
        "  {:<28} {:<16} {m0:>9} {m1:>9} {m2:>9} {:>9}  result",
        "LUT", "preset", "render"
    );
    for row in rows {
        match &row.outcome {
            Ok(o) => {
                let w = o.errors.worst();
                let render = o.render_worst().map_or_else(|| "-".into(), pct);
                let _ = writeln!(
                    out,
                    "  {:<28} {:<16} {:>9} {:>9} {:>9} {:>9}  {}",
                    row.file,
                    o.preset,
                    pct(w[0]),
                    pct(w[1]),
                    pct(w[2]),
                    render,
                    verdict(o.pass())
                );
            }
            Err(_) => {
                let _ = writeln!(
                    out,
                    "  {:<28} {:<16} {:>9} {:>9} {:>9} {:>9}  ERROR (unreadable)",
                    row.file, "-", "-", "-", "-", "-"
                );
            }
        }
    }
}

/// Writes to stdout (a closed pipe ends the run quietly, see [`Error::report`]).
fn print(text: &str) -> io::Result<()> {
    let mut out = io::stdout().lock();
    out.write_all(text.as_bytes())?;
    out.flush()?;
    Ok(())
}

fn eprintln_line(line: &str) {
    let _ = writeln!(io::stderr().lock(), "{line}");
}
