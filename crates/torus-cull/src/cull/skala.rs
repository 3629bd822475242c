//! `skala`: V. Skala's circle-based test ("Line–Torus Intersection for Ray Tracing:
//! Alternative Formulations"), with the paper's misprints corrected (see `docs/math.md`).

use super::cychosz::{SphereSlab, sphere_slab};
use super::kernel::{CullKernel, LaneBounds, scalar_cull};
use super::{AXIS_PARALLEL_H2, CullBounds, rescaled};
use crate::num::{Real, Real32, RealMask, V3};

scalar_cull! {
    /// Cychosz's sphere + slab first (cheap, and most rejections), then, on the survivors,
    /// tests in the plane that holds the line and is parallel to the axis.
    ///
    /// With foot point p and h = |(d_x, d_z)|, the plane's distance from the axis is
    /// a = |p_x d_z − p_z d_x| / h; the case is picked by comparing squares, so no root is
    /// taken before it is needed, and each case takes only its own:
    ///
    /// * **hole, a < R − r** (case a): with x_B = √((R − r)² − a²) (Eq. 104, not the printed
    ///   Eq. 102) the circles k, k′ of radius r centred at (±(x_B + r), 0) bound the two ovals
    ///   near the hole. With the line's in-plane moment about the axis L and unit direction
    ///   d̂, "crosses Y = 0 with |X₀| < x_B + r and misses both circles" is the one inequality
    ///   `x_B·|d̂_y| ≥ |L| + r·(1 − |d̂_y|)`; multiplied by h·|d| and squared it needs the
    ///   roots h and |d| and no division.
    ///   *Why it is sound:* with u = ρ − (R − r) and w = X − x_B, dX/dρ = ρ/X ≥ 1 gives w ≥ u,
    ///   and on the section (w − r)² + Y² − r² = (w − u)(w + u − 2r) ≤ 0 while w ≤ r: the part
    ///   of the oval with X ≤ x_B + r lies in k. A line from the hole that reaches the rest of
    ///   the oval crosses X = x_B + r at |Y| ≤ r, which is inside k too. A crossing with
    ///   x_B ≤ |X₀| < x_B + r is inside k, so the widened window is free and rounding-proof.
    /// * **outer band, R ≤ a < R + r** (case c): the section's height is
    ///   |Y| ≤ h_c = √(r² − (a − R)²) (Eq. 105 corrected), so the slab planes move in from ±r
    ///   to ±h_c: reject if the chord's lowest |Y| exceeds h_c (or h_c² < 0: case d).
    /// * **R − r ≤ a < R** (case b): the section has inflection points; sphere + slab stays.
    /// * **axis-parallel lines** (h ≈ 0): exact, keep iff R − r < ρ < R + r.
    /// * **d_y = 0**: falls out of the same formulas (constant Y; the hole test cannot fire).
    ///
    /// All radii carry the safety margin of [`CullBounds`]. Rejects a superset of `cychosz`.
    ///
    /// **One source for scalar and lanes.** The case masks select the answer, and each
    /// case runs only if some lane is in it (`any`), and returns as soon as no lane is
    /// left undecided: at width 1 those are the scalar code's branches and returns, on
    /// lanes the tail that every open lane needs. At width 1 each `any` is the test of one
    /// `bool`, so the scalar cull does what a hand-written scalar one would: after
    /// Cychosz's stage only its own case, and a square root only where that case needs
    /// one. On lanes, a register whose lanes are all decided skips the remaining cases
    /// (and their square roots) instead of computing every case and selecting.
    pub struct SkalaCull = "skala";
}

impl CullKernel for SkalaCull {
    #[inline(always)]
    fn keeps_lanes<R: Real32>(self, b: &LaneBounds<R>, o: V3<R>, d: V3<R>) -> R::Mask {
        skala_lanes::<R, Corrected>(b, o, d)
    }
}

