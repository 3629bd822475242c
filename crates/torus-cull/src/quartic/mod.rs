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
//! - the all-roots solve gives each root one Newton step on the caller's polynomial, taken
//!   at once where it is small next to the roots' separation (a well-conditioned root),
//!   and checked (within half the gap, lowering |f|) everywhere else;
//! - an even quartic (`q = 0`, a line perpendicular or parallel to the axis) is solved as
//!   a quadratic in `x²` (`even.rs`), where every tangent is decided by an exact sign;
//! - the nearest-root query and the depressed all-roots solve first reject a quartic whose
//!   discriminant's signs, beyond rounding, say it has no real root (`discriminant.rs`):
//!   a missed line costs no resolvent.
//!
//! Two entry points: [`nearest_root_depressed`], the nearest root in an interval, which is
//! all a renderer needs (no sort, no final Newton step); and the all-roots [`solve_depressed_monic`]
//! / [`solve_quartic`] for CSG and the tests.
//!
//! Files: `nearest.rs` and `all_roots.rs` (the entry points), `discriminant.rs` (the
//! early exit), `even.rs` (`q = 0`),
//! `resolvent.rs` (the cubic in `m²`), `cube_root.rs` (its cube root and trisection without
//! libm), `factor.rs` (Ferrari's split and near-double factors), `pieces.rs` (every real
//! root by monotone pieces: `solve_quartic`'s path where the depression cannot be
//! trusted), `roots.rs` ([`RealRoots`]); `corpus/` (tests: the published quartic corpus,
//! its reference roots derived exactly by `corpus/cases.py`).
//!
//! References: L. Ferrari's method as in Abramowitz & Stegun 3.8.3; the resolvent in `m²`
//! is Descartes'. Peers measured in the bench: the `roots` crate (Ferrari) and
//! `kurbo::common::solve_quartic` (Orellana & De Michele, ACM TOMS 46(2), 2020, Alg. 1010).

mod all_roots;
#[cfg(test)]
mod corpus;
mod discriminant;
mod even;
pub(crate) mod factor;
pub(crate) mod lanes;
pub(crate) mod nearest;
mod pick;
mod pieces;
pub(crate) mod resolvent;
mod roots;
mod scales;
#[cfg(test)]
mod tests;
pub(crate) mod trisect;

pub use all_roots::{solve_depressed_monic, solve_quartic};
pub use nearest::nearest_root_depressed;
pub(crate) use nearest::nearest_root_in_range;

pub use roots::RealRoots;

pub(crate) const EPS: f64 = f64::EPSILON;

/// For `x⁴ + p x² + q x + r` with a coefficient beyond 2^±100 in magnitude (where the
/// resolvent's squares and cubes would overflow or underflow), the power of two s such
/// that `y = x/s` has O(1) roots: solve `y⁴ + (p/s²) y² + (q/s³) y + r/s⁴` and multiply
/// the roots by s (exact). `None` in the range every caller of this crate produces, which
/// is left untouched, bit for bit.
#[inline]
pub(crate) fn out_of_range_scale(p: f64, q: f64, r: f64) -> Option<f64> {
    const LOW: f64 = 7.888_609_052_210_118e-31; // 2⁻¹⁰⁰
    const HIGH: f64 = 1.267_650_600_228_229_4e30; // 2¹⁰⁰
    let big = p.abs().max(q.abs()).max(r.abs());
    if (LOW..=HIGH).contains(&big) || big == 0.0 || !big.is_finite() {
        return None;
    }
    let m = p
        .abs()
        .sqrt()
        .max(q.abs().cbrt())
        .max(r.abs().sqrt().sqrt());
    Some(2f64.powi(m.log2().round() as i32))
}

/// `x·2^n` in steps of at most 2^±1000 toward the result: exact unless the result is
/// subnormal or overflows, since every step lies between `x` and the result.
pub(super) fn times_pow2(mut x: f64, mut n: i32) -> f64 {
    while n != 0 && x != 0.0 && x.is_finite() {
        let step = n.clamp(-1000, 1000);
        x *= f64::from_bits(((step + 1023) as u64) << 52);
        n -= step;
    }
    x
}

/// `(p/s², q/s³, r/s⁴)`, each a product of exact power-of-two steps (s⁴ alone may
/// overflow).
#[inline]
pub(crate) fn scaled(p: f64, q: f64, r: f64, s: f64) -> (f64, f64, f64) {
    let inv = 1.0 / s;
    (
        p * inv * inv,
        q * inv * inv * inv,
        r * inv * inv * inv * inv,
    )
}

/// `f(t)`, `f'(t)` and `f''(t)` for `c = [c4, c3, c2, c1, c0]`, Horner.
#[inline]
pub(super) fn eval2(c: &[f64; 5], x: f64) -> (f64, f64, f64) {
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

/// `f(x)` and `f'(x)` for the coefficients `c`, highest degree first (`[c4, c3, c2, c1,
/// c0]` for a quartic), Horner.
#[inline]
pub(crate) fn eval(c: &[f64], x: f64) -> (f64, f64) {
    let mut f = c[0];
    let mut df = 0.0;
    for &ci in &c[1..] {
        df = df * x + f;
        f = f * x + ci;
    }
    (f, df)
}
