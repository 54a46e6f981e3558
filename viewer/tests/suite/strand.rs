//! A colour per fiber from where its root is on the body (docs/model.md §14, "Stripes and
//! textures"): stripes and an image give each fiber the colour its root's place asks for
//! (known fibers of the patch and the ball), `viewer render --colour-stripes` and
//! `--colour-texture` render the same bits twice and, when the pattern is one colour, the
//! same bits as `--colour` of that colour; bad values and unreadable images exit 2 with one
//! `error:` line.

use bcsdf_core::Rgb;
use render::pattern::{srgb_decode, BodyColour, RootColours, Texture};
use render::scene::Scene;
use render::{scenes, SceneKind, SceneOptions};
use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::sync::OnceLock;

fn scene(kind: SceneKind, fibers: usize) -> Scene {
    scenes::build(&SceneOptions {
        kind,
        fibers: Some(fibers),
        seed: 3,
        aspect: 4.0 / 3.0,
    })
}

/// Each fiber's root (the start of its segment at v = 0), by fiber index.
fn roots(scene: &Scene) -> Vec<[f32; 3]> {
    let mut r = Vec::new();
    for s in scene.fibers.segments().iter().filter(|s| s.v0 == 0.0) {
        let (i, p) = (s.fiber as usize, [s.p0.x, s.p0.y, s.p0.z]);
        if r.len() <= i {
            r.resize(i + 1, p);
        }
        r[i] = p;
    }
    r
}

/// A PNG of `w` × `h` 8-bit sRGB texels, row by row from the top.
fn png(w: u32, h: u32, rgb: &[[u8; 3]]) -> Vec<u8> {
    let mut bytes = Vec::new();
    let mut e = png::Encoder::new(&mut bytes, w, h);
    e.set_color(png::ColorType::Rgb);
    e.set_depth(png::BitDepth::Eight);
    let mut writer = e.write_header().unwrap();
    writer
        .write_image_data(&rgb.iter().flatten().copied().collect::<Vec<u8>>())
        .unwrap();
    drop(writer);
    bytes
}

/// Stripes: on the patch, a fiber rooted at x is in band ⌊(x + 1)/2 / w⌋ and takes the
/// stripe colour in the odd bands; on the ball, by the longitude of its root seen from the
/// ball's centre (0, 1.3, 0), ½ facing the camera (+z). Checked at the fibers whose root is
/// away from a band's edge (a hundredth of a band), and both colours are met.
#[test]
fn stripes_give_known_fibers_their_band_colour() {
    let (base, stripe) = (Rgb([0.6, 0.4, 0.2]), Rgb([0.05, 0.04, 0.03]));
    let width = 0.125;
    let body = BodyColour::stripes(base, stripe, width).unwrap();
    for kind in [SceneKind::Patch, SceneKind::Ball] {
        let s = scene(kind, 2000);
        let colours = RootColours::new(&s, kind, &body);
        let (mut in_stripe, mut in_base) = (0, 0);
        for (fiber, p) in roots(&s).iter().enumerate() {
            let u = match kind {
                SceneKind::Patch => (p[0] + 1.0) / 2.0,
                // atan2 needs no normalising: the longitude of (x, y − 1.3, z).
                _ => 0.5 + p[0].atan2(p[2]) / (2.0 * std::f32::consts::PI),
            };
            let band = u / width;
            if (band - band.round()).abs() < 0.01 {
                continue;
            }
            let want = if band.floor() as i64 % 2 == 1 {
                in_stripe += 1;
                stripe
            } else {
                in_base += 1;
                base
            };
            assert_eq!(
                colours.colour(fiber as u32),
                want,
                "{kind}: fiber {fiber} at {p:?}, u {u}"
            );
        }
        println!("{kind}: {in_stripe} fibers in the stripes, {in_base} between");
        assert!(in_stripe > 500 && in_base > 500, "{in_stripe} {in_base}");
    }
}

