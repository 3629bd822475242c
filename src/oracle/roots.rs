//! The crossings of a line with the torus surface, to near f64 precision: the reference
//! the solver bench and the intersection tests score roots against.

use super::Query;
use super::frame::LineFrame;
use super::interval::bisect;

/// All `t ∈ [t_min, t_max]` where the [`Query`]'s line `o + t d` crosses the torus surface (D = r),
/// sorted, to near f64 precision. Pass infinite ends for the whole line.
///
/// D is monotone between consecutive critical points of D, so each such segment holds at
/// most one crossing; each sign change of `g = D − r` is bisected to adjacent floats in the
/// unit-arc-length parameter, then mapped back to `t`.
///
/// **Tangencies.** Only sign changes are reported (g = 0 counts as outside). A line that
/// touches the surface reports no root if its computed minimum of g is ≥ 0 and two nearly
/// equal roots if it is < 0. So for an ambiguous line
/// ([`OracleClass::Ambiguous`](super::OracleClass::Ambiguous)) the roots near the tangency
/// are not meaningful: compare root counts only outside the ambiguity band, where a line
/// hit gives 2 or 4 roots and a line miss gives none.
///
/// # Panics
/// As [`Query`].
pub fn reference_roots(query: &Query) -> Vec<f64> {
    let frame = LineFrame::new(query);
    // Farther than 1e100·(R + r) from the centre the line never reaches the tube; a line
    // whose numbers overflow has no roots the oracle can find.
    if frame.is_far() || !frame.is_finite() {
        return Vec::new();
    }
    let Query {
        major,
        minor,
        t_min,
        t_max,
        ..
    } = *query;
    // Beyond |s + p·u| > R + r the point is farther than R + r from the centre, so D > r.
    let reach = (major + minor) * (1.0 + 1e-6) + frame.e.abs();
    let mut cuts = vec![-reach - frame.e];
    cuts.extend(
        frame
            .d_candidates(f64::NEG_INFINITY, f64::INFINITY)
            .into_iter()
            .filter(|&s| s > -reach - frame.e && s < reach - frame.e),
    );
    cuts.push(reach - frame.e);
    cuts.sort_by(f64::total_cmp);
    let g = |s: f64| frame.dist(s) - minor;
    let mut roots = Vec::new();
    for w in cuts.windows(2) {
        let (a, b) = (w[0], w[1]);
        let (ga, gb) = (g(a), g(b));
        if (ga < 0.0) != (gb < 0.0) {
            if let Some(s) = bisect(&g, a, b, ga) {
                roots.push(frame.t_of_s(s));
            }
        }
    }
    roots.retain(|&t| t >= t_min && t <= t_max);
    roots
}
