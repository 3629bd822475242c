//! `quadric`: the outer ellipsoid ∩ the slab ∩ the inner hyperboloid, two quadrics that
//! touch the torus.

use super::ellipsoid::{EllipsoidChord, ellipsoid_slab};
use super::kernel::{CullKernel, LaneBounds, scalar_cull};
use crate::num::{Real, Real32, RealMask, V3};

scalar_cull! {
    /// Reject lines that miss E ∩ {|y| ≤ r} ∩ {H ≥ 0}, with the outer ellipsoid
    /// E: ρ² + (ν + 1)·y² ≤ (R + r)² and the inner hyperboloid H: ρ² − (ν − 1)·y² − (R − r)².
    ///
    /// **Bound.** First `ellipsoid`'s test (the chord of E and the slab); on the survivors,
    /// the chord is clipped to the slab and H, a quadratic along the line, is maximized over
    /// what is left: at the two ends, or at the vertex when H is concave along the line.
    /// Reject when that maximum is < 0. E wins at small ν, H (which hugs the hole) at large ν.
    ///
    /// **Why it is sound.** On the tube surface ρ = R + r cos θ, y = r sin θ, H equals
    /// Rr(1 + cos θ)² ≥ 0, zero only on the inner equator; H's Hessian diag(2, −2(ν − 1)) is
    /// indefinite, so H has no interior minimum on a cross-section disk and the whole solid
    /// torus has H ≥ 0. With `ellipsoid`'s argument the torus lies in E ∩ slab ∩ {H ≥ 0}.
    /// The first stage is `ellipsoid`'s own code, so this rejects a superset of it exactly.
    ///
    /// **Floating point.** Both quadrics are those of the padded torus T_η (tube r_η = r + η),
    /// with their y coefficients rounded toward the wider solid. A line through the torus
    /// passes a point x with a ball of radius η around it inside T_η, so x is ≥ η inside the
    /// clipped chord and H_η(x) ≥ η·|∇H(x)| − η² ≥ (R − r)·η. The evaluation error is
    /// ≈ 10ε·(R + r)², below that margin down to ν ≈ 1.01: H is evaluated at the clip ends
    /// as points, and at the vertex as C·|A| + B² ≥ 0, where C = H(q) and B²/|A| =
    /// H(τ*) − H(q) are differences of values of H over E, bounded by 3(R + r)². A
    /// horizontal line (d_y = 0) leaves the slab unclipped.
    ///
    /// **Cost.** `ellipsoid`'s test, then the hyperboloid stage (a root for the chord, a
    /// division for the slab) only when some lane survived `ellipsoid`: at width 1 that is
    /// the scalar early exit, so a line `ellipsoid` rejects pays no root and no division
    /// beyond it; on lanes a register with no survivor skips the stage, and any other
    /// pays one `any` test besides the branch-free form.
    pub struct QuadricCull = "quadric";
}

impl CullKernel for QuadricCull {
    #[inline(always)]
    fn keeps_lanes<R: Real32>(self, b: &LaneBounds<R>, o: V3<R>, d: V3<R>) -> R::Mask {
        let chord = ellipsoid_slab(b, o, d);
        // No line left to decide: at width 1 the scalar early exit.
        if !chord.keep.any() {
            return chord.keep;
        }
        chord.keep & reaches_hyperboloid(b, &chord)
    }
}

/// |d_y| below this (|d| ≥ 2⁻²⁰ after `moderate`) is treated as horizontal: the slab
/// interval is then ±(s·r_η + |q_y|)·1e20, far beyond the chord, instead of ±∞ or 0·∞.
pub(crate) const HORIZONTAL_DY: f32 = 1e-20;

