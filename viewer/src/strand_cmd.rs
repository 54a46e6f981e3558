//! `viewer render --colour R,G,B [--tip-colour R,G,B] [--colour-jitter P]
//! [--colour-stripes R,G,B[:WIDTH]]`, `viewer render --colour-texture FILE.png`: a colour per
//! strand (docs/model.md §14, "Per-strand colour", "Stripes and textures"), from root to tip
//! with a per-strand variation, the root's colour one for all, striped or from an image by
//! where the root is on the body; each hit's base colour turned into σ_ca through the coat
//! colour table measured from the LUT and the LUT read at that σ_ca
//! ([`render::strand::Coloured`], [`render::pattern::Patterned`]).

use crate::cli::{Method as MethodArg, RenderArgs};
use crate::error::Error;
use bcsdf_core::baked::BakedBcsdf;
use bcsdf_core::colour::{CoatColour, CoatWalk};
use bcsdf_core::{Absorption, Rgb};
use render::pattern::{BodyColour, Patterned, RootColours, Texture};
use render::strand::{Coloured, StrandColour};
use render::{integrator, Method, Render, SceneKind, Settings};
use std::io::{self, Write};

/// The colours `viewer render` was asked for, checked.
#[derive(Clone, Debug, PartialEq)]
pub struct StrandRequest {
    /// The root colour of every strand (`--colour`), or `None` with a texture.
    pub root: Option<Rgb>,
    /// The tip colour (`--tip-colour`; `None`: each strand's root colour at its tip too).
    pub tip: Option<Rgb>,
    /// The per-strand variation as a fraction (`--colour-jitter` / 100).
    pub jitter: f32,
    /// The root colour by place on the body (`--colour-stripes`, `--colour-texture`).
    pub body: Option<BodyColour>,
}

/// The per-strand colour of `args`, or `None` without `--colour` and `--colour-texture`; bad
/// values, an unreadable image, and a render that cannot colour strands (the analytic
/// evaluator, `dual`, `--compare`), are bad input naming the flag.
pub fn request(args: &RenderArgs, baked: bool) -> Result<Option<StrandRequest>, Error> {
    if args.colour.is_none() && args.colour_texture.is_none() {
        for (flag, given) in [
            ("--tip-colour", args.tip_colour.is_some()),
            ("--colour-jitter", args.colour_jitter.is_some()),
        ] {
            if given {
                return Err(Error::input(format!(
                    "{flag} needs a strand colour: --colour R,G,B or --colour-texture FILE.png"
                )));
            }
        }
        return Ok(None);
    }
    let root = args
        .colour
        .as_deref()
        .map(|c| parse_colour("--colour", c))
        .transpose()?;
    let tip = args
        .tip_colour
        .as_deref()
        .map(|t| parse_colour("--tip-colour", t))
        .transpose()?;
    let percent = args.colour_jitter.unwrap_or(0.0);
    if !(0.0..=100.0).contains(&percent) {
        return Err(Error::input(format!(
            "--colour-jitter {percent}: the per-strand variation is a percentage from 0 to 100"
        )));
    }
    let body = match (&args.colour_stripes, &args.colour_texture, root) {
        (Some(text), _, Some(base)) => Some(parse_stripes(text, base)?),
        (_, Some(path), _) => {
            let bytes = std::fs::read(path)
                .map_err(|e| Error::input(format!("--colour-texture {}: {e}", path.display())))?;
            let texture = Texture::from_png(&bytes)
                .map_err(|e| Error::input(format!("--colour-texture {}: {e}", path.display())))?;
            Some(BodyColour::Texture(texture))
        }
        // clap: --colour-stripes requires --colour.
        _ => None,
    };
    if !baked {
        return Err(Error::input(
            "--colour, --tip-colour, --colour-jitter, --colour-stripes and --colour-texture \
             need the baked evaluator (the default; not --evaluator analytic): \
             a base colour becomes sigma_ca through the coat colour table measured from the \
             LUT. The analytic evaluator renders one colour, given as --set sigma_ca=R,G,B or \
             the melanin keys",
        ));
    }
    if args.compare || args.method == MethodArg::Dual {
        return Err(Error::input(
            "--colour and --colour-texture render with --method path or single: the \
             dual-scattering tables are read at one colour",
        ));
    }
    Ok(Some(StrandRequest {
        root,
        tip,
        jitter: percent / 100.0,
        body,
    }))
}

