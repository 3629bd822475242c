//! A ray's line in the certified path's frame: the foot point of the torus centre, scaled
//! by 1/R, formed in f64 and rounded to f32 once.
//!
//! The foot point removes the quartic's cubic term and makes its coefficients O(1)
//! whatever the origin's distance; forming it in f64 keeps the f32 line within
//! 2⁻²⁴·(|q| + |u|) of the true one (each coordinate rounded once), so the certificate's
//! bounds do not grow with the distance of the origin.

use super::certificate::{ScaledLine, U32, V3};
use crate::intersect::reduce::{FootLine, foot_line, t_at};
use crate::num::{Real, Sc, sc};
use crate::{Ray, Torus};

/// The f64 side of a [`ScaledLine`]: what maps `u` back to the ray's `t`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct BackMap {
    /// R.
    pub(crate) major: f64,
    /// `o·d̂` (unscaled).
    pub(crate) s: f64,
    /// `1/|d|`.
    pub(crate) inv_len: f64,
}

impl BackMap {
    /// The ray parameter of the point at `u`: `t = (u·R − o·d̂)/|d|`.
    #[inline(always)]
    pub(crate) fn t(&self, u: f64) -> f64 {
        t_at(sc(u), sc(self.major), sc(self.s), sc(self.inv_len)).v
    }
}

/// A scaled line in f64 (one ray at width 1, a register on lanes), before its one
/// rounding to f32.
pub(crate) struct WideLine<R: Real> {
    /// The foot-point line: foot point over R, unit direction, and the back map
    /// `t = (u·R − s)/|d|`.
    pub(crate) foot: FootLine<R>,
    /// The ray's range in `u`, clamped to ±4.
    pub(crate) lo: R,
    pub(crate) hi: R,
    /// Origins too far for the bounds (see [`FAR_SCALED`]), or not finite: they escalate.
    pub(crate) far: R::Mask,
}

/// The scaled line of torus-frame lines `o + t·d`, `t ∈ [t_min, t_max]`, in f64.
#[inline(always)]
pub(crate) fn scale<R: Real>(o: V3<R>, d: V3<R>, inv_major: R, t_min: R, t_max: R) -> WideLine<R> {
    // f64 forms q = (o − (o·d̂)d̂)/R with an error of about 2⁻⁵¹·|o|/R: past
    // `FAR_SCALED` that outgrows `LINE_ABS`. NaN (a non-finite input) fails the test too.
    let far_sq = o.dot(o) * inv_major * inv_major;
    let far = !far_sq.le(inv_major.k(FAR_SCALED * FAR_SCALED));
    let line = foot_line(o, d, inv_major);
    let (lo, hi) = line.u_range(t_min, t_max, inv_major);
    // Every root has |u| < 2: a range end beyond ±4 is as good as infinite, and keeps f32
    // finite.
    let (min, max) = (inv_major.k(-4.0), inv_major.k(4.0));
    WideLine {
        foot: line,
        lo: lo.max(min).min(max),
        hi: hi.max(min).min(max),
        far,
    }
}

/// The farthest origin, in units of R, whose foot point f64 forms within [`LINE_ABS`].
pub(crate) const FAR_SCALED: f64 = 4096.0;

/// The bounds' line error for a line rounded once from f64 (`scale`): each coordinate of
/// q and d̂ within 2⁻²⁴ of its size, then `q + u·d̂` with two roundings, hence
/// 3.1·2⁻²⁴·(|q| + |u|); the f64 steps add far less than 10⁻¹².
pub(crate) const LINE_REL: f64 = 3.1 * U32;
/// See [`LINE_REL`].
pub(crate) const LINE_ABS: f64 = 4e-12;

/// The scaled line as [`Real`] values, from its f32 columns (`splat` gives the lane type
/// and SIMD token).
#[inline(always)]
pub(crate) fn lanes<R: Real>(like: R, q: [R; 3], d: [R; 3], rr_lo_hi: [R; 3]) -> ScaledLine<R> {
    ScaledLine {
        q: V3 {
            x: q[0],
            y: q[1],
            z: q[2],
        },
        d: V3 {
            x: d[0],
            y: d[1],
            z: d[2],
        },
        rr: rr_lo_hi[0],
        lo: rr_lo_hi[1],
        hi: rr_lo_hi[2],
        line_rel: like.k(LINE_REL),
        line_abs: like.k(LINE_ABS),
    }
}

/// The scaled line of a ray as f32 values (`[q, d̂, (rr, lo, hi)]`), and its back map;
/// `None` when it must escalate.
#[inline(always)]
pub(crate) fn of_ray(torus: &Torus, ray: &Ray) -> Option<([[f32; 3]; 3], BackMap)> {
    let (o, d) = torus.line_to_local_f64(ray);
    let tube = torus.tube();
    let wide = scale(
        V3::from_dvec3(o),
        V3::from_dvec3(d),
        sc(tube.inv_major),
        sc(f64::from(ray.t_min())),
        sc(f64::from(ray.t_max())),
    );
    if wide.far.m {
        return None;
    }
    let f = |x: Sc| x.v as f32;
    let (q, dh) = (wide.foot.p, wide.foot.dh);
    Some((
        [
            [f(q.x), f(q.y), f(q.z)],
            [f(dh.x), f(dh.y), f(dh.z)],
            [tube.minor_rel as f32, f(wide.lo), f(wide.hi)],
        ],
        BackMap {
            major: tube.major,
            s: wide.foot.s.v,
            inv_len: wide.foot.inv_len.v,
        },
    ))
}
