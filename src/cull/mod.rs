//! Culls: cheap tests that prove a line cannot hit the torus, so the quartic is skipped.
//!
//! Every cull is a **line** test in the torus frame (centre at the origin, axis +y) and is
//! therefore conservative for any ray on that line. A cull returns `true` to *keep* the
//! line (the exact intersection must run) and `false` to *reject* it (proven miss).
//!
//! Each cull lives in its own file behind the one-method [`Cull`] trait. [`CullKind`] is
//! the registry by stable name, used in results, the CLI and the plots; its
//! [`CullKind::visit`] hands a concrete cull type to generic code, so that benchmark and
//! BVH loops are monomorphized per cull instead of paying a dynamic dispatch per ray.
//!
//! # Floating-point safety margin
//! Exact arithmetic is conservative, rounding is not: a plain f32 evaluation rejects some
//! lines that graze the surface. Every timed cull therefore tests the torus `T_η` whose
//! tube radius is inflated to `r + η` with `η = SAFETY_REL · (R + r)` (see [`CullBounds`]).
//! Any error that acts like moving the line, or a plane through it, by less than `η` is
//! absorbed: every point within `η` of the true torus lies inside `T_η`. The errors of the
//! world→torus transform and of the foot-point shift are about `4·2⁻²⁴·|o − c|`, so the
//! margin covers origins with `|o − c| ≤ 256·(R + r)`. [`crate::Torus::line_to_local`]
//! moves origins beyond 64·(R + r) to the line's foot point in f64, so every origin is
//! covered; lines built by hand must stay within that distance. The squares in the culls
//! bound the torus size: see [`crate::MIN_OUTER_RADIUS`] and [`crate::MAX_OUTER_RADIUS`].

mod aabb;
mod cychosz;
mod discriminant;
mod ellipsoid;
mod none;
mod quadric;
mod skala;
mod sphere;
mod thick_cylinder;

pub use aabb::AabbCull;
pub use cychosz::CychoszCull;
pub use discriminant::{DiscriminantCull, DiscriminantF64Cull};
pub use ellipsoid::EllipsoidCull;
pub use none::NoCull;
pub(crate) use quadric::HORIZONTAL_DY;
pub use quadric::QuadricCull;
pub use skala::SkalaCull;
// The paper-as-printed fixtures (`harness::errata`) reuse the section formulas.
#[cfg(feature = "harness")]
pub(crate) use skala::{SectionFormulas, skala_keeps};
pub use sphere::SphereCull;
pub use thick_cylinder::ThickCylinderCull;

use glam::Vec3;
use std::fmt;
use std::str::FromStr;

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
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CullBounds {
    /// R.
    pub major_radius: f32,
    /// r (unpadded, for the paper-as-printed variants).
    pub minor_radius: f32,
    /// r_η = r + η: the padded tube radius used by every timed cull.
    pub minor_safe: f32,
    /// r_η².
    pub minor_safe_sq: f32,
    /// (R + r_η)²: the padded bounding sphere.
    pub outer_safe_sq: f32,
    /// R + r_η.
    pub outer_safe: f32,
    /// R − r_η: the padded hole radius (≥ 0 is not guaranteed for ν near 1).
    pub inner_safe: f32,
    /// (R − r_η)², or 0 when the padded hole closes.
    pub inner_safe_sq: f32,
    /// s = √(ν_η + 1) with ν_η = R/r_η, rounded down: scaling y by s turns the padded
    /// outer ellipsoid ρ² + (ν_η + 1)·y² ≤ (R + r_η)² into the sphere of radius R + r_η.
    /// Rounding s down only widens the ellipsoid.
    pub ellipsoid_y_scale: f32,
    /// s·r_η: the slab |y| ≤ r_η in the y-scaled coordinates.
    pub ellipsoid_slab: f32,
    /// (ν_η − 1)/(ν_η + 1) = (R − r_η)/(R + r_η), rounded down, or 0 when the padded hole
    /// closes: the inner hyperboloid ρ² − (ν_η − 1)·y² ≥ (R − r_η)² in the y-scaled
    /// coordinates is ρ² − this·y′² ≥ (R − r_η)². Rounding down only widens it.
    pub hyperboloid_y_coef: f32,
    /// 1/R²: the discriminant works at R = 1.
    pub inv_major_sq: f32,
    /// (r_η/R)²: the padded tube radius at R = 1.
    pub minor_rel_sq: f32,
    /// 1/R² in f64, for `discriminant_f64`.
    pub inv_major_sq_f64: f64,
    /// (r_η/R)² in f64, from the f32 r_η and R, for `discriminant_f64`.
    pub minor_rel_sq_f64: f64,
}

