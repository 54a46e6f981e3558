//! Dual scattering judged against the path tracer (docs/model.md §13,
//! docs/accuracy.md "Dual scattering"): for a light preset (dog) and a dark one (deer), in the
//! energy closure, `ball` and `patch` under their key (rim) light, the `dual` image against a
//! converged-enough `path` image: mean luminance within 10 % and relative RMSE over 16×16
//! tiles ≤ 20 %; `single` printed beside them and, for the light preset, far darker than
//! `path`. Every preset's table and the density grid search are `#[ignore]`d runs.
//!
//! Metrics (`render::compare`, luminance): mean error = mean(dual)/mean(path) − 1 over the
//! whole image; tile RMSE over a 16 × 16 arrangement of tiles, relative to path's mean tile.
//! The same numbers restricted to the fur (pixels whose centre's camera ray first meets a
//! fiber) are printed beside them.

use crate::common;

use bcsdf_core::dual::{encode, Attenuation, Density, DualLut, DualTables, Quadrature};
use bcsdf_core::{presets, Closure, FurBcsdf};
use render::compare::{self, TILE_GRID};
use render::scatter::One;
use render::scene::{HitKind, Scene};
use render::{render_method, scenes, Image, Method, SceneKind, SceneOptions, Settings};

const SIDE: u32 = 64;

fn scene(kind: SceneKind) -> Scene {
    scenes::build(&SceneOptions {
        kind,
        fibers: None,
        seed: 3,
        aspect: 1.0,
    })
}

/// Mean number of fibers the key light's shadow ray crosses from the first fiber each pixel
/// centre sees (the dual term's n), and the fraction of those points with n = 0.
fn mean_fibers_to_key(scene: &Scene) -> (f64, f64) {
    let Some(key) = scene.lights.sample(0.0, [0.5, 0.5]) else {
        return (0.0, 0.0);
    };
    let (mut sum, mut zero, mut count) = (0.0f64, 0.0f64, 0.0f64);
    for i in 0..SIDE * SIDE {
        let (x, y) = (i % SIDE, i / SIDE);
        let (o, d) = scene.camera.ray(x as f32 + 0.5, y as f32 + 0.5, SIDE, SIDE);
        if let Some(h) = scene.intersect(&o, &d, None) {
            if let HitKind::Fiber { fiber, .. } = h.kind {
                if let Some(n) = scene.fibers_crossed(&h.point, &key, Some(fiber)) {
                    sum += f64::from(n);
                    zero += f64::from(u8::from(n == 0));
                }
                count += 1.0;
            }
        }
    }
    (sum / count.max(1.0), zero / count.max(1.0))
}

/// (mean error, tile relative RMSE) of `a` against the reference `r` (render::compare, a
/// [`TILE_GRID`] × [`TILE_GRID`] arrangement of tiles), over the pixels of `mask` (all when
/// `None`).
fn metrics(a: &Image, r: &Image, mask: Option<&[bool]>) -> (f64, f64) {
    let m = compare::metrics(a, r, TILE_GRID, mask);
    if mask.is_none() {
        println!(
            "    (tile RMSE {:.1} %, of which sampling noise alone {:.1} %)",
            100.0 * m.tiles,
            100.0 * m.noise
        );
    }
    (m.mean, m.tiles)
}

struct Row {
    preset: &'static str,
    scene: SceneKind,
    mean_dual: f64,
    rmse_dual: f64,
    mean_single: f64,
    rmse_single: f64,
}

