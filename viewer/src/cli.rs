//! Command-line syntax (clap derive).

use clap::{Args, Parser, Subcommand};
use std::path::PathBuf;

const EXAMPLES: &str = "\
Examples:
  viewer presets
  viewer probe --preset bobcat --theta-i 30 --theta-r -20 --phi 45
  viewer probe --preset bobcat --theta-i 30 --theta-r -20 --phi 45 --h 0.3
  viewer probe --preset human-hair --set sigma_ca=0.2,0.3,0.6 --set kappa=0.4 \\
      --theta-i 10 --theta-r -10 --phi 180
  printf '30 -20 45\\n30 -20 45 0.3\\n' | viewer probe --preset bobcat --stdin
  viewer probe --presets my-presets.toml --preset my-fur --theta-i 0 --theta-r 0 --phi 0
  viewer probe --preset red-fox --no-cache --photons-scale 0.1 --theta-i 30 --theta-r -20 --phi 45
  viewer probe --preset bobcat --theta-i 30 --theta-r -20 --phi 45 --pdf
  viewer probe --lut luts/bobcat.exr --theta-i 30 --theta-r -20 --phi 45 --pdf
  viewer sample --preset bobcat --theta-r -20 -n 1000 --seed 7
  viewer sample --lut luts/bobcat.furlut --theta-r -20 -n 1000
  viewer compare luts/bobcat.exr
  viewer compare --all luts --budget 1%,0.5%,2%

Bad input (unknown preset or key, out-of-range value, malformed angle or stdin line, missing
or corrupt LUT) prints one line starting with `error:` on stderr and exits with code 2.";

const PROBE_EXAMPLES: &str = "\
Output: one JSON line per query,
  {\"total\":[r,g,b],\"lobes\":{\"R\":[r,g,b],\"TT\":[r,g,b],...}}
with the lobes in the model's order (the eight unscattered paths, then the medulla-scattered
TttT_s, TtrtT_s, TttRttT_s). With --lut, the LUT's far field per lobe family instead:
  {\"total\":[r,g,b],\"families\":{\"R\":[r,g,b],\"TT\":[r,g,b],\"TRT\":[r,g,b],\"scattered\":[r,g,b]}}
With --pdf every line ends with ,\"pdf\":p before the closing brace: the density per unit
solid angle with which importance sampling (`viewer sample`) draws this omega_i given
omega_r. Numbers print with enough digits to round-trip f32.

The scattered lobes need medulla profiles, generated once per parameter set (7-13 s on two
cores) and cached (see --cache-dir); presets with sigma_ms = 0 or kappa = 0 need none.

Examples:
  viewer probe --preset bobcat --theta-i 30 --theta-r -20 --phi 45          (far field)
  viewer probe --preset bobcat --theta-i 30 --theta-r -20 --phi 45 --h 0.3  (near field)
  viewer probe --preset red-fox --set sigma_ca=0 --set eta_m=1.3 \\
      --theta-i 20 --theta-r -15 --phi 170
  printf '# theta_i theta_r phi [h]\\n30 -20 45\\n30 -20 45 0.3\\n' \\
      | viewer probe --preset bobcat --stdin
  viewer probe --preset bobcat --cache-dir /tmp/fur-cache --seed 2 \\
      --theta-i 30 --theta-r -20 --phi 45
  viewer probe --preset human-hair --theta-i 30 --theta-r -20 --phi 45 --pdf
  viewer probe --lut luts/bobcat.exr --theta-i 30 --theta-r -20 --phi 45
  printf '30 -20 45\\n0 0 180\\n' | viewer probe --lut luts/bobcat.furlut --pdf --stdin
  viewer probe --lut luts/bobcat.furlut --gpu --theta-i 30 --theta-r -20 --phi 45 --pdf

A LUT (.exr or .furlut, told apart by content) holds the far field only, and --pdf is a
far-field density: with --lut or --pdf, --h and stdin lines with h are errors.

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
    /// List the presets: a table of every parameter (docs/model.md §9), then where each
    /// preset's numbers come from, then the former names that still select a preset.
    #[command(
        after_help = "Examples:\n  viewer presets\n  viewer presets --json\n  viewer presets --presets my-presets.toml"
    )]
    Presets(PresetsListArgs),
    /// Evaluate the BCSDF of a preset (far field, or near field at offset h with --h) or of a
    /// baked LUT (far field).
    #[command(after_help = PROBE_EXAMPLES)]
    Probe(ProbeArgs),
    /// Importance-sample incident directions for one view angle, from the analytic model of a
    /// preset or a baked LUT: direction, pdf, weight and lobe family of each draw.
    // `--seed` seeds the draws here, so the profile generator's seed is `--profile-seed`.
    #[command(
        after_help = SAMPLE_EXAMPLES,
        mut_arg("seed", |a| a.long("profile-seed"))
    )]
    Sample(SampleArgs),
    /// Check a baked LUT against the analytic model it was baked from: error metrics per RGB
    /// channel against a budget, heat maps, polar lobe plots, fur renders, a summary page.
    #[command(after_help = COMPARE_EXAMPLES)]
    Compare(CompareArgs),
    /// Path-trace a furry scene (many fibers, multiple scattering, next-event estimation
    /// with MIS) with the analytic model of a preset or a baked LUT: render.exr (linear RGB,
    /// f32), render.png (tone-mapped sRGB) and render.json in the output folder.
    #[command(after_help = RENDER_EXAMPLES)]
    Render(RenderArgs),
}

