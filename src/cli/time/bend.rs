//! `torus-cull time --bend`: pipe bends' paired ratios ([`torus_cull_lab::paired::bend`])
//! on uniform rays at the outer torus's box, ν = R/r_max = 4: Δφ = 2π, π, π/2, π/6 at
//! r_min/r_max = 0.5, and r_min/r_max = 0 and 0.9 at Δφ = π/2, written as the `ratio`
//! section of a results file (metric `bend_total_ns`), which `compare` reads.

use super::shapes::{show, write};
use std::path::Path;
use std::process::ExitCode;
use torus_cull_lab::paired::bend::{BENDS, bend_records};
use torus_cull_lab::workload::spec::Workload;

/// Runs per bend, in this process (fresh ray buffers each).
const RUNS: usize = 3;

/// Times every bend for `seconds` in all, writes `out` (or the default
/// `results/<commit>-bend-time.json`) and prints the best cull with and without the wedge.
pub(super) fn run(
    workload: &Workload,
    seconds: f64,
    batch: usize,
    out: Option<&Path>,
) -> Result<ExitCode, Box<dyn std::error::Error>> {
    let per_run = seconds / (BENDS.len() * RUNS) as f64;
    let records = bend_records(workload.seed, batch, (RUNS, per_run), |bend, ratios| {
        let best = |wedge: bool| {
            ratios
                .iter()
                .filter(|r| r.reference == "none" && r.contender.starts_with("wedge+") == wedge)
                .min_by(|x, y| x.ratio.total_cmp(&y.ratio))
                .expect("every cull is timed")
        };
        let (plain, wedged) = (best(false), best(true));
        println!(
            "dphi = {:.4}, r_min/r_max = {}: over no cull, best {} {}, best with the wedge {} {}",
            bend.delta_phi(),
            bend.bore_radius_f64() / bend.tube_radius_f64(),
            plain.contender,
            show(plain),
            wedged.contender,
            show(wedged)
        );
    })
    .map_err(|e| format!("time --bend: {e}"))?;
    write(workload, "time-bend", "-bend-time", records, out)?;
    Ok(ExitCode::SUCCESS)
}
