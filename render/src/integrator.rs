//! Unidirectional path tracing with next-event estimation and multiple importance sampling
//! (power heuristic), Russian roulette (docs/model.md §11), and per-pixel random streams (pbrt-v4's `PathIntegrator`
//! is the model).
//!
//! At every scattering vertex (a fiber, far-field S·cos θ_i; or a Lambertian surface):
//! 1. next-event estimation: a direction from the lights' mixture ([`crate::light::Lights`]),
//!    weighted by w_L = p_L²/(p_L² + p_S²) when it reaches infinity unblocked;
//! 2. a direction from the scatterer's sampler; if that ray escapes, the lights' radiance
//!    found there is weighted by w_S = p_S²/(p_L² + p_S²).
//!
//! The two weights sum to one for every direction, so the estimate is unbiased. Strategy
//! [`Strategy::Bcsdf`] uses only 2 (weight 1), [`Strategy::Light`] only 1 (weight 1): all
//! three estimate the same image. After [`Settings::rr_depth`] vertices a path survives with
//! probability min(1, max β) and its throughput β is divided by it (unbiased).
//!
//! Every vertex draws exactly seven numbers (light pick 1, light direction 2, scattering 3,
//! roulette 1) from the pixel's stream, whatever happens, so the strategies see the same
//! numbers and the image is the same bits for any thread count.

use crate::film::{Image, Render};
use crate::method::Method;
use crate::sampler::Sampler;
use crate::scatter::Scatterer;
use crate::scene::{HitKind, Scene};
use crate::strand::{FiberMaterial, StrandPoint};
use crate::surface::{cosine_pdf, lambert_f, sample_cosine};
use core::fmt;
use indicatif::{ProgressBar, ProgressStyle};
use rayon::prelude::*;
use std::io::IsTerminal;
use std::time::Instant;

/// Which estimators a render combines.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Strategy {
    /// Light sampling and BCSDF sampling, combined by the power heuristic.
    Mis,
    /// BCSDF sampling only (lights are found by escaping rays).
    Bcsdf,
    /// Light sampling only (next-event estimation; escaping rays after a bounce add nothing).
    Light,
}

/// What to render.
#[derive(Clone, Copy, Debug)]
pub struct Settings {
    /// Image width in pixels (1 to [`Settings::MAX_SIDE`]).
    pub width: u32,
    /// Image height in pixels (1 to [`Settings::MAX_SIDE`]).
    pub height: u32,
    /// Samples (camera paths) per pixel, at least 1.
    pub spp: u32,
    /// Largest number of scattering events on a path (1 to [`Settings::MAX_DEPTH`]).
    pub max_depth: u32,
    /// Vertices before Russian roulette starts.
    pub rr_depth: u32,
    /// Seed of the per-pixel random streams.
    pub seed: u64,
    /// Which estimators to use.
    pub strategy: Strategy,
    /// Worker threads (`None` or 0: one per core). The image is the same bits for any count.
    pub threads: Option<usize>,
    /// Show a progress bar on stderr (only when stderr is a terminal).
    pub progress: bool,
}

impl Settings {
    /// Largest image side.
    pub const MAX_SIDE: u32 = 16_384;
    /// Largest path depth.
    pub const MAX_DEPTH: u32 = 4096;

    /// Defaults for a `width` × `height` image at `spp` samples: depth 32, roulette after 3
    /// vertices, seed 1, MIS, all cores, no progress bar.
    #[must_use]
    pub fn new(width: u32, height: u32, spp: u32) -> Settings {
        Settings {
            width,
            height,
            spp,
            max_depth: 32,
            rr_depth: 3,
            seed: 1,
            strategy: Strategy::Mis,
            threads: None,
            progress: false,
        }
    }

    /// Checks every field; the error names the one that is wrong.
    pub fn validate(&self) -> Result<(), SettingsError> {
        let side = 1..=Settings::MAX_SIDE;
        if !side.contains(&self.width) {
            return Err(SettingsError::Width(self.width));
        }
        if !side.contains(&self.height) {
            return Err(SettingsError::Height(self.height));
        }
        if self.spp == 0 {
            return Err(SettingsError::Spp);
        }
        if !(1..=Settings::MAX_DEPTH).contains(&self.max_depth) {
            return Err(SettingsError::MaxDepth(self.max_depth));
        }
        Ok(())
    }
}

/// Why [`Settings`] were rejected.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SettingsError {
    /// Width outside 1..=MAX_SIDE.
    Width(u32),
    /// Height outside 1..=MAX_SIDE.
    Height(u32),
    /// Zero samples per pixel.
    Spp,
    /// Depth outside 1..=MAX_DEPTH.
    MaxDepth(u32),
    /// The worker pool could not be made.
    Threads,
}

