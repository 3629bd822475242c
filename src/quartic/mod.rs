//! Real roots of a quartic, the core of the exact intersection.
//!
//! **Method: Ferrari, with the resolvent solved for `m²`.** The depressed monic quartic
//! `x⁴ + p x² + q x + r` splits as `(x² + m x + n₁)(x² − m x + n₂)` where `z = m²` is the
//! greatest root of `z³ + 2p z² + (p² − 4r) z − q²` (`resolvent.rs`), and the two quadratics
//! are solved in their stable forms (`factor.rs`). Each choice has a reason:
//! - the greatest resolvent root is `≥ 0`, so `m` is real, and solving for `z` keeps a tiny
//!   `m²` (a small `q`) to full relative precision, where Ferrari's usual `ξ = (z + p)/2`
//!   loses it to cancellation;
//! - `n₂ − n₁` is taken as `q/m` or `±√((p + z)² − 4r)`, whichever is better conditioned,
//!   and the smaller of `n₁, n₂` as `r` over the larger;
//! - a factor with a near-zero discriminant is decided on the quartic itself (its value at
//!   the nearby extremum against a rounding bound), never on the factor;
//! - roots get guarded Newton steps on the caller's polynomial;
//! - the nearest-root query first rejects a quartic whose discriminant's signs, beyond
//!   rounding, say it has no real root: a missed line costs no resolvent.
//!
//! Two entry points: [`nearest_root_depressed`], the nearest root in an interval, which is
//! all a renderer needs (one Newton step, no sort); and the all-roots [`solve_depressed_monic`]
//! / [`solve_quartic`] for CSG and the tests.
//!
//! References: L. Ferrari's method as in Abramowitz & Stegun 3.8.3; the resolvent in `m²`
//! is Descartes'. Peers measured in the bench: the `roots` crate (Ferrari) and
//! `kurbo::common::solve_quartic` (Orellana & De Michele, ACM TOMS 46(2), 2020, Alg. 1010).

mod factor;
mod resolvent;

/// The thresholds below which the solver takes its careful (cold) paths; the batch solver
/// hands exactly those lanes back to [`nearest_root_depressed`].
pub(crate) use factor::NEAR_DOUBLE;
pub(crate) use resolvent::DISC_NEAR;

const EPS: f64 = f64::EPSILON;

/// Up to four real roots, sorted ascending. A double root is reported twice.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct RealRoots {
    roots: [f64; 4],
    len: usize,
}

impl RealRoots {
    /// The roots, ascending.
    #[inline]
    pub fn as_slice(&self) -> &[f64] {
        &self.roots[..self.len]
    }

    /// How many real roots (with multiplicity), 0 to 4.
    #[inline]
    pub fn len(&self) -> usize {
        self.len
    }

    /// No real root.
    #[inline]
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    #[inline]
    fn push(&mut self, x: f64) {
        // A quartic has at most four roots; each of the two factors pushes at most two.
        debug_assert!(self.len < 4);
        if self.len < 4 {
            self.roots[self.len] = x;
            self.len += 1;
        }
    }

    /// Insertion sort: at most four elements.
    #[inline]
    fn sort(&mut self) {
        for i in 1..self.len {
            let mut j = i;
            while j > 0 && self.roots[j - 1] > self.roots[j] {
                self.roots.swap(j - 1, j);
                j -= 1;
            }
        }
    }

    /// Applies an increasing map to every root (order is kept), e.g. a change of variable.
    #[inline]
    pub(crate) fn map_increasing(mut self, f: impl Fn(f64) -> f64) -> RealRoots {
        for x in &mut self.roots[..self.len] {
            *x = f(*x);
        }
        self
    }
}

/// The nearest real root of `x⁴ + p x² + q x + r` in `[lo, hi]` (either end may be
/// infinite), or `None`: the renderer's query.
///
/// A quartic whose discriminant says, beyond rounding, that it has no real root returns at
/// once (half the lines of a uniform workload). Otherwise finds the roots of both Ferrari
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
        let pick = |x: f64, ok: bool| {
            if ok && x >= lo && x <= hi {
                x
            } else {
                f64::INFINITY
            }
        };
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
        .copied()
        .filter(|&x| x >= lo && x <= hi)
        .fold(f64::INFINITY, f64::min)
}

