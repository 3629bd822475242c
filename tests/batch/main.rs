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
mod bend_paths;
mod bvh;
mod bvh_family;
mod bvh_rays;
mod certified_f32;
mod renderer_rays;

/// Every dispatch level this machine runs (scalar and each SIMD width it has), forced: the
/// batch paths are checked at each, not only at the widest.
fn dispatch_levels() -> Vec<torus_cull::batch::Dispatch> {
    torus_cull::batch::Isa::available()
        .into_iter()
        .map(|isa| torus_cull::batch::Dispatch::forced(isa).unwrap())
        .collect()
}
