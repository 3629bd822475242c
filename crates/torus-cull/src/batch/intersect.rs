//! The exact intersection over f64 lanes: [`crate::intersect()`] for many rays at once.
//!
//! One driver for both: `crate::intersect::nearest_hit` (the foot point and the scale 1/R,
//! the range and the bounding sphere's chord, the quartic's coefficients in their
//! non-cancelling forms, the nearest root, `t` and the normal), here on f64 lanes with the
//! lane solver ([`super::quartic`]) after the world-to-torus transform. A lane whose
//! quartic needs the scalar solver's careful paths is flagged, and the wavefront runs the
//! scalar [`crate::intersect()`] on that ray instead, so tangent rays get exactly the
//! scalar answer.

use super::lines::{BLOCK, size_lane_output};
use super::mask::set_bits;
use crate::Torus;
use crate::certified::on_surface::clear_start;
use crate::certified::surface_cubic;
use crate::geometry::Tube;
use crate::intersect::TorusRay;
use crate::intersect::nearest_hit::{NearestRoot, nearest_hit};
use crate::intersect::sealed::Steps;
pub(crate) use crate::num::DVec3s;
use crate::num::V3;
use crate::num::{F64s, M64s};
use crate::quartic::lanes::nearest_root;
use glam::{DMat3, DVec3};
use pulp::{Simd, WithSimd};

/// World rays in f64, structure of arrays, padded to whole blocks; each remembers its
/// index in the caller's ray slice.
#[derive(Debug, Clone, Default)]
pub(crate) struct RaysF64 {
    len: usize,
    /// origin x, y, z, direction x, y, z, t_min, t_max.
    pub(crate) columns: [Vec<f64>; 8],
    /// The ray's index in the caller's slice.
    pub(crate) index: Vec<usize>,
    /// Per block, a bit for each ray that starts on the surface ([`crate::Ray::from_surface`]):
    /// the lanes solve the literal ray, so the scalar path answers these.
    pub(crate) on_surface: Vec<u64>,
}

impl RaysF64 {
    /// The rays `rays[i]` for each `i` of `kept` (ascending, `count` of them), widened to
    /// f64 exactly, with whole blocks of padding: a ray from (4, 0, 0) along +x,
    /// harmless, whose answers are dropped.
    pub(crate) fn fill<R: TorusRay>(
        &mut self,
        rays: &[R],
        kept: impl Iterator<Item = usize>,
        count: usize,
    ) {
        self.len = count;
        let padded = count.div_ceil(BLOCK) * BLOCK;
        for (c, pad) in self
            .columns
            .iter_mut()
            .zip([4.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0])
        {
            c.clear();
            c.resize(padded, pad);
        }
        self.index.clear();
        self.index.extend(kept);
        assert_eq!(
            self.index.len(),
            count,
            "kept lines and their count disagree"
        );
        self.on_surface.clear();
        self.on_surface.resize(padded / BLOCK, 0);
        let [ox, oy, oz, dx, dy, dz, lo, hi] = &mut self.columns;
        for (j, &i) in self.index.iter().enumerate() {
            let ray = &rays[i];
            self.on_surface[j / BLOCK] |= u64::from(ray.on_surface()) << (j % BLOCK);
            let (o, d) = ray.world_f64();
            (ox[j], oy[j], oz[j]) = (o.x, o.y, o.z);
            (dx[j], dy[j], dz[j]) = (d.x, d.y, d.z);
            (lo[j], hi[j]) = ray.range_f64();
        }
    }

    pub(crate) fn len(&self) -> usize {
        self.len
    }

    /// For the certified f32 pass: each ray from a surface point that leaves into the
    /// outside starts past its origin's own root (its t_min raised to
    /// [`clear_start`], where the only root before is the
    /// origin's); returns the bits of the other rays from a surface point, which the
    /// f64 path answers.
    pub(crate) fn start_past_origins(&mut self, torus: &Torus) -> Vec<u64> {
        let mut open = vec![0u64; self.on_surface.len()];
        for j in set_bits(&self.on_surface, self.len) {
            let (o, d) = self.world(j);
            let [.., lo, hi] = &mut self.columns;
            match clear_start(torus, o, d) {
                Some(start) if lo[j].max(start) <= hi[j] => lo[j] = lo[j].max(start),
                _ => open[j / BLOCK] |= 1 << (j % BLOCK),
            }
        }
        open
    }

    /// The certified cubic ([`crate::certified::surface_cubic`]) on ray `j` (from a surface
    /// point) over `[t_min, t_max]`: `Some(None)` a proved miss, `Some(Some((t, n)))` a
    /// proved hit with its world normal, `None` not proved.
    pub(crate) fn by_cubic(
        &self,
        torus: &Torus,
        j: usize,
        (t_min, t_max): (f64, f64),
    ) -> Option<Option<(f64, DVec3)>> {
        let to_local = torus.to_local_rotation_f64();
        let (o, d) = self.world(j);
        let (o, d) = (to_local * (o - torus.center_f64()), to_local * d);
        match surface_cubic::prove(torus, (o, d), t_min, t_max) {
            surface_cubic::Verdict::Miss => Some(None),
            surface_cubic::Verdict::Hit { t, .. } => {
                // The outward normal at the point: away from the core circle.
                let t = f64::from(t);
                let x = o + d * t;
                let rho = x.x.hypot(x.z);
                let core = DVec3::new(x.x, 0.0, x.z) * (torus.major_radius_f64() / rho);
                let n = (to_local.transpose() * (x - core)).normalize();
                n.is_finite().then_some(Some((t, n)))
            }
            // A stretch proved clear would need a second lane pass: the f64 path answers.
            surface_cubic::Verdict::Clear(_) | surface_cubic::Verdict::Escalate => None,
        }
    }

