//! `quadric` over lanes: the outer ellipsoid ∩ the slab ∩ the inner hyperboloid
//! ρ² − (ν − 1)·y² ≥ (R − r)² (see [`crate::QuadricCull`]).

use super::LaneCull;
use super::ellipsoid::{EllipsoidChord, ellipsoid_slab};
use crate::CullBounds;
use crate::batch::lanes::{F32s, M32s};
use crate::batch::vec3s::Vec3s;
use crate::cull::HORIZONTAL_DY;
use pulp::Simd;

/// `ellipsoid`'s chord, clipped to the slab; keep iff H ≥ 0 at a clip end or at the
/// vertex of H(τ) when it is concave and inside. The scalar cull skips the hyperboloid
/// stage for lines `ellipsoid` rejects; here every lane runs it and the verdicts are
/// combined with `&`, which is the same answer.
#[derive(Clone, Copy)]
pub(super) struct Quadric;

impl LaneCull for Quadric {
    #[inline(always)]
    fn keeps<S: Simd>(self, s: S, b: &CullBounds, origin: Vec3s<S>, dir: Vec3s<S>) -> M32s<S> {
        let chord = ellipsoid_slab(s, b, origin, dir);
        chord.keep & reaches_hyperboloid(s, b, &chord)
    }
}

/// The scalar `reaches_hyperboloid`, lane for lane (f32 `min`/`max` ignore NaN, as there).
#[inline(always)]
fn reaches_hyperboloid<S: Simd>(s: S, b: &CullBounds, chord: &EllipsoidChord<S>) -> M32s<S> {
    macro_rules! c_ {
        ($x:expr) => {
            F32s::splat(s, $x)
        };
    }
    let EllipsoidChord {
        foot: q,
        dir: d,
        inv_len_sq,
        half_chord_sq,
        ..
    } = *chord;
    let half = (half_chord_sq.max_num(c_!(0.0)) * inv_len_sq).sqrt();
    let dy = d.y.abs().max_num(c_!(HORIZONTAL_DY)).copysign(d.y);
    let inv_dy = c_!(1.0) / dy;
    let slab = c_!(b.ellipsoid_slab);
    let t_bottom = (-slab - q.y) * inv_dy;
    let t_top = (slab - q.y) * inv_dy;
    let lo = (-half).max_num(t_bottom.min_num(t_top));
    let hi = half.min_num(t_bottom.max_num(t_top));
    let c = c_!(b.hyperboloid_y_coef);
    let inner_sq = c_!(b.inner_safe_sq);
    macro_rules! h_at {
        ($x:expr) => {{
            let x: Vec3s<S> = $x;
            x.x * x.x + x.z * x.z - c * x.y * x.y - inner_sq
        }};
    }
    let neg_a = c * d.y * d.y - d.x * d.x - d.z * d.z;
    let half_b = q.x * d.x + q.z * d.z - c * q.y * d.y;
    let vertex_inside = neg_a.gt(c_!(0.0)) & half_b.ge(lo * neg_a) & half_b.le(hi * neg_a);
    let vertex_reaches = (h_at!(q) * neg_a + half_b * half_b).ge(c_!(0.0));
    h_at!(q + d * lo).ge(c_!(0.0))
        | h_at!(q + d * hi).ge(c_!(0.0))
        | (vertex_inside & vertex_reaches)
}
