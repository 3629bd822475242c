//! The f32 check (issue 19): the certified f32 intersection, the whole f32 path and the
//! plain f32 closed form of shaders ([`crate::peer_f32`]) counted against the
//! oracle on the same rays, family by family ([`families`]).
//!
//! Per ray the oracle gives the class (hit / miss / ambiguous, [`Query::classify`]) and,
//! for a hit, the first crossing in the ray's range ([`reference_roots`]). An
//! intersector's [`Answer`] is then tallied ([`Tally`]):
//!
//! - **missed**: a definite hit answered "miss"; **spurious**: a definite miss answered
//!   with a `t`. Ambiguous rays count for neither.
//! - **t error**: `|t − t_oracle|·|d| / (R + r)` over the definite hits answered with a
//!   `t`: median, p99 (nearest rank) and max.
//! - **far**: such an answer outside the tolerance,
//!   `|t − t_oracle|·|d| > 2e-4·(R + r) + 4·ulp(t)·|d|` (the tolerance is on the length
//!   along the ray; `|d| = 1` for every family but `camera`).
//! - **escalated**: rays the certified f32 path handed to the f64 solver. For the
//!   certified verdict alone an escalated ray has no answer and counts for nothing else;
//!   for the whole f32 path ([`torus_cull::intersect_f32`]) it is answered by f64 and counted.

pub mod families;
pub mod plot;

use crate::oracle::{
    OracleClass, Query, classify_from_surface, first_crossing_from_surface, reference_roots,
};
use families::Family;
use serde::{Deserialize, Serialize};
use std::fmt::Write;
use torus_cull::{F32Hit, F32Verdict, Ray, Torus, intersect_f32, intersect_f32_certified};

pub use crate::peer_f32::intersect_peer_f32;

/// The tolerance's part proportional to the torus: 2e-4·(R + r).
pub const TOLERANCE_REL: f64 = 2e-4;
/// The tolerance's part in ulps of `t`.
pub const TOLERANCE_ULPS: f64 = 4.0;

/// The schema version of the f32-check JSON.
pub const SCHEMA_VERSION: u32 = 1;

/// One ray with the oracle's label.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Labeled {
    /// The torus.
    pub torus: Torus,
    /// The ray.
    pub ray: Ray,
    /// The oracle's class over the ray's range.
    pub class: OracleClass,
    /// The oracle's margin (length units; negative enters the tube).
    pub margin: f64,
    /// For a definite hit, the first crossing in the range (units of the ray's `d`).
    pub first_root: Option<f64>,
}

impl Labeled {
    /// The oracle's label of `ray`; for a ray from a surface point
    /// ([`Ray::from_surface`]), by the rule of docs/math.md §9 (the origin's own crossing
    /// excluded, [`classify_from_surface`]).
    pub fn new(torus: Torus, ray: Ray) -> Labeled {
        let query = Query::ray(&torus, &ray);
        let (label, first) = if ray.starts_on_surface() {
            (
                classify_from_surface(&query),
                first_crossing_from_surface as fn(&Query) -> Option<f64>,
            )
        } else {
            (
                query.classify(),
                first_root_in_range as fn(&Query) -> Option<f64>,
            )
        };
        let first_root = if label.class == OracleClass::Hit {
            first(&query)
        } else {
            None
        };
        Labeled {
            torus,
            ray,
            class: label.class,
            margin: label.margin,
            first_root,
        }
    }

    /// R + r, f64.
    pub fn outer(&self) -> f64 {
        f64::from(self.torus.major_radius()) + f64::from(self.torus.minor_radius())
    }

    /// The error of `t` against the first root, as a length over R + r, and whether it is
    /// within the tolerance; `None` without a root to compare to.
    pub fn t_error(&self, t: f32) -> Option<(f64, bool)> {
        let root = self.first_root?;
        let len = f64::from(self.ray.dir().length());
        let err = (f64::from(t) - root).abs() * len;
        let tol = TOLERANCE_REL * self.outer() + TOLERANCE_ULPS * ulp(t) * len;
        Some((err / self.outer(), err <= tol))
    }
}

/// The spacing of f32 at `t` (the gap to the next float away from zero).
pub fn ulp(t: f32) -> f64 {
    let a = t.abs();
    if !a.is_finite() {
        return f64::INFINITY;
    }
    f64::from(f32::from_bits(a.to_bits() + 1)) - f64::from(a)
}

