//! `torus-cull compare OLD NEW`: the diff of two results files, exit 1 on a regression.

use super::CliResult;
use crate::out;
use std::path::Path;
use std::process::ExitCode;
use torus_cull_lab::results::Results;

/// Runs `compare`.
pub fn compare(
    old: &Path,
    new: &Path,
    threshold: f64,
    only_changes: bool,
    allow_missing: bool,
) -> CliResult {
    if !(threshold.is_finite() && threshold >= 0.0) {
        return Err(
            format!("--threshold {threshold} is invalid (allowed: a percentage >= 0)").into(),
        );
    }
    let (a, b) = (Results::load(old)?, Results::load(new)?);
    torus_cull_lab::compare::comparable(&a, &b)
        .map_err(|e| format!("{} vs {}: {e}", old.display(), new.display()))?;
    let report = torus_cull_lab::compare::compare(&a, &b, threshold / 100.0);
    let name = |p: &Path| {
        p.file_stem()
            .map_or("?".into(), |s| s.to_string_lossy().into_owned())
    };
    out!(
        "{}",
        torus_cull_lab::compare::render(&report, &name(old), &name(new), only_changes)
    )?;
    if report.rows.is_empty() {
        // A comparison of nothing must not pass a CI gate.
        return Err(format!(
            "{} and {} share no record: nothing was compared",
            old.display(),
            new.display()
        )
        .into());
    }
    let missing = report.missing();
    let lost = missing > 0 && !allow_missing;
    if missing > 0 {
        eprintln!(
            "{}: {missing} records of {} are missing from {} (listed above as 'only in'){}",
            if lost { "error" } else { "warning" },
            old.display(),
            new.display(),
            if lost {
                "; pass --allow-missing to only warn"
            } else {
                ""
            }
        );
    }
    Ok(if report.regressions() > 0 || lost {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    })
}