/// All real roots of `c[0]·t⁴ + c[1]·t³ + c[2]·t² + c[3]·t + c[4]`, `c[0] ≠ 0`, sorted.
///
/// The quartic is made monic and depressed (`t = x − c[1]/(4c[0])`), factored, and each
/// root is then Newton-polished on the original coefficients (the depression loses
/// absolute accuracy when the shift is large).
/// Returns no roots if `c[0] = 0` or a coefficient is not finite.
pub fn solve_quartic(c: [f64; 5]) -> RealRoots {
    let [c4, c3, c2, c1, c0] = c;
    if c4 == 0.0 || !c.iter().all(|v| v.is_finite()) {
        return RealRoots::default();
    }
    let inv = 1.0 / c4;
    let (b, cc, d) = (c2 * inv, c1 * inv, c0 * inv);
    let s = 0.25 * c3 * inv;
    // t = x − s:  p = b − 6s², q = c − 2s(b − 4s²), r = d − s(c − s(b − 3s²)).
    let p = b - 6.0 * s * s;
    let q = cc - 2.0 * s * (b - 4.0 * s * s);
    let r = d - s * (cc - s * (b - 3.0 * s * s));
    // Near-tangent decisions look for a local extremum, so they need the monic form.
    let monic = [1.0, c3 * inv, b, cc, d];
    let near = factor::near_double_threshold(p, q, r, &monic, s);
    let mut roots = factor::real_roots(p, q, r, &monic, s, near).map_increasing(|x| x - s);
    roots.sort();
    polish(&mut roots, &c);
    roots
}

/// All real roots of the depressed monic quartic `x⁴ + p x² + q x + r`, sorted, each
/// Newton-polished on that quartic. A double root is reported twice.
pub fn solve_depressed_monic(p: f64, q: f64, r: f64) -> RealRoots {
    if !(p.is_finite() && q.is_finite() && r.is_finite()) {
        return RealRoots::default();
    }
    let c = [1.0, 0.0, p, q, r];
    let mut roots = factor::real_roots(p, q, r, &c, 0.0, factor::NEAR_DOUBLE);
    roots.sort();
    polish(&mut roots, &c);
    roots
}

/// `f(t)`, `f'(t)` and `f''(t)` for `c = [c4, c3, c2, c1, c0]`, Horner.
#[inline]
fn eval2(c: &[f64; 5], x: f64) -> (f64, f64, f64) {
    let mut f = c[0];
    let mut df = 0.0;
    let mut d2f = 0.0;
    for &ci in &c[1..] {
        d2f = d2f * x + 2.0 * df;
        df = df * x + f;
        f = f * x + ci;
    }
    (f, df, d2f)
}

/// `f(x)` and `f'(x)` for `c = [c4, c3, c2, c1, c0]`, Horner.
#[inline]
fn eval(c: &[f64; 5], x: f64) -> (f64, f64) {
    let mut f = c[0];
    let mut df = 0.0;
    for &ci in &c[1..] {
        df = df * x + f;
        f = f * x + ci;
    }
    (f, df)
}

/// Up to two Newton steps per (sorted) root on `c`. A step is taken only if it stays
/// within half the distance to the neighbouring roots (so two close roots cannot merge; a
/// double root reported twice does not move) and reduces |f|.
#[inline]
fn polish(roots: &mut RealRoots, c: &[f64; 5]) {
    let n = roots.len;
    refine_close_pairs(roots, c);
    let orig = roots.roots;
    for i in 0..n {
        let x0 = orig[i];
        let mut lim = f64::INFINITY;
        if i > 0 {
            lim = lim.min(x0 - orig[i - 1]);
        }
        if i + 1 < n {
            lim = lim.min(orig[i + 1] - x0);
        }
        lim *= 0.5;
        let mut x = x0;
        let (mut f, mut df) = eval(c, x);
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
        roots.roots[i] = x;
    }
    roots.sort();
}

