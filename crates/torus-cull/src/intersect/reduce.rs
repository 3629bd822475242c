//! The reduction every exact path shares, written once over [`Real`]: a line to the
//! scaled foot-point frame, and the depressed quartic's coefficients there.
//!
//! The scalar f64 path ([`super::intersect`]), the f64 lanes (`crate::batch`'s
//! intersection) and the certified f32 path (scalar and lanes) all call these two
//! functions; glam's operation order is kept (`dot` = (x·x′ + y·y′) + z·z′), so the
//! scalar f64 instantiation rounds exactly as glam's `DVec3` code did.

use crate::num::Real;
use crate::num::V3;

/// A line `o + t·d` in the foot-point frame scaled by `1/R` (module docs of
/// [`super`]): the point at `u` is `p + u·d̂`, and `t = (u·R − s)/|d|`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct FootLine<R> {
    /// Unit direction d̂.
    pub(crate) dh: V3<R>,
    /// Foot point divided by R.
    pub(crate) p: V3<R>,
    /// `o·d̂` (unscaled).
    pub(crate) s: R,
    /// `1/|d|`.
    pub(crate) inv_len: R,
}

impl<R: Real> FootLine<R> {
    /// The ray's range `[t_min, t_max]` in `u`: `u = (t·|d| + s)/R`.
    #[inline(always)]
    pub(crate) fn u_range(&self, t_min: R, t_max: R, inv_major: R) -> (R, R) {
        let len = self.s.k(1.0) / self.inv_len;
        (
            (t_min * len + self.s) * inv_major,
            (t_max * len + self.s) * inv_major,
        )
    }

    /// The ray parameter of the point at `u`.
    #[inline(always)]
    pub(crate) fn t_at(&self, u: R, major: R) -> R {
        t_at(u, major, self.s, self.inv_len)
    }

    /// The squared half-chord of the bounding sphere (radius `outer` = 1 + r/R here) on
    /// this line, `outer² − |p|²`: every root lies on the chord, `u² ≤` this, so a line
    /// with it `< 0` misses. The slack [`CHORD_SLACK`] leaves tangencies within rounding
    /// of the outer equator to the solver, which decides them on the quartic itself.
    #[inline(always)]
    pub(crate) fn chord_sq(&self, outer: R) -> R {
        outer * outer * outer.k(1.0 + CHORD_SLACK) - self.p.dot(self.p)
    }
}

/// Lanes whose chord (`chord_sq`, see [`FootLine::chord_sq`]) is not wholly before `lo`
/// or after `hi`.
#[inline(always)]
pub(crate) fn chord_in_range<R: Real>(chord_sq: R, lo: R, hi: R) -> R::Mask {
    let zero = lo.k(0.0);
    !((lo.gt(zero) & (lo * lo).gt(chord_sq)) | (hi.lt(zero) & (hi * hi).gt(chord_sq)))
}

/// The relative slack of the bounding-sphere chord test ([`FootLine::chord_sq`]).
pub(crate) const CHORD_SLACK: f64 = 1e-12;

/// `t = (u·R − s)/|d|`: the ray parameter of the point at `u` on a [`FootLine`] with
/// `s` = o·d̂ and `inv_len` = 1/|d| (for callers that kept only those two).
#[inline(always)]
pub(crate) fn t_at<R: Real>(u: R, major: R, s: R, inv_len: R) -> R {
    (u * major - s) * inv_len
}

/// The foot point of the centre on the line `o + t·d`, scaled by `inv_major` = 1/R.
#[inline(always)]
pub(crate) fn foot_line<R: Real>(o: V3<R>, d: V3<R>, inv_major: R) -> FootLine<R> {
    let inv_len = inv_major.k(1.0) / d.dot(d).sqrt();
    let dh = d * inv_len;
    let s = o.dot(dh);
    let p = (o - dh * s) * inv_major;
    FootLine { dh, p, s, inv_len }
}

/// `[c2, c1, c0]` of the depressed monic quartic `u⁴ + c2 u² + c1 u + c0` along
/// `p + u·d̂` (scaled frame, `rr` = r/R), in the forms that do not cancel.
///
/// With ρ, y the foot point's distance from the axis and height and d̂ a unit vector,
/// K = ρ² + y² + 1 − rr² and:
/// - c0 = K² − 4ρ² = ((ρ − 1)² + y² − rr²)·((ρ + 1)² + y² − rr²): the direct form
///   cancels when the foot point is near the surface (4e-7 relative at ν = 600 near the
///   inner equator), the factored one has an error ∝ rr² instead of 1;
/// - c2 = 2K − 4(d̂x² + d̂z²) = 2(ρ − 1)(ρ + 1) + 2(y − rr)(y + rr) + 4d̂y²: the direct
///   form cancels for lines along the top and bottom circles (K ≈ 2, d̂y ≈ 0), where the
///   contact is of fourth order and every ulp of c2 shows in the root;
/// - c1 = −8(px d̂x + pz d̂z) = 8(py − δ d̂y)·d̂y, as p ⊥ d̂ up to the rounding δ = p·d̂:
///   exactly 0 for a horizontal line, where the direct form leaves ε (a fourth-order
///   contact along the top circle turns that into 4e-11 of t).
#[inline(always)]
pub(crate) fn coefficients<R: Real>(p: V3<R>, dh: V3<R>, rr: R) -> [R; 3] {
    let one = rr.k(1.0);
    let two = rr.k(2.0);
    let rho = (p.x * p.x + p.z * p.z).sqrt();
    let tube = (p.y - rr) * (p.y + rr);
    let c2 = two * (rho - one) * (rho + one) + two * tube + rr.k(4.0) * dh.y * dh.y;
    let delta = p.dot(dh);
    let c1 = rr.k(8.0) * (p.y - delta * dh.y) * dh.y;
    let c0 = ((rho - one) * (rho - one) + tube) * ((rho + one) * (rho + one) + tube);
    [c2, c1, c0]
}

/// The unit outward normal at `p + u·d̂` (scaled frame, `k` = 1 − rr²): ∇F ∝
/// (|x|² + k)·x − 2(x, 0, z), a positive multiple of the tube's outward normal on the
/// surface (the second factor of F is > 0 for a ring torus); normalized as glam does,
/// times 1/|∇F|.
#[inline(always)]
pub(crate) fn normal<R: Real>(p: V3<R>, dh: V3<R>, u: R, k: R) -> V3<R> {
    let x = p + dh * u;
    let w = x.length_squared() + k;
    let two = u.k(2.0);
    let grad = V3::new(w * x.x - two * x.x, w * x.y, w * x.z - two * x.z);
    grad * (u.k(1.0) / grad.dot(grad).sqrt())
}
