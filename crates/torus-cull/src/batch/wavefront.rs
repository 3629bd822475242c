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
use super::lines::{BLOCK, Lines};
use super::mask::{KeepMask, set_bits};
use crate::cull::BatchCull;
use crate::intersect::TorusRay;
use crate::intersect::sealed::{FromExact, Steps};
use crate::num::Dispatch;
use crate::{Crossings, Precision, Ray, Torus, intersect, intersect_all, occluded};
use glam::DVec3;

/// Reusable buffers for [`Wavefront::intersect`]: a renderer keeps one per thread.
///
/// Every pass takes a slice of [`crate::Ray`]s (hits in f32, [`crate::Hit`]) or of
/// [`crate::DRay`]s (hits in f64, [`crate::DHit`]), rays from a surface point
/// ([`crate::Torus::spawn`]) among them, and after it [`Wavefront::finished_in_f64`] names
/// the rays the scalar f64 path answered. Shadow rays take the any-hit passes
/// ([`Wavefront::occluded`], [`Wavefront::occluded_f32`]).
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
    /// The rays of the last pass the scalar f64 path answered (indices, ascending).
    pub(super) finished: Vec<usize>,
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
    /// quartics, and rays from a surface point).
    pub scalar_fallbacks: usize,
    /// Rays with a hit (for the any-hit passes: rays occluded).
    pub hits: usize,
    /// Kept rays the f32 path could not prove, answered by the f64 [`crate::intersect()`]
    /// ([`Wavefront::intersect_f32`] and [`Wavefront::occluded_f32`] only).
    pub escalated: usize,
}

impl Wavefront {
    /// Empty buffers.
    pub fn new() -> Wavefront {
        Wavefront::default()
    }

    /// The nearest hit of every ray (`hits[i]` for `rays[i]`, resized), culled with
    /// `cull` first: what [`crate::intersect_culled`] returns ray by ray, to the batch
    /// solver's rounding. [`crate::Ray`]s get f32 hits, [`crate::DRay`]s f64 ones.
    ///
    /// `none` skips the cull stage (every ray is intersected): the baseline.
    pub fn intersect<R: TorusRay>(
        &mut self,
        dispatch: &Dispatch,
        cull: BatchCull,
        torus: &Torus,
        rays: &[R],
        hits: &mut Vec<Option<R::Hit>>,
    ) -> WavefrontStats {
        self.f64_pass(dispatch, cull, torus, rays, hits)
    }

    /// [`Wavefront::intersect`] through the certified f32 path ([`crate::intersect_f32`]
    /// on lanes): the kept rays are solved and proved on f32 lanes, twice as many per
    /// register, and only the rays f32 cannot prove go to the f64 [`crate::intersect()`]
    /// (counted in [`WavefrontStats::escalated`], named by
    /// [`Wavefront::finished_in_f64`]). Never misses a hit the f64 path finds; a proved
    /// hit's `t` is within 1.9·10⁻⁴·R of it (for a [`crate::DRay`] too: the proof is
    /// f32's, on the f64 line rounded once), and it is a front face (the proof is a
    /// crossing from outside to inside).
    ///
    /// ```
    /// use glam::DVec3;
    /// use torus_cull::batch::{BatchCull, Dispatch, Wavefront};
    /// use torus_cull::{DRay, Torus, intersect};
    /// let torus = Torus::canonical(4.0, 1.0)?;
    /// let rays = [
    ///     DRay::new(DVec3::new(4.0, 10.0, 0.0), DVec3::NEG_Y)?, // proved in f32
    ///     DRay::new(DVec3::new(4.0, 0.0, 0.0), DVec3::X)?,      // inside the tube: f64
    /// ];
    /// let mut wavefront = Wavefront::new();
    /// let mut hits = Vec::new();
    /// let stats =
    ///     wavefront.intersect_f32(&Dispatch::best(), BatchCull::Skala, &torus, &rays, &mut hits);
    /// assert_eq!((stats.hits, stats.escalated), (2, 1));
    /// assert_eq!(wavefront.finished_in_f64(), &[1]);
    /// assert_eq!(hits[1], intersect(&torus, &rays[1])); // the f64 answer, exactly
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn intersect_f32<R: TorusRay>(
        &mut self,
        dispatch: &Dispatch,
        cull: BatchCull,
        torus: &Torus,
        rays: &[R],
        hits: &mut Vec<Option<R::Hit>>,
    ) -> WavefrontStats {
        self.f32_pass(dispatch, cull, torus, rays, hits, Proof::Certify)
    }

