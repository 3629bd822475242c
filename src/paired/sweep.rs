//! The driver: paired ratio records for every (case, ν) of a workload, or for one batch.

use super::contender::{Metric, Workset, escalation_rate, time_pass};
use super::engine::Interleaver;
use super::stats::{QUIET_FRACTION, quiet_rounds, ratio_estimate};
use crate::results::{CPU_DEVICE, F64_REFERENCE, RatioRecord};
use crate::workload::spec::Workload;
use crate::workload::{Batch, Case, GenerateError, generate};
use rand::seq::SliceRandom;
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64;
use std::fmt;
use std::time::Duration;
use torus_cull::Named;
use torus_cull::batch::{Dispatch, Isa};
use torus_cull::{CullKind, Ray, Torus};

/// The references every cull is timed against: the classic test, and no test at all.
pub const REFERENCES: [CullKind; 2] = [CullKind::Cychosz, CullKind::NoCull];

/// One cull-alone timing lasts at least this long (the pass over the batch is repeated),
/// so that the clock's own cost (tens of ns) stays below 0.2 % of it.
const CULL_PASS_TARGET: Duration = Duration::from_micros(25);

/// Fewest rounds left alone by the operating system that are used on their own.
pub const MIN_UNDISTURBED: usize = 20;

/// How much to measure, over all (case, ν) together.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PairedOptions {
    /// Rays per batch: every round times every contender on these same rays.
    pub batch: usize,
    /// Rounds run and discarded first, spread over every (case, ν).
    pub warm_up: Duration,
    /// Measured time, shared evenly by every (case, ν).
    pub budget: Duration,
    /// About how long one visit to a (case, ν) lasts before the next one's turn.
    pub visit: Duration,
    /// At least this many measured rounds per (case, ν), whatever the budget.
    pub min_rounds: usize,
    /// Also time the batch metrics (`batch_total_ns`, `batch_cull_ns`, and the f32
    /// wavefront's `batch_f32_total_ns` and `batch_f32_uncertified_ns`, for the culls
    /// with a batch form) at this instruction set, in the same rounds as the scalar ones.
    pub batch_isa: Option<Isa>,
    /// Which of several independent runs this is (0 for the first, or the only one). Run
    /// 0 times the units as given; any other run times them in a fresh layout: its own
    /// copy of each batch in a new allocation, placed after a padding allocation of
    /// seeded size (0–256 KiB, so the buffers land at other addresses and cache sets), with
    /// the rays in a seeded shuffled order, and the round orders and the bootstraps
    /// seeded apart. The rays are the same, so every run measures the same ratios; what
    /// differs is what a layout does to them (see [`crate::paired::runs`]).
    pub run: u64,
}

/// Rays per batch unless told otherwise: about 0.02–0.2 ms per `total_ns` timing, so a
/// round of all twelve contenders stays near a millisecond.
pub const DEFAULT_BATCH: usize = 1024;

impl PairedOptions {
    /// `seconds` in all: 5 % (at most 1 s) warms up, the rest is measured in visits of
    /// about 25 ms: the machine's slow state comes in spells of milliseconds to seconds
    /// (docs/results.md), and short visits spread each batch's rounds over both states,
    /// so that its quietest rounds can come from the fast one.
    pub fn total(seconds: f64, batch: usize) -> PairedOptions {
        let warm_up = (0.05 * seconds).min(1.0);
        PairedOptions {
            batch,
            warm_up: Duration::from_secs_f64(warm_up),
            budget: Duration::from_secs_f64(seconds - warm_up),
            visit: Duration::from_millis(25),
            min_rounds: 40,
            batch_isa: None,
            run: 0,
        }
    }
}

/// Why ratios could not be measured.
#[derive(Debug, Clone, PartialEq)]
pub enum PairedError {
    /// The workload's batch could not be generated.
    Generate(GenerateError),
    /// The batch metrics were asked for at an instruction set this CPU lacks.
    Isa(torus_cull::batch::IsaError),
    /// No round gave a usable timing (a clock that never advanced).
    NoRounds {
        /// The case.
        case: Case,
        /// ν.
        nu: f64,
        /// The contender.
        cull: CullKind,
    },
}

impl fmt::Display for PairedError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            PairedError::Generate(e) => write!(f, "{e}"),
            PairedError::Isa(e) => write!(f, "{e}"),
            PairedError::NoRounds { case, nu, cull } => write!(
                f,
                "case {case} at nu = {nu}: no round timed cull {cull} (the clock did not advance)"
            ),
        }
    }
}

