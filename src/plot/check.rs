//! The charts of a check file (`torus-cull check`, any shape): per group of classes (the
//! shape's `group_by` parameters), each cull's capture of the far misses and its
//! rejection rate against the shape's x parameter, one line per cull (declined culls
//! left out); and, where the intersectors' t errors were measured, their answers per
//! class ([`super::answers`]).

use super::{Charts, Place, Placed, group_charts, provenance};
use crate::check::record::{CheckFile, CullRecord};
use std::path::{Path, PathBuf};

/// Written to `out_dir` (which must exist) as `<stem>-<group>-capture.svg` and
/// `…-rejection.svg` (group: `aspect0.25`, `bore_ratio0.5-nu4`), then the answers'
/// charts; returns the paths written.
pub fn plot_check(
    file: &CheckFile,
    out_dir: &Path,
    stem: &str,
) -> Result<Vec<PathBuf>, Box<dyn std::error::Error>> {
    let axes = &file.chart;
    let what = format!("{} rays a class", file.rays_per_class);
    let mut charts = Charts::new(out_dir, stem, provenance(what, &file.meta), &axes.x_title)?;
    let points: Vec<Placed<'_, CullRecord>> = file
        .classes
        .iter()
        .flat_map(|c| {
            let group: Vec<String> = axes
                .group_by
                .iter()
                .map(|k| format!("{k}{}", c.params.get(k).copied().unwrap_or(f64::NAN)))
                .collect();
            let group = group.join("-");
            let x = c.params.get(&axes.x).copied().unwrap_or(f64::NAN);
            c.culls
                .iter()
                .filter(|c| c.accepts)
                .map(move |cull| Placed {
                    place: Place::new(group.clone(), &cull.cull, x),
                    record: cull,
                })
        })
        .collect();
    let title = format!("{}, ", file.shape);
    group_charts(
        &points,
        &mut charts,
        ("", &title),
        &[
            (
                "capture",
                "capture of the misses beyond 1.25 eta",
                "% of far misses rejected",
                |p| p.record.capture.map(|c| (100.0 * c, None)),
            ),
            ("rejection", "rejection rate", "% of rays rejected", |p| {
                Some((100.0 * p.record.rejection_rate, None))
            }),
        ],
    )?;
    let mut written = charts.written;
    let measured = file.classes.iter().flat_map(|c| &c.answers);
    if measured.clone().any(|a| a.t_error.is_some()) {
        let prefix = charts_dir(out_dir).join(stem);
        written.extend(super::answers::plot_answers(file, &prefix)?);
    }
    Ok(written)
}

/// `out_dir`, or `.` for the empty path (the parent of a bare file name).
fn charts_dir(out_dir: &Path) -> &Path {
    if out_dir.as_os_str().is_empty() {
        Path::new(".")
    } else {
        out_dir
    }
}
