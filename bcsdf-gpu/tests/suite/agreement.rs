//! The WGSL evaluator on a real Vulkan device (a GPU, or Mesa's llvmpipe) against
//! `BakedBcsdf::eval_far`, for every preset: 2¹⁶ random directions plus edge cases (θ at
//! ±89.9° and ±90°, φ at 0 and ±π, NaN and out-of-range angles the CPU maps to zero, grazing
//! and degenerate vectors), in both closures (the energy closure reads the LUT's 1/Z_g table). Per channel and family: |gpu − cpu| ≤ 1e-5·max(cpu, 1e-3·peak),
//! peak the largest value of that channel and family over the queries. A shader with one
//! table index off by one must fail the same check.
//!
//! Colour (LUT format 5): the queries above run at the LUT's own colour (`GpuLut::eval`, the
//! preset's σ_ca); 2¹⁴ angle queries, the vector queries, the pdfs and the samples run again
//! each at a random colour (`random_colour`: channels over [0, 1000], 0 and ≥ 100 included,
//! some above 1000, which both sides clamp) against `BakedBcsdf::at`, within the same bound
//! plus the CPU's own change when the absorption coordinate's exponential e^(−σ/s0) moves by
//! two ulps ([`colour_slack`]): the shader's `fur_pow2_neg` can differ from the CPU's
//! `math::pow2_neg` in the last bit where the compiler fuses a multiply and an add, and next to a node where a family falls by orders of magnitude
//! (bobcat's TRT between the first two planes) the quadratic weights turn that ulp into 7e-5
//! of the value. A shader whose absorption coordinate is wrong must fail that check.
//!
//! Without an adapter the tests print "skipped: no GPU adapter" and pass, unless
//! `FUR_BCSDF_REQUIRE_GPU=1` (set by `.ci/run`), which makes a missing adapter a failure.

use crate::common;

use bcsdf_core::baked::BakedBcsdf;
use bcsdf_core::lut::LutResolution;
use bcsdf_core::rng::{cell_stream, Pcg32};
use bcsdf_core::shader::FUR_BCSDF_WGSL;
use bcsdf_core::{presets, Absorption, Angles, Bcsdf, Closure, Rgb};
use bcsdf_gpu::{GpuFamilies, GpuLut, SampleQuery};
use common::{or_skip, preset_lut};
use std::f32::consts::{FRAC_PI_2, PI};

/// The default LUT resolution with six absorption planes instead of 22 (the quadratic
/// cells still start at four different planes: two residual simulations per energy-closure
/// bake instead of eight) and a quarter of its |θ_r| rows and |φ| nodes (16 × 32: the 24 LUTs
/// of this file bake in a sixteenth of the time). GPU = CPU on one LUT depends on neither:
/// the shader reads whatever sizes the header states, and other sizes than the default
/// exercise that; colour_budget and bake_budget measure the default's accuracy. (The dual
/// test keeps the default: its tables are computed from the LUT, and its GPU margin was
/// measured on those.)
const TEST_RESOLUTION: LutResolution = LutResolution {
    n_abs: 6,
    n_theta_r: 16,
    n_phi: 32,
    ..LutResolution::DEFAULT
};

const RELATIVE: f32 = 1e-5;
/// The pdf's bound within 1e-2 rad of the poles, where p/cos θ_i magnifies a last-bit
/// difference in π/2 − |θ_i| or a sampled direction: 2.8e-6 measured on llvmpipe; 5.4e-4
/// (and 1.9e-4 for the samples' pdfs) while the shader let the compiler fold π/2's low part.
const POLE_RELATIVE: f32 = 1e-4;
/// The samples' weights S·cos θ_i/pdf at random colours, where GPU and CPU drew the same
/// direction (within 1e-4 rad, away from the poles), beyond the colour's last-bit slack: 3.8e-5
/// measured on llvmpipe (red fox; every preset 4e-6 to 3.8e-5). S and the pdf each agree
/// within RELATIVE; the rest comes from the direction's last bits and the shader's built-in
/// cos θ_i against the CPU's libm (not separated).
const SAMPLE_WEIGHT_RELATIVE: f32 = 1e-4;

