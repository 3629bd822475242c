//! `torus-cull bend`'s console table.

use super::{CAPTURE_ETAS, ClassRecord};
use std::fmt::Write as _;
use torus_cull::{CullKind, Named};

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
    let _ = write!(out, "{:<26}", "class");
    for c in CullKind::TIMED {
        let _ = write!(out, " {:>19}", truncate(c.name(), 19));
    }
    let _ = writeln!(out);
    for r in records {
        let _ = write!(out, "{:<26}", r.label());
        let n = CullKind::TIMED.len();
        for j in 0..n {
            let cell = |c: &super::CullRecord| {
                let capture = c
                    .capture
                    .map_or("-".into(), |v| format!("{:.0}", 100.0 * v));
                format!("{:.0}/{capture}", 100.0 * c.rejection_rate)
            };
            let both = format!("{}|{}", cell(&r.culls[j]), cell(&r.culls[n + j]));
            let _ = write!(out, " {both:>19}");
        }
        let _ = writeln!(out);
    }
    out
}

fn truncate(s: &str, n: usize) -> &str {
    s.get(..n).unwrap_or(s)
}
