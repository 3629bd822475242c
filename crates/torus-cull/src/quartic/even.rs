//! The even quartic `x⁴ + p x² + r` (`q = 0`): a quadratic in `y = x²`.
//!
//! A torus quartic is even whenever the line's closest approach to the axis is also the
//! midpoint of its crossings: every line in a plane perpendicular to the axis, and every
//! line parallel to it. In torus-local coordinates that is every horizontal ray of an
//! upright torus, so a level camera produces whole scanlines of them, and a quarter to all
//! of the tangent lines in the solver suite are exactly even.
//!
//! There the resolvent is wasted work and, worse, ill-conditioned: a line tangent at its
//! foot point has a double root `x = 0` that makes the resolvent's top root near-double
//! too. In `y` it is neither. The quadratic `y² + p y + r` has the stable roots
//! `y₁ = −(p + sign(p)·√(p² − 4r))/2` and `y₂ = r/y₁`, each to a few ulps, and `x = ±√y`
//! for each `y ≥ 0`. A tangent at the foot point is `y₂ ≈ 0`, and whether its two roots are
//! real is the sign of `y₂ = r/y₁`: exact, given the coefficients, with no rounding to
//! decide on. A double `y` (`p² ≈ 4r`: a line tangent at two points symmetric about its foot
//! point, such as any line in the plane of the top circle that touches it) is decided by the
//! sign of `p² − 4r`, which a fused multiply-add makes exact too.

use super::pick::in_range_f64;
use super::{RealRoots, factor::NEAR_DOUBLE};

/// The roots `y₁, y₂` of `y² + p y + r`, `Some(None)` when they are complex (no real
/// `x`), or `None` for non-finite input (left to the general solver, which rejects it).
#[inline]
fn y_roots(p: f64, r: f64) -> Option<Option<(f64, f64)>> {
    let mut disc = p * p - 4.0 * r;
    let scale = p * p + 4.0 * r.abs();
    if !scale.is_finite() {
        return None;
    }
    // Finite from here on; a zero scale (x⁴) also comes in.
    if disc.abs() <= NEAR_DOUBLE * scale {
        // A near-double y: whether it is real is the sign of p² − 4r, which rounding could
        // flip. Fused, it is rounded once, so its sign is exact and its value good to an ulp.
        disc = p.mul_add(p, -4.0 * r);
    }
    if disc < 0.0 {
        return Some(None);
    }
    // |y₁| ≥ |p|/2 and ≥ √disc/2: it is 0 only for x⁴, whose roots are all 0.
    let y1 = -0.5 * (p + disc.sqrt().copysign(p));
    let y2 = if y1 == 0.0 { 0.0 } else { r / y1 };
    Some(Some((y1, y2)))
}

/// The nearest real root of `x⁴ + p x² + r` in `[lo, hi]`, ∞ when there is none in range,
/// or `None` for non-finite input.
#[inline]
pub(super) fn nearest_root(p: f64, r: f64, lo: f64, hi: f64) -> Option<f64> {
    let Some((y1, y2)) = y_roots(p, r)? else {
        return Some(f64::INFINITY);
    };
    // Each y ≥ 0 gives ±√y (y = 0: the double root 0).
    let pick = |x: f64, real: bool| in_range_f64(x, real, lo, hi);
    let (x1, x2) = (y1.max(0.0).sqrt(), y2.max(0.0).sqrt());
    let (real1, real2) = (y1 >= 0.0, y2 >= 0.0);
    let best = pick(-x1, real1)
        .min(pick(x1, real1))
        .min(pick(-x2, real2))
        .min(pick(x2, real2));
    Some(best)
}

