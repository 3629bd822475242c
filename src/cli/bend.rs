//! `torus-cull bend`: every cull, alone and behind the wedge, and the exact intersection of
//! the pipe bend against the bend oracle, class by class (`torus_cull_lab::bend_check`).

use super::CliResult;
use crate::console::out;
use crate::whole::Whole;
use std::f64::consts::TAU;
use std::path::PathBuf;
use std::process::ExitCode;
use torus_cull::MAX_NU;
use torus_cull_lab::bend_check::{self, BendFile, ClassRecord};
use torus_cull_lab::number::Num;
use torus_cull_lab::workload::bend_spec::{bore_ratio_ok, delta_phi_ok};
use torus_cull_lab::workload::spec::Workload;

/// The most rays per class.
const MAX_RAYS: usize = 10_000_000;

/// `torus-cull bend`'s arguments.
#[derive(clap::Args)]
pub struct BendArgs {
    /// Rays per (ν, Δφ, r_min/r_max) class, cycling through the kinds random, cut-away,
    /// pipe axis, hole, cap edge, bore tangent and spawned (1 ..= 10 000 000).
    #[arg(long, default_value_t = Whole(20_000))]
    rays: Whole,
    /// The seed every pose draws its bend and rays from.
    #[arg(long, default_value_t = Whole(20261128))]
    seed: Whole,
    /// ν = R/r_max of the classes, comma-separated (each 1 < ν <= 1000; with a bore
    /// ratio > 0, ν <= 1000·ratio, the bore's torus's own ν = ν/ratio at most 1000).
    #[arg(long, value_delimiter = ',', default_value = "4")]
    nu: Vec<f64>,
    /// The segments Δφ of the classes in radians, comma-separated (each 0 < Δφ <= 2π;
    /// default 2π, π, π/2, π/6).
    #[arg(long = "delta-phi", value_delimiter = ',', allow_hyphen_values = true)]
    delta_phi: Vec<f64>,
    /// r_min/r_max of the classes, comma-separated (each 0, or ν/1000 <= ratio <= 1 −
    /// 10⁻⁷·(ν + 1): the bore's torus's ν at most 1000, the wall r_max − r_min at least
    /// 10⁻⁷·(R + r_max), the thinnest tested; default 0, 0.5, 0.9).
    #[arg(long = "bore-ratio", value_delimiter = ',', allow_hyphen_values = true)]
    bore_ratio: Vec<f64>,
    /// A workload file (or `quick`/`default`) whose `bend` key names the classes and the
    /// rays per class, its `seed` the seed: instead of --nu, --delta-phi, --bore-ratio,
    /// --rays and --seed.
    #[arg(long, conflicts_with_all = ["nu", "delta_phi", "bore_ratio", "rays", "seed"])]
    workload: Option<PathBuf>,
    /// Worker threads (default: the available cores); the counts do not depend on it.
    #[arg(long)]
    threads: Option<Whole>,
    /// Results JSON (default: results/<short commit>[-dirty]-bend.json). Its directory
    /// must exist.
    #[arg(long)]
    out: Option<PathBuf>,
    /// Skip the SVG charts (capture and rejection rate per cull and per wedge + cull
    /// against Δφ, one pair per r_min/r_max and ν), otherwise written next to the JSON as
    /// `<stem>-*.svg`.
    #[arg(long)]
    no_plots: bool,
}

/// Runs `bend`. Exit 1 when a cull rejected a hit of the oracle, or the exact
/// intersection missed, invented or misplaced a hit.
pub fn run(args: BendArgs) -> CliResult {
    let (classes, rays, seed) = match &args.workload {
        Some(file) => {
            let workload = Workload::open(file)?;
            let spec = workload.bend.ok_or_else(|| {
                format!(
                    "--workload {}: no `bend` key (the classes: nu, delta_phi, bore_ratio, rays)",
                    file.display()
                )
            })?;
            let classes = bend_check::classes(&spec.nu, &spec.delta_phi, &spec.bore_ratio);
            for &class in &classes {
                bend_check::refuse_class(class, ("bend.nu", "bend.delta_phi", "bend.bore_ratio"))
                    .map_err(|e| format!("--workload {}: {e}", file.display()))?;
            }
            let rays = i128::try_from(spec.rays).map_or(Whole(i128::MAX), Whole);
            (classes, rays, workload.seed)
        }
        None => (flag_classes(&args)?, args.rays, args.seed.seed("--seed")?),
    };
    let rays = super::plot::check_rays(rays, MAX_RAYS)?;
    let threads = super::threads::pick(args.threads)?;
    // Before the work, not after it.
    let path = super::plot::check_file_out(args.out, "-bend", args.no_plots)?;
    let mut file = BendFile::new(&classes, rays, seed);
    let heartbeat = crate::console::Heartbeat::new(
        format!("bend: {} classes x {rays} rays", classes.len()),
        "poses",
    );
    let checked = bend_check::check(rays, seed, &classes, threads, &|done, all| {
        heartbeat.update(done as u64, all as u64);
    })?;
    out!("{}", bend_check::table(&checked.records))?;
    let failed: Vec<String> = checked
        .records
        .iter()
        .filter(|r| r.false_rejects() > 0 || r.exact.bad() > 0)
        .map(ClassRecord::label)
        .collect();
    for (class, why) in &checked.disagreements {
        eprintln!("disagreement in {class}:\n{why}\n");
    }
    file.classes = checked.records;
    super::plot::write_check_file(&path, &file)?;
    if !args.no_plots {
        super::plot::write_charts(&path, |dir, stem| {
            torus_cull_lab::plot::bend::plot_bend(&file, dir, stem)
        })?;
    }
    if !failed.is_empty() {
        eprintln!(
            "error: a false reject, or a missed, invented or misplaced hit of the exact \
             intersection, in: {}",
            failed.join(", ")
        );
        return Ok(ExitCode::from(1));
    }
    Ok(ExitCode::SUCCESS)
}

/// The classes of --nu, --delta-phi and --bore-ratio (their defaults where not given),
/// each value checked against its range.
fn flag_classes(args: &BendArgs) -> Result<Vec<(f64, f64, f64)>, String> {
    if let Some(nu) = args
        .nu
        .iter()
        .find(|nu| !(nu.is_finite() && **nu > 1.0 && **nu <= MAX_NU))
    {
        return Err(format!(
            "--nu {} is invalid (allowed: 1 < --nu <= {MAX_NU})",
            Num(*nu)
        ));
    }
    if let Some(d) = args.delta_phi.iter().find(|d| !delta_phi_ok(**d)) {
        return Err(format!(
            "--delta-phi {} is invalid (allowed: 0 < --delta-phi <= 2*pi = {TAU})",
            Num(*d)
        ));
    }
    if let Some(r) = args.bore_ratio.iter().find(|r| !bore_ratio_ok(**r)) {
        return Err(format!(
            "--bore-ratio {} is invalid (allowed: 0 <= --bore-ratio < 1)",
            Num(*r)
        ));
    }
    let or = |given: &[f64], default: &[f64]| {
        if given.is_empty() {
            default.to_vec()
        } else {
            given.to_vec()
        }
    };
    let classes = bend_check::classes(
        &args.nu,
        &or(&args.delta_phi, &bend_check::DELTAS),
        &or(&args.bore_ratio, &bend_check::RATIOS),
    );
    // Each class's bend is built before any work: a bore ratio the library refuses at
    // some ν (the bore's own ν above 1000, a wall below the thinnest tested) names both.
    for &class in &classes {
        bend_check::refuse_class(class, ("--nu", "--delta-phi", "--bore-ratio"))?;
    }
    Ok(classes)
}