const RENDER_EXAMPLES: &str = "\
Scenes: ball (a furry sphere on a grey ground, key light and dim sky; 20000 fibers of 6
segments), patch (a square of skin with fur, rim light and dim sky), furnace (a clump of
fibers in a uniform white environment of radiance 1 and nothing else). Fibers are far-field
scatterers: each segment's BCSDF is evaluated and importance-sampled in its own frame.

Output in DIR (each file written to a temporary file, then renamed):
  render.exr   linear RGB radiance, 32-bit float
  render.png   8-bit sRGB after the tone curve 1 - exp(-exposure x)
  render.json  scene, preset, evaluator, spp, depth, seconds, paths and rays per second,
               mean radiance RGB, energy per bounce order
The image is the same bits for any --threads.

Examples:
  viewer render --scene ball --preset human-hair --spp 64 --out ball-hair
  viewer render --scene ball --preset raccoon --spp 64 --max-depth 32 \\
      --width 320 --height 240 --out ball-row-c
  viewer render --scene ball --preset raccoon --evaluator analytic --spp 16 --out ball-analytic
  viewer render --scene ball --lut luts/bobcat.furlut --spp 16 --out ball-row-a
  viewer render --scene furnace --preset human-hair --set sigma_ca=0 --spp 32 --out furnace
  viewer render --scene patch --preset air-medulla --fibers 2000 --spp 8 --threads 2 --out patch
  viewer render --scene ball --lut luts/bobcat.furlut --colour 0.35,0.2,0.1 \\
      --colour-stripes 0.03,0.025,0.02:0.05 --spp 16 --out ball-striped
  viewer render --scene patch --lut luts/cat.furlut --colour-texture coat.png --spp 16 \\
      --out patch-textured

Bad input (unknown scene, preset or key, --spp 0, a size or depth out of range, --lut with
the analytic evaluator, a missing or corrupt LUT) prints one line starting with `error:` on
stderr and exits with code 2; an output folder that cannot be written exits with 1.";

/// Which evaluator `viewer render` uses.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Evaluator {
    /// The analytic far field of the preset.
    Analytic,
    /// Baked tables: the LUT of --lut, or the preset baked in memory.
    Baked,
}

/// The light transport method of `viewer render` (docs/model.md §11, §13).
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Method {
    /// Unidirectional path tracing with next-event estimation and MIS (the reference).
    Path,
    /// `single`, with rays toward a fiber's lights and surfaces that count the fibers they
    /// cross (and, away from the light, the fibers of the coat below), plus the
    /// dual-scattering term (tables computed from the evaluator first).
    Dual,
    /// No fiber-to-fiber light: at a fiber, light sampling with a binary shadow ray and a
    /// bounce only to a surface no fiber hides (skin and ground path traced as in `path`).
    Single,
}

