//! `viewer probe`: one query from the flags, or many from stdin.

use crate::catalog;
use crate::cli::{ProbeArgs, ProfileArgs};
use crate::error::Error;
use crate::json::write_lobes;
use bake::profiles::{self, CacheOutcome, OwnedModel, ProfileKey, ProfileOptions};
use bcsdf_core::{Angles, FurBcsdf, FurParams, Lobes, PhotonBudget, ProfileLayout, Resolution};
use std::io::{self, BufRead, BufWriter, IsTerminal, Write};

/// One validated query: the angles and, for the near field, the offset h.
#[derive(Clone, Copy, Debug)]
pub struct Query {
    angles: Angles,
    h: Option<f32>,
}

impl Query {
    /// Checks degrees and h: θ within [-90, 90], every value finite, h within [-1, 1].
    pub fn new(theta_i: f32, theta_r: f32, phi: f32, h: Option<f32>) -> Result<Query, String> {
        for (name, v) in [("theta_i", theta_i), ("theta_r", theta_r), ("phi", phi)] {
            if !v.is_finite() {
                return Err(format!("{name} = {v} is not a finite number of degrees"));
            }
        }
        for (name, v) in [("theta_i", theta_i), ("theta_r", theta_r)] {
            if v.abs() > 90.0 {
                return Err(format!("{name} = {v} is outside [-90, 90] degrees"));
            }
        }
        if let Some(h) = h {
            if !(-1.0..=1.0).contains(&h) {
                return Err(format!(
                    "h = {h} is outside [-1, 1] (offset of the view ray in fiber radii)"
                ));
            }
        }
        let angles = Angles::from_degrees(theta_i, theta_r, phi).map_err(|e| e.to_string())?;
        Ok(Query { angles, h })
    }

    /// Evaluates the model: near field at h if given, else far field.
    pub fn eval(&self, model: &FurBcsdf) -> Lobes {
        match self.h {
            Some(h) => model.eval_near(&self.angles, h),
            None => model.eval_far_lobes(&self.angles),
        }
    }
}

/// Parses one stdin line; `Ok(None)` for a blank or comment line.
pub fn parse_line(line: &str) -> Result<Option<Query>, String> {
    let line = line.trim();
    if line.is_empty() || line.starts_with('#') {
        return Ok(None);
    }
    let mut values = [0.0f32; 4];
    let mut count = 0;
    for field in line.split_ascii_whitespace() {
        if count == values.len() {
            count += 1;
            break;
        }
        values[count] = field.parse().map_err(|_| {
            format!("`{field}` is not a number (expected `theta_i theta_r phi [h]`)")
        })?;
        count += 1;
    }
    if !(3..=4).contains(&count) {
        let found = line.split_ascii_whitespace().count();
        return Err(format!(
            "expected 3 or 4 numbers `theta_i theta_r phi [h]`, found {found} fields"
        ));
    }
    let h = (count == 4).then_some(values[3]);
    Query::new(values[0], values[1], values[2], h).map(Some)
}

/// The profile options `args` select: the cache directory (`--cache-dir`, else the default
/// one, none with `--no-cache`), the seed, the scaled photon budget and the thread count.
pub fn profile_options(args: &ProfileArgs) -> Result<ProfileOptions, Error> {
    let budget =
        profiles::scale_budget(PhotonBudget::DEFAULT, args.photons_scale).ok_or_else(|| {
            Error::input(format!(
                "--photons-scale {} must be a positive finite number",
                args.photons_scale
            ))
        })?;
    let cache_dir = if args.no_cache {
        None
    } else {
        args.cache_dir.clone().or_else(profiles::default_cache_dir)
    };
    Ok(ProfileOptions {
        res: Resolution::DEFAULT,
        budget,
        seed: args.seed,
        cache_dir,
        threads: args.threads,
    })
}

