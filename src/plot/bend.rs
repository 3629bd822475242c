//! The charts of a `torus-cull bend` file: per r_min/r_max (and ν), each cull's capture
//! of the far misses and its rejection rate against Δφ, alone and behind the wedge.

use super::{Charts, Record, group_charts, provenance};
use crate::bend_check::{BendFile, CullRecord};
use std::path::{Path, PathBuf};

/// Written to `out_dir` (which must exist) as `<stem>-rmin<r>-nu<ν>-capture.svg` and
/// `…-rejection.svg`: one line per cull and per `cull+wedge`, x = Δφ in degrees (log
/// scale); returns the paths written.
pub fn plot_bend(
    file: &BendFile,
    out_dir: &Path,
    stem: &str,
) -> Result<Vec<PathBuf>, Box<dyn std::error::Error>> {
    let what = format!("{} rays a class", file.rays_per_class);
    let mut charts = Charts::new(
        out_dir,
        stem,
        provenance(what, &file.meta),
        "Δφ in degrees (log scale)",
    )?;
    let points: Vec<BendPoint<'_>> = file
        .classes
        .iter()
        .flat_map(|c| {
            c.culls.iter().map(move |cull| BendPoint {
                group: format!("rmin{}-nu{}", c.bore_ratio, c.nu),
                degrees: c.delta_phi_deg,
                label: cull.label(),
                cull,
            })
        })
        .collect();
    group_charts(
        &points,
        &mut charts,
        ("", "pipe bend, "),
        &[
            (
                "capture",
                "capture of the misses beyond 1.25 eta, by delta phi",
                "% of far misses rejected",
                |p| p.cull.capture.map(|c| (100.0 * c, None)),
            ),
            (
                "rejection",
                "rejection rate, by delta phi",
                "% of rays rejected",
                |p| Some((100.0 * p.cull.rejection_rate, None)),
            ),
        ],
    )?;
    Ok(charts.written)
}

/// One cull (or cull + wedge) on one class, as a chart point (group: r_min/r_max and ν;
/// x: Δφ in degrees).
struct BendPoint<'a> {
    group: String,
    degrees: f64,
    label: String,
    cull: &'a CullRecord,
}

impl Record for BendPoint<'_> {
    fn group(&self) -> String {
        self.group.clone()
    }
    fn cull(&self) -> &str {
        &self.label
    }
    fn nu(&self) -> f64 {
        self.degrees
    }
}
