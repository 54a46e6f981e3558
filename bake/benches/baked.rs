//! Baked versus analytic far field, in the same run (RGB, one query per iteration from a fixed
//! list of 256 directions over θ_i, θ_r ∈ ±80°, φ ∈ (−180°, 180°]):
//!
//! - `far_field_analytic/<preset>`: `FurBcsdf::eval_far(..).total()`, the full model (eight
//!   unscattered paths, the scattered lobes and, in the presets' energy closure, the lobes'
//!   sphere normalisation and the residual);
//! - `far_field_analytic_report/<preset>`: the same parameters in the report closure (no
//!   normalisation, no residual), so that the energy closure's analytic cost is a ratio
//!   measured in one run (docs/model.md §12);
//! - `far_field_baked/<preset>`: `BakedBcsdf::eval_far(..).total()` on the LUT of the same
//!   model at the default resolution (the preset's closure: energy);
//! - `far_field_baked_report/<preset>`: the same LUT with its header's closure set to report
//!   (the lookups do not depend on the tables' values), i.e. without the energy closure's 1/Z_g
//!   lookup, so that its cost is a ratio measured in one run.
//!
//! - `far_field_baked_reference/<preset>`: a copy of the scalar baked path as it was before
//!   the SIMD kernels (`reference` below), so that the speed-up is a ratio measured in one run;
//! - `far_field_baked_batch/<preset>/<size>`: `BakedBcsdf::eval_far_batch` over consecutive
//!   batches of `size` queries (structure of arrays), per query (criterion's throughput),
//!   with the CPU's best kernel (`Kernel::best`), and `sse2-256` with the baseline (SSE2) kernel;
//! - `far_field_baked_dirs/<preset>`: `BakedBcsdf::eval_far_dirs(..).total()` on the same
//!   directions as world-space vectors.
//!
//! Before timing, the setup checks that the reference and the report-closure scalar path, and
//! each closure's scalar path and batch, agree bit for bit on the 256 queries.
//!
//! The profiles use a small photon budget: neither evaluation's cost depends on it. The
//! query index is masked (256 queries), not taken modulo: a division would cost as much as a
//! third of a baked evaluation.
//! `cargo bench -p bake --bench baked`; the speed-up is the ratio of the two medians.

use bake::profiles::{build_model, scale_budget, ProfileOptions};
use bake::tables;
use bcsdf_core::baked::{BakedBcsdf, Kernel};
use bcsdf_core::bench_support::{QueryStream, QUERY_COUNT};
use bcsdf_core::lut::LutResolution;
use bcsdf_core::medulla::PhotonBudget;
use bcsdf_core::{presets, Absorption, Angles, FurParams};
use bcsdf_core::{Rgb, Vec3};
use criterion::{black_box, criterion_group, criterion_main, Criterion, Throughput};

/// The scalar baked evaluation before the SIMD kernels (commit 406e438), restated over the public
/// LUT layout: per-channel loops over decoded texel pairs, saturating float-to-int
/// conversions, a branch in the cosine, the families formed and then summed.
mod reference {
    use bcsdf_core::lut::{f16_biased, LutHeader, Table, F16_UNBIAS};
    use bcsdf_core::model::inv_cos2_theta_i;
    use bcsdf_core::{Angles, Rgb};
    use std::f32::consts::PI;

    pub struct Lut<'a> {
        header: LutHeader,
        tables: [&'a [u8]; 3],
        unbias: [f32; 3],
        /// sum, θ_r, φ, M^s θ_i, M^s θ_r.
        axes: [Axis; 5],
    }

    struct Axis {
        inv_step: f32,
        offset: f32,
        last: f32,
        nodes: usize,
    }

    impl Axis {
        fn new(lo: f32, inv_span: f32, nodes: u32) -> Axis {
            let last = (nodes - 1) as f32;
            Axis {
                inv_step: last * inv_span,
                offset: if lo == 0.0 { 0.0 } else { 0.5 * last },
                last,
                nodes: nodes as usize,
            }
        }
        #[inline(always)]
        fn locate(&self, x: f32) -> (usize, f32) {
            let u = (x * self.inv_step + self.offset).max(0.0).min(self.last);
            let i = (u as i32).min(self.nodes as i32 - 2);
            (i as u32 as usize, u - i as f32)
        }
    }

