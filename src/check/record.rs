//! The one check file (`meta.tool` = `check`) and its records, for every shape and
//! precision: a class of rays (a shape's member, a ray family) holds its oracle
//! labels per ray kind, each cull's counts, the captures a shape adds (the wedge's
//! cut-away misses) and each intersector's answers against the oracle.
//!
//! Every count is a sum over rays, so a class drawn in several jobs is the sum of their
//! records ([`ClassRecord::add`]); the figures that are not sums (the largest t error) are
//! maxima, and the rates are recomputed from the counts once the class is whole
//! ([`ClassRecord::finish`]). `compare` recomputes every rate from the counts, too.

pub use crate::check_counts::{CullCounts, KindRecord};
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// The check file's schema: the results files' (`read_json` holds every file to it); the
/// kind is `meta.tool` = [`TOOL`] (before, one kind per shape, refused by `results_file`).
pub const SCHEMA_VERSION: u32 = crate::results::SCHEMA_VERSION;

/// The file's `meta.tool`.
pub const TOOL: &str = "check";

/// One cull (or a cull behind a shape's own cull, `cychosz+wedge`) on one class.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CullRecord {
    /// The cull's label: its stable name, `+wedge` behind the wedge.
    pub cull: String,
    /// Whether the cull accepts the class's shape (false: declined, keeps every ray).
    pub accepts: bool,
    /// Its counts (in the file, fields of the record).
    #[serde(flatten)]
    pub counts: CullCounts,
    /// rejected / rays.
    pub rejection_rate: f64,
    /// far_misses_rejected / far_misses (null without far misses).
    pub capture: Option<f64>,
}

impl CullRecord {
    /// A record with no rays counted yet.
    pub fn new(cull: String, accepts: bool) -> CullRecord {
        CullRecord {
            cull,
            accepts,
            counts: CullCounts::default(),
            rejection_rate: 0.0,
            capture: None,
        }
    }
}

/// A share of some misses that one cull rejects, beyond the far misses every cull is held
/// to (a segment's cut-away misses and the cull that cuts the segment).
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct CaptureRecord {
    /// What the misses are (`cut-away`).
    pub name: String,
    /// Which cull is held to them (`wedge`).
    pub by: String,
    /// The misses.
    pub misses: u64,
    /// Of those, rejected.
    pub rejected: u64,
    /// rejected / misses (null without any).
    pub capture: Option<f64>,
}

/// Median, p99 and max of a set of errors (nearest rank).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct ErrorStats {
    /// Median.
    pub median: f64,
    /// 99th percentile.
    pub p99: f64,
    /// Maximum.
    pub max: f64,
}

impl ErrorStats {
    /// The stats of `errors`; `None` when empty.
    pub fn of(mut errors: Vec<f64>) -> Option<ErrorStats> {
        if errors.is_empty() {
            return None;
        }
        errors.sort_by(f64::total_cmp);
        let rank =
            |q: f64| errors[((q * errors.len() as f64).ceil() as usize).clamp(1, errors.len()) - 1];
        Some(ErrorStats {
            median: rank(0.5),
            p99: rank(0.99),
            max: errors[errors.len() - 1],
        })
    }
}

/// One intersector's answers on one class against the oracle.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct AnswerRecord {
    /// The intersector (`intersect`, `intersect_all`, `cert`, `f32`, `peer`).
    pub who: String,
    /// Whether its wrong answers fail the check (false for a peer it is measured against).
    pub ours: bool,
    /// Its wrong answers by kind (`missed`, `invented`, `wrong_face`, …): each must stay 0
    /// for ours.
    pub wrong: BTreeMap<String, u64>,
    /// Its other counts (`escalated`, `hits_answered`, …).
    pub counts: BTreeMap<String, u64>,
    /// Its figures that are maxima over rays (`max_t_error_rel`, …).
    pub max: BTreeMap<String, f64>,
    /// Its t error's median, p99 and max, where one job holds the whole class.
    pub t_error: Option<ErrorStats>,
}

impl AnswerRecord {
    /// An intersector with its wrong-answer kinds `wrong` at 0.
    pub fn new(who: &str, ours: bool, wrong: &[&str]) -> AnswerRecord {
        AnswerRecord {
            who: who.into(),
            ours,
            wrong: wrong.iter().map(|w| ((*w).into(), 0)).collect(),
            ..AnswerRecord::default()
        }
    }

    /// Every wrong answer.
    pub fn wrong_answers(&self) -> u64 {
        self.wrong.values().sum()
    }

    /// A count by name (0 when absent).
    pub fn count(&self, name: &str) -> u64 {
        self.counts.get(name).copied().unwrap_or(0)
    }

    /// Raises the maximum `name` to `value`.
    pub fn raise(&mut self, name: &str, value: f64) {
        let m = self.max.entry(name.into()).or_insert(0.0);
        *m = m.max(value);
    }

