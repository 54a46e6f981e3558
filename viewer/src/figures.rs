//! The two comparison figures drawn from direct evaluations of both far fields:
//!
//! - [`heat_maps`] (`heatmap.png`, [`HEATMAP_SIZE`]): S·cos²θ_i (luminance) over
//!   θ_i ∈ [−85°, 85°] × φ ∈ [−180°, 180°] for θ_r ∈ [`HEATMAP_THETA_R`], one row per θ_r:
//!   analytic | baked on a shared log scale over [`DECADES`] decades, and their signed
//!   relative error on a diverging scale of ± the E_peak budget. Each panel is
//!   [`PANEL_W`] × [`PANEL_H`] pixels, one pixel per degree.
//! - [`polar_plots`] (`polar.png`, [`POLAR_SIZE`]): S (luminance) over φ at the fixed
//!   (θ_i, θ_r) of [`POLAR_ANGLES`], one panel per lobe family, analytic solid and baked
//!   dashed, radius log-scaled over three decades.

use crate::plot::{
    colour_bar, decade_label, diverging, sequential, text_width, Canvas, ANALYTIC_COLOUR,
    BAKED_COLOUR, BLACK, GREY, LIGHT_GREY, WHITE,
};
use bcsdf_core::{Angles, Bcsdf, LobeFamily, Rgb};
use rayon::prelude::*;

/// Luminance (Rec. 709 weights) of a linear RGB value.
pub fn luminance(c: Rgb) -> f64 {
    0.2126 * f64::from(c.0[0]) + 0.7152 * f64::from(c.0[1]) + 0.0722 * f64::from(c.0[2])
}

/// θ_r of the heat-map rows, degrees.
pub const HEATMAP_THETA_R: [f32; 4] = [-30.0, 0.0, 30.0, 60.0];
/// Width of one heat-map panel (φ, one pixel per degree).
pub const PANEL_W: usize = 360;
/// Height of one heat-map panel (θ_i from 85° at the top to −85° at the bottom).
pub const PANEL_H: usize = 170;
/// Decades shown by the log colour scale.
pub const DECADES: i32 = 4;

const LEFT: usize = 72;
const GAP: usize = 40;
const BAR_BLOCK: usize = 76;
const RIGHT: usize = 10;
const TOP: usize = 50;
const ROW_TITLE: usize = 16;
const ROW_BOTTOM: usize = 36;
const ROW_H: usize = ROW_TITLE + PANEL_H + ROW_BOTTOM;

/// Size of `heatmap.png`: 1394 × 942 pixels.
pub const HEATMAP_SIZE: (usize, usize) = (
    LEFT + 3 * PANEL_W + 2 * GAP + 2 * BAR_BLOCK + RIGHT,
    TOP + HEATMAP_THETA_R.len() * ROW_H + 4,
);

/// (θ_i, θ_r) of the polar-plot rows, degrees.
pub const POLAR_ANGLES: [(f32, f32); 3] = [(30.0, -20.0), (0.0, 0.0), (60.0, -50.0)];
/// φ samples per polar curve (every half degree, both ends).
const POLAR_SAMPLES: usize = 721;
const CELL_W: usize = 250;
const CELL_H: usize = 270;
const POLAR_HEADER: usize = 52;
const POLAR_RADIUS: f32 = 96.0;

/// Size of `polar.png`: 1016 × 870 pixels.
pub const POLAR_SIZE: (usize, usize) = (
    16 + LobeFamily::ALL.len() * CELL_W,
    POLAR_HEADER + POLAR_ANGLES.len() * CELL_H + 8,
);

/// A heat-map panel's pixel centre → (θ_i, φ) in degrees.
fn panel_angles(px: usize, py: usize) -> (f32, f32) {
    let phi = -180.0 + (px as f32 + 0.5) * 360.0 / PANEL_W as f32;
    let theta_i = 85.0 - (py as f32 + 0.5) * 170.0 / PANEL_H as f32;
    (theta_i, phi)
}

