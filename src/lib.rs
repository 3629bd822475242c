//! # torus-cull-lab
//!
//! **The lab** that measures the `torus_cull` library: everything behind the `torus-cull`
//! command and `cargo bench`. A renderer links the library alone and never this crate (nor
//! its clap, plotters, serde, rand, obvhs, …).
//!
//! * Ground truth: [`oracle`], the independent f64 labels (hit / miss / ambiguous with a
//!   margin); it shares no code with the timed path, so it can catch its bugs.
//! * Rays: [`workload`], the seeded generators per case (hole, outer band, grazing,
//!   uniform, camera, and the adversarial line families) and the workload files.
//! * Counting and timing: [`measure`] (rejection counts against the oracle) and
//!   [`paired`] (culls timed against each other in interleaved rounds, so ratios hold on a
//!   loaded machine).
//! * Many tori: [`scene`], an obvhs BVH with a cull at the leaves, and [`render`], its
//!   picture and cull map.
//! * Output: [`results`] (the results JSON), [`compare`], [`report`] (tables), [`plot`]
//!   (SVG), [`eval`] (a user's own rays) and [`output`] (how every file is written).
//! * Test fixtures: [`errata`], the seed paper's culls as printed, which are **not
//!   conservative**; they exist to prove that the oracle catches a broken cull.

pub mod check;
pub mod check_counts;
pub mod compare;
pub mod count;
pub mod errata;
pub mod eval;
pub mod family_label;
pub mod lab_shape;
pub mod measure;
pub mod named;
pub mod number;
pub mod oracle;
pub mod output;
pub mod paired;
pub mod peer_f32;
pub mod plot;
pub mod precision;
pub mod random;
pub mod render;
pub mod report;
pub mod results;
pub mod results_file;
pub mod scene;
pub mod scene_kind;
pub mod shape_sweep;
pub mod solver_suite;
pub mod summary;
pub mod workload;
