//! SVG charts (plotters): rejection, capture, timing, BVH and paired-ratio figures
//! against ν, and a check file's (`check.rs`: capture and rejection per cull against the
//! shape's parameter; `answers.rs`: the intersectors' answers per class).

use crate::results::{
    BvhRecord, CPU_DEVICE, EstimateRecord, F64_PRECISION, F64_REFERENCE, RatioRecord,
    RejectionRecord, Results, TimingRecord,
};
use plotters::prelude::*;
use std::collections::BTreeMap;
use std::ops::Range;
use std::path::{Path, PathBuf};

pub mod answers;
pub mod check;
mod shapes;

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
const _: () = assert!(COLOURS.len() >= torus_cull::CullKind::TIMED.len());

/// Draw `series` against ν on a log axis into an SVG at `path`.
///
/// The chart is drawn in memory and then written through [`crate::output`], so a failed
/// or interrupted plot never leaves a truncated SVG; every error names `path`.
pub fn line_chart(
    path: &Path,
    title: &str,
    y_label: &str,
    series: &[Series],
    y_from_zero: bool,
) -> Result<(), Box<dyn std::error::Error>> {
    let lines: Vec<Line> = series
        .iter()
        .enumerate()
        .map(|(i, (name, pts))| Line {
            name: name.clone(),
            colour: i,
            pts: pts.iter().map(|&(x, y)| (x, y, None)).collect(),
        })
        .collect();
    write_chart(path, title, (NU_AXIS, y_label), &lines, y_from_zero)
}

/// The x axis of every chart but a check file's (its shape names its own).
const NU_AXIS: &str = "ν = R/r (log scale)";

/// The x axis of a bend's charts: its segment.
const DELTA_AXIS: &str = "Δφ in degrees (log scale)";

/// One line of a chart: its points (x, y, optional 95 % interval of y) and its colour
/// index (the series' place among all the file's culls, so a cull keeps its colour).
struct Line {
    name: String,
    colour: usize,
    pts: Vec<(f64, f64, Option<[f64; 2]>)>,
}

fn write_chart(
    path: &Path,
    title: &str,
    axes: (&str, &str),
    lines: &[Line],
    y_from_zero: bool,
) -> Result<(), Box<dyn std::error::Error>> {
    let mut svg = String::new();
    draw_chart(&mut svg, title, axes, lines, y_from_zero)
        .map_err(|e| format!("{}: {e}", path.display()))?;
    crate::output::write_file(path, svg.as_bytes())
        .map_err(|e| format!("{}: {e}", path.display()))?;
    Ok(())
}

/// The SVG text of one chart. Lines with no points are left out (legend included); a line
/// identical to an earlier one says so in the legend, and each line has its own marker
/// shape, so that neither hides the other; intervals are drawn as error bars. `axes`:
/// the x and y labels (x on a log scale).
fn draw_chart(
    svg: &mut String,
    title: &str,
    (x_label, y_label): (&str, &str),
    lines: &[Line],
    y_from_zero: bool,
) -> Result<(), Box<dyn std::error::Error>> {
    let lines: Vec<&Line> = lines.iter().filter(|l| !l.pts.is_empty()).collect();
    let ([x_min, x_max], y_range) = axis_ranges(&lines, y_from_zero).ok_or("nothing to plot")?;
    // The legend gets its own strip, so it never hides a line, and the strip is as wide
    // as its longest entry, so no name is cut at the right edge.
    let legend_width = (0..lines.len())
        .map(|i| LEGEND_TEXT_X + text_width(&legend_text(i, &lines)))
        .max()
        .unwrap_or(0)
        .max(160);
    let root = SVGBackend::with_string(svg, (PLOT_WIDTH + legend_width, 480)).into_drawing_area();
    root.fill(&WHITE)?;
    let (plot_area, legend_area) = root.split_horizontally(PLOT_WIDTH);
    let mut chart = ChartBuilder::on(&plot_area)
        .caption(title, ("sans-serif", 17))
        .margin(12)
        .x_label_area_size(44)
        .y_label_area_size(64)
        .build_cartesian_2d(
            (x_min * 0.95..x_max * 1.05)
                .log_scale()
                .with_key_points(x_ticks(&lines)),
            y_range,
        )?;
    chart
        .configure_mesh()
        .x_desc(x_label)
        .y_desc(y_label)
        .label_style(("sans-serif", 14))
        .light_line_style(WHITE)
        .x_label_formatter(&|x| format!("{x}"))
        .draw()?;
    for (i, line) in lines.iter().enumerate() {
        let colour = COLOURS[line.colour % COLOURS.len()];
        let xy = || line.pts.iter().map(|&(x, y, _)| (x, y));
        // A line that later lines coincide with is drawn wider, 3 px per twin, so that
        // each twin drawn over it leaves a band of its colour showing on either side.
        let twins_after = lines[i + 1..].iter().filter(|l| l.pts == line.pts).count();
        let width = 2 + 3 * twins_after as u32;
        chart.draw_series(LineSeries::new(xy(), colour.stroke_width(width)))?;
        draw_error_bars(&mut chart, line, colour)?;
        draw_markers(&mut chart, i, xy(), colour)?;
        draw_legend_entry(&legend_area, i, &lines, colour)?;
    }
    root.present()?;
    Ok(())
}

