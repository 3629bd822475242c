//! `torus-cull compare OLD NEW`: a critcmp-style diff of two results files.
//!
//! * **rejection**: the same workload and seed must give identical counts, so any changed
//!   count is flagged `changed`; a new false reject or a lower miss capture is a
//!   **regression**. The `shapes` records (`run`'s family members and bends, `shapes.rs`)
//!   likewise, per member and cull.
//! * **timing**: `total_ns` slower by more than the threshold *and* with disjoint
//!   confidence intervals is a regression; anything else is noise.
//! * **ratio**: when both files have paired ratio records, they give the timing verdicts
//!   instead (see `ratio.rs`).
//! * **bvh**: a changed hit count or `matches_brute_force: false` is a regression. Mrays/s
//!   is a single criterion figure with no interval, so a change beyond the threshold is
//!   shown as `no verdict (no interval)` and decides nothing.
//!
//! * **count** (`counts.rs`): instructions per ray under callgrind; more by more than the
//!   count threshold (0.1 %) is a regression, and where a file holds ratios too, each
//!   moved record says which channel moved (the count alone, the wall alone, both).
//!
//! * **check** (two `torus-cull check` files, any shape and precision, `check.rs`): per
//!   class and cull a new false reject or a lower capture is a regression, as are a lower
//!   capture of a shape's own and more wrong answers of our intersectors.
//!
//! Records on one side only are listed. The exit code is 1 if any regression is flagged,
//! and 1 too when records of the old file are missing from the new one (a run that lost
//! records must not pass a gate), unless `--allow-missing` makes that a warning.
//!
//! Only like is compared with like. Files of different workloads (or, see [`comparable`],
//! made at different sizes) are refused, because their counts differ for reasons that are
//! not regressions; the CLI then exits 2, as it does when the two files share no record,
//! so that a vacuous comparison never passes a CI gate.

pub mod check;
pub mod counts;
pub mod coverage;
pub mod machine;
mod ratio;
mod rows;
mod shapes;

pub use rows::{Report, Row};

use crate::results::{BvhRecord, EstimateRecord, RejectionRecord, Results, TimingRecord};
use rows::{TIMED_SECTIONS, counts, first_duplicate, noise_or_faster, pair_up};
use std::fmt::Write;

fn key(kind: &str, nu: f64, cull: &str) -> String {
    format!("{kind} {nu} {cull}")
}

fn rejection_key(r: &RejectionRecord) -> String {
    key(&r.case, r.nu, &r.cull)
}

fn timing_key(r: &TimingRecord) -> String {
    key(&r.case, r.nu, &r.label())
}

fn bvh_key(r: &BvhRecord) -> String {
    key(&format!("{} {}", r.scene, r.ray_set), r.nu, &r.cull)
}

/// Refuses a file with two records under one key in a section: compare pairs records by
/// key, and with two candidates it would silently pick one. The error names the section
/// and the record. Also refuses a ratio that is not a positive finite number
/// (`ratio::check_ratios`): a negative ratio would read as a change of −100 % or more.
pub fn check_unique(r: &Results) -> Result<(), String> {
    ratio::check_ratios(&r.ratio)?;
    let twice = |section: &str, key: Option<String>| match key {
        Some(key) => Err(format!(
            "record `{section} {key}` appears more than once (each case × ν × cull once per \
             section): compare cannot tell which to pair"
        )),
        None => Ok(()),
    };
    twice("rejection", first_duplicate(&r.rejection, rejection_key))?;
    twice("timing", first_duplicate(&r.timing, timing_key))?;
    twice("bvh", first_duplicate(&r.bvh, bvh_key))?;
    twice("ratio", first_duplicate(&r.ratio, ratio::ratio_key))?;
    twice("shapes", shapes::duplicate(&r.shapes))?;
    counts::check(&r.counts)?;
    twice("counts", counts::duplicate(&r.counts))?;
    twice(
        "estimate",
        first_duplicate(&r.estimates, |e| e.benchmark.clone()),
    )
}

/// Compare `old` with `new`; `threshold` is a fraction (0.10 for 10 %). Timing verdicts
/// across machines are withheld (see [`machine`]).
pub fn compare(old: &Results, new: &Results, threshold: f64) -> Report {
    compare_across(old, new, threshold, false)
}

/// [`compare`], giving timing verdicts across machines too when `across_machines`.
pub fn compare_across(
    old: &Results,
    new: &Results,
    threshold: f64,
    across_machines: bool,
) -> Report {
    let default = counts::DEFAULT_COUNT_THRESHOLD;
    compare_channels(old, new, (threshold, default), across_machines)
}

