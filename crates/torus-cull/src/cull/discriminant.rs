//! `discriminant` and `discriminant_f64`: the ray–torus quartic's real-root
//! classification, exact and root-free.

use super::kernel::{CullKernel, LaneBounds, scalar_cull};
use super::moderate;
use crate::num::{Real, Real32, V3};

scalar_cull! {
    /// Reject a line when its quartic has no real root, read from the discriminant; f32.
    ///
    /// **Bound.** With unit d, the foot point f (f·d = 0) and lengths in units of R
    /// (r′ = r/R), the torus quartic along the line is exactly
    /// F(t) = t⁴ + 2P t² + 8Q t + S, with k = |f|² + 1 − r′², P = k − 2 + 2d_y²,
    /// Q = f_y d_y, S = k² − 4(f_x² + f_z²). A depressed quartic y⁴ + p y² + q y + s has no
    /// real root iff its discriminant is > 0 and (p > 0 or s > p²/4) (E. L. Rees, Amer.
    /// Math. Monthly 29, 1922; D. Lazard, J. Symbolic Comput. 5, 1988), here:
    /// **reject ⇔ Δ′ > 0 ∧ (P > 0 ∨ S > P²)**, with
    /// Δ′ = Δ/256 = S(S − P²)² − 8Q²(P³ − 9PS + 54Q²). Only Q² appears, so d_y enters as
    /// d_y²/|d|²: one division (as in Cychosz), no root, no branch (it vectorizes). Lines
    /// outside the padded bounding sphere are rejected too, which also keeps the degree-12
    /// terms of Δ′ far from overflow for distant lines.
    ///
    /// **Why it is sound.** F > 0 exactly outside the tube (F = (D² − r²)·G with D the
    /// distance to the core circle and G > 0 on a ring torus), and its leading coefficient is
    /// positive, so no real root means the line never enters the torus. The one no-root case
    /// not rejected (two complex-conjugate double roots, Δ = 0) is kept: harmless.
    ///
    /// **Floating point.** At a tangent line Δ has a simple zero, so its relative error is
    /// unbounded there: no margin is put on Δ. The tube is padded instead (r′ = r_η/R,
    /// r_η = r + η), so a line that hits the torus has to move by more than η before its
    /// T_η quartic loses its real roots: rounding that acts like a smaller move cannot make
    /// it look rootless. The kept misses are the lines within η of the surface (the padding
    /// band), and nothing else. Two evaluation details keep f32 rounding that small:
    /// * f must be orthogonal to d to the precision of the torus, not of the origin: the
    ///   foot point is projected twice (the second time from a point near the torus), as a
    ///   far f32 foot point slides along the line by ≈ ε|o| and changes Q;
    /// * S is evaluated as (ρ² − 1)² + b(2(ρ² + 1) + b), b = f_y² − r′², ρ² = f_x² + f_z²:
    ///   k² − 4ρ² without its cancellation (both ≈ 4 on a hitting line, S ≈ r′²).
    ///
    /// That this suffices is measured, not proven: 0 rejected hits on the adversarial and
    /// conservativeness families (ν 1.01–1000, R 1e-3–1e3, tangents to ±1e-7·r, near-double
    /// roots, origins 250·(R + r) away), where every cull, even `sphere`, still passes with
    /// η four times smaller, and fails at sixteen times smaller.
    pub struct DiscriminantCull = "discriminant";
}

impl CullKernel for DiscriminantCull {
    #[inline(always)]
    fn keeps_lanes<R: Real32>(self, b: &LaneBounds<R>, o: V3<R>, d: V3<R>) -> R::Mask {
        // The foot point from the moment m = o × d, f = d × m/|d|², is orthogonal to d
        // to the rounding of f itself; o − d(o·d)/|d|² slides along the line by ≈ ε|o|,
        // which changes Q = f_y d_y (a far, steep line through a small hole was once
        // rejected although it hit). It is also a shorter dependency chain.
        // With |d|² in [2⁻⁴⁰, 2⁴⁰], |m|² cannot overflow for origins within 10¹³.
        let d = moderate(d);
        let m = o.cross(d);
        let inv_len_sq = b.inv_major_sq.k(1.0) / d.length_squared();
        let f_sq = m.length_squared() * inv_len_sq;
        let f_y = (d.z * m.x - d.x * m.z) * inv_len_sq;
        let inside_sphere = f_sq.le(b.outer_safe_sq);
        let fy_sq = f_y * f_y * b.inv_major_sq;
        let rho_sq = f_sq * b.inv_major_sq - fy_sq;
        let unit_y_sq = d.y * d.y * inv_len_sq;
        inside_sphere & !no_real_root(rho_sq, fy_sq, unit_y_sq, b.minor_rel_sq)
    }
}

