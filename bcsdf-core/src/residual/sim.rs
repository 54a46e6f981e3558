//! The model's own cross-section simulation at one (θ_r, h) cell (docs/model.md §12,
//! "Residual"): the flatland problem of §3 — outer circle of radius 1 with the layered cuticle
//! Fresnel at η'_c, medulla circle κ at η'_m, cortex absorption σ_ca/cos θ_tc, medulla
//! scattering σ_ms/cos θ_tm (2D Henyey–Greenstein) and absorption σ_ma/cos θ_tm per 2D length.
//!
//! - **Unscattered light** is a deterministic beam tree: the beam entering at h is split at
//!   every interface into its reflected and transmitted beams (× f, × (1 − f); total internal
//!   reflection included), absorbed per leg, until a beam carries less than [`BEAM_CUTOFF`]
//!   (what the cutoff drops is tallied). A chord's signed impact parameter is conserved by
//!   reflection off a circle and only rescaled by refraction (b = h/η'_c in the cortex,
//!   h/η'_m in the medulla), so every leg's length and every event's rotation is the one of
//!   §3's event rule, and the exit azimuth is that rule's Φ.
//! - **Scattered light**: on each medulla chord a beam of weight w crosses, w·(1 − e^{−σ_s ℓ})
//!   scatters. It is carried by photons (first scattering from the truncated exponential on the
//!   chord, medulla absorption up to it) walked with full physics — stochastic Fresnel choice
//!   at every boundary, both absorptions, re-entry into the medulla allowed — until they leave
//!   the fiber. The rest continues as a beam.
//!
//! **Common random numbers.** The cutoff and the photon count go by the weight a beam would
//! carry at σ_ca = 0 (the cortex's absorption is the only colour in the walk; every other
//! factor is grey), and a photon's random choices never depend on its weight. So a cell draws
//! the same random numbers at every σ_ca: the simulation is one smooth function of the colour
//! per seed, and the tables of two colours differ by that function, not by independent noise
//! (what the absorption axis of a baked LUT interpolates between, docs/lut.md "The
//! absorption axis"). At σ_ca = 0 this is the plain weight.
//!
//! Tallies: the total exiting energy and the energy on paths the model does not model, by
//! exit azimuth |Φ| (docs/model.md §12 lists which paths those are).

use crate::fresnel;
use crate::geometry::{Chord, MedullaEvent, ViewSlice};
use crate::math::{wrap_angle, Libm, PI};
use crate::medulla::sample_hg_2d;
use crate::rng::Pcg32;
use crate::spectrum::Rgb;
use crate::unscattered::{cortex_leg, transmittance, Extinction};

use super::flatland::{dot, entry_distance, exit_distance, normal, reflect, refract};

/// A beam that would carry less than this without cortex absorption is dropped; its weight
/// is tallied as [`CellTally::dropped`].
pub const BEAM_CUTOFF: f32 = 1e-7;

/// Beams waiting in the depth-first walk of the tree; a beam that does not fit is dropped
/// (tallied like the cutoff).
pub const BEAM_STACK: usize = 1024;

/// Interface and scattering events after which a photon walk is abandoned (tallied as
/// dropped); never reached for the presets.
pub const MAX_PHOTON_EVENTS: u32 = 10_000;

pub use super::events::{
    Event, Events, MODELLED_AFTER_SCATTERING, MODELLED_BEFORE_SCATTERING, MODELLED_UNSCATTERED,
};

/// The cross-section at one θ_r and the coefficients of its regions, per 2D length.
#[derive(Clone, Copy, Debug)]
pub struct Section {
    /// Bravais indices, κ, and the 3D-length factors.
    pub slice: ViewSlice,
    /// σ_ca/cos θ_tc (RGB), (σ_ms + σ_ma)/cos θ_tm, σ_ms/cos θ_tm.
    pub ext: Extinction,
    /// σ_ma/cos θ_tm.
    pub medulla_absorption: f32,
    /// Cuticle layers l.
    pub layers: f32,
    /// The Henyey–Greenstein g of the medulla.
    pub g: f32,
}