/// The x range of `lines`' points and the y range of the chart: the points and their
/// intervals, padded by 5 % (not below zero when `y_from_zero`, which also takes zero
/// in); `None` without a point.
fn axis_ranges(lines: &[&Line], y_from_zero: bool) -> Option<([f64; 2], Range<f64>)> {
    let (mut x_min, mut x_max, mut y_min, mut y_max) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for &(x, y, ci) in lines.iter().flat_map(|l| l.pts.iter()) {
        x_min = x_min.min(x);
        x_max = x_max.max(x);
        let [lo, hi] = ci.unwrap_or([y, y]);
        y_min = y_min.min(y).min(lo);
        y_max = y_max.max(y).max(hi);
    }
    if x_min > x_max {
        return None;
    }
    if y_from_zero {
        y_min = y_min.min(0.0);
    }
    let pad = ((y_max - y_min) * 0.05).max(1e-9);
    let y_lo = y_min - if y_from_zero { 0.0 } else { pad };
    Some(([x_min, x_max], y_lo..y_max + pad))
}

/// Every ν of `lines`, once each, ascending: the x axis labels exactly the ν measured.
fn x_ticks(lines: &[&Line]) -> Vec<f64> {
    let mut ticks: Vec<f64> = lines
        .iter()
        .flat_map(|l| l.pts.iter().map(|&(x, _, _)| x))
        .collect();
    ticks.sort_by(f64::total_cmp);
    ticks.dedup();
    ticks
}

/// `line`'s intervals: a bar with caps a few pixels wide (in data units on a log axis: a
/// small factor of x).
fn draw_error_bars(
    chart: &mut ChartContext<'_, SVGBackend<'_>, impl CoordTranslate<From = (f64, f64)>>,
    line: &Line,
    colour: RGBColor,
) -> Result<(), Box<dyn std::error::Error>> {
    for &(x, _, ci) in &line.pts {
        if let Some([lo, hi]) = ci {
            let (xl, xr) = (x / 1.012, x * 1.012);
            chart.draw_series(std::iter::once(PathElement::new(
                vec![(x, lo), (x, hi)],
                colour.stroke_width(1),
            )))?;
            for y in [lo, hi] {
                chart.draw_series(std::iter::once(PathElement::new(
                    vec![(xl, y), (xr, y)],
                    colour.stroke_width(1),
                )))?;
            }
        }
    }
    Ok(())
}

/// Line `i`'s legend entry: its stroke, its marker and its name, with the earlier line it
/// coincides with, if any (on the chart the earlier one is drawn wider underneath).
fn draw_legend_entry(
    area: &DrawingArea<SVGBackend<'_>, plotters::coord::Shift>,
    i: usize,
    lines: &[&Line],
    colour: RGBColor,
) -> Result<(), Box<dyn std::error::Error>> {
    let y = 60 + 24 * i as i32;
    area.draw(&PathElement::new(
        vec![(8, y), (32, y)],
        colour.stroke_width(3),
    ))?;
    legend_marker(area, i, (20, y), colour)?;
    area.draw(&Text::new(
        legend_text(i, lines),
        (LEGEND_TEXT_X as i32, y - 8),
        ("sans-serif", 13).into_font().color(&BLACK),
    ))?;
    Ok(())
}

