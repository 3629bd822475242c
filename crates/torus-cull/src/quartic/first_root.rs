//! The renderer's query by a **bracketed walk** (issue 61): the first real root of
//! `f(u) = u⁴ + p u² + q u + r` in `[lo, hi]`, found without the resolvent and without the
//! roots past it. Measured slower than the closed form ([`super::nearest_root_depressed`])
//! on uniform lines and about even on tangent ones (docs/math.md, "The bracketed
//! first-root walk"), so [`crate::intersect()`] keeps the closed form; this is the
//! library's second answer to the same question, held to the same tests.
//!
//! **Pieces.** `f″ = 12u² + 2p` vanishes only at `±w`, `w = √(−p/6)` (for `p < 0`), so
//! those two points split any interval into at most three pieces on each of which `f` is
//! convex or concave: `f′` is monotone there, so a piece holds at most one extremum and
//! at most two roots. No cubic is solved to find the pieces (the derivative's root is
//! only sought on a piece whose ends have the same sign and whose slope changes sign).
//! This is C. Yuksel's "High-Performance Polynomial Root Finding for Graphics" (HPG 2022)
//! cut down to a quartic without a cubic term: the split one degree further down, where
//! it is a square root.
//!
//! **The walk**, near to far, stops at the first piece that holds a root. With `g = ±f`
//! convex on a piece `[x₀, x₁]`:
//! - `g(x₀) < 0`: a root iff `g(x₁) ≥ 0`, one crossing, approached from `x₁`;
//! - `g(x₀) > 0`, `g′(x₀) ≥ 0`: none (`g` only grows); `g(x₁) < 0`: one crossing,
//!   approached from `x₀`; `g′(x₁) ≤ 0`: none (`g ≥ g(x₁) > 0`);
//! - otherwise Newton's steps on `g′` seek the minimum `m` from the secant's root, and
//!   stop at the first point where `g < −`[`SIGN_SURE`]`·ε·Σ|cᵢ||u|ⁱ` (two roots: the
//!   first is refined left of it, from the parabola there), or where the two outermost
//!   tangents, which lie below the convex `g`, prove it above [`TOUCH`]`·ε·Σ` on the whole
//!   piece (none). At `m` itself `g(m)` decides exactly as the closed form's near-double
//!   pairs are decided ([`super::factor`]): above `TOUCH·ε·Σ` none; from
//!   `−SIGN_SURE·ε·Σ` to that, a double root at `m`, a tangent that is never lost; below,
//!   two roots, the first refined on `[x₀, m]`.
//!
//! A piece end at `±w` where `|f|` is within `TOUCH·ε·Σ` is a root too: an extremum that
//! rounding put on the wrong side of the inflection point is not lost there.
//!
//! **Steps.** Each refinement keeps a bracket with a sign change and takes Halley's step
//! `f f′/(f′² − f f″/2)` where it stays inside and is at most ¾ of the last, bisecting
//! (in magnitude across binades) otherwise. It stops when the step's predicted successor,
//! `K·δ³` with `K = (f″/2f′)² + |f‴/6f′|`, is below `2ε·|u|` for a step under 2⁻¹⁶`|u|`
//! (the last step is taken), when `|f|` is within Horner's rounding `8ε·Σ|cᵢ||u|ⁱ` (then
//! the point is a root of a quartic within rounding of the given one: the error is
//! `8κε|u|`, κ the root's condition number), or when the bracket is down to adjacent
//! floats.
//!
//! **Range.** The walk covers `[max(lo, −h), min(hi, h)]` for a bound `h` on every root:
//! the smaller of `max(1, √S)`, `S = max(0, −p) + |q| + max(0, −r)` (for `|u| ≥ 1`,
//! `f(u) ≥ u⁴ − S u² > 0` beyond it), and Fujiwara's bound rounded up to a power of two.
//!
//! An even quartic (`q = 0`) and the discriminant's early exit are shared with
//! [`super::nearest_root_depressed`], so every tangent those decide by an exact sign is
//! decided the same way here.