    #[inline(always)]
    fn texel_pair<const C: usize, const B: usize>(data: &[u8], index: usize) -> &[u8; B] {
        let start = 2 * C * index;
        match data.get(start..).and_then(|s| s.get(..B)) {
            Some(s) => s.try_into().unwrap_or(&[0; B]),
            None => &[0; B],
        }
    }

    #[inline(always)]
    fn decode<const B: usize, const H: usize>(bytes: &[u8; B]) -> [f32; H] {
        let mut out = [0.0; H];
        for (o, pair) in out.iter_mut().zip(bytes.chunks_exact(2)) {
            *o = f16_biased(u16::from_le_bytes([pair[0], pair[1]]));
        }
        out
    }

    #[inline(always)]
    fn linear<const C: usize, const B: usize, const H: usize>(
        data: &[u8],
        (index, w): (usize, f32),
        k: f32,
    ) -> [f32; C] {
        let (w0, w1) = ((1.0 - w) * k, w * k);
        let t: [f32; H] = decode(texel_pair::<C, B>(data, index));
        let mut out = [0.0; C];
        for c in 0..C {
            out[c] = w0 * t[c] + w1 * t[C + c];
        }
        out
    }

    #[inline(always)]
    fn bilinear<const C: usize, const B: usize, const H: usize>(
        data: &[u8],
        width: usize,
        (row, wy): (usize, f32),
        (col, wx): (usize, f32),
        k: f32,
    ) -> [f32; C] {
        let (ky0, ky1) = ((1.0 - wy) * k, wy * k);
        let w = [ky0 * (1.0 - wx), ky0 * wx, ky1 * (1.0 - wx), ky1 * wx];
        let i0 = row * width + col;
        let t: [f32; H] = decode(texel_pair::<C, B>(data, i0));
        let b: [f32; H] = decode(texel_pair::<C, B>(data, i0 + width));
        let mut out = [0.0; C];
        for c in 0..C {
            out[c] = w[0] * t[c] + w[1] * t[C + c] + w[2] * b[c] + w[3] * b[C + c];
        }
        out
    }

    #[inline]
    fn cos_within_half_pi(x: f32) -> f32 {
        const PIO2_HI: f32 = 1.570_796_4;
        const PIO2_LO: f32 = -4.371_139e-8;
        let a = x.abs();
        if a <= std::f32::consts::FRAC_PI_4 {
            let y = a * a;
            let mut acc = -1.0 / 3_628_800.0;
            acc = acc * y + 1.0 / 40_320.0;
            acc = acc * y - 1.0 / 720.0;
            acc = acc * y + 1.0 / 24.0;
            acc = acc * y - 0.5;
            acc * y + 1.0
        } else {
            let r = (PIO2_HI - a) + PIO2_LO;
            let y = r * r;
            let mut acc = 1.0 / 362_880.0;
            acc = acc * y - 1.0 / 5_040.0;
            acc = acc * y + 1.0 / 120.0;
            acc = acc * y - 1.0 / 6.0;
            (acc * y) * r + r
        }
    }

