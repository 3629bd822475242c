//! A BVH in batch mode: collect every ray's leaf candidates, then cull and intersect
//! them torus by torus with the wavefront.
//!
//! obvhs 0.4 traverses one ray at a time (`ray_traverse`, `ray_traverse_anyhit`, and the
//! resumable `ray_traverse_dynamic` / `traverse!`); it has no packet traversal. What it
//! allows is this two-pass form: an all-hit traversal (the lab's [`super::traverse::each_leaf`],
//! as obvhs's `ray_traverse_anyhit` but honouring `t_min`) reports every leaf whose box a ray
//! enters, the candidates are grouped by torus, and each torus's rays go through
//! [`torus_cull::batch::Wavefront`] as one batch (one torus per batch, because the lane kernels share
//! the torus's frame and bounds across lanes). It gives up two things the scalar
//! closest-hit traversal has: the shrinking `t_max` that skips boxes behind the nearest
//! hit found so far (every box on the ray is a candidate), and full registers (a torus
//! sees only the few rays that reach its box). [`LeafBatchStats`] counts both.

use crate::scene::rays::Spawned;
use crate::scene::{Scene, SceneHit};
use torus_cull::Ray;
use torus_cull::batch::{BatchCull, Dispatch, Wavefront};

/// What a batched traversal did, summed over its rays.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct LeafBatchStats {
    /// Rays traced.
    pub rays: u64,
    /// Leaf candidates: (ray, torus) pairs whose box the ray enters.
    pub leaf_candidates: u64,
    /// Candidates the batch cull rejected.
    pub cull_rejects: u64,
    /// Candidates intersected exactly (on lanes, or by the scalar path for tangents).
    pub intersections: u64,
    /// Batches run (tori with at least one candidate).
    pub batches: u64,
}

/// The buffers of the batched traversal, kept between calls: a renderer traces batch after
/// batch, and an allocation per torus and per call would be timed (and would add the
/// allocator's noise to every paired ratio of `time bvh`).
#[derive(Debug, Clone, Default)]
pub struct LeafBatcher {
    /// Per torus, the indices of the rays whose path enters its box.
    candidates: Vec<Vec<u32>>,
    wavefront: Wavefront,
    batch_rays: Vec<Ray>,
    hits: Vec<Option<torus_cull::Hit>>,
    /// Per ray, the nearest hit so far: what [`LeafBatcher::trace`] returns.
    best: Vec<SceneHit>,
}

impl LeafBatcher {
    /// Empty buffers, grown by the first call.
    #[must_use]
    pub fn new() -> LeafBatcher {
        LeafBatcher::default()
    }

    /// The closest hit of every ray through `scene` (`hits[i]` for `rays[i]`), with `cull`
    /// applied torus by torus to the collected leaf candidates; adds to `stats`.
    ///
    /// Every (ray, torus) pair the scalar traversal would test is tested here too (and
    /// more: those behind the closest hit), so the closest hit is the same, up to the
    /// batch solver's last bits.
    pub fn trace(
        &mut self,
        scene: &Scene,
        dispatch: &Dispatch,
        cull: BatchCull,
        rays: &[Ray],
        stats: &mut LeafBatchStats,
    ) -> &[SceneHit] {
        self.batched(scene, dispatch, cull, rays, |i, _| rays[i], stats)
    }

    /// The two passes, with `ray_for(ray index, torus index)` the ray that torus is tested
    /// on.
    fn batched(
        &mut self,
        scene: &Scene,
        dispatch: &Dispatch,
        cull: BatchCull,
        rays: &[Ray],
        ray_for: impl Fn(usize, usize) -> Ray,
        stats: &mut LeafBatchStats,
    ) -> &[SceneHit] {
        let bvh = scene.bvh();
        // Pass 1: every (torus, ray) candidate, bucketed by torus.
        self.candidates.resize_with(scene.tori.len(), Vec::new);
        self.candidates.iter_mut().for_each(Vec::clear);
        for (i, ray) in rays.iter().enumerate() {
            // The lab's traversal: obvhs's skips boxes the ray leaves before t = 1e-4.
            super::traverse::each_leaf(bvh, ray, |prim| self.candidates[prim].push(i as u32));
        }
        // Pass 2: per torus, the wavefront on its candidates; keep each ray's nearest hit.
        self.best.clear();
        self.best.resize(rays.len(), None);
        stats.rays += rays.len() as u64;
        for (torus_index, which) in self.candidates.iter().enumerate() {
            if which.is_empty() {
                continue;
            }
            self.batch_rays.clear();
            self.batch_rays
                .extend(which.iter().map(|&i| ray_for(i as usize, torus_index)));
            let torus = &scene.tori[torus_index];
            let s =
                self.wavefront
                    .intersect(dispatch, cull, torus, &self.batch_rays, &mut self.hits);
            stats.leaf_candidates += which.len() as u64;
            stats.cull_rejects += (s.rays - s.kept) as u64;
            stats.intersections += s.kept as u64;
            stats.batches += 1;
            for (&i, hit) in which.iter().zip(&self.hits) {
                if let Some(h) = hit {
                    let slot = &mut self.best[i as usize];
                    if slot.is_none_or(|(_, t)| h.t < t) {
                        *slot = Some((torus_index as u32, h.t));
                    }
                }
            }
        }
        &self.best
    }
}

/// [`LeafBatcher::trace`] with fresh buffers.
pub fn trace_leaves_batched(
    scene: &Scene,
    dispatch: &Dispatch,
    cull: BatchCull,
    rays: &[Ray],
    stats: &mut LeafBatchStats,
) -> Vec<SceneHit> {
    LeafBatcher::new()
        .trace(scene, dispatch, cull, rays, stats)
        .to_vec()
}

/// [`trace_leaves_batched`] of spawned rays: each ray's own torus sees the surface ray,
/// every other torus the literal one ([`Spawned::literal`]).
pub fn trace_spawned_batched(
    scene: &Scene,
    dispatch: &Dispatch,
    cull: BatchCull,
    spawned: &[Spawned],
    stats: &mut LeafBatchStats,
) -> Vec<SceneHit> {
    let rays: Vec<Ray> = spawned.iter().map(|s| s.ray).collect();
    let literal: Vec<Ray> = spawned.iter().map(Spawned::literal).collect();
    let pick = |i: usize, torus: usize| {
        if spawned[i].from as usize == torus {
            rays[i]
        } else {
            literal[i]
        }
    };
    LeafBatcher::new()
        .batched(scene, dispatch, cull, &rays, pick, stats)
        .to_vec()
}
