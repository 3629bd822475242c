//! `ellipsoid` over lanes: Cychosz's test on the outer ellipsoid
//! ρ² + (ν + 1)·y² ≤ (R + r)² (see [`crate::EllipsoidCull`]).

use super::{LaneCull, foot_point, moderate};
use crate::CullBounds;
use crate::batch::lanes::{F32s, M32s};
use crate::batch::vec3s::Vec3s;
use pulp::Simd;

/// Scale y by s = √(ν_η + 1) (rounded down), then the sphere chord R + r_η and the slab
/// |y′| ≤ s·r_η, as the scalar cull.
#[derive(Clone, Copy)]
pub(super) struct Ellipsoid;

impl LaneCull for Ellipsoid {
    #[inline(always)]
    fn keeps<S: Simd>(self, s: S, b: &CullBounds, origin: Vec3s<S>, dir: Vec3s<S>) -> M32s<S> {
        ellipsoid_slab(s, b, origin, dir).keep
    }
}

/// The y-scaled line and its chord, shared with `quadric`.
#[derive(Clone, Copy)]
pub(super) struct EllipsoidChord<S: Simd> {
    /// Foot point of the y-scaled line.
    pub foot: Vec3s<S>,
    /// Direction of the y-scaled line.
    pub dir: Vec3s<S>,
    /// 1/|dir|².
    pub inv_len_sq: F32s<S>,
    /// (R + r_η)² − |foot|².
    pub half_chord_sq: F32s<S>,
    /// The verdict: the line meets E ∩ slab.
    pub keep: M32s<S>,
}

/// [`crate::cull`]'s `ellipsoid_slab`, lane for lane.
#[inline(always)]
pub(super) fn ellipsoid_slab<S: Simd>(
    s: S,
    b: &CullBounds,
    origin: Vec3s<S>,
    dir: Vec3s<S>,
) -> EllipsoidChord<S> {
    let zero = F32s::splat(s, 0.0);
    let d = moderate(dir);
    let scale = F32s::splat(s, b.ellipsoid_y_scale);
    let dir = Vec3s::new(d.x, scale * d.y, d.z);
    let (foot, inv_len_sq) = foot_point(Vec3s::new(origin.x, scale * origin.y, origin.z), dir);
    let half_chord_sq = F32s::splat(s, b.outer_safe_sq) - foot.length_squared();
    let unit_y_sq = dir.y * dir.y * inv_len_sq;
    let above = foot.y.abs() - F32s::splat(s, b.ellipsoid_slab);
    let beyond_slab = above.gt(zero) & (above * above).gt(unit_y_sq * half_chord_sq);
    EllipsoidChord {
        foot,
        dir,
        inv_len_sq,
        half_chord_sq,
        keep: half_chord_sq.ge(zero) & !beyond_slab,
    }
}