impl CullBounds {
    /// Bounds for R = `major_radius`, r = `minor_radius` (a valid ring torus).
    pub fn new(major_radius: f32, minor_radius: f32) -> CullBounds {
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

    /// Bounds for a [`crate::Torus`].
    pub fn of(torus: &crate::Torus) -> CullBounds {
        CullBounds::new(torus.major_radius(), torus.minor_radius())
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

/// A bounding test for one torus in its own frame.
///
/// `keeps` is a **line** test: `origin + t·dir` for all real t, `dir` finite and non-zero
/// of any length. `false` means the line provably misses the torus.
pub trait Cull {
    /// The stable name used in results, the CLI and plots.
    fn name(&self) -> &'static str;

    /// `true` to keep the line (run the quartic), `false` to reject it.
    fn keeps(&self, bounds: &CullBounds, origin: Vec3, dir: Vec3) -> bool;
}

/// The foot point p = o − d (o·d)/|d|² of the line (its point closest to the torus
/// centre) and 1/|d|². Shared first step of the sphere-based culls: it removes the
/// far-origin cancellation from every later formula, for one division and no root.
#[inline(always)]
pub(crate) fn foot_point(origin: Vec3, dir: Vec3) -> (Vec3, f32) {
    let inv_len_sq = 1.0 / dir.length_squared();
    (origin - dir * (origin.dot(dir) * inv_len_sq), inv_len_sq)
}

/// `v` times a power of two that brings its largest component into [1, 2): exact (no
/// rounding), so scale-free formulas give bit-identical answers, and their fourth powers of
/// a direction stay inside f32's range however the ray is parametrized.
#[inline(always)]
pub(crate) fn rescaled(v: Vec3) -> Vec3 {
    let exponent = (v.abs().max_element().to_bits() >> 23) & 0xff;
    // A valid ray's |d|² is a finite normal f32, so 1 ≤ exponent ≤ 191 and 2^(127 − e) is
    // a normal f32.
    v * f32::from_bits((254 - exponent) << 23)
}

/// 2⁻⁴⁰ and 2⁴⁰: the range of |v|² that [`moderate`] leaves alone.
pub(crate) const MODERATE_LOW: f32 = 9.094_947e-13;
pub(crate) const MODERATE_HIGH: f32 = 1.099_511_6e12;

/// `v` itself when |v|² lies in [2⁻⁴⁰, 2⁴⁰], else [`rescaled`]: either way fourth powers
/// of `v`, and |o|²·|v|² for origins within 10¹³, stay inside f32's normal range. The
/// test is one branch, predictable on a renderer's rays; `rescaled`'s trip through the
/// integer unit cost a short cull about 3 ns per line when taken always.
#[inline(always)]
pub(crate) fn moderate(v: Vec3) -> Vec3 {
    let len_sq = v.length_squared();
    if len_sq > MODERATE_LOW && len_sq < MODERATE_HIGH {
        v
    } else {
        rescaled(v)
    }
}

/// Every cull by name: the registry.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum CullKind {
    /// No test: always run the quartic (the baseline).
    None,
    /// Bounding sphere of radius R + r.
    Sphere,
    /// The torus's box [−(R+r), R+r] × [−r, r] × [−(R+r), R+r].
    Aabb,
    /// Cychosz (Graphics Gems II, 1991): sphere R + r, then the slab |y| ≤ r at the chord ends.
    Cychosz,
    /// The shell R − r ≤ ρ ≤ R + r, |y| ≤ r (POV-Ray's `Test_Thick_Cylinder`).
    ThickCylinder,
    /// Skala's circle-based test, with the paper's misprints corrected.
    Skala,
    /// Cychosz with the sphere replaced by the outer ellipsoid ρ² + (ν + 1)·y² ≤ (R + r)².
    Ellipsoid,
    /// The outer ellipsoid ∩ the slab ∩ the inner hyperboloid ρ² − (ν − 1)·y² ≥ (R − r)².
    Quadric,
    /// The quartic's real-root classification (no root, no branch), in f32.
    Discriminant,
    /// The same classification evaluated in f64.
    DiscriminantF64,
}

impl CullKind {
    /// The culls measured by the harness, in table order.
    pub const TIMED: [CullKind; 10] = [
        CullKind::None,
        CullKind::Sphere,
        CullKind::Aabb,
        CullKind::Cychosz,
        CullKind::ThickCylinder,
        CullKind::Skala,
        CullKind::Ellipsoid,
        CullKind::Quadric,
        CullKind::Discriminant,
        CullKind::DiscriminantF64,
    ];

    /// The stable name.
    pub fn name(self) -> &'static str {
        match self {
            CullKind::None => "none",
            CullKind::Sphere => "sphere",
            CullKind::Aabb => "aabb",
            CullKind::Cychosz => "cychosz",
            CullKind::ThickCylinder => "thick_cylinder",
            CullKind::Skala => "skala",
            CullKind::Ellipsoid => "ellipsoid",
            CullKind::Quadric => "quadric",
            CullKind::Discriminant => "discriminant",
            CullKind::DiscriminantF64 => "discriminant_f64",
        }
    }

    /// Hands the concrete cull to `visitor`, so generic code is monomorphized per cull.
    pub fn visit<V: CullVisitor>(self, visitor: V) -> V::Output {
        match self {
            CullKind::None => visitor.visit(NoCull),
            CullKind::Sphere => visitor.visit(SphereCull),
            CullKind::Aabb => visitor.visit(AabbCull),
            CullKind::Cychosz => visitor.visit(CychoszCull),
            CullKind::ThickCylinder => visitor.visit(ThickCylinderCull),
            CullKind::Skala => visitor.visit(SkalaCull),
            CullKind::Ellipsoid => visitor.visit(EllipsoidCull),
            CullKind::Quadric => visitor.visit(QuadricCull),
            CullKind::Discriminant => visitor.visit(DiscriminantCull),
            CullKind::DiscriminantF64 => visitor.visit(DiscriminantF64Cull),
        }
    }

    /// One line through the registry: convenient, but dispatches per call.
    pub fn keeps(self, bounds: &CullBounds, origin: Vec3, dir: Vec3) -> bool {
        struct One<'a>(&'a CullBounds, Vec3, Vec3);
        impl CullVisitor for One<'_> {
            type Output = bool;
            fn visit<C: Cull>(self, cull: C) -> bool {
                cull.keeps(self.0, self.1, self.2)
            }
        }
        self.visit(One(bounds, origin, dir))
    }
}

