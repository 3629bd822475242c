//! `torus-cull bend`'s console table.

use super::{CAPTURE_ETAS, ClassRecord};
use crate::check_counts::{cull_columns, rate_and_capture};
use std::fmt::Write as _;
use torus_cull::CullKind;

/// One line per class (rays, ambiguous labels, false rejects, the exact intersection's
/// missed/invented/wrong-face/wrong-value answers of `intersect` and `intersect_all`, the
/// worst t error, the wedge's capture of the cut-away misses), then per class and cull the
/// rejection rate and capture, alone and behind the wedge.
pub fn table(records: &[ClassRecord]) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "{:<26} {:>8} {:>6} {:>6} {:>15} {:>15} {:>8} {:>14}",
        "class",
        "rays",
        "ambig",
        "falseR",
        "i miss/inv/f/v",
        "all miss/inv/f/v",
        "t err",
        "cut-away wedge"
    );
    for r in records {
        let e = &r.exact;
        let ambiguous: u64 = r.kinds.iter().map(|k| k.ambiguous).sum();
        let cut = &r.cut_away;
        let cut = cut.capture.map_or("-".into(), |c| {
            format!("{:.1}% of {}", 100.0 * c, cut.misses)
        });
        let _ = writeln!(
            out,
            "{:<26} {:>8} {:>6} {:>6} {:>15} {:>15} {:>8.1e} {:>14}",
            r.label(),
            r.rays,
            ambiguous,
            r.false_rejects(),
            format!(
                "{}/{}/{}/{}",
                e.missed, e.invented, e.wrong_face, e.wrong_value
            ),
            format!(
                "{}/{}/{}/{}",
                e.all_missed, e.all_invented, e.all_wrong_face, e.all_wrong_value
            ),
            e.max_t_error_rel,
            cut
        );
    }
    let _ = writeln!(
        out,
        "\nrejection rate / capture of misses > {CAPTURE_ETAS}·η, per cull: alone | behind the wedge"
    );
    let n = CullKind::TIMED.len();
    let cell = |c: &super::CullRecord| rate_and_capture(c.rejection_rate, c.capture, "");
    let rows = records.iter().map(|r| {
        let cells = (0..n).map(|j| format!("{}|{}", cell(&r.culls[j]), cell(&r.culls[n + j])));
        (r.label(), cells.collect())
    });
    cull_columns(&mut out, ("class", 26), 19, rows);
    out
}
