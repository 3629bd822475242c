//! Adapters to other crates' shape APIs, each behind its own feature (the library's default
//! dependencies stay glam and pulp):
//!
//! * [`parry`] (feature `parry`, parry3d 0.31): the torus, and over the [`crate::Solid`]
//!   interface the family member and the pipe bend, as parry3d shapes, answering parry's
//!   ray casts and point queries with the library's exact ones.
//! * [`bevy`] (feature `bevy`, bevy_shape and bevy_math 0.20; Rust 1.94, Bevy's minimum,
//!   where the library alone needs 1.85): Bevy's `Torus` with an `Isometry3d` to the
//!   library's torus or family member, and a ray cast with the signature of Bevy's
//!   proposed `local_ray_cast`.
//!
//! Both speak glam 0.33 (their own); the library's glam (0.34) is converted to at the
//! boundary, component by component, so no value changes on the way.

#[cfg(feature = "bevy")]
pub mod bevy;
#[cfg(feature = "parry")]
pub mod parry;
