//! `bake`: turns fur presets into half-float LUTs of the whole far-field BCSDF
//! (`bake --help`).

use bake::metrics::{ErrorBudget, MetricSet};
use bake::pipeline::{self, BakeOptions, BakeReport, Step};
use bake::presets::{self, NamedPreset};
use bake::profiles::{self, ProfileOptions};
use bake::shard::Shard;
use bcsdf_core::lut::LutResolution;
use bcsdf_core::medulla::{PhotonBudget, Resolution};
use clap::Parser;
use indicatif::{ProgressBar, ProgressStyle};
use std::io::{self, Write};
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Duration;

const EXAMPLES: &str = "\
Examples:
  bake --all --out luts
  bake --preset bobcat --preset human-hair --out luts
  bake --presets my-presets.toml --preset my-fur --out luts
  bake --all --out luts --res-phi 181 --res-theta-r 64 --threads 2
  bake --all --out luts --no-cache          (regenerate the medulla profiles)
  bake --presets variants.toml --shard 0/8 --out luts   (the first of 8 jobs; K = 0..7)

Writes <OUT>/<preset>.exr (one f16 layer per table, metadata attributes: versions, parameters,
axes, scales, profile provenance, measured error) and <OUT>/<preset>.furlut (the raw
little-endian blob that bcsdf_core::baked::BakedBcsdf::from_bytes reads in place, e.g. from
include_bytes!), and <OUT>/<preset>.furdual (the dual-scattering tables computed from that
LUT, 292 944 bytes of f16: one grey table set per node of the absorption axis, bcsdf_core::dual::DualLut::decode; docs/model.md §13). Files are
written to a temporary file and renamed, so an interrupted bake never leaves a partial LUT
under the final name. The table layout is in docs/lut.md.

Exit codes: 0 all presets baked within the error budget; 1 I/O failure (e.g. unwritable
output directory, disk full); 2 bad input (unknown preset, invalid preset file or value);
3 a preset exceeds the error budget (its files are still written, for inspection).

