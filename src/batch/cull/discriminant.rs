//! `discriminant` over lanes: the quartic's real-root classification in f32 (Rees 1922,
//! Lazard 1988; see [`crate::DiscriminantCull`]).

use super::{LaneCull, moderate};
use crate::CullBounds;
use crate::batch::lanes::{F32s, M32s};
use crate::batch::vec3s::Vec3s;
use pulp::Simd;

/// Reject iff Δ′ > 0 ∧ (P > 0 ∨ S > P²), or the line misses the padded sphere, with
/// F(t) = t⁴ + 2P t² + 8Q t + S the quartic along the line (unit d, foot point f from the
/// moment m = o × d, lengths over R) and Δ′ = S(S − P²)² − 8Q²(P³ − 9PS + 54Q²).
/// About 30 multiplies, one division, no root and no branch: the cull that was written
/// for lanes.
#[derive(Clone, Copy)]
pub(super) struct Discriminant;

impl LaneCull for Discriminant {
    #[inline(always)]
    fn keeps<S: Simd>(self, s: S, b: &CullBounds, origin: Vec3s<S>, dir: Vec3s<S>) -> M32s<S> {
        macro_rules! c {
            ($x:expr) => {
                F32s::splat(s, $x)
            };
        }
        let d = moderate(dir);
        let m = origin.cross(d);
        let inv_len_sq = c!(1.0) / d.length_squared();
        let f_sq = m.length_squared() * inv_len_sq;
        let f_y = (d.z * m.x - d.x * m.z) * inv_len_sq;
        let inside_sphere = f_sq.le(c!(b.outer_safe_sq));
        let fy_sq = f_y * f_y * c!(b.inv_major_sq);
        let rho_sq = f_sq * c!(b.inv_major_sq) - fy_sq;
        let unit_y_sq = d.y * d.y * inv_len_sq;
        inside_sphere & !no_real_root(s, rho_sq, fy_sq, unit_y_sq, c!(b.minor_rel_sq))
    }
}

/// The scalar `no_real_root`, lane for lane: whether t⁴ + 2P t² + 8Q t + S has no real
/// root, at R = 1, from ρ² = f_x² + f_z², f_y², d̂_y² and r′².
#[inline(always)]
fn no_real_root<S: Simd>(
    s: S,
    rho_sq: F32s<S>,
    fy_sq: F32s<S>,
    unit_y_sq: F32s<S>,
    minor_sq: F32s<S>,
) -> M32s<S> {
    macro_rules! c {
        ($x:expr) => {
            F32s::splat(s, $x)
        };
    }
    let rho_sq_m1 = rho_sq - c!(1.0);
    let b = fy_sq - minor_sq;
    let p = rho_sq_m1 + b + c!(2.0) * unit_y_sq;
    let s_ = rho_sq_m1 * rho_sq_m1 + b * (c!(2.0) * (rho_sq + c!(1.0)) + b);
    let q_sq = fy_sq * unit_y_sq;
    let p_sq = p * p;
    let s_minus_p_sq = s_ - p_sq;
    let delta = s_ * s_minus_p_sq * s_minus_p_sq
        - c!(8.0) * q_sq * (p_sq * p - c!(9.0) * p * s_ + c!(54.0) * q_sq);
    delta.gt(c!(0.0)) & (p.gt(c!(0.0)) | s_minus_p_sq.gt(c!(0.0)))
}
