//! Line families shared by the integration tests.
#![allow(dead_code, reason = "shared by several test crates, each using a part")]

use torus_cull::{DRay, Ray, Torus};
use torus_cull_lab::oracle::{
    OracleClass, Query, classify_from_surface, first_crossing_from_surface,
};
use torus_cull_lab::workload::{Batch, Case, Pose, generate};

pub mod adversarial;
pub mod bend;

/// Whether this is a CI run: the environment variable `CI` is `true` (or `1`), as CI
/// services set it.
pub fn under_ci() -> bool {
    std::env::var("CI").is_ok_and(|v| v.eq_ignore_ascii_case("true") || v == "1")
}

/// A GPU test found no adapter (`why`): on a developer's machine it prints one loud
/// SKIPPED line and the test passes; under CI (`CI=true`, see [`under_ci`]) it panics, so
/// that a CI machine that lost its adapter (a failed `mesa-vulkan-drivers` install) fails
/// instead of passing without running the kernel.
pub fn no_adapter(why: &str) {
    let hint = "install the Debian package mesa-vulkan-drivers (Mesa's software Vulkan) to \
                run the GPU tests";
    if under_ci() {
        panic!("no GPU adapter under CI=true ({why}): {hint}");
    }
    use std::io::Write;
    // To stderr directly: libtest captures println! of a passing test.
    let _ = writeln!(std::io::stderr(), "SKIPPED: no GPU adapter ({why}); {hint}");
}

/// The ν values the conservativeness claims are tested at.
pub const NUS: [f64; 7] = [1.1, 1.5, 2.0, 3.0, 5.0, 10.0, 32.0];

/// Rays per pose: each batch draws a new random world pose.
pub const BATCH: usize = 2_000;

/// A family of `count` rays of `case` at ν, in batches at different random poses.
pub fn family(case: Case, nu: f64, count: usize, seed: u64) -> Vec<Batch> {
    (0..count.div_ceil(BATCH))
        .map(|i| {
            let n = BATCH.min(count - i * BATCH);
            generate(case, nu, n, seed.wrapping_add(i as u64), Pose::Random)
                .unwrap_or_else(|e| panic!("generating {case} at nu={nu}: {e}"))
        })
        .collect()
}

/// The same line as `ray` with its origin moved `distance` back along it (f32).
pub fn pushed_back(ray: &Ray, distance: f32) -> Ray {
    let d = ray.dir();
    Ray::new(ray.origin() - d * (distance / d.length()), d).unwrap()
}

/// Every (torus, ray) of a list of batches.
pub fn pairs(batches: &[Batch]) -> impl Iterator<Item = (&Torus, &Ray)> {
    batches
        .iter()
        .flat_map(|b| b.rays.iter().map(move |r| (&b.torus, r)))
}

/// What the oracle expects of a ray from a surface point (its on-surface rule,
/// `classify_from_surface`: the origin moved onto the surface, its own crossing
/// excluded): `Some(next)` (the first crossing after the origin's own, or `None`), or
/// `None` where the input cannot decide (a tangent at the origin, a crossing not
/// separable from it, a graze within the origin's own offset).
pub fn from_surface_reference(torus: &Torus, ray: &DRay) -> Option<Option<f64>> {
    let query = Query::dray(torus, ray);
    match classify_from_surface(&query).class {
        OracleClass::Ambiguous => None,
        OracleClass::Miss => Some(None),
        OracleClass::Hit => Some(Some(first_crossing_from_surface(&query)?)),
    }
}
