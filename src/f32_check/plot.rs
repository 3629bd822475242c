//! The charts of an f32-check file: one row per family (the families are not a scale,
//! so each chart is a dot plot with the family names down the left), one marker per
//! intersector. Written by `f32-check` next to its file and by `plot FILE`.
//!
//! - `<stem>-escalation.svg`: the rays the f32 path handed to f64, in % of the family.
//! - `<stem>-wrong.svg`: missed + spurious answers in % of the family, for the f32 path
//!   (0 everywhere, or f32-check fails) and the peer.
//! - `<stem>-t_error.svg`: the p99 t error, × (R + r), of the f32 path and the peer, on a
//!   log axis (a family with no hit answered has no dot).
//! - `<stem>-ns_per_ray.svg`: the f32 path, the peer and the f64 intersection, ns per ray
//!   (only when the file was timed).

use super::{CheckFile, FamilyRecord};
use plotters::prelude::*;
use std::path::{Path, PathBuf};

/// One intersector's value per family (`None`: no dot).
type Column = (&'static str, Vec<Option<f64>>);

/// The marker colours: the f32 path, the peer, the f64 intersection.
const COLOURS: [RGBColor; 3] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(120, 120, 120),
];

/// Writes every chart of `file` to `out_dir` (which must exist), named `<stem>-*.svg`;
/// returns the paths written.
pub fn plot_check(
    file: &CheckFile,
    out_dir: &Path,
    stem: &str,
) -> Result<Vec<PathBuf>, Box<dyn std::error::Error>> {
    let f = &file.families;
    let names: Vec<String> = f.iter().map(row_name).collect();
    let pct = |v: f64| Some(100.0 * v);
    let of_rays = |r: &FamilyRecord, n: u64| pct(n as f64 / r.rays.max(1) as f64);
    let provenance = format!(
        "{} rays a family, {}{}",
        file.rays_per_family,
        file.meta.commit.as_deref().unwrap_or("no commit"),
        if file.meta.dirty { "-dirty" } else { "" }
    );
    let mut charts: Vec<(&str, String, &str, Vec<Column>, bool)> = vec![
        (
            "escalation",
            "f32 path: rays escalated to f64".into(),
            "% of the family's rays",
            vec![(
                "f32 path",
                f.iter().map(|r| pct(r.f32_path.escalation_rate)).collect(),
            )],
            false,
        ),
        (
            "wrong",
            "missed + spurious answers".into(),
            "% of the family's rays",
            vec![
                (
                    "f32 path",
                    f.iter()
                        .map(|r| of_rays(r, r.f32_path.missed + r.f32_path.spurious))
                        .collect(),
                ),
                (
                    "peer (shader closed form)",
                    f.iter()
                        .map(|r| of_rays(r, r.peer.missed + r.peer.spurious))
                        .collect(),
                ),
            ],
            false,
        ),
        (
            "t_error",
            "p99 t error of the hits answered".into(),
            "|t - t_oracle|·|d| / (R + r), log scale",
            vec![
                (
                    "f32 path",
                    f.iter()
                        .map(|r| r.f32_path.t_error.map(|e| e.p99))
                        .collect(),
                ),
                (
                    "peer (shader closed form)",
                    f.iter().map(|r| r.peer.t_error.map(|e| e.p99)).collect(),
                ),
            ],
            true,
        ),
    ];
    if f.iter().any(|r| r.ns_per_ray.is_some()) {
        let ns = |pick: fn(&super::Timings) -> f64| -> Vec<Option<f64>> {
            f.iter().map(|r| r.ns_per_ray.as_ref().map(pick)).collect()
        };
        charts.push((
            "ns_per_ray",
            "ns per ray (minimum of rounds, one thread)".into(),
            "ns per ray, log scale",
            vec![
                ("f32 path", ns(|t| t.f32_path)),
                ("peer (shader closed form)", ns(|t| t.peer)),
                ("f64 intersect", ns(|t| t.f64_intersect)),
            ],
            true,
        ));
    }
    let mut written = Vec::new();
    for (name, title, x_label, columns, log) in charts {
        let path = out_dir.join(format!("{stem}-{name}.svg"));
        let mut svg = String::new();
        let title = format!("f32-check: {title} ({provenance})");
        draw(&mut svg, &title, x_label, &names, &columns, log)
            .map_err(|e| format!("{}: {e}", path.display()))?;
        crate::output::write_file(&path, svg.as_bytes())
            .map_err(|e| format!("{}: {e}", path.display()))?;
        written.push(path);
    }
    Ok(written)
}