/// Draws the heat-map figure of `analytic` vs `baked`; `error_scale` is the relative error
/// at the ends of the diverging colour bar (the E_peak budget).
pub fn heat_maps<A, B>(analytic: &A, baked: &B, title: &str, error_scale: f64) -> Canvas
where
    A: Bcsdf + Sync,
    B: Bcsdf + Sync,
{
    // One line of one panel pair per task: (row, py) → PANEL_W values each.
    let rows = HEATMAP_THETA_R.len();
    let lines: Vec<(Vec<f64>, Vec<f64>)> = (0..rows * PANEL_H)
        .into_par_iter()
        .map(|line| {
            let (j, py) = (line / PANEL_H, line % PANEL_H);
            let mut a = Vec::with_capacity(PANEL_W);
            let mut b = Vec::with_capacity(PANEL_W);
            for px in 0..PANEL_W {
                let (ti, phi) = panel_angles(px, py);
                let angles = Angles::from_degrees(ti, HEATMAP_THETA_R[j], phi)
                    .expect("heat-map angles are in range");
                let w = f64::from(ti.to_radians().cos()).powi(2);
                a.push(luminance(analytic.eval(&angles).total()) * w);
                b.push(luminance(baked.eval(&angles).total()) * w);
            }
            (a, b)
        })
        .collect();

    let peak = lines
        .iter()
        .flat_map(|(a, _)| a.iter())
        .fold(0.0f64, |m, &v| m.max(v));
    let top = if peak > 0.0 {
        peak.log10().ceil() as i32
    } else {
        0
    };
    let lo = top - DECADES;
    let floor = 10f64.powi(lo + 1);
    let log_t = |v: f64| {
        if v > 0.0 {
            ((v.log10() - f64::from(lo)) / f64::from(DECADES)) as f32
        } else {
            0.0
        }
    };
    let err_scale = if error_scale > 0.0 { error_scale } else { 0.01 };

    let (w, h) = HEATMAP_SIZE;
    let mut c = Canvas::new(w, h, WHITE);
    c.text(LEFT as i64, 8, title, BLACK, 2);
    c.text(
        LEFT as i64,
        30,
        &format!(
            "S cos^2(theta_i), luminance; log scale over {DECADES} decades. Relative error = (baked - analytic) / max(analytic, {}); colour bar ends at +/-{} %",
            decade_label(lo + 1),
            fmt_percent(err_scale)
        ),
        GREY,
        1,
    );

    let x_analytic = LEFT;
    let x_baked = x_analytic + PANEL_W + GAP;
    let x_error = x_baked + PANEL_W + BAR_BLOCK + GAP;
    for (j, &theta_r) in HEATMAP_THETA_R.iter().enumerate() {
        let y0 = TOP + j * ROW_H;
        let py0 = y0 + ROW_TITLE;
        for py in 0..PANEL_H {
            let (a, b) = &lines[j * PANEL_H + py];
            for px in 0..PANEL_W {
                let (va, vb) = (a[px], b[px]);
                let e = (vb - va) / va.max(floor);
                let yy = (py0 + py) as i64;
                c.set((x_analytic + px) as i64, yy, sequential(log_t(va)));
                c.set((x_baked + px) as i64, yy, sequential(log_t(vb)));
                c.set((x_error + px) as i64, yy, diverging((e / err_scale) as f32));
            }
        }
        let titles = [
            (x_analytic, "analytic"),
            (x_baked, "baked"),
            (x_error, "relative error"),
        ];
        for (x, name) in titles {
            c.text(
                x as i64,
                (y0 + 4) as i64,
                &format!("{name}, theta_r = {theta_r} deg"),
                BLACK,
                1,
            );
            axes(&mut c, x, py0, x == x_analytic);
        }
        let decade_ticks: Vec<(f32, String)> = (0..=DECADES)
            .map(|k| (k as f32 / DECADES as f32, decade_label(lo + k)))
            .collect();
        colour_bar(
            &mut c,
            (
                (x_baked + PANEL_W + 10) as i64,
                py0 as i64,
                14,
                PANEL_H as i64,
            ),
            &sequential,
            &decade_ticks,
        );
        let s = err_scale;
        let error_ticks: Vec<(f32, String)> = [-1.0, -0.5, 0.0, 0.5, 1.0]
            .iter()
            .map(|&f| {
                let label = if f == 0.0 {
                    "0".to_string()
                } else {
                    format!(
                        "{}{}%",
                        if f > 0.0 { "+" } else { "-" },
                        fmt_percent(s * f64::abs(f))
                    )
                };
                ((f as f32 + 1.0) / 2.0, label)
            })
            .collect();
        colour_bar(
            &mut c,
            (
                (x_error + PANEL_W + 10) as i64,
                py0 as i64,
                14,
                PANEL_H as i64,
            ),
            &|t| diverging(2.0 * t - 1.0),
            &error_ticks,
        );
    }
    c
}