/// Label `rays` with the oracle.
pub fn label(rays: &[(Torus, Ray)]) -> Vec<Labeled> {
    rays.iter().map(|&(t, r)| Labeled::new(t, r)).collect()
}

/// An intersector's answer for one ray.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Answer {
    /// The nearest hit's `t`, or `None` for a miss (or no answer).
    pub t: Option<f32>,
    /// The ray was escalated to the f64 solver.
    pub escalated: bool,
    /// The intersector answered (false only for an escalated certified verdict).
    pub decided: bool,
}

impl Answer {
    /// A plain answer (no escalation): a hit at `t` or a miss.
    pub fn plain(t: Option<f32>) -> Answer {
        Answer {
            t,
            escalated: false,
            decided: true,
        }
    }
}

impl From<F32Verdict> for Answer {
    fn from(verdict: F32Verdict) -> Answer {
        match verdict {
            F32Verdict::Hit { t, .. } => Answer::plain(Some(t)),
            F32Verdict::Miss => Answer::plain(None),
            // `F32Verdict` is non-exhaustive: anything else is not a proof either.
            _ => Answer {
                t: None,
                escalated: true,
                decided: false,
            },
        }
    }
}

impl From<F32Hit> for Answer {
    fn from(hit: F32Hit) -> Answer {
        Answer {
            t: hit.hit.map(|h| h.t),
            escalated: hit.escalated,
            decided: true,
        }
    }
}

/// The certified verdict alone ([`intersect_f32_certified`]).
pub fn certified(torus: &Torus, ray: &Ray) -> Answer {
    intersect_f32_certified(torus, ray).into()
}

/// The whole f32 path, escalations answered in f64 ([`intersect_f32`]).
pub fn f32_path(torus: &Torus, ray: &Ray) -> Answer {
    intersect_f32(torus, ray).into()
}

/// The peer ([`intersect_peer_f32`]).
pub fn peer(torus: &Torus, ray: &Ray) -> Answer {
    Answer::plain(intersect_peer_f32(torus, ray))
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

/// One intersector's counts on one family (see the module docs).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Tally {
    /// Rays escalated to f64.
    pub escalated: u64,
    /// escalated / rays.
    pub escalation_rate: f64,
    /// Definite hits answered "miss".
    pub missed: u64,
    /// Definite misses answered with a `t`.
    pub spurious: u64,
    /// Definite hits answered with a `t` (the t error's sample).
    pub hits_answered: u64,
    /// Of those, the ones outside the tolerance.
    pub far: u64,
    /// `|t − t_oracle|·|d| / (R + r)` over `hits_answered` whose t is finite (a NaN or
    /// infinite t is counted in `far`); null when there are none.
    pub t_error: Option<ErrorStats>,
}

impl Tally {
    /// Whether the intersector broke the promise here (missed, spurious or far).
    pub fn failed(&self) -> bool {
        self.missed + self.spurious + self.far > 0
    }
}

/// Tally `intersector` on labelled rays.
pub fn tally(rays: &[Labeled], intersector: impl Fn(&Torus, &Ray) -> Answer) -> Tally {
    let mut tally = Tally {
        escalated: 0,
        escalation_rate: 0.0,
        missed: 0,
        spurious: 0,
        hits_answered: 0,
        far: 0,
        t_error: None,
    };
    let mut errors = Vec::new();
    for ray in rays {
        let answer = intersector(&ray.torus, &ray.ray);
        tally.escalated += u64::from(answer.escalated);
        if !answer.decided {
            continue;
        }
        match (ray.class, answer.t) {
            (OracleClass::Hit, None) => tally.missed += 1,
            (OracleClass::Hit, Some(t)) => {
                tally.hits_answered += 1;
                match ray.t_error(t) {
                    // A t that is not finite (a peer's NaN) is far, and stays out of the
                    // stats: JSON has no NaN, and serde would write it as null.
                    Some((err, within)) if err.is_finite() => {
                        errors.push(err);
                        tally.far += u64::from(!within);
                    }
                    Some(_) => tally.far += 1,
                    // No root to compare to (never seen): it cannot be called near.
                    None => tally.far += 1,
                }
            }
            (OracleClass::Miss, Some(_)) => tally.spurious += 1,
            _ => {}
        }
    }
    tally.escalation_rate = if rays.is_empty() {
        0.0
    } else {
        tally.escalated as f64 / rays.len() as f64
    };
    tally.t_error = ErrorStats::of(errors);
    tally
}