Sharding (--shard K/N), for job schedulers: K counts from 0 (0 to N-1), like Slurm's
SLURM_ARRAY_TASK_ID with --array=0-(N-1), Kubernetes' JOB_COMPLETION_INDEX, and GNU parallel
fed with `seq 0 N-1` (not {#} or {%}, which count from 1). Preset i of the list (from 0,
in file order) belongs to shard i mod N: the N shards are disjoint, together bake every preset
once, and shard K always bakes the same presets for the same file (appending presets moves
none of the existing ones). A shard with no presets (N above the preset count) succeeds and
writes nothing. Shards may share --out and the profile cache: bake writes only
<OUT>/<preset>.exr, .furlut and .furdual (each via a uniquely named temporary file), and
the summary goes to standard output, so concurrent shards never write the same file. Shards
sharing a profile cache generate each missing entry once: one takes the entry's lock file
(medulla-<hash>.lock) and generates, the others wait and read it; a killed holder leaves no
lock held, and the next bake repairs the entry.

Preset names (files, --preset): 1 to 64 ASCII letters, digits, '-', '_', '.', not starting
with '.' or '-', not a Windows device name (CON, NUL, COM1, ...); any other name exits 2.";

/// Bake fur presets into half-float lookup tables of the full far-field BCSDF (unscattered
/// and medulla-scattered lobes), and measure them against the analytic model.
#[derive(Debug, Parser)]
#[command(name = "bake", version, after_help = EXAMPLES)]
struct Cli {
    /// Bake this preset (repeatable).
    #[arg(long, value_name = "NAME", required_unless_present_any = ["all", "shard"])]
    preset: Vec<String>,

    /// Bake every preset (of --presets FILE, or the built-in ones).
    #[arg(long, conflicts_with = "preset")]
    all: bool,

    /// Bake only shard K of N of all the presets (of --presets FILE, or the built-in ones):
    /// those at positions i with i mod N = K, counting from 0 in file order; K is 0 to N-1.
    /// Implies --all; not with --preset. See "Sharding" below.
    #[arg(long, value_name = "K/N", conflicts_with = "preset")]
    shard: Option<String>,

    /// Read presets from FILE (same format as bcsdf-core/presets.toml) instead of the
    /// built-in ones.
    #[arg(long, value_name = "FILE")]
    presets: Option<PathBuf>,

    /// Output directory (created if needed).
    #[arg(long, value_name = "DIR")]
    out: PathBuf,

    /// Nodes of theta_i + theta_r over [-180, 180] deg (the M table).
    #[arg(long, value_name = "N", default_value_t = LutResolution::DEFAULT.n_sum)]
    res_sum: u32,

    /// Nodes of |theta_r| over [0, 90] deg (rows of the N tables).
    #[arg(long, value_name = "N", default_value_t = LutResolution::DEFAULT.n_theta_r)]
    res_theta_r: u32,

    /// Nodes of |phi| over [0, 180] deg (columns of the N tables).
    #[arg(long, value_name = "N", default_value_t = LutResolution::DEFAULT.n_phi)]
    res_phi: u32,

    /// Nodes of theta_i and of theta_r over [-90, 90] deg (the M_s table).
    #[arg(long, value_name = "N", default_value_t = LutResolution::DEFAULT.n_ms_i)]
    res_ms: u32,

    /// Nodes of the absorption axis, sigma_ca over [0, 1000] per fiber radius (planes of the
    /// N tables; at least 3; docs/lut.md "The absorption axis").
    #[arg(long, value_name = "N", default_value_t = LutResolution::DEFAULT.n_abs)]
    res_abs: u32,

    /// Quadrature of the dual-scattering tables (.furdual): THETA,PHI midpoint nodes in theta_i
    /// (8 to 1024) and |phi| (8 to 256, even). Coarser is faster and less accurate; the
    /// default is what the shipped tables use (docs/model.md §13).
    #[arg(long, value_name = "THETA,PHI", default_value = "128,96")]
    res_dual: String,

    /// Threads (default and 0: one per core; at most 8 per core, above 4096 refused). The
    /// LUTs are the same bits for any count.
    #[arg(long, value_name = "N")]
    threads: Option<usize>,

    /// Error budget E1,E_albedo,E_peak (fractions or percentages).
    #[arg(long, value_name = "E1,EA,EP", default_value = "1%,0.5%,2%")]
    budget: String,

    /// Skip measuring the baked tables against the analytic model (faster; no budget check).
    #[arg(long)]
    no_check: bool,

    /// Cache the medulla profiles in DIR (default: $FUR_BCSDF_CACHE, else
    /// ${XDG_CACHE_HOME:-$HOME/.cache}/fur-bcsdf).
    #[arg(long, value_name = "DIR", conflicts_with = "no_cache")]
    cache_dir: Option<PathBuf>,

    /// Generate the medulla profiles without reading or writing any cache.
    #[arg(long)]
    no_cache: bool,

    /// Seed of the profile generator.
    #[arg(long, value_name = "N", default_value_t = profiles::DEFAULT_SEED)]
    seed: u64,

    /// Multiply the photons per profile cell by F (1: noise below 1 %; at most 16, the
    /// generation time grows with F and is estimated above 1).
    #[arg(long, value_name = "F", default_value_t = 1.0)]
    photons_scale: f64,
}

/// A failure with its exit code and one-line message.
struct Failure {
    code: u8,
    message: String,
}

fn input(message: impl ToString) -> Failure {
    Failure {
        code: 2,
        message: message.to_string(),
    }
}

fn main() -> ExitCode {
    match run(Cli::parse()) {
        Ok(code) => ExitCode::from(code),
        Err(f) => {
            let _ = writeln!(io::stderr().lock(), "error: {}", f.message);
            ExitCode::from(f.code)
        }
    }
}

fn select(cli: &Cli, shard: Option<Shard>) -> Result<Vec<NamedPreset>, Failure> {
    let all = match &cli.presets {
        Some(path) => presets::load_file(path).map_err(input)?,
        None => presets::builtin().map_err(input)?,
    };
    if let Some(shard) = shard {
        let selected = shard.select(&all);
        let names: Vec<&str> = selected.iter().map(|p| p.name.as_str()).collect();
        if selected.is_empty() {
            eprintln!(
                "shard {shard}: no presets (the list has {}), nothing to bake",
                all.len()
            );
        } else {
            eprintln!(
                "shard {shard}: {} of {} presets ({})",
                selected.len(),
                all.len(),
                names.join(", ")
            );
        }
        return Ok(selected);
    }
    if cli.all {
        return Ok(all);
    }
    cli.preset
        .iter()
        .map(|name| {
            bcsdf_core::params::check_name(name)
                .map_err(|e| input(format!("--preset: name {name:?} {e}")))?;
            let (preset, alias) = presets::lookup(&all, name).ok_or_else(|| {
                let known: Vec<&str> = all.iter().map(|p| p.name.as_str()).collect();
                input(format!(
                    "unknown preset '{name}' (known: {})",
                    known.join(", ")
                ))
            })?;
            if let Some(alias) = alias {
                eprintln!("note: {alias}");
            }
            Ok(preset.clone())
        })
        .collect()
}

fn options(cli: &Cli) -> Result<BakeOptions, Failure> {
    let res = LutResolution {
        n_sum: cli.res_sum,
        n_theta_r: cli.res_theta_r,
        n_phi: cli.res_phi,
        n_ms_i: cli.res_ms,
        n_ms_r: cli.res_ms,
        n_abs: cli.res_abs,
    };
    res.validate().map_err(input)?;
    let (budget, note) =
        bake::limits::photon_budget(PhotonBudget::DEFAULT, cli.photons_scale).map_err(input)?;
    if let Some(note) = note {
        eprintln!("note: {note}");
    }
    let cache_dir = if cli.no_cache {
        None
    } else {
        cli.cache_dir.clone().or_else(profiles::default_cache_dir)
    };
    Ok(BakeOptions {
        res,
        profiles: ProfileOptions {
            res: Resolution::DEFAULT,
            budget,
            seed: cli.seed,
            cache_dir,
            threads: None,
        },
        out_dir: cli.out.clone(),
        metrics: (!cli.no_check).then_some(MetricSet::DEFAULT),
        dual: bake::limits::dual_quadrature(&cli.res_dual).map_err(input)?,
    })
}

fn spinner(name: &str) -> ProgressBar {
    let bar = ProgressBar::new_spinner();
    bar.set_style(
        ProgressStyle::with_template("{spinner} {prefix:12} {msg} ({elapsed})")
            .unwrap_or_else(|_| ProgressStyle::default_spinner()),
    );
    bar.set_prefix(name.to_string());
    bar.enable_steady_tick(Duration::from_millis(120));
    bar
}

fn run(cli: Cli) -> Result<u8, Failure> {
    let budget = ErrorBudget::parse(&cli.budget).map_err(input)?;
    let shard = cli
        .shard
        .as_deref()
        .map(str::parse::<Shard>)
        .transpose()
        .map_err(input)?;
    let selected = select(&cli, shard)?;
    let mut opts = options(&cli)?;
    let (threads, note) = bake::limits::threads("--threads", cli.threads).map_err(input)?;
    if let Some(note) = note {
        eprintln!("note: {note}");
    }
    if let Some(n) = threads {
        rayon::ThreadPoolBuilder::new()
            .num_threads(n)
            .build_global()
            .map_err(|e| Failure {
                code: 1,
                message: format!("cannot start {n} threads: {e}"),
            })?;
    }
    // Every output path is known (and inside --out) before anything is created.
    for preset in &selected {
        pipeline::output_paths(&opts.out_dir, &preset.name).map_err(bake_failure)?;
    }
    pipeline::prepare_out_dir(&opts.out_dir).map_err(|e| Failure {
        code: 1,
        message: e.to_string(),
    })?;

    let mut reports = Vec::new();
    for preset in &selected {
        let bar = spinner(&preset.name);
        let result = pipeline::bake_preset(preset, &opts, &|step: Step| {
            bar.set_message(step.describe())
        });
        bar.finish_and_clear();
        let report = match result {
            Ok(r) => r,
            // The default cache directory is a convenience: when it cannot be used (not
            // writable, no advisory locks), say so and bake without a cache. A directory the
            // user named is an error.
            Err(pipeline::BakeError::Profiles(
                e @ (profiles::Error::CacheDir { .. } | profiles::Error::CacheLock { .. }),
            )) if cli.cache_dir.is_none() && opts.profiles.cache_dir.is_some() => {
                eprintln!("note: {e}; continuing without a cache");
                opts.profiles.cache_dir = None;
                pipeline::bake_preset(preset, &opts, &|_| {}).map_err(bake_failure)?
            }
            Err(e) => return Err(bake_failure(e)),
        };
        if let Some(note) = report.cache.as_ref().and_then(|c| c.note()) {
            eprintln!("note: {note}");
        }
        if let Some(note) = &report.residual_note {
            eprintln!("note: {note}");
        }
        if let Some(b) = &report.base_colour {
            let tag = if b.is_clamped() { "warning" } else { "note" };
            eprintln!("{tag}: preset {}: {b}", report.preset);
        }
        reports.push(report);
    }
    print_summary(&reports, &budget, &opts.res, &opts.out_dir);
    let failed = reports
        .iter()
        .filter_map(|r| r.errors.as_ref().map(|e| (r, budget.check(e))))
        .filter(|(_, ex)| !ex.is_empty())
        .collect::<Vec<_>>();
    for (r, ex) in &failed {
        for e in ex {
            eprintln!("error: {}: {e}", r.preset);
        }
    }
    Ok(if failed.is_empty() { 0 } else { 3 })
}

fn bake_failure(e: pipeline::BakeError) -> Failure {
    let code = match e {
        pipeline::BakeError::Params { .. } | pipeline::BakeError::Name(_) => 2,
        _ => 1,
    };
    Failure {
        code,
        message: e.to_string(),
    }
}

fn print_summary(
    reports: &[BakeReport],
    budget: &ErrorBudget,
    res: &LutResolution,
    out_dir: &std::path::Path,
) {
    let pct = |v: f64| format!("{:.3}%", 100.0 * v);
    println!(
        "LUT resolution: n_sum {} | n_theta_r {} x n_phi {} x n_abs {} | n_ms {} x {}   budget: E1 {} E_albedo {} E_peak {}",
        res.n_sum,
        res.n_theta_r,
        res.n_phi,
        res.n_abs,
        res.n_ms_i,
        res.n_ms_r,
        pct(budget.e1),
        pct(budget.e_albedo),
        pct(budget.e_peak)
    );
    println!(
        "sizes: f16 KB = the half-float tables; LUT KB = the whole .furlut (header, tables and \
         the sampling data) as BakedBcsdf reads it; dual KB = the .furdual dual-scattering \
         tables (f16, beside the LUT), dual s = the time to compute them from the baked LUT"
    );
    println!(
        "{:<14} {:>9} {:>9} {:>9} {:>8} {:>7} {:>10} {:>8} {:>8} {:>9} {:>9} {:>9}  result",
        "preset",
        "f16 KB",
        "LUT KB",
        "EXR KB",
        "dual KB",
        "dual s",
        "profiles",
        "bake s",
        "check s",
        "E1",
        "E_albedo",
        "E_peak",
    );
    for r in reports {
        let profiles = match &r.cache {
            None => "none",
            Some(profiles::CacheOutcome::Hit { .. }) => "cached",
            Some(_) => "generated",
        };
        let (e, verdict) = match &r.errors {
            Some(s) => {
                let w = s.worst();
                let ok = budget.check(s).is_empty();
                (w.map(pct), if ok { "ok" } else { "OVER BUDGET" })
            }
            None => (
                ["-".to_string(), "-".to_string(), "-".to_string()],
                "unchecked",
            ),
        };
        println!(
            "{:<14} {:>9.1} {:>9.1} {:>9.1} {:>8.1} {:>7.2} {:>10} {:>8.2} {:>8.2} {:>9} {:>9} {:>9}  {}",
            r.preset,
            r.table_bytes as f64 / 1024.0,
            r.blob_bytes as f64 / 1024.0,
            r.exr_bytes as f64 / 1024.0,
            r.dual_bytes as f64 / 1024.0,
            r.dual_seconds,
            profiles,
            r.bake_seconds(),
            r.metric_seconds,
            e[0],
            e[1],
            e[2],
            verdict
        );
    }
    println!(
        "wrote {} LUTs (.exr, .furlut and .furdual) to {}",
        reports.len(),
        out_dir.display()
    );
}