/// The plot's width in pixels; the legend strip comes to its right.
const PLOT_WIDTH: u32 = 740;

/// Where a legend entry's text starts in the strip, pixels.
const LEGEND_TEXT_X: u32 = 40;

/// Line `i`'s legend text: its name, and the earlier line it coincides with, if any.
fn legend_text(i: usize, lines: &[&Line]) -> String {
    let line = lines[i];
    let same_as = lines[..i]
        .iter()
        .find(|earlier| earlier.pts == line.pts)
        .map(|earlier| format!(" (= {})", earlier.name))
        .unwrap_or_default();
    format!("{}{same_as}", line.name)
}

/// A generous width of `text` in 13 px sans-serif, pixels: 8 px a character (the widest
/// common glyphs, `m` and `w`, are about 10, most are 6-7) and a margin, so an entry is
/// never cut where the SVG's viewer picks a wide font.
fn text_width(text: &str) -> u32 {
    8 * text.chars().count() as u32 + 12
}

/// The markers of line `i`: a circle, triangle, cross or square in turn, so lines that
/// coincide stay distinguishable.
fn draw_markers(
    chart: &mut ChartContext<'_, SVGBackend<'_>, impl CoordTranslate<From = (f64, f64)>>,
    i: usize,
    pts: impl Iterator<Item = (f64, f64)> + Clone,
    colour: RGBColor,
) -> Result<(), Box<dyn std::error::Error>> {
    match i % 4 {
        0 => chart.draw_series(pts.map(|p| Circle::new(p, 3, colour.filled())))?,
        1 => chart.draw_series(pts.map(|p| TriangleMarker::new(p, 5, colour.stroke_width(1))))?,
        2 => chart.draw_series(pts.map(|p| Cross::new(p, 5, colour.stroke_width(2))))?,
        _ => chart.draw_series(pts.map(|p| {
            EmptyElement::at(p) + Rectangle::new([(-3, -3), (3, 3)], colour.stroke_width(1))
        }))?,
    };
    Ok(())
}

/// Line `i`'s marker in the legend, at pixel `at`.
fn legend_marker(
    area: &DrawingArea<SVGBackend<'_>, plotters::coord::Shift>,
    i: usize,
    at: (i32, i32),
    colour: RGBColor,
) -> Result<(), Box<dyn std::error::Error>> {
    match i % 4 {
        0 => area.draw(&Circle::new(at, 4, colour.filled()))?,
        1 => area.draw(&TriangleMarker::new(at, 6, WHITE.filled()))?,
        2 => area.draw(&Cross::new(at, 5, WHITE.stroke_width(2)))?,
        _ => {
            area.draw(&(EmptyElement::at(at) + Rectangle::new([(-4, -4), (4, 4)], WHITE.filled())))?
        }
    };
    match i % 4 {
        1 => area.draw(&TriangleMarker::new(at, 6, colour.stroke_width(1)))?,
        2 => area.draw(&Cross::new(at, 5, colour.stroke_width(2)))?,
        3 => area.draw(
            &(EmptyElement::at(at) + Rectangle::new([(-4, -4), (4, 4)], colour.stroke_width(1))),
        )?,
        _ => {}
    };
    Ok(())
}

/// Before any work: every existing entry of `out_dir` that a chart of [`plot_results`]
/// with this `stem` could be written to (`<stem>-*.svg`) must be replaceable
/// ([`crate::output::check_writable`]: not a directory, its directory writable). The
/// error names the path.
pub fn check_chart_paths(out_dir: &Path, stem: &str) -> Result<(), String> {
    let Ok(entries) = std::fs::read_dir(out_dir) else {
        // A missing or unreadable directory is the results file's own check to report.
        return Ok(());
    };
    let prefix = format!("{stem}-");
    for entry in entries.flatten() {
        let name = entry.file_name();
        let name = name.to_string_lossy();
        if name.starts_with(&prefix) && name.ends_with(".svg") {
            let path = entry.path();
            crate::output::check_writable(&path)
                .map_err(|e| format!("plot {}: {e}", path.display()))?;
        }
    }
    Ok(())
}

