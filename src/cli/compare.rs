//! `torus-cull compare OLD NEW`: the diff of two results files (or two check files),
//! exit 1 on a regression.

use super::CliResult;
use crate::console::{out, outln};
use std::path::Path;
use std::process::ExitCode;
use torus_cull_lab::compare::{self, Report, coverage};
use torus_cull_lab::number::Num;
use torus_cull_lab::results_file::ResultsFile;

/// `compare`'s options after the two files.
pub struct CompareOptions {
    /// Slowdown in percent.
    pub threshold: f64,
    /// Show only flagged records.
    pub only_changes: bool,
    /// Records of OLD missing from NEW only warn.
    pub allow_missing: bool,
    /// Give timing verdicts across machines.
    pub across_machines: bool,
    /// `--count-threshold` in percent, if given.
    pub count_threshold: Option<f64>,
}

/// Runs `compare`.
pub fn compare(old: &Path, new: &Path, options: &CompareOptions) -> CliResult {
    let threshold = options.threshold;
    if !(threshold.is_finite() && threshold >= 0.0) {
        return Err(format!(
            "--threshold {} is invalid (allowed: a percentage >= 0)",
            Num(threshold)
        )
        .into());
    }
    let count_threshold = match options.count_threshold {
        Some(t) if !(t.is_finite() && t >= 0.0) => {
            return Err(format!(
                "--count-threshold {} is invalid (allowed: a percentage >= 0)",
                Num(t)
            )
            .into());
        }
        Some(t) => t / 100.0,
        None => compare::counts::DEFAULT_COUNT_THRESHOLD,
    };
    let (a, b) = (ResultsFile::load(old)?, ResultsFile::load(new)?);
    let pair = format!("{} vs {}", old.display(), new.display());
    let report = match (&a, &b) {
        (ResultsFile::Results(a), ResultsFile::Results(b)) => {
            // A summary against a full file: the full file's summary, as summarize writes it.
            let (a, b, summarized) = torus_cull_lab::summary::alike(a, b);
            if summarized {
                outln!("one file is a summary (meta.summary_of): comparing the records it keeps")?;
            }
            let (a, b) = (a.as_ref(), b.as_ref());
            compare::check_unique(a).map_err(|e| format!("{}: {e}", old.display()))?;
            compare::check_unique(b).map_err(|e| format!("{}: {e}", new.display()))?;
            compare::comparable(a, b).map_err(|e| format!("{pair}: {e}"))?;
            if options.count_threshold.is_some() && a.counts.is_empty() && b.counts.is_empty() {
                return Err(format!(
                    "{pair}: --count-threshold judges `counts` records, and neither file has \
                     any (torus-cull count writes them)"
                )
                .into());
            }
            let thresholds = (threshold / 100.0, count_threshold);
            compare::compare_channels(a, b, thresholds, options.across_machines)
        }
        (ResultsFile::Check(_), ResultsFile::Check(_)) if options.count_threshold.is_some() => {
            return Err(format!(
                "{pair}: --count-threshold judges `counts` records, which check files do not \
                 have"
            )
            .into());
        }
        (ResultsFile::Check(a), ResultsFile::Check(b)) => {
            compare::check::comparable(a, b).map_err(|e| format!("{pair}: {e}"))?;
            compare::check::compare(a, b, threshold / 100.0, options.across_machines)
        }
        _ => {
            return Err(format!(
                "{pair}: {} was written by `{}` and {} by `{}`: they hold different \
                 records, so nothing is compared (compare two files of one command)",
                old.display(),
                a.tool(),
                new.display(),
                b.tool()
            )
            .into());
        }
    };
    finish(&report, old, new, options)
}

/// Runs `intervals`: the run-to-run honesty check of the paired intervals.
pub fn intervals(runs: &[std::path::PathBuf]) -> CliResult {
    // The same run twice would agree with itself and pass every goal: refuse it, by path
    // (links followed) and by contents (a copy).
    for (i, a) in runs.iter().enumerate() {
        for b in &runs[..i] {
            let same = torus_cull_lab::output::same_file(a, b)
                || matches!(
                    (std::fs::read(a), std::fs::read(b)),
                    (Ok(x), Ok(y)) if x == y
                );
            if same {
                return Err(format!(
                    "{} and {} are the same run (the same file or identical contents): \
                     intervals needs independent runs (benches/honest_intervals.sh)",
                    b.display(),
                    a.display()
                )
                .into());
            }
        }
    }
    let mut loaded = Vec::new();
    for path in runs {
        match ResultsFile::load(path)? {
            ResultsFile::Results(r) => loaded.push(r),
            other => {
                return Err(format!(
                    "{}: written by `{}`, which has no paired ratios (allowed: files of \
                     `torus-cull time`)",
                    path.display(),
                    other.tool()
                )
                .into());
            }
        }
    }
    // With a summary among them, every file as its summary: the records they all keep.
    if loaded.iter().any(|r| r.meta.summary_of.is_some()) {
        loaded = loaded
            .iter()
            .map(|r| torus_cull_lab::summary::summarize(r, ""))
            .collect();
    }
    let names: Vec<String> = runs.iter().map(|p| p.display().to_string()).collect();
    let report = coverage::coverage(&loaded, &names)?;
    out!("{}", coverage::render(&report))?;
    Ok(if report.goals_met() {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}

/// Prints the report and turns it into the exit code.
fn finish(report: &Report, old: &Path, new: &Path, options: &CompareOptions) -> CliResult {
    let name = |p: &Path| {
        p.file_stem()
            .map_or("?".into(), |s| s.to_string_lossy().into_owned())
    };
    out!(
        "{}",
        compare::render(report, &name(old), &name(new), options.only_changes)
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
    if report.meta.machines_differ() {
        eprintln!(
            "warning: {} and {} were measured on different machines ({}): {}",
            old.display(),
            new.display(),
            report.meta.machine.join("; "),
            if options.across_machines {
                "timing verdicts given because of --across-machines"
            } else {
                "timing verdicts withheld (--across-machines to judge them)"
            }
        );
    }
    let missing = report.missing();
    let lost = missing > 0 && !options.allow_missing;
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
