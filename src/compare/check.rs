//! `torus-cull compare` on two check files (`torus-cull check`, any shape and precision),
//! class by class, paired by label on the same rays: the counts are exact, so there is no
//! noise to allow for.
//!
//! * **check** rows (`<class> <cull>`): the capture of the far misses, recomputed from its
//!   counts; a changed count is flagged `changed`; a new false reject or a lower capture
//!   is a **regression**.
//! * **check capture** rows (`<class> <name>`, a shape's own capture, of misses only
//!   its own cull is held to): lower is a **regression**.
//! * **check answers** rows (`<class> <who>`, one per intersector): more wrong answers of
//!   ours (missed, invented, wrong face or value, spurious, far) than before is a
//!   **regression**; a peer's (not ours) are shown and decide nothing. The value is the
//!   escalation rate where the intersector escalates, else its largest t error; a change
//!   of the oracle's labels is flagged on the class's first answer.
//! * **check timing** rows (`<class> <who> ns`): ns per ray, the minimum over a few rounds
//!   with no interval, so a change is shown as `no verdict (no interval)`.
//!
//! Two files of different shapes, precisions, classes, rays or seed
//! (`meta.workload_sha256`) are refused by [`comparable`].

use super::rows::{
    Report, Row, TIMED_SECTIONS, changed_counts, cull_capture_row, first_duplicate, judged_row,
    pair_up, ratio,
};
use crate::check::record::{AnswerRecord, CaptureRecord, CheckFile, ClassRecord};

/// Refuses files whose rays differ (their counts are of different rays), and a file that
/// holds a class twice (which of the two would be compared?).
pub fn comparable(old: &CheckFile, new: &CheckFile) -> Result<(), String> {
    for file in [old, new] {
        if let Some(dup) = first_duplicate(&file.classes, |c| c.label.clone()) {
            return Err(format!(
                "class `{dup}` appears more than once: compare cannot tell which to pair"
            ));
        }
    }
    if old.meta.workload_sha256 != new.meta.workload_sha256 {
        return Err(format!(
            "the check's rays differ (field `meta.workload_sha256`; --shape {} vs {}, \
             --precision {} vs {}, rays per class {} vs {}, seeds {} vs {}): their counts are \
             of different rays, so nothing is compared",
            old.shape,
            new.shape,
            old.precision,
            new.precision,
            old.rays_per_class,
            new.rays_per_class,
            old.seed,
            new.seed
        ));
    }
    Ok(())
}

/// The rows of two check files; `threshold` (a fraction) only flags the timings.
#[must_use]
pub fn compare(old: &CheckFile, new: &CheckFile, threshold: f64, across_machines: bool) -> Report {
    let mut report = Report {
        meta: super::machine::differences(&old.meta, &new.meta),
        across_machines,
        ..Report::default()
    };
    let label = |c: &ClassRecord| c.label.clone();
    let pairs = pair_up(&old.classes, &new.classes, label, &mut report, "check");
    for (class, o, n) in &pairs {
        let key = |c: &crate::check::record::CullRecord| format!("{class} {}", c.cull);
        for (key, a, b) in pair_up(&o.culls, &n.culls, key, &mut report, "check") {
            let accepts = ("accepts", u64::from(a.accepts), u64::from(b.accepts));
            let row = cull_capture_row(("check", key), a.counts, b.counts, &[accepts]);
            report.rows.push(row);
        }
        let key = |c: &CaptureRecord| format!("{class} {}", c.name);
        for (key, a, b) in pair_up(&o.captures, &n.captures, key, &mut report, "check capture") {
            report.rows.push(capture_row(key, a, b));
        }
        let labels = |r: &ClassRecord| r.labels();
        let ((oh, om, oa), (nh, nm, na)) = (labels(o), labels(n));
        let oracle = changed_counts(&[("hits", oh, nh), ("misses", om, nm), ("ambiguous", oa, na)]);
        let key = |a: &AnswerRecord| format!("{class} {}", a.who);
        let answers = pair_up(&o.answers, &n.answers, key, &mut report, "check answers");
        for (i, (key, a, b)) in answers.into_iter().enumerate() {
            let mut row = answer_row(key, (a, o.rays), (b, n.rays));
            if i == 0 && !oracle.is_empty() {
                row.flags
                    .insert(0, format!("oracle counts changed: {}", oracle.join(", ")));
            }
            report.rows.push(row);
        }
    }
    for (class, o, n) in &pairs {
        let (Some(a), Some(b)) = (&o.ns_per_ray, &n.ns_per_ray) else {
            continue;
        };
        for (who, &was) in a.iter().filter(|(k, _)| *k != "rounds") {
            let Some(&is) = b.get(who) else { continue };
            let change = is / was - 1.0;
            let flags = if change.abs() > threshold {
                vec![format!(
                    "{} {:+.1}%: no verdict (no interval)",
                    if change > 0.0 { "slower" } else { "faster" },
                    change * 100.0
                )]
            } else {
                Vec::new()
            };
            report.rows.push(Row {
                section: TIMED_SECTIONS[2],
                key: format!("{class} {who} ns"),
                metric: "ns_per_ray (min of rounds)",
                old: was,
                new: is,
                flags,
                regression: false,
            });
        }
    }
    super::judge_across_machines(&mut report);
    report
}

/// A shape's own capture on one class: lower is a regression.
fn capture_row(key: String, a: &CaptureRecord, b: &CaptureRecord) -> Row {
    let capture = (ratio(a.rejected, a.misses), ratio(b.rejected, b.misses));
    let counts = [
        ("misses", a.misses, b.misses),
        ("rejected", a.rejected, b.rejected),
    ];
    let lower = (capture.1 < capture.0).then(|| format!("REGRESSION: lower {} capture", a.name));
    judged_row(("check capture", key, "capture"), capture, &counts, lower)
}

/// One intersector on one class: its changed counts, and (for ours) a regression when it
/// got more answers wrong.
fn answer_row(
    key: String,
    (o, o_rays): (&AnswerRecord, u64),
    (n, n_rays): (&AnswerRecord, u64),
) -> Row {
    let mut counts: Vec<(&str, u64, u64)> = Vec::new();
    for (name, &a) in o.wrong.iter().chain(&o.counts) {
        let b = n
            .wrong
            .get(name)
            .or(n.counts.get(name))
            .copied()
            .unwrap_or(0);
        counts.push((name, a, b));
    }
    let (was, is) = (o.wrong_answers(), n.wrong_answers());
    let names: Vec<&str> = o.wrong.keys().map(String::as_str).collect();
    let worse = (o.ours && is > was)
        .then(|| format!("REGRESSION: {} answers {was} -> {is}", names.join("/")));
    let escalates = o.counts.contains_key("escalated");
    let (metric, values) = if escalates {
        let rate = |a: &AnswerRecord, rays: u64| ratio(a.count("escalated"), rays);
        ("escalation_rate", (rate(o, o_rays), rate(n, n_rays)))
    } else {
        let max = |a: &AnswerRecord| a.max.get("max_t_error_rel").copied().unwrap_or(0.0);
        ("max_t_error_rel", (max(o), max(n)))
    };
    judged_row(("check answers", key, metric), values, &counts, worse)
}