fn queries() -> Vec<[f32; 3]> {
    let mut q = Vec::new();
    for i in 0..(1u64 << 16) {
        let mut r = Pcg32::new(cell_stream(7, 1, i), cell_stream(7, 2, i));
        q.push([
            (r.uniform() - 0.5) * PI,
            (r.uniform() - 0.5) * PI,
            (r.uniform() - 0.5) * 2.0 * PI,
        ]);
    }
    let edge_t = [
        89.9f32.to_radians(),
        -89.9f32.to_radians(),
        FRAC_PI_2,
        -FRAC_PI_2,
        0.0,
    ];
    let edge_p = [0.0f32, PI, -PI, 1e-7, PI - 1e-6, 7.0, -7.0];
    for &a in &edge_t {
        for &b in &edge_t {
            for &c in &edge_p {
                q.push([a, b, c]);
            }
        }
    }
    for bad in [
        [f32::NAN, 0.1, 0.2],
        [0.1, f32::NAN, 0.2],
        [0.1, 0.2, f32::NAN],
        [f32::INFINITY, 0.1, 0.2],
        [0.1, 0.2, f32::NEG_INFINITY],
        [1.6, 0.1, 0.2],
        [0.1, -1.6, 0.2],
    ] {
        q.push(bad);
    }
    q
}

/// A random colour for query `i`: each channel 0 (1 in 8), in [100, 1000] (1 in 8), 1000 or
/// above (1 in 16: 1000, 1500 or +inf, clamped to 1000 by both sides), else log-uniform over
/// [1e-3, 100] (the absorption axis's knee is near s0 = 1.25).
fn random_colour(i: u64) -> [f32; 3] {
    let mut r = Pcg32::new(cell_stream(13, 1, i), cell_stream(13, 2, i));
    core::array::from_fn(|_| {
        let pick = r.uniform();
        let v = r.uniform();
        if pick < 0.125 {
            0.0
        } else if pick < 0.25 {
            100.0 + 900.0 * v
        } else if pick < 0.3125 {
            [1000.0, 1500.0, f32::INFINITY][(3.0 * v) as usize % 3]
        } else {
            10f32.powf(5.0 * v - 3.0)
        }
    })
}

/// `sigma` with each channel's e^(−σ/s0) moved by `ulps` units in the last place of 1 (f64
/// arithmetic, clamped to [0, 1000]): the colours whose absorption coordinate differs from
/// `sigma`'s in its last bits.
fn nudged(sigma: &[f32; 3], scale: f32, ulps: f64) -> [f32; 3] {
    sigma.map(|s| {
        let s = f64::from(s.min(1000.0));
        let e = (-s / f64::from(scale)).exp() + ulps * f64::from(f32::EPSILON) / 2.0;
        let e = e.clamp(1e-300, 1.0);
        (-f64::from(scale) * e.ln()).clamp(0.0, 1000.0) as f32
    })
}

/// Per value, how far the CPU's result moves when every channel's e^(−σ/s0) moves by two
/// ulps either way: the part of a GPU–CPU difference that the absorption coordinate's last
/// bit accounts for. `eval` gives the CPU's values at a colour.
fn colour_slack(
    sigma: &[f32; 3],
    scale: f32,
    eval: impl Fn(&[f32; 3]) -> GpuFamilies,
) -> GpuFamilies {
    let mid = eval(sigma);
    let lo = eval(&nudged(sigma, scale, -2.0));
    let hi = eval(&nudged(sigma, scale, 2.0));
    core::array::from_fn(|k| (lo[k] - mid[k]).abs().max((hi[k] - mid[k]).abs()))
}

/// The CPU at colour `sigma`.
fn cpu_colour(sigma: &[f32; 3]) -> Absorption {
    Absorption::from_sigma(Rgb(*sigma)).unwrap()
}

fn cpu_angles(lut: &BakedBcsdf<'_>, q: &[f32; 3]) -> GpuFamilies {
    match Angles::new(q[0], q[1], q[2]) {
        Ok(a) => flatten(lut.eval_far(&a)),
        Err(_) => [0.0; 15],
    }
}

