//! `torus-cull f32-check`: the certified f32 intersection, the whole f32 path and the
//! plain f32 closed form of shaders, counted against the oracle family by family.

use super::CliResult;
use crate::console::{out, outln};
use crate::whole::Whole;
use indicatif::{ProgressBar, ProgressStyle};
use std::path::PathBuf;
use std::process::ExitCode;
use torus_cull_lab::f32_check::{self, CheckFile, families};

/// The most rays per family.
const MAX_RAYS: usize = 1_000_000;

/// The most timing rounds per family: 1000 rounds of 20 000 rays are already hours.
const MAX_ROUNDS: u32 = 1000;

/// `torus-cull f32-check`'s arguments.
#[derive(clap::Args)]
pub struct F32CheckArgs {
    /// Rays per family.
    #[arg(long, default_value_t = Whole(20_000))]
    rays: Whole,
    /// The seed every family draws its rays from.
    #[arg(long, default_value_t = Whole(20261121))]
    seed: Whole,
    /// Results JSON (default: results/<short commit>[-dirty]-f32-check.json). Its
    /// directory must exist.
    #[arg(long)]
    out: Option<PathBuf>,
    /// Worker threads for the oracle's labels, 1 ..= 1024 (default: available cores); the timings
    /// run on one.
    #[arg(long)]
    threads: Option<Whole>,
    /// Timing rounds per family, 0 ..= 1000 (0: no timings).
    #[arg(long, default_value_t = Whole(5))]
    rounds: Whole,
    /// Skip the SVG plots (by default escalation, wrong answers, t error and ns per ray
    /// per family, next to the results file).
    #[arg(long)]
    no_plots: bool,
    /// Only the families whose name contains this text (e.g. `spawned` for the secondary
    /// rays from a surface point); by default every family.
    #[arg(long)]
    family: Option<String>,
}

/// Runs `f32-check`. Exit 1 when ours (the certified verdict or the whole f32 path)
/// missed a hit, answered a miss with a `t` or put a `t` outside the tolerance: the
/// peer's speckles are what it measures, not a failure.
pub fn run(args: F32CheckArgs) -> CliResult {
    let rays = super::plot::check_rays(args.rays, MAX_RAYS)?;
    let rounds: u32 = args.rounds.within("--rounds", (0, MAX_ROUNDS), "")?;
    let seed = args.seed.seed("--seed")?;
    let threads = crate::threads::pick(args.threads)?;
    // Before the work, not after it.
    let path = crate::plot::check_file_out(args.out, "-f32-check", args.no_plots)?;

    let mut families = families::all();
    if let Some(part) = &args.family {
        families.retain(|f| f.name.contains(part.as_str()));
        if families.is_empty() {
            return Err(format!("--family {part}: no family's name contains it").into());
        }
    }
    let bar = ProgressBar::new(families.len() as u64).with_style(
        ProgressStyle::with_template("{msg} [{bar:40}] {pos}/{len} families ({eta})")
            .expect("valid template")
            .progress_chars("=> "),
    );
    let message = format!("f32-check: {} families x {} rays", families.len(), rays);
    bar.set_message(message.clone());
    let heartbeat = crate::console::Heartbeat::new(message, "families");
    heartbeat.update(0, families.len() as u64);
    let records = f32_check::check(&families, rays, seed, threads, rounds, &|done, all| {
        bar.set_position(done as u64);
        heartbeat.update(done as u64, all as u64);
    })?;
    bar.finish_and_clear();

    out!("{}", f32_check::table(&records))?;
    let failed: Vec<String> = records
        .iter()
        .filter(|r| r.ours_failed())
        .map(|r| r.family.clone())
        .collect();
    let file = CheckFile::new(records, rays, seed, threads);
    super::plot::write_check_file(&path, &file)?;
    if !args.no_plots {
        let (dir, stem) = super::plot::plot_place(&path, "f32-check");
        let written = f32_check::plot::plot_check(&file, &dir, &stem)?;
        outln!(
            "wrote {} plots to {}/{stem}-*.svg",
            written.len(),
            dir.display()
        )?;
    }
    if !failed.is_empty() {
        eprintln!(
            "error: the f32 path missed a hit, reported a spurious one or a t outside the \
             tolerance in: {}",
            failed.join(", ")
        );
        return Ok(ExitCode::from(1));
    }
    Ok(ExitCode::SUCCESS)
}
