//! `thick_cylinder`: the shell R − r ≤ ρ ≤ R + r, |y| ≤ r (POV-Ray's `Test_Thick_Cylinder`).

use super::{Cull, CullBounds, foot_point};
use glam::Vec3;

/// Clip the line to the slab |y| ≤ r_η and to the outer cylinder ρ ≤ R + r_η; reject if
/// nothing is left, or if what is left lies wholly inside the inner cylinder ρ < R − r_η.
///
/// ρ² along the line is a convex quadratic in t, so "both clip ends inside the inner
/// cylinder" means the whole clipped piece is inside it. Works from the foot point so the
/// quadratic is well conditioned for far origins.
#[derive(Debug, Clone, Copy, Default)]
pub struct ThickCylinderCull;

impl Cull for ThickCylinderCull {
    fn name(&self) -> &'static str {
        "thick_cylinder"
    }

    #[inline(always)]
    fn keeps(&self, b: &CullBounds, origin: Vec3, dir: Vec3) -> bool {
        let (p, inv_len_sq) = foot_point(origin, dir);
        let n = dir * inv_len_sq.sqrt();
        // Slab |y| ≤ r_η as an interval of t (t measured from the foot point, unit speed).
        let (mut lo, mut hi) = if n.y == 0.0 {
            if p.y.abs() > b.minor_safe {
                return false;
            }
            (f32::NEG_INFINITY, f32::INFINITY)
        } else {
            let inv = 1.0 / n.y;
            let t0 = (-b.minor_safe - p.y) * inv;
            let t1 = (b.minor_safe - p.y) * inv;
            (t0.min(t1), t0.max(t1))
        };
        // Outer cylinder: ρ²(t) = h² t² + 2 (p_x n_x + p_z n_z) t + (p_x² + p_z²).
        let h2 = n.x * n.x + n.z * n.z;
        let half_b = p.x * n.x + p.z * n.z;
        let rho2_foot = p.x * p.x + p.z * p.z;
        if h2 < super::AXIS_PARALLEL_H2 {
            // Parallel to the axis: ρ is constant on the line.
            return rho2_foot <= b.outer_safe_sq && rho2_foot >= b.inner_safe_sq;
        }
        let disc = half_b * half_b - h2 * (rho2_foot - b.outer_safe_sq);
        if disc < 0.0 {
            return false;
        }
        let root = disc.sqrt();
        lo = lo.max((-half_b - root) / h2);
        hi = hi.min((-half_b + root) / h2);
        if lo > hi {
            return false;
        }
        // Reject only if both ends of the clipped piece are inside the hole.
        let rho2 = |t: f32| (h2 * t + 2.0 * half_b) * t + rho2_foot;
        !(rho2(lo) < b.inner_safe_sq && rho2(hi) < b.inner_safe_sq)
    }
}
