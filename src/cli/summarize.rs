//! `torus-cull summarize FULL.json [--out SUMMARY.json]`: the records of a full results
//! file that the docs quote ([`torus_cull_lab::summary`]), written compact beside it as
//! `FULL-summary.json` unless `--out` says where. A full `cargo bench` commits this file;
//! its full file is restored from the history (results/README.md, "Removed files").

use super::CliResult;
use crate::console::outln;
use std::path::Path;
use std::process::ExitCode;
use torus_cull_lab::results_file::ResultsFile;

/// Runs `summarize`.
pub fn summarize(full: &Path, out: Option<&Path>) -> CliResult {
    let results = match ResultsFile::load(full)? {
        ResultsFile::Results(r) => r,
        other => {
            return Err(format!(
                "{}: written by `{}`, which has no records to summarize (allowed: files of \
                 `cargo bench`, `torus-cull run` or `torus-cull time`)",
                full.display(),
                other.tool()
            )
            .into());
        }
    };
    let path = out.map_or_else(
        || torus_cull_lab::summary::default_path(full),
        Path::to_path_buf,
    );
    if torus_cull_lab::output::same_file(full, &path) {
        return Err(format!(
            "--out {}: is FULL itself (the summary would replace the full file)",
            path.display()
        )
        .into());
    }
    let summary = torus_cull_lab::summary::summarize(&results, &full.display().to_string());
    summary
        .save(&path)
        .map_err(|e| format!("--out {}: {e}", path.display()))?;
    outln!(
        "wrote {} ({} of {} ratio records, no estimates; {} bytes)",
        path.display(),
        summary.ratio.len(),
        results.ratio.len(),
        std::fs::metadata(&path).map_or(0, |m| m.len())
    )?;
    Ok(ExitCode::SUCCESS)
}
