//! `cargo bench`: what each cull costs and what it saves, written as results JSON.
//!
//! Per case × timed ν × cull, on the first `batch` rays of each (case, ν) stream of the
//! workload (the same rays `torus-cull run` counts):
//! * `cull_ns`: the cull alone on torus-frame lines, per ray;
//! * `total_ns`: [`intersect_culled`] on world rays (transform, cull, quartic if kept);
//!   the `none` column is `solve_ns`, the baseline.
//!
//! Plus the quartic solver against the `roots` crate on the same coefficient sets, the
//! full-ν rejection sweep, and the workload's `bvh` scenes: obvhs CWBVH over many tori,
//! each cull at the leaves, Mrays/s and quartic solves per ray. The figures are criterion's medians and confidence intervals
//! of this run, read back from its `estimates.json` files.
//!
//! And the headline: the paired, interleaved ratios of `torus-cull time` for the same
//! cases and ν (each cull against cychosz and none, both metrics, in shuffled rounds on
//! the same rays; see [`torus_cull::paired`]).
//!
//! `TORUS_CULL_BENCH` picks the size: `smoke` (seconds, for CI), `default` (< 10 min on
//! 2 cores), `full` (every ν of the workload, longer measurements).
//! `TORUS_CULL_WORKLOAD` (default `workloads/default.json`) and `TORUS_CULL_RESULTS`
//! (default `results/<commit>[-dirty].json`) override the paths.

#[path = "support/mod.rs"]
mod support;

use criterion::{BenchmarkId, Criterion};
use std::hint::black_box;
use std::path::{Path, PathBuf};
use std::time::SystemTime;
use support::{BenchConfig, Estimate, bvh, read_estimate, solver};
use torus_cull::measure::{self, LabeledBatch};
use torus_cull::oracle::OracleClass;
use torus_cull::paired;
use torus_cull::results::{RatioRecord, Results, TimingRecord};
use torus_cull::workload::spec::Workload;
use torus_cull::workload::{Case, generate};
use torus_cull::{
    Cull, CullBounds, CullKind, CullVisitor, LocalLine, Ray, Torus, intersect, intersect_culled,
};

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
        let bounds = CullBounds::of(self.torus);
        let id = BenchmarkId::new(cull.name(), self.nu);
        self.c
            .benchmark_group(format!("cull_ns-{}", self.case))
            .bench_with_input(id.clone(), self.lines, |b, lines| {
                b.iter(|| {
                    for line in lines {
                        black_box(cull.keeps(&bounds, line.origin, line.dir));
                    }
                })
            });
        self.c
            .benchmark_group(format!("total_ns-{}", self.case))
            .bench_with_input(id, self.rays, |b, rays| {
                b.iter(|| {
                    for ray in rays {
                        black_box(intersect_culled(&cull, self.torus, &bounds, ray));
                    }
                })
            });
    }
}

