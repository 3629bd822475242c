//! The oracle's label for a ray whose origin is a surface point (`Ray::from_surface`),
//! by the rule of docs/math.md §9: the origin is the surface point it rounds, its own
//! crossing is excluded, and the rest of the ray is labelled as any ray is. Computed from
//! the line's reference crossings and distances alone (no code of the crate's solver).
//!
//! **The surface point.** The origin `o` is moved onto the surface in f64 (the closed-form
//! nearest point `p′`, computed here independently of the crate), and the line through
//! `p′` is labelled: the offset `|o − p′|` is the rounding of a surface point, not
//! information, so the origin's own crossing is known to f64 rounding. A re-hit close to
//! the origin (at the saddle, where the surface curves back to meet a ray that leaves it
//! nearly along the ring) is then found wherever f64 can separate it from the origin: its
//! existence depends on the angle and the curvature, not on the rounding of the origin
//! along the normal.
//!
//! **The rule.** With θ₀ the angle between the direction and the normal at `p′`, the own
//! crossing lies within `w = 4·(δ′ + 10⁻¹¹·(R + r))/(|cos θ₀|·|d|)` of `t = 0` (δ′ the
//! distance of `p′` from the surface, f64 rounding; the 10⁻¹¹ covers the oracle's own
//! error). The roots within `w` are the origin's. Then:
//! - **ambiguous** when a crossing lies in `(w, 2w]` (not separable from the origin's),
//!   or when the line rises (or, into the tube, sinks) by no more than the oracle's error
//!   `4·10⁻¹¹·(R + r)` before its next crossing (a re-hit that cannot be told from a
//!   touch at the origin);
//! - otherwise, for a ray that leaves into the outside, the label, with its margin, of the
//!   line over `[max(t_min, t_a), t_max]`, `t_a` its highest point before its next
//!   crossing (none: it never comes back, a miss); ambiguous where `|margin| ≤
//!   ε·(R + r) + 2·|o − p′|`, since the input locates its surface point only to within its
//!   own offset, and a graze that close is not determined by it;
//! - for a ray into the tube, whether its next crossing (where it leaves the tube) lies in
//!   the range: hit or miss, ambiguous within the band of `t_max`; the margin is that of
//!   the range, negative (the ray runs inside the tube).

use super::frame::{LineFrame, across_axis};
use super::spawned_rule::{SpawnedLine, miss_by};
use super::{OracleClass, OracleLabel, Query, reference_roots};
use glam::DVec3;

/// [`Query::classify`] for a ray from a surface point: the rule of the module docs.
///
/// # Panics
/// As [`Query`].
pub fn classify_from_surface(query: &Query) -> OracleLabel {
    match decide(query) {
        Some((label, _)) => label,
        None => OracleLabel {
            class: OracleClass::Ambiguous,
            margin: 0.0,
        },
    }
}

/// For a ray that [`classify_from_surface`] labels a hit: its first crossing after the
/// origin's own (units of `t`, from the surface point).
pub fn first_crossing_from_surface(query: &Query) -> Option<f64> {
    decide(query).and_then(|(label, first)| (label.class == OracleClass::Hit).then_some(first)?)
}

/// The line of a ray from a surface point as the on-surface rule reads it: its origin
/// moved onto the surface (the oracle's own closed form; an origin on the axis or the
/// core circle stays), the direction and range unchanged.
pub fn on_surface_line(query: &Query) -> Query {
    Query {
        o: moved_onto_surface(query).0,
        ..*query
    }
}

