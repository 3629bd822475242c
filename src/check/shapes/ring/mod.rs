//! `torus-cull check --shape ring --precision f32` (alias `torus-cull f32-check`; issue
//! 19): the certified f32 intersection, the whole f32 path and the
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

pub use crate::check::record::ErrorStats;
use crate::check::record::{AnswerRecord, ClassRecord, KindRecord};
use crate::check::{About, CheckShape, Job};
use crate::oracle::{
    OracleClass, Query, classify_from_surface, first_crossing_from_surface, reference_roots,
};
use families::Family;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use torus_cull::{F32Hit, F32Verdict, Ray, Torus, intersect_f32, intersect_f32_certified};

pub use crate::peer_f32::intersect_peer_f32;

/// The tolerance's part proportional to the torus: 2e-4·(R + r).
pub const TOLERANCE_REL: f64 = 2e-4;
/// The tolerance's part in ulps of `t`.
pub const TOLERANCE_ULPS: f64 = 4.0;

/// The seed `--seed` defaults to.
pub const SEED: u64 = 20261121;

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
pub fn time(rays: &[(Torus, Ray)], rounds: u32) -> Timings {
    use std::hint::black_box;
    use std::time::Instant;
    let run = |f: &dyn Fn(&Torus, &Ray) -> bool| {
        let start = Instant::now();
        let mut n = 0u32;
        for r in rays {
            n += u32::from(f(black_box(&r.0), black_box(&r.1)));
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

/// A family's label: its name, and its ν when it has one (the workload generators'
/// families share a name across ν).
pub fn family_label(family: &Family) -> String {
    match family.nu() {
        Some(nu) => format!("{} {nu}", family.name),
        None => family.name.clone(),
    }
}

/// The tally as an answer record: `missed`, `spurious` and `far` its wrong answers,
/// `escalated` and `hits_answered` its counts, and its t error's stats.
fn answer(who: &str, ours: bool, t: &Tally) -> AnswerRecord {
    let mut a = AnswerRecord::new(who, ours, &[]);
    for (k, v) in [
        ("missed", t.missed),
        ("spurious", t.spurious),
        ("far", t.far),
    ] {
        a.wrong.insert(k.into(), v);
    }
    for (k, v) in [
        ("escalated", t.escalated),
        ("hits_answered", t.hits_answered),
    ] {
        a.counts.insert(k.into(), v);
    }
    a.t_error = t.t_error;
    a
}

/// Count one family on labelled rays: the certified verdict (`cert`), the whole f32
/// path (`f32`), both ours, and the peer (`peer`), measured, not held to the rules.
pub fn record(family: &Family, rays: &[Labeled]) -> ClassRecord {
    let count = |c: OracleClass| rays.iter().filter(|r| r.class == c).count() as u64;
    let nus = rays
        .iter()
        .map(|r| f64::from(r.torus.major_radius()) / f64::from(r.torus.minor_radius()));
    let [lo, hi] = match family.nu() {
        Some(nu) => [nu, nu],
        None => [
            nus.clone().fold(f64::INFINITY, f64::min),
            nus.fold(f64::NEG_INFINITY, f64::max),
        ],
    };
    let mut params: BTreeMap<String, f64> =
        [("nu_lo".to_string(), lo), ("nu_hi".into(), hi)].into();
    if let Some(nu) = family.nu() {
        params.insert("nu".into(), nu);
    }
    let kind = KindRecord {
        kind: "all".into(),
        rays: rays.len() as u64,
        hits: count(OracleClass::Hit),
        misses: count(OracleClass::Miss),
        ambiguous: count(OracleClass::Ambiguous),
    };
    ClassRecord {
        label: family_label(family),
        params,
        words: [("family".to_string(), family.name.clone())].into(),
        rays: rays.len() as u64,
        kinds: vec![kind],
        culls: Vec::new(),
        captures: Vec::new(),
        answers: vec![
            answer("cert", true, &tally(rays, certified)),
            answer("f32", true, &tally(rays, f32_path)),
            answer("peer", false, &tally(rays, peer)),
        ],
        ns_per_ray: None,
    }
}

/// The ring torus's f32 paths as a check's shape: the ray [`families`], timed in
/// `rounds` rounds after the counts (0: not timed).
pub struct RingF32 {
    /// The families, in order.
    pub families: Vec<Family>,
    /// Timing rounds per family.
    pub rounds: u32,
}

impl CheckShape for RingF32 {
    fn about(&self) -> About {
        About {
            name: "ring",
            precision: "f32",
            oracle: "oracle (Query; on-surface rule for rays from a surface point)",
            constants: vec![
                ("tolerance_rel", TOLERANCE_REL),
                ("tolerance_ulps", TOLERANCE_ULPS),
            ],
            chart: ("nu_lo", "ν = R/r (log scale)", &[]),
            spec: String::new(),
        }
    }
    fn labels(&self) -> Vec<String> {
        self.families.iter().map(family_label).collect()
    }
    fn jobs(&self, _rays: usize) -> usize {
        1
    }
    fn check_job(&self, job: Job) -> Result<(ClassRecord, Vec<String>), String> {
        let family = &self.families[job.index];
        let pairs = family
            .generate(job.rays, job.seed)
            .map_err(|e| format!("{}: {e}", family.name))?;
        Ok((record(family, &label(&pairs)), Vec::new()))
    }
    fn after(&self, job: Job, record: &mut ClassRecord) {
        if self.rounds == 0 {
            return;
        }
        // Drawn again (the draw is deterministic and cheap), so that the labelled rays
        // need not be kept for every family at once.
        let Ok(pairs) = self.families[job.index].generate(job.rays, job.seed) else {
            return;
        };
        let t = time(&pairs, self.rounds);
        let ns = [
            ("f32", t.f32_path),
            ("peer", t.peer),
            ("f64_intersect", t.f64_intersect),
            ("rounds", f64::from(t.rounds)),
        ];
        record.ns_per_ray = Some(ns.map(|(k, v)| (k.to_string(), v)).into());
    }
}

/// The ν a family without one ν spans, `lo..hi` to four significant digits, or one value
/// when the two agree to that precision (a family of one ray). It was `{lo:.3}-{hi:.0}`,
/// which read `3.145-3` for rays between 3.145 and 3.4.
pub fn nu_span([lo, hi]: [f64; 2]) -> String {
    let sig = |v: f64| crate::number::Num(format!("{v:.3e}").parse().unwrap_or(v)).to_string();
    let (lo, hi) = (sig(lo), sig(hi));
    if lo == hi { lo } else { format!("{lo}..{hi}") }
}

/// The ring torus to the lab: the circular oracle ([`Query::dray`], refusing a line it
/// cannot reach; the on-surface rule for a ray from the surface) and its size R + r.
impl crate::lab_shape::LabShape for Torus {
    type Solid = Torus;

    fn solid(&self) -> &Torus {
        self
    }

    fn label(&self, ray: &torus_cull::DRay) -> Result<crate::oracle::OracleLabel, String> {
        let query = Query::dray(self, ray);
        query.check_reach()?;
        Ok(if ray.starts_on_surface() {
            classify_from_surface(&query)
        } else {
            query.classify()
        })
    }

    fn size(&self) -> f64 {
        self.major_radius_f64() + self.minor_radius_f64()
    }
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

    /// The ray along +x from (−5, y, 0) on the torus R = 2, r = 1, labelled.
    fn along_x(y: f32) -> Labeled {
        let torus = Torus::canonical(2.0, 1.0).unwrap();
        let ray = Ray::new(glam::Vec3::new(-5.0, y, 0.0), glam::Vec3::X).unwrap();
        Labeled::new(torus, ray)
    }

    #[test]
    fn tally_counts_missed_spurious_far_and_escalations() {
        let (hit, miss) = (along_x(0.0), along_x(5.0));
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
        let hit = along_x(0.0);
        let t = tally(&[hit], |_: &Torus, _: &Ray| Answer::plain(Some(f32::NAN)));
        assert_eq!((t.hits_answered, t.far, t.t_error), (1, 1, None));
        let other = along_x(0.25);
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
