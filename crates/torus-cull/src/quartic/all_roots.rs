//! Every real root, sorted and Newton-polished on the caller's polynomial: for CSG, the
//! oracle's checks and the tests.

use super::discriminant::surely_no_real_root;
use super::{EPS, RealRoots, eval, eval2, even, factor, pieces, scales};

/// All real roots of `c[0]·t⁴ + c[1]·t³ + c[2]·t² + c[3]·t + c[4]`, `c[0] ≠ 0`, sorted.
///
/// The quartic is made monic and depressed (`t = x − c[1]/(4c[0])`), factored, and each
/// root is then Newton-polished on the original coefficients (the depression loses
/// absolute accuracy when the shift is large). Where that answer cannot be trusted (a
/// returned root that is no root within rounding, or a shift that can have rounded a
/// small root away: roots −1, 1, 2 beside 10¹⁴), the roots are found on the original
/// coefficients by monotone pieces instead (`pieces.rs`), each to its own condition.
/// Returns no roots if `c[0] = 0` or a coefficient is not finite.
///
/// Coefficients of any finite size are taken: where the roots' scale lies beyond 2^±25
/// or the coefficients beyond 2^±900, each group of root sizes (from the Newton polygon)
/// is solved by monotone pieces for t/2^m, its terms scaled by powers of two
/// (`scales.rs`), and a root too large for f64 is left out.
///
/// ```
/// use torus_cull::quartic::solve_quartic;
/// // 2(t − 1)(t − 2)(t − 3)(t − 4) = 2t⁴ − 20t³ + 70t² − 100t + 48.
/// let roots = solve_quartic([2.0, -20.0, 70.0, -100.0, 48.0]);
/// assert_eq!(roots.len(), 4);
/// for (got, want) in roots.as_slice().iter().zip([1.0, 2.0, 3.0, 4.0]) {
///     assert!((got - want).abs() < 1e-12);
/// }
/// // t⁴ + 1 has no real root; a double root is reported twice: (t − 5)²(t² + 1).
/// assert!(solve_quartic([1.0, 0.0, 0.0, 0.0, 1.0]).is_empty());
/// let double = solve_quartic([1.0, -10.0, 26.0, -10.0, 25.0]);
/// assert_eq!(double.len(), 2);
/// assert!(double.as_slice().iter().all(|t| (t - 5.0).abs() < 1e-6));
/// ```
#[must_use]
pub fn solve_quartic(c: [f64; 5]) -> RealRoots {
    if c[0] == 0.0 || !c.iter().all(|v| v.is_finite()) {
        return RealRoots::default();
    }
    if out_of_range(&c) {
        // One power-of-two scale cannot serve roots whose sizes span more than f64's
        // range (at the large roots' scale the small ones underflow: roots near 1 beside
        // one near 10²⁹² gave a spurious −1, and a root 2⁻⁵⁷⁵ below the others came out
        // halved): each group of root sizes is solved at its own.
        return scales::real_roots(&c);
    }
    solve_in_range(c)
}

/// [`solve_quartic`] for coefficients that neither overflow nor underflow when made monic
/// and depressed.
fn solve_in_range(c: [f64; 5]) -> RealRoots {
    let [c4, c3, c2, c1, c0] = c;
    let inv = 1.0 / c4;
    let (b, cc, d) = (c2 * inv, c1 * inv, c0 * inv);
    let s = 0.25 * c3 * inv;
    // t = x − s:  p = b − 6s², q = c − 2s(b − 4s²), r = d − s(c − s(b − 3s²)).
    let p = b - 6.0 * s * s;
    let q = cc - 2.0 * s * (b - 4.0 * s * s);
    let r = d - s * (cc - s * (b - 3.0 * s * s));
    // Near-tangent decisions look for a local extremum, so they need the monic form.
    let monic = [1.0, c3 * inv, b, cc, d];
    // q = 0: a quadratic in x², solved as one (as `solve_depressed_monic` does). Ferrari's
    // split has no pairing to find there (its resolvent's greatest root is 0), and took
    // x⁴ − 16 to ±1.07·10⁸.
    let even = if q == 0.0 {
        even::real_roots(p, r)
    } else {
        None
    };
    let mut roots = even
        .unwrap_or_else(|| {
            let near = factor::near_double_threshold(p, q, r, &monic, s);
            factor::real_roots(p, q, r, &monic, s, near)
        })
        .map_increasing(|x| x - s);
    roots.sort();
    polish(&mut roots, &c);
    if trusted(&roots, &c, s) {
        roots
    } else {
        pieces::real_roots(&c)
    }
}