/// The first reference root in the query's range.
fn first_root_in_range(query: &Query) -> Option<f64> {
    reference_roots(query).first().copied()
}

/// Nanoseconds per ray, the minimum over interleaved rounds on one thread.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Timings {
    /// The whole f32 path ([`intersect_f32`]).
    pub f32_path: f64,
    /// The peer.
    pub peer: f64,
    /// The f64 exact intersection ([`torus_cull::intersect()`]), for scale.
    pub f64_intersect: f64,
    /// Rounds each was timed.
    pub rounds: u32,
}

/// Time the f32 path, the peer and the f64 intersection on the same rays, in `rounds`
/// interleaved rounds (the order rotating from round to round); each one's minimum per
/// ray. Indicative only: on a loaded machine use paired timings for claims.
pub fn time(rays: &[Labeled], rounds: u32) -> Timings {
    use std::hint::black_box;
    use std::time::Instant;
    let run = |f: &dyn Fn(&Torus, &Ray) -> bool| {
        let start = Instant::now();
        let mut n = 0u32;
        for r in rays {
            n += u32::from(f(black_box(&r.torus), black_box(&r.ray)));
        }
        black_box(n);
        start.elapsed().as_secs_f64() * 1e9 / rays.len().max(1) as f64
    };
    type Contender<'a> = &'a dyn Fn(&Torus, &Ray) -> bool;
    let contenders: [Contender; 3] = [
        &|t, r| intersect_f32(t, r).hit.is_some(),
        &|t, r| intersect_peer_f32(t, r).is_some(),
        &|t, r| torus_cull::intersect(t, r).is_some(),
    ];
    let mut best = [f64::INFINITY; 3];
    for round in 0..rounds as usize {
        for k in 0..3 {
            let i = (round + k) % 3;
            best[i] = best[i].min(run(contenders[i]));
        }
    }
    Timings {
        f32_path: best[0],
        peer: best[1],
        f64_intersect: best[2],
        rounds,
    }
}

/// One family's figures.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct FamilyRecord {
    /// The family's name.
    pub family: String,
    /// ν, or null where ν is drawn per ray (log-uniform in `nu_range`).
    pub nu: Option<f64>,
    /// The ν the family's rays span.
    pub nu_range: [f64; 2],
    /// Rays.
    pub rays: u64,
    /// Oracle definite hits.
    pub hits: u64,
    /// Oracle definite misses.
    pub misses: u64,
    /// Oracle ambiguous (counted by nothing but `rays`).
    pub ambiguous: u64,
    /// The certified verdict alone ([`intersect_f32_certified`]).
    pub certified: Tally,
    /// The whole f32 path ([`intersect_f32`]).
    pub f32_path: Tally,
    /// The plain f32 closed form of shaders ([`intersect_peer_f32`]).
    pub peer: Tally,
    /// ns per ray, null when not timed.
    pub ns_per_ray: Option<Timings>,
}

impl FamilyRecord {
    /// Whether ours (the certified verdict or the whole f32 path) missed a hit, reported
    /// a spurious one or put a `t` outside the tolerance.
    pub fn ours_failed(&self) -> bool {
        self.certified.failed() || self.f32_path.failed()
    }
}

/// Count and (with `rounds > 0`) time one family on labelled rays.
pub fn record(family: &Family, rays: &[Labeled], rounds: u32) -> FamilyRecord {
    let count = |c: OracleClass| rays.iter().filter(|r| r.class == c).count() as u64;
    let nu_range = match family.nu() {
        Some(nu) => [nu, nu],
        None => {
            let nus = rays
                .iter()
                .map(|r| f64::from(r.torus.major_radius()) / f64::from(r.torus.minor_radius()));
            let lo = nus.clone().fold(f64::INFINITY, f64::min);
            let hi = nus.fold(f64::NEG_INFINITY, f64::max);
            [lo, hi]
        }
    };
    FamilyRecord {
        family: family.name.clone(),
        nu: family.nu(),
        nu_range,
        rays: rays.len() as u64,
        hits: count(OracleClass::Hit),
        misses: count(OracleClass::Miss),
        ambiguous: count(OracleClass::Ambiguous),
        certified: tally(rays, certified),
        f32_path: tally(rays, f32_path),
        peer: tally(rays, peer),
        ns_per_ray: (rounds > 0).then(|| time(rays, rounds)),
    }
}