    /// Adds `o`'s counts and maxima (the same intersector on other rays of the class).
    fn add(&mut self, o: &AnswerRecord) {
        for (k, v) in &o.wrong {
            *self.wrong.entry(k.clone()).or_default() += v;
        }
        for (k, v) in &o.counts {
            *self.counts.entry(k.clone()).or_default() += v;
        }
        for (k, v) in &o.max {
            self.raise(k, *v);
        }
    }
}

/// One class of rays.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct ClassRecord {
    /// The class's label, unique in its file: the key `compare` pairs by.
    pub label: String,
    /// The shape's parameters of the class (`nu`, `aspect`, `delta_phi_deg`, …).
    pub params: BTreeMap<String, f64>,
    /// The shape's words for the class (`kind`: ring/horn/spindle, …).
    pub words: BTreeMap<String, String>,
    /// Rays drawn.
    pub rays: u64,
    /// The oracle's labels per ray kind.
    pub kinds: Vec<KindRecord>,
    /// Per cull, in the shape's order.
    pub culls: Vec<CullRecord>,
    /// The shape's own captures.
    pub captures: Vec<CaptureRecord>,
    /// Per intersector.
    pub answers: Vec<AnswerRecord>,
    /// ns per ray by intersector (the minimum over rounds on one thread), where timed.
    pub ns_per_ray: Option<BTreeMap<String, f64>>,
}

impl ClassRecord {
    /// False rejects over every cull.
    pub fn false_rejects(&self) -> u64 {
        self.culls.iter().map(|c| c.counts.false_rejects).sum()
    }

    /// Wrong answers of our intersectors.
    pub fn ours_wrong(&self) -> u64 {
        let ours = self.answers.iter().filter(|a| a.ours);
        ours.map(AnswerRecord::wrong_answers).sum()
    }

    /// Whether the class fails the check: a false reject or a wrong answer of ours.
    pub fn failed(&self) -> bool {
        self.false_rejects() + self.ours_wrong() > 0
    }

    /// Oracle labels over every kind: (hits, misses, ambiguous).
    pub fn labels(&self) -> (u64, u64, u64) {
        let sum = |f: fn(&KindRecord) -> u64| self.kinds.iter().map(f).sum();
        (sum(|k| k.hits), sum(|k| k.misses), sum(|k| k.ambiguous))
    }

    /// Adds `o`'s counts (the same class, drawn in another job); records in the same
    /// order, as one shape makes them.
    pub fn add(&mut self, o: &ClassRecord) {
        self.rays += o.rays;
        for (a, b) in self.kinds.iter_mut().zip(&o.kinds) {
            a.add(b);
        }
        for (a, b) in self.culls.iter_mut().zip(&o.culls) {
            a.counts.add(&b.counts);
        }
        for (a, b) in self.captures.iter_mut().zip(&o.captures) {
            a.misses += b.misses;
            a.rejected += b.rejected;
        }
        for (a, b) in self.answers.iter_mut().zip(&o.answers) {
            a.add(b);
        }
    }

    /// The rates from the counts, once the class is whole.
    pub fn finish(&mut self) {
        let rays = usize::try_from(self.rays).unwrap_or(usize::MAX).max(1);
        for c in &mut self.culls {
            c.rejection_rate = c.counts.rejection_rate(rays);
            c.capture = c.counts.capture();
        }
        for c in &mut self.captures {
            c.capture = (c.misses > 0).then(|| c.rejected as f64 / c.misses as f64);
        }
    }
}

/// The check file.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CheckFile {
    /// Always [`SCHEMA_VERSION`].
    pub schema_version: u32,
    /// Provenance, as in the other results files (`meta.tool` = [`TOOL`]).
    pub meta: crate::results::Meta,
    /// The shape checked (`torus-cull check --shape`).
    pub shape: String,
    /// `f64` (the culls and the exact intersection) or `f32` (the f32 paths).
    pub precision: String,
    /// Rays per class.
    pub rays_per_class: u64,
    /// The seed.
    pub seed: u64,
    /// Which oracle labelled the rays.
    pub oracle: String,
    /// The tolerances and thresholds the counts were made with (`eta_rel`, …).
    pub constants: BTreeMap<String, f64>,
    /// What the charts put on x and which classes share a chart.
    pub chart: ChartAxes,
    /// One record per class, in the shape's order.
    pub classes: Vec<ClassRecord>,
}

/// What a check file's charts put on x (a key of the classes' `params`, and its axis
/// title) and the parameters whose values make one chart's group.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ChartAxes {
    /// The x parameter.
    pub x: String,
    /// Its axis title.
    pub x_title: String,
    /// The parameters a chart's classes share.
    pub group_by: Vec<String>,
}
