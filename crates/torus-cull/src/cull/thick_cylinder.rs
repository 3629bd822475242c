//! `thick_cylinder`: the shell R − r ≤ ρ ≤ R + r, |y| ≤ r (POV-Ray's `Test_Thick_Cylinder`).

use super::kernel::{CullKernel, LaneBounds, scalar_cull};
use super::{AXIS_PARALLEL_H2, foot_point};
use crate::num::{Real32, RealMask, V3};

scalar_cull! {
    /// Clip the line to the slab |y| ≤ r_η and to the outer cylinder ρ ≤ R + r_η; reject if
    /// nothing is left, or if what is left lies wholly inside the inner cylinder ρ < R − r_η.
    ///
    /// ρ² along the line is a convex quadratic in t, so "both clip ends inside the inner
    /// cylinder" means the whole clipped piece is inside it. Works from the foot point so the
    /// quadratic is well conditioned for far origins. The four cases (outside the slab,
    /// parallel to the axis, missing the cylinder, nothing left after the clip) are masks,
    /// selected, with an exit wherever no lane is still undecided (at width 1, the scalar
    /// early exits); the clip uses the float type's `min`/`max`, which ignore a NaN operand.
    pub struct ThickCylinderCull = "thick_cylinder";
}

impl CullKernel for ThickCylinderCull {
    #[inline(always)]
    fn keeps_lanes<R: Real32>(self, b: &LaneBounds<R>, o: V3<R>, d: V3<R>) -> R::Mask {
        let (p, inv_len_sq) = foot_point(o, d);
        let n = d * inv_len_sq.sqrt();
        let ms = b.minor_safe;
        let zero = ms.k(0.0);
        // Slab |y| ≤ r_η as an interval of t (t measured from the foot point, unit
        // speed); a horizontal line is in it or not at all.
        let horizontal = n.y.eq(zero);
        let outside_slab = horizontal & p.y.abs().gt(ms);
        // The scalar code's early exits, as "no lane is still undecided" (at width 1, the
        // exit itself): every lane outside the slab, …
        if outside_slab.all() {
            return !outside_slab;
        }
        let inv = ms.k(1.0) / n.y;
        let t0 = (ms.negate() - p.y) * inv;
        let t1 = (ms - p.y) * inv;
        let (below, above) = (ms.k(f32::NEG_INFINITY), ms.k(f32::INFINITY));
        // Selected only where the lanes disagree: at width 1 the scalar code's branch.
        let (lo, hi) = if horizontal.all() {
            (below, above)
        } else if !horizontal.any() {
            (t0.min_num(t1), t0.max_num(t1))
        } else {
            (
                R::select(horizontal, below, t0.min_num(t1)),
                R::select(horizontal, above, t0.max_num(t1)),
            )
        };
        // Outer cylinder: ρ²(t) = h² t² + 2 (p_x n_x + p_z n_z) t + (p_x² + p_z²).
        let h2 = n.x * n.x + n.z * n.z;
        let half_b = p.x * n.x + p.z * n.z;
        let rho2_foot = p.x * p.x + p.z * p.z;
        let (outer_sq, inner_sq) = (b.outer_safe_sq, b.inner_safe_sq);
        // Parallel to the axis: ρ is constant on the line.
        let axis_parallel = h2.lt(ms.k(AXIS_PARALLEL_H2));
        let axis_keep = rho2_foot.le(outer_sq) & rho2_foot.ge(inner_sq);
        // … or every lane outside the slab or parallel to the axis, …
        if (outside_slab | axis_parallel).all() {
            return !outside_slab & axis_parallel & axis_keep;
        }
        let disc = half_b * half_b - h2 * (rho2_foot - outer_sq);
        let misses_cylinder = disc.lt(zero);
        // … or every lane settled without the cylinder's root: outside the slab, parallel
        // to the axis, or missing the cylinder.
        if (outside_slab | axis_parallel | misses_cylinder).all() {
            return !outside_slab & axis_parallel & axis_keep;
        }
        let root = disc.sqrt();
        let lo = lo.max_num((half_b.negate() - root) / h2);
        let hi = hi.min_num((half_b.negate() + root) / h2);
        let empty = lo.gt(hi);
        // … or nothing left of any lane's line after the clip.
        if (outside_slab | axis_parallel | misses_cylinder | empty).all() {
            return !outside_slab & axis_parallel & axis_keep;
        }
        // Reject only if both ends of the clipped piece are inside the hole.
        let two = ms.k(2.0);
        // A macro, not a closure: a closure that LLVM leaves outlined would run without
        // the SIMD target features.
        macro_rules! rho2 {
            ($t:expr) => {
                (h2 * $t + two * half_b) * $t + rho2_foot
            };
        }
        let in_hole = rho2!(lo).lt(inner_sq) & rho2!(hi).lt(inner_sq);
        let general = !misses_cylinder & !empty & !in_hole;
        !outside_slab & ((axis_parallel & axis_keep) | (!axis_parallel & general))
    }
}
