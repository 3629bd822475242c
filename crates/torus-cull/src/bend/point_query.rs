//! A pipe bend's point queries: its signed distance and closest surface point.
//!
//! The distance to the boundary is the least distance to its faces, each a closed set,
//! and each in closed form (torus frame, `D = √((ρ − R)² + y²)` the distance to the
//! core circle):
//! - **the outer and inner tubes**, for a point in the segment (on its planes and the
//!   axis included): `|D − r_max|` and `|D − r_min|`, reached in the point's own meridian
//!   half-plane, which lies in the segment. For a point outside the segment a tube's
//!   nearest point lies on the segment's nearer edge (the squared distance to a tube
//!   point, `ρ² + ρ'² − 2ρρ' cos Δφ + (y − y')²`, grows with the angle Δφ between their
//!   meridians, and ρ' > 0), that is on the rim of a cap, which the cap's term covers;
//! - **each cap**, a planar annulus of radii `[r_min, r_max]` about the core point `R·ŝ`
//!   in its half-plane (ŝ the cap's direction): with `h` the point's height over the
//!   cap's plane and `s` the distance of its foot from the core point,
//!   `√(h² + (s − clamp(s, r_min, r_max))²)`, for every point.
//!
//! The sign is the solid's own inside test ([`PipeBend::contains`]): negative inside, so
//! the two never disagree. Each term is a few roundings of the point's torus-frame
//! coordinates, so the distance is within `8ε·(|p − centre| + R + r_max)` of the exact
//! one (ε = 2⁻⁵³; against a brute-force reference the tests measure at most 3.9ε, the
//! reference's own rounding included), and so is the closest point. The whole ring
//! without a bore is [`crate::Torus::signed_distance`] to that bound (its `D` is formed
//! in the meridian's coordinates, `hypot(ρ − R, y)`, not bit for bit the torus's).
//!
//! Where the closest point is not unique a choice is made, never a NaN: on the axis the
//! meridian of the start cap's direction (of the torus frame's x axis for the whole
//! ring, as [`crate::Torus::project_point`] chooses), on the core circle the outer
//! equator's point, on a cap's normal through its core point the outer equator's
//! direction; of equally near faces the first of outer, inner, start cap, end cap (a
//! point on a cap's rim is reported on the tube in the segment, on the cap outside it).

use super::{BendFace, PipeBend};
use crate::NonFinitePoint;
use glam::DVec3;

/// The closest surface point of a pipe bend to a query point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BendProjection {
    /// The closest surface point, world space.
    pub point: DVec3,
    /// The unit outward normal of `face` there, world space (the bore's points to the
    /// core circle; a cap's along its plane's normal, away from the solid).
    pub normal: DVec3,
    /// The face the point was taken from (module docs for ties).
    pub face: BendFace,
    /// The query point's signed distance to the surface: negative inside the solid.
    pub signed_distance: f64,
}

/// A face's candidate: its nearest point and normal (torus frame), the distance to it.
#[derive(Debug, Clone, Copy)]
struct Candidate {
    point: DVec3,
    normal: DVec3,
    distance: f64,
    face: BendFace,
}

impl PipeBend {
    /// The signed distance from `p` to the bend's surface (module docs): negative inside.
    ///
    /// ```
    /// use glam::DVec3;
    /// use torus_cull::bend::{BendFace, PipeBend};
    /// let pi = std::f64::consts::PI;
    /// // R = 30, bore 5, tube 10, φ over [π/4, π]; φ grows from +x toward −z.
    /// let bend = PipeBend::canonical(30.0, 5.0, 10.0, pi / 4.0, 3.0 * pi / 4.0)?;
    /// // At φ = π/2 (−z), 7 from the core: 2 inside the bore's wall, 3 inside the tube's.
    /// assert!((bend.signed_distance(DVec3::new(0.0, 0.0, -37.0))? + 2.0).abs() < 1e-12);
    /// // In the bore, on the core circle: 5 from the bore's wall.
    /// assert!((bend.signed_distance(DVec3::new(0.0, 0.0, -30.0))? - 5.0).abs() < 1e-12);
    /// // In the cut-away arc, 3 before the start cap (φ = π/4) at 37 from the axis: the
    /// // cap's point, not the tube's.
    /// let (s, g) = (DVec3::new(1.0, 0.0, -1.0), DVec3::new(-1.0, 0.0, -1.0));
    /// let (s, g) = (s / 2f64.sqrt(), g / 2f64.sqrt()); // the cap's direction, growing φ
    /// let near = bend.project_point(s * 37.0 - g * 3.0)?;
    /// assert_eq!(near.face, BendFace::StartCap);
    /// assert!((near.signed_distance - 3.0).abs() < 1e-12);
    /// assert!((near.point - s * 37.0).length() < 1e-12 && (near.normal + g).length() < 1e-12);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    ///
    /// [`NonFinitePoint`] for a NaN or infinite coordinate.
    pub fn signed_distance(&self, p: DVec3) -> Result<f64, NonFinitePoint> {
        Ok(self.project_point(p)?.signed_distance)
    }

