//! The oracle's labels for a member of the torus family ([`Toroid`]): **interim**, until
//! the independent family oracle (`oracle::family`) is merged.
//!
//! **How.** The map `S: y ↦ y·a/b` (in the member's frame, axis y) takes the member onto
//! the circular torus (R, a) and a line `o + t d` onto `S o + t S d` with the same `t`
//! at every point, so a point of the line is inside the member exactly when its image is
//! inside the image torus: the circular oracle ([`Query`]) on the image line gives the
//! member's class, its crossings (their `t`) and the on-surface rule. A horn or spindle
//! (R ≤ a) is the circular oracle's apple: its distance D uses ρ ≥ 0, so `D < a` exactly
//! inside the solid of revolution and the lemon is never a crossing of `D = a`.
//!
//! **What is not independent.** The map S is the library's own idea (docs of
//! `torus_cull::family`); the frame here is built from the member's f64 centre and axis
//! alone (any two unit vectors orthogonal to the axis), not from the library's rotation,
//! and the roots, the distance and the on-surface rule are the circular oracle's, which
//! share no code with the library. The margin is the image's (`D − a` on the image
//! line, length units of the image), which differs from the member's distance by at most
//! a factor `max(a/b, b/a)`: its sign is the member's.

use crate::oracle::{
    OracleLabel, Query, classify_from_surface, first_crossing_from_surface, reference_roots,
};
use glam::DVec3;
use torus_cull::DRay;
use torus_cull::family::Toroid;

/// The ray's image line over its range, against the image torus (centre at the origin,
/// axis y, R, a).
pub fn image_query(toroid: &Toroid, ray: &DRay) -> Query {
    let y = toroid.axis_f64().normalize();
    let (x, z) = y.any_orthonormal_pair();
    let scale = toroid.radial_semi_axis_f64() / toroid.axial_semi_axis_f64();
    let to_image = |v: DVec3| DVec3::new(v.dot(x), v.dot(y) * scale, v.dot(z));
    Query {
        center: DVec3::ZERO,
        axis: DVec3::Y,
        major: toroid.major_radius_f64(),
        minor: toroid.radial_semi_axis_f64(),
        o: to_image(ray.origin() - toroid.center_f64()),
        d: to_image(ray.dir()),
        t_min: ray.t_min(),
        t_max: ray.t_max(),
    }
}

/// The oracle's label of the ray over its range: the literal ray's, or by the on-surface
/// rule for a ray from a surface point. `Err` where the oracle cannot answer the line.
pub fn label(toroid: &Toroid, ray: &DRay) -> Result<OracleLabel, String> {
    let query = image_query(toroid, ray);
    query.check_reach()?;
    Ok(if ray.starts_on_surface() {
        classify_from_surface(&query)
    } else {
        query.classify()
    })
}

/// The oracle's first crossing in range (`t` in units of the ray's direction): the
/// literal ray's smallest root, or for a ray from a surface point the first past its
/// origin's own (where the on-surface rule labels it a hit).
pub fn first_crossing(toroid: &Toroid, ray: &DRay) -> Option<f64> {
    let query = image_query(toroid, ray);
    if ray.starts_on_surface() {
        first_crossing_from_surface(&query)
    } else {
        reference_roots(&query).first().copied()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::oracle::OracleClass;

    #[test]
    fn spindle_apple_crossings_and_labels() {
        // R = 0.5, a = b = 1: along x through the centre the apple is crossed at x = ∓1.5.
        let spindle = Toroid::canonical(0.5, 1.0, 1.0).unwrap();
        let ray = DRay::new(DVec3::new(-3.0, 0.0, 0.0), DVec3::X).unwrap();
        let roots = reference_roots(&image_query(&spindle, &ray));
        assert_eq!(roots.len(), 2, "{roots:?}");
        assert!((roots[0] - 1.5).abs() < 1e-12 && (roots[1] - 4.5).abs() < 1e-12);
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