impl fmt::Display for SettingsError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SettingsError::Width(w) => write!(f, "width {w} must be 1 to {}", Settings::MAX_SIDE),
            SettingsError::Height(h) => write!(f, "height {h} must be 1 to {}", Settings::MAX_SIDE),
            SettingsError::Spp => f.write_str("spp must be at least 1"),
            SettingsError::MaxDepth(d) => {
                write!(f, "max depth {d} must be 1 to {}", Settings::MAX_DEPTH)
            }
            SettingsError::Threads => f.write_str("could not start the worker threads"),
        }
    }
}

impl std::error::Error for SettingsError {}

/// Power heuristic weight of a strategy of density `a` against one of density `b`.
#[inline]
fn power_heuristic(a: f32, b: f32) -> f32 {
    let (a2, b2) = (a * a, b * b);
    if a2 + b2 > 0.0 && (a2 + b2).is_finite() {
        a2 / (a2 + b2)
    } else if a.is_infinite() {
        1.0
    } else {
        0.0
    }
}

/// One row's results.
struct Row {
    mean: Vec<[f32; 3]>,
    variance: Vec<[f32; 3]>,
    orders: Vec<[f64; 3]>,
    rays: u64,
}

/// Renders `scene` with fiber material `fiber` by path tracing: any scatterer (see
/// [`crate::scatter`], one colour everywhere) or a material coloured per strand
/// ([`crate::strand`]).
pub fn render<S: FiberMaterial>(
    scene: &Scene,
    fiber: &S,
    settings: &Settings,
) -> Result<Render, SettingsError> {
    render_method(scene, fiber, settings, &Method::Path)
}

/// Renders `scene` with fiber material `fiber` including the light paths `method` includes
/// ([`crate::method`], docs/model.md §13).
pub fn render_method<S: FiberMaterial>(
    scene: &Scene,
    fiber: &S,
    settings: &Settings,
    method: &Method<'_>,
) -> Result<Render, SettingsError> {
    settings.validate()?;
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(settings.threads.unwrap_or(0))
        .build()
        .map_err(|_| SettingsError::Threads)?;
    let bar = if settings.progress && std::io::stderr().is_terminal() {
        let bar = ProgressBar::new(u64::from(settings.height));
        if let Ok(style) =
            ProgressStyle::with_template("{bar:40} {pos}/{len} rows, {elapsed} (eta {eta})")
        {
            bar.set_style(style);
        }
        bar
    } else {
        ProgressBar::hidden()
    };
    let start = Instant::now();
    let rows: Vec<Row> = pool.install(|| {
        (0..settings.height)
            .into_par_iter()
            .map(|y| {
                let row = render_row(scene, fiber, settings, method, y);
                bar.inc(1);
                row
            })
            .collect()
    });
    bar.finish_and_clear();
    let seconds = start.elapsed().as_secs_f64();

    let pixels = f64::from(settings.width) * f64::from(settings.height);
    let mut orders = vec![[0.0f64; 3]; settings.max_depth as usize + 1];
    let mut mean = Vec::with_capacity(pixels as usize);
    let mut variance = Vec::with_capacity(pixels as usize);
    let mut rays = 0;
    for row in rows {
        for (acc, o) in orders.iter_mut().zip(&row.orders) {
            for c in 0..3 {
                acc[c] += o[c];
            }
        }
        mean.extend(row.mean);
        variance.extend(row.variance);
        rays += row.rays;
    }
    let samples = pixels * f64::from(settings.spp);
    for o in &mut orders {
        *o = o.map(|v| v / samples);
    }
    Ok(Render {
        image: Image {
            width: settings.width,
            height: settings.height,
            mean,
            variance,
        },
        orders,
        paths: samples as u64,
        rays,
        seconds,
    })
}

fn render_row<S: FiberMaterial>(
    scene: &Scene,
    fiber: &S,
    settings: &Settings,
    method: &Method<'_>,
    y: u32,
) -> Row {
    let w = settings.width as usize;
    let mut row = Row {
        mean: Vec::with_capacity(w),
        variance: Vec::with_capacity(w),
        orders: vec![[0.0; 3]; settings.max_depth as usize + 1],
        rays: 0,
    };
    let n = f64::from(settings.spp);
    for x in 0..settings.width {
        let index = u64::from(y) * u64::from(settings.width) + u64::from(x);
        let mut sampler = Sampler::for_pixel(settings.seed, index);
        let mut sum = [0.0f64; 3];
        let mut sum_sq = [0.0f64; 3];
        for _ in 0..settings.spp {
            let l = trace(
                scene,
                fiber,
                settings,
                method,
                (x, y),
                &mut sampler,
                &mut row,
            );
            for c in 0..3 {
                sum[c] += l[c];
                sum_sq[c] += l[c] * l[c];
            }
        }
        let mean = sum.map(|s| s / n);
        let var_of_mean: [f64; 3] = core::array::from_fn(|c| {
            ((sum_sq[c] / n - mean[c] * mean[c]).max(0.0) * n / (n - 1.0).max(1.0)) / n
        });
        row.mean.push(mean.map(|v| v as f32));
        row.variance.push(var_of_mean.map(|v| v as f32));
    }
    row
}

