//! `torus-cull time family` and `time bend`: the paired ratios of the shapes beyond the
//! ring torus, on uniform rays at each shape's box ([`torus_cull_lab::paired::shapes`]):
//! the torus family's members ([`torus_cull_lab::paired::family`]: the elliptical tubes
//! at ν = R/a = 4 with b/a = 1/4 … 4, the horn and two spindles, metric
//! `family_total_ns`) or the pipe bends ([`torus_cull_lab::paired::bend`]: Δφ = 2π … π/6
//! and r_min/r_max = 0, 0.5, 0.9 at ν = R/r_max = 4, metric `bend_total_ns`), written as
//! the `ratio` section of a results file, which `compare` and `plot` read.

use super::args::ShapeArgs;
use super::common::{check_seconds, out_path, pick_batch, pick_runs, save};
use crate::console::{Heartbeat, Ticker, outln};
use std::process::ExitCode;
use torus_cull::bend::PipeBend;
use torus_cull::family::Toroid;
use torus_cull_lab::paired::shapes::{ShapeRatio, TimedShape, shape_records};
use torus_cull_lab::paired::{bend, family};
use torus_cull_lab::results::{RatioRecord, Results};
use torus_cull_lab::workload::spec::Workload;

/// Runs per shape unless `--runs` says otherwise, in this process (fresh ray buffers
/// each).
const DEFAULT_RUNS: u64 = 3;

/// Which shapes: `time family` or `time bend`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Shapes {
    /// The torus family's members.
    Family,
    /// The pipe bends.
    Bend,
}

impl Shapes {
    /// The subcommand, the `meta.tool`'s suffix (`time-<name>`) and the file's
    /// (`-<name>-time`).
    fn name(self) -> &'static str {
        match self {
            Shapes::Family => "family",
            Shapes::Bend => "bend",
        }
    }
}

/// Times every shape of `shapes` for `--seconds` in all and writes the results file.
pub(super) fn run(
    args: &ShapeArgs,
    shapes: Shapes,
) -> Result<ExitCode, Box<dyn std::error::Error>> {
    let common = &args.common;
    let workload = Workload::open(&common.workload)?;
    check_seconds(common.seconds)?;
    let batch = pick_batch(common.batch, &workload, &common.workload)?;
    let runs = pick_runs(args.runs, DEFAULT_RUNS)? as usize;
    let name = shapes.name();
    let path = out_path(common, &format!("-{name}-time"), false)?;
    let interval = if runs > 1 {
        format!("[95% CI between {runs} runs]")
    } else {
        "[95% CI within 1 run]".to_string()
    };
    let timing = |count: usize| {
        let per_run = common.seconds / (count * runs) as f64;
        outln!(
            "time {name}: {count} shapes, {batch} rays each, {runs} runs of {per_run:.2} s \
             each; every ratio {interval}"
        )?;
        let ticker = Ticker::start(
            Heartbeat::new(format!("time {name}"), "shapes"),
            count as u64,
        );
        Ok::<_, std::io::Error>((ticker, (runs, per_run)))
    };
    let seed = workload.seed;
    let records = match shapes {
        Shapes::Family => {
            let members = family::members()?;
            let (ticker, timing) = timing(members.len())?;
            timed(&members, seed, batch, timing, &ticker, family_line)
        }
        Shapes::Bend => {
            let bends = bend::bends()?;
            let (ticker, timing) = timing(bends.len())?;
            timed(&bends, seed, batch, timing, &ticker, bend_line)
        }
    }
    .map_err(|e| format!("time {name}: {e}"))?;
    let mut results = Results::new(&workload, &format!("time-{name}"));
    results.meta.threads = Some(1);
    results.ratio = records;
    save(&results, &path, common)?;
    Ok(ExitCode::SUCCESS)
}

/// [`shape_records`] of `shapes`, each shape's line printed by `line` as it comes and
/// counted on `ticker`.
fn timed<S: TimedShape>(
    shapes: &[S],
    seed: u64,
    batch: usize,
    timing: (usize, f64),
    ticker: &Ticker,
    line: fn(&S, &[ShapeRatio]) -> String,
) -> Result<Vec<RatioRecord>, String> {
    let mut done = 0;
    shape_records(shapes, seed, batch, timing, |shape, ratios| {
        done += 1;
        ticker.set(done);
        // A closed stdout stops the lines only (`outln!`'s contract).
        let _ = outln!("{}", line(shape, ratios));
    })
}

/// A member's line: its exact intersection's cost and its fastest cull.
fn family_line(member: &Toroid, ratios: &[ShapeRatio]) -> String {
    let best = ratios[2..]
        .iter()
        .min_by(|x, y| x.ratio.total_cmp(&y.ratio))
        .expect("every cull is timed");
    format!(
        "R = {}, a = {}, b = {} ({:?}): exact / circular exact = {}, on the images {}; \
         fastest cull: {} / cychosz = {}",
        member.major_radius_f64(),
        member.radial_semi_axis_f64(),
        member.axial_semi_axis_f64(),
        member.kind(),
        show(&ratios[0]),
        show(&ratios[1]),
        best.contender,
        show(best)
    )
}

/// A bend's line: the best cull over no cull, with and without the wedge.
fn bend_line(bend: &PipeBend, ratios: &[ShapeRatio]) -> String {
    let best = |wedge: bool| {
        ratios
            .iter()
            .filter(|r| r.reference == "none" && r.contender.starts_with("wedge+") == wedge)
            .min_by(|x, y| x.ratio.total_cmp(&y.ratio))
            .expect("every cull is timed")
    };
    let (plain, wedged) = (best(false), best(true));
    format!(
        "dphi = {:.4}, r_min/r_max = {}: over no cull, best {} {}, best with the wedge {} {}",
        bend.delta_phi(),
        bend.bore_radius_f64() / bend.tube_radius_f64(),
        plain.contender,
        show(plain),
        wedged.contender,
        show(wedged)
    )
}

/// `ratio [interval]`: the between-run interval of several runs, else the run's own.
fn show(r: &ShapeRatio) -> String {
    let [lo, hi] = r.between.unwrap_or(r.within);
    format!("{:.3} [{lo:.3}, {hi:.3}]", r.ratio)
}
