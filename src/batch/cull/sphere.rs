//! `sphere` over lanes: the bounding sphere |x| ≤ R + r_η (see [`crate::SphereCull`]).

use super::{LaneCull, foot_point};
use crate::CullBounds;
use crate::batch::lanes::{F32s, M32s};
use crate::batch::vec3s::Vec3s;
use pulp::Simd;

/// Keep iff the foot point p = o − d (o·d)/|d|² has |p|² ≤ (R + r_η)².
#[derive(Clone, Copy)]
pub(super) struct Sphere;

impl LaneCull for Sphere {
    #[inline(always)]
    fn keeps<S: Simd>(self, s: S, b: &CullBounds, origin: Vec3s<S>, dir: Vec3s<S>) -> M32s<S> {
        let (foot, _) = foot_point(origin, dir);
        foot.length_squared().le(F32s::splat(s, b.outer_safe_sq))
    }
}
