//! The whole scattered component (docs/model.md §6–§7) against a brute-force Monte Carlo of
//! photons through the explicit 2D cross-section (`fur_tests::cross_section_mc`, f64, no code
//! shared with the core): cortex absorption, Fresnel at the cuticle and the medulla,
//! scattering and absorption in the medulla, followed through any sequence of events.
//! (Over 600 lines: the simulation settings, the reduction of the analytic lobes to the same
//! tallies and the four comparisons share their fixtures; split up, one comparison would span files.)
//!
//! For each parameter set and view angle θ_r, the scattered energy leaving per unit φ, in
//! `N_BINS` bins of (−π, π] and averaged over h ∈ [−1, 1] (the far field's ½∫dh), is compared
//! with the model's far field Σ_p N^s_p(φ) (lobes 8–10 of `azimuthal_far`) averaged over each
//! bin (`SUB` points per bin). Two simulators:
//!
//! - **full** ([`Options::FULL`]): the physical flatland problem. It differs from the model by
//!   the report's simplifications — (a) only three scattered paths, (b) radial exit through
//!   the cortex (length 1 − κ, no refraction, no cuticle Fresnel in N^s), (c) no re-entry
//!   into the medulla, (d) the C^N walk has an index-matched medulla boundary — so the
//!   agreement is only as good as those: the tolerances are stated per parameter set from the
//!   measured differences plus a margin. The model's own prediction of the energy that
//!   leaves is N^s(φ)·T(φ) with T = ∫ M^s dθ_i (M^s carries the exit Fresnel F_t, docs/model.md
//!   §8); both N^s·T and bare N^s are compared.
//! - **simplified** ([`Options::SIMPLIFIED`]): the same tracer making exactly the report's
//!   simplifications (docs/model.md §6). σ_ma acts on each photon's own medulla path in both
//!   (the model's C^N walk weights each photon by its survival, docs/model.md §7), so nothing
//!   is left but the noise: this comparison isolates bugs in the core from the model's
//!   simplifications. (With the former mean-path rule exp(−σ_ma·κ·ℓ̄/cos θ_tm), the
//!   exponential of the mean path instead of the mean of the exponential, bobcat sat
//!   0.7–0.9 % low, outside the band asserted now.)
//!
//! Metrics: `ratio` = model energy / MC energy (∫ over φ); `L1` = ∫ |n_mc/E_mc − n_model/E_model| dφ,
//! the L1 distance of the two normalised shapes (0 = same shape, 2 = disjoint).
//!
//! The comparison can fail: the model's lobes scaled by 2, turned by π in φ (φ − Φ^s instead
//! of φ − π − Φ^s), or computed from C^N tables mirrored in ψ (the sign convention of ψ or
//! h_m reversed — the far field is symmetric in φ, so mirroring the far field itself would be
//! no test) must all fail the checks; the test asserts that they do.
//!
//! Noise: the MC's standard errors are printed and asserted to be well below the
//! tolerances. The model's own noise (profiles at 200k photons per C^N cell) was measured by regenerating the C^N tables with another seed: shape L1 between
//! the two models 0.0022–0.0026 (bobcat, θ_r = 0°, 30°), total within 1e-5; the simplified
//! comparison sits at that floor. C^M only enters T (through ⟨F_t⟩), so it uses a smaller
//! budget.
//!
//! # Measured (2.5M full, 10M simplified photons, 24 bins; ratio = model/MC)
//!
//! | set, θ_r | simplified vs N^s | full vs N^s·T | full vs N^s |
//! |---|---|---|---|
//! | bobcat, 0° | 1.0003, L1 0.0022 | 1.077, L1 0.015 | 1.151, L1 0.014 |
//! | bobcat, 30° | 1.0001, L1 0.0027 | 1.130, L1 0.014 | 1.209, L1 0.013 |
//! | air-medulla, 0° | 0.9997, L1 0.0033 | 0.907, L1 0.056 | 1.043, L1 0.052 |
//! | air-medulla, 30° | 0.9994, L1 0.0031 | 0.917, L1 0.063 | 1.060, L1 0.060 |
//! | small-medulla, 0° | 1.0002, L1 0.0030 | 0.951, L1 0.014 | 1.021, L1 0.014 |
//!
//! The simplified comparison is at the noise floor (MC ≈ 0.002 + tables ≈ 0.0017 in L1) for
//! every set, bobcat's σ_ma = 0.17 included. With the former mean-path rule
//! exp(−σ_ma·κ·ℓ̄/cos θ_tm) bobcat gave 0.9929 and 0.9914 (L1 0.0037, 0.0051), a gap growing
//! as σ_ma² (0.9999, 0.9928, 0.9721, 0.8972 at σ_ma = 0, 0.17, 0.34, 0.68), ~1.5 % low toward
//! φ = 0 (long back-scattering paths): the tolerance 0.005 on the ratio fails that rule.
//!
//! Where the full–model difference comes from (`attribution`, switching the report's
//! simplifications off one at a time): bobcat (κ = 0.88) loses 12–17% of the energy on
//! the actual, oblique cortex chords and to cuticle reflections (12–16% of the leaving energy
//! was reflected at the cuticle at least once — every exit with impact parameter above
//! 1/η'_c ≈ 0.65 < κ is totally reflected — and went
//! back through the medulla) — (b), (c); the other paths (a) carry < 0.01%. air-medulla:
//! other paths +0.3–0.4% (a); refraction and Fresnel at the medulla boundary on the way out
//! (d) change the shape most (L1 0.003 → 0.064–0.072); the cortex exit takes 4–6% of the
//! energy (b, c); refraction at the cuticle moves the shape back part of the way (L1 0.084–0.097
//! → 0.052–0.060). small-medulla: (b, c) −2% energy, exit refraction L1 0.015.
//!
//! Runtime: about 25 s on two cores (profiles ≈ 3 s per set; the three tests run in parallel).

