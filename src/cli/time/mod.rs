//! `torus-cull time`: paired, interleaved timing ratios of the culls on a workload, in
//! about half a minute, written as the `ratio` section of a results file.

mod bend;
mod family;
pub(crate) mod gpu_bvh;
pub(crate) mod gpu_submissions;
mod shapes;

use crate::console::{out, outln};
use crate::whole::Whole;
use indicatif::{ProgressBar, ProgressStyle};
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use torus_cull::CullKind;
use torus_cull::Named;
use torus_cull::batch::Dispatch;
use torus_cull_lab::measure::CountedCull;
use torus_cull_lab::number::Num;
use torus_cull_lab::paired::runs::combine_runs;
use torus_cull_lab::paired::sweep::{
    DEFAULT_BATCH, PairedError, PairedOptions, REFERENCES, time_workload,
};
use torus_cull_lab::results::{self, RatioRecord, Results};
use torus_cull_lab::workload::spec::{self, Workload};

/// The longest `--seconds` accepted: an hour.
const MAX_SECONDS: f64 = 3600.0;

/// The smallest batch: below it a timing is mostly the clock.
const MIN_BATCH: usize = 16;

/// `torus-cull time`'s arguments.
#[derive(clap::Args)]
pub struct TimeArgs {
    /// Workload: `quick` or `default` (built into the binary), or a workload file.
    #[arg(long, default_value = "quick")]
    workload: PathBuf,
    /// Culls to time, comma-separated (default: all ten timed culls: none, sphere, aabb,
    /// cychosz, thick_cylinder, skala, ellipsoid, quadric, discriminant,
    /// discriminant_f64). The references cychosz and none are timed in any case.
    #[arg(long, value_delimiter = ',')]
    culls: Vec<String>,
    /// ν values to time, comma-separated, each one of the workload's (default: all).
    #[arg(long, value_delimiter = ',')]
    nu: Vec<f64>,
    /// Cases to time, comma-separated, each one of the workload's (default: all), in the
    /// workload's order.
    #[arg(long, value_delimiter = ',')]
    cases: Vec<String>,
    /// With `--device gpu` (on an adapter with `SHADER_F64`): also time the f64 finish
    /// pass after the kernel, per case × ν × cull, as the library runs it
    /// (`intersect_finished`): its device time per ray of the batch and per escalated
    /// ray, as estimates `gpu_finish_ns-<case>/<cull>/<ν>` and
    /// `gpu_finish_per_escalated_ns-…`, in the same rounds as the kernel.
    #[arg(long)]
    finish: bool,
    /// With `--device gpu`: threads per workgroup of the kernel (32, 64, 128 or 256; the
    /// answers are the same, only the speed may differ). The results' device names it.
    #[arg(long, default_value_t = Whole(64))]
    workgroup: Whole,
    /// Total measuring time in seconds, shared evenly by every case × ν.
    #[arg(long, default_value_t = 30.0)]
    seconds: f64,
    /// Rays per batch, timed by every contender in every round (default: 1024, or the
    /// workload's rays if fewer).
    #[arg(long)]
    batch: Option<Whole>,
    /// Results JSON (default: results/<short commit>[-dirty]-<workload>-time.json, or
    /// …-time.json for the workload named `default`; …-secondary-time.json with
    /// --secondary and …-gpu-time.json with --device gpu, so that neither replaces the
    /// primary CPU timing). Its directory must exist.
    #[arg(long)]
    out: Option<PathBuf>,
    /// `scalar`: one ray at a time (`total_ns`, `cull_ns`); `both`: also the batch mode
    /// (`batch_total_ns`, `batch_cull_ns`: SIMD cull and wavefront; `batch_f32_total_ns`
    /// and `batch_f32_uncertified_ns`: the certified f32 wavefront and the same without
    /// its proof, also against the cull's f64 wavefront, with escalation rates) in the
    /// same rounds, for the culls with a batch form, at the instruction set
    /// `TORUS_CULL_ISA` names (default: the best this CPU has).
    #[arg(long, value_enum, default_value_t = Mode::Scalar)]
    mode: Mode,
    /// `cpu`: the paired ratios above. `gpu` (a binary built with `--features gpu`): the
    /// WGSL kernel (cull and certified f32 intersection) with the rays resident on the
    /// device, per case × ν and every cull with a batch form: ns per ray from the device's
    /// timestamps, each cull's paired ratio to none and cychosz, and its time over a copy
    /// kernel's (the bandwidth floor), `--batch` rays (default 2 097 152, drawn from the
    /// workload's generators at that count); upload and read-back are timed apart.
    /// Written as `ratio` (metric `gpu_kernel_ns`, device `gpu`) and `estimates`, with the
    /// adapter in `meta.device`. A software adapter (device type Cpu, e.g. Mesa's
    /// lavapipe) is timed too, but as a CPU proxy, never as GPU speed.
    #[arg(long, value_enum, default_value_t = Device::Cpu)]
    device: Device,
    /// Time secondary rays instead of the workload's: for each batch, one diffuse bounce
    /// (cosine-weighted) spawned from every hit with `Torus::spawn`, so every ray starts
    /// on the surface (`Ray::from_surface`). The records' case is `<case>_bounce`. With
    /// `--mode both` this pairs the certified f32 wavefront against the f64 one on the
    /// rays a path tracer sends after its primary rays. CPU only.
    #[arg(long)]
    secondary: bool,
    /// Time the torus family instead of the workload's cases (`torus_cull::family`,
    /// docs/family.md): on uniform rays (`--batch`, default 1024), the exact intersection
    /// of elliptical tubes (ν = 4, b/a = 1/4 … 4), the horn and two spindles over the
    /// circular torus (R, a), and each cull's total over `cychosz`'s on each member, three
    /// runs each with within- and between-run intervals; written to
    /// `results/<commit>-family-time.json` (or `--out`). CPU, scalar.
    #[arg(long)]
    family: bool,
    /// Time pipe bends instead (`torus_cull::bend`, docs/bend.md): on uniform rays at the
    /// outer torus's box, each cull and each cull with the segment's wedge against
    /// `cychosz` and against no cull, at Δφ = 2π … π/6 and r_min/r_max = 0, 0.5, 0.9;
    /// three runs each; written to `results/<commit>-bend-time.json` (or `--out`).
    #[arg(long, conflicts_with = "family")]
    bend: bool,
    /// Skip the SVG plots (by default the paired ratios, or with `--device gpu` the ns
    /// per ray, are drawn against ν with their intervals, next to the results file).
    #[arg(long)]
    no_plots: bool,
    /// Independent runs sharing `--seconds` (default 5, fewer where `--seconds` is under
    /// 1.25, each run having at least 0.25 s; CPU only; runs in a slow state of the machine
    /// are set aside, see `runs_set_aside`): each in a worker
    /// process of its own (a fresh copy of this binary: its own code and data placement,
    /// heap, and ray buffers shuffled and laid out afresh). Every ratio then carries,
    /// besides the within-run interval of its rounds, a between-run interval over the
    /// runs' ratios (`runs`, `run_ratios`, `ratio_ci_between`), which the console tables
    /// show and `compare` judges by. More runs give a narrower between-run interval. 1:
    /// one run in this process, with the within-run interval only.
    #[arg(long)]
    runs: Option<Whole>,
    /// Time inside the BVH instead (the workload's `bvh` scenes, `--nu` any ν, default
    /// the workload's; the scenes it lacks at ν = 4): each cull at the leaves over `none` and `cychosz`, per ray, for
    /// closest-hit camera rays, any-hit shadow rays, closest-hit diffuse bounce rays from
    /// the camera hits and batched leaves, `--runs` runs (default 10) in this process;
    /// metrics `bvh_closest_ns`, `bvh_anyhit_ns`, `bvh_bounce_ns`, `bvh_batched_ns`.
    /// Default file …-bvh-time.json.
    #[arg(long)]
    bvh: bool,
    /// Internal: this process is worker run K of a `--runs` timing (writes its records
    /// to `--out`, prints no tables).
    #[arg(long, hide = true)]
    worker_run: Option<u64>,
}