/// [`compare_across`] with the count channel's threshold too: `(wall, count)`, fractions.
pub fn compare_channels(
    old: &Results,
    new: &Results,
    (threshold, count_threshold): (f64, f64),
    across_machines: bool,
) -> Report {
    let mut report = Report {
        meta: machine::differences(&old.meta, &new.meta),
        across_machines,
        ..Report::default()
    };
    if old.meta.workload_sha256 != new.meta.workload_sha256 {
        report.notes.push(format!(
            "the workloads differ ({} {} vs {} {}): rejection counts are not comparable",
            old.meta.workload,
            &old.meta.workload_sha256[..old.meta.workload_sha256.len().min(12)],
            new.meta.workload,
            &new.meta.workload_sha256[..new.meta.workload_sha256.len().min(12)]
        ));
    }
    for (key, o, n) in pair_up(
        &old.rejection,
        &new.rejection,
        rejection_key,
        &mut report,
        "rejection",
    ) {
        report.rows.push(rejection_row(key, o, n));
    }
    shapes::rows(&old.shapes, &new.shapes, &mut report);
    for (key, o, n) in pair_up(&old.timing, &new.timing, timing_key, &mut report, "timing") {
        report.rows.push(timing_row(key, o, n, threshold));
    }
    for (key, o, n) in pair_up(&old.bvh, &new.bvh, bvh_key, &mut report, "bvh") {
        report.rows.push(bvh_row(key, o, n, threshold));
    }
    // Estimates repeat the timing records in a complete bench file; a file with only
    // estimates (`time gpu`, a filtered bench) is compared by them.
    let timed = |r: &Results| !r.timing.is_empty() || !r.ratio.is_empty();
    if !timed(old) && !timed(new) {
        for (key, o, n) in pair_up(
            &old.estimates,
            &new.estimates,
            |e: &EstimateRecord| e.benchmark.clone(),
            &mut report,
            "estimate",
        ) {
            report.rows.push(estimate_row(key, o, n, threshold));
        }
    }
    ratio::ratio_rows(old, new, threshold, &mut report);
    counts::count_rows(old, new, count_threshold, &mut report);
    judge_across_machines(&mut report);
    report
}

/// When the machines differ: without `--across-machines` a timing regression is not
/// counted and every timing flag says it is no verdict; with it, the verdicts stand and
/// say they were taken across machines. Counts are left alone.
pub(crate) fn judge_across_machines(report: &mut Report) {
    if !report.meta.machines_differ() {
        return;
    }
    let across = report.across_machines;
    let mut withheld = 0;
    for row in report
        .rows
        .iter_mut()
        .filter(|r| TIMED_SECTIONS.contains(&r.section))
    {
        if across {
            for flag in &mut row.flags {
                flag.push_str(" (across machines)");
            }
            continue;
        }
        if row.regression {
            row.regression = false;
            withheld += 1;
        }
        for flag in &mut row.flags {
            *flag = match flag.strip_prefix("REGRESSION: ") {
                Some(rest) => format!("not comparable (different machines): {rest}"),
                None => format!("{flag} (different machines: not a verdict)"),
            };
        }
    }
    report.withheld = withheld;
}

/// The miss capture a record's counts give, rejected / misses (what `run` stores), and
/// whether the stored value disagrees with it.
fn capture(r: &RejectionRecord) -> (Option<f64>, bool) {
    let computed = (r.misses > 0).then(|| r.rejected as f64 / r.misses as f64);
    let disagrees = match (computed, r.miss_capture) {
        (Some(c), Some(s)) => (c - s).abs() > 1e-9 * c.abs().max(1.0),
        (a, b) => a.is_some() != b.is_some(),
    };
    (computed, disagrees)
}

fn rejection_row(key: String, o: &RejectionRecord, n: &RejectionRecord) -> Row {
    let mut flags = Vec::new();
    let mut regression = false;
    let counts = counts!(o, n; rays, hits, misses, ambiguous, rejected, false_rejects);
    flags.extend(rows::changed(&counts));
    if n.false_rejects > o.false_rejects {
        regression = true;
        flags.push(format!(
            "REGRESSION: false rejects {} -> {}",
            o.false_rejects, n.false_rejects
        ));
    }
    // The counts decide, not a stored ratio that may be stale or edited.
    let ((old_c, old_stale), (new_c, new_stale)) = (capture(o), capture(n));
    for (side, stale, r, c) in [("old", old_stale, o, old_c), ("new", new_stale, n, new_c)] {
        if stale {
            let shown = |v: Option<f64>| v.map_or("null".into(), |v| format!("{v:.6}"));
            flags.push(format!(
                "{side}: stored miss_capture {} disagrees with its counts ({}/{} = {}); the \
                 counts are compared",
                shown(r.miss_capture),
                r.rejected,
                r.misses,
                shown(c)
            ));
        }
    }
    let (old_c, new_c) = (old_c.unwrap_or(f64::NAN), new_c.unwrap_or(f64::NAN));
    if new_c < old_c {
        regression = true;
        flags.push("REGRESSION: lower miss capture".into());
    }
    Row {
        section: "rejection",
        key,
        metric: "miss_capture",
        old: old_c,
        new: new_c,
        flags,
        regression,
    }
}

