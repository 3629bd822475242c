//! # torus-cull
//!
//! Bounding tests ("culls") for ray–torus intersection, and an exact intersection that
//! never misses a hit.
//!
//! # The renderer API
//!
//! A renderer needs four things: a [`Torus`], a [`Ray`], a [`Cull`] and [`intersect()`]
//! (or both at once: [`intersect_culled`]).
//!
//! * [`Torus`] and [`Ray`]: validated shapes (or [`DRay`], an f64 ray with f64 hits); the
//!   torus computes its cull constants once ([`Torus::bounds`]), and
//!   [`Torus::line_to_local`] moves a ray into the torus frame (centre at the origin,
//!   axis +y) where every cull works.
//! * [`RayCast`]: the nearest hit, its `t` alone, or a shadow ray's bool, from a
//!   [`Torus`] or from a torus behind a cull ([`Torus::with_cull`]); the free functions
//!   [`intersect()`], [`intersect_culled`] and [`occluded()`] are what it calls.
//! * [`Solid`]: one interface for the ring [`Torus`], the family's [`family::Toroid`] and
//!   the [`bend::PipeBend`]: the world box, nearest hit and shadow test of f32 and f64
//!   rays, every crossing and the spans ([`SolidCrossings`], iterated by reference), the
//!   certified f32 answer, spawning a ray from a hit, inside, signed distance and closest
//!   point, with one hit type carrying its face ([`SolidHit`]). All three are [`RayCast`]
//!   too, bare or behind a cull, so a `Box<dyn RayCast>` holds any of them.
//! * [`cull`]: one file per cull behind the one-method [`Cull`] trait, all conservative
//!   (a rejected line provably misses), from Cychosz's sphere + slab ([`CychoszCull`]) and
//!   Skala's circle test ([`SkalaCull`], the seed paper's misprints corrected) to the
//!   root-free [`DiscriminantCull`]; [`CullKind`] names them for run-time choice.
//! * [`intersect()`]: the nearest hit, from [`quartic`]'s nearest-root solver on the
//!   torus quartic; [`intersect_all`] every crossing in range with its normal and whether
//!   the ray enters or leaves, paired into the spans inside the solid (for CSG and
//!   transport); [`quartic::solve_quartic`] every real root of a quartic of your own.
//! * [`batch`]: the same culls and solver on SIMD lanes, for packets and wavefronts, with
//!   the instruction set picked at run time.
//!
//! With `default-features = false` this is all the crate builds, and its only
//! dependencies are `glam` and `pulp` (the SIMD lanes of [`batch`]):
//!
//! ```toml
//! [dependencies]
//! # From a clone of the repository, beside your project (the crate is not yet on crates.io):
//! torus-cull = { path = "../torus-cull/crates/torus-cull", default-features = false }
//! # Once published, the same line reads:
//! # torus-cull = { version = "0.1", default-features = false }
//! ```
//!
//! The geometry, each cull's bound and soundness argument, the floating-point margin, the
//! supported range and the seed paper's errata are written up in `docs/math.md`, which
//! ships in this package with the project's other pages (`docs/`).
//!
//! ```
//! use torus_cull::{Cull, Ray, SkalaCull, Torus, intersect};
//! use glam::Vec3;
//!
//! let torus = Torus::new(Vec3::ZERO, Vec3::Y, 4.0, 1.0)?; // and its cull bounds, once
//! let bounds = torus.bounds();
//!
//! // A ray that falls straight through the hole: skala proves the miss, no quartic.
//! let ray = Ray::new(Vec3::new(0.5, 10.0, 0.0), Vec3::new(0.0, -1.0, 0.0))?;
//! let line = torus.line_to_local(&ray);
//! assert!(!SkalaCull.keeps(bounds, line.origin, line.dir));
//!
//! // A ray aimed at the tube: kept, and the exact intersection finds it.
//! let ray = Ray::new(Vec3::new(4.0, 10.0, 0.0), Vec3::new(0.0, -1.0, 0.0))?;
//! let line = torus.line_to_local(&ray);
//! assert!(SkalaCull.keeps(bounds, line.origin, line.dir));
//! let hit = intersect(&torus, &ray).expect("hits the top of the tube");
//! assert!((hit.t - 9.0).abs() < 1e-4);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! # The lab
//!
//! The measurements behind this crate's choices (the f64 oracle, the workload generators,
//! rejection counts, paired timing, BVH scenes, results files and plots, the `torus-cull`
//! command and `cargo bench`) live in the workspace's other crate, `torus-cull-lab`, which
//! this one never imports.

#![warn(missing_docs)]

/// The glam this API speaks (0.34): a renderer on another glam version converts through
/// `torus_cull::glam::Vec3` instead of meeting "multiple different versions of crate glam".
pub use glam;

pub mod batch;
pub mod bend;
pub mod certified;
pub mod cull;
pub mod family;
mod geometry;
pub mod intersect;
mod names;
mod num;
pub mod quartic;
mod solids;

#[cfg(feature = "gpu")]
pub mod gpu;

#[cfg(any(feature = "parry", feature = "bevy"))]
pub mod adapters;

/// What the lab's paper-as-printed fixtures (`torus-cull-lab`'s `errata`: the seed paper's
/// culls with its misprints, which are *not* conservative) are built from. Not renderer
/// API, no stability promise.
#[doc(hidden)]
pub mod internals {
    pub use crate::cull::{LaneBounds, SectionFormulas, foot_point, skala_keeps};
    pub use crate::num::{F32s, Real, Vec3s};
}

pub use certified::{
    F32Hit, F32Occluded, F32Verdict, intersect_f32, intersect_f32_certified, intersect_f32_culled,
    occluded_f32, occluded_f32_culled,
};
pub use cull::{Cull, CullBounds, CullKind, CullVisitor};
// Every cull type of the table of culls (`NoCull`, `CychoszCull`, `SkalaCull`, …).
use cull::table::export_culls;
export_culls!(root);
pub use geometry::{
    DRay, DRayError, FAR_LIMIT_REL, LocalLine, MAX_NU, MAX_OUTER_RADIUS, MIN_OUTER_RADIUS,
    NEAR_ORIGIN_REL, NonFinitePoint, ON_SURFACE_REL, Precision, Ray, RayError, SurfaceProjection,
    Torus, TorusError,
};
pub use geometry::{
    MAX_CROSSINGS, MAX_SPANS, NoFace, PointQueryError, SolidCrossing, SolidCrossings, SolidF32Hit,
    SolidHit, SolidProjection, SolidSpan, SolidSpans, SpanOf,
};
pub use intersect::{
    Crossing, Crossings, Culled, DHit, Hit, Passage, RayCast, Span, Spans, SurfaceCoords,
    SurfaceTangents, TorusRay, intersect, intersect_all, intersect_culled, occluded,
};
pub use names::{Named, UnknownName};
pub use solids::Solid;

/// The README's examples, compiled and run by `cargo test --doc`.
#[cfg(doctest)]
#[doc = include_str!("../../../README.md")]
struct ReadmeExamples;

/// The crate's own README (the package's, for crates.io), compiled and run too.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct CrateReadmeExamples;
