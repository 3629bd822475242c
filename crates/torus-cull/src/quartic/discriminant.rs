//! The early exit of both depressed-form entry points: a quartic whose discriminant's
//! signs, beyond rounding, say it has no real root costs no resolvent.

use super::EPS;

/// Whether `x⁴ + p x² + q x + r` has no real root, by signs that rounding cannot flip.
///
/// Its discriminant `Δ = 16r(p² − 4r)² − q²(4p(p² − 36r) + 27q²) > 0` means four real
/// roots or none, and `p > 0` or `4r > p²` rules out four. Each sign must exceed the
/// rounding of its evaluation (bounded by the same expression on absolute values), so a
/// near-tangent quartic, whose complex pair rounding could make real, is left to the solver.
/// Half the lines of a uniform workload miss and end here, before the resolvent, in the
/// nearest-root query and the all-roots solve alike.
#[inline]
pub(super) fn surely_no_real_root(p: f64, q: f64, r: f64) -> bool {
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
