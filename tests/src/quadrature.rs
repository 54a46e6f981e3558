//! Brute-force reference integrals, in f64, independent of the core's far-field quadrature.

/// Gauss–Legendre nodes and weights on [−1, 1] by Newton iteration on P_n (f64).
pub fn gauss_legendre(n: usize) -> Vec<(f64, f64)> {
    let mut out = Vec::with_capacity(n);
    for i in 0..n {
        let mut x = (std::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
        let mut dp = 0.0;
        for _ in 0..100 {
            let (mut p0, mut p1) = (1.0, x);
            for k in 2..=n {
                let k = k as f64;
                let p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            dp = n as f64 * (x * p1 - p0) / (x * x - 1.0);
            let dx = p1 / dp;
            x -= dx;
            if dx.abs() < 1e-15 {
                break;
            }
        }
        out.push((x, 2.0 / ((1.0 - x * x) * dp * dp)));
    }
    out
}

/// ∫ f over [a, b], split into `panels` panels of `order`-point Gauss–Legendre, after the
/// smoothstep substitution x = a + (b − a)(3s² − 2s³), which turns square-root behaviour at
/// either end into smooth behaviour.
pub fn integrate_smoothstep(
    a: f64,
    b: f64,
    panels: usize,
    order: usize,
    mut f: impl FnMut(f64) -> f64,
) -> f64 {
    let mut acc = [0.0];
    integrate_smoothstep_into(a, b, panels, order, &mut acc, |x, out| out[0] = f(x));
    acc[0]
}

/// Nodes and weights of composite 4-point Gauss–Legendre over the sorted, deduplicated
/// `breaks` (at least two), each interval split into panels at most `max_width` wide.
pub fn composite_gl_nodes(breaks: &[f64], max_width: f64) -> Vec<(f64, f64)> {
    let gl = gauss_legendre(4);
    let mut nodes = Vec::new();
    for w in breaks.windows(2) {
        let n = ((w[1] - w[0]) / max_width).ceil().max(1.0) as usize;
        let step = (w[1] - w[0]) / n as f64;
        for j in 0..n {
            let a = w[0] + step * j as f64;
            for &(u, wt) in &gl {
                nodes.push((a + 0.5 * step * (1.0 + u), 0.5 * step * wt));
            }
        }
    }
    nodes
}

/// Nodes and weights of ∫ over [a, b] with `panels` panels of `order`-point Gauss–Legendre
/// after the smoothstep substitution x = a + (b − a)(3s² − 2s³).
pub fn smoothstep_nodes(a: f64, b: f64, panels: usize, order: usize) -> Vec<(f64, f64)> {
    let gl = gauss_legendre(order);
    let mut nodes = Vec::with_capacity(panels * order);
    for j in 0..panels {
        let (s0, s1) = (j as f64 / panels as f64, (j + 1) as f64 / panels as f64);
        for &(x, w) in &gl {
            let s = 0.5 * (s0 + s1) + 0.5 * (s1 - s0) * x;
            let h = a + (b - a) * (3.0 * s * s - 2.0 * s * s * s);
            let jac = (b - a) * (6.0 * s - 6.0 * s * s);
            nodes.push((h, 0.5 * (s1 - s0) * w * jac));
        }
    }
    nodes
}

/// Like [`integrate_smoothstep`] for a vector-valued integrand: adds ∫ f into `acc`, where
/// `f(x, out)` writes its values into `out` (same length as `acc`).
pub fn integrate_smoothstep_into(
    a: f64,
    b: f64,
    panels: usize,
    order: usize,
    acc: &mut [f64],
    mut f: impl FnMut(f64, &mut [f64]),
) {
    let mut tmp = vec![0.0; acc.len()];
    for (h, wt) in smoothstep_nodes(a, b, panels, order) {
        f(h, &mut tmp);
        for (a, t) in acc.iter_mut().zip(&tmp) {
            *a += wt * t;
        }
    }
}
