//! `cargo bench`: what each cull costs and what it saves, written as results JSON.
//!
//! Per case × timed ν × cull, on the first `batch` rays of each (case, ν) stream of the
//! workload (the same rays `torus-cull run` counts):
//! * `cull_ns`: the cull alone on torus-frame lines, per ray;
//! * `total_ns`: [`intersect_culled`] on world rays (transform, cull, quartic if kept);
//!   the `none` column is `solve_ns`, the baseline.
//!
//! And the same in batch mode (`"mode": "batch"` records, for `none`, `cychosz`,
//! `skala`, `ellipsoid`, `quadric`, `discriminant`):
//! * `batch_cull_ns`: the SIMD cull over structure-of-arrays lines, into a keep mask;
//! * `batch_total_ns`: the wavefront of [`torus_cull::batch::Wavefront`] on the world
//!   rays (lines, cull, compaction, exact intersection on f64 lanes, hits);
//! * `batch_f32_total_ns`: the same wavefront through the certified f32 path
//!   ([`torus_cull::batch::Wavefront::intersect_f32`]: f32 lanes, unproved rays to the f64
//!   solver), written as `"precision": "f32"` batch records with their `escalation_rate`.
//!
//! The instruction set is picked at run time and recorded in `meta.isa`;
//! `TORUS_CULL_ISA=avx2` (or `scalar`) forces a lower one.
//!
//! Plus the quartic solver (scalar, and the batch solver on lanes) against the `roots`,
//! `kurbo` and `polycool` crates on the same coefficient sets, the
//! workload's `bvh` scenes (obvhs CWBVH over many tori, each cull at the leaves, Mrays/s
//! and quartic solves per ray) and, last, the rejection sweep over every ν. The figures
//! are criterion's medians and confidence intervals of this run, read back from its
//! `estimates.json` files.
//!
//! **What gets written.** A run that measured every benchmark writes the complete file:
//! `TORUS_CULL_RESULTS`, or `results/<commit>[-dirty][-<workload>][-<preset>][-nu…].json`
//! (the default preset on the default workload is plain `results/<commit>.json`, the file
//! that gets committed; `run` writes `…-run.json`, so neither clobbers the other). A run
//! that a filter cut short (`cargo bench -- skala`) writes only what it measured, with
//! `meta.partial = true`, to the same name with `-partial` added, and never runs the
//! rejection sweep; a complete file is never touched by it. `--list`, `--test` and
//! `--profile-time` write nothing, and `--list` does no setup.
//!
//! And the headline: the paired, interleaved ratios of `torus-cull time --mode both` for
//! the same cases and ν (each cull against cychosz and none, the scalar and the batch
//! metrics, the f32 wavefront also against the cull's own f64 wavefront, in shuffled
//! rounds on the same rays; see [`torus_cull_lab::paired`]). The same again for secondary
//! rays, as `torus-cull time secondary` times them: one diffuse bounce spawned from each
//! hit (`Ray::from_surface`), the records' case named `<case>_bounce`.
//!
//! `TORUS_CULL_BENCH` picks the size: `smoke` (seconds, for CI), `default` (< 10 min on
//! 2 cores), `full` (every ν of the workload, longer measurements); `TORUS_CULL_BENCH_NU`
//! times a subset of the workload's ν. `TORUS_CULL_WORKLOAD` (default
//! `workloads/default.json`) and `TORUS_CULL_RESULTS` override the paths. A bad value is an
//! error naming the variable and what it allows (the harness exits 2, and cargo reports
//! the failure).

#[path = "support/mod.rs"]
mod support;

use criterion::{BenchmarkId, Criterion};
use std::hint::black_box;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::SystemTime;
use support::batch::{BATCH_GROUPS, BATCH_TIMED, BatchCase, time_batch_cull};
use support::{BenchConfig, Estimate, Mode, bvh, ratios, read_estimate, solver};
use torus_cull::Named;
use torus_cull::batch::{Dispatch, Lines, Wavefront};
use torus_cull::{Cull, CullKind, CullVisitor, LocalLine, Ray, Torus, intersect, intersect_culled};
use torus_cull_lab::measure::{self, LabeledBatch};
use torus_cull_lab::oracle::OracleClass;
use torus_cull_lab::paired;
use torus_cull_lab::results::{
    BATCH_MODE, BvhSizes, CPU_DEVICE, EstimateRecord, F32_PRECISION, F64_PRECISION, RatioRecord,
    Results, SCALAR_MODE, Sizes, TimingRecord,
};
use torus_cull_lab::solver_suite::SolverCase;
use torus_cull_lab::workload::spec::{BvhSpec, Workload};
use torus_cull_lab::workload::{Case, generate, secondary};