/// The label and the first crossing in range past the origin's own; `None` ambiguous.
fn decide(query: &Query) -> Option<(OracleLabel, Option<f64>)> {
    let size = query.major + query.minor;
    let (on, offset) = moved_onto_surface(query);
    let line = Query { o: on, ..*query };
    let (delta, normal) = off_surface_at(&line, on);
    let len = line.d.length();
    let cos0 = normal.dot(line.d / len);
    if cos0.abs() <= 1e-12 {
        // Tangent at the origin: nothing past it can be told.
        return None;
    }
    let range = (query.t_min, query.t_max);
    let spawned = SpawnedLine::new(delta.abs(), cos0.abs(), range, len, size);
    let window = spawned.window;
    let roots = reference_roots(&line.over(f64::NEG_INFINITY, f64::INFINITY));
    let next = roots.iter().copied().find(|&t| t > window);
    if next.is_some_and(|t| t <= 2.0 * window) {
        return None;
    }
    let frame = LineFrame::new(&line);
    let g = |t: f64| frame.dist(frame.s_of_t(t)) - line.minor;
    // The line's extreme point between the origin's window and its next crossing (the
    // ray's end where there is none): the highest out of the tube, the deepest into it.
    let outward = cos0 > 0.0;
    let end = next.unwrap_or(f64::INFINITY);
    let (lo_s, hi_s) = (frame.s_of_t(window), frame.s_of_t(end));
    let mut extreme: Option<(f64, f64)> = None;
    for s in frame.d_candidates(lo_s, hi_s) {
        let t = frame.t_of_s(s);
        let v = g(t);
        let better = extreme.is_none_or(|(_, e)| if outward { v > e } else { v < e });
        if better {
            extreme = Some((t, v));
        }
    }
    let first = roots.iter().copied().find(|&t| spawned.ahead_in_range(t));
    // The line over [lo, t_max]: the answer past the extreme point.
    let over = |lo: f64| line.over(lo, query.t_max).classify();
    if outward {
        let Some(t_next) = next else {
            // Never comes back: a miss, by the distance at the range's start.
            let lo = query.t_min.max(window);
            let margin = if lo <= query.t_max { g(lo) } else { 0.0 };
            return Some((miss_by(margin), None));
        };
        let mid = 0.5 * (window + t_next);
        let rise = (Some(extreme.unwrap_or((mid, g(mid)))), true);
        return spawned.leaving_solid(rise, || g(query.t_max), over, offset, first);
    }
    // Into the tube: the next crossing is where the ray leaves it.
    spawned.entering_solid(next?, extreme.map(|(_, depth)| depth), over, first)
}

/// The surface point nearest to the query's origin (f64, closed form: the nearest point
/// of the core circle, then `r` along the way to the origin) and the origin's distance
/// from it. An origin on the axis or the core circle (no unique nearest point) stays.
fn moved_onto_surface(query: &Query) -> (DVec3, f64) {
    let axis = query.axis.normalize();
    let rel = query.o - query.center;
    let (_, radial) = across_axis(rel, axis);
    let rho = radial.length();
    if rho.is_nan() || rho <= 0.0 {
        return (query.o, 0.0);
    }
    let core = radial * (query.major / rho);
    let off = rel - core;
    let dist = off.length();
    if dist.is_nan() || dist <= 0.0 {
        return (query.o, 0.0);
    }
    let on = query.center + core + off * (query.minor / dist);
    (on, (on - query.o).length())
}

/// A point's signed distance from the surface (negative inside the tube) and the unit
/// outward normal at its nearest surface point.
fn off_surface_at(query: &Query, x: DVec3) -> (f64, DVec3) {
    let axis = query.axis.normalize();
    let rel = x - query.center;
    let (_, radial) = across_axis(rel, axis);
    let rho = radial.length();
    let core = if rho > 0.0 {
        radial * (query.major / rho)
    } else {
        DVec3::ZERO
    };
    let off = rel - core;
    let dist = off.length();
    let normal = if dist > 0.0 { off / dist } else { axis };
    (dist - query.minor, normal)
}

#[cfg(test)]
mod tests {
    use super::*;
    use torus_cull::{DRay, Torus};

    fn label(o: DVec3, d: DVec3, t_max: f64) -> OracleLabel {
        let torus = Torus::canonical(4.0, 1.0).unwrap();
        let ray = DRay::with_range(o, d, 0.0, t_max).unwrap();
        classify_from_surface(&Query::dray(&torus, &ray))
    }

    #[test]
    fn the_origins_own_crossing_is_excluded() {
        let (inner, top) = (DVec3::new(3.0, 0.0, 0.0), DVec3::new(4.0, 1.0, 0.0));
        let inf = f64::INFINITY;
        for (o, d, t_max, class) in [
            // From the inner equator across the hole: the far wall at t = 6 is the hit.
            (inner, DVec3::NEG_X, inf, OracleClass::Hit),
            (inner, DVec3::NEG_X, 5.0, OracleClass::Miss),
            // From the top, straight up: nothing.
            (top, DVec3::Y, inf, OracleClass::Miss),
            // Into the tube, from the top: the bottom, t = 2.
            (top, DVec3::NEG_Y, 2.5, OracleClass::Hit),
            (top, DVec3::NEG_Y, 1.5, OracleClass::Miss),
            // Tangent at the top, along z: the own crossing is a double root, and nothing
            // else can be told at the origin: ambiguous.
            (top, DVec3::Z, inf, OracleClass::Ambiguous),
        ] {
            assert_eq!(
                label(o, d, t_max).class,
                class,
                "from {o} along {d} to {t_max}"
            );
        }
    }
}
