//! `torus-cull time --family`: the torus family's paired ratios
//! ([`torus_cull_lab::paired::family`]) on uniform rays, at ν = R/a = 4 for the elliptical
//! tubes (b/a = 1/4, 1/2, 1, 2, 4) and at the horn and two spindles, written as the
//! `ratio` section of a results file (metric `family_total_ns`), which `compare` reads.

use super::shapes::{show, write};
use std::path::Path;
use std::process::ExitCode;
use torus_cull_lab::paired::family::{MEMBERS, family_records};
use torus_cull_lab::workload::spec::Workload;

/// Runs per member, in this process (fresh ray buffers each).
const RUNS: usize = 3;

/// Times every member for `seconds` in all, writes `out` (or the default
/// `results/<commit>-family-time.json`) and prints a line per member.
pub(super) fn run(
    workload: &Workload,
    seconds: f64,
    batch: usize,
    out: Option<&Path>,
) -> Result<ExitCode, Box<dyn std::error::Error>> {
    let per_run = seconds / (MEMBERS.len() * RUNS) as f64;
    let records = family_records(workload.seed, batch, (RUNS, per_run), |member, ratios| {
        let best = ratios[2..]
            .iter()
            .min_by(|x, y| x.ratio.total_cmp(&y.ratio))
            .expect("every cull is timed");
        println!(
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
        );
    })
    .map_err(|e| format!("time --family: {e}"))?;
    write(workload, "time-family", "-family-time", records, out)?;
    Ok(ExitCode::SUCCESS)
}
