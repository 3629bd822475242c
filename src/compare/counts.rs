//! `torus-cull compare` on the count channel (`counts` records, `torus-cull count`), and
//! which channel moved.
//!
//! **Counts.** Instructions per ray of the same binary on the same rays repeat exactly
//! (docs/counts.md), so a count that changed by more than the count threshold (default
//! 0.1 %) changed: more instructions is a **regression**, fewer is flagged with its
//! direction. Counts are not timings: they hold across machines with the same instruction
//! set, and decide whatever `meta.cpu` says. Counts of another dispatch level
//! (`meta.counts.isa`) are of other code, and records of another ray count
//! (`rays`) of other rays: those are shown and decide nothing.
//!
//! **Channels.** Where both files hold counts and paired ratios (a `time` file with
//! `count --add-to`, or a `cargo bench` file), each record says which channel moved: a
//! count row whose count moved says `count alone` or `both` (a ratio of that cull, case,
//! ν and metric against `cychosz` or `none` moved too: past the threshold with disjoint
//! intervals); a ratio row that moved with its count unchanged says `wall alone` (the
//! machine, or what counts do not see: divisions, square roots, branches, memory).

use super::rows::{Report, Row, first_duplicate, pair_up};
use crate::results::Results;
use crate::results::counts::CountRecord;

/// The default count threshold, a fraction: 0.1 %. Two counts of one build on one ray set
/// are identical; 0.1 % is about one instruction in a ray's thousand.
pub const DEFAULT_COUNT_THRESHOLD: f64 = 0.001;

/// The section name of count rows.
pub const SECTION: &str = "count";

/// The first key two count records share.
pub(super) fn duplicate(records: &[CountRecord]) -> Option<String> {
    first_duplicate(records, CountRecord::key)
}

/// Every count record's `per_ray` and `ratio` a finite number ≥ 0: the error names the
/// record and the field.
pub(super) fn check(records: &[CountRecord]) -> Result<(), String> {
    for r in records {
        for (field, v) in [("per_ray", Some(r.per_ray)), ("ratio", r.ratio)] {
            if let Some(v) = v
                && !(v.is_finite() && v >= 0.0)
            {
                return Err(format!(
                    "count record `{}`: field `{field}` = {} is invalid (allowed: a finite \
                     number >= 0)",
                    r.key(),
                    crate::number::Num(v)
                ));
            }
        }
    }
    Ok(())
}

/// Adds one `count` row per record present in both files, then marks which channel moved
/// where both files also have ratios. `threshold` is a fraction (0.001 for 0.1 %).
pub(super) fn count_rows(old: &Results, new: &Results, threshold: f64, report: &mut Report) {
    if old.counts.is_empty() && new.counts.is_empty() {
        return;
    }
    let isa = |r: &Results| r.meta.counts.as_ref().map(|m| m.isa.clone());
    let valgrind = |r: &Results| r.meta.counts.as_ref().map(|m| m.valgrind.clone());
    let other_isa = isa(old) != isa(new) && isa(old).is_some() && isa(new).is_some();
    if other_isa {
        report.notes.push(format!(
            "the counts ran at different dispatch levels (meta.counts.isa: {} vs {}): other \
             code, so count changes are shown and decide nothing",
            isa(old).unwrap_or_default(),
            isa(new).unwrap_or_default()
        ));
    }
    if valgrind(old) != valgrind(new) && valgrind(old).is_some() && valgrind(new).is_some() {
        report.notes.push(format!(
            "the counts were made by different valgrinds (meta.counts.valgrind: {} vs {}): \
             they count the same instructions, so they are compared",
            valgrind(old).unwrap_or_default(),
            valgrind(new).unwrap_or_default()
        ));
    }
    for (key, o, n) in pair_up(&old.counts, &new.counts, CountRecord::key, report, SECTION) {
        report
            .rows
            .push(count_row(key, (o, n), threshold, other_isa));
    }
    if !old.ratio.is_empty() && !new.ratio.is_empty() {
        mark_channels(report);
    }
}

