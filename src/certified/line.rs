//! A ray's line in the certified path's frame: the foot point of the torus centre, scaled
//! by 1/R, formed in f64 and rounded to f32 once.
//!
//! The foot point removes the quartic's cubic term and makes its coefficients O(1)
//! whatever the origin's distance; forming it in f64 keeps the f32 line within
//! 2⁻²⁴·(|q| + |u|) of the true one (each coordinate rounded once), so the certificate's
//! bounds do not grow with the distance of the origin.

use super::certificate::{ScaledLine, U32, V3};
use crate::batch::real::{Real, sc};
use crate::intersect::foot_line;
use crate::{Ray, Torus};
use glam::DVec3;

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
        (u * self.major - self.s) * self.inv_len
    }
}

/// The scaled line of a torus-frame line `o + t·d`, `t ∈ [t_min, t_max]`, as f32 values
/// (`[q, d̂, (rr, lo, hi)]`), and its back map.
#[inline(always)]
pub(crate) fn scale(
    major: f64,
    minor: f64,
    o: DVec3,
    d: DVec3,
    t_min: f64,
    t_max: f64,
) -> Option<([[f32; 3]; 3], BackMap)> {
    // f64 forms q = (o − (o·d̂)d̂)/R with an error of about 2⁻⁵¹·|o|/R: past
    // `FAR_SCALED` that outgrows `LINE_ABS`, and the caller escalates.
    let far_sq = o.length_squared() * (1.0 / major) * (1.0 / major);
    // NaN (a non-finite input) fails the test too.
    if far_sq.is_nan() || far_sq > FAR_SCALED * FAR_SCALED {
        return None;
    }
    let inv_major = 1.0 / major;
    let v = |x: DVec3| V3::new(sc(x.x), sc(x.y), sc(x.z));
    let line = foot_line(v(o), v(d), sc(inv_major));
    let (inv_len, s) = (line.inv_len.v, line.s.v);
    let q = DVec3::new(line.p.x.v, line.p.y.v, line.p.z.v);
    let dh = DVec3::new(line.dh.x.v, line.dh.y.v, line.dh.z.v);
    let len = 1.0 / inv_len;
    // Every root has |u| < 2: a range end beyond ±4 is as good as infinite, and keeps f32
    // finite.
    let lo = ((t_min * len + s) * inv_major).clamp(-4.0, 4.0);
    let hi = ((t_max * len + s) * inv_major).clamp(-4.0, 4.0);
    Some((
        [
            q.as_vec3().to_array(),
            dh.as_vec3().to_array(),
            [(minor * inv_major) as f32, lo as f32, hi as f32],
        ],
        BackMap { major, s, inv_len },
    ))
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
        line_rel: like.splat(LINE_REL),
        line_abs: like.splat(LINE_ABS),
    }
}

/// [`scale`] for a ray and torus.
#[inline(always)]
pub(crate) fn of_ray(torus: &Torus, ray: &Ray) -> Option<([[f32; 3]; 3], BackMap)> {
    let (o, d) = torus.line_to_local_f64(ray);
    scale(
        f64::from(torus.major_radius()),
        f64::from(torus.minor_radius()),
        o,
        d,
        f64::from(ray.t_min()),
        f64::from(ray.t_max()),
    )
}