    /// Rays `at..at + F64_LANES` as lanes: origin, direction, t_min, t_max.
    #[inline(always)]
    pub(crate) fn lanes<S: Simd>(
        &self,
        s: S,
        at: usize,
    ) -> (DVec3s<S>, DVec3s<S>, F64s<S>, F64s<S>) {
        let at = at..at + S::F64_LANES;
        let [ox, oy, oz, dx, dy, dz, lo, hi] = self
            .columns
            .each_ref()
            .map(|c| F64s::load(s, &c[at.clone()]));
        (V3::new(ox, oy, oz), V3::new(dx, dy, dz), lo, hi)
    }

    /// Ray `j`'s world origin and direction (f64).
    pub(crate) fn world(&self, j: usize) -> (DVec3, DVec3) {
        let [ox, oy, oz, dx, dy, dz, ..] = &self.columns;
        (
            DVec3::new(ox[j], oy[j], oz[j]),
            DVec3::new(dx[j], dy[j], dz[j]),
        )
    }

    pub(crate) fn padded(&self) -> usize {
        self.columns[0].len()
    }
}

/// The lanes' answers: t and the world normal (f64, to be narrowed to the [`crate::Hit`]'s
/// f32), and per block a bit of "hit" and a bit of "ask the scalar path".
#[derive(Debug, Clone, Default)]
pub(crate) struct Answers {
    pub(crate) t: Vec<f64>,
    pub(crate) normal: [Vec<f64>; 3],
    pub(crate) hit: Vec<u64>,
    pub(crate) fallback: Vec<u64>,
}

/// Runs the exact intersection on every ray of `rays` for `torus`.
pub(crate) fn intersect_lanes(
    dispatch: &super::Dispatch,
    torus: &Torus,
    rays: &RaysF64,
    out: &mut Answers,
) {
    let n = rays.padded();
    out.t.resize(n, 0.0);
    size_lane_output(n, &mut out.normal, [&mut out.hit, &mut out.fallback]);
    dispatch.run(Kernel {
        frame: TorusF64::of(torus),
        rays,
        out,
    });
}

/// The torus as the scalar exact path sees it, in f64.
#[derive(Clone, Copy)]
pub(crate) struct TorusF64 {
    pub(crate) center: DVec3,
    pub(crate) to_local: DMat3,
    pub(crate) to_world: DMat3,
    /// The per-torus constants the scalar path computes per ray, computed once.
    pub(crate) tube: Tube,
}

impl TorusF64 {
    pub(crate) fn of(torus: &Torus) -> TorusF64 {
        let to_local = torus.to_local_rotation_f64();
        TorusF64 {
            center: torus.center_f64(),
            to_local,
            to_world: to_local.transpose(),
            tube: *torus.tube(),
        }
    }

    /// `Torus::line_to_local_f64` over lanes: origins and directions in the torus frame.
    #[inline(always)]
    pub(crate) fn line_to_local<S: Simd>(
        &self,
        origin: DVec3s<S>,
        dir: DVec3s<S>,
    ) -> (DVec3s<S>, DVec3s<S>) {
        let s = origin.x.s;
        (
            (origin - DVec3s::splat(s, self.center)).rotated(&self.to_local),
            dir.rotated(&self.to_local),
        )
    }
}

struct Kernel<'a> {
    frame: TorusF64,
    rays: &'a RaysF64,
    out: &'a mut Answers,
}

impl WithSimd for Kernel<'_> {
    type Output = ();

    #[inline(always)]
    fn with_simd<S: Simd>(self, s: S) {
        let lanes = S::F64_LANES;
        let Kernel { frame, rays, out } = self;
        for block in 0..rays.padded() / BLOCK {
            let (mut hit_bits, mut cold_bits) = (0u64, 0u64);
            // The last block stops at the register holding the last ray.
            for k in (0..BLOCK.min(rays.len() - block * BLOCK)).step_by(lanes) {
                let at = block * BLOCK + k..block * BLOCK + k + lanes;
                let (origin, dir, t_min, t_max) = rays.lanes(s, at.start);
                let (o, d) = frame.line_to_local(origin, dir);
                // No lane with a hit or a fallback: the stale answers are never read.
                let Some(lane) = nearest_hit::<_, Lanes>(&frame.tube, o, d, t_min, t_max) else {
                    continue;
                };
                lane.t.store(&mut out.t[at.clone()]);
                let normal = lane.normal.rotated(&frame.to_world);
                let [nx, ny, nz] = &mut out.normal;
                normal.x.store(&mut nx[at.clone()]);
                normal.y.store(&mut ny[at.clone()]);
                normal.z.store(&mut nz[at.clone()]);
                hit_bits |= lane.hit.bits() << k;
                cold_bits |= lane.fallback.bits() << k;
            }
            out.hit[block] = hit_bits;
            out.fallback[block] = cold_bits;
        }
    }
}

/// The lane solver: the careful one's common path, flagging the rest.
struct Lanes;

impl<S: Simd> NearestRoot<F64s<S>> for Lanes {
    #[inline(always)]
    fn nearest(
        c2: F64s<S>,
        c1: F64s<S>,
        c0: F64s<S>,
        lo: F64s<S>,
        hi: F64s<S>,
    ) -> (F64s<S>, M64s<S>) {
        nearest_root(c2, c1, c0, lo, hi)
    }
}