/// `viewer render` arguments.
#[derive(Debug, Args)]
pub struct RenderArgs {
    /// The scene: ball, patch or furnace.
    #[arg(long, value_name = "SCENE")]
    pub scene: String,

    /// The preset whose fur to render (`viewer presets` lists them).
    #[arg(long, value_name = "NAME", required_unless_present = "lut")]
    pub preset: Option<String>,

    #[command(flatten)]
    pub presets: PresetsArgs,

    /// Override one parameter of the preset (as in `viewer probe`); repeatable. With
    /// `--lut`, only the colour keys: the LUT (and its .furdual) is read at that sigma_ca.
    #[arg(long = "set", value_name = "KEY=VALUE")]
    pub set: Vec<String>,

    /// Render with this baked LUT (.exr or .furlut) instead of a preset. `dual` reads the
    /// .furdual of the same name beside it (written by `bake`) if there is one, refused unless
    /// it was computed from this LUT; otherwise it computes the tables from the LUT.
    #[arg(long, value_name = "FILE", conflicts_with_all = ["preset", "presets"])]
    pub lut: Option<PathBuf>,

    /// The evaluator: baked (the default: the LUT of --lut, or with --preset the preset's
    /// LUT baked in memory first, at the default resolution) or analytic (--preset only).
    /// The summary line says which one rendered.
    #[arg(long, value_enum)]
    pub evaluator: Option<Evaluator>,

    /// Light transport method.
    #[arg(long, value_enum, default_value = "path")]
    pub method: Method,

    /// Render path, dual and single, and write them side by side with |dual − path|
    /// (compare.png, compare.exr) and the numbers judging dual and single against path — mean
    /// luminance error and 16 x 16 tile RMSE (compare.json, stdout) — instead of one render
    /// (docs/model.md §13).
    #[arg(long, conflicts_with = "method")]
    pub compare: bool,

    /// Colour of the strands (at the root, with --tip-colour): a linear base colour R,G,B
    /// (or one grey), each in [0, 1], turned into sigma_ca per query through the coat colour
    /// table measured from the LUT (docs/model.md §14). Needs the baked evaluator (the
    /// default) and --method path or single.
    #[arg(long, value_name = "R,G,B")]
    pub colour: Option<String>,

    /// Colour at the tips: the colour goes linearly from the root's (--colour, the stripes'
    /// or the texture's) to this at the tip. Needs --colour or --colour-texture.
    #[arg(long, value_name = "R,G,B")]
    pub tip_colour: Option<String>,

    /// Random per-strand variation of the colour's lightness, in percent (0 to 100): each
    /// strand's colour times 1 + P/100 x (2u - 1), u drawn from --seed and the fiber's index.
    /// Needs --colour or --colour-texture.
    #[arg(long, value_name = "P")]
    pub colour_jitter: Option<f32>,

