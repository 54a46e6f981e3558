//! The thick coat's colour by a random walk (docs/model.md §14, "How it is measured"): light
//! followed backward from the viewer through a semi-infinite coat of straight fibers, each
//! fiber a far-field scatterer sampled through [`Bcsdf::sample_dirs`].
//!
//! The coat is a Boolean medium: fibers of radius r at length density λ, placed independently,
//! their tangents drawn from [`sample_tangent`]. A ray travelling along d meets fibers of
//! tangent u at the rate 2rλ·|d × u| per unit length, so with the majorant 2rλ as the unit of
//! depth (the coat's thickness does not matter, it is semi-infinite) the walk draws a free
//! path of mean 1 and accepts a fiber drawn from the tangent distribution with probability
//! |d × u| (delta tracking): exactly the rate above, with no mean over tangents to compute.
//! A path that leaves the coat (depth above 0) sees the white sky, radiance 1 per channel.

use crate::bcsdf::Bcsdf;
use crate::frame::Vec3;
use crate::rng::{cell_stream, Pcg32};
use crate::spectrum::Rgb;

/// The coat's fibers lie within this sine of the skin plane, tips up: the tangent's component
/// along the skin normal is uniform in [0, `COAT_TANGENT_MAX_SIN`] (sin 30°), its azimuth
/// uniform (docs/model.md §14).
pub const COAT_TANGENT_MAX_SIN: f32 = 0.5;

/// The random stream tag of the walk ("coat").
const STREAM: u64 = 0x636f_6174;

/// How many free paths (null collisions included) one flight may take before the walk gives
/// the photon up as lost (its light counted as absorbed). Tangents have every azimuth, so the
/// acceptance |d × u| averages at least about 0.6 for any d and the limit is never reached in
/// practice; it bounds the loop.
const MAX_FLIGHT_STEPS: u32 = 4096;

/// The walk's budget (docs/model.md §14).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CoatWalk {
    /// Photons per estimate (each a path from the viewer).
    pub photons: u32,
    /// Scattering events after which a photon still inside the coat is dropped (its weight
    /// counted in [`CoatEstimate::unfinished`]).
    pub max_bounces: u32,
    /// Seed of the photons' streams (photon k has its own stream, the same at every colour,
    /// so estimates at neighbouring colours share their noise).
    pub seed: u64,
    /// The coat's depth in majorant free paths over a black floor; `f32::INFINITY` is the
    /// semi-infinite coat of the definition (a finite depth measures a check scene's slab).
    pub depth: f32,
}

impl CoatWalk {
    /// The budget [`super::CoatColour::measure`] uses: 8192 photons, at most 4096 events (the
    /// path tracer's depth limit), the semi-infinite coat.
    pub const DEFAULT: CoatWalk = CoatWalk {
        photons: 8192,
        max_bounces: 4096,
        seed: 1,
        depth: f32::INFINITY,
    };
}

/// A coat colour estimate per channel (docs/model.md §14).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CoatEstimate {
    /// The coat's reflectance toward the viewer under a white sky of radiance 1.
    pub colour: Rgb,
    /// The standard error of `colour`.
    pub std_error: Rgb,
    /// The mean weight of photons still inside the coat after `max_bounces` events (the
    /// most the estimate can lack).
    pub unfinished: Rgb,
}

/// A fiber tangent of the coat from two uniform numbers: the normal component uniform in
/// [0, [`COAT_TANGENT_MAX_SIN`]], the azimuth uniform (z is the skin normal).
#[must_use]
pub fn sample_tangent(u0: f32, u1: f32) -> Vec3 {
    let z = COAT_TANGENT_MAX_SIN * u0;
    let r = libm::sqrtf((1.0 - z * z).max(0.0));
    let phi = core::f32::consts::TAU * u1;
    [r * libm::cosf(phi), r * libm::sinf(phi), z]
}

/// |a × b| of two unit vectors.
fn sine_between(a: Vec3, b: Vec3) -> f32 {
    let c = [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ];
    libm::sqrtf(c[0] * c[0] + c[1] * c[1] + c[2] * c[2])
}