use bcsdf_core::medulla::{
    generate_cm_row, generate_cn_cell, PhotonBudget, ProfileLayout, Resolution,
};
use bcsdf_core::{
    presets, Angles, FurBcsdf, FurParams, FurParamsInput, MedullaProfiles, Pigment, Rgb,
};
use fur_tests::cross_section_mc::{simulate, Class, McParams, Options, Tally};
use std::f64::consts::{PI, TAU};

/// φ bins over (−π, π] (15° each).
const N_BINS: usize = 24;
/// Model evaluations per bin (midpoint rule; the scattered lobes are smooth on 15°).
const SUB: usize = 8;
/// θ_i points for T = ∫ M^s dθ_i.
const THETA_I_POINTS: usize = 512;
/// MC photons: the full simulator's noise (shape L1 ≈ 0.004) only needs to be well below its
/// disagreement with the model (≥ 0.013); the simplified one is compared much more tightly.
const FULL_PHOTONS: u64 = 2_500_000;
const SIMPLIFIED_PHOTONS: u64 = 10_000_000;
const SEED: u64 = 0x5eed_2015;
/// C^N at 200k photons per cell (its noise is the floor of the simplified comparison; the
/// tolerances below were measured with it); C^M only feeds T through ⟨F_t⟩, to which its
/// noise hardly matters.
const BUDGET: PhotonBudget = PhotonBudget {
    per_cn_cell: 200_000,
    per_cm_row: 100_000,
};

/// Stated tolerances of one parameter set (measured values in the comments, all θ_r).
#[derive(Clone, Copy, Debug)]
struct Tolerances {
    /// Simplified: |E_model/E_mc − 1| (Σ N^s); 0.005 for every set, the noise floor.
    simp_total: f64,
    /// Simplified: shape L1.
    simp_l1: f64,
    /// Simplified, per lobe: |E_lobe/E_class − 1| ≤ this + 4 standard errors.
    simp_lobe: f64,
    /// Full: |E_model/E_mc − 1| with the model's exiting energy N^s·T.
    full_total_exiting: f64,
    /// Full: |E_model/E_mc − 1| with bare N^s.
    full_total_ns: f64,
    /// Full: shape L1 (N^s·T; bare N^s has nearly the same shape).
    full_l1: f64,
    /// Whether the full comparison can tell C^N mirrored in ψ from the right one. For the
    /// air-medulla set it cannot: there Φ^s is small (the refractions at the cuticle and at
    /// the lower-index medulla nearly cancel), so the mirrored lobe differs from the right
    /// one by less than the simplifications do; the simplified comparison catches it.
    full_detects_mirror: bool,
}