/// A pair of roots much closer to each other than to the rest is a (near-)double root,
/// which Newton on `f` cannot improve (f' ≈ 0) and which the depression may have blurred by
/// √(rounding of the shift). Re-derive it from the caller's `c`: Newton on `f'` to the
/// extremum `x*` between them, then `x* ± √(−2f/f'')` (both `x*` if `f(x*)` has the wrong sign,
/// which is within rounding since Ferrari found the pair real).
#[inline]
fn refine_close_pairs(roots: &mut RealRoots, c: &[f64; 5]) {
    let n = roots.len;
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
        if gap > 1e-4 * scale {
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
        let (f, _, d2) = eval2(c, x);
        let delta = if d2 != 0.0 && f * d2 < 0.0 {
            (-2.0 * f / d2).sqrt()
        } else {
            0.0
        };
        roots.roots[i] = x - delta;
        roots.roots[i + 1] = x + delta;
        i += 2;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{RngExt, SeedableRng};
    use rand_pcg::Pcg64;

    /// Coefficients of k·(t − a)(t − b)(t − c)(t − d).
    fn from_roots(k: f64, rs: [f64; 4]) -> [f64; 5] {
        let mut c = [k, 0.0, 0.0, 0.0, 0.0];
        // Multiply by (t − ρ) one factor at a time: c holds the polynomial, highest first.
        let mut deg = 0;
        for rho in rs {
            deg += 1;
            for j in (1..=deg).rev() {
                c[j] -= rho * c[j - 1];
            }
        }
        c
    }

    /// Coefficients of (t² + b t + c)(t − x)(t − y).
    fn from_pair_and_roots(b: f64, cq: f64, x: f64, y: f64) -> [f64; 5] {
        let l = [1.0, -(x + y), x * y];
        let qd = [1.0, b, cq];
        let mut c = [0.0; 5];
        for i in 0..3 {
            for j in 0..3 {
                c[i + j] += l[i] * qd[j];
            }
        }
        c
    }

    /// A line far from the torus gives x⁴ + p x² + q x + r ≈ (x² + p/2)² with tiny q: the
    /// resolvent's top two roots nearly merge, and rounding once returned the isolated
    /// root −√r, whose factors had real, spurious double roots (found by the BVH bench).
    #[test]
    fn near_square_without_real_roots_gives_none() {
        let got = solve_depressed_monic(4563.646856842148, 0.001742656689884825, 5206718.203343114);
        assert!(got.is_empty(), "{:?}", got.as_slice());
        let mut rng = Pcg64::seed_from_u64(77);
        for _ in 0..20_000 {
            let a: f64 = 10f64.powf(rng.random_range(-2.0..5.0));
            let eps: f64 = a * a * 10f64.powf(rng.random_range(-12.0..-2.0));
            let q: f64 = a.sqrt() * 10f64.powf(rng.random_range(-9.0..-3.0));
            // (x² + a)² + eps + q x: positive for every real x when q is this small.
            let (p, r) = (2.0 * a, a * a + eps);
            let min_f = (0..200)
                .map(|i| {
                    let x = (i as f64 - 100.0) * a.sqrt() / 20.0;
                    ((x * x + p) * x + q) * x + r
                })
                .fold(f64::INFINITY, f64::min);
            if min_f <= 0.0 {
                continue;
            }
            let got = solve_depressed_monic(p, q, r);
            assert!(got.is_empty(), "p={p} q={q} r={r}: {:?}", got.as_slice());
        }
    }

    fn sorted(mut v: [f64; 4]) -> [f64; 4] {
        v.sort_by(f64::total_cmp);
        v
    }

    /// Asserts the solver returns exactly `want` (sorted) with |err| ≤ tol·max(1, |root|).
    fn assert_roots(c: [f64; 5], want: &[f64], tol: f64) {
        let got = solve_quartic(c);
        let got = got.as_slice();
        assert_eq!(
            got.len(),
            want.len(),
            "c = {c:?}: got {got:?}, want {want:?}"
        );
        for (g, w) in got.iter().zip(want) {
            assert!(
                (g - w).abs() <= tol * w.abs().max(1.0),
                "c = {c:?}: got {got:?}, want {want:?} (tol {tol})"
            );
        }
    }

    #[test]
    fn distinct_roots() {
        assert_roots(
            from_roots(1.0, [1.0, 2.0, 3.0, 4.0]),
            &[1.0, 2.0, 3.0, 4.0],
            1e-13,
        );
        assert_roots(
            from_roots(-3.0, [-2.5, 0.5, 0.0, 7.0]),
            &[-2.5, 0.0, 0.5, 7.0],
            1e-13,
        );
        assert_roots(
            from_roots(1.0, [-1.0, -2.0, 1.0, 2.0]),
            &[-2.0, -1.0, 1.0, 2.0],
            1e-14,
        );
        // Large shift: roots clustered far from 0 (the depression cancels; polish repairs it).
        assert_roots(
            from_roots(1.0, [1000.0, 1001.0, 1002.0, 1003.0]),
            &[1000.0, 1001.0, 1002.0, 1003.0],
            1e-11,
        );
    }

    #[test]
    fn double_roots() {
        // Double roots are ill-conditioned: error ~ √ε ≈ 1.5e-8, asserted at 1e-6.
        assert_roots(
            from_roots(1.0, [1.0, 1.0, 2.0, 3.0]),
            &[1.0, 1.0, 2.0, 3.0],
            1e-6,
        );
        assert_roots(
            from_roots(1.0, [-1.0, 0.5, 3.0, 3.0]),
            &[-1.0, 0.5, 3.0, 3.0],
            1e-6,
        );
        assert_roots(
            from_roots(2.0, [-4.0, 0.0, 0.0, 5.0]),
            &[-4.0, 0.0, 0.0, 5.0],
            1e-6,
        );
        // Two double pairs, symmetric (the tangent-on-top torus case, q = 0) and not.
        assert_roots(
            from_roots(1.0, [-1.0, -1.0, 1.0, 1.0]),
            &[-1.0, -1.0, 1.0, 1.0],
            1e-12,
        );
        assert_roots(
            from_roots(1.0, [-2.0, -2.0, 3.0, 3.0]),
            &[-2.0, -2.0, 3.0, 3.0],
            1e-6,
        );
        assert_roots(
            from_roots(1.0, [0.3, 0.3, 1.7, 1.7]),
            &[0.3, 0.3, 1.7, 1.7],
            1e-6,
        );
    }

    #[test]
    fn triple_and_quadruple_roots() {
        // Triple root: error ~ ε^(1/3) ≈ 6e-6; asserted at 1e-4. The cluster may come back
        // as one or three real roots (both are within rounding of the truth), but every
        // returned root must be close to a true one and the simple root must be there.
        for (rs, simple) in [([2.0, 2.0, 2.0, -1.0], -1.0), ([-1.0, 0.5, 0.5, 0.5], -1.0)] {
            let got = solve_quartic(from_roots(1.0, rs));
            let got = got.as_slice();
            assert!(got.len() == 2 || got.len() == 4, "{rs:?}: {got:?}");
            assert!(
                got.iter().any(|g| (g - simple).abs() < 1e-10),
                "{rs:?}: {got:?}"
            );
            for g in got {
                assert!(
                    rs.iter().any(|w| (g - w).abs() < 1e-4),
                    "{rs:?}: spurious {g} in {got:?}"
                );
            }
        }
        // Quadruple root: error ~ ε^(1/4) ≈ 1.2e-4; asserted at 1e-3.
        for a in [0.0, 1.0, -2.5] {
            let got = solve_quartic(from_roots(1.0, [a; 4]));
            let got = got.as_slice();
            assert!(!got.is_empty(), "quadruple {a}: no root");
            assert!(got.len() % 2 == 0, "quadruple {a}: {got:?}");
            for g in got {
                assert!((g - a).abs() < 1e-3, "quadruple {a}: {got:?}");
            }
        }
        // Exactly t⁴ = 0 and (t−1)⁴ come back as four roots.
        assert_roots([1.0, 0.0, 0.0, 0.0, 0.0], &[0.0; 4], 0.0);
        assert_eq!(solve_quartic(from_roots(1.0, [1.0; 4])).len(), 4);
    }

    #[test]
    fn complex_pairs() {
        // (t² + 1)(t − 1)(t − 3): two real roots.
        assert_roots(from_pair_and_roots(0.0, 1.0, 1.0, 3.0), &[1.0, 3.0], 1e-13);
        // (t² − 2t + 5)(t + 2)(t − 0.5): pair 1 ± 2i.
        assert_roots(
            from_pair_and_roots(-2.0, 5.0, -2.0, 0.5),
            &[-2.0, 0.5],
            1e-13,
        );
        // Two complex pairs: (t² + 1)(t² + 2t + 2): no real root.
        let c = [1.0, 2.0, 3.0, 2.0, 2.0];
        assert!(solve_quartic(c).is_empty(), "{:?}", solve_quartic(c));
        // t⁴ + 1 and t⁴ + t² + 1: none.
        assert!(solve_quartic([1.0, 0.0, 0.0, 0.0, 1.0]).is_empty());
        assert!(solve_quartic([1.0, 0.0, 1.0, 0.0, 1.0]).is_empty());
        // Near-tangent miss: (t² + 1e-6)(t − 2)(t − 5): the pair ±1e-3 i is far above rounding.
        assert_roots(from_pair_and_roots(0.0, 1e-6, 2.0, 5.0), &[2.0, 5.0], 1e-13);
        // Near-tangent hit: (t² − 1e-6)(t − 2)(t − 5): roots ±1e-3 stay real and distinct.
        assert_roots(
            from_pair_and_roots(0.0, -1e-6, 2.0, 5.0),
            &[-1e-3, 1e-3, 2.0, 5.0],
            1e-12,
        );
    }

    #[test]
    fn wide_dynamic_range_and_scaling() {
        // Roots over nine decades: each relative error ≤ 1e-12.
        let rs = [1e-6, 1e-2, 1e1, 1e3];
        let got = solve_quartic(from_roots(1.0, rs));
        assert_eq!(got.len(), 4, "{got:?}");
        for (g, w) in got.as_slice().iter().zip(rs) {
            assert!(((g - w) / w).abs() < 1e-12, "{got:?}");
        }
        // Scaling every root by 2^k and the leading coefficient by anything: same relative roots.
        for k in [-40, -10, 0, 10, 40] {
            let s = 2f64.powi(k);
            let rs = [-1.5 * s, 0.25 * s, 0.75 * s, 2.0 * s];
            let got = solve_quartic(from_roots(1e-7, rs));
            assert_eq!(got.len(), 4, "k = {k}: {got:?}");
            for (g, w) in got.as_slice().iter().zip(rs) {
                assert!(((g - w) / w).abs() < 1e-12, "k = {k}: {got:?}");
            }
        }
    }

    #[test]
    fn depressed_monic_matches_general() {
        // x⁴ − 5x² + 4 = (x² − 1)(x² − 4), and a q ≠ 0 case built from roots summing to 0.
        let r = solve_depressed_monic(-5.0, 0.0, 4.0);
        assert_eq!(r.as_slice(), &[-2.0, -1.0, 1.0, 2.0]);
        let c = from_roots(1.0, [-3.0, -0.5, 1.0, 2.5]);
        assert_eq!(c[1], 0.0);
        let r = solve_depressed_monic(c[2], c[3], c[4]);
        let want = [-3.0, -0.5, 1.0, 2.5];
        assert_eq!(r.len(), 4);
        for (g, w) in r.as_slice().iter().zip(want) {
            assert!((g - w).abs() < 1e-14, "{r:?}");
        }
        // Tangent pair of double roots with rounding-level q (a horizontal torus ray).
        let r = solve_depressed_monic(-2.0, 3e-16, 1.0);
        assert_eq!(r.len(), 4, "{r:?}");
        for (g, w) in r.as_slice().iter().zip([-1.0, -1.0, 1.0, 1.0]) {
            assert!((g - w).abs() < 1e-7, "{r:?}");
        }
    }

    #[test]
    fn bad_input_gives_no_roots() {
        assert!(solve_quartic([0.0, 1.0, 2.0, 3.0, 4.0]).is_empty());
        assert!(solve_quartic([1.0, f64::NAN, 0.0, 0.0, -1.0]).is_empty());
        assert!(solve_depressed_monic(f64::INFINITY, 0.0, 0.0).is_empty());
    }

    /// Condition-aware tolerance for a simple root w: ε·Σ|cᵢ wⁱ| / |f'(w)|.
    fn cond_tol(c: &[f64; 5], w: f64) -> f64 {
        let (_, df) = eval(c, w);
        let mag = c.iter().fold(0.0, |acc, ci| acc * w.abs() + ci.abs());
        EPS * mag / df.abs()
    }

    #[test]
    fn random_real_root_sets() {
        // 20 000 sets of four real roots in [−10, 10]: exactly four found, each within
        // 64·(ε·Σ|cᵢwⁱ|/|f'(w)|) + 1e-14 of the truth (the root's own condition number).
        let mut rng = Pcg64::seed_from_u64(0x7051_0001);
        let mut worst = 0.0f64;
        for _ in 0..20_000 {
            let rs = sorted([(); 4].map(|_| rng.random_range(-10.0..10.0)));
            let k = rng.random_range(0.1..10.0);
            let c = from_roots(k, rs);
            let got = solve_quartic(c);
            assert_eq!(got.len(), 4, "roots {rs:?}: got {got:?}");
            for (g, w) in got.as_slice().iter().zip(rs) {
                let tol = 64.0 * cond_tol(&c, w) + 1e-14;
                worst = worst.max((g - w).abs() / tol);
                assert!((g - w).abs() <= tol, "roots {rs:?}: got {got:?}, tol {tol}");
            }
        }
        assert!(worst <= 1.0);
    }

    #[test]
    fn random_sets_with_complex_pairs() {
        // Two real roots and a pair α ± iβ with β ≥ 0.05: exactly the two real roots,
        // and four complex roots: none.
        let mut rng = Pcg64::seed_from_u64(0x7051_0002);
        for _ in 0..10_000 {
            let x = rng.random_range(-10.0..10.0);
            let y = rng.random_range(-10.0..10.0);
            let (x, y) = if x < y { (x, y) } else { (y, x) };
            let alpha: f64 = rng.random_range(-10.0..10.0);
            let beta: f64 = rng.random_range(0.05..5.0);
            let c = from_pair_and_roots(-2.0 * alpha, alpha * alpha + beta * beta, x, y);
            let got = solve_quartic(c);
            assert_eq!(got.len(), 2, "{x} {y} {alpha}±{beta}i: {got:?}");
            for (g, w) in got.as_slice().iter().zip([x, y]) {
                let tol = 64.0 * cond_tol(&c, w) + 1e-14;
                assert!((g - w).abs() <= tol, "{x} {y} {alpha}±{beta}i: {got:?}");
            }
            // (t² − 2αt + α² + β²)(t² − 2γt + γ² + δ²): no real roots.
            let gamma: f64 = rng.random_range(-10.0..10.0);
            let delta: f64 = rng.random_range(0.05..5.0);
            let (b1, c1) = (-2.0 * alpha, alpha * alpha + beta * beta);
            let (b2, c2) = (-2.0 * gamma, gamma * gamma + delta * delta);
            let c = [1.0, b1 + b2, c1 + c2 + b1 * b2, b1 * c2 + b2 * c1, c1 * c2];
            assert!(solve_quartic(c).is_empty(), "{c:?}: {:?}", solve_quartic(c));
        }
    }

    #[test]
    fn random_double_roots_are_kept() {
        // (t − a)²(t − b)(t − c) with random a, b, c: the double root must not be lost.
        // A double root is √-conditioned: rounding the coefficients moves it by up to
        // √(2ε·Σ|cᵢaⁱ|/|f''(a)|); asserted within 8× that (+1e-12). Simple roots as above.
        let mut rng = Pcg64::seed_from_u64(0x7051_0003);
        for _ in 0..10_000 {
            let a = rng.random_range(-5.0..5.0);
            let b = rng.random_range(-5.0..5.0);
            let cc = rng.random_range(-5.0..5.0);
            let want = sorted([a, a, b, cc]);
            let c = from_roots(1.0, want);
            let got = solve_quartic(c);
            assert_eq!(got.len(), 4, "{want:?}: {got:?}");
            let mag = c.iter().fold(0.0, |acc, ci| acc * a.abs() + ci.abs());
            let d2 = 2.0 * ((a - b) * (a - cc)).abs();
            let tol_double = 8.0 * (2.0 * EPS * mag / d2).sqrt() + 1e-12;
            for (g, w) in got.as_slice().iter().zip(want) {
                let tol = if w == a {
                    tol_double
                } else {
                    64.0 * cond_tol(&c, w) + 1e-14
                };
                assert!((g - w).abs() <= tol, "{want:?}: {got:?}, tol {tol}");
            }
        }
    }
}