/// The coat colour of `fiber` seen from straight above (docs/model.md §14): the mean over
/// `walk.photons` paths from the viewer of the throughput with which each leaves the coat.
/// Russian roulette after 8 events on the largest channel's throughput (unbiased). Never NaN:
/// a sample with a non-finite weight ends its photon.
#[must_use]
pub fn coat_reflectance<B: Bcsdf>(fiber: &B, walk: &CoatWalk) -> CoatEstimate {
    let n = walk.photons.max(1);
    let (mut sum, mut sum2, mut lost) = ([0.0f64; 3], [0.0f64; 3], [0.0f64; 3]);
    for photon in 0..n {
        let mut rng = Pcg32::new(walk.seed, cell_stream(walk.seed, STREAM, u64::from(photon)));
        let (escaped, left) = one_photon(fiber, walk, &mut rng);
        for c in 0..3 {
            let e = f64::from(escaped[c]);
            sum[c] += e;
            sum2[c] += e * e;
            lost[c] += f64::from(left[c]);
        }
    }
    let nf = f64::from(n);
    let mut est = CoatEstimate {
        colour: Rgb::ZERO,
        std_error: Rgb::ZERO,
        unfinished: Rgb::ZERO,
    };
    for c in 0..3 {
        let mean = sum[c] / nf;
        let var = (sum2[c] / nf - mean * mean).max(0.0);
        est.colour[c] = mean as f32;
        est.std_error[c] = libm::sqrt(var / nf) as f32;
        est.unfinished[c] = (lost[c] / nf) as f32;
    }
    est
}

/// One photon: (the throughput it leaves the coat with, the throughput still inside after
/// `max_bounces` events).
fn one_photon<B: Bcsdf>(fiber: &B, walk: &CoatWalk, rng: &mut Pcg32) -> (Rgb, Rgb) {
    // Depth below the coat's top (≤ 0 inside), in majorant free paths; the path's direction.
    let mut z = 0.0f32;
    let mut d: Vec3 = [0.0, 0.0, -1.0];
    let mut beta = Rgb::splat(1.0);
    let floor = -walk.depth;
    for bounce in 0..walk.max_bounces {
        let tangent = match flight(&mut z, d, floor, rng) {
            Flight::Fiber(t) => t,
            Flight::Leaves => return (beta, Rgb::ZERO),
            Flight::Floor | Flight::Lost => return (Rgb::ZERO, Rgb::ZERO),
        };
        let wr = [-d[0], -d[1], -d[2]];
        let u = [rng.uniform(), rng.uniform(), rng.uniform()];
        let Some(s) = fiber.sample_dirs(wr, tangent, u) else {
            return (Rgb::ZERO, Rgb::ZERO);
        };
        let Some(wi) = s.wi else {
            return (Rgb::ZERO, Rgb::ZERO);
        };
        if !s.weight.is_finite() {
            return (Rgb::ZERO, Rgb::ZERO);
        }
        beta = beta * s.weight.map(|w| w.max(0.0));
        d = wi;
        if bounce >= 8 {
            let survive = beta.max_channel().min(1.0);
            if survive <= 0.0 || rng.uniform() >= survive {
                return (Rgb::ZERO, Rgb::ZERO);
            }
            beta = beta * (1.0 / survive);
        }
    }
    // Still inside: one more flight decides whether the last event's light leaves directly.
    match flight(&mut z, d, floor, rng) {
        Flight::Leaves => (beta, Rgb::ZERO),
        Flight::Floor => (Rgb::ZERO, Rgb::ZERO),
        Flight::Fiber(_) | Flight::Lost => (Rgb::ZERO, beta),
    }
}

/// Where one flight ends.
enum Flight {
    /// At a fiber of this tangent.
    Fiber(Vec3),
    /// Out of the coat, into the sky.
    Leaves,
    /// Through the coat's bottom onto its black floor.
    Floor,
    /// Given up after [`MAX_FLIGHT_STEPS`] null collisions.
    Lost,
}

/// Moves the path from depth `z` along `d` to its next fiber (delta tracking, the module's
/// rate), or out of the coat through its top or onto its floor at depth `floor` (≤ 0).
fn flight(z: &mut f32, d: Vec3, floor: f32, rng: &mut Pcg32) -> Flight {
    for _ in 0..MAX_FLIGHT_STEPS {
        *z += -libm::logf(rng.uniform_open0()) * d[2];
        if *z > 0.0 {
            return Flight::Leaves;
        }
        if *z < floor {
            return Flight::Floor;
        }
        let t = sample_tangent(rng.uniform(), rng.uniform());
        if rng.uniform() < sine_between(d, t) {
            return Flight::Fiber(t);
        }
    }
    Flight::Lost
}