/// A returned root whose backward error `|f(t)|/Σ|cᵢ||t|ⁱ` exceeds this multiple of ε is
/// no root of any quartic within rounding of the caller's.
const BACKWARD: f64 = 1e3;

/// A root smaller than this fraction of the depression's shift `s` lies within
/// `ε·|s|/|t| > 2²⁰ε` of its neighbours in the depressed variable: rounded away.
const SHIFT_RATIO: f64 = 9.5367431640625e-7; // 2⁻²⁰

/// Whether the closed form's roots can be returned: each is a root within rounding of
/// `c`, and the depression `t = x − s` cannot have rounded a root away. A root much
/// smaller than `|s|` sits in a cluster of the depressed quartic (Algorithm 1010's case 4:
/// roots −1, 1, 2 beside 10¹⁴ became one root 0.99988), so that is refused by a lower
/// bound on every root's size, Fujiwara's bound for the reversed polynomial:
/// `|t| ≥ 1/(2·max_k |c[4−k]/c[4]|^(1/k))`, and `t = 0` (a zero constant) with any shift.
/// Otherwise [`pieces::real_roots`] solves `c` itself.
fn trusted(roots: &RealRoots, c: &[f64; 5], s: f64) -> bool {
    let backward_ok = roots.as_slice().iter().all(|&t| {
        let f = eval(c, t).0.abs();
        let mag = c.iter().fold(0.0, |acc, ci| acc * t.abs() + ci.abs());
        // Written so that NaN fails.
        f <= BACKWARD * EPS * mag
    });
    if !backward_ok {
        return false;
    }
    if s == 0.0 {
        return true;
    }
    if c[4] == 0.0 {
        return false;
    }
    // 1/|t| ≤ 2·max_k |c[4−k]/c[4]|^(1/k), in exponents: no overflow.
    let exp = |x: f64| x.abs().log2();
    let inv_exp = (1..5)
        .filter(|&k| c[4 - k] != 0.0)
        .map(|k| (exp(c[4 - k]) - exp(c[4])) / k as f64)
        .fold(f64::NEG_INFINITY, f64::max);
    // log2 of the lower bound on |t|, against log2(2⁻²⁰·|s|).
    -(inv_exp + 1.0) >= exp(s) + SHIFT_RATIO.log2()
}

/// Whether the quartic's monic form would leave f64's comfortable range, so that it is
/// solved by [`scales::real_roots`]: the roots' scale beyond 2^±25 (the monic
/// coefficients beyond 2^±100, where the depressed solvers rescale; see
/// `out_of_range`) or a coefficient beyond 2^±900 (where `1/c[0]` and the polishing
/// overflow). Within, the solver's own range, its answers are left bit for bit.
fn out_of_range(c: &[f64; 5]) -> bool {
    const ROOT_EXP: f64 = 25.0;
    const COEFFICIENT_EXP: f64 = 900.0;
    let exp = |x: f64| x.abs().log2();
    let lead = exp(c[0]);
    // Fujiwara's bound in exponents: every root has |t| ≤ 2·max_k |c[k]/c[0]|^(1/k), and
    // the largest term is the scale at which the monic coefficients are O(1).
    let root_exp = (1..5)
        .filter(|&k| c[k] != 0.0)
        .map(|k| (exp(c[k]) - lead) / k as f64)
        .fold(f64::NEG_INFINITY, f64::max);
    // t⁴ alone: every root is 0 at any scale.
    let root_exp = if root_exp.is_finite() { root_exp } else { 0.0 };
    let largest = c.iter().map(|&x| exp(x)).fold(f64::NEG_INFINITY, f64::max);
    root_exp.abs() > ROOT_EXP || largest.abs() > COEFFICIENT_EXP
}

