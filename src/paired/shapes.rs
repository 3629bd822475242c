//! Paired timing of the shapes beyond the ring torus: named contenders over one ray set,
//! interleaved in the module's rounds (docs of [`super`]), each of `runs` runs keeping
//! its quietest quarter of rounds ([`super::stats::quiet_rounds`]) and giving a median
//! ratio with its bootstrap interval; the runs' ratios give the between-run interval
//! ([`super::runs::between_run_interval`]). [`super::family`] and [`super::bend`] name
//! the contenders.

use super::engine::{Schedule, interleave};
use super::runs::between_run_interval;
use super::stats::{QUIET_FRACTION, quiet_rounds, ratio_estimate};
use super::sweep::undisturbed;
use std::time::Duration;

/// One paired ratio of a shape's timing.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct ShapeRatio {
    /// What is timed: `exact` (the shape, no cull), a cull's name (its `total_ns`), or
    /// `wedge+<cull>` (a pipe bend's wedge with that cull).
    pub contender: String,
    /// Against what: another contender's name (`cychosz`, `exact`, `circular_exact`,
    /// `circular_exact_on_images`).
    pub reference: String,
    /// The geometric mean of the runs' median ratios.
    pub ratio: f64,
    /// Each run's median ratio.
    pub run_ratios: Vec<f64>,
    /// The first run's bootstrap 95 % interval (within-run).
    pub within: [f64; 2],
    /// The 95 % interval over the runs; `None` for a single run.
    pub between: Option<[f64; 2]>,
    /// The contender's median ns per ray (first run).
    pub ns_per_ray: f64,
}

/// A contender against a reference, by index into the contenders, with their names.
pub type Pair = (usize, usize, String, String);

/// The paired ratios `pairs` of `contenders` timings: for each of `runs` runs of about
/// `seconds`, `fresh(run)` gives that run's timer (its own copy of the rays: a run's
/// layout is its own, module docs of `super::runs`), called with a contender's index
/// once per round. `work` rays per timing. `None` for no run or a run without rounds.
pub fn time_contenders<F: FnMut(usize) -> Duration>(
    contenders: usize,
    pairs: Vec<Pair>,
    (runs, seconds, seed): (usize, f64, u64),
    work: usize,
    mut fresh: impl FnMut(usize) -> F,
) -> Option<Vec<ShapeRatio>> {
    if runs == 0 || work == 0 {
        return None;
    }
    let mut per_run: Vec<Vec<(f64, [f64; 2], f64)>> = vec![Vec::new(); pairs.len()];
    for run in 0..runs {
        let schedule = Schedule {
            warm_up: Duration::from_secs_f64(0.1 * seconds),
            budget: Duration::from_secs_f64(0.9 * seconds),
            min_rounds: 20,
            max_rounds: 100_000,
            seed: seed.wrapping_add(run as u64),
        };
        let rounds = interleave(contenders, &schedule, fresh(run));
        let kept = quiet_rounds(&rounds.ns, &undisturbed(&rounds.disturbed), QUIET_FRACTION);
        let pick = |c: usize| -> Vec<f64> { kept.iter().map(|&k| rounds.ns[c][k]).collect() };
        for (slot, &(c, r, _, _)) in per_run.iter_mut().zip(&pairs) {
            let est = ratio_estimate(&pick(c), &pick(r), work as f64, seed ^ c as u64)?;
            slot.push((est.ratio, est.ratio_ci, est.ns_per_ray));
        }
    }
    Some(
        pairs
            .into_iter()
            .zip(per_run)
            .map(|((_, _, contender, reference), runs)| {
                let run_ratios: Vec<f64> = runs.iter().map(|r| r.0).collect();
                let log_mean =
                    run_ratios.iter().map(|r| r.ln()).sum::<f64>() / run_ratios.len() as f64;
                ShapeRatio {
                    contender,
                    reference,
                    ratio: log_mean.exp(),
                    between: between_run_interval(&run_ratios),
                    run_ratios,
                    within: runs[0].1,
                    ns_per_ray: runs[0].2,
                }
            })
            .collect(),
    )
}