/// An image: a 2 × 2 PNG (sRGB 8 bit) on the patch, the root at (x, z) reading texture
/// coordinates ((x + 1)/2, (z + 1)/2) bilinearly between the texel centres, each texel
/// sRGB-decoded; the ball's top (colatitude 0) reads the top row.
#[test]
fn a_texture_gives_known_fibers_the_colour_at_their_root() {
    let texels = [[255, 0, 0], [0, 0, 255], [0, 255, 0], [188, 188, 188]];
    let texture = Texture::from_png(&png(2, 2, &texels)).unwrap();
    let linear: Vec<Rgb> = texels
        .iter()
        .map(|t| Rgb(t.map(|v| srgb_decode(f32::from(v) / 255.0))))
        .collect();
    // 188/255 in sRGB is about 0.5 linear.
    assert!((linear[3][0] - 0.5029).abs() < 1e-3, "{:?}", linear[3]);
    let body = BodyColour::Texture(texture);
    let s = scene(SceneKind::Patch, 500);
    let colours = RootColours::new(&s, SceneKind::Patch, &body);
    let lerp = |a: Rgb, b: Rgb, t: f32| Rgb(std::array::from_fn(|c| a[c] + (b[c] - a[c]) * t));
    for (fiber, p) in roots(&s).iter().enumerate() {
        let (u, v) = ((p[0] + 1.0) / 2.0, (p[2] + 1.0) / 2.0);
        let want = lerp(
            lerp(linear[0], linear[1], u),
            lerp(linear[2], linear[3], u),
            v,
        );
        let got = colours.colour(fiber as u32);
        for c in 0..3 {
            assert!(
                (got[c] - want[c]).abs() < 1e-5,
                "fiber {fiber} at {p:?}: {got:?}, want {want:?}"
            );
        }
    }
    // On the ball: the fiber whose root is nearest the top pole (colatitude about 0.05 rad of
    // 2000) reads the top row, red to blue by its longitude: almost no green, R + B near 1.
    let ball = scene(SceneKind::Ball, 2000);
    let colours = RootColours::new(&ball, SceneKind::Ball, &body);
    let (top, _) = roots(&ball)
        .iter()
        .enumerate()
        .max_by(|a, b| a.1[1].total_cmp(&b.1[1]))
        .unwrap();
    let got = colours.colour(top as u32);
    assert!(got[1] < 0.03 && got[0] + got[2] > 0.95, "{got:?}");
}

fn viewer(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_viewer"))
        .args(args)
        .env_remove("FUR_BCSDF_CACHE")
        .output()
        .expect("viewer runs")
}

/// A folder for this test binary's files (removed at exit).
fn dir() -> &'static Path {
    static DIR: OnceLock<tempfile::TempDir> = OnceLock::new();
    DIR.get_or_init(|| {
        tempfile::Builder::new()
            .prefix("viewer-strand-")
            .tempdir_in(env!("CARGO_TARGET_TMPDIR"))
            .unwrap()
    })
    .path()
}

/// Human hair baked at the default resolution (no medulla: no profiles to simulate).
fn lut() -> &'static Path {
    static LUT: OnceLock<PathBuf> = OnceLock::new();
    LUT.get_or_init(|| {
        use bcsdf_core::{lut::LutResolution, presets, FurParams};
        let preset = presets::find("human-hair").unwrap();
        let params = FurParams::new(&preset.input).unwrap();
        let (model, _) =
            bake::profiles::build_model(params, &bake::profiles::ProfileOptions::default())
                .unwrap();
        let path = dir().join("human-hair.furlut");
        std::fs::write(
            &path,
            bake::tables::bake(&model, &preset.input, LutResolution::DEFAULT),
        )
        .unwrap();
        path
    })
}

/// Renders the small patch with the LUT and `extra` into `dir()/name`; the EXR's bytes.
fn render(name: &str, extra: &[&str]) -> Vec<u8> {
    let out = dir().join(name);
    let mut args = vec!["render", "--lut", lut().to_str().unwrap()];
    args.extend_from_slice(&[
        "--scene",
        "patch",
        "--fibers",
        "300",
        "--spp",
        "2",
        "--width",
        "24",
        "--height",
        "16",
        "--max-depth",
        "4",
        "--threads",
        "2",
        "--out",
    ]);
    args.push(out.to_str().unwrap());
    args.extend_from_slice(extra);
    let o = viewer(&args);
    assert!(
        o.status.success(),
        "{extra:?}: {}",
        String::from_utf8_lossy(&o.stderr)
    );
    std::fs::read(out.join("render.exr")).unwrap()
}

