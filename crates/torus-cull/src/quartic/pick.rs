//! The nearest-root pick's one test: is a candidate a real root inside the ray's range?

use crate::num::{Real, RealMask, sc, sc_mask};

/// `x` if it is a real root (`real`) in `[lo, hi]`, else ∞: a candidate for the nearest
/// root, selected rather than branched on, since which roots qualify is a coin toss from
/// ray to ray.
#[inline(always)]
pub(crate) fn in_range<R: Real>(x: R, real: R::Mask, lo: R, hi: R) -> R {
    let inf = x.k(f64::INFINITY);
    if R::LANES == 1 {
        // The same value as the select below, short-circuited: at one lane three plain
        // `bool` tests that stop at the first false one, instead of three masks combined
        // and a select.
        if real.any() && x.ge(lo).any() && x.le(hi).any() {
            x
        } else {
            inf
        }
    } else {
        R::select(real & x.ge(lo) & x.le(hi), x, inf)
    }
}

/// [`in_range`] for one `f64`.
#[inline(always)]
pub(crate) fn in_range_f64(x: f64, real: bool, lo: f64, hi: f64) -> f64 {
    in_range(sc(x), sc_mask(real), sc(lo), sc(hi)).v
}