    /// The closest surface point to `p`, its face and outward normal, and `p`'s signed
    /// distance (module docs: exact but for rounding, a choice where it is not unique).
    ///
    /// # Errors
    ///
    /// [`NonFinitePoint`] for a NaN or infinite coordinate.
    pub fn project_point(&self, p: DVec3) -> Result<BendProjection, NonFinitePoint> {
        let x = self.outer.point_to_local_f64(p)?;
        let best = self.nearest_face(x);
        let inside = self.contains_local(x, false);
        let to_world = self.outer.to_local_rotation_f64().transpose();
        Ok(BendProjection {
            point: self.outer.point_to_world_f64(best.point),
            normal: to_world * best.normal,
            face: best.face,
            signed_distance: if inside {
                -best.distance
            } else {
                best.distance
            },
        })
    }

    /// The nearest face's candidate to the torus-frame point `x` (module docs).
    fn nearest_face(&self, x: DVec3) -> Candidate {
        let (big, r_max) = (self.major_radius_f64(), self.tube_radius_f64());
        let mut best: Option<Candidate> = None;
        let mut offer = |c: Candidate| {
            if best.is_none_or(|b| c.distance < b.distance) {
                best = Some(c);
            }
        };
        if self.wedge.is_none_or(|w| w.contains(x, false)) {
            let rho = x.x.hypot(x.z);
            let radial = if rho > 0.0 {
                DVec3::new(x.x / rho, 0.0, x.z / rho)
            } else {
                self.wedge.map_or(DVec3::X, |w| w.cap(false).0)
            };
            let core = radial * big;
            // The offset from the core point in the meridian's (ρ̂, y) coordinates, so the
            // tube point stays in the meridian however small the offset.
            let (u, v) = (rho - big, x.y);
            let dist = u.hypot(v);
            let out = if dist > 0.0 {
                radial * (u / dist) + DVec3::Y * (v / dist)
            } else {
                radial
            };
            offer(Candidate {
                point: core + out * r_max,
                normal: out,
                distance: (dist - r_max).abs(),
                face: BendFace::Outer,
            });
            if let Some(inner) = self.inner {
                let r_min = inner.minor_radius_f64();
                offer(Candidate {
                    point: core + out * r_min,
                    normal: -out,
                    distance: (dist - r_min).abs(),
                    face: BendFace::Inner,
                });
            }
        }
        if let Some(w) = self.wedge {
            let r_min = self.bore_radius_f64();
            for (end, face) in [(false, BendFace::StartCap), (true, BendFace::EndCap)] {
                let (dir, growing) = w.cap(end);
                let h = x.dot(growing);
                let core = dir * big;
                // The foot's offset from the core point, in the cap's plane (dir, y).
                let foot = dir * (x.dot(dir) - big) + DVec3::Y * x.y;
                let s = foot.length();
                let rim = s.clamp(r_min, r_max);
                let unit = if s > 0.0 { foot / s } else { dir };
                offer(Candidate {
                    point: core + unit * rim,
                    normal: if end { growing } else { -growing },
                    distance: h.hypot(s - rim),
                    face,
                });
            }
        }
        best.expect("the outer tube or a cap is always offered")
    }
}