/// The same bits twice; a one-colour pattern (stripes of --colour itself, an image of one
/// texel) the same bits as --colour of that colour; real stripes and a real image change the
/// picture.
#[test]
fn strand_patterns_render_deterministically_and_one_colour_is_colour() {
    let grey_png = dir().join("grey.png");
    std::fs::write(&grey_png, png(1, 1, &[[120, 90, 60]])).unwrap();
    let linear = [120u8, 90, 60].map(|v| srgb_decode(f32::from(v) / 255.0));
    // `{:?}` prints the shortest decimal that parses back to the same f32.
    let colour = format!("{:?},{:?},{:?}", linear[0], linear[1], linear[2]);
    let plain = render("plain", &["--colour", colour.as_str()]);
    let texture = grey_png.to_str().unwrap();
    assert!(
        render("one-texel", &["--colour-texture", texture]) == plain,
        "an image of one colour must render as --colour of that colour"
    );
    let same = format!("{colour}:0.2");
    assert!(
        render(
            "same-stripes",
            &[
                "--colour",
                colour.as_str(),
                "--colour-stripes",
                same.as_str()
            ]
        ) == plain,
        "stripes of the base colour must render as --colour"
    );
    let stripes = [
        "--colour",
        colour.as_str(),
        "--colour-stripes",
        "0.02,0.02,0.02:0.2",
    ];
    let a = render("stripes-a", &stripes);
    assert!(
        a == render("stripes-b", &stripes),
        "stripes: not the same bits twice"
    );
    assert!(a != plain, "dark stripes changed nothing");
    let four = dir().join("four.png");
    std::fs::write(
        &four,
        png(
            2,
            2,
            &[[250, 240, 230], [20, 10, 5], [200, 40, 10], [10, 40, 200]],
        ),
    )
    .unwrap();
    let textured = [
        "--colour-texture",
        four.to_str().unwrap(),
        "--colour-jitter",
        "20",
    ];
    let t = render("texture-a", &textured);
    assert!(
        t == render("texture-b", &textured),
        "texture: not the same bits twice"
    );
    assert!(t != plain);
}

/// Bad stripes, a missing or unreadable image, a pattern without a LUT, a tip colour with no
/// colour: exit 2, one `error:` line naming the flag, nothing rendered.
#[test]
fn bad_strand_patterns_exit_2_with_one_error_line() {
    let not_png = dir().join("not.png");
    std::fs::write(&not_png, b"GIF89a: not a PNG").unwrap();
    let out = dir().join("bad");
    let out = out.to_str().unwrap();
    let lut = lut().to_str().unwrap();
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (
            vec!["--lut", lut, "--colour", "0.3", "--colour-stripes", "0.1:0"],
            "--colour-stripes",
        ),
        (
            vec!["--lut", lut, "--colour", "0.3", "--colour-stripes", "0.1:2"],
            "(0, 1]",
        ),
        (
            vec![
                "--lut",
                lut,
                "--colour",
                "0.3",
                "--colour-stripes",
                "1.2,0,0",
            ],
            "--colour-stripes",
        ),
        (
            vec!["--lut", lut, "--colour", "0.3", "--colour-stripes", "0.1:x"],
            "--colour-stripes",
        ),
        (
            vec!["--lut", lut, "--colour-texture", "missing.png"],
            "missing.png",
        ),
        (
            vec!["--lut", lut, "--colour-texture", not_png.to_str().unwrap()],
            "not a readable PNG",
        ),
        (
            vec!["--lut", lut, "--tip-colour", "0.5"],
            "--tip-colour needs",
        ),
        (
            vec![
                "--preset",
                "human-hair",
                "--evaluator",
                "analytic",
                "--colour",
                "0.3",
                "--colour-stripes",
                "0.1",
            ],
            "need the baked evaluator",
        ),
    ];
    for (extra, needle) in cases {
        let mut args = vec!["render", "--scene", "patch", "--spp", "1", "--out", out];
        args.extend(extra);
        let o = viewer(&args);
        crate::assert_refused(&o, &args, &[needle]);
    }
    assert!(!Path::new(out).join("render.exr").exists());
}
