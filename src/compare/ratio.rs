//! `torus-cull compare` on ratio records: the timing verdicts when both files have them.
//!
//! A `total_ns` ratio record (or a family member's, a pipe bend's, a BVH's total:
//! `family_total_ns`, `bend_total_ns`, `bvh_*_ns`) is a **regression** when the cull's ratio against the same
//! reference grew by more than the threshold *and* the two intervals do not overlap; it
//! is `faster` in the mirror case. The intervals are the between-run ones
//! (`ratio_ci_between`, over `time --runs`' independent runs) when both records have
//! them, else the within-run bootstrap intervals, which miss what moves a whole run
//! (code and data placement, the machine's state; see [`crate::paired::runs`]). A note
//! says how many runs stood behind each file. `cull_ns` ratios are shown with the same
//! flags but decide nothing: on a loaded virtual machine a slow spell of the host that
//! lasts a whole run moves them by 10–20 % (it slows throughput-bound code more than
//! latency-bound code), while the `total_ns` ratios move by a few percent. A cull that got
//! slower still shows in `total_ns`, wherever it rejects most rays.
//!
//! **A ratio decides only about its cull.** Ratios against `none` (and `none`'s own
//! ratio) measure the reference, the exact intersection, as much as the cull: when the
//! intersection gets faster every cull's ratio against `none` grows, with no cull changed.
//! They are shown, flagged `(against none: not a verdict)`, and decide nothing. A ratio
//! against `cychosz` that grew while `cychosz` itself got faster by more than the
//! threshold (its `reference_ns_per_ray`) and the cull's own time (`ns_per_ray`) did not
//! grow by more than the threshold is a faster reference, not a slower cull: it is shown,
//! flagged, and decides nothing.
//!
//! A ratio is blind to a slow-down that hits the cull and
//! its reference alike (the exact intersection got slower for everyone): the criterion
//! `timing` rows still show that, as information, but with ratios on both sides they no
//! longer decide, because two absolute timings taken minutes apart differ by 10–20 % on a
//! shared machine whatever the code does.

use super::rows::{Report, Row, noise_or_faster, pair_up};
use crate::paired::runs::SLOW_STATE;
use crate::results::{CPU_DEVICE, F64_PRECISION, RatioRecord, Results};

/// Adds one `ratio` row per record present in both files to `report`, and, when both
/// files have ratios, demotes the criterion `timing` rows' regressions to notes.
/// `threshold` is a fraction (0.10 for 10 %).
pub(super) fn ratio_rows(old: &Results, new: &Results, threshold: f64, report: &mut Report) {
    if old.ratio.is_empty() || new.ratio.is_empty() {
        return;
    }
    for row in report.rows.iter_mut().filter(|r| r.section == "timing") {
        if row.regression {
            row.regression = false;
            for flag in &mut row.flags {
                if let Some(rest) = flag.strip_prefix("REGRESSION: ") {
                    *flag = format!("{rest} (criterion, not a verdict: the ratios decide)");
                }
            }
        }
    }
    report.notes.push(runs_note(old, new));
    for (key, o, n) in pair_up(&old.ratio, &new.ratio, ratio_key, report, "ratio") {
        report.rows.push(ratio_row(key, o, n, threshold));
    }
}

/// How many runs stand behind each file's ratios (`1 run` for a file from before
/// `--runs`), and which intervals the verdicts use.
fn runs_note(old: &Results, new: &Results) -> String {
    let runs = |r: &Results| {
        let (lo, hi) = r.ratio.iter().fold((u64::MAX, 0), |(lo, hi), x| {
            (lo.min(x.runs), hi.max(x.runs))
        });
        let plural = if hi == 1 { "" } else { "s" };
        if lo == hi {
            format!("{hi} run{plural}")
        } else {
            format!("{lo}-{hi} runs")
        }
    };
    let between = |r: &Results| r.ratio.iter().all(|x| x.ratio_ci_between.is_some());
    let how = match (between(old), between(new)) {
        (true, true) => "timing verdicts by the between-run intervals".to_string(),
        (o, n) => {
            let lacking = match (o, n) {
                (false, false) => "neither file has",
                (false, true) => "the old file lacks",
                _ => "the new file lacks",
            };
            format!(
                "timing verdicts by the within-run (bootstrap) intervals, as {lacking} \
                 between-run intervals (time --runs 2 or more): they miss what moves a whole \
                 run, so a change of a few percent may be run-to-run noise"
            )
        }
    };
    format!(
        "ratio records: old file {}, new file {} per record; {how}",
        runs(old),
        runs(new)
    )
}

