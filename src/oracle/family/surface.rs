//! The family oracle's label for a ray whose origin is a surface point, by the same rule as
//! the ring oracle's `from_surface.rs`: the origin is the surface point it rounds, its own
//! crossing is excluded, and the rest of the ray is labelled as any ray is.
//!
//! **The surface point.** The origin `o` is moved onto the surface in f64: in its meridian
//! half-plane, to the nearest point `p′` of the tube's ellipse ([`nearest_on_ellipse`],
//! bisection to adjacent floats; not the library's code). The offset `|o − p′|` is the
//! rounding of a surface point, not information. An origin on the axis (a horn's centre,
//! a spindle's cusps) or whose nearest ellipse point lies across the axis (within rounding
//! of a spindle's cusp) is at a singular point of the surface, with no tangent plane:
//! every ray from it is **ambiguous**.
//!
//! **The rule.** With θ₀ the angle between the direction and the normal `∇E` at `p′`, the
//! own crossing lies within `w = 4·(δ′ + 10⁻¹¹·S)/(|cos θ₀|·|d|)` of `t = 0`, S = R +
//! max(a, b), δ′ = |E(p′) − 1|·max(a, b) ≥ the distance of `p′` from the surface to first
//! order (f64 rounding). Crossings within `w` are the origin's. Then, as in the ring
//! oracle, and calling ambiguous only what the input cannot determine:
//! - **ambiguous** when the direction is tangent (|cos θ₀| ≤ 10⁻¹²), when the next
//!   crossing lies in `(w, 2w]` (not separable from the origin's), or when the line rises
//!   (into the solid: sinks) by no more than the oracle's error `4·10⁻¹¹·S` before its next
//!   crossing (a re-hit that cannot be told from a touch at the origin);
//! - a ray that leaves into the outside and never comes back, with no local maximum of E
//!   past `w`: a **miss**, margin `g` at the range's start past `w`;
//! - otherwise, leaving outward: the label, with its margin, of the line over
//!   `[max(t_min, t_a), t_max]`, `t_a` its highest point before its next crossing;
//!   ambiguous where `|margin| ≤ ε·S + 2·|o − p′|` (a graze within the origin's own
//!   rounding distance is not determined by the input);
//! - into the solid: whether its next crossing (where it leaves) lies in the range: hit or
//!   miss, ambiguous within `10·ε·S` of `t_max`, or where the range lies within `2w`; the
//!   margin is that of the range past `2w`.
//!
//! The first crossing reported is the first point of [`FamilyQuery::crossings`] on the line
//! through `p′` past `w` in the range.

use super::line::Line;
use super::{FamilyQuery, nearest_on_ellipse};
use crate::oracle::frame::across_axis;
use crate::oracle::spawned_rule::SpawnedLine;
use crate::oracle::{OracleClass, OracleLabel};
use glam::DVec3;

impl FamilyQuery {
    /// [`FamilyQuery::classify`] for a ray from a surface point: the rule of the module
    /// docs. Ambiguous labels carry margin 0.
    pub fn classify_from_surface(&self) -> OracleLabel {
        match decide(self) {
            Some((label, _)) => label,
            None => OracleLabel {
                class: OracleClass::Ambiguous,
                margin: 0.0,
            },
        }
    }

    /// For a ray that [`FamilyQuery::classify_from_surface`] labels a hit: its first
    /// crossing past the origin's own (units of `dir`, from the surface point).
    pub fn first_crossing_from_surface(&self) -> Option<f64> {
        decide(self).and_then(|(l, first)| (l.class == OracleClass::Hit).then_some(first)?)
    }

    /// The query with its origin moved onto the surface as the on-surface rule does (an
    /// origin at a singular point, or on the axis, stays).
    pub fn on_surface(&self) -> FamilyQuery {
        match moved_onto_surface(self) {
            Some((origin, _, _)) => FamilyQuery { origin, ..*self },
            None => *self,
        }
    }
}

/// The label and the first crossing in range past the origin's own; `None` ambiguous.
fn decide(query: &FamilyQuery) -> Option<(OracleLabel, Option<f64>)> {
    query.check_line();
    assert!(query.t_min <= query.t_max, "bad range");
    let size = query.size();
    let (on, offset, normal) = moved_onto_surface(query)?;
    let line = FamilyQuery {
        origin: on,
        ..*query
    };
    let len = line.dir.length();
    let cos0 = normal.dot(line.dir / len);
    if cos0.abs() <= 1e-12 {
        return None;
    }
    let (lo_ab, hi_ab) = (line.radial.min(line.axial), line.radial.max(line.axial));
    let delta = line.g(0.0).abs() / lo_ab * hi_ab;
    let spawned = SpawnedLine::new(delta, cos0.abs(), (query.t_min, query.t_max), len, size);
    let window = spawned.window;
    let whole = line.over(f64::NEG_INFINITY, f64::INFINITY);
    let ts: Vec<f64> = whole.crossings().iter().map(|c| c.t).collect();
    let next = ts.iter().copied().find(|&t| t > window);
    if next.is_some_and(|t| t <= 2.0 * window) {
        return None;
    }
    let first = ts.iter().copied().find(|&t| spawned.ahead_in_range(t));
    let frame = Line::new(&whole);
    let end = next.unwrap_or(f64::INFINITY);
    let outward = cos0 > 0.0;
    // The line's extreme point between the origin's window and its next crossing: the
    // highest outside, the deepest inside.
    let mut extreme: Option<(f64, f64)> = None;
    for s in frame.stationary() {
        let t = frame.t_of_s(s);
        if t <= window || t >= end {
            continue;
        }
        let v = line.g(t);
        if extreme.is_none_or(|(_, e)| if outward { v > e } else { v < e }) {
            extreme = Some((t, v));
        }
    }
    // The line over [lo, t_max]: the answer past the extreme point.
    let over = |lo: f64| line.over(lo, query.t_max).classify();
    if outward {
        // Past the highest point; a miss's margin is g at the range's start past the window.
        let start = query.t_min.max(window).min(query.t_max);
        let rise = (extreme, next.is_some());
        return spawned.leaving_solid(rise, || line.g(start), over, offset, first);
    }
    spawned.entering_solid(next?, extreme.map(|(_, depth)| depth), over, first)
}

/// The surface point nearest to the query's origin, the origin's distance from it and the
/// unit outward normal there; `None` at a singular point (module docs).
fn moved_onto_surface(query: &FamilyQuery) -> Option<(DVec3, f64, DVec3)> {
    let (big, a, b) = (query.major, query.radial, query.axial);
    let axis = query.axis.normalize();
    let rel = query.origin - query.center;
    let (y, radial) = across_axis(rel, axis);
    let rho = radial.length();
    if rho.is_nan() || rho <= 0.0 {
        return None;
    }
    let e_r = radial / rho;
    let (du, dv) = nearest_on_ellipse(a, b, rho - big, y);
    let rho_on = big + du;
    if rho_on.is_nan() || rho_on < 0.0 {
        return None;
    }
    let on = query.center + e_r * rho_on + axis * dv;
    let normal = (e_r * (du / (a * a)) + axis * (dv / (b * b))).normalize();
    normal
        .is_finite()
        .then_some((on, (on - query.origin).length(), normal))
}