fn flatten(f: bcsdf_core::Families) -> GpuFamilies {
    let mut v = [0.0f32; 15];
    for (k, c) in f.as_array().iter().chain([f.total()].iter()).enumerate() {
        v[3 * k..3 * k + 3].copy_from_slice(&c.0);
    }
    v
}

/// The worst |gpu − cpu| / max(cpu, 1e-3·peak) over all queries and values.
fn worst(cpu: &[GpuFamilies], gpu: &[GpuFamilies]) -> (f32, usize) {
    worst_with(cpu, gpu, &vec![[0.0; 15]; cpu.len()])
}

/// [`worst`] of the difference less `slack` (per query and value, at least 0).
fn worst_with(cpu: &[GpuFamilies], gpu: &[GpuFamilies], slack: &[GpuFamilies]) -> (f32, usize) {
    let mut peak = [0.0f32; 15];
    for v in cpu {
        for (p, x) in peak.iter_mut().zip(v) {
            *p = p.max(*x);
        }
    }
    let mut w = (0.0f32, 0);
    for (i, (c, g)) in cpu.iter().zip(gpu).enumerate() {
        for k in 0..15 {
            let scale = c[k].max(1e-3 * peak[k]).max(f32::MIN_POSITIVE);
            let e = ((g[k] - c[k]).abs() - slack[i][k]).max(0.0) / scale;
            let e = if e.is_nan() { f32::INFINITY } else { e };
            if e > w.0 {
                w = (e, i);
            }
        }
    }
    w
}

