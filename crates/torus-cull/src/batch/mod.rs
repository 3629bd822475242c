//! Batch (SIMD) culls: many lines at once, branch-free, one keep bit per line.
//!
//! A renderer that traces packets or wavefronts has the rays of a batch side by side;
//! there the cost model of a cull changes. A branch-free cull over 8 or 16 lanes costs
//! its instructions divided by the lane count per ray, the keep/reject branches that a
//! scalar loop mispredicts vanish, and what remains is the solve of the survivors.
//!
//! * [`Lines`]: torus-frame lines as structure of arrays ([`Lines::from_rays`] builds
//!   them from world rays with [`crate::Torus::line_to_local`], the scalar path's own
//!   transform).
//! * [`cull_batch`]: one cull over every line, into a [`KeepMask`]. The culls with a batch
//!   form are [`BatchCull`] ([`crate::CullKind::batched`] converts). Each cull is written
//!   once in [`crate::cull`], generic over the lane width; the scalar cull is the same
//!   kernel at width 1, so the verdicts are bit-identical (`tests/batch/batch.rs` checks it at
//!   every dispatch level).
//! * [`Dispatch`] and [`Isa`]: the instruction set, detected at run time (AVX-512, AVX2,
//!   NEON, or the scalar fallback) and recorded in `meta.isa`; `TORUS_CULL_ISA` forces a
//!   lower one.
//!
//! * [`nearest_roots`]: the nearest root of many depressed quartics ([`Quartics`]) at
//!   once on f64 lanes, the scalar solver's method branch-free, its rare careful cases
//!   handed back to it.
//! * [`Wavefront`]: the two together for a batch of world rays: cull, compact the
//!   survivors, batch-solve, hits; the `"mode": "batch"` timings of `cargo bench`.
//!
//! The lab's BVH scenes use the wavefront at their leaves (`torus_cull_lab::scene::batched`).
//!
//! ```
//! use torus_cull::batch::{BatchCull, Dispatch, KeepMask, Lines, Wavefront, cull_batch};
//! use torus_cull::{CullKind, Ray, Torus, intersect_culled};
//! use glam::Vec3;
//!
//! let torus = Torus::new(Vec3::ZERO, Vec3::Y, 4.0, 1.0)?;
//! // A row of rays straight down: through the hole (|x| < 3), the tube, and outside.
//! let rays = (0..64)
//!     .map(|i| Ray::new(Vec3::new(i as f32 * 0.125 - 4.0, 10.0, 0.0), Vec3::NEG_Y))
//!     .collect::<Result<Vec<_>, _>>()?;
//! let dispatch = Dispatch::best(); // AVX-512, AVX2, NEON or scalar, at run time
//!
//! // The cull alone: one keep bit per ray, the scalar verdict bit for bit.
//! let mut keep = KeepMask::new();
//! let lines = Lines::from_rays(&torus, &rays); // in the torus frame, as the culls see them
//! cull_batch(&dispatch, BatchCull::Skala, torus.bounds(), &lines, &mut keep);
//! assert!(!keep.get(32)); // x = 0: down the middle of the hole
//! assert!(keep.get(0)); // x = −4: down through the tube
//!
//! // Cull, compact the survivors, intersect them on f64 lanes.
//! let mut wavefront = Wavefront::new();
//! let mut hits = Vec::new();
//! let stats = wavefront.intersect(&dispatch, BatchCull::Skala, &torus, &rays, &mut hits);
//! assert_eq!(stats.kept, keep.count_kept());
//! for (ray, hit) in rays.iter().zip(&hits) {
//!     let scalar = intersect_culled(&CullKind::Skala, &torus, ray);
//!     assert_eq!(hit.is_some(), scalar.is_some());
//! }
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! The lanes are [pulp](https://crates.io/crates/pulp)'s: one generic kernel, compiled
//! for each level with `#[target_feature]`, picked by a runtime check, on stable Rust.
//! Why pulp: it dispatches at run time to AVX-512, AVX2 + FMA, NEON or a scalar fallback
//! from one binary (`wide` picks its width at compile time; `std::simd` needs nightly and
//! has no dispatch of its own; `multiversion` clones functions but leaves vectorizing to
//! the compiler, which branchy culls defeat), it exposes every operation explicitly, so
//! nothing is fused or reordered behind the code's back (the bit-identity above rests on
//! that), and it gives AVX-512 masks as bit masks, one instruction from a keep bit
//! mask. `fearless_simd` (1.x, also with runtime dispatch and an AVX-512 level) is the
//! closest alternative; pulp was taken for its longer record (the SIMD layer of `faer`)
//! and its mask-register support, not by a measurement of both on this code.

mod bend;
mod certified;
mod cull;
mod intersect;
mod lines;
mod mask;
mod solve;
mod to_local;
mod wavefront;

pub use crate::cull::{BATCHED, BatchCull};
pub use crate::num::{Dispatch, ISA_ENV, Isa, IsaError};
pub use cull::cull_batch;
pub use lines::{BLOCK, Lines};
pub use mask::KeepMask;
pub use solve::{Quartics, SolveStats, nearest_roots};
pub use wavefront::{Wavefront, WavefrontStats};

#[cfg(test)]
mod tests;