struct Case {
    name: &'static str,
    input: FurParamsInput,
    thetas_deg: &'static [f32],
    tol: Tolerances,
}

fn cases() -> [Case; 3] {
    let row_a = presets::find("bobcat").unwrap().input;
    let mut air = presets::find("air-medulla").unwrap().input;
    // One grey channel (the MC tracks one); 0.35 ≈ the preset's green channel.
    air.pigment = Pigment::Absorption(Rgb::splat(0.35));
    [
        Case {
            // κ = 0.88, index-matched, σ_ma = 0.17.
            name: "bobcat",
            input: row_a,
            thetas_deg: &[0.0, 30.0],
            tol: Tolerances {
                simp_total: 0.005, // 0.0003, 0.0001 (0.0071, 0.0086 with the former ℓ̄ rule)
                simp_l1: 0.006,    // 0.0022, 0.0027
                simp_lobe: 0.02,
                full_total_exiting: 0.2, // 0.077, 0.130
                full_total_ns: 0.3,      // 0.151, 0.209
                full_l1: 0.03,           // 0.015, 0.014
                full_detects_mirror: true,
            },
        },
        Case {
            // κ = 0.5, η_m = 1.2 < η_c = 1.55 (total internal reflection at the medulla).
            name: "air-medulla (grey σ_ca 0.35)",
            input: air,
            thetas_deg: &[0.0, 30.0],
            tol: Tolerances {
                simp_total: 0.005, // 0.0003, 0.0006
                simp_l1: 0.006,    // 0.0033, 0.0031
                simp_lobe: 0.02,
                full_total_exiting: 0.15, // 0.094, 0.083
                full_total_ns: 0.1,       // 0.043, 0.060
                full_l1: 0.09,            // 0.056, 0.063
                full_detects_mirror: false,
            },
        },
        Case {
            // A small index-matched medulla, no medulla absorption: the radial exit is a
            // better approximation (impact parameter ≤ κ, far from total internal reflection).
            name: "small-medulla",
            input: FurParamsInput {
                kappa: 0.35,
                sigma_ms: 4.0,
                sigma_ma: 0.0,
                g: 0.3,
                closure: bcsdf_core::Closure::Energy,
                pigment: Pigment::Absorption(Rgb::splat(0.2)),
                l: 0.5,
                ..row_a
            },
            thetas_deg: &[0.0],
            tol: Tolerances {
                simp_total: 0.005, // 0.0002
                simp_l1: 0.006,    // 0.0030
                simp_lobe: 0.02,
                full_total_exiting: 0.08, // 0.049
                full_total_ns: 0.04,      // 0.021
                full_l1: 0.025,           // 0.014
                full_detects_mirror: true,
            },
        },
    ]
}

fn threads() -> usize {
    std::thread::available_parallelism()
        .map(|n| n.get())
        .unwrap_or(1)
}

/// Profile tables, generated cell by cell on all cores (the core's cells are independent
/// streams, so this is the same as `bcsdf_core::medulla::generate`).
struct Tables {
    layout: ProfileLayout,
    cn: Vec<f32>,
    cm: Vec<f32>,
}

/// Runs `f` on every job, the jobs dealt round-robin to [`threads`] scoped threads.
fn spread<T: Send>(jobs: Vec<T>, f: &(dyn Fn(T) + Sync)) {
    let t = threads();
    let mut per: Vec<Vec<T>> = (0..t).map(|_| Vec::new()).collect();
    for (k, job) in jobs.into_iter().enumerate() {
        per[k % t].push(job);
    }
    std::thread::scope(|s| {
        for list in per {
            s.spawn(move || list.into_iter().for_each(f));
        }
    });
}