/// Times one cull on one batch, both ways.
struct TimeCull<'a> {
    c: &'a mut Criterion,
    case: Case,
    nu: f64,
    torus: &'a Torus,
    rays: &'a [Ray],
    lines: &'a [LocalLine],
}

impl CullVisitor for TimeCull<'_> {
    type Output = ();
    fn visit<C: Cull>(self, cull: C) {
        let bounds = self.torus.bounds();
        let id = BenchmarkId::new(cull.name(), self.nu);
        self.c
            .benchmark_group(format!("cull_ns-{}", self.case))
            .bench_with_input(id.clone(), self.lines, |b, lines| {
                b.iter(|| {
                    for line in lines {
                        black_box(cull.keeps(bounds, line.origin, line.dir));
                    }
                })
            });
        self.c
            .benchmark_group(format!("total_ns-{}", self.case))
            .bench_with_input(id, self.rays, |b, rays| {
                b.iter(|| {
                    for ray in rays {
                        black_box(intersect_culled(&cull, self.torus, ray));
                    }
                })
            });
    }
}

fn main() -> ExitCode {
    match bench() {
        Ok(code) => code,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }
    }
}

/// One benchmark registered with criterion, and how many elements an iteration covers.
struct Registered {
    group: String,
    function: String,
    parameter: String,
    elements: usize,
}

impl Registered {
    fn new(group: String, function: &str, parameter: impl ToString, elements: usize) -> Self {
        Registered {
            group,
            function: function.to_string(),
            parameter: parameter.to_string(),
            elements,
        }
    }
}

/// What a run is asked to do, from its arguments and the `TORUS_CULL_*` variables.
struct Setup {
    args: Vec<String>,
    mode: Mode,
    /// The workload file, which the results file must not overwrite.
    workload_path: PathBuf,
    workload: Workload,
    config: BenchConfig,
    dispatch: Dispatch,
    /// The results file of a complete run.
    out: PathBuf,
}

impl Setup {
    /// Reads the arguments and the environment; a bad value is an error naming the
    /// variable and what it allows.
    fn from_env() -> Result<Setup, String> {
        let args: Vec<String> = std::env::args().skip(1).collect();
        let mode = Mode::from_args(&args);
        let workload_path = match std::env::var_os("TORUS_CULL_WORKLOAD") {
            Some(p) if p.is_empty() => {
                return Err("TORUS_CULL_WORKLOAD is empty (allowed: a workload file)".into());
            }
            Some(p) => PathBuf::from(p),
            None => PathBuf::from("workloads/default.json"),
        };
        let workload =
            Workload::load(&workload_path).map_err(|e| format!("TORUS_CULL_WORKLOAD: {e}"))?;
        let config = BenchConfig::from_env(&workload)?;
        let dispatch = Dispatch::from_env().map_err(|e| e.to_string())?;
        let out = match std::env::var_os("TORUS_CULL_RESULTS") {
            Some(p) if p.is_empty() => {
                return Err("TORUS_CULL_RESULTS is empty (allowed: a file path)".into());
            }
            Some(p) => PathBuf::from(p),
            None => {
                let out = torus_cull_lab::results::default_path(
                    Path::new("results"),
                    &config.file_suffix(&workload),
                );
                if mode == Mode::Benchmark {
                    torus_cull_lab::output::create_default_dir(&out)
                        .map_err(|e| format!("{}: {e}", out.display()))?;
                }
                out
            }
        };
        Ok(Setup {
            args,
            mode,
            workload_path,
            workload,
            config,
            dispatch,
            out,
        })
    }

    /// The BVH scenes to time, if the workload has them and the preset times them.
    fn bvh_spec(&self) -> Option<BvhSpec> {
        match (&self.workload.bvh, self.config.bvh) {
            (Some(spec), true) => Some(self.config.bvh_spec(spec)),
            _ => None,
        }
    }
}

