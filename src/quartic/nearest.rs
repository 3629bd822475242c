//! The renderer's query: the nearest real root in an interval, with an early exit for
//! quartics that surely have no real root.

use super::{EPS, RealRoots, even, factor};

/// The nearest real root of `x⁴ + p x² + q x + r` in `[lo, hi]` (either end may be
/// infinite), or `None`: the renderer's query.
///
/// A quartic whose discriminant says, beyond rounding, that it has no real root returns at
/// once (half the lines of a uniform workload); an even one (`q = 0`) is solved as a
/// quadratic in `x²`. Otherwise finds the roots of both Ferrari
/// factors and takes the smallest one in range, without a sort and without a final Newton
/// step: the factors' roots are already accurate to a few ε·(R + r) in absolute terms (see
/// the solver bench's accuracy records), and near-double factors are refined on the
/// quartic itself on a cold path.
///
/// ```
/// use torus_cull::quartic::nearest_root_depressed;
/// // (x² − 1)(x² − 4) = x⁴ − 5x² + 4: roots ±1, ±2.
/// assert_eq!(nearest_root_depressed(-5.0, 0.0, 4.0, -1.5, 10.0), Some(-1.0));
/// assert_eq!(nearest_root_depressed(-5.0, 0.0, 4.0, 1.5, 10.0), Some(2.0));
/// assert_eq!(nearest_root_depressed(-5.0, 0.0, 4.0, 2.5, 10.0), None);
/// ```
#[inline]
pub fn nearest_root_depressed(p: f64, q: f64, r: f64, lo: f64, hi: f64) -> Option<f64> {
    if surely_no_real_root(p, q, r) {
        return None;
    }
    // An even quartic (a line perpendicular or parallel to the axis) is a quadratic in x²,
    // where a tangent at the foot point is decided by a sign, not by rounding.
    if q == 0.0 {
        if let Some(best) = even::nearest_root(p, r, lo, hi) {
            return found(best);
        }
    }
    let f = factor::split(p, q, r);
    let (disc1, disc2) = (f.z - 4.0 * f.n1, f.z - 4.0 * f.n2);
    let near = factor::NEAR_DOUBLE;
    // Written so that NaN (non-finite input) takes the cold path.
    let clear = disc1.abs() > near * (f.z + 4.0 * f.n1.abs())
        && disc2.abs() > near * (f.z + 4.0 * f.n2.abs());
    let best = if clear {
        // Both factors clearly have two real roots or none: solve them without branches
        // (which way a factor goes is a coin toss from ray to ray) and take the nearest.
        // `(−b ± √disc)/2` is accurate to ε·(|b| + √disc) in absolute terms, which is what
        // a hit point needs; the division-based stable form only buys relative accuracy
        // for roots near 0, and costs a division on the critical path.
        let pick = |x: f64, real: bool| in_range(x, real, lo, hi);
        let (s1, s2) = (disc1.max(0.0).sqrt(), disc2.max(0.0).sqrt());
        let (ok1, ok2) = (disc1 > 0.0, disc2 > 0.0);
        let half_m = 0.5 * f.m;
        let first = pick(-half_m - 0.5 * s1, ok1).min(pick(-half_m + 0.5 * s1, ok1));
        let second = pick(half_m - 0.5 * s2, ok2).min(pick(half_m + 0.5 * s2, ok2));
        first.min(second)
    } else {
        if !(p.is_finite() && q.is_finite() && r.is_finite()) {
            return None;
        }
        let c = [1.0, 0.0, p, q, r];
        nearest_of(&factor::roots_of_split(&f, &c, 0.0, near), lo, hi)
    };
    found(best)
}

/// `x` if it is a real root (`real`) in `[lo, hi]`, else ∞: a candidate for the nearest
/// root, selected rather than branched on, since which roots qualify is a coin toss from
/// ray to ray.
#[inline(always)]
pub(super) fn in_range(x: f64, real: bool, lo: f64, hi: f64) -> f64 {
    if real && x >= lo && x <= hi {
        x
    } else {
        f64::INFINITY
    }
}

/// The nearest root found (∞: none).
#[inline(always)]
fn found(best: f64) -> Option<f64> {
    (best != f64::INFINITY).then_some(best)
}

/// Whether `x⁴ + p x² + q x + r` has no real root, by signs that rounding cannot flip.
///
/// Its discriminant `Δ = 16r(p² − 4r)² − q²(4p(p² − 36r) + 27q²) > 0` means four real
/// roots or none, and `p > 0` or `4r > p²` rules out four. Each sign must exceed the
/// rounding of its evaluation (bounded by the same expression on absolute values), so a
/// near-tangent quartic, whose complex pair rounding could make real, is left to the solver.
/// Half the lines of a uniform workload miss and end here, before the resolvent.
#[inline]
fn surely_no_real_root(p: f64, q: f64, r: f64) -> bool {
    let (p2, q2, r_abs) = (p * p, q * q, r.abs());
    let e = p2 - 4.0 * r;
    let e_abs = p2 + 4.0 * r_abs;
    let g = 4.0 * p * (p2 - 36.0 * r) + 27.0 * q2;
    let g_abs = 4.0 * p.abs() * (p2 + 36.0 * r_abs) + 27.0 * q2;
    let disc = 16.0 * r * e * e - q2 * g;
    let disc_abs = 16.0 * r_abs * e_abs * e_abs + q2 * g_abs;
    // Rounding moves `disc` by under 12ε·disc_abs and `e` by under 2ε·e_abs.
    disc > 32.0 * EPS * disc_abs && (p > 0.0 || -e > 8.0 * EPS * e_abs)
}

/// The nearest root in `[lo, hi]` of a cold-path root set, or ∞.
#[cold]
fn nearest_of(roots: &RealRoots, lo: f64, hi: f64) -> f64 {
    roots
        .as_slice()
        .iter()
        .map(|&x| in_range(x, true, lo, hi))
        .fold(f64::INFINITY, f64::min)
}
