//! `cychosz`: Cychosz's bounding sphere R + r plus the slab |y| ≤ r (Graphics Gems II, 1991).

use super::{Cull, CullBounds, foot_point};
use glam::Vec3;

/// Sphere, then slab: reject if the sphere chord's end heights are both > r or both < −r.
///
/// With foot point p, unit direction d̂ and half chord w = √((R + r)² − |p|²) the chord's
/// heights span p_y ± |d̂_y|·w, so "both ends beyond the same plane" is the single test
/// |p_y| − |d̂_y|·w > r: no branch on the sign of d̂_y.
/// (The paper's Eq. 35 prints the second clause as "< r"; see [`super::CychoszPrintedCull`].)
#[derive(Debug, Clone, Copy, Default)]
pub struct CychoszCull;

impl Cull for CychoszCull {
    fn name(&self) -> &'static str {
        "cychosz"
    }

    #[inline(always)]
    fn keeps(&self, b: &CullBounds, origin: Vec3, dir: Vec3) -> bool {
        sphere_slab(b, origin, dir).is_some()
    }
}

/// What survives the sphere + slab test: the foot point, unit direction and the lowest
/// |y| on the sphere chord (may be negative: the chord crosses y = 0).
#[derive(Debug, Clone, Copy)]
pub(crate) struct SphereSlab {
    pub foot: Vec3,
    pub unit: Vec3,
    pub min_abs_y: f32,
}

/// Cychosz's test, shared with `skala`, which runs it first and refines the survivors.
#[inline(always)]
pub(crate) fn sphere_slab(b: &CullBounds, origin: Vec3, dir: Vec3) -> Option<SphereSlab> {
    let (foot, unit) = foot_point(origin, dir);
    let half_chord_sq = b.outer_safe_sq - foot.length_squared();
    if half_chord_sq < 0.0 {
        return None;
    }
    let min_abs_y = foot.y.abs() - unit.y.abs() * half_chord_sq.sqrt();
    if min_abs_y > b.minor_safe {
        return None;
    }
    Some(SphereSlab {
        foot,
        unit,
        min_abs_y,
    })
}
