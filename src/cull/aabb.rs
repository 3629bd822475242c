//! `aabb`: the torus's own box, what a BVH leaf already knows.

use super::{Cull, CullBounds};
use glam::Vec3;

/// Rejects lines that miss the box [−(R+r_η), R+r_η] × [−r_η, r_η] × [−(R+r_η), R+r_η].
///
/// The slab method over all t. A zero direction component gives ±∞ slab distances, and
/// an origin exactly on that slab's plane gives 0·∞ = NaN. glam's component-wise
/// `min`/`max` (`a < b ? a : b`) can pass that NaN on, and the verdict for such a line
/// is then whatever the comparisons make of it. That is still conservative: the line lies
/// in the plane of a padded face, η = 2⁻¹²·(R + r) beyond the torus's own box, so it cannot
/// hit the torus.
#[derive(Debug, Clone, Copy, Default)]
pub struct AabbCull;

impl Cull for AabbCull {
    fn name(&self) -> &'static str {
        "aabb"
    }

    #[inline(always)]
    fn keeps(&self, b: &CullBounds, origin: Vec3, dir: Vec3) -> bool {
        let half = Vec3::new(b.outer_safe, b.minor_safe, b.outer_safe);
        let inv = dir.recip();
        let t0 = (-half - origin) * inv;
        let t1 = (half - origin) * inv;
        let near = t0.min(t1);
        let far = t0.max(t1);
        near.max_element() <= far.min_element()
    }
}
