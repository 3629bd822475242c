//! The intersectors' charts of a check file whose answers carry t errors (`torus-cull
//! check --precision f32`): one row per class (the classes are not a scale, so each
//! chart is a dot plot with the class labels down the left), one marker per intersector.
//! Written by `check` next to its file and by `plot FILE`.
//!
//! - `<stem>-escalation.svg`: the rays each intersector handed to f64, in % of the class.
//! - `<stem>-wrong.svg`: its wrong answers in % of the class (0 everywhere for ours, or
//!   the check fails; a peer's are what it is measured for).
//! - `<stem>-t_error.svg`: the p99 t error, × the shape's size, on a log axis (a class
//!   with no hit answered has no dot).
//! - `<stem>-ns_per_ray.svg`: ns per ray of each timed intersector (only when the file
//!   was timed).

use crate::check::record::{AnswerRecord, CheckFile, ClassRecord};
use plotters::prelude::*;
use std::path::{Path, PathBuf};

/// One intersector's value per class (`None`: no dot).
type Column = (String, Vec<Option<f64>>);

/// The marker colours, in the intersectors' order.
const COLOURS: [RGBColor; 3] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(120, 120, 120),
];

/// One column per intersector of the first class that `keep`s, its value per class by
/// `value` (classes are paired by the intersector's name).
fn columns(
    classes: &[ClassRecord],
    keep: impl Fn(&AnswerRecord) -> bool,
    value: impl Fn(&ClassRecord, &AnswerRecord) -> Option<f64>,
) -> Vec<Column> {
    let Some(first) = classes.first() else {
        return Vec::new();
    };
    first
        .answers
        .iter()
        .filter(|a| keep(a))
        .map(|a| {
            let values = classes
                .iter()
                .map(|c| {
                    let same = c.answers.iter().find(|b| b.who == a.who)?;
                    value(c, same)
                })
                .collect();
            (a.who.clone(), values)
        })
        .collect()
}

/// Writes every chart of `file` as `<prefix>-<chart>.svg` (`prefix`: the directory, which
/// must exist, joined with the file's stem); returns the paths written.
pub fn plot_answers(
    file: &CheckFile,
    prefix: &Path,
) -> Result<Vec<PathBuf>, Box<dyn std::error::Error>> {
    let f = &file.classes;
    let names: Vec<String> = f.iter().map(|c| c.label.clone()).collect();
    let of_rays = |c: &ClassRecord, n: u64| Some(100.0 * n as f64 / c.rays.max(1) as f64);
    let provenance = format!(
        "{} rays a class, {}{}",
        file.rays_per_class,
        file.meta.commit.as_deref().unwrap_or("no commit"),
        if file.meta.dirty { "-dirty" } else { "" }
    );
    let mut charts: Vec<(&str, &str, &str, Vec<Column>, bool)> = vec![
        (
            "escalation",
            "rays escalated to f64",
            "% of the class's rays",
            columns(
                f,
                |a| a.counts.contains_key("escalated"),
                |c, a| of_rays(c, a.count("escalated")),
            ),
            false,
        ),
        (
            "wrong",
            "wrong answers",
            "% of the class's rays",
            columns(f, |_| true, |c, a| of_rays(c, a.wrong_answers())),
            false,
        ),
        (
            "t_error",
            "p99 t error of the hits answered",
            "|t - t_oracle|·|d| / size, log scale",
            columns(f, |a| a.t_error.is_some(), |_, a| a.t_error.map(|e| e.p99)),
            true,
        ),
    ];
    if let Some(ns) = f.iter().find_map(|c| c.ns_per_ray.as_ref()) {
        let timed: Vec<Column> = ns
            .keys()
            .filter(|k| *k != "rounds")
            .map(|k| {
                let values = f
                    .iter()
                    .map(|c| c.ns_per_ray.as_ref().and_then(|n| n.get(k)).copied())
                    .collect();
                (k.clone(), values)
            })
            .collect();
        charts.push((
            "ns_per_ray",
            "ns per ray (minimum of rounds, one thread)",
            "ns per ray, log scale",
            timed,
            true,
        ));
    }
    let mut written = Vec::new();
    for (name, title, x_label, columns, log) in charts {
        if columns.is_empty() {
            continue;
        }
        let mut path = prefix.as_os_str().to_owned();
        path.push(format!("-{name}.svg"));
        let path = PathBuf::from(path);
        let mut svg = String::new();
        let title = format!("{} {}: {title} ({provenance})", file.shape, file.precision);
        draw(&mut svg, &title, x_label, &names, &columns, log)
            .map_err(|e| format!("{}: {e}", path.display()))?;
        crate::output::write_file(&path, svg.as_bytes())
            .map_err(|e| format!("{}: {e}", path.display()))?;
        written.push(path);
    }
    Ok(written)
}

/// One dot plot: a row per class, `x` linear from 0 or (with `log`) log10 of the
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
