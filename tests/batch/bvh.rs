//! Through the obvhs BVH, every cull gives the brute-force closest hit (torus and t).

// Every check here runs against the harness's oracle or CLI.

use glam::Vec3;
use torus_cull::Named;
use torus_cull::{Cull, CullKind, CullVisitor, Ray, intersect};
use torus_cull_lab::oracle::{OracleClass, classify_line};
use torus_cull_lab::scene::{Scene, SceneKind, TraceStats, same_hit};

struct Check<'a> {
    scene: &'a Scene,
    rays: &'a [Ray],
    truth: &'a [Option<(u32, f32)>],
}

impl CullVisitor for Check<'_> {
    type Output = (usize, TraceStats);
    fn visit<C: Cull>(self, cull: C) -> (usize, TraceStats) {
        let mut stats = TraceStats::default();
        let mut wrong = 0;
        for (ray, truth) in self.rays.iter().zip(self.truth) {
            let got = self.scene.trace(&cull, ray, &mut stats);
            if !same_hit(got, *truth) {
                wrong += 1;
                eprintln!(
                    "{}: {ray:?}: bvh {got:?} vs brute force {truth:?}",
                    cull.name()
                );
            }
        }
        (wrong, stats)
    }
}

/// Axis-aligned rays over the scene, with -0.0 direction components (the CwBvh trap).
fn axis_rays(scene: &Scene) -> Vec<Ray> {
    let (c, r) = scene.bounding_sphere;
    let c = c.as_vec3();
    let r = r as f32;
    let mut rays = Vec::new();
    for i in 0..24 {
        for j in 0..24 {
            let (u, v) = ((i as f32 / 23.0 - 0.5) * r, (j as f32 / 23.0 - 0.5) * r);
            for (o, d) in [
                (c + Vec3::new(u, v, 2.0 * r), Vec3::new(-0.0, 0.0, -1.0)),
                (c + Vec3::new(u, 2.0 * r, v), Vec3::new(0.0, -1.0, -0.0)),
                (c + Vec3::new(-2.0 * r, u, v), Vec3::new(1.0, -0.0, -0.0)),
                (c + Vec3::new(u, v, -2.0 * r), Vec3::Z),
            ] {
                rays.push(Ray::new(o, d).unwrap());
            }
        }
    }
    rays
}

#[test]
fn every_cull_matches_brute_force_through_the_bvh() {
    for &kind in SceneKind::ALL {
        for nu in [1.5, 4.0] {
            let scene = Scene::build(kind, nu, 60, 3).unwrap();
            let mut rays = scene.camera_rays(40);
            rays.extend(scene.random_rays(600, 9));
            rays.extend(axis_rays(&scene));
            let truth: Vec<_> = rays.iter().map(|r| scene.brute_force(r)).collect();
            let hits = truth.iter().filter(|h| h.is_some()).count();
            assert!(
                hits > rays.len() / 20,
                "{kind} nu={nu}: only {hits} hits, test too weak"
            );
            let mut solves = Vec::new();
            for cull in CullKind::TIMED {
                let (wrong, stats) = cull.visit(Check {
                    scene: &scene,
                    rays: &rays,
                    truth: &truth,
                });
                assert_eq!(wrong, 0, "{cull} on {kind} nu={nu}");
                assert_eq!(stats.leaf_visits, stats.cull_rejects + stats.quartic_solves);
                solves.push(stats.quartic_solves);
            }
            // none solves at every leaf; skala never solves more than cychosz, nor quadric
            // more than ellipsoid (both supersets hold line by line).
            let at = |c: CullKind| solves[CullKind::TIMED.iter().position(|&k| k == c).unwrap()];
            let (none, cychosz, skala) = (
                at(CullKind::NoCull),
                at(CullKind::Cychosz),
                at(CullKind::Skala),
            );
            assert!(
                skala <= cychosz && cychosz <= none,
                "{kind} nu={nu}: {solves:?}"
            );
            assert!(
                at(CullKind::Quadric) <= at(CullKind::Ellipsoid),
                "{kind} nu={nu}: {solves:?}"
            );
        }
    }
}

