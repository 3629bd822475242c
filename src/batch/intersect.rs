//! The exact intersection over f64 lanes: [`crate::intersect()`] for many rays at once.
//!
//! Every step is the scalar code's, in the same order (see `src/intersect.rs`): the world
//! ray to the torus frame in f64, the foot point and the scale 1/R, the quartic's
//! coefficients in their non-cancelling forms, the bounding-sphere chord and range tests,
//! the nearest root (the batch solver, [`super::quartic`]), and the normal. A lane whose
//! quartic needs the scalar solver's careful paths is flagged, and the wavefront runs the
//! scalar [`crate::intersect()`] on that ray instead, so tangent rays get exactly the
//! scalar answer.

use super::lanes::{F64s, M64s};
use super::lines::BLOCK;
use super::quartic::nearest::nearest_root;
pub(crate) use super::vec3s::DVec3s;
use super::vec3s::V3;
use crate::intersect::reduce::FootLine;
use crate::intersect::{CHORD_SLACK, coefficients, foot_line, normal};
use crate::{Ray, Torus};
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
}

impl RaysF64 {
    /// The rays `rays[i]` for each `i` of `kept` (ascending, `count` of them), widened to
    /// f64 exactly, with whole blocks of padding: a ray from (4, 0, 0) along +x,
    /// harmless, whose answers are dropped.
    pub(crate) fn fill(&mut self, rays: &[Ray], kept: impl Iterator<Item = usize>, count: usize) {
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
        let [ox, oy, oz, dx, dy, dz, lo, hi] = &mut self.columns;
        for (j, &i) in self.index.iter().enumerate() {
            let ray = &rays[i];
            let (o, d) = (ray.origin().as_dvec3(), ray.dir().as_dvec3());
            (ox[j], oy[j], oz[j]) = (o.x, o.y, o.z);
            (dx[j], dy[j], dz[j]) = (d.x, d.y, d.z);
            (lo[j], hi[j]) = (f64::from(ray.t_min()), f64::from(ray.t_max()));
        }
    }

    pub(crate) fn len(&self) -> usize {
        self.len
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
    for c in &mut out.normal {
        c.resize(n, 0.0);
    }
    out.hit.resize(n / BLOCK, 0);
    out.fallback.resize(n / BLOCK, 0);
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
    pub(crate) major: f64,
    /// The per-torus constants of `reduce` and the chord test, computed once in f64
    /// exactly as the scalar code computes them per ray: 1/R, r/R, 1 − (r/R)², 1 + r/R.
    pub(crate) inv_major: f64,
    pub(crate) minor_rel: f64,
    k: f64,
    outer: f64,
}

impl TorusF64 {
    pub(crate) fn of(torus: &Torus) -> TorusF64 {
        let to_local = torus.to_local_rotation_f64();
        let (major, minor) = (
            f64::from(torus.major_radius()),
            f64::from(torus.minor_radius()),
        );
        TorusF64 {
            center: torus.center().as_dvec3(),
            to_local,
            to_world: to_local.transpose(),
            major,
            inv_major: 1.0 / major,
            minor_rel: minor * (1.0 / major),
            k: 1.0 - (minor * (1.0 / major)) * (minor * (1.0 / major)),
            outer: 1.0 + minor / major,
        }
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
                let lane = intersect_lane(s, &frame, origin, dir, t_min, t_max);
                lane.t.store(&mut out.t[at.clone()]);
                let [nx, ny, nz] = &mut out.normal;
                lane.normal.x.store(&mut nx[at.clone()]);
                lane.normal.y.store(&mut ny[at.clone()]);
                lane.normal.z.store(&mut nz[at.clone()]);
                hit_bits |= lane.hit.bits() << k;
                cold_bits |= lane.fallback.bits() << k;
            }
            out.hit[block] = hit_bits;
            out.fallback[block] = cold_bits;
        }
    }
}

/// One register of rays' answers.
struct Lane<S: Simd> {
    t: F64s<S>,
    normal: DVec3s<S>,
    hit: M64s<S>,
    fallback: M64s<S>,
}

/// [`crate::intersect()`], lane for lane (with the batch solver).
#[inline(always)]
fn intersect_lane<S: Simd>(
    s: S,
    frame: &TorusF64,
    origin: DVec3s<S>,
    dir: DVec3s<S>,
    t_min: F64s<S>,
    t_max: F64s<S>,
) -> Lane<S> {
    // Macros, not closures: a closure that LLVM leaves outlined would run without the
    // SIMD target features and call every intrinsic out of line.
    macro_rules! c {
        ($x:expr) => {
            F64s::splat(s, $x)
        };
    }
    // `Torus::line_to_local_f64`, then `reduce` (its shared steps).
    let o = (origin - DVec3s::splat(s, frame.center)).rotated(&frame.to_local);
    let d = dir.rotated(&frame.to_local);
    let major = c!(frame.major);
    let inv_r = c!(frame.inv_major);
    let FootLine {
        dh,
        p,
        s: s_,
        inv_len,
    } = foot_line(o, d, inv_r);
    let k = c!(frame.k);
    let [c2, c1, c0] = coefficients(p, dh, c!(frame.minor_rel));
    // `intersect_local`: the chord of the bounding sphere and the range.
    let outer = c!(frame.outer);
    let chord_sq = outer * outer * c!(1.0 + CHORD_SLACK) - p.dot(p);
    let inv_major = inv_r;
    let len = c!(1.0) / inv_len;
    let lo = (t_min * len + s_) * inv_major;
    let hi = (t_max * len + s_) * inv_major;
    let out_of_reach =
        (lo.gt(c!(0.0)) & (lo * lo).gt(chord_sq)) | (hi.lt(c!(0.0)) & (hi * hi).gt(chord_sq));
    let reaches = !chord_sq.lt(c!(0.0)) & !out_of_reach;
    // The nearest root, then `t`, the normal, and the normal in the world (`intersect`).
    let (u, cold) = nearest_root(c2, c1, c0, lo, hi);
    let t = (u * major - s_) * inv_len;
    let normal = normal(p, dh, u, k).rotated(&frame.to_world);
    let found = !u.is_nan();
    Lane {
        t,
        normal,
        hit: reaches & found & !cold,
        fallback: reaches & cold,
    }
}