fn timing_row(key: String, o: &TimingRecord, n: &TimingRecord, threshold: f64) -> Row {
    let old = (o.total_ns, o.total_ns_ci);
    let new = (n.total_ns, n.total_ns_ci);
    time_row(("timing", "total_ns"), key, old, new, threshold)
}

/// An estimate (ns per element with its interval): slower by more than the threshold with
/// disjoint intervals is a regression, as for a criterion timing.
fn estimate_row(key: String, o: &EstimateRecord, n: &EstimateRecord, threshold: f64) -> Row {
    let old = (o.ns_per_element, o.ns_per_element_ci);
    let new = (n.ns_per_element, n.ns_per_element_ci);
    time_row(("estimate", "ns_per_element"), key, old, new, threshold)
}

/// A time with its interval, old against new: slower by more than the threshold with
/// disjoint intervals is a regression.
fn time_row(
    (section, metric): (&'static str, &'static str),
    key: String,
    (old, old_ci): (f64, [f64; 2]),
    (new, new_ci): (f64, [f64; 2]),
    threshold: f64,
) -> Row {
    let change = new / old - 1.0;
    let disjoint = new_ci[0] > old_ci[1] || new_ci[1] < old_ci[0];
    let slower = (change > threshold && disjoint).then(|| {
        format!(
            "REGRESSION: {:+.1}% slower, intervals disjoint",
            change * 100.0
        )
    });
    let mut row = rows::judged_row((section, key, metric), (old, new), &[], slower);
    if !row.regression {
        row.flags
            .extend(noise_or_faster(change, threshold, disjoint));
    }
    row
}

fn bvh_row(key: String, o: &BvhRecord, n: &BvhRecord, threshold: f64) -> Row {
    let mut flags = Vec::new();
    let mut regression = false;
    if o.hits != n.hits || o.rays != n.rays {
        regression = true;
        flags.push(format!(
            "REGRESSION: hits {}/{} -> {}/{}",
            o.hits, o.rays, n.hits, n.rays
        ));
    }
    if !n.matches_brute_force {
        regression = true;
        flags.push("REGRESSION: does not match brute force".into());
    }
    // One criterion median, no interval: run-to-run noise alone moves it 10-20 %.
    let change = n.mrays_per_s / o.mrays_per_s - 1.0;
    if change < -threshold {
        flags.push(format!(
            "slower {:+.1}% Mrays/s: no verdict (no interval)",
            change * 100.0
        ));
    } else if change > threshold {
        flags.push(format!(
            "faster {:+.1}% Mrays/s: no verdict (no interval)",
            change * 100.0
        ));
    }
    if (o.quartic_solves_per_ray - n.quartic_solves_per_ray).abs() > 0.0 {
        flags.push(format!(
            "quartic solves/ray {:.4} -> {:.4}",
            o.quartic_solves_per_ray, n.quartic_solves_per_ray
        ));
    }
    Row {
        section: "bvh",
        key,
        metric: "mrays_per_s",
        old: o.mrays_per_s,
        new: n.mrays_per_s,
        flags,
        regression,
    }
}

