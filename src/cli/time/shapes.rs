//! What `time --family` and `time --bend` share: a results file whose `ratio` section holds
//! a shape's paired ratios (the usual `meta` block, written atomically), and the
//! console's `ratio [interval]`.

use std::path::{Path, PathBuf};
use std::process::ExitCode;
use torus_cull_lab::paired::shapes::ShapeRatio;
use torus_cull_lab::results::{RatioRecord, Results, default_path};
use torus_cull_lab::workload::spec::Workload;

/// Runs per shape, in this process (fresh ray buffers each).
const RUNS: usize = 3;

/// A shape set's `ratio` records, or why there are none.
pub(super) type Records = Result<Vec<RatioRecord>, String>;

/// A set of shapes `time` takes: `time --<name>` times `shapes` of them through
/// `records(seed, batch, (runs, seconds per run))`, which prints a line per shape.
pub(super) struct Timed {
    /// `family` or `bend`: the flag, the `meta.tool` (`time-<name>`) and the file's
    /// suffix (`-<name>-time`).
    pub name: &'static str,
    /// How many shapes share the time.
    pub shapes: usize,
    /// Their `ratio` records.
    pub records: fn(u64, usize, (usize, f64)) -> Records,
}

/// Times every shape of `timed` for `seconds` in all, and writes `out` (or the default
/// `results/<commit>-family-time.json` or `-bend-time.json`).
pub(super) fn run(
    timed: &Timed,
    workload: &Workload,
    seconds: f64,
    batch: usize,
    out: Option<&Path>,
) -> Result<ExitCode, Box<dyn std::error::Error>> {
    let per_run = seconds / (timed.shapes * RUNS) as f64;
    let name = timed.name;
    let records = (timed.records)(workload.seed, batch, (RUNS, per_run))
        .map_err(|e| format!("time --{name}: {e}"))?;
    let (tool, suffix) = (format!("time-{name}"), format!("-{name}-time"));
    write(workload, &tool, &suffix, records, out)?;
    Ok(ExitCode::SUCCESS)
}

/// Writes `records` as the `ratio` section of `out`, or of the default
/// `results/<commit><suffix>.json`, with `meta.tool` = `tool`; returns the path.
fn write(
    workload: &Workload,
    tool: &str,
    suffix: &str,
    records: Vec<RatioRecord>,
    out: Option<&Path>,
) -> Result<PathBuf, Box<dyn std::error::Error>> {
    let mut results = Results::new(workload, tool);
    results.meta.threads = Some(1);
    results.ratio = records;
    let path = match out {
        Some(p) => p.to_path_buf(),
        None => {
            let p = default_path(Path::new("results"), suffix);
            torus_cull_lab::output::create_default_dir(&p)
                .map_err(|e| format!("--out {}: {e}", p.display()))?;
            p
        }
    };
    results
        .save(&path)
        .map_err(|e| format!("{}: {e}", path.display()))?;
    println!("wrote {}", path.display());
    Ok(path)
}

/// `ratio [between-run interval]`.
pub(super) fn show(r: &ShapeRatio) -> String {
    match r.between {
        Some([lo, hi]) => format!("{:.3} [{lo:.3}, {hi:.3}]", r.ratio),
        None => format!("{:.3}", r.ratio),
    }
}
