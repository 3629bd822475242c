//! The pipe bend on the SIMD lanes: the lanes answer what the outer torus settles, the
//! scalar f64 solid the rest.
//!
//! A whole bend is the ring torus ([`Wavefront::intersect`], every hit on the face
//! `Outer`). For a cut one (a bore or a segment) the lanes ask the outer torus, behind the
//! cull, which rays meet it in range at all ([`Wavefront::occluded`]); a ray that does not
//! and starts outside the outer tube misses the solid, whose every face lies in the closed
//! outer tube (`bend::f32`'s argument). Every other ray, and every ray from a surface
//! point, is answered by [`PipeBend::intersect`] and named in
//! [`Wavefront::finished_in_f64`].

use super::wavefront::{Wavefront, WavefrontStats};
use crate::bend::{BendHit, PipeBend};
use crate::cull::BatchCull;
use crate::num::Dispatch;
use crate::{Precision, Ray};

impl Wavefront {
    /// The nearest crossing of `bend` for every ray (`hits[i]` for `rays[i]`, resized):
    /// [`PipeBend::intersect`]'s answer, the lanes first (module docs). In the stats,
    /// `kept` counts the rays the cull kept on the outer torus and `scalar_fallbacks` the
    /// rays the scalar solid answered.
    ///
    /// ```
    /// use glam::Vec3;
    /// use std::f64::consts::FRAC_PI_2;
    /// use torus_cull::Ray;
    /// use torus_cull::batch::{BatchCull, Dispatch, Wavefront};
    /// use torus_cull::bend::PipeBend;
    /// let bend = PipeBend::canonical(4.0, 0.5, 1.0, 0.0, FRAC_PI_2)?;
    /// let rays = [
    ///     Ray::new(Vec3::new(0.0, 10.0, 0.0), Vec3::X)?,             // misses the outer torus
    ///     Ray::new(Vec3::new(2.828, 10.0, -2.828), Vec3::NEG_Y)?,   // φ = π/4: the solid
    ///     Ray::new(Vec3::new(-4.0, 10.0, 0.0), Vec3::NEG_Y)?,       // φ = π: the cut-away arc
    /// ];
    /// let mut wavefront = Wavefront::new();
    /// let mut hits = Vec::new();
    /// let stats = wavefront.intersect_bend(&Dispatch::best(), BatchCull::Skala, &bend, &rays, &mut hits);
    /// assert_eq!(wavefront.finished_in_f64(), &[1, 2]);
    /// assert_eq!(stats.hits, 1);
    /// for (ray, hit) in rays.iter().zip(&hits) {
    ///     assert_eq!(*hit, bend.intersect(ray));
    /// }
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn intersect_bend<P: Precision>(
        &mut self,
        dispatch: &Dispatch,
        cull: BatchCull,
        bend: &PipeBend,
        rays: &[Ray<P>],
        hits: &mut Vec<Option<BendHit<P>>>,
    ) -> WavefrontStats {
        hits.clear();
        if let Ok(torus) = bend.as_torus() {
            let mut ring = Vec::new();
            let stats = self.intersect(dispatch, cull, torus, rays, &mut ring);
            hits.extend(ring.into_iter().map(|h| h.map(BendHit::on_outer)));
            return stats;
        }
        let mut meets = Vec::new();
        let mut stats = self.occluded(dispatch, cull, bend.outer_torus(), rays, &mut meets);
        self.finished.clear();
        stats.hits = 0;
        for (i, (ray, &meets)) in rays.iter().zip(&meets).enumerate() {
            let hit = if !meets && bend.proved_clear(ray) {
                None
            } else {
                self.finished.push(i);
                bend.intersect(ray)
            };
            stats.hits += usize::from(hit.is_some());
            hits.push(hit);
        }
        stats.scalar_fallbacks = self.finished.len();
        stats
    }
}
