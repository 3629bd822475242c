//! `torus-cull time gpu`: the WGSL kernel timed with its rays resident on the
//! device, every cull paired against `none` and `cychosz` (and a copy kernel, the
//! memory-bound floor) in the same interleaved rounds.
//!
//! Per case × ν the rays are uploaded once ([`GpuIntersector::upload`]); each round runs
//! every contender, in an order rotated from round to round, `repeats` dispatches each in
//! one submission, and takes the device's timestamps (the submission's wall time where
//! the adapter has none). Upload and read-back are timed once per case × ν and reported
//! apart.

use super::args::GpuArgs;
use super::common::{MIN_BATCH, out_path, picked, save, time_suffix, timing_sizes};
use crate::console::{Heartbeat, Ticker, outln};
use crate::whole::Whole;
use std::process::ExitCode;
use std::time::{Duration, Instant};
use torus_cull::gpu::{FinishCounts, GpuCull, GpuIntersector, ResidentRays};
use torus_cull::{CullKind, F32Verdict, Named};
use torus_cull_lab::paired::ratio_estimate;
use torus_cull_lab::precision::Path;
use torus_cull_lab::results::{EstimateRecord, RatioRecord, Results};
use torus_cull_lab::workload::spec::Workload;
use torus_cull_lab::workload::{Batch, Case, GenerateError, generate};

/// Rounds per case × ν at least, whatever the time share.
const MIN_ROUNDS: usize = 7;

/// Each timed submission lasts about this long (repeats of the whole batch), so that
/// the wall clock's latency is small beside it where there are no timestamps.
const SUBMISSION: Duration = Duration::from_millis(4);

/// The metric of the records: the kernel's device time per ray (cull and certified f32
/// intersection), rays resident.
const METRIC: &str = "gpu_kernel_ns";

/// The path the kernel times on the precision × engine axis: the certified f32 path on
/// the GPU (its records' `precision` `f32`, `device` `gpu`); `--finish` adds
/// [`Path::GPU_F64`], the f64 pass after it.
const PATH: Path = Path::GPU_F32;

/// The contender that only copies each ray's record: the bandwidth floor.
const COPY: &str = "copy";

/// Rays per case × ν on the GPU by default: a GPU needs about this many in flight before
/// its time per ray stops falling (an H100 holds 132 multiprocessors × 2 048 threads).
/// Not a power of two: on an H100, 2²⁰ rays (and, for uniform rays, 2²¹ and 2²²) ran in a
/// slow state 3–5× slower than 2²⁰ ± 64 (docs/gpu.md, "Batch size on the H100").
const GPU_BATCH: usize = 2_000_000;

/// The most rays per case × ν on the GPU: 64 bytes each on the device, 2 GiB in all.
const MAX_GPU_BATCH: usize = 1 << 25;

/// `--batch` on the GPU: drawn from the workload's generators at that count, whatever
/// the workload's `rays`.
fn pick_gpu_batch(asked: Option<Whole>) -> Result<usize, String> {
    match asked {
        None => Ok(GPU_BATCH),
        Some(b) => b.within("--batch", (MIN_BATCH, MAX_GPU_BATCH), " with time gpu"),
    }
}