use super::discriminant::surely_no_real_root;
use super::factor::{SIGN_SURE, TOUCH};
use super::pieces::split;
use super::{EPS, even};

/// `f(u)` and `f′(u)` of `u⁴ + p u² + q u + r`, Horner (`f` as on `[1, 0, p, q, r]`).
#[inline(always)]
fn value(p: f64, q: f64, r: f64, u: f64) -> (f64, f64) {
    let u2 = u * u;
    let f = ((u2 + p) * u + q) * u + r;
    let df = (4.0 * u2 + 2.0 * p) * u + q;
    (f, df)
}

/// `Σ|cᵢ||u|ⁱ`: what the rounding of Horner's `f(u)` is measured by.
#[inline(always)]
fn magnitude(p: f64, q: f64, r: f64, u: f64) -> f64 {
    let a = u.abs();
    ((a * a + p.abs()) * a + q.abs()) * a + r.abs()
}

/// At most this many steps in one refinement: a bisection in magnitude ([`split`]) takes a
/// bracket spanning f64's range to adjacent floats in about 75; Newton's steps converge
/// far sooner.
const MAX_STEPS: usize = 200;

/// The first real root of `u⁴ + p u² + q u + r` in `[lo, hi]` (either end may be
/// infinite), or `None`: the same question as [`super::nearest_root_depressed`], answered
/// by the bracketed walk of this module.
///
/// ```
/// use torus_cull::quartic::first_root_depressed;
/// // (x² − 1)(x² − 4) = x⁴ − 5x² + 4: roots ±1, ±2.
/// assert_eq!(first_root_depressed(-5.0, 0.0, 4.0, -1.5, 10.0), Some(-1.0));
/// // (x − 1)(x − 2)(x² + 3x + 3.25) = x⁴ − 3.75x² − 3.75x + 6.5: the walk.
/// let first = first_root_depressed(-3.75, -3.75, 6.5, 0.0, 10.0).unwrap();
/// assert!((first - 1.0).abs() < 1e-15);
/// let second = first_root_depressed(-3.75, -3.75, 6.5, 1.5, 10.0).unwrap();
/// assert!((second - 2.0).abs() < 1e-15);
/// // (x − 1)²(x² + 2x + 3) = x⁴ + 0x³ + 0x² − 4x + 3: a tangent at 1.
/// let t = first_root_depressed(0.0, -4.0, 3.0, 0.0, 10.0).unwrap();
/// assert!((t - 1.0).abs() < 1e-7);
/// assert_eq!(first_root_depressed(0.0, -4.0, 3.0, 1.5, 10.0), None);
/// ```
///
/// Coefficients beyond 2^±100 (see `out_of_range`) are passed to
/// [`super::nearest_root_depressed`], which solves them at their own scales.
#[inline]
#[must_use]
pub fn first_root_depressed(p: f64, q: f64, r: f64, lo: f64, hi: f64) -> Option<f64> {
    if super::out_of_range(p, q, r) {
        return super::nearest_root_depressed(p, q, r, lo, hi);
    }
    // The bound is computed only for a quartic past the discriminant's early exit.
    first_root_in_range(p, q, r, lo, hi, || coefficient_bound(p, q, r))
}

