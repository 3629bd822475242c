//! The shapes a renderer hands over: a ring torus with its pose, and a ray; and what the
//! torus computes once for its culls ([`CullBounds`]) and its exact path ([`Tube`]).

mod bounds;
#[cfg(test)]
pub(crate) mod draw;
mod point_query;
pub(crate) mod ray;
mod solid_crossings;
mod solid_hit;
mod solid_query;
mod torus;
mod tube;

pub(crate) use bounds::cull_bounds_table;
pub use bounds::{CullBounds, SAFETY_REL};
pub use point_query::{NonFinitePoint, SurfaceProjection};
pub(crate) use tube::Tube;

pub use ray::{DRay, DRayError, ON_SURFACE_REL, Precision, Ray, RayError};
pub(crate) use solid_crossings::pair_spans;
pub use solid_crossings::{
    MAX_CROSSINGS, MAX_SPANS, Passage, SolidCrossing, SolidCrossings, SolidSpan, SolidSpans, SpanOf,
};
pub use solid_hit::{NoFace, SolidF32Hit, SolidHit};
pub use solid_query::{PointQueryError, SolidProjection};
pub use torus::{
    FAR_LIMIT_REL, LocalLine, MAX_NU, MAX_OUTER_RADIUS, MIN_OUTER_RADIUS, NEAR_ORIGIN_REL, Torus,
    TorusError,
};
