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

use super::rows::{
    CullCounts, Report, Row, changed, cull_capture_row, first_duplicate, pair_up, ratio,
};
use crate::bend_check::{BendFile, ClassRecord, CullRecord};

/// Refuses files whose rays differ, and a file that holds a class twice.
pub fn comparable(old: &BendFile, new: &BendFile) -> Result<(), String> {
    for file in [old, new] {
        if let Some(class) = first_duplicate(&file.classes, ClassRecord::label) {
            return Err(format!(
                "class `{class}` appears more than once: compare cannot tell which to pair"
            ));
        }
    }
    if old.meta.workload_sha256 != new.meta.workload_sha256 {
        return Err(format!(
            "the bend-check rays differ (field `meta.workload_sha256`; rays per class {} vs \
             {}, seeds {} vs {}): their counts are of different rays, so nothing is compared",
            old.rays_per_class, new.rays_per_class, old.seed, new.seed
        ));
    }
    Ok(())
}

/// The rows of two bend-check files (counts only: no timing, so no threshold).
#[must_use]
pub fn compare(old: &BendFile, new: &BendFile, across_machines: bool) -> Report {
    let mut report = Report {
        meta: super::machine::differences(&old.meta, &new.meta),
        across_machines,
        ..Report::default()
    };
    let classes = pair_up(
        &old.classes,
        &new.classes,
        ClassRecord::label,
        &mut report,
        "bend",
    );
    for (class, o, n) in &classes {
        let key = |c: &CullRecord| format!("{class} {}", c.label());
        for (key, a, b) in pair_up(&o.culls, &n.culls, key, &mut report, "bend") {
            report.rows.push(cull_row(key, a, b));
        }
        report
            .rows
            .push(cut_away_row(format!("{class} cut-away"), o, n));
        report.rows.push(exact_row(format!("{class} exact"), o, n));
    }
    super::judge_across_machines(&mut report);
    report
}

/// One cull (or cull + wedge) on one class ([`cull_capture_row`]).
fn cull_row(key: String, o: &CullRecord, n: &CullRecord) -> Row {
    let counts = |c: &CullRecord| CullCounts {
        rejected: c.rejected,
        false_rejects: c.false_rejects,
        far_misses: c.far_misses,
        far_misses_rejected: c.far_misses_rejected,
    };
    cull_capture_row(("bend", key), counts(o), counts(n), &[])
}

/// The wedge alone's capture of the cut-away misses: lower is a regression.
fn cut_away_row(key: String, o: &ClassRecord, n: &ClassRecord) -> Row {
    let (a, b) = (&o.cut_away, &n.cut_away);
    let mut flags = changed(&[
        ("misses", a.misses, b.misses),
        ("wedge_rejected", a.wedge_rejected, b.wedge_rejected),
    ]);
    let (old_c, new_c) = (
        ratio(a.wedge_rejected, a.misses),
        ratio(b.wedge_rejected, b.misses),
    );
    let regression = new_c < old_c;
    if regression {
        flags.push("REGRESSION: lower cut-away capture".into());
    }
    Row {
        section: "bend cut-away",
        key,
        metric: "capture",
        old: old_c,
        new: new_c,
        flags,
        regression,
    }
}

/// The exact intersection on one class: more missed, invented, wrong-face or wrong-value
/// answers is a regression; the row's value is the largest t error (relative to S).
fn exact_row(key: String, o: &ClassRecord, n: &ClassRecord) -> Row {
    let (a, b) = (&o.exact, &n.exact);
    let counts = [
        ("missed", a.missed, b.missed),
        ("invented", a.invented, b.invented),
        ("wrong_face", a.wrong_face, b.wrong_face),
        ("wrong_value", a.wrong_value, b.wrong_value),
        ("all_missed", a.all_missed, b.all_missed),
        ("all_invented", a.all_invented, b.all_invented),
        ("all_wrong_face", a.all_wrong_face, b.all_wrong_face),
        ("all_wrong_value", a.all_wrong_value, b.all_wrong_value),
    ];
    let mut flags = changed(&counts);
    let regression = b.bad() > a.bad();
    if regression {
        flags.push(format!(
            "REGRESSION: missed/invented/wrong-face/wrong-value answers {} -> {}",
            a.bad(),
            b.bad()
        ));
    }
    Row {
        section: "bend exact",
        key,
        metric: "max_t_error_rel",
        old: a.max_t_error_rel,
        new: b.max_t_error_rel,
        flags,
        regression,
    }
}
