//! The checks and defaults every `time` subcommand shares: `--seconds`, `--batch`, the
//! workload's cases, ν and culls, the output path (checked before any measuring), the
//! results file's `meta.sizes`, and the plots.

use super::args::{Common, Pick};
use crate::whole::Whole;
use std::path::{Path, PathBuf};
use torus_cull::{CullKind, Named};
use torus_cull_lab::measure::CountedCull;
use torus_cull_lab::number::Num;
use torus_cull_lab::paired::sweep::{DEFAULT_BATCH, REFERENCES};
use torus_cull_lab::results::{self, Results};
use torus_cull_lab::workload::spec::{self, Workload};

/// The longest `--seconds` accepted: an hour.
const MAX_SECONDS: f64 = 3600.0;

/// The smallest batch: below it a timing is mostly the clock.
pub(super) const MIN_BATCH: usize = 16;

/// The most `--runs`.
pub(super) const MAX_RUNS: u64 = 100;

/// The workload of `--workload` with the cases of `--cases`, the culls of `--culls` and
/// the ν of `--nu`, once `--seconds` is checked: what `time ring`, `secondary` and `gpu`
/// time.
pub(super) fn picked(common: &Common, pick: &Pick) -> Result<Picked, Box<dyn std::error::Error>> {
    let mut workload = Workload::open(&common.workload)?;
    pick_cases(&pick.cases, &mut workload, &common.workload)?;
    let culls = parse_culls(&pick.culls)?;
    let nus = pick_nus(&pick.nu, &workload, &common.workload)?;
    check_seconds(common.seconds)?;
    Ok(Picked {
        workload,
        culls,
        nus,
    })
}

/// What [`picked`] gives: the workload (its cases those picked), the culls and the ν.
pub(super) struct Picked {
    pub workload: Workload,
    pub culls: Vec<CullKind>,
    pub nus: Vec<f64>,
}

/// `--seconds`: positive, finite and at most [`MAX_SECONDS`].
pub(super) fn check_seconds(seconds: f64) -> Result<(), String> {
    if !(seconds.is_finite() && seconds > 0.0 && seconds <= MAX_SECONDS) {
        return Err(format!(
            "--seconds {} is invalid (allowed: 0 < seconds <= {MAX_SECONDS})",
            Num(seconds)
        ));
    }
    Ok(())
}

/// The least time a run may have: below it a run is mostly its warm-up and its process
/// start.
pub(super) const MIN_RUN_SECONDS: f64 = 0.25;

/// `--runs` of `seconds`: each run at least [`MIN_RUN_SECONDS`].
pub(super) fn check_run_seconds(runs: u64, seconds: f64) -> Result<(), String> {
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

/// `--runs`: `asked` within 1 ..= [`MAX_RUNS`], or `default`.
pub(super) fn pick_runs(asked: Option<Whole>, default: u64) -> Result<u64, String> {
    asked.map_or(Ok(default), |r| r.within("--runs", (1, MAX_RUNS), ""))
}

/// `--batch`: at least [`MIN_BATCH`] and at most the workload's rays (`file` names it);
/// default [`DEFAULT_BATCH`], or the workload's rays if fewer.
pub(super) fn pick_batch(
    asked: Option<Whole>,
    workload: &Workload,
    file: &Path,
) -> Result<usize, String> {
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

/// The culls to report: the timed ones by name (the paper-as-printed variants reject hits
/// and are not worth timing), default all.
pub(super) fn parse_culls(names: &[String]) -> Result<Vec<CullKind>, String> {
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
    if !asked.is_empty() {
        workload
            .cases
            .retain(|c| asked.iter().any(|name| name == c.name()));
    }
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
                Num(nu),
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

/// The default file's suffix for a timing of `kind` (`""` for the ring's, `secondary`,
/// `gpu`, `bvh`): the workload unless `default`, then the kind, then `time`, so that no
/// kind replaces another's file of the same commit (as `run` names its files).
pub(super) fn time_suffix(workload: &str, kind: &str) -> String {
    let mut suffix = String::new();
    for part in [workload, kind] {
        if !part.is_empty() && part != "default" {
            suffix += &format!("-{part}");
        }
    }
    suffix + "-time"
}

/// Where a subcommand writes: `--out`, or the default file under `results/` named by
/// `suffix` (its directory made if need be); checked writable, its plots' paths too
/// unless `--no-plots` or `worker`, and never one of the inputs, before any measuring.
pub(super) fn out_path(common: &Common, suffix: &str, worker: bool) -> Result<PathBuf, String> {
    let path = match &common.out {
        Some(path) => path.clone(),
        None => {
            let path = results::default_path(Path::new("results"), suffix);
            torus_cull_lab::output::create_default_dir(&path)
                .map_err(|e| format!("--out {}: {e}", path.display()))?;
            path
        }
    };
    torus_cull_lab::output::check_writable(&path)
        .map_err(|e| format!("--out {}: {e}", path.display()))?;
    if !common.no_plots && !worker {
        crate::plot::check_plot_paths(&path)?;
    }
    if spec::built_in(&common.workload).is_none() {
        torus_cull_lab::output::check_not_input(
            ("--out", &path),
            &[("--workload", &common.workload)],
        )?;
    }
    Ok(path)
}

/// `meta.sizes` of a timing on one thread: what was timed, so that compare can tell files
/// of other batches apart.
pub(super) fn timing_sizes(batch: usize, nus: &[f64]) -> results::Sizes {
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

/// Saves `results` to `path`, says so, and draws its plots unless `--no-plots`.
pub(super) fn save(
    results: &Results,
    path: &Path,
    common: &Common,
) -> Result<(), Box<dyn std::error::Error>> {
    results
        .save(path)
        .map_err(|e| format!("{}: {e}", path.display()))?;
    crate::console::outln!("wrote {}", path.display())?;
    if !common.no_plots {
        crate::plot::write_plots(results, path)?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::time_suffix;

    #[test]
    fn every_kind_of_timing_has_its_own_default_name() {
        assert_eq!(time_suffix("default", ""), "-time");
        assert_eq!(time_suffix("default", "gpu"), "-gpu-time");
        assert_eq!(time_suffix("quick", ""), "-quick-time");
        assert_eq!(time_suffix("quick", "gpu"), "-quick-gpu-time");
        assert_eq!(time_suffix("default", "secondary"), "-secondary-time");
        assert_eq!(time_suffix("quick", "secondary"), "-quick-secondary-time");
        assert_eq!(time_suffix("default", "bvh"), "-bvh-time");
        assert_eq!(time_suffix("quick", "bvh"), "-quick-bvh-time");
        assert_eq!(time_suffix("", "family"), "-family-time");
    }
}
