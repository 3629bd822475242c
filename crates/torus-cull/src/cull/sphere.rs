//! `sphere`: the bounding sphere |x| ≤ R + r.

use super::kernel::{CullKernel, scalar_cull};
use super::{CullBounds, foot_point};
use crate::num::Vec3s;
use crate::num::{F32s, M32s};
use pulp::Simd;

scalar_cull! {
    /// Rejects lines whose distance from the centre, |foot point|, exceeds R + r_η.
    ///
    /// The distance is taken at the foot point p = o − d (o·d)/|d|², not from
    /// |o|² − (o·d)²/|d|², which cancels catastrophically for far origins.
    pub struct SphereCull = "sphere";
}

impl CullKernel for SphereCull {
    #[inline(always)]
    fn keeps_lanes<S: Simd>(self, s: S, b: &CullBounds, o: Vec3s<S>, d: Vec3s<S>) -> M32s<S> {
        let (foot, _) = foot_point(o, d);
        foot.length_squared().le(F32s::splat(s, b.outer_safe_sq))
    }
}
