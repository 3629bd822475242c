//! What `torus-cull check` counts for every shape: per ray kind, the oracle's labels;
//! per cull, its rejections, its false rejects and its capture of the far misses.
//! `compare` recomputes the capture from these counts.

use crate::oracle::OracleClass;
use serde::{Deserialize, Serialize};
use std::fmt::Write as _;

/// `into.field += from.field` for each named count: the sum of two tallies of the same
/// thing drawn on other rays.
macro_rules! add_counts {
    ($into:expr, $from:expr; $($field:ident),+ $(,)?) => {
        $($into.$field += $from.$field;)+
    };
}
pub(crate) use add_counts;

/// Per ray kind: rays, oracle hits, misses and ambiguous rows.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct KindRecord {
    /// The kind's name.
    pub kind: String,
    /// Rays drawn.
    pub rays: u64,
    /// Oracle hits.
    pub hits: u64,
    /// Oracle misses.
    pub misses: u64,
    /// Ambiguous rows (counted apart: neither for the culls' false rejects nor for the
    /// exact intersection).
    pub ambiguous: u64,
}

impl KindRecord {
    /// One empty record per kind, named `names`.
    pub fn zeroed<'a>(names: impl IntoIterator<Item = &'a str>) -> Vec<KindRecord> {
        let zero = |kind: &str| KindRecord {
            kind: kind.into(),
            ..KindRecord::default()
        };
        names.into_iter().map(zero).collect()
    }

    /// Counts one ray the oracle labels `class`.
    pub fn count(&mut self, class: OracleClass) {
        self.rays += 1;
        match class {
            OracleClass::Hit => self.hits += 1,
            OracleClass::Miss => self.misses += 1,
            OracleClass::Ambiguous => self.ambiguous += 1,
        }
    }

    /// Adds `other`'s counts (the same kind, drawn elsewhere).
    pub fn add(&mut self, other: &KindRecord) {
        add_counts!(self, other; rays, hits, misses, ambiguous);
    }
}

/// A cull's counts on a check's rays.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct CullCounts {
    /// Rays rejected.
    pub rejected: u64,
    /// Oracle hits rejected: must be 0.
    pub false_rejects: u64,
    /// The oracle's misses with margin > 1.25·η, literal rays only (a spawned ray's line
    /// passes through its own surface point, which no line cull can reject).
    pub far_misses: u64,
    /// Of those, rejected.
    pub far_misses_rejected: u64,
}

impl CullCounts {
    /// Counts one ray the cull `kept` or rejected: a false reject if the oracle says it
    /// `hit`s, and one of the far misses if it is one (`far_miss`).
    pub fn count(&mut self, kept: bool, hit: bool, far_miss: bool) {
        let rejected = u64::from(!kept);
        self.rejected += rejected;
        self.false_rejects += u64::from(hit && !kept);
        if far_miss {
            self.far_misses += 1;
            self.far_misses_rejected += rejected;
        }
    }

    /// Adds `other`'s counts (the same cull on other rays).
    pub fn add(&mut self, other: &CullCounts) {
        add_counts!(self, other; rejected, false_rejects, far_misses, far_misses_rejected);
    }

    /// rejected / `rays`.
    #[must_use]
    pub fn rejection_rate(&self, rays: usize) -> f64 {
        self.rejected as f64 / rays as f64
    }

    /// far_misses_rejected / far_misses; `None` without far misses.
    #[must_use]
    pub fn capture(&self) -> Option<f64> {
        (self.far_misses > 0).then(|| self.far_misses_rejected as f64 / self.far_misses as f64)
    }
}

/// A cull's console cell: its rejection rate and its capture in percent, each followed by
/// `unit` (`-` for a capture without far misses).
#[must_use]
pub fn rate_and_capture(rejection_rate: f64, capture: Option<f64>, unit: &str) -> String {
    let capture = capture.map_or("-".into(), |v| format!("{:.0}", 100.0 * v));
    format!("{:.0}{unit}/{capture}{unit}", 100.0 * rejection_rate)
}

/// The per-cull part of a check's console table: a header (`first`, then each of
/// `names` cut to `cell` characters) and a row per class (its label and its cells),
/// the first column `width` wide, each cell right-aligned in `cell`.
pub fn cull_columns(
    out: &mut String,
    (first, width): (&str, usize),
    cell: usize,
    names: &[String],
    rows: impl IntoIterator<Item = (String, Vec<String>)>,
) {
    let _ = write!(out, "{first:<width$}");
    for name in names {
        let _ = write!(out, " {:>cell$}", name.get(..cell).unwrap_or(name));
    }
    let _ = writeln!(out);
    for (label, cells) in rows {
        let _ = write!(out, "{label:<width$}");
        for c in cells {
            let _ = write!(out, " {c:>cell$}");
        }
        let _ = writeln!(out);
    }
}