/// Criterion, configured by the preset and then by criterion's own arguments.
fn criterion(config: &BenchConfig) -> Criterion {
    Criterion::default()
        .warm_up_time(config.warm_up)
        .measurement_time(config.measurement)
        .sample_size(config.samples)
        .nresamples(10_000)
        .without_plots()
        .configure_from_args()
}

/// Prints how far the run is, seconds since `clock`.
fn stage(clock: std::time::Instant, name: &str) {
    eprintln!("[{:>6.1} s] {name}", clock.elapsed().as_secs_f64());
}

/// Times every workload case at every timed ν (the hits' exact intersection, each cull
/// both ways, each batch cull both ways), registering each benchmark; the labelled
/// batches, for the timing records and the paired ratios.
fn time_culls(
    c: &mut Criterion,
    setup: &Setup,
    timed_nus: &[f64],
    registered: &mut Vec<Registered>,
) -> Result<Vec<LabeledBatch>, String> {
    let (workload, config) = (&setup.workload, &setup.config);
    let mut batches = Vec::new();
    for &case in &workload.cases {
        for &nu in timed_nus {
            let batch = generate(case, nu, config.batch, workload.seed, workload.pose)
                .map_err(|e| e.to_string())?;
            let labeled = LabeledBatch::label(batch);
            time_case(c, &setup.dispatch, case, nu, &labeled, registered);
            batches.push(labeled);
        }
    }
    Ok(batches)
}

/// [`time_culls`] for one case and ν.
fn time_case(
    c: &mut Criterion,
    dispatch: &Dispatch,
    case: Case,
    nu: f64,
    labeled: &LabeledBatch,
    registered: &mut Vec<Registered>,
) {
    let lines: Vec<LocalLine> = labeled
        .batch
        .rays
        .iter()
        .map(|r| labeled.batch.torus.line_to_local(r))
        .collect();
    let torus = labeled.batch.torus;
    let hit_rays: Vec<Ray> = labeled
        .batch
        .rays
        .iter()
        .zip(&labeled.labels)
        .filter(|(_, l)| l.class == OracleClass::Hit)
        .map(|(r, _)| *r)
        .collect();
    if !hit_rays.is_empty() {
        let group = format!("solve_hits-{case}");
        c.benchmark_group(&group).bench_with_input(
            BenchmarkId::new("none", nu),
            &hit_rays,
            |b, rays| {
                b.iter(|| {
                    for ray in rays {
                        black_box(intersect(&torus, ray));
                    }
                })
            },
        );
        registered.push(Registered::new(group, "none", nu, hit_rays.len()));
    }
    let n = labeled.batch.rays.len();
    for cull in CullKind::TIMED {
        cull.visit(TimeCull {
            c,
            case,
            nu,
            torus: &labeled.batch.torus,
            rays: &labeled.batch.rays,
            lines: &lines,
        });
        for group in ["cull_ns", "total_ns"] {
            registered.push(Registered::new(
                format!("{group}-{case}"),
                cull.name(),
                nu,
                n,
            ));
        }
    }
    let soa = Lines::from_local(&lines);
    for cull in BATCH_TIMED {
        time_batch_cull(
            c,
            dispatch,
            cull,
            &BatchCase {
                case,
                nu,
                torus: &labeled.batch.torus,
                rays: &labeled.batch.rays,
                lines: &soa,
            },
        );
        for group in BATCH_GROUPS {
            registered.push(Registered::new(
                format!("{group}-{case}"),
                cull.name(),
                nu,
                n,
            ));
        }
    }
}

/// The solver families' quartics, timed and registered.
fn time_solvers(
    c: &mut Criterion,
    setup: &Setup,
    registered: &mut Vec<Registered>,
) -> Vec<(&'static str, Vec<SolverCase>)> {
    let solver_sets: Vec<_> = solver::FAMILIES
        .iter()
        .map(|&f| (f, solver::family_sets(f, &setup.workload, &setup.config)))
        .collect();
    solver::bench(c, &solver_sets, &setup.dispatch);
    for (family, sets) in &solver_sets {
        for name in solver::solver_names() {
            registered.push(Registered::new(
                format!("solver-{family}"),
                name,
                "all",
                sets.len(),
            ));
        }
    }
    solver_sets
}

