//! The rays a renderer traces through a BVH scene, brute force's answers for them, and
//! each cull's mismatches: one home for the torus scenes (`bvh_rays`) and the family's
//! (`bvh_family`), which differ only in their shapes.

use torus_cull::{Cull, CullKind, CullVisitor, Ray};
use torus_cull_lab::scene::family::FamilyScene;
use torus_cull_lab::scene::rays::{Spawned, Surfaces, bounce_rays, light, shadow_rays, stretched};
use torus_cull_lab::scene::{Scene, SceneHit, TraceStats, same_hit};

/// A scene the lab traverses (its BVH, a cull at the leaves) and answers by brute force
/// (every shape, no BVH, no cull).
pub trait TracedScene: Surfaces {
    fn brute_force(&self, ray: &Ray) -> SceneHit;
    fn brute_force_spawned(&self, spawned: &Spawned) -> SceneHit;
    fn brute_force_occluded_spawned(&self, spawned: &Spawned) -> bool;
    fn trace<C: Cull>(&self, cull: &C, ray: &Ray, stats: &mut TraceStats) -> SceneHit;
    fn trace_spawned<C: Cull>(&self, cull: &C, s: &Spawned, stats: &mut TraceStats) -> SceneHit;
    fn occluded_spawned<C: Cull>(&self, cull: &C, s: &Spawned, stats: &mut TraceStats) -> bool;
}

/// The scene's own methods, by path (an inherent method of the same name).
macro_rules! traced_scene {
    ($scene:ty) => {
        impl TracedScene for $scene {
            fn brute_force(&self, ray: &Ray) -> SceneHit {
                <$scene>::brute_force(self, ray)
            }
            fn brute_force_spawned(&self, spawned: &Spawned) -> SceneHit {
                <$scene>::brute_force_spawned(self, spawned)
            }
            fn brute_force_occluded_spawned(&self, spawned: &Spawned) -> bool {
                <$scene>::brute_force_occluded_spawned(self, spawned)
            }
            fn trace<C: Cull>(&self, cull: &C, ray: &Ray, stats: &mut TraceStats) -> SceneHit {
                <$scene>::trace(self, cull, ray, stats)
            }
            fn trace_spawned<C: Cull>(
                &self,
                cull: &C,
                s: &Spawned,
                stats: &mut TraceStats,
            ) -> SceneHit {
                <$scene>::trace_spawned(self, cull, s, stats)
            }
            fn occluded_spawned<C: Cull>(
                &self,
                cull: &C,
                s: &Spawned,
                stats: &mut TraceStats,
            ) -> bool {
                <$scene>::occluded_spawned(self, cull, s, stats)
            }
        }
    };
}
traced_scene!(Scene);
traced_scene!(FamilyScene);

/// A scene's renderer rays and brute force's answers for them.
pub struct Rays {
    pub primary: Vec<Ray>,
    pub primary_truth: Vec<SceneHit>,
    pub bounce: Vec<Spawned>,
    pub bounce_truth: Vec<SceneHit>,
    pub shadow: Vec<Spawned>,
    pub shadow_truth: Vec<bool>,
}

impl Rays {
    /// The `primary` rays (directions times `stretch`), their hits by brute force, and a
    /// shadow ray and a bounce per hit.
    pub fn of(scene: &impl TracedScene, primary: &[Ray], stretch: f32) -> Rays {
        let primary = stretched(primary, stretch);
        let primary_truth: Vec<SceneHit> = primary.iter().map(|r| scene.brute_force(r)).collect();
        let bounce = bounce_rays(scene, &primary, &primary_truth, 11, stretch);
        let shadow = shadow_rays(scene, &primary, &primary_truth, light(scene), stretch);
        Rays {
            bounce_truth: bounce
                .iter()
                .map(|s| scene.brute_force_spawned(s))
                .collect(),
            shadow_truth: shadow
                .iter()
                .map(|s| scene.brute_force_occluded_spawned(s))
                .collect(),
            primary,
            primary_truth,
            bounce,
            shadow,
        }
    }

    /// All the rays: primary, bounces and shadow rays.
    pub fn len(&self) -> usize {
        self.primary.len() + self.bounce.len() + self.shadow.len()
    }

    /// Bounces whose closest hit is on another shape than their own, at t below `t`.
    pub fn neighbour_hits_below(&self, t: f32) -> usize {
        self.bounce
            .iter()
            .zip(&self.bounce_truth)
            .filter(|(s, h)| h.is_some_and(|(id, th)| id != s.from && th < t))
            .count()
    }
}

/// Per cull: the rays whose BVH answer differs from brute force, as messages, and the
/// work counts.
struct Check<'a, S>(pub &'a S, pub &'a Rays);

impl<S: TracedScene> CullVisitor for Check<'_, S> {
    type Output = (Vec<String>, TraceStats);
    fn visit<C: Cull>(self, cull: C) -> (Vec<String>, TraceStats) {
        let (scene, rays) = (self.0, self.1);
        let mut stats = TraceStats::default();
        let mut wrong = Vec::new();
        for (ray, truth) in rays.primary.iter().zip(&rays.primary_truth) {
            let got = scene.trace(&cull, ray, &mut stats);
            if !same_hit(got, *truth) {
                wrong.push(format!("closest {ray:?}: bvh {got:?}, brute {truth:?}"));
            }
        }
        for (s, truth) in rays.bounce.iter().zip(&rays.bounce_truth) {
            let got = scene.trace_spawned(&cull, s, &mut stats);
            if !same_hit(got, *truth) {
                wrong.push(format!("bounce {s:?}: bvh {got:?}, brute {truth:?}"));
            }
        }
        for (s, &truth) in rays.shadow.iter().zip(&rays.shadow_truth) {
            let got = scene.occluded_spawned(&cull, s, &mut stats);
            if got != truth {
                wrong.push(format!("any-hit {s:?}: bvh {got}, brute {truth}"));
            }
        }
        (wrong, stats)
    }
}

/// Every cull ([`CullKind::TIMED`]) through the scene against brute force, closest and
/// any-hit, `each` seeing its work counts first; panics naming the first mismatches.
pub fn assert_every_cull_matches<S: TracedScene>(
    scene: &S,
    rays: &Rays,
    what: &str,
    mut each: impl FnMut(CullKind, usize, &TraceStats),
) {
    for cull in CullKind::TIMED {
        let (wrong, stats) = cull.visit(Check(scene, rays));
        each(cull, wrong.len(), &stats);
        assert!(
            wrong.is_empty(),
            "{what}: {cull}: {} of {} rays wrong, e.g.\n{}",
            wrong.len(),
            rays.len(),
            wrong[..wrong.len().min(3)].join("\n")
        );
    }
}