fn count_row(
    key: String,
    (o, n): (&CountRecord, &CountRecord),
    threshold: f64,
    other_isa: bool,
) -> Row {
    let mut flags = Vec::new();
    let mut regression = false;
    let change = if o.per_ray > 0.0 {
        n.per_ray / o.per_ray - 1.0
    } else if n.per_ray > 0.0 {
        f64::INFINITY
    } else {
        0.0
    };
    let verdict = |why: &str| format!(" ({why}: not a verdict)");
    let caveat = if o.rays != n.rays {
        verdict(&format!("{} vs {} rays", o.rays, n.rays))
    } else if other_isa {
        verdict("another dispatch level")
    } else {
        String::new()
    };
    if change > threshold {
        let text = format!("count {:+.2}% (more instructions){caveat}", change * 100.0);
        if caveat.is_empty() {
            regression = true;
            flags.push(format!("REGRESSION: {text}"));
        } else {
            flags.push(text);
        }
    } else if change < -threshold {
        flags.push(format!(
            "count {:+.2}% (fewer instructions){caveat}",
            change * 100.0
        ));
    }
    Row {
        section: SECTION,
        key,
        metric: "instructions per ray",
        old: o.per_ray,
        new: n.per_ray,
        flags,
        regression,
    }
}

/// The ratio rows' keys a ring, BVH, family or bend count row (`group case ν cull metric`) stands
/// beside: its cull against `cychosz` and against `none` under the wall metric
/// `<metric>_ns` (with ` [f32]` for the f32 wavefront), as `compare`'s ratio section keys
/// them (a BVH's case is its scene there too).
fn wall_keys(count_key: &str) -> Vec<String> {
    let words: Vec<&str> = count_key.split(' ').collect();
    let [group, case, nu, cull, metric] = words.as_slice() else {
        return Vec::new();
    };
    if !["ring", "bvh", "family", "bend"].contains(group) {
        return Vec::new();
    }
    let tag = if metric.contains("f32") { " [f32]" } else { "" };
    ["cychosz", "none"]
        .iter()
        .map(|reference| format!("{case} {nu} {cull}/{reference} {metric}_ns{tag}"))
        .collect()
}

/// Whether a ratio row moved: beyond the threshold with disjoint intervals, either way
/// (a regression, `slower, … disjoint …`, or `faster`).
fn wall_moved(row: &Row) -> bool {
    row.regression
        || row
            .flags
            .iter()
            .any(|f| f == "faster" || (f.contains("disjoint") && !f.contains("overlap")))
}

/// Whether a count row moved past the threshold.
fn count_moved(row: &Row) -> bool {
    row.flags.iter().any(|f| f.contains("count "))
}