/// What this run measured: the estimate of every registered benchmark that ran (a
/// benchmark a filter left out has no fresh estimate).
fn fresh_estimates(registered: &[Registered], started: SystemTime) -> Vec<EstimateRecord> {
    let home = criterion_home();
    registered
        .iter()
        .filter_map(|r| {
            let e = read_estimate(&home, &r.group, &r.function, &r.parameter, started)?;
            let per = e.scaled(1.0 / r.elements.max(1) as f64);
            Some(EstimateRecord {
                benchmark: format!("{}/{}/{}", r.group, r.function, r.parameter),
                elements: r.elements as u64,
                ns_per_element: per.median,
                ns_per_element_ci: [per.lower, per.upper],
            })
        })
        .collect()
}

/// The sizes a results file records.
fn sizes(setup: &Setup, complete: bool, timed_nus: &[f64], bvh_spec: Option<&BvhSpec>) -> Sizes {
    let config = &setup.config;
    Sizes {
        rejection_rays: complete.then_some(config.sweep_workload(&setup.workload).rays as u64),
        timing_rays: Some(config.batch as u64),
        timed_nu: timed_nus.to_vec(),
        warm_up_s: Some(config.warm_up.as_secs_f64()),
        measurement_s: Some(config.measurement.as_secs_f64()),
        samples: Some(config.samples as u64),
        bvh: bvh_spec.map(|s| BvhSizes {
            scenes: s.scenes.iter().map(|k| k.name().to_string()).collect(),
            nu: s.nu.clone(),
            tori: s.tori as u64,
            image: s.image as u64,
            random_rays: s.random_rays as u64,
        }),
        bench_args: setup
            .args
            .iter()
            .filter(|a| *a != "--bench")
            .cloned()
            .collect(),
    }
}

/// Prints the tables of a saved results file and writes its plots beside it.
fn report(results: &Results, path: &Path, complete: bool, registered: usize) {
    use torus_cull_lab::report;
    print!("{}", report::timing_tables(results));
    print!("{}", report::cull_ns_tables(results));
    print!("{}", report::scalar_vs_batch_tables(results));
    print!("{}", report::ratio_tables(results));
    print!("{}", solver::table(&results.solver));
    print!("{}", report::bvh_tables(results));
    if complete {
        println!("wrote {}", path.display());
    } else {
        println!(
            "wrote {} (partial: {} of {} benchmarks ran; it holds only what was measured)",
            path.display(),
            results.estimates.len(),
            registered
        );
    }
    let dir = path.parent().unwrap_or(Path::new("."));
    let stem = path
        .file_stem()
        .map_or("results".into(), |s| s.to_string_lossy());
    match torus_cull_lab::plot::plot_results(results, dir, &stem) {
        Ok(w) => println!("wrote {} plots to {}/{stem}-*.svg", w.len(), dir.display()),
        Err(e) => eprintln!("plots failed: {e}"),
    }
}

