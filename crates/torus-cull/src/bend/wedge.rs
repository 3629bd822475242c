//! The φ segment: its inside test, its two caps, and whether a line meets it (the wedge
//! cull's test, [`super::wedge_cull`]).
//!
//! In the outer torus's frame (axis +y), with `e0` the direction of φ = 0 and `e1 = y × e0`,
//! a point's plane coordinates are `q = (x·e0, x·e1)` and φ = atan2(q₁, q₀). The segment
//! `[φ₀, φ₁]`, φ₁ = φ₀ + Δφ, is the cone between the unit directions `s` (φ₀) and `e`
//! (φ₁): for Δφ ≤ π the convex cone `s × q ≥ 0 ≤ q × e`, for Δφ > π the complement of
//! the convex cone from `e` to `s`.

use glam::{DVec2, DVec3};

/// The segment in the outer torus's frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Wedge {
    e0: DVec3,
    e1: DVec3,
    /// The plane directions of φ₀ and φ₁ in `(e0, e1)` coordinates.
    start: DVec2,
    end: DVec2,
    /// Δφ > π: the segment is the complement of the convex cone from `end` to `start`.
    reflex: bool,
}

/// The 2-D cross product `a × b`: > 0 where `b` is counterclockwise (toward growing φ)
/// of `a`.
#[inline]
fn cross(a: DVec2, b: DVec2) -> f64 {
    a.x * b.y - a.y * b.x
}

impl Wedge {
    pub(super) fn new(e0: DVec3, e1: DVec3, start_phi: f64, delta_phi: f64) -> Wedge {
        let end_phi = start_phi + delta_phi;
        Wedge {
            e0,
            e1,
            start: DVec2::new(start_phi.cos(), start_phi.sin()),
            end: DVec2::new(end_phi.cos(), end_phi.sin()),
            reflex: delta_phi > std::f64::consts::PI,
        }
    }

    /// The torus-frame point's plane coordinates.
    #[inline]
    fn plane(&self, x: DVec3) -> DVec2 {
        DVec2::new(x.dot(self.e0), x.dot(self.e1))
    }

    /// The torus-frame point `x` lies in the segment (`strict`: not on its planes).
    pub(super) fn contains(&self, x: DVec3, strict: bool) -> bool {
        let q = self.plane(x);
        let (a, b) = if self.reflex {
            (cross(self.end, q), cross(q, self.start))
        } else {
            (cross(self.start, q), cross(q, self.end))
        };
        match (self.reflex, strict) {
            (false, false) => a >= 0.0 && b >= 0.0,
            (false, true) => a > 0.0 && b > 0.0,
            (true, false) => !(a > 0.0 && b > 0.0),
            (true, true) => !(a >= 0.0 && b >= 0.0),
        }
    }

    /// A cap's unit direction in the torus frame (its half-plane is `x·dir > 0` of its
    /// plane) and the unit normal of its plane toward growing φ.
    pub(super) fn cap(&self, end: bool) -> (DVec3, DVec3) {
        let c = if end { self.end } else { self.start };
        let dir = self.e0 * c.x + self.e1 * c.y;
        let growing = self.e1 * c.x - self.e0 * c.y;
        (dir, growing)
    }

    /// Whether the line `o + t·d` (torus frame) passes within `eta` of the segment's cone
    /// inside the ball of radius `reach` (which holds the solid): false only when a line
    /// provably misses the segment there. The chord of the ball, projected on the plane,
    /// against the cone inflated by `eta`: separated by one of the cone's edges, or (for
    /// Δφ ≤ π) by the chord's own line (the separating axes of two convex sets), or (for
    /// Δφ > π) held inside the complementary convex cone shrunk by `eta`.
    pub(super) fn line_meets(&self, o: DVec3, d: DVec3, reach: f64, eta: f64) -> bool {
        let dd = d.length_squared();
        let half = o.dot(d) / dd;
        let disc = half * half - (o.length_squared() - reach * reach) / dd;
        if disc.is_nan() {
            return true;
        }
        if disc < 0.0 {
            // The line misses the ball.
            return false;
        }
        let root = disc.sqrt();
        let (p0, p1) = (
            self.plane(o + d * (-half - root)),
            self.plane(o + d * (-half + root)),
        );
        if self.reflex {
            let inside = |p: DVec2| cross(self.end, p) > eta && cross(p, self.start) > eta;
            return !(inside(p0) && inside(p1));
        }
        let outside = |f: &dyn Fn(DVec2) -> f64| f(p0) < -eta && f(p1) < -eta;
        if outside(&|p| cross(self.start, p)) || outside(&|p| cross(p, self.end)) {
            return false;
        }
        let along = p1 - p0;
        let len = along.length();
        if len > eta {
            let m = DVec2::new(-along.y, along.x) / len;
            let h = m.dot(p0);
            let (ms, me) = (m.dot(self.start), m.dot(self.end));
            if (ms >= 0.0 && me >= 0.0 && h < -eta) || (ms <= 0.0 && me <= 0.0 && h > eta) {
                return false;
            }
        }
        true
    }
}