/// A bound `h` with every real root of `u⁴ + p u² + q u + r` in `(−h, h)`, the smaller
/// of two (module docs): `max(1, √S)` widened by [`WIDEN`] for the rounding of `S` and its
/// square root, and Fujiwara's `2·max(|p|^½, |q|^⅓, |r|^¼)` with each power rounded up to
/// a power of two from the exponents alone (tight within 4× at any scale, where `√S` is
/// the scale squared for roots far from 1).
#[inline(always)]
fn coefficient_bound(p: f64, q: f64, r: f64) -> f64 {
    let s = (-p).max(0.0) + q.abs() + (-r).max(0.0);
    let near_one = s.max(1.0).sqrt() * (1.0 + WIDEN);
    // 2^e > |x| for e = the biased exponent − 1022 (≥ −1022); ⌈e/k⌉ by an integer
    // division of a positive number.
    let ceil_root_exp = |x: f64, k: i32| {
        let e = ((x.to_bits() >> 52) & 0x7ff) as i32 - 1022;
        (e + 1200 * k + k - 1) / k - 1200
    };
    let e = ceil_root_exp(p, 2)
        .max(ceil_root_exp(q, 3))
        .max(ceil_root_exp(r, 4));
    let fujiwara = f64::from_bits(((e + 1 + 1023) as u64) << 52);
    near_one.min(fujiwara)
}

/// A step below this fraction of `|u|` is short enough for the derivatives at its start
/// to predict the next one.
const SHORT: f64 = 1.52587890625e-5; // 2⁻¹⁶

/// The relative widening of a bound on the roots, for the rounding of its computation.
const WIDEN: f64 = 9.5367431640625e-7; // 2⁻²⁰

/// [`first_root_depressed`] for coefficients within 2^±100, with a bound `h()` that every
/// root in `[lo, hi]` is known to lie within (`|u| ≤ h`): the walk covers
/// `[max(lo, −h), min(hi, h)]`. A caller that knows a tighter interval (the bounding
/// sphere's chord) can pass it here.
#[inline(always)]
fn first_root_in_range(
    p: f64,
    q: f64,
    r: f64,
    lo: f64,
    hi: f64,
    h: impl FnOnce() -> f64,
) -> Option<f64> {
    if surely_no_real_root(p, q, r) {
        return None;
    }
    // Written so that NaN (a coefficient, an end) also returns.
    if !(lo <= hi && p.is_finite() && q.is_finite() && r.is_finite()) {
        return None;
    }
    if q == 0.0 {
        // An even quartic: a quadratic in u², with its tangents decided by exact signs.
        let best = even::nearest_root(p, r, lo, hi)?;
        return (best != f64::INFINITY).then_some(best);
    }
    // Both finite and not NaN from here on (lo, hi and h are).
    let h = h();
    let (a, b) = (lo.max(-h), hi.min(h));
    if a > b {
        return None;
    }
    walk(p, q, r, a, b)
}

/// The first root in `[a, b]` (both finite), piece by piece (module docs).
#[inline(always)]
fn walk(p: f64, q: f64, r: f64, a: f64, b: f64) -> Option<f64> {
    // f″ < 0 on (−w, w) only; for p ≥ 0 f is convex everywhere, and the splits lie at
    // ±∞, outside every interval.
    let w = if p < 0.0 {
        (-p * (1.0 / 6.0)).sqrt()
    } else {
        f64::INFINITY
    };
    let (mut x0, (mut f0, mut d0)) = (a, value(p, q, r, a));
    if f0 == 0.0 {
        return Some(a);
    }
    for end in [-w, w, b] {
        let interior = end != b;
        if interior && !(end > x0 && end < b) {
            continue;
        }
        let x1 = end;
        let (f1, d1) = value(p, q, r, x1);
        let mid = 0.5 * (x0 + x1);
        let s = if p < 0.0 && mid.abs() < w { -1.0 } else { 1.0 };
        let g = Piece {
            x0,
            x1,
            g0: s * f0,
            e0: s * d0,
            g1: s * f1,
            e1: s * d1,
            s,
        };
        if let Some(u) = g.first_root(p, q, r) {
            return Some(u);
        }
        if interior && f1.abs() <= TOUCH * EPS * magnitude(p, q, r, x1) {
            // f within rounding of 0 at an inflection point: an extremum within rounding
            // of it, on either side; a touch, as at an extremum.
            return Some(x1);
        }
        (x0, f0, d0) = (x1, f1, d1);
    }
    None
}