/// The intervals a verdict compares, and what to call them: the between-run intervals
/// when both records have them (see [`crate::paired::runs`]), else the within-run ones.
fn verdict_intervals(o: &RatioRecord, n: &RatioRecord) -> ([f64; 2], [f64; 2], String) {
    match (o.ratio_ci_between, n.ratio_ci_between) {
        (Some(a), Some(b)) => (
            a,
            b,
            format!(
                "between-run intervals disjoint ({} vs {} runs)",
                o.runs, n.runs
            ),
        ),
        _ => (o.ratio_ci, n.ratio_ci, "intervals disjoint".to_string()),
    }
}

/// Whether a metric's ratios decide (a regression fails `compare`): the per-ray totals of
/// one torus (`total_ns`), a family member or a pipe bend, or a BVH traversal.
pub(super) fn is_decisive(metric: &str) -> bool {
    metric == "total_ns"
        || crate::paired::shapes::SHAPE_METRICS.contains(&metric)
        || crate::paired::bvh::BVH_METRICS.contains(&metric)
}

/// `case ν cull/reference metric`, then ` [f32]` (and the device, when not the CPU) for
/// records of another precision or device: f32 and f64 records never pair, while the
/// keys of f64 CPU records stay what they were before those fields existed.
pub(super) fn ratio_key(r: &RatioRecord) -> String {
    let mut key = format!(
        "{} {} {}/{} {}",
        r.case, r.nu, r.cull, r.reference, r.metric
    );
    let mut tags: Vec<&str> = Vec::new();
    if r.precision != F64_PRECISION {
        tags.push(&r.precision);
    }
    if r.device != CPU_DEVICE {
        tags.push(&r.device);
    }
    if !tags.is_empty() {
        key += &format!(" [{}]", tags.join(" "));
    }
    key
}

/// Every ratio record's `ratio`, `ratio_ci` and `ratio_ci_between` a positive finite
/// number: a time ratio is t(cull) / t(reference) of two positive times, and compare's
/// percentages divide by it. The error names the record and the field.
pub fn check_ratios(records: &[RatioRecord]) -> Result<(), String> {
    for r in records {
        let mut fields = vec![("ratio", r.ratio)];
        fields.extend([
            ("ratio_ci[0]", r.ratio_ci[0]),
            ("ratio_ci[1]", r.ratio_ci[1]),
        ]);
        if let Some([lo, hi]) = r.ratio_ci_between {
            fields.extend([("ratio_ci_between[0]", lo), ("ratio_ci_between[1]", hi)]);
        }
        for (field, v) in fields {
            if !(v.is_finite() && v > 0.0) {
                return Err(format!(
                    "ratio record `{}`: field `{field}` = {} is invalid (allowed: a finite \
                     ratio > 0, t(cull) / t(reference))",
                    ratio_key(r),
                    crate::number::Num(v)
                ));
            }
        }
    }
    Ok(())
}

