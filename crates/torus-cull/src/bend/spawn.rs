//! Rays leaving a bend's surface: the nearest face point of a hit, and the secondary ray
//! spawned there (the origin's own face found as `crossings` finds it).

use super::PipeBend;
use crate::{Precision, Ray, RayError};
use glam::DVec3;

impl PipeBend {
    /// The point of the nearest face to the world point `p`, with the faces it lies on
    /// (module docs of [`crate::bend`]): onto a torus along its meridian, onto a cap along
    /// its plane's normal; a point near a cap's edge is moved onto both. `p` itself where
    /// no face is within reach.
    #[must_use]
    pub fn nearest_face_point(&self, p: DVec3) -> DVec3 {
        let local = self.local_point(p);
        self.outer
            .point_to_world_f64(super::crossings::own_faces(self, local).point)
    }

    /// The secondary ray leaving the hit at `t` on `ray` in direction `dir`, marked as
    /// starting on the surface: its origin is the point at `t` moved onto its face
    /// ([`PipeBend::nearest_face_point`]).
    ///
    /// # Errors
    ///
    /// A [`RayError`], as [`crate::Torus::spawn`]'s (size R + r_max in `OffSurface`'s tolerance,
    /// the distance [`PipeBend::signed_distance`]'s).
    pub fn spawn<P: Precision>(
        &self,
        ray: &Ray<P>,
        t: P::Float,
        dir: P,
    ) -> Result<Ray<P>, RayError<P>> {
        let distance = |at| self.signed_distance(at).map_or(f64::INFINITY, f64::abs);
        let size = self.major_radius_f64() + self.tube_radius_f64();
        ray.spawn_onto(t, dir, size, distance, |at| self.nearest_face_point(at))
    }
}
