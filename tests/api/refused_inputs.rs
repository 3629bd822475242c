//! Issue 52.3: the library calls that accepted what they should not, each refused now
//! with a typed error that names the value given.

use glam::{DVec3, Vec3};
use std::f64::consts::PI;
use torus_cull::bend::PipeBend;
use torus_cull::family::{Toroid, ToroidError};
use torus_cull::{DRay, DRayError, Ray, RayError, Torus, TorusError, intersect};

#[test]
fn a_nan_t_max_is_refused_not_unbounded() {
    let ray = Ray::new(Vec3::ZERO, Vec3::X).unwrap();
    let e = ray.with_t_max(f32::NAN).unwrap_err();
    assert!(
        matches!(e, RayError::BadRange { t_max, .. } if t_max.is_nan()),
        "{e:?}"
    );
    assert!(e.to_string().contains("NaN"), "{e}");
    let wide = DRay::new(DVec3::ZERO, DVec3::X).unwrap();
    assert!(matches!(
        wide.with_t_max(f64::NAN),
        Err(DRayError::BadRange { .. })
    ));
    // A shadow ray from a surface point, the case.
    let torus = Torus::canonical(4.0, 1.0).unwrap();
    let shadow = torus
        .spawn_from_point(Vec3::new(5.0, 0.0, 0.0), Vec3::X)
        .unwrap();
    assert!(shadow.with_t_max(f32::NAN).is_err());
    // Numbers still cut, never widen, never go below t_min.
    assert_eq!(ray.with_t_max(2.0).unwrap().t_max(), 2.0);
    assert_eq!(
        ray.with_t_max(f32::INFINITY).unwrap().t_max(),
        f32::INFINITY
    );
    let late = Ray::with_range(Vec3::ZERO, Vec3::X, 1.0, 5.0).unwrap();
    assert_eq!(late.with_t_max(0.5).unwrap().t_max(), 1.0);
    assert_eq!(late.with_t_max(9.0).unwrap().t_max(), 5.0);
}

#[test]
fn a_negative_or_nan_t_min_is_refused() {
    let (o, d) = (Vec3::ZERO, Vec3::X);
    let e = Ray::with_range(o, d, -1.0, 1.0).unwrap_err();
    assert_eq!(
        e,
        RayError::BadRange {
            t_min: -1.0,
            t_max: 1.0
        }
    );
    assert_eq!(
        e.to_string(),
        "ray range [-1, 1] is invalid (need 0 ≤ t_min ≤ t_max, t_min finite, t_max not NaN)"
    );
    assert!(Ray::from_surface_with_range(o, d, -1e-30, 1.0).is_err());
    assert!(Ray::with_range(o, d, f32::NAN, 1.0).is_err());
    assert!(DRay::with_range(DVec3::ZERO, DVec3::X, -1.0, 1.0).is_err());
    // −0 is 0, the smallest allowed.
    assert!(Ray::with_range(o, d, -0.0, 1.0).is_ok());
}

/// `spawn` at `t` on `ray`, and the `OffSurface` error's distance.
fn off<P: torus_cull::Precision>(got: Result<Ray<P>, RayError<P>>) -> f64 {
    match got {
        Err(RayError::OffSurface {
            distance,
            tolerance,
            ..
        }) => {
            assert!(distance > tolerance && tolerance > 0.0);
            distance
        }
        other => panic!("expected OffSurface, got {other:?}"),
    }
}