impl Tables {
    fn generate(p: &FurParams, seed: u64) -> Tables {
        let res = Resolution::DEFAULT;
        let layout = ProfileLayout::for_params(p, res);
        let mut cn = vec![0.0f32; layout.cn_len()];
        let mut cm = vec![0.0f32; layout.cm_len()];
        let jobs: Vec<_> = cn.chunks_exact_mut(res.n_psi).enumerate().collect();
        spread(jobs, &|(cell, c)| {
            generate_cn_cell(&layout, cell, &BUDGET, seed, c);
        });
        let n_out = res.n_out;
        let (back, front) = cm.split_at_mut(res.n_in * n_out);
        let jobs: Vec<_> = back
            .chunks_exact_mut(n_out)
            .zip(front.chunks_exact_mut(n_out))
            .enumerate()
            .collect();
        spread(jobs, &|(row, (b, f))| {
            generate_cm_row(&layout, row, &BUDGET, seed, b, f);
        });
        Tables { layout, cn, cm }
    }

    /// The same tables with C^N reversed in ψ: C'(ψ | h_m) = C(−ψ | h_m).
    fn mirrored_in_psi(&self) -> Tables {
        let n = self.layout.res.n_psi;
        let flip = |v: &[f32]| -> Vec<f32> {
            v.chunks_exact(n)
                .flat_map(|row| row.iter().rev().copied())
                .collect()
        };
        Tables {
            layout: self.layout,
            cn: flip(&self.cn),
            cm: self.cm.clone(),
        }
    }

    fn profiles(&self) -> MedullaProfiles<'_> {
        MedullaProfiles::new(self.layout, &self.cn, &self.cm).unwrap()
    }
}

/// The model per bin: each scattered lobe's N^s_p averaged over the bin, their sum, and the
/// exiting energy Σ N^s_p·T.
struct ModelBins {
    lobes: [Vec<f64>; 3],
    ns: Vec<f64>,
    exiting: Vec<f64>,
}

impl ModelBins {
    fn new(model: &FurBcsdf, theta_r: f32) -> ModelBins {
        let w = TAU / N_BINS as f64;
        let mut lobes: [Vec<f64>; 3] = std::array::from_fn(|_| vec![0.0; N_BINS]);
        let mut exiting = vec![0.0; N_BINS];
        for b in 0..N_BINS {
            for k in 0..SUB {
                let phi = (-PI + w * (b as f64 + (k as f64 + 0.5) / SUB as f64)) as f32;
                let n = model.azimuthal_far(theta_r, phi);
                let t = exit_fraction(model, theta_r, phi);
                for (j, lobe) in lobes.iter_mut().enumerate() {
                    let v = n[8 + j].0[0] as f64 / SUB as f64;
                    lobe[b] += v;
                    exiting[b] += v * t;
                }
            }
        }
        let ns = (0..N_BINS)
            .map(|b| lobes.iter().map(|l| l[b]).sum())
            .collect();
        ModelBins { lobes, ns, exiting }
    }
}

/// T(θ_r, φ) = ∫ M^s(θ_i, θ_r, φ) dθ_i: the part of N^s the model lets out of the fiber
/// (docs/model.md §8: ρ = ∫∫ M N dθ_i dφ).
fn exit_fraction(model: &FurBcsdf, theta_r: f32, phi: f32) -> f64 {
    let h = PI / THETA_I_POINTS as f64;
    (0..THETA_I_POINTS)
        .map(|i| {
            let theta_i = -PI / 2.0 + (i as f64 + 0.5) * h;
            let a = Angles::new(theta_i as f32, theta_r, phi).unwrap();
            model.longitudinal_scattered(&a) as f64 * h
        })
        .sum()
}

fn energy(bins: &[f64]) -> f64 {
    bins.iter().sum::<f64>() * TAU / bins.len() as f64
}

