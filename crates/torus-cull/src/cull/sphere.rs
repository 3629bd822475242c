//! `sphere`: the bounding sphere |x| ≤ R + r.

use super::foot_point;
use super::kernel::{CullKernel, LaneBounds, scalar_cull};
use crate::num::{Real32, V3};

scalar_cull! {
    /// Rejects lines whose distance from the centre, |foot point|, exceeds R + r_η.
    ///
    /// The distance is taken at the foot point p = o − d (o·d)/|d|², not from
    /// |o|² − (o·d)²/|d|², which cancels catastrophically for far origins.
    pub struct SphereCull = "sphere";
}

impl CullKernel for SphereCull {
    #[inline(always)]
    fn keeps_lanes<R: Real32>(self, b: &LaneBounds<R>, o: V3<R>, d: V3<R>) -> R::Mask {
        let (foot, _) = foot_point(o, d);
        foot.length_squared().le(b.outer_safe_sq)
    }
}
