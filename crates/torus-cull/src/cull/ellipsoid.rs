//! `ellipsoid`: Cychosz's test with the sphere replaced by the outer ellipsoid
//! ρ² + (ν + 1)·y² ≤ (R + r)², which touches the torus.

use super::kernel::{CullKernel, LaneBounds, scalar_cull};
use super::{foot_point, moderate};
use crate::num::{Real, Real32, V3};

scalar_cull! {
    /// Reject lines that miss E ∩ {|y| ≤ r}, E the ellipsoid ρ² + (ν + 1)·y² ≤ (R + r)².
    ///
    /// **Bound.** Scaling y by s = √(ν + 1) turns E into the sphere of radius R + r, so this
    /// is Cychosz's sphere chord and slab test on the y-scaled line, with the slab scaled to
    /// |y′| ≤ s·r.
    ///
    /// **Why it is sound.** On the tube surface ρ = R + r cos θ, y = r sin θ the left side
    /// of E minus (R + r)² is −Rr(1 − cos θ)² ≤ 0, and ρ² + (ν + 1)·y² is convex on each
    /// cross-section disk, so the solid torus lies in E, touching it on the outer equator
    /// (θ = 0); the slab touches it on the circles ρ = R, y = ±r. E lies in the sphere
    /// R + r, so in exact arithmetic this rejects every line `cychosz` rejects, and more:
    /// 0.56 → 0.91 of the isotropic misses at ν = 1.1 (Cychosz 1991, Graphics Gems II; the
    /// ellipsoid is this crate's addition).
    ///
    /// **Floating point.** The identity holds for any R > 0, r > 0, so it is applied to the
    /// padded torus T_η (tube r_η = r + η): ν_η = R/r_η, s = √(ν_η + 1) rounded down (which
    /// only widens the ellipsoid), radius R + r_η, slab s·r_η. Every point within η of the
    /// torus lies in T_η ⊂ E_η, so rounding that moves the line by less than η is absorbed.
    /// The foot point of the y-scaled line is taken from the y-scaled origin: for a line
    /// that passes near the torus the origin is its foot point minus t·d, so the projection
    /// cancels ≈ ε·|t d| per component, in unscaled units the same ≈ ε|o| as Cychosz's (not
    /// s times it). Cost: Cychosz's plus the scaling (two multiplies by s, a per-torus
    /// constant) and `moderate`'s range test of |d|²: still one division and no square
    /// root.
    pub struct EllipsoidCull = "ellipsoid";
}

impl CullKernel for EllipsoidCull {
    #[inline(always)]
    fn keeps_lanes<R: Real32>(self, b: &LaneBounds<R>, o: V3<R>, d: V3<R>) -> R::Mask {
        ellipsoid_slab(b, o, d).keep
    }
}

/// The y-scaled line and its ellipsoid chord, shared with `quadric`, which refines the
/// survivors (so `quadric` rejects everything `ellipsoid` does, bit for bit).
#[derive(Clone, Copy)]
pub(crate) struct EllipsoidChord<R: Real> {
    /// Foot point of the y-scaled line: its point closest to the centre.
    pub foot: V3<R>,
    /// Direction of the y-scaled line (from the moderated direction).
    pub dir: V3<R>,
    /// 1/|dir|².
    pub inv_len_sq: R,
    /// (R + r_η)² − |foot|²: the squared half chord, negative when E is missed.
    pub half_chord_sq: R,
    /// The verdict: the line meets E ∩ slab.
    pub keep: R::Mask,
}

/// The y-scaled line's sphere chord and slab test, without a square root or a branch.
#[inline(always)]
pub(crate) fn ellipsoid_slab<R: Real32>(
    b: &LaneBounds<R>,
    origin: V3<R>,
    dir: V3<R>,
) -> EllipsoidChord<R> {
    let zero = b.outer_safe_sq.k(0.0);
    // |d′|² ≤ (ν + 1)|d|², and `quadric` takes fourth powers of d′.
    let d = moderate(dir);
    let scale = b.ellipsoid_y_scale;
    let dir = V3::new(d.x, scale * d.y, d.z);
    let (foot, inv_len_sq) = foot_point(V3::new(origin.x, scale * origin.y, origin.z), dir);
    let half_chord_sq = b.outer_safe_sq - foot.length_squared();
    let unit_y_sq = dir.y * dir.y * inv_len_sq;
    let above = foot.y.abs() - b.ellipsoid_slab;
    let beyond_slab = above.gt(zero) & (above * above).gt(unit_y_sq * half_chord_sq);
    EllipsoidChord {
        foot,
        dir,
        inv_len_sq,
        half_chord_sq,
        keep: half_chord_sq.ge(zero) & !beyond_slab,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Cull;
    use crate::CullBounds;
    use glam::Vec3;

    fn keeps(big: f32, small: f32, o: [f32; 3], d: [f32; 3]) -> bool {
        EllipsoidCull.keeps(&CullBounds::new(big, small), Vec3::from(o), Vec3::from(d))
    }

    #[test]
    fn rejects_the_corner_that_the_sphere_keeps() {
        // R = 1, r = 0.5 (ν = 2): E is ρ² + 3y² ≤ 2.25. The line x = 1.4, y = 0.45 along
        // z is inside the sphere (1.96 + 0.2025 < 2.25) and the slab, but outside E
        // (1.96 + 0.6075 > 2.25); the tube at y = 0.45 only spans 0.78 < ρ < 1.22.
        assert!(!keeps(1.0, 0.5, [1.4, 0.45, -3.0], [0.0, 0.0, 1.0]));
        assert!(super::super::CychoszCull.keeps(
            &CullBounds::new(1.0, 0.5),
            Vec3::new(1.4, 0.45, -3.0),
            Vec3::Z
        ));
        // The same height through the axis crosses the tube: kept.
        assert!(keeps(1.0, 0.5, [-3.0, 0.45, 0.0], [1.0, 0.0, 0.0]));
    }

    #[test]
    fn keeps_the_contact_circles() {
        // Tangent to the top circle y = r, ρ = R (the slab's contact), and to the outer
        // equator (E's contact), horizontally and vertically.
        assert!(keeps(1.0, 0.5, [1.0, 0.5, -3.0], [0.0, 0.0, 1.0]));
        assert!(keeps(1.0, 0.5, [1.5, 0.0, -3.0], [0.0, 0.0, 1.0]));
        assert!(keeps(1.0, 0.5, [1.5, -3.0, 0.0], [0.0, 1.0, 0.0]));
    }

    #[test]
    fn y_scale_rounds_down() {
        for (big, small) in [(1.0f32, 0.5f32), (1.0, 0.99), (1000.0, 1.0), (1e-3, 1e-6)] {
            let b = CullBounds::new(big, small);
            let exact =
                ((f64::from(big) + f64::from(b.minor_safe)) / f64::from(b.minor_safe)).sqrt();
            assert!(f64::from(b.ellipsoid_y_scale) <= exact);
            assert!(f64::from(b.ellipsoid_y_scale) > exact * (1.0 - 1e-6));
        }
    }
}
