//! The quartic solvers against their peers and the published corpus.
//!
//! One test crate (one link step); each module was its own crate before.

#[path = "../common/mod.rs"]
mod common;

mod quartic_corpus_peers;
mod solver_peers;
