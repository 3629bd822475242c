//! `cychosz`: Cychosz's bounding sphere R + r plus the slab |y| ≤ r (Graphics Gems II, 1991).

use super::foot_point;
use super::kernel::{CullKernel, LaneBounds, scalar_cull};
use crate::num::{Real, Real32, V3};

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
    fn keeps_lanes<R: Real32>(self, b: &LaneBounds<R>, o: V3<R>, d: V3<R>) -> R::Mask {
        sphere_slab(b, o, d).keep
    }
}

/// The sphere + slab quantities, shared with `skala`, which refines the survivors.
#[derive(Clone, Copy)]
pub(crate) struct SphereSlab<R: Real> {
    /// The foot point p = o − d (o·d)/|d|².
    pub foot: V3<R>,
    /// (R + r)² − |p|²: the squared half chord, negative when the sphere is missed.
    pub half_chord_sq: R,
    /// d_y²/|d|².
    pub unit_y_sq: R,
    /// Cychosz's verdict.
    pub keep: R::Mask,
}

/// Cychosz's test without a square root and without a branch.
#[inline(always)]
pub(crate) fn sphere_slab<R: Real>(b: &LaneBounds<R>, origin: V3<R>, dir: V3<R>) -> SphereSlab<R> {
    let zero = b.outer_safe_sq.k(0.0);
    let (foot, inv_len_sq) = foot_point(origin, dir);
    let half_chord_sq = b.outer_safe_sq - foot.length_squared();
    let unit_y_sq = dir.y * dir.y * inv_len_sq;
    let above = foot.y.abs() - b.minor_safe;
    let beyond_slab = above.gt(zero) & (above * above).gt(unit_y_sq * half_chord_sq);
    SphereSlab {
        foot,
        half_chord_sq,
        unit_y_sq,
        keep: half_chord_sq.ge(zero) & !beyond_slab,
    }
}
