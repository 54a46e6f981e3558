//! Command-line syntax (clap derive).

use clap::{Args, Parser, Subcommand};
use std::path::PathBuf;

const EXAMPLES: &str = "\
Examples:
  viewer presets
  viewer probe --preset yan-row-a --theta-i 30 --theta-r -20 --phi 45
  viewer probe --preset yan-row-a --theta-i 30 --theta-r -20 --phi 45 --h 0.3
  viewer probe --preset human-hair --set sigma_ca=0.2,0.3,0.6 --set kappa=0.4 \\
      --theta-i 10 --theta-r -10 --phi 180
  printf '30 -20 45\\n30 -20 45 0.3\\n' | viewer probe --preset yan-row-a --stdin
  viewer probe --presets my-presets.toml --preset my-fur --theta-i 0 --theta-r 0 --phi 0
  viewer probe --preset yan-row-b --no-cache --photons-scale 0.1 --theta-i 30 --theta-r -20 --phi 45

Bad input (unknown preset or key, out-of-range value, malformed angle or stdin line) prints
one line starting with `error:` on stderr and exits with code 2.";

const PROBE_EXAMPLES: &str = "\
Output: one JSON line per query,
  {\"total\":[r,g,b],\"lobes\":{\"R\":[r,g,b],\"TT\":[r,g,b],...}}
with the lobes in the model's order (the eight unscattered paths, then the medulla-scattered
TttT_s, TtrtT_s, TttRttT_s); numbers print with enough digits to round-trip f32.

The scattered lobes need medulla profiles, generated once per parameter set (7-13 s on two
cores) and cached (see --cache-dir); presets with sigma_ms = 0 or kappa = 0 need none.

Examples:
  viewer probe --preset yan-row-a --theta-i 30 --theta-r -20 --phi 45          (far field)
  viewer probe --preset yan-row-a --theta-i 30 --theta-r -20 --phi 45 --h 0.3  (near field)
  viewer probe --preset yan-row-b --set sigma_ca=0 --set eta_m=1.3 \\
      --theta-i 20 --theta-r -15 --phi 170
  printf '# theta_i theta_r phi [h]\\n30 -20 45\\n30 -20 45 0.3\\n' \\
      | viewer probe --preset yan-row-a --stdin
  viewer probe --preset yan-row-a --cache-dir /tmp/fur-cache --seed 2 \\
      --theta-i 30 --theta-r -20 --phi 45

Bad input prints one line starting with `error:` on stderr and exits with code 2; with
--stdin the message starts `error: line N:` and the lines before it have been printed.";

/// Command-line probe of the double-cylinder fur BCSDF (Yan et al. 2015).
#[derive(Debug, Parser)]
#[command(name = "viewer", version, after_help = EXAMPLES)]
pub struct Cli {
    /// What to do.
    #[command(subcommand)]
    pub command: Command,
}

/// The subcommands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// List the presets: one line each, the name, a tab, then where its numbers come from.
    #[command(
        after_help = "Examples:\n  viewer presets\n  viewer presets --presets my-presets.toml"
    )]
    Presets(PresetsArgs),
    /// Evaluate the BCSDF of a preset: far field, or near field at offset h with --h.
    #[command(after_help = PROBE_EXAMPLES)]
    Probe(ProbeArgs),
}

/// Where presets come from.
#[derive(Debug, Args)]
pub struct PresetsArgs {
    /// Read presets from FILE (same format as bcsdf-core/presets.toml) instead of the
    /// built-in ones.
    #[arg(long, value_name = "FILE")]
    pub presets: Option<PathBuf>,
}

/// `viewer probe` arguments.
#[derive(Debug, Args)]
pub struct ProbeArgs {
    /// The preset to evaluate (`viewer presets` lists them).
    #[arg(long, value_name = "NAME")]
    pub preset: String,

    #[command(flatten)]
    pub presets: PresetsArgs,

    /// Override one parameter of the preset; repeatable, applied left to right. KEY is one
    /// of eta_c, sigma_ca, eumelanin, pheomelanin, alpha_deg, beta_m_deg, beta_n_deg, l,
    /// kappa, eta_m, sigma_ms, sigma_ma, g; sigma_ca also takes r,g,b.
    #[arg(long = "set", value_name = "KEY=VALUE")]
    pub set: Vec<String>,

    /// Longitudinal angle of the light direction, degrees in [-90, 90].
    #[arg(
        long,
        value_name = "DEG",
        allow_negative_numbers = true,
        required_unless_present = "stdin",
        conflicts_with = "stdin"
    )]
    pub theta_i: Option<f32>,

    /// Longitudinal angle of the view direction, degrees in [-90, 90].
    #[arg(
        long,
        value_name = "DEG",
        allow_negative_numbers = true,
        required_unless_present = "stdin",
        conflicts_with = "stdin"
    )]
    pub theta_r: Option<f32>,

    /// Azimuth phi_r - phi_i, degrees (wrapped to (-180, 180]).
    #[arg(
        long,
        value_name = "DEG",
        allow_negative_numbers = true,
        required_unless_present = "stdin",
        conflicts_with = "stdin"
    )]
    pub phi: Option<f32>,

    /// Near field at this offset of the view ray, in [-1, 1] fiber radii (default: far field,
    /// h integrated).
    #[arg(
        long = "h",
        value_name = "H",
        allow_negative_numbers = true,
        conflicts_with = "stdin"
    )]
    pub h: Option<f32>,

    /// Read queries from stdin instead, one per line: `theta_i theta_r phi [h]` (degrees,
    /// whitespace-separated; a line with h is a near-field query). Blank lines and lines
    /// starting with # are skipped. Prints one JSON line per query, in order.
    #[arg(long)]
    pub stdin: bool,

    #[command(flatten)]
    pub profiles: ProfileArgs,
}

/// Where the medulla profiles of the scattered lobes come from (only presets with
/// sigma_ms > 0 and kappa > 0 need them).
#[derive(Debug, Args)]
#[command(next_help_heading = "Medulla profiles")]
pub struct ProfileArgs {
    /// Cache the generated medulla profiles in DIR (default: $FUR_BCSDF_CACHE, else
    /// ${XDG_CACHE_HOME:-$HOME/.cache}/fur-bcsdf; no cache if none is set). A stale or
    /// corrupt cache file is regenerated and rewritten, with a one-line note on stderr. A
    /// DIR given here that cannot be written is an error (exit code 1); an unusable default
    /// directory is skipped with a note.
    #[arg(long, value_name = "DIR", conflicts_with = "no_cache")]
    pub cache_dir: Option<PathBuf>,

    /// Generate the profiles without reading or writing any cache.
    #[arg(long)]
    pub no_cache: bool,

    /// Seed of the profile generator (the same seed always gives the same bits).
    #[arg(long, value_name = "N", default_value_t = bake::profiles::DEFAULT_SEED)]
    pub seed: u64,

    /// Multiply the photons simulated per profile cell by F (1: noise below 1 % RMS;
    /// smaller is faster and noisier).
    #[arg(long, value_name = "F", default_value_t = 1.0)]
    pub photons_scale: f64,

    /// Threads generating the profiles (default: one per core). The profiles are the same
    /// bits for any count.
    #[arg(long, value_name = "N")]
    pub threads: Option<usize>,
}