fn bench() -> Result<ExitCode, String> {
    let setup = Setup::from_env()?;
    let (mode, config, dispatch) = (setup.mode, &setup.config, &setup.dispatch);
    if mode == Mode::Benchmark {
        // Before the measurements, not after them: a directory, a missing parent or the
        // workload file itself is refused here.
        torus_cull_lab::output::check_writable(&setup.out)
            .map_err(|e| format!("TORUS_CULL_RESULTS {}: {e}", setup.out.display()))?;
        torus_cull_lab::output::check_not_input(
            ("TORUS_CULL_RESULTS", &setup.out),
            &[("TORUS_CULL_WORKLOAD", &setup.workload_path)],
        )?;
    }
    let started = SystemTime::now();
    let timed_nus = config.timed_nus(&setup.workload);
    println!(
        "torus-cull bench: size {}, workload {}, timed nu {:?}, batch {} rays, batch mode on {}",
        config.name,
        setup.workload.name,
        timed_nus,
        config.batch,
        dispatch.isa()
    );
    let mut c = criterion(config);
    let bvh_spec = setup.bvh_spec();
    if mode == Mode::List {
        // Names only: none of the data, none of the setup, nothing written.
        list(&mut c, &setup.workload, &timed_nus, bvh_spec.as_ref());
        return Ok(ExitCode::SUCCESS);
    }

    let clock = std::time::Instant::now();
    let mut registered = Vec::new();
    let batches = time_culls(&mut c, &setup, &timed_nus, &mut registered)?;
    stage(clock, "cull timings done");
    let solver_sets = time_solvers(&mut c, &setup, &mut registered);
    stage(clock, "solver timings done");
    let bvh_pending = match &bvh_spec {
        Some(spec) => bvh::bench(&mut c, spec, setup.workload.seed),
        None => Vec::new(),
    };
    registered.extend(bvh_pending.iter().map(|p| {
        let (group, cull, nu, timed) = p.benchmark();
        Registered::new(group, cull, nu, timed)
    }));
    c.final_summary();
    stage(clock, "bvh done");
    if mode != Mode::Benchmark {
        println!("{mode:?} mode: nothing was timed, no results written");
        return Ok(ExitCode::SUCCESS);
    }

    let estimates = fresh_estimates(&registered, started);
    if estimates.is_empty() {
        println!("no benchmark ran (all filtered out): no results written");
        return Ok(ExitCode::SUCCESS);
    }
    let complete = estimates.len() == registered.len();
    let home = criterion_home();
    let mut results = Results::new(&setup.workload, "bench");
    results.meta.preset = Some(config.name.to_string());
    results.meta.partial = !complete;
    results.meta.isa = Some(dispatch.isa().name().to_string());
    results.timing = timing_records(&home, &batches, config.batch, started, dispatch);
    if complete {
        // The paired ratios take a minute: only a complete run pays for them.
        results.ratio = paired_ratios(&batches, config, dispatch);
        stage(clock, "paired ratios done");
        results
            .ratio
            .extend(ratios::shapes(config, setup.workload.seed));
        stage(clock, "family and bend ratios done");
        if let Some(spec) = &bvh_spec {
            let bvh = ratios::bvh(spec, config, setup.workload.seed, dispatch);
            results.ratio.extend(bvh);
            stage(clock, "paired BVH ratios done");
        }
        support::counts::add(
            &mut results,
            config,
            (&setup.workload_path, &setup.workload),
        );
        stage(clock, "instruction counts done");
    }
    results.solver = solver::records(&home, &solver_sets, started, dispatch);
    results.bvh = bvh::records(&home, bvh_pending, started);
    results.estimates = estimates;
    let mut false_rejects = Vec::new();
    let path = if complete {
        // The sweep runs only for a complete set, so that a file never mixes a full
        // sweep with part of the timings (or old timings with a new sweep).
        let sweep = config.sweep_workload(&setup.workload);
        let (records, rejected_hits) =
            measure::rejection_sweep(&sweep, &CullKind::TIMED.map(Into::into), 2, &|_| {})
                .map_err(|e| e.to_string())?;
        results.rejection = records;
        false_rejects = rejected_hits;
        stage(clock, "rejection sweep done");
        setup.out.clone()
    } else {
        partial_path(&setup.out)
    };
    results.meta.sizes = Some(sizes(&setup, complete, &timed_nus, bvh_spec.as_ref()));
    results.save(&path).map_err(|e| e.to_string())?;
    report(&results, &path, complete, registered.len());
    if complete {
        // The file to commit (issue 53): the records the docs quote, as `torus-cull
        // summarize` writes them. The line does not end in `.json`, so that scripts reading
        // the full file's `wrote …` line (.ci/bench-safety.sh) find one.
        let to = torus_cull_lab::summary::default_path(&path);
        let summary = torus_cull_lab::summary::summarize(&results, &path.display().to_string());
        summary.save(&to).map_err(|e| e.to_string())?;
        println!("wrote {} (the summary to commit)", to.display());
    }
    if !false_rejects.is_empty() {
        eprintln!(
            "error: {} false rejects in the rejection sweep: {:?}",
            false_rejects.len(),
            &false_rejects[..false_rejects.len().min(5)]
        );
        return Ok(ExitCode::from(1));
    }
    Ok(ExitCode::SUCCESS)
}

/// `x.json` → `x-partial.json`: a partial file never takes a complete file's name.
fn partial_path(out: &Path) -> PathBuf {
    let stem = out
        .file_stem()
        .map_or("results".into(), |s| s.to_string_lossy());
    out.with_file_name(format!("{stem}-partial.json"))
}

