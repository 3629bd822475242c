//! `torus-cull check`'s console table, the same for every shape: a line per class and
//! intersector (the oracle's labels, false rejects, the wrong answers by kind, the
//! escalations, the t error, ns per ray), the shape's own captures, then per class and
//! cull the rejection rate and the capture of the far misses.

use super::record::{AnswerRecord, ClassRecord};
use crate::check_counts::{cull_columns, rate_and_capture};
use std::fmt::Write as _;

/// The table's columns; `class` to `falseR` are filled on each class's first line only.
const HEADER: [&str; 13] = [
    "class",
    "rays",
    "hit",
    "miss",
    "amb",
    "falseR",
    "who",
    "wrong",
    "esc%",
    "t err med",
    "p99",
    "max",
    "ns/ray",
];

/// The whole table of `records`.
pub fn table(records: &[ClassRecord]) -> String {
    let mut out = String::new();
    let rows: Vec<[String; 13]> = records.iter().flat_map(class_rows).collect();
    out.push_str(&aligned(&HEADER.map(String::from), &rows));
    if let Some(kinds) = records
        .iter()
        .flat_map(|r| &r.answers)
        .find(|a| !a.wrong.is_empty())
    {
        let names: Vec<&str> = kinds.wrong.keys().map(String::as_str).collect();
        let _ = writeln!(out, "(wrong: {})", names.join("/"));
    }
    for r in records {
        for c in &r.captures {
            let share = c
                .capture
                .map_or("-".into(), |v| format!("{:.1}%", 100.0 * v));
            let _ = writeln!(
                out,
                "{}: {} of {} {} misses rejected by the {}",
                r.label, share, c.misses, c.name, c.by
            );
        }
    }
    if records.iter().any(|r| !r.culls.is_empty()) {
        let etas = "far misses";
        let _ = writeln!(
            out,
            "\nrejection rate / capture of the {etas}, per cull ('-': declined)"
        );
        let width = records.iter().map(|r| r.label.len()).max().unwrap_or(5) + 2;
        let cell = records
            .iter()
            .flat_map(|r| &r.culls)
            .map(|c| c.cull.len())
            .max()
            .unwrap_or(8)
            .max(10)
            + 2;
        let rows = records.iter().map(|r| {
            let cells = r.culls.iter().map(|c| match c.accepts {
                true => rate_and_capture(c.rejection_rate, c.capture, "%"),
                false => "-".into(),
            });
            (r.label.clone(), cells.collect())
        });
        let names: Vec<String> = records[0].culls.iter().map(|c| c.cull.clone()).collect();
        cull_columns(&mut out, ("class", width), cell, &names, rows);
    }
    let sum = |f: &dyn Fn(&ClassRecord) -> u64| records.iter().map(f).sum::<u64>();
    let _ = writeln!(
        out,
        "\ntotal: {} rays, {} false rejects, {} wrong answers of ours",
        sum(&|r| r.rays),
        sum(&ClassRecord::false_rejects),
        sum(&ClassRecord::ours_wrong),
    );
    out
}

/// `r`'s lines: one per intersector (one line when it has none).
fn class_rows(r: &ClassRecord) -> Vec<[String; 13]> {
    let (hits, misses, ambiguous) = r.labels();
    let lead = [
        r.label.clone(),
        r.rays.to_string(),
        hits.to_string(),
        misses.to_string(),
        ambiguous.to_string(),
        r.false_rejects().to_string(),
    ];
    let empty = AnswerRecord::default();
    let answers: Vec<&AnswerRecord> = if r.answers.is_empty() {
        vec![&empty]
    } else {
        r.answers.iter().collect()
    };
    // Timed figures with no intersector of the same name (the f64 intersection, for
    // scale) get a line of their own.
    let scale: Vec<AnswerRecord> = r
        .ns_per_ray
        .iter()
        .flat_map(|ns| ns.keys())
        .filter(|k| *k != "rounds" && !answers.iter().any(|a| &a.who == *k))
        .map(|k| AnswerRecord {
            who: k.clone(),
            ours: true,
            ..AnswerRecord::default()
        })
        .collect();
    let answers: Vec<&AnswerRecord> = answers.into_iter().chain(&scale).collect();
    answers
        .iter()
        .enumerate()
        .map(|(i, a)| {
            let mut row: [String; 13] = Default::default();
            if i == 0 {
                row[..6].clone_from_slice(&lead);
            }
            row[6] = format!("{}{}", a.who, if a.ours { "" } else { " (measured)" });
            let wrong: Vec<String> = a.wrong.values().map(u64::to_string).collect();
            row[7] = wrong.join("/");
            row[8] = match a.counts.get("escalated") {
                Some(&e) => format!("{:.2}", 100.0 * e as f64 / r.rays.max(1) as f64),
                None => "-".into(),
            };
            let sci = |v: f64| format!("{v:.1e}");
            match (a.t_error, a.max.get("max_t_error_rel")) {
                (Some(s), _) => {
                    [row[9], row[10], row[11]] = [sci(s.median), sci(s.p99), sci(s.max)];
                }
                (None, Some(&m)) => {
                    [row[9], row[10], row[11]] = ["-".into(), "-".into(), sci(m)];
                }
                (None, None) => {
                    [row[9], row[10], row[11]] = ["-".into(), "-".into(), "-".into()];
                }
            }
            row[12] = r
                .ns_per_ray
                .as_ref()
                .and_then(|ns| ns.get(&a.who))
                .map_or("-".into(), |v| format!("{v:.1}"));
            row
        })
        .collect()
}

/// `header` and `rows` in columns as wide as their widest cell: the class and who to the
/// left, numbers to the right; no trailing blanks.
fn aligned(header: &[String; 13], rows: &[[String; 13]]) -> String {
    let mut widths = header.each_ref().map(|h| h.chars().count());
    for row in rows {
        for (w, cell) in widths.iter_mut().zip(row) {
            *w = (*w).max(cell.chars().count());
        }
    }
    let mut out = String::new();
    for cells in std::iter::once(header).chain(rows) {
        for (i, (cell, w)) in cells.iter().zip(&widths).enumerate() {
            let sep = if i == 0 { "" } else { "  " };
            if i == 0 || i == 6 {
                let _ = write!(out, "{sep}{cell:<w$}");
            } else {
                let _ = write!(out, "{sep}{cell:>w$}");
            }
        }
        let trimmed = out.trim_end().len();
        out.truncate(trimmed);
        out.push('\n');
    }
    out
}
