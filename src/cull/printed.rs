//! The paper-as-printed variants. **Not conservative**: they exist so the errata tests can
//! show that the oracle catches a broken cull. Never use them to render.

use super::skala::{SectionFormulas, skala_keeps};
use super::{Cull, CullBounds, foot_point};
use glam::Vec3;

/// Cychosz with Eq. 35 as printed: reject if (y_min > r ∧ y_max > r) ∨ (y_min < r ∧ y_max < r).
/// The second clause should read "< −r"; as printed it rejects lines crossing the tube.
#[derive(Debug, Clone, Copy, Default)]
pub struct CychoszPrintedCull;

impl Cull for CychoszPrintedCull {
    fn name(&self) -> &'static str {
        "cychosz_printed"
    }

    fn keeps(&self, b: &CullBounds, origin: Vec3, dir: Vec3) -> bool {
        let (foot, inv_len_sq) = foot_point(origin, dir);
        let unit = dir * inv_len_sq.sqrt();
        let half_chord_sq = b.outer_safe_sq - foot.length_squared();
        if half_chord_sq < 0.0 {
            return false;
        }
        let w = half_chord_sq.sqrt();
        let (y_min, y_max) = (foot.y - unit.y * w, foot.y + unit.y * w);
        let r = b.minor_radius;
        !((y_min > r && y_max > r) || (y_min < r && y_max < r))
    }
}

/// Skala with Eq. 105 as printed: h_c² = r² − (a − r)² instead of r² − (a − R)².
#[derive(Debug, Clone, Copy, Default)]
pub struct SkalaPrintedCCull;

struct PrintedBand;

impl SectionFormulas for PrintedBand {
    fn minor(b: &CullBounds) -> f32 {
        b.minor_radius
    }
    fn hole_edge_sq_h2(b: &CullBounds, a_h: f32, h_sq: f32) -> f32 {
        let inner = b.major_radius - b.minor_radius;
        inner * inner * h_sq - a_h * a_h
    }
    fn band_height_sq_h2(b: &CullBounds, a_h: f32, h: f32) -> f32 {
        let off = a_h - b.minor_radius * h;
        b.minor_radius * b.minor_radius * h * h - off * off
    }
}

impl Cull for SkalaPrintedCCull {
    fn name(&self) -> &'static str {
        "skala_printed_c"
    }

    fn keeps(&self, b: &CullBounds, origin: Vec3, dir: Vec3) -> bool {
        skala_keeps::<PrintedBand>(b, origin, dir)
    }
}

/// Skala with Eq. 102–103 as printed: x_B = (R − r) cos φ with sin φ = a/R, i.e.
/// x_B² = (R − r)²(1 − a²/R²), wider than the true √((R − r)² − a²).
#[derive(Debug, Clone, Copy, Default)]
pub struct SkalaEq102Cull;

struct PrintedHole;

impl SectionFormulas for PrintedHole {
    fn minor(b: &CullBounds) -> f32 {
        b.minor_radius
    }
    fn hole_edge_sq_h2(b: &CullBounds, a_h: f32, h_sq: f32) -> f32 {
        let inner = b.major_radius - b.minor_radius;
        let sin_phi_h = a_h / b.major_radius;
        inner * inner * (h_sq - sin_phi_h * sin_phi_h)
    }
    fn band_height_sq_h2(b: &CullBounds, a_h: f32, h: f32) -> f32 {
        let off = a_h - b.major_radius * h;
        b.minor_radius * b.minor_radius * h * h - off * off
    }
}

impl Cull for SkalaEq102Cull {
    fn name(&self) -> &'static str {
        "skala_eq102"
    }

    fn keeps(&self, b: &CullBounds, origin: Vec3, dir: Vec3) -> bool {
        skala_keeps::<PrintedHole>(b, origin, dir)
    }
}