    impl<'a> Lut<'a> {
        pub fn new(blob: &'a [u8]) -> Lut<'a> {
            let header = bcsdf_core::lut::validate(blob).unwrap();
            let res = header.res;
            Lut {
                header,
                tables: Table::ALL.map(|t| &blob[header.res.byte_range(t)]),
                unbias: header.scales.map(|s| s * F16_UNBIAS),
                axes: [
                    Axis::new(-PI, 1.0 / (2.0 * PI), res.n_sum),
                    Axis::new(0.0, 1.0 / (PI / 2.0), res.n_theta_r),
                    Axis::new(0.0, 1.0 / PI, res.n_phi),
                    Axis::new(-PI / 2.0, 1.0 / PI, res.n_ms_i),
                    Axis::new(-PI / 2.0, 1.0 / PI, res.n_ms_r),
                ],
            }
        }

        /// Inlined into the caller, as `BakedBcsdf::eval_far` was.
        #[inline]
        pub fn eval_far_total(&self, angles: &Angles) -> Rgb {
            let res = &self.header.res;
            let (ti, tr, phi) = (angles.theta_i(), angles.theta_r(), angles.phi());
            let abs_phi = phi.abs();
            let [sum, theta_r, phi_axis, ms_i, ms_r] = &self.axes;
            let m = linear::<3, 12, 6>(self.tables[0], sum.locate(ti + tr), self.unbias[0]);
            let ms = bilinear::<2, 8, 4>(
                self.tables[2],
                res.n_ms_i as usize,
                ms_r.locate(tr),
                ms_i.locate(ti),
                self.unbias[2],
            );
            let n = bilinear::<12, 48, 24>(
                self.tables[1],
                res.n_phi as usize,
                theta_r.locate(tr.abs()),
                phi_axis.locate(abs_phi),
                self.unbias[1],
            );
            let front = (abs_phi * (1.0 / PI)).min(1.0);
            let inv_cos2 = inv_cos2_theta_i(cos_within_half_pi(ti));
            let [back, fr] = ms;
            let msv = back + front * (fr - back);
            let longitudinal = [m[0], m[1], m[2], msv];
            let mut out = [Rgb::ZERO; 4];
            for (f, o) in out.iter_mut().enumerate() {
                let weight = longitudinal[f] * inv_cos2;
                *o = Rgb([n[3 * f], n[3 * f + 1], n[3 * f + 2]]) * weight;
            }
            out.iter().fold(Rgb::ZERO, |acc, &v| acc + v)
        }
    }
}

/// The query's directions as world-space vectors (tangent along z, ω_r in the x-z plane).
fn directions(a: &Angles) -> (Vec3, Vec3, Vec3) {
    let (ti, tr, phi) = (a.theta_i(), a.theta_r(), a.phi());
    let wr = [tr.cos(), 0.0, tr.sin()];
    // φ = φ_r − φ_i, so ω_i's azimuth is −φ.
    let wi = [ti.cos() * (-phi).cos(), ti.cos() * (-phi).sin(), ti.sin()];
    (wi, wr, [0.0, 0.0, 1.0])
}

fn queries() -> Vec<Angles> {
    let mut stream = QueryStream::new();
    (0..QUERY_COUNT).map(|_| stream.angles()).collect()
}

fn bench(c: &mut Criterion) {
    let qs = queries();
    let opts = ProfileOptions {
        budget: scale_budget(PhotonBudget::DEFAULT, 0.01).unwrap(),
        ..ProfileOptions::default()
    };
    for preset in presets::PRESETS.iter() {
        let name = preset.name;
        let params = FurParams::new(&preset.input).unwrap();
        let (model, _) = build_model(params, &opts).unwrap();
        let blob = tables::bake(&model, &preset.input, LutResolution::DEFAULT);
        let baked = BakedBcsdf::from_bytes(&blob).unwrap();
        // The presets use the energy closure; the same tables in the report closure (header
        // word 26, after g, is the closure) measure what the energy closure's 1/Z_g lookup
        // costs, with nothing else different.
        assert_eq!(baked.params().closure(), bcsdf_core::Closure::Energy);
        let mut report_blob = blob.clone();
        report_blob[104..108].copy_from_slice(&0u32.to_le_bytes());
        bcsdf_core::lut::seal(&mut report_blob);
        let report = BakedBcsdf::from_bytes(&report_blob).unwrap();
        assert_eq!(report.params().closure(), bcsdf_core::Closure::Report);
        let analytic = model.model();
        // The report closure's analytic model: no sphere normalisation, no residual.
        let (report_model, _) =
            build_model(params.with_closure(bcsdf_core::Closure::Report), &opts).unwrap();
        let analytic_report = report_model.model();

        let mut i = 0usize;
        c.bench_function(&format!("far_field_analytic/{name}"), |b| {
            b.iter(|| {
                let a = &qs[i & 255];
                i += 1;
                black_box(analytic.eval_far(black_box(a)).total())
            })
        });
        let mut i = 0usize;
        c.bench_function(&format!("far_field_analytic_report/{name}"), |b| {
            b.iter(|| {
                let a = &qs[i & 255];
                i += 1;
                black_box(analytic_report.eval_far(black_box(a)).total())
            })
        });
        let reference = reference::Lut::new(&report_blob);
        let (ti, tr, ph): (Vec<f32>, Vec<f32>, Vec<f32>) = {
            let cycle = || qs.iter().chain(&qs);
            (
                cycle().map(Angles::theta_i).collect(),
                cycle().map(Angles::theta_r).collect(),
                cycle().map(Angles::phi).collect(),
            )
        };
        for lut in [&baked, &report] {
            let mut batch_out = vec![Rgb::ZERO; 256];
            lut.eval_far_batch(&ti[..256], &tr[..256], &ph[..256], &mut batch_out)
                .unwrap();
            for (a, b) in qs.iter().zip(&batch_out) {
                let scalar = lut.eval_far(a).total();
                assert_eq!(scalar.0.map(f32::to_bits), b.0.map(f32::to_bits));
            }
        }
        for a in &qs {
            assert_eq!(
                report.eval_far(a).total().0.map(f32::to_bits),
                reference.eval_far_total(a).0.map(f32::to_bits)
            );
        }
        let dirs: Vec<(Vec3, Vec3, Vec3)> = qs.iter().map(directions).collect();

        let mut i = 0usize;
        c.bench_function(&format!("far_field_baked_reference/{name}"), |b| {
            b.iter(|| {
                let a = &qs[i & 255];
                i += 1;
                black_box(reference.eval_far_total(black_box(a)))
            })
        });
        let mut i = 0usize;
        c.bench_function(&format!("far_field_baked/{name}"), |b| {
            b.iter(|| {
                let a = &qs[i & 255];
                i += 1;
                black_box(baked.eval_far(black_box(a)).total())
            })
        });
        // A colour per query (docs/lut.md "The absorption axis"): 256 random σ_ca.
        let colours: Vec<Absorption> = (0..256)
            .map(|k| {
                let u = |j: u32| ((k * 3 + j) as f32 * 0.618_034).fract();
                Absorption::from_sigma(Rgb([0, 1, 2].map(|j| 10f32.powf(-2.0 + 5.0 * u(j)))))
                    .unwrap()
            })
            .collect();
        let mut i = 0usize;
        c.bench_function(&format!("far_field_baked_colour/{name}"), |b| {
            b.iter(|| {
                let k = i & 255;
                i += 1;
                black_box(
                    baked
                        .at(black_box(&colours[k]))
                        .eval_far(black_box(&qs[k]))
                        .total(),
                )
            })
        });
        let mut i = 0usize;
        c.bench_function(&format!("far_field_baked_report/{name}"), |b| {
            b.iter(|| {
                let a = &qs[i & 255];
                i += 1;
                black_box(report.eval_far(black_box(a)).total())
            })
        });
        let mut i = 0usize;
        c.bench_function(&format!("far_field_baked_dirs/{name}"), |b| {
            b.iter(|| {
                let (wi, wr, u) = dirs[i & 255];
                i += 1;
                black_box(
                    baked
                        .eval_far_dirs(black_box(wi), black_box(wr), black_box(u))
                        .total(),
                )
            })
        });
        let mut group = c.benchmark_group(format!("far_field_baked_batch/{name}"));
        // The CPU's best kernel at two sizes, and the SSE2 kernel (x86-64's baseline).
        let sse2 = baked.with_kernel(Kernel::Baseline).unwrap();
        let kernels = [
            (&baked, 64usize, ""),
            (&baked, 256, ""),
            (&sse2, 256, "sse2-"),
        ];
        for (lut, size, label) in kernels {
            group.throughput(Throughput::Elements(size as u64));
            let mut out = vec![Rgb::ZERO; size];
            let mut start = 0usize;
            group.bench_function(format!("{label}{size}"), |b| {
                b.iter(|| {
                    let r = start..start + size;
                    start = (start + size) & 255;
                    black_box(lut)
                        .eval_far_batch(&ti[r.clone()], &tr[r.clone()], &ph[r], &mut out)
                        .unwrap();
                    black_box(&out);
                })
            });
        }
        group.throughput(Throughput::Elements(256));
        let mut out = vec![Rgb::ZERO; 256];
        group.bench_function("colours-256", |b| {
            b.iter(|| {
                black_box(&baked)
                    .eval_far_batch_colours(&ti[..256], &tr[..256], &ph[..256], &colours, &mut out)
                    .unwrap();
                black_box(&out);
            })
        });
        group.finish();
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
