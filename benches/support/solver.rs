//! Quartic solvers on the same torus quartics, per line family: speed by criterion and
//! by a paired, interleaved ratio against `roots` 0.0.8, accuracy against the oracle's
//! high-precision reference roots.
//!
//! Every solver answers the renderer's question, the nearest root at or after the ray's
//! origin (t ≥ 0): ours directly (`torus_cull`: [`nearest_root_depressed`], the closed
//! form the scalar intersection uses; `torus_cull_first`: [`first_root_depressed`], issue
//! 61's bracketed walk, paired against it in one run), the all-roots solvers
//! (ours, `roots` 0.0.8, `kurbo` 0.13's Algorithm 1010) by solving and then picking, and
//! `polycool` 0.4 (Yuksel's monotone pieces) by its roots in `[lo, B]`.
//! Accuracy is counted on that nearest root by [`NearestScore`], the count
//! `tests/batch/batch_solve.rs` uses too.

use super::{BenchConfig, read_estimate};
use criterion::{BenchmarkId, Criterion};
use std::fmt::Write;
use std::hint::black_box;
use std::path::Path;
use std::time::{Duration, Instant, SystemTime};
use torus_cull::batch::{Dispatch, Quartics, nearest_roots};
use torus_cull::quartic::{first_root_depressed, nearest_root_depressed, solve_depressed_monic};
use torus_cull_lab::paired::stats::{QUIET_FRACTION, quiet_rounds};
use torus_cull_lab::paired::{Schedule, interleave, ratio_estimate};
use torus_cull_lab::results::{SolverPairedRatio, SolverRecord};
use torus_cull_lab::solver_suite::{NearestScore, SolverCase, family_cases};
use torus_cull_lab::workload::spec::Workload;

pub use torus_cull_lab::solver_suite::FAMILIES;

/// The family's quartics at the timed ν (lines the oracle calls ambiguous are left out).
pub fn family_sets(family: &str, workload: &Workload, config: &BenchConfig) -> Vec<SolverCase> {
    family_cases(
        family,
        &config.timed_nus(workload),
        config.batch.min(2048),
        (workload.seed, workload.pose),
        workload.seed,
    )
    .unwrap_or_else(|e| panic!("{e}"))
}

/// The nearest of `roots` at or after `lo`.
#[inline(always)]
fn nearest_at_or_after(roots: &[f64], lo: f64) -> Option<f64> {
    roots
        .iter()
        .copied()
        .filter(|&u| u >= lo)
        .min_by(f64::total_cmp)
}

#[inline(always)]
fn ours_first(c: &[f64; 3], lo: f64) -> Option<f64> {
    first_root_depressed(c[0], c[1], c[2], lo, f64::INFINITY)
}

#[inline(always)]
fn ours_nearest(c: &[f64; 3], lo: f64) -> Option<f64> {
    nearest_root_depressed(c[0], c[1], c[2], lo, f64::INFINITY)
}

#[inline(always)]
fn ours_all(c: &[f64; 3], lo: f64) -> Option<f64> {
    nearest_at_or_after(solve_depressed_monic(c[0], c[1], c[2]).as_slice(), lo)
}

#[inline(always)]
fn roots_crate(c: &[f64; 3], lo: f64) -> Option<f64> {
    nearest_at_or_after(
        roots::find_roots_quartic(1.0, 0.0, c[0], c[1], c[2]).as_ref(),
        lo,
    )
}

#[inline(always)]
fn kurbo_crate(c: &[f64; 3], lo: f64) -> Option<f64> {
    nearest_at_or_after(
        &kurbo::common::solve_quartic(c[2], c[1], c[0], 0.0, 1.0),
        lo,
    )
}

/// `polycool` 0.4 (linebender; C. Yuksel's method, HPG 2022: the roots of the derivative
/// split the interval into monotone pieces, each sign change bracketed and refined by
/// Newton's steps) asked for the roots in `[lo, B]`, B = 1 + max|cᵢ| (Cauchy's bound),
/// to an absolute 10⁻¹⁴ in u (about 50 ulps of the O(1) roots: the others' accuracy).
/// Its roots come sorted, so the first is the nearest.
#[inline(always)]
fn polycool_crate(c: &[f64; 3], lo: f64) -> Option<f64> {
    let bound = 1.0 + c[0].abs().max(c[1].abs()).max(c[2].abs());
    polycool::Quartic::new([c[2], c[1], c[0], 0.0, 1.0])
        .roots_between(lo, bound, POLYCOOL_X_ERROR)
        .first()
        .copied()
}

