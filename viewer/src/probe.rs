//! `viewer probe`: one query from the flags, or many from stdin, answered by the analytic
//! model of a preset or by a baked LUT (`--lut`), optionally with the sampling pdf.

use crate::cli::ProbeArgs;
use crate::error::Error;
use crate::json::{write_families, write_lobes};
use crate::source::{Source, Target};
use bcsdf_core::{Angles, Bcsdf};
use std::io::{self, BufRead, BufWriter, Write};

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

    /// Why `target` cannot answer this query, if it cannot: the near field (h) needs the
    /// analytic model and has no pdf.
    pub fn unsupported(&self, target: &Target<'_>, pdf: bool) -> Option<String> {
        let h = self.h?;
        match target {
            Target::Baked(..) => Some(format!(
                "h = {h} asks for the near field, but a LUT holds the far field only \
                 (expected `theta_i theta_r phi`)"
            )),
            Target::Analytic(_) if pdf => Some(format!(
                "h = {h} asks for the near field, but --pdf is a far-field density \
                 (expected `theta_i theta_r phi`)"
            )),
            Target::Analytic(_) => None,
        }
    }

    /// Writes the JSON line answering the query, with the pdf if `pdf`: the analytic model
    /// per lobe (near field at h if given, else far field), a LUT per lobe family. The
    /// caller has checked [`Query::unsupported`].
    pub fn answer<W: Write>(&self, target: &Target<'_>, pdf: bool, out: &mut W) -> io::Result<()> {
        let a = &self.angles;
        match (target, self.h) {
            (Target::Analytic(model), Some(h)) => write_lobes(out, &model.eval_near(a, h), None),
            (Target::Analytic(model), None) => {
                let density = pdf.then(|| Bcsdf::pdf(model, a));
                write_lobes(out, &model.eval_far_lobes(a), density)
            }
            (Target::Baked(baked, colour), _) => {
                let at = baked.at(colour);
                let density = pdf.then(|| Bcsdf::pdf(&at, a));
                write_families(out, &Bcsdf::eval(&at, a), density)
            }
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

/// `viewer probe`.
pub fn run(args: &ProbeArgs) -> Result<(), Error> {
    let source = Source::load(&args.model, &args.profiles)?;
    if args.gpu {
        return run_gpu(args, &source);
    }
    let target = source.target()?;
    let mut out = BufWriter::new(io::stdout().lock());
    if args.stdin {
        return run_stdin(&target, args.pdf, &mut io::stdin().lock(), &mut out);
    }
    // clap guarantees all three angles without --stdin.
    let (Some(ti), Some(tr), Some(phi)) = (args.theta_i, args.theta_r, args.phi) else {
        return Err(Error::input("--theta-i, --theta-r and --phi are required"));
    };
    let query = Query::new(ti, tr, phi, args.h).map_err(Error::input)?;
    // clap rejects --h with --lut or --pdf; this is the same rule.
    if let Some(message) = query.unsupported(&target, args.pdf) {
        return Err(Error::input(message));
    }
    query.answer(&target, args.pdf, &mut out)?;
    out.flush()?;
    Ok(())
}

/// Answers every query line of `input` in order (with the pdf if `pdf`); stops at the first
/// malformed line, or one `target` cannot answer, with `line N: …` after flushing the
/// answers so far.
pub fn run_stdin<R: BufRead, W: Write>(
    target: &Target<'_>,
    pdf: bool,
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
            .and_then(parse_line)
            .and_then(|query| match query {
                Some(q) => q.unsupported(target, pdf).map_or(Ok(Some(q)), Err),
                None => Ok(None),
            });
        match parsed {
            Ok(Some(query)) => query.answer(target, pdf, out)?,
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

/// `viewer probe --lut FILE --gpu`: the same queries and output, evaluated by the WGSL shader
/// on the first adapter, in one dispatch per run (per malformed-line stop with --stdin).
fn run_gpu(args: &ProbeArgs, source: &Source) -> Result<(), Error> {
    let Source::Baked { blob, .. } = source else {
        return Err(Error::input("--gpu needs --lut FILE"));
    };
    let gpu = bcsdf_gpu::GpuLut::new(blob).map_err(|e| Error::input(format!("--gpu: {e}")))?;
    let mut out = BufWriter::new(io::stdout().lock());
    let mut queries = Vec::new();
    let mut failure = None;
    if args.stdin {
        let mut line_no = 0usize;
        for line in io::stdin().lock().split(b'\n') {
            line_no += 1;
            let parsed = std::str::from_utf8(&line?)
                .map_err(|_| "not valid UTF-8".to_string())
                .and_then(parse_line);
            match parsed {
                Ok(Some(q)) if q.h.is_some() => {
                    failure = Some(format!(
                        "line {line_no}: h = {} asks for the near field, but a LUT holds the far field only (expected `theta_i theta_r phi`)",
                        q.h.unwrap_or(0.0)
                    ));
                    break;
                }
                Ok(Some(q)) => queries.push(q),
                Ok(None) => {}
                Err(message) => {
                    failure = Some(format!("line {line_no}: {message}"));
                    break;
                }
            }
        }
    } else {
        let (Some(ti), Some(tr), Some(phi)) = (args.theta_i, args.theta_r, args.phi) else {
            return Err(Error::input("--theta-i, --theta-r and --phi are required"));
        };
        queries.push(Query::new(ti, tr, phi, None).map_err(Error::input)?);
    }
    let angles: Vec<[f32; 3]> = queries
        .iter()
        .map(|q| [q.angles.theta_i(), q.angles.theta_r(), q.angles.phi()])
        .collect();
    let gpu_error = |e: bcsdf_gpu::GpuError| Error::Failure(format!("--gpu: {e}"));
    let values = gpu.eval(&angles).map_err(gpu_error)?;
    let pdfs = if args.pdf {
        Some(gpu.pdf(&angles).map_err(gpu_error)?)
    } else {
        None
    };
    for (k, v) in values.iter().enumerate() {
        let families = bcsdf_gpu::families(v);
        write_families(&mut out, &families, pdfs.as_ref().map(|p| p[k]))?;
    }
    out.flush()?;
    match failure {
        Some(message) => Err(Error::input(message)),
        None => Ok(()),
    }
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
