//! Per-strand colour (docs/model.md §14, "Per-strand colour"): the colour varies along the
//! strand in the requested direction, no variation is the same bits as one colour, and a
//! per-strand variation changes the image the same way on any thread count.

use bcsdf_core::colour::{coat_node, CoatColour};
use bcsdf_core::{presets, Absorption, FurBcsdf, FurParams, Rgb};
use render::scatter::One;
use render::scene::{HitKind, Scene};
use render::strand::{AnalyticColours, Coloured, FiberMaterial, StrandColour};
use render::{integrator, output, scenes, Image, SceneKind, SceneOptions, Settings};

const SEED: u64 = 5;
const W: u32 = 128;
const H: u32 = 96;

fn scene() -> Scene {
    scenes::build(&SceneOptions {
        kind: SceneKind::Patch,
        fibers: Some(1500),
        seed: SEED,
        aspect: W as f32 / H as f32,
    })
}

/// A made-up coat colour table, c(σ) = 0.02 + 0.9/(1 + 4σ): the test is about the renderer's
/// wiring, not about a preset's coat (docs/accuracy.md "Base colour" measures those).
fn coat() -> CoatColour {
    CoatColour::from_colours(core::array::from_fn(|k| {
        0.02 + 0.9 / (1.0 + 4.0 * coat_node(k))
    }))
    .unwrap()
}

/// Unscattered human hair (no residual table: readable at any colour).
fn hair() -> FurBcsdf<'static> {
    FurBcsdf::unscattered(FurParams::new(&presets::find("human-hair").unwrap().input).unwrap())
}

fn image<M: FiberMaterial>(scene: &Scene, material: &M, threads: usize) -> Image {
    image_to_depth(scene, material, threads, 8)
}

fn image_to_depth<M: FiberMaterial>(
    scene: &Scene,
    material: &M,
    threads: usize,
    max_depth: u32,
) -> Image {
    let settings = Settings {
        threads: Some(threads),
        seed: SEED,
        max_depth,
        ..Settings::new(W, H, 4)
    };
    integrator::render(scene, material, &settings)
        .unwrap()
        .image
}

/// Mean R − B and mean (R + B)/2 of the pixels that show one part of the strands: at least 4 of a 4 × 4 grid of
/// camera rays through the pixel meet a fiber first, every one of them at a position `v`
/// along its strand with `keep(v)` (a pixel is wider than a fiber: most show several); and
/// how many pixels there are.
fn red_minus_blue(scene: &Scene, img: &Image, keep: impl Fn(f32) -> bool) -> (f64, f64, usize) {
    let (mut r, mut b, mut n) = (0.0f64, 0.0f64, 0);
    for y in 0..H {
        for x in 0..W {
            let (mut fiber, mut kept) = (0, 0);
            for k in 0..16 {
                let (dx, dy) = ((k % 4) as f32 + 0.5, (k / 4) as f32 + 0.5);
                let (o, d) = scene
                    .camera
                    .ray(x as f32 + dx / 4.0, y as f32 + dy / 4.0, W, H);
                if let Some(HitKind::Fiber { v, .. }) =
                    scene.intersect(&o, &d, None).map(|h| h.kind)
                {
                    fiber += 1;
                    kept += usize::from(keep(v));
                }
            }
            if fiber >= 4 && kept == fiber {
                let m = img.mean[(y * W + x) as usize];
                r += f64::from(m[0]);
                b += f64::from(m[2]);
                n += 1;
            }
        }
    }
    let n_f = n.max(1) as f64;
    ((r - b) / n_f, 0.5 * (r + b) / n_f, n)
}