/// Every chart a results file supports, written to `out_dir` (which must exist) with file names starting
/// with `stem`; returns the paths written. Titles name the workload and the commit;
/// timings and paired ratios carry their 95 % intervals as error bars.
pub fn plot_results(
    results: &Results,
    out_dir: &Path,
    stem: &str,
) -> Result<Vec<PathBuf>, Box<dyn std::error::Error>> {
    let what = results.meta.workload.clone();
    let mut charts = Charts::new(out_dir, stem, provenance(what, &results.meta), NU_AXIS)?;
    group_charts(&results.rejection, &mut charts, ("", ""), REJECTION_CHARTS)?;
    group_charts(&results.timing, &mut charts, ("", ""), TIMING_CHARTS)?;
    group_charts(&results.bvh, &mut charts, ("bvh-", "BVH "), BVH_CHARTS)?;
    ratio_charts(&results.ratio, &mut charts)?;
    // A file with only estimates (`time gpu`, a filtered bench) is drawn from
    // them; in a complete bench file they repeat the timing records and are not.
    if results.timing.is_empty() && results.ratio.is_empty() {
        estimate_charts(&results.estimates, &mut charts)?;
    }
    let what = results.meta.workload.clone();
    let mut bends = Charts::new(out_dir, stem, provenance(what, &results.meta), DELTA_AXIS)?;
    shapes::charts(&results.shapes, &mut charts, &mut bends)?;
    charts.written.extend(bends.written);
    Ok(charts.written)
}

/// An estimate whose benchmark id reads `group/cull/ν` (`gpu_ns-hole/cychosz/2`,
/// `total_ns-hole/skala/2`) placed by it: one point of a chart per group; `None` for an id
/// of another shape (the solver and BVH benchmarks).
fn placed_estimate(record: &EstimateRecord) -> Option<Placed<'_, EstimateRecord>> {
    let mut parts = record.benchmark.split('/');
    let (group, cull, nu) = (parts.next()?, parts.next()?, parts.next()?);
    let x: f64 = nu.parse().ok()?;
    let place = Place::new(group.to_string(), cull, x);
    (parts.next().is_none() && x.is_finite()).then_some(Placed { place, record })
}

/// One chart per estimate group: ns per element against ν, one line per cull, with the
/// record's interval.
fn estimate_charts(
    records: &[EstimateRecord],
    charts: &mut Charts<'_>,
) -> Result<(), Box<dyn std::error::Error>> {
    let estimates: Vec<Placed<EstimateRecord>> =
        records.iter().filter_map(placed_estimate).collect();
    for group in ordered(estimates.iter().map(|e| e.place().group)) {
        let pts = lines(&estimates, &group, |e| {
            Some((e.record.ns_per_element, Some(e.record.ns_per_element_ci)))
        });
        charts.chart(
            format!("estimates-{group}"),
            format!("{group}: ns per element [interval]"),
            "ns per element",
            pts,
            true,
        )?;
    }
    Ok(())
}

/// `what, <commit>[-dirty]`: what a file holds and the build that wrote it, for titles.
fn provenance(what: String, meta: &crate::results::Meta) -> String {
    format!(
        "{what}, {}{}",
        meta.commit.as_deref().unwrap_or("no commit"),
        if meta.dirty { "-dirty" } else { "" }
    )
}

/// Where a results file's charts go, and the ones written so far.
struct Charts<'a> {
    out_dir: &'a Path,
    stem: &'a str,
    /// Workload and commit, appended to every title.
    provenance: String,
    /// The x axis's label.
    x_label: String,
    written: Vec<PathBuf>,
}