#[test]
fn every_spawn_refuses_a_t_that_is_not_a_hit() {
    // The repro: t = 3 is 2 outside the outer equator (x = 7), t = 1e30 far off.
    let torus = Torus::canonical(4.0, 1.0).unwrap();
    let ray = Ray::new(Vec3::new(10.0, 0.0, 0.0), Vec3::NEG_X).unwrap();
    let hit = intersect(&torus, &ray).unwrap();
    assert!(torus.spawn(&ray, hit.t, Vec3::X).is_ok());
    assert!((off(torus.spawn(&ray, 3.0, Vec3::X)) - 2.0).abs() < 1e-9);
    off(torus.spawn(&ray, 1e30, Vec3::X));
    let e = torus.spawn(&ray, 3.0, Vec3::X).unwrap_err().to_string();
    assert!(
        e.starts_with("spawn at t = 3: the point there is 2 from the surface"),
        "{e}"
    );
    // A NaN t is still a non-finite origin.
    assert!(matches!(
        torus.spawn(&ray, f32::NAN, Vec3::X),
        Err(RayError::NonFiniteOrigin(_))
    ));
    // On the axis or the core circle (no unique nearest point): not on the surface.
    off(torus.spawn(&ray, 10.0, Vec3::X)); // the centre
    off(torus.spawn(&ray, 6.0, Vec3::X)); // the core circle at x = 4
    // A small torus far from the camera: f32's rounding of the hit's t (about 10⁻³ here,
    // ten times ON_SURFACE_REL·(R + r)) is within the tolerance's second term.
    let small = Torus::new(Vec3::new(0.0, 0.0, -2e4), Vec3::Z, 0.8, 0.2).unwrap();
    let far = Ray::new(Vec3::new(0.9, 0.1, 0.0), Vec3::NEG_Z).unwrap();
    let hit = intersect(&small, &far).unwrap();
    assert!(small.spawn(&far, hit.t, Vec3::Z).is_ok());
    off(small.spawn(&far, hit.t - 0.1, Vec3::Z));

    // The family: an elliptical ring tube, and an elliptical spindle, whose distance is a
    // lower bound (the whole meridian ellipse's).
    let flat = Toroid::canonical(4.0, 1.0, 0.5).unwrap();
    let hit = flat.intersect(&ray).unwrap();
    assert!(flat.spawn(&ray, hit.t, Vec3::X).is_ok());
    assert!((off(flat.spawn(&ray, 3.0, Vec3::X)) - 2.0).abs() < 1e-9);
    let spindle = Toroid::canonical(0.75, 1.0, 2.0).unwrap();
    let down = Ray::new(Vec3::new(1.0, 10.0, 0.0), Vec3::NEG_Y).unwrap();
    let hit = spindle.intersect(&down).unwrap();
    assert!(spindle.spawn(&down, hit.t, Vec3::Y).is_ok());
    assert!((off(spindle.spawn(&down, 10.0, Vec3::Y)) - 0.75).abs() < 1e-9);

    // The pipe bend: 2 inside the wall at t = 42 (y = 8, between the bore at 5 and the
    // outer face at 10).
    let bend = PipeBend::canonical(30.0, 5.0, 10.0, PI / 4.0, 3.0 * PI / 4.0).unwrap();
    let down = DRay::new(DVec3::new(0.0, 50.0, -30.0), DVec3::NEG_Y).unwrap();
    let hit = bend.intersect(&down).unwrap();
    assert!(bend.spawn(&down, hit.t, DVec3::Y).is_ok());
    assert!((off(bend.spawn(&down, 42.0, DVec3::Y)) - 2.0).abs() < 1e-9);
    off(bend.spawn(&down, 1e30, DVec3::Y));
}

#[test]
fn an_out_of_range_error_reports_the_value_given() {
    let e = Toroid::canonical(1e300, 1e300, 1e300).unwrap_err();
    assert_eq!(
        e,
        ToroidError::Torus(TorusError::OutOfRange {
            major_radius: 1e300,
            minor_radius: 1e300
        })
    );
    let text = e.to_string();
    assert!(
        text.starts_with("major_radius = 1e300, minor_radius = 1e300: R + r = 2e300 is outside"),
        "{text}"
    );
    let e = Torus::new_f64(DVec3::ZERO, DVec3::Y, 3e-300, 1e-300).unwrap_err();
    assert!(matches!(e, TorusError::OutOfRange { major_radius, .. } if major_radius == 3e-300));
    let e = Torus::new_f64(DVec3::ZERO, DVec3::Y, 1e300, 1e290).unwrap_err();
    assert!(matches!(e, TorusError::OutOfRange { minor_radius, .. } if minor_radius == 1e290));
    // An f32 value is widened exactly: the same number as given.
    let e = Torus::canonical(0.1, 0.2).unwrap_err();
    assert_eq!(
        e,
        TorusError::NoHole {
            major_radius: f64::from(0.1f32),
            minor_radius: f64::from(0.2f32)
        }
    );
}
