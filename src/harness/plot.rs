//! SVG charts (plotters): rejection, capture, timing and BVH figures against ν.

use crate::harness::results::{BvhRecord, RejectionRecord, Results, TimingRecord};
use plotters::prelude::*;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// One named line of (x, y) points.
pub type Series = (String, Vec<(f64, f64)>);

/// One colour per timed cull, so no two series of a chart share one.
const COLOURS: [RGBColor; 12] = [
    RGBColor(120, 120, 120),
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
    RGBColor(214, 39, 40),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(23, 190, 207),
    RGBColor(188, 189, 34),
    RGBColor(0, 0, 0),
    RGBColor(255, 187, 120),
];
const _: () = assert!(COLOURS.len() >= crate::CullKind::TIMED.len());

/// Draw `series` against ν on a log axis into an SVG at `path`.
///
/// The chart is drawn in memory and then written through [`crate::harness::output`], so a failed
/// or interrupted plot never leaves a truncated SVG; every error names `path`.
pub fn line_chart(
    path: &Path,
    title: &str,
    y_label: &str,
    series: &[Series],
    y_from_zero: bool,
) -> Result<(), Box<dyn std::error::Error>> {
    let mut svg = String::new();
    draw_chart(&mut svg, title, y_label, series, y_from_zero)
        .map_err(|e| format!("{}: {e}", path.display()))?;
    crate::harness::output::write_file(path, svg.as_bytes())
        .map_err(|e| format!("{}: {e}", path.display()))?;
    Ok(())
}

/// The SVG text of one chart.
fn draw_chart(
    svg: &mut String,
    title: &str,
    y_label: &str,
    series: &[Series],
    y_from_zero: bool,
) -> Result<(), Box<dyn std::error::Error>> {
    let points = series.iter().flat_map(|(_, p)| p.iter());
    let (mut x_min, mut x_max, mut y_min, mut y_max) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for &(x, y) in points {
        x_min = x_min.min(x);
        x_max = x_max.max(x);
        y_min = y_min.min(y);
        y_max = y_max.max(y);
    }
    if x_min > x_max {
        return Err("nothing to plot".into());
    }
    if y_from_zero {
        y_min = y_min.min(0.0);
    }
    let pad = ((y_max - y_min) * 0.05).max(1e-9);
    let (y_lo, y_hi) = (y_min - if y_from_zero { 0.0 } else { pad }, y_max + pad);
    let root = SVGBackend::with_string(svg, (900, 480)).into_drawing_area();
    root.fill(&WHITE)?;
    // The legend gets its own strip, so it never hides a line.
    let (plot_area, legend_area) = root.split_horizontally(740);
    let mut ticks: Vec<f64> = series
        .iter()
        .flat_map(|(_, p)| p.iter().map(|&(x, _)| x))
        .collect();
    ticks.sort_by(f64::total_cmp);
    ticks.dedup();
    let mut chart = ChartBuilder::on(&plot_area)
        .caption(title, ("sans-serif", 20))
        .margin(12)
        .x_label_area_size(44)
        .y_label_area_size(64)
        .build_cartesian_2d(
            (x_min * 0.95..x_max * 1.05)
                .log_scale()
                .with_key_points(ticks),
            y_lo..y_hi,
        )?;
    chart
        .configure_mesh()
        .x_desc("ν = R/r (log scale)")
        .y_desc(y_label)
        .label_style(("sans-serif", 14))
        .light_line_style(WHITE)
        .x_label_formatter(&|x| format!("{x}"))
        .draw()?;
    for (i, (name, pts)) in series.iter().enumerate() {
        let colour = COLOURS[i % COLOURS.len()];
        chart.draw_series(LineSeries::new(pts.iter().copied(), colour.stroke_width(2)))?;
        chart.draw_series(pts.iter().map(|&p| Circle::new(p, 3, colour.filled())))?;
        let y = 60 + 24 * i as i32;
        legend_area.draw(&PathElement::new(
            vec![(8, y), (32, y)],
            colour.stroke_width(3),
        ))?;
        legend_area.draw(&Text::new(
            name.clone(),
            (40, y - 8),
            ("sans-serif", 15).into_font().color(&BLACK),
        ))?;
    }
    root.present()?;
    Ok(())
}