/// The two section formulas that the paper misprints; the variants swap them.
#[doc(hidden)]
pub trait SectionFormulas {
    /// Tube radius the formulas use (padded for the timed cull).
    fn minor<R: Real>(b: &LaneBounds<R>) -> R;
    /// x_B²·h² for case a), given A = a·h and h² (any common scale of A and h).
    fn hole_edge_sq_h2<R: Real>(b: &LaneBounds<R>, a_h: R, h_sq: R) -> R;
    /// h_c²·h² for case c), given A = a·h and h (any common scale of A and h).
    fn band_height_sq_h2<R: Real>(b: &LaneBounds<R>, a_h: R, h: R) -> R;
}

/// The corrected formulas, x_B² = (R − r)² − a² (Eq. 104) and h_c² = r² − (a − R)²
/// (Eq. 105 corrected), on the padded torus T_η.
pub(crate) struct Corrected;

impl SectionFormulas for Corrected {
    #[inline(always)]
    fn minor<R: Real>(b: &LaneBounds<R>) -> R {
        b.minor_safe
    }
    #[inline(always)]
    fn hole_edge_sq_h2<R: Real>(b: &LaneBounds<R>, a_h: R, h_sq: R) -> R {
        // Rounding here acts like moving R − r and a by ~ε relative, which the margin η
        // absorbs, even where x_B has infinite slope (a ≈ R − r).
        b.inner_safe_sq * h_sq - a_h * a_h
    }
    #[inline(always)]
    fn band_height_sq_h2<R: Real>(b: &LaneBounds<R>, a_h: R, h: R) -> R {
        let off = a_h - b.major_radius * h;
        b.minor_safe_sq * h * h - off * off
    }
}

/// The Skala test with the section formulas `F`, at width 1: the scalar verdict. The
/// paper-as-printed fixtures (the lab's `errata`) are this with their own `F`.
#[doc(hidden)]
#[inline(always)]
pub fn skala_keeps<F: SectionFormulas>(
    b: &CullBounds,
    origin: glam::Vec3,
    dir: glam::Vec3,
) -> bool {
    struct With<F>(std::marker::PhantomData<F>);
    impl<F> Clone for With<F> {
        fn clone(&self) -> Self {
            *self
        }
    }
    impl<F> Copy for With<F> {}
    impl<F: SectionFormulas> CullKernel for With<F> {
        #[inline(always)]
        fn keeps_lanes<R: Real32>(self, b: &LaneBounds<R>, o: V3<R>, d: V3<R>) -> R::Mask {
            skala_lanes::<R, F>(b, o, d)
        }
    }
    super::kernel::keeps_scalar(With::<F>(std::marker::PhantomData), b, origin, dir)
}

