//! Ferrari's factorization of the depressed quartic into two real quadratics, and their roots.
//!
//! `x⁴ + p x² + q x + r = (x² + m x + n₁)(x² − m x + n₂)` with `z = m²` the greatest root of
//! the resolvent (see [`super::resolvent`]), `n₁ + n₂ = p + z`, `n₂ − n₁ = q/m` and
//! `n₁ n₂ = r`. (Skala's Eq. 17/18 print the sign of this split untied from `q`; here it is
//! tied through `n₂ − n₁ = q/m`.)
//!
//! A quadratic factor whose discriminant is within rounding of zero may hold a tangent
//! double root, or a complex pair that rounding made real: that is decided on the quartic
//! itself (the sign of its value at the nearby extremum), never on the factor.

use super::resolvent::{self, Root};
use super::{EPS, RealRoots, eval, eval2};
use crate::num::{Real, sc};

/// Below this `|disc| / (m² + 4|n|)` a factor's two roots are decided on the quartic, for a
/// quartic given in depressed form (a depression by the caller adds its own rounding:
/// see [`near_double_threshold`]).
pub(crate) const NEAR_DOUBLE: f64 = 1e-7;

/// Beyond this multiple of `ε·Σ|cᵢ||t|ⁱ`, the sign of `f(t)` computed by Horner is the
/// sign of the quartic's exact value at `t`: Horner's error bound is `γ₈·Σ|cᵢ||t|ⁱ`,
/// `γ₈ = 8u/(1 − 8u) ≈ 4ε` (degree 4, `u = ε/2`), doubled to cover the rounding of the
/// monic coefficients after a depression and of `Σ` itself. A near-double pair whose
/// extremum is beyond it on the real side is split ([`near_double_root`]).
pub(crate) const SIGN_SURE: f64 = 8.0;

/// Within this multiple of `ε·Σ|cᵢ||t|ⁱ` of zero, a near-double pair whose extremum says
/// complex is still taken as a double root: a tangent hit for a line that misses by
/// rounding, on the safe side for a renderer ([`near_double_root`]).
pub(crate) const TOUCH: f64 = 32.0;

/// The near-double threshold for a quartic depressed from `orig` by `t = x − shift`: the
/// depression rounds `p, q, r` by about `ε·Σ|cᵢ||shift|ⁱ`, which, next to the depressed
/// quartic's own size `X⁴` (`X² = max(|p|, √|r|, |q|^⅔)`), is the relative uncertainty of
/// every factor's discriminant.
pub(super) fn near_double_threshold(p: f64, q: f64, r: f64, orig: &[f64; 5], shift: f64) -> f64 {
    let m = orig
        .iter()
        .fold(0.0, |acc, ci| acc * shift.abs() + ci.abs());
    let x2 = p.abs().max(r.abs().sqrt()).max(q.abs().powf(2.0 / 3.0));
    let rel = 64.0 * EPS * m / (x2 * x2);
    // Written so that NaN (x2 = 0: x⁴ itself) keeps the default.
    if rel > NEAR_DOUBLE { rel } else { NEAR_DOUBLE }
}

/// The real roots (unsorted, not yet polished) of `x⁴ + p x² + q x + r`.
///
/// `orig` is the caller's quartic in `t = x − shift`: near-tangent decisions are made on it,
/// because a depression with a large shift adds rounding far above the depressed
/// quartic's own magnitudes; `near` is the relative discriminant below which that is done
/// ([`NEAR_DOUBLE`], or [`near_double_threshold`] after a depression).
#[inline]
pub(super) fn real_roots(
    p: f64,
    q: f64,
    r: f64,
    orig: &[f64; 5],
    shift: f64,
    near: f64,
) -> RealRoots {
    roots_of_split(&split(p, q, r), orig, shift, near)
}

/// The real roots (unsorted, not yet polished) of both factors of a [`split`]; `orig`,
/// `shift` and `near` as for [`real_roots`].
#[inline]
pub(super) fn roots_of_split(f: &Split<f64>, orig: &[f64; 5], shift: f64, near: f64) -> RealRoots {
    let (disc1, disc2) = (f.z - 4.0 * f.n1, f.z - 4.0 * f.n2);
    // Written so that NaN takes the general path, which decides on the quartic.
    let clear1 = disc1.abs() > near * (f.z + 4.0 * f.n1.abs());
    let clear2 = disc2.abs() > near * (f.z + 4.0 * f.n2.abs());
    if clear1 && clear2 {
        return clear_roots([f.m, -f.m], [f.n1, f.n2], [disc1, disc2]);
    }
    let mut out = RealRoots::default();
    quadratic_factor(f.m, f.n1, f.z, orig, shift, near, &mut out);
    quadratic_factor(-f.m, f.n2, f.z, orig, shift, near, &mut out);
    out
}