/// Generate, label, count and time every family: the labelling on `threads` threads, the
/// timings afterwards on one. `progress(done, total)` is called as families finish.
pub fn check(
    families: &[Family],
    rays: usize,
    seed: u64,
    threads: usize,
    rounds: u32,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<Vec<FamilyRecord>, crate::workload::GenerateError> {
    use std::sync::Mutex;
    use std::sync::atomic::{AtomicUsize, Ordering};
    let next = AtomicUsize::new(0);
    let done = AtomicUsize::new(0);
    let labeled: Mutex<Vec<Option<Result<Vec<Labeled>, _>>>> =
        Mutex::new(vec![None; families.len()]);
    std::thread::scope(|s| {
        for _ in 0..threads.max(1) {
            s.spawn(|| {
                loop {
                    let i = next.fetch_add(1, Ordering::Relaxed);
                    let Some(family) = families.get(i) else {
                        break;
                    };
                    let result = family.generate(rays, seed).map(|pairs| label(&pairs));
                    labeled.lock().expect("no worker panics holding it")[i] = Some(result);
                    progress(done.fetch_add(1, Ordering::Relaxed) + 1, families.len());
                }
            });
        }
    });
    let labeled = labeled.into_inner().expect("no worker panicked");
    families
        .iter()
        .zip(labeled)
        .map(|(family, rays)| {
            let rays = rays.expect("every family was labelled")?;
            Ok(record(family, &rays, rounds))
        })
        .collect()
}

/// The f32-check JSON file.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CheckFile {
    /// Always [`SCHEMA_VERSION`].
    pub schema_version: u32,
    /// Provenance, as in the results files (`meta.workload` is `f32-check`,
    /// `meta.workload_sha256` hashes the family list and sizes, `meta.tool` is
    /// `f32-check`).
    pub meta: crate::results::Meta,
    /// Rays per family.
    pub rays_per_family: u64,
    /// The tolerance on an accepted `t`: `rel`·(R + r) + `ulps`·ulp(t).
    pub tolerance: Tolerance,
    /// One record per family, in table order.
    pub families: Vec<FamilyRecord>,
}

/// The tolerance on an accepted `t`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Tolerance {
    /// × (R + r).
    pub rel: f64,
    /// × ulp(t).
    pub ulps: f64,
}

impl CheckFile {
    /// A file for `families` drawn with `rays` per family from `seed`.
    pub fn new(families: Vec<FamilyRecord>, rays: usize, seed: u64, threads: usize) -> CheckFile {
        let mut spec = format!("f32-check v{SCHEMA_VERSION} rays {rays} seed {seed}");
        for f in &families {
            let _ = write!(spec, " {}@{:?}", f.family, f.nu);
        }
        let workload = crate::workload::spec::Workload::drawn("f32-check", seed, rays, &spec);
        let mut meta = crate::results::Results::new(&workload, "f32-check").meta;
        meta.threads = Some(threads as u64);
        CheckFile {
            schema_version: SCHEMA_VERSION,
            meta,
            rays_per_family: rays as u64,
            tolerance: Tolerance {
                rel: TOLERANCE_REL,
                ulps: TOLERANCE_ULPS,
            },
            families,
        }
    }
}

fn opt_stats(s: Option<ErrorStats>) -> [String; 3] {
    match s {
        None => ["-".into(), "-".into(), "-".into()],
        Some(s) => [s.median, s.p99, s.max].map(|v| format!("{v:.1e}")),
    }
}

/// The table's columns; `family` to `amb` are filled on each family's first line only,
/// `f64 ns/ray` on its `f32` line, beside the f32 path's own time.
const TABLE_HEADER: [&str; 16] = [
    "family",
    "nu",
    "rays",
    "hit",
    "miss",
    "amb",
    "who",
    "esc%",
    "missed",
    "spurious",
    "far",
    "t err med",
    "p99",
    "max",
    "ns/ray",
    "f64 ns/ray",
];