/// Times the kernel on every case × ν of the workload; `workgroup` is `--workgroup`,
/// checked.
pub(super) fn run(args: &GpuArgs, workgroup: u32) -> Result<ExitCode, Box<dyn std::error::Error>> {
    let common = &args.common;
    let asked = picked(common, &args.pick)?;
    let batch = pick_gpu_batch(common.batch)?;
    let path = out_path(common, &time_suffix(&asked.workload.name, "gpu"), false)?;
    let (workload, nus) = (&asked.workload, &asked.nus[..]);
    let (seconds, finish) = (common.seconds, args.finish);
    let mut culls = gpu_culls(&asked.culls)?;
    for reference in [GpuCull::NoCull, GpuCull::Cychosz] {
        if !culls.contains(&reference) {
            culls.insert(0, reference);
        }
    }
    let gpu = GpuIntersector::with_workgroup(workgroup)?;
    let device = announce_adapter(&gpu, "its submission's wall clock")?;
    if finish {
        if let Some(why) = gpu.device_finish_unavailable() {
            return Err(format!("--finish: the adapter has no f64 finish pass: {why}").into());
        }
    }
    let share = seconds / (workload.cases.len() * nus.len()) as f64;
    outln!(
        "one run in this process: each ratio's 95% CI is within its rounds (no between-run \
         interval)"
    )?;
    outln!(
        "{:<11} {:>6} {:<15} {:>8} {:>9} {:>21} {:>21} {:>7} {:>6}",
        "case",
        "nu",
        "cull",
        "ns/ray",
        "Mrays/s",
        "vs none [95% CI]",
        "vs cychosz [95% CI]",
        "of_copy",
        "escal"
    )?;
    let mut results = Results::new(workload, "time");
    let units = workload.cases.len() * nus.len();
    let ticker = Ticker::start(Heartbeat::new("time gpu".into(), "case x nu"), units as u64);
    for (done, (case, nu, b)) in generate_all(workload, nus, batch)?.into_iter().enumerate() {
        ticker.set(done as u64);
        let mut resident = gpu.upload(&b.torus, &b.rays)?;
        let finish_upload = if finish {
            Some(resident.upload_finish(&b.torus, &b.rays)?)
        } else {
            None
        };
        let unit = time_unit(&resident, &culls, share, finish)?;
        let rays = resident.len() as f64;
        let tag = format!("{}/{nu}", case.name());
        let per_ray = |d: Duration| d.as_nanos() as f64 / rays;
        let uploads = [
            ("upload", Some(resident.upload_time())),
            ("readback", Some(unit.read_back)),
            ("finish_upload", finish_upload),
        ];
        for (name, d) in uploads
            .into_iter()
            .filter_map(|(name, d)| d.map(|d| (name, d)))
        {
            results.estimates.push(EstimateRecord {
                benchmark: format!("gpu_{name}_ns-{tag}"),
                elements: rays as u64,
                ns_per_element: per_ray(d),
                ns_per_element_ci: [per_ray(d); 2],
            });
        }
        let copy = &unit.ns[0];
        results
            .estimates
            .push(estimate(&format!("gpu_copy_ns-{tag}"), copy, rays));
        let seed = workload.seed ^ nu.to_bits();
        for (k, &cull) in culls.iter().enumerate() {
            let mine = &unit.ns[k + 1];
            let escalated = unit.escalated[k] as f64 / rays;
            results.estimates.push(estimate(
                &format!("gpu_ns-{}/{}/{nu}", case.name(), cull.name()),
                mine,
                rays,
            ));
            let mut cells = Vec::new();
            for reference in [GpuCull::NoCull, GpuCull::Cychosz] {
                if reference == cull {
                    cells.push("-".into());
                    continue;
                }
                let r = culls.iter().position(|&c| c == reference).expect("added");
                let est = ratio_estimate(mine, &unit.ns[r + 1], rays, seed)
                    .ok_or("the GPU's clock did not advance")?;
                cells.push(format!(
                    "{:.3} [{:.3},{:.3}]",
                    est.ratio, est.ratio_ci[0], est.ratio_ci[1]
                ));
                results.ratio.push(RatioRecord {
                    case: case.name().into(),
                    nu,
                    cull: cull.name().into(),
                    reference: reference.name().into(),
                    metric: METRIC.into(),
                    ratio: est.ratio,
                    ratio_ci: est.ratio_ci,
                    rounds: est.rounds as u64,
                    rounds_measured: unit.rounds as u64,
                    rays: rays as u64,
                    ns_per_ray: est.ns_per_ray,
                    reference_ns_per_ray: est.reference_ns_per_ray,
                    precision: PATH.precision.name().into(),
                    device: PATH.engine.name().into(),
                    escalation_rate: Some(escalated),
                    ..RatioRecord::default()
                });
            }
            let ns = median(mine) / rays;
            outln!(
                "{:<11} {:>6} {:<15} {:>8.4} {:>9.1} {:>21} {:>21} {:>7.2} {:>5.2}%",
                case.name(),
                nu,
                cull.name(),
                ns,
                1e3 / ns,
                cells[0],
                cells[1],
                median(copy) / median(mine),
                100.0 * escalated
            )?;
        }
        outln!(
            "{:<11} {:>6} {:<15} {:>8.4} {:>9.1}   ({:.0} GB/s read+written; upload {:.2} ns/ray, read-back {:.2} ns/ray, not in the times above)",
            case.name(),
            nu,
            COPY,
            median(copy) / rays,
            1e3 * rays / median(copy),
            ResidentRays::BYTES_PER_RAY as f64 * rays / median(copy),
            per_ray(resident.upload_time()),
            per_ray(unit.read_back),
        )?;
        for (k, f) in unit.finish.iter().enumerate() {
            let cull = culls[k];
            let name = |what: &str| format!("gpu_{what}-{}/{}/{nu}", case.name(), cull.name());
            results
                .estimates
                .push(estimate(&name("finish_ns"), &f.ns, rays));
            let escalated = f.counts.device + f.counts.host;
            if escalated > 0 {
                results.estimates.push(estimate(
                    &name("finish_per_escalated_ns"),
                    &f.ns,
                    escalated as f64,
                ));
            }
            let per_escalated = if escalated > 0 {
                format!("{:.3}", median(&f.ns) / escalated as f64)
            } else {
                "-".into()
            };
            outln!(
                "{:<11} {:>6} {:<15} f64 finish pass: {:.4} ns/ray of the batch, {per_escalated} ns per escalated ray ({} escalated: {} finished on the device, {} handed to the host){}",
                case.name(),
                nu,
                cull.name(),
                median(&f.ns) / rays,
                escalated,
                f.counts.device,
                f.counts.host,
                if f.wall {
                    "; no timestamps: wall clock of both passes less the kernel's median"
                } else {
                    ""
                },
            )?;
        }
    }
    ticker.set(units as u64);
    drop(ticker);
    results.meta.device = Some(device);
    results.meta.threads = Some(1);
    results.meta.sizes = Some(timing_sizes(batch, nus));
    // The plots: ns per ray against ν, from the estimates.
    save(&results, &path, common)?;
    Ok(ExitCode::SUCCESS)
}

