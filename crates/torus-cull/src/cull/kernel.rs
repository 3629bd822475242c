//! The cull trait ([`Cull`], one line at a time), its visitor ([`CullVisitor`]), and the one
//! kernel behind both the scalar and the lane form of each cull ([`CullKernel`]).
//!
//! **One source.** Each cull is written once, as a [`CullKernel`]: a function generic over
//! the number trait [`Real32`] (the solver's [`crate::num::Real`] on f32 lanes), with the
//! torus's bounds lifted into lanes once ([`LaneBounds`]). At `F32s<pulp::Scalar>` (one
//! `f32`, masks `bool`) the kernel *is* the scalar cull ([`keeps_scalar`], what every
//! [`Cull::keeps`] calls), and at AVX2, AVX-512 or NEON it is the batch cull of
//! [`crate::batch::cull_batch`]. The two agree bit for bit by construction: the same
//! operations in the same order, no fused multiply-add (see `src/num/lanes.rs`);
//! `tests/batch/batch.rs` checks it at every dispatch level.

use super::{CullBounds, Shape};
use crate::num::{Real, Real32, V3, Vec3s};
use glam::Vec3;
use pulp::Scalar;

/// A bounding test for one torus in its own frame.
///
/// `keeps` is a **line** test: `origin + t·dir` for all real t, `dir` finite and non-zero
/// of any length. `false` means the line provably misses the torus.
///
/// It is the low-level form, in the torus frame: the line from
/// [`crate::Torus::line_to_local`] (of a `Ray` or a `DRay`) and the bounds
/// from [`crate::Torus::bounds`] of the same torus. Bounds come only from a validated
/// [`crate::Torus`], so a torus without a hole (R ≤ r) cannot reach a cull.
/// [`crate::intersect_culled`] and [`crate::Torus::with_cull`] do both steps for a world
/// ray.
///
/// ```
/// use glam::Vec3;
/// use torus_cull::{Cull, CychoszCull, NoCull, Ray, SkalaCull, Torus};
/// let torus = Torus::new(Vec3::new(0.0, 0.0, 5.0), Vec3::Y, 4.0, 1.0)?;
/// // Through the hole along the axis: a line that misses, in the torus's frame.
/// let hole = torus.line_to_local(&Ray::new(Vec3::new(0.0, 10.0, 5.0), Vec3::NEG_Y)?);
/// assert!(!SkalaCull.keeps(torus.bounds(), hole.origin, hole.dir));
/// assert!(NoCull.keeps(torus.bounds(), hole.origin, hole.dir)); // keeps every line
/// // A line through the tube is kept by every cull (they are conservative).
/// let tube = torus.line_to_local(&Ray::new(Vec3::new(4.0, 10.0, 5.0), Vec3::NEG_Y)?);
/// assert!(SkalaCull.keeps(torus.bounds(), tube.origin, tube.dir));
/// assert!(CychoszCull.keeps(torus.bounds(), tube.origin, tube.dir));
/// assert_eq!(SkalaCull.name(), "skala");
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub trait Cull {
    /// The stable name used in results, the CLI and plots.
    fn name(&self) -> &'static str;

    /// `true` to keep the line (run the quartic), `false` to reject it.
    #[must_use]
    fn keeps(&self, bounds: &CullBounds, origin: Vec3, dir: Vec3) -> bool;

    /// The shapes of the torus family this cull is proved conservative for (the table's
    /// `shapes` column, [`crate::CullKind::shapes`]). A family member of another shape
    /// ([`crate::family::Toroid`]) declines the cull and runs its exact intersection
    /// alone. A cull outside the table accepts the ring torus only.
    #[must_use]
    fn shapes(&self) -> &'static [Shape] {
        &[Shape::Ring]
    }
}

/// Generic code that runs with a concrete cull type; see [`super::CullKind::visit`].
pub trait CullVisitor {
    /// What the visit returns.
    type Output;
    /// Called once with the concrete cull.
    fn visit<C: Cull>(self, cull: C) -> Self::Output;
}

/// A cull written once for every lane width: the verdict for each lane's line, true keeps
/// it. Instantiated at [`pulp::Scalar`] it is the scalar cull ([`keeps_scalar`]).
///
/// Where a scalar cull would leave early, the kernel evaluates every case and selects (a
/// lane cannot leave alone); an early exit is kept only as "no lane is still undecided",
/// which at width 1 is the scalar early exit.
pub(crate) trait CullKernel: Copy {
    /// The keep mask of the lines `o + t·d`, one per lane.
    fn keeps_lanes<R: Real32>(self, b: &LaneBounds<R>, o: V3<R>, d: V3<R>) -> R::Mask;
}

/// `LaneBounds` from the rows of the table of per-torus constants
/// (`crate::geometry::cull_bounds_table`) that have the form `lanes`.
macro_rules! define_lane_bounds {
    ($($field:ident: $ty:ty [$($lanes:ident $($gpu:ident $wgsl:ident)?)?], $doc:literal;)*) => {
        /// A torus's [`CullBounds`] in lanes: each constant in every lane, made once per
        /// torus (per batch, or per scalar call, where it is free) instead of in every
        /// kernel step.
        #[doc(hidden)]
        #[derive(Debug, Clone, Copy)]
        pub struct LaneBounds<R> {
            $($(#[doc = $doc] #[cfg_attr(any(), doc = stringify!($lanes))] pub $field: R,)?)*
        }

        impl<R: Real> LaneBounds<R> {
            /// `b`'s constants in every lane, with `like`'s SIMD token (see [`CullBounds`]
            /// for what each one is).
            #[inline(always)]
            pub fn new(b: &CullBounds, like: R) -> Self {
                LaneBounds {
                    $($($field: define_lane_bounds!(@k like, b.$field, $lanes),)?)*
                }
            }
        }
    };
    // A field of a row with the form `$flag`: the flag only selects the row.
    (@k $like:ident, $value:expr, $flag:ident) => { $like.k($value) };
}
crate::geometry::cull_bounds_table!(define_lane_bounds);

/// The kernel at width 1: the scalar cull.
#[inline(always)]
pub(crate) fn keeps_scalar<K: CullKernel>(
    kernel: K,
    b: &CullBounds,
    origin: Vec3,
    dir: Vec3,
) -> bool {
    let s = Scalar::new();
    let (o, d) = (Vec3s::splat(s, origin), Vec3s::splat(s, dir));
    kernel.keeps_lanes(&LaneBounds::new(b, o.x), o, d).m
}

/// Declares a cull, `pub struct $cull = "$name";` with its docs, and its [`Cull`] impl: the
/// stable name, and [`Cull::keeps`] as the cull's [`CullKernel`] at [`pulp::Scalar`].
macro_rules! scalar_cull {
    ($(#[$doc:meta])* pub struct $cull:ident = $name:literal;) => {
        $(#[$doc])*
        #[derive(Debug, Clone, Copy, Default)]
        pub struct $cull;

        impl $crate::cull::Cull for $cull {
            fn name(&self) -> &'static str {
                $name
            }

            fn shapes(&self) -> &'static [$crate::cull::Shape] {
                $cull::SHAPES
            }

            #[inline(always)]
            fn keeps(&self, b: &$crate::CullBounds, origin: glam::Vec3, dir: glam::Vec3) -> bool {
                $crate::cull::kernel::keeps_scalar(*self, b, origin, dir)
            }
        }
    };
}
pub(crate) use scalar_cull;