/// The Skala test with the section formulas `F`; see [`SkalaCull`].
#[inline(always)]
fn skala_lanes<R: Real32, F: SectionFormulas>(
    b: &LaneBounds<R>,
    origin: V3<R>,
    dir: V3<R>,
) -> R::Mask {
    let SphereSlab {
        foot: p,
        half_chord_sq,
        unit_y_sq,
        keep,
    } = sphere_slab(b, origin, dir);
    // No line left to decide: at width 1 the scalar early exit (most lines leave here).
    if !keep.any() {
        return keep;
    }
    // The tail has terms of fourth degree in d (x_B²h²·d_y², M²): with |d| ~ 1e10 they
    // overflow and with |d| ~ 1e-10 they underflow, which once rejected hits.
    let d = rescaled(dir);
    let len_sq = d.length_squared();
    let h_sq = d.x * d.x + d.z * d.z;
    // Parallel to the axis: ρ is constant; the sphere already bounds it from outside.
    let axis_parallel = h_sq.lt(len_sq.k(AXIS_PARALLEL_H2) * len_sq);
    // ≥: where the padded hole closes (R ≤ r_η, a horn or spindle image) inner_safe_sq is
    // 0, and the axis itself (ρ = 0) crosses the solid.
    let axis_keep = (p.x * p.x + p.z * p.z).ge(b.inner_safe_sq);
    // a·h, with h = |(d_x, d_z)| unnormalized.
    let a_h = (p.x * d.z - p.z * d.x).abs();
    let a_h_sq = a_h * a_h;

    // Each case below runs only if some lane is in it, and takes its roots only if some
    // lane is still open in it: at width 1, the scalar code's branches and early keeps.
    // A lane that is not in a case (or not open in it) is not decided by that case's
    // answer, or is kept by it anyway, so `true` stands in for it. `kept` gathers the
    // verdicts of the lanes decided so far; once no lane is left undecided it is the
    // answer (at width 1, the scalar code's return right after each case).
    let yes = len_sq.mask(true);
    // (No lane parallel to the axis keeps none by it: at width 1, ρ's test only there.)
    let kept = if axis_parallel.any() {
        keep & axis_parallel & axis_keep
    } else {
        !yes
    };
    let undecided = keep & !axis_parallel;
    if !undecided.any() {
        return kept;
    }

    // Outer band (case c, and d when h_c² < 0): the slab shrinks to |Y| ≤ h_c, tested as
    // lowest² + (a − R)² ≤ r², times h² so that no division is needed. A chord that
    // crosses y = 0 (p_y² ≤ its squared height reach) has lowest = 0: keep, no root.
    let band = a_h_sq.ge(b.major_radius * b.major_radius * h_sq);
    let in_band = undecided & band;
    let (kept, undecided) = if in_band.any() {
        let band_keep =
            outer_band_keeps::<R, F>(b, p, unit_y_sq * half_chord_sq, (a_h, h_sq), in_band);
        let undecided = undecided & !band;
        let kept = kept | (in_band & band_keep);
        if !undecided.any() {
            return kept;
        }
        (kept, undecided)
    } else {
        (kept, undecided)
    };

    // Hole (case a): reject if the line falls through between k and k′. The in-plane
    // moment, times h·|d|, is M = (p_x d_x + p_z d_z)·d_y − p_y·h², the same at every
    // point of the line. (p_y·|d|/h would do at the exact foot point, but in f32 p slides
    // along the line by ~ε|o|, and 1/h would amplify that for steep lines.) Rejection
    // needs x_B·h·|d_y| ≥ |M| + r·h·(|d| − |d_y|): if even |M| alone is out of reach the
    // line is kept, before any root is taken.
    let in_hole = undecided & a_h_sq.lt(b.inner_safe_sq * h_sq);
    let hole_keep = if in_hole.any() {
        hole_keeps::<R, F>(b, p, d, (a_h, h_sq, len_sq), in_hole)
    } else {
        yes
    };

    // Case b (R − r ≤ a < R) keeps what sphere + slab keep.
    kept | (undecided & (!in_hole | hole_keep))
}

/// The outer band's verdict on the lanes `in_band`: the slab shrinks to |Y| ≤ h_c, tested
/// as lowest² + (a − R)² ≤ r², times h² so that no division is needed; `reach_sq` is the
/// chord's squared height reach, so a chord that crosses y = 0 (p_y² ≤ reach²) has
/// lowest = 0: keep, no root.
#[inline(always)]
fn outer_band_keeps<R: Real, F: SectionFormulas>(
    b: &LaneBounds<R>,
    p: V3<R>,
    reach_sq: R,
    (a_h, h_sq): (R, R),
    in_band: R::Mask,
) -> R::Mask {
    let crosses_mid_plane = (p.y * p.y).le(reach_sq);
    if !(in_band & !crosses_mid_plane).any() {
        return p.x.mask(true);
    }
    let lowest = p.y.abs() - reach_sq.sqrt();
    let h = h_sq.sqrt();
    crosses_mid_plane | (lowest * lowest * h_sq).le(F::band_height_sq_h2(b, a_h, h))
}