/// Outline, ticks and tick labels of a heat-map panel at (x, y); `labels_y` adds the θ_i
/// tick numbers and axis label on the left.
fn axes(c: &mut Canvas, x: usize, y: usize, labels_y: bool) {
    let (x, y) = (x as i64, y as i64);
    let (pw, ph) = (PANEL_W as i64, PANEL_H as i64);
    c.outline(x, y, pw, ph, BLACK);
    for phi in [-180, -90, 0, 90, 180] {
        let tx = x + ((phi + 180) as i64 * pw / 360).min(pw - 1);
        c.fill_rect(tx, y + ph + 1, 1, 4, BLACK);
        c.text_centred(tx, y + ph + 7, &phi.to_string(), BLACK, 1);
    }
    c.text_centred(x + pw / 2, y + ph + 21, "phi (deg)", BLACK, 1);
    for theta in [-60, -30, 0, 30, 60] {
        let ty = y + ((85 - theta) as i64 * ph / 170);
        c.fill_rect(x - 5, ty, 4, 1, BLACK);
        if labels_y {
            c.text_right(x - 8, ty - 3, &theta.to_string(), BLACK, 1);
        }
    }
    if labels_y {
        c.text_vertical(x - 62, y + ph / 2, "theta_i (deg)", BLACK);
    }
}

/// A fraction as a short percentage: `2`, `0.5`, `0.25`.
fn fmt_percent(f: f64) -> String {
    let s = format!("{:.3}", 100.0 * f);
    s.trim_end_matches('0').trim_end_matches('.').to_string()
}

/// Draws the polar-plot figure: per (θ_i, θ_r) row and lobe family column, S over φ.
pub fn polar_plots<A, B>(analytic: &A, baked: &B, title: &str) -> Canvas
where
    A: Bcsdf + Sync,
    B: Bcsdf + Sync,
{
    let (w, h) = POLAR_SIZE;
    let mut c = Canvas::new(w, h, WHITE);
    c.text(16, 8, title, BLACK, 2);
    c.text(
        16,
        30,
        "S (luminance) over phi per lobe family; radius: log10 S over 3 decades (rings); phi = 0 right, 90 up",
        GREY,
        1,
    );
    // Legend, top right.
    let lx = (w - 230) as f32;
    c.line((lx, 12.0), (lx + 30.0, 12.0), ANALYTIC_COLOUR, 2.0);
    c.text(lx as i64 + 38, 8, "analytic", BLACK, 1);
    c.polyline(
        &[(lx + 110.0, 12.0), (lx + 140.0, 12.0)],
        BAKED_COLOUR,
        2.0,
        Some((6.0, 4.0)),
    );
    c.text(lx as i64 + 148, 8, "baked", BLACK, 1);

    let curves: Vec<[Vec<f64>; 2]> = POLAR_ANGLES
        .par_iter()
        .flat_map(|&(ti, tr)| {
            LobeFamily::ALL.par_iter().map(move |&family| {
                let eval = |f: &dyn Fn(&Angles) -> Rgb| -> Vec<f64> {
                    (0..POLAR_SAMPLES)
                        .map(|k| {
                            let phi = -180.0 + 360.0 * k as f32 / (POLAR_SAMPLES - 1) as f32;
                            let angles = Angles::from_degrees(ti, tr, phi)
                                .expect("polar angles are in range");
                            luminance(f(&angles))
                        })
                        .collect()
                };
                [
                    eval(&|a| analytic.eval(a).get(family)),
                    eval(&|a| baked.eval(a).get(family)),
                ]
            })
        })
        .collect();

    for (row, &(ti, tr)) in POLAR_ANGLES.iter().enumerate() {
        for (col, family) in LobeFamily::ALL.iter().enumerate() {
            let [a, b] = &curves[row * LobeFamily::ALL.len() + col];
            let x0 = 8 + col * CELL_W;
            let y0 = POLAR_HEADER + row * CELL_H;
            polar_panel(&mut c, (x0, y0), family.name(), a, b);
        }
        let y0 = (POLAR_HEADER + row * CELL_H) as i64;
        c.fill_rect(8, y0, (w - 16) as i64, 1, LIGHT_GREY);
        c.text(
            8,
            y0 + 4,
            &format!("theta_i = {ti} deg, theta_r = {tr} deg"),
            BLACK,
            1,
        );
    }
    c
}