/// All real roots of the depressed monic quartic `x⁴ + p x² + q x + r`, sorted, each
/// Newton-polished on that quartic (except an even one's, `q = 0`, already within a few
/// ulps as the square roots of a quadratic's stable roots). A double root is reported
/// twice. A quartic whose discriminant's signs prove, beyond rounding, that it has no real
/// root returns before the resolvent, as in [`super::nearest_root_depressed`].
///
/// Coefficients of any finite size are taken: beyond 2^±100 each group of root sizes is
/// solved at its own power-of-two scale, by monotone pieces (`scales.rs`).
#[must_use]
pub fn solve_depressed_monic(p: f64, q: f64, r: f64) -> RealRoots {
    if !(p.is_finite() && q.is_finite() && r.is_finite()) {
        return RealRoots::default();
    }
    if super::out_of_range(p, q, r) {
        // Each group of root sizes at its own scale: one scale for all took r/s⁴ of
        // x⁴ + 4.9·10¹⁵⁰x + 4.6·10⁻¹⁵¹ to 0, and its root −9.3·10⁻³⁰² with it.
        return scales::real_roots(&[1.0, 0.0, p, q, r]);
    }
    // The nearest-root query's early exit: no real root, by signs beyond rounding.
    if surely_no_real_root(p, q, r) {
        return RealRoots::default();
    }
    // An even quartic's roots ±√y, from the stable roots y of y² + p y + r, are each within
    // a few ulps of the exact roots of the given p and r (`even.rs`): Newton on x cannot
    // improve them, and at a tangent (a double y, or y ≈ 0 for a tangent at the foot
    // point) it would only blur them with f's rounding, on the guarded path.
    if q == 0.0 {
        if let Some(mut roots) = even::real_roots(p, r) {
            roots.sort();
            return roots;
        }
    }
    let c = [1.0, 0.0, p, q, r];
    let mut roots = factor::real_roots(p, q, r, &c, 0.0, factor::NEAR_DOUBLE);
    roots.sort();
    polish(&mut roots, &c);
    roots
}

/// A Newton step below this fraction of the distance to the neighbouring roots is taken
/// without checking that it lowers |f|: the root is then simple and well separated, and
/// the step is the correction of a start deep inside Newton's quadratic basin.
const SMALL_STEP: f64 = 1e-6;

/// Newton steps on `c` for each (sorted) root, kept only where they stay within half the
/// distance to the neighbouring roots (so two close roots cannot merge; a double root
/// reported twice does not move).
///
/// The factors' roots are already accurate to a few ε in relative terms where the root is
/// well conditioned (see the solver bench's accuracy records), so one step, whose error is
/// about `e²·|f″/2f′|` from an error `e`, reaches rounding. Where every step is small next
/// to the roots' separation ([`SMALL_STEP`]) the steps are taken at once, all four slots
/// in straight-line code (the empty ones padded and ignored), which the compiler pairs
/// into vector evaluations and divisions. A larger step (an ill-conditioned root, a
/// cluster that the depression blurred), or a (near-)double pair that
/// [`refine_close_pairs`] re-derived, where `f′ ≈ 0` lets Newton overshoot, sends every
/// root to the checked steps of [`guarded_newton`] instead.
#[inline]
fn polish(roots: &mut RealRoots, c: &[f64; 5]) {
    let close = refine_close_pairs(roots, c);
    let n = roots.len;
    // Slots past the roots hold +∞: the last root's upper gap is then ∞, and their own
    // (NaN) steps are never used.
    let mut x = roots.roots;
    for (i, v) in x.iter_mut().enumerate() {
        if i >= n {
            *v = f64::INFINITY;
        }
    }
    let mut stepped = [0.0; 4];
    let mut small = [false; 4];
    for i in 0..4 {
        let below = if i > 0 {
            x[i] - x[i - 1]
        } else {
            f64::INFINITY
        };
        let above = if i < 3 {
            x[i + 1] - x[i]
        } else {
            f64::INFINITY
        };
        let lim = 0.5 * below.min(above);
        let (f, df) = eval(c, x[i]);
        stepped[i] = x[i] - f / df;
        // Written so that NaN (f′ = 0) also fails the test.
        small[i] = (stepped[i] - x[i]).abs() <= SMALL_STEP * lim;
    }
    let all_small = (0..4).all(|i| i >= n || small[i]);
    if all_small && !close {
        roots.roots[..n].copy_from_slice(&stepped[..n]);
    } else {
        polish_guarded(roots, c);
    }
}

/// [`guarded_newton`] for every (sorted) root, each step kept within half the distance to
/// the neighbouring roots. Cold: ill-conditioned and (near-)double roots.
#[cold]
fn polish_guarded(roots: &mut RealRoots, c: &[f64; 5]) {
    let n = roots.len;
    let orig = roots.roots;
    for i in 0..n {
        let x0 = orig[i];
        let below = if i > 0 {
            x0 - orig[i - 1]
        } else {
            f64::INFINITY
        };
        let above = if i + 1 < n {
            orig[i + 1] - x0
        } else {
            f64::INFINITY
        };
        let (f, df) = eval(c, x0);
        roots.roots[i] = guarded_newton(c, x0, f, df, 0.5 * below.min(above));
    }
}

