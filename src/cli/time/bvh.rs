//! `torus-cull time bvh`: the paired ratios inside the BVH
//! ([`torus_cull_lab::paired::bvh`]) on the workload's `bvh` scenes, written as the
//! `ratio` section of a results file (metrics `bvh_closest_ns`, `bvh_anyhit_ns`,
//! `bvh_bounce_ns`, `bvh_batched_ns`) that `compare` and `intervals` read like the others.

use super::args::BvhArgs;
use super::common::{
    check_run_seconds, check_seconds, out_path, parse_culls, pick_runs, save, time_suffix,
    timing_sizes,
};
use crate::console::out;
use std::process::ExitCode;
use torus_cull::Named;
use torus_cull::batch::Dispatch;
use torus_cull_lab::paired::bvh::{BvhTiming, FAMILY_SCENE, NEW_SCENE_NU, time_bvh, units_of};
use torus_cull_lab::results::{BvhSizes, Results};
use torus_cull_lab::scene::SceneKind;
use torus_cull_lab::workload::spec::Workload;

/// Camera rays per timed pass unless `--batch` says otherwise: enough that a torus sees
/// a few of them in the batched leaves, few enough for hundreds of rounds a run.
const DEFAULT_BVH_RAYS: usize = 1024;

/// `--runs` unless given: more runs than `time ring`'s 5, as the slow-state runs set
/// aside per batch leave 1 to 3 of 5 on a shared machine, and the t quantile of so few
/// is wide.
const DEFAULT_BVH_RUNS: u64 = 10;

/// Runs `torus-cull time bvh`.
pub(super) fn run(args: &BvhArgs) -> Result<ExitCode, Box<dyn std::error::Error>> {
    let common = &args.common;
    let workload = Workload::open(&common.workload)?;
    let spec = workload.bvh.clone().ok_or_else(|| {
        format!(
            "time bvh: workload {} has no `bvh` key (its scenes)",
            common.workload.display()
        )
    })?;
    let culls = parse_culls(&args.culls)?;
    // Any valid ν (Scene::build checks it), by default the workload's.
    let nus = if args.nu.is_empty() {
        spec.nu.clone()
    } else {
        args.nu.clone()
    };
    check_seconds(common.seconds)?;
    let runs = pick_runs(args.runs, DEFAULT_BVH_RUNS)?;
    check_run_seconds(runs, common.seconds)?;
    let rays = match common.batch {
        None => DEFAULT_BVH_RAYS,
        Some(b) => b.within(
            "--batch",
            (super::common::MIN_BATCH, usize::MAX),
            " with time bvh",
        )?,
    };
    let path = out_path(common, &time_suffix(&workload.name, "bvh"), false)?;
    let dispatch = Dispatch::from_env()?;
    let timing = BvhTiming {
        units: units_of(&spec.scenes, &nus),
        tori: spec.tori,
        seed: workload.seed,
        culls,
        rays,
        seconds: common.seconds,
        runs: runs as usize,
        dispatch,
        family: Some(NEW_SCENE_NU),
    };
    eprintln!(
        "time bvh: {} scene x nu, {} tori, {rays} camera rays a pass, {runs} runs in {:.0} s",
        timing.units.len(),
        spec.tori,
        common.seconds
    );
    // A line every 5 s from the start, building the scenes included.
    let heartbeat = crate::console::Heartbeat::new("time bvh".to_string(), "visits");
    let ticker = crate::console::Ticker::start(heartbeat, 0);
    let records = time_bvh(&timing, &mut |done, all| {
        ticker.set_of(done as u64, all as u64);
    })?;
    drop(ticker);
    let mut results = Results::new(&workload, "time");
    results.ratio = records;
    results.meta.threads = Some(1);
    let mut sizes = timing_sizes(rays, &nus);
    sizes.bvh = Some(BvhSizes {
        scenes: SceneKind::ALL
            .iter()
            .map(|s| s.to_string())
            .chain([FAMILY_SCENE.to_string()])
            .collect(),
        nu: nus,
        tori: spec.tori as u64,
        image: 0,
        random_rays: 0,
    });
    results.meta.sizes = Some(sizes);
    results.meta.isa = Some(dispatch.isa().name().to_string());
    out!("{}", torus_cull_lab::report::ratio_tables(&results))?;
    save(&results, &path, common)?;
    Ok(ExitCode::SUCCESS)
}
