//! `torus-cull intervals RUN…`: whether the paired ratios' intervals hold from one run to
//! the next (the honesty check of docs/results.md).
//!
//! A 95 % interval promises that a repeat of the measurement lands inside it, or close. So
//! for every ordered pair of runs (i, j), i ≠ j, and every ratio record the runs share,
//! this counts whether run i's point estimate lies inside run j's intervals, three of
//! them:
//!
//! * the within-run interval (`ratio_ci`): the rounds' noise alone;
//! * the between-run interval (`ratio_ci_between`, `time --runs K`, K ≥ 2): the mean's
//!   interval over K runs. Even when it is honest, a repeat's mean, uncertain itself,
//!   lands inside it only about 83 % of the time (Cumming & Maillardet, 2006);
//! * the next-run interval ([`next_run_interval_of`], from run j's spread, for a repeat
//!   of run i's K): the prediction interval, which is the one that promises 95 %.
//!
//! It also gives the headline ratios' spread, `|ratioᵢ/ratioⱼ − 1|` over the pairs: the
//! headline is every total `compare` decides by (`total_ns`, a family member's, a pipe
//! bend's) against `cychosz`, and a BVH traversal's against `none` (issue 40: a cull at
//! a leaf is judged by what it saves over the box test alone), f64, on the CPU.
//!
//! The goals it checks (issue 29): coverage ≥ [`COVERAGE_GOAL`], judged by the next-run
//! interval where every run has K ≥ 2 (else by the widest interval the runs have), and a
//! worst headline change ≤ [`HEADLINE_CHANGE_GOAL`]. Only runs of one workload on one
//! machine are checked: across machines a ratio moves for reasons no interval describes.

use super::{check_unique, comparable, machine, ratio::ratio_key};
use crate::paired::runs::next_run_interval_of;
use crate::results::{CPU_DEVICE, F64_PRECISION, RatioRecord, Results};
use std::collections::BTreeMap;

/// The share of points that must fall inside the other runs' intervals.
pub const COVERAGE_GOAL: f64 = 0.95;

/// The largest change of a headline ratio between two runs.
pub const HEADLINE_CHANGE_GOAL: f64 = 0.03;

/// Points inside intervals, over the ordered pairs of runs.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Tally {
    /// Points checked: shared records × ordered pairs of runs.
    pub points: usize,
    /// Of those, inside the other run's within-run interval (`ratio_ci`).
    pub inside_within: usize,
    /// Inside the other run's between-run interval (`ratio_ci_between`), or its within-run
    /// one where it has no between-run interval.
    pub inside_between: usize,
    /// Inside the other run's next-run interval, or its between-run one where it has no
    /// run ratios.
    pub inside_next: usize,
}

impl Tally {
    /// The share inside the within-run intervals.
    #[must_use]
    pub fn within(&self) -> f64 {
        share(self.inside_within, self.points)
    }

    /// The share inside the between-run intervals.
    #[must_use]
    pub fn between(&self) -> f64 {
        share(self.inside_between, self.points)
    }

    /// The share inside the next-run intervals.
    #[must_use]
    pub fn next(&self) -> f64 {
        share(self.inside_next, self.points)
    }
}

fn share(part: usize, all: usize) -> f64 {
    if all == 0 {
        0.0
    } else {
        part as f64 / all as f64
    }
}

/// The check over a set of runs.
#[derive(Debug, Clone, PartialEq)]
pub struct Coverage {
    /// Runs checked.
    pub files: usize,
    /// Ratio records present in every run.
    pub shared: usize,
    /// Every shared record.
    pub all: Tally,
    /// The headline records alone.
    pub headline: Tally,
    /// Per headline record, the largest `|ratioᵢ/ratioⱼ − 1|` over the pairs of runs,
    /// sorted, with its key.
    pub headline_changes: Vec<(f64, String)>,
    /// Whether every run has between-run intervals (the goal judges by them).
    pub between_known: bool,
}

impl Coverage {
    /// The worst headline change (0 without headline records).
    #[must_use]
    pub fn worst_headline_change(&self) -> f64 {
        self.headline_changes.last().map_or(0.0, |c| c.0)
    }

    /// The median headline change (0 without headline records).
    #[must_use]
    pub fn median_headline_change(&self) -> f64 {
        let n = self.headline_changes.len();
        if n == 0 {
            return 0.0;
        }
        if n % 2 == 1 {
            self.headline_changes[n / 2].0
        } else {
            0.5 * (self.headline_changes[n / 2 - 1].0 + self.headline_changes[n / 2].0)
        }
    }

    /// The coverage the goal is judged by: next-run where every run has K ≥ 2 runs (then
    /// every record has its run ratios), else within-run.
    #[must_use]
    pub fn judged_coverage(&self) -> f64 {
        if self.between_known {
            self.all.next()
        } else {
            self.all.within()
        }
    }