/// `--runs` unless given.
const DEFAULT_RUNS: u64 = 5;

/// The most `--runs`.
const MAX_RUNS: u64 = 100;

/// The least time a run may have: below it a run is mostly its warm-up and its process
/// start.
const MIN_RUN_SECONDS: f64 = 0.25;

/// Where `torus-cull time` measures.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
enum Device {
    /// The culls on this CPU, as paired ratios.
    Cpu,
    /// The WGSL kernel on the first GPU adapter wgpu finds.
    Gpu,
}

/// Which modes `torus-cull time` measures.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
enum Mode {
    /// One ray at a time.
    Scalar,
    /// One ray at a time and batch mode, in the same rounds.
    Both,
}

/// Runs `torus-cull time`.
pub fn run(args: TimeArgs) -> Result<ExitCode, Box<dyn std::error::Error>> {
    // Before any mode returns: a GPU flag on a CPU timing is refused, never ignored.
    if args.device != Device::Gpu && args.workgroup != Whole(64) {
        return Err("--workgroup sizes the GPU kernel: only with --device gpu".into());
    }
    for (given, flag) in [(args.family, "--family"), (args.bend, "--bend")] {
        if given && (args.device == Device::Gpu || args.finish) {
            return Err(
                format!("{flag} times the CPU's paths: not with --device gpu or --finish").into(),
            );
        }
    }
    if args.bvh {
        return bvh::run(&args);
    }
    let mut workload = Workload::open(&args.workload)?;
    pick_cases(&args.cases, &mut workload, &args.workload)?;
    let culls = parse_culls(&args.culls)?;
    let nus = pick_nus(&args.nu, &workload, &args.workload)?;
    check_seconds(args.seconds)?;
    if args.family || args.bend {
        let timed = if args.family {
            &family::TIMED
        } else {
            &bend::TIMED
        };
        let batch = pick_batch(args.batch, &workload, &args.workload)?;
        return shapes::run(timed, &workload, args.seconds, batch, args.out.as_deref());
    }
    let batch = match args.device {
        Device::Cpu => pick_batch(args.batch, &workload, &args.workload)?,
        Device::Gpu => pick_gpu_batch(args.batch)?,
    };
    let path = out_path(args.out, &workload, args.device, args.secondary)?;
    check_writable(&path)?;
    if !args.no_plots && args.worker_run.is_none() {
        crate::plot::check_plot_paths(&path)?;
    }
    if spec::built_in(&args.workload).is_none() {
        torus_cull_lab::output::check_not_input(
            ("--out", &path),
            &[("--workload", &args.workload)],
        )?;
    }

    if args.device == Device::Gpu {
        if args.secondary {
            return Err("--secondary times the CPU's paths: not with --device gpu".into());
        }
        if args.runs.is_some() {
            return Err("--runs applies to the CPU's paired ratios: not with --device gpu".into());
        }
        if args.mode == Mode::Both {
            return Err("--mode both times the CPU's batch mode: not with --device gpu".into());
        }
        let code = gpu::run(
            &workload,
            &nus,
            &culls,
            args.seconds,
            batch,
            GpuOptions {
                finish: args.finish,
                workgroup: args.workgroup.within(
                    "--workgroup",
                    (32, 256),
                    "; 32, 64, 128 or 256",
                )?,
            },
            &path,
        )?;
        if !args.no_plots {
            // Drawn from the file as written: its estimates, ns per ray against ν.
            crate::plot::write_plots(&Results::load(&path)?, &path)?;
        }
        return Ok(code);
    }

    if args.finish {
        return Err("--finish times the GPU's f64 finish pass: only with --device gpu".into());
    }
    // TORUS_CULL_ISA is checked in either mode: a typo must not pass silently because
    // only `--mode both` uses it.
    let dispatch = Dispatch::from_env()?;
    let mut options = PairedOptions::total(args.seconds, batch);
    if args.mode == Mode::Both {
        options.batch_isa = Some(dispatch.isa());
        if let Some(note) = no_batch_form_note(&culls) {
            eprintln!("{note}");
        }
    }
    let time_once = |options: &PairedOptions| {
        if args.secondary {
            time_secondary(&workload, &nus, &culls, options)
        } else {
            Ok(time_with_progress(&workload, &nus, &culls, options)?)
        }
    };
    if let Some(run) = args.worker_run {
        // A worker: its records only, for the parent to combine.
        options.run = run;
        let records = time_once(&options)?;
        ratio_results(&workload, records, &nus, &options).save(&path)?;
        return Ok(ExitCode::SUCCESS);
    }
    // Unless asked for, as many runs as `--seconds` allows, up to the default.
    let runs = match args.runs {
        Some(runs) => runs.within("--runs", (1, MAX_RUNS), "")?,
        None => ((args.seconds / MIN_RUN_SECONDS).floor() as u64).clamp(1, DEFAULT_RUNS),
    };
    check_runs(runs, args.seconds)?;
    let records = if runs == 1 {
        time_once(&options)?
    } else {
        let plan = WorkerPlan {
            workload: &args.workload,
            cases: &args.cases,
            culls: &culls,
            nus: &nus,
            seconds: args.seconds / runs as f64,
            batch,
            mode: args.mode,
            secondary: args.secondary,
        };
        time_in_workers(&plan, runs)?
    };
    let results = ratio_results(&workload, records, &nus, &options);
    out!("{}", torus_cull_lab::report::ratio_tables(&results))?;
    results.save(&path)?;
    outln!("wrote {}", path.display())?;
    if !args.no_plots {
        crate::plot::write_plots(&results, &path)?;
    }
    Ok(ExitCode::SUCCESS)
}

