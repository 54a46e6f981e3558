//! `viewer render --colour R,G,B [--tip-colour R,G,B] [--colour-jitter P]`: a colour per
//! strand (docs/model.md §14, "Per-strand colour"), from root to tip with a per-strand
//! variation, each hit's base colour turned into σ_ca through the coat colour table measured
//! from the LUT and the LUT read at that σ_ca ([`render::strand::Coloured`]).

use crate::cli::{Method as MethodArg, RenderArgs};
use crate::error::Error;
use bcsdf_core::baked::BakedBcsdf;
use bcsdf_core::colour::{CoatColour, CoatWalk};
use bcsdf_core::{Absorption, Rgb};
use render::strand::{Coloured, StrandColour};
use render::{integrator, Method, Render, Settings};
use std::io::{self, Write};

/// The colours `viewer render` was asked for, checked.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StrandRequest {
    /// The root colour (`--colour`).
    pub root: Rgb,
    /// The tip colour (`--tip-colour`; the root's without it).
    pub tip: Rgb,
    /// The per-strand variation as a fraction (`--colour-jitter` / 100).
    pub jitter: f32,
}

/// The per-strand colour of `args`, or `None` without `--colour`; bad values, and a render
/// that cannot colour strands (the analytic evaluator, `dual`, `--compare`), are bad input
/// naming the flag.
pub fn request(args: &RenderArgs, baked: bool) -> Result<Option<StrandRequest>, Error> {
    let Some(root) = &args.colour else {
        return Ok(None);
    };
    let root = parse_colour("--colour", root)?;
    let tip = match &args.tip_colour {
        Some(t) => parse_colour("--tip-colour", t)?,
        None => root,
    };
    let percent = args.colour_jitter.unwrap_or(0.0);
    if !(0.0..=100.0).contains(&percent) {
        return Err(Error::input(format!(
            "--colour-jitter {percent}: the per-strand variation is a percentage from 0 to 100"
        )));
    }
    if !baked {
        return Err(Error::input(
            "--colour, --tip-colour and --colour-jitter need a baked LUT (--lut FILE, or \
             --evaluator baked to bake the preset in memory): a base colour becomes sigma_ca \
             through the coat colour table measured from the LUT. The analytic evaluator \
             renders one colour, given as --set sigma_ca=R,G,B or the melanin keys",
        ));
    }
    if args.compare || args.method == MethodArg::Dual {
        return Err(Error::input(
            "--colour renders with --method path or single: the dual-scattering tables are \
             read at one colour",
        ));
    }
    Ok(Some(StrandRequest {
        root,
        tip,
        jitter: percent / 100.0,
    }))
}

/// `R,G,B` (or one grey), each a number in [0, 1].
fn parse_colour(flag: &str, text: &str) -> Result<Rgb, Error> {
    let parts: Vec<&str> = text.split(',').map(str::trim).collect();
    let values: Vec<f32> = parts
        .iter()
        .map(|p| p.parse::<f32>())
        .collect::<Result<_, _>>()
        .map_err(|_| {
            Error::input(format!(
                "{flag} {text}: expected a linear colour R,G,B (or one grey), numbers in [0, 1]"
            ))
        })?;
    let rgb = match values[..] {
        [g] => Rgb::splat(g),
        [r, g, b] => Rgb([r, g, b]),
        _ => {
            return Err(Error::input(format!(
                "{flag} {text}: expected 3 channels R,G,B (or one grey), got {}",
                values.len()
            )))
        }
    };
    for (k, v) in rgb.0.iter().enumerate() {
        if !(0.0..=1.0).contains(v) {
            return Err(Error::input(format!(
                "{flag} {text}: channel {} = {v} must be in [0, 1] (a linear colour)",
                ["R", "G", "B"][k]
            )));
        }
    }
    Ok(rgb)
}

/// Renders `scene` with the LUT coloured per strand as `req` says (`method` path or single).
/// Measures the LUT's coat colour table first (1–7 s on one core) and reports on stderr the
/// σ_ca of the root and tip colours, with the channels out of the fur's reach.
pub fn render(
    scene: &render::scene::Scene,
    lut: &BakedBcsdf<'_>,
    req: &StrandRequest,
    settings: &Settings,
    method: MethodArg,
) -> Result<Render, Error> {
    let coat = CoatColour::measure(lut, &CoatWalk::DEFAULT);
    let mut err = io::stderr().lock();
    for (flag, c) in [("--colour", req.root), ("--tip-colour", req.tip)] {
        let found = Absorption::from_base_colour(c, &coat)
            .map_err(|e| Error::input(format!("{flag}: {e}")))?;
        let tag = if found.is_clamped() {
            "warning"
        } else {
            "note"
        };
        let _ = writeln!(err, "{tag}: {flag}: {found}");
    }
    drop(err);
    let colour = StrandColour::new(req.root, req.tip, req.jitter, settings.seed)
        .map_err(|e| Error::input(format!("--colour: {e}")))?;
    let material = Coloured {
        fur: lut,
        coat: &coat,
        colour,
    };
    let method = match method {
        MethodArg::Single => Method::Single,
        _ => Method::Path,
    };
    integrator::render_method(scene, &material, settings, &method)
        .map_err(|e| Error::input(e.to_string()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn colours_are_parsed_and_bad_ones_name_the_flag() {
        assert_eq!(
            parse_colour("--colour", "0.3, 0.15,0.07").unwrap(),
            Rgb([0.3, 0.15, 0.07])
        );
        assert_eq!(parse_colour("--colour", "0.18").unwrap(), Rgb::splat(0.18));
        for bad in ["1.2,0,0", "0,-0.1,0", "NaN", "0.1,0.2", "red", "0,0,inf"] {
            let Error::Input(m) = parse_colour("--tip-colour", bad).unwrap_err() else {
                panic!("{bad}: not bad input");
            };
            assert!(m.starts_with("--tip-colour"), "{m}");
        }
    }
}