    /// Whether both goals are met.
    #[must_use]
    pub fn goals_met(&self) -> bool {
        self.judged_coverage() >= COVERAGE_GOAL
            && self.worst_headline_change() <= HEADLINE_CHANGE_GOAL
    }
}

/// Whether a record is a headline ratio: a decisive total (`total_ns`, a family
/// member's or a pipe bend's, as `compare` judges them) against `cychosz`, or a BVH
/// traversal's against `none`; f64, on the CPU.
fn is_headline(r: &RatioRecord) -> bool {
    let reference = if crate::paired::bvh::BVH_METRICS.contains(&r.metric.as_str()) {
        "none"
    } else {
        "cychosz"
    };
    super::ratio::is_decisive(&r.metric)
        && r.reference == reference
        && r.precision == F64_PRECISION
        && r.device == CPU_DEVICE
}

fn inside(x: f64, ci: [f64; 2]) -> bool {
    ci[0] <= x && x <= ci[1]
}

/// The check over `runs` (named by `names` in errors): at least two runs of one
/// workload on one machine, each with ratio records and no duplicate keys.
pub fn coverage(runs: &[Results], names: &[String]) -> Result<Coverage, String> {
    if runs.len() < 2 {
        return Err(format!(
            "{} file given: the check needs at least 2 runs (allowed: 2 or more results files \
             of `torus-cull time` on one workload and machine)",
            runs.len()
        ));
    }
    for (run, name) in runs.iter().zip(names) {
        check_unique(run).map_err(|e| format!("{name}: {e}"))?;
        if run.ratio.is_empty() {
            return Err(format!(
                "{name}: no paired ratio records (section `ratio`): write the runs with \
                 `torus-cull time`"
            ));
        }
    }
    let (first, first_name) = (&runs[0], &names[0]);
    for (run, name) in runs.iter().zip(names).skip(1) {
        comparable(first, run).map_err(|e| format!("{first_name} vs {name}: {e}"))?;
        let diff = machine::differences(&first.meta, &run.meta);
        if diff.machines_differ() {
            return Err(format!(
                "{first_name} vs {name}: measured on different machines ({}): run-to-run \
                 spread is only defined on one machine",
                diff.machine.join("; ")
            ));
        }
    }
    let keyed: Vec<BTreeMap<String, &RatioRecord>> = runs
        .iter()
        .map(|r| r.ratio.iter().map(|x| (ratio_key(x), x)).collect())
        .collect();
    let shared: Vec<&String> = keyed[0]
        .keys()
        .filter(|k| keyed.iter().all(|m| m.contains_key(*k)))
        .collect();
    if shared.is_empty() {
        return Err(format!(
            "the runs share no ratio record (by `case ν cull/reference metric`): {}",
            names.join(", ")
        ));
    }
    // Timed in K ≥ 2 runs. A record whose runs but one were set aside as slow
    // (`runs_set_aside`) takes the spread pooled over its comparison; in a file written
    // before the pool, it has no between-run interval and its within-run one stands in.
    let between_known = runs.iter().all(|r| {
        r.ratio
            .iter()
            .all(|x| x.ratio_ci_between.is_some() || x.runs + x.runs_set_aside >= 2)
    });
    let mut report = Coverage {
        files: runs.len(),
        shared: shared.len(),
        all: Tally::default(),
        headline: Tally::default(),
        headline_changes: Vec::new(),
        between_known,
    };
    for key in shared {
        let records: Vec<&RatioRecord> = keyed.iter().map(|m| m[key]).collect();
        let headline = is_headline(records[0]);
        let mut worst = 0.0_f64;
        for (i, a) in records.iter().enumerate() {
            for (j, b) in records.iter().enumerate() {
                if i == j {
                    continue;
                }
                let within = inside(a.ratio, b.ratio_ci);
                let between_ci = b.ratio_ci_between.unwrap_or(b.ratio_ci);
                let between = inside(a.ratio, between_ci);
                let next = inside(
                    a.ratio,
                    next_run_interval_of(b, a.runs as usize).unwrap_or(between_ci),
                );
                for tally in [
                    Some(&mut report.all),
                    headline.then_some(&mut report.headline),
                ]
                .into_iter()
                .flatten()
                {
                    tally.points += 1;
                    tally.inside_within += usize::from(within);
                    tally.inside_between += usize::from(between);
                    tally.inside_next += usize::from(next);
                }
                worst = worst.max((a.ratio / b.ratio - 1.0).abs());
            }
        }
        if headline {
            report.headline_changes.push((worst, key.clone()));
        }
    }
    report
        .headline_changes
        .sort_by(|a, b| a.0.total_cmp(&b.0).then_with(|| a.1.cmp(&b.1)));
    Ok(report)
}

