//! `torus-cull time gpu-submissions`: the single-torus
//! kernel's submissions one by one (issue 60, item 3; **not yet run on a GPU**). On an
//! H100, exactly 2²⁰ rays ran 3–5× slower than 2²⁰ ± 64, for every cull and the copy
//! kernel alike (docs/gpu.md, "Batch size on the H100"); `time gpu` reports only
//! each contender's median. Here every submission's wall time and device times are
//! logged, per batch size and contender (the copy kernel and each cull asked for), the
//! contenders in an order rotated from submission to submission, so that a slow state that
//! comes and goes, one that follows the batch or one that follows a contender can be told
//! apart.
//!
//! The rays are drawn once at the largest batch (the workload's generator, one case and
//! ν) and each batch is a prefix of them, uploaded afresh ([`GpuIntersector::upload`]).
//! Written: a results file of `estimates` (`gpu_submission_ns-<case>/<contender>/<batch>`:
//! the median device time per ray of one pass, the fastest and slowest submission as its
//! range) and, next to it, `<stem>-submissions.csv`: one line per submission.

use crate::whole::Whole;
use std::error::Error;
use std::path::PathBuf;
use std::process::ExitCode;

/// `torus-cull time gpu-submissions`'s arguments.
#[derive(clap::Args)]
pub struct SubmissionsArgs {
    /// Workload whose generator draws the rays: `default` or `quick` (built in), or a file.
    #[arg(long, default_value = "default")]
    workload: PathBuf,
    /// The workload's case to draw (default uniform).
    #[arg(long, default_value = "uniform")]
    case: String,
    /// ν of the torus (default 4).
    #[arg(long, default_value_t = 4.0)]
    nu: f64,
    /// Batch sizes, comma-separated, each 16 ..= 2^26 (default: 2^20, 2^20 − 64, 2^20 +
    /// 64, then 2^21 … 2^26).
    #[arg(long, value_delimiter = ',')]
    batches: Vec<Whole>,
    /// GPU culls, comma-separated (default none,discriminant); the copy kernel in any case.
    #[arg(long, value_delimiter = ',')]
    culls: Vec<String>,
    /// Submissions per contender and batch, 1 ..= 1000.
    #[arg(long, default_value_t = Whole(10))]
    submissions: Whole,
    /// Passes over the batch in each submission, 1 ..= 100.
    #[arg(long, default_value_t = Whole(1))]
    repeats: Whole,
    /// Results JSON (default: under results/, named by commit, workload and
    /// gpu-submissions); the log is written next to it as <stem>-submissions.csv. Its
    /// directory must exist.
    #[arg(long)]
    out: Option<PathBuf>,
}

/// Runs `torus-cull time gpu-submissions`.
#[cfg(not(feature = "gpu"))]
pub fn run(_args: &SubmissionsArgs) -> Result<ExitCode, Box<dyn Error>> {
    Err(
        "time gpu-submissions needs a binary built with the feature gpu: \
         cargo run --release --features gpu -- time gpu-submissions"
            .into(),
    )
}

/// Runs `torus-cull time gpu-submissions`.
#[cfg(feature = "gpu")]
pub fn run(args: &SubmissionsArgs) -> Result<ExitCode, Box<dyn Error>> {
    measure::run(args)
}

#[cfg(feature = "gpu")]
mod measure {
    use super::SubmissionsArgs;
    use crate::console::outln;
    use std::error::Error;
    use std::fmt::Write as _;
    use std::path::{Path, PathBuf};
    use std::process::ExitCode;
    use std::time::{Duration, Instant};
    use torus_cull::Named;
    use torus_cull::gpu::{GpuCull, GpuIntersector};
    use torus_cull_lab::number::Num;
    use torus_cull_lab::results::{self, EstimateRecord, Results};
    use torus_cull_lab::workload::spec::Workload;
    use torus_cull_lab::workload::{Case, generate};

