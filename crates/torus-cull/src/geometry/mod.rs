//! The shapes a renderer hands over: a ring torus with its pose, and a ray; and what the
//! torus computes once for its culls ([`CullBounds`]) and its exact path ([`Tube`]).

mod bounds;
#[cfg(test)]
pub(crate) mod draw;
mod point_query;
pub(crate) mod ray;
mod torus;
mod tube;

pub use bounds::{CullBounds, SAFETY_REL};
pub use point_query::{NonFinitePoint, SurfaceProjection};
pub(crate) use tube::Tube;

pub use ray::{DRay, DRayError, ON_SURFACE_REL, Precision, Ray, RayError};
pub use torus::{
    FAR_LIMIT_REL, LocalLine, MAX_NU, MAX_OUTER_RADIUS, MIN_OUTER_RADIUS, NEAR_ORIGIN_REL, Torus,
    TorusError,
};