/// One piece `[x0, x1]` on which `g = s·f` is convex, with `g` and `g′` at its ends.
struct Piece {
    x0: f64,
    x1: f64,
    g0: f64,
    e0: f64,
    g1: f64,
    e1: f64,
    /// `+1` where `f` is convex, `−1` where it is concave.
    s: f64,
}

impl Piece {
    /// The first root of `f` in `(x0, x1]` (`g0 ≠ 0`), or `None` (module docs).
    #[inline(always)]
    fn first_root(&self, p: f64, q: f64, r: f64) -> Option<f64> {
        let Piece {
            x0,
            x1,
            g0,
            e0,
            g1,
            e1,
            s,
        } = *self;
        // f < 0 at x0 iff g < 0 there and s = 1, or g > 0 and s = −1.
        if g0 < 0.0 {
            // Convex from below: one crossing up, or none.
            if g1 < 0.0 {
                return None;
            }
            if g1 == 0.0 {
                return Some(x1);
            }
            return Some(refine(p, q, r, x0, x1, (g0 < 0.0) == (s > 0.0), x1));
        }
        // g0 > 0 (g0 = 0 was returned by the caller; every value here is finite: the
        // coefficients are within 2^±100 and |u| within their root bound).
        if e0 >= 0.0 {
            return None;
        }
        if g1 < 0.0 || (g1 == 0.0 && e1 <= 0.0) {
            if g1 == 0.0 {
                return Some(x1);
            }
            return Some(refine(p, q, r, x0, x1, (g0 < 0.0) == (s > 0.0), x0));
        }
        if e1 <= 0.0 {
            return None;
        }
        self.at_extremum(p, q, r)
    }

    /// `g0, g1 > 0` with the slope from `< 0` to `> 0`: Newton's steps on `g′` toward the
    /// minimum `m`, from the secant's root, stopping as soon as a point with `g < 0` shows
    /// two roots (the first then lies left of it), the two end tangents prove `g` above
    /// [`TOUCH`]'s bound on the whole piece, or `m` is found and `g(m)` decides (module
    /// docs).
    fn at_extremum(&self, p: f64, q: f64, r: f64) -> Option<f64> {
        let s = self.s;
        // Left of m (g′ < 0) and right of it (g′ > 0), each with g > 0, g′ there: the
        // piece's ends, narrowed as the steps go.
        let (mut xa, mut ga, mut ea) = (self.x0, self.g0, self.e0);
        let (mut xb, mut gb, mut eb) = (self.x1, self.g1, self.e1);
        let mut x = xa - ea * ((xb - xa) / (eb - ea));
        if !(x > xa && x < xb) {
            x = 0.5 * (xa + xb);
        }
        let mut last = xb - xa;
        for _ in 0..MAX_STEPS {
            let u2 = x * x;
            let (f, df) = value(p, q, r, x);
            let (g, e) = (s * f, s * df);
            let d2 = s * (12.0 * u2 + 2.0 * p);
            let bound = EPS * magnitude(p, q, r, x);
            if g < -SIGN_SURE * bound {
                // Two roots, the first in (xa, x).
                return Some(first_of_pair(p, q, r, s, (xa, ga, ea), (x, g, e, d2)));
            }
            if e < 0.0 {
                (xa, ga, ea) = (x, g, e);
            } else if e > 0.0 {
                (xb, gb, eb) = (x, g, e);
            } else {
                return None;
            }
            // The tangents at xa and xb lie below the convex g: their crossing bounds its
            // minimum from below.
            let cross = (gb - ga + ea * xa - eb * xb) / (ea - eb);
            let floor = ga + ea * (cross - xa);
            if floor > TOUCH * bound {
                return None;
            }
            let step = e / d2;
            let next = x - step;
            let newton = next > xa && next < xb && step.abs() <= 0.75 * last;
            let next = if newton { next } else { split(xa, xb) };
            // m to the last bits (|f‴/(2f″)|·δ² below 2ε|u| for a short step, or f′
            // within its rounding): g(m) within TOUCH's bound above 0 is a double root.
            let slope_noise = SIGN_SURE * EPS * ((4.0 * u2 + 2.0 * p.abs()) * x.abs() + q.abs());
            let converged = newton
                && (e.abs() <= slope_noise
                    || step.abs() <= SHORT * x.abs()
                        && step * step * (24.0 * x).abs() <= 4.0 * EPS * x.abs() * d2.abs());
            if converged || !(next > xa && next < xb) {
                let m = if next > xa && next < xb { next } else { x };
                let (f, df) = value(p, q, r, m);
                let (g, bound) = (s * f, EPS * magnitude(p, q, r, m));
                if g > TOUCH * bound {
                    return None;
                }
                if g >= -SIGN_SURE * bound {
                    // A double root (module docs), or a pair within rounding of one.
                    return Some(m);
                }
                let d2 = s * (12.0 * m * m + 2.0 * p);
                return Some(first_of_pair(p, q, r, s, (xa, ga, ea), (m, g, s * df, d2)));
            }
            last = (next - x).abs();
            x = next;
        }
        None
    }
}