fn measure(
    model: &FurBcsdf<'_>,
    lut: &DualLut,
    kind: SceneKind,
    density: Density,
    path_spp: u32,
) -> ((f64, f64), (f64, f64)) {
    let scene = scene(kind);
    let settings = |spp| Settings {
        seed: 23,
        ..Settings::new(SIDE, SIDE, spp)
    };
    let fiber = One(model);
    let path = render_method(&scene, &fiber, &settings(path_spp), &Method::Path).unwrap();
    let dual = render_method(
        &scene,
        &fiber,
        &settings(32),
        &Method::Dual { lut, density },
    )
    .unwrap();
    let single = render_method(&scene, &fiber, &settings(32), &Method::Single).unwrap();
    let mask = compare::fur_mask(&scene, SIDE, SIDE);
    let (n_mean, n_zero) = mean_fibers_to_key(&scene);
    println!(
        "  {kind}: fibers toward the key from the visible fur: mean {n_mean:.1}, {:.0} % unoccluded \
         (surface-blocked rays counted as occluded, not in the mean)",
        100.0 * n_zero
    );
    let (d, s) = (
        metrics(&dual.image, &path.image, None),
        metrics(&single.image, &path.image, None),
    );
    let (df, sf) = (
        metrics(&dual.image, &path.image, Some(&mask)),
        metrics(&single.image, &path.image, Some(&mask)),
    );
    println!(
        "  {kind}: path {:.2} s ({path_spp} spp), dual {:.2} s, single {:.2} s; fur only: dual \
         mean {:+.1} % tiles {:.1} %, single mean {:+.1} % tiles {:.1} %",
        path.seconds,
        dual.seconds,
        single.seconds,
        100.0 * df.0,
        100.0 * df.1,
        100.0 * sf.0,
        100.0 * sf.1
    );
    (d, s)
}

/// The evaluator an engine would load: `tables` for `attenuation` through the `.furdual` blob.
fn lut_of(tables: &DualTables, attenuation: Attenuation) -> Box<DualLut> {
    let mut lut = Box::new(DualLut::EMPTY);
    lut.decode(&encode(tables, attenuation, 0)).unwrap();
    lut
}