/// Every real root of `x⁴ + p x² + r`, unsorted and unpolished (a double root twice), or
/// `None` for non-finite input.
#[inline]
pub(super) fn real_roots(p: f64, r: f64) -> Option<RealRoots> {
    let mut out = RealRoots::default();
    if let Some((y1, y2)) = y_roots(p, r)? {
        for y in [y1, y2] {
            if y >= 0.0 {
                let x = y.sqrt();
                out.push(-x);
                out.push(x);
            }
        }
    }
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn two_real_y_give_four_roots() {
        // (x² − 1)(x² − 4) = x⁴ − 5x² + 4.
        let mut roots = real_roots(-5.0, 4.0).unwrap();
        roots.sort();
        assert_eq!(roots.as_slice(), &[-2.0, -1.0, 1.0, 2.0]);
        assert_eq!(nearest_root(-5.0, 4.0, -1.5, 9.0), Some(-1.0));
        assert_eq!(nearest_root(-5.0, 4.0, 2.5, 9.0), Some(f64::INFINITY));
    }

    #[test]
    fn the_sign_of_a_tiny_y_decides_a_foot_point_tangent() {
        // x⁴ − 2x² + r with r = ±1e-30: y₁ = 2 and y₂ = r/2, so the pair around 0 is
        // real exactly when r > 0.
        let (p, tiny) = (-2.0, 1e-30);
        let below = real_roots(p, tiny).unwrap();
        assert_eq!(below.len(), 4, "y₂ = r/y₁ > 0: a pair ±√(r/2) around 0");
        let x = (tiny / 2.0).sqrt();
        let mut sorted = below;
        sorted.sort();
        assert!((sorted.as_slice()[2] - x).abs() <= 1e-15 * x);
        let above = real_roots(p, -tiny).unwrap();
        assert_eq!(above.len(), 2, "y₂ < 0: only ±√2");
        // Nearest from the far left is −√2 either way; from 0 it is the tiny root or √2.
        assert_eq!(nearest_root(p, tiny, 0.0, 9.0), Some(x));
        assert_eq!(nearest_root(p, -tiny, 0.0, 9.0), Some(2f64.sqrt()));
    }

    #[test]
    fn complex_y_means_no_root() {
        // y² + y + 1: no real y.
        assert_eq!(real_roots(1.0, 1.0), Some(RealRoots::default()));
        assert_eq!(
            nearest_root(1.0, 1.0, f64::NEG_INFINITY, f64::INFINITY),
            Some(f64::INFINITY)
        );
    }

    #[test]
    fn a_double_y_is_decided_by_the_exact_sign_of_p2_minus_4r() {
        // (x² − 1)² = x⁴ − 2x² + 1: y = 1 double, so x = ±1 twice each.
        let mut roots = real_roots(-2.0, 1.0).unwrap();
        roots.sort();
        assert_eq!(roots.as_slice(), &[-1.0, -1.0, 1.0, 1.0]);
        // r = 1 + 2⁻⁴⁰ is above the double root: no real root.
        let tiny = 2f64.powi(-40);
        assert_eq!(real_roots(-2.0, 1.0 + tiny), Some(RealRoots::default()));
        assert_eq!(
            nearest_root(-2.0, 1.0 + tiny, 0.0, 9.0),
            Some(f64::INFINITY)
        );
        // p = −2(1 + 2⁻³⁰), r = 1 + 2⁻²⁹: p² = 4r + 2⁻⁵⁸ rounds to 4r, so unfused the y's
        // would merge into a double 1 + 2⁻³⁰. Fused, they are 1 + 2⁻²⁹ and exactly 1.
        let (p, r) = (-2.0 * (1.0 + 2f64.powi(-30)), 1.0 + 2f64.powi(-29));
        assert_eq!(p * p - 4.0 * r, 0.0, "the test needs a rounded p²");
        let mut roots = real_roots(p, r).unwrap();
        roots.sort();
        let big = (1.0 + 2f64.powi(-29)).sqrt();
        assert_eq!(roots.as_slice(), &[-big, -1.0, 1.0, big]);
        assert_eq!(nearest_root(p, r, 0.0, 9.0), Some(1.0));
        // x⁴: the quadruple root 0.
        assert_eq!(
            real_roots(0.0, 0.0).unwrap().as_slice(),
            &[-0.0, 0.0, -0.0, 0.0]
        );
    }

    #[test]
    fn non_finite_input_is_left_to_the_general_solver() {
        assert_eq!(real_roots(f64::NAN, 1.0), None);
        assert_eq!(nearest_root(-2.0, f64::INFINITY, 0.0, 9.0), None);
        assert_eq!(nearest_root(1e200, 1.0, 0.0, 9.0), None);
    }
}
