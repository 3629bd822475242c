//! The oracle's labels for a member of the torus family ([`Toroid`]), from the
//! independent family oracle ([`crate::oracle::family::FamilyQuery`]: its own method on
//! `E = √(((ρ − R)/a)² + (y/b)²)`, no code of the library's solver and not the library's
//! image map `y ↦ y·a/b`).
//!
//! The query is the member's f64 pose and radii as the library stores them
//! ([`Toroid::center_f64`], [`Toroid::axis_f64`], R, a, b) and the ray's f64 origin,
//! direction and range. The margin is the oracle's, `(E − 1)·min(a, b)` at its least over
//! the range (a length; negative enters the solid).

use crate::oracle::OracleLabel;
use crate::oracle::family::FamilyQuery;
use torus_cull::DRay;
use torus_cull::family::Toroid;

/// The family oracle's question for the ray over its range.
pub fn query(toroid: &Toroid, ray: &DRay) -> FamilyQuery {
    FamilyQuery::new(
        toroid.center_f64(),
        toroid.axis_f64(),
        toroid.major_radius_f64(),
        toroid.radial_semi_axis_f64(),
        toroid.axial_semi_axis_f64(),
        ray.origin(),
        ray.dir(),
        ray.t_min(),
        ray.t_max(),
    )
}

/// The oracle's label of the ray over its range: the literal ray's, or by the family
/// oracle's on-surface rule for a ray from a surface point ([`DRay::starts_on_surface`]).
/// `Err` where the oracle cannot answer the line (its numbers overflow f64: a NaN margin).
pub fn label(toroid: &Toroid, ray: &DRay) -> Result<OracleLabel, String> {
    let query = query(toroid, ray);
    let label = if ray.starts_on_surface() {
        query.classify_from_surface()
    } else {
        query.classify()
    };
    if label.margin.is_nan() {
        return Err(format!(
            "the oracle cannot answer this line: its numbers overflow f64 (origin components \
             up to {:e} from the centre's, direction components up to {:e})",
            (query.origin - query.center).abs().max_element(),
            query.dir.abs().max_element()
        ));
    }
    Ok(label)
}

/// The oracle's first crossing in range (`t` in units of the ray's direction): the
/// literal ray's first crossing, or for a ray from a surface point the first past its
/// origin's own (where the on-surface rule labels it a hit).
pub fn first_crossing(toroid: &Toroid, ray: &DRay) -> Option<f64> {
    let query = query(toroid, ray);
    if ray.starts_on_surface() {
        query.first_crossing_from_surface()
    } else {
        query.first_crossing()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::oracle::OracleClass;
    use glam::DVec3;

    #[test]
    fn spindle_apple_crossings_and_labels() {
        // R = 0.5, a = b = 1: along x through the centre the apple is crossed at x = −1.5.
        let spindle = Toroid::canonical(0.5, 1.0, 1.0).unwrap();
        let ray = DRay::new(DVec3::new(-3.0, 0.0, 0.0), DVec3::X).unwrap();
        let crossings = query(&spindle, &ray).crossings();
        assert_eq!(crossings.len(), 2, "{crossings:?}");
        assert!((crossings[0].t - 1.5).abs() < 1e-12 && (crossings[1].t - 4.5).abs() < 1e-12);
        assert_eq!(label(&spindle, &ray).unwrap().class, OracleClass::Hit);
        // Flattened (b = 0.5): a line at y = 0.6 misses, y = 0.4 hits.
        let flat = Toroid::canonical(4.0, 1.0, 0.5).unwrap();
        for (y, class) in [(0.6, OracleClass::Miss), (0.4, OracleClass::Hit)] {
            let ray = DRay::new(DVec3::new(-9.0, y, 0.0), DVec3::X).unwrap();
            assert_eq!(label(&flat, &ray).unwrap().class, class, "y = {y}");
        }
        let down = DRay::new(DVec3::new(4.0, 3.0, 0.0), DVec3::NEG_Y).unwrap();
        assert!((first_crossing(&flat, &down).unwrap() - 2.5).abs() < 1e-12);
    }
}
