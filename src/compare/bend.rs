//! `torus-cull compare` on two bend-check files (`torus-cull bend`), class by class, with
//! the rules of the family check's files (`family.rs`):
//!
//! * **bend** rows (`<class> <cull>`, `<class> <cull>+wedge`): the capture of the far
//!   misses, recomputed from its counts; a new false reject or a lower capture is a
//!   **regression** (the rays are the same: the counts are exact).
//! * **bend cut-away** rows (`<class> cut-away`): the wedge alone's capture of the cut-away
//!   misses; lower is a **regression**.
//! * **bend exact** rows (`<class> exact`): the exact intersection's missed, invented,
//!   wrong-face and wrong-value answers (`intersect` and `intersect_all`), which must stay
//!   0: more than before is a **regression**; the largest t error is shown.
//!
//! Two files of different classes, rays or seed (`meta.workload_sha256`) are refused by
//! [`comparable`].

use super::counted::{self, CountedFile};
use super::rows::{Report, Row, counts, cull_capture_row, judged_row, ratio};
use crate::bend_check::{BendFile, ClassRecord, CullRecord};

/// The file as [`counted`] sees it.
fn counted(file: &BendFile) -> CountedFile<'_, ClassRecord> {
    CountedFile {
        kind: "bend-check",
        class: "class",
        meta: &file.meta,
        classes: &file.classes,
        rays: file.rays_per_class,
        seed: file.seed.to_string(),
    }
}

/// Refuses files whose rays differ, and a file that holds a class twice.
pub fn comparable(old: &BendFile, new: &BendFile) -> Result<(), String> {
    counted::comparable(&counted(old), &counted(new), ClassRecord::label)
}

/// The rows of two bend-check files (counts only: no timing, so no threshold).
#[must_use]
pub fn compare(old: &BendFile, new: &BendFile, across_machines: bool) -> Report {
    let files = (&counted(old), &counted(new));
    counted::report(
        files,
        ("bend", ClassRecord::label),
        across_machines,
        |class, o, n, report| {
            let key = |c: &CullRecord| format!("{class} {}", c.label());
            for (key, a, b) in super::rows::pair_up(&o.culls, &n.culls, key, report, "bend") {
                let row = cull_capture_row(("bend", key), a.counts, b.counts, &[]);
                report.rows.push(row);
            }
            report
                .rows
                .push(cut_away_row(format!("{class} cut-away"), o, n));
            report.rows.push(exact_row(format!("{class} exact"), o, n));
        },
    )
}

/// The wedge alone's capture of the cut-away misses: lower is a regression.
fn cut_away_row(key: String, o: &ClassRecord, n: &ClassRecord) -> Row {
    let (a, b) = (&o.cut_away, &n.cut_away);
    let capture = (
        ratio(a.wedge_rejected, a.misses),
        ratio(b.wedge_rejected, b.misses),
    );
    let counts = counts!(a, b; misses, wedge_rejected);
    let lower = (capture.1 < capture.0).then(|| "REGRESSION: lower cut-away capture".into());
    judged_row(("bend cut-away", key, "capture"), capture, &counts, lower)
}

/// The exact intersection on one class: more missed, invented, wrong-face or wrong-value
/// answers is a regression; the row's value is the largest t error (relative to S).
fn exact_row(key: String, o: &ClassRecord, n: &ClassRecord) -> Row {
    let (a, b) = (&o.exact, &n.exact);
    let counts = counts!(a, b; missed, invented, wrong_face, wrong_value, all_missed, all_invented, all_wrong_face, all_wrong_value);
    let worse = (b.bad() > a.bad()).then(|| {
        format!(
            "REGRESSION: missed/invented/wrong-face/wrong-value answers {} -> {}",
            a.bad(),
            b.bad()
        )
    });
    let t_error = (a.max_t_error_rel, b.max_t_error_rel);
    judged_row(
        ("bend exact", key, "max_t_error_rel"),
        t_error,
        &counts,
        worse,
    )
}
