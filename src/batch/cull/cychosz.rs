//! `cychosz` over lanes: the sphere R + r_η, then the slab |y| ≤ r_η at the chord's ends
//! (Cychosz, Graphics Gems II, 1991; see [`crate::CychoszCull`]).

use super::{LaneCull, foot_point};
use crate::CullBounds;
use crate::batch::lanes::{F32s, M32s};
use crate::batch::vec3s::Vec3s;
use pulp::Simd;

/// Keep iff w² = (R + r_η)² − |p|² ≥ 0 and not (s > 0 ∧ s² > (d_y²/|d|²)·w²), with
/// s = |p_y| − r_η: one division, no root, no branch.
#[derive(Clone, Copy)]
pub(super) struct Cychosz;

impl LaneCull for Cychosz {
    #[inline(always)]
    fn keeps<S: Simd>(self, s: S, b: &CullBounds, origin: Vec3s<S>, dir: Vec3s<S>) -> M32s<S> {
        sphere_slab(s, b, origin, dir).keep
    }
}

/// The sphere + slab quantities, shared with `skala` (as in the scalar code).
#[derive(Clone, Copy)]
pub(super) struct SphereSlab<S: Simd> {
    /// The foot point p.
    pub foot: Vec3s<S>,
    /// (R + r_η)² − |p|².
    pub half_chord_sq: F32s<S>,
    /// d_y²/|d|².
    pub unit_y_sq: F32s<S>,
    /// Cychosz's verdict.
    pub keep: M32s<S>,
}

/// [`crate::cull`]'s `sphere_slab`, lane for lane.
#[inline(always)]
pub(super) fn sphere_slab<S: Simd>(
    s: S,
    b: &CullBounds,
    origin: Vec3s<S>,
    dir: Vec3s<S>,
) -> SphereSlab<S> {
    let zero = F32s::splat(s, 0.0);
    let (foot, inv_len_sq) = foot_point(origin, dir);
    let half_chord_sq = F32s::splat(s, b.outer_safe_sq) - foot.length_squared();
    let unit_y_sq = dir.y * dir.y * inv_len_sq;
    let above = foot.y.abs() - F32s::splat(s, b.minor_safe);
    let beyond_slab = above.gt(zero) & (above * above).gt(unit_y_sq * half_chord_sq);
    SphereSlab {
        foot,
        half_chord_sq,
        unit_y_sq,
        keep: half_chord_sq.ge(zero) & !beyond_slab,
    }
}