/// Generic code that runs with a concrete cull type; see [`CullKind::visit`].
pub trait CullVisitor {
    /// What the visit returns.
    type Output;
    /// Called once with the concrete cull.
    fn visit<C: Cull>(self, cull: C) -> Self::Output;
}

impl fmt::Display for CullKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// An unknown cull name.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct UnknownCull(pub String);

impl fmt::Display for UnknownCull {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let names: Vec<_> = CullKind::TIMED.iter().map(|c| c.name()).collect();
        write!(
            f,
            "unknown cull '{}' (allowed: {})",
            self.0,
            names.join(", ")
        )
    }
}

impl std::error::Error for UnknownCull {}

impl FromStr for CullKind {
    type Err = UnknownCull;
    fn from_str(s: &str) -> Result<CullKind, UnknownCull> {
        CullKind::TIMED
            .iter()
            .copied()
            .find(|c| c.name() == s)
            .ok_or_else(|| UnknownCull(s.to_string()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn registry_round_trips_names() {
        for c in CullKind::TIMED {
            assert_eq!(c.name().parse::<CullKind>().unwrap(), c);
            struct Name;
            impl CullVisitor for Name {
                type Output = &'static str;
                fn visit<C: Cull>(self, cull: C) -> &'static str {
                    cull.name()
                }
            }
            assert_eq!(c.visit(Name), c.name());
        }
        let err = "bogus".parse::<CullKind>().unwrap_err().to_string();
        assert!(err.contains("bogus") && err.contains("skala"), "{err}");
    }

    #[test]
    fn moderate_keeps_fourth_powers_in_range() {
        assert_eq!(2f32.powi(-40), 9.094_947e-13);
        assert_eq!(2f32.powi(40), 1.099_511_6e12);
        for scale in [1e-19f32, 1e-15, 1e-5, 1.0, 1e5, 1e15, 1e19] {
            let v = moderate(Vec3::new(0.3, -1.0, 0.2) * scale);
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
