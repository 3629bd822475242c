//! The timed loops: one cull, one metric, one pass over a batch.
//!
//! [`CullKind::visit`] hands the concrete cull type to [`time_pass`]'s loop, so each loop
//! is compiled per cull and nothing is dispatched per ray; the one `match` per pass sits
//! outside the timed region.

use crate::precision::Path;
use std::cell::RefCell;
use std::fmt;
use std::hint::black_box;
use std::time::{Duration, Instant};
use torus_cull::batch::{Dispatch, KeepMask, Lines, Wavefront, cull_batch};
use torus_cull::{Cull, CullKind, CullVisitor, Hit, LocalLine, Ray, Torus, intersect_culled};

/// What a contender's timing covers.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Metric {
    /// What a renderer pays per ray: world ray → torus frame, the cull, and the exact
    /// intersection when the cull keeps the ray ([`intersect_culled`]).
    TotalNs,
    /// The cull alone on torus-frame lines.
    CullNs,
    /// [`Metric::TotalNs`] in batch mode: the wavefront of [`torus_cull::batch::Wavefront`]
    /// (SIMD cull, compaction, exact intersection on lanes).
    BatchTotalNs,
    /// [`Metric::CullNs`] in batch mode: [`torus_cull::batch::cull_batch`] on
    /// structure-of-arrays lines.
    BatchCullNs,
    /// [`Metric::BatchTotalNs`] through the certified f32 path
    /// ([`torus_cull::batch::Wavefront::intersect_f32`]): the kept rays solved and proved on
    /// f32 lanes, the unproved ones escalated to the f64 solver.
    BatchF32TotalNs,
    /// The f32 wavefront without the proof
    /// ([`torus_cull::batch::Wavefront::intersect_f32_uncertified`]): not a usable answer, only
    /// the yardstick of what the proof costs.
    BatchF32UncertifiedNs,
}

impl Metric {
    /// The scalar (one ray at a time) metrics, in table order.
    pub const ALL: [Metric; 2] = [Metric::TotalNs, Metric::CullNs];

    /// The batch-mode metrics, in table order: the f64 wavefront and SIMD cull, then the
    /// f32 wavefront, certified and not.
    pub const BATCH: [Metric; 4] = [
        Metric::BatchTotalNs,
        Metric::BatchCullNs,
        Metric::BatchF32TotalNs,
        Metric::BatchF32UncertifiedNs,
    ];

    /// The stable name used in results: `total_ns`, `cull_ns`, `batch_total_ns`,
    /// `batch_cull_ns`, `batch_f32_total_ns` or `batch_f32_uncertified_ns`.
    pub fn name(self) -> &'static str {
        match self {
            Metric::TotalNs => "total_ns",
            Metric::CullNs => "cull_ns",
            Metric::BatchTotalNs => "batch_total_ns",
            Metric::BatchCullNs => "batch_cull_ns",
            Metric::BatchF32TotalNs => "batch_f32_total_ns",
            Metric::BatchF32UncertifiedNs => "batch_f32_uncertified_ns",
        }
    }

    /// The path this times on the precision × engine axis: the CPU's, one ray at a time
    /// or in batches, f64 or (the f32 wavefront, certified or not) f32. The cull-alone
    /// metrics run no intersection and are f64, what a record without the field means.
    pub fn path(self) -> Path {
        match self {
            Metric::TotalNs | Metric::CullNs => Path::SCALAR_F64,
            Metric::BatchTotalNs | Metric::BatchCullNs => Path::BATCH_F64,
            Metric::BatchF32TotalNs | Metric::BatchF32UncertifiedNs => Path::BATCH_F32,
        }
    }

    /// Whether this times the batch mode ([`Metric::path`]'s mode is batch; written
    /// out, as [`time_pass`] asks it before each timed pass).
    pub fn is_batch(self) -> bool {
        !matches!(self, Metric::TotalNs | Metric::CullNs)
    }

    /// Whether this times the f32 wavefront, certified or not ([`Metric::path`]'s
    /// precision is f32).
    pub fn is_f32(self) -> bool {
        matches!(
            self,
            Metric::BatchF32TotalNs | Metric::BatchF32UncertifiedNs
        )
    }

    /// The exact intersection's precision, as results record it: [`Metric::path`]'s,
    /// `f32` for the f32 wavefront, `f64` otherwise.
    pub fn precision(self) -> &'static str {
        self.path().precision.name()
    }

    /// Whether `cull` is timed under this metric: batch metrics need a batch form, and the
    /// cull-alone metrics leave out `none`, whose "cull alone" is an empty loop (about
    /// 0.4 ns per ray of loop overhead that moves with code placement by more than any
    /// interval from one run holds, issue 29): a ratio against it measures the loop, not
    /// a cull. A cull's own time alone stays in its records against `cychosz`.
    pub fn covers(self, cull: CullKind) -> bool {
        if self.is_cull_alone() && cull == CullKind::NoCull {
            return false;
        }
        !self.is_batch() || cull.batched().is_some()
    }

    /// Whether this times the cull alone (scalar or batch), with no intersection.
    pub fn is_cull_alone(self) -> bool {
        matches!(self, Metric::CullNs | Metric::BatchCullNs)
    }
}

