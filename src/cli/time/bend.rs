//! `torus-cull time --bend`: pipe bends' paired ratios ([`torus_cull_lab::paired::bend`])
//! on uniform rays at the outer torus's box, ν = R/r_max = 4: Δφ = 2π, π, π/2, π/6 at
//! r_min/r_max = 0.5, and r_min/r_max = 0 and 0.9 at Δφ = π/2; one JSON.

use super::shapes::show;
use std::f64::consts::{FRAC_PI_2, PI, TAU};
use std::path::Path;
use std::process::ExitCode;
use torus_cull::bend::PipeBend;
use torus_cull_lab::paired::bend::time_bend;
use torus_cull_lab::paired::shapes::ShapeRatio;
use torus_cull_lab::workload::box_rays::box_rays;
use torus_cull_lab::workload::spec::Workload;

/// The bends timed: (Δφ, r_min/r_max), R = 4, r_max = 1, φ₀ = 0.
const BENDS: [(f64, f64); 6] = [
    (TAU, 0.5),
    (PI, 0.5),
    (FRAC_PI_2, 0.5),
    (PI / 6.0, 0.5),
    (FRAC_PI_2, 0.0),
    (FRAC_PI_2, 0.9),
];

/// Runs per bend, in this process (fresh ray buffers each).
const RUNS: usize = 3;

/// One bend's ratios.
#[derive(serde::Serialize)]
struct BendRecord {
    major_radius: f64,
    tube_radius: f64,
    bore_radius: f64,
    start_phi: f64,
    delta_phi: f64,
    rays: usize,
    ratios: Vec<ShapeRatio>,
}

/// Times every bend for `seconds` in all, writes `out` (or the default
/// `results/<commit>-bend-time.json`) and prints the best cull with and without the wedge.
pub(super) fn run(
    workload: &Workload,
    seconds: f64,
    batch: usize,
    out: Option<&Path>,
) -> Result<ExitCode, Box<dyn std::error::Error>> {
    let per_run = seconds / (BENDS.len() * RUNS) as f64;
    let mut bends = Vec::new();
    for (i, &(delta_phi, bore)) in BENDS.iter().enumerate() {
        let bend = PipeBend::canonical(4.0, bore, 1.0, 0.0, delta_phi)?;
        let rays = box_rays(4.0, 1.0, 1.0, batch, workload.seed.wrapping_add(i as u64));
        let ratios = time_bend(&bend, &rays, RUNS, per_run, workload.seed)
            .ok_or("time --bend: a bend gave no rounds (raise --seconds)")?;
        let best = |wedge: bool| {
            ratios
                .iter()
                .filter(|r| r.reference == "exact" && r.contender.starts_with("wedge+") == wedge)
                .min_by(|x, y| x.ratio.total_cmp(&y.ratio))
                .expect("every cull is timed")
        };
        let (plain, wedged) = (best(false), best(true));
        println!(
            "dphi = {delta_phi:.4}, r_min/r_max = {bore}: over no cull, best {} {}, best with the wedge {} {}",
            plain.contender,
            show(plain),
            wedged.contender,
            show(wedged)
        );
        bends.push(BendRecord {
            major_radius: 4.0,
            tube_radius: 1.0,
            bore_radius: bore,
            start_phi: 0.0,
            delta_phi,
            rays: rays.len(),
            ratios,
        });
    }
    super::shapes::write(workload, "time-bend", ("bend", "-bend-time"), bends, out)?;
    Ok(ExitCode::SUCCESS)
}
