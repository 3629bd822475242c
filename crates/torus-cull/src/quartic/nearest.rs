//! The renderer's query: the nearest real root in an interval, with an early exit for
//! quartics that surely have no real root.

//!
//! The common ("clear") path after the resolvent, [`clear_factors`] and
//! [`nearest_of_clear`], is generic over [`Real`]: the lane solver runs the same two
//! steps on its registers.

use super::discriminant::surely_no_real_root;
use super::factor::{self, Split};
use super::pick::{in_range, in_range_f64};
use super::{RealRoots, even};
use crate::num::{Real, RealMask, sc};

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
/// **Near-double pairs**, at any scale: a pair is decided by `f` at the quartic's
/// extremum `t*` between its roots. Where the sign of `f(t*)` is sure (beyond Horner's
/// rounding, 8ε·Σ|cᵢ||t*|ⁱ) it is followed: a real pair is split and each root refined,
/// to within `16κε|x|` (`κ = Σ|cᵢ||x|ⁱ/(|x|·|f′(x)|)`, the root's condition number) and
/// usually far closer. Within that rounding the pair is one double root at `t*`, which
/// then lies within `16κε|x|` of both roots; and a pair on the complex side within
/// 32ε·Σ is returned as that double root too (a tangent hit). Issue 36's close pairs of
/// large roots (`quartic/close_pairs.rs`: roots `X`, `X + δ` with `δ/X` down to 10⁻⁷ and
/// `|p|` up to 10¹⁴) are held to this.
///
/// ```
/// use torus_cull::quartic::nearest_root_depressed;
/// // (x² − 1)(x² − 4) = x⁴ − 5x² + 4: roots ±1, ±2.
/// assert_eq!(nearest_root_depressed(-5.0, 0.0, 4.0, -1.5, 10.0), Some(-1.0));
/// assert_eq!(nearest_root_depressed(-5.0, 0.0, 4.0, 1.5, 10.0), Some(2.0));
/// assert_eq!(nearest_root_depressed(-5.0, 0.0, 4.0, 2.5, 10.0), None);
/// ```
///
/// Coefficients of any size are taken: beyond 2^±100, or a nonzero one below 2⁻³⁰⁰ (see
/// `out_of_range`), the quartic is solved by [`super::solve_depressed_monic`], which keeps
/// a small root beside a huge one to its own relative accuracy. That range check (a few
/// absolute values and compares in front of every solve) is skipped by
/// [`crate::intersect()`], whose coefficients are O(1).
#[inline]
#[must_use]
pub fn nearest_root_depressed(p: f64, q: f64, r: f64, lo: f64, hi: f64) -> Option<f64> {
    if super::out_of_range(p, q, r) {
        // Coefficients this far apart put roots of very different sizes side by side
        // (±10³⁰ next to 0.25 in the corpus, `corpus/`): the nearest-root path's roots are
        // accurate to ε of the largest in absolute terms, which left the small ones at 0.
        // The all-roots solve (each group of root sizes at its own power-of-two scale, by
        // monotone pieces) keeps every root to its own relative accuracy; this path is
        // rare and was already the slow one. The range is checked on the roots
        // themselves, so no rounding of lo or hi can move a root in or out.
        return found(nearest_of(&super::solve_depressed_monic(p, q, r), lo, hi));
    }
    nearest_root_in_range(p, q, r, lo, hi)
}

/// [`nearest_root_depressed`] for coefficients within 2^±100 (the exact intersection's,
/// and the lane solver's fallbacks), without the range check.
#[inline(always)]
pub(crate) fn nearest_root_in_range(p: f64, q: f64, r: f64, lo: f64, hi: f64) -> Option<f64> {
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
    let fs = Split {
        z: sc(f.z),
        m: sc(f.m),
        n1: sc(f.n1),
        n2: sc(f.n2),
    };
    let (disc1, disc2, clear) = clear_factors(&fs);
    let best = if clear.any() {
        nearest_of_clear(&fs, disc1, disc2, sc(lo), sc(hi)).v
    } else {
        if !(p.is_finite() && q.is_finite() && r.is_finite()) {
            return None;
        }
        let c = [1.0, 0.0, p, q, r];
        nearest_of(
            &factor::roots_of_split(&f, &c, 0.0, factor::NEAR_DOUBLE),
            lo,
            hi,
        )
    };
    found(best)
}

/// The discriminants of both factors of a split, and where both are clearly positive or
/// clearly negative ([`factor::NEAR_DOUBLE`]); elsewhere the roots are decided on the
/// quartic, on the cold path. NaN (non-finite input) is not clear.
#[inline(always)]
pub(crate) fn clear_factors<R: Real>(f: &Split<R>) -> (R, R, R::Mask) {
    let (four, near) = (f.z.k(4.0), f.z.k(factor::NEAR_DOUBLE));
    let (disc1, disc2) = (f.z - four * f.n1, f.z - four * f.n2);
    let clear = disc1.abs().gt(near * (f.z + four * f.n1.abs()))
        & disc2.abs().gt(near * (f.z + four * f.n2.abs()));
    (disc1, disc2, clear)
}

/// The nearest root in `[lo, hi]` of a split whose factors are both clear (two real
/// roots or none each), or ∞.
///
/// Both factors are solved without branches (which way a factor goes is a coin toss from
/// ray to ray) and the nearest is taken. `(−b ± √disc)/2` is accurate to
/// ε·(|b| + √disc) in absolute terms, which is what a hit point needs; the division-based
/// stable form only buys relative accuracy for roots near 0, and costs a division on the
/// critical path.
#[inline(always)]
pub(crate) fn nearest_of_clear<R: Real>(f: &Split<R>, disc1: R, disc2: R, lo: R, hi: R) -> R {
    let (zero, half) = (lo.k(0.0), lo.k(0.5));
    let (s1, s2) = (disc1.max(zero).sqrt(), disc2.max(zero).sqrt());
    let (ok1, ok2) = (disc1.gt(zero), disc2.gt(zero));
    let half_m = half * f.m;
    let first = in_range(half_m.negate() - half * s1, ok1, lo, hi).min(in_range(
        half_m.negate() + half * s1,
        ok1,
        lo,
        hi,
    ));
    let second =
        in_range(half_m - half * s2, ok2, lo, hi).min(in_range(half_m + half * s2, ok2, lo, hi));
    first.min(second)
}

/// The nearest root found (∞: none).
#[inline(always)]
fn found(best: f64) -> Option<f64> {
    (best != f64::INFINITY).then_some(best)
}

/// The nearest root in `[lo, hi]` of a cold-path root set, or ∞.
#[cold]
fn nearest_of(roots: &RealRoots, lo: f64, hi: f64) -> f64 {
    roots
        .as_slice()
        .iter()
        .map(|&x| in_range_f64(x, true, lo, hi))
        .fold(f64::INFINITY, f64::min)
}
