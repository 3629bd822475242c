//! The wavefront: cull a batch of rays on lanes, compact the survivors, intersect them
//! on lanes, hits.
//!
//! This is the cost model of a renderer that traces rays in packets or wavefronts:
//! every stage runs over many rays at once, so a cull costs what its arithmetic costs
//! (no mispredicted keep/reject branch per ray) and the survivors' exact intersection
//! (f64 reduction, solve, normal) is amortized over SIMD lanes too. Both kernels follow
//! the scalar code step for step ([`super::cull_batch`], and [`super::intersect`] for
//! [`crate::intersect()`]), and the rays whose quartic needs the scalar solver's careful
//! paths (tangents) get the scalar [`crate::intersect()`] itself; so a wavefront hit is
//! the [`crate::intersect_culled`] hit up to the last bits of the solver.

use super::certified::{F32Answers, Proof, certify_lanes};
use super::cull::cull_batch;
use super::intersect::{Answers, RaysF64, intersect_lanes};
use super::lines::Lines;
use super::mask::{KeepMask, set_bits};
use crate::cull::BatchCull;
use crate::num::Dispatch;
use crate::{Crossings, Hit, Ray, Torus, intersect, intersect_all};
use glam::Vec3;

/// Reusable buffers for [`Wavefront::intersect`]: a renderer keeps one per thread.
///
/// ```
/// use glam::Vec3;
/// use torus_cull::batch::{BatchCull, Dispatch, Wavefront};
/// use torus_cull::{CullKind, Ray, Torus, intersect_culled};
/// let torus = Torus::new(Vec3::ZERO, Vec3::Y, 4.0, 1.0)?;
/// // A row of rays straight down: x = 0 and 1 fall through the hole, 3 to 5 hit the tube.
/// let rays: Vec<Ray> = (0..6)
///     .map(|x| Ray::new(Vec3::new(x as f32, 10.0, 0.0), Vec3::NEG_Y))
///     .collect::<Result<_, _>>()?;
/// let mut wavefront = Wavefront::new(); // reused from batch to batch
/// let mut hits = Vec::new();
/// let stats = wavefront.intersect(&Dispatch::best(), BatchCull::Skala, &torus, &rays, &mut hits);
/// assert_eq!(hits.len(), rays.len());
/// assert_eq!(stats.hits, 3);
/// assert!(stats.kept < rays.len()); // the cull proved some misses
/// for (ray, hit) in rays.iter().zip(&hits) {
///     // The scalar answer, to the batch solver's rounding.
///     let scalar = intersect_culled(&CullKind::Skala, &torus, ray);
///     assert_eq!(hit.is_some(), scalar.is_some());
///     if let (Some(a), Some(b)) = (hit, scalar) {
///         assert!((a.t - b.t).abs() < 1e-5);
///     }
/// }
/// assert!((hits[4].unwrap().t - 9.0).abs() < 1e-5); // the top of the tube at x = 4
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, Default)]
pub struct Wavefront {
    lines: Lines,
    keep: KeepMask,
    survivors: RaysF64,
    answers: Answers,
    answers_f32: F32Answers,
}

/// What one wavefront did.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
#[non_exhaustive]
pub struct WavefrontStats {
    /// Rays in.
    pub rays: usize,
    /// Rays the cull kept (all of them for `none`): the exact intersection's lanes.
    pub kept: usize,
    /// Kept rays handed to the scalar [`crate::intersect()`] (tangent and near-tangent
    /// quartics).
    pub scalar_fallbacks: usize,
    /// Rays with a hit.
    pub hits: usize,
    /// Kept rays the f32 path could not prove, answered by the f64 [`crate::intersect()`]
    /// ([`Wavefront::intersect_f32`] only).
    pub escalated: usize,
}

impl Wavefront {
    /// Empty buffers.
    pub fn new() -> Wavefront {
        Wavefront::default()
    }

