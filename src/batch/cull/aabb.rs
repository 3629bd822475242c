//! `aabb` over lanes: the torus's box, by the slab method (see [`crate::AabbCull`]).

use super::LaneCull;
use crate::CullBounds;
use crate::batch::lanes::{F32s, M32s};
use crate::batch::vec3s::Vec3s;
use pulp::Simd;

/// Keep iff the slab intervals t ∈ [(−h − o)/d, (h − o)/d] of the three axes overlap,
/// h = (R + r_η, r_η, R + r_η). The min/max are glam's `a < b` selections, as in the
/// scalar cull, so a 0·∞ = NaN slab (origin on a face plane, zero direction component)
/// resolves the same way here.
#[derive(Clone, Copy)]
pub(super) struct Aabb;

impl LaneCull for Aabb {
    #[inline(always)]
    fn keeps<S: Simd>(self, s: S, b: &CullBounds, origin: Vec3s<S>, dir: Vec3s<S>) -> M32s<S> {
        let outer = F32s::splat(s, b.outer_safe);
        let half = Vec3s::new(outer, F32s::splat(s, b.minor_safe), outer);
        let neg_half = Vec3s::new(-half.x, -half.y, -half.z);
        let one = F32s::splat(s, 1.0);
        let inv = Vec3s::new(one / dir.x, one / dir.y, one / dir.z);
        let t0 = (neg_half - origin).mul_elem(inv);
        let t1 = (half - origin).mul_elem(inv);
        let near = t0.min_cmp(t1);
        let far = t0.max_cmp(t1);
        near.max_element().le(far.min_element())
    }
}