/// Registers every benchmark name without data, for `--list` (criterion prints them and
/// runs none).
fn list(c: &mut Criterion, workload: &Workload, timed_nus: &[f64], bvh: Option<&BvhSpec>) {
    let mut name = |group: String, function: &str, parameter: String| {
        c.benchmark_group(group)
            .bench_function(BenchmarkId::new(function, parameter), |b| b.iter(|| ()));
    };
    for &case in &workload.cases {
        for &nu in timed_nus {
            if case != Case::Hole {
                // Hole rays are all misses: no hit to solve.
                name(format!("solve_hits-{case}"), "none", nu.to_string());
            }
            for cull in CullKind::TIMED {
                name(format!("cull_ns-{case}"), cull.name(), nu.to_string());
                name(format!("total_ns-{case}"), cull.name(), nu.to_string());
            }
            for cull in BATCH_TIMED {
                for group in BATCH_GROUPS {
                    name(format!("{group}-{case}"), cull.name(), nu.to_string());
                }
            }
        }
    }
    for family in solver::FAMILIES {
        for solver in solver::solver_names() {
            name(format!("solver-{family}"), solver, "all".into());
        }
    }
    if let Some(spec) = bvh {
        for scene in &spec.scenes {
            for &nu in &spec.nu {
                for (set, n) in [("camera", spec.image), ("random", spec.random_rays)] {
                    if n == 0 {
                        continue;
                    }
                    for cull in CullKind::TIMED {
                        name(format!("bvh-{scene}-{set}"), cull.name(), nu.to_string());
                    }
                }
            }
        }
    }
}

/// Paired, interleaved ratios of every timed cull against cychosz and none, on the first
/// rays of each timed batch (the engine `torus-cull time` uses), in both modes, over
/// `config.ratio_runs` independent runs with their between-run intervals.
fn paired_ratios(
    batches: &[LabeledBatch],
    config: &BenchConfig,
    dispatch: &Dispatch,
) -> Vec<RatioRecord> {
    let rays = config.batch.min(paired::sweep::DEFAULT_BATCH);
    let units: Vec<paired::Unit<'_>> = batches
        .iter()
        .map(|l| paired::Unit {
            rays: &l.batch.rays[..rays.min(l.batch.rays.len())],
            ..paired::Unit::of(&l.batch)
        })
        .collect();
    // The runs share the seconds; each lays the buffers out afresh in this process (a
    // bench cannot start itself again as `time --runs` does), so the between-run
    // interval covers data placement and the machine's drift, not code placement.
    let runs = config.ratio_runs.max(1);
    let mut options = paired::PairedOptions::total(config.ratio_seconds / runs as f64, rays);
    options.batch_isa = Some(dispatch.isa());
    // Secondary rays: one diffuse bounce spawned from each hit (`Ray::from_surface`), in
    // their own rounds with the same time per batch, as `time secondary` times them;
    // a batch with too few hits to time (the hole's) is left out.
    let bounce_batches: Vec<_> = batches
        .iter()
        .map(|l| secondary::bounces(&l.batch))
        .filter(|b| b.rays.len() >= MIN_BOUNCES)
        .collect();
    let bounce_units: Vec<paired::Unit<'_>> = bounce_batches
        .iter()
        .map(|b| paired::Unit {
            rays: &b.rays[..rays.min(b.rays.len())],
            ..paired::Unit::of(b)
        })
        .collect();
    let bounce_options = paired::PairedOptions {
        batch_isa: Some(dispatch.isa()),
        ..paired::PairedOptions::total(
            config.ratio_seconds / runs as f64 * bounce_units.len() as f64 / units.len() as f64,
            rays,
        )
    };
    let all: Vec<Vec<RatioRecord>> = (0..runs)
        .map(|run| {
            let options = paired::PairedOptions { run, ..options };
            let mut records =
                paired::time_units(&units, &CullKind::TIMED, &options, &mut |_, _| {})
                    .unwrap_or_else(|e| panic!("{e}"));
            if !bounce_units.is_empty() {
                let options = paired::PairedOptions {
                    run,
                    ..bounce_options
                };
                let mut bounced =
                    paired::time_units(&bounce_units, &CullKind::TIMED, &options, &mut |_, _| {})
                        .unwrap_or_else(|e| panic!("{e}"));
                for r in &mut bounced {
                    r.case.push_str(secondary::BOUNCE_SUFFIX);
                }
                records.extend(bounced);
            }
            records
        })
        .collect();
    paired::combine_runs(&all).unwrap_or_else(|e| panic!("{e}"))
}