    /// The nearest hit of every ray (`hits[i]` for `rays[i]`, resized), culled with
    /// `cull` first: what [`crate::intersect_culled`] returns ray by ray, to the batch
    /// solver's rounding.
    ///
    /// `none` skips the cull stage (every ray is intersected): the baseline.
    pub fn intersect(
        &mut self,
        dispatch: &Dispatch,
        cull: BatchCull,
        torus: &Torus,
        rays: &[Ray],
        hits: &mut Vec<Option<Hit>>,
    ) -> WavefrontStats {
        self.cull_and_compact(dispatch, cull, torus, rays, hits);
        intersect_lanes(dispatch, torus, &self.survivors, &mut self.answers);
        let a = &self.answers;
        // Padding lanes lie past `len` and are never read.
        let len = self.survivors.len();
        for j in set_bits(&a.hit, len) {
            hits[self.survivors.index[j]] = Some(Hit {
                t: a.t[j] as f32,
                normal: Vec3::new(
                    a.normal[0][j] as f32,
                    a.normal[1][j] as f32,
                    a.normal[2][j] as f32,
                ),
            });
        }
        let open: Vec<u64> = (a.fallback.iter().zip(&self.survivors.on_surface))
            .map(|(f, s)| f | s)
            .collect();
        let scalar_fallbacks = self.finish_in_f64(torus, rays, hits, &open);
        WavefrontStats {
            scalar_fallbacks,
            ..self.stats(rays, hits)
        }
    }

    /// [`Wavefront::intersect`] through the certified f32 path ([`crate::intersect_f32`]
    /// on lanes): the kept rays are solved and proved on f32 lanes, twice as many per
    /// register, and only the rays f32 cannot prove go to the f64 [`crate::intersect()`]
    /// (counted in [`WavefrontStats::escalated`]). Never misses a hit the f64 path finds;
    /// a hit's `t` is within 1.9·10⁻⁴·R of it.
    pub fn intersect_f32(
        &mut self,
        dispatch: &Dispatch,
        cull: BatchCull,
        torus: &Torus,
        rays: &[Ray],
        hits: &mut Vec<Option<Hit>>,
    ) -> WavefrontStats {
        self.f32_pass(dispatch, cull, torus, rays, hits, Proof::Certify)
    }

    /// The f32 wavefront **without** the proof: every f32 answer taken as it comes (hits
    /// lost and invented near tangents). Only for timing what the proof costs.
    #[doc(hidden)]
    pub fn intersect_f32_uncertified(
        &mut self,
        dispatch: &Dispatch,
        cull: BatchCull,
        torus: &Torus,
        rays: &[Ray],
        hits: &mut Vec<Option<Hit>>,
    ) -> WavefrontStats {
        self.f32_pass(dispatch, cull, torus, rays, hits, Proof::Uncertified)
    }

    fn f32_pass(
        &mut self,
        dispatch: &Dispatch,
        cull: BatchCull,
        torus: &Torus,
        rays: &[Ray],
        hits: &mut Vec<Option<Hit>>,
        proof: Proof,
    ) -> WavefrontStats {
        self.cull_and_compact(dispatch, cull, torus, rays, hits);
        certify_lanes(
            dispatch,
            torus,
            &self.survivors,
            proof,
            &mut self.answers_f32,
        );
        let len = self.survivors.len();
        let a = &self.answers_f32;
        let major = torus.major_radius_f64();
        for j in set_bits(&a.hit, len) {
            let t = a.t(major, j) as f32;
            hits[self.survivors.index[j]] = t.is_finite().then_some(Hit {
                t,
                normal: Vec3::new(a.normal[0][j], a.normal[1][j], a.normal[2][j]),
            });
        }
        // Escalated: neither proved, or from a surface point (the f64 path divides its
        // root out). The bits past `len` are padding, never read.
        let open: Vec<u64> = (a.hit.iter().zip(&a.miss).zip(&self.survivors.on_surface))
            .map(|((h, m), s)| !(h | m) | s)
            .collect();
        let escalated = self.finish_in_f64(torus, rays, hits, &open);
        WavefrontStats {
            escalated,
            ..self.stats(rays, hits)
        }
    }

