//! `torus-cull plot`: the SVG figures of a results file or a check file.

use super::CliResult;
use crate::console::outln;
use crate::whole::Whole;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use torus_cull_lab::results::Results;
use torus_cull_lab::results_file::ResultsFile;

/// Runs `plot`.
pub fn plot(file: &Path, out_dir: Option<PathBuf>) -> CliResult {
    let results = ResultsFile::load(file)?;
    let (next_to_it, stem) = plot_place(file, "results");
    let dir = match out_dir {
        Some(dir) => {
            check_out_dir(&dir)?;
            dir
        }
        None => next_to_it,
    };
    let written = match &results {
        ResultsFile::Results(r) => torus_cull_lab::plot::plot_results(r, &dir, &stem)?,
        ResultsFile::Check(c) => torus_cull_lab::plot::check::plot_check(c, &dir, &stem)?,
    };
    if written.is_empty() {
        return Err(format!(
            "{}: nothing to plot (no rejection, timing, bvh, ratio or estimate records)",
            file.display()
        )
        .into());
    }
    for p in &written {
        outln!("wrote {}", p.display())?;
    }
    Ok(ExitCode::SUCCESS)
}

/// `--out-dir` must be an existing directory, as every `--out`'s directory must: a
/// typed path never gets a directory created (a typo would scatter charts), and a file
/// is named as one rather than reported as "File exists".
fn check_out_dir(dir: &Path) -> Result<(), String> {
    match std::fs::metadata(dir) {
        Ok(m) if m.is_dir() => Ok(()),
        Ok(_) => Err(format!(
            "--out-dir {}: is a file, not a directory (allowed: an existing directory)",
            dir.display()
        )),
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => Err(format!(
            "--out-dir {}: no such directory (it is not created: make it first, as for \
             every --out)",
            dir.display()
        )),
        Err(e) => Err(format!("--out-dir {}: {e}", dir.display())),
    }
}

/// The directory and file-name stem of the SVG charts of the results file `path`. A bare
/// file name's parent is the empty path, which is the working directory: it is named `.`
/// here, once, so that no message says `/NAME-*.svg` (the root).
/// `default_stem` names a path with no file name.
pub(crate) fn plot_place(path: &Path, default_stem: &str) -> (PathBuf, String) {
    let dir = path
        .parent()
        .filter(|p| !p.as_os_str().is_empty())
        .map_or_else(|| PathBuf::from("."), Path::to_path_buf);
    let stem = path
        .file_stem()
        .map_or(default_stem.into(), |s| s.to_string_lossy().into_owned());
    (dir, stem)
}

/// Before any work (`run` and `time`, unless `--no-plots`): every chart [`write_plots`]
/// may write next to `path` (`<stem>-*.svg`) that exists already must be a file that can
/// be replaced, not a directory, as docs/results.md promises for every output.
pub(crate) fn check_plot_paths(path: &Path) -> Result<(), String> {
    let (dir, stem) = plot_place(path, "results");
    torus_cull_lab::plot::check_chart_paths(&dir, &stem)
        .map_err(|e| format!("{e} (a plot of --out {}; or --no-plots)", path.display()))
}

/// The SVG charts of the file `path`, next to it and named after it, drawn by `draw(dir,
/// stem)` (`plot_results` for `run` and `time`, `plot_check` for `check`).
pub(crate) fn write_charts(
    path: &Path,
    draw: impl FnOnce(&Path, &str) -> Result<Vec<PathBuf>, Box<dyn std::error::Error>>,
) -> Result<(), Box<dyn std::error::Error>> {
    let (dir, stem) = plot_place(path, "results");
    let written = draw(&dir, &stem)?;
    outln!(
        "wrote {} plots to {}/{stem}-*.svg",
        written.len(),
        dir.display()
    )?;
    Ok(())
}

/// The SVG charts of a results file, next to it (`run` and `time`).
pub(crate) fn write_plots(
    results: &Results,
    path: &Path,
) -> Result<(), Box<dyn std::error::Error>> {
    write_charts(path, |dir, stem| {
        torus_cull_lab::plot::plot_results(results, dir, stem)
    })
}

/// Writes a check command's file to `path`: `file` as compact JSON (one line, as results
/// files are; see `Results::save`) and a newline, a regular
/// file replaced atomically (a temp file, then renamed); then says so.
pub(crate) fn write_check_file(
    path: &Path,
    file: &impl serde::Serialize,
) -> Result<(), Box<dyn std::error::Error>> {
    let mut text = serde_json::to_string(file)?;
    text.push('\n');
    torus_cull_lab::output::write_file(path, text.as_bytes())
        .map_err(|e| format!("--out {}: {e}", path.display()))?;
    outln!("wrote {}", path.display())?;
    Ok(())
}

/// `check`'s `--rays`: 1 ..= `max`, else the
/// message that says so.
pub(crate) fn check_rays(rays: Whole, max: usize) -> Result<usize, String> {
    rays.within("--rays", (1, max), "")
}

/// Where `check` writes its file: `--out`, or
/// `results/<commit><suffix>.json` (its folder made); checked writable, and its charts'
/// paths too unless `no_plots`, before any work, so a finished run is never lost to them.
pub(crate) fn check_file_out(
    out: Option<PathBuf>,
    suffix: &str,
    no_plots: bool,
) -> Result<PathBuf, Box<dyn std::error::Error>> {
    let path = match out {
        Some(path) => path,
        None => {
            let path = torus_cull_lab::results::default_path(Path::new("results"), suffix);
            torus_cull_lab::output::create_default_dir(&path)
                .map_err(|e| format!("--out {}: {e}", path.display()))?;
            path
        }
    };
    torus_cull_lab::output::check_writable(&path)
        .map_err(|e| format!("--out {}: {e}", path.display()))?;
    if !no_plots {
        check_plot_paths(&path)?;
    }
    Ok(path)
}
