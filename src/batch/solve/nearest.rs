//! Ferrari's split and the nearest root in range, over f64 lanes: the scalar
//! [`crate::quartic::nearest_root_depressed`]'s common ("clear") path, lane for lane.

use super::resolvent::greatest_root;
use crate::batch::lanes::{F64s, M64s};
use crate::quartic::NEAR_DOUBLE;
use pulp::Simd;

/// The nearest root of x⁴ + p x² + q x + r in [lo, hi] (NaN for none), and the lanes the
/// scalar solver must decide instead.
///
/// The quartic splits as (x² + m x + n₁)(x² − m x + n₂) with z = m² the resolvent's
/// greatest root; n₂ − n₁ is q/m or ±√((p + z)² − 4r), whichever is better conditioned,
/// and the smaller of n₁, n₂ is r over the larger (all selected, as in the scalar code).
/// Each factor's roots come from the stable quadratic formula; the nearest in range
/// gets one guarded Newton step on the quartic (kept only if it lowers |f|, stays in
/// range and moves less than half-way to its factor's other root).
///
/// Fallback lanes: the resolvent's (see [`greatest_root`]), and a factor whose
/// discriminant is within 10⁻⁷ of zero relative to its size: a tangent or near-tangent
/// line, decided by the scalar solver on the quartic itself.
#[inline(always)]
pub(crate) fn nearest_root<S: Simd>(
    p: F64s<S>,
    q: F64s<S>,
    r: F64s<S>,
    lo: F64s<S>,
    hi: F64s<S>,
) -> (F64s<S>, M64s<S>) {
    let s = p.s;
    // Macros and functions, not closures: a closure that LLVM leaves outlined would run
    // without the SIMD target features and call every intrinsic out of line.
    macro_rules! c_ {
        ($x:expr) => {
            F64s::splat(s, $x)
        };
    }
    let (z, dh, resolvent_fallback) = greatest_root(p, q, r);

    // The split (the scalar `factor::split`).
    let eps = c_!(f64::EPSILON);
    let m = z.sqrt();
    let sum = p + z;
    let w2 = sum * sum - c_!(4.0) * r;
    let b_abs = p * p + c_!(4.0) * r.abs();
    let h_mag = ((z + c_!(2.0) * p.abs()) * z + b_abs) * z + q * q;
    let zdh = z * dh;
    let err_w_zdh = eps
        * ((sum * sum + c_!(4.0) * r.abs() + c_!(2.0) * sum.abs() * p.abs()) * zdh
            + c_!(2.0) * sum.abs() * h_mag * z);
    let use_q_over_m = zdh.gt(c_!(0.0)) & (w2.le(c_!(0.0)) | (eps * h_mag * w2).le(err_w_zdh));
    let by_q = q / m;
    let by_w = w2.max_num(c_!(0.0)).sqrt().copysign(q);
    let d = use_q_over_m.select(by_q, by_w);
    let n1_direct = c_!(0.5) * (sum - d);
    let n2_direct = c_!(0.5) * (sum + d);
    let n2_bigger = n2_direct.abs().ge(n1_direct.abs());
    let big = n2_bigger.select(n2_direct, n1_direct);
    let other = big.eq(c_!(0.0)).select(c_!(0.0), r / big);
    let n1 = n2_bigger.select(other, n1_direct);
    let n2 = n2_bigger.select(n2_direct, other);

    // Both factors clearly two real roots or none.
    let disc1 = z - c_!(4.0) * n1;
    let disc2 = z - c_!(4.0) * n2;
    let near = c_!(NEAR_DOUBLE);
    let clear = disc1.abs().gt(near * (z + c_!(4.0) * n1.abs()))
        & disc2.abs().gt(near * (z + c_!(4.0) * n2.abs()));
    let (a1, b1) = quadratic_roots(m, n1, disc1);
    let (a2, b2) = quadratic_roots(-m, n2, disc2);
    let inf = c_!(f64::INFINITY);
    macro_rules! pick {
        ($x:expr, $ok:expr) => {
            ($ok & $x.ge(lo) & $x.le(hi)).select($x, inf)
        };
    }
    let (ok1, ok2) = (disc1.gt(c_!(0.0)), disc2.gt(c_!(0.0)));
    let (a1, b1, a2, b2) = (
        pick!(a1, ok1),
        pick!(b1, ok1),
        pick!(a2, ok2),
        pick!(b2, ok2),
    );
    let (x1, y1) = (a1.min_num(b1), a1.max_num(b1));
    let (x2, y2) = (a2.min_num(b2), a2.max_num(b2));
    let first = x1.le(x2);
    let best = first.select(x1, x2);
    let partner = first.select(y1, y2);

    // One guarded Newton step on f = x⁴ + p x² + q x + r.
    let lim = c_!(0.5) * (partner - best).abs();
    let (fx, dfx) = eval(p, q, r, best);
    let xn = best - fx / dfx;
    let ok =
        (xn - best).abs().le(lim) & xn.ge(lo) & xn.le(hi) & eval(p, q, r, xn).0.abs().lt(fx.abs());
    let root = ok.select(xn, best);
    let root = best.eq(inf).select(c_!(f64::NAN), root);
    let bad_input = !(p.is_finite() & q.is_finite() & r.is_finite());
    (root, resolvent_fallback | !clear | bad_input)
}

/// The roots of x² + b x + c with discriminant `disc > 0`, in the stable form (garbage,
/// never used, when `disc ≤ 0`): the scalar `quadratic_roots`.
#[inline(always)]
fn quadratic_roots<S: Simd>(b: F64s<S>, c: F64s<S>, disc: F64s<S>) -> (F64s<S>, F64s<S>) {
    let s = b.s;
    let zero = F64s::splat(s, 0.0);
    let t = F64s::splat(s, -0.5) * (b + disc.max_num(zero).sqrt().copysign(b));
    (t, c / t)
}

/// f(x) and f′(x) of x⁴ + p x² + q x + r by Horner, as the scalar `eval` on
/// `[1, 0, p, q, r]`.
#[inline(always)]
fn eval<S: Simd>(p: F64s<S>, q: F64s<S>, r: F64s<S>, x: F64s<S>) -> (F64s<S>, F64s<S>) {
    let s = x.s;
    let mut f = F64s::splat(s, 1.0);
    let mut df = F64s::splat(s, 0.0);
    for ci in [F64s::splat(s, 0.0), p, q, r] {
        df = df * x + f;
        f = f * x + ci;
    }
    (f, df)
}