#[derive(Clone, Copy, Debug)]
struct Agreement {
    /// E_model / E_mc.
    ratio: f64,
    /// L1 distance of the normalised shapes.
    l1: f64,
}

impl Agreement {
    fn of(mc: &[f64], model: &[f64]) -> Agreement {
        let (em, eo) = (energy(mc), energy(model));
        let w = TAU / mc.len() as f64;
        let l1 = mc
            .iter()
            .zip(model)
            .map(|(a, b)| (a / em - b / eo).abs())
            .sum::<f64>()
            * w;
        Agreement { ratio: eo / em, l1 }
    }

    fn passes(&self, total_tol: f64, l1_tol: f64) -> bool {
        (self.ratio - 1.0).abs() <= total_tol && self.l1 <= l1_tol
    }
}

/// Σ standard errors · bin width / energy: the MC noise on the shape L1 scale (the expected
/// L1 of pure noise is about 0.8 of this).
fn noise_l1(t: &Tally) -> f64 {
    t.std_error().iter().sum::<f64>() * t.width() / t.total()
}

fn mc_params(p: &FurParams, theta_r: f32) -> McParams {
    McParams {
        eta_c: p.eta_c() as f64,
        eta_m: p.eta_m() as f64,
        kappa: p.kappa() as f64,
        layers: p.l() as f64,
        sigma_ca: p.sigma_ca().0[0] as f64,
        sigma_ms: p.sigma_ms() as f64,
        sigma_ma: p.sigma_ma() as f64,
        g: p.g() as f64,
        theta_r: theta_r as f64,
    }
}

/// The three model variants that must not pass, as (name, N^s bins, exiting bins).
fn variants(right: &ModelBins, mirrored: &ModelBins) -> Vec<(&'static str, Vec<f64>, Vec<f64>)> {
    let turned =
        |v: &[f64]| -> Vec<f64> { (0..N_BINS).map(|b| v[(b + N_BINS / 2) % N_BINS]).collect() };
    let doubled = |v: &[f64]| -> Vec<f64> { v.iter().map(|x| 2.0 * x).collect() };
    vec![
        ("scaled by 2", doubled(&right.ns), doubled(&right.exiting)),
        ("turned by π", turned(&right.ns), turned(&right.exiting)),
        (
            "C^N mirrored in ψ",
            mirrored.ns.clone(),
            mirrored.exiting.clone(),
        ),
    ]
}