/// Every case × ν's batch, drawn on all cores (the generators are the slow part of a
/// GPU run: a few µs per ray, the grazing one the slowest), in the workload's order. The
/// units are dealt to the threads round-robin, so that one case's units (all slow or all
/// fast) are spread over the threads rather than given to a few.
fn generate_all(
    workload: &Workload,
    nus: &[f64],
    batch: usize,
) -> Result<Vec<(Case, f64, Batch)>, GenerateError> {
    let units: Vec<(Case, f64)> = workload
        .cases
        .iter()
        .flat_map(|&case| nus.iter().map(move |&nu| (case, nu)))
        .collect();
    let threads = std::thread::available_parallelism()
        .map_or(1, |n| n.get())
        .clamp(1, units.len().max(1));
    std::thread::scope(|scope| {
        let handles: Vec<_> = (0..threads)
            .map(|t| {
                let units = &units;
                scope.spawn(move || {
                    units
                        .iter()
                        .enumerate()
                        .skip(t)
                        .step_by(threads)
                        .map(|(k, &(case, nu))| {
                            generate(case, nu, batch, workload.seed, workload.pose)
                                .map(|b| (k, (case, nu, b)))
                        })
                        .collect::<Result<Vec<_>, _>>()
                })
            })
            .collect();
        let mut all = Vec::with_capacity(units.len());
        for h in handles {
            all.extend(h.join().expect("a generator thread panicked")?);
        }
        all.sort_by_key(|(k, _)| *k);
        Ok(all.into_iter().map(|(_, unit)| unit).collect())
    })
}

/// One case × ν: per contender (the copy kernel first, then `culls` in order), the
/// device time of one pass over the batch in each round (ns); the rays each cull
/// escalated; the read-back time.
struct UnitTimes {
    ns: Vec<Vec<f64>>,
    escalated: Vec<usize>,
    read_back: Duration,
    rounds: usize,
    /// With `--finish`, per cull in order: the f64 pass's times.
    finish: Vec<FinishTimes>,
}

/// The f64 finish pass after one cull's kernel: ns of one pass over the batch per round,
/// who answered the rays, and whether the times are the wall clock's (no timestamps:
/// both passes' wall time per repeat less the kernel's median).
struct FinishTimes {
    ns: Vec<f64>,
    counts: FinishCounts,
    wall: bool,
}

