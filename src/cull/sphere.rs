//! `sphere`: the bounding sphere |x| ≤ R + r.

use super::{Cull, CullBounds, foot_point};
use glam::Vec3;

/// Rejects lines whose distance from the centre, |foot point|, exceeds R + r_η.
///
/// The distance is taken at the foot point p = o − d (o·d)/|d|², not from
/// |o|² − (o·d)²/|d|², which cancels catastrophically for far origins.
#[derive(Debug, Clone, Copy, Default)]
pub struct SphereCull;

impl Cull for SphereCull {
    fn name(&self) -> &'static str {
        "sphere"
    }

    #[inline(always)]
    fn keeps(&self, b: &CullBounds, origin: Vec3, dir: Vec3) -> bool {
        let (foot, _) = foot_point(origin, dir);
        foot.length_squared() <= b.outer_safe_sq
    }
}
