//! A brute-force Monte Carlo of photons through the explicit 2D cross-section of the double
//! cylinder (docs/model.md §3, §4, §6), in f64, for checking the scattered component as a whole.
//! (Over 600 lines: geometry, Fresnel, the walks and the tallies form one independent reference,
//! kept in one file that shares nothing with the core.)
//!
//! By reciprocity the photons are the traced **view ray** (docs/model.md §1): each enters the
//! cross-section travelling along −x at height y = h, h uniform (stratified) in [−1, 1], at a
//! fixed view angle θ_r. The cross-section is drawn explicitly — outer circle of radius 1
//! (cuticle; Bravais index η'_c inside), concentric medulla circle of radius κ (index η'_m) —
//! and every step is an explicit ray–circle intersection, a vector Snell refraction or a
//! mirror reflection. Per unit 2D length the cortex absorbs σ_ca/cos θ_tc, the medulla
//! scatters σ_ms/cos θ_tm and absorbs σ_ma/cos θ_tm (the 2D problem at fixed θ_r, as in
//! docs/model.md §3 and §7: a scattering event turns the photon within the cross-section only).
//! Scattering is 2D Henyey–Greenstein (wrapped Cauchy), sampled here by wrapping a Cauchy
//! variate of scale −ln|g| — a different construction from the core's inverse-CDF sampler.
//!
//! One tracer, with the report's simplifications as switches ([`Options`]):
//! - [`Options::FULL`]: the physical flatland problem. Fresnel reflection/transmission is
//!   chosen stochastically at every interface crossing (cuticle: layered f of docs/model.md §4 at
//!   the actual incidence; medulla: dielectric f_m at the actual incidence, total internal
//!   reflection included), and the photon is followed through any sequence of events until
//!   it leaves the fiber (or is absorbed; Russian roulette below weight 1e-3).
//! - [`Options::SIMPLIFIED`]: docs/model.md §6 exactly, as a simulation: only the three structures
//!   TttT^s, TtrtT^s, TttRttT^s are followed up to their scattering chord (a photon whose
//!   events leave them is dropped); once scattered, the photon walks in the medulla with an
//!   index-matched boundary (no Fresnel, no refraction: it leaves when it crosses the medulla
//!   circle), and its travel direction there is its exit direction, attenuated by the radial
//!   cortex leg exp(−σ_ca·(1 − κ)/cos θ_tc), without any cuticle Fresnel (the model puts the
//!   exit transmittance F_t into M^s, not into N^s). σ_ma acts on each photon's own path
//!   (exp(−σ_ma·L/cos θ_tm)), as in the model's C^N walk.
//! - anything in between, to attribute the difference between the two to single
//!   simplifications.
//!
//! Tallies: the energy of every photon leaving the fiber ([`Tally::all_exiting`]), and photons
//! that scattered at least once in the medulla, by exit azimuth
//! Φ = −atan2(d_y, d_x) of the final travel direction d (the tracer's convention, Φ_R = −2 asin h)
//! in `n_bins` equal bins of (−π, π], as energy per unit φ averaged over h ∈ [−1, 1] —
//! i.e. normalised like the far field N(φ) = ½∫ N(h, φ) dh. Each tally is split by the
//! event string before the first scattering (see [`Class`]).
//!
//! Nothing here uses the closed-form angles a, c, m, μ or anything of `bcsdf-core`; the
//! Fresnel formulas and the Bravais index come from `crate::tracer` (also independent).

use crate::tracer::{bravais, cos_refracted, cuticle, dielectric, SplitMix64};
use std::f64::consts::{PI, TAU};

