//! What `time --family` and `time --bend` share: the results file of a shape's paired
//! ratios (the usual `meta` block and one section of records, written atomically) and
//! the console's `ratio [interval]`.

use std::path::{Path, PathBuf};
use torus_cull_lab::paired::shapes::ShapeRatio;
use torus_cull_lab::results::{Meta, Results, default_path, write_atomic};
use torus_cull_lab::workload::spec::Workload;

/// The file: `schema_version`, `meta`, and the section `section` holding `records`.
#[derive(serde::Serialize)]
struct ShapesFile<'a, T: serde::Serialize> {
    schema_version: u32,
    meta: Meta,
    #[serde(flatten)]
    section: std::collections::BTreeMap<&'a str, T>,
}

/// Writes `records` as section `section` of `out`, or of the default
/// `results/<commit><suffix>.json`, with `meta.tool` = `tool`; returns the path.
pub(super) fn write<T: serde::Serialize>(
    workload: &Workload,
    tool: &str,
    (section, suffix): (&str, &str),
    records: T,
    out: Option<&Path>,
) -> Result<PathBuf, Box<dyn std::error::Error>> {
    let mut meta = Results::new(workload, tool).meta;
    meta.threads = Some(1);
    let file = ShapesFile {
        schema_version: torus_cull_lab::results::SCHEMA_VERSION,
        meta,
        section: [(section, records)].into_iter().collect(),
    };
    let path = match out {
        Some(p) => p.to_path_buf(),
        None => {
            let p = default_path(Path::new("results"), suffix);
            torus_cull_lab::output::create_default_dir(&p)
                .map_err(|e| format!("--out {}: {e}", p.display()))?;
            p
        }
    };
    let mut text = serde_json::to_string_pretty(&file)?;
    text.push('\n');
    write_atomic(&path, text.as_bytes()).map_err(|e| format!("{}: {e}", path.display()))?;
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