    /// The any-hit pass for shadow rays: `occluded[i]` (resized) is whether `rays[i]`
    /// meets the torus at some `t ∈ [t_min, t_max]`, what [`crate::occluded()`] answers
    /// ray by ray. The same lanes as [`Wavefront::intersect`] (which form the normal
    /// anyway), answered as a bool; the rays the scalar path finishes (tangents, and
    /// every ray from a surface point) get [`crate::occluded()`], which skips the hit's
    /// normal, point and world transform.
    ///
    /// ```
    /// use glam::Vec3;
    /// use torus_cull::batch::{BatchCull, Dispatch, Wavefront};
    /// use torus_cull::{Ray, Torus, intersect};
    /// let torus = Torus::canonical(4.0, 1.0)?;
    /// // Up from below onto the bottom of the tube, then shadow rays from that hit.
    /// let up = Ray::new(Vec3::new(4.0, -10.0, 0.0), Vec3::Y)?;
    /// let hit = intersect(&torus, &up).expect("the bottom of the tube, at t = 9");
    /// let shadow = [
    ///     torus.spawn(&up, hit.t, Vec3::Y)?,     // up, through the tube: blocked by its top
    ///     torus.spawn(&up, hit.t, Vec3::NEG_Y)?, // down, away from the torus: clear
    ///     torus.spawn(&up, hit.t, Vec3::Y)?.with_t_max(1.5)?, // a light inside the tube
    /// ];
    /// let mut wavefront = Wavefront::new();
    /// let mut blocked = Vec::new();
    /// wavefront.occluded(&Dispatch::best(), BatchCull::Skala, &torus, &shadow, &mut blocked);
    /// assert_eq!(blocked, [true, false, false]);
    /// // Rays from a surface point are answered by the f64 path, and named.
    /// assert_eq!(wavefront.finished_in_f64(), &[0, 1, 2]);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn occluded<R: TorusRay>(
        &mut self,
        dispatch: &Dispatch,
        cull: BatchCull,
        torus: &Torus,
        rays: &[R],
        occluded: &mut Vec<bool>,
    ) -> WavefrontStats {
        self.f64_pass(dispatch, cull, torus, rays, occluded)
    }

    /// [`Wavefront::occluded`] through the certified f32 path: a proved hit is a proved
    /// root in range, a proved miss none; every other kept ray (counted in
    /// [`WavefrontStats::escalated`], named by [`Wavefront::finished_in_f64`]) gets the
    /// f64 answer. Always [`crate::occluded()`]'s answer.
    pub fn occluded_f32<R: TorusRay>(
        &mut self,
        dispatch: &Dispatch,
        cull: BatchCull,
        torus: &Torus,
        rays: &[R],
        occluded: &mut Vec<bool>,
    ) -> WavefrontStats {
        self.f32_pass(dispatch, cull, torus, rays, occluded, Proof::Certify)
    }

    /// The rays of the last pass (indices into its slice, ascending) that the scalar f64
    /// path answered: after [`Wavefront::intersect_f32`] or [`Wavefront::occluded_f32`]
    /// the escalated ones (not proved in f32, or from a surface point), after
    /// [`Wavefront::intersect`] or [`Wavefront::occluded`] the scalar fallbacks (tangent
    /// quartics, rays from a surface point). Its length is the pass's
    /// [`WavefrontStats::escalated`] or [`WavefrontStats::scalar_fallbacks`].
    #[must_use]
    pub fn finished_in_f64(&self) -> &[usize] {
        &self.finished
    }

    /// The f32 wavefront **without** the proof: every f32 answer taken as it comes (hits
    /// lost and invented near tangents). Only for timing what the proof costs.
    #[doc(hidden)]
    pub fn intersect_f32_uncertified<R: TorusRay>(
        &mut self,
        dispatch: &Dispatch,
        cull: BatchCull,
        torus: &Torus,
        rays: &[R],
        hits: &mut Vec<Option<R::Hit>>,
    ) -> WavefrontStats {
        self.f32_pass(dispatch, cull, torus, rays, hits, Proof::Uncertified)
    }

    /// The f64 lanes, then the scalar f64 path on the lanes they leave open: hits, or
    /// bools for the any-hit pass.
    fn f64_pass<R: TorusRay, A: Answer<R>>(
        &mut self,
        dispatch: &Dispatch,
        cull: BatchCull,
        torus: &Torus,
        rays: &[R],
        out: &mut Vec<A>,
    ) -> WavefrontStats {
        self.cull_and_compact(dispatch, cull, torus, rays, out);
        intersect_lanes(dispatch, torus, &self.survivors, &mut self.answers);
        let a = &self.answers;
        // Padding lanes lie past `len` and are never read.
        let len = self.survivors.len();
        for j in set_bits(&a.hit, len) {
            let (o, d) = self.survivors.world(j);
            let normal = DVec3::new(a.normal[0][j], a.normal[1][j], a.normal[2][j]);
            out[self.survivors.index[j]] = A::exact(a.t[j], normal, o, d);
        }
        let open: Vec<u64> = (a.fallback.iter().zip(&self.survivors.on_surface))
            .map(|(f, s)| f | s)
            .collect();
        let scalar_fallbacks = self.finish_in_f64(torus, rays, out, &open);
        WavefrontStats {
            scalar_fallbacks,
            ..self.stats(rays, out)
        }
    }

    fn f32_pass<R: TorusRay, A: Answer<R>>(
        &mut self,
        dispatch: &Dispatch,
        cull: BatchCull,
        torus: &Torus,
        rays: &[R],
        out: &mut Vec<A>,
        proof: Proof,
    ) -> WavefrontStats {
        self.cull_and_compact(dispatch, cull, torus, rays, out);
        let unproved_on_surface = self.survivors.start_past_origins(torus);
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
            let (o, d) = self.survivors.world(j);
            let normal = DVec3::new(
                f64::from(a.normal[0][j]),
                f64::from(a.normal[1][j]),
                f64::from(a.normal[2][j]),
            );
            out[self.survivors.index[j]] = A::proved(a.t(major, j), normal, o, d);
        }
        // Escalated: neither proved, or from a surface point with no proved start past
        // its origin's root. The bits past `len` are padding, never read.
        let mut open: Vec<u64> = (a.hit.iter().zip(&a.miss).zip(&unproved_on_surface))
            .map(|((h, m), s)| !(h | m) | s)
            .collect();
        // Of those, the rays from a surface point get the certified cubic (one at a time,
        // over their own range) before f64: a proved hit takes the f64 path's face,
        // `d·n < 0`, as a ray into the tube is proved where it leaves.
        let on_surface: Vec<u64> = (open.iter().zip(&self.survivors.on_surface))
            .map(|(o, s)| o & s)
            .collect();
        for j in set_bits(&on_surface, len) {
            let i = self.survivors.index[j];
            if let Some(hit) = self.survivors.by_cubic(torus, j, rays[i].range_f64()) {
                let (o, d) = self.survivors.world(j);
                out[i] = hit.map_or(A::NONE, |(t, normal)| A::exact(t, normal, o, d));
                open[j / BLOCK] &= !(1 << (j % BLOCK));
            }
        }
        let escalated = self.finish_in_f64(torus, rays, out, &open);
        WavefrontStats {
            escalated,
            ..self.stats(rays, out)
        }
    }

    /// Every crossing of every ray (`all[i]` for `rays[i]`, resized): what
    /// [`crate::intersect_all`] returns ray by ray, exactly, for [`crate::Ray`]s (f32
    /// crossings) and [`crate::DRay`]s (f64 ones) alike. The cull runs on lanes and a
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
    /// use glam::DVec3;
    /// use torus_cull::{DRay, Ray, Torus, intersect_all};
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
    /// // f64 rays get f64 crossings, the scalar path's exactly.
    /// let drays = [DRay::new(DVec3::new(-10.0, 0.5, 0.0), DVec3::X)?];
    /// let mut dall = Vec::new();
    /// Wavefront::new().intersect_all(&Dispatch::best(), BatchCull::Skala, &torus, &drays, &mut dall);
    /// assert_eq!(dall[0], intersect_all(&torus, &drays[0]));
    /// assert_eq!(dall[0].len(), 4);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn intersect_all<P: Precision>(
        &mut self,
        dispatch: &Dispatch,
        cull: BatchCull,
        torus: &Torus,
        rays: &[Ray<P>],
        all: &mut Vec<Crossings<P>>,
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

    /// The survivors whose bit is set in `open` (the lanes left undecided), answered by
    /// the scalar f64 path and recorded in `finished`; how many.
    fn finish_in_f64<R: TorusRay, A: Answer<R>>(
        &mut self,
        torus: &Torus,
        rays: &[R],
        out: &mut [A],
        open: &[u64],
    ) -> usize {
        self.finished.clear();
        for j in set_bits(open, self.survivors.len()) {
            let i = self.survivors.index[j];
            out[i] = A::scalar(torus, &rays[i]);
            self.finished.push(i);
        }
        self.finished.len()
    }

    /// The counts every pass reports: rays, survivors of the cull, hits.
    fn stats<R: TorusRay, A: Answer<R>>(&self, rays: &[R], out: &[A]) -> WavefrontStats {
        WavefrontStats {
            rays: rays.len(),
            kept: self.survivors.len(),
            hits: out.iter().filter(|h| h.is_hit()).count(),
            ..WavefrontStats::default()
        }
    }

    /// Cull on lanes (all rays for `none`) and compact the survivors into f64 columns;
    /// `out` cleared to "no hit" for every ray. f32 rays reach the culls' frame on lanes
    /// ([`Lines::fill_from_rays_batch`]), f64 ones through their scalar transform.
    fn cull_and_compact<R: TorusRay, A: Answer<R>>(
        &mut self,
        dispatch: &Dispatch,
        cull: BatchCull,
        torus: &Torus,
        rays: &[R],
        out: &mut Vec<A>,
    ) {
        out.clear();
        out.resize(rays.len(), A::NONE);
        self.finished.clear();
        self.cull_only(dispatch, cull, torus, rays);
    }

    /// Cull on lanes (all rays for `none`) and compact the survivors into f64 columns.
    fn cull_only<R: TorusRay>(
        &mut self,
        dispatch: &Dispatch,
        cull: BatchCull,
        torus: &Torus,
        rays: &[R],
    ) {
        if cull == BatchCull::NoCull {
            self.survivors.fill(rays, 0..rays.len(), rays.len());
        } else {
            match R::as_f32_rays(rays) {
                Some(rays) => self.lines.fill_from_rays_batch(dispatch, torus, rays),
                None => {
                    self.lines.clear();
                    for ray in rays {
                        let line = ray.cull_line(torus);
                        self.lines.push(line.origin, line.dir);
                    }
                }
            }
            cull_batch(dispatch, cull, torus.bounds(), &self.lines, &mut self.keep);
            let count = self.keep.count_kept();
            self.survivors.fill(rays, self.keep.kept(), count);
        }
    }
}