impl<'a> Charts<'a> {
    /// The charts of one file, to `out_dir` (which must exist: like every output, a missing
    /// one is not created; an empty path, the parent of a bare file name, is the current
    /// directory), named `<stem>-*.svg`, each title ending in `provenance`.
    fn new(
        out_dir: &'a Path,
        stem: &'a str,
        provenance: String,
        x_label: &str,
    ) -> Result<Charts<'a>, Box<dyn std::error::Error>> {
        let out_dir = if out_dir.as_os_str().is_empty() {
            Path::new(".")
        } else {
            out_dir
        };
        if !out_dir.is_dir() {
            return Err(format!("{}: no such directory", out_dir.display()).into());
        }
        Ok(Charts {
            out_dir,
            stem,
            provenance,
            x_label: x_label.into(),
            written: Vec::new(),
        })
    }

    /// Writes chart `<stem>-<name>.svg`, unless none of `lines` has a point.
    fn chart(
        &mut self,
        name: String,
        title: String,
        y: &str,
        lines: Vec<Line>,
        zero: bool,
    ) -> Result<(), Box<dyn std::error::Error>> {
        if lines.iter().all(|l| l.pts.is_empty()) {
            return Ok(());
        }
        let path = self.out_dir.join(format!("{}-{name}.svg", self.stem));
        let title = format!("{title} ({})", self.provenance);
        write_chart(&path, &title, (&self.x_label, y), &lines, zero)?;
        self.written.push(path);
        Ok(())
    }
}

/// One chart per group: the name's suffix, the title after the group, the y label, and
/// each record's value with its interval, if it has one.
type GroupChart<R> = (
    &'static str,
    &'static str,
    &'static str,
    fn(&R) -> Option<(f64, Option<[f64; 2]>)>,
);

/// Per group of `records`, in order, each of `specs` as chart
/// `<name_prefix><group>-<suffix>` titled `<title_prefix><group>: <title>`, from zero.
fn group_charts<R: Record>(
    records: &[R],
    charts: &mut Charts<'_>,
    (name_prefix, title_prefix): (&str, &str),
    specs: &[GroupChart<R>],
) -> Result<(), Box<dyn std::error::Error>> {
    for group in ordered(records.iter().map(|r| r.place().group)) {
        for &(suffix, title, y, value) in specs {
            charts.chart(
                format!("{name_prefix}{group}-{suffix}"),
                format!("{title_prefix}{group}: {title}"),
                y,
                lines(records, &group, value),
                true,
            )?;
        }
    }
    Ok(())
}

/// `run`'s counts: miss capture and rejection rate per case.
const REJECTION_CHARTS: &[GroupChart<RejectionRecord>] = &[
    (
        "miss_capture",
        "miss capture (rejected / misses)",
        "miss capture",
        |r| r.miss_capture.map(|v| (v, None)),
    ),
    (
        "rejection_rate",
        "rejection rate (rejected / rays)",
        "rejection rate",
        |r| Some((r.rejection_rate, None)),
    ),
];

/// The benches' timings: ns per ray and speedup against no cull, per group.
const TIMING_CHARTS: &[GroupChart<TimingRecord>] = &[
    (
        "total_ns",
        "cull + exact intersection, ns per ray [CI]",
        "total ns per ray",
        |r| Some((r.total_ns, Some(r.total_ns_ci))),
    ),
    (
        "speedup",
        "speedup vs none",
        "total_ns(none) / total_ns(cull)",
        |r| Some((r.speedup_vs_none, None)),
    ),
];

/// The BVH scenes: throughput and quartic solves per ray, per scene and ray set.
const BVH_CHARTS: &[GroupChart<BvhRecord>] = &[
    ("mrays", "million rays per second", "Mrays/s", |r| {
        Some((r.mrays_per_s, None))
    }),
    (
        "quartic_solves",
        "quartic solves per ray",
        "quartic solves per ray",
        |r| Some((r.quartic_solves_per_ray, None)),
    ),
];

