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
//! early exit), `even.rs` (`q = 0`; `exact_sign.rs`, tests: its tangent sign without an fma, as the GPU
//! computes it),
//! `resolvent.rs` (the cubic in `m²`), `cube_root.rs` (its cube root and trisection without
//! libm), `factor.rs` (Ferrari's split and near-double factors), `pieces.rs` (every real
//! root by monotone pieces: `solve_quartic`'s path where the depression cannot be
//! trusted), `first_root.rs` ([`first_root_depressed`]: the same question as
//! [`nearest_root_depressed`] answered by a bracketed walk over convexity pieces, issue
//! 61; measured slower on uniform lines, so not on the intersect path), `roots.rs`
//! ([`RealRoots`]); `corpus/` (tests: the published quartic corpus,
//! its reference roots derived exactly by `corpus/cases.py`); `close_pairs.rs` (tests: a
//! grid of close pairs of large roots, issue 36).
//!
//! References: L. Ferrari's method as in Abramowitz & Stegun 3.8.3; the resolvent in `m²`
//! is Descartes'. Peers measured in the bench: the `roots` crate (Ferrari) and
//! `kurbo::common::solve_quartic` (Orellana & De Michele, ACM TOMS 46(2), 2020, Alg. 1010).

mod all_roots;
#[cfg(test)]
mod close_pairs;
#[cfg(test)]
mod corpus;
mod discriminant;
mod even;
mod first_root;
// The fma-free sign of p² − 4r that the GPU's f64 pass computes, proved here (tests only:
// the CPU's own even quartic uses a fused multiply-add).
#[cfg(test)]
mod exact_sign;
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
pub use first_root::first_root_depressed;
pub use nearest::nearest_root_depressed;
pub(crate) use nearest::nearest_root_in_range;

pub use roots::RealRoots;

pub(crate) const EPS: f64 = f64::EPSILON;

/// Whether `x⁴ + p x² + q x + r` leaves the range where Ferrari's split is computed
/// without overflow or underflow: a coefficient beyond 2^±100 in magnitude (where the
/// resolvent's squares and cubes leave f64), or a nonzero one below 2⁻³⁰⁰ (where `q²`
/// and the resolvent's products underflow, and roots near `√(r/p)` beside roots near
/// `√|p|` span more than its digits). Such a quartic is solved by
/// [`scales::real_roots`](self::scales::real_roots). The range every caller of this
/// crate produces is left untouched, bit for bit.
#[inline]
pub(crate) fn out_of_range(p: f64, q: f64, r: f64) -> bool {
    const LOW: f64 = 7.888_609_052_210_118e-31; // 2⁻¹⁰⁰
    const HIGH: f64 = 1.267_650_600_228_229_4e30; // 2¹⁰⁰
    const TINY: f64 = 4.909_093_465_297_727e-91; // 2⁻³⁰⁰
    let big = p.abs().max(q.abs()).max(r.abs());
    let tiny = |x: f64| x != 0.0 && x.abs() < TINY;
    if big == 0.0 || !big.is_finite() {
        return false;
    }
    !(LOW..=HIGH).contains(&big) || tiny(p) || tiny(q) || tiny(r)
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