/// Parameters of one cross-section simulation (lengths in fiber radii, σ per fiber radius).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct McParams {
    /// η_c (cortex and cuticle).
    pub eta_c: f64,
    /// η_m (medulla).
    pub eta_m: f64,
    /// κ, medulla radius.
    pub kappa: f64,
    /// l, cuticle layers.
    pub layers: f64,
    /// σ_ca, cortex absorption (one channel).
    pub sigma_ca: f64,
    /// σ_ms, medulla scattering.
    pub sigma_ms: f64,
    /// σ_ma, medulla absorption.
    pub sigma_ma: f64,
    /// g, Henyey–Greenstein anisotropy.
    pub g: f64,
    /// θ_r, view angle (radians).
    pub theta_r: f64,
}

/// Which of the report's simplifications (docs/model.md §6) the simulation makes. Each switch set
/// to `true` removes one simplification; [`Options::FULL`] has them all `true` (the physical
/// flatland problem), [`Options::SIMPLIFIED`] all `false` (docs/model.md §6 exactly).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Options {
    /// Before the first scattering, follow any event sequence (false: only the three
    /// structures "Tt", "Ttr", "TttRt" of TttT^s, TtrtT^s, TttRttT^s; a photon that leaves
    /// them is dropped).
    pub all_paths: bool,
    /// After the first scattering, the medulla boundary reflects and refracts (false: it is
    /// index-matched, as in the C^N walk: the photon crosses it straight, without Fresnel).
    pub medulla_boundary: bool,
    /// After the first scattering, the photon crosses the cortex along its actual chord, meets
    /// the cuticle with Fresnel reflection (total internal reflection included) and may
    /// re-enter the medulla any number of times (false: the radial exit — on leaving the
    /// medulla it is tallied at once with its current direction and weight
    /// × exp(−σ_ca·(1 − κ)/cos θ_tc), no cuticle Fresnel).
    pub cortex_exit: bool,
    /// Refraction at the cuticle turns the exit direction (false: the tally uses the travel
    /// direction inside the cortex; only with `cortex_exit`).
    pub exit_refraction: bool,
}

impl Options {
    /// The physical flatland problem: no simplification.
    pub const FULL: Options = Options {
        all_paths: true,
        medulla_boundary: true,
        cortex_exit: true,
        exit_refraction: true,
    };
    /// docs/model.md §6 exactly: three paths, index-matched walk, radial exit.
    pub const SIMPLIFIED: Options = Options {
        all_paths: false,
        medulla_boundary: false,
        cortex_exit: false,
        exit_refraction: false,
    };
}

/// The event string of a photon before its first scattering event.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Class {
    /// "Tt": scattered on its first medulla chord (TttT^s).
    TttT = 0,
    /// "Ttr": reflected inside the medulla, scattered on the second chord (TtrtT^s).
    TtrtT = 1,
    /// "TttRt": left the medulla, reflected at the cuticle, scattered on re-entry (TttRttT^s).
    TttRttT = 2,
    /// Anything else (only with [`Options::all_paths`]).
    Other = 3,
}

/// Number of [`Class`]es.
pub const CLASSES: usize = 4;

/// Photons whose weight drops below this play Russian roulette.
const ROULETTE_WEIGHT: f64 = 1e-3;
/// Survival probability in Russian roulette.
const ROULETTE_SURVIVE: f64 = 0.1;
/// Events after which a photon is abandoned (and its weight counted in `abandoned`).
const MAX_EVENTS: u32 = 100_000;

/// Energy tallies of the scattered photons.
#[derive(Clone, Debug, PartialEq)]
pub struct Tally {
    /// Number of bins over (−π, π].
    pub n_bins: usize,
    /// Photons launched.
    pub photons: u64,
    /// Σ weight per class and bin.
    pub sum: [Vec<f64>; CLASSES],
    /// Σ weight² per bin (all classes; a photon lands in one bin at most).
    pub sum_sq: Vec<f64>,
    /// Σ weight² per class.
    pub class_sum_sq: [f64; CLASSES],
    /// Σ weight of scattered photons leaving after at least one internal reflection at the
    /// cuticle that happened after their first scattering (with [`Options::cortex_exit`]).
    pub after_cuticle_reflection: f64,
    /// Σ weight of scattered photons leaving after re-entering the medulla from the cortex
    /// after their first scattering (with [`Options::cortex_exit`]).
    pub after_reentry: f64,
    /// Σ weight of photons abandoned after `MAX_EVENTS` events.
    pub abandoned: f64,
    /// Σ weight of photons leaving the fiber without having scattered (reflected at entry
    /// included).
    pub unscattered: f64,
    /// Σ weight² of every photon leaving the fiber (scattered or not).
    pub exit_sq: f64,
}

