//! `viewer sample`: importance-sampled incident directions for one view angle, from the
//! analytic model of a preset or a baked LUT, through [`Bcsdf::sample`].

use crate::cli::SampleArgs;
use crate::error::Error;
use crate::json::write_number;
use crate::source::{Source, Target};
use bcsdf_core::rng::Pcg32;
use bcsdf_core::Bcsdf;
use std::io::{self, BufWriter, Write};

/// The [`Pcg32`] stream of the draws (documented in `viewer sample --help`, so that a draw
/// can be reproduced in-process).
pub const STREAM: u64 = 0;

/// The most draws `-n` accepts: 10⁹ lines are already about 80 GB of text.
const MAX_DRAWS: u64 = 1_000_000_000;

/// Bytes of one output line, about.
const LINE_BYTES: f64 = 80.0;

/// `viewer sample`: checks the arguments (before the model, which may take seconds), loads
/// the model, prints one line per successful draw and, if any draw failed, a note on stderr.
pub fn run(args: &SampleArgs) -> Result<(), Error> {
    let theta_r = check_theta_r(args.theta_r)?;
    if args.count == 0 {
        return Err(Error::input("-n 0: nothing to draw (N must be at least 1)"));
    }
    if args.count > MAX_DRAWS {
        return Err(Error::input(format!(
            "-n {}: more than {MAX_DRAWS} draws (about {:.0} GB of output lines)",
            args.count,
            args.count as f64 * LINE_BYTES / 1e9
        )));
    }
    let source = Source::load(&args.model, &args.profiles)?;
    let mut out = BufWriter::new(io::stdout().lock());
    let failed = match source.target()? {
        Target::Analytic(model) => draw(&model, theta_r, args.count, args.sampling_seed, &mut out),
        Target::Baked(baked, colour) => draw(
            &baked.at(&colour),
            theta_r,
            args.count,
            args.sampling_seed,
            &mut out,
        ),
    }?;
    out.flush()?;
    if failed > 0 {
        let _ = writeln!(
            io::stderr().lock(),
            "note: {failed} of {} draws failed (zero albedo)",
            args.count
        );
    }
    Ok(())
}

/// θ_r in radians from `--theta-r` degrees: finite and strictly inside (−90, 90) (along the
/// fiber, ω_r has no azimuth to sample around).
pub fn check_theta_r(degrees: f32) -> Result<f32, Error> {
    if !degrees.is_finite() {
        return Err(Error::input(format!(
            "theta_r = {degrees} is not a finite number of degrees"
        )));
    }
    if degrees.abs() >= 90.0 {
        return Err(Error::input(format!(
            "theta_r = {degrees} is outside (-90, 90) degrees (the view direction must not \
             be along the fiber)"
        )));
    }
    Ok(degrees.to_radians())
}

/// Draws `count` samples of `bcsdf` at `theta_r` (radians), draw k from the uniform numbers
/// 3k, 3k + 1, 3k + 2 of `Pcg32::new(seed, STREAM)`, and writes one line per sample:
/// `theta_i phi pdf weight_r weight_g weight_b family` (degrees, numbers that round-trip
/// f32). Returns how many draws gave no sample.
pub fn draw<B: Bcsdf, W: Write>(
    bcsdf: &B,
    theta_r: f32,
    count: u64,
    seed: u64,
    out: &mut W,
) -> io::Result<u64> {
    let mut rng = Pcg32::new(seed, STREAM);
    let mut failed = 0;
    for _ in 0..count {
        let u = [rng.uniform(), rng.uniform(), rng.uniform()];
        let Some(s) = bcsdf.sample(theta_r, u) else {
            failed += 1;
            continue;
        };
        let [r, g, b] = s.weight.0;
        let numbers = [
            s.angles.theta_i().to_degrees(),
            s.angles.phi().to_degrees(),
            s.pdf,
            r,
            g,
            b,
        ];
        for v in numbers {
            write_number(out, v)?;
            out.write_all(b" ")?;
        }
        out.write_all(s.family.name().as_bytes())?;
        out.write_all(b"\n")?;
    }
    Ok(failed)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn theta_r_must_be_finite_and_inside_90() {
        assert_eq!(check_theta_r(-20.0).unwrap(), (-20.0f32).to_radians());
        assert!(check_theta_r(89.9).is_ok());
        for bad in [90.0, -90.0, 91.0, f32::NAN, f32::INFINITY] {
            assert!(check_theta_r(bad).is_err(), "{bad}");
        }
    }
}
