//! What the comparisons of check files share (`family.rs`, `bend.rs`, `f32_check.rs`):
//! their classes paired by label on the same rays, refused when the rays differ.

use super::rows::{Report, first_duplicate, pair_up};
use crate::results::Meta;

/// A check file as its comparison sees it: exact counts, class by class, on rays drawn
/// from `meta.workload_sha256`.
pub(super) struct CountedFile<'a, C> {
    /// `family-check`, `bend-check` or `f32-check`: the file's kind, in messages.
    pub kind: &'static str,
    /// `member`, `class` or `family`: what a class is called, in messages.
    pub class: &'static str,
    /// Its provenance.
    pub meta: &'a Meta,
    /// Its classes, in table order.
    pub classes: &'a [C],
    /// Rays per class.
    pub rays: u64,
    /// Its seed, as the file states it.
    pub seed: String,
}

/// Refuses files whose rays differ (their counts are of different rays), and a file that
/// holds a class twice (which of the two would be compared?).
pub(super) fn comparable<C>(
    old: &CountedFile<'_, C>,
    new: &CountedFile<'_, C>,
    label: impl Fn(&C) -> String,
) -> Result<(), String> {
    let class = old.class;
    for file in [old, new] {
        if let Some(dup) = first_duplicate(file.classes, &label) {
            return Err(format!(
                "{class} `{dup}` appears more than once: compare cannot tell which to pair"
            ));
        }
    }
    if old.meta.workload_sha256 != new.meta.workload_sha256 {
        return Err(format!(
            "the {} rays differ (field `meta.workload_sha256`; rays per {class} {} vs {}, \
             seeds {} vs {}): their counts are of different rays, so nothing is compared",
            old.kind, old.rays, new.rays, old.seed, new.seed
        ));
    }
    Ok(())
}

/// The report of two files: their classes paired by `label` (keys in `section`), each
/// pair's rows pushed by `rows(label, old, new, report)`, then the verdicts across machines.
pub(super) fn report<'a, C>(
    (old, new): (&CountedFile<'a, C>, &CountedFile<'a, C>),
    (section, label): (&str, impl Fn(&C) -> String),
    across_machines: bool,
    mut rows: impl FnMut(&str, &'a C, &'a C, &mut Report),
) -> Report {
    let mut report = Report {
        meta: super::machine::differences(old.meta, new.meta),
        across_machines,
        ..Report::default()
    };
    for (key, o, n) in pair_up(old.classes, new.classes, label, &mut report, section) {
        rows(&key, o, n, &mut report);
    }
    super::judge_across_machines(&mut report);
    report
}
