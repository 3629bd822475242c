//! `torus-cull run`: the rejection sweep of a workload, its tables, JSON and plots.

use super::CliResult;
use crate::console::{out, outln};
use indicatif::{ProgressBar, ProgressStyle};
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use torus_cull::Named;
use torus_cull_lab::measure::{self, CountedCull, FalseReject};
use torus_cull_lab::output;
use torus_cull_lab::report;
use torus_cull_lab::results::shapes::ShapeRecord;
use torus_cull_lab::results::{self, RejectionRecord, Results};
use torus_cull_lab::shape_sweep::{self, ShapeFalseReject};
use torus_cull_lab::workload::GenerateError;
use torus_cull_lab::workload::spec::{self, Workload};

/// Runs `run`.
pub fn run(
    workload: &Path,
    out: Option<PathBuf>,
    threads: Option<crate::whole::Whole>,
    no_plots: bool,
    culls: &[String],
) -> CliResult {
    let workload_path = workload;
    let workload = Workload::open(workload_path)?;
    let culls = parse_culls(culls)?;
    let threads = crate::threads::pick(threads)?;
    let path = out_path(out, &workload)?;
    // Before the sweep, not after it: an unwritable --out must not cost the whole run.
    output::check_writable(&path).map_err(|e| format!("--out {}: {e}", path.display()))?;
    if spec::built_in(workload_path).is_none() {
        output::check_not_input(("--out", &path), &[("--workload", workload_path)])?;
    }
    if let Some(shapes) = &workload.shapes {
        // Before the sweep: a bend the library does not build must not cost the run.
        shape_sweep::refuse_bends(shapes).map_err(|e| {
            format!(
                "workload {}: field `shapes.bends`: {e}",
                workload_path.display()
            )
        })?;
    }
    if !no_plots {
        crate::plot::check_plot_paths(&path)?;
    }
    let (records, false_rejects, (shape_records, shape_false_rejects)) =
        sweep(&workload, &culls, threads)?;
    let mut results = Results::new(&workload, "run");
    results.meta.sizes = Some(results::Sizes::rejection_only(workload.rays as u64));
    results.meta.threads = Some(threads as u64);
    results.rejection = records;
    results.shapes = shape_records;
    out!("{}", report::miss_capture_tables(&results))?;
    out!("{}", report::shape_tables(&results))?;
    print_false_reject_total(&results, &culls)?;
    results.save(&path)?;
    outln!("wrote {}", path.display())?;
    if !no_plots {
        crate::plot::write_plots(&results, &path)?;
    }
    if !false_rejects.is_empty() || !shape_false_rejects.is_empty() {
        report_false_rejects(&false_rejects, workload.seed);
        report_shape_false_rejects(&shape_false_rejects, workload.seed);
        eprintln!(
            "error: {} false rejects: a cull rejected rays the oracle calls hits",
            false_rejects.len() + shape_false_rejects.len()
        );
        return Ok(ExitCode::from(1));
    }
    Ok(ExitCode::SUCCESS)
}

/// `--culls`: timed culls and paper-as-printed variants by name; default every timed cull.
/// A cull named twice is counted once, in the place it was first named (as `time` does):
/// the records are keyed by cull, so a second copy would only repeat every record.
fn parse_culls(names: &[String]) -> Result<Vec<CountedCull>, String> {
    if names.is_empty() {
        return Ok(torus_cull::CullKind::TIMED.map(CountedCull::Timed).to_vec());
    }
    let mut culls: Vec<CountedCull> = Vec::new();
    for name in names {
        let cull = name
            .trim()
            .parse::<CountedCull>()
            .map_err(|e| format!("--culls: {e}"))?;
        if !culls.iter().any(|c| c.name() == cull.name()) {
            culls.push(cull);
        }
    }
    Ok(culls)
}

/// `--out`, or the default file under `results/` (its directory made if need be).
fn out_path(out: Option<PathBuf>, workload: &Workload) -> Result<PathBuf, String> {
    if let Some(path) = out {
        return Ok(path);
    }
    // `run` has its own default name, so that it never overwrites `cargo bench`'s file.
    let suffix = match workload.name.as_str() {
        "default" => "-run".to_string(),
        other => format!("-{other}-run"),
    };
    let path = results::default_path(Path::new("results"), &suffix);
    output::create_default_dir(&path).map_err(|e| format!("--out {}: {e}", path.display()))?;
    Ok(path)
}

