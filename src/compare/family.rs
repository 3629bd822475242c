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

use super::rows::{CullCounts, Report, Row, changed, cull_capture_row, first_duplicate, pair_up};
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

/// One cull on one member ([`cull_capture_row`]); whether it accepts the member's shape
/// is flagged when it changes.
fn cull_row(key: String, o: &CullRecord, n: &CullRecord) -> Row {
    let counts = |c: &CullRecord| CullCounts {
        rejected: c.rejected,
        false_rejects: c.false_rejects,
        far_misses: c.far_misses,
        far_misses_rejected: c.far_misses_rejected,
    };
    let accepts = ("accepts", u64::from(o.accepts), u64::from(n.accepts));
    cull_capture_row(("family", key), counts(o), counts(n), &[accepts])
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
