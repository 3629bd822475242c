//! # torus-cull
//!
//! Bounding tests ("culls") for ray–torus intersection, an exact intersection, and an
//! independent f64 oracle to prove the culls conservative.
//!
//! A renderer needs four things: a [`Torus`], a [`Ray`], a [`Cull`] and [`intersect()`]
//! (or both at once: [`intersect_culled`]).
//!
//! The rest of the crate is the measuring harness behind the `torus-cull` command and
//! `cargo bench`: [`oracle`] (f64 ground truth, never timed), [`workload`] (ray
//! generators and workload files), [`measure`] (counting), [`results`] (the results
//! JSON), [`compare`], [`report`] and [`plot`], [`eval`], [`output`] (how every output file
//! is written), and [`scene`] (many tori in an obvhs BVH) with [`render`]. [`paired`]
//! times culls against each other in interleaved rounds (`torus-cull time`), so that
//! ratios hold on a loaded machine.
//!
//! The geometry, each cull's bound and soundness argument, the floating-point margin, the
//! supported range and the seed paper's errata are written up in the repository's
//! `docs/math.md`.
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

pub mod batch;
pub mod compare;
pub mod cull;
pub mod eval;
pub mod intersect;
pub mod measure;
pub mod oracle;
pub mod output;
pub mod paired;
pub mod plot;
pub mod quartic;
mod ray;
pub mod render;
pub mod report;
pub mod results;
pub mod scene;
mod torus;
pub mod workload;

pub use cull::{
    AabbCull, Cull, CullBounds, CullKind, CullVisitor, CychoszCull, DiscriminantCull,
    DiscriminantF64Cull, EllipsoidCull, NoCull, QuadricCull, SkalaCull, SphereCull,
    ThickCylinderCull,
};
pub use intersect::{Hit, intersect};
pub use ray::{Ray, RayError};
pub use torus::{
    LocalLine, MAX_OUTER_RADIUS, MIN_OUTER_RADIUS, NEAR_ORIGIN_REL, Torus, TorusError,
};

/// What a renderer does per torus: `cull` in the torus frame (f32), then the exact
/// intersection only if the cull keeps the ray. This is the timed `total_ns` path.
///
/// ```
/// use torus_cull::{CullBounds, CychoszCull, NoCull, Ray, SkalaCull, Torus, intersect_culled};
/// use glam::Vec3;
/// let torus = Torus::new(Vec3::ZERO, Vec3::Y, 4.0, 1.0)?;
/// let bounds = CullBounds::of(&torus);
/// let hole = Ray::new(Vec3::new(0.5, 10.0, 0.0), Vec3::new(0.1, -1.0, 0.0))?;
/// // Every conservative cull gives the same answer; skala just gets there without the quartic.
/// assert_eq!(intersect_culled(&SkalaCull, &torus, &bounds, &hole), None);
/// assert_eq!(intersect_culled(&CychoszCull, &torus, &bounds, &hole), None);
/// assert_eq!(intersect_culled(&NoCull, &torus, &bounds, &hole), None);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[inline(always)]
pub fn intersect_culled<C: Cull>(
    cull: &C,
    torus: &Torus,
    bounds: &CullBounds,
    ray: &Ray,
) -> Option<Hit> {
    let line = torus.line_to_local(ray);
    if cull.keeps(bounds, line.origin, line.dir) {
        intersect(torus, ray)
    } else {
        None
    }
}
