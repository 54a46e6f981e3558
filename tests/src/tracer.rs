//! A brute-force 2D ray tracer of the double cylinder's cross-section (docs/model.md §3), in f64.
//!
//! The cross-section is drawn explicitly: an outer circle of radius 1 (the cuticle, index
//! η'_c inside) and a concentric medulla circle of radius κ (index η'_m inside). A ray is
//! followed through a given event string such as `"TttRttT"` — uppercase events at the outer
//! circle, lowercase at the medulla, `R`/`r` reflect and `T`/`t` transmit — with explicit
//! ray–circle intersections, vector Snell refraction and mirror reflection. Nothing here uses
//! the angles a, c, m, μ of the closed forms, and nothing is shared with `bcsdf-core`.
//!
//! The view ray comes in travelling along −x at height y = h, so its direction toward the
//! viewer is +x (φ_r = 0); the exit azimuth of the traced path is Φ = −atan2(d_y, d_x) of the
//! final travel direction d, which makes Φ_R = −2·asin h as in docs/model.md §1.

/// The eight unscattered paths in `bcsdf_core::Lobe::ALL` order, as event strings.
pub const PATHS: [&str; 8] = ["R", "TT", "TRT", "TrT", "TttT", "TtrtT", "TrRrT", "TttRttT"];

/// Bravais' effective index of a medium of index `eta` for the normal-plane projection of a
/// ray at longitudinal angle `theta`: √(η² − sin²θ)/cos θ (docs/model.md §3).
pub fn bravais(eta: f64, theta: f64) -> f64 {
    (eta * eta - theta.sin().powi(2)).sqrt() / theta.cos()
}

/// Cosine of the refracted longitudinal angle inside a medium of index `eta` for a ray at
/// longitudinal angle `theta` outside: sin θ_t = sin θ/η.
pub fn cos_refracted(eta: f64, theta: f64) -> f64 {
    let s = theta.sin() / eta;
    (1.0 - s * s).sqrt()
}

/// Dielectric reflectances (r_s, r_p) at one interface from index `n1` into index `n2` for
/// incidence cosine `cos_i`; (1, 1) under total internal reflection.
pub fn dielectric_sp(cos_i: f64, n1: f64, n2: f64) -> (f64, f64) {
    let cos_i = cos_i.clamp(0.0, 1.0);
    let sin_t = n1 / n2 * (1.0 - cos_i * cos_i).sqrt();
    if sin_t >= 1.0 {
        return (1.0, 1.0);
    }
    let cos_t = (1.0 - sin_t * sin_t).sqrt();
    let rs = (n1 * cos_i - n2 * cos_t) / (n1 * cos_i + n2 * cos_t);
    let rp = (n2 * cos_i - n1 * cos_t) / (n2 * cos_i + n1 * cos_t);
    (rs * rs, rp * rp)
}

/// Unpolarised dielectric reflectance (r_s + r_p)/2 (the medulla boundary, docs/model.md §4).
pub fn dielectric(cos_i: f64, n1: f64, n2: f64) -> f64 {
    let (rs, rp) = dielectric_sp(cos_i, n1, n2);
    0.5 * (rs + rp)
}

/// The cuticle's layered reflectance f (docs/model.md §4): per polarisation one plate reflects
/// 2r/(1 + r); R1 is their average and f = l·R1/(1 + (l − 1)·R1).
pub fn cuticle(cos_i: f64, n1: f64, n2: f64, layers: f64) -> f64 {
    let (rs, rp) = dielectric_sp(cos_i, n1, n2);
    let plate = |r: f64| 2.0 * r / (1.0 + r);
    let r1 = 0.5 * (plate(rs) + plate(rp));
    if r1 >= 1.0 {
        return 1.0;
    }
    layers * r1 / (1.0 + (layers - 1.0) * r1)
}

/// The cross-section at one view angle.
#[derive(Clone, Copy, Debug)]
pub struct CrossSection {
    /// η'_c, Bravais index of the cortex.
    pub eta_c: f64,
    /// η'_m, Bravais index of the medulla.
    pub eta_m: f64,
    /// κ, medulla radius (outer radius 1).
    pub kappa: f64,
    /// l, cuticle layers.
    pub layers: f64,
}

impl CrossSection {
    /// The cross-section seen by a view ray at longitudinal angle `theta_r` (radians) for
    /// real indices `eta_c`, `eta_m`.
    pub fn at_view(eta_c: f64, eta_m: f64, kappa: f64, layers: f64, theta_r: f64) -> Self {
        CrossSection {
            eta_c: bravais(eta_c, theta_r),
            eta_m: bravais(eta_m, theta_r),
            kappa,
            layers,
        }
    }
}

/// What a traced path did.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Traced {
    /// Exit azimuth Φ = −atan2(d_y, d_x) ∈ (−π, π].
    pub exit_azimuth: f64,
    /// 2D length travelled in the cortex.
    pub cortex_length: f64,
    /// 2D length travelled in the medulla.
    pub medulla_length: f64,
    /// Product of the Fresnel factors of all events (f or 1 − f at the cuticle, f_m or
    /// 1 − f_m at the medulla), each at the actual incidence cosine.
    pub fresnel: f64,
}