    /// Stripes of a second colour over --colour across the body: bands of width WIDTH (a
    /// fraction of the body's u coordinate, 0 < WIDTH <= 1, default 0.1: ten bands),
    /// alternately --colour and R,G,B, chosen by where each fiber's root is: u is the patch's
    /// x, the ball's longitude (docs/model.md §14). Needs --colour.
    #[arg(
        long,
        value_name = "R,G,B[:WIDTH]",
        requires = "colour",
        conflicts_with = "colour_texture"
    )]
    pub colour_stripes: Option<String>,

    /// Each fiber's root colour from an image (PNG, sRGB, decoded to linear), looked up at
    /// the root's (u, v) on the body: the patch's (x, z) with the image's top row at the far
    /// edge, the ball's longitude and colatitude (an equirectangular map). Instead of
    /// --colour; needs a baked LUT like it.
    #[arg(long, value_name = "FILE.png", conflicts_with = "colour")]
    pub colour_texture: Option<PathBuf>,

    /// Dual scattering's forward density factor d_f (docs/model.md §13).
    #[arg(long, value_name = "D", default_value_t = bcsdf_core::dual::Density::DEFAULT.d_f)]
    pub d_f: f32,

    /// Dual scattering's backward density factor d_b (docs/model.md §13).
    #[arg(long, value_name = "D", default_value_t = bcsdf_core::dual::Density::DEFAULT.d_b)]
    pub d_b: f32,

    /// Samples (camera paths) per pixel.
    #[arg(long, value_name = "N")]
    pub spp: u32,

    /// Largest number of scattering events on a path.
    #[arg(long, value_name = "D", default_value_t = 32)]
    pub max_depth: u32,

    /// Image width in pixels.
    #[arg(long, value_name = "W", default_value_t = 320)]
    pub width: u32,

    /// Image height in pixels.
    #[arg(long, value_name = "H", default_value_t = 240)]
    pub height: u32,

    /// Number of fibers (default: the scene's).
    #[arg(long, value_name = "N")]
    pub fibers: Option<usize>,

    /// Seed of the fiber placement and of the per-pixel random streams.
    #[arg(long, value_name = "S", default_value_t = 1)]
    pub seed: u64,

    /// Worker threads (default: one per core). The image is the same bits for any count.
    #[arg(long, value_name = "N")]
    pub threads: Option<usize>,

    /// Exposure of render.png's tone curve 1 - exp(-exposure x).
    #[arg(long, value_name = "E", default_value_t = 1.0)]
    pub exposure: f32,

    /// Output folder (created if needed).
    #[arg(long, value_name = "DIR")]
    pub out: PathBuf,

    /// Cache of the medulla profiles (as in `viewer probe`).
    #[arg(long, value_name = "DIR", conflicts_with = "no_cache")]
    pub cache_dir: Option<PathBuf>,

    /// Generate the profiles without reading or writing any cache.
    #[arg(long)]
    pub no_cache: bool,
}

const COMPARE_EXAMPLES: &str = "\
The analytic model is rebuilt from the parameters stored in the LUT; its medulla profiles
are regenerated from the seed, photon budget and resolution stored there (or loaded from the
profile cache), so it is the model the tables were baked from.

Output: a table per LUT on stdout (rows E1, E_albedo, E_peak; columns R, G, B in percent,
the budget and PASS/FAIL; a `render` row with the mean relative difference of the fur
renders), and in the output folder:
  heatmap.png     1394 x 942  S cos^2(theta_i) over theta_i in [-85, 85] x phi in [-180, 180]
                              for theta_r = -30, 0, 30, 60: analytic | baked (log colour
                              scale, 4 decades) | relative error (+/- the E_peak budget);
                              each panel 360 x 170, one pixel per degree
  polar.png       1016 x 870  S over phi at (theta_i, theta_r) = (30, -20), (0, 0), (60, -50),
                              one panel per lobe family R, TT, TRT, scattered; analytic solid,
                              baked dashed; radius log10 S over 3 decades
  analytic.png     512 x 384  a patch of 500 curved fibers lit by one directional light,
  baked.png        512 x 384  rendered with the analytic and the baked far field (same
                              exposure)
  difference.png   512 x 384  |baked - analytic| amplified by 1 / (E1 budget), scale written on it
  families.png     512 x 384  the analytic render split by lobe family (2 x 2, half size)
  index.html                  the page putting it together; compare.json: the numbers
With --all DIR: one `<lut-stem>-compare/` folder per LUT under the output folder (default
DIR), a combined table at the end and `index.html` linking every LUT's page.

Exit codes: 0 within the budget; 3 when a metric exceeds it (stderr names each metric and
channel); 2 for bad input (missing, corrupt or incompatible LUT, malformed --budget, a
folder without *.exr); 1 when the output folder cannot be written (checked before any work)
or the profiles cannot be made. --all reports every LUT first, then exits 2 if any could not
be read, else 3 if any exceeded the budget.

Examples:
  viewer compare luts/bobcat.exr
  viewer compare luts/bobcat.exr --out /tmp/row-a --budget 0.5%,0.5%,1%
  viewer compare luts/human-hair.exr --no-images
  viewer compare --all luts --cache-dir /tmp/fur-cache --threads 2";

