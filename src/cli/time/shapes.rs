//! What `time --family` and `time --bend` share: a results file whose `ratio` section holds
//! a shape's paired ratios (the usual `meta` block, written atomically), and the
//! console's `ratio [interval]`.

use std::path::{Path, PathBuf};
use torus_cull_lab::paired::shapes::ShapeRatio;
use torus_cull_lab::results::{RatioRecord, Results, default_path};
use torus_cull_lab::workload::spec::Workload;

/// Writes `records` as the `ratio` section of `out`, or of the default
/// `results/<commit><suffix>.json`, with `meta.tool` = `tool`; returns the path.
pub(super) fn write(
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
