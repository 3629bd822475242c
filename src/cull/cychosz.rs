//! `cychosz`: Cychosz's bounding sphere R + r plus the slab |y| ≤ r (Graphics Gems II, 1991).

use super::{Cull, CullBounds, foot_point};
use glam::Vec3;

/// Sphere, then slab: reject if the sphere chord's end heights are both > r or both < −r.
///
/// With foot point p and half chord w = √((R + r)² − |p|²) the chord's heights span
/// p_y ± |d̂_y|·w, so "both ends beyond the same plane" is |p_y| − |d̂_y|·w > r, which is
/// squared here to `s > 0 ∧ s² > (d_y²/|d|²)·((R + r)² − |p|²)` with s = |p_y| − r:
/// one division (1/|d|²) and no square root, no branch on the sign of d_y.
/// (The paper's Eq. 35 prints the second clause as "< r", which rejects lines that cross the
/// tube; the harness keeps that form only as a test fixture, to show the oracle catching it.)
#[derive(Debug, Clone, Copy, Default)]
pub struct CychoszCull;

impl Cull for CychoszCull {
    fn name(&self) -> &'static str {
        "cychosz"
    }

    #[inline(always)]
    fn keeps(&self, b: &CullBounds, origin: Vec3, dir: Vec3) -> bool {
        sphere_slab(b, origin, dir).keep
    }
}

/// The sphere + slab quantities, shared with `skala`, which refines the survivors.
#[derive(Debug, Clone, Copy)]
pub(crate) struct SphereSlab {
    /// The foot point p = o − d (o·d)/|d|².
    pub foot: Vec3,
    /// (R + r)² − |p|²: the squared half chord, negative when the sphere is missed.
    pub half_chord_sq: f32,
    /// d_y²/|d|².
    pub unit_y_sq: f32,
    /// Cychosz's verdict.
    pub keep: bool,
}

/// Cychosz's test without a square root and without a branch.
#[inline(always)]
pub(crate) fn sphere_slab(b: &CullBounds, origin: Vec3, dir: Vec3) -> SphereSlab {
    let (foot, inv_len_sq) = foot_point(origin, dir);
    let half_chord_sq = b.outer_safe_sq - foot.length_squared();
    let unit_y_sq = dir.y * dir.y * inv_len_sq;
    let above = foot.y.abs() - b.minor_safe;
    let beyond_slab = (above > 0.0) & (above * above > unit_y_sq * half_chord_sq);
    SphereSlab {
        foot,
        half_chord_sq,
        unit_y_sq,
        keep: (half_chord_sq >= 0.0) & !beyond_slab,
    }
}
