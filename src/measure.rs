//! Counting: the oracle labels every ray of a batch, then each cull's verdicts are tallied
//! against the labels (the metrics are defined in `docs/math.md`). The oracle runs here,
//! never inside a timed loop.

use crate::errata::PrintedCull;
use crate::oracle::{OracleClass, OracleLabel, classify};
use crate::results::RejectionRecord;
use crate::workload::{Batch, Case, GenerateError, generate_labeled, spec::Workload};
use torus_cull::{Cull, CullKind, CullVisitor, Named, Ray};

/// A cull the harness can count: a real one, or a paper-as-printed test fixture (counted
/// only to watch the oracle catch it; never timed).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum CountedCull {
    /// A conservative cull of the renderer API.
    Timed(CullKind),
    /// A paper-as-printed variant ([`crate::errata`]).
    Printed(PrintedCull),
}

/// Every countable cull by its stable name: the timed ones in table order, then the
/// printed ones.
impl Named for CountedCull {
    const KIND: &'static str = "cull";
    const ALL: &'static [CountedCull] = &{
        const TIMED: usize = CullKind::TIMED.len();
        let mut all = [CountedCull::Timed(CullKind::NoCull); TIMED + PrintedCull::ALL.len()];
        let mut i = 0;
        while i < all.len() {
            all[i] = if i < TIMED {
                CountedCull::Timed(CullKind::TIMED[i])
            } else {
                CountedCull::Printed(PrintedCull::ALL[i - TIMED])
            };
            i += 1;
        }
        all
    };

    fn name(self) -> &'static str {
        match self {
            CountedCull::Timed(c) => c.name(),
            CountedCull::Printed(c) => c.name(),
        }
    }
}

impl CountedCull {
    /// Hands the concrete cull to `visitor`.
    pub fn visit<V: CullVisitor>(self, visitor: V) -> V::Output {
        match self {
            CountedCull::Timed(c) => c.visit(visitor),
            CountedCull::Printed(c) => c.visit(visitor),
        }
    }
}

impl From<CullKind> for CountedCull {
    fn from(c: CullKind) -> CountedCull {
        CountedCull::Timed(c)
    }
}

impl From<PrintedCull> for CountedCull {
    fn from(c: PrintedCull) -> CountedCull {
        CountedCull::Printed(c)
    }
}

torus_cull::named_display_and_from_str!(CountedCull);

/// A batch with the oracle's label for each ray (ray mode, t ≥ 0).
#[derive(Debug, Clone)]
pub struct LabeledBatch {
    /// The rays and their torus.
    pub batch: Batch,
    /// One label per ray.
    pub labels: Vec<OracleLabel>,
}

impl LabeledBatch {
    /// Generate and label one (case, ν) batch of a workload.
    pub fn generate(
        workload: &Workload,
        case: Case,
        nu: f64,
    ) -> Result<LabeledBatch, GenerateError> {
        let (batch, labels) = generate_labeled(workload, case, nu)?;
        Ok(LabeledBatch { batch, labels })
    }

    /// Label an existing batch.
    pub fn label(batch: Batch) -> LabeledBatch {
        let labels = batch
            .rays
            .iter()
            .map(|r| classify(&batch.torus, r))
            .collect();
        LabeledBatch { batch, labels }
    }

    /// Oracle hits in the batch.
    pub fn hits(&self) -> usize {
        self.labels
            .iter()
            .filter(|l| l.class == OracleClass::Hit)
            .count()
    }
}

/// A ray that a cull rejected although the oracle calls it a hit.
#[derive(Debug, Clone)]
pub struct FalseReject {
    /// Case.
    pub case: Case,
    /// ν.
    pub nu: f64,
    /// The cull at fault.
    pub cull: CountedCull,
    /// Index of the ray in its batch.
    pub index: usize,
    /// The ray (world space).
    pub ray: Ray,
    /// The batch's stream seed.
    pub stream_seed: u64,
    /// The oracle's margin.
    pub margin: f64,
}