/// The BVH against the oracle, not against the code's own brute force: a hit must be a
/// torus the oracle says the ray enters (or touches, within its band) at the oracle's first
/// root, and no torus the oracle says is hit may be closer or missed.
#[test]
fn every_cull_through_the_bvh_agrees_with_the_oracle() {
    use torus_cull_lab::oracle::{OracleClass, Query, classify, reference_roots};
    let mut definite = 0;
    for &kind in SceneKind::ALL {
        // The mixed and dense scenes at one ν: the oracle over every torus is slow.
        let nus: &[f64] = match kind {
            SceneKind::MixedNu | SceneKind::Dense => &[4.0],
            _ => &[1.1, 1.5, 4.0, 16.0],
        };
        for &nu in nus {
            let scene = Scene::build(kind, nu, 60, 5).unwrap();
            let mut rays = scene.camera_rays(40);
            rays.extend(scene.random_rays(800, 11));
            rays.extend(axis_rays(&scene));
            // Per ray: the nearest oracle-hit torus's first root, and every torus's label.
            let truth: Vec<Vec<(OracleClass, f64)>> = rays
                .iter()
                .map(|ray| {
                    scene
                        .tori
                        .iter()
                        .map(|t| {
                            let class = classify(t, ray).class;
                            let first = if class == OracleClass::Miss {
                                f64::INFINITY
                            } else {
                                reference_roots(&Query::ray(t, ray))
                                    .first()
                                    .copied()
                                    .unwrap_or(f64::INFINITY)
                            };
                            (class, first)
                        })
                        .collect()
                })
                .collect();
            for cull in CullKind::TIMED {
                struct Trace<'a>(&'a Scene, &'a [Ray]);
                impl CullVisitor for Trace<'_> {
                    type Output = Vec<Option<(u32, f32)>>;
                    fn visit<C: Cull>(self, cull: C) -> Self::Output {
                        let mut stats = TraceStats::default();
                        self.1
                            .iter()
                            .map(|r| self.0.trace(&cull, r, &mut stats))
                            .collect()
                    }
                }
                let got = cull.visit(Trace(&scene, &rays));
                for ((ray, labels), got) in rays.iter().zip(&truth).zip(got) {
                    let nearest_hit = labels
                        .iter()
                        .filter(|(c, _)| *c == OracleClass::Hit)
                        .map(|&(_, t)| t)
                        .fold(f64::INFINITY, f64::min);
                    let tol = |t: f64| 1e-6 * t.abs().max(1.0);
                    match got {
                        None => assert!(
                            nearest_hit.is_infinite(),
                            "{cull} {kind} nu={nu}: BVH missed a hit at t={nearest_hit}: {ray:?}"
                        ),
                        Some((id, t)) => {
                            definite += 1;
                            let (class, first) = labels[id as usize];
                            assert_ne!(class, OracleClass::Miss, "{cull} {kind}: {ray:?}");
                            let t = f64::from(t);
                            assert!(
                                (t - first).abs() <= tol(first),
                                "{cull} {kind} nu={nu}: t={t} vs oracle {first}: {ray:?}"
                            );
                            assert!(
                                t <= nearest_hit + tol(nearest_hit),
                                "{cull} {kind} nu={nu}: t={t} behind a hit at {nearest_hit}: {ray:?}"
                            );
                        }
                    }
                }
            }
        }
    }
    assert!(definite > 10_000, "only {definite} hits checked");
}

#[test]
fn minus_zero_directions_are_traversed() {
    let scene = Scene::build(SceneKind::FacingGrid, 4.0, 16, 1).unwrap();
    // Straight down the axis of a facing-grid torus onto its tube, with -0.0 components.
    let t = &scene.tori[5];
    let axis = t.axis();
    let on_tube = t.center() + t.dir_to_world(Vec3::new(t.major_radius(), 0.0, 0.0));
    let ray = Ray::new(on_tube + axis * 10.0, -axis + Vec3::new(-0.0, -0.0, 0.0)).unwrap();
    let truth = scene.brute_force(&ray);
    assert!(truth.is_some());
    let got = scene.trace(&torus_cull::NoCull, &ray, &mut TraceStats::default());
    assert!(same_hit(got, truth), "{got:?} vs {truth:?}");
}