/// Whether H ≥ 0 somewhere on the chord of E clipped to the slab (all in y-scaled
/// coordinates, where H is ρ² − c·y′² − (R − r_η)², c = (ν_η − 1)/(ν_η + 1)). The clip
/// uses the float type's `min`/`max`, which ignore a NaN operand.
#[inline(always)]
fn reaches_hyperboloid<R: Real>(b: &LaneBounds<R>, chord: &EllipsoidChord<R>) -> R::Mask {
    let EllipsoidChord {
        foot: q,
        dir: d,
        inv_len_sq,
        half_chord_sq,
        ..
    } = *chord;
    // Points are q + τ·d; the chord of E is |τ| ≤ √(half_chord_sq)/|d|.
    let zero = inv_len_sq.k(0.0);
    let half = (half_chord_sq.max_num(zero) * inv_len_sq).sqrt();
    let dy = d.y.abs().max_num(zero.k(HORIZONTAL_DY)).copysign(d.y);
    let inv_dy = zero.k(1.0) / dy;
    let slab = b.ellipsoid_slab;
    let t_bottom = (slab.negate() - q.y) * inv_dy;
    let t_top = (slab - q.y) * inv_dy;
    let lo = half.negate().max_num(t_bottom.min_num(t_top));
    let hi = half.min_num(t_bottom.max_num(t_top));
    let c = b.hyperboloid_y_coef;
    let inner_sq = b.inner_safe_sq;
    // A macro, not a closure: a closure that LLVM leaves outlined would run without the
    // SIMD target features.
    macro_rules! h_at {
        ($x:expr) => {{
            let x: V3<R> = $x;
            x.x * x.x + x.z * x.z - c * x.y * x.y - inner_sq
        }};
    }
    // H(τ) = A τ² + 2B τ + C. Concave (A < 0), its maximum C + B²/|A| is at τ* = B/|A|;
    // both tests are multiplied through by |A|, so no division is needed. A vertex
    // misjudged at an end is harmless: H there is within second order of H(τ*).
    let neg_a = c * d.y * d.y - d.x * d.x - d.z * d.z;
    let half_b = q.x * d.x + q.z * d.z - c * q.y * d.y;
    let vertex_inside = neg_a.gt(zero) & half_b.ge(lo * neg_a) & half_b.le(hi * neg_a);
    let vertex_reaches = (h_at!(q) * neg_a + half_b * half_b).ge(zero);
    h_at!(q + d * lo).ge(zero) | h_at!(q + d * hi).ge(zero) | (vertex_inside & vertex_reaches)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Cull;
    use crate::CullBounds;
    use crate::cull::EllipsoidCull;
    use glam::Vec3;

    fn both(big: f32, small: f32, o: [f32; 3], d: [f32; 3]) -> (bool, bool) {
        let b = CullBounds::new(big, small);
        let (o, d) = (Vec3::from(o), Vec3::from(d));
        (EllipsoidCull.keeps(&b, o, d), QuadricCull.keeps(&b, o, d))
    }

    #[test]
    fn hyperboloid_rejects_steep_lines_through_the_hole() {
        // R = 1, r = 0.125 (ν = 8): a line through the centre, 20° off the axis, stays
        // inside the hole within the slab (ρ ≤ 0.125·tan 20° ≈ 0.05 < 0.875).
        let (s, c) = 20f32.to_radians().sin_cos();
        let (e, q) = both(1.0, 0.125, [-3.0 * s, -3.0 * c, 0.0], [s, c, 0.0]);
        assert!(e && !q, "ellipsoid {e} quadric {q}");
    }

    #[test]
    fn keeps_lines_tangent_to_the_inner_equator() {
        // Horizontal, tangent to the inner equator ρ = R − r at y = 0, and vertical there.
        assert_eq!(
            both(1.0, 0.125, [0.875, 0.0, -3.0], [0.0, 0.0, 1.0]),
            (true, true)
        );
        assert_eq!(
            both(1.0, 0.125, [0.875, -3.0, 0.0], [0.0, 1.0, 0.0]),
            (true, true)
        );
        // Just inside the hole, vertical: rejected (by more than η ≈ 2.7e-4).
        assert_eq!(
            both(1.0, 0.125, [0.87, -3.0, 0.0], [0.0, 1.0, 0.0]),
            (true, false)
        );
    }

    #[test]
    fn horizontal_lines_at_the_slab_planes() {
        let b = CullBounds::new(1.0, 0.25);
        // Through the axis: touching the tube's top and bottom circles, and crossing it.
        for y in [0.25, -0.25, 0.0] {
            assert!(
                QuadricCull.keeps(&b, Vec3::new(-3.0, y, 0.0), Vec3::X),
                "{y}"
            );
            assert!(
                QuadricCull.keeps(&b, Vec3::new(0.0, y, 3.0), -Vec3::Z),
                "{y}"
            );
        }
        // Above and below the padded slab.
        for y in [1.01 * b.minor_safe, -1.01 * b.minor_safe] {
            assert!(
                !QuadricCull.keeps(&b, Vec3::new(-3.0, y, 0.0), Vec3::X),
                "{y}"
            );
        }
    }
}