/// `R,G,B[:WIDTH]` of `--colour-stripes` over the base colour `base`.
fn parse_stripes(text: &str, base: Rgb) -> Result<BodyColour, Error> {
    const FLAG: &str = "--colour-stripes";
    let (colour, width) = match text.split_once(':') {
        Some((c, w)) => {
            let width = w.trim().parse::<f32>().map_err(|_| {
                Error::input(format!(
                    "{FLAG} {text}: expected R,G,B[:WIDTH] with WIDTH a number in (0, 1]"
                ))
            })?;
            (c, width)
        }
        None => (text, BodyColour::STRIPE_WIDTH),
    };
    let stripe = parse_colour(FLAG, colour)?;
    BodyColour::stripes(base, stripe, width)
        .map_err(|e| Error::input(format!("{FLAG} {text}: {e}")))
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

/// Renders `scene` (built as `kind`) with the LUT coloured per strand as `req` says
/// (`method` path or single). Measures the LUT's coat colour table first (1–7 s on one core)
/// and reports on stderr the σ_ca of the colours asked for, with the channels out of the
/// fur's reach (for a texture: how many fibers' root colours are).
pub fn render(
    scene: &render::scene::Scene,
    kind: SceneKind,
    lut: &BakedBcsdf<'_>,
    req: &StrandRequest,
    settings: &Settings,
    method: MethodArg,
) -> Result<Render, Error> {
    let coat = CoatColour::measure(lut, &CoatWalk::DEFAULT);
    let mut named: Vec<(&str, Rgb)> = Vec::new();
    if let Some(root) = req.root {
        named.push(("--colour", root));
    }
    if let Some(BodyColour::Stripes { stripe, .. }) = &req.body {
        named.push(("--colour-stripes", *stripe));
    }
    if let Some(tip) = req.tip {
        named.push(("--tip-colour", tip));
    }
    let mut err = io::stderr().lock();
    for (flag, c) in named {
        let found = Absorption::from_base_colour(c, &coat)
            .map_err(|e| Error::input(format!("{flag}: {e}")))?;
        let tag = if found.is_clamped() {
            "warning"
        } else {
            "note"
        };
        let _ = writeln!(err, "{tag}: {flag}: {found}");
    }
    let method = match method {
        MethodArg::Single => Method::Single,
        _ => Method::Path,
    };
    let r = match (&req.body, req.root) {
        (Some(body), _) => {
            let roots = RootColours::new(scene, kind, body);
            if let BodyColour::Texture(t) = body {
                let clamped = roots
                    .colours()
                    .iter()
                    .filter(|c| {
                        Absorption::from_base_colour(**c, &coat).is_ok_and(|b| b.is_clamped())
                    })
                    .count();
                let (w, h) = t.size();
                let _ = writeln!(
                    err,
                    "{}: --colour-texture: {w} x {h} texels; {clamped} of {} fibers' root \
                     colours out of this fur's reach [{:.4}, {:.4}] (clamped)",
                    if clamped > 0 { "warning" } else { "note" },
                    roots.colours().len(),
                    coat.darkest(),
                    coat.brightest()
                );
            }
            drop(err);
            let material = Patterned::new(lut, &coat, &roots, req.tip, req.jitter, settings.seed)
                .map_err(|e| Error::input(format!("--tip-colour: {e}")))?;
            integrator::render_method(scene, &material, settings, &method)
        }
        (None, Some(root)) => {
            drop(err);
            let colour =
                StrandColour::new(root, req.tip.unwrap_or(root), req.jitter, settings.seed)
                    .map_err(|e| Error::input(format!("--colour: {e}")))?;
            let material = Coloured {
                fur: lut,
                coat: &coat,
                colour,
            };
            integrator::render_method(scene, &material, settings, &method)
        }
        (None, None) => {
            return Err(Error::input(
                "a strand colour needs --colour R,G,B or --colour-texture FILE.png",
            ))
        }
    };
    r.map_err(|e| Error::input(e.to_string()))
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

    #[test]
    fn stripes_take_a_width_and_bad_ones_name_the_flag() {
        let base = Rgb::splat(0.4);
        assert_eq!(
            parse_stripes("0.05,0.04,0.03:0.25", base).unwrap(),
            BodyColour::stripes(base, Rgb([0.05, 0.04, 0.03]), 0.25).unwrap()
        );
        assert_eq!(
            parse_stripes("0.1", base).unwrap(),
            BodyColour::stripes(base, Rgb::splat(0.1), BodyColour::STRIPE_WIDTH).unwrap()
        );
        for bad in [
            "0.1:0",
            "0.1:1.5",
            "0.1:wide",
            "0.1:NaN",
            "2,0,0:0.1",
            "0.1,0.2:0.1",
        ] {
            let Error::Input(m) = parse_stripes(bad, base).unwrap_err() else {
                panic!("{bad}: not bad input");
            };
            assert!(m.starts_with("--colour-stripes"), "{m}");
        }
    }
}
