//! The torus family: elliptical tubes, and horn and spindle tori ([`Toroid`]).
//!
//! A member has major radius R and a tube that is an ellipse with semi-axes `a`
//! (radial, in the equatorial plane) and `b` (along the axis):
//! `((ρ − R)/a)² + (y/b)² ≤ 1` in the torus frame, ρ ≥ 0 the distance from the axis.
//! That is OpenMC's and MCNP's z-torus (A = R, B = b, C = a), Celeritas' `Toroid`
//! (r = R, a, b), and for a = b Bevy's `Torus` (major R, minor a; its `TorusKind` is
//! [`ToroidKind`]).
//!
//! **One image.** The map `S: (x, y, z) ↦ (x, y·a/b, z)` takes the member onto the
//! circular torus (R, a) and a line `o + t·d` onto the line `S o + t·S d`, with the same
//! `t` at every point. So every query is the circular torus's on the image line: the
//! exact intersection ([`crate::intersect()`]'s solver), every crossing
//! ([`crate::intersect_all`]'s), and every cull, which stays conservative because a
//! line misses the member exactly when its image misses the image torus. A normal maps
//! back by `Sᵀ`: `(n_x, n_y·a/b, n_z)`, normalized. For a = b the image is the member
//! itself and nothing is scaled, so a circular ring member answers bit for bit as its
//! [`crate::Torus`].
//!
//! **Horn and spindle (R ≤ a): the apple.** The surface is the boundary of the solid of
//! revolution, whose points have ρ ≥ 0: the outer "apple". The quartic of the image also
//! vanishes on the inner "lemon" `(ρ + R)² + y² = a²`, which bounds nothing (it lies inside
//! the apple); its roots are dropped by the sign of `s = |x|² + R² − a²` at the root
//! (`s = 2Rρ` on the apple, `−2Rρ` on the lemon), OpenMC's sign test (docs/family.md).
//!
//! **Scope.** Everything here runs in f64, scalar. The SIMD lanes, the certified f32 path
//! and the GPU take a [`crate::Torus`]: a circular ring member hands them its own
//! ([`Toroid::as_torus`]); the others are refused there with
//! [`ToroidError::NotCircular`], and [`Toroid::intersect_f32`] answers them in f64,
//! counted as escalated.

mod ellipse;
mod intersect;
mod point_query;
mod toroid;

pub use point_query::FamilyPointError;
pub use toroid::{MAX_ASPECT, MIN_ASPECT, MIN_FAMILY_NU, Toroid, ToroidError, ToroidKind};

#[cfg(test)]
mod tests;