/// The hole's verdict on the lanes `in_hole`: keep unless the line falls through between
/// k and k′ (the in-plane moment M against the edge, see the caller).
#[inline(always)]
fn hole_keeps<R: Real, F: SectionFormulas>(
    b: &LaneBounds<R>,
    p: V3<R>,
    d: V3<R>,
    (a_h, h_sq, len_sq): (R, R, R),
    in_hole: R::Mask,
) -> R::Mask {
    let moment = (p.x * d.x + p.z * d.z) * d.y - p.y * h_sq;
    let edge = F::hole_edge_sq_h2(b, a_h, h_sq) * (d.y * d.y);
    let out_of_reach = edge.lt(moment * moment);
    if !(in_hole & !out_of_reach).any() {
        return p.x.mask(true);
    }
    let h = h_sq.sqrt();
    let len = len_sq.sqrt();
    let rhs = moment.abs() + F::minor(b) * h * (len - d.y.abs());
    out_of_reach | edge.lt(rhs * rhs)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Cull;
    use glam::Vec3;

    fn keeps(r_major: f32, r_minor: f32, o: [f32; 3], d: [f32; 3]) -> bool {
        SkalaCull.keeps(
            &CullBounds::new(r_major, r_minor),
            Vec3::from(o),
            Vec3::from(d),
        )
    }

    #[test]
    fn vertical_lines_exact() {
        // R = 2, r = 1: tube spans 1 < ρ < 3.
        assert!(!keeps(2.0, 1.0, [0.5, 5.0, 0.0], [0.0, -1.0, 0.0])); // through the hole
        assert!(keeps(2.0, 1.0, [1.5, 5.0, 0.0], [0.0, -1.0, 0.0])); // through the tube
        assert!(keeps(2.0, 1.0, [0.0, 5.0, 2.9], [0.0, 1.0, 0.0]));
        assert!(!keeps(2.0, 1.0, [3.1, 5.0, 0.0], [0.0, 1.0, 0.0])); // outside
    }

    #[test]
    fn steep_line_through_the_hole_is_rejected() {
        // Crosses y = 0 at the centre, tilted 10° from the axis: falls through the hole.
        let (s, c) = 10f32.to_radians().sin_cos();
        assert!(!keeps(4.0, 1.0, [-5.0 * s, -5.0 * c, 0.0], [s, c, 0.0]));
        // Cychosz keeps it: the crossing is inside its sphere and slab.
        assert!(cychosz_keeps(
            4.0,
            1.0,
            [-5.0 * s, -5.0 * c, 0.0],
            [s, c, 0.0]
        ));
    }

    fn cychosz_keeps(r_major: f32, r_minor: f32, o: [f32; 3], d: [f32; 3]) -> bool {
        super::super::CychoszCull.keeps(
            &CullBounds::new(r_major, r_minor),
            Vec3::from(o),
            Vec3::from(d),
        )
    }

    #[test]
    fn horizontal_lines_use_band_height() {
        // R = 2, r = 1, plane z = 2.5 (a = 2.5, case c): h_c = √(1 − 0.25) ≈ 0.866.
        assert!(keeps(2.0, 1.0, [-5.0, 0.85, 2.5], [1.0, 0.0, 0.0]));
        assert!(!keeps(2.0, 1.0, [-5.0, 0.88, 2.5], [1.0, 0.0, 0.0]));
        // Case boundaries a = R − r, R, R + r, with a line at mid height.
        assert!(keeps(2.0, 1.0, [-5.0, 0.5, 1.0], [1.0, 0.0, 0.0]));
        assert!(keeps(2.0, 1.0, [-5.0, 0.5, 2.0], [1.0, 0.0, 0.0]));
        assert!(keeps(2.0, 1.0, [-5.0, 0.0, 3.0], [1.0, 0.0, 0.0]));
        assert!(!keeps(2.0, 1.0, [-5.0, 0.5, 3.0], [1.0, 0.0, 0.0]));
    }
}