/// The absolute accuracy in u asked of `polycool`.
const POLYCOOL_X_ERROR: f64 = 1e-14;

/// A solver under test: its name and its nearest root u ≥ lo for one quartic.
pub type Solver = (&'static str, fn(&[f64; 3], f64) -> Option<f64>);

/// Ours first; the ratio tables compare everyone with `roots_0.0.8`.
pub const SOLVERS: [Solver; 6] = [
    ("torus_cull", ours_nearest),
    ("torus_cull_first", ours_first),
    ("torus_cull_all", ours_all),
    ("roots_0.0.8", roots_crate),
    ("kurbo_0.13", kurbo_crate),
    ("polycool_0.4", polycool_crate),
];

/// The batch solver ([`nearest_roots`]: every quartic of a family at once, on SIMD
/// lanes), timed per solve like the others.
pub const BATCH_SOLVER: &str = "torus_cull_batch";

/// Every solver's name, in table order: the scalar ones, then the batch solver.
pub fn solver_names() -> impl Iterator<Item = &'static str> {
    SOLVERS.iter().map(|(n, _)| *n).chain([BATCH_SOLVER])
}

/// The family's quartics as the batch solver takes them (nearest root u ≥ u_origin).
fn quartics(sets: &[SolverCase]) -> Quartics {
    let mut q = Quartics::new();
    for s in sets {
        q.push(s.c[0], s.c[1], s.c[2], s.u_origin, f64::INFINITY);
    }
    q
}

pub fn bench(c: &mut Criterion, families: &[(&str, Vec<SolverCase>)], dispatch: &Dispatch) {
    for (family, sets) in families {
        let mut group = c.benchmark_group(format!("solver-{family}"));
        for (name, solve) in SOLVERS {
            group.bench_function(BenchmarkId::new(name, "all"), |b| {
                b.iter(|| {
                    for s in sets {
                        black_box(solve(black_box(&s.c), s.u_origin));
                    }
                })
            });
        }
        let q = quartics(sets);
        let mut roots = Vec::new();
        group.bench_function(BenchmarkId::new(BATCH_SOLVER, "all"), |b| {
            b.iter(|| black_box(nearest_roots(dispatch, black_box(&q), &mut roots)))
        });
        group.finish();
    }
}

/// The peer every paired ratio is taken against.
const REFERENCE: &str = "roots_0.0.8";

/// Paired ratios t(solver) / t([`REFERENCE`]) on one family's quartics, in
/// [`solver_names`] order: every solver runs once over all of them per round, in a
/// shuffled order, for about 3 s at the default size (0.3 s or more), and the ratio is
/// the median over the quietest rounds, with its bootstrap interval ([`torus_cull_lab::paired`]).
fn paired_vs_roots(
    family: &str,
    sets: &[SolverCase],
    q: &Quartics,
    dispatch: &Dispatch,
    seed: u64,
) -> Vec<Option<SolverPairedRatio>> {
    let names: Vec<&str> = solver_names().collect();
    let Some(reference) = names.iter().position(|n| *n == REFERENCE) else {
        return vec![None; names.len()];
    };
    let schedule = Schedule {
        warm_up: Duration::from_millis(200),
        budget: Duration::from_secs_f64((sets.len() as f64 * 3e-4).clamp(0.3, 3.0)),
        min_rounds: 40,
        max_rounds: 100_000,
        seed,
    };
    let mut batch_roots = Vec::new();
    let rounds = interleave(names.len(), &schedule, |i| {
        let start = Instant::now();
        match SOLVERS.get(i) {
            Some((_, solve)) => {
                for s in sets {
                    black_box(solve(black_box(&s.c), s.u_origin));
                }
            }
            None => {
                black_box(nearest_roots(dispatch, black_box(q), &mut batch_roots));
            }
        }
        start.elapsed()
    });
    // As the cull ratios do: the rounds the operating system left alone, if most were.
    let clean = rounds.disturbed.iter().filter(|d| !**d).count();
    let eligible: Vec<bool> = if clean >= 20.max(rounds.len() / 4) {
        rounds.disturbed.iter().map(|d| !d).collect()
    } else {
        vec![true; rounds.len()]
    };
    let quiet = quiet_rounds(&rounds.ns, &eligible, QUIET_FRACTION);
    let pick = |i: usize| quiet.iter().map(|&k| rounds.ns[i][k]).collect::<Vec<f64>>();
    let work = sets.len().max(1) as f64;
    // The walk over the closed form on the same rounds (printed, not recorded: the
    // records pair with `roots`).
    let (new, old) = (
        names.iter().position(|n| *n == "torus_cull_first"),
        names.iter().position(|n| *n == "torus_cull"),
    );
    if let (Some(new), Some(old)) = (new, old) {
        if let Some(e) = ratio_estimate(&pick(new), &pick(old), work, seed ^ 0xf1) {
            println!(
                "solver-{family}: paired torus_cull_first / torus_cull {:.3} [{:.3}, {:.3}] over {} rounds",
                e.ratio, e.ratio_ci[0], e.ratio_ci[1], e.rounds
            );
        }
    }
    (0..names.len())
        .map(|i| {
            let e = ratio_estimate(&pick(i), &pick(reference), work, seed ^ i as u64)?;
            Some(SolverPairedRatio {
                ratio: e.ratio,
                ratio_ci: e.ratio_ci,
                rounds: e.rounds as u64,
                ns_per_solve: e.ns_per_ray,
            })
        })
        .collect()
}

