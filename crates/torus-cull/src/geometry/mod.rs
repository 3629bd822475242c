//! The shapes a renderer hands over: a ring torus with its pose, and a ray.

pub(crate) mod ray;
mod torus;

pub use ray::{DRay, DRayError, Precision, Ray, RayError};
pub use torus::{
    FAR_LIMIT_REL, LocalLine, MAX_NU, MAX_OUTER_RADIUS, MIN_OUTER_RADIUS, NEAR_ORIGIN_REL, Torus,
    TorusError,
};