/// Appends `channel: …` to every moved count row and to every moved ratio row that has a
/// count beside it, and a note with the tally.
fn mark_channels(report: &mut Report) {
    let moved_walls: std::collections::BTreeSet<String> = report
        .rows
        .iter()
        .filter(|r| r.section == "ratio" && wall_moved(r))
        .map(|r| r.key.clone())
        .collect();
    let mut counted = std::collections::BTreeMap::new();
    let (mut count_alone, mut both, mut wall_alone) = (0, 0, 0);
    for row in report.rows.iter_mut().filter(|r| r.section == SECTION) {
        let walls = wall_keys(&row.key);
        let count = count_moved(row);
        let wall = walls.iter().any(|k| moved_walls.contains(k));
        for k in walls {
            counted.insert(k, count);
        }
        match (count, wall) {
            (true, false) => {
                count_alone += 1;
                row.flags.push("channel: count alone".into());
            }
            (true, true) => {
                both += 1;
                row.flags
                    .push("channel: both (the wall ratio moved too)".into());
            }
            _ => {}
        }
    }
    for row in report.rows.iter_mut().filter(|r| r.section == "ratio") {
        if moved_walls.contains(&row.key) && counted.get(&row.key) == Some(&false) {
            wall_alone += 1;
            row.flags.push(
                "channel: wall alone (same instructions: the machine's state, or divisions, \
                 square roots, branches, memory)"
                    .into(),
            );
        }
    }
    report.notes.push(format!(
        "channels: {count_alone} records moved in the count alone, {both} in both, \
         {wall_alone} ratios in the wall alone (with their count unchanged)"
    ));
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rec(cull: &str, per_ray: f64) -> CountRecord {
        CountRecord {
            group: "ring".into(),
            case: "hole".into(),
            nu: 2.0,
            cull: cull.into(),
            metric: "total".into(),
            rays: 64,
            instructions: (per_ray * 64.0) as u64,
            per_ray,
            reference: None,
            ratio: None,
        }
    }

    /// More instructions beyond the threshold is a regression, fewer a change with its
    /// direction, within it nothing; other rays decide nothing.
    #[test]
    fn counts_judged_by_the_threshold() {
        let t = DEFAULT_COUNT_THRESHOLD;
        let row = |o, n| {
            count_row(
                String::new(),
                (&rec("skala", o), &rec("skala", n)),
                t,
                false,
            )
        };
        let up = row(1000.0, 1002.0);
        assert!(
            up.regression && up.flags[0].contains("+0.20% (more"),
            "{up:?}"
        );
        let down = row(1000.0, 998.0);
        assert!(
            !down.regression && down.flags[0].contains("-0.20% (fewer"),
            "{down:?}"
        );
        assert!(row(1000.0, 1000.5).flags.is_empty());
        let mut other = rec("skala", 1100.0);
        other.rays = 32;
        let r = count_row(String::new(), (&rec("skala", 1000.0), &other), t, false);
        assert!(
            !r.regression && r.flags[0].contains("64 vs 32 rays"),
            "{r:?}"
        );
        let isa = count_row(String::new(), (&rec("a", 1.0), &rec("a", 2.0)), t, true);
        assert!(
            !isa.regression && isa.flags[0].contains("dispatch level"),
            "{isa:?}"
        );
    }

    /// With counts and ratios in both files: a count that moved with its ratio steady is
    /// `count alone`, a ratio that moved with its count steady `wall alone`, and the tally
    /// is a note; the count's regression fails the comparison.
    #[test]
    fn each_moved_record_names_its_channel() {
        use crate::compare::ratio::tests::{record, results};
        let on_uniform = |cull: &str, per_ray: f64| CountRecord {
            case: "uniform".into(),
            ..rec(cull, per_ray)
        };
        let mut old = results(vec![record("skala", 1.0, [0.99, 1.01])], Vec::new());
        old.ratio.push(record("sphere", 1.0, [0.99, 1.01]));
        old.counts = vec![on_uniform("skala", 1000.0), on_uniform("sphere", 500.0)];
        let mut new = old.clone();
        new.counts[0].per_ray = 1010.0;
        new.ratio[1] = record("sphere", 1.3, [1.29, 1.31]);
        let report = crate::compare::compare(&old, &new, 0.1);
        let row = |section: &str, cull: &str| {
            report
                .rows
                .iter()
                .find(|r| r.section == section && r.key.contains(&format!(" {cull}")))
                .unwrap()
                .clone()
        };
        let skala = row(SECTION, "skala");
        assert!(skala.regression, "{skala:?}");
        assert!(
            skala.flags.iter().any(|f| f == "channel: count alone"),
            "{skala:?}"
        );
        let sphere = row("ratio", "sphere/");
        assert!(
            sphere
                .flags
                .iter()
                .any(|f| f.starts_with("channel: wall alone")),
            "{sphere:?}"
        );
        assert!(row(SECTION, "sphere").flags.is_empty());
        let note = report
            .notes
            .iter()
            .find(|n| n.starts_with("channels:"))
            .unwrap();
        assert!(
            note.contains("1 records moved in the count alone, 0 in both, 1 ratios"),
            "{note}"
        );
    }

    /// A ring count stands beside its cull's ratios against both references.
    #[test]
    fn wall_keys_follow_the_ratio_keys() {
        assert_eq!(
            wall_keys("ring hole 2 skala batch_f32_total"),
            [
                "hole 2 skala/cychosz batch_f32_total_ns [f32]",
                "hole 2 skala/none batch_f32_total_ns [f32]"
            ]
        );
        assert!(wall_keys("solver uniform 0 torus_cull solve").is_empty());
        assert_eq!(
            wall_keys("bvh chain 4 skala bvh_anyhit")[1],
            "chain 4 skala/none bvh_anyhit_ns"
        );
    }
}
