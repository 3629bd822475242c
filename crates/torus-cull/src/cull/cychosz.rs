//! `cychosz`: Cychosz's bounding sphere R + r plus the slab |y| ≤ r (Graphics Gems II, 1991).

use super::kernel::{CullKernel, scalar_cull};
use super::{CullBounds, foot_point};
use crate::num::Vec3s;
use crate::num::{F32s, M32s};
use pulp::Simd;

scalar_cull! {
    /// Sphere, then slab: reject if the sphere chord's end heights are both > r or both < −r.
    ///
    /// With foot point p and half chord w = √((R + r)² − |p|²) the chord's heights span
    /// p_y ± |d̂_y|·w, so "both ends beyond the same plane" is |p_y| − |d̂_y|·w > r, which is
    /// squared here to `s > 0 ∧ s² > (d_y²/|d|²)·((R + r)² − |p|²)` with s = |p_y| − r:
    /// one division (1/|d|²) and no square root, no branch on the sign of d_y.
    /// (The paper's Eq. 35 prints the second clause as "< r", which rejects lines that cross the
    /// tube; the harness keeps that form only as a test fixture, to show the oracle catching it.)
    pub struct CychoszCull = "cychosz";
}

impl CullKernel for CychoszCull {
    #[inline(always)]
    fn keeps_lanes<S: Simd>(self, s: S, b: &CullBounds, o: Vec3s<S>, d: Vec3s<S>) -> M32s<S> {
        sphere_slab(s, b, o, d).keep
    }
}

/// The sphere + slab quantities, shared with `skala`, which refines the survivors.
#[derive(Debug, Clone, Copy)]
pub(crate) struct SphereSlab<S: Simd> {
    /// The foot point p = o − d (o·d)/|d|².
    pub foot: Vec3s<S>,
    /// (R + r)² − |p|²: the squared half chord, negative when the sphere is missed.
    pub half_chord_sq: F32s<S>,
    /// d_y²/|d|².
    pub unit_y_sq: F32s<S>,
    /// Cychosz's verdict.
    pub keep: M32s<S>,
}

/// Cychosz's test without a square root and without a branch.
#[inline(always)]
pub(crate) fn sphere_slab<S: Simd>(
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