/// The two factors `x² + m x + n₁` and `x² − m x + n₂`, with `z = m²`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Split<R> {
    pub z: R,
    pub m: R,
    pub n1: R,
    pub n2: R,
}

/// Ferrari's split of `x⁴ + p x² + q x + r` (see the module docs).
#[inline]
pub(super) fn split(p: f64, q: f64, r: f64) -> Split<f64> {
    let root = resolvent::greatest_root(p, q, r);
    let f = split_at(sc(p), sc(q), sc(r), &root);
    Split {
        z: f.z.v,
        m: f.m.v,
        n1: f.n1.v,
        n2: f.n2.v,
    }
}

/// Ferrari's split of `x⁴ + p x² + q x + r` at the resolvent's greatest root `root`: the
/// step the scalar [`split`] and the lane solver share.
#[inline(always)]
pub(crate) fn split_at<R: Real>(p: R, q: R, r: R, root: &Root<R>) -> Split<R> {
    let (z, dh, m) = (root.z, root.dh, root.m);
    let s = p + root.z_early;
    let w2 = s * s - p.k(4.0) * r;

    // n₂ − n₁ is both q/m and sign(q)·√((p + z)² − 4r). The first inherits half the
    // relative error of z, ε·Σ|terms of h|/(z·h'(z)), large at a double root of the
    // resolvent; the second cancels when (p + z)² ≈ 4r, with relative error
    // ε·((p + z)² + 4|r|)/(2w²) plus what the error of z adds to p + z. Take whichever is
    // better determined (compared without dividing: both denominators are > 0 when used).
    let b_abs = p * p + p.k(4.0) * r.abs();
    let z_early = root.z_early;
    let h_mag = ((z_early + p.k(2.0) * p.abs()) * z_early + b_abs) * z_early + q * q;
    let zdh = z * dh;
    // rel(q/m) = ½·ε·h_mag/zdh ≤ rel(√w²) = ½·err_w/w2, with err_w = ε·(s² + 4|r|) plus
    // 2|s|·(ε|p| + ε·h_mag/dh), multiplied out so that no division is needed.
    let eps = p.k(EPS);
    let err_w_zdh = eps
        * ((s * s + p.k(4.0) * r.abs() + p.k(2.0) * s.abs() * p.abs()) * zdh
            + p.k(2.0) * s.abs() * h_mag * z);
    let zero = p.k(0.0);
    let use_q_over_m =
        root.q_over_m_exact | (zdh.gt(zero) & (w2.le(zero) | (eps * h_mag * w2).le(err_w_zdh)));
    // Both candidates are computed and one is selected: which one wins is a coin toss from
    // ray to ray, and a mispredicted branch costs more than a division and a root.
    let by_q = root.q_over_m;
    let by_w = w2.max(zero).sqrt().copysign(q);
    let d = R::select(use_q_over_m, by_q, by_w);

    // n₁ n₂ = r: compute the larger-magnitude constant directly and the other as r over it,
    // which avoids the cancellation in (p + z ∓ d)/2 (again selected, not branched).
    let (n1_direct, n2_direct) = (p.k(0.5) * (s - d), p.k(0.5) * (s + d));
    let n2_bigger = n2_direct.abs().ge(n1_direct.abs());
    let big = R::select(n2_bigger, n2_direct, n1_direct);
    let r_over_big = if R::LANES == 1 {
        // Both quotients start before the comparison is known (a division is long, and
        // one lane is latency-bound); the same bits as `r / big`.
        R::select(n2_bigger, r / n2_direct, r / n1_direct)
    } else {
        // Lanes are bound by the divider's throughput: one division.
        r / big
    };
    let other = R::select(big.eq(zero), zero, r_over_big);
    let n1 = R::select(n2_bigger, other, n1_direct);
    let n2 = R::select(n2_bigger, n2_direct, other);
    Split { z, m, n1, n2 }
}

/// The roots of both factors `x² + bₖ x + cₖ` when both discriminants are clear of
/// rounding (the common case): each factor's stable pair `t = −(b + sign(b)·√disc)/2` and
/// `c/t`, as [`quadratic_factor`] gives them, computed for both factors and kept where
/// `disc > 0`, without a branch (which factors are real is a coin toss from ray to ray).
#[inline]
fn clear_roots(b: [f64; 2], c: [f64; 2], disc: [f64; 2]) -> RealRoots {
    let mut out = RealRoots::default();
    let mut len = 0;
    for k in 0..2 {
        let t = -0.5 * (b[k] + disc[k].max(0.0).sqrt().copysign(b[k]));
        let real = disc[k] > 0.0;
        // Slots `len` and `len + 1` exist: at most one factor was kept before.
        out.roots[len] = if real { t } else { 0.0 };
        out.roots[len + 1] = if real { c[k] / t } else { 0.0 };
        len += 2 * usize::from(real);
    }
    out.len = len;
    out
}

