//! Paired, interleaved timing ratios: how much faster or slower one cull is than a
//! reference, measured so that the machine's load cancels out.
//!
//! On a shared machine the speed of the CPU drifts by 10–20 % within minutes (steal time,
//! frequency changes, other processes), so the ratio of two timings taken seconds apart
//! measures the drift as much as the code. Here every figure is a ratio of timings taken
//! **within one round** of about a millisecond:
//!
//! 1. All contenders (each cull's `total_ns` path and its cull alone, `cull_ns`) run on
//!    the same batch of rays, once per round, in an order shuffled anew each round
//!    (seeded Pcg64), after a warm-up.
//! 2. Each round gives one ratio per contender, `t(cull) / t(reference)`, with the
//!    references `cychosz` and `none`. A change of load that lasts longer than a round
//!    scales both timings alike and cancels.
//! 3. Every (case, ν) is visited in turn for about 0.1 s, over and over until the time is
//!    spent, so a spell of load that lasts seconds falls on all of them alike.
//! 4. Rounds in which the operating system switched the thread out (or the round
//!    after, which starts on another process's caches) are set aside, and of the rest
//!    the quietest quarter is kept: the rounds in which all contenders together ran
//!    fastest. A shared machine has slower spells lasting seconds that slow
//!    throughput-bound code more than latency-bound code, so they change the ratios
//!    themselves, not just the timings; load only ever adds time, so the fastest rounds
//!    are the least disturbed.
//! 5. The figure is the **median of the kept rounds' ratios**, with a percentile
//!    bootstrap 95 % interval of that median (2000 seeded resamples), and the per-ray
//!    median nanoseconds of both sides.
//!
//! The interval says how well this run pinned its own figure down. It does not cover
//! what moves a whole run: code and data placement, a slow spell that lasts the whole
//! run (on a loaded virtual machine the cull-alone ratios can then move by 10–20 % from
//! run to run, the `total_ns` ratios by a few percent). [`runs`] measures that: K
//! independent runs, each in a fresh layout, combined into a between-run interval beside
//! the within-run one.
//!
//! A ratio below 1 means the cull is faster than the reference (0.25: four times as
//! fast); 1/ratio is the median speedup (exactly so for an odd number of rounds).
//!
//! [`stats`] holds the median, the bootstrap and the choice of quiet rounds, [`engine`]
//! the rounds, [`switches`] the context-switch count, [`contender`] the per-cull timed
//! loops, [`sweep`] the workload driver that makes
//! [`RatioRecord`](crate::results::RatioRecord)s; the verdicts of `torus-cull compare` on
//! them are [`crate::compare`]'s.

pub mod bend;
pub mod bvh;
pub mod contender;
pub mod engine;
pub mod family;
#[cfg(feature = "gpu")]
pub mod gpu_bvh;
pub mod runs;
pub mod shapes;
pub mod stats;
pub mod sweep;
pub mod switches;

pub use contender::Metric;
pub use engine::{Interleaver, Rounds, Schedule, interleave};
pub use runs::{between_run_interval, combine_runs};
pub use stats::{RatioEstimate, bootstrap_median_ci, median, ratio_estimate};
pub use sweep::{PairedOptions, REFERENCES, Unit, time_batch, time_units, time_workload};