/// With `--mode both`, what the batch tables will lack and why: the culls asked for with
/// no batch form (`discriminant_f64`, whose point is the scalar f64 discriminant) are timed
/// one ray at a time only. `None` when every cull asked for has a batch form.
fn no_batch_form_note(culls: &[CullKind]) -> Option<String> {
    let scalar_only: Vec<&str> = culls
        .iter()
        .filter(|c| c.batched().is_none())
        .map(|c| c.name())
        .collect();
    if scalar_only.is_empty() {
        return None;
    }
    let batched: Vec<&str> = culls
        .iter()
        .filter(|c| c.batched().is_some())
        .map(|c| c.name())
        .collect();
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

/// `--runs`: 1 to [`MAX_RUNS`], each with at least [`MIN_RUN_SECONDS`] of `--seconds`.
fn check_runs(runs: u64, seconds: f64) -> Result<(), String> {
    if !(1..=MAX_RUNS).contains(&runs) {
        return Err(format!(
            "--runs {runs} is invalid (allowed: 1 ..= {MAX_RUNS})"
        ));
    }
    if seconds / (runs as f64) < MIN_RUN_SECONDS {
        return Err(format!(
            "--seconds {} is too short for --runs {runs} (allowed: seconds >= \
             {MIN_RUN_SECONDS} x runs = {}): give more seconds or fewer runs",
            Num(seconds),
            MIN_RUN_SECONDS * runs as f64
        ));
    }
    Ok(())
}

/// What every worker of a `--runs` timing is told to time: the parent's arguments as it
/// parsed them, with its share of the seconds.
struct WorkerPlan<'a> {
    workload: &'a Path,
    cases: &'a [String],
    culls: &'a [CullKind],
    nus: &'a [f64],
    seconds: f64,
    batch: usize,
    mode: Mode,
    secondary: bool,
}

