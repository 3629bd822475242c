//! What a [`crate::Solid`]'s point queries answer: the closest surface point with its
//! face, and one error for a point they refuse.

use super::point_query::{NonFinitePoint, SurfaceProjection};
use super::solid_hit::NoFace;
use glam::DVec3;
use std::fmt;

/// The closest surface point of a [`crate::Solid`] to a query point, in f64.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct SolidProjection<F> {
    /// The closest surface point, world space.
    pub point: DVec3,
    /// The unit outward normal of `face` there, world space.
    pub normal: DVec3,
    /// The query point's signed distance to the surface: negative inside the solid.
    pub signed_distance: f64,
    /// The face the point was taken from.
    pub face: F,
}

impl<F> SolidProjection<F> {
    /// A projection from its fields (a solid of your own: the struct is
    /// `#[non_exhaustive]`, so this is how a shape outside the library answers
    /// [`crate::Solid::project_point`]).
    #[must_use]
    pub const fn new(point: DVec3, normal: DVec3, signed_distance: f64, face: F) -> Self {
        SolidProjection {
            point,
            normal,
            signed_distance,
            face,
        }
    }
}

/// A ring torus's or family member's projection, on its one face.
impl From<SurfaceProjection> for SolidProjection<NoFace> {
    fn from(p: SurfaceProjection) -> Self {
        SolidProjection {
            point: p.point,
            normal: p.normal,
            signed_distance: p.signed_distance,
            face: NoFace,
        }
    }
}

/// Why a [`crate::Solid`]'s point query was refused.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum PointQueryError {
    /// A NaN or infinite coordinate.
    NonFinite(NonFinitePoint),
    /// The shape has no supported answer for this query: the text says which shape and
    /// why (the closest point of an elliptical horn or spindle torus).
    Unsupported(&'static str),
}

impl fmt::Display for PointQueryError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            PointQueryError::NonFinite(e) => write!(f, "{e}"),
            PointQueryError::Unsupported(why) => f.write_str(why),
        }
    }
}

impl std::error::Error for PointQueryError {}

impl From<NonFinitePoint> for PointQueryError {
    fn from(e: NonFinitePoint) -> Self {
        PointQueryError::NonFinite(e)
    }
}