fn ratio_row(key: String, o: &RatioRecord, n: &RatioRecord, threshold: f64) -> Row {
    let change = n.ratio / o.ratio - 1.0;
    let (o_ci, n_ci, disjoint) = verdict_intervals(o, n);
    let worse_disjoint = n_ci[0] > o_ci[1];
    let better_disjoint = n_ci[1] < o_ci[0];
    // Ratios of different batches differ by sampling alone.
    let same_batch = o.rays == n.rays;
    // Against `none` the ratio measures the exact intersection as much as the cull.
    let about_none = n.reference == "none" || n.cull == "none";
    // The ratio grew because the reference got faster, not because the cull got slower.
    let faster_reference = n.reference_ns_per_ray < o.reference_ns_per_ray * (1.0 - threshold)
        && n.ns_per_ray <= o.ns_per_ray * (1.0 + threshold);
    let decides = is_decisive(&n.metric) && same_batch && !about_none && !faster_reference;
    let mut flags = Vec::new();
    let mut regression = false;
    if change > threshold && worse_disjoint && about_none {
        flags.push(format!(
            "slower, {disjoint} (against none: measures the exact intersection too, not a \
                 verdict)"
        ));
    } else if change > threshold && worse_disjoint && faster_reference && same_batch {
        flags.push(format!(
            "slower against {0}, but {0} itself got faster ({1:.2} -> {2:.2} ns/ray) and \
             this cull did not slow ({3:.2} -> {4:.2} ns/ray): not a verdict",
            n.reference, o.reference_ns_per_ray, n.reference_ns_per_ray, o.ns_per_ray, n.ns_per_ray
        ));
    } else if change > threshold && worse_disjoint && decides {
        regression = true;
        // The reference itself slower by more than a run's slow state: the two files may
        // come from different states of the machine (docs/results.md), which move a
        // division-heavy path more than a light one. Said, not excused: a rerun decides.
        let state = if n.reference_ns_per_ray > o.reference_ns_per_ray * (1.0 + SLOW_STATE) {
            format!(
                "; {} itself slowed {:.1} -> {:.1} ns/ray: a slower machine state? rerun both",
                n.reference, o.reference_ns_per_ray, n.reference_ns_per_ray
            )
        } else {
            String::new()
        };
        flags.push(format!(
            "REGRESSION: {:+.1}% against {}, {disjoint}{state}",
            change * 100.0,
            n.reference
        ));
    } else if change > threshold && worse_disjoint && !same_batch {
        flags.push(format!(
            "slower, {disjoint} (batches of {} and {} rays: not a verdict)",
            o.rays, n.rays
        ));
    } else if change > threshold && worse_disjoint {
        flags.push(format!(
            "slower, {disjoint} ({}: shown, not a verdict)",
            n.metric
        ));
    } else {
        flags.extend(noise_or_faster(change, threshold, better_disjoint));
    }
    Row {
        section: "ratio",
        key,
        metric: "ratio (cull / reference)",
        old: o.ratio,
        new: n.ratio,
        flags,
        regression,
    }
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;
    use crate::compare::compare;
    use crate::results::{Meta, Results, SCHEMA_VERSION, TimingRecord};

    /// A headline-style f64 record (`uniform 2 CULL/cychosz`), one run.
    pub(in crate::compare) fn record(cull: &str, ratio: f64, ci: [f64; 2]) -> RatioRecord {
        RatioRecord {
            case: "uniform".into(),
            nu: 2.0,
            cull: cull.into(),
            reference: "cychosz".into(),
            metric: if cull == "aabb_alone" {
                "cull_ns"
            } else {
                "total_ns"
            }
            .into(),
            ratio,
            ratio_ci: ci,
            rounds: 250,
            rounds_measured: 1000,
            rays: 1024,
            ns_per_ray: 100.0 * ratio,
            reference_ns_per_ray: 100.0,
            precision: "f64".into(),
            device: "cpu".into(),
            ..RatioRecord::default()
        }
    }

    fn timing(total_ns: f64) -> TimingRecord {
        TimingRecord {
            case: "uniform".into(),
            nu: 2.0,
            cull: "skala".into(),
            cull_ns: 5.0,
            total_ns,
            total_ns_ci: [total_ns * 0.99, total_ns * 1.01],
            speedup_vs_none: 1.0,
            ideal_total_ns: 50.0,
            solve_hit_ns: None,
            ideal_total_ns_at_hit_cost: None,
            source: "criterion".into(),
            mode: "scalar".into(),
            precision: "f64".into(),
            device: "cpu".into(),
            escalation_rate: None,
        }
    }

    /// A `time` results file of these records.
    pub(in crate::compare) fn results(
        ratio: Vec<RatioRecord>,
        timing: Vec<TimingRecord>,
    ) -> Results {
        Results {
            schema_version: SCHEMA_VERSION,
            meta: Meta {
                commit: None,
                dirty: false,
                created: "2026-11-21T12:00:00Z".into(),
                rustc: "rustc".into(),
                cpu: "cpu".into(),
                workload: "quick".into(),
                workload_sha256: "00".repeat(32),
                seed: Some(7),
                torus_cull_version: None,
                tool: Some("time".into()),
                partial: false,
                preset: None,
                sizes: None,
                isa: None,
                cores: None,
                threads: None,
                os: None,
                device: None,
                summary_of: None,
                counts: None,
            },
            rejection: Vec::new(),
            timing,
            bvh: Vec::new(),
            solver: Vec::new(),
            estimates: Vec::new(),
            ratio,
            shapes: Vec::new(),
            counts: Vec::new(),
        }
    }

    fn flags_of<'a>(report: &'a Report, cull: &str) -> &'a Row {
        report
            .rows
            .iter()
            .find(|r| r.section == "ratio" && r.key.contains(&format!(" {cull}/")))
            .unwrap()
    }

    #[test]
    fn ratio_verdicts_need_the_threshold_and_disjoint_intervals() {
        // Each cull's (ratio, interval) in the old file and in the new one.
        let pairs = [
            ("skala", (0.80, [0.79, 0.81]), (1.00, [0.99, 1.01])), // 25 % worse, apart: regression
            ("aabb", (0.80, [0.79, 0.81]), (0.84, [0.835, 0.845])), // 5 % worse: under 10 %
            ("sphere", (0.80, [0.70, 0.90]), (1.00, [0.85, 1.15])), // overlapping: noise
            ("thick_cylinder", (0.80, [0.79, 0.81]), (0.60, [0.59, 0.61])), // 25 % better: faster
            ("aabb_alone", (0.50, [0.49, 0.51]), (0.65, [0.64, 0.66])), // alone: no verdict
        ];
        let mut old: Vec<RatioRecord> = pairs
            .iter()
            .map(|&(cull, (ratio, ci), _)| record(cull, ratio, ci))
            .collect();
        // Only in the old file.
        old.push(record("none", 1.20, [1.19, 1.21]));
        let new = pairs
            .iter()
            .map(|&(cull, _, (ratio, ci))| record(cull, ratio, ci))
            .collect();
        let (old, new) = (results(old, Vec::new()), results(new, Vec::new()));
        let report = compare(&old, &new, 0.10);
        assert_eq!(report.regressions(), 1);
        let skala = flags_of(&report, "skala");
        assert!(
            skala.regression && skala.flags[0].starts_with("REGRESSION"),
            "{skala:?}"
        );
        assert!(flags_of(&report, "aabb").flags.is_empty());
        let sphere = flags_of(&report, "sphere");
        assert!(
            !sphere.regression && sphere.flags[0].contains("noise"),
            "{sphere:?}"
        );
        assert_eq!(flags_of(&report, "thick_cylinder").flags, ["faster"]);
        let alone = flags_of(&report, "aabb_alone");
        assert!(
            !alone.regression && alone.flags[0].contains("not a verdict"),
            "{alone:?}"
        );
        assert!(report.only_old.iter().any(|k| k.contains("none/cychosz")));
    }

    /// Issue 17: the exact intersection got faster, so every ratio against `none` grew
    /// and `cychosz` (the other reference) got faster: no cull got slower, and nothing is
    /// a regression; a cull that did get slower against `cychosz` still is.
    /// A regression whose reference also slowed beyond a slow state says so (a rerun
    /// decides); one whose reference held steady does not. Both stay regressions.
    #[test]
    fn a_regression_with_a_slower_reference_names_the_machine_state() {
        let old = results(
            vec![
                record("skala", 0.80, [0.79, 0.81]),
                record("quadric", 0.80, [0.79, 0.81]),
            ],
            Vec::new(),
        );
        let mut slow_state = record("skala", 1.00, [0.99, 1.01]);
        slow_state.reference_ns_per_ray = 120.0;
        slow_state.ns_per_ray = 120.0;
        let new = results(
            vec![slow_state, record("quadric", 1.00, [0.99, 1.01])],
            Vec::new(),
        );
        let report = compare(&old, &new, 0.10);
        assert_eq!(report.regressions(), 2);
        let skala = flags_of(&report, "skala");
        assert!(
            skala.flags[0].contains("cychosz itself slowed 100.0 -> 120.0 ns/ray")
                && skala.flags[0].contains("rerun"),
            "{skala:?}"
        );
        let quadric = flags_of(&report, "quadric");
        assert!(!quadric.flags[0].contains("machine state"), "{quadric:?}");
    }

    #[test]
    fn a_faster_reference_is_not_a_slower_cull() {
        // (cull, reference): (ratio, ns, reference's ns) in the old file and in the new one.
        let pairs = [
            // The intersection 40 % faster: skala's ratio against none 0.5 -> 0.8.
            (("skala", "none"), (0.5, 50.0, 100.0), (0.8, 48.0, 60.0)),
            (("cychosz", "none"), (0.8, 80.0, 100.0), (1.0, 60.0, 60.0)),
            (("none", "cychosz"), (1.25, 100.0, 80.0), (1.0, 60.0, 60.0)),
            // cychosz 25 % faster, skala the same: its ratio grew 28 %.
            (("skala", "cychosz"), (0.625, 50.0, 80.0), (0.8, 48.0, 60.0)),
            // aabb itself 50 % slower against an unchanged reference: a regression.
            (("aabb", "cychosz"), (0.9, 72.0, 80.0), (1.35, 108.0, 80.0)),
        ];
        let against =
            |(cull, reference): (&str, &str), (ratio, ns, ref_ns): (f64, f64, f64)| RatioRecord {
                reference: reference.into(),
                metric: "total_ns".into(),
                ns_per_ray: ns,
                reference_ns_per_ray: ref_ns,
                ..record(cull, ratio, [ratio * 0.99, ratio * 1.01])
            };
        let file = |records: Vec<RatioRecord>| results(records, Vec::new());
        let old = file(pairs.iter().map(|&(k, old, _)| against(k, old)).collect());
        let new = file(pairs.iter().map(|&(k, _, new)| against(k, new)).collect());
        let report = compare(&old, &new, 0.10);
        let flagged: Vec<_> = report.rows.iter().filter(|r| r.regression).collect();
        assert_eq!(flagged.len(), 1, "{:#?}", report.rows);
        assert!(flagged[0].key.contains("aabb/cychosz"), "{flagged:?}");
        let row = |k: &str| report.rows.iter().find(|r| r.key.contains(k)).unwrap();
        assert!(
            row("skala/none").flags[0].contains("against none"),
            "{:?}",
            row("skala/none")
        );
        assert!(
            row("skala/cychosz").flags[0].contains("cychosz itself got faster"),
            "{:?}",
            row("skala/cychosz")
        );
    }

    /// An f32 record never pairs with the f64 record of the same cull, reference and
    /// metric: one file's f32 ratios against another's f64 ones would be a 2× "change"
    /// that is no change of code.
    #[test]
    fn f32_and_f64_ratios_never_pair() {
        let f32 = |r: RatioRecord| RatioRecord {
            metric: "batch_total_ns".into(),
            precision: "f32".into(),
            escalation_rate: Some(0.001),
            ..r
        };
        let f64 = |r: RatioRecord| RatioRecord {
            metric: "batch_total_ns".into(),
            ..r
        };
        let old = results(vec![f64(record("skala", 0.80, [0.79, 0.81]))], Vec::new());
        let new = results(
            vec![
                f32(record("skala", 0.40, [0.39, 0.41])),
                f64(record("aabb", 0.80, [0.79, 0.81])),
            ],
            Vec::new(),
        );
        let report = compare(&old, &new, 0.10);
        assert!(
            !report.rows.iter().any(|r| r.section == "ratio"),
            "{:#?}",
            report.rows
        );
        assert_eq!(
            report.only_old,
            ["ratio uniform 2 skala/cychosz batch_total_ns"]
        );
        assert!(
            report
                .only_new
                .iter()
                .any(|k| k.ends_with("skala/cychosz batch_total_ns [f32]")),
            "{:?}",
            report.only_new
        );
        // f32 against f32 pairs, under its own key.
        let report = compare(&new, &new, 0.10);
        assert!(
            report
                .rows
                .iter()
                .any(|r| r.key == "uniform 2 skala/cychosz batch_total_ns [f32]"),
            "{:#?}",
            report.rows
        );
    }

    #[test]
    fn criterion_timings_decide_only_when_a_file_has_no_ratios() {
        let ratios = vec![record("skala", 0.80, [0.79, 0.81])];
        let (slow, fast) = (vec![timing(150.0)], vec![timing(100.0)]);
        // Without ratios the 50 % criterion slow-down is a regression ...
        let report = compare(
            &results(Vec::new(), fast.clone()),
            &results(Vec::new(), slow.clone()),
            0.10,
        );
        assert_eq!(report.regressions(), 1);
        // ... with ratios on both sides (and no change in them) it is shown, not a verdict.
        let report = compare(&results(ratios.clone(), fast), &results(ratios, slow), 0.10);
        assert_eq!(report.regressions(), 0);
        let row = report.rows.iter().find(|r| r.section == "timing").unwrap();
        assert!(row.flags[0].contains("not a verdict"), "{row:?}");
    }
}