/// A family's row label: its name, and its ν (or ν range).
fn row_name(r: &FamilyRecord) -> String {
    match r.nu {
        Some(nu) => format!("{} ν={nu}", r.family),
        None => format!("{} ν={}", r.family, super::nu_span(r.nu_range)),
    }
}

/// One dot plot: a row per family, `x` linear from 0 or (with `log`) log10 of the
/// positive values; a legend above the plot.
fn draw(
    svg: &mut String,
    title: &str,
    x_label: &str,
    names: &[String],
    columns: &[Column],
    log: bool,
) -> Result<(), Box<dyn std::error::Error>> {
    let x = |v: f64| if log { v.log10() } else { v };
    let values: Vec<f64> = columns
        .iter()
        .flat_map(|(_, v)| v.iter().flatten())
        .filter(|v| v.is_finite() && (!log || **v > 0.0))
        .map(|&v| x(v))
        .collect();
    let (lo, hi) = values
        .iter()
        .fold((f64::MAX, f64::MIN), |(a, b), &v| (a.min(v), b.max(v)));
    let (lo, hi) = match (values.is_empty(), log) {
        (true, _) => (0.0, 1.0),
        (false, true) => (lo.floor(), hi.ceil().max(lo.floor() + 1.0)),
        (false, false) => (0.0, (hi * 1.05).max(1e-9)),
    };
    let label_width = names.iter().map(|n| n.chars().count()).max().unwrap_or(0) as u32;
    let rows = names.len().max(1);
    let height = 110 + 16 * rows as u32;
    let root = SVGBackend::with_string(svg, (760 + 7 * label_width, height)).into_drawing_area();
    root.fill(&WHITE)?;
    let (legend, body) = root.split_vertically(46);
    let mut chart = ChartBuilder::on(&body)
        .caption(title, ("sans-serif", 15))
        .margin(10)
        .x_label_area_size(40)
        .y_label_area_size(7 * label_width + 16)
        .build_cartesian_2d(lo..hi, (0..rows as i32).into_segmented())?;
    chart
        .configure_mesh()
        .x_desc(x_label)
        .label_style(("sans-serif", 12))
        .y_labels(rows)
        .y_label_formatter(&|y| match y {
            SegmentValue::CenterOf(i) | SegmentValue::Exact(i) => usize::try_from(*i)
                .ok()
                .and_then(|i| names.get(i).cloned())
                .unwrap_or_default(),
            SegmentValue::Last => String::new(),
        })
        .x_label_formatter(&|v| {
            if log {
                format!("1e{}", v.round())
            } else {
                format!("{v}")
            }
        })
        .draw()?;
    for (k, (name, column)) in columns.iter().enumerate() {
        let colour = COLOURS[k % COLOURS.len()];
        let dots = column.iter().enumerate().filter_map(|(row, v)| {
            let v = (*v)?;
            (v.is_finite() && (!log || v > 0.0))
                .then_some((x(v), SegmentValue::CenterOf(row as i32)))
        });
        match k {
            0 => chart.draw_series(dots.map(|p| Circle::new(p, 4, colour.filled())))?,
            1 => chart
                .draw_series(dots.map(|p| TriangleMarker::new(p, 5, colour.stroke_width(2))))?,
            _ => chart.draw_series(dots.map(|p| Cross::new(p, 4, colour.stroke_width(2))))?,
        };
        let at = (20 + 260 * k as i32, 24);
        legend.draw(&Circle::new(at, 4, colour.filled()))?;
        legend.draw(&Text::new(
            name.to_string(),
            (at.0 + 10, at.1 - 7),
            ("sans-serif", 13).into_font().color(&BLACK),
        ))?;
    }
    root.present()?;
    Ok(())
}