/// What one cell's simulation found; energies per unit incident energy, f64.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct CellTally {
    /// All energy leaving the fiber, E_sim.
    pub exiting: [f64; 3],
    /// The part on paths the model does not model.
    pub unmodelled: [f64; 3],
    /// Energy dropped by the beam cutoff, the stack bound and the photon event bound.
    pub dropped: [f64; 3],
    /// Beams processed.
    pub beams: u64,
    /// Photons launched.
    pub photons: u64,
}

/// Where a beam is, heading where.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Place {
    /// In the cortex just inside the cuticle, heading inward.
    CortexIn,
    /// In the cortex just outside the medulla, heading out.
    CortexOut,
    /// Just inside the medulla boundary, about to cross the medulla.
    Medulla,
}

/// A beam of the tree, carrying its weight in each of `P` colours (cortex absorptions) at
/// once: the walk is the same at every colour ("Common random numbers"), only the weights
/// differ, so one walk serves `P` absorption planes ([`simulate_cells`]).
#[derive(Clone, Copy, Debug)]
struct Beam<const P: usize> {
    /// The weight at each colour.
    weight: [Rgb; P],
    /// The weight the beam would carry without cortex absorption (σ_ca = 0; every other
    /// factor is grey): what the cutoff and the photon count go by, so that the tree's shape,
    /// the photons launched and therefore the random numbers drawn are the same at every
    /// colour ("Common random numbers" in the module documentation).
    clear: f32,
    events: Events,
    /// Sum of the event rule's rotations so far (docs/model.md §3); the travel direction
    /// angle is π − turn, the exit azimuth π + turn.
    turn: f32,
    place: Place,
}

/// Each colour's weight `w` times the grey factor `s`.
#[inline(always)]
fn scaled<const P: usize>(w: &[Rgb; P], s: f32) -> [Rgb; P] {
    core::array::from_fn(|k| w[k] * s)
}

/// Each colour's weight `w` times that colour's factor `t`.
#[inline(always)]
fn filtered<const P: usize>(w: &[Rgb; P], t: &[Rgb; P]) -> [Rgb; P] {
    core::array::from_fn(|k| w[k] * t[k])
}

/// The per-chord constants of the beam tree at offset h.
struct Legs<const P: usize> {
    /// a, c and the medulla event of the chord.
    chord: Chord,
    /// Cuticle reflectance f (outside at a, inside at c: the same, docs/model.md §4).
    f: f32,
    /// Medulla reflectance f_m (1 under total reflection; 0 when missed).
    fm: f32,
    /// Transmittance of the cortex chord that misses the medulla (2 cos c), or of one cortex
    /// leg ℓ_c when it hits, at each colour.
    cortex: [Rgb; P],
    /// Medulla chord ℓ_m = 2κ cos μ (0 unless the ray enters).
    ell_m: f32,
}

/// Adds `w` to the RGB tally `acc`.
fn add(acc: &mut [f64; 3], w: Rgb) {
    for (a, v) in acc.iter_mut().zip(w.0) {
        *a += f64::from(v);
    }
}

/// The tallies of `P` colours and their histograms (`n_phi` bins each, colour k's at
/// `hist[k·n_phi..]`).
struct Tallies<'h, const P: usize> {
    cells: [CellTally; P],
    hist: &'h mut [[f64; 3]],
    n_phi: usize,
}

impl<const P: usize> Tallies<'_, P> {
    fn exiting(&mut self, w: &[Rgb; P]) {
        for (t, w) in self.cells.iter_mut().zip(w) {
            add(&mut t.exiting, *w);
        }
    }

    fn dropped(&mut self, w: &[Rgb; P]) {
        for (t, w) in self.cells.iter_mut().zip(w) {
            add(&mut t.dropped, *w);
        }
    }

    /// Tallies `w` as unmodelled and bins it at exit azimuth `phi`.
    fn unmodelled(&mut self, phi: f32, w: &[Rgb; P]) {
        let n = self.n_phi;
        for (k, (t, w)) in self.cells.iter_mut().zip(w).enumerate() {
            add(&mut t.unmodelled, *w);
            bin(&mut self.hist[k * n..(k + 1) * n], phi, *w);
        }
    }
}

