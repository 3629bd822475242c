//! Pipe bends: a torus solid with a hollow core and a φ segment closed by flat end caps
//! ([`PipeBend`]), Geant4's `G4Torus(Rmin, Rmax, Rtor, SPhi, DPhi)` and VecGeom's torus.
//!
//! In the torus frame (centre 0, axis +y) the solid is the set of points whose distance
//! `D = √((ρ − R)² + y²)` from the core circle lies in `[r_min, r_max]` and whose angle
//! φ about the axis lies in `[φ₀, φ₀ + Δφ]`. Its boundary has up to four faces
//! ([`BendFace`]): the outer torus (r_max), the inner torus (the bore, r_min > 0), and
//! the two end caps, annuli in the half-planes φ = φ₀ and φ = φ₀ + Δφ.
//!
//! **Method** (docs/bend.md). The candidates are every root of the outer torus's quartic
//! and of the inner one's (the ring torus's solver, `crate::intersect`), and the line's
//! meeting with each cap's plane. Sorted, they cut the ray's range into intervals, and the
//! side of each (inside the solid or not) is read off the solid itself at the interval's
//! midpoint: a candidate is a crossing where the side changes, of the face it came from.
//! So a torus root outside the segment, or a plane point off its annulus, is dropped by
//! construction, and no rule of parity is needed where faces meet at the caps' edges.
//!
//! **Rays from a surface point** ([`crate::Ray::from_surface`], [`PipeBend::spawn`]): the
//! origin's face is found (the nearest within reach; both faces at a cap's edge), a torus
//! face's own root is divided out as for the ring torus (docs/math.md §9), a cap's plane
//! root is dropped (a line meets a plane once, and the origin is that point), and the
//! first interval's side is read past the origin: no self-hit, and no ε.
//!
//! **Scope.** The solid is answered in f64. The whole torus (no bore, Δφ = 2π) is the
//! ring torus, and answers bit for bit as its [`crate::Torus`]. The certified f32 path
//! ([`PipeBend::intersect_f32`]) and the SIMD lanes (`batch::Wavefront::intersect_bend`)
//! answer a cut bend's misses of the outer torus themselves and hand every other ray to
//! the f64 solid, counted. The GPU takes a `Torus`: [`PipeBend::as_torus`] hands over the
//! whole torus's and refuses a cut one ([`BendError::NotWhole`]).

mod crossings;
mod f32;
mod iter;
mod point_query;
mod solid;
mod spawn;
mod wedge;
mod wedge_cull;

pub use crossings::{BendCrossing, BendCrossings, BendHit};
pub use f32::BendF32Hit;
pub use point_query::BendProjection;
pub use solid::{BendError, BendFace, MIN_WALL_REL, PipeBend};
pub use wedge_cull::WedgeCull;

#[cfg(test)]
mod near_tangent_tests;
#[cfg(test)]
mod point_query_tests;
#[cfg(test)]
mod tests;