    /// Every crossing of every ray (`all[i]` for `rays[i]`, resized): what
    /// [`crate::intersect_all`] returns ray by ray, exactly. The cull runs on lanes and a
    /// ray it rejects gets no crossing (a cull proves that the whole line misses the
    /// torus, so the ray is outside all along); each ray it keeps is solved by the scalar
    /// all-roots path, since the lane solver finds only the nearest root. So this form
    /// saves the quartic on the rays a cull proves to miss and nothing more. In the stats,
    /// `hits` counts the rays with a crossing and `scalar_fallbacks` the kept rays (all of
    /// them solved by the scalar path).
    ///
    /// ```
    /// use glam::Vec3;
    /// use torus_cull::batch::{BatchCull, Dispatch, Wavefront};
    /// use torus_cull::{Ray, Torus, intersect_all};
    /// let torus = Torus::new(Vec3::ZERO, Vec3::Y, 4.0, 1.0)?;
    /// // Rays along x at heights 0 (through both sides of the tube) and 5 (above it).
    /// let rays = [
    ///     Ray::new(Vec3::new(-10.0, 0.0, 0.0), Vec3::X)?,
    ///     Ray::new(Vec3::new(-10.0, 5.0, 0.0), Vec3::X)?,
    /// ];
    /// let mut all = Vec::new();
    /// let stats = Wavefront::new().intersect_all(&Dispatch::best(), BatchCull::Skala, &torus, &rays, &mut all);
    /// assert_eq!((all[0].len(), all[0].spans().len()), (4, 2));
    /// assert!(all[1].is_empty());
    /// assert_eq!(all[0], intersect_all(&torus, &rays[0]));
    /// assert_eq!(stats.kept, 1); // the ray above the torus is culled
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn intersect_all(
        &mut self,
        dispatch: &Dispatch,
        cull: BatchCull,
        torus: &Torus,
        rays: &[Ray],
        all: &mut Vec<Crossings>,
    ) -> WavefrontStats {
        self.cull_only(dispatch, cull, torus, rays);
        all.clear();
        all.extend(rays.iter().map(Crossings::none));
        let kept = self.survivors.len();
        for &i in &self.survivors.index[..kept] {
            all[i] = intersect_all(torus, &rays[i]);
        }
        WavefrontStats {
            rays: rays.len(),
            kept,
            scalar_fallbacks: kept,
            hits: all.iter().filter(|c| !c.is_empty()).count(),
            ..WavefrontStats::default()
        }
    }

    /// The survivors whose bit is set in `open` (the lanes left undecided), intersected by
    /// the scalar f64 path; how many.
    fn finish_in_f64(
        &self,
        torus: &Torus,
        rays: &[Ray],
        hits: &mut [Option<Hit>],
        open: &[u64],
    ) -> usize {
        let mut finished = 0;
        for j in set_bits(open, self.survivors.len()) {
            let i = self.survivors.index[j];
            hits[i] = intersect(torus, &rays[i]);
            finished += 1;
        }
        finished
    }

    /// The counts every pass reports: rays, survivors of the cull, hits.
    fn stats(&self, rays: &[Ray], hits: &[Option<Hit>]) -> WavefrontStats {
        WavefrontStats {
            rays: rays.len(),
            kept: self.survivors.len(),
            hits: hits.iter().filter(|h| h.is_some()).count(),
            ..WavefrontStats::default()
        }
    }

    /// Cull on lanes (all rays for `none`) and compact the survivors into f64 columns;
    /// `hits` cleared to `None` for every ray.
    fn cull_and_compact(
        &mut self,
        dispatch: &Dispatch,
        cull: BatchCull,
        torus: &Torus,
        rays: &[Ray],
        hits: &mut Vec<Option<Hit>>,
    ) {
        hits.clear();
        hits.resize(rays.len(), None);
        self.cull_only(dispatch, cull, torus, rays);
    }

    /// Cull on lanes (all rays for `none`) and compact the survivors into f64 columns.
    fn cull_only(&mut self, dispatch: &Dispatch, cull: BatchCull, torus: &Torus, rays: &[Ray]) {
        if cull == BatchCull::NoCull {
            self.survivors.fill(rays, 0..rays.len(), rays.len());
        } else {
            self.lines.fill_from_rays_batch(dispatch, torus, rays);
            cull_batch(dispatch, cull, torus.bounds(), &self.lines, &mut self.keep);
            let count = self.keep.count_kept();
            self.survivors.fill(rays, self.keep.kept(), count);
        }
    }
}
