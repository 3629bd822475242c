//! Every real root of a polynomial of degree ≤ 4 by **monotone pieces**: the slow and sure
//! path of [`super::solve_quartic`] where its closed form cannot be trusted.
//!
//! Between consecutive real roots of `f′` (found the same way, one degree down, down to
//! a quadratic) `f` is monotone, so each piece holds at most one simple root, found by its
//! sign change with Newton's steps kept inside the shrinking bracket (a bisection, in
//! magnitude where the bracket spans orders of magnitude, where a step would leave it). A
//! critical point where `|f|` is within its rounding bound is a double root, reported
//! twice. Every decision is made on the caller's coefficients, evaluated by Horner, which
//! is backward stable: a root comes out to its own condition, whatever the sizes of the
//! others. This is what a depression `t = x − c₃/(4c₄)` cannot do when one root is 10¹⁴
//! times the others (Algorithm 1010's case 4, roots −1, 1, 2, 10¹⁴): the shift then
//! rounds the small roots away. It is the method of the oracle's cubic and of C. Yuksel's
//! "High-Performance Polynomial Root Finding for Graphics" (HPG 2022), without its
//! speed-ups.

use super::{EPS, RealRoots, eval, times_pow2};

/// Below this multiple of ε·Σ|cᵢ||x|ⁱ, `f` at a critical point is a double root.
const TOUCH: f64 = 16.0;

/// `Σ|cᵢ||x|ⁱ`: what `f(x)`'s rounding is measured by.
#[inline]
fn magnitude(c: &[f64], x: f64) -> f64 {
    c.iter().fold(0.0, |acc, ci| acc * x.abs() + ci.abs())
}

/// Every real root of `c[0]·t⁴ + … + c[4]` (`c[0] ≠ 0`, all finite, within 2^±900), sorted,
/// a double root twice. A zero constant term is divided out exactly first (each `t = 0` root).
pub(super) fn real_roots(c: &[f64; 5]) -> RealRoots {
    let (mut out, degree) = zero_roots(c);
    for &x in roots_of_poly(&c[..=degree]).as_slice() {
        out.push(x);
    }
    out.sort();
    out
}

/// The roots `t = 0` of `c` (`c[0] ≠ 0`), one per zero trailing coefficient, exactly, and
/// the degree of what is left once they are divided out: `c[..=degree]`.
pub(super) fn zero_roots(c: &[f64; 5]) -> (RealRoots, usize) {
    let mut out = RealRoots::default();
    let mut degree = 4;
    while degree > 0 && c[degree] == 0.0 {
        out.push(0.0);
        degree -= 1;
    }
    (out, degree)
}

/// The real roots of `c` (degree `c.len() − 1` ≤ 4, `c[0] ≠ 0`, nonzero constant, all
/// within 2^±900), sorted, a double root twice.
pub(super) fn roots_of_poly(c: &[f64]) -> RealRoots {
    let mut found = [0.0; 4];
    let n = roots_of(c, &mut found);
    let mut out = RealRoots::default();
    // A root beyond f64's range (a linear `−c₁/c₀` that overflows) is left out, as
    // `solve_quartic` documents.
    for &x in found[..n].iter().filter(|x| x.is_finite()) {
        out.push(x);
    }
    out
}

/// The real roots of `c` (degree `c.len() − 1` ≤ 4, `c[0] ≠ 0`) into `out`, ascending, a
/// double root twice; returns how many.
fn roots_of(c: &[f64], out: &mut [f64; 4]) -> usize {
    let degree = c.len() - 1;
    match degree {
        0 => 0,
        1 => {
            out[0] = -c[1] / c[0];
            1
        }
        2 => quadratic(c[0], c[1], c[2], out),
        _ => by_pieces(c, out),
    }
}