/// The table: per family one line each for the certified verdict (`cert`), the whole f32
/// path (`f32`) and the peer (`peer`): escalated %, missed, spurious, far, the t error
/// (× (R + r)) and ns per ray.
pub fn table(records: &[FamilyRecord]) -> String {
    let rows: Vec<[String; 16]> = records.iter().flat_map(family_rows).collect();
    let mut out = aligned(&TABLE_HEADER.map(String::from), &rows);
    out.push_str(&totals(records));
    out
}

/// `r`'s three lines of the table: `cert`, `f32` and `peer`.
fn family_rows(r: &FamilyRecord) -> Vec<[String; 16]> {
    let nu = match r.nu {
        Some(nu) => format!("{nu}"),
        None => nu_span(r.nu_range),
    };
    let lines = [
        ("cert", &r.certified, None),
        ("f32", &r.f32_path, r.ns_per_ray.map(|t| t.f32_path)),
        ("peer", &r.peer, r.ns_per_ray.map(|t| t.peer)),
    ];
    let row = |i: usize, (who, t, ns): (&str, &Tally, Option<f64>)| {
        let first = i == 0;
        let lead = |s: String| if first { s } else { String::new() };
        // The peer never escalates: it has no f64 to hand a ray to.
        let esc = if who == "peer" {
            "-".to_string()
        } else {
            format!("{:.2}", 100.0 * t.escalation_rate)
        };
        let [med, p99, max] = opt_stats(t.t_error);
        [
            lead(r.family.clone()),
            lead(nu.clone()),
            lead(r.rays.to_string()),
            lead(r.hits.to_string()),
            lead(r.misses.to_string()),
            lead(r.ambiguous.to_string()),
            who.to_string(),
            esc,
            t.missed.to_string(),
            t.spurious.to_string(),
            t.far.to_string(),
            med,
            p99,
            max,
            ns.map_or_else(|| "-".into(), |v| format!("{v:.1}")),
            // On the f32 path's row, beside the time it is the scale for.
            if who == "f32" {
                r.ns_per_ray
                    .map_or_else(|| "-".into(), |t| format!("{:.1}", t.f64_intersect))
            } else {
                String::new()
            },
        ]
    };
    lines
        .into_iter()
        .enumerate()
        .map(|(i, l)| row(i, l))
        .collect()
}

/// The ν a family without one ν spans, `lo..hi` to four significant digits, or one value
/// when the two agree to that precision (a family of one ray). It was `{lo:.3}-{hi:.0}`,
/// which read `3.145-3` for rays between 3.145 and 3.4.
pub fn nu_span([lo, hi]: [f64; 2]) -> String {
    let sig = |v: f64| crate::number::Num(format!("{v:.3e}").parse().unwrap_or(v)).to_string();
    let (lo, hi) = (sig(lo), sig(hi));
    if lo == hi { lo } else { format!("{lo}..{hi}") }
}

/// `header` and `rows` in columns as wide as their widest cell: family, nu and who to the
/// left, numbers to the right; no trailing blanks.
fn aligned(header: &[String; 16], rows: &[[String; 16]]) -> String {
    let mut widths = header.each_ref().map(|h| h.len());
    for row in rows {
        for (w, cell) in widths.iter_mut().zip(row) {
            *w = (*w).max(cell.chars().count());
        }
    }
    let mut out = String::new();
    for cells in std::iter::once(header).chain(rows) {
        for (i, (cell, w)) in cells.iter().zip(&widths).enumerate() {
            let sep = if i == 0 { "" } else { "  " };
            if i < 2 || i == 6 {
                let _ = write!(out, "{sep}{cell:<w$}");
            } else {
                let _ = write!(out, "{sep}{cell:>w$}");
            }
        }
        let trimmed = out.trim_end().len();
        out.truncate(trimmed);
        out.push('\n');
    }
    out
}

