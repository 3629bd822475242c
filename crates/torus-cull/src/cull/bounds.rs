//! The per-torus constants of the culls with their safety margin ([`CullBounds`]), and the
//! scale steps every cull shares ([`foot_point`], [`rescaled`], [`moderate`]), written once
//! over lanes: at [`pulp::Scalar`] they are the scalar steps.

use crate::batch::lanes::F32s;
use crate::batch::real::RealMask;
use crate::batch::vec3s::Vec3s;
use pulp::Simd;

/// The relative safety margin: `η = SAFETY_REL · (R + r)`, 2⁻¹² ≈ 2.4e-4.
///
/// About 4000 f32 ulps of the torus size: large enough to absorb the transform and
/// foot-point rounding for origins within 256·(R + r), small enough to cost nothing
/// measurable in rejection rate (it only keeps lines that pass within η of the surface).
pub const SAFETY_REL: f32 = 1.0 / 4096.0;

/// Below this squared horizontal direction fraction (|h|/|d| < 1e-6) a line is treated as
/// parallel to the axis: within the bounding sphere its distance from the axis changes by
/// less than 2e-6·(R + r), far inside η.
pub(crate) const AXIS_PARALLEL_H2: f32 = 1e-12;

/// Per-torus constants for the culls, in f32, with the safety margin folded in.
///
/// Owned by its [`crate::Torus`] (computed once in [`crate::Torus::new`], read with
/// [`crate::Torus::bounds`]): bounds exist only for a torus the constructor accepted, so a
/// cull can be handed neither another torus's constants nor those of a torus without a
/// hole (R ≤ r, where the padded hole test would reject lines that hit).
///
/// ```compile_fail
/// // Not constructible outside the crate: R < r has no bounds, only a `TorusError`.
/// let bounds = torus_cull::CullBounds::new(1.0, 2.0);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CullBounds {
    /// R.
    pub(crate) major_radius: f32,
    /// r (unpadded, for the paper-as-printed variants).
    pub(crate) minor_radius: f32,
    /// r_η = r + η: the padded tube radius used by every timed cull.
    pub(crate) minor_safe: f32,
    /// r_η².
    pub(crate) minor_safe_sq: f32,
    /// (R + r_η)²: the padded bounding sphere.
    pub(crate) outer_safe_sq: f32,
    /// R + r_η.
    pub(crate) outer_safe: f32,
    /// R − r_η: the padded hole radius (≥ 0 is not guaranteed for ν near 1).
    pub(crate) inner_safe: f32,
    /// (R − r_η)², or 0 when the padded hole closes.
    pub(crate) inner_safe_sq: f32,
    /// s = √(ν_η + 1) with ν_η = R/r_η, rounded down: scaling y by s turns the padded
    /// outer ellipsoid ρ² + (ν_η + 1)·y² ≤ (R + r_η)² into the sphere of radius R + r_η.
    /// Rounding s down only widens the ellipsoid.
    pub(crate) ellipsoid_y_scale: f32,
    /// s·r_η: the slab |y| ≤ r_η in the y-scaled coordinates.
    pub(crate) ellipsoid_slab: f32,
    /// (ν_η − 1)/(ν_η + 1) = (R − r_η)/(R + r_η), rounded down, or 0 when the padded hole
    /// closes: the inner hyperboloid ρ² − (ν_η − 1)·y² ≥ (R − r_η)² in the y-scaled
    /// coordinates is ρ² − this·y′² ≥ (R − r_η)². Rounding down only widens it.
    pub(crate) hyperboloid_y_coef: f32,
    /// 1/R²: the discriminant works at R = 1.
    pub(crate) inv_major_sq: f32,
    /// (r_η/R)²: the padded tube radius at R = 1.
    pub(crate) minor_rel_sq: f32,
    /// 1/R² in f64, for `discriminant_f64`.
    pub(crate) inv_major_sq_f64: f64,
    /// (r_η/R)² in f64, from the f32 r_η and R, for `discriminant_f64`.
    pub(crate) minor_rel_sq_f64: f64,
}

