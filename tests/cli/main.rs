//! The `torus-cull` command end to end: run, time, eval, f32-check, compare, intervals,
//! their files and their errors.
//!
//! One test crate (one link step); each module was its own crate before.

#[path = "../common/mod.rs"]
mod common;

mod adversarial_rows;
mod bend_cli;
mod check_cli;
mod check_ring_f32;
mod count_cli;
mod eval_cli;
mod eval_wedge_cli;
mod family_cli;
mod issue36_cli;
mod issue52_cli;
mod nothing_lost_cli;
mod outputs_cli;
mod results_compare;
mod results_index;
mod run_cli;
mod run_shapes_cli;
mod summarize_cli;
mod support;
mod time_cli;
mod time_flags_cli;