fn with_tables<R>(name: &str, f: impl FnOnce(&FurBcsdf<'_>, &DualLut) -> R) -> R {
    let mut input = presets::find(name).unwrap().input;
    input.closure = Closure::Energy;
    common::with_model(&input, |model| {
        let mut tables = Box::new(DualTables::ZERO);
        let t = std::time::Instant::now();
        tables.compute(
            model,
            Quadrature {
                theta_steps: 96,
                phi_steps: 64,
            },
        );
        println!("{name}: tables in {:.2} s", t.elapsed().as_secs_f64());
        f(model, &lut_of(&tables, SHIPPED.1))
    })
}

/// The shipped method and default: the coat's attenuation, `Density::DEFAULT`.
const SHIPPED: (Density, Attenuation) = (Density::DEFAULT, Attenuation::Coat);

fn rows(presets_: &[&'static str], scenes_: &[SceneKind], path_spp: u32) -> Vec<Row> {
    let mut rows = Vec::new();
    for &preset in presets_ {
        with_tables(preset, |model, tables| {
            for &kind in scenes_ {
                let ((md, rd), (ms, rs)) = measure(model, tables, kind, SHIPPED.0, path_spp);
                rows.push(Row {
                    preset,
                    scene: kind,
                    mean_dual: md,
                    rmse_dual: rd,
                    mean_single: ms,
                    rmse_single: rs,
                });
            }
        });
    }
    println!("preset  scene  dual: mean  tiles | single: mean  tiles");
    for r in &rows {
        println!(
            "{:7} {:6} {:+9.1} % {:5.1} % | {:+10.1} % {:5.1} %",
            r.preset,
            r.scene.name(),
            100.0 * r.mean_dual,
            100.0 * r.rmse_dual,
            100.0 * r.mean_single,
            100.0 * r.rmse_single
        );
    }
    rows
}

/// The accuracy bounds, shipped attenuation ([`Attenuation::Coat`]) and density (d_f = d_b = 1),
/// for preset `name` on `ball` and `patch`: the `dual` image's mean luminance is within 10 % of
/// `path`'s and its tile RMSE at most 20 %; `single` is darker than `path`, and for a light
/// preset by far (more than 30 %).
fn within_the_bounds(name: &'static str, light: bool) {
    let rows = rows(&[name], &[SceneKind::Ball, SceneKind::Patch], 32);
    for r in &rows {
        assert!(
            r.mean_dual.abs() <= 0.10 && r.rmse_dual <= 0.20,
            "{} {}: dual mean {:+.3}, tiles {:.3}",
            r.preset,
            r.scene,
            r.mean_dual,
            r.rmse_dual
        );
        assert!(r.mean_single < 0.0, "{} {}: single", r.preset, r.scene);
        if light {
            assert!(r.mean_single < -0.3, "{} {}: single", r.preset, r.scene);
        }
    }
}

/// [`within_the_bounds`] for a light preset, dog (one test per preset: the harness runs them
/// side by side).
#[test]
fn dual_scattering_is_within_the_bounds_of_the_path_tracer_dog() {
    within_the_bounds("dog", true);
}

/// [`within_the_bounds`] for a dark preset, deer.
#[test]
fn dual_scattering_is_within_the_bounds_of_the_path_tracer_deer() {
    within_the_bounds("deer", false);
}

/// The table of docs/accuracy.md ("Dual scattering"): every preset (or those named in
/// `DUAL_PRESETS`, comma-separated), `ball` and `patch`, `path` at 32 spp.
/// `cargo test --release -p render --test suite -- --ignored --nocapture every_preset`.
#[test]
#[ignore = "every preset, minutes; its table is in docs/accuracy.md"]
fn every_preset_against_the_path_tracer() {
    let only = std::env::var("DUAL_PRESETS").ok();
    let names: Vec<&'static str> = bcsdf_core::presets::PRESETS
        .iter()
        .map(|p| p.name)
        .filter(|n| only.as_ref().is_none_or(|o| o.split(',').any(|x| x == *n)))
        .collect();
    let rows = rows(&names, &[SceneKind::Ball, SceneKind::Patch], 32);
    let worst = rows
        .iter()
        .map(|r| r.mean_dual.abs())
        .fold(0.0f64, f64::max);
    println!("worst |mean| {:.1} %", 100.0 * worst);
}

/// `dual` and `single` are the same bits on one and on two threads.
#[test]
fn dual_renders_are_deterministic() {
    let mut input = presets::find("human-hair").unwrap().input;
    input.closure = Closure::Energy;
    common::with_model(&input, |model| {
        let tables = common::coarse_dual_tables(model);
        let scene = scenes::build(&SceneOptions {
            kind: SceneKind::Patch,
            fibers: Some(800),
            seed: 2,
            aspect: 1.0,
        });
        for method in [
            Method::Single,
            Method::Dual {
                lut: &lut_of(&tables, SHIPPED.1),
                density: SHIPPED.0,
            },
        ] {
            let run = |threads| {
                let settings = Settings {
                    threads: Some(threads),
                    ..Settings::new(16, 16, 4)
                };
                render_method(&scene, &One(model), &settings, &method).unwrap()
            };
            let (a, b) = (run(1), run(2));
            assert!(a.image.mean.iter().flatten().any(|&v| v > 0.0));
            assert_eq!(a.image.mean, b.image.mean, "{:?}", method.kind());
        }
    });
}

/// The grid search of d_f, d_b (docs/accuracy.md): `cargo test -p render --test suite dual:: --
/// --ignored --nocapture fit` (every preset, or the list in `DUAL_FIT_PRESETS`). 48 × 48
/// pixels, 16 spp, one `path` image per preset and scene, a `dual` image per point of
/// {0.5, 1, 1.5}²; the best point is the one whose worse scene's |mean error| is least.
#[test]
#[ignore = "a grid search, minutes; its table is in docs/accuracy.md"]
fn fit_density() {
    const FIT_SIDE: u32 = 48;
    let grid = [0.5f32, 1.0, 1.5];
    let presets: Vec<String> = std::env::var("DUAL_FIT_PRESETS")
        .map(|v| v.split(',').map(str::to_string).collect())
        .unwrap_or_else(|_| {
            bcsdf_core::presets::PRESETS
                .iter()
                .map(|p| p.name.to_string())
                .collect()
        });
    for preset in &presets {
        with_tables(preset, |model, tables| {
            // (d_f, d_b) → the metrics of each scene.
            let mut results: Vec<((f32, f32), Vec<compare::Metrics>)> = Vec::new();
            for &d_f in &grid {
                for &d_b in &grid {
                    results.push(((d_f, d_b), Vec::new()));
                }
            }
            for kind in [SceneKind::Ball, SceneKind::Patch] {
                let scene = scene(kind);
                let settings = |spp| Settings {
                    seed: 23,
                    ..Settings::new(FIT_SIDE, FIT_SIDE, spp)
                };
                let fiber = One(model);
                let path = render_method(&scene, &fiber, &settings(16), &Method::Path).unwrap();
                for ((d_f, d_b), row) in &mut results {
                    let method = Method::Dual {
                        lut: tables,
                        density: Density {
                            d_f: *d_f,
                            d_b: *d_b,
                        },
                    };
                    let dual = render_method(&scene, &fiber, &settings(16), &method).unwrap();
                    let m = compare::metrics(&dual.image, &path.image, TILE_GRID, None);
                    println!(
                        "FIT {preset} {kind} d_f {d_f} d_b {d_b}: mean {:+.2} % tiles {:.2} %",
                        100.0 * m.mean,
                        100.0 * m.tiles
                    );
                    row.push(m);
                }
            }
            // Best: the smallest worse-scene |mean error|.
            let worst = |r: &[compare::Metrics]| r.iter().map(|x| x.mean.abs()).fold(0.0, f64::max);
            if let Some(((d_f, d_b), r)) = results
                .iter()
                .min_by(|a, b| worst(&a.1).total_cmp(&worst(&b.1)))
            {
                println!(
                    "BEST {preset}: d_f {d_f} d_b {d_b}: ball {:+.1} % / {:.1} %, patch {:+.1} % / {:.1} %",
                    100.0 * r[0].mean,
                    100.0 * r[0].tiles,
                    100.0 * r[1].mean,
                    100.0 * r[1].tiles
                );
            }
        });
    }
}

/// The dual term at a colour its tables were not computed for (docs/model.md §13, the
/// absorption axis of `.furdual` format 2): the blob holds one grey table set per node of the
/// absorption axis, each computed from the preset at that grey σ_ca (as `bake` computes them
/// from `lut.at`), and records `colour` as its own, so `Method::Dual` evaluates every channel
/// interpolated along the axis at `colour`; `path` renders the preset with its σ_ca replaced
/// by `colour`. Mean luminance within 10 % of `path` for two presets at two colours each, on
/// `ball`, `path` at 32 spp. `cargo test -p render --test suite dual:: -- --ignored --nocapture
/// dual_at_a_colour`.
#[test]
#[ignore]
fn dual_at_a_colour_between_the_nodes_is_within_the_bounds_of_the_path_tracer() {
    use bcsdf_core::dual::{encode_axis, BLOB_LEN};
    use bcsdf_core::{Absorption, Rgb};
    let colours = [Rgb([0.35, 0.6, 1.1]), Rgb([2.5, 4.5, 8.0])];
    let mut failures = Vec::new();
    for preset in ["dog", "deer"] {
        let mut input = presets::find(preset).unwrap().input;
        input.closure = Closure::Energy;
        // The node tables, once per preset (the colour only changes the header's default).
        let t = std::time::Instant::now();
        let mut nodes: Vec<Box<DualTables>> = Vec::new();
        let mut scratch = Box::new(DualTables::ZERO);
        let mut blob = vec![0u8; BLOB_LEN];
        encode_axis(
            (&mut blob[..]).try_into().unwrap(),
            &mut scratch,
            |sigma, tables| {
                let grey = Absorption::from_sigma(Rgb::splat(sigma)).unwrap();
                common::with_model(&grey.apply(&input), |model| {
                    tables.compute(
                        model,
                        Quadrature {
                            theta_steps: 96,
                            phi_steps: 64,
                        },
                    );
                });
                nodes.push(Box::new(tables.clone()));
            },
            SHIPPED.1,
            0,
            Absorption::LOSSLESS,
        );
        println!(
            "{preset}: 16 node tables in {:.1} s",
            t.elapsed().as_secs_f64()
        );
        for sigma in colours {
            let colour = Absorption::from_sigma(sigma).unwrap();
            let mut k = 0;
            encode_axis(
                (&mut blob[..]).try_into().unwrap(),
                &mut scratch,
                |_, tables| {
                    tables.clone_from(&nodes[k]);
                    k += 1;
                },
                SHIPPED.1,
                0,
                colour,
            );
            let mut lut = Box::new(DualLut::EMPTY);
            lut.decode(&blob).unwrap();
            assert_eq!(lut.absorption(), colour);
            common::with_model(&colour.apply(&input), |model| {
                let ((md, rd), (ms, _)) = measure(model, &lut, SceneKind::Ball, SHIPPED.0, 32);
                println!(
                    "{preset} at sigma_ca {:?}: dual mean {:+.1} % tiles {:.1} %, single mean {:+.1} %",
                    sigma.0,
                    100.0 * md,
                    100.0 * rd,
                    100.0 * ms
                );
                if md.abs() > 0.10 {
                    failures.push(format!("{preset} {:?}: dual mean {md:+.3}", sigma.0));
                }
            });
        }
    }
    assert!(failures.is_empty(), "{failures:?}");
}

/// Where `dual` misses light on `ball` (docs/accuracy.md "Dual scattering", the curved coat):
/// for the presets in `DUAL_DIAGNOSE_PRESETS` (default cat, deer), `path`, `dual` and `single`
/// over the fur's pixels with both lights, the key alone and the sky alone, with the skin and
/// ground as they are and black; with the key alone and black surfaces (the fur's light is
/// then fiber light only) `path`'s light by path depth; and `dual`/`path` over the fur's
/// pixels grouped by the fibers toward the key from the pixel centre's first fiber and by the
/// key's incidence on the coat (cos between the key and the ball's normal there).
/// `cargo test --release -p render --test suite dual:: -- --ignored --nocapture diagnose`.
#[test]
#[ignore = "a diagnostic, minutes; its findings are in docs/accuracy.md"]
fn diagnose_the_curved_coat() {
    use render::compare::luminance;
    use render::light::{DistantDisc, Light, Lights, UniformEnvironment};
    use render::surface::Shape;
    let presets: Vec<String> = std::env::var("DUAL_DIAGNOSE_PRESETS")
        .map(|v| v.split(',').map(str::to_string).collect())
        .unwrap_or_else(|_| vec!["cat".into(), "deer".into()]);
    let key_axis = nalgebra::Vector3::new(0.6f32, 0.9, 0.8).normalize();
    let key =
        || -> Box<dyn Light> { Box::new(DistantDisc::with_irradiance(key_axis, 4.0, [2.5; 3])) };
    let sky = || -> Box<dyn Light> {
        Box::new(UniformEnvironment {
            radiance: [0.08; 3],
        })
    };
    let fur_mean = |img: &Image, mask: &[bool]| -> f64 {
        img.mean
            .iter()
            .zip(mask)
            .filter(|(_, &m)| m)
            .map(|(p, _)| luminance(p))
            .sum::<f64>()
    };
    for preset in &presets {
        with_tables(preset, |model, lut| {
            let fiber = One(model);
            let settings = |spp| Settings {
                seed: 23,
                ..Settings::new(SIDE, SIDE, spp)
            };
            let method = Method::Dual {
                lut,
                density: SHIPPED.0,
            };
            for (lights, label) in [(0u8, "both"), (1, "key"), (2, "sky")] {
                for black in [false, true] {
                    let mut s = scene(SceneKind::Ball);
                    s.lights = match lights {
                        0 => Lights::new(vec![(key(), 0.8), (sky(), 0.2)]),
                        1 => Lights::new(vec![(key(), 1.0)]),
                        _ => Lights::new(vec![(sky(), 1.0)]),
                    };
                    if black {
                        for surf in &mut s.surfaces {
                            surf.albedo = [0.0; 3];
                        }
                    }
                    let mask = compare::fur_mask(&s, SIDE, SIDE);
                    let path = render_method(&s, &fiber, &settings(64), &Method::Path).unwrap();
                    let dual = render_method(&s, &fiber, &settings(32), &method).unwrap();
                    let single = render_method(&s, &fiber, &settings(32), &Method::Single).unwrap();
                    let p = fur_mean(&path.image, &mask);
                    println!(
                        "DIAG {preset} lights {label:4} surfaces {}: fur path {:.3}, dual {:+.1} %, single {:+.1} %",
                        if black { "black" } else { "as is" },
                        p / mask.iter().filter(|&&m| m).count().max(1) as f64,
                        100.0 * (fur_mean(&dual.image, &mask) / p - 1.0),
                        100.0 * (fur_mean(&single.image, &mask) / p - 1.0)
                    );
                    if lights == 1 && black {
                        let total: f64 = path.orders.iter().map(luminance_f64).sum();
                        let shares: Vec<String> = path
                            .orders
                            .iter()
                            .take(8)
                            .map(|o| format!("{:.3}", luminance_f64(o) / total))
                            .collect();
                        println!("DIAG {preset} key, black: path light by depth 0.. {shares:?}");
                    }
                    if lights != 2 {
                        // Groups: fibers toward the key (0, 1-2, 3-9, ≥ 10, blocked by a
                        // surface) and the key's incidence cos on the coat (< 0.2, 0.2-0.5,
                        // 0.5-0.8, ≥ 0.8).
                        let centre = match s.surfaces[0].shape {
                            Shape::Sphere { center, .. } => center,
                            _ => unreachable!("ball's skin is a sphere"),
                        };
                        let mut by_n = [[0.0f64; 3]; 5];
                        let mut by_cos = [[0.0f64; 3]; 4];
                        for (i, _) in mask.iter().enumerate().filter(|(_, &m)| m) {
                            let (x, y) = (i as u32 % SIDE, i as u32 / SIDE);
                            let (o, d) = s.camera.ray(x as f32 + 0.5, y as f32 + 0.5, SIDE, SIDE);
                            let Some(h) = s.intersect(&o, &d, None) else {
                                continue;
                            };
                            let HitKind::Fiber { fiber: id, .. } = h.kind else {
                                continue;
                            };
                            let gn = match s.fibers_crossed(&h.point, &key_axis, Some(id)) {
                                None => 4,
                                Some(0) => 0,
                                Some(1..=2) => 1,
                                Some(3..=9) => 2,
                                Some(_) => 3,
                            };
                            let c = (h.point - centre).normalize().dot(&key_axis);
                            let gc = if c < 0.2 {
                                0
                            } else if c < 0.5 {
                                1
                            } else if c < 0.8 {
                                2
                            } else {
                                3
                            };
                            let v = [
                                luminance(&path.image.mean[i]),
                                luminance(&dual.image.mean[i]),
                                1.0,
                            ];
                            for k in 0..3 {
                                by_n[gn][k] += v[k];
                                by_cos[gc][k] += v[k];
                            }
                        }
                        let fmt = |g: &[[f64; 3]]| -> Vec<String> {
                            let tot: f64 = g.iter().map(|r| r[0]).sum();
                            g.iter()
                                .map(|r| {
                                    format!(
                                        "{:.0} px, {:.0} % of light, dual {:+.1} %",
                                        r[2],
                                        100.0 * r[0] / tot,
                                        100.0 * (r[1] / r[0] - 1.0)
                                    )
                                })
                                .collect()
                        };
                        println!(
                            "DIAG {preset} {label} {}: by n (0, 1-2, 3-9, >=10, surface) {:?}",
                            if black { "black" } else { "as is" },
                            fmt(&by_n)
                        );
                        println!(
                            "DIAG {preset} {label} {}: by key cos (<0.2, 0.2-0.5, 0.5-0.8, >=0.8) {:?}",
                            if black { "black" } else { "as is" },
                            fmt(&by_cos)
                        );
                    }
                }
            }
        });
    }
}

fn luminance_f64(o: &[f64; 3]) -> f64 {
    0.2126 * o[0] + 0.7152 * o[1] + 0.0722 * o[2]
}

#[path = "dual_incidence.rs"]
mod incidence;
