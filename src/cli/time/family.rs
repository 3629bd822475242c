//! `torus-cull time --family`: the torus family's paired ratios
//! ([`torus_cull_lab::paired::family`]) on uniform rays, at ν = R/a = 4 for the elliptical
//! tubes (b/a = 1/4, 1/2, 1, 2, 4) and at the horn and two spindles, written as one JSON.

use super::shapes::show;
use std::path::Path;
use std::process::ExitCode;
use torus_cull::family::Toroid;
use torus_cull_lab::paired::family::time_family;
use torus_cull_lab::paired::shapes::ShapeRatio;
use torus_cull_lab::workload::box_rays::box_rays;
use torus_cull_lab::workload::spec::Workload;

/// The members timed: (R, a, b), a = 1.
const MEMBERS: [(f64, f64, f64); 8] = [
    (4.0, 1.0, 0.25),
    (4.0, 1.0, 0.5),
    (4.0, 1.0, 1.0),
    (4.0, 1.0, 2.0),
    (4.0, 1.0, 4.0),
    (1.0, 1.0, 1.0),
    (0.75, 1.0, 1.0),
    (0.75, 1.0, 2.0),
];

/// Runs per member, in this process (fresh ray buffers each).
const RUNS: usize = 3;

/// One member's ratios.
#[derive(serde::Serialize)]
struct MemberRecord {
    major_radius: f64,
    radial_semi_axis: f64,
    axial_semi_axis: f64,
    kind: String,
    rays: usize,
    ratios: Vec<ShapeRatio>,
}

/// Times every member for `seconds` in all, writes `out` (or the default
/// `results/<commit>-family-time.json`) and prints a table.
pub(super) fn run(
    workload: &Workload,
    seconds: f64,
    batch: usize,
    out: Option<&Path>,
) -> Result<ExitCode, Box<dyn std::error::Error>> {
    let per_member = seconds / (MEMBERS.len() * RUNS) as f64;
    let mut family = Vec::new();
    for (i, &(big, a, b)) in MEMBERS.iter().enumerate() {
        let member = Toroid::canonical(big, a, b)?;
        let rays = box_rays(big, a, b, batch, workload.seed.wrapping_add(i as u64));
        let ratios = time_family(&member, &rays, RUNS, per_member, workload.seed)
            .ok_or("time --family: a member gave no rounds (raise --seconds)")?;
        println!(
            "R = {big}, a = {a}, b = {b} ({:?}): exact / circular exact = {}, on the images {}",
            member.kind(),
            show(&ratios[0]),
            show(&ratios[1])
        );
        let best = ratios[2..]
            .iter()
            .min_by(|x, y| x.ratio.total_cmp(&y.ratio))
            .expect("every cull is timed");
        println!(
            "  fastest cull: {} / cychosz = {}",
            best.contender,
            show(best)
        );
        family.push(MemberRecord {
            major_radius: big,
            radial_semi_axis: a,
            axial_semi_axis: b,
            kind: format!("{:?}", member.kind()).to_lowercase(),
            rays: rays.len(),
            ratios,
        });
    }
    super::shapes::write(
        workload,
        "time-family",
        ("family", "-family-time"),
        family,
        out,
    )?;
    Ok(ExitCode::SUCCESS)
}