impl Tally {
    fn new(n_bins: usize) -> Tally {
        Tally {
            n_bins,
            photons: 0,
            sum: std::array::from_fn(|_| vec![0.0; n_bins]),
            sum_sq: vec![0.0; n_bins],
            class_sum_sq: [0.0; CLASSES],
            after_cuticle_reflection: 0.0,
            after_reentry: 0.0,
            abandoned: 0.0,
            unscattered: 0.0,
            exit_sq: 0.0,
        }
    }

    fn merge(&mut self, other: &Tally) {
        self.photons += other.photons;
        for (a, b) in self.sum.iter_mut().zip(other.sum.iter()) {
            for (x, y) in a.iter_mut().zip(b) {
                *x += y;
            }
        }
        for (x, y) in self.sum_sq.iter_mut().zip(&other.sum_sq) {
            *x += y;
        }
        for (x, y) in self.class_sum_sq.iter_mut().zip(&other.class_sum_sq) {
            *x += y;
        }
        self.after_cuticle_reflection += other.after_cuticle_reflection;
        self.after_reentry += other.after_reentry;
        self.abandoned += other.abandoned;
        self.unscattered += other.unscattered;
        self.exit_sq += other.exit_sq;
    }

    /// All energy leaving the fiber per photon, scattered or not (h averaged over [−1, 1]).
    pub fn all_exiting(&self) -> f64 {
        let scattered: f64 = self.sum.iter().flatten().sum();
        (scattered + self.unscattered) / self.photons as f64
    }

    /// Standard error of [`Tally::all_exiting`].
    pub fn all_exiting_std_error(&self) -> f64 {
        let n = self.photons as f64;
        let mean = self.all_exiting();
        ((self.exit_sq / n - mean * mean).max(0.0) / n).sqrt()
    }

    /// Bin width in φ.
    pub fn width(&self) -> f64 {
        TAU / self.n_bins as f64
    }

    /// Centre of bin `b`.
    pub fn centre(&self, b: usize) -> f64 {
        -PI + (b as f64 + 0.5) * self.width()
    }

    fn norm(&self) -> f64 {
        1.0 / (self.photons as f64 * self.width())
    }

    /// Energy per unit φ in each bin, all classes: comparable with Σ_p N^s_p(φ) averaged over
    /// the bin.
    pub fn density(&self) -> Vec<f64> {
        (0..self.n_bins)
            .map(|b| self.sum.iter().map(|s| s[b]).sum::<f64>() * self.norm())
            .collect()
    }

    /// Energy per unit φ in each bin for one class.
    pub fn class_density(&self, class: Class) -> Vec<f64> {
        self.sum[class as usize]
            .iter()
            .map(|s| s * self.norm())
            .collect()
    }

    /// Standard error of [`Tally::density`] per bin.
    pub fn std_error(&self) -> Vec<f64> {
        let n = self.photons as f64;
        (0..self.n_bins)
            .map(|b| {
                let mean = self.sum.iter().map(|s| s[b]).sum::<f64>() / n;
                let var = (self.sum_sq[b] / n - mean * mean).max(0.0);
                (var / n).sqrt() / self.width()
            })
            .collect()
    }

    /// Total scattered energy leaving, ∫ density dφ (comparable with Σ_p ∫ N^s_p dφ).
    pub fn total(&self) -> f64 {
        self.density().iter().sum::<f64>() * self.width()
    }