/// The report as text: the shares, the headline spread, the worst records and the verdict.
#[must_use]
pub fn render(c: &Coverage) -> String {
    let pct = |x: f64| format!("{:.1} %", 100.0 * x);
    let mut s = String::new();
    let pairs = c.files * (c.files - 1);
    s += &format!(
        "{} runs, {} shared ratio records ({} headline), {} ordered pairs of runs\n\n",
        c.files,
        c.shared,
        c.headline_changes.len(),
        pairs
    );
    s += "points inside the other runs' intervals   within-run   between-run   next-run\n";
    let known = |x: f64| {
        if c.between_known {
            pct(x)
        } else {
            "unknown".into()
        }
    };
    for (name, t) in [("all ratios", &c.all), ("headline ratios", &c.headline)] {
        s += &format!(
            "  {name:<39} {:>10}   {:>11}   {:>8}\n",
            pct(t.within()),
            known(t.between()),
            known(t.next())
        );
    }
    if c.between_known {
        s += "  (an honest between-run interval holds a repeat's mean about 83 % of the time;\n   \
              the next-run interval is the one that promises 95 %)\n";
    }
    s += &format!(
        "\nheadline change between runs (|ratio_i/ratio_j - 1|): median {}, worst {}\n",
        pct(c.median_headline_change()),
        pct(c.worst_headline_change())
    );
    for (change, key) in c.headline_changes.iter().rev().take(3) {
        s += &format!("  {:>6}  {key}\n", pct(*change));
    }
    let judged = if c.between_known {
        "next-run"
    } else {
        "within-run (the runs have no between-run intervals: time --runs K, K >= 2)"
    };
    s += &format!(
        "\ngoal: coverage >= {} ({judged}): {} -> {}\n",
        pct(COVERAGE_GOAL),
        pct(c.judged_coverage()),
        verdict(c.judged_coverage() >= COVERAGE_GOAL)
    );
    s += &format!(
        "goal: worst headline change <= {}: {} -> {}\n",
        pct(HEADLINE_CHANGE_GOAL),
        pct(c.worst_headline_change()),
        verdict(c.worst_headline_change() <= HEADLINE_CHANGE_GOAL)
    );
    s
}