impl CullBounds {
    /// Bounds for R = `major_radius`, r = `minor_radius`: only [`crate::Torus::new`]'s
    /// validated radii come here (and the unit tests').
    pub(crate) fn new(major_radius: f32, minor_radius: f32) -> CullBounds {
        let eta = SAFETY_REL * (major_radius + minor_radius);
        let minor_safe = minor_radius + eta;
        let outer_safe = major_radius + minor_safe;
        let inner_safe = major_radius - minor_safe;
        let (big, small) = (f64::from(major_radius), f64::from(minor_safe));
        let hyperboloid_y_coef = if inner_safe > 0.0 {
            round_down((big - small) / (big + small))
        } else {
            0.0
        };
        let ellipsoid_y_scale = round_down(((big + small) / small).sqrt());
        CullBounds {
            major_radius,
            minor_radius,
            minor_safe,
            minor_safe_sq: minor_safe * minor_safe,
            outer_safe_sq: outer_safe * outer_safe,
            outer_safe,
            inner_safe,
            inner_safe_sq: if inner_safe > 0.0 {
                inner_safe * inner_safe
            } else {
                0.0
            },
            ellipsoid_y_scale,
            ellipsoid_slab: ellipsoid_y_scale * minor_safe,
            hyperboloid_y_coef,
            inv_major_sq: (1.0 / (big * big)) as f32,
            minor_rel_sq: ((small / big) * (small / big)) as f32,
            inv_major_sq_f64: 1.0 / (big * big),
            minor_rel_sq_f64: (small / big) * (small / big),
        }
    }

    /// r_η = r + η: the padded tube radius every timed cull tests against (η =
    /// [`SAFETY_REL`]·(R + r), rounded in f32), for code that checks a cull's margin.
    #[must_use]
    #[inline]
    pub const fn minor_safe(&self) -> f32 {
        self.minor_safe
    }

    /// R, the major radius these bounds were made for.
    #[must_use]
    #[inline]
    pub const fn major_radius(&self) -> f32 {
        self.major_radius
    }

    /// r, the minor (tube) radius these bounds were made for.
    #[must_use]
    #[inline]
    pub const fn minor_radius(&self) -> f32 {
        self.minor_radius
    }

    /// (R + r + η)²: the padded bounding sphere's squared radius.
    #[doc(hidden)]
    #[must_use]
    #[inline]
    pub const fn outer_safe_sq(&self) -> f32 {
        self.outer_safe_sq
    }
}

/// The largest f32 ≤ `x` (for a positive finite `x`).
fn round_down(x: f64) -> f32 {
    let y = x as f32;
    if f64::from(y) > x {
        f32::from_bits(y.to_bits() - 1)
    } else {
        y
    }
}

/// The foot point p = o − d (o·d)/|d|² of the line (its point closest to the torus
/// centre) and 1/|d|². Shared first step of the sphere-based culls: it removes the
/// far-origin cancellation from every later formula, for one division and no root.
#[inline(always)]
pub fn foot_point<S: Simd>(origin: Vec3s<S>, dir: Vec3s<S>) -> (Vec3s<S>, F32s<S>) {
    let one = F32s::splat(origin.x.s, 1.0);
    let inv_len_sq = one / dir.length_squared();
    (origin - dir * (origin.dot(dir) * inv_len_sq), inv_len_sq)
}

/// `v` times a power of two that brings its largest component into [1, 2): exact (no
/// rounding), so scale-free formulas give bit-identical answers, and their fourth powers of
/// a direction stay inside f32's range however the ray is parametrized.
///
/// A valid ray's |d|² is a finite normal f32, so the largest component's biased exponent
/// e is in 1..=191 and the factor 2^(127 − e) is a normal f32.
#[inline(always)]
pub(crate) fn rescaled<S: Simd>(v: Vec3s<S>) -> Vec3s<S> {
    let largest = v.abs().max_element();
    Vec3s::new(
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
pub(crate) fn moderate<S: Simd>(v: Vec3s<S>) -> Vec3s<S> {
    let s = v.x.s;
    let len_sq = v.length_squared();
    let plain = len_sq.gt(F32s::splat(s, MODERATE_LOW)) & len_sq.lt(F32s::splat(s, MODERATE_HIGH));
    if plain.all() {
        return v;
    }
    let r = rescaled(v);
    Vec3s::new(
        plain.select(v.x, r.x),
        plain.select(v.y, r.y),
        plain.select(v.z, r.z),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
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

    #[test]
    fn margin_is_small_and_positive() {
        let b = CullBounds::new(2.0, 1.0);
        assert!(b.minor_safe > 1.0 && b.minor_safe < 1.001);
        assert!(b.outer_safe > 3.0 && b.outer_safe < 3.001);
        assert!(b.inner_safe < 1.0 && b.inner_safe > 0.999);
    }
}
