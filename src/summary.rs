//! The summary of a full results file: the records the docs quote, small enough to commit
//! (issue 53). A full `cargo bench` file is 3–4 MB of JSON, 84 % of it `ratio` records no
//! page reads; its summary is the same schema with
//!
//! - `meta` as it was, plus `meta.summary_of` (the full file's name);
//! - the whole `rejection`, `solver`, `bvh` and `timing` sections (the rejection, solver,
//!   BVH and per-cull timing tables the README and docs/ quote);
//! - no `estimates` (criterion's raw per-benchmark medians, from which `timing` is made);
//! - of the `ratio` section, the headline ratios with their intervals ([`is_quoted`]):
//!   `total_ns` and `batch_total_ns` over `cychosz` (the README's table), `cull_ns` and
//!   `batch_cull_ns` over `cychosz` (a cull's own cost, ns per ray), the certified
//!   f32 wavefront over f64 (`batch_f32_total_ns` / `f64`), the BVH traversals over `none`
//!   and over their own scalar traversal, and the family's and the pipe bends' totals.
//!
//! The full file stays restorable from the history (results/README.md, "Removed files").
//! `compare` and `intervals` given a summary and a full file summarize the full one first
//! ([`alike`]), so that a question the summary answers needs no more.

use crate::paired::bvh::{BVH_METRICS, SCALAR_REFERENCE};
use crate::results::Results;
use std::borrow::Cow;

/// Whether a `ratio` record is one the docs quote, kept by [`summarize`].
#[must_use]
pub fn is_quoted(metric: &str, reference: &str) -> bool {
    match metric {
        "total_ns" | "batch_total_ns" | "cull_ns" | "batch_cull_ns" => reference == "cychosz",
        "batch_f32_total_ns" => reference == "f64",
        "family_total_ns" | "bend_total_ns" => true,
        m if BVH_METRICS.contains(&m) => reference == "none" || reference == SCALAR_REFERENCE,
        _ => false,
    }
}

/// The summary of `full`, which was (or will be) saved as `of`. A summary summarizes to
/// itself.
#[must_use]
pub fn summarize(full: &Results, of: &str) -> Results {
    let mut out = full.clone();
    if full.meta.summary_of.is_none() {
        out.meta.summary_of = Some(of.to_string());
    }
    out.estimates.clear();
    out.ratio.retain(|r| is_quoted(&r.metric, &r.reference));
    out
}

/// `old` and `new` as `compare` should read them: when one is a summary and the other
/// not, the other's summary (its records beyond the summary's have no counterpart, and
/// would read as lost); else both as they are. The flag: whether one was summarized.
#[must_use]
pub fn alike<'a>(old: &'a Results, new: &'a Results) -> (Cow<'a, Results>, Cow<'a, Results>, bool) {
    match (old.meta.summary_of.is_some(), new.meta.summary_of.is_some()) {
        (false, true) => (Cow::Owned(summarize(old, "")), Cow::Borrowed(new), true),
        (true, false) => (Cow::Borrowed(old), Cow::Owned(summarize(new, "")), true),
        _ => (Cow::Borrowed(old), Cow::Borrowed(new), false),
    }
}

/// The summary's default path beside the full file: `X.json` → `X-summary.json`.
#[must_use]
pub fn default_path(full: &std::path::Path) -> std::path::PathBuf {
    let stem = full
        .file_stem()
        .map_or_else(|| "results".into(), |s| s.to_string_lossy());
    full.with_file_name(format!("{stem}-summary.json"))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::results::RatioRecord;

    fn rec(metric: &str, reference: &str) -> RatioRecord {
        RatioRecord {
            case: "uniform".into(),
            nu: 4.0,
            cull: "skala".into(),
            reference: reference.into(),
            metric: metric.into(),
            ratio: 1.0,
            ..RatioRecord::default()
        }
    }

    /// The headline ratios stay, the rest and `estimates` go, `meta.summary_of` names
    /// the full file, and a summary of a summary is itself.
    #[test]
    fn a_summary_keeps_the_quoted_records_only() {
        let mut full: Results = serde_json::from_str(
            r#"{"schema_version": 1, "rejection": [], "meta": {"commit": "x", "dirty": false,
                "created": "", "rustc": "", "cpu": "", "workload": "w", "workload_sha256": ""},
                "estimates": [{"benchmark": "cull_ns-hole/none/2", "elements": 1,
                    "ns_per_element": 1.0, "ns_per_element_ci": [1.0, 1.0]}]}"#,
        )
        .unwrap();
        full.ratio = vec![
            rec("total_ns", "cychosz"),
            rec("total_ns", "none"),
            rec("cull_ns", "cychosz"),
            rec("cull_ns", "none"),
            rec("batch_f32_total_ns", "f64"),
            rec("batch_f32_total_ns", "none"),
            rec("batch_f32_uncertified_ns", "f64"),
            rec("bvh_anyhit_ns", "none"),
            rec("bvh_closest_ns", "cychosz"),
            rec("bvh_batched_ns", "scalar"),
            rec("family_total_ns", "circular_exact"),
        ];
        assert_eq!(full.estimates.len(), 1);
        let s = summarize(&full, "results/x.json");
        let kept: Vec<_> = s
            .ratio
            .iter()
            .map(|r| (r.metric.as_str(), r.reference.as_str()))
            .collect();
        assert_eq!(
            kept,
            [
                ("total_ns", "cychosz"),
                ("cull_ns", "cychosz"),
                ("batch_f32_total_ns", "f64"),
                ("bvh_anyhit_ns", "none"),
                ("bvh_batched_ns", "scalar"),
                ("family_total_ns", "circular_exact"),
            ]
        );
        assert!(s.estimates.is_empty());
        assert_eq!(s.meta.summary_of.as_deref(), Some("results/x.json"));
        assert_eq!(summarize(&s, "other.json"), s);
        // compare reads a full file against a summary as two summaries.
        let (a, b, summarized) = alike(&full, &s);
        assert!(summarized);
        assert_eq!(a.ratio, b.ratio);
        let (_, _, summarized) = alike(&full, &full);
        assert!(!summarized);
    }

    #[test]
    fn the_default_path_is_beside_the_full_file() {
        assert_eq!(
            default_path(std::path::Path::new("results/f53cc7f.json")),
            std::path::Path::new("results/f53cc7f-summary.json")
        );
    }
}