/// What a pass writes per ray: the hit (`Option<R::Hit>`, the nearest-hit passes), or
/// whether there is one (`bool`, the any-hit passes).
trait Answer<R: TorusRay>: Copy {
    /// No hit.
    const NONE: Self;
    /// From the f64 lanes' root `t` and world normal on the world line `o + t·d`.
    fn exact(t: f64, normal: DVec3, o: DVec3, d: DVec3) -> Self;
    /// From a root the f32 lanes proved.
    fn proved(t: f64, normal: DVec3, o: DVec3, d: DVec3) -> Self;
    /// The scalar f64 path's answer.
    fn scalar(torus: &Torus, ray: &R) -> Self;
    fn is_hit(&self) -> bool;
}

impl<R: TorusRay> Answer<R> for Option<R::Hit> {
    const NONE: Self = None;
    #[inline(always)]
    fn exact(t: f64, normal: DVec3, o: DVec3, d: DVec3) -> Self {
        R::Hit::from_exact(t, normal, o, d)
    }
    #[inline(always)]
    fn proved(t: f64, normal: DVec3, o: DVec3, d: DVec3) -> Self {
        R::Hit::from_proved(t, normal, o, d)
    }
    fn scalar(torus: &Torus, ray: &R) -> Self {
        intersect(torus, ray)
    }
    fn is_hit(&self) -> bool {
        self.is_some()
    }
}

/// A hit whose `t` the ray's float can hold, as [`crate::occluded()`] counts one.
impl<R: TorusRay> Answer<R> for bool {
    const NONE: Self = false;
    #[inline(always)]
    fn exact(t: f64, _: DVec3, _: DVec3, _: DVec3) -> Self {
        R::fits(t)
    }
    #[inline(always)]
    fn proved(t: f64, _: DVec3, _: DVec3, _: DVec3) -> Self {
        R::fits(t)
    }
    fn scalar(torus: &Torus, ray: &R) -> Self {
        occluded(torus, ray)
    }
    fn is_hit(&self) -> bool {
        *self
    }
}
