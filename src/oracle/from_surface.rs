//! The oracle's label for a ray whose origin is a surface point (`Ray::from_surface`),
//! by the rule of docs/math.md §9: the origin's own crossing is excluded, the rest of the
//! ray is labelled as any ray is. Computed from the line's reference crossings and
//! [`Query::classify`] alone (no code of the crate's solver).
//!
//! **The rule.** Let δ be the origin's distance from the surface and θ₀ the angle between
//! the direction and the surface's normal at the nearest surface point. The origin's own
//! crossing lies within the window `w = 4·(δ + 10⁻¹¹·(R + r))/(|cos θ₀|·|d|)` of `t = 0`
//! (in units of `t`; the 10⁻¹¹ covers the oracle's own error); past
//! `w′ = w + 10·ε·(R + r)/(|cos θ₀|·|d|)` (ε the ambiguity band) the ray has left the
//! band around the surface near its origin. Then:
//! - **ambiguous** when no crossing of the whole line lies within `w` (no own root to
//!   exclude: the ray leaves the surface tangentially), when a second crossing lies within
//!   `w′` (not decidable at f64's resolution: as for the literal ray), or when the range
//!   ends before `w′`;
//! - otherwise, for a ray that leaves into the outside, the label, with its margin, of the
//!   ray over `[max(t_min, w′), t_max]`; for a ray that goes into the tube (inside at
//!   `w′`), whether its next crossing (where it leaves the tube) lies in the range: hit or
//!   miss, ambiguous within the band of `t_max`; the margin is still that of the range,
//!   negative (the ray runs inside the tube).

use super::{AMBIGUITY_REL, OracleClass, OracleLabel, Query, reference_roots};
use glam::DVec3;

/// [`Query::classify`] for a ray from a surface point: the rule of the module docs.
///
/// # Panics
/// As [`Query`].
pub fn classify_from_surface(query: &Query) -> OracleLabel {
    let size = query.major + query.minor;
    let ambiguous = OracleLabel {
        class: OracleClass::Ambiguous,
        margin: 0.0,
    };
    let len = query.d.length();
    let (window, clear) = windows(query);
    let roots = reference_roots(&query.over(f64::NEG_INFINITY, f64::INFINITY));
    let Some(own) = roots
        .iter()
        .copied()
        .min_by(|a, b| a.abs().total_cmp(&b.abs()))
    else {
        return ambiguous;
    };
    let second = roots.iter().any(|&t| t != own && t.abs() <= clear);
    if own.abs() > window || second {
        return ambiguous;
    }
    let lo = query.t_min.max(clear);
    if lo > query.t_max {
        return ambiguous;
    }
    let outside = query.over(lo, query.t_max).classify();
    // Into the tube: the next crossing is where the ray leaves it.
    let (depth, _) = off_surface_at(query, query.o + query.d * clear);
    if depth >= 0.0 {
        return outside;
    }
    let Some(exit) = roots.iter().copied().find(|&t| t > clear) else {
        return ambiguous;
    };
    if exit < lo {
        return outside;
    }
    if (exit - query.t_max).abs() * len <= 10.0 * AMBIGUITY_REL * size {
        return ambiguous;
    }
    OracleLabel {
        class: if exit <= query.t_max {
            OracleClass::Hit
        } else {
            OracleClass::Miss
        },
        margin: outside.margin,
    }
}

/// The origin's own window `w` and the distance `w′` past which the ray has left the
/// band around the surface near its origin (the module docs), in units of `t`.
fn windows(query: &Query) -> (f64, f64) {
    let size = query.major + query.minor;
    let (delta, normal) = off_surface(query);
    let len = query.d.length();
    let cos0 = normal.dot(query.d / len).abs().max(1e-12);
    let window = 4.0 * (delta + 1e-11 * size) / cos0 / len;
    (window, window + 10.0 * AMBIGUITY_REL * size / cos0 / len)
}

/// For a ray that [`classify_from_surface`] labels a hit: its first crossing after the
/// origin's own, the first reference root in `[max(t_min, w′), t_max]` (units of `t`).
pub fn first_crossing_from_surface(query: &Query) -> Option<f64> {
    let (_, clear) = windows(query);
    let lo = query.t_min.max(clear);
    reference_roots(&query.over(f64::NEG_INFINITY, f64::INFINITY))
        .into_iter()
        .find(|&t| t >= lo && t <= query.t_max)
}

/// The origin's distance from the surface and the unit outward normal at its nearest
/// surface point (for an origin on the axis or the core circle, the direction has no
/// nearest point: the normal is taken as the axis, and δ is still exact).
fn off_surface(query: &Query) -> (f64, DVec3) {
    let (signed, normal) = off_surface_at(query, query.o);
    (signed.abs(), normal)
}

/// A point's signed distance from the surface (negative inside the tube) and the unit
/// outward normal at its nearest surface point.
fn off_surface_at(query: &Query, x: DVec3) -> (f64, DVec3) {
    let axis = query.axis.normalize();
    let rel = x - query.center;
    let y = rel.dot(axis);
    let radial = rel - axis * y;
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
        // From the inner equator across the hole: the far wall at t = 6 is the hit.
        let across = label(DVec3::new(3.0, 0.0, 0.0), DVec3::NEG_X, f64::INFINITY);
        assert_eq!(across.class, OracleClass::Hit);
        assert_eq!(
            label(DVec3::new(3.0, 0.0, 0.0), DVec3::NEG_X, 5.0).class,
            OracleClass::Miss
        );
        // From the top, straight up: nothing.
        assert_eq!(
            label(DVec3::new(4.0, 1.0, 0.0), DVec3::Y, f64::INFINITY).class,
            OracleClass::Miss
        );
        // Into the tube, from the top: the bottom, t = 2.
        assert_eq!(
            label(DVec3::new(4.0, 1.0, 0.0), DVec3::NEG_Y, 2.5).class,
            OracleClass::Hit
        );
        assert_eq!(
            label(DVec3::new(4.0, 1.0, 0.0), DVec3::NEG_Y, 1.5).class,
            OracleClass::Miss
        );
        // Tangent at the top, along z: the own crossing is a double root, and nothing
        // else can be told at the origin: ambiguous.
        assert_eq!(
            label(DVec3::new(4.0, 1.0, 0.0), DVec3::Z, f64::INFINITY).class,
            OracleClass::Ambiguous
        );
    }
}
