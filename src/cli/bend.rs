//! `torus-cull bend`: every cull, alone and behind the wedge, and the exact intersection of
//! the pipe bend against the bend oracle, class by class (`torus_cull_lab::bend_check`).

use super::CliResult;
use crate::console::out;
use std::path::PathBuf;
use std::process::ExitCode;
use torus_cull_lab::bend_check::{self, BendFile, ClassRecord};

/// The most rays per class.
const MAX_RAYS: usize = 10_000_000;

/// `torus-cull bend`'s arguments.
#[derive(clap::Args)]
pub struct BendArgs {
    /// Rays per (ν, Δφ, r_min/r_max) class, cycling through the kinds random, cut-away,
    /// pipe axis, hole, cap edge, bore tangent and spawned (1 ..= 10 000 000).
    #[arg(long, default_value_t = 20_000)]
    rays: usize,
    /// The seed every pose draws its bend and rays from.
    #[arg(long, default_value_t = 20261128)]
    seed: u64,
    /// ν = R/r_max of the classes, comma-separated (each finite, > 1).
    #[arg(long, value_delimiter = ',', default_value = "4")]
    nu: Vec<f64>,
    /// Worker threads (default: the available cores); the counts do not depend on it.
    #[arg(long)]
    threads: Option<usize>,
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
    super::plot::check_rays(args.rays, MAX_RAYS)?;
    if let Some(nu) = args.nu.iter().find(|nu| !(nu.is_finite() && **nu > 1.0)) {
        return Err(format!("--nu {nu} is invalid (allowed: finite, > 1)").into());
    }
    let threads = super::threads::pick(args.threads)?;
    // Before the work, not after it.
    let path = super::plot::check_file_out(args.out, "-bend", args.no_plots)?;
    let classes = bend_check::classes(&args.nu);
    let mut file = BendFile::new(&classes, args.rays, args.seed);
    let classes = classes.len();
    let heartbeat = crate::console::Heartbeat::new(
        format!("bend: {classes} classes x {} rays", args.rays),
        "poses",
    );
    let checked = bend_check::check(args.rays, args.seed, &args.nu, threads, &|done, all| {
        heartbeat.update(done as u64, all as u64);
    });
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