/// Each cull's verdict on each ray of the batch (`true` = keep), cull by cull.
pub fn verdicts(cull: impl Into<CountedCull>, batch: &Batch) -> Vec<bool> {
    struct All<'a>(&'a Batch);
    impl CullVisitor for All<'_> {
        type Output = Vec<bool>;
        fn visit<C: Cull>(self, cull: C) -> Vec<bool> {
            let torus = &self.0.torus;
            self.0
                .rays
                .iter()
                .map(|r| {
                    let line = torus.line_to_local(r);
                    cull.keeps(torus.bounds(), line.origin, line.dir)
                })
                .collect()
        }
    }
    cull.into().visit(All(batch))
}

/// The rejection counts of `cull` on a labeled batch, and its false rejects.
pub fn count(
    cull: impl Into<CountedCull>,
    labeled: &LabeledBatch,
) -> (RejectionRecord, Vec<FalseReject>) {
    let cull = cull.into();
    let batch = &labeled.batch;
    let keeps = verdicts(cull, batch);
    let (mut hits, mut misses, mut ambiguous, mut rejected) = (0u64, 0u64, 0u64, 0u64);
    let mut false_rejects = Vec::new();
    for (i, (label, keep)) in labeled.labels.iter().zip(keeps).enumerate() {
        match label.class {
            OracleClass::Hit => hits += 1,
            OracleClass::Miss => misses += 1,
            OracleClass::Ambiguous => ambiguous += 1,
        }
        if !keep {
            rejected += 1;
            if label.class == OracleClass::Hit {
                false_rejects.push(FalseReject {
                    case: batch.case,
                    nu: batch.nu,
                    cull,
                    index: i,
                    ray: batch.rays[i],
                    stream_seed: batch.stream_seed,
                    margin: label.margin,
                });
            }
        }
    }
    let rays = batch.rays.len() as u64;
    let record = RejectionRecord {
        case: batch.case.name().to_string(),
        nu: batch.nu,
        cull: cull.name().to_string(),
        rays,
        hits,
        misses,
        ambiguous,
        rejected,
        false_rejects: false_rejects.len() as u64,
        rejection_rate: if rays > 0 {
            rejected as f64 / rays as f64
        } else {
            0.0
        },
        miss_capture: (misses > 0).then(|| rejected as f64 / misses as f64),
    };
    (record, false_rejects)
}

/// Every (case, ν) of the workload, as a work list in table order.
pub fn units(workload: &Workload) -> Vec<(Case, f64)> {
    workload
        .cases
        .iter()
        .flat_map(|&c| workload.nu.iter().map(move |&nu| (c, nu)))
        .collect()
}

/// Rejection records for the whole workload over `culls`, with any false rejects, on
/// `threads` threads; `progress` is called with each finished unit's rays.
pub fn rejection_sweep(
    workload: &Workload,
    culls: &[CountedCull],
    threads: usize,
    progress: &(dyn Fn(u64) + Sync),
) -> Result<(Vec<RejectionRecord>, Vec<FalseReject>), GenerateError> {
    use std::sync::Mutex;
    use std::sync::atomic::{AtomicUsize, Ordering};
    let units = units(workload);
    let next = AtomicUsize::new(0);
    type Unit = Result<(Vec<RejectionRecord>, Vec<FalseReject>), GenerateError>;
    let out: Mutex<Vec<Option<Unit>>> = Mutex::new((0..units.len()).map(|_| None).collect());
    std::thread::scope(|s| {
        for _ in 0..threads.max(1) {
            s.spawn(|| {
                loop {
                    let i = next.fetch_add(1, Ordering::Relaxed);
                    let Some(&(case, nu)) = units.get(i) else {
                        break;
                    };
                    let result = LabeledBatch::generate(workload, case, nu).map(|labeled| {
                        let mut records = Vec::new();
                        let mut bad = Vec::new();
                        for &cull in culls {
                            let (r, f) = count(cull, &labeled);
                            records.push(r);
                            bad.extend(f);
                        }
                        (records, bad)
                    });
                    progress(workload.rays as u64);
                    out.lock().unwrap()[i] = Some(result);
                }
            });
        }
    });
    let mut records = Vec::new();
    let mut false_rejects = Vec::new();
    for r in out.into_inner().unwrap() {
        let (rec, bad) = r.expect("every unit ran")?;
        records.extend(rec);
        false_rejects.extend(bad);
    }
    Ok((records, false_rejects))
}
