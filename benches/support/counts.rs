//! The count channel of a complete bench: `torus-cull count`'s records (instructions per
//! ray under callgrind, `torus_cull_lab::count`) at the bench's timed ν and batch, added to
//! the results file beside the paired ratios, so that `compare` of two bench files judges
//! both channels. The worker is the `torus-cull` binary cargo builds with the bench.

use super::BenchConfig;
use torus_cull_lab::count::{MAX_RAYS, MIN_RAYS, Plan, PlanArgs};
use torus_cull_lab::results::Results;
use torus_cull_lab::workload::spec::Workload;

/// Fills `results.counts` and `meta.counts`; where valgrind is missing says so in one
/// line (naming the package) and leaves them empty: a bench is not refused for it.
pub fn add(
    results: &mut Results,
    config: &BenchConfig,
    (path, workload): (&std::path::Path, &Workload),
) {
    let args = PlanArgs {
        nu: config.timed_nus(workload),
        rays: Some(config.batch.clamp(MIN_RAYS, MAX_RAYS)),
        ..PlanArgs::default()
    };
    let exe = std::path::Path::new(env!("CARGO_BIN_EXE_torus-cull"));
    let counted = Plan::new(workload.clone(), path, &args)
        .and_then(|plan| torus_cull_lab::count::count(exe, path, &plan));
    match counted {
        Ok((meta, records)) => {
            results.meta.counts = Some(meta);
            results.counts = records;
        }
        Err(e) => eprintln!("warning: no instruction counts in this file: {e}"),
    }
}
