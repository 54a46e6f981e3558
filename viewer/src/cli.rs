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

Bad input (unknown preset or key, out-of-range value, malformed angle or stdin line) prints
one line starting with `error:` on stderr and exits with code 2.";

const PROBE_EXAMPLES: &str = "\
Output: one JSON line per query,
  {\"total\":[r,g,b],\"lobes\":{\"R\":[r,g,b],\"TT\":[r,g,b],...}}
with the lobes in the model's order; numbers print with enough digits to round-trip f32.

Examples:
  viewer probe --preset yan-row-a --theta-i 30 --theta-r -20 --phi 45          (far field)
  viewer probe --preset yan-row-a --theta-i 30 --theta-r -20 --phi 45 --h 0.3  (near field)
  viewer probe --preset yan-row-b --set sigma_ca=0 --set eta_m=1.3 \\
      --theta-i 20 --theta-r -15 --phi 170
  printf '# theta_i theta_r phi [h]\\n30 -20 45\\n30 -20 45 0.3\\n' \\
      | viewer probe --preset yan-row-a --stdin

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
}