fn check_case(case: &Case) {
    let start = std::time::Instant::now();
    let p = FurParams::new(&case.input).unwrap();
    let tables = Tables::generate(&p, SEED);
    let mirrored_tables = tables.mirrored_in_psi();
    let model: FurBcsdf = FurBcsdf::new(p, tables.profiles()).unwrap();
    let mirrored: FurBcsdf = FurBcsdf::new(p, mirrored_tables.profiles()).unwrap();
    let tol = case.tol;
    let mut failures = Vec::new();
    let mut out = format!("== {} ==\n", case.name);
    for (k, &deg) in case.thetas_deg.iter().enumerate() {
        let theta_r = deg.to_radians();
        let bins = ModelBins::new(&model, theta_r);
        let mbins = ModelBins::new(&mirrored, theta_r);
        let mp = mc_params(&p, theta_r);
        let seed = SEED + 16 * k as u64;
        let full = simulate(&mp, &Options::FULL, N_BINS, FULL_PHOTONS, seed, threads());
        let simp = simulate(
            &mp,
            &Options::SIMPLIFIED,
            N_BINS,
            SIMPLIFIED_PHOTONS,
            seed + 1,
            threads(),
        );
        let (fd, sd) = (full.density(), simp.density());
        let s = Agreement::of(&sd, &bins.ns);
        let fe = Agreement::of(&fd, &bins.exiting);
        let fn_ = Agreement::of(&fd, &bins.ns);
        let (noise_s, noise_f) = (noise_l1(&simp), noise_l1(&full));
        out += &format!(
            "θ_r = {deg}°: energy  model N^s {:.5}, model N^s·T {:.5}, simplified MC {:.5}, full MC {:.5}\n",
            energy(&bins.ns),
            energy(&bins.exiting),
            simp.total(),
            full.total()
        );
        out += &format!(
            "  simplified vs N^s:   ratio {:.4}  L1 {:.4}   (MC noise {:.4}; tol {} / {})\n",
            s.ratio, s.l1, noise_s, tol.simp_total, tol.simp_l1
        );
        out += &format!(
            "  full vs N^s·T:       ratio {:.4}  L1 {:.4}   (MC noise {:.4}; tol {} / {})\n",
            fe.ratio, fe.l1, noise_f, tol.full_total_exiting, tol.full_l1
        );
        out += &format!(
            "  full vs N^s:         ratio {:.4}  L1 {:.4}   (tol {} / {})\n",
            fn_.ratio, fn_.l1, tol.full_total_ns, tol.full_l1
        );
        out += &format!(
            "  full MC: from other paths {:.2}%, after a cuticle reflection {:.2}%, after re-entering the medulla {:.2}%, abandoned {:.1e}\n",
            100.0 * full.class_total(Class::Other) / full.total(),
            100.0 * full.fraction(full.after_cuticle_reflection) / full.total(),
            100.0 * full.fraction(full.after_reentry) / full.total(),
            full.fraction(full.abandoned)
        );
        let mut fail = |what: String| failures.push(format!("{} θ_r {deg}°: {what}", case.name));
        if !s.passes(tol.simp_total, tol.simp_l1) {
            fail(format!("simplified MC vs model {s:?}"));
        }
        if !fe.passes(tol.full_total_exiting, tol.full_l1) {
            fail(format!("full MC vs model N^s·T {fe:?}"));
        }
        if !fn_.passes(tol.full_total_ns, tol.full_l1) {
            fail(format!("full MC vs model N^s {fn_:?}"));
        }
        // MC noise well below what is compared (the L1 of pure noise is ≈ 0.8 × noise_l1).
        if noise_s > tol.simp_l1 / 2.0 || noise_f > tol.full_l1 / 4.0 {
            fail(format!("MC noise too large: {noise_s} {noise_f}"));
        }
        // Per lobe (simplified): the class of photons that scattered on that path.
        for (j, class) in [Class::TttT, Class::TtrtT, Class::TttRttT]
            .iter()
            .enumerate()
        {
            let (want, got) = (energy(&bins.lobes[j]), simp.class_total(*class));
            let se = simp.class_std_error(*class);
            out += &format!(
                "  lobe {:?}^s: model {:.5}, simplified MC {:.5} ± {:.5}, full MC {:.5}\n",
                class,
                want,
                got,
                se,
                full.class_total(*class)
            );
            let ok = if want == 0.0 {
                got <= 1e-9 * simp.total()
            } else {
                (want - got).abs() <= tol.simp_lobe * got + 4.0 * se
            };
            if !ok {
                fail(format!(
                    "lobe {class:?}: model {want} vs simplified MC {got} ± {se}"
                ));
            }
        }
        // The comparison can fail.
        for (name, ns, ex) in variants(&bins, &mbins) {
            let vs = Agreement::of(&sd, &ns);
            let ve = Agreement::of(&fd, &ex);
            let vn = Agreement::of(&fd, &ns);
            out += &format!(
                "  variant {name:<18}: simplified ratio {:.4} L1 {:.4} | full (N^s·T) ratio {:.4} L1 {:.4} | full (N^s) ratio {:.4}\n",
                vs.ratio, vs.l1, ve.ratio, ve.l1, vn.ratio
            );
            if vs.passes(tol.simp_total, tol.simp_l1) {
                fail(format!("variant '{name}' passes the simplified comparison"));
            }
            let full_must_fail = name != "C^N mirrored in ψ" || tol.full_detects_mirror;
            let full_passes = ve.passes(tol.full_total_exiting, tol.full_l1)
                && vn.passes(tol.full_total_ns, tol.full_l1);
            if full_must_fail && full_passes {
                fail(format!("variant '{name}' passes the full comparison"));
            }
        }
        out += "  φ (deg)   N^s    simplified ± se  |  N^s·T    full ± se\n";
        let (se_s, se_f) = (simp.std_error(), full.std_error());
        for b in 0..N_BINS {
            out += &format!(
                "  {:7.1}  {:.5}  {:.5} {:.5}  |  {:.5}  {:.5} {:.5}\n",
                full.centre(b).to_degrees(),
                bins.ns[b],
                sd[b],
                se_s[b],
                bins.exiting[b],
                fd[b],
                se_f[b]
            );
        }
    }
    out += &format!("({:.1} s)\n", start.elapsed().as_secs_f64());
    println!("{out}");
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn scattered_far_field_vs_mc_bobcat() {
    check_case(&cases()[0]);
}

#[test]
fn scattered_far_field_vs_mc_air_medulla() {
    check_case(&cases()[1]);
}

#[test]
fn scattered_far_field_vs_mc_small_medulla() {
    check_case(&cases()[2]);
}

/// Attribution of the full–simplified difference to the report's simplifications, one at a
/// time (printed; run with `--ignored --nocapture`). Also the σ_ma dependence of the
/// simplified comparison (profiles regenerated for each σ_ma: C^N carries the absorption).
#[test]
#[ignore = "diagnostic printout (about a minute)"]
fn attribution() {
    let photons = 8_000_000;
    let steps: [(&str, Options); 5] = [
        ("simplified (docs/model.md §6)", Options::SIMPLIFIED),
        (
            "+ all paths before scattering (a)",
            Options {
                all_paths: true,
                ..Options::SIMPLIFIED
            },
        ),
        (
            "+ physical medulla boundary after scattering (d)",
            Options {
                all_paths: true,
                medulla_boundary: true,
                ..Options::SIMPLIFIED
            },
        ),
        (
            "+ actual cortex chord, cuticle Fresnel, re-entries (b, c)",
            Options {
                exit_refraction: false,
                ..Options::FULL
            },
        ),
        ("+ refraction at the cuticle (b) = full", Options::FULL),
    ];
    for case in cases() {
        let p = FurParams::new(&case.input).unwrap();
        let tables = Tables::generate(&p, SEED);
        let model: FurBcsdf = FurBcsdf::new(p, tables.profiles()).unwrap();
        for &deg in case.thetas_deg {
            let theta_r = deg.to_radians();
            let bins = ModelBins::new(&model, theta_r);
            println!(
                "== {} θ_r = {deg}° (model N^s energy {:.5})",
                case.name,
                energy(&bins.ns)
            );
            for (name, o) in &steps {
                let t = simulate(&mc_params(&p, theta_r), o, N_BINS, photons, SEED, threads());
                let a = Agreement::of(&t.density(), &bins.ns);
                println!(
                    "  {name:<58} MC energy {:.5}  model/MC {:.4}  L1 {:.4}",
                    t.total(),
                    a.ratio,
                    a.l1
                );
            }
        }
        if p.sigma_ma() > 0.0 {
            for scale in [0.0f32, 1.0, 2.0, 4.0] {
                let input = FurParamsInput {
                    sigma_ma: case.input.sigma_ma * scale,
                    ..case.input
                };
                let q = FurParams::new(&input).unwrap();
                let tables_q = Tables::generate(&q, SEED);
                let m: FurBcsdf = FurBcsdf::new(q, tables_q.profiles()).unwrap();
                let bins = ModelBins::new(&m, 0.0);
                let t = simulate(
                    &mc_params(&q, 0.0),
                    &Options::SIMPLIFIED,
                    N_BINS,
                    photons,
                    SEED,
                    threads(),
                );
                let a = Agreement::of(&t.density(), &bins.ns);
                println!(
                    "  σ_ma = {:.2}: simplified model/MC {:.4}  L1 {:.4}",
                    q.sigma_ma(),
                    a.ratio,
                    a.l1
                );
            }
        }
    }
}