impl Traced {
    /// Attenuation A = fresnel · exp(−σ_ca·L_c/cos θ_tc) · exp(−σ_med·L_m/cos θ_tm), with the
    /// coefficients already divided by the refracted longitudinal cosines.
    pub fn attenuation(&self, cortex_per_2d: f64, medulla_per_2d: f64) -> f64 {
        self.fresnel
            * (-cortex_per_2d * self.cortex_length).exp()
            * (-medulla_per_2d * self.medulla_length).exp()
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Region {
    Outside,
    Cortex,
    Medulla,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Surface {
    Outer,
    Medulla,
}

type V2 = [f64; 2];

fn dot(a: V2, b: V2) -> f64 {
    a[0] * b[0] + a[1] * b[1]
}

/// Nearest positive parameter t at which p + t·d (|d| = 1) crosses the circle of radius r
/// about the origin, from outside (`from_inside = false`, entering) or inside (leaving).
fn hit_circle(p: V2, d: V2, r: f64, from_inside: bool) -> Option<f64> {
    let b = dot(p, d);
    let c = dot(p, p) - r * r;
    let disc = b * b - c;
    if disc <= 0.0 {
        return None;
    }
    let s = disc.sqrt();
    let t = if from_inside { -b + s } else { -b - s };
    (t > 1e-12).then_some(t)
}

/// Traces the view ray entering at offset `h` through `events` (e.g. `"TttRttT"`).
///
/// Returns `None` when the path does not exist: the ray misses the surface the next event
/// needs (an uppercase event while the next surface is the medulla, a lowercase event while
/// it is the outer circle), a required transmission is totally reflected, or the ray does not
/// end outside the fiber.
pub fn trace(xs: &CrossSection, h: f64, events: &str) -> Option<Traced> {
    if h.is_nan() || h.abs() >= 1.0 {
        return None;
    }
    let mut p: V2 = [2.0, h];
    let mut d: V2 = [-1.0, 0.0];
    let mut region = Region::Outside;
    let mut out = Traced {
        exit_azimuth: 0.0,
        cortex_length: 0.0,
        medulla_length: 0.0,
        fresnel: 1.0,
    };
    let index = |r: Region| match r {
        Region::Outside => 1.0,
        Region::Cortex => xs.eta_c,
        Region::Medulla => xs.eta_m,
    };
    for e in events.chars() {
        // The next surface along the ray.
        let (t, surface) = match region {
            Region::Outside => (hit_circle(p, d, 1.0, false)?, Surface::Outer),
            Region::Cortex => {
                let med = if xs.kappa > 0.0 {
                    hit_circle(p, d, xs.kappa, false)
                } else {
                    None
                };
                match med {
                    Some(t) => (t, Surface::Medulla),
                    None => (hit_circle(p, d, 1.0, true)?, Surface::Outer),
                }
            }
            Region::Medulla => (hit_circle(p, d, xs.kappa, true)?, Surface::Medulla),
        };
        let wanted = if e.is_ascii_uppercase() {
            Surface::Outer
        } else {
            Surface::Medulla
        };
        if surface != wanted {
            return None;
        }
        match region {
            Region::Cortex => out.cortex_length += t,
            Region::Medulla => out.medulla_length += t,
            Region::Outside => {}
        }
        p = [p[0] + t * d[0], p[1] + t * d[1]];
        // Unit normal facing the incoming ray.
        let len = dot(p, p).sqrt();
        let mut n = [p[0] / len, p[1] / len];
        if dot(n, d) > 0.0 {
            n = [-n[0], -n[1]];
        }
        let other = match (surface, region) {
            (Surface::Outer, Region::Outside) => Region::Cortex,
            (Surface::Outer, _) => Region::Outside,
            (Surface::Medulla, Region::Cortex) => Region::Medulla,
            (Surface::Medulla, _) => Region::Cortex,
        };
        let (n1, n2) = (index(region), index(other));
        let cos_i = -dot(n, d);
        let refl = match surface {
            Surface::Outer => cuticle(cos_i, n1, n2, xs.layers),
            Surface::Medulla => dielectric(cos_i, n1, n2),
        };
        match e {
            'R' | 'r' => {
                d = [d[0] + 2.0 * cos_i * n[0], d[1] + 2.0 * cos_i * n[1]];
                out.fresnel *= refl;
            }
            'T' | 't' => {
                let eta = n1 / n2;
                let sin2_t = eta * eta * (1.0 - cos_i * cos_i);
                if sin2_t >= 1.0 {
                    return None;
                }
                let cos_t = (1.0 - sin2_t).sqrt();
                let k = eta * cos_i - cos_t;
                d = [eta * d[0] + k * n[0], eta * d[1] + k * n[1]];
                let dl = dot(d, d).sqrt();
                d = [d[0] / dl, d[1] / dl];
                out.fresnel *= 1.0 - refl;
                region = other;
            }
            _ => panic!("unknown event {e:?} in {events:?}"),
        }
    }
    if region != Region::Outside {
        return None;
    }
    out.exit_azimuth = -d[1].atan2(d[0]);
    Some(out)
}

/// Wraps an angle to (−π, π].
pub fn wrap(x: f64) -> f64 {
    use std::f64::consts::{PI, TAU};
    let mut y = x - TAU * ((x + PI) / TAU).floor();
    if y <= -PI {
        y += TAU;
    }
    if y > PI {
        y -= TAU;
    }
    y
}

/// SplitMix64: a tiny seeded generator so that the randomised tests are reproducible without
/// a dependency.
#[derive(Clone, Debug)]
pub struct SplitMix64(pub u64);

impl SplitMix64 {
    /// Next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1).
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Uniform in [lo, hi), rounded to f32 (the core's precision), returned as f32.
    pub fn range_f32(&mut self, lo: f64, hi: f64) -> f32 {
        (lo + (hi - lo) * self.unit()) as f32
    }
}