/// The real roots of `a t² + b t + c`, by the cancellation-free form; a discriminant
/// within rounding of 0 is fused (one rounding, so its sign is exact given a, b, c).
///
/// The three are first scaled by one power of two (the roots are unchanged) so that the
/// larger of `|b|` and `√|ac|` is near 1: `b²` and `4ac` then neither overflow (a `b` of
/// 2^512 would make the discriminant ∞ and a root −∞) nor lose the terms that decide the
/// roots. What underflows is below 2⁻¹⁰⁷⁰ of the larger term.
fn quadratic(a: f64, b: f64, c: f64, out: &mut [f64; 4]) -> usize {
    let size = b.abs().max(a.abs().sqrt() * c.abs().sqrt());
    let (a, b, c) = if size == 0.0 {
        (a, b, c)
    } else {
        let n = -(size.log2().round() as i32);
        (times_pow2(a, n), times_pow2(b, n), times_pow2(c, n))
    };
    let mut disc = b * b - 4.0 * a * c;
    if disc.abs() <= 1e-7 * (b * b + (4.0 * a * c).abs()) {
        disc = b.mul_add(b, -4.0 * a * c);
    }
    if disc < 0.0 {
        return 0;
    }
    let q = -0.5 * (b + disc.sqrt().copysign(b));
    let (x, y) = if q == 0.0 { (0.0, 0.0) } else { (q / a, c / q) };
    out[0] = x.min(y);
    out[1] = x.max(y);
    2
}

/// Degree 3 or 4: pieces between the critical points over `[−B, B]`, B a power of two
/// above Fujiwara's bound `2·max|cᵢ/c₀|^(1/i)` (every root lies strictly inside, so `f(±B)`
/// has the sign of its leading term there). Unlike Cauchy's `1 + max|cᵢ/c₀|`, which is
/// the roots' scale to the fourth power, every term `|cᵢ|·B^(n−i)` stays below `|c₀|·Bⁿ`,
/// so `f(±B)` is finite and has its sign.
fn by_pieces(c: &[f64], out: &mut [f64; 4]) -> usize {
    let degree = c.len() - 1;
    let mut derivative = [0.0; 4];
    for (k, d) in derivative[..degree].iter_mut().enumerate() {
        *d = c[k] * (degree - k) as f64;
    }
    let mut crit = [0.0; 4];
    let n_crit = roots_of(&derivative[..degree], &mut crit);
    let lead = c[0].abs().log2();
    let root_exp = c[1..]
        .iter()
        .enumerate()
        .filter(|(_, ci)| **ci != 0.0)
        .map(|(i, ci)| (ci.abs().log2() - lead) / (i + 1) as f64)
        .fold(f64::NEG_INFINITY, f64::max);
    // A zero tail (`c₀tⁿ` alone) has every root at 0: any positive bound serves.
    let bound = if root_exp.is_finite() {
        times_pow2(1.0, root_exp.ceil() as i32 + 2)
    } else {
        1.0
    };
    let mut n = 0;
    let mut x = -bound;
    // f(−B) has the sign of c₀·(−1)^degree.
    let mut negative = (c[0] < 0.0) != (degree % 2 == 1);
    let mut last_crit = f64::NAN;
    let mut touched = false;
    for (i, &y) in crit[..n_crit].iter().chain([bound].iter()).enumerate() {
        let at_end = i == n_crit;
        // A repeated critical point (a double root of f′), or one outside the bound.
        if y.partial_cmp(&x) != Some(std::cmp::Ordering::Greater)
            || y == last_crit
            || (!at_end && y >= bound)
        {
            continue;
        }
        let fy = eval(c, y).0;
        if !at_end && fy.abs() <= TOUCH * EPS * magnitude(c, y) {
            // A double root at the critical point; f turns back there. Right after
            // another one, with no crossing between, the two are one cluster of three
            // (a triple root blurred by rounding): one more root, not two, or a quartic's
            // near-triple root took all four slots and its simple root was lost.
            let more = if touched { 1 } else { 2 };
            for _ in 0..more {
                if n < 4 {
                    out[n] = y;
                    n += 1;
                }
            }
            (x, last_crit, touched) = (y, y, true);
            continue;
        }
        let below = fy < 0.0;
        // Right of a double root f starts from 0 and is monotone up to y: no crossing.
        if below != negative && !touched && n < 4 {
            out[n] = bracketed(c, x, y, negative);
            n += 1;
        }
        (x, negative, last_crit, touched) = (y, below, y, false);
    }
    n
}