impl std::error::Error for PairedError {}

impl From<GenerateError> for PairedError {
    fn from(e: GenerateError) -> PairedError {
        PairedError::Generate(e)
    }
}

/// One (case, ν) to time: a torus and its batch of world rays.
#[derive(Debug, Clone, Copy)]
pub struct Unit<'a> {
    /// The case.
    pub case: Case,
    /// ν.
    pub nu: f64,
    /// The torus.
    pub torus: &'a Torus,
    /// The batch.
    pub rays: &'a [Ray],
    /// Seeds the round order and the bootstrap.
    pub seed: u64,
}

impl<'a> Unit<'a> {
    /// A generated batch as a unit, seeded by its stream seed.
    #[must_use]
    pub fn of(batch: &'a Batch) -> Unit<'a> {
        Unit {
            case: batch.case,
            nu: batch.nu,
            torus: &batch.torus,
            rays: &batch.rays,
            seed: batch.stream_seed,
        }
    }
}

/// A unit ready to time: its batch in every form and its cull-alone repetitions.
struct Timed<'a> {
    unit: Unit<'a>,
    set: Workset<'a>,
    cull_reps: usize,
    batch_cull_reps: usize,
}

impl<'a> Timed<'a> {
    /// `unit`'s batch, in the batch forms too with a `dispatch`, and the repetitions of
    /// its cull-alone passes.
    fn new(unit: Unit<'a>, dispatch: Option<Dispatch>) -> Timed<'a> {
        let set = match dispatch {
            Some(d) => Workset::with_batch(unit.torus, unit.rays, d),
            None => Workset::new(unit.torus, unit.rays),
        };
        Timed {
            unit,
            cull_reps: cull_pass_reps(&set, Metric::CullNs),
            batch_cull_reps: if dispatch.is_some() {
                cull_pass_reps(&set, Metric::BatchCullNs)
            } else {
                1
            },
            set,
        }
    }

    fn reps(&self, metric: Metric) -> usize {
        match metric {
            Metric::TotalNs
            | Metric::BatchTotalNs
            | Metric::BatchF32TotalNs
            | Metric::BatchF32UncertifiedNs => 1,
            Metric::CullNs => self.cull_reps,
            Metric::BatchCullNs => self.batch_cull_reps,
        }
    }

    fn time(&self, contender: (CullKind, Metric)) -> Duration {
        let (kind, metric) = contender;
        time_pass(kind, metric, &self.set, self.reps(metric))
    }
}

/// Ratio records of `culls` against each of [`REFERENCES`] for every metric, on each of
/// `units`; with a batch level, the f32 wavefront metrics also against the same cull's
/// f64 wavefront (reference [`F64_REFERENCE`]), with each f32 record's escalation rate
/// from one untimed pass. The references are timed whether listed or not; a cull is not
/// timed against itself. The units are visited in turn, in a shuffled order, until the budget is
/// spent, so that each one's rounds spread over the whole run. `progress` is told
/// (visits done, visits in all).
pub fn time_units(
    units: &[Unit<'_>],
    culls: &[CullKind],
    options: &PairedOptions,
    progress: &mut dyn FnMut(usize, usize),
) -> Result<Vec<RatioRecord>, PairedError> {
    let dispatch = match options.batch_isa {
        Some(isa) => Some(Dispatch::forced(isa).map_err(PairedError::Isa)?),
        None => None,
    };
    let lineup = Lineup::new(culls, dispatch.is_some());
    let layout = Layout::new(units, options.run);
    let units = layout.units(units);
    let timed: Vec<Timed<'_>> = units
        .iter()
        .map(|&unit| Timed::new(unit, dispatch))
        .collect();
    let rounds = measure_rounds(&timed, &lineup.contenders, options, progress);
    let mut records = Vec::new();
    for (t, r) in timed.iter().zip(&rounds) {
        push_unit_records(&mut records, t, r, culls, &lineup)?;
    }
    Ok(records)
}

/// A run's fresh layout of the units (see [`PairedOptions::run`]): nothing for run 0;
/// otherwise a padding allocation, then a shuffled copy of every batch.
struct Layout {
    run: u64,
    /// Held while the run lasts, so that the copies below sit after it.
    _padding: Vec<u8>,
    rays: Vec<Vec<Ray>>,
}

impl Layout {
    fn new(units: &[Unit<'_>], run: u64) -> Layout {
        if run == 0 {
            return Layout {
                run,
                _padding: Vec::new(),
                rays: Vec::new(),
            };
        }
        let mut rng = Pcg64::seed_from_u64(run.wrapping_mul(0xA076_1D64_78BD_642F));
        // A multiple of 64 bytes up to 256 KiB, written so that the pages are really
        // mapped.
        let padding = vec![1u8; 64 * rng.random_range(0..4096usize)];
        let rays = units
            .iter()
            .map(|u| {
                let mut copy = u.rays.to_vec();
                copy.shuffle(&mut rng);
                copy
            })
            .collect();
        Layout {
            run,
            _padding: std::hint::black_box(padding),
            rays,
        }
    }

    /// `units` in this layout: the copies, and seeds mixed with the run.
    fn units<'a>(&'a self, units: &[Unit<'a>]) -> Vec<Unit<'a>> {
        if self.run == 0 {
            return units.to_vec();
        }
        units
            .iter()
            .zip(&self.rays)
            .map(|(u, rays)| Unit {
                rays,
                seed: u.seed ^ self.run.wrapping_mul(0x9E37_79B9_7F4A_7C15),
                ..*u
            })
            .collect()
    }
}

/// What every round times: the culls asked for with the references, the metrics, and
/// each (cull, metric) pair a metric covers; a contender is its index in `contenders`.
struct Lineup {
    kinds: Vec<CullKind>,
    metrics: Vec<Metric>,
    contenders: Vec<(CullKind, Metric)>,
}

impl Lineup {
    /// `culls` and the references, once each, in [`CullKind::TIMED`] order (then any
    /// other cull in the order asked); the batch metrics too when `batch`.
    fn new(culls: &[CullKind], batch: bool) -> Lineup {
        let kinds: Vec<CullKind> = CullKind::TIMED
            .into_iter()
            .chain(culls.iter().copied())
            .filter(|k| culls.contains(k) || REFERENCES.contains(k))
            .fold(Vec::new(), |mut v, k| {
                if !v.contains(&k) {
                    v.push(k);
                }
                v
            });
        let metrics: Vec<Metric> = Metric::ALL
            .into_iter()
            .chain(batch.then_some(Metric::BATCH).into_iter().flatten())
            .collect();
        let contenders: Vec<(CullKind, Metric)> = metrics
            .iter()
            .flat_map(|&m| {
                kinds
                    .iter()
                    .filter(move |&&k| m.covers(k))
                    .map(move |&k| (k, m))
            })
            .collect();
        Lineup {
            kinds,
            metrics,
            contenders,
        }
    }

    fn index(&self, kind: CullKind, metric: Metric) -> usize {
        self.contenders
            .iter()
            .position(|&c| c == (kind, metric))
            .expect("every cull and reference is a contender")
    }

    /// What `cull` is compared with under `metric` (name, contender index): the
    /// references, then, for the f32 metrics, the same cull's f64 wavefront: the headline
    /// f32 / f64 ratio.
    fn references_of(&self, cull: CullKind, metric: Metric) -> Vec<(String, usize)> {
        REFERENCES
            .into_iter()
            .filter(|&r| r != cull && metric.covers(r))
            .map(|r| (r.name().to_string(), self.index(r, metric)))
            .chain(metric.is_f32().then(|| {
                (
                    F64_REFERENCE.to_string(),
                    self.index(cull, Metric::BatchTotalNs),
                )
            }))
            .collect()
    }
}

/// The rounds of every unit: a warm-up, then visits in a freshly shuffled unit order each
/// pass until the budget is spent, then whatever rounds a unit still lacks of
/// `options.min_rounds`. One [`Interleaver`] per unit, in `timed`'s order.
fn measure_rounds(
    timed: &[Timed<'_>],
    contenders: &[(CullKind, Metric)],
    options: &PairedOptions,
    progress: &mut dyn FnMut(usize, usize),
) -> Vec<Interleaver> {
    let mut rounds: Vec<Interleaver> = timed
        .iter()
        .map(|t| Interleaver::new(contenders.len(), t.unit.seed))
        .collect();
    let n = timed.len().max(1) as u32;
    let passes = ((options.budget.as_secs_f64() / (options.visit.as_secs_f64() * n as f64)).round()
        as u32)
        .max(1);
    let visit = options.budget / (passes * n);
    let mut order_rng = Pcg64::seed_from_u64(timed.first().map_or(0, |t| t.unit.seed));
    let mut order: Vec<usize> = (0..timed.len()).collect();
    let time_one = |u: usize| move |i: usize| timed[u].time(contenders[i]);
    for (u, r) in rounds.iter_mut().enumerate() {
        r.warm_up(&mut time_one(u), options.warm_up / n);
    }
    let total = (passes * n) as usize;
    for pass in 0..passes as usize {
        order.shuffle(&mut order_rng);
        for (k, &u) in order.iter().enumerate() {
            // One discarded round re-warms caches and predictors after the other units.
            rounds[u].visit(&mut time_one(u), 1, visit, 0, usize::MAX);
            progress(pass * timed.len() + k + 1, total);
        }
    }
    for (u, r) in rounds.iter_mut().enumerate() {
        let short = options.min_rounds.saturating_sub(r.rounds());
        if short > 0 {
            r.visit(&mut time_one(u), 1, Duration::ZERO, short, usize::MAX);
        }
    }
    rounds
}

/// Appends unit `t`'s records, from its rounds `r`, to `records`: for each metric, each
/// of `culls` it covers against each of its references, on the quiet rounds only.
fn push_unit_records(
    records: &mut Vec<RatioRecord>,
    t: &Timed<'_>,
    r: &Interleaver,
    culls: &[CullKind],
    lineup: &Lineup,
) -> Result<(), PairedError> {
    let quiet = quiet_rounds(&r.ns, &undisturbed(&r.disturbed), QUIET_FRACTION);
    let pick = |i: usize| quiet.iter().map(|&k| r.ns[i][k]).collect::<Vec<f64>>();
    let Unit { case, nu, seed, .. } = t.unit;
    for &metric in &lineup.metrics {
        let work = (t.set.len() * t.reps(metric)) as f64;
        for &cull in lineup
            .kinds
            .iter()
            .filter(|&&k| culls.contains(&k) && metric.covers(k))
        {
            let escalation = escalation_rate(cull, metric, &t.set);
            for (reference, reference_index) in lineup.references_of(cull, metric) {
                // Seeded by the record's place in the whole run, so that no two
                // bootstraps share a stream.
                let bootstrap_seed = seed ^ (records.len() as u64 + 1).wrapping_mul(0x9E37_79B9);
                let e = ratio_estimate(
                    &pick(lineup.index(cull, metric)),
                    &pick(reference_index),
                    work,
                    bootstrap_seed,
                )
                .ok_or(PairedError::NoRounds { case, nu, cull })?;
                records.push(RatioRecord {
                    case: case.name().to_string(),
                    nu,
                    cull: cull.name().to_string(),
                    reference,
                    metric: metric.name().to_string(),
                    ratio: e.ratio,
                    ratio_ci: e.ratio_ci,
                    rounds: e.rounds as u64,
                    rounds_measured: r.rounds() as u64,
                    rays: t.set.len() as u64,
                    ns_per_ray: e.ns_per_ray,
                    reference_ns_per_ray: e.reference_ns_per_ray,
                    precision: metric.precision().to_string(),
                    device: CPU_DEVICE.to_string(),
                    escalation_rate: escalation,
                    ..RatioRecord::default()
                });
            }
        }
    }
    Ok(())
}

/// The rounds the operating system left alone, if there are enough of them (a quarter,
/// and at least [`MIN_UNDISTURBED`]); otherwise every round, as a machine that switches
/// this thread out in most rounds leaves nothing better to choose from.
pub fn undisturbed(disturbed: &[bool]) -> Vec<bool> {
    let clean = disturbed.iter().filter(|d| !**d).count();
    if clean >= MIN_UNDISTURBED.max(disturbed.len() / 4) {
        disturbed.iter().map(|d| !d).collect()
    } else {
        vec![true; disturbed.len()]
    }
}

/// [`time_units`] on a single batch.
pub fn time_batch(
    unit: Unit<'_>,
    culls: &[CullKind],
    options: &PairedOptions,
) -> Result<Vec<RatioRecord>, PairedError> {
    time_units(&[unit], culls, options, &mut |_, _| {})
}

/// Repetitions of the cull-alone pass (`metric`: scalar or batch) that make the
/// reference's timing reach [`CULL_PASS_TARGET`], from the fastest of a few trial passes.
fn cull_pass_reps(set: &Workset<'_>, metric: Metric) -> usize {
    let one = (0..5)
        .map(|_| time_pass(REFERENCES[0], metric, set, 1))
        .min()
        .unwrap_or(Duration::ZERO)
        .max(Duration::from_nanos(1));
    (CULL_PASS_TARGET.as_nanos().div_ceil(one.as_nanos()) as usize).clamp(1, 100_000)
}

/// Ratio records for every case of `workload` at each of `nus`, on the first
/// `options.batch` rays of each (case, ν) stream; see [`time_units`].
pub fn time_workload(
    workload: &Workload,
    nus: &[f64],
    culls: &[CullKind],
    options: &PairedOptions,
    progress: &mut dyn FnMut(usize, usize),
) -> Result<Vec<RatioRecord>, PairedError> {
    let mut batches = Vec::new();
    for &case in &workload.cases {
        for &nu in nus {
            batches.push(generate(
                case,
                nu,
                options.batch,
                workload.seed,
                workload.pose,
            )?);
        }
    }
    let units: Vec<Unit<'_>> = batches.iter().map(Unit::of).collect();
    time_units(&units, culls, options, progress)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::workload::Pose;

    fn quick(batch: usize) -> PairedOptions {
        PairedOptions {
            batch,
            warm_up: Duration::from_millis(5),
            budget: Duration::from_millis(60),
            visit: Duration::from_millis(20),
            min_rounds: 30,
            batch_isa: None,
            run: 0,
        }
    }

    fn unit(b: &crate::workload::Batch) -> Unit<'_> {
        Unit::of(b)
    }

    /// With a batch level: the batch metrics for the culls with a batch form, in the
    /// same rounds; `discriminant_f64` (no batch form) keeps its scalar records only.
    #[test]
    fn batch_metrics_cover_the_batched_culls() {
        let b = generate(Case::Hole, 8.0, 128, 3, Pose::Random).unwrap();
        let culls = [CullKind::Skala, CullKind::DiscriminantF64];
        let options = PairedOptions {
            batch_isa: Some(Isa::Scalar),
            ..quick(128)
        };
        let r = time_batch(unit(&b), &culls, &options).unwrap();
        let count = |metric: &str, cull: &str| {
            r.iter()
                .filter(|x| x.metric == metric && x.cull == cull)
                .count()
        };
        // The cull-alone metrics against `cychosz` only (`none`'s is an empty loop).
        assert_eq!(count("total_ns", "skala"), 2);
        assert_eq!(count("total_ns", "discriminant_f64"), 2);
        assert_eq!(count("cull_ns", "skala"), 1);
        assert_eq!(count("cull_ns", "discriminant_f64"), 1);
        assert_eq!(count("batch_total_ns", "skala"), 2);
        assert_eq!(count("batch_cull_ns", "skala"), 1);
        for metric in ["batch_total_ns", "batch_cull_ns"] {
            assert_eq!(count(metric, "discriminant_f64"), 0);
        }
        // The f32 wavefront, certified and not: against both references and against
        // skala's own f64 wavefront; every f32 record has its escalation rate.
        for metric in ["batch_f32_total_ns", "batch_f32_uncertified_ns"] {
            assert_eq!(count(metric, "skala"), 3);
            assert_eq!(count(metric, "discriminant_f64"), 0);
            let vs_f64 = r
                .iter()
                .find(|x| x.metric == metric && x.cull == "skala" && x.reference == "f64")
                .unwrap();
            // Its reference is skala's own f64 wavefront, in the same rounds.
            let f64_total = r
                .iter()
                .find(|x| x.metric == "batch_total_ns" && x.cull == "skala")
                .unwrap();
            assert_eq!(
                vs_f64.reference_ns_per_ray, f64_total.ns_per_ray,
                "{vs_f64:?}"
            );
        }
        for x in &r {
            let f32 = x.metric.starts_with("batch_f32_");
            assert_eq!(x.precision, if f32 { "f32" } else { "f64" }, "{x:?}");
            assert_eq!(x.device, "cpu");
            match x.escalation_rate {
                Some(e) => assert!(f32 && (0.0..=1.0).contains(&e), "{x:?}"),
                None => assert!(!f32, "{x:?}"),
            }
        }
        // On hole lines the batch skala skips the lane solver for almost every ray.
        let skala = r
            .iter()
            .find(|x| x.metric == "batch_total_ns" && x.cull == "skala" && x.reference == "none")
            .unwrap();
        assert!(skala.ratio < 0.6, "{skala:?}");
        // A level this CPU lacks is an error, not a silent fallback.
        let missing = Isa::ALL
            .iter()
            .copied()
            .find(|i| !Isa::available().contains(i));
        if let Some(isa) = missing {
            let options = PairedOptions {
                batch_isa: Some(isa),
                ..quick(128)
            };
            assert!(matches!(
                time_batch(unit(&b), &culls, &options),
                Err(PairedError::Isa(_))
            ));
        }
    }

    #[test]
    fn records_cover_every_cull_reference_and_metric_once() {
        let b = generate(Case::Uniform, 2.0, 128, 3, Pose::Random).unwrap();
        let culls = [CullKind::Skala, CullKind::Cychosz];
        let r = time_batch(unit(&b), &culls, &quick(128)).unwrap();
        let keys: Vec<(&str, &str, &str)> = r
            .iter()
            .map(|x| (x.metric.as_str(), x.reference.as_str(), x.cull.as_str()))
            .collect();
        // skala vs both references, cychosz vs none only, for the total; the cull alone
        // against cychosz only (`none`'s cull alone is an empty loop, not timed). `none`
        // is timed for the total (it is a reference) but not reported, as it was not asked
        // for.
        let want = [
            ("total_ns", "none", "cychosz"),
            ("total_ns", "cychosz", "skala"),
            ("total_ns", "none", "skala"),
            ("cull_ns", "cychosz", "skala"),
        ];
        assert_eq!(keys, want);
        for x in &r {
            assert!(x.rounds >= 5 && x.rounds <= x.rounds_measured, "{x:?}");
            assert_eq!(x.rays, 128);
            assert!(x.ratio.is_finite() && x.ratio > 0.0, "{x:?}");
            assert!(
                x.ratio_ci[0] <= x.ratio && x.ratio <= x.ratio_ci[1],
                "{x:?}"
            );
            assert!(x.ns_per_ray > 0.0 && x.reference_ns_per_ray > 0.0, "{x:?}");
        }
    }

    /// Several units share the budget, each gets its own records, and none falls short
    /// of the minimum rounds even when the budget is nil.
    #[test]
    fn units_share_the_budget_and_keep_the_minimum_rounds() {
        let a = generate(Case::Hole, 2.0, 64, 3, Pose::Random).unwrap();
        let b = generate(Case::Camera, 8.0, 64, 3, Pose::Random).unwrap();
        let options = PairedOptions {
            budget: Duration::ZERO,
            warm_up: Duration::ZERO,
            ..quick(64)
        };
        let mut calls = Vec::new();
        let r = time_units(
            &[unit(&a), unit(&b)],
            &[CullKind::Aabb],
            &options,
            &mut |d, n| calls.push((d, n)),
        )
        .unwrap();
        assert_eq!(calls.last(), Some(&(2, 2)));
        // Per unit: the total against both references, the cull alone against cychosz.
        assert_eq!(r.len(), 2 * 3);
        // The quietest quarter of at least 30 measured rounds (at least 20 of them
        // undisturbed, or all of them).
        assert!(
            r.iter().all(|x| x.rounds_measured >= 30 && x.rounds >= 5),
            "{r:?}"
        );
        assert_eq!(
            r.iter().filter(|x| x.case == "hole" && x.nu == 2.0).count(),
            3
        );
        assert_eq!(
            r.iter()
                .filter(|x| x.case == "camera" && x.nu == 8.0)
                .count(),
            3
        );
    }

    /// On rays that fall through the hole, skala rejects almost all of them without the
    /// quartic and cychosz none: skala's total must be a small fraction of cychosz's
    /// (about 0.2 on an idle machine), whatever the load.
    #[test]
    fn hole_rays_show_skala_far_cheaper_than_cychosz() {
        let b = generate(Case::Hole, 8.0, 512, 3, Pose::Random).unwrap();
        let r = time_batch(unit(&b), &[CullKind::Skala], &quick(512)).unwrap();
        let total = r
            .iter()
            .find(|x| x.metric == "total_ns" && x.reference == "cychosz")
            .unwrap();
        assert!(total.ratio < 0.6 && total.ratio_ci[1] < 0.7, "{total:?}");
        let vs_none = r
            .iter()
            .find(|x| x.metric == "total_ns" && x.reference == "none")
            .unwrap();
        assert!(vs_none.ratio < 0.6, "{vs_none:?}");
    }

    #[test]
    fn total_splits_warm_up_and_budget() {
        let o = PairedOptions::total(30.0, 1024);
        assert!(((o.budget + o.warm_up).as_secs_f64() - 30.0).abs() < 1e-6);
        assert!(o.warm_up > Duration::ZERO && o.warm_up <= Duration::from_secs(1));
    }
}