/// The model for the chosen preset with the `--set` overrides applied: the full model, its
/// medulla profiles from the cache or generated. A rejected (stale or corrupt) cache file is
/// reported as one `note:` line on stderr.
fn model(args: &ProbeArgs) -> Result<OwnedModel, Error> {
    let list = catalog::load(&args.presets)?;
    let preset = catalog::find(&list, &args.preset)?;
    let mut input = preset.input;
    bake::apply_overrides(&mut input, &args.set).map_err(|e| Error::input(format!("--set {e}")))?;
    let params = FurParams::new(&input)
        .map_err(|e| Error::input(format!("preset `{}` with the overrides: {e}", preset.name)))?;
    let mut opts = profile_options(&args.profiles)?;
    announce_generation(&params, &opts);
    let (model, outcome) = match profiles::build_model(params, &opts) {
        // The default cache directory is a convenience: when it cannot be used, say so and
        // go on without a cache. A directory the user named is an error.
        Err(e @ profiles::Error::CacheDir { .. }) if args.profiles.cache_dir.is_none() => {
            let _ = writeln!(io::stderr().lock(), "note: {e}; continuing without a cache");
            opts.cache_dir = None;
            profiles::build_model(params, &opts).map_err(|e| Error::Failure(e.to_string()))?
        }
        result => result.map_err(|e| Error::Failure(e.to_string()))?,
    };
    if let Some(note) = outcome.as_ref().and_then(CacheOutcome::note) {
        let _ = writeln!(io::stderr().lock(), "note: {note}");
    }
    Ok(model)
}

/// On a terminal, says that the profiles are about to be generated (it takes seconds) when
/// the parameters need them and the cache holds no file for them. Pipes and scripts get
/// nothing: stderr stays quiet unless a cache file is rejected.
fn announce_generation(params: &FurParams, opts: &ProfileOptions) {
    if !profiles::needs_profiles(params) || !io::stderr().is_terminal() {
        return;
    }
    let key = ProfileKey {
        layout: ProfileLayout::for_params(params, opts.res),
        budget: opts.budget,
        seed: opts.seed,
    };
    let where_to = match &opts.cache_dir {
        Some(dir) if dir.join(key.file_name()).is_file() => return,
        Some(dir) => format!("cached in {}", dir.display()),
        None => "not cached".to_string(),
    };
    let _ = writeln!(
        io::stderr().lock(),
        "note: generating the medulla profiles for these parameters ({where_to})"
    );
}

/// `viewer probe`.
pub fn run(args: &ProbeArgs) -> Result<(), Error> {
    let owned = model(args)?;
    let model = owned.model();
    let mut out = BufWriter::new(io::stdout().lock());
    if args.stdin {
        return run_stdin(&model, &mut io::stdin().lock(), &mut out);
    }
    // clap guarantees all three angles without --stdin.
    let (Some(ti), Some(tr), Some(phi)) = (args.theta_i, args.theta_r, args.phi) else {
        return Err(Error::input("--theta-i, --theta-r and --phi are required"));
    };
    let query = Query::new(ti, tr, phi, args.h).map_err(Error::input)?;
    write_lobes(&mut out, &query.eval(&model))?;
    out.flush()?;
    Ok(())
}

/// Answers every query line of `input` in order; stops at the first malformed line with
/// `line N: …` after flushing the answers so far.
pub fn run_stdin<R: BufRead, W: Write>(
    model: &FurBcsdf,
    input: &mut R,
    out: &mut W,
) -> Result<(), Error> {
    let mut buf = Vec::new();
    let mut line_no = 0usize;
    loop {
        buf.clear();
        if input.read_until(b'\n', &mut buf)? == 0 {
            break;
        }
        line_no += 1;
        let parsed = std::str::from_utf8(&buf)
            .map_err(|_| "not valid UTF-8".to_string())
            .and_then(parse_line);
        match parsed {
            Ok(Some(query)) => write_lobes(out, &query.eval(model))?,
            Ok(None) => {}
            Err(message) => {
                out.flush()?;
                return Err(Error::input(format!("line {line_no}: {message}")));
            }
        }
    }
    out.flush()?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lines() {
        assert!(parse_line("").unwrap().is_none());
        assert!(parse_line("   # comment").unwrap().is_none());
        assert!(parse_line("30 -20 45").unwrap().unwrap().h.is_none());
        assert_eq!(
            parse_line("30\t-20 45  0.5\r\n").unwrap().unwrap().h,
            Some(0.5)
        );
        assert!(parse_line("30 -20").unwrap_err().contains("found 2"));
        assert!(parse_line("30 -20 45 0.5 1")
            .unwrap_err()
            .contains("found 5"));
        assert!(parse_line("30 x 45").unwrap_err().contains("`x`"));
        assert!(parse_line("95 0 0").unwrap_err().contains("theta_i = 95"));
        assert!(parse_line("0 0 0 1.5").unwrap_err().contains("h = 1.5"));
        assert!(parse_line("0 nan 0").unwrap_err().contains("theta_r"));
    }
}
