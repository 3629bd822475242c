//! Exact ray–torus intersection: the expensive path a cull saves (timed).

use crate::{Ray, Torus};
use glam::Vec3;

/// The nearest hit of a ray.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Hit {
    /// Ray parameter, in units of the ray's direction.
    pub t: f32,
    /// Unit outward surface normal, world space.
    pub normal: Vec3,
}

/// The nearest hit with `t ∈ [t_min, t_max]`, or `None`.
pub fn intersect(_torus: &Torus, _ray: &Ray) -> Option<Hit> {
    todo!("intersect helper")
}