fn main() {
    let config = BenchConfig::from_env();
    let workload_path = std::env::var_os("TORUS_CULL_WORKLOAD")
        .map_or_else(|| PathBuf::from("workloads/default.json"), PathBuf::from);
    let workload = Workload::load(&workload_path).unwrap_or_else(|e| panic!("{e}"));
    let started = SystemTime::now();
    let timed_nus = config.timed_nus(&workload);
    println!(
        "torus-cull bench: size {}, workload {}, timed nu {:?}, batch {} rays",
        config.name, workload.name, timed_nus, config.batch
    );

    let clock = std::time::Instant::now();
    let stage = |name: &str| eprintln!("[{:>6.1} s] {name}", clock.elapsed().as_secs_f64());
    let mut results = Results::new(&workload, "bench");
    let sweep = config.sweep_workload(&workload);
    let (records, false_rejects) = measure::rejection_sweep(&sweep, &CullKind::TIMED, 2, &|_| {})
        .unwrap_or_else(|e| panic!("{e}"));
    assert!(
        false_rejects.is_empty(),
        "false rejects in the rejection sweep: {false_rejects:?}"
    );
    results.rejection = records;
    stage("rejection sweep done");

    let mut c = Criterion::default()
        .warm_up_time(config.warm_up)
        .measurement_time(config.measurement)
        .sample_size(config.samples)
        .nresamples(10_000)
        .without_plots()
        .configure_from_args();

    let mut batches = Vec::new();
    for &case in &workload.cases {
        for &nu in &timed_nus {
            let batch = generate(case, nu, config.batch, workload.seed, workload.pose)
                .unwrap_or_else(|e| panic!("{e}"));
            let labeled = LabeledBatch::label(batch);
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
                c.benchmark_group(format!("solve_hits-{case}"))
                    .bench_with_input(BenchmarkId::new("none", nu), &hit_rays, |b, rays| {
                        b.iter(|| {
                            for ray in rays {
                                black_box(intersect(&torus, ray));
                            }
                        })
                    });
            }
            for cull in CullKind::TIMED {
                cull.visit(TimeCull {
                    c: &mut c,
                    case,
                    nu,
                    torus: &labeled.batch.torus,
                    rays: &labeled.batch.rays,
                    lines: &lines,
                });
            }
            batches.push(labeled);
        }
    }

    stage("cull timings done");
    results.ratio = paired_ratios(&batches, &config);
    stage("paired ratios done");
    let solver_sets = solver::coefficient_sets(&workload, &config);
    solver::bench(&mut c, &solver_sets);
    stage("solver timings done");
    let bvh_pending = match (&workload.bvh, config.bvh) {
        (Some(spec), true) => bvh::bench(&mut c, &config.bvh_spec(spec), workload.seed),
        _ => Vec::new(),
    };
    c.final_summary();
    stage("bvh done");

    let home = criterion_home();
    results.timing = timing_records(&home, &batches, config.batch, started);
    results.solver = solver::records(&home, &solver_sets, started);
    results.bvh = bvh::records(&home, bvh_pending, started);

    let path = std::env::var_os("TORUS_CULL_RESULTS").map_or_else(
        || torus_cull::results::default_path(Path::new("results"), ""),
        PathBuf::from,
    );
    // A bench of part of the set keeps the other parts of an existing file for this commit.
    if let Ok(old) = Results::load(&path) {
        if old.meta.workload_sha256 == results.meta.workload_sha256 && results.timing.is_empty() {
            results.timing = old.timing;
        }
        if results.bvh.is_empty() {
            results.bvh = old.bvh;
        }
    }
    results.save(&path).unwrap_or_else(|e| panic!("{e}"));
    print!("{}", torus_cull::report::timing_tables(&results));
    print!("{}", torus_cull::report::cull_ns_tables(&results));
    print!("{}", torus_cull::report::ratio_tables(&results));
    print!("{}", solver::table(&results.solver));
    print!("{}", torus_cull::report::bvh_tables(&results));
    println!("wrote {}", path.display());
    let dir = path.parent().unwrap_or(Path::new("."));
    let stem = path
        .file_stem()
        .map_or("results".into(), |s| s.to_string_lossy());
    match torus_cull::plot::plot_results(&results, dir, &stem) {
        Ok(w) => println!("wrote {} plots to {}/{stem}-*.svg", w.len(), dir.display()),
        Err(e) => eprintln!("plots failed: {e}"),
    }
}

/// Paired, interleaved ratios of every timed cull against cychosz and none, on the first
/// rays of each timed batch (the engine `torus-cull time` uses).
fn paired_ratios(batches: &[LabeledBatch], config: &BenchConfig) -> Vec<RatioRecord> {
    let rays = config.batch.min(paired::sweep::DEFAULT_BATCH);
    let units: Vec<paired::Unit<'_>> = batches
        .iter()
        .map(|l| paired::Unit {
            case: l.batch.case,
            nu: l.batch.nu,
            torus: &l.batch.torus,
            rays: &l.batch.rays[..rays.min(l.batch.rays.len())],
            seed: l.batch.stream_seed,
        })
        .collect();
    let options = paired::PairedOptions::total(config.ratio_seconds, rays);
    paired::time_units(&units, &CullKind::TIMED, &options, &mut |_, _| {})
        .unwrap_or_else(|e| panic!("{e}"))
}

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
/// left out, never filled from an older run.
fn timing_records(
    home: &Path,
    batches: &[LabeledBatch],
    batch_len: usize,
    since: SystemTime,
) -> Vec<TimingRecord> {
    let per_ray = |e: Estimate| e.scaled(1.0 / batch_len as f64);
    let mut out = Vec::new();
    for labeled in batches {
        let (case, nu) = (labeled.batch.case, labeled.batch.nu);
        let read = |group: &str, cull: CullKind| {
            read_estimate(home, &format!("{group}-{case}"), cull.name(), nu, since).map(per_ray)
        };
        let Some(solve) = read("total_ns", CullKind::None) else {
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
        for cull in CullKind::TIMED {
            let (Some(cull_ns), Some(total)) = (read("cull_ns", cull), read("total_ns", cull))
            else {
                continue;
            };
            out.push(TimingRecord {
                case: case.name().to_string(),
                nu,
                cull: cull.name().to_string(),
                cull_ns: cull_ns.median,
                total_ns: total.median,
                total_ns_ci: [total.lower, total.upper],
                speedup_vs_none: solve.median / total.median,
                ideal_total_ns: cull_ns.median + hit_fraction * solve.median,
                solve_hit_ns: solve_hit,
                ideal_total_ns_at_hit_cost: solve_hit.map(|s| cull_ns.median + hit_fraction * s),
                source: "criterion".into(),
            });
        }
    }
    out
}