/// Simulates the cell (θ_r of `section`, offset `h`): the beam tree, and `photons` photons
/// per unit of scattered weight without cortex absorption (at least one per medulla chord
/// that scatters; the same random numbers at every colour), drawn from `rng`. Unmodelled
/// energy is binned by |Φ| into `hist` (`n_phi` bins of [0, π], RGB interleaved,
/// accumulated). Allocation-free; the same bits for the same inputs. [`simulate_cells`] at
/// the one colour of `section`.
pub fn simulate_cell(
    section: &Section,
    h: f32,
    photons: u32,
    rng: &mut Pcg32,
    hist: &mut [[f64; 3]],
) -> CellTally {
    let n_phi = hist.len();
    let [t] = simulate_cells(section, &[section.ext.cortex], h, photons, rng, hist, n_phi);
    t
}

/// [`simulate_cell`] at `P` colours in one walk: colour k has the cortex extinction
/// `cortex[k]` (σ_ca/cos θ_tc per channel) in place of `section.ext.cortex`, everything else
/// of `section`. The walk draws the same random numbers at every colour ("Common random
/// numbers"), so colour k's tally is, bit for bit, what [`simulate_cell`] gives for the
/// section with `ext.cortex = cortex[k]` and the same `rng` state; `rng` ends where that
/// call leaves it. Colour k's histogram is `hist[k·n_phi..(k + 1)·n_phi]`; nothing is
/// simulated (all tallies zero) when `hist` is shorter than `P·n_phi`. What the bake's
/// absorption planes are made with: their walk's geometry, Fresnel choices and scattering
/// are computed once for all planes.
pub fn simulate_cells<const P: usize>(
    section: &Section,
    cortex: &[Rgb; P],
    h: f32,
    photons: u32,
    rng: &mut Pcg32,
    hist: &mut [[f64; 3]],
    n_phi: usize,
) -> [CellTally; P] {
    let Some(hist) = hist.get_mut(..P * n_phi) else {
        return [CellTally::default(); P];
    };
    let mut tally = Tallies {
        cells: [CellTally::default(); P],
        hist,
        n_phi,
    };
    let (mut beams, mut launched) = (0u64, 0u64);
    let slice = &section.slice;
    let chord = Chord::at_offset::<Libm>(slice, h);
    let f = fresnel::cuticle::<Libm>(chord.cos_a, slice.eta_c_prime, section.layers);
    let legs_through = |length: f32| -> [Rgb; P] {
        core::array::from_fn(|k| transmittance::<Libm>(cortex[k], length))
    };
    let (fm, cortex_t, ell_m) = match chord.medulla {
        MedullaEvent::Miss => (0.0, legs_through(2.0 * chord.cos_c), 0.0),
        MedullaEvent::TotalReflection { cos_m, .. } => {
            (1.0, legs_through(cortex_leg(slice, &chord, cos_m)), 0.0)
        }
        MedullaEvent::Enter { cos_m, cos_mu, .. } => (
            fresnel::medulla::<Libm>(cos_m, slice.eta_m_prime / slice.eta_c_prime),
            legs_through(cortex_leg(slice, &chord, cos_m)),
            2.0 * slice.kappa * cos_mu,
        ),
    };
    let legs = Legs {
        chord,
        f,
        fm,
        cortex: cortex_t,
        ell_m,
    };
    let (a, c) = (chord.a, chord.c);
    // R: reflection off the outside, Φ_R = −2a.
    tally.exiting(&[Rgb::splat(f); P]);
    beams += 1;
    let mut stack = [Beam {
        weight: [Rgb::ZERO; P],
        clear: 0.0,
        events: Events::EMPTY,
        turn: 0.0,
        place: Place::CortexIn,
    }; BEAM_STACK];
    let mut top = 0usize;
    push(
        &mut stack,
        &mut top,
        &mut tally,
        Beam {
            weight: [Rgb::splat(1.0 - f); P],
            clear: 1.0 - f,
            events: Events::EMPTY.push(Event::T),
            turn: c - a,
            place: Place::CortexIn,
        },
    );
    while top > 0 {
        top -= 1;
        let beam = stack[top];
        beams += 1;
        let w = beam.weight;
        match (beam.place, legs.chord.medulla) {
            (Place::CortexIn, MedullaEvent::Miss) | (Place::CortexOut, _) => {
                // A cortex leg to the cuticle, then out (T) or back in (R).
                let w = filtered(&w, &legs.cortex);
                exit_beam(
                    &Beam {
                        weight: scaled(&w, 1.0 - legs.f),
                        clear: beam.clear * (1.0 - legs.f),
                        events: beam.events.push(Event::T),
                        turn: beam.turn + (c - a),
                        ..beam
                    },
                    &mut tally,
                );
                push(
                    &mut stack,
                    &mut top,
                    &mut tally,
                    Beam {
                        weight: scaled(&w, legs.f),
                        clear: beam.clear * legs.f,
                        events: beam.events.push(Event::R),
                        turn: beam.turn + PI + 2.0 * c,
                        place: Place::CortexIn,
                    },
                );
            }
            (Place::CortexIn, MedullaEvent::TotalReflection { m, .. })
            | (Place::CortexIn, MedullaEvent::Enter { m, .. }) => {
                // A cortex leg to the medulla, reflected off it (r) or into it (t).
                let w = filtered(&w, &legs.cortex);
                push(
                    &mut stack,
                    &mut top,
                    &mut tally,
                    Beam {
                        weight: scaled(&w, legs.fm),
                        clear: beam.clear * legs.fm,
                        events: beam.events.push(Event::Rm),
                        turn: beam.turn + PI - 2.0 * m,
                        place: Place::CortexOut,
                    },
                );
                if let MedullaEvent::Enter { mu, .. } = legs.chord.medulla {
                    push(
                        &mut stack,
                        &mut top,
                        &mut tally,
                        Beam {
                            weight: scaled(&w, 1.0 - legs.fm),
                            clear: beam.clear * (1.0 - legs.fm),
                            events: beam.events.push(Event::Tm),
                            turn: beam.turn + (mu - m),
                            place: Place::Medulla,
                        },
                    );
                }
            }
            (Place::Medulla, MedullaEvent::Enter { m, mu, .. }) => {
                // Across the medulla: the part that scatters goes to the photons, the rest
                // reaches the far side, reflected (r) or out (t).
                let ell = legs.ell_m;
                let p = 1.0 - libm::expf(-section.ext.medulla_scattering * ell);
                if p > 0.0 {
                    let count = photon_count(photons, beam.clear * p);
                    launched += u64::from(count);
                    let photon_walk = Scatter {
                        section,
                        cortex,
                        beam: &beam,
                        h,
                    };
                    photon_walk.run(&scaled(&w, p), count, rng, &mut tally);
                }
                let through = libm::expf(-section.ext.medulla * ell);
                let (w, clear) = (scaled(&w, through), beam.clear * through);
                push(
                    &mut stack,
                    &mut top,
                    &mut tally,
                    Beam {
                        weight: scaled(&w, legs.fm),
                        clear: clear * legs.fm,
                        events: beam.events.push(Event::Rm),
                        turn: beam.turn + PI + 2.0 * mu,
                        place: Place::Medulla,
                    },
                );
                push(
                    &mut stack,
                    &mut top,
                    &mut tally,
                    Beam {
                        weight: scaled(&w, 1.0 - legs.fm),
                        clear: clear * (1.0 - legs.fm),
                        events: beam.events.push(Event::Tm),
                        turn: beam.turn + (mu - m),
                        place: Place::CortexOut,
                    },
                );
            }
            // A beam in the medulla exists only where the chord enters it.
            (Place::Medulla, _) => tally.dropped(&w),
        }
    }
    let mut cells = tally.cells;
    for t in &mut cells {
        t.beams = beams;
        t.photons = launched;
    }
    cells
}

