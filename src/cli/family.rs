//! `torus-cull family`: every cull and the exact intersection of the torus family against
//! the oracle, member class by member class (`torus_cull_lab::family_check`).

use super::CliResult;
use crate::console::out;
use crate::whole::Whole;
use std::path::PathBuf;
use std::process::ExitCode;
use torus_cull_lab::family_check::{self, FamilyFile};

/// The most rays per member.
const MAX_RAYS: usize = 1_000_000;

/// `torus-cull family`'s arguments.
#[derive(clap::Args)]
pub struct FamilyArgs {
    /// Rays per member class, cycling through the kinds uniform, grazing, axis/hole and
    /// spawned (1 ..= 1 000 000).
    #[arg(long, default_value_t = Whole(20_000))]
    rays: Whole,
    /// The seed every member draws its pose and rays from.
    #[arg(long, default_value_t = Whole(20261127))]
    seed: Whole,
    /// Results JSON (default: results/<short commit>[-dirty]-family.json). Its directory
    /// must exist.
    #[arg(long)]
    out: Option<PathBuf>,
    /// Skip the SVG charts (capture and rejection rate per cull against ν, one pair per
    /// aspect b/a), otherwise written next to the JSON as `<stem>-b<b/a>-*.svg`.
    #[arg(long)]
    no_plots: bool,
}

/// Runs `family`. Exit 1 when a cull rejected a hit of the oracle, or the exact
/// intersection missed or invented a hit.
pub fn run(args: FamilyArgs) -> CliResult {
    let rays = super::plot::check_rays(args.rays, MAX_RAYS)?;
    let seed = args.seed.seed("--seed")?;
    // Before the work, not after it.
    let path = super::plot::check_file_out(args.out, "-family", args.no_plots)?;
    let members = family_check::members().len();
    let heartbeat = crate::console::Heartbeat::new(
        format!("family: {members} members x {} rays", rays),
        "members",
    );
    heartbeat.update(0, members as u64);
    let records = family_check::check(rays, seed, &|done, all| {
        heartbeat.update(done as u64, all as u64);
    })?;
    out!("{}", family_check::table(&records))?;
    let failed: Vec<String> = records
        .iter()
        .filter(|r| r.false_rejects() > 0 || r.exact_wrong() > 0)
        .map(family_check::MemberRecord::label)
        .collect();
    let file = FamilyFile::new(records, rays, seed);
    super::plot::write_check_file(&path, &file)?;
    if !args.no_plots {
        super::plot::write_charts(&path, |dir, stem| {
            torus_cull_lab::plot::plot_family(&file, dir, stem)
        })?;
    }
    if !failed.is_empty() {
        eprintln!(
            "error: a false reject, or a missed or invented hit of the exact intersection, in: {}",
            failed.join(", ")
        );
        return Ok(ExitCode::from(1));
    }
    Ok(ExitCode::SUCCESS)
}