/// The fewest bounces a batch must give to be timed (as `time secondary` asks).
const MIN_BOUNCES: usize = 16;

/// Where criterion writes its estimates (its own rule: `$CRITERION_HOME`, else
/// `$CARGO_TARGET_DIR/criterion`, else `target/criterion`).
fn criterion_home() -> PathBuf {
    if let Some(h) = std::env::var_os("CRITERION_HOME") {
        return PathBuf::from(h);
    }
    std::env::var_os("CARGO_TARGET_DIR")
        .map_or_else(|| PathBuf::from("target"), PathBuf::from)
        .join("criterion")
}

/// Timing records from this run's estimates; benchmarks filtered out of the run are
/// left out, never filled from an older run. The f32 records' escalation rates come from
/// one untimed pass of the certified f32 wavefront on the same batch.
fn timing_records(
    home: &Path,
    batches: &[LabeledBatch],
    batch_len: usize,
    since: SystemTime,
    dispatch: &Dispatch,
) -> Vec<TimingRecord> {
    let per_ray = |e: Estimate| e.scaled(1.0 / batch_len as f64);
    let mut out = Vec::new();
    for labeled in batches {
        let (case, nu) = (labeled.batch.case, labeled.batch.nu);
        let read = |group: &str, cull: CullKind| {
            read_estimate(home, &format!("{group}-{case}"), cull.name(), nu, since).map(per_ray)
        };
        let Some(solve) = read("total_ns", CullKind::NoCull) else {
            continue;
        };
        let hits = labeled.hits();
        let hit_fraction = hits as f64 / labeled.labels.len() as f64;
        let solve_hit = (hits > 0)
            .then(|| {
                read_estimate(home, &format!("solve_hits-{case}"), "none", nu, since)
                    .map(|e| e.median / hits as f64)
            })
            .flatten();
        let record =
            |cull: CullKind, cull_ns: Estimate, total: Estimate, solve: f64| TimingRecord {
                case: case.name().to_string(),
                nu,
                cull: cull.name().to_string(),
                cull_ns: cull_ns.median,
                total_ns: total.median,
                total_ns_ci: [total.lower, total.upper],
                speedup_vs_none: solve / total.median,
                ideal_total_ns: cull_ns.median + hit_fraction * solve,
                solve_hit_ns: None,
                ideal_total_ns_at_hit_cost: None,
                source: "criterion".into(),
                mode: SCALAR_MODE.into(),
                precision: F64_PRECISION.into(),
                device: CPU_DEVICE.into(),
                escalation_rate: None,
            };
        for cull in CullKind::TIMED {
            let (Some(cull_ns), Some(total)) = (read("cull_ns", cull), read("total_ns", cull))
            else {
                continue;
            };
            out.push(TimingRecord {
                solve_hit_ns: solve_hit,
                ideal_total_ns_at_hit_cost: solve_hit.map(|s| cull_ns.median + hit_fraction * s),
                ..record(cull, cull_ns, total, solve.median)
            });
        }
        // Batch mode: the same rays through the wavefront; `none` is the batch baseline
        // (every ray to the lane solver), so speedups are within the mode, and within the
        // precision for the f32 wavefront (its `cull_ns` is the same SIMD cull).
        let mut wavefront = Wavefront::new();
        let mut hits = Vec::new();
        for (group, precision) in [
            ("batch_total_ns", F64_PRECISION),
            ("batch_f32_total_ns", F32_PRECISION),
        ] {
            let Some(batch_solve) = read(group, CullKind::NoCull) else {
                continue;
            };
            for cull in BATCH_TIMED {
                let kind = cull.kind();
                let (Some(cull_ns), Some(total)) = (read("batch_cull_ns", kind), read(group, kind))
                else {
                    continue;
                };
                let escalation_rate = (precision == F32_PRECISION).then(|| {
                    let stats = wavefront.intersect_f32(
                        dispatch,
                        cull,
                        &labeled.batch.torus,
                        &labeled.batch.rays,
                        &mut hits,
                    );
                    stats.escalated as f64 / stats.rays.max(1) as f64
                });
                out.push(TimingRecord {
                    mode: BATCH_MODE.into(),
                    precision: precision.into(),
                    escalation_rate,
                    ..record(kind, cull_ns, total, batch_solve.median)
                });
            }
        }
    }
    out
}
