//! Flatland geometry of the fiber's cross-section (docs/model.md §3): rays against the
//! cuticle and medulla circles about the origin, reflection and refraction at them, for the
//! photon walks of [`super::sim`].

/// A 2D vector.
pub(crate) type V2 = [f32; 2];

/// The dot product.
#[inline]
pub(crate) fn dot(p: V2, q: V2) -> f32 {
    p[0] * q[0] + p[1] * q[1]
}

/// Distance along unit `d` from `p` to the circle of radius `r`, leaving it from inside
/// (the far intersection).
#[inline]
pub(crate) fn exit_distance(p: V2, d: V2, r: f32) -> f32 {
    let pd = dot(p, d);
    let disc = (pd * pd + r * r - dot(p, p)).max(0.0);
    (-pd + libm::sqrtf(disc)).max(0.0)
}

/// Distance along unit `d` from `p` (outside the circle of radius `r`) to where it enters
/// the circle, if it does.
#[inline]
pub(crate) fn entry_distance(p: V2, d: V2, r: f32) -> Option<f32> {
    let pd = dot(p, d);
    if pd >= 0.0 {
        return None;
    }
    let disc = pd * pd + r * r - dot(p, p);
    if disc <= 0.0 {
        return None;
    }
    let t = -pd - libm::sqrtf(disc);
    (t >= 0.0).then_some(t)
}

/// Reflects `d` about the unit normal `n`.
#[inline]
pub(crate) fn reflect(d: V2, n: V2) -> V2 {
    let k = 2.0 * dot(d, n);
    [d[0] - k * n[0], d[1] - k * n[1]]
}

/// Refracts unit `d` through a boundary with unit normal `n` (either orientation), relative
/// index `eta` = n_from/n_to; `None` under total internal reflection.
#[inline]
pub(crate) fn refract(d: V2, n: V2, eta: f32) -> Option<V2> {
    let mut n = n;
    let mut cos_i = -dot(d, n);
    if cos_i < 0.0 {
        n = [-n[0], -n[1]];
        cos_i = -cos_i;
    }
    let sin2_t = eta * eta * (1.0 - cos_i * cos_i).max(0.0);
    if sin2_t >= 1.0 {
        return None;
    }
    let cos_t = libm::sqrtf(1.0 - sin2_t);
    let k = eta * cos_i - cos_t;
    let out = [eta * d[0] + k * n[0], eta * d[1] + k * n[1]];
    let len = libm::sqrtf(dot(out, out));
    Some([out[0] / len, out[1] / len])
}

/// The outward unit normal at `p` (on a circle about the origin).
#[inline]
pub(crate) fn normal(p: V2) -> V2 {
    let r = libm::sqrtf(dot(p, p)).max(1e-30);
    [p[0] / r, p[1] / r]
}
