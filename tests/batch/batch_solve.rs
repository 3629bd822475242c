//! The batch solver against the scalar solver and the oracle, at every dispatch level.
//!
//! * **Oracle** (the accuracy goal): on the solver families of the bench (uniform lines,
//!   hole-edge lines, tangents to the four special circles at ±1e-6 … ±1e-4·r, and the
//!   tangent limit ±1e-9 … ±1e-7·r) at ν = 1.25 … 16, the nearest root at or after the
//!   ray's origin matches the oracle's high-precision reference within 1e-6·(R + r): 0
//!   missed, 0 spurious, at every level, and the scalar solver as the control.
//! * **Scalar solver**: on the same quartics and on random ones, the batch answer is the
//!   scalar answer to rounding (both none, or both within 1e-9 relative): the lane code
//!   follows the scalar method step for step, only libm's `cbrt`/`acos`/`cos` differ.

// Every check here runs against the harness's oracle or CLI.

use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64;
use torus_cull::Named;
use torus_cull::batch::{Quartics, nearest_roots};
use torus_cull::quartic::nearest_root_depressed;
use torus_cull_lab::solver_suite::{NearestScore, SolverCase, family_cases};
use torus_cull_lab::workload::Pose;

const NUS: [f64; 5] = [1.25, 2.0, 4.0, 8.0, 16.0];

/// The bench's solver families at the timed ν.
fn family(name: &str) -> Vec<SolverCase> {
    family_cases(name, &NUS, 2048, (20261121, Pose::Random), 0x501E).unwrap()
}

/// The bench's count of missed and spurious roots, and the answers that differ from the
/// scalar solver's.
fn score(
    cases: &[SolverCase],
    roots: &[Option<f64>],
    scalar: &[Option<f64>],
) -> (NearestScore, usize) {
    let mut score = NearestScore::default();
    let mut disagree_with_scalar = 0;
    for ((case, &got), &control) in cases.iter().zip(roots).zip(scalar) {
        score.add(case, got);
        disagree_with_scalar += usize::from(!same(got, control));
    }
    (score, disagree_with_scalar)
}

fn same(a: Option<f64>, b: Option<f64>) -> bool {
    match (a, b) {
        (None, None) => true,
        (Some(x), Some(y)) => (x - y).abs() <= 1e-9 * x.abs().max(1.0),
        _ => false,
    }
}

#[test]
fn batch_solver_misses_nothing_and_invents_nothing_on_the_solver_families() {
    let levels = crate::dispatch_levels();
    for name in ["uniform", "hole_edge", "tangent", "tangent_limit"] {
        let cases = family(name);
        let mut quartics = Quartics::new();
        for c in &cases {
            quartics.push(c.c[0], c.c[1], c.c[2], c.u_origin, f64::INFINITY);
        }
        let scalar: Vec<Option<f64>> = cases
            .iter()
            .map(|c| nearest_root_depressed(c.c[0], c.c[1], c.c[2], c.u_origin, f64::INFINITY))
            .collect();
        let (control, _) = score(&cases, &scalar, &scalar);
        println!("{name:<14} scalar: {control:?}");
        assert!(
            control.missed == 0 && control.spurious == 0,
            "{name}: {control:?}"
        );
        let mut roots = Vec::new();
        for d in &levels {
            let stats = nearest_roots(d, &quartics, &mut roots);
            let (s, disagree_with_scalar) = score(&cases, &roots, &scalar);
            println!(
                "{name:<14} {:<7} {s:?}, scalar fallbacks {} of {}",
                d.isa().name(),
                stats.scalar_fallbacks,
                stats.quartics
            );
            assert!(s.sets > 5_000 && s.reference > 1_000, "{name}: {s:?}");
            assert_eq!(
                (s.missed, s.spurious, disagree_with_scalar),
                (0, 0, 0),
                "{name} at {}: {s:?}, {disagree_with_scalar} differ from the scalar solver",
                d.isa()
            );
            if name == "uniform" {
                // The batch path is the common path: most lanes never fall back.
                assert!(
                    stats.scalar_fallbacks * 20 < stats.quartics,
                    "{name}: {stats:?}"
                );
            }
        }
    }
}

/// Random quartics over many scales, with every kind of root set, and intervals that cut
/// through them: the batch answer is the scalar answer.
#[test]
fn batch_solver_agrees_with_the_scalar_solver_on_random_quartics() {
    let mut rng = Pcg64::seed_from_u64(0x501F);
    let mut quartics = Quartics::new();
    let mut want = Vec::new();
    for i in 0..40_000 {
        let scale: f64 = 10f64.powf(rng.random_range(-3.0..3.0));
        let (p, q, r) = if i % 2 == 0 {
            // From four real roots summing to 0 (a depressed quartic).
            let mut xs = [0.0f64; 4];
            for x in &mut xs[..3] {
                *x = rng.random_range(-2.0..2.0) * scale;
            }
            xs[3] = -(xs[0] + xs[1] + xs[2]);
            let e2 = xs[0] * xs[1]
                + xs[0] * xs[2]
                + xs[0] * xs[3]
                + xs[1] * xs[2]
                + xs[1] * xs[3]
                + xs[2] * xs[3];
            let e3 = xs[0] * xs[1] * xs[2]
                + xs[0] * xs[1] * xs[3]
                + xs[0] * xs[2] * xs[3]
                + xs[1] * xs[2] * xs[3];
            let e4 = xs[0] * xs[1] * xs[2] * xs[3];
            (e2, -e3, e4)
        } else {
            (
                rng.random_range(-4.0..4.0) * scale * scale,
                rng.random_range(-4.0..4.0) * scale.powi(3),
                rng.random_range(-4.0..4.0) * scale.powi(4),
            )
        };
        let lo = rng.random_range(-3.0..1.0) * scale;
        let hi = if i % 3 == 0 {
            f64::INFINITY
        } else {
            lo + rng.random_range(0.0..4.0) * scale
        };
        quartics.push(p, q, r, lo, hi);
        want.push(nearest_root_depressed(p, q, r, lo, hi));
    }
    // Non-finite input: no root, as the scalar solver says.
    quartics.push(f64::NAN, 1.0, 1.0, 0.0, 1.0);
    want.push(None);
    quartics.push(f64::INFINITY, 0.0, -1.0, f64::NEG_INFINITY, f64::INFINITY);
    want.push(nearest_root_depressed(
        f64::INFINITY,
        0.0,
        -1.0,
        f64::NEG_INFINITY,
        f64::INFINITY,
    ));
    let mut roots = Vec::new();
    for d in crate::dispatch_levels() {
        let stats = nearest_roots(&d, &quartics, &mut roots);
        assert_eq!(roots.len(), want.len());
        let bad: Vec<String> = roots
            .iter()
            .zip(&want)
            .enumerate()
            .filter(|(_, (g, w))| !same(**g, **w))
            .take(5)
            .map(|(i, (g, w))| format!("{:?}: batch {g:?}, scalar {w:?}", quartics.get(i)))
            .collect();
        println!(
            "{}: {} quartics, {} scalar fallbacks",
            d.isa(),
            stats.quartics,
            stats.scalar_fallbacks
        );
        assert!(bad.is_empty(), "{}: {}", d.isa(), bad.join("\n"));
        assert!(roots.iter().filter(|r| r.is_some()).count() > 10_000);
    }
}