#[test]
fn trace_respects_t_min() {
    let scene = Scene::build(SceneKind::FacingGrid, 4.0, 9, 1).unwrap();
    let rays = scene.camera_rays(24);
    for ray in rays.iter().filter(|r| scene.brute_force(r).is_some()) {
        let (_, t) = scene.brute_force(ray).unwrap();
        let later = Ray::with_range(ray.origin(), ray.dir(), t * 1.0001, f32::INFINITY).unwrap();
        let got = scene.trace(&torus_cull::NoCull, &later, &mut TraceStats::default());
        assert!(
            got.is_none_or(|(_, t2)| t2 >= t * 1.0001),
            "{got:?} before t_min"
        );
        assert!(same_hit(got, scene.brute_force(&later)));
    }
}

/// Three camera rays of the default ring_field (ν = 2) for which the solver once returned
/// spurious double roots on torus 523, 50·R away: brute force then disagreed with the BVH.
#[test]
fn pinned_far_line_regression() {
    let scene = Scene::build(SceneKind::RingField, 2.0, 1000, 20261121).unwrap();
    let rays = scene.camera_rays(512);
    let torus = &scene.tori[523];
    for i in [197184usize, 212016, 240656] {
        let ray = &rays[i];
        let label = torus_cull_lab::oracle::classify(torus, ray);
        assert_eq!(label.class, torus_cull_lab::oracle::OracleClass::Miss);
        assert!(label.margin > 40.0, "{label:?}");
        assert_eq!(torus_cull::intersect(torus, ray), None, "ray {i}");
        let got = scene.trace(&torus_cull::NoCull, ray, &mut TraceStats::default());
        assert!(same_hit(got, scene.brute_force(ray)), "ray {i}");
    }
}

/// With `discriminant` at the leaves, the quartic runs almost only where the line really
/// hits the torus: solves are within 0.5 % of the leaf visits whose line the oracle calls
/// a hit (the rest is the padding band), and no such visit is culled.
#[test]
fn discriminant_solves_only_at_leaves_whose_line_hits() {
    for kind in [SceneKind::FacingGrid, SceneKind::RingField] {
        for nu in [1.5, 4.0, 16.0] {
            let scene = Scene::build(kind, nu, 100, 5).unwrap();
            let mut rays = scene.camera_rays(48);
            rays.extend(scene.random_rays(1500, 2));
            for cull in [CullKind::Discriminant, CullKind::DiscriminantF64] {
                let (mut visits, mut line_hits, mut solves, mut culled_hits) = (0, 0, 0, 0);
                for ray in &rays {
                    let got = scene.trace_with(ray, |torus, ray, t_max| {
                        visits += 1;
                        let hit = classify_line(torus, ray).class == OracleClass::Hit;
                        line_hits += usize::from(hit);
                        let line = torus.line_to_local(ray);
                        if !cull.keeps(torus.bounds(), line.origin, line.dir) {
                            culled_hits += usize::from(hit);
                            return f32::INFINITY;
                        }
                        solves += 1;
                        // t_max is a hit's t or +∞, never NaN.
                        let cut = ray.with_t_max(t_max).expect("t_max is not NaN");
                        intersect(torus, &cut).map_or(f32::INFINITY, |h| h.t)
                    });
                    assert!(same_hit(got, scene.brute_force(ray)), "{cull} {ray:?}");
                }
                let n = rays.len() as f64;
                println!(
                    "{kind} nu={nu} {cull}: per ray {:.3} leaf visits, {:.4} line hits, \
                     {:.4} quartic solves",
                    visits as f64 / n,
                    line_hits as f64 / n,
                    solves as f64 / n
                );
                assert_eq!(culled_hits, 0, "{kind} nu={nu} {cull}");
                assert!(
                    line_hits > 200,
                    "{kind} nu={nu}: only {line_hits} line hits"
                );
                assert!(
                    solves as f64 <= line_hits as f64 * 1.005,
                    "{kind} nu={nu} {cull}: {solves} solves for {line_hits} line hits"
                );
            }
        }
    }
}
