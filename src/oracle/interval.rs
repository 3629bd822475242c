//! One-variable numerics on an interval: bisection to adjacent floats, and the real roots
//! of a cubic by monotone pieces. Slow and sure, with no closed form to go wrong.

/// The most halvings [`bisect`] takes: from any finite interval of f64 to adjacent floats
/// is at most about 2100 (the exponents' range, 2 × 1024, plus the 53 bits of the
/// significand), so the bound is never reached by a finite interval; it only keeps a
/// caller's mistake from spinning forever.
pub(super) const MAX_BISECTIONS: usize = 4096;

/// A root of `f` in [a, b], given `fa = f(a)` and a sign change over [a, b], bisected until
/// a and b are adjacent floats; returns the end with the smaller |f|. `None` where a or b
/// is not finite (the midpoint of an infinite interval is NaN or infinite) or `f` gives
/// NaN at an end or a midpoint: no root can be found there by halving.
pub(super) fn bisect(f: &dyn Fn(f64) -> f64, mut a: f64, mut b: f64, mut fa: f64) -> Option<f64> {
    if !(a.is_finite() && b.is_finite()) || fa.is_nan() {
        return None;
    }
    let mut fb = f(b);
    if fb.is_nan() {
        return None;
    }
    for _ in 0..MAX_BISECTIONS {
        let m = 0.5 * (a + b);
        // Also stops on an overflow of a + b (m infinite) or NaN.
        if !(m > a && m < b) {
            break;
        }
        let fm = f(m);
        if fm == 0.0 {
            return Some(m);
        }
        if fm.is_nan() {
            return None;
        }
        if (fm < 0.0) == (fa < 0.0) {
            a = m;
            fa = fm;
        } else {
            b = m;
            fb = fm;
        }
    }
    Some(if fa.abs() <= fb.abs() { a } else { b })
}

/// The real roots of c3 s³ + c2 s² + c1 s + c0 (c3 > 0), sorted.
///
/// No closed form: the roots of the derivative split [−M, M] (M the Cauchy bound) into
/// monotone pieces and each sign change is bisected. Slow and sure, which is what the
/// oracle wants; a double root without a sign change is not an extremum of F, so skipping
/// it loses nothing here.
pub(super) fn cubic_real_roots(c3: f64, c2: f64, c1: f64, c0: f64) -> Vec<f64> {
    let f = |s: f64| ((c3 * s + c2) * s + c1) * s + c0;
    let bound = 1.0 + (c2.abs().max(c1.abs()).max(c0.abs())) / c3;
    // An overflowed or NaN coefficient gives no bound to split: no roots (the callers'
    // candidates from F′ are extras, see the module text of `oracle`).
    if !(bound.is_finite() && c3 > 0.0 && c3.is_finite()) {
        return Vec::new();
    }
    let mut cuts = vec![-bound];
    let mut crit = quadratic_real_roots(3.0 * c3, 2.0 * c2, c1);
    crit.retain(|s| s.abs() < bound);
    cuts.extend(crit);
    cuts.push(bound);
    let mut roots = Vec::new();
    for w in cuts.windows(2) {
        let (a, b) = (w[0], w[1]);
        let (fa, fb) = (f(a), f(b));
        if fa == 0.0 {
            roots.push(a);
        } else if (fa < 0.0) != (fb < 0.0) && fb != 0.0 {
            roots.extend(bisect(&f, a, b, fa));
        }
    }
    if f(bound) == 0.0 {
        roots.push(bound);
    }
    roots.sort_by(f64::total_cmp);
    roots.dedup();
    roots
}

/// The real roots of a s² + b s + c, a ≠ 0, by the cancellation-free form.
pub(super) fn quadratic_real_roots(a: f64, b: f64, c: f64) -> Vec<f64> {
    let disc = b * b - 4.0 * a * c;
    if disc < 0.0 {
        return Vec::new();
    }
    let q = -0.5 * (b + b.signum() * disc.sqrt());
    if q == 0.0 {
        return vec![0.0];
    }
    let mut r = vec![q / a, c / q];
    r.sort_by(f64::total_cmp);
    r
}