    /// Total scattered energy of one class.
    pub fn class_total(&self, class: Class) -> f64 {
        self.sum[class as usize].iter().sum::<f64>() / self.photons as f64
    }

    /// Standard error of [`Tally::class_total`].
    pub fn class_std_error(&self, class: Class) -> f64 {
        let n = self.photons as f64;
        let mean = self.class_total(class);
        ((self.class_sum_sq[class as usize] / n - mean * mean).max(0.0) / n).sqrt()
    }

    /// Total weight, as energy per photon, of the `after_*` and `abandoned` counters.
    pub fn fraction(&self, counter: f64) -> f64 {
        counter / self.photons as f64
    }
}

type V2 = [f64; 2];

fn dot(a: V2, b: V2) -> f64 {
    a[0] * b[0] + a[1] * b[1]
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Region {
    Outside,
    Cortex,
    Medulla,
}

/// The cross-section at the view angle, with per-2D-length coefficients.
#[derive(Clone, Copy, Debug)]
struct Slice {
    eta_c: f64,
    eta_m: f64,
    kappa: f64,
    layers: f64,
    cortex_abs: f64,
    medulla_sca: f64,
    medulla_abs: f64,
    /// Cauchy scale −ln|g| of the wrapped Cauchy (∞ for g = 0).
    cauchy_scale: f64,
    /// g < 0: the wrapped Cauchy is turned by π.
    backward: bool,
}

impl Slice {
    fn new(p: &McParams) -> Slice {
        Slice {
            eta_c: bravais(p.eta_c, p.theta_r),
            eta_m: bravais(p.eta_m, p.theta_r),
            kappa: p.kappa,
            layers: p.layers,
            cortex_abs: p.sigma_ca / cos_refracted(p.eta_c, p.theta_r),
            medulla_sca: p.sigma_ms / cos_refracted(p.eta_m, p.theta_r),
            medulla_abs: p.sigma_ma / cos_refracted(p.eta_m, p.theta_r),
            cauchy_scale: -(p.g.abs().ln()),
            backward: p.g < 0.0,
        }
    }

    fn index(&self, r: Region) -> f64 {
        match r {
            Region::Outside => 1.0,
            Region::Cortex => self.eta_c,
            Region::Medulla => self.eta_m,
        }
    }

    /// A 2D Henyey–Greenstein deflection: the wrapped Cauchy with ρ = |g| is the Cauchy
    /// distribution of scale −ln ρ wrapped onto the circle (turned by π for g < 0).
    fn deflection(&self, rng: &mut SplitMix64) -> f64 {
        let u = rng.unit();
        let base = if self.cauchy_scale.is_finite() {
            self.cauchy_scale * (PI * (u - 0.5)).tan()
        } else {
            TAU * u
        };
        if self.backward {
            base + PI
        } else {
            base
        }
    }
}

/// Distance along d (|d| = 1) from p to the circle of radius r, for a point inside (or on)
/// it: the larger root, never negative.
fn exit_circle(p: V2, d: V2, r: f64) -> f64 {
    let b = dot(p, d);
    let c = dot(p, p) - r * r;
    (-b + (b * b - c).max(0.0).sqrt()).max(0.0)
}

/// Distance along d from a point outside (or on) the circle of radius r to where it enters
/// it, if it does.
fn enter_circle(p: V2, d: V2, r: f64) -> Option<f64> {
    if r <= 0.0 {
        return None;
    }
    let b = dot(p, d);
    if b >= 0.0 {
        return None; // moving away from the centre: a point on or outside never enters
    }
    let c = dot(p, p) - r * r;
    let disc = b * b - c;
    if disc <= 0.0 {
        return None;
    }
    let t = -b - disc.sqrt();
    (t > 1e-12).then_some(t)
}

fn rotate(d: V2, angle: f64) -> V2 {
    let (s, c) = angle.sin_cos();
    [c * d[0] - s * d[1], s * d[0] + c * d[1]]
}

/// Outcome of a Fresnel event.
enum Crossing {
    Reflected,
    Transmitted(Region),
}

/// One photon's state.
struct Photon {
    p: V2,
    d: V2,
    w: f64,
    region: Region,
    /// Scattering events so far.
    scatters: u32,
    /// Events before the first scattering (at most 8 kept; longer strings are `Other`).
    prefix: [u8; 8],
    prefix_len: usize,
    prefix_overflow: bool,
    cuticle_reflection_after: bool,
    reentry_after: bool,
    events: u32,
}

impl Photon {
    fn new(h: f64) -> Photon {
        Photon {
            p: [(1.0 - h * h).max(0.0).sqrt(), h],
            d: [-1.0, 0.0],
            w: 1.0,
            region: Region::Outside,
            scatters: 0,
            prefix: [0; 8],
            prefix_len: 0,
            prefix_overflow: false,
            cuticle_reflection_after: false,
            reentry_after: false,
            events: 0,
        }
    }

    fn record(&mut self, e: u8) {
        if self.scatters > 0 {
            return;
        }
        if self.prefix_len < self.prefix.len() {
            self.prefix[self.prefix_len] = e;
            self.prefix_len += 1;
        } else {
            self.prefix_overflow = true;
        }
    }

    fn class(&self) -> Class {
        if self.prefix_overflow {
            return Class::Other;
        }
        match &self.prefix[..self.prefix_len] {
            b"Tt" => Class::TttT,
            b"Ttr" => Class::TtrtT,
            b"TttRt" => Class::TttRttT,
            _ => Class::Other,
        }
    }

    /// Moves by `t` in the current region, absorbing.
    fn advance(&mut self, s: &Slice, t: f64) {
        self.p = [self.p[0] + t * self.d[0], self.p[1] + t * self.d[1]];
        let sigma = match self.region {
            Region::Cortex => s.cortex_abs,
            Region::Medulla => s.medulla_abs,
            Region::Outside => 0.0,
        };
        if sigma > 0.0 {
            self.w *= (-sigma * t).exp();
        }
    }

    /// A Fresnel event at the circle of radius `r` the photon is on (the outer circle, r = 1,
    /// is the cuticle), reflecting or transmitting with the Fresnel probabilities.
    fn cross(&mut self, s: &Slice, r: f64, rng: &mut SplitMix64) -> Crossing {
        // Snap onto the circle, so that rounding never accumulates.
        let len = dot(self.p, self.p).sqrt();
        self.p = [self.p[0] * r / len, self.p[1] * r / len];
        let mut n = [self.p[0] / r, self.p[1] / r];
        if dot(n, self.d) > 0.0 {
            n = [-n[0], -n[1]];
        }
        let other = match (r == 1.0, self.region) {
            (true, Region::Outside) => Region::Cortex,
            (true, _) => Region::Outside,
            (false, Region::Cortex) => Region::Medulla,
            (false, _) => Region::Cortex,
        };
        let (n1, n2) = (s.index(self.region), s.index(other));
        let cos_i = (-dot(n, self.d)).clamp(0.0, 1.0);
        let refl = if r == 1.0 {
            cuticle(cos_i, n1, n2, s.layers)
        } else {
            dielectric(cos_i, n1, n2)
        };
        let eta = n1 / n2;
        let sin2_t = eta * eta * (1.0 - cos_i * cos_i);
        if rng.unit() < refl || sin2_t >= 1.0 {
            self.d = [
                self.d[0] + 2.0 * cos_i * n[0],
                self.d[1] + 2.0 * cos_i * n[1],
            ];
            self.normalise();
            Crossing::Reflected
        } else {
            let k = eta * cos_i - (1.0 - sin2_t).sqrt();
            self.d = [eta * self.d[0] + k * n[0], eta * self.d[1] + k * n[1]];
            self.normalise();
            self.region = other;
            Crossing::Transmitted(other)
        }
    }

    fn normalise(&mut self) {
        let l = dot(self.d, self.d).sqrt();
        self.d = [self.d[0] / l, self.d[1] / l];
    }

    /// Free flight to the next scattering event inside the medulla, or to its boundary.
    /// Returns true when the photon scattered (its direction is then already turned).
    fn medulla_flight(&mut self, s: &Slice, rng: &mut SplitMix64) -> bool {
        let t_exit = exit_circle(self.p, self.d, s.kappa);
        let dist = if s.medulla_sca > 0.0 {
            -(1.0 - rng.unit()).ln() / s.medulla_sca
        } else {
            f64::INFINITY
        };
        if dist < t_exit {
            self.advance(s, dist);
            self.d = rotate(self.d, s.deflection(rng));
            self.normalise();
            self.scatters += 1;
            true
        } else {
            self.advance(s, t_exit);
            false
        }
    }

    /// Russian roulette; false when the photon dies.
    fn roulette(&mut self, rng: &mut SplitMix64) -> bool {
        if self.w >= ROULETTE_WEIGHT {
            return true;
        }
        if rng.unit() < ROULETTE_SURVIVE {
            self.w /= ROULETTE_SURVIVE;
            true
        } else {
            false
        }
    }

    /// The photon leaves (after scattering) with its current direction and weight × `factor`.
    fn exit(&self, factor: f64) -> Fate {
        Fate::Exit(Exit {
            class: self.class(),
            phi: -self.d[1].atan2(self.d[0]),
            w: self.w * factor,
            cuticle_reflection_after: self.cuticle_reflection_after,
            reentry_after: self.reentry_after,
        })
    }
}

/// What one photon contributes: (class, exit azimuth, weight) when it scattered and left.
struct Exit {
    class: Class,
    phi: f64,
    w: f64,
    cuticle_reflection_after: bool,
    reentry_after: bool,
}

/// Result of one photon: its exit, or the weight abandoned at `MAX_EVENTS`.
enum Fate {
    Exit(Exit),
    /// Left the fiber without scattering, with this weight.
    Unscattered(f64),
    Abandoned(f64),
    Nothing,
}

/// Prefixes (events before the first scattering) that can still become one of the model's
/// three structures "Tt", "Ttr", "TttRt".
const MODEL_PREFIXES: [&[u8]; 6] = [b"T", b"Tt", b"Ttr", b"Ttt", b"TttR", b"TttRt"];

fn run(s: &Slice, o: &Options, h: f64, rng: &mut SplitMix64) -> Fate {
    let mut ph = Photon::new(h);
    let radial = (-s.cortex_abs * (1.0 - s.kappa)).exp();
    // Entry at the cuticle.
    match ph.cross(s, 1.0, rng) {
        Crossing::Reflected => return Fate::Unscattered(ph.w),
        Crossing::Transmitted(_) => ph.record(b'T'),
    }
    loop {
        ph.events += 1;
        if ph.events > MAX_EVENTS {
            return Fate::Abandoned(ph.w);
        }
        if !ph.roulette(rng) {
            return Fate::Nothing;
        }
        if ph.scatters == 0
            && !o.all_paths
            && !MODEL_PREFIXES.contains(&&ph.prefix[..ph.prefix_len])
        {
            return Fate::Nothing;
        }
        // After the first scattering, an index-matched medulla boundary is crossed straight.
        let matched = ph.scatters > 0 && !o.medulla_boundary;
        match ph.region {
            Region::Cortex => {
                let (t, r) = match enter_circle(ph.p, ph.d, s.kappa) {
                    Some(t) => (t, s.kappa),
                    None => (exit_circle(ph.p, ph.d, 1.0), 1.0),
                };
                ph.advance(s, t);
                if r != 1.0 && matched {
                    ph.region = Region::Medulla;
                    ph.reentry_after = true;
                    continue;
                }
                let before = ph.d;
                match ph.cross(s, r, rng) {
                    Crossing::Reflected => {
                        ph.record(if r == 1.0 { b'R' } else { b'r' });
                        if r == 1.0 && ph.scatters > 0 {
                            ph.cuticle_reflection_after = true;
                        }
                    }
                    Crossing::Transmitted(Region::Outside) => {
                        ph.record(b'T');
                        if ph.scatters == 0 {
                            return Fate::Unscattered(ph.w);
                        }
                        if !o.exit_refraction {
                            ph.d = before;
                        }
                        return ph.exit(1.0);
                    }
                    Crossing::Transmitted(_) => {
                        ph.record(b't');
                        if ph.scatters > 0 {
                            ph.reentry_after = true;
                        }
                    }
                }
            }
            Region::Medulla => {
                if ph.medulla_flight(s, rng) {
                    continue;
                }
                let left = if matched {
                    ph.region = Region::Cortex;
                    true
                } else {
                    match ph.cross(s, s.kappa, rng) {
                        Crossing::Reflected => {
                            ph.record(b'r');
                            false
                        }
                        Crossing::Transmitted(_) => {
                            ph.record(b't');
                            true
                        }
                    }
                };
                // The report's radial exit: the direction on leaving the medulla is the exit
                // direction, attenuated by the radial cortex leg, no cuticle Fresnel.
                if left && ph.scatters > 0 && !o.cortex_exit {
                    return ph.exit(radial);
                }
            }
            Region::Outside => unreachable!("photons leaving the fiber are finished"),
        }
    }
}

/// Runs `photons` photons in `chunks` fixed chunks (each with its own SplitMix64 stream from
/// `seed`), on up to `threads` threads. The result does not depend on `threads`: chunks are
/// merged in order. Offsets are stratified: photon i of N enters at h = −1 + 2(i + u)/N.
pub fn simulate(
    params: &McParams,
    options: &Options,
    n_bins: usize,
    photons: u64,
    seed: u64,
    threads: usize,
) -> Tally {
    const CHUNKS: u64 = 32;
    let slice = Slice::new(params);
    let run_chunk = |c: u64| -> Tally {
        let mut tally = Tally::new(n_bins);
        let mut rng = SplitMix64(seed ^ (c.wrapping_add(1)).wrapping_mul(0xd134_2543_de82_ef95));
        let (lo, hi) = (photons * c / CHUNKS, photons * (c + 1) / CHUNKS);
        for i in lo..hi {
            tally.photons += 1;
            let h = -1.0 + 2.0 * (i as f64 + rng.unit()) / photons as f64;
            let fate = run(&slice, options, h, &mut rng);
            match fate {
                Fate::Exit(e) => {
                    let u = (e.phi + PI) / TAU;
                    let b = ((u * n_bins as f64) as usize).min(n_bins - 1);
                    tally.sum[e.class as usize][b] += e.w;
                    tally.sum_sq[b] += e.w * e.w;
                    tally.class_sum_sq[e.class as usize] += e.w * e.w;
                    tally.exit_sq += e.w * e.w;
                    if e.cuticle_reflection_after {
                        tally.after_cuticle_reflection += e.w;
                    }
                    if e.reentry_after {
                        tally.after_reentry += e.w;
                    }
                }
                Fate::Abandoned(w) => tally.abandoned += w,
                Fate::Unscattered(w) => {
                    tally.unscattered += w;
                    tally.exit_sq += w * w;
                }
                Fate::Nothing => {}
            }
        }
        tally
    };
    let threads = threads.clamp(1, CHUNKS as usize) as u64;
    let mut parts: Vec<(u64, Tally)> = std::thread::scope(|scope| {
        let handles: Vec<_> = (0..threads)
            .map(|t| {
                let run_chunk = &run_chunk;
                scope.spawn(move || {
                    (t..CHUNKS)
                        .step_by(threads as usize)
                        .map(|c| (c, run_chunk(c)))
                        .collect::<Vec<_>>()
                })
            })
            .collect();
        handles
            .into_iter()
            .flat_map(|h| h.join().expect("MC thread panicked"))
            .collect()
    });
    parts.sort_by_key(|(c, _)| *c);
    let mut total = Tally::new(n_bins);
    for (_, t) in &parts {
        total.merge(t);
    }
    total
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The wrapped-Cauchy sampler has the 2D HG mean cosine g and the right density.
    #[test]
    fn deflection_is_2d_henyey_greenstein() {
        for g in [-0.5, 0.0, 0.3, 0.8] {
            let p = McParams {
                eta_c: 1.5,
                eta_m: 1.5,
                kappa: 0.5,
                layers: 0.5,
                sigma_ca: 0.0,
                sigma_ms: 1.0,
                sigma_ma: 0.0,
                g,
                theta_r: 0.0,
            };
            let s = Slice::new(&p);
            let mut rng = SplitMix64(7);
            let n = 400_000;
            let bins = 36;
            let mut hist = vec![0.0; bins];
            let mut mean_cos = 0.0;
            for _ in 0..n {
                let x = s.deflection(&mut rng);
                mean_cos += x.cos();
                let w = crate::tracer::wrap(x);
                let b = (((w + PI) / TAU * bins as f64) as usize).min(bins - 1);
                hist[b] += 1.0;
            }
            mean_cos /= n as f64;
            assert!((mean_cos - g).abs() < 5e-3, "g {g}: mean cos {mean_cos}");
            for (b, c) in hist.iter().enumerate() {
                let x = -PI + (b as f64 + 0.5) * TAU / bins as f64;
                let pdf = (1.0 - g * g) / (TAU * (1.0 + g * g - 2.0 * g * x.cos()));
                let got = c / (n as f64 * TAU / bins as f64);
                assert!((got - pdf).abs() < 0.05 * pdf + 2e-3, "g {g} bin {b}");
            }
        }
    }

    /// Without a medulla nothing scatters; with a transparent fiber and no cuticle reflection
    /// every photon leaves, and a scattering medulla with no absorption conserves energy.
    #[test]
    fn energy_bookkeeping() {
        let base = McParams {
            eta_c: 1.55,
            eta_m: 1.55,
            kappa: 0.6,
            layers: 0.5,
            sigma_ca: 0.0,
            sigma_ms: 2.0,
            sigma_ma: 0.0,
            g: 0.3,
            theta_r: 0.0,
        };
        let none = simulate(
            &McParams {
                sigma_ms: 0.0,
                ..base
            },
            &Options::FULL,
            12,
            20_000,
            1,
            2,
        );
        assert_eq!(none.total(), 0.0);
        // With l = 0 there is no cuticle reflection and an index-matched medulla has none
        // either: the scattered energy is exactly the probability of scattering, and the
        // simplified simulator (no absorption) must give the same.
        let clear = McParams {
            layers: 0.0,
            ..base
        };
        let full = simulate(&clear, &Options::FULL, 12, 200_000, 2, 2);
        let simp = simulate(&clear, &Options::SIMPLIFIED, 12, 200_000, 2, 2);
        // P(scatter) = ½∫ (1 − exp(−σ·2√(κ² − b²))) dh over the medulla-hitting h.
        let eta = bravais(1.55, 0.0);
        let n = 20_000;
        let mut want = 0.0;
        for i in 0..n {
            let h = -1.0 + 2.0 * (i as f64 + 0.5) / n as f64;
            let b = h / eta;
            if b.abs() < clear.kappa {
                let chord = 2.0 * (clear.kappa * clear.kappa - b * b).sqrt();
                want += (1.0 - (-clear.sigma_ms * chord).exp()) / n as f64;
            }
        }
        assert!(
            (full.total() - want).abs() < 0.01 * want,
            "{} {want}",
            full.total()
        );
        assert!(
            (simp.total() - want).abs() < 0.01 * want,
            "{} {want}",
            simp.total()
        );
        assert_eq!(full.abandoned, 0.0);
    }
}