impl WorkerPlan<'_> {
    /// The command line of worker `run`, writing to `out`.
    fn args(&self, run: u64, out: &Path) -> Vec<std::ffi::OsString> {
        let mut args: Vec<std::ffi::OsString> = vec!["time".into(), "--workload".into()];
        args.push(self.workload.as_os_str().to_owned());
        let culls: Vec<&str> = self.culls.iter().map(|c| c.name()).collect();
        let nus: Vec<String> = self.nus.iter().map(f64::to_string).collect();
        for (flag, value) in [
            ("--culls", culls.join(",")),
            ("--nu", nus.join(",")),
            ("--seconds", self.seconds.to_string()),
            ("--batch", self.batch.to_string()),
            (
                "--mode",
                match self.mode {
                    Mode::Scalar => "scalar".into(),
                    Mode::Both => "both".into(),
                },
            ),
            ("--runs", "1".into()),
            ("--worker-run", run.to_string()),
        ] {
            args.push(flag.into());
            args.push(value.into());
        }
        if !self.cases.is_empty() {
            args.push("--cases".into());
            args.push(self.cases.join(",").into());
        }
        if self.secondary {
            args.push("--secondary".into());
        }
        args.push("--no-plots".into());
        args.push("--out".into());
        args.push(out.as_os_str().to_owned());
        args
    }
}