#[test]
fn gpu_matches_cpu_for_every_preset() {
    for (preset, closure) in presets::PRESETS
        .iter()
        .flat_map(|p| Closure::ALL.map(|c| (p, c)))
    {
        println!("{} in the {closure:?} closure:", preset.name);
        let bytes = preset_lut(preset.name, closure, TEST_RESOLUTION);
        let Some(g) = or_skip(GpuLut::with_shader(&bytes, FUR_BCSDF_WGSL)) else {
            return;
        };
        let cpu_lut = BakedBcsdf::from_bytes(&bytes).unwrap();
        let q = queries();
        let cpu: Vec<GpuFamilies> = q.iter().map(|a| cpu_angles(&cpu_lut, a)).collect();
        let got = g.eval(&q).unwrap();
        let (e, at) = worst(&cpu, &got);
        println!(
            "{} on {}: {} angle queries, worst relative difference {e:.2e} at {:?}",
            preset.name,
            g.adapter_name(),
            q.len(),
            q[at]
        );
        assert!(
            e <= RELATIVE,
            "{}: {e} at {:?}: cpu {:?} gpu {:?}",
            preset.name,
            q[at],
            cpu[at],
            got[at]
        );

        // The first 2^14 angle queries (and the edge and invalid ones), each at a random colour.
        let cq: Vec<([f32; 3], [f32; 3])> = q
            .iter()
            .enumerate()
            .filter(|&(i, _)| !(1 << 14..1 << 16).contains(&i))
            .map(|(i, a)| (*a, random_colour(i as u64)))
            .collect();
        let cpu: Vec<GpuFamilies> = cq
            .iter()
            .map(|(a, s)| match Angles::new(a[0], a[1], a[2]) {
                Ok(x) => flatten(cpu_lut.at(&cpu_colour(s)).eval_far(&x)),
                Err(_) => [0.0; 15],
            })
            .collect();
        let got = g.eval_at(&cq).unwrap();
        let scale = cpu_lut.header().absorption_scale();
        let slack: Vec<GpuFamilies> = cq
            .iter()
            .map(|(a, s)| match Angles::new(a[0], a[1], a[2]) {
                Ok(x) => colour_slack(s, scale, |c| {
                    flatten(cpu_lut.at(&cpu_colour(c)).eval_far(&x))
                }),
                Err(_) => [0.0; 15],
            })
            .collect();
        let (plain, _) = worst(&cpu, &got);
        let (e, at) = worst_with(&cpu, &got, &slack);
        println!(
            "{}: {} angle queries at random colours, worst relative difference {plain:.2e}; {e:.2e} beyond the coordinate's last bit, at {:?}",
            preset.name,
            cq.len(),
            cq[at]
        );
        assert!(
            e <= RELATIVE,
            "{}: {e} at {:?}: cpu {:?} gpu {:?}",
            preset.name,
            cq[at],
            cpu[at],
            got[at]
        );

        // Vectors: random, grazing (along the fiber), degenerate (zero, NaN).
        let mut vq: Vec<[[f32; 3]; 3]> = Vec::new();
        for i in 0..4096u64 {
            let mut r = Pcg32::new(cell_stream(9, 1, i), cell_stream(9, 2, i));
            let mut v = || [r.uniform() - 0.5, r.uniform() - 0.5, r.uniform() - 0.5];
            vq.push([v(), v(), v()]);
        }
        let t = [0.2f32, -0.4, 0.9];
        vq.push([t, [0.3, 0.1, 0.0], t]);
        vq.push([[0.3, 0.1, 0.0], t, t]);
        vq.push([[0.0; 3], [0.3, 0.1, 0.0], t]);
        vq.push([[0.3, 0.1, 0.0], [0.3, 0.1, 0.0], [0.0; 3]]);
        vq.push([[f32::NAN, 0.1, 0.0], [0.3, 0.1, 0.0], t]);
        let cpu: Vec<GpuFamilies> = vq
            .iter()
            .map(|v| flatten(Bcsdf::eval_dirs(&cpu_lut, v[0], v[1], v[2])))
            .collect();
        let got = g.eval_dirs(&vq).unwrap();
        // The edge cases (the last five: grazing, zero, NaN) meet the angle budget.
        let edges = vq.len() - 5;
        let (e_edge, _) = worst(&cpu[edges..], &got[edges..]);
        println!(
            "{}: vector edge cases, worst relative difference {e_edge:.2e}",
            preset.name
        );
        assert!(
            e_edge <= RELATIVE,
            "{}: vector edge cases {e_edge}",
            preset.name
        );
        let (e, at) = worst(&cpu, &got);
        println!(
            "{}: {} vector queries, worst relative difference {e:.2e}",
            preset.name,
            vq.len()
        );
        // From vectors both sides run the same branch-free polynomial conversion
        // (frame::polynomial_angles): the angle budget holds for random vectors too.
        assert!(
            e <= RELATIVE,
            "{}: {e} at {:?}: cpu {:?} gpu {:?}",
            preset.name,
            vq[at],
            cpu[at],
            got[at]
        );
        // The vector queries again, each at a random colour.
        let cvq: Vec<([[f32; 3]; 3], [f32; 3])> = vq
            .iter()
            .enumerate()
            .map(|(i, v)| (*v, random_colour(1 << 20 | i as u64)))
            .collect();
        let cpu: Vec<GpuFamilies> = cvq
            .iter()
            .map(|(v, s)| {
                flatten(Bcsdf::eval_dirs(
                    &cpu_lut.at(&cpu_colour(s)),
                    v[0],
                    v[1],
                    v[2],
                ))
            })
            .collect();
        let got = g.eval_dirs_at(&cvq).unwrap();
        let slack: Vec<GpuFamilies> = cvq
            .iter()
            .map(|(v, s)| {
                colour_slack(s, scale, |c| {
                    flatten(Bcsdf::eval_dirs(
                        &cpu_lut.at(&cpu_colour(c)),
                        v[0],
                        v[1],
                        v[2],
                    ))
                })
            })
            .collect();
        let (plain, _) = worst(&cpu, &got);
        let (e, at) = worst_with(&cpu, &got, &slack);
        println!(
            "{}: {} vector queries at random colours, worst relative difference {plain:.2e}; {e:.2e} beyond the coordinate's last bit",
            preset.name,
            cvq.len()
        );
        assert!(
            e <= RELATIVE,
            "{}: {e} at {:?}: cpu {:?} gpu {:?}",
            preset.name,
            cvq[at],
            cpu[at],
            got[at]
        );
    }
}

