//! The BVH in batch mode (leaf candidates collected per ray, then the wavefront torus by
//! torus) gives the brute-force closest hit for every batched cull, at every dispatch
//! level, and tests every leaf the scalar closest-hit traversal tests (and more: it has
//! no shrinking t_max).

// Every check here runs against the harness's oracle or CLI.

use glam::Vec3;
use torus_cull::Named;
use torus_cull::batch::{BATCHED, BatchCull};
use torus_cull::{NoCull, Ray};
use torus_cull_lab::scene::{LeafBatchStats, trace_leaves_batched};
use torus_cull_lab::scene::{Scene, SceneHit, SceneKind, TraceStats};

/// Both miss, or both hit at the same t up to the batch solver's rounding (the torus may
/// differ only where two tori tie at that t, as `same_hit` allows).
fn close(a: SceneHit, b: SceneHit) -> bool {
    match (a, b) {
        (None, None) => true,
        (Some((_, ta)), Some((_, tb))) => (ta - tb).abs() <= 1e-6 * ta.abs().max(1.0),
        _ => false,
    }
}

/// Axis-aligned rays with -0.0 direction components (the CwBvh trap).
fn axis_rays(scene: &Scene) -> Vec<Ray> {
    let (c, r) = scene.bounding_sphere;
    let (c, r) = (c.as_vec3(), r as f32);
    let mut rays = Vec::new();
    for i in 0..12 {
        for j in 0..12 {
            let (u, v) = ((i as f32 / 11.0 - 0.5) * r, (j as f32 / 11.0 - 0.5) * r);
            rays.push(Ray::new(c + Vec3::new(u, v, 2.0 * r), Vec3::new(-0.0, 0.0, -1.0)).unwrap());
            rays.push(Ray::new(c + Vec3::new(u, 2.0 * r, v), Vec3::new(0.0, -1.0, -0.0)).unwrap());
        }
    }
    rays
}

#[test]
fn batched_bvh_matches_brute_force_for_every_batched_cull() {
    let levels = crate::dispatch_levels();
    for &kind in SceneKind::ALL {
        for nu in [1.5, 4.0] {
            let scene = Scene::build(kind, nu, 60, 3).unwrap();
            let mut rays = scene.camera_rays(32);
            rays.extend(scene.random_rays(400, 9));
            rays.extend(axis_rays(&scene));
            let truth: Vec<SceneHit> = rays.iter().map(|r| scene.brute_force(r)).collect();
            let n_hits = truth.iter().filter(|h| h.is_some()).count();
            assert!(n_hits > rays.len() / 20, "{kind} nu={nu}: {n_hits} hits");
            let mut scalar = TraceStats::default();
            for ray in &rays {
                scene.trace(&NoCull, ray, &mut scalar);
            }
            for d in &levels {
                let mut intersections = Vec::new();
                for cull in BATCHED {
                    let mut stats = LeafBatchStats::default();
                    let got = trace_leaves_batched(&scene, d, cull, &rays, &mut stats);
                    let wrong: Vec<String> = rays
                        .iter()
                        .zip(got.iter().zip(&truth))
                        .filter(|(_, (g, t))| !close(**g, **t))
                        .take(3)
                        .map(|(r, (g, t))| format!("{r:?}: batch {g:?}, brute force {t:?}"))
                        .collect();
                    assert!(
                        wrong.is_empty(),
                        "{cull} on {kind} nu={nu} at {}:\n{}",
                        d.isa(),
                        wrong.join("\n")
                    );
                    assert_eq!(
                        stats.leaf_candidates,
                        stats.cull_rejects + stats.intersections
                    );
                    // Every box on the ray, not only those before the closest hit.
                    assert!(stats.leaf_candidates >= scalar.leaf_visits, "{stats:?}");
                    intersections.push(stats.intersections);
                }
                let at =
                    |c: BatchCull| intersections[BATCHED.iter().position(|&k| k == c).unwrap()];
                assert!(at(BatchCull::Skala) <= at(BatchCull::Cychosz));
                assert!(at(BatchCull::Cychosz) <= at(BatchCull::NoCull));
                if d.isa() == levels.last().unwrap().isa() {
                    println!(
                        "{kind} nu={nu} ({}): {} rays, leaf candidates {} (scalar closest-hit \
                         traversal visits {}), intersections per cull {:?}",
                        d.isa(),
                        rays.len(),
                        {
                            let mut s = LeafBatchStats::default();
                            trace_leaves_batched(&scene, d, BatchCull::NoCull, &rays, &mut s);
                            s.leaf_candidates
                        },
                        scalar.leaf_visits,
                        BATCHED.iter().zip(&intersections).collect::<Vec<_>>()
                    );
                }
            }
        }
    }
}
