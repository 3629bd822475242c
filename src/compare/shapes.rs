//! The `shapes` records of two `run` files (the family members and bends beside the
//! ring): paired by member and cull, each compared as a ring rejection record is (a new
//! false reject or a lower miss capture is a regression, a changed count is flagged),
//! and a cull that starts or stops declining a shape is flagged.

use super::rejection_row;
use super::rows::{Report, first_duplicate, pair_up};
use crate::results::RejectionRecord;
use crate::results::shapes::ShapeRecord;

/// `elliptic nu=4 b/a=0.5 skala`.
fn key(r: &ShapeRecord) -> String {
    format!("{} {}", r.member(), r.counts.cull)
}

/// The record's counts with the capture a declined cull's counts give (0 of the misses:
/// it kept every ray), so that its null `miss_capture` is not read as a stale one.
fn counts(r: &ShapeRecord) -> RejectionRecord {
    let mut c = r.counts.clone();
    if !r.accepts {
        c.miss_capture = (c.misses > 0).then(|| c.rejected as f64 / c.misses as f64);
    }
    c
}

/// A record twice under one key, named, for [`super::check_unique`].
pub(super) fn duplicate(r: &[ShapeRecord]) -> Option<String> {
    first_duplicate(r, key)
}

/// The rows of the two files' shape records, into `report`.
pub(super) fn rows(old: &[ShapeRecord], new: &[ShapeRecord], report: &mut Report) {
    for (key, o, n) in pair_up(old, new, key, report, "shapes") {
        let mut row = rejection_row(key, &counts(o), &counts(n));
        row.section = "shapes";
        if o.accepts != n.accepts {
            let what = |a: bool| if a { "accepts" } else { "declines" };
            row.flags.push(format!(
                "the cull {} the shape, then {}",
                what(o.accepts),
                what(n.accepts)
            ));
        }
        report.rows.push(row);
    }
}
