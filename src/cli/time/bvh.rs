//! `torus-cull time --bvh`: the paired ratios inside the BVH
//! ([`torus_cull_lab::paired::bvh`]) on the workload's `bvh` scenes, written as the
//! `ratio` section of a results file (metrics `bvh_closest_ns`, `bvh_anyhit_ns`,
//! `bvh_bounce_ns`, `bvh_batched_ns`) that `compare` and `intervals` read like the others.

use super::{TimeArgs, check_runs, check_seconds, check_writable, parse_culls, timing_sizes};
use crate::console::{out, outln};
use std::path::Path;
use std::process::ExitCode;
use torus_cull::Named;
use torus_cull::batch::Dispatch;
use torus_cull_lab::paired::bvh::{BvhTiming, FAMILY_SCENE, NEW_SCENE_NU, time_bvh, units_of};
use torus_cull_lab::results::{self, BvhSizes, Results};
use torus_cull_lab::scene::SceneKind;
use torus_cull_lab::workload::spec::Workload;

/// Camera rays per timed pass unless `--batch` says otherwise: enough that a torus sees
/// a few of them in the batched leaves, few enough for hundreds of rounds a run.
const DEFAULT_BVH_RAYS: usize = 1024;

/// `--runs` unless given: more runs than `time`'s 5, as the slow-state runs set aside per
/// batch leave 1 to 3 of 5 on a shared machine, and the t quantile of so few is wide.
const DEFAULT_BVH_RUNS: u64 = 10;

/// Runs `torus-cull time --bvh`.
pub(super) fn run(args: &TimeArgs) -> Result<ExitCode, Box<dyn std::error::Error>> {
    for (given, flag) in [
        (args.secondary, "--secondary"),
        (args.finish, "--finish"),
        (args.device != super::Device::Cpu, "--device gpu"),
        (args.mode != super::Mode::Scalar, "--mode both"),
        (!args.cases.is_empty(), "--cases"),
        (args.worker_run.is_some(), "--worker-run"),
    ] {
        if given {
            return Err(format!(
                "--bvh times the workload's BVH scenes on the CPU: not with {flag}"
            )
            .into());
        }
    }
    let workload = Workload::open(&args.workload)?;
    let spec = workload.bvh.clone().ok_or_else(|| {
        format!(
            "--bvh: workload {} has no `bvh` key (its scenes)",
            args.workload.display()
        )
    })?;
    let culls = parse_culls(&args.culls)?;
    // Any valid ν (Scene::build checks it), by default the workload's.
    let nus = if args.nu.is_empty() {
        spec.nu.clone()
    } else {
        args.nu.clone()
    };
    check_seconds(args.seconds)?;
    let runs = match args.runs {
        Some(runs) => runs.within("--runs", (1, super::MAX_RUNS), "")?,
        None => DEFAULT_BVH_RUNS,
    };
    check_runs(runs, args.seconds)?;
    let rays = match args.batch {
        None => DEFAULT_BVH_RAYS,
        Some(b) => b.within("--batch", (16, usize::MAX), " with --bvh")?,
    };
    let path = match &args.out {
        Some(p) => p.clone(),
        None => {
            let suffix = if workload.name == "default" {
                "-bvh-time".to_string()
            } else {
                format!("-{}-bvh-time", workload.name)
            };
            let path = results::default_path(Path::new("results"), &suffix);
            torus_cull_lab::output::create_default_dir(&path)
                .map_err(|e| format!("--out {}: {e}", path.display()))?;
            path
        }
    };
    check_writable(&path)?;
    let dispatch = Dispatch::from_env()?;
    let timing = BvhTiming {
        units: units_of(&spec.scenes, &nus),
        tori: spec.tori,
        seed: workload.seed,
        culls,
        rays,
        seconds: args.seconds,
        runs: runs as usize,
        dispatch,
        family: Some(NEW_SCENE_NU),
    };
    eprintln!(
        "time --bvh: {} scene x nu, {} tori, {rays} camera rays a pass, {runs} runs in {:.0} s",
        timing.units.len(),
        spec.tori,
        args.seconds
    );
    let heartbeat = crate::console::Heartbeat::new("time --bvh".to_string(), "visits");
    let records = time_bvh(&timing, &mut |done, all| {
        heartbeat.update(done as u64, all as u64)
    })?;
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
    results.save(&path)?;
    outln!("wrote {}", path.display())?;
    Ok(ExitCode::SUCCESS)
}