/// Adds `beta · value · weight` to the path's radiance and to bounce order `order`; a
/// non-finite contribution is dropped.
fn add(
    l: &mut [f64; 3],
    orders: &mut [[f64; 3]],
    order: usize,
    beta: &[f32; 3],
    value: &[f32; 3],
    weight: f32,
) {
    let c: [f64; 3] =
        core::array::from_fn(|k| f64::from(beta[k]) * f64::from(value[k]) * f64::from(weight));
    if c.iter().all(|v| v.is_finite()) {
        for k in 0..3 {
            l[k] += c[k];
            orders[order][k] += c[k];
        }
    }
}

/// One camera path through pixel (x, y): its radiance estimate.
fn trace<S: FiberMaterial>(
    scene: &Scene,
    fiber: &S,
    settings: &Settings,
    method: &Method<'_>,
    (x, y): (u32, u32),
    sampler: &mut Sampler,
    row: &mut Row,
) -> [f64; 3] {
    let mut l = [0.0f64; 3];
    let jitter = sampler.next_2d();
    let (mut origin, mut dir) = scene.camera.ray(
        x as f32 + jitter[0],
        y as f32 + jitter[1],
        settings.width,
        settings.height,
    );
    let mut from: Option<u32> = None;
    let mut beta = [1.0f32; 3];
    // Density of the direction `dir` was drawn with; 0 for the camera ray (no MIS there).
    let mut pdf_prev = 0.0f32;
    // `single` and `dual`: the ray being traced left a fiber and goes through fibers to the
    // first surface (crate::method).
    let mut through_fibers = false;
    let approximate = !matches!(method, Method::Path);
    let lights = &scene.lights;
    for depth in 0..=settings.max_depth {
        row.rays += 1;
        let hit = if through_fibers {
            scene.intersect_surfaces(&origin, &dir)
        } else {
            scene.intersect(&origin, &dir, from)
        };
        let Some(hit) = hit else {
            let le = lights.radiance(&dir);
            let weight = match (depth, settings.strategy) {
                (0, _) | (_, Strategy::Bcsdf) => 1.0,
                (_, Strategy::Mis) => power_heuristic(pdf_prev, lights.pdf(&dir)),
                (_, Strategy::Light) => 0.0,
            };
            add(&mut l, &mut row.orders, depth as usize, &beta, &le, weight);
            break;
        };
        if depth == settings.max_depth {
            break;
        }
        let order = depth as usize + 1;
        let wr = -dir;
        let u_pick = sampler.next_1d();
        let u_light = sampler.next_2d();
        let u_scatter = sampler.next_3d();
        let u_rr = sampler.next_1d();

        // The vertex: how it scatters (a fiber's material asked once, at this point of its
        // strand), where rays leave it from.
        let strand = match hit.kind {
            HitKind::Fiber { fiber: id, v, .. } => Some(fiber.at(&StrandPoint { fiber: id, v })),
            HitKind::Surface { .. } => None,
        };
        let (next_origin, next_from) = match hit.kind {
            HitKind::Fiber { fiber: id, .. } => (hit.point, Some(id)),
            HitKind::Surface { normal, .. } => {
                if normal.dot(&dir) > 0.0 {
                    break; // the inside of a one-sided surface is black
                }
                (hit.point + normal * scene.epsilon, None)
            }
        };
        // `single` and `dual` at a fiber: light sampling with a counted shadow ray; the path
        // goes on only through the fibers to a surface (crate::method).
        let approximated = if let (HitKind::Fiber { tangent, .. }, Some(s), true) =
            (hit.kind, &strand, approximate)
        {
            if let Some(wl) = lights.sample(u_pick, u_light) {
                let p_light = lights.pdf(&wl);
                if p_light > 0.0 {
                    row.rays += 1;
                    if let Some(n) = scene.fibers_crossed(&next_origin, &wl, next_from) {
                        let below = || scene.fibers_below(&next_origin, &wl, next_from);
                        let f = method.fiber_light(s, &wl, &wr, &tangent, n, below);
                        let le = lights.radiance(&wl);
                        let value: [f32; 3] = core::array::from_fn(|c| f[c] * le[c]);
                        add(&mut l, &mut row.orders, order, &beta, &value, 1.0 / p_light);
                    }
                }
            }
            Some(tangent)
        } else {
            None
        };

        // The light's direction for next-event estimation, and the vertex's two questions
        // about it and the continuation: at a fiber in one call, so that a baked BCSDF
        // builds its per-view context once (`Scatterer::eval_and_sample`).
        let light = if settings.strategy != Strategy::Bcsdf && approximated.is_none() {
            lights.sample(u_pick, u_light)
        } else {
            None
        };
        let (light_value, scattered) = match (hit.kind, &strand) {
            (HitKind::Fiber { tangent, .. }, Some(s)) => match &light {
                Some(wl) => s.eval_and_sample(wl, &wr, &tangent, u_scatter),
                None => (([0.0; 3], 0.0), s.sample(&wr, &tangent, u_scatter)),
            },
            (HitKind::Fiber { .. }, None) => (([0.0; 3], 0.0), None),
            (HitKind::Surface { normal, albedo }, _) => {
                let value = light.as_ref().map_or(([0.0; 3], 0.0), |wl| {
                    let cos = normal.dot(wl);
                    if cos > 0.0 {
                        (lambert_f(albedo).map(|f| f * cos), cosine_pdf(cos))
                    } else {
                        ([0.0; 3], 0.0)
                    }
                });
                let wi = sample_cosine(&normal, [u_scatter[0], u_scatter[1]]);
                let pdf = cosine_pdf(normal.dot(&wi));
                let sampled = (pdf > 0.0).then_some(crate::scatter::Scattered {
                    wi,
                    weight: albedo,
                    pdf,
                });
                (value, sampled)
            }
        };

        // 1. Next-event estimation.
        if let Some(wl) = light {
            let p_light = lights.pdf(&wl);
            let (f_cos, p_scatter) = light_value;
            if p_light > 0.0 && f_cos.iter().any(|&v| v > 0.0) {
                row.rays += 1;
                if scene.escapes(&next_origin, &wl, next_from) {
                    let le = lights.radiance(&wl);
                    let weight = if settings.strategy == Strategy::Mis {
                        power_heuristic(p_light, p_scatter)
                    } else {
                        1.0
                    };
                    let value: [f32; 3] = core::array::from_fn(|c| f_cos[c] * le[c]);
                    add(
                        &mut l,
                        &mut row.orders,
                        order,
                        &beta,
                        &value,
                        weight / p_light,
                    );
                }
            }
        }

        // 2. The scattered direction.
        let Some(s) = scattered else { break };
        let weight = match approximated {
            None => s.weight,
            Some(tangent) => {
                // Light from the first surface behind n fibers: S·V + D(n) (crate::method);
                // with no surface there the light came by light sampling alone.
                row.rays += 1;
                let (Some(n), Some(at)) = (
                    scene.fibers_before_surface(&next_origin, &s.wi, next_from),
                    &strand,
                ) else {
                    break;
                };
                let below = || scene.fibers_below(&next_origin, &s.wi, next_from);
                let f = method.fiber_light(at, &s.wi, &wr, &tangent, n, below);
                f.map(|v| v / s.pdf)
            }
        };
        for (b, w) in beta.iter_mut().zip(weight) {
            *b *= w;
        }
        if !beta.iter().any(|&b| b > 0.0) || !beta.iter().all(|b| b.is_finite()) {
            break;
        }
        origin = next_origin;
        from = next_from;
        dir = s.wi;
        pdf_prev = s.pdf;
        through_fibers = approximated.is_some();

        // 3. Russian roulette.
        if order as u32 >= settings.rr_depth {
            let q = beta.iter().fold(0.0f32, |m, &b| m.max(b));
            if q < 1.0 {
                if u_rr >= q {
                    break;
                }
                beta = beta.map(|b| b / q);
            }
        }
    }
    l
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn power_heuristic_weights_sum_to_one() {
        for (a, b) in [(1.0, 1.0), (0.3, 7.0), (0.0, 2.0), (5.0, 0.0)] {
            assert!((power_heuristic(a, b) + power_heuristic(b, a) - 1.0).abs() < 1e-6);
        }
        assert_eq!(power_heuristic(1.0, 3.0), 0.1);
        assert_eq!(power_heuristic(0.0, 0.0), 0.0);
    }

    #[test]
    fn settings_name_the_bad_field() {
        let ok = Settings::new(8, 8, 1);
        assert!(ok.validate().is_ok());
        let e = Settings { spp: 0, ..ok }.validate().unwrap_err();
        assert!(e.to_string().contains("spp"));
        let e = Settings { max_depth: 0, ..ok }.validate().unwrap_err();
        assert!(e.to_string().contains("max depth 0"));
        let e = Settings { width: 0, ..ok }.validate().unwrap_err();
        assert!(e.to_string().contains("width 0"));
    }
}
