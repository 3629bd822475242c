//! `torus-cull time ring` (a bare `time`) and `time secondary`: paired, interleaved
//! timing ratios of the culls on the ring torus, on the workload's rays or on one diffuse
//! bounce spawned from each of their hits, written as the `ratio` section of a results
//! file. Several runs go to worker processes ([`super::workers`]).

use super::args::RingArgs;
use super::common::{
    MIN_BATCH, MIN_RUN_SECONDS, Picked, check_run_seconds, out_path, pick_batch, pick_runs, picked,
    save, time_suffix, timing_sizes,
};
use super::workers::{WorkerPlan, time_in_workers};
use crate::console::out;
use indicatif::{ProgressBar, ProgressStyle};
use std::process::ExitCode;
use torus_cull::batch::Dispatch;
use torus_cull::{CullKind, Named};
use torus_cull_lab::paired::sweep::{PairedOptions, time_units};
use torus_cull_lab::paired::{Unit, combine_runs};
use torus_cull_lab::results::{RatioRecord, Results};
use torus_cull_lab::workload::spec::Workload;
use torus_cull_lab::workload::{Batch, generate};

/// `--runs` unless given.
const DEFAULT_RUNS: u64 = 5;

/// Runs `time ring` (`secondary` false) or `time secondary`.
pub(super) fn run(
    args: &RingArgs,
    secondary: bool,
) -> Result<ExitCode, Box<dyn std::error::Error>> {
    let common = &args.common;
    let Picked {
        workload,
        culls,
        nus,
    } = picked(common, &args.pick)?;
    let batch = pick_batch(common.batch, &workload, &common.workload)?;
    let kind = if secondary { "secondary" } else { "" };
    let path = out_path(
        common,
        &time_suffix(&workload.name, kind),
        args.worker_run.is_some(),
    )?;
    // TORUS_CULL_ISA is checked in either mode: a typo must not pass silently because
    // only `--mode both` uses it.
    let dispatch = Dispatch::from_env()?;
    let mut options = PairedOptions::total(common.seconds, batch);
    if args
        .mode
        .modes()
        .contains(&torus_cull_lab::precision::Mode::Batch)
    {
        options.batch_isa = Some(dispatch.isa());
        if let Some(note) = no_batch_form_note(&culls) {
            eprintln!("{note}");
        }
    }
    // Drawn here, before any worker starts, so that a workload without a batch to time
    // fails at once; a worker says nothing of what the parent has said.
    let units = units(&workload, &nus, batch, secondary, args.worker_run.is_some())?;
    if let Some(run) = args.worker_run {
        // A worker: its records only, for the parent to combine.
        options.run = run;
        let records = time_with_progress(&workload.name, &units, &culls, &options, secondary)?;
        ratio_results(&workload, records, &nus, &options).save(&path)?;
        return Ok(ExitCode::SUCCESS);
    }
    // Unless asked for, as many runs as `--seconds` allows, up to the default.
    let runs = pick_runs(
        args.runs,
        ((common.seconds / MIN_RUN_SECONDS).floor() as u64).clamp(1, DEFAULT_RUNS),
    )?;
    check_run_seconds(runs, common.seconds)?;
    let records = if runs == 1 {
        time_with_progress(&workload.name, &units, &culls, &options, secondary)?
    } else {
        let plan = WorkerPlan {
            subcommand: if secondary { "secondary" } else { "ring" },
            workload: &common.workload,
            cases: &args.pick.cases,
            culls: &culls,
            nus: &nus,
            seconds: common.seconds / runs as f64,
            batch,
            mode: args.mode,
        };
        combine_runs(&time_in_workers(&plan, runs)?).map_err(|e| format!("--runs: {e}"))?
    };
    let results = ratio_results(&workload, records, &nus, &options);
    out!("{}", torus_cull_lab::report::ratio_tables(&results))?;
    save(&results, &path, common)?;
    Ok(ExitCode::SUCCESS)
}