#[test]
fn a_wrong_absorption_coordinate_is_caught() {
    // sigma * s0 instead of sigma / s0: right at sigma = 0 (the lossless plane) and at the
    // clamped end, wrong in between, where the random colours lie.
    let bytes = preset_lut("human-hair", Closure::Report, TEST_RESOLUTION);
    let wrong = FUR_BCSDF_WGSL.replace(
        "fur_pow2_neg(s / scale * FUR_LOG2_E)",
        "fur_pow2_neg(s * scale * FUR_LOG2_E)",
    );
    assert_ne!(wrong, FUR_BCSDF_WGSL, "the mutation applies");
    let Some(g) = or_skip(GpuLut::with_shader(&bytes, &wrong)) else {
        return;
    };
    let cpu_lut = BakedBcsdf::from_bytes(&bytes).unwrap();
    let cq: Vec<([f32; 3], [f32; 3])> = queries()
        .into_iter()
        .take(1 << 12)
        .enumerate()
        .map(|(i, a)| (a, random_colour(i as u64)))
        .collect();
    let cpu: Vec<GpuFamilies> = cq
        .iter()
        .map(|(a, s)| {
            let x = Angles::new(a[0], a[1], a[2]).unwrap();
            flatten(cpu_lut.at(&cpu_colour(s)).eval_far(&x))
        })
        .collect();
    let (e, _) = worst(&cpu, &g.eval_at(&cq).unwrap());
    println!("wrong absorption coordinate: worst relative difference {e:.2e}");
    assert!(
        e > RELATIVE,
        "the colour check missed a wrong absorption coordinate ({e})"
    );
}

#[test]
fn an_off_by_one_table_index_is_caught() {
    let bytes = preset_lut("human-hair", Closure::Report, TEST_RESOLUTION);
    let wrong = FUR_BCSDF_WGSL.replace(
        "let b = fur_half(m0 + 3u * (lm.i + 1u) + ch);",
        "let b = fur_half(m0 + 3u * (lm.i + 2u) + ch);",
    );
    assert_ne!(wrong, FUR_BCSDF_WGSL, "the mutation applies");
    let Some(g) = or_skip(GpuLut::with_shader(&bytes, &wrong)) else {
        return;
    };
    let cpu_lut = BakedBcsdf::from_bytes(&bytes).unwrap();
    let q = queries();
    let cpu: Vec<GpuFamilies> = q.iter().map(|a| cpu_angles(&cpu_lut, a)).collect();
    let got = g.eval(&q).unwrap();
    let (e, _) = worst(&cpu, &got);
    println!("off by one: worst relative difference {e:.2e}");
    assert!(
        e > RELATIVE,
        "the agreement check missed an off-by-one index ({e})"
    );
}

