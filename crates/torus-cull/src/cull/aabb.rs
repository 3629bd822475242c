//! `aabb`: the torus's own box, what a BVH leaf already knows.

use super::kernel::{CullKernel, LaneBounds, scalar_cull};
use crate::num::{Real32, V3};

scalar_cull! {
    /// Rejects lines that miss the box [−(R+r_η), R+r_η] × [−r_η, r_η] × [−(R+r_η), R+r_η].
    ///
    /// The slab method over all t: keep iff the intervals t ∈ [(−h − o)/d, (h − o)/d] of the
    /// three axes overlap. A zero direction component gives ±∞ slab distances, and an origin
    /// exactly on that slab's plane gives 0·∞ = NaN. glam's component-wise `min`/`max`
    /// (`a < b ? a : b`, kept on lanes) can pass that NaN on, and the verdict for such a
    /// line is then whatever the comparisons make of it. That is still conservative: the line
    /// lies in the plane of a padded face, η = 2⁻¹²·(R + r) beyond the torus's own box, so it
    /// cannot hit the torus.
    pub struct AabbCull = "aabb";
}

impl CullKernel for AabbCull {
    #[inline(always)]
    fn keeps_lanes<R: Real32>(self, b: &LaneBounds<R>, o: V3<R>, d: V3<R>) -> R::Mask {
        let half = V3::new(b.outer_safe, b.minor_safe, b.outer_safe);
        let neg_half = half.negate();
        let one = b.outer_safe.k(1.0);
        let inv = V3::new(one / d.x, one / d.y, one / d.z);
        let t0 = (neg_half - o).mul_elem(inv);
        let t1 = (half - o).mul_elem(inv);
        let near = t0.min_cmp(t1);
        let far = t0.max_cmp(t1);
        near.max_element().le(far.min_element())
    }
}