/// Whether F(t) = t⁴ + 2P t² + 8Q t + S has no real root, at R = 1, from ρ² = f_x² + f_z²,
/// f_y², d̂_y² and r′². About 20 multiplies and 12 adds, no branch.
#[inline(always)]
pub(super) fn no_real_root<T: Real>(rho_sq: T, fy_sq: T, unit_y_sq: T, minor_sq: T) -> T::Mask {
    let (zero, one, two) = (rho_sq.k(0.0), rho_sq.k(1.0), rho_sq.k(2.0));
    let rho_sq_m1 = rho_sq - one;
    let b = fy_sq - minor_sq;
    // P = k − 2 + 2d̂_y², with k − 2 = (ρ² − 1) + b.
    let p = rho_sq_m1 + b + two * unit_y_sq;
    // S = k² − 4ρ², rearranged so that no two large terms cancel.
    let s = rho_sq_m1 * rho_sq_m1 + b * (two * (rho_sq + one) + b);
    let q_sq = fy_sq * unit_y_sq;
    let p_sq = p * p;
    let s_minus_p_sq = s - p_sq;
    let delta = s * s_minus_p_sq * s_minus_p_sq
        - zero.k(8.0) * q_sq * (p_sq * p - zero.k(9.0) * p * s + zero.k(54.0) * q_sq);
    delta.gt(zero) & (p.gt(zero) | s_minus_p_sq.gt(zero))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::{F32s, F64s};
    use glam::DVec3;
    use pulp::Scalar;

    /// The quartic's coefficients from P, Q, S against the direct expansion of
    /// (|x|² + 1 − r′²)² − 4ρ² along the line, at a few points.
    #[test]
    fn foot_point_form_matches_the_torus_quartic() {
        let minor_sq = 0.3f64 * 0.3;
        let f = DVec3::new(0.4, 0.16, -0.12);
        let d = DVec3::new(0.0, 0.6, 0.8); // unit, f·d = 0
        assert!(f.dot(d).abs() < 1e-15);
        let rho_sq = f.x * f.x + f.z * f.z;
        let k = f.length_squared() + 1.0 - minor_sq;
        let p = k - 2.0 + 2.0 * d.y * d.y;
        let q = f.y * d.y;
        let s = k * k - 4.0 * rho_sq;
        let a1 = rho_sq - 1.0;
        let b = f.y * f.y - minor_sq;
        assert!((s - (a1 * a1 + b * (2.0 * (rho_sq + 1.0) + b))).abs() < 1e-12);
        for t in [-2.0, -0.5, 0.0, 0.3, 1.7] {
            let x = f + d * t;
            let direct =
                (x.length_squared() + 1.0 - minor_sq).powi(2) - 4.0 * (x.x * x.x + x.z * x.z);
            let folded = t * t * t * t + 2.0 * p * t * t + 8.0 * q * t + s;
            assert!((direct - folded).abs() < 1e-12, "t={t}");
        }
    }

    /// [`no_real_root`] itself on quartics t⁴ + 2P t² + 8Q t + S with known roots, driven
    /// through its inputs.
    ///
    /// With d̂_y² = u, a₁ = ρ² − 1 and b = f_y² − r′², the cull forms P = a₁ + b + 2u,
    /// Q² = f_y² u and S = a₁² + b(2(ρ² + 1) + b) = c² + 4b with c = a₁ + b. So a target
    /// (P, Q, S) is c = P − 2u, b = (S − c²)/4, a₁ = c − b, f_y² = Q²/u (the inputs are
    /// algebraic here: ρ² or r′² may be negative). Every value is a short dyadic fraction,
    /// so the f32 and f64 evaluations are exact and Δ = 0 stays 0.
    #[test]
    fn classification_on_known_quartics() {
        let rootless = |p: f64, q: f64, s: f64| {
            let u = 0.25;
            let c = p - 2.0 * u;
            let b = (s - c * c) / 4.0;
            let rho_sq = c - b + 1.0;
            let fy_sq = q * q / u;
            let minor_sq = fy_sq - b;
            let f64s = |x: f64| F64s::splat(Scalar::new(), x);
            let f32s = |x: f64| F32s::splat(Scalar::new(), x as f32);
            let wide = no_real_root(f64s(rho_sq), f64s(fy_sq), f64s(u), f64s(minor_sq)).m;
            let narrow = no_real_root(f32s(rho_sq), f32s(fy_sq), f32s(u), f32s(minor_sq)).m;
            assert_eq!(wide, narrow, "P = {p}, Q = {q}, S = {s}");
            wide
        };
        // (t² + 1)(t² + 4) = t⁴ + 5t² + 4: no real root.
        assert!(rootless(2.5, 0.0, 4.0));
        // (t² + 2t + 2)(t² − 2t + 5) = t⁴ + 3t² + 6t + 10: no real root, Q ≠ 0.
        assert!(rootless(1.5, 0.75, 10.0));
        // (t² − 1)(t² + 1) = t⁴ − 1: two real roots.
        assert!(!rootless(0.0, 0.0, -1.0));
        // (t − 1)(t − 2)(t² + 3t + 3.25) = t⁴ − 3.75t² − 3.75t + 6.5: two, Q ≠ 0.
        assert!(!rootless(-1.875, -0.46875, 6.5));
        // (t² − 1)(t² − 4) = t⁴ − 5t² + 4: four real roots, Δ > 0, P < 0, S < P².
        assert!(!rootless(-2.5, 0.0, 4.0));
        // (t² + 1)² = t⁴ + 2t² + 1: a complex double pair, Δ = 0: kept.
        assert!(!rootless(1.0, 0.0, 1.0));
        // (t² − 1)² = t⁴ − 2t² + 1: a real double pair, Δ = 0: kept.
        assert!(!rootless(-1.0, 0.0, 1.0));
    }
}