/// Speed (from this run's estimates, and paired against `roots` 0.0.8) and accuracy of
/// each solver on each family.
pub fn records(
    home: &Path,
    families: &[(&str, Vec<SolverCase>)],
    since: SystemTime,
    dispatch: &Dispatch,
) -> Vec<SolverRecord> {
    let mut out = Vec::new();
    for (f, (family, sets)) in families.iter().enumerate() {
        let q = quartics(sets);
        let mut batch = Vec::new();
        nearest_roots(dispatch, &q, &mut batch);
        let paired = paired_vs_roots(family, sets, &q, dispatch, 0x5017_0000 + f as u64);
        for (name, paired) in solver_names().zip(paired) {
            let solve = SOLVERS.iter().find(|(n, _)| *n == name).map(|(_, f)| *f);
            let mut score = NearestScore::default();
            for (i, s) in sets.iter().enumerate() {
                let root = match solve {
                    Some(solve) => solve(&s.c, s.u_origin),
                    None => batch[i],
                };
                score.add(s, root);
            }
            let est = read_estimate(home, &format!("solver-{family}"), name, "all", since)
                .map(|e| e.scaled(1.0 / sets.len().max(1) as f64));
            let Some(est) = est else { continue };
            out.push(SolverRecord {
                solver: name.to_string(),
                family: family.to_string(),
                coefficient_sets: sets.len() as u64,
                reference_roots: score.reference,
                missed_roots: score.missed,
                spurious_roots: score.spurious,
                max_rel_t_error: score.max_rel_t_error,
                ns_per_solve: est.median,
                ns_per_solve_ci: [est.lower, est.upper],
                source: "criterion".into(),
                paired_vs_roots: paired,
            });
        }
    }
    out
}

pub fn table(records: &[SolverRecord]) -> String {
    let mut out = String::from(
        "quartic solvers, nearest root t ≥ 0, same quartics per family (ratio: ns vs roots_0.0.8 in this run;\n\
         paired: median per-round ratio vs roots_0.0.8, interleaved, [95 % interval]):\n",
    );
    let _ = writeln!(
        out,
        "  {:<14} {:<15} {:>9} {:>6} {:>19} {:>7} {:>7} {:>9} {:>11}",
        "family", "solver", "ns/solve", "ratio", "paired", "missed", "spur.", "sets", "max err"
    );
    for r in records {
        let peer = records
            .iter()
            .find(|p| p.family == r.family && p.solver == "roots_0.0.8")
            .map_or(f64::NAN, |p| r.ns_per_solve / p.ns_per_solve);
        let paired = r.paired_vs_roots.as_ref().map_or("-".to_string(), |p| {
            format!(
                "{:.2} [{:.2}, {:.2}]",
                p.ratio, p.ratio_ci[0], p.ratio_ci[1]
            )
        });
        let _ = writeln!(
            out,
            "  {:<14} {:<15} {:>9.1} {:>6.2} {:>19} {:>7} {:>7} {:>9} {:>11.2e}",
            r.family,
            r.solver,
            r.ns_per_solve,
            peer,
            paired,
            r.missed_roots,
            r.spurious_roots,
            r.coefficient_sets,
            r.max_rel_t_error
        );
    }
    out
}