#[test]
fn gpu_pdf_and_samples_match_cpu() {
    for (preset, closure) in presets::PRESETS
        .iter()
        .flat_map(|p| Closure::ALL.map(|c| (p, c)))
    {
        println!("{} in the {closure:?} closure:", preset.name);
        let bytes = preset_lut(preset.name, closure, TEST_RESOLUTION);
        let Some(g) = or_skip(GpuLut::with_shader(&bytes, FUR_BCSDF_WGSL)) else {
            return;
        };
        let cpu_lut = BakedBcsdf::from_bytes(&bytes).unwrap();
        // pdf at the angle queries (the invalid ones give 0 on both sides).
        let q = queries();
        let cpu: Vec<f32> = q
            .iter()
            .map(|a| Angles::new(a[0], a[1], a[2]).map_or(0.0, |x| cpu_lut.pdf(&x)))
            .collect();
        let got = g.pdf(&q).unwrap();
        let peak = cpu.iter().copied().fold(0.0f32, f32::max);
        let (mut worst, mut at) = (0.0f32, 0);
        let mut worst_pole = 0.0f32;
        for (i, (c, x)) in cpu.iter().zip(&got).enumerate() {
            // Within 1e-2 rad of the fiber axis (where S itself runs on the guarded 1/cos²θ_i)
            // the solid-angle conversion p/cos θ_i magnifies the last bit of π/2 − |θ_i|
            // (formed with a two-float π/2, whose low part the shader hides from constant
            // folding): checked separately, at POLE_RELATIVE.
            if q[i][0].abs() > FRAC_PI_2 - 1e-2 {
                let e = (x - c).abs() / c.max(1e-3 * peak);
                worst_pole = worst_pole.max(if e.is_nan() { f32::INFINITY } else { e });
                continue;
            }
            let e = (x - c).abs() / c.max(1e-3 * peak);
            let e = if e.is_nan() { f32::INFINITY } else { e };
            if e > worst {
                (worst, at) = (e, i);
            }
        }
        println!(
            "{}: pdf worst relative difference {worst:.2e} at {:?} (cpu {}, gpu {})",
            preset.name, q[at], cpu[at], got[at]
        );
        println!(
            "{}: pdf within 1e-2 rad of the poles: {worst_pole:.2e}",
            preset.name
        );
        assert!(worst <= RELATIVE, "{}: pdf {worst}", preset.name);
        assert!(
            worst_pole <= POLE_RELATIVE,
            "{}: pdf near the poles {worst_pole}",
            preset.name
        );

        // The pdf at random colours: the lossless plane's density, the same as above.
        let cq: Vec<([f32; 3], [f32; 3])> = q
            .iter()
            .take(1 << 14)
            .enumerate()
            .map(|(i, a)| (*a, random_colour(i as u64)))
            .collect();
        let got_at = g.pdf_at(&cq).unwrap();
        let mut worst_at = 0.0f32;
        for (i, ((a, s), x)) in cq.iter().zip(&got_at).enumerate() {
            let c =
                Angles::new(a[0], a[1], a[2]).map_or(0.0, |x| cpu_lut.at(&cpu_colour(s)).pdf(&x));
            assert_eq!(
                c.to_bits(),
                cpu[i].to_bits(),
                "the CPU's pdf depends on the colour"
            );
            if a[0].abs() <= FRAC_PI_2 - 1e-2 {
                let e = (x - c).abs() / c.max(1e-3 * peak);
                worst_at = worst_at.max(if e.is_nan() { f32::INFINITY } else { e });
            }
        }
        println!(
            "{}: pdf at random colours, worst relative difference {worst_at:.2e}",
            preset.name
        );
        assert!(
            worst_at <= RELATIVE,
            "{}: pdf at colours {worst_at}",
            preset.name
        );

        // Samples: the same uniforms on both sides.
        let n = 1u64 << 14;
        let sq: Vec<(f32, [f32; 3])> = (0..n)
            .map(|i| {
                let mut r = Pcg32::new(cell_stream(11, 1, i), cell_stream(11, 2, i));
                (
                    (r.uniform() - 0.5) * 0.99 * PI,
                    [r.uniform(), r.uniform(), r.uniform()],
                )
            })
            .collect();
        let got = g.sample(&sq).unwrap();
        let (mut close, mut count) = (0usize, 0usize);
        let (mut worst_pdf, mut worst_pole_pdf) = (0.0f32, 0.0f32);
        for ((tr, u), gs) in sq.iter().zip(&got) {
            let cs = cpu_lut.sample(*tr, *u);
            assert_eq!(
                cs.is_some(),
                gs.is_some(),
                "{}: theta_r {tr} u {u:?}",
                preset.name
            );
            let (Some(c), Some(s)) = (cs, gs) else {
                continue;
            };
            count += 1;
            let same_dir = (c.angles.theta_i() - s.theta_i).abs() <= 1e-4
                && (c.angles.phi() - s.phi).abs() <= 1e-4
                && c.family as u32 == s.family;
            if same_dir {
                close += 1;
                // The GPU's density against the CPU's `pdf` of the GPU's own direction: near
                // grazing and in a lobe's far tail, a last-bit difference in a row
                // inversion's target moves the direction by a few ulps (6e-7 rad at θ_i =
                // 1.553, where p/cos θ_i turns that into 2e-5), which is not a pdf error.
                let at_gpu = Angles::new(s.theta_i, *tr, s.phi).map_or(0.0, |a| cpu_lut.pdf(&a));
                let e = (at_gpu - s.pdf).abs() / at_gpu;
                if c.angles.theta_i().abs() > FRAC_PI_2 - 1e-2 {
                    worst_pole_pdf = worst_pole_pdf.max(e);
                } else {
                    worst_pdf = worst_pdf.max(e);
                }
            }
        }
        println!(
            "{}: {close} of {count} GPU samples at the CPU's direction (1e-4 rad) and family; pdf there within {worst_pdf:.2e} ({worst_pole_pdf:.2e} within 1e-2 rad of the poles)",
            preset.name
        );
        // A last-bit difference may flip a discrete choice (part, block, segment) for a
        // handful of draws; everything else lands on the same direction.
        assert!(
            close as f64 >= 0.999 * count as f64,
            "{}: {close} of {count}",
            preset.name
        );
        assert!(worst_pdf <= RELATIVE, "{}: pdf {worst_pdf}", preset.name);
        assert!(
            worst_pole_pdf <= POLE_RELATIVE,
            "{}: pdf {worst_pole_pdf}",
            preset.name
        );

        // Samples at random colours: the direction and pdf as at the LUT's own colour, the
        // weight S cos(theta_i)/pdf this colour's, compared where the direction is the CPU's.
        let csq: Vec<(SampleQuery, [f32; 3])> = sq
            .iter()
            .enumerate()
            .map(|(i, s)| (*s, random_colour(1 << 21 | i as u64)))
            .collect();
        let got = g.sample_at(&csq).unwrap();
        let (mut same, mut count, mut worst_w) = (0usize, 0usize, 0.0f32);
        let mut wpeak = [0.0f32; 3];
        let mut pairs = Vec::new();
        for (((tr, u), s), gs) in csq.iter().zip(&got) {
            let cs = cpu_lut.at(&cpu_colour(s)).sample(*tr, *u);
            assert_eq!(
                cs.is_some(),
                gs.is_some(),
                "{}: theta_r {tr} u {u:?}",
                preset.name
            );
            let (Some(c), Some(x)) = (cs, gs) else {
                continue;
            };
            count += 1;
            let same_dir = (c.angles.theta_i() - x.theta_i).abs() <= 1e-4
                && (c.angles.phi() - x.phi).abs() <= 1e-4
                && c.family as u32 == x.family;
            same += usize::from(same_dir);
            if same_dir && c.angles.theta_i().abs() <= FRAC_PI_2 - 1e-2 {
                for (p, w) in wpeak.iter_mut().zip(c.weight.0) {
                    *p = p.max(w);
                }
                // The CPU's weight at the nudged colours (the same direction: the sampler
                // does not depend on the colour).
                let scale = cpu_lut.header().absorption_scale();
                let w = |c: &[f32; 3]| {
                    cpu_lut
                        .at(&cpu_colour(c))
                        .sample(*tr, *u)
                        .map_or([0.0; 3], |q| q.weight.0)
                };
                let (lo, hi) = (w(&nudged(s, scale, -2.0)), w(&nudged(s, scale, 2.0)));
                let slack: [f32; 3] = core::array::from_fn(|k| {
                    (lo[k] - c.weight.0[k])
                        .abs()
                        .max((hi[k] - c.weight.0[k]).abs())
                });
                pairs.push((c.weight.0, x.weight, slack));
            }
        }
        for (c, x, slack) in &pairs {
            for k in 0..3 {
                let d = ((x[k] - c[k]).abs() - slack[k]).max(0.0);
                let e = d / c[k].max(1e-3 * wpeak[k]).max(f32::MIN_POSITIVE);
                worst_w = worst_w.max(if e.is_nan() { f32::INFINITY } else { e });
            }
        }
        println!(
            "{}: {same} of {count} GPU samples at random colours at the CPU's direction and family; weight there (away from the poles) within {worst_w:.2e} beyond the coordinate's last bit",
            preset.name
        );
        assert!(
            same as f64 >= 0.999 * count as f64,
            "{}: {same} of {count}",
            preset.name
        );
        assert!(
            worst_w <= SAMPLE_WEIGHT_RELATIVE,
            "{}: weight {worst_w}",
            preset.name
        );
    }
}
