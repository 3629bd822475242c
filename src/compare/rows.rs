//! The rows of a comparison ([`Row`], [`Report`]) and the pairing of two files' records by
//! key: what every section of `torus-cull compare` builds on (the criterion sections in
//! `mod.rs`, the ratio section in `ratio.rs`).

use crate::check_counts::CullCounts;
use std::collections::BTreeMap;

/// `[("field", old.field, new.field), …]`: each count named by its own field, so that a
/// flag's name cannot drift from what it counts.
macro_rules! counts {
    ($old:expr, $new:expr; $($field:ident),+ $(,)?) => {
        [$((stringify!($field), $old.$field, $new.$field)),+]
    };
}
pub(super) use counts;

/// One compared record.
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    /// `rejection`, `timing` or `bvh`.
    pub section: &'static str,
    /// `case nu cull` or `scene nu cull`.
    pub key: String,
    /// What is compared.
    pub metric: &'static str,
    /// Old value.
    pub old: f64,
    /// New value.
    pub new: f64,
    /// Flags: `changed`, `REGRESSION: …`, `faster`, `slower (noise)`.
    pub flags: Vec<String>,
    /// Whether this row is a regression.
    pub regression: bool,
}

/// The whole comparison.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Report {
    /// Records present in both files.
    pub rows: Vec<Row>,
    /// Keys only in the old file.
    pub only_old: Vec<String>,
    /// Keys only in the new file.
    pub only_new: Vec<String>,
    /// Notes on the files themselves (e.g. different workloads).
    pub notes: Vec<String>,
    /// How the files' `meta` differ: the machine (timing verdicts withheld unless
    /// `across_machines`) and the setup (notes).
    pub meta: super::machine::MetaDiff,
    /// Whether timing verdicts were given although the machines differ
    /// (`--across-machines`).
    pub across_machines: bool,
    /// Timing regressions not counted because the machines differ.
    pub withheld: usize,
}

/// The sections whose verdicts are timings: a fact about the machine as much as the code.
pub(super) const TIMED_SECTIONS: [&str; 4] = ["timing", "ratio", "check timing", "estimate"];

/// The flag of a timed value that moved by `change` (relative, positive slower) without
/// a disjoint slowdown: noise when it grew past `threshold`, `faster` when it fell past
/// it with disjoint intervals (`better_disjoint`), else none.
pub(super) fn noise_or_faster(
    change: f64,
    threshold: f64,
    better_disjoint: bool,
) -> Option<String> {
    if change > threshold {
        Some("slower, intervals overlap (noise)".into())
    } else if change < -threshold && better_disjoint {
        Some("faster".into())
    } else {
        None
    }
}

impl Report {
    /// Number of regressions.
    pub fn regressions(&self) -> usize {
        self.rows.iter().filter(|r| r.regression).count()
    }

    /// Number of records of the old file missing from the new one.
    pub fn missing(&self) -> usize {
        self.only_old.len()
    }
}

/// The first key that two of `records` share, if any: such a file cannot be paired
/// record by record (which of the two would be compared?).
pub(super) fn first_duplicate<R>(records: &[R], k: impl Fn(&R) -> String) -> Option<String> {
    let mut seen = std::collections::BTreeSet::new();
    records.iter().map(k).find(|key| !seen.insert(key.clone()))
}

/// Matches records of the two files by key; keys on one side only go to the report.
pub(super) fn pair_up<'a, R>(
    old: &'a [R],
    new: &'a [R],
    k: impl Fn(&R) -> String,
    report: &mut Report,
    section: &str,
) -> Vec<(String, &'a R, &'a R)> {
    let old_map: BTreeMap<String, &R> = old.iter().map(|r| (k(r), r)).collect();
    let new_map: BTreeMap<String, &R> = new.iter().map(|r| (k(r), r)).collect();
    for key in old_map.keys().filter(|k| !new_map.contains_key(*k)) {
        report.only_old.push(format!("{section} {key}"));
    }
    for key in new_map.keys().filter(|k| !old_map.contains_key(*k)) {
        report.only_new.push(format!("{section} {key}"));
    }
    // Keep the new file's order, which is table order.
    new.iter()
        .filter_map(|r| {
            let key = k(r);
            old_map.get(&key).map(|o| (key, *o, r))
        })
        .collect()
}

/// `name a->b` for each count that changed.
pub(super) fn changed_counts(counts: &[(&str, u64, u64)]) -> Vec<String> {
    counts
        .iter()
        .filter(|(_, a, b)| a != b)
        .map(|(name, a, b)| format!("{name} {a}->{b}"))
        .collect()
}

/// `changed: name a->b, …` for the counts that changed, or no flag.
pub(super) fn changed(counts: &[(&str, u64, u64)]) -> Vec<String> {
    let moved = changed_counts(counts);
    if moved.is_empty() {
        Vec::new()
    } else {
        vec![format!("changed: {}", moved.join(", "))]
    }
}

/// A row of `metric`, old against new: `counts` flagged where they changed (exact counts
/// on the same rays), and the `regression` message added (the row a regression) when the
/// new file answers worse.
pub(super) fn judged_row(
    (section, key, metric): (&'static str, String, &'static str),
    (old, new): (f64, f64),
    counts: &[(&str, u64, u64)],
    regression: Option<String>,
) -> Row {
    let mut flags = changed(counts);
    flags.extend(regression.iter().cloned());
    Row {
        section,
        key,
        metric,
        old,
        new,
        flags,
        regression: regression.is_some(),
    }
}

/// `num / den`, NaN without a denominator (a capture with nothing to capture).
pub(super) fn ratio(num: u64, den: u64) -> f64 {
    if den > 0 {
        num as f64 / den as f64
    } else {
        f64::NAN
    }
}

/// One cull of a check file: its capture of the far misses from its counts (`extra`
/// counts flagged when they change too); a new false reject or a lower capture is a
/// regression, the rays being the same.
pub(super) fn cull_capture_row(
    (section, key): (&'static str, String),
    o: CullCounts,
    n: CullCounts,
    extra: &[(&str, u64, u64)],
) -> Row {
    let mut counts = extra.to_vec();
    counts.extend(counts!(o, n; rejected, false_rejects, far_misses, far_misses_rejected));
    let mut flags = changed(&counts);
    let mut regression = false;
    if n.false_rejects > o.false_rejects {
        regression = true;
        flags.push(format!(
            "REGRESSION: false rejects {} -> {}",
            o.false_rejects, n.false_rejects
        ));
    }
    let old_c = ratio(o.far_misses_rejected, o.far_misses);
    let new_c = ratio(n.far_misses_rejected, n.far_misses);
    if new_c < old_c {
        regression = true;
        flags.push("REGRESSION: lower capture".into());
    }
    Row {
        section,
        key,
        metric: "capture",
        old: old_c,
        new: new_c,
        flags,
        regression,
    }
}
