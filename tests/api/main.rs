//! The public API on any bits, and the house itself: imports that point down, paths in the
//! text that exist.
//!
//! One test crate (one link step); each module was its own crate before.

#[path = "../common/mod.rs"]
mod common;

mod api_bit_patterns;
mod layout;
mod new_shape;
mod package;
mod phi_convention;
mod refused_inputs;
mod rust_version;
mod solid_client;