/// A goal's verdict as the report prints it.
fn verdict(met: bool) -> &'static str {
    if met { "met" } else { "NOT MET" }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::compare::ratio::tests::{record, results};

    /// A record of `cull` with its within-run interval and, for K = 3 runs, a between-run one.
    fn rec(cull: &str, ratio: f64, ci: [f64; 2], between: Option<[f64; 2]>) -> RatioRecord {
        let mut r = record(cull, ratio, ci);
        r.ratio_ci_between = between;
        r.runs = if between.is_some() { 3 } else { 1 };
        r
    }

    fn run(ratio: Vec<RatioRecord>) -> Results {
        results(ratio, Vec::new())
    }

    fn names(n: usize) -> Vec<String> {
        (0..n).map(|i| format!("run{i}.json")).collect()
    }

    #[test]
    fn counts_points_inside_each_others_intervals() {
        // Run 0's skala (1.00) lies inside run 1's between-run interval but not its
        // within-run one; run 1's (1.04) lies outside both of run 0's. `aabb_alone` is a
        // `cull_ns` record: counted in all, not in the headline.
        let a = run(vec![
            rec("skala", 1.00, [0.99, 1.01], Some([0.98, 1.02])),
            rec("aabb_alone", 0.5, [0.49, 0.51], Some([0.48, 0.52])),
        ]);
        let b = run(vec![
            rec("skala", 1.04, [1.03, 1.05], Some([0.99, 1.06])),
            rec("aabb_alone", 0.5, [0.49, 0.51], Some([0.48, 0.52])),
        ]);
        let c = coverage(&[a, b], &names(2)).expect("two comparable runs");
        assert_eq!((c.shared, c.all.points, c.headline.points), (2, 4, 2));
        assert_eq!((c.all.inside_within, c.all.inside_between), (2, 3));
        // No run ratios: the next-run interval is the between-run one.
        assert_eq!(c.all.inside_next, 3);
        assert_eq!(
            (c.headline.inside_within, c.headline.inside_between),
            (0, 1)
        );
        assert!((c.worst_headline_change() - 0.04).abs() < 1e-12);
        assert!(
            !c.goals_met(),
            "75 % coverage and a 4 % change miss both goals"
        );
        let text = render(&c);
        assert!(
            text.contains("NOT MET") && text.contains("uniform 2 skala/cychosz total_ns"),
            "{text}"
        );
    }

    #[test]
    fn steady_runs_meet_the_goals() {
        let r = |x: f64| rec("skala", x, [x - 0.01, x + 0.01], Some([0.97, 1.03]));
        let runs = [run(vec![r(1.0)]), run(vec![r(1.01)]), run(vec![r(0.995)])];
        let c = coverage(&runs, &names(3)).expect("three runs");
        assert_eq!(c.all.points, 6);
        assert!(c.goals_met(), "{}", render(&c));
    }

    #[test]
    fn the_next_run_interval_holds_a_repeat_the_mean_interval_misses() {
        // Three runs each; run 1's mean (1.0253) lies outside run 0's between-run interval
        // of its mean (1.0 ± 2.5 %) but inside the next-run interval (± 3.5 %).
        let with_runs = |runs: [f64; 3]| {
            let mut r = rec("skala", 1.0, [0.999, 1.001], None);
            r.run_ratios = runs.to_vec();
            r.runs = 3;
            r.ratio = (runs.iter().map(|x| x.ln()).sum::<f64>() / 3.0).exp();
            r.ratio_ci_between = crate::paired::runs::between_run_interval(&runs);
            r
        };
        let a = run(vec![with_runs([0.99, 1.0, 1.01])]);
        let b = run(vec![with_runs([1.015, 1.025, 1.036])]);
        let c = coverage(&[a, b], &names(2)).expect("runs");
        assert!(c.between_known);
        assert_eq!(c.all.points, 2);
        assert!(c.all.inside_next > c.all.inside_between, "{c:?}");
    }

    #[test]
    fn without_between_run_intervals_the_within_run_ones_judge() {
        let r = |x: f64| rec("skala", x, [x - 0.001, x + 0.001], None);
        let c = coverage(&[run(vec![r(1.0)]), run(vec![r(1.01)])], &names(2)).expect("runs");
        assert!(!c.between_known);
        assert_eq!(c.judged_coverage(), 0.0);
        assert!(render(&c).contains("unknown"));
    }

    /// A family member's and a pipe bend's totals against `cychosz`, and a BVH
    /// traversal's against `none`, are headline ratios as `total_ns` is (they decide in
    /// `compare`), and a 10 % move of one fails the goal; the other reference's, and a
    /// `cull_ns` ratio, are not headlines.
    #[test]
    fn every_decisive_total_is_a_headline() {
        // The BVH's headline is over `none` (issue 40), the others' over `cychosz`.
        for (metric, reference) in [
            ("bvh_closest_ns", "none"),
            ("bvh_anyhit_ns", "none"),
            ("bvh_bounce_ns", "none"),
            ("bvh_batched_ns", "none"),
            ("family_total_ns", "cychosz"),
            ("bend_total_ns", "cychosz"),
            ("total_ns", "cychosz"),
        ] {
            let r = |x: f64, reference: &str| {
                let mut r = rec("skala", x, [x - 0.01, x + 0.01], Some([x - 0.2, x + 0.2]));
                r.metric = metric.into();
                r.reference = reference.into();
                r
            };
            let c = coverage(
                &[run(vec![r(1.0, reference)]), run(vec![r(1.1, reference)])],
                &names(2),
            )
            .expect("runs");
            assert_eq!(c.headline_changes.len(), 1, "{metric}");
            assert!(!c.goals_met(), "{metric}");
            let other = if reference == "none" {
                "cychosz"
            } else {
                "none"
            };
            let c = coverage(
                &[run(vec![r(1.0, other)]), run(vec![r(1.1, other)])],
                &names(2),
            )
            .expect("runs");
            assert!(c.headline_changes.is_empty(), "{metric} over {other}");
        }
        let mut r = rec("skala", 1.0, [0.99, 1.01], Some([0.8, 1.2]));
        r.metric = "cull_ns".into();
        let mut s = r.clone();
        s.ratio = 1.1;
        let c = coverage(&[run(vec![r]), run(vec![s])], &names(2)).expect("runs");
        assert!(c.headline_changes.is_empty());
    }

    #[test]
    fn refuses_one_run_and_runs_without_ratios() {
        let one = [run(vec![rec("skala", 1.0, [0.9, 1.1], None)])];
        let e = coverage(&one, &names(1)).unwrap_err();
        assert!(e.contains("at least 2 runs"), "{e}");
        let empty = [run(Vec::new()), run(Vec::new())];
        let e = coverage(&empty, &names(2)).unwrap_err();
        assert!(
            e.contains("run0.json") && e.contains("no paired ratio records"),
            "{e}"
        );
    }

    #[test]
    fn refuses_runs_from_different_machines() {
        let a = run(vec![rec("skala", 1.0, [0.9, 1.1], None)]);
        let mut b = a.clone();
        b.meta.cpu = "another processor".into();
        let e = coverage(&[a, b], &names(2)).unwrap_err();
        assert!(e.contains("different machines"), "{e}");
    }
}
