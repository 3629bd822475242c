//! The wavefront: cull a batch of rays on lanes, compact the survivors, solve their
//! quartics on lanes, then turn the roots into hits.
//!
//! This is the cost model of a renderer that traces rays in packets or wavefronts:
//! every stage runs over many rays at once, so a cull costs what its arithmetic costs
//! (no mispredicted keep/reject branch per ray) and the solve of the survivors is
//! amortized over SIMD lanes too. The per-ray work around the two batch kernels (the
//! f32 transform to the torus frame, the f64 reduction of a survivor to its depressed
//! quartic, and the normal of a hit) is the scalar path's own code, so a wavefront hit
//! is the [`crate::intersect_culled`] hit up to the last bits of the solver.

use super::cull::{NoBatchForm, cull_batch};
use super::isa::Dispatch;
use super::lines::Lines;
use super::mask::KeepMask;
use super::solve::{Quartics, nearest_roots};
use crate::intersect::{Prepared, prepare_ray, world_hit};
use crate::{CullBounds, CullKind, Hit, Ray, Torus};

/// Reusable buffers for [`Wavefront::intersect`]: a renderer keeps one per thread.
#[derive(Default)]
pub struct Wavefront {
    lines: Lines,
    keep: KeepMask,
    quartics: Quartics,
    /// The survivors that reach the solver: ray index and prepared quartic.
    pending: Vec<(usize, Prepared)>,
    roots: Vec<Option<f64>>,
}

/// What one wavefront did.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct WavefrontStats {
    /// Rays in.
    pub rays: usize,
    /// Rays the cull kept.
    pub kept: usize,
    /// Quartics solved (kept rays whose bounding-sphere chord reaches their range).
    pub solved: usize,
    /// Of them, solved by the scalar solver (tangent and near-tangent lines).
    pub scalar_fallbacks: usize,
    /// Rays with a hit.
    pub hits: usize,
}

impl Wavefront {
    /// Empty buffers.
    pub fn new() -> Wavefront {
        Wavefront::default()
    }

    /// The nearest hit of every ray (`hits[i]` for `rays[i]`, resized), culled with
    /// `cull` first: what [`crate::intersect_culled`] returns ray by ray, with the batch
    /// solver's rounding.
    ///
    /// `none` skips the cull stage (every ray goes to the solver), the baseline.
    pub fn intersect(
        &mut self,
        dispatch: &Dispatch,
        cull: CullKind,
        torus: &Torus,
        bounds: &CullBounds,
        rays: &[Ray],
        hits: &mut Vec<Option<Hit>>,
    ) -> Result<WavefrontStats, NoBatchForm> {
        hits.clear();
        hits.resize(rays.len(), None);
        self.pending.clear();
        self.quartics.clear();
        // Cull and compact: the kept rays' quartics, in ray order.
        let kept = if cull == CullKind::None {
            self.prepare(torus, rays, 0..rays.len());
            rays.len()
        } else {
            self.lines.fill_from_rays(torus, rays);
            cull_batch(dispatch, cull, bounds, &self.lines, &mut self.keep)?;
            let keep = std::mem::take(&mut self.keep);
            self.prepare(torus, rays, keep.kept());
            let kept = keep.count_kept();
            self.keep = keep;
            kept
        };
        let solve = nearest_roots(dispatch, &self.quartics, &mut self.roots);
        let mut n_hits = 0;
        for ((i, prepared), root) in self.pending.iter().zip(&self.roots) {
            if let Some(u) = *root {
                let (t, n) = prepared.finish(u);
                hits[*i] = Some(world_hit(torus, t, n));
                n_hits += 1;
            }
        }
        Ok(WavefrontStats {
            rays: rays.len(),
            kept,
            solved: solve.quartics,
            scalar_fallbacks: solve.scalar_fallbacks,
            hits: n_hits,
        })
    }

    /// Reduces the rays `kept` to their quartics (those whose chord reaches their range).
    fn prepare(&mut self, torus: &Torus, rays: &[Ray], kept: impl Iterator<Item = usize>) {
        for i in kept {
            if let Some(prepared) = prepare_ray(torus, &rays[i]) {
                let [c2, c1, c0] = prepared.coefficients();
                self.quartics.push(c2, c1, c0, prepared.lo, prepared.hi);
                self.pending.push((i, prepared));
            }
        }
    }
}
