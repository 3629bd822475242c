//! `skala` over lanes: Skala's circle-based test with the paper's misprints corrected
//! (see [`crate::SkalaCull`] and `docs/math.md`).

use super::cychosz::{SphereSlab, sphere_slab};
use super::{LaneCull, rescaled};
use crate::CullBounds;
use crate::batch::lanes::{F32s, M32s};
use crate::batch::vec3s::Vec3s;
use crate::cull::AXIS_PARALLEL_H2;
use pulp::Simd;

/// Cychosz's sphere + slab, then the case of the line's plane (distance a from the axis):
/// axis-parallel (keep iff R − r_η < ρ), outer band a ≥ R (the slab shrinks to
/// |Y| ≤ h_c = √(r² − (a − R)²)), hole a < R − r (reject a line that falls through
/// between the circles k, k′), else keep.
///
/// The scalar cull leaves early, because on branchy hardware most lines leave at
/// Cychosz's test; on lanes there is no leaving, so every case is evaluated on every lane
/// (three square roots and no division) and the case selects the answer. Each case's
/// formula is the scalar one, term for term, so the selected bit is the scalar verdict.
#[derive(Clone, Copy)]
pub(super) struct Skala;

impl LaneCull for Skala {
    #[inline(always)]
    fn keeps<S: Simd>(self, s: S, b: &CullBounds, origin: Vec3s<S>, dir: Vec3s<S>) -> M32s<S> {
        macro_rules! c {
            ($x:expr) => {
                F32s::splat(s, $x)
            };
        }
        let SphereSlab {
            foot: p,
            half_chord_sq,
            unit_y_sq,
            keep,
        } = sphere_slab(s, b, origin, dir);
        let d = rescaled(dir);
        let len_sq = d.length_squared();
        let h_sq = d.x * d.x + d.z * d.z;
        let axis_parallel = h_sq.lt(c!(AXIS_PARALLEL_H2) * len_sq);
        let axis_keep = (p.x * p.x + p.z * p.z).gt(c!(b.inner_safe_sq));
        let a_h = (p.x * d.z - p.z * d.x).abs();
        let a_h_sq = a_h * a_h;
        let h = h_sq.sqrt();

        // Outer band (cases c, d): lowest² + (a − R)² ≤ r_η², times h².
        let band = a_h_sq.ge(c!(b.major_radius) * c!(b.major_radius) * h_sq);
        let reach_sq = unit_y_sq * half_chord_sq;
        let crosses_mid_plane = (p.y * p.y).le(reach_sq);
        let lowest = p.y.abs() - reach_sq.sqrt();
        let off = a_h - c!(b.major_radius) * h;
        let band_height_sq_h2 = c!(b.minor_safe_sq) * h * h - off * off;
        let band_keep = crosses_mid_plane | (lowest * lowest * h_sq).le(band_height_sq_h2);

        // Hole (case a): reject if x_B·h·|d_y| ≥ |M| + r_η·h·(|d| − |d_y|), squared.
        let hole = a_h_sq.lt(c!(b.inner_safe_sq) * h_sq);
        let moment = (p.x * d.x + p.z * d.z) * d.y - p.y * h_sq;
        let edge = (c!(b.inner_safe_sq) * h_sq - a_h * a_h) * (d.y * d.y);
        let out_of_reach = edge.lt(moment * moment);
        let len = len_sq.sqrt();
        let rhs = moment.abs() + c!(b.minor_safe) * h * (len - d.y.abs());
        let hole_keep = out_of_reach | edge.lt(rhs * rhs);

        let by_case = axis_parallel.select_mask(
            axis_keep,
            band.select_mask(band_keep, hole.select_mask(hole_keep, M32s::splat(s, true))),
        );
        keep & by_case
    }
}
