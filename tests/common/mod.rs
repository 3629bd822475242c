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

/// `f` of every item of `items`, in order, computed on two threads (each takes one half):
/// the long tests' sweeps over ν take half the wall time on CI's two cores.
pub fn on_two_threads<T: Sync, R: Send>(items: &[T], f: impl Fn(&T) -> R + Sync) -> Vec<R> {
    let f = &f;
    std::thread::scope(|s| {
        let handles: Vec<_> = items
            .chunks(items.len().div_ceil(2).max(1))
            .map(|chunk| s.spawn(move || chunk.iter().map(f).collect::<Vec<_>>()))
            .collect();
        handles
            .into_iter()
            .flat_map(|h| h.join().unwrap())
            .collect()
    })
}

/// The f32-check's spawned secondary-ray families (issue 26: bounces with two t_min,
/// grazing, across, saddle), in the order the tests report them.
pub fn spawned_families() -> Vec<torus_cull_lab::check::shapes::ring::families::Family> {
    let names = [
        "spawned_bounce",
        "spawned_bounce_scene_eps",
        "spawned_grazing",
        "spawned_across",
        "spawned_saddle",
    ];
    let all = torus_cull_lab::check::shapes::ring::families::all();
    names
        .iter()
        .map(|name| {
            let family = all.iter().find(|f| f.name == *name);
            family.expect("an f32-check family").clone()
        })
        .collect()
}

/// Asserts that no check failed: otherwise how many did, and the first ten.
pub fn assert_no_failures(failures: &[String]) {
    assert!(
        failures.is_empty(),
        "{} failures:\n{}",
        failures.len(),
        failures[..failures.len().min(10)].join("\n")
    );
}

/// `eval` rows with the optional columns t_min, t_max, on_surface (after ox … dz) on the
/// torus R = 4, r = 1, each with the oracle's class and t_hit (`None`: no hit): the CPU
/// modes' test and the GPU's read the same rows.
pub const RANGE_ROWS: [(&str, &str, Option<f64>); 9] = [
    // From the inner equator across the hole: the far wall at t = 6 …
    ("3,0,0,-1,0,0,0,inf,1", "hit", Some(6.0)),
    // … beyond a light at t = 5.
    ("3,0,0,-1,0,0,0,5,1", "miss", None),
    // From the top of the tube into it: it leaves at the bottom, t = 2 …
    ("4,1,0,0,-1,0,0,2.5,1", "hit", Some(2.0)),
    // … not before t = 1.5.
    ("4,1,0,0,-1,0,0,1.5,1", "miss", None),
    // From the top, up: nothing.
    ("4,1,0,0,1,0,0,inf,1", "miss", None),
    // Literal rays with a range: the top of the tube at t = 9 …
    ("4,10,0,0,-1,0,0,8.5,0", "miss", None),
    ("4,10,0,0,-1,0,8.5,20,0", "hit", Some(9.0)),
    // … from inside the tube (t_min = 9.5): the oracle's hit, the exit at t = 11.
    ("4,10,0,0,-1,0,9.5,20,0", "hit", Some(11.0)),
    // t_min = t_max = 9: the one point of the top.
    ("4,10,0,0,-1,0,8,10,0", "hit", Some(9.0)),
];
