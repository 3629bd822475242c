//! Culls: cheap tests that prove a line cannot hit the torus, so the quartic is skipped.
//!
//! Every cull is a **line** test in the torus frame (centre at the origin, axis +y) and is
//! therefore conservative for any ray on that line. A cull returns `true` to *keep* the
//! line (the exact intersection must run) and `false` to *reject* it (proven miss).
//!
//! Each cull lives in its own file, written **once** for every lane width: a kernel generic
//! over the number trait `Real32` (`num::real`; `kernel`'s `CullKernel`) whose
//! instantiation at width 1 is the one-line [`Cull::keeps`] and whose instantiation at
//! AVX2, AVX-512 or NEON is the batch cull of [`crate::batch::cull_batch`]. The module
//! splits into
//! * `kernel`: the [`Cull`] trait, [`CullVisitor`], the kernel shape, and the bounds in
//!   lanes ([`LaneBounds`]);
//! * `steps`: the scale steps every cull shares (the foot point, rescaling); the
//!   per-torus constants with their safety margin, [`CullBounds`], belong to the torus;
//! * `registry`: [`CullKind`], the registry by stable name, used in results, the CLI and
//!   the plots; its [`CullKind::visit`] hands a concrete cull type to generic code, so that
//!   benchmark and BVH loops are monomorphized per cull instead of paying a dynamic
//!   dispatch per ray; [`BatchCull`] names the culls with a batch form ([`BATCHED`]).
//!
//! # Floating-point safety margin
//! Exact arithmetic is conservative, rounding is not: a plain f32 evaluation rejects some
//! lines that graze the surface. Every timed cull therefore tests the torus `T_η` whose
//! tube radius is inflated to `r + η` with `η = SAFETY_REL · (R + r)` (see [`CullBounds`]).
//! Any error that acts like moving the line, or a plane through it, by less than `η` is
//! absorbed: every point within `η` of the true torus lies inside `T_η`. The errors of the
//! world→torus transform and of the foot-point shift are about `4·2⁻²⁴·|o − c|`, so the
//! margin covers origins with `|o − c| ≤ 256·(R + r)`. [`crate::Torus::line_to_local`]
//! moves origins beyond 64·(R + r) to the line's foot point in f64, so every origin is
//! covered; lines built by hand must stay within that distance. The squares in the culls
//! bound the torus size: see [`crate::MIN_OUTER_RADIUS`] and [`crate::MAX_OUTER_RADIUS`].

pub(crate) mod kernel;
mod registry;
mod steps;
pub(crate) mod table;

pub use crate::geometry::{CullBounds, SAFETY_REL};
// Every cull's module (`aabb`, `cychosz`, …) and its type (`AabbCull`, `CychoszCull`, …),
// from the table's rows.
use table::export_culls;
export_culls!(modules);
export_culls!(cull);
#[doc(hidden)]
pub use kernel::LaneBounds;
pub use kernel::{Cull, CullVisitor};
#[cfg(feature = "gpu")]
pub(crate) use quadric::HORIZONTAL_DY;
pub(crate) use registry::KernelVisitor;
pub use registry::{BATCHED, BatchCull, CullKind};
pub use steps::foot_point;
pub(crate) use steps::{AXIS_PARALLEL_H2, moderate, rescaled};
pub use table::Shape;
// The paper-as-printed fixtures (the lab's `errata`) reuse the section formulas; not
// renderer API.
#[doc(hidden)]
pub use skala::{SectionFormulas, skala_keeps};