impl fmt::Display for Metric {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// One torus and its batch, in every form the metrics need.
#[derive(Debug, Clone)]
pub struct Workset<'a> {
    torus: &'a Torus,
    rays: &'a [Ray],
    lines: Vec<LocalLine>,
    /// For the batch metrics: the lines as structure of arrays, the dispatch level, and
    /// the wavefront's buffers (reused from pass to pass, as a renderer would).
    batch: Option<BatchSet>,
}

/// What the batch metrics need besides the rays.
#[derive(Debug, Clone)]
struct BatchSet {
    dispatch: Dispatch,
    soa: Lines,
    scratch: RefCell<(Wavefront, Vec<Option<Hit>>, KeepMask)>,
}

impl<'a> Workset<'a> {
    /// The batch `rays` of `torus`; the torus-frame lines are made here, outside any timing.
    pub fn new(torus: &'a Torus, rays: &'a [Ray]) -> Workset<'a> {
        let lines: Vec<LocalLine> = rays.iter().map(|r| torus.line_to_local(r)).collect();
        Workset {
            torus,
            rays,
            lines,
            batch: None,
        }
    }

    /// [`Workset::new`], ready for the batch metrics too, at the level `dispatch`.
    pub fn with_batch(torus: &'a Torus, rays: &'a [Ray], dispatch: Dispatch) -> Workset<'a> {
        let mut set = Workset::new(torus, rays);
        set.batch = Some(BatchSet {
            dispatch,
            soa: Lines::from_local(&set.lines),
            scratch: RefCell::default(),
        });
        set
    }

    /// Rays in the batch.
    pub fn len(&self) -> usize {
        self.rays.len()
    }

    /// Whether the batch is empty.
    pub fn is_empty(&self) -> bool {
        self.rays.is_empty()
    }

    /// The batch forms; panics on a set made without [`Workset::with_batch`].
    fn batch_set(&self) -> &BatchSet {
        self.batch
            .as_ref()
            .expect("a batch metric needs Workset::with_batch")
    }
}

/// Time `reps` passes of `cull` over the batch, measuring `metric`.
///
/// Panics for a batch metric on a [`Workset`] made without [`Workset::with_batch`], or
/// on a cull without a batch form (see [`Metric::covers`]).
pub fn time_pass(cull: CullKind, metric: Metric, set: &Workset<'_>, reps: usize) -> Duration {
    if metric.is_batch() {
        return time_batch_pass(cull, metric, set, reps);
    }
    cull.visit(Pass { metric, set, reps })
}