/// `viewer compare` arguments.
#[derive(Debug, Args)]
pub struct CompareArgs {
    /// The LUT to check: an .exr written by `bake`.
    #[arg(
        value_name = "LUT.exr",
        required_unless_present = "all",
        conflicts_with = "all"
    )]
    pub lut: Option<PathBuf>,

    /// Check every *.exr in DIR instead (by name), then print one combined summary.
    #[arg(long, value_name = "DIR")]
    pub all: Option<PathBuf>,

    /// Output folder (created if needed). Default: `<lut-stem>-compare/` beside the LUT;
    /// with --all, DIR itself (one `<lut-stem>-compare/` per LUT and `index.html`).
    #[arg(long, value_name = "DIR")]
    pub out: Option<PathBuf>,

    /// Largest acceptable E1, E_albedo and E_peak: fractions (0.01,0.005,0.02) or
    /// percentages (1%,0.5%,2%).
    #[arg(long, value_name = "E1,E_ALBEDO,E_PEAK", default_value = "1%,0.5%,2%")]
    pub budget: String,

    /// Measure and print only: no images, no pages, nothing written.
    #[arg(long)]
    pub no_images: bool,

    /// Also render the fur patch through the WGSL shader on the first GPU adapter and print
    /// its mean relative difference to the CPU's baked render (no adapter: exit 2).
    #[arg(long)]
    pub gpu: bool,

    /// Cache of the medulla profiles (default: $FUR_BCSDF_CACHE, else
    /// ${XDG_CACHE_HOME:-$HOME/.cache}/fur-bcsdf). A DIR given here that cannot be written
    /// is an error (exit code 1); an unusable default directory is skipped with a note.
    #[arg(long, value_name = "DIR", conflicts_with = "no_cache")]
    pub cache_dir: Option<PathBuf>,

    /// Regenerate the profiles without reading or writing any cache.
    #[arg(long)]
    pub no_cache: bool,

    /// Worker threads for the profiles, metrics and images (default: one per core; 0 also
    /// means the default). Results are the same bits for any count.
    #[arg(long, value_name = "N")]
    pub threads: Option<usize>,

    /// Also measure the LUT at this many random colours (0 to 16; a fixed set, each channel
    /// of σ_ca over [0.01, 1000] with lossless and ≥ 100 channels among them) against the
    /// analytic model at each colour, within the same budget.
    #[arg(long, value_name = "N", default_value_t = 3, value_parser = clap::value_parser!(u8).range(0..=16))]
    pub colours: u8,
}

/// Where presets come from.
#[derive(Debug, Args)]
pub struct PresetsArgs {
    /// Read presets from FILE (same format as bcsdf-core/presets.toml) instead of the
    /// built-in ones.
    #[arg(long, value_name = "FILE")]
    pub presets: Option<PathBuf>,
}

/// `viewer presets` arguments.
#[derive(Debug, Args)]
pub struct PresetsListArgs {
    #[command(flatten)]
    pub presets: PresetsArgs,
    /// Print the presets as one JSON document instead of the table.
    #[arg(long)]
    pub json: bool,
}

/// `viewer probe` arguments.
#[derive(Debug, Args)]
pub struct ProbeArgs {
    #[command(flatten)]
    pub model: ModelArgs,

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
    /// h integrated). Not with --lut or --pdf (far field only).
    #[arg(
        long = "h",
        value_name = "H",
        allow_negative_numbers = true,
        conflicts_with_all = ["stdin", "lut", "pdf"]
    )]
    pub h: Option<f32>,

    /// Read queries from stdin instead, one per line: `theta_i theta_r phi [h]` (degrees,
    /// whitespace-separated; a line with h is a near-field query). Blank lines and lines
    /// starting with # are skipped. Prints one JSON line per query, in order.
    #[arg(long)]
    pub stdin: bool,

    /// Also print the sampling density of each far-field query: `"pdf":p`, per unit solid
    /// angle, of omega_i given omega_r (what `viewer sample` draws from), as the last key.
    #[arg(long)]
    pub pdf: bool,

    /// With --lut: evaluate through the WGSL shader (bcsdf-core/shaders/fur_bcsdf.wgsl) on
    /// the first GPU adapter (Vulkan; without a GPU, Mesa's software driver: Debian packages
    /// mesa-vulkan-drivers and libvulkan1). Same output as without it. No adapter: exit 2.
    #[arg(long, requires = "lut", conflicts_with = "h")]
    pub gpu: bool,

    #[command(flatten)]
    pub profiles: ProfileArgs,
}