    /// The most rays a batch: 64 bytes each on the device and a record each for the read
    /// back, a few GiB at 2²⁶.
    const MAX_BATCH: usize = 1 << 26;

    /// A line on stderr at least this often.
    const EVERY: Duration = Duration::from_secs(5);

    pub(super) fn run(args: &SubmissionsArgs) -> Result<ExitCode, Box<dyn Error>> {
        let workload = Workload::open(&args.workload)?;
        let case: Case = workload
            .cases
            .iter()
            .copied()
            .find(|c| c.name() == args.case)
            .ok_or_else(|| {
                let have: Vec<&str> = workload.cases.iter().map(|c| c.name()).collect();
                format!(
                    "--case {} is not in workload {} (allowed: {})",
                    args.case,
                    args.workload.display(),
                    have.join(", ")
                )
            })?;
        if !(args.nu.is_finite() && args.nu > 1.0) {
            return Err(
                format!("--nu {} is invalid (allowed: nu > 1, finite)", Num(args.nu)).into(),
            );
        }
        let batches: Vec<usize> = if args.batches.is_empty() {
            let mut b = vec![1 << 20, (1 << 20) - 64, (1 << 20) + 64];
            b.extend((21..=26).map(|p| 1usize << p));
            b
        } else {
            args.batches
                .iter()
                .map(|b| b.within("--batches", (16, MAX_BATCH), ""))
                .collect::<Result<_, _>>()?
        };
        let names = if args.culls.is_empty() {
            vec!["none".to_string(), "discriminant".to_string()]
        } else {
            args.culls.clone()
        };
        let culls = names
            .iter()
            .map(|n| {
                GpuCull::ALL
                    .iter()
                    .copied()
                    .find(|c| c.name() == n.trim())
                    .ok_or_else(|| {
                        let allowed: Vec<&str> = GpuCull::ALL.iter().map(|c| c.name()).collect();
                        format!(
                            "--culls: '{}' is not a GPU cull (allowed: {})",
                            n.trim(),
                            allowed.join(", ")
                        )
                    })
            })
            .collect::<Result<Vec<_>, _>>()?;
        let submissions = args.submissions.within("--submissions", (1, 1000), "")?;
        let repeats = args.repeats.within("--repeats", (1, 100), "")?;
        let path = match &args.out {
            Some(p) => p.clone(),
            None => {
                let suffix = if workload.name == "default" {
                    "-gpu-submissions".to_string()
                } else {
                    format!("-{}-gpu-submissions", workload.name)
                };
                let p = results::default_path(Path::new("results"), &suffix);
                torus_cull_lab::output::create_default_dir(&p)
                    .map_err(|e| format!("--out {}: {e}", p.display()))?;
                p
            }
        };
        torus_cull_lab::output::check_writable(&path)
            .map_err(|e| format!("--out {}: {e}", path.display()))?;
        let csv = log_path(&path);
        torus_cull_lab::output::check_writable(&csv)
            .map_err(|e| format!("the log {}: {e}", csv.display()))?;

        let gpu = GpuIntersector::new()?;
        let mut device = format!(
            "{} ({:?}, {:?})",
            gpu.adapter_name(),
            gpu.device_type(),
            gpu.backend()
        );
        if gpu.is_software() {
            device.push_str("; software adapter: a CPU proxy, no GPU timing claimed");
        }
        outln!(
            "adapter: {device}; timestamps {}",
            if gpu.has_timestamps() {
                "yes"
            } else {
                "no (wall clock only)"
            }
        )?;
        let largest = *batches.iter().max().expect("at least one batch");
        let start = Instant::now();
        eprintln!(
            "time gpu-submissions: drawing {largest} rays of {} at nu = {}",
            case.name(),
            Num(args.nu)
        );
        let batch = generate(case, args.nu, largest, workload.seed, workload.pose)?;
        eprintln!(
            "time gpu-submissions: drawn in {:.1} s",
            start.elapsed().as_secs_f64()
        );
        let mut log = String::from("batch,contender,submission,order,repeats,wall_ns,device_ns\n");
        let mut estimates = Vec::new();
        let mut last = Instant::now();
        outln!(
            "{:>9} {:<13} {:>11} {:>11} {:>11} {:>12}",
            "batch",
            "contender",
            "median ns",
            "min ns/ray",
            "max ns/ray",
            "wall ms/sub"
        )?;
        for (b, &n) in batches.iter().enumerate() {
            let resident = gpu.upload(&batch.torus, &batch.rays[..n])?;
            // Warm-up: every contender once, not logged.
            resident.run_copy(1)?;
            for &c in &culls {
                resident.run(c, 1)?;
            }
            let contenders = 1 + culls.len();
            let mut per_ray: Vec<Vec<f64>> = vec![Vec::new(); contenders];
            let mut walls: Vec<Vec<f64>> = vec![Vec::new(); contenders];
            for s in 0..submissions {
                for j in 0..contenders {
                    let k = (j + s) % contenders;
                    let time = if k == 0 {
                        resident.run_copy(repeats)?
                    } else {
                        resident.run(culls[k - 1], repeats)?
                    };
                    let name = contender(&culls, k);
                    let device_ns: Vec<String> = time
                        .device
                        .iter()
                        .map(|d| d.as_nanos().to_string())
                        .collect();
                    writeln!(
                        log,
                        "{n},{name},{s},{j},{repeats},{},{}",
                        time.wall.as_nanos(),
                        device_ns.join(";")
                    )?;
                    per_ray[k].push(time.pass_ns(repeats) / n as f64);
                    walls[k].push(time.wall.as_secs_f64() * 1e3);
                    if last.elapsed() >= EVERY {
                        last = Instant::now();
                        eprintln!(
                            "time gpu-submissions: batch {} of {} ({n} rays), submission {} of {submissions}, {:.0} s",
                            b + 1,
                            batches.len(),
                            s + 1,
                            start.elapsed().as_secs_f64()
                        );
                    }
                }
            }
            for k in 0..contenders {
                let name = contender(&culls, k);
                let v = &per_ray[k];
                let lo = v.iter().copied().fold(f64::INFINITY, f64::min);
                let hi = v.iter().copied().fold(0.0, f64::max);
                let med = median(v);
                outln!(
                    "{n:>9} {name:<13} {med:>11.4} {lo:>11.4} {hi:>11.4} {:>12.3}",
                    median(&walls[k])
                )?;
                estimates.push(EstimateRecord {
                    benchmark: format!("gpu_submission_ns-{}/{name}/{n}", case.name()),
                    elements: n as u64,
                    ns_per_element: med,
                    ns_per_element_ci: [lo, hi],
                });
            }
        }
        torus_cull_lab::output::write_file(&csv, log.as_bytes())
            .map_err(|e| format!("the log {}: {e}", csv.display()))?;
        let mut results = Results::new(&workload, "time");
        results.estimates = estimates;
        results.meta.device = Some(device);
        results.meta.threads = Some(1);
        results.save(&path)?;
        outln!("wrote {} and {}", path.display(), csv.display())?;
        Ok(ExitCode::SUCCESS)
    }

    /// Contender `k`'s name: the copy kernel first, then the culls.
    fn contender(culls: &[GpuCull], k: usize) -> &'static str {
        if k == 0 { "copy" } else { culls[k - 1].name() }
    }

    fn median(v: &[f64]) -> f64 {
        let mut v = v.to_vec();
        torus_cull_lab::paired::median(&mut v)
    }

    /// `<stem>-submissions.csv` beside the results file.
    fn log_path(path: &Path) -> PathBuf {
        let stem = path
            .file_stem()
            .map_or("results".into(), |s| s.to_string_lossy().into_owned());
        path.with_file_name(format!("{stem}-submissions.csv"))
    }
}