/// `torus-cull time`'s paired ratios: one chart per case × metric × reference, each ratio
/// with its between-run interval where it has one (several runs), else its within-run one.
fn ratio_charts(
    records: &[RatioRecord],
    charts: &mut Charts<'_>,
) -> Result<(), Box<dyn std::error::Error>> {
    for group in ordered(records.iter().map(|r| r.place().group)) {
        let ratios = lines(records, &group, |r| {
            Some((r.ratio, Some(r.ratio_ci_between.unwrap_or(r.ratio_ci))))
        });
        let Some(first) = records.iter().find(|r| r.place().group == group) else {
            continue;
        };
        charts.chart(
            format!("ratio-{group}"),
            ratio_title(first),
            &format!("t(cull) / t({}), below 1 faster", first.reference),
            ratios,
            false,
        )?;
    }
    Ok(())
}

/// The title of the ratio chart of `record`'s group: what was timed, against what.
fn ratio_title(record: &RatioRecord) -> String {
    let what = match record.metric.as_str() {
        "cull_ns" | "batch_cull_ns" => "cull alone",
        "batch_f32_total_ns" => "certified f32 wavefront",
        "batch_f32_uncertified_ns" => "uncertified f32 wavefront",
        _ => "cull + exact intersection",
    };
    let reference = if record.reference == F64_REFERENCE {
        "the same cull's f64 wavefront"
    } else {
        record.reference.as_str()
    };
    format!(
        "{}: {what} / {reference}, paired ratio [95% CI]",
        record.case
    )
}

/// One line per cull of the file (first-seen order, which fixes its colour): the (ν, y,
/// interval) of the records in `group`; a cull with no record there has no points.
fn lines<R: Record>(
    records: &[R],
    group: &str,
    y: impl Fn(&R) -> Option<(f64, Option<[f64; 2]>)>,
) -> Vec<Line> {
    ordered(records.iter().map(|r| r.place().cull.to_string()))
        .into_iter()
        .enumerate()
        .map(|(colour, cull)| {
            let pts = records
                .iter()
                .filter_map(|r| {
                    let place = r.place();
                    (place.group == group && place.cull == cull).then_some((place.x, r))
                })
                .filter_map(|(x, r)| y(r).map(|(v, ci)| (x, v, ci)))
                .collect();
            Line {
                name: cull,
                colour,
                pts,
            }
        })
        .collect()
}

/// Where a record sits on the charts: its chart (`group`: the case, or the scene and ray
/// set, …), its line (the cull) and its x (ν, or the shape's own parameter).
#[derive(Clone)]
struct Place<'a> {
    group: String,
    cull: &'a str,
    x: f64,
}

impl<'a> Place<'a> {
    fn new(group: String, cull: &'a str, x: f64) -> Place<'a> {
        Place { group, cull, x }
    }
}

/// What the charts need of a record: its [`Place`].
trait Record {
    fn place(&self) -> Place<'_>;
}

/// A record with its place worked out beforehand, where the place is not among its fields
/// (an estimate's benchmark id, a check class's parameters, a family member's aspect).
struct Placed<'a, R> {
    place: Place<'a>,
    record: &'a R,
}

impl<R> Record for Placed<'_, R> {
    fn place(&self) -> Place<'_> {
        self.place.clone()
    }
}

impl Record for RejectionRecord {
    fn place(&self) -> Place<'_> {
        Place::new(self.case.clone(), &self.cull, self.nu)
    }
}

/// Each mode, precision and device on charts of its own.
impl Record for TimingRecord {
    fn place(&self) -> Place<'_> {
        let mut group = self.case.clone();
        if self.is_batch() {
            group += "-batch";
        }
        if self.precision != F64_PRECISION {
            group += &format!("-{}", self.precision);
        }
        if self.device != CPU_DEVICE {
            group += &format!("-{}", self.device);
        }
        Place::new(group, &self.cull, self.nu)
    }
}

impl Record for BvhRecord {
    fn place(&self) -> Place<'_> {
        Place::new(
            format!("{}-{}", self.scene, self.ray_set),
            &self.cull,
            self.nu,
        )
    }
}

impl Record for RatioRecord {
    fn place(&self) -> Place<'_> {
        Place::new(
            format!("{}-{}-vs-{}", self.case, self.metric, self.reference),
            &self.cull,
            self.nu,
        )
    }
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

#[cfg(test)]
mod tests;