/// The ring's sweep and the other shapes' records with their false rejects.
type Swept = (
    Vec<RejectionRecord>,
    Vec<FalseReject>,
    (Vec<ShapeRecord>, Vec<ShapeFalseReject>),
);

/// The rejection sweep of the ring, then of the workload's other shapes, with a progress
/// bar (or, off a terminal, a heartbeat) in rays.
fn sweep(workload: &Workload, culls: &[CountedCull], threads: usize) -> Result<Swept, String> {
    let units = measure::units(workload).len() as u64;
    let shape_rays = workload.shapes.as_ref().map_or(0, shape_sweep::rays);
    let total = units * workload.rays as u64 + shape_rays;
    let bar = ProgressBar::new(total).with_style(
        ProgressStyle::with_template("{msg} [{bar:40}] {pos}/{len} rays ({eta})")
            .expect("valid template")
            .progress_chars("=> "),
    );
    let members = workload
        .shapes
        .as_ref()
        .map_or(0, |s| s.family.len() + s.bends.len());
    let message = match members {
        0 => format!("{}: {} case x nu", workload.name, units),
        m => format!("{}: {} case x nu, {m} shapes", workload.name, units),
    };
    bar.set_message(message.clone());
    let heartbeat = crate::console::Heartbeat::new(format!("run {message}"), "rays");
    heartbeat.update(0, total);
    let progress = |n| {
        bar.inc(n);
        heartbeat.update(bar.position(), total);
    };
    let (records, false_rejects) = measure::rejection_sweep(workload, culls, threads, &progress)
        .map_err(|e: GenerateError| e.to_string())?;
    let shapes = match &workload.shapes {
        Some(spec) => shape_sweep::sweep(spec, culls, workload.seed, threads, &progress)?,
        None => (Vec::new(), Vec::new()),
    };
    bar.finish_and_clear();
    Ok((records, false_rejects, shapes))
}

/// The project's central claim, stated every time: the false rejects among the rays.
fn print_false_reject_total(results: &Results, culls: &[CountedCull]) -> std::io::Result<()> {
    // Each ray is counted once, with the first cull's records: every cull sees the same
    // rays.
    let of_one_cull = || {
        results
            .rejection
            .iter()
            .filter(|r| r.cull == culls[0].name())
    };
    let rays: u64 = of_one_cull().map(|r| r.rays).sum();
    let ambiguous: u64 = of_one_cull().map(|r| r.ambiguous).sum();
    let rejected_hits: u64 = results.rejection.iter().map(|r| r.false_rejects).sum();
    outln!(
        "{rejected_hits} false rejects in {rays} rays (each checked by {} culls; {ambiguous} \
         rays the oracle calls ambiguous are not counted)",
        culls.len()
    )?;
    if results.shapes.is_empty() {
        return Ok(());
    }
    // Each member's rays once: its records of the first cull.
    let first = || {
        results
            .shapes
            .iter()
            .filter(|r| r.counts.cull == culls[0].name())
    };
    let rays: u64 = first().map(|r| r.counts.rays).sum();
    let ambiguous: u64 = first().map(|r| r.counts.ambiguous).sum();
    let members = first().count();
    let rejected_hits: u64 = results.shapes.iter().map(|r| r.counts.false_rejects).sum();
    outln!(
        "{rejected_hits} false rejects in {rays} rays of {members} family members and bends \
         (each checked by every cull, a bend's also behind its wedge; {ambiguous} rays the \
         shapes' oracles call ambiguous are not counted)"
    )
}

/// The first 20 false rejects of the ring on stderr, each with what it takes to replay it.
fn report_false_rejects(false_rejects: &[FalseReject], workload_seed: u64) {
    for f in false_rejects.iter().take(20) {
        eprintln!(
            "FALSE REJECT: cull {} case {} nu {} ray #{} (workload seed {}, stream seed {:#x}): \
             origin {} dir {} margin {:e}",
            f.cull,
            f.case,
            f.nu,
            f.index,
            workload_seed,
            f.stream_seed,
            f.ray.origin(),
            f.ray.dir(),
            f.margin
        );
    }
}

/// The first 20 false rejects on the family and the bends on stderr, each with what it
/// takes to replay it.
fn report_shape_false_rejects(false_rejects: &[ShapeFalseReject], workload_seed: u64) {
    for f in false_rejects.iter().take(20) {
        eprintln!(
            "FALSE REJECT: cull {} on {} ray #{} (workload seed {workload_seed}; {}): origin \
             {} dir {} margin {:e}",
            f.cull, f.member, f.index, f.pose, f.origin, f.dir, f.margin
        );
    }
}
