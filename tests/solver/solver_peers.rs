//! The peers of the solver bench scored by the oracle without timing them: the same
//! quartics as `cargo bench`'s solver group on the default workload (its seed and pose,
//! ν = 1.25, 2, 4, 8, 16, 2 048 lines each per family), each solver asked for the nearest
//! root at or after the ray's origin and scored by `NearestScore` (missed, spurious, the
//! worst |Δt|·|d|/(R + r)). Ours must miss and invent nothing; the peers' counts are
//! printed (`--nocapture`) for docs/solver.md.

use std::path::Path;
use torus_cull::quartic::{first_root_depressed, nearest_root_depressed, solve_depressed_monic};
use torus_cull_lab::solver_suite::{FAMILIES, NearestScore, family_cases};
use torus_cull_lab::workload::spec::Workload;

/// The bench's default timed ν (`benches/support/mod.rs`, `DEFAULT_TIMED_NU`).
const NUS: [f64; 5] = [1.25, 2.0, 4.0, 8.0, 16.0];
/// The bench's lines per ν and family at its default size.
const PER_NU: usize = 2048;

fn nearest_at_or_after(roots: &[f64], lo: f64) -> Option<f64> {
    roots
        .iter()
        .copied()
        .filter(|&u| u >= lo)
        .min_by(f64::total_cmp)
}

type Solver = (&'static str, fn(&[f64; 3], f64) -> Option<f64>);

const SOLVERS: [Solver; 6] = [
    ("torus_cull", |c, lo| {
        nearest_root_depressed(c[0], c[1], c[2], lo, f64::INFINITY)
    }),
    // Issue 61's bracketed walk, held to the same count.
    ("torus_cull_first", |c, lo| {
        first_root_depressed(c[0], c[1], c[2], lo, f64::INFINITY)
    }),
    ("torus_cull_all", |c, lo| {
        nearest_at_or_after(solve_depressed_monic(c[0], c[1], c[2]).as_slice(), lo)
    }),
    ("roots_0.0.8", |c, lo| {
        nearest_at_or_after(
            roots::find_roots_quartic(1.0, 0.0, c[0], c[1], c[2]).as_ref(),
            lo,
        )
    }),
    ("kurbo_0.13", |c, lo| {
        nearest_at_or_after(
            &kurbo::common::solve_quartic(c[2], c[1], c[0], 0.0, 1.0),
            lo,
        )
    }),
    // As the bench asks it: the roots in [lo, Cauchy's bound] to 1e-14 in u, sorted.
    ("polycool_0.4", |c, lo| {
        let bound = 1.0 + c[0].abs().max(c[1].abs()).max(c[2].abs());
        polycool::Quartic::new([c[2], c[1], c[0], 0.0, 1.0])
            .roots_between(lo, bound, 1e-14)
            .first()
            .copied()
    }),
];

#[test]
fn peers_scored_by_the_oracle_on_the_bench_families() {
    let workload = Workload::load(Path::new("workloads/default.json")).expect("default workload");
    let mut table = String::new();
    for family in FAMILIES {
        let cases = family_cases(
            family,
            &NUS,
            PER_NU,
            (workload.seed, workload.pose),
            workload.seed,
        )
        .expect("the family's cases");
        for (name, solve) in SOLVERS {
            let mut score = NearestScore::default();
            for case in &cases {
                score.add(case, solve(&case.c, case.u_origin));
            }
            table += &format!(
                "| {family} | {name} | {} | {} | {} | {} | {:.1e} |\n",
                score.sets, score.reference, score.missed, score.spurious, score.max_rel_t_error
            );
            if name.starts_with("torus_cull") {
                assert_eq!((score.missed, score.spurious), (0, 0), "{name} on {family}");
            }
        }
    }
    println!(
        "| family | solver | quartics | with a root | missed | spurious | max |Δt|·|d|/(R + r) |\n|---|---|---|---|---|---|---|\n{table}"
    );
}