/// The report as a table, critcmp-style: one line per record, the key column as wide as
/// the longest key. Different machines come first (a warning line) and last (in the
/// summary); the first line is never blank, so `compare … | head -1` shows something.
pub fn render(report: &Report, old_name: &str, new_name: &str, only_changes: bool) -> String {
    let mut out = String::new();
    if report.meta.machines_differ() {
        let _ = writeln!(
            out,
            "WARNING: {old_name} and {new_name} were measured on different machines ({}): {}",
            report.meta.machine.join("; "),
            if report.across_machines {
                "timing verdicts are given (--across-machines), but they measure the \
                 machines as much as the code"
            } else {
                "timings are not comparable and give no verdict (--across-machines to judge \
                 them); counts and capture are compared as usual"
            }
        );
    }
    if !report.meta.setup.is_empty() {
        let _ = writeln!(
            out,
            "note: the setups differ ({})",
            report.meta.setup.join("; ")
        );
    }
    for note in &report.notes {
        let _ = writeln!(out, "note: {note}");
    }
    let shown: Vec<&Row> = report
        .rows
        .iter()
        .filter(|r| !only_changes || !r.flags.is_empty())
        .collect();
    let width = shown
        .iter()
        .map(|r| r.key.chars().count().max(r.metric.chars().count()))
        .max()
        .unwrap_or(0)
        .max(34);
    let w_section = shown
        .iter()
        .map(|r| r.section.chars().count())
        .max()
        .unwrap_or(0)
        .max(9);
    let names = [old_name, new_name].map(|n| n.chars().count().max(12));
    let [w_old, w_new] = names;
    let mut section = "";
    for row in shown {
        if row.section != section {
            if !out.is_empty() {
                out.push('\n');
            }
            section = row.section;
            let _ = writeln!(
                out,
                "{:<w_section$} {:<width$} {:>w_old$} {:>w_new$} {:>9}  flags",
                section, row.metric, old_name, new_name, "change"
            );
        }
        let change = if row.old.is_finite() && row.new.is_finite() && row.old != 0.0 {
            let percent = (row.new / row.old - 1.0) * 100.0;
            if percent.abs() < 1e6 {
                format!("{percent:+.2}%")
            } else {
                format!("{percent:+.2e}%")
            }
        } else {
            "-".into()
        };
        let line = format!(
            "{:<w_section$} {:<width$} {:>w_old$} {:>w_new$} {:>9}  {}",
            "",
            row.key,
            fmt_value(row.old),
            fmt_value(row.new),
            change,
            row.flags.join("; ")
        );
        let _ = writeln!(out, "{}", line.trim_end());
    }
    for k in &report.only_old {
        let _ = writeln!(out, "only in {old_name} (missing from {new_name}): {k}");
    }
    for k in &report.only_new {
        let _ = writeln!(out, "only in {new_name}: {k}");
    }
    if !out.is_empty() {
        out.push('\n');
    }
    let _ = write!(
        out,
        "{} records compared, {} regressions, {} only in old, {} only in new",
        report.rows.len(),
        report.regressions(),
        report.only_old.len(),
        report.only_new.len()
    );
    if report.meta.machines_differ() {
        if report.across_machines {
            let _ = write!(out, "; different machines, timings judged anyway");
        } else {
            let _ = write!(
                out,
                "; different machines: {} timing regressions not counted",
                report.withheld
            );
        }
    }
    out.push('\n');
    out
}

fn fmt_value(v: f64) -> String {
    if v.is_nan() {
        "n/a".into()
    } else if v.abs() >= 1e7 {
        // Significant digits, not 309 of them: the table stays a table.
        format!("{v:.4e}")
    } else if v.abs() >= 100.0 {
        format!("{v:.1}")
    } else {
        format!("{v:.4}")
    }
}

/// Whether `old` and `new` measure the same thing, so that a changed figure means a changed
/// build: the same workload file (by SHA-256) and, where both files record them and both
/// hold the records concerned, the same sizes (`smoke`'s capped rejection sweep, timed
/// batch and shrunk BVH scenes differ from the default's for reasons that are not
/// regressions). The error says which field differs.
pub fn comparable(old: &Results, new: &Results) -> Result<(), String> {
    let short = |s: &str| s[..s.len().min(12)].to_string();
    if old.meta.workload_sha256 != new.meta.workload_sha256 {
        return Err(format!(
            "the workloads differ (field `meta.workload_sha256`: {} {} vs {} {}): their \
             rejection counts and timings are of different rays, so nothing is compared",
            old.meta.workload,
            short(&old.meta.workload_sha256),
            new.meta.workload,
            short(&new.meta.workload_sha256)
        ));
    }
    let (Some(a), Some(b)) = (&old.meta.sizes, &new.meta.sizes) else {
        return Ok(());
    };
    let both = |o: bool, n: bool| o && n;
    let checks = [
        (
            "rejection_rays",
            both(!old.rejection.is_empty(), !new.rejection.is_empty())
                && a.rejection_rays != b.rejection_rays,
            format!("{:?} vs {:?}", a.rejection_rays, b.rejection_rays),
        ),
        (
            "timing_rays",
            both(!old.timing.is_empty(), !new.timing.is_empty()) && a.timing_rays != b.timing_rays,
            format!("{:?} vs {:?}", a.timing_rays, b.timing_rays),
        ),
        (
            "bvh",
            both(!old.bvh.is_empty(), !new.bvh.is_empty()) && a.bvh != b.bvh,
            format!("{:?} vs {:?}", a.bvh, b.bvh),
        ),
    ];
    for (field, differs, values) in checks {
        if differs {
            return Err(format!(
                "the sizes differ (field `meta.sizes.{field}`: {values}; presets {:?} vs \
                 {:?}): make both files with the same preset",
                old.meta.preset, new.meta.preset
            ));
        }
    }
    Ok(())
}
