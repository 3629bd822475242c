//! The second, independent method for the margin: dense samples in world coordinates and
//! golden-section refinement. Slow; the tests compare the oracle against it.

use super::Query;

/// The margin by the second, independent method: dense sampling of D in world coordinates
/// over the part of the line that can hold the minimum, then golden-section refinement
/// around every discrete local minimum. Same inputs and meaning as
/// [`Query::classify`]; slow, for tests only.
///
/// The window: let x_n be the point of the range closest to the centre. D(x_n) ≤ |x_n| + R
/// and D(x) ≥ |x| − R everywhere, so every minimizer has |x| ≤ |x_n| + 2R: sampling the
/// chord of that sphere (clipped to the range) is enough, also for lines that miss the torus.
pub fn margin_by_sampling(query: &Query) -> f64 {
    query.check();
    let Query {
        center,
        axis,
        major,
        minor,
        o,
        d,
        t_min,
        t_max,
    } = *query;
    let a = axis.normalize();
    let dist = |t: f64| {
        let x = (o + t * d) - center;
        let y = x.dot(a);
        let rho = (x - y * a).length();
        (rho - major).hypot(y)
    };
    let dd = d.length_squared();
    let t_c = -(o - center).dot(d) / dd;
    let t_n = t_c.clamp(t_min, t_max);
    let d_c = (o + t_c * d - center).length();
    let d_n = (o + t_n * d - center).length();
    let big = d_n + 2.0 * major + minor;
    let half = ((big * big - d_c * d_c).max(0.0)).sqrt() / dd.sqrt();
    let lo = (t_c - half).max(t_min);
    let hi = (t_c + half).min(t_max);
    // Local minima of D along a line are about r apart at least; r/32 resolves them.
    let chord = (hi - lo) * dd.sqrt();
    let n = ((chord / (minor / 32.0)).ceil() as usize).clamp(2000, 400_000);
    // 0.618^120 ≈ 1e-25: golden-section steps far past f64 resolution of any bracket.
    min_by_samples(&dist, lo, hi, n, 120) - minor
}

/// The least value of `f` over `[lo, hi]` from `n + 1` evenly spaced samples, refined by
/// [`golden_min`] (`iterations` at most) between the neighbours of every discrete local
/// minimum: both oracles' second method (the ring's D, the family's E).
pub(super) fn min_by_samples(
    f: &dyn Fn(f64) -> f64,
    lo: f64,
    hi: f64,
    n: usize,
    iterations: usize,
) -> f64 {
    let ts: Vec<f64> = (0..=n)
        .map(|i| lo + (hi - lo) * (i as f64 / n as f64))
        .collect();
    let fs: Vec<f64> = ts.iter().map(|&t| f(t)).collect();
    let mut best = fs.iter().copied().fold(f64::INFINITY, f64::min);
    for i in 0..=n {
        let left = if i > 0 { fs[i - 1] } else { f64::INFINITY };
        let right = if i < n { fs[i + 1] } else { f64::INFINITY };
        if fs[i] <= left && fs[i] <= right {
            let a = ts[i.saturating_sub(1)];
            let b = ts[(i + 1).min(n)];
            best = best.min(golden_min(f, a, b, iterations));
        }
    }
    best
}

/// The least value of `f` found by golden-section search on [a, b], `iterations` steps at
/// most (unimodal assumed; otherwise still an upper bound on the minimum, since every value
/// is a real sample).
fn golden_min(f: &dyn Fn(f64) -> f64, mut a: f64, mut b: f64, iterations: usize) -> f64 {
    let g = 0.5 * (5f64.sqrt() - 1.0);
    let mut best = f(a).min(f(b));
    let mut x1 = b - g * (b - a);
    let mut x2 = a + g * (b - a);
    let (mut f1, mut f2) = (f(x1), f(x2));
    for _ in 0..iterations {
        best = best.min(f1).min(f2);
        if f1 <= f2 {
            b = x2;
            x2 = x1;
            f2 = f1;
            x1 = b - g * (b - a);
            f1 = f(x1);
        } else {
            a = x1;
            x1 = x2;
            f1 = f2;
            x2 = a + g * (b - a);
            f2 = f(x2);
        }
        if !(a < x1 && x1 <= x2 && x2 < b) {
            break;
        }
    }
    best.min(f1).min(f2)
}
