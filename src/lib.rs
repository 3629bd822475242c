//! # torus-cull
//!
//! Bounding tests ("culls") for ray–torus intersection, an exact intersection, and an
//! independent f64 oracle to prove the culls conservative.
//!
//! A renderer needs four things: a [`Torus`], a [`Ray`], a [`Cull`] and [`intersect`].
//!
//! ```
//! use torus_cull::{Cull, CullBounds, Ray, SkalaCull, Torus, intersect};
//! use glam::Vec3;
//!
//! let torus = Torus::new(Vec3::ZERO, Vec3::Y, 4.0, 1.0)?;
//! let bounds = CullBounds::of(&torus);
//!
//! // A ray that falls straight through the hole: skala proves the miss, no quartic.
//! let ray = Ray::new(Vec3::new(0.5, 10.0, 0.0), Vec3::new(0.0, -1.0, 0.0))?;
//! let line = torus.line_to_local(&ray);
//! assert!(!SkalaCull.keeps(&bounds, line.origin, line.dir));
//!
//! // A ray aimed at the tube: kept, and the exact intersection finds it.
//! let ray = Ray::new(Vec3::new(4.0, 10.0, 0.0), Vec3::new(0.0, -1.0, 0.0))?;
//! let line = torus.line_to_local(&ray);
//! assert!(SkalaCull.keeps(&bounds, line.origin, line.dir));
//! let hit = intersect(&torus, &ray).expect("hits the top of the tube");
//! assert!((hit.t - 9.0).abs() < 1e-4);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

#![warn(missing_docs)]

pub mod cull;
pub mod intersect;
pub mod oracle;
pub mod quartic;
mod ray;
mod torus;

pub use cull::{
    AabbCull, Cull, CullBounds, CullKind, CychoszCull, NoCull, SkalaCull, SphereCull,
    ThickCylinderCull,
};
pub use intersect::{Hit, intersect};
pub use ray::{Ray, RayError};
pub use torus::{LocalLine, Torus, TorusError};