#[test]
fn root_and_tip_show_their_colours() {
    let (scene, coat, hair) = (scene(), coat(), hair());
    let fur = AnalyticColours::new(hair).unwrap();
    let red = Rgb([0.6, 0.12, 0.05]);
    let blue = Rgb([0.05, 0.12, 0.6]);
    let graded = |root, tip| Coloured {
        fur: &fur,
        coat: &coat,
        colour: StrandColour::new(root, tip, 0.0, SEED).unwrap(),
    };
    // R − B at the roots and at the tips of a red-to-blue and a blue-to-red coat. One
    // scattering event (the light the fiber seen sends by itself): deeper, the roots are lit
    // mostly by light that crossed the tips above them and took the tips' colour (at depth
    // 8 the roots of the red-rooted coat look bluer than those of the blue-rooted one). The
    // skin a root pixel also shows is the same bits in both images (binary shadow rays), so
    // the difference of the two is the fibers' colour alone.
    let mut rows = Vec::new();
    for (root, tip) in [(red, blue), (blue, red)] {
        let img = image_to_depth(&scene, &graded(root, tip), 2, 1);
        let (at_root, mean_root, n_root) = red_minus_blue(&scene, &img, |v| v < 0.3);
        let (at_tip, mean_tip, n_tip) = red_minus_blue(&scene, &img, |v| v > 0.7);
        println!(
            "root {:?} tip {:?}: R - B {at_root:+.4} (mean {mean_root:.4}) over {n_root} root \
             pixels, {at_tip:+.4} (mean {mean_tip:.4}) over {n_tip} tip pixels",
            root.0, tip.0
        );
        assert!(
            n_root > 100 && n_tip > 100,
            "{n_root} root, {n_tip} tip pixels"
        );
        rows.push((at_root, at_tip, mean_root, mean_tip));
    }
    let (a, b) = (rows[0], rows[1]);
    // Roots redder where the root is red, tips redder where the tip is red: by a tenth of the
    // pixels' brightness at the roots (dark, shaded by the fur; measured 0.23), by half at
    // the tips (measured 1.96).
    assert!(a.0 - b.0 > 0.1 * a.2, "roots: {a:?} vs {b:?}");
    assert!(b.1 - a.1 > 0.5 * a.3, "tips: {a:?} vs {b:?}");
}

#[test]
fn no_variation_is_one_colour_and_variation_is_per_strand_on_any_thread_count() {
    let (scene, coat, hair) = (scene(), coat(), hair());
    let fur = AnalyticColours::new(hair).unwrap();
    let brown = Rgb([0.3, 0.15, 0.07]);
    let coloured = |jitter| Coloured {
        fur: &fur,
        coat: &coat,
        colour: StrandColour::new(brown, brown, jitter, SEED).unwrap(),
    };
    let bytes = |img: &Image| output::exr_bytes(img).unwrap();
    // One colour: the model at the σ_ca that colour gives, with no per-hit material.
    let sigma = Absorption::from_base_colour(brown, &coat)
        .unwrap()
        .absorption;
    let one = hair.at_absorption(&sigma).unwrap();
    let plain = bytes(&image(&scene, &One(&one), 2));
    assert!(
        bytes(&image(&scene, &coloured(0.0), 2)) == plain,
        "no variation must be the same bits as the one colour"
    );
    let varied = bytes(&image(&scene, &coloured(0.5), 1));
    assert!(
        varied == bytes(&image(&scene, &coloured(0.5), 2)),
        "1 and 2 threads gave different bytes"
    );
    assert!(varied != plain, "a variation of 50 % changed nothing");
    // The strands differ from one another, not the whole image alike: the ratio of the varied
    // to the plain image over the fiber pixels spreads.
    let (v, p) = (
        image(&scene, &coloured(0.5), 2),
        image(&scene, &One(&one), 2),
    );
    let ratios: Vec<f64> = v
        .mean
        .iter()
        .zip(&p.mean)
        .filter(|(_, b)| b[1] > 1e-3)
        .map(|(a, b)| f64::from(a[1] / b[1]))
        .collect();
    let mean = ratios.iter().sum::<f64>() / ratios.len() as f64;
    let sd = (ratios.iter().map(|r| (r - mean).powi(2)).sum::<f64>() / ratios.len() as f64).sqrt();
    println!(
        "varied/plain over {} pixels: mean {mean:.3}, sd {sd:.3}",
        ratios.len()
    );
    assert!(sd > 0.1, "sd {sd}");
}