/// The totals over every family, after a blank line.
fn totals(records: &[FamilyRecord]) -> String {
    let sum = |f: &dyn Fn(&FamilyRecord) -> u64| records.iter().map(f).sum::<u64>();
    format!(
        "\ntotal: {} rays ({} hit, {} miss, {} ambiguous); missed/spurious/far: cert {}/{}/{}, \
         f32 {}/{}/{}, peer {}/{}/{}; escalated {}\n",
        sum(&|r| r.rays),
        sum(&|r| r.hits),
        sum(&|r| r.misses),
        sum(&|r| r.ambiguous),
        sum(&|r| r.certified.missed),
        sum(&|r| r.certified.spurious),
        sum(&|r| r.certified.far),
        sum(&|r| r.f32_path.missed),
        sum(&|r| r.f32_path.spurious),
        sum(&|r| r.f32_path.far),
        sum(&|r| r.peer.missed),
        sum(&|r| r.peer.spurious),
        sum(&|r| r.peer.far),
        sum(&|r| r.certified.escalated),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Issue 29: one ray's ν is one value, a range keeps four significant digits (it
    /// printed "3.145-3" for 3.145..3.4).
    #[test]
    fn nu_spans_keep_their_digits() {
        assert_eq!(nu_span([3.145, 3.145]), "3.145");
        assert_eq!(nu_span([3.145, 3.4]), "3.145..3.4");
        assert_eq!(nu_span([1.0123, 999.87]), "1.012..999.9");
        assert_eq!(nu_span([22.713, 22.713]), "22.71");
    }

    #[test]
    fn ulp_and_stats() {
        assert_eq!(ulp(1.0), f64::from(f32::EPSILON));
        assert_eq!(ulp(-2.0), 2.0 * f64::from(f32::EPSILON));
        let s = ErrorStats::of((1..=100).map(f64::from).collect()).unwrap();
        assert_eq!((s.median, s.p99, s.max), (50.0, 99.0, 100.0));
        assert_eq!(ErrorStats::of(Vec::new()), None);
    }

    #[test]
    fn tally_counts_missed_spurious_far_and_escalations() {
        let torus = Torus::canonical(2.0, 1.0).unwrap();
        let hit = Labeled::new(
            torus,
            Ray::new(glam::Vec3::new(-5.0, 0.0, 0.0), glam::Vec3::X).unwrap(),
        );
        let miss = Labeled::new(
            torus,
            Ray::new(glam::Vec3::new(-5.0, 5.0, 0.0), glam::Vec3::X).unwrap(),
        );
        assert_eq!(hit.class, OracleClass::Hit);
        assert!((hit.first_root.unwrap() - 2.0).abs() < 1e-12);
        assert_eq!(miss.class, OracleClass::Miss);
        let rays = [hit, miss];
        let always = |t: Option<f32>| move |_: &Torus, _: &Ray| Answer::plain(t);
        let t = tally(&rays, always(None));
        assert_eq!((t.missed, t.spurious, t.hits_answered), (1, 0, 0));
        let t = tally(&rays, always(Some(2.0)));
        assert_eq!((t.missed, t.spurious, t.far, t.hits_answered), (0, 1, 0, 1));
        // 2e-4·(R + r) = 6e-4 plus 4 ulp(2): 2.001 is far.
        let t = tally(&rays, always(Some(2.001)));
        assert_eq!(t.far, 1);
        let t = tally(&rays, |_: &Torus, _: &Ray| F32Verdict::Escalate.into());
        assert_eq!((t.escalated, t.missed, t.spurious), (2, 0, 0));
        assert_eq!(t.escalation_rate, 1.0);
    }

    /// A peer's NaN t is far and stays out of the error stats, so the file holds no null
    /// where a number belongs (f7cccf8-f32-check-spawned.json had `"max": null`).
    #[test]
    fn a_nan_t_is_far_and_out_of_the_stats() {
        let torus = Torus::canonical(2.0, 1.0).unwrap();
        let hit = Labeled::new(
            torus,
            Ray::new(glam::Vec3::new(-5.0, 0.0, 0.0), glam::Vec3::X).unwrap(),
        );
        let t = tally(&[hit], |_: &Torus, _: &Ray| Answer::plain(Some(f32::NAN)));
        assert_eq!((t.hits_answered, t.far, t.t_error), (1, 1, None));
        let other = Labeled::new(
            torus,
            Ray::new(glam::Vec3::new(-5.0, 0.25, 0.0), glam::Vec3::X).unwrap(),
        );
        let t = tally(&[hit, other], |_: &Torus, r: &Ray| {
            let exact = other.first_root.unwrap() as f32;
            Answer::plain(Some(if r.origin().y == 0.0 { f32::NAN } else { exact }))
        });
        assert_eq!((t.hits_answered, t.far), (2, 1));
        let stats = t.t_error.expect("the finite t's stats");
        assert!(stats.max.is_finite() && stats.max < 1e-6, "{stats:?}");
        let json = serde_json::to_string(&t).unwrap();
        assert!(!json.contains("null"), "{json}");
    }
}
