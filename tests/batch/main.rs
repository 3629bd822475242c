//! Batch (SIMD) mode, the wavefront, certified f32 and the BVH, against the scalar path and
//! the oracle.
//!
//! One test crate (one link step); each module was its own crate before.

#[path = "../common/mod.rs"]
mod common;

mod batch;
mod batch_bvh;
mod batch_solve;
mod batch_wavefront;
mod bvh;
mod bvh_family;
mod bvh_rays;
mod certified_f32;
