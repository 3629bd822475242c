//! The shapes a renderer hands over: a ring torus with its pose, and a ray.

mod ray;
mod torus;

pub use ray::{DRay, DRayError, Ray, RayError};
pub use torus::{
    FAR_LIMIT_REL, LocalLine, MAX_NU, MAX_OUTER_RADIUS, MIN_OUTER_RADIUS, NEAR_ORIGIN_REL, Torus,
    TorusError,
};
