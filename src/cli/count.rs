//! `torus-cull count`: instructions per ray under callgrind for every region of a plan
//! (`torus_cull_lab::count`), written as the `counts` section of a results file, or added
//! to an existing one (`--add-to`, e.g. a `time` file, so that `compare` judges both
//! channels record by record).

use crate::console::{out, outln};
use crate::whole::Whole;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use torus_cull_lab::count::{self, MAX_RAYS, MIN_RAYS, Plan, PlanArgs};
use torus_cull_lab::results::{self, Results};
use torus_cull_lab::workload::spec::Workload;

/// `torus-cull count`'s arguments.
#[derive(clap::Args)]
pub struct CountArgs {
    /// Workload: `quick` or `default` (built into the binary), or a workload file.
    #[arg(long, default_value = "quick")]
    workload: PathBuf,
    /// Rays per case × ν: the first rays of each (case, ν) stream, as `time` draws its
    /// batch (default 1024, or the workload's rays if fewer), 4 ..= 65536. The solver
    /// families take as many quartics per ν.
    #[arg(long)]
    rays: Option<Whole>,
    /// Culls to count, comma-separated (default: every timed cull). The references
    /// cychosz and none are counted in any case.
    #[arg(long, value_delimiter = ',')]
    culls: Vec<String>,
    /// Cases to count, comma-separated, each one of the workload's (default: all).
    #[arg(long, value_delimiter = ',')]
    cases: Vec<String>,
    /// ν values to count, comma-separated, each one of the workload's (default: all; the
    /// solver families' quartics are drawn at these ν).
    #[arg(long, value_delimiter = ',')]
    nu: Vec<f64>,
    /// Paths to count, comma-separated: `scalar` (each cull alone and cull + exact
    /// intersection, one ray at a time), `batch` (the wavefront at the dispatch level:
    /// f64, the SIMD cull alone, certified f32), `solver` (the quartic solver on each
    /// line family), `bvh` (closest and any hit in the workload's BVH scenes), `family`
    /// (the torus family's members), `bend` (the pipe bends, with and without the
    /// wedge). Default: all.
    #[arg(long, value_delimiter = ',')]
    paths: Vec<String>,
    /// Results JSON (default: results/<short commit>[-dirty]-<workload>-count.json, or
    /// …-count.json for the workload named `default`). Its directory must exist.
    #[arg(long, conflicts_with = "add_to")]
    out: Option<PathBuf>,
    /// Add the counts to this existing results file of the same workload (a `time` file,
    /// say) instead of writing a new one, replacing any counts it had: `compare` then
    /// says per record which channel moved.
    #[arg(long)]
    add_to: Option<PathBuf>,
    /// Internal: this process is the worker under callgrind, its plan in this file
    /// (announces its regions on stdout, writes no file).
    #[arg(long, hide = true, conflicts_with_all = ["rays", "culls", "cases", "nu", "paths", "out", "add_to"])]
    worker: Option<PathBuf>,
}

/// Runs `torus-cull count`.
pub fn run(args: CountArgs) -> Result<ExitCode, Box<dyn std::error::Error>> {
    if let Some(file) = &args.worker {
        let plan = count::WorkerPlan::load(file)?;
        count::work(&plan, std::io::stdout().lock())?;
        return Ok(ExitCode::SUCCESS);
    }
    let workload = Workload::open(&args.workload)?;
    let rays = match args.rays {
        Some(n) => Some(n.within("--rays", (MIN_RAYS, MAX_RAYS), "")?),
        None => None,
    };
    let plan_args = PlanArgs {
        culls: args.culls.clone(),
        cases: args.cases.clone(),
        nu: args.nu.clone(),
        rays,
        paths: args.paths.clone(),
    };
    let plan = Plan::new(workload.clone(), &args.workload, &plan_args)?;
    // The file to add to is read before the minute of counting, so a bad one fails fast.
    let target = match &args.add_to {
        Some(path) => {
            let existing = Results::load(path)?;
            if existing.meta.workload_sha256 != workload.sha256 {
                return Err(format!(
                    "--add-to {}: its workload (field `meta.workload_sha256`, {} {}) is not \
                     --workload {} ({}): counts of other rays would pair with its records",
                    path.display(),
                    existing.meta.workload,
                    short(&existing.meta.workload_sha256),
                    args.workload.display(),
                    short(&workload.sha256)
                )
                .into());
            }
            Some((path.clone(), existing))
        }
        None => None,
    };
    let start = std::time::Instant::now();
    let exe = std::env::current_exe().map_err(|e| format!("this binary's path: {e}"))?;
    let (meta, records) = count::count(&exe, &args.workload, &plan)?;
    let (path, mut file) = match target {
        Some((path, existing)) => (path, existing),
        None => {
            let path = match &args.out {
                Some(p) => p.clone(),
                None => results::default_path(Path::new("results"), &suffix(&workload.name)),
            };
            (path, Results::new(&workload, "count"))
        }
    };
    file.meta.counts = Some(meta.clone());
    file.counts = records;
    file.save(&path)?;
    out!("{}", table(&file.counts))?;
    outln!(
        "{} count records ({} rays per case × ν; {}, dispatch {} under valgrind) in {:.0} s: {}",
        file.counts.len(),
        meta.rays,
        meta.valgrind,
        meta.isa,
        start.elapsed().as_secs_f64(),
        path.display()
    )?;
    Ok(ExitCode::SUCCESS)
}

fn short(s: &str) -> &str {
    &s[..s.len().min(12)]
}

/// The default file's suffix: `-count` for the `default` workload, `-<name>-count` else.
fn suffix(workload: &str) -> String {
    if workload == "default" {
        "-count".into()
    } else {
        format!("-{workload}-count")
    }
}

/// Per metric and cull: the mean instructions per ray over the case × ν records, and the
/// geometric mean of the count ratios over `cychosz`.
fn table(records: &[results::counts::CountRecord]) -> String {
    use std::fmt::Write;
    let mut keys: Vec<(String, String)> = Vec::new();
    for r in records {
        let k = (r.metric.clone(), r.cull.clone());
        if !keys.contains(&k) {
            keys.push(k);
        }
    }
    let mut s = String::new();
    let _ = writeln!(
        s,
        "{:<16} {:<18} {:>8} {:>12} {:>14}",
        "metric", "cull", "records", "instr/ray", "over cychosz"
    );
    for (metric, cull) in keys {
        let of: Vec<_> = records
            .iter()
            .filter(|r| r.metric == metric && r.cull == cull)
            .collect();
        let mean = of.iter().map(|r| r.per_ray).sum::<f64>() / of.len() as f64;
        let ratios: Vec<f64> = of.iter().filter_map(|r| r.ratio).collect();
        let ratio = if ratios.is_empty() {
            "-".to_string()
        } else {
            let g = (ratios.iter().map(|x| x.ln()).sum::<f64>() / ratios.len() as f64).exp();
            format!("{g:.3}")
        };
        let _ = writeln!(
            s,
            "{metric:<16} {cull:<18} {:>8} {mean:>12.1} {ratio:>14}",
            of.len()
        );
    }
    s
}