/// Pushes `beam` onto the walk's stack, or tallies it as dropped when its weight without
/// cortex absorption is below the cutoff or the stack is full.
fn push<const P: usize>(
    stack: &mut [Beam<P>; BEAM_STACK],
    top: &mut usize,
    tally: &mut Tallies<'_, P>,
    beam: Beam<P>,
) {
    if beam.clear < BEAM_CUTOFF || *top == BEAM_STACK {
        tally.dropped(&beam.weight);
    } else {
        stack[*top] = beam;
        *top += 1;
    }
}

/// Tallies a beam leaving the fiber: all of it as exiting, and in the histograms at its exit
/// azimuth Φ = π + turn when its event string is not one of the eight modelled paths.
fn exit_beam<const P: usize>(beam: &Beam<P>, tally: &mut Tallies<'_, P>) {
    tally.exiting(&beam.weight);
    if !MODELLED_UNSCATTERED.contains(&beam.events) {
        tally.unmodelled(PI + beam.turn, &beam.weight);
    }
}

/// Adds `w` to the |Φ| bin of `hist`.
fn bin(hist: &mut [[f64; 3]], phi: f32, w: Rgb) {
    let n = hist.len();
    if n == 0 {
        return;
    }
    let x = wrap_angle(phi).abs() / PI;
    let k = ((x * n as f32) as usize).min(n - 1);
    for (a, v) in hist[k].iter_mut().zip(w.0) {
        *a += f64::from(v);
    }
}

