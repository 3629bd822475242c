//! The WGSL kernel and the includable WGSL modules on whatever adapter wgpu finds (feature
//! `gpu`).
//!
//! One test crate (one link step); each module was its own crate before.

#[path = "../common/mod.rs"]
mod common;

mod gpu;
mod gpu_bvh;
mod scene;
mod wgsl_module;