/// A point strictly between `x < y` that halves the bracket, in magnitude where it spans
/// orders of magnitude (so a root near 0 next to a bound of 10¹⁰⁰ takes tens of steps, not
/// hundreds).
#[inline]
pub(super) fn split(x: f64, y: f64) -> f64 {
    let candidate = if x > 0.0 && y > 4.0 * x || y < 0.0 && x < 4.0 * y {
        (x * y).sqrt().copysign(y)
    } else if x < 0.0 && y > 0.0 {
        0.0
    } else if x == 0.0 {
        y * 2f64.powi(-64)
    } else if y == 0.0 {
        x * 2f64.powi(-64)
    } else {
        0.5 * (x + y)
    };
    if candidate > x && candidate < y {
        candidate
    } else {
        0.5 * (x + y)
    }
}

/// The root of `f` in `[x, y]`, where `f` is monotone and changes sign (`f < 0` on the
/// `x` side iff `negative_at_x`): Newton's steps inside the shrinking bracket, a
/// [`split`] where a step would leave it or is not under a quarter of the last.
fn bracketed(c: &[f64], mut x: f64, mut y: f64, negative_at_x: bool) -> f64 {
    let mut v = split(x, y);
    let mut last_step = f64::INFINITY;
    for _ in 0..400 {
        let (f, df) = eval(c, v);
        if f == 0.0 {
            return v;
        }
        if (f < 0.0) == negative_at_x {
            x = v;
        } else {
            y = v;
        }
        let newton = v - f / df;
        // Each Newton step must be under a quarter of the last one, as they are once
        // convergence is quadratic. From far outside a root pair (f ≈ a − bt², a tiny)
        // they only halve t: 400 of them stopped at 10⁻¹⁴⁰ on the way to 10⁻¹⁵⁶. A split
        // there crosses up to 64 binades at a time.
        let next = if newton > x && newton < y && (newton - v).abs() <= 0.25 * last_step {
            newton
        } else {
            split(x, y)
        };
        last_step = (next - v).abs();
        // Converged, or the bracket is down to adjacent floats (`split` returns an end
        // only then).
        if (next - v).abs() <= 2.0 * EPS * next.abs() || next <= x || next >= y {
            return next.clamp(x, y);
        }
        v = next;
    }
    v
}

#[cfg(test)]
mod tests {
    use super::*;

    fn roots(c: [f64; 5]) -> Vec<f64> {
        real_roots(&c).as_slice().to_vec()
    }

    #[test]
    fn simple_double_and_zero_roots() {
        // (t − 1)(t − 2)(t − 3)(t − 4).
        let got = roots([1.0, -10.0, 35.0, -50.0, 24.0]);
        for (g, w) in got.iter().zip([1.0, 2.0, 3.0, 4.0]) {
            assert!((g - w).abs() < 1e-14, "{got:?}");
        }
        assert_eq!(got.len(), 4);
        // (t² − 1)² : ±1 double, decided at the critical points.
        assert_eq!(roots([1.0, 0.0, -2.0, 0.0, 1.0]), [-1.0, -1.0, 1.0, 1.0]);
        // t⁴ and t⁴ − t³: the zero roots divided out exactly.
        assert_eq!(roots([1.0, 0.0, 0.0, 0.0, 0.0]), [0.0; 4]);
        assert_eq!(roots([1.0, -1.0, 0.0, 0.0, 0.0]), [0.0, 0.0, 0.0, 1.0]);
        // t⁴ + 1: none.
        assert!(roots([1.0, 0.0, 0.0, 0.0, 1.0]).is_empty());
    }

    #[test]
    fn small_roots_beside_a_huge_one_keep_their_relative_accuracy() {
        // (t + 1)(t − 1)(t − 2)(t − 10¹⁴), coefficients as stored in f64.
        let c = [
            1.0,
            -100000000000002.0,
            199999999999999.0,
            100000000000002.0,
            -200000000000000.0,
        ];
        let got = roots(c);
        assert_eq!(got.len(), 4, "{got:?}");
        for (g, w) in got.iter().zip([-1.0, 1.0, 2.0, 1e14]) {
            assert!(((g - w) / w).abs() < 1e-15, "{got:?}");
        }
    }
}