/// A batch-mode pass: one call per pass over the whole batch (the kernels dispatch once
/// per call, outside the per-ray work).
#[inline(never)]
fn time_batch_pass(cull: CullKind, metric: Metric, set: &Workset<'_>, reps: usize) -> Duration {
    let cull = cull.batched().expect("a cull with a batch form");
    let batch = set.batch_set();
    let mut scratch = batch.scratch.borrow_mut();
    let (wavefront, hits, keep) = &mut *scratch;
    let d = &batch.dispatch;
    let start = Instant::now();
    for _ in 0..reps {
        // Opaque per pass, so no work is hoisted out of the repetitions.
        let rays = || black_box(set.rays);
        match metric {
            Metric::BatchTotalNs => {
                wavefront.intersect(d, cull, set.torus, rays(), hits);
                black_box(&hits);
            }
            Metric::BatchF32TotalNs => {
                wavefront.intersect_f32(d, cull, set.torus, rays(), hits);
                black_box(&hits);
            }
            Metric::BatchF32UncertifiedNs => {
                wavefront.intersect_f32_uncertified(d, cull, set.torus, rays(), hits);
                black_box(&hits);
            }
            Metric::BatchCullNs => {
                cull_batch(d, cull, set.torus.bounds(), black_box(&batch.soa), keep);
                black_box(&keep);
            }
            Metric::TotalNs | Metric::CullNs => unreachable!("scalar metrics are timed by Pass"),
        }
    }
    start.elapsed()
}

/// The f32 metrics' escalation rate for `cull` on the batch: rays the f32 pass of
/// `metric` did not prove (answered by the f64 solver) over the batch's rays, from one
/// untimed pass; `None` for the f64 metrics.
///
/// Panics as [`time_pass`] does.
pub fn escalation_rate(cull: CullKind, metric: Metric, set: &Workset<'_>) -> Option<f64> {
    if !metric.is_f32() {
        return None;
    }
    let batch = set.batch_set();
    let mut scratch = batch.scratch.borrow_mut();
    let (wavefront, hits, _) = &mut *scratch;
    let (d, torus) = (&batch.dispatch, set.torus);
    let cull = cull.batched().expect("a cull with a batch form");
    let stats = if metric == Metric::BatchF32TotalNs {
        wavefront.intersect_f32(d, cull, torus, set.rays, hits)
    } else {
        wavefront.intersect_f32_uncertified(d, cull, torus, set.rays, hits)
    };
    Some(stats.escalated as f64 / stats.rays.max(1) as f64)
}

struct Pass<'s, 'a> {
    metric: Metric,
    set: &'s Workset<'a>,
    reps: usize,
}

impl CullVisitor for Pass<'_, '_> {
    type Output = Duration;

    #[inline(never)]
    fn visit<C: Cull>(self, cull: C) -> Duration {
        let Workset {
            torus, rays, lines, ..
        } = self.set;
        let bounds = torus.bounds();
        let start = Instant::now();
        match self.metric {
            Metric::TotalNs => {
                for _ in 0..self.reps {
                    // Opaque per pass, so no work is hoisted out of the repetitions.
                    for ray in black_box(*rays) {
                        black_box(intersect_culled(&cull, torus, ray));
                    }
                }
            }
            Metric::CullNs => {
                for _ in 0..self.reps {
                    for line in black_box(lines.as_slice()) {
                        black_box(cull.keeps(bounds, line.origin, line.dir));
                    }
                }
            }
            Metric::BatchTotalNs
            | Metric::BatchCullNs
            | Metric::BatchF32TotalNs
            | Metric::BatchF32UncertifiedNs => {
                unreachable!("batch metrics are timed by time_batch_pass")
            }
        }
        start.elapsed()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::workload::{Case, Pose, generate};

    /// Each metric's path on the precision × engine axis agrees with its own tests.
    #[test]
    fn every_metric_is_on_its_path() {
        use crate::precision::{Mode, Precision};
        for m in Metric::ALL.into_iter().chain(Metric::BATCH) {
            assert_eq!(m.is_batch(), m.path().mode == Mode::Batch, "{m}");
            assert_eq!(m.is_f32(), m.path().precision == Precision::F32, "{m}");
            assert_eq!(m.precision(), m.path().precision.name(), "{m}");
        }
    }

    #[test]
    fn every_timed_cull_runs_both_metrics() {
        let batch = generate(Case::Uniform, 4.0, 64, 1, Pose::Random).unwrap();
        let set = Workset::new(&batch.torus, &batch.rays);
        assert_eq!(set.len(), 64);
        for cull in CullKind::TIMED {
            for metric in Metric::ALL {
                let one = time_pass(cull, metric, &set, 1);
                assert!(one > Duration::ZERO, "{cull} {metric}");
            }
        }
        assert_eq!(Metric::TotalNs.to_string(), "total_ns");
        assert_eq!(Metric::CullNs.to_string(), "cull_ns");
    }
}