fn time_unit(
    resident: &ResidentRays<'_>,
    culls: &[GpuCull],
    share: f64,
    finish: bool,
) -> Result<UnitTimes, Box<dyn std::error::Error>> {
    // Warm-up: every contender once, each cull's verdicts counted.
    let mut escalated = Vec::with_capacity(culls.len());
    let mut read_back = Duration::MAX;
    resident.run_copy(1)?;
    for &cull in culls {
        resident.run(cull, 1)?;
        let (verdicts, took) = resident.read_back()?;
        read_back = read_back.min(took);
        escalated.push(
            verdicts
                .iter()
                .filter(|(v, _)| *v == F32Verdict::Escalate)
                .count(),
        );
    }
    let mut counts = Vec::new();
    if finish {
        for &cull in culls {
            resident.run_finished(cull, 1)?;
            counts.push(resident.finish_counts()?);
        }
    }
    let once = resident.run(GpuCull::NoCull, 1)?.wall;
    let repeats = (SUBMISSION.as_secs_f64() / once.as_secs_f64().max(1e-9)).ceil() as usize;
    let repeats = repeats.clamp(1, 1000);
    let contenders = culls.len() + 1;
    let finishers = if finish { culls.len() } else { 0 };
    let mut ns = vec![Vec::new(); contenders];
    // Per cull: the f64 pass's ns per round, and whether it is the wall clock's (both
    // passes, to be less the kernel's median).
    let mut finish_ns = vec![Vec::new(); finishers];
    let mut finish_wall = false;
    let start = Instant::now();
    let mut round = 0;
    while round < MIN_ROUNDS || start.elapsed().as_secs_f64() < share {
        for j in 0..contenders + finishers {
            // Rotated order: no contender always follows the same one.
            let k = (j + round) % (contenders + finishers);
            if k >= contenders {
                let f = k - contenders;
                let time = resident.run_finished(culls[f], repeats)?;
                if time.finish.is_empty() {
                    finish_wall = true;
                    finish_ns[f].push(time.wall.as_nanos() as f64 / repeats as f64);
                } else {
                    let total: Duration = time.finish.iter().sum();
                    finish_ns[f].push(total.as_nanos() as f64 / time.finish.len() as f64);
                }
                continue;
            }
            let time = if k == 0 {
                resident.run_copy(repeats)?
            } else {
                resident.run(culls[k - 1], repeats)?
            };
            ns[k].push(time.pass_ns(repeats));
        }
        round += 1;
    }
    let finish = finish_ns
        .into_iter()
        .zip(counts)
        .enumerate()
        .map(|(f, (mut times, counts))| {
            if finish_wall {
                let kernel = median(&ns[f + 1]);
                for t in &mut times {
                    *t = (*t - kernel).max(1.0);
                }
            }
            FinishTimes {
                ns: times,
                counts,
                wall: finish_wall,
            }
        })
        .collect();
    Ok(UnitTimes {
        ns,
        escalated,
        read_back,
        rounds: round,
        finish,
    })
}

fn median(ns: &[f64]) -> f64 {
    let mut v = ns.to_vec();
    torus_cull_lab::paired::median(&mut v)
}

/// A per-ray estimate from per-pass times: the median, with the fastest and slowest.
fn estimate(benchmark: &str, ns: &[f64], rays: f64) -> EstimateRecord {
    let lo = ns.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = ns.iter().copied().fold(0.0, f64::max);
    EstimateRecord {
        benchmark: benchmark.into(),
        elements: rays as u64,
        ns_per_element: median(ns) / rays,
        ns_per_element_ci: [lo / rays, hi / rays],
    }
}

/// The adapter, described and said on stdout; a software one is called out, so that
/// its figures are not taken for a GPU's. `wall_clock` says what a pass's wall clock
/// holds where the adapter has no timestamp queries.
pub(super) fn announce_adapter(gpu: &GpuIntersector, wall_clock: &str) -> std::io::Result<String> {
    let mut device = format!(
        "{} ({:?}, {:?})",
        gpu.adapter_name(),
        gpu.device_type(),
        gpu.backend()
    );
    if gpu.workgroup() != 64 {
        device.push_str(&format!("; workgroup {}", gpu.workgroup()));
    }
    if gpu.is_software() {
        device.push_str("; software adapter: a CPU proxy, no GPU timing claimed");
    }
    outln!("adapter: {device}")?;
    if gpu.is_software() {
        outln!(
            "the adapter is a CPU rasteriser (device type Cpu): these figures time \
             this CPU through {:?}, not a GPU",
            gpu.backend()
        )?;
    }
    if !gpu.has_timestamps() {
        outln!("the adapter has no timestamp queries: each pass is timed by {wall_clock}")?;
    }
    Ok(device)
}

/// The GPU kernel's culls among `culls` (default: all it has).
fn gpu_culls(culls: &[CullKind]) -> Result<Vec<GpuCull>, String> {
    if culls.len() == CullKind::TIMED.len() {
        return Ok(GpuCull::ALL.to_vec());
    }
    let allowed = || {
        GpuCull::ALL
            .iter()
            .map(|c| c.name())
            .collect::<Vec<_>>()
            .join(", ")
    };
    culls
        .iter()
        .map(|c| {
            GpuCull::ALL
                .iter()
                .copied()
                .find(|g| g.name() == c.name())
                .ok_or_else(|| {
                    format!(
                        "--culls: the GPU kernel has no {c} (allowed with time gpu: {})",
                        allowed()
                    )
                })
        })
        .collect()
}