/// Up to two Newton steps on `c` from `x0` (where `f, f′ = f(x0), f′(x0)`), each taken only
/// if it stays within `lim` of `x0` and reduces |f|.
#[inline]
fn guarded_newton(c: &[f64; 5], x0: f64, mut f: f64, mut df: f64, lim: f64) -> f64 {
    let mut x = x0;
    for _ in 0..2 {
        if f == 0.0 || df == 0.0 {
            break;
        }
        let xn = x - f / df;
        // Written so that NaN also fails the test.
        let ok = (xn - x0).abs() <= lim;
        if !ok {
            break;
        }
        let (fnew, dfnew) = eval(c, xn);
        if fnew.abs() >= f.abs() {
            break;
        }
        x = xn;
        f = fnew;
        df = dfnew;
    }
    x
}

/// A pair of roots much closer to each other than to the rest is a (near-)double root,
/// which Newton on `f` cannot improve (f' ≈ 0) and which the depression may have blurred by
/// √(rounding of the shift). Re-derive it from the caller's `c`: Newton on `f'` to the
/// extremum `x*` between them, then `x* ± √(−2f/f'')`. Where `f(x*)` has the wrong sign
/// (a local maximum below 0, a minimum above) within rounding, the pair is double, at
/// `x*`; beyond rounding, and out of the slope's reach of the pair, it is complex and is
/// dropped: Ferrari's split of x⁴ − 1.5x² + 10⁻³⁰(x − 1) takes the resolvent's rounded
/// double root 1.5, whose factors hold a real pair near 10⁻¹⁵ where f < −10⁻³⁰. Returns
/// whether it found such a pair.
#[inline]
fn refine_close_pairs(roots: &mut RealRoots, c: &[f64; 5]) -> bool {
    let n = roots.len;
    let mut any = false;
    let mut dropped = false;
    let mut keep = [true; 4];
    let mut i = 0;
    while i + 1 < n {
        let (a, b) = (roots.roots[i], roots.roots[i + 1]);
        let gap = b - a;
        let mid = 0.5 * (a + b);
        let mut other = f64::INFINITY;
        if i > 0 {
            other = other.min(mid - roots.roots[i - 1]);
        }
        if i + 2 < n {
            other = other.min(roots.roots[i + 2] - mid);
        }
        // Distance scale: to the other real roots, or |x| if there are none.
        let scale = if other.is_finite() { other } else { mid.abs() };
        // A pair whose smaller root is far below its gap (roots 0 and 1 beside ±4·10⁴) is
        // no double root in its own terms, and x* ± δ would round the small one to 0.
        if gap > 1e-4 * scale || a.abs().min(b.abs()) < 1e-3 * gap {
            i += 1;
            continue;
        }
        let mut x = mid;
        for _ in 0..3 {
            let (_, d1, d2) = eval2(c, x);
            if d2 == 0.0 {
                break;
            }
            let xn = x - d1 / d2;
            // Stay far from the other critical points (≈ half-way to the other roots).
            // Written so that NaN also fails the test.
            let ok = (xn - mid).abs() <= 0.1 * scale;
            if !ok {
                break;
            }
            x = xn;
        }
        let (f, d1, d2) = eval2(c, x);
        let delta = if d2 != 0.0 && f * d2 < 0.0 {
            (-2.0 * f / d2).sqrt()
        } else {
            0.0
        };
        let rounding = 64.0 * EPS * c.iter().fold(0.0, |acc, ci| acc * x.abs() + ci.abs());
        let reach = d1.abs() * ((x - a).abs() + (x - b).abs());
        if f * d2 > 0.0 && f.abs() > rounding && f.abs() > reach {
            (keep[i], keep[i + 1], dropped) = (false, false, true);
        }
        roots.roots[i] = x - delta;
        roots.roots[i + 1] = x + delta;
        any = true;
        i += 2;
    }
    if dropped {
        let mut kept = RealRoots::default();
        for k in (0..n).filter(|&k| keep[k]) {
            kept.push(roots.roots[k]);
        }
        *roots = kept;
    }
    any
}