/// The paired ratios of `runs` independent runs, one worker process each (this binary
/// again, one after the other so that they never share the cores), combined by
/// [`combine_runs`]. A worker that fails fails the whole timing, with its exit status
/// (its own message is on stderr above): nothing is written.
fn time_in_workers(plan: &WorkerPlan<'_>, runs: u64) -> Result<Vec<RatioRecord>, String> {
    let exe = std::env::current_exe()
        .map_err(|e| format!("--runs {runs}: cannot find this binary to start workers: {e}"))?;
    let dir = tempfile::tempdir()
        .map_err(|e| format!("--runs {runs}: cannot make a directory for the workers: {e}"))?;
    let mut all = Vec::new();
    for run in 0..runs {
        let out = dir.path().join(format!("run-{run}.json"));
        eprintln!(
            "run {} of {runs}: {:.1} s in a worker process",
            run + 1,
            plan.seconds
        );
        let status = std::process::Command::new(&exe)
            .args(plan.args(run, &out))
            .stdout(std::process::Stdio::null())
            .status()
            .map_err(|e| format!("--runs: cannot start worker run {}: {e}", run + 1))?;
        if !status.success() {
            return Err(format!(
                "--runs: worker run {} of {runs} failed ({status}); no results written",
                run + 1
            ));
        }
        let results = Results::load(&out)
            .map_err(|e| format!("--runs: worker run {} wrote no usable file: {e}", run + 1))?;
        all.push(results.ratio);
    }
    combine_runs(&all).map_err(|e| format!("--runs: {e}"))
}

/// `--seconds`: positive, finite and at most [`MAX_SECONDS`].
fn check_seconds(seconds: f64) -> Result<(), String> {
    if !(seconds.is_finite() && seconds > 0.0 && seconds <= MAX_SECONDS) {
        return Err(format!(
            "--seconds {} is invalid (allowed: 0 < seconds <= {MAX_SECONDS})",
            Num(seconds)
        ));
    }
    Ok(())
}

/// `--batch`: at least [`MIN_BATCH`] and at most the workload's rays (`file` names it);
/// default [`DEFAULT_BATCH`], or the workload's rays if fewer.
fn pick_batch(asked: Option<Whole>, workload: &Workload, file: &Path) -> Result<usize, String> {
    let batch = match asked {
        None => DEFAULT_BATCH.min(workload.rays),
        Some(b) => b.within(
            "--batch",
            (MIN_BATCH, workload.rays),
            &format!(", the rays of workload {}", file.display()),
        )?,
    };
    // Only the default can fall short: the workload itself has too few rays.
    if batch < MIN_BATCH {
        return Err(format!(
            "workload {}: field `rays`: {} is too few to time (allowed: >= {MIN_BATCH})",
            file.display(),
            workload.rays
        ));
    }
    Ok(batch)
}

/// Rays per case × ν on the GPU by default: a GPU needs about this many in flight before
/// its time per ray stops falling (an H100 holds 132 multiprocessors × 2 048 threads).
/// Not a power of two: on an H100, 2²⁰ rays (and, for uniform rays, 2²¹ and 2²²) ran in a
/// slow state 3–5× slower than 2²⁰ ± 64 (docs/gpu.md, "Batch size on the H100").
const GPU_BATCH: usize = 2_000_000;

/// The most rays per case × ν on the GPU: 64 bytes each on the device, 2 GiB in all.
const MAX_GPU_BATCH: usize = 1 << 25;

/// `--batch` with `--device gpu`: drawn from the workload's generators at that count,
/// whatever the workload's `rays`.
fn pick_gpu_batch(asked: Option<Whole>) -> Result<usize, String> {
    match asked {
        None => Ok(GPU_BATCH),
        Some(b) => b.within("--batch", (MIN_BATCH, MAX_GPU_BATCH), " with --device gpu"),
    }
}

/// `--out`, or the default file under `results/` (its directory made if need be).
fn out_path(
    out: Option<PathBuf>,
    workload: &Workload,
    device: Device,
    secondary: bool,
) -> Result<PathBuf, String> {
    if let Some(path) = out {
        return Ok(path);
    }
    let path = results::default_path(
        Path::new("results"),
        &time_suffix(&workload.name, device, secondary),
    );
    torus_cull_lab::output::create_default_dir(&path)
        .map_err(|e| format!("--out {}: {e}", path.display()))?;
    Ok(path)
}