/// Region of a photon.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Region {
    Medulla,
    Cortex,
}

/// Photons carrying a scattering chord's weight: `photons` per unit of `clear`, the chord's
/// scattered weight without cortex absorption (the same at every colour), at least one.
fn photon_count(photons: u32, clear: f32) -> u32 {
    (libm::ceilf(photons as f32 * clear) as u32).max(1)
}

/// The photons of one scattering medulla chord: the chord `beam` crosses at offset `h`,
/// in `section` with the colours' cortex extinctions `cortex` (docs/model.md §12,
/// "Residual").
struct Scatter<'a, const P: usize> {
    section: &'a Section,
    cortex: &'a [Rgb; P],
    beam: &'a Beam<P>,
    h: f32,
}

impl<const P: usize> Scatter<'_, P> {
    /// Launches `k` photons carrying `w_s` (per colour), the weight of the beam that
    /// scatters on its medulla chord, and walks them out of the fiber.
    fn run(&self, w_s: &[Rgb; P], k: u32, rng: &mut Pcg32, tally: &mut Tallies<'_, P>) {
        let section = self.section;
        let slice = &section.slice;
        let kappa = slice.kappa;
        let sigma_s = section.ext.medulla_scattering;
        // The chord: travel direction at angle π − turn, signed impact parameter h/η'_m.
        let angle = PI - self.beam.turn;
        let d0 = [libm::cosf(angle), libm::sinf(angle)];
        let b = self.h / slice.eta_m_prime;
        let q = [b * d0[1], -b * d0[0]];
        let half = libm::sqrtf((kappa * kappa - b * b).max(0.0));
        let entry = [q[0] - half * d0[0], q[1] - half * d0[1]];
        let ell = 2.0 * half;
        let p_scatter = 1.0 - libm::expf(-sigma_s * ell);
        let modelled_before = MODELLED_BEFORE_SCATTERING.contains(&self.beam.events);
        let w0 = scaled(w_s, 1.0 / k as f32);
        for _ in 0..k {
            // First scattering from the truncated exponential on the chord.
            let u = rng.uniform();
            let s = (-libm::logf(1.0 - u * p_scatter) / sigma_s).min(ell);
            let mut w = scaled(&w0, libm::expf(-section.medulla_absorption * s));
            let mut p = [entry[0] + s * d0[0], entry[1] + s * d0[1]];
            let mut a = angle + sample_hg_2d(section.g, rng.uniform());
            let mut d = [libm::cosf(a), libm::sinf(a)];
            let mut region = Region::Medulla;
            let mut after = Events::EMPTY;
            let mut events = 0u32;
            let mut left = false;
            while events < MAX_PHOTON_EVENTS {
                events += 1;
                match region {
                    Region::Medulla => {
                        let t = exit_distance(p, d, kappa);
                        let free = -libm::logf(rng.uniform_open0()) / sigma_s;
                        if free < t {
                            p = [p[0] + free * d[0], p[1] + free * d[1]];
                            w = scaled(&w, libm::expf(-section.medulla_absorption * free));
                            a = libm::atan2f(d[1], d[0]) + sample_hg_2d(section.g, rng.uniform());
                            d = [libm::cosf(a), libm::sinf(a)];
                            continue;
                        }
                        p = [p[0] + t * d[0], p[1] + t * d[1]];
                        w = scaled(&w, libm::expf(-section.medulla_absorption * t));
                        let n = normal(p);
                        let cos_i = dot(d, n).clamp(0.0, 1.0);
                        let eta = slice.eta_m_prime / slice.eta_c_prime;
                        let fr = fresnel::dielectric::<Libm>(
                            cos_i,
                            slice.eta_c_prime / slice.eta_m_prime,
                        );
                        match refract(d, n, eta) {
                            Some(out) if rng.uniform() >= fr => {
                                d = out;
                                region = Region::Cortex;
                                after = after.push(Event::Tm);
                            }
                            _ => {
                                d = reflect(d, n);
                                after = after.push(Event::Rm);
                            }
                        }
                    }
                    Region::Cortex => {
                        let to_medulla = if kappa > 0.0 {
                            entry_distance(p, d, kappa)
                        } else {
                            None
                        };
                        let t = to_medulla.unwrap_or_else(|| exit_distance(p, d, 1.0));
                        p = [p[0] + t * d[0], p[1] + t * d[1]];
                        let through: [Rgb; P] =
                            core::array::from_fn(|c| transmittance::<Libm>(self.cortex[c], t));
                        w = filtered(&w, &through);
                        let n = normal(p);
                        if to_medulla.is_some() {
                            // From the cortex onto the medulla.
                            let cos_i = (-dot(d, n)).clamp(0.0, 1.0);
                            let eta = slice.eta_c_prime / slice.eta_m_prime;
                            let fr = fresnel::medulla::<Libm>(
                                cos_i,
                                slice.eta_m_prime / slice.eta_c_prime,
                            );
                            match refract(d, n, eta) {
                                Some(inside) if rng.uniform() >= fr => {
                                    d = inside;
                                    region = Region::Medulla;
                                    after = after.push(Event::Tm);
                                }
                                _ => {
                                    d = reflect(d, n);
                                    after = after.push(Event::Rm);
                                }
                            }
                        } else {
                            // From the cortex onto the cuticle: the outside angle a has
                            // sin a = η'_c sin c; beyond 1 the cuticle reflects totally.
                            let cos_c = dot(d, n).clamp(0.0, 1.0);
                            let sin_a =
                                slice.eta_c_prime * libm::sqrtf((1.0 - cos_c * cos_c).max(0.0));
                            let fr = if sin_a >= 1.0 {
                                1.0
                            } else {
                                let cos_a = libm::sqrtf((1.0 - sin_a) * (1.0 + sin_a));
                                fresnel::cuticle::<Libm>(cos_a, slice.eta_c_prime, section.layers)
                            };
                            match refract(d, n, slice.eta_c_prime) {
                                Some(out) if rng.uniform() >= fr => {
                                    after = after.push(Event::T);
                                    d = out;
                                    left = true;
                                    break;
                                }
                                _ => {
                                    d = reflect(d, n);
                                    after = after.push(Event::R);
                                }
                            }
                        }
                    }
                }
            }
            if !left {
                tally.dropped(&w);
                continue;
            }
            tally.exiting(&w);
            if !(modelled_before && after == MODELLED_AFTER_SCATTERING) {
                // The exit azimuth of the event rule: Φ = −(travel direction angle).
                tally.unmodelled(-libm::atan2f(d[1], d[0]), &w);
            }
        }
    }
}