/// Roots of the factor `x² + b x + c` with `b² = z` (passed exactly, so the discriminant
/// does not pay for rounding `m²`).
#[inline]
fn quadratic_factor(
    b: f64,
    c: f64,
    z: f64,
    orig: &[f64; 5],
    shift: f64,
    near: f64,
    out: &mut RealRoots,
) {
    let disc = z - 4.0 * c;
    let scale = z + 4.0 * c.abs();
    // Written so that NaN takes the cold path, which decides on the quartic.
    let clear = disc.abs() > near * scale;
    if clear {
        if disc > 0.0 {
            let t = -0.5 * (b + disc.sqrt().copysign(b));
            out.push(t);
            out.push(c / t);
        }
    } else {
        near_double_root(-0.5 * b, disc.abs().sqrt(), orig, shift, out);
    }
}

/// A near-double pair of roots around `x0`: find the quartic's extremum `t*` near it
/// (Newton on `f'`, within `spread` plus how far the rounding of `f` itself can move a
/// double root, `√(8ε·Σ|cᵢtⁱ|/|f''|)`, which covers the depression's rounding when the
/// shift is large), and decide on `f(t*)`. A local minimum below zero (or a local
/// maximum above zero: a line touching the tube from inside) by more than the
/// evaluation's rounding ([`SIGN_SURE`]) holds two real roots `t* ± √(−2f/f'')`, each
/// then refined by Newton on `f` on its own side. `f(t*)` within that of zero is a double
/// root, and so is a pair of the other sign within [`TOUCH`]'s wider bound (a line that
/// misses by a hair is counted a tangent hit); beyond that the pair is complex. Cold:
/// only tangent and near-tangent lines come here.
#[cold]
fn near_double_root(x0: f64, spread: f64, orig: &[f64; 5], shift: f64, out: &mut RealRoots) {
    let t0 = x0 - shift;
    let mag0 = orig.iter().fold(0.0, |acc, ci| acc * t0.abs() + ci.abs());
    let (_, _, d2_0) = eval2(orig, t0);
    let halfwidth = spread + 4.0 * (8.0 * EPS * mag0 / d2_0.abs()).sqrt();
    let mut t = t0;
    for _ in 0..4 {
        let (_, d1, d2) = eval2(orig, t);
        if d2 == 0.0 {
            break;
        }
        let tn = t - d1 / d2;
        // Written so that NaN also fails the test.
        let ok = (tn - t0).abs() <= halfwidth;
        if !ok {
            break;
        }
        let step = (tn - t).abs();
        t = tn;
        // Converged (quadratically): a further step would move t by rounding only.
        if step <= 4.0 * EPS * t.abs() {
            break;
        }
    }
    let (f, _, d2) = eval2(orig, t);
    let mag = orig.iter().fold(0.0, |acc, ci| acc * t.abs() + ci.abs());
    let real = f * d2 < 0.0;
    if !(real || f.abs() <= TOUCH * EPS * mag) {
        return;
    }
    // The sign of f(t*) says real wherever it is beyond the evaluation's rounding. Until
    // issue 36 a real pair within TOUCH's bound was also made double: the roots
    // 192 889.337 and 192 889.364 of x⁴ − 5.9·10¹⁰x² − 5.8·10¹⁵x + 1.9·10²¹ (f(t*) =
    // 20ε·Σ|cᵢtⁱ|, and the same at any scale) came back as one double root between them.
    let delta = if real && f.abs() > SIGN_SURE * EPS * mag {
        (-2.0 * f / d2).sqrt()
    } else {
        0.0
    };
    if delta == 0.0 {
        out.push(t + shift);
        out.push(t + shift);
        return;
    }
    // The parabola's roots are only approximate (the cubic term); Newton on f converges from
    // them, and is kept on its own side of t* so the two roots cannot merge. Both sides
    // step together, so that their independent chains overlap.
    let sides = [-1.0, 1.0];
    let mut xs = sides.map(|side| t + side * delta);
    let mut active = [true; 2];
    for _ in 0..3 {
        for ((x, live), side) in xs.iter_mut().zip(&mut active).zip(sides) {
            if !*live {
                continue;
            }
            let (fx, dfx) = eval(orig, *x);
            let xn = *x - fx / dfx;
            // Written so that NaN (and f = 0 or f' = 0) also fails the test.
            let ok = fx != 0.0 && (xn - t) * side > 0.0 && (xn - t).abs() <= 4.0 * delta;
            if !ok {
                *live = false;
                continue;
            }
            let step = (xn - *x).abs();
            *x = xn;
            // Converged: a further step would move x by rounding only.
            *live = step > 4.0 * EPS * x.abs();
        }
    }
    for x in xs {
        out.push(x + shift);
    }
}
