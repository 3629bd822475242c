//! The rays a renderer traces through the BVH (camera rays; per hit, a shadow ray to a
//! light and a cosine-weighted bounce spawned with `Torus::spawn`) give brute force's
//! answers for every cull: the closest hit over all tori, and for shadow rays whether
//! any torus blocks the segment. At scene scales R = 10⁻³ … 10³, and where obvhs's node
//! clamp at t = 10⁻⁴ bites: tori below its scale, and long direction vectors.

// Every check here runs against the harness's oracle or CLI.

use crate::renderer_rays::{Rays, assert_every_cull_matches};
use torus_cull::batch::{BATCHED, Dispatch};
use torus_cull::{Named, Ray};
use torus_cull_lab::scene::{LeafBatchStats, Scene, SceneHit, SceneKind, trace_spawned_batched};

/// Camera and random rays of a torus scene, for [`Rays::of`].
fn primary(scene: &Scene) -> Vec<Ray> {
    let mut primary = scene.camera_rays(24);
    primary.extend(scene.random_rays(300, 5));
    primary
}

/// Both miss, or both hit at the same t up to the batch solver's rounding.
fn close(a: SceneHit, b: SceneHit) -> bool {
    match (a, b) {
        (None, None) => true,
        (Some((_, ta)), Some((_, tb))) => (ta - tb).abs() <= 1e-6 * ta.abs().max(1e-30),
        _ => false,
    }
}

/// Every cull (closest and any-hit) and every batched cull (closest) against brute force;
/// panics naming the first mismatches.
fn assert_all_match(scene: &Scene, rays: &Rays, what: &str) {
    assert_every_cull_matches(scene, rays, what, |_, _, _| {});
    let dispatch = Dispatch::best();
    for cull in BATCHED {
        let mut stats = LeafBatchStats::default();
        let got = trace_spawned_batched(scene, &dispatch, cull, &rays.bounce, &mut stats);
        let wrong = got
            .iter()
            .zip(&rays.bounce_truth)
            .filter(|(g, t)| !close(**g, **t))
            .count();
        assert_eq!(wrong, 0, "{what}: batched {cull}: bounces wrong");
    }
}

/// Tori below the clamp's scale (R = 10⁻⁵, R + r = 1.25·10⁻⁵, unit directions): a bounce
/// re-hits its interlocked neighbour at t < 10⁻⁴, inside a box that obvhs's node test
/// skipped.
#[test]
fn tiny_tori_below_obvhs_clamp() {
    let scene = Scene::build_scaled(SceneKind::Chain, 4.0, 120, 3, 1e-5).unwrap();
    assert_clamp_case(&scene, 1.0, "R = 1e-5");
}

/// Tori of R = 1 and directions 10⁵ long: every box within 10 of a spawned ray's origin
/// lies below t = 10⁻⁴.
#[test]
fn long_directions_under_obvhs_clamp() {
    let scene = Scene::build(SceneKind::Chain, 4.0, 120, 3).unwrap();
    assert_clamp_case(&scene, 1e5, "|d| = 1e5");
}

/// Where obvhs's clamp bites: more than 20 bounces re-hit a neighbour below t = 10⁻⁴ (so
/// the case is real), and every traversal still equals brute force.
fn assert_clamp_case(scene: &Scene, direction_length: f32, what: &str) {
    let rays = Rays::of(scene, &primary(scene), direction_length);
    let shallow = rays.neighbour_hits_below(1e-4);
    assert!(
        shallow > 20,
        "{what}: only {shallow} neighbour re-hits below 1e-4"
    );
    assert_all_match(scene, &rays, what);
}

/// Every scene at R = 10⁻³, 1 and 10³: camera, shadow and bounce rays.
#[test]
fn renderer_rays_match_brute_force_at_every_scale() {
    for &kind in SceneKind::ALL {
        for scale in [1e-3, 1.0, 1e3] {
            let scene = Scene::build_scaled(kind, 4.0, 60, 7, scale).unwrap();
            let rays = Rays::of(&scene, &primary(&scene), 1.0);
            let hits = rays.primary_truth.iter().flatten().count();
            let blocked = rays.shadow_truth.iter().filter(|&&b| b).count();
            let rehits = rays.bounce_truth.iter().flatten().count();
            assert!(
                hits > 50 && blocked > 5 && blocked < rays.shadow.len() && rehits > 5,
                "{kind} R={scale}: {hits} hits, {blocked} of {} shadow rays blocked, \
                 {rehits} bounces hit: test too weak",
                rays.shadow.len()
            );
            assert_all_match(&scene, &rays, &format!("{kind} R={scale}"));
        }
    }
}
