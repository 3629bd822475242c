//! The scale steps every cull shares ([`foot_point`], [`rescaled`], [`moderate`]), written
//! once over [`crate::num::Real`]: at width 1 they are the scalar steps.

use crate::num::{Real, Real32, RealMask, V3};

/// Below this squared horizontal direction fraction (|h|/|d| < 1e-6) a line is treated as
/// parallel to the axis: within the bounding sphere its distance from the axis changes by
/// less than 2e-6·(R + r), far inside η.
pub(crate) const AXIS_PARALLEL_H2: f32 = 1e-12;

/// The foot point p = o − d (o·d)/|d|² of the line (its point closest to the torus
/// centre) and 1/|d|². Shared first step of the sphere-based culls: it removes the
/// far-origin cancellation from every later formula, for one division and no root.
#[inline(always)]
pub fn foot_point<R: Real>(origin: V3<R>, dir: V3<R>) -> (V3<R>, R) {
    let inv_len_sq = origin.x.k(1.0) / dir.length_squared();
    (origin - dir * (origin.dot(dir) * inv_len_sq), inv_len_sq)
}

/// `v` times a power of two that brings its largest component into [1, 2): exact (no
/// rounding), so scale-free formulas give bit-identical answers, and their fourth powers of
/// a direction stay inside f32's range however the ray is parametrized.
///
/// A valid ray's |d|² is a finite normal f32, so the largest component's biased exponent
/// e is in 1..=191 and the factor 2^(127 − e) is a normal f32.
#[inline(always)]
pub(crate) fn rescaled<R: Real32>(v: V3<R>) -> V3<R> {
    let largest = v.abs().max_element();
    V3::new(
        v.x.times_inverse_exponent(largest),
        v.y.times_inverse_exponent(largest),
        v.z.times_inverse_exponent(largest),
    )
}

/// 2⁻⁴⁰ and 2⁴⁰: the range of |v|² that [`moderate`] leaves alone.
pub(crate) const MODERATE_LOW: f32 = 9.094_947e-13;
pub(crate) const MODERATE_HIGH: f32 = 1.099_511_6e12;

/// `v` itself when |v|² lies in (2⁻⁴⁰, 2⁴⁰), else [`rescaled`]: either way fourth powers
/// of `v`, and |o|²·|v|² for origins within 10¹³, stay inside f32's normal range.
///
/// When every lane is in range (a renderer's rays nearly always are) `v` is returned
/// before `rescaled` runs: at width 1 that is the scalar branch, predictable on a
/// renderer's rays. Taken always, `rescaled` would put a largest-component search and,
/// per component, an integer exponent step (float bits to integers, shift, mask, clamp,
/// subtract, shift, back to a float and multiply) in front of every cull's first product,
/// against one length and two compares here. Otherwise the lanes select.
#[inline(always)]
pub(crate) fn moderate<R: Real32>(v: V3<R>) -> V3<R> {
    let len_sq = v.length_squared();
    let plain = len_sq.gt(len_sq.k(MODERATE_LOW)) & len_sq.lt(len_sq.k(MODERATE_HIGH));
    if plain.all() {
        return v;
    }
    let r = rescaled(v);
    V3::new(
        R::select(plain, v.x, r.x),
        R::select(plain, v.y, r.y),
        R::select(plain, v.z, r.z),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::Vec3s;
    use glam::Vec3;
    use pulp::Scalar;

    #[test]
    fn moderate_keeps_fourth_powers_in_range() {
        assert_eq!(2f32.powi(-40), 9.094_947e-13);
        assert_eq!(2f32.powi(40), 1.099_511_6e12);
        let s = Scalar::new();
        for scale in [1e-19f32, 1e-15, 1e-5, 1.0, 1e5, 1e15, 1e19] {
            let m = moderate(Vec3s::splat(s, Vec3::new(0.3, -1.0, 0.2) * scale));
            let v = Vec3::new(m.x.v, m.y.v, m.z.v);
            let fourth = v.length_squared() * v.length_squared();
            assert!(fourth.is_normal() && fourth < 1.3e24, "{scale}: {v}");
            // Only the length changes.
            let cos = v.normalize().dot(Vec3::new(0.3, -1.0, 0.2).normalize());
            assert!((cos - 1.0).abs() < 1e-6);
        }
    }
}
