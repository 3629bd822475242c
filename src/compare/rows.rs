//! The rows of a comparison ([`Row`], [`Report`]) and the pairing of two files' records by
//! key: what every section of `torus-cull compare` builds on (the criterion sections in
//! `mod.rs`, the ratio section in `ratio.rs`).

use std::collections::BTreeMap;

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
pub(super) const TIMED_SECTIONS: [&str; 4] = ["timing", "ratio", "f32-check timing", "estimate"];

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