/// Every chart a results file supports, written to `out_dir` with file names starting
/// with `stem`; returns the paths written.
pub fn plot_results(
    results: &Results,
    out_dir: &Path,
    stem: &str,
) -> Result<Vec<PathBuf>, Box<dyn std::error::Error>> {
    std::fs::create_dir_all(out_dir).map_err(|e| format!("{}: {e}", out_dir.display()))?;
    let mut written = Vec::new();
    let mut chart = |name: String, title: String, y: &str, series: Vec<Series>, zero: bool| {
        if series.iter().all(|(_, p)| p.is_empty()) {
            return Ok::<(), Box<dyn std::error::Error>>(());
        }
        let path = out_dir.join(format!("{stem}-{name}.svg"));
        line_chart(&path, &title, y, &series, zero)?;
        written.push(path);
        Ok(())
    };
    for group in ordered(results.rejection.iter().map(Record::group)) {
        let of = |y: fn(&RejectionRecord) -> Option<f64>| series(&results.rejection, &group, y);
        let capture = of(|r| r.miss_capture);
        let rate = of(|r| Some(r.rejection_rate));
        chart(
            format!("{group}-miss_capture"),
            format!("{group}: miss capture (rejected / misses)"),
            "miss capture",
            capture,
            true,
        )?;
        chart(
            format!("{group}-rejection_rate"),
            format!("{group}: rejection rate (rejected / rays)"),
            "rejection rate",
            rate,
            true,
        )?;
    }
    for group in ordered(results.timing.iter().map(Record::group)) {
        let of = |y: fn(&TimingRecord) -> Option<f64>| series(&results.timing, &group, y);
        let total = of(|r| Some(r.total_ns));
        let speedup = of(|r| Some(r.speedup_vs_none));
        chart(
            format!("{group}-total_ns"),
            format!("{group}: cull + exact intersection, ns per ray"),
            "total ns per ray",
            total,
            true,
        )?;
        chart(
            format!("{group}-speedup"),
            format!("{group}: speedup vs none"),
            "total_ns(none) / total_ns(cull)",
            speedup,
            true,
        )?;
    }
    for group in ordered(results.bvh.iter().map(Record::group)) {
        let of = |y: fn(&BvhRecord) -> Option<f64>| series(&results.bvh, &group, y);
        let mrays = of(|r| Some(r.mrays_per_s));
        let solves = of(|r| Some(r.quartic_solves_per_ray));
        chart(
            format!("bvh-{group}-mrays"),
            format!("BVH {group}: million rays per second"),
            "Mrays/s",
            mrays,
            true,
        )?;
        chart(
            format!("bvh-{group}-quartic_solves"),
            format!("BVH {group}: quartic solves per ray"),
            "quartic solves per ray",
            solves,
            true,
        )?;
    }
    Ok(written)
}

/// What the charts need of a record: its chart (case, or scene and ray set), its series
/// (the cull) and its x (ν).
trait Record {
    fn group(&self) -> String;
    fn cull(&self) -> &str;
    fn nu(&self) -> f64;
}

impl Record for RejectionRecord {
    fn group(&self) -> String {
        self.case.clone()
    }
    fn cull(&self) -> &str {
        &self.cull
    }
    fn nu(&self) -> f64 {
        self.nu
    }
}

impl Record for TimingRecord {
    fn group(&self) -> String {
        if self.is_batch() {
            format!("{}-batch", self.case)
        } else {
            self.case.clone()
        }
    }
    fn cull(&self) -> &str {
        &self.cull
    }
    fn nu(&self) -> f64 {
        self.nu
    }
}

impl Record for BvhRecord {
    fn group(&self) -> String {
        format!("{}-{}", self.scene, self.ray_set)
    }
    fn cull(&self) -> &str {
        &self.cull
    }
    fn nu(&self) -> f64 {
        self.nu
    }
}

/// One series per cull, in first-seen order: (ν, y) of the records in `group`.
fn series<R: Record>(records: &[R], group: &str, y: fn(&R) -> Option<f64>) -> Vec<Series> {
    ordered(records.iter().map(|r| r.cull().to_string()))
        .into_iter()
        .map(|cull| {
            let pts = records
                .iter()
                .filter(|r| r.group() == group && r.cull() == cull)
                .filter_map(|r| y(r).map(|v| (r.nu(), v)))
                .collect();
            (cull, pts)
        })
        .collect()
}

/// Distinct values in first-seen order.
fn ordered(values: impl Iterator<Item = String>) -> Vec<String> {
    let mut seen = BTreeMap::new();
    for v in values {
        let n = seen.len();
        seen.entry(v).or_insert(n);
    }
    let mut v: Vec<_> = seen.into_iter().collect();
    v.sort_by_key(|(_, i)| *i);
    v.into_iter().map(|(k, _)| k).collect()
}
