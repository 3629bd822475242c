//! Paired timing of the shapes beyond the ring torus: named contenders over one ray set,
//! interleaved in the module's rounds (docs of [`super`]), each of `runs` runs keeping
//! its quietest quarter of rounds ([`super::stats::quiet_rounds`]) and giving a median
//! ratio with its bootstrap interval; the runs' ratios give the between-run interval
//! ([`super::runs::between_run_interval`]). [`super::family`] and [`super::bend`] name
//! the contenders.

use super::engine::{Schedule, interleave, timed_pass};
use super::runs::{between_run_interval, pooled_within_interval};
use super::stats::{QUIET_FRACTION, RatioEstimate, quiet_rounds, ratio_estimate};
use super::sweep::undisturbed;
use crate::results::{CPU_DEVICE, F64_PRECISION, RatioRecord};
use crate::workload::box_rays::box_rays;
use std::time::Duration;
use torus_cull::{Cull, CullVisitor, Ray};

/// One paired ratio of a shape's timing.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct ShapeRatio {
    /// What is timed: `exact` (the shape, no cull), a cull's name (its `total_ns`), or
    /// `wedge+<cull>` (a pipe bend's wedge with that cull).
    pub contender: String,
    /// Against what: another contender's name (`cychosz`, `none`, `circular_exact`,
    /// `circular_exact_on_images`).
    pub reference: String,
    /// The geometric mean of the runs' median ratios.
    pub ratio: f64,
    /// Each run's median ratio.
    pub run_ratios: Vec<f64>,
    /// The runs' bootstrap 95 % intervals pooled (within-run: how well the rounds pinned
    /// the ratio down, [`pooled_within_interval`]).
    pub within: [f64; 2],
    /// The 95 % interval over the runs; `None` for a single run.
    pub between: Option<[f64; 2]>,
    /// The contender's median ns per ray (first run).
    pub ns_per_ray: f64,
    /// The reference's median ns per ray over the same rounds (first run).
    pub reference_ns_per_ray: f64,
    /// Rounds behind the first run's ratio (its quiet ones), and measured in it.
    pub rounds: (u64, u64),
}

impl ShapeRatio {
    /// This ratio as a results file's `ratio` record, so that `compare`, `intervals` and
    /// the report read it as they read the ring torus's: `case` names the shape, `nu` is
    /// R over its tube's radial size, `metric` is `family_total_ns` or `bend_total_ns`
    /// ([`SHAPE_METRICS`]), `rays` the batch.
    #[must_use]
    pub fn record(&self, case: &str, nu: f64, metric: &str, rays: usize) -> RatioRecord {
        RatioRecord {
            case: case.to_string(),
            nu,
            cull: self.contender.clone(),
            reference: self.reference.clone(),
            metric: metric.to_string(),
            ratio: self.ratio,
            ratio_ci: self.within,
            rounds: self.rounds.0,
            rounds_measured: self.rounds.1,
            rays: rays as u64,
            ns_per_ray: self.ns_per_ray,
            reference_ns_per_ray: self.reference_ns_per_ray,
            precision: F64_PRECISION.to_string(),
            device: CPU_DEVICE.to_string(),
            escalation_rate: None,
            runs: self.run_ratios.len() as u64,
            runs_set_aside: 0,
            run_ratios: if self.run_ratios.len() > 1 {
                self.run_ratios.clone()
            } else {
                Vec::new()
            },
            ratio_ci_between: self.between,
            run_spread: None,
        }
    }
}

/// The metrics of the shapes beyond the ring torus: a torus family member's and a pipe
/// bend's per-ray total (cull + exact intersection), decisive in `compare` as `total_ns`.
pub const SHAPE_METRICS: [&str; 2] = ["family_total_ns", "bend_total_ns"];