/// `--set`'s help text: every key of `bcsdf_core::SCHEMA` (docs/model.md §2), so the list
/// can never lose one.
pub fn set_help() -> String {
    let keys: Vec<&str> = bcsdf_core::SCHEMA.iter().map(|spec| spec.key).collect();
    format!(
        "Override one parameter of the preset; repeatable, applied left to right. KEY is one \
         of {}; sigma_ca and base_colour also take r,g,b, closure takes report or energy. \
         With --lut only the colour keys (the LUT is read at that sigma_ca; base_colour is \
         inverted with the LUT's coat colour table). Without --lut, base_colour is refused: \
         bake a LUT from it.",
        keys.join(", ")
    )
}

/// Which BCSDF a command works on: the analytic model of a preset (with `--set` overrides;
/// its medulla profiles come from [`ProfileArgs`]), or a baked LUT with `--lut`.
#[derive(Debug, Args)]
pub struct ModelArgs {
    /// The preset to use (`viewer presets` lists them): its analytic model.
    #[arg(long, value_name = "NAME", required_unless_present = "lut")]
    pub preset: Option<String>,

    #[command(flatten)]
    pub presets: PresetsArgs,

    /// Override one parameter of the preset; repeatable, applied left to right (the keys:
    /// [`set_help`], from `bcsdf_core::SCHEMA`). With `--lut`, only the colour keys: the
    /// LUT is read at that σ_ca.
    #[arg(long = "set", value_name = "KEY=VALUE", help = set_help())]
    pub set: Vec<String>,

    /// Use this baked LUT (written by `bake`: OpenEXR or raw .furlut, told apart by content)
    /// instead of a preset: its far field, per lobe family.
    #[arg(
        long,
        value_name = "FILE",
        conflicts_with_all = [
            "preset", "presets",
            "cache_dir", "no_cache", "seed", "photons_scale", "threads",
        ]
    )]
    pub lut: Option<PathBuf>,
}

const SAMPLE_EXAMPLES: &str = "\
Output: one line per draw, space-separated,
  theta_i phi pdf weight_r weight_g weight_b family
  theta_i, phi  the sampled omega_i in degrees (phi = phi_r - phi_i, in (-180, 180])
  pdf           its density per unit solid angle (what `viewer probe --pdf` prints for it)
  weight_*      S cos(theta_i) / pdf, per RGB channel
  family        the lobe family it was drawn from: R, TT, TRT or scattered
Numbers print with enough digits to round-trip f32.

Draw k (from 0) takes the uniform numbers 3k, 3k+1 and 3k+2 of
bcsdf_core::rng::Pcg32::new(SEED, 0).uniform(): the same seed gives the same output. A draw
that finds nothing to sample (zero albedo) prints no line; if any did, a note on stderr at
the end says how many.

Examples:
  viewer sample --preset human-hair --theta-r -20 -n 1000
  viewer sample --preset bobcat --theta-r 30 -n 100000 --seed 7 > row-a-samples.txt
  viewer sample --preset red-fox --set kappa=0.4 --profile-seed 2 --theta-r 0 -n 10
  viewer sample --lut luts/bobcat.exr --theta-r 30 -n 100000

Bad input (N = 0, theta_r not finite or not inside (-90, 90), unknown preset or key, missing
or corrupt LUT) prints one line starting with `error:` on stderr and exits with code 2.";

/// `viewer sample` arguments.
#[derive(Debug, Args)]
pub struct SampleArgs {
    #[command(flatten)]
    pub model: ModelArgs,

    /// Longitudinal angle of the view direction, degrees inside (-90, 90).
    #[arg(long, value_name = "DEG", allow_negative_numbers = true)]
    pub theta_r: f32,

    /// Number of draws (at least 1).
    #[arg(short = 'n', value_name = "N")]
    pub count: u64,

    /// Seed of the uniform numbers the draws use (the same seed gives the same output).
    #[arg(long = "seed", value_name = "S", default_value_t = 1)]
    pub sampling_seed: u64,

    /// The profiles' options (`--seed` renamed `--profile-seed`, see [`Command::Sample`]).
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