/// One polar panel with its cell's top-left corner at `origin`.
fn polar_panel(c: &mut Canvas, origin: (usize, usize), title: &str, a: &[f64], b: &[f64]) {
    let cx = (origin.0 + CELL_W / 2) as f32;
    let cy = (origin.1 + 146) as f32;
    let r = POLAR_RADIUS;
    c.text_centred(cx as i64, origin.1 as i64 + 20, title, BLACK, 1);
    let peak = a.iter().chain(b).fold(0.0f64, |m, &v| m.max(v));
    // Spokes every 45°, outer circle and labels.
    for k in 0..8 {
        let ang = std::f32::consts::FRAC_PI_4 * k as f32;
        c.line(
            (cx, cy),
            (cx + r * ang.cos(), cy - r * ang.sin()),
            LIGHT_GREY,
            1.0,
        );
    }
    for (deg, dx, dy) in [
        ("0", 1.0, 0.0),
        ("90", 0.0, -1.0),
        ("180", -1.0, 0.0),
        ("-90", 0.0, 1.0),
    ] {
        let lw = text_width(deg, 1) as f32;
        let x = cx
            + dx * (r + 6.0)
            + if dx < 0.0 {
                -lw
            } else if dx == 0.0 {
                -lw / 2.0
            } else {
                0.0
            };
        let y = cy
            + dy * (r + 6.0)
            + if dy < 0.0 {
                -8.0
            } else if dy == 0.0 {
                -4.0
            } else {
                0.0
            };
        c.text(x as i64, y as i64, deg, GREY, 1);
    }
    if !(peak > 0.0 && peak.is_finite()) {
        c.circle((cx, cy), r, LIGHT_GREY, 1.0);
        c.text_centred(cx as i64, cy as i64 - 12, "zero: no medulla", GREY, 1);
        c.text_centred(cx as i64, cy as i64 + 4, "scattering", GREY, 1);
        return;
    }
    let top = peak.log10().ceil() as i32;
    let lo = top - 3;
    for k in 1..=3 {
        let rr = r * k as f32 / 3.0;
        c.circle((cx, cy), rr, if k == 3 { GREY } else { LIGHT_GREY }, 1.0);
        // Ring labels along the spoke at -60 degrees (lower right).
        let (dx, dy) = (0.5 * rr, 0.866 * rr);
        c.text(
            (cx + dx) as i64 + 3,
            (cy + dy) as i64 - 4,
            &decade_label(lo + k),
            GREY,
            1,
        );
    }
    let to_points = |v: &[f64]| -> Vec<(f32, f32)> {
        v.iter()
            .enumerate()
            .map(|(k, &s)| {
                let phi = (-180.0 + 360.0 * k as f32 / (v.len() - 1) as f32).to_radians();
                let t = if s > 0.0 {
                    ((s.log10() - f64::from(lo)) / 3.0).clamp(0.0, 1.0) as f32
                } else {
                    0.0
                };
                (cx + r * t * phi.cos(), cy - r * t * phi.sin())
            })
            .collect()
    };
    c.polyline(&to_points(a), ANALYTIC_COLOUR, 2.0, None);
    c.polyline(&to_points(b), BAKED_COLOUR, 1.5, Some((5.0, 4.0)));
}

#[cfg(test)]
mod tests {
    use super::*;
    use bcsdf_core::Families;

    /// A far field that is 1 for the R family everywhere.
    struct Flat(f32);
    impl Bcsdf for Flat {
        type Math = bcsdf_core::Libm;
        fn eval(&self, _: &Angles) -> Families {
            Families::from_array([Rgb::splat(self.0), Rgb::ZERO, Rgb::ZERO, Rgb::ZERO])
        }
        fn pdf(&self, _: &Angles) -> f32 {
            0.0
        }
        fn sample_direction(&self, _: f32, _: [f32; 3]) -> Option<bcsdf_core::SampledDirection> {
            None
        }
    }

    #[test]
    fn figures_have_their_documented_sizes() {
        let hm = heat_maps(&Flat(1.0), &Flat(1.01), "test", 0.02);
        assert_eq!((hm.width(), hm.height()), HEATMAP_SIZE);
        assert_eq!(HEATMAP_SIZE, (1394, 942));
        let polar = polar_plots(&Flat(1.0), &Flat(1.0), "test");
        assert_eq!((polar.width(), polar.height()), POLAR_SIZE);
        assert_eq!(POLAR_SIZE, (1016, 870));
        // A +1 % error on a ±2 % scale is a light red in the error panel.
        let px = hm.get(
            LEFT + 2 * PANEL_W + 2 * GAP + BAR_BLOCK + 180,
            TOP + ROW_TITLE + 85,
        );
        assert!(px[0] > px[2] + 40, "{px:?}");
    }
}