/// The paired ratios of every case × ν of `nus`, with a progress bar (or, off a
/// terminal, a heartbeat) in visits.
fn time_with_progress(
    workload: &Workload,
    nus: &[f64],
    culls: &[CullKind],
    options: &PairedOptions,
) -> Result<Vec<RatioRecord>, PairedError> {
    let units = workload.cases.len() * nus.len();
    let bar = ProgressBar::new(0).with_style(
        ProgressStyle::with_template("{msg} [{bar:40}] {pos}/{len} visits ({eta})")
            .expect("valid template")
            .progress_chars("=> "),
    );
    let message = format!(
        "{}: {units} case x nu, {} rays each",
        workload.name, options.batch
    );
    bar.set_message(message.clone());
    let heartbeat = crate::console::Heartbeat::new(format!("time {message}"), "visits");
    let records = time_workload(workload, nus, culls, options, &mut |done, all| {
        bar.set_length(all as u64);
        bar.set_position(done as u64);
        heartbeat.update(done as u64, all as u64);
    })?;
    bar.finish_and_clear();
    Ok(records)
}

/// [`time_with_progress`] on the bounces of each batch's hits
/// ([`torus_cull_lab::workload::secondary::bounces`]), the records' case renamed
/// `<case>_bounce`.
fn time_secondary(
    workload: &Workload,
    nus: &[f64],
    culls: &[CullKind],
    options: &PairedOptions,
) -> Result<Vec<RatioRecord>, Box<dyn std::error::Error>> {
    use torus_cull_lab::workload::generate;
    use torus_cull_lab::workload::secondary::{BOUNCE_SUFFIX, bounces};
    let mut batches = Vec::new();
    for &case in &workload.cases {
        for &nu in nus {
            let primary = generate(case, nu, options.batch, workload.seed, workload.pose)?;
            let batch = bounces(&primary);
            if batch.rays.len() < MIN_BATCH {
                // The hole case's rays pass through the hole: no hits, no bounces.
                eprintln!(
                    "note: --secondary: {} of {} rays of {} at nu = {nu} hit the torus, too \
                     few to time (allowed: >= {MIN_BATCH}): skipped",
                    batch.rays.len(),
                    primary.rays.len(),
                    case.name()
                );
                continue;
            }
            batches.push(batch);
        }
    }
    if batches.is_empty() {
        return Err("--secondary: no case of the workload has rays that hit the torus".into());
    }
    let units: Vec<torus_cull_lab::paired::Unit<'_>> = batches
        .iter()
        .map(torus_cull_lab::paired::Unit::of)
        .collect();
    let mut records = torus_cull_lab::paired::time_units(&units, culls, options, &mut |_, _| {})?;
    for r in &mut records {
        r.case.push_str(BOUNCE_SUFFIX);
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

/// `meta.sizes` of a timing on one thread: what was timed, so that compare can tell files
/// of other batches apart.
fn timing_sizes(batch: usize, nus: &[f64]) -> results::Sizes {
    results::Sizes {
        rejection_rays: None,
        timing_rays: Some(batch as u64),
        timed_nu: nus.to_vec(),
        warm_up_s: None,
        measurement_s: None,
        samples: None,
        bvh: None,
        bench_args: Vec::new(),
    }
}

/// The culls to report: the timed ones by name (the paper-as-printed variants reject hits
/// and are not worth timing), default all.
fn parse_culls(names: &[String]) -> Result<Vec<CullKind>, String> {
    if names.is_empty() {
        return Ok(CullKind::TIMED.to_vec());
    }
    let allowed = || CullKind::allowed().join(", ");
    let mut culls = Vec::new();
    for name in names {
        let parsed = name.trim().parse().map_err(|_| {
            format!(
                "--culls: '{}' is not a timed cull (allowed: {})",
                name.trim(),
                allowed()
            )
        })?;
        let kind = match parsed {
            CountedCull::Timed(kind) => kind,
            CountedCull::Printed(printed) => {
                return Err(format!(
                    "--culls: '{}' is not conservative and is not timed (allowed: {})",
                    printed.name(),
                    allowed()
                ));
            }
        };
        if !culls.contains(&kind) {
            culls.push(kind);
        }
    }
    debug_assert!(REFERENCES.iter().all(|r| CullKind::TIMED.contains(r)));
    Ok(culls)
}

/// `--cases`: keeps the workload's cases named (each must be one of them), in the
/// workload's order; all of them where none is named.
fn pick_cases(asked: &[String], workload: &mut Workload, file: &Path) -> Result<(), String> {
    if asked.is_empty() {
        return Ok(());
    }
    use torus_cull::Named;
    for name in asked {
        if !workload.cases.iter().any(|c| c.name() == name) {
            let have: Vec<&str> = workload.cases.iter().map(|c| c.name()).collect();
            return Err(format!(
                "--cases {name} is not in workload {} (allowed: {})",
                file.display(),
                have.join(", ")
            ));
        }
    }
    workload
        .cases
        .retain(|c| asked.iter().any(|name| name == c.name()));
    Ok(())
}

/// `--nu`: each value must be one of the workload's (its rays are defined there); default
/// all of them.
fn pick_nus(asked: &[f64], workload: &Workload, file: &Path) -> Result<Vec<f64>, String> {
    if asked.is_empty() {
        return Ok(workload.nu.clone());
    }
    let mut nus = Vec::new();
    for &nu in asked {
        if !workload.nu.contains(&nu) {
            let have: Vec<String> = workload.nu.iter().map(f64::to_string).collect();
            return Err(format!(
                "--nu {} is not in workload {} (allowed: {})",
                torus_cull_lab::number::Num(nu),
                file.display(),
                have.join(", ")
            ));
        }
        if !nus.contains(&nu) {
            nus.push(nu);
        }
    }
    Ok(nus)
}

/// The default file name's suffix: `-time` for the `default` workload, `-<name>-time` for
/// any other (as `run` names its files), so that timing two workloads keeps both files.
/// The default file's suffix: the workload (unless `default`), `secondary` for
/// `--secondary`, `gpu` for a GPU timing, then `time`. Each kind has its own name: it
/// holds other records (bounces, or the kernel's on another device) and must never
/// replace the primary CPU timing of the same commit.
fn time_suffix(workload: &str, device: Device, secondary: bool) -> String {
    let mut suffix = String::new();
    if workload != "default" {
        suffix += &format!("-{workload}");
    }
    if secondary {
        suffix += "-secondary";
    }
    if device == Device::Gpu {
        suffix += "-gpu";
    }
    suffix + "-time"
}

/// Fails now, not after the measurement, if `path` cannot be written the way every output
/// is (see [`torus_cull_lab::output`]).
fn check_writable(path: &Path) -> Result<(), String> {
    torus_cull_lab::output::check_writable(path)
        .map_err(|e| format!("--out {}: {e}", path.display()))
}

/// `torus-cull time --bvh`.
mod bvh;

/// What `time --device gpu` runs besides the kernel's default (read only by a binary
/// built with the feature gpu).
#[cfg_attr(not(feature = "gpu"), allow(dead_code))]
struct GpuOptions {
    /// Also time the f64 finish pass.
    finish: bool,
    /// Threads per workgroup of the kernel (`GpuIntersector::with_workgroup`).
    workgroup: u32,
}

/// `torus-cull time --device gpu`.
#[cfg(feature = "gpu")]
mod gpu;

/// `torus-cull time --device gpu` in a binary built without the feature.
#[cfg(not(feature = "gpu"))]
mod gpu {
    use std::path::Path;
    use std::process::ExitCode;
    use torus_cull::CullKind;
    use torus_cull_lab::workload::spec::Workload;

    pub(super) fn run(
        _workload: &Workload,
        _nus: &[f64],
        _culls: &[CullKind],
        _seconds: f64,
        _batch: usize,
        _options: super::GpuOptions,
        _path: &Path,
    ) -> Result<ExitCode, Box<dyn std::error::Error>> {
        Err("--device gpu needs a binary built with the feature gpu: \
             cargo run --release --features gpu -- time --device gpu"
            .into())
    }
}

#[cfg(test)]
mod tests {
    use super::{Device, time_suffix};

    #[test]
    fn a_gpu_timing_has_its_own_default_name() {
        assert_eq!(time_suffix("default", Device::Cpu, false), "-time");
        assert_eq!(time_suffix("default", Device::Gpu, false), "-gpu-time");
        assert_eq!(time_suffix("quick", Device::Cpu, false), "-quick-time");
        assert_eq!(time_suffix("quick", Device::Gpu, false), "-quick-gpu-time");
        assert_eq!(time_suffix("default", Device::Cpu, true), "-secondary-time");
        assert_eq!(
            time_suffix("quick", Device::Cpu, true),
            "-quick-secondary-time"
        );
    }
}