/// A shape that `time family`, `time bend` and `cargo bench` time (a torus family
/// member, a pipe bend): its case in a results file, its ray box and its ratios.
pub trait TimedShape {
    /// Its records' metric, one of [`SHAPE_METRICS`].
    const METRIC: &'static str;
    /// (R, a, b) of the box its uniform rays are drawn at; the records' ν is R/a.
    fn box_radii(&self) -> (f64, f64, f64);
    /// Its case in a results file.
    fn case_name(&self) -> String;
    /// Its ratios on `rays` from `timing` = (runs, seconds, seed): that many runs of about
    /// that many seconds each, as [`time_contenders`] takes them; `None` for an empty ray
    /// set or a run without rounds.
    fn ratios(&self, rays: &[Ray], timing: (usize, f64, u64)) -> Option<Vec<ShapeRatio>>;
    /// Whether the shape behind `cull` (its `intersect_culled`) hits `ray`: what
    /// [`CulledPass`] times.
    fn hit_culled<C: Cull>(&self, cull: &C, ray: &Ray) -> bool;
}

/// One timed pass of a shape behind a cull over the rays ([`TimedShape::hit_culled`]),
/// monomorphized per cull and shape.
pub struct CulledPass<'a, S> {
    /// The shape.
    pub shape: &'a S,
    /// The rays.
    pub rays: &'a [Ray],
}

impl<S: TimedShape> CullVisitor for CulledPass<'_, S> {
    type Output = Duration;

    #[inline(never)]
    fn visit<C: Cull>(self, cull: C) -> Duration {
        let shape = self.shape;
        timed_pass(self.rays, |ray, (): &mut ()| shape.hit_culled(&cull, ray))
    }
}

/// Every shape of `shapes` timed on `batch` uniform rays at its box (seeded per shape
/// from `seed`), `runs` runs of `seconds` each, as `ratio` records; `shown` sees each
/// shape's ratios as they come.
///
/// # Errors
///
/// A shape without rounds (too short a time), named by its case.
pub fn shape_records<S: TimedShape>(
    shapes: &[S],
    seed: u64,
    batch: usize,
    (runs, seconds): (usize, f64),
    mut shown: impl FnMut(&S, &[ShapeRatio]),
) -> Result<Vec<RatioRecord>, String> {
    let mut records = Vec::new();
    for (i, shape) in shapes.iter().enumerate() {
        let (big, a, b) = shape.box_radii();
        let rays = box_rays(big, a, b, batch, seed.wrapping_add(i as u64));
        let case = shape.case_name();
        let ratios = shape
            .ratios(&rays, (runs, seconds, seed))
            .ok_or_else(|| format!("{case}: no rounds (raise the time)"))?;
        shown(shape, &ratios);
        records.extend(
            ratios
                .iter()
                .map(|r| r.record(&case, big / a, S::METRIC, rays.len())),
        );
    }
    Ok(records)
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
    // Per pair, each run's estimate and the rounds it measured.
    let mut per_run: Vec<Vec<(RatioEstimate, u64)>> = vec![Vec::new(); pairs.len()];
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
            slot.push((est, rounds.ns[c].len() as u64));
        }
    }
    Some(
        pairs
            .into_iter()
            .zip(per_run)
            .map(|((_, _, contender, reference), runs)| {
                let run_ratios: Vec<f64> = runs.iter().map(|r| r.0.ratio).collect();
                let run_cis: Vec<[f64; 2]> = runs.iter().map(|r| r.0.ratio_ci).collect();
                let (first, measured) = &runs[0];
                let log_mean =
                    run_ratios.iter().map(|r| r.ln()).sum::<f64>() / run_ratios.len() as f64;
                ShapeRatio {
                    contender,
                    reference,
                    ratio: log_mean.exp(),
                    between: between_run_interval(&run_ratios),
                    within: pooled_within_interval(&run_ratios, &run_cis),
                    run_ratios,
                    ns_per_ray: first.ns_per_ray,
                    reference_ns_per_ray: first.reference_ns_per_ray,
                    rounds: (first.rounds as u64, *measured),
                }
            })
            .collect(),
    )
}