/// The first of two roots on a piece where `g = s·f` is convex: `g > 0` with `g′ < 0` at
/// `xa`, `g < 0` at `x` (with `g′`, `g″` there). Refined on `(xa, x)` from the left root
/// of the parabola at `x`, or from Newton's point from `xa`, which lies left of the root
/// (`g` is convex and `g(xa) > 0`).
fn first_of_pair(
    p: f64,
    q: f64,
    r: f64,
    s: f64,
    (xa, ga, ea): (f64, f64, f64),
    (x, g, e, d2): (f64, f64, f64, f64),
) -> f64 {
    let left = xa - ga / ea;
    let vertex = x - e / d2;
    let depth = g - 0.5 * e * (e / d2);
    let start = vertex - (-2.0 * depth / d2).sqrt();
    let start = if start > left && start < x {
        start
    } else if left > xa && left < x {
        left
    } else {
        0.5 * (xa + x)
    };
    // f at xa has the sign of g > 0 times s.
    refine(p, q, r, xa, x, s < 0.0, start)
}

/// The root of `f` in `[a, b]`, where `f` is monotone with `f(a) < 0` iff `neg_at_a`,
/// from `x` (module docs: the steps and when they stop).
fn refine(p: f64, q: f64, r: f64, mut a: f64, mut b: f64, neg_at_a: bool, mut x: f64) -> f64 {
    let mut last = f64::INFINITY;
    for _ in 0..MAX_STEPS {
        let (f, df) = value(p, q, r, x);
        if f == 0.0 {
            return x;
        }
        if (f < 0.0) == neg_at_a {
            a = x;
        } else {
            b = x;
        }
        // Halley's step (cubic convergence): δ = f f′ / (f′² − f f″/2).
        let d2 = 12.0 * x * x + 2.0 * p;
        let step = (f * df) / (df * df - 0.5 * f * d2);
        let next = x - step;
        let newton = next > a && next < b && step.abs() <= 0.75 * last;
        if newton {
            // The next error, about K·δ³ with K = (f″/2f′)² + |f‴/6f′| (f‴ = 24u), below
            // 2ε|u|, or f within rounding. K is taken at x, so the prediction holds only
            // for a step too short for it to change much.
            let k = 0.25 * (d2 / df) * (d2 / df) + (4.0 * x / df).abs();
            let tiny = step.abs() <= SHORT * next.abs()
                && step.abs() * step * step * k <= 2.0 * EPS * next.abs();
            if tiny || f.abs() <= SIGN_SURE * EPS * magnitude(p, q, r, x) {
                return next;
            }
        }
        let next = if newton { next } else { split(a, b) };
        if !(next > a && next < b) {
            // Adjacent floats: the bracket is the answer.
            return if next == a || next == b { next } else { x };
        }
        last = (next - x).abs();
        x = next;
    }
    x
}
