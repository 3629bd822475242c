//! `torus-cull compare` on two family-check files (`torus-cull family`), member class by
//! member class, with the rules `compare` applies to `run`'s rejection records:
//!
//! * **family** rows (`<member> <cull>`): the capture of the far misses, recomputed from
//!   `far_misses_rejected / far_misses`. A changed count is flagged `changed`; a new false
//!   reject or a lower capture is a **regression** (the rays are the same: the counts are
//!   exact, there is no noise to allow for).
//! * **family exact** rows (`<member> exact`): the exact intersection's missed and invented
//!   hits (`intersect` and `intersect_all`), which must stay 0: more than before is a
//!   **regression**; the largest t error is shown.
//!
//! Two files of different members, rays or seed (`meta.workload_sha256`) are refused by
//! [`comparable`].

use super::rows::{Report, Row, first_duplicate, pair_up};
use crate::family_check::{CullRecord, FamilyFile, MemberRecord};

/// Refuses files whose rays differ, and a file that holds a member class twice.
pub fn comparable(old: &FamilyFile, new: &FamilyFile) -> Result<(), String> {
    for file in [old, new] {
        if let Some(member) = first_duplicate(&file.members, MemberRecord::label) {
            return Err(format!(
                "member `{member}` appears more than once: compare cannot tell which to pair"
            ));
        }
    }
    if old.meta.workload_sha256 != new.meta.workload_sha256 {
        return Err(format!(
            "the family-check rays differ (field `meta.workload_sha256`; rays per member {} \
             vs {}, seeds {} vs {}): their counts are of different rays, so nothing is \
             compared",
            old.rays_per_member, new.rays_per_member, old.seed, new.seed
        ));
    }
    Ok(())
}

/// The rows of two family-check files (counts only: no timing, so no threshold).
#[must_use]
pub fn compare(old: &FamilyFile, new: &FamilyFile, across_machines: bool) -> Report {
    let mut report = Report {
        meta: super::machine::differences(&old.meta, &new.meta),
        across_machines,
        ..Report::default()
    };
    let members = pair_up(
        &old.members,
        &new.members,
        MemberRecord::label,
        &mut report,
        "family",
    );
    for (member, o, n) in &members {
        let key = |c: &CullRecord| format!("{member} {}", c.cull);
        for (key, a, b) in pair_up(&o.culls, &n.culls, key, &mut report, "family") {
            report.rows.push(cull_row(key, a, b));
        }
        report.rows.push(exact_row(format!("{member} exact"), o, n));
    }
    super::judge_across_machines(&mut report);
    report
}

/// One cull on one member: its capture from its counts, a regression on a new false
/// reject or a lower capture.
fn cull_row(key: String, o: &CullRecord, n: &CullRecord) -> Row {
    let capture = |c: &CullRecord| {
        if c.far_misses > 0 {
            c.far_misses_rejected as f64 / c.far_misses as f64
        } else {
            f64::NAN
        }
    };
    let counts = [
        ("accepts", u64::from(o.accepts), u64::from(n.accepts)),
        ("rejected", o.rejected, n.rejected),
        ("false_rejects", o.false_rejects, n.false_rejects),
        ("far_misses", o.far_misses, n.far_misses),
        (
            "far_misses_rejected",
            o.far_misses_rejected,
            n.far_misses_rejected,
        ),
    ];
    let mut flags = changed(&counts);
    let mut regression = false;
    if n.false_rejects > o.false_rejects {
        regression = true;
        flags.push(format!(
            "REGRESSION: false rejects {} -> {}",
            o.false_rejects, n.false_rejects
        ));
    }
    let (old_c, new_c) = (capture(o), capture(n));
    if new_c < old_c {
        regression = true;
        flags.push("REGRESSION: lower capture".into());
    }
    Row {
        section: "family",
        key,
        metric: "capture",
        old: old_c,
        new: new_c,
        flags,
        regression,
    }
}

/// The exact intersection on one member: more missed or invented hits is a regression;
/// the row's value is the largest t error (relative to the size).
fn exact_row(key: String, o: &MemberRecord, n: &MemberRecord) -> Row {
    let (a, b) = (&o.exact, &n.exact);
    let counts = [
        ("intersect_missed", a.intersect_missed, b.intersect_missed),
        (
            "intersect_invented",
            a.intersect_invented,
            b.intersect_invented,
        ),
        ("all_missed", a.all_missed, b.all_missed),
        ("all_invented", a.all_invented, b.all_invented),
    ];
    let mut flags = changed(&counts);
    let regression = n.exact_wrong() > o.exact_wrong();
    if regression {
        flags.push(format!(
            "REGRESSION: missed/invented hits {} -> {}",
            o.exact_wrong(),
            n.exact_wrong()
        ));
    }
    Row {
        section: "family exact",
        key,
        metric: "max_t_error_rel",
        old: a.max_t_error_rel,
        new: b.max_t_error_rel,
        flags,
        regression,
    }
}

/// `changed: name a->b, …` for the counts that changed, or nothing.
pub(super) fn changed(counts: &[(&str, u64, u64)]) -> Vec<String> {
    let moved: Vec<String> = counts
        .iter()
        .filter(|(_, a, b)| a != b)
        .map(|(name, a, b)| format!("{name} {a}->{b}"))
        .collect();
    if moved.is_empty() {
        Vec::new()
    } else {
        vec![format!("changed: {}", moved.join(", "))]
    }
}
