//! `torus-cull plot`: the SVG figures of a results file.

use super::CliResult;
use crate::outln;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use torus_cull_lab::results::Results;

/// Runs `plot`.
pub fn plot(file: &Path, out_dir: Option<PathBuf>) -> CliResult {
    let results = Results::load(file)?;
    let dir = out_dir.unwrap_or_else(|| {
        file.parent()
            .map_or_else(|| PathBuf::from("."), Path::to_path_buf)
    });
    let stem = file
        .file_stem()
        .map_or("results".into(), |s| s.to_string_lossy());
    let written = torus_cull_lab::plot::plot_results(&results, &dir, &stem)?;
    if written.is_empty() {
        return Err(format!(
            "{}: nothing to plot (no rejection, timing, bvh or ratio records)",
            file.display()
        )
        .into());
    }
    for p in &written {
        outln!("wrote {}", p.display())?;
    }
    Ok(ExitCode::SUCCESS)
}
