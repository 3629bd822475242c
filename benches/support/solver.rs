//! Our quartic solver against the `roots` crate, on the same coefficient sets: speed by
//! criterion, accuracy against the oracle's high-precision reference roots.

use super::{BenchConfig, read_estimate};
use criterion::{BenchmarkId, Criterion};
use glam::DVec3;
use std::fmt::Write;
use std::hint::black_box;
use std::path::Path;
use std::time::SystemTime;
use torus_cull::intersect::quartic_coefficients_local;
use torus_cull::oracle::{OracleClass, classify_line, reference_roots};
use torus_cull::quartic::solve_quartic;
use torus_cull::results::SolverRecord;
use torus_cull::workload::spec::Workload;
use torus_cull::workload::{Case, generate};

/// A root counts as found when it is within this distance, × (R + r), of the reference.
pub const MATCH_TOLERANCE_REL: f64 = 1e-6;

/// One quartic from one line, with what it takes to map its roots u back to t.
pub struct SolverSet {
    pub coefficients: [f64; 5],
    major: f64,
    minor: f64,
    foot_offset: f64,
    inv_len: f64,
    len: f64,
    reference: Vec<f64>,
}

impl SolverSet {
    fn t_of_u(&self, u: f64) -> f64 {
        (u * self.major - self.foot_offset) * self.inv_len
    }
}

/// The quartics of the uniform and grazing batches at the timed ν (lines the oracle calls
/// ambiguous are left out: their tangent roots are not defined to better than the band).
pub fn coefficient_sets(workload: &Workload, config: &BenchConfig) -> Vec<SolverSet> {
    let mut sets = Vec::new();
    for case in [Case::Uniform, Case::Grazing] {
        for nu in config.timed_nus(workload) {
            let b = generate(
                case,
                nu,
                config.batch.min(2048),
                workload.seed,
                workload.pose,
            )
            .unwrap_or_else(|e| panic!("{e}"));
            let t = &b.torus;
            let (major, minor) = (t.major_radius() as f64, t.minor_radius() as f64);
            for ray in &b.rays {
                if classify_line(t, ray).class == OracleClass::Ambiguous {
                    continue;
                }
                let (o, d): (DVec3, DVec3) = t.line_to_local_f64(ray);
                let len = d.length();
                sets.push(SolverSet {
                    coefficients: quartic_coefficients_local(major, minor, o, d),
                    major,
                    minor,
                    foot_offset: o.dot(d / len),
                    inv_len: 1.0 / len,
                    len,
                    reference: reference_roots(
                        t.center().as_dvec3(),
                        t.axis().as_dvec3(),
                        major,
                        minor,
                        ray.origin().as_dvec3(),
                        ray.dir().as_dvec3(),
                        f64::NEG_INFINITY,
                        f64::INFINITY,
                    ),
                });
            }
        }
    }
    sets
}

fn ours(c: &[f64; 5]) -> Vec<f64> {
    solve_quartic(*c).as_slice().to_vec()
}

fn peer(c: &[f64; 5]) -> Vec<f64> {
    roots::find_roots_quartic(c[0], c[1], c[2], c[3], c[4])
        .as_ref()
        .to_vec()
}

/// A solver under test: its name and its roots for one coefficient set.
pub type Solver = (&'static str, fn(&[f64; 5]) -> Vec<f64>);

pub const SOLVERS: [Solver; 2] = [("torus_cull", ours), ("roots_0.0.8", peer)];

pub fn bench(c: &mut Criterion, sets: &[SolverSet]) {
    let mut group = c.benchmark_group("solver");
    group.bench_function(BenchmarkId::new("torus_cull", "all"), |b| {
        b.iter(|| {
            for s in sets {
                black_box(solve_quartic(black_box(s.coefficients)));
            }
        })
    });
    group.bench_function(BenchmarkId::new("roots_0.0.8", "all"), |b| {
        b.iter(|| {
            for s in sets {
                let c = black_box(s.coefficients);
                black_box(roots::find_roots_quartic(c[0], c[1], c[2], c[3], c[4]));
            }
        })
    });
    group.finish();
}

/// Speed (from this run's estimates) and accuracy of each solver.
pub fn records(home: &Path, sets: &[SolverSet], since: SystemTime) -> Vec<SolverRecord> {
    SOLVERS
        .iter()
        .map(|(name, solve)| {
            let (mut missed, mut spurious, mut reference, mut max_err) = (0u64, 0u64, 0u64, 0f64);
            for s in sets {
                let scale = (s.major + s.minor) * s.inv_len;
                let tol = MATCH_TOLERANCE_REL * scale;
                let found: Vec<f64> = solve(&s.coefficients)
                    .into_iter()
                    .map(|u| s.t_of_u(u))
                    .collect();
                reference += s.reference.len() as u64;
                for &r in &s.reference {
                    let nearest = found
                        .iter()
                        .map(|&t| (t - r).abs())
                        .fold(f64::INFINITY, f64::min);
                    if nearest > tol {
                        missed += 1;
                    } else {
                        max_err = max_err.max(nearest * s.len / (s.major + s.minor));
                    }
                }
                spurious += found
                    .iter()
                    .filter(|&&t| s.reference.iter().all(|&r| (t - r).abs() > tol))
                    .count() as u64;
            }
            let est = read_estimate(home, "solver", name, "all", since)
                .map(|e| e.scaled(1.0 / sets.len().max(1) as f64));
            SolverRecord {
                solver: name.to_string(),
                coefficient_sets: sets.len() as u64,
                reference_roots: reference,
                missed_roots: missed,
                spurious_roots: spurious,
                max_rel_t_error: max_err,
                ns_per_solve: est.map_or(f64::NAN, |e| e.median),
                ns_per_solve_ci: est.map_or([f64::NAN; 2], |e| [e.lower, e.upper]),
                source: "criterion".into(),
            }
        })
        .filter(|r| r.ns_per_solve.is_finite())
        .collect()
}

pub fn table(records: &[SolverRecord]) -> String {
    let mut out = String::from("quartic solvers on the same coefficient sets:\n");
    for r in records {
        let _ = writeln!(
            out,
            "  {:<12} {:>8.1} ns/solve  {} sets, {} reference roots, {} missed, {} spurious, max |dt|·|d|/(R+r) {:.2e}",
            r.solver,
            r.ns_per_solve,
            r.coefficient_sets,
            r.reference_roots,
            r.missed_roots,
            r.spurious_roots,
            r.max_rel_t_error
        );
    }
    out
}
