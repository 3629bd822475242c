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

use super::counted::{self, CountedFile};
use super::rows::{Report, Row, counts, cull_capture_row, judged_row, pair_up};
use crate::family_check::{CullRecord, FamilyFile, MemberRecord};

/// The file as [`counted`] sees it.
fn counted(file: &FamilyFile) -> CountedFile<'_, MemberRecord> {
    CountedFile {
        kind: "family-check",
        class: "member",
        meta: &file.meta,
        classes: &file.members,
        rays: file.rays_per_member,
        seed: file.seed.to_string(),
    }
}

/// Refuses files whose rays differ, and a file that holds a member class twice.
pub fn comparable(old: &FamilyFile, new: &FamilyFile) -> Result<(), String> {
    counted::comparable(&counted(old), &counted(new), MemberRecord::label)
}

/// The rows of two family-check files (counts only: no timing, so no threshold).
#[must_use]
pub fn compare(old: &FamilyFile, new: &FamilyFile, across_machines: bool) -> Report {
    let files = (&counted(old), &counted(new));
    let section = ("family", MemberRecord::label);
    counted::report(files, section, across_machines, |member, o, n, report| {
        let key = |c: &CullRecord| format!("{member} {}", c.cull);
        for (key, a, b) in pair_up(&o.culls, &n.culls, key, report, "family") {
            // Whether the cull accepts the member's shape is flagged when it changes.
            let accepts = ("accepts", u64::from(a.accepts), u64::from(b.accepts));
            let counts = (a.counts, b.counts);
            report.rows.push(cull_capture_row(
                ("family", key),
                counts.0,
                counts.1,
                &[accepts],
            ));
        }
        report.rows.push(exact_row(format!("{member} exact"), o, n));
    })
}

/// The exact intersection on one member: more missed or invented hits is a regression;
/// the row's value is the largest t error (relative to the size).
fn exact_row(key: String, o: &MemberRecord, n: &MemberRecord) -> Row {
    let (a, b) = (&o.exact, &n.exact);
    let counts = counts!(a, b; intersect_missed, intersect_invented, all_missed, all_invented);
    let (was, is) = (o.exact_wrong(), n.exact_wrong());
    let worse = (is > was).then(|| format!("REGRESSION: missed/invented hits {was} -> {is}"));
    let t_error = (a.max_t_error_rel, b.max_t_error_rel);
    judged_row(
        ("family exact", key, "max_t_error_rel"),
        t_error,
        &counts,
        worse,
    )
}
