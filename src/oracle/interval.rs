//! One-variable numerics on an interval: bisection to adjacent floats, and the real roots
//! of a cubic by monotone pieces. Slow and sure, with no closed form to go wrong.

/// A root of `f` in [a, b], given `fa = f(a)` and a sign change over [a, b], bisected until
/// a and b are adjacent floats; returns the end with the smaller |f|.
pub(super) fn bisect(f: &dyn Fn(f64) -> f64, mut a: f64, mut b: f64, mut fa: f64) -> f64 {
    let mut fb = f(b);
    loop {
        let m = 0.5 * (a + b);
        if m <= a || m >= b {
            break;
        }
        let fm = f(m);
        if fm == 0.0 {
            return m;
        }
        if (fm < 0.0) == (fa < 0.0) {
            a = m;
            fa = fm;
        } else {
            b = m;
            fb = fm;
        }
    }
    if fa.abs() <= fb.abs() { a } else { b }
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
            roots.push(bisect(&f, a, b, fa));
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