/// With `--mode both`, what the batch tables will lack and why: the culls asked for with
/// no batch form (`discriminant_f64`, whose point is the scalar f64 discriminant) are timed
/// one ray at a time only. `None` when every cull asked for has a batch form.
fn no_batch_form_note(culls: &[CullKind]) -> Option<String> {
    let names = |batched: bool| -> Vec<&str> {
        culls
            .iter()
            .filter(|c| c.batched().is_some() == batched)
            .map(|c| c.name())
            .collect()
    };
    let (scalar_only, batched) = (names(false), names(true));
    if scalar_only.is_empty() {
        return None;
    }
    let rest = if batched.is_empty() {
        ", so no batch table is printed (no cull asked for has a batch form)".to_string()
    } else {
        format!("; the batch tables cover {}", batched.join(", "))
    };
    Some(format!(
        "note: --mode both: {} has no batch form and is timed one ray at a time only{rest}",
        scalar_only.join(", ")
    ))
}

/// The batches timed: every case × ν of `nus`, or with `secondary` the bounces of each
/// one's hits ([`torus_cull_lab::workload::secondary::bounces`]), a batch with too few
/// of them left out with a note (unless `quiet`).
fn units(
    workload: &Workload,
    nus: &[f64],
    batch: usize,
    secondary: bool,
    quiet: bool,
) -> Result<Vec<Batch>, Box<dyn std::error::Error>> {
    use torus_cull_lab::workload::secondary::bounces;
    let mut batches = Vec::new();
    for &case in &workload.cases {
        for &nu in nus {
            let primary = generate(case, nu, batch, workload.seed, workload.pose)?;
            if !secondary {
                batches.push(primary);
                continue;
            }
            let bounced = bounces(&primary);
            if bounced.rays.len() < MIN_BATCH {
                // The hole case's rays pass through the hole: no hits, no bounces.
                if quiet {
                    continue;
                }
                eprintln!(
                    "note: time secondary: {} of {} rays of {} at nu = {nu} hit the torus, \
                     too few to time (allowed: >= {MIN_BATCH}): skipped",
                    bounced.rays.len(),
                    primary.rays.len(),
                    case.name()
                );
                continue;
            }
            batches.push(bounced);
        }
    }
    if batches.is_empty() {
        return Err("time secondary: no case of the workload has rays that hit the torus".into());
    }
    Ok(batches)
}

/// The paired ratios of `batches`, with a progress bar (or, off a terminal, a line at
/// least every 5 s) in visits; with `secondary`, the records' case renamed
/// `<case>_bounce`.
fn time_with_progress(
    workload: &str,
    batches: &[Batch],
    culls: &[CullKind],
    options: &PairedOptions,
    secondary: bool,
) -> Result<Vec<RatioRecord>, Box<dyn std::error::Error>> {
    let bar = ProgressBar::new(0).with_style(
        ProgressStyle::with_template("{msg} [{bar:40}] {pos}/{len} visits ({eta})")
            .expect("valid template")
            .progress_chars("=> "),
    );
    let what = if secondary {
        "bounce batches"
    } else {
        "case x nu"
    };
    let message = format!(
        "{workload}: {} {what}, {} rays each",
        batches.len(),
        options.batch
    );
    bar.set_message(message.clone());
    let heartbeat = crate::console::Heartbeat::new(format!("time {message}"), "visits");
    let units: Vec<Unit<'_>> = batches.iter().map(Unit::of).collect();
    let mut records = time_units(&units, culls, options, &mut |done, all| {
        bar.set_length(all as u64);
        bar.set_position(done as u64);
        heartbeat.update(done as u64, all as u64);
    })?;
    bar.finish_and_clear();
    if secondary {
        use torus_cull_lab::workload::secondary::BOUNCE_SUFFIX;
        for r in &mut records {
            r.case.push_str(BOUNCE_SUFFIX);
        }
    }
    Ok(records)
}

/// The results file of a CPU timing: `records` as its `ratio` section.
fn ratio_results(
    workload: &Workload,
    records: Vec<RatioRecord>,
    nus: &[f64],
    options: &PairedOptions,
) -> Results {
    let mut results = Results::new(workload, "time");
    results.ratio = records;
    // The paired timings run on one thread.
    results.meta.threads = Some(1);
    results.meta.sizes = Some(timing_sizes(options.batch, nus));
    results.meta.isa = options.batch_isa.map(|i| i.name().to_string());
    results
}
