//! The worker processes of a `--runs` timing (`time ring`, `time secondary`): each run is
//! this binary again, `time <subcommand> … --worker-run K --out <temp>`, one after the
//! other so that they never share the cores, each in a fresh code and data layout.

use super::args::Mode;
use std::ffi::OsString;
use std::path::Path;
use torus_cull::{CullKind, Named};
use torus_cull_lab::results::{RatioRecord, Results};

/// What every worker of a `--runs` timing is told to time: the parent's arguments as it
/// parsed them, with its share of the seconds.
pub(super) struct WorkerPlan<'a> {
    /// `ring` or `secondary`.
    pub subcommand: &'static str,
    pub workload: &'a Path,
    pub cases: &'a [String],
    pub culls: &'a [CullKind],
    pub nus: &'a [f64],
    pub seconds: f64,
    pub batch: usize,
    pub mode: Mode,
}

impl WorkerPlan<'_> {
    /// The command line of worker `run`, writing to `out`.
    fn args(&self, run: u64, out: &Path) -> Vec<OsString> {
        let mut args: Vec<OsString> = vec!["time".into(), self.subcommand.into()];
        args.push("--workload".into());
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
        args.push("--no-plots".into());
        args.push("--out".into());
        args.push(out.as_os_str().to_owned());
        args
    }
}

/// Each of `runs` independent runs' records, one worker process each. A worker that
/// fails fails the whole timing, with its exit status (its own message is on stderr
/// above): nothing is written.
pub(super) fn time_in_workers(
    plan: &WorkerPlan<'_>,
    runs: u64,
) -> Result<Vec<Vec<RatioRecord>>, String> {
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
    Ok(all)
}
