//! The BVH bench: per scene × ν × cull, counts over every ray (untimed) and Mrays/s
//! (criterion) on a fixed subset.

use super::read_estimate;
use criterion::{BenchmarkId, Criterion};
use std::hint::black_box;
use std::path::Path;
use std::time::SystemTime;
use torus_cull::Named;
use torus_cull::{Cull, CullKind, CullVisitor, Ray};
use torus_cull_lab::results::BvhRecord;
use torus_cull_lab::scene::{Scene, SceneHit, TraceStats, same_hit};
use torus_cull_lab::workload::spec::BvhSpec;

/// Rays per timed iteration: an evenly strided subset of each ray set.
pub const TIMED_RAYS: usize = 8192;

/// What the untimed pass found for one scene × ν × ray set × cull.
pub struct Pending {
    record: BvhRecord,
    timed: usize,
}

impl Pending {
    /// The criterion benchmark that times it: (group, cull, ν, rays per iteration).
    pub fn benchmark(&self) -> (String, &str, f64, usize) {
        let r = &self.record;
        (
            format!("bvh-{}-{}", r.scene, r.ray_set),
            &r.cull,
            r.nu,
            self.timed,
        )
    }
}

struct Count<'a> {
    scene: &'a Scene,
    rays: &'a [Ray],
}

impl CullVisitor for Count<'_> {
    type Output = (Vec<SceneHit>, TraceStats);
    fn visit<C: Cull>(self, cull: C) -> Self::Output {
        let mut stats = TraceStats::default();
        let hits = self
            .rays
            .iter()
            .map(|r| self.scene.trace(&cull, r, &mut stats))
            .collect();
        (hits, stats)
    }
}

struct Time<'a> {
    c: &'a mut Criterion,
    group: String,
    nu: f64,
    scene: &'a Scene,
    rays: &'a [Ray],
}

impl CullVisitor for Time<'_> {
    type Output = ();
    fn visit<C: Cull>(self, cull: C) {
        let (scene, rays) = (self.scene, self.rays);
        self.c.benchmark_group(self.group).bench_with_input(
            BenchmarkId::new(cull.name(), self.nu),
            &rays,
            |b, rays| {
                b.iter(|| {
                    let mut stats = TraceStats::default();
                    for ray in rays.iter() {
                        black_box(scene.trace(&cull, ray, &mut stats));
                    }
                    black_box(stats)
                })
            },
        );
    }
}

/// Count and time every scene × ν × cull of the spec; returns records still missing Mrays/s.
pub fn bench(c: &mut Criterion, spec: &BvhSpec, seed: u64) -> Vec<Pending> {
    let mut pending = Vec::new();
    for &kind in &spec.scenes {
        for &nu in &spec.nu {
            let scene = Scene::build(kind, nu, spec.tori, seed).unwrap_or_else(|e| panic!("{e}"));
            for (set, rays) in [
                ("camera", scene.camera_rays(spec.image)),
                ("random", scene.random_rays(spec.random_rays, seed)),
            ] {
                if rays.is_empty() {
                    continue;
                }
                let (baseline, _) = CullKind::NoCull.visit(Count {
                    scene: &scene,
                    rays: &rays,
                });
                let brute_ok = rays
                    .iter()
                    .zip(&baseline)
                    .step_by(spec.brute_force_stride)
                    .all(|(r, h)| same_hit(scene.brute_force(r), *h));
                let stride = rays.len().div_ceil(TIMED_RAYS).max(1);
                let timed: Vec<Ray> = rays.iter().step_by(stride).copied().collect();
                for cull in CullKind::TIMED {
                    let (hits, stats) = cull.visit(Count {
                        scene: &scene,
                        rays: &rays,
                    });
                    let matches =
                        brute_ok && hits.iter().zip(&baseline).all(|(a, b)| same_hit(*a, *b));
                    let n = rays.len() as f64;
                    pending.push(Pending {
                        record: BvhRecord {
                            scene: kind.name().to_string(),
                            nu,
                            cull: cull.name().to_string(),
                            ray_set: set.to_string(),
                            rays: rays.len() as u64,
                            hits: hits.iter().filter(|h| h.is_some()).count() as u64,
                            leaf_visits_per_ray: stats.leaf_visits as f64 / n,
                            cull_rejects_per_ray: stats.cull_rejects as f64 / n,
                            quartic_solves_per_ray: stats.quartic_solves as f64 / n,
                            mrays_per_s: f64::NAN,
                            matches_brute_force: matches,
                        },
                        timed: timed.len(),
                    });
                    cull.visit(Time {
                        c,
                        group: format!("bvh-{kind}-{set}"),
                        nu,
                        scene: &scene,
                        rays: &timed,
                    });
                }
            }
        }
    }
    pending
}

/// Fill Mrays/s from this run's estimates; records whose bench was filtered out are dropped.
pub fn records(home: &Path, pending: Vec<Pending>, since: SystemTime) -> Vec<BvhRecord> {
    pending
        .into_iter()
        .filter_map(|p| {
            let r = p.record;
            let group = format!("bvh-{}-{}", r.scene, r.ray_set);
            let est = read_estimate(home, &group, &r.cull, r.nu, since)?;
            Some(BvhRecord {
                mrays_per_s: p.timed as f64 / est.median * 1e3,
                ..r
            })
        })
        .collect()
}
