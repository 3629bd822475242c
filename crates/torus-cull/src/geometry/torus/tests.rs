use super::*;

#[test]
fn rejects_bad_parameters() {
    assert!(matches!(
        Torus::canonical(1.0, 1.0),
        Err(TorusError::NoHole { .. })
    ));
    assert!(matches!(
        Torus::canonical(0.5, 1.0),
        Err(TorusError::NoHole { .. })
    ));
    assert!(matches!(
        Torus::canonical(f32::NAN, 1.0),
        Err(TorusError::BadRadius { .. })
    ));
    assert!(matches!(
        Torus::canonical(2.0, 0.0),
        Err(TorusError::BadRadius { .. })
    ));
    assert!(matches!(
        Torus::canonical(2.0, -1.0),
        Err(TorusError::BadRadius { .. })
    ));
    assert!(matches!(
        Torus::new(Vec3::ZERO, Vec3::ZERO, 2.0, 1.0),
        Err(TorusError::BadAxis(_))
    ));
    assert!(matches!(
        Torus::new(Vec3::splat(f32::INFINITY), Vec3::Y, 2.0, 1.0),
        Err(TorusError::NonFiniteCenter(_))
    ));
    let msg = Torus::canonical(1.0, 2.0).unwrap_err().to_string();
    assert!(msg.contains("nu") && msg.contains("> 1"), "{msg}");
}

#[test]
fn new_f64_refuses_what_new_refuses() {
    let bad =
        |c: DVec3, a: DVec3, big: f64, small: f64| Torus::new_f64(c, a, big, small).unwrap_err();
    let (o, y) = (DVec3::ZERO, DVec3::Y);
    assert!(matches!(
        bad(o, y, f64::NAN, 1.0),
        TorusError::BadRadius { .. }
    ));
    assert!(matches!(bad(o, y, 2.0, -1.0), TorusError::BadRadius { .. }));
    assert!(matches!(bad(o, y, 1.0, 1.0), TorusError::NoHole { .. }));
    assert!(matches!(bad(o, y, 2e3, 1.0), TorusError::TooThin { .. }));
    assert!(matches!(
        bad(o, y, 2e15, 1e15),
        TorusError::OutOfRange { .. }
    ));
    assert!(matches!(
        bad(DVec3::splat(f64::NAN), y, 2.0, 1.0),
        TorusError::NonFiniteCenter(_)
    ));
    // Finite in f64, infinite in f32.
    assert!(matches!(
        bad(DVec3::splat(1e39), y, 2.0, 1.0),
        TorusError::NonFiniteCenter(_)
    ));
    assert!(matches!(
        bad(o, DVec3::ZERO, 2.0, 1.0),
        TorusError::BadAxis(_)
    ));
    // The same errors as the f32 constructor on f32 values.
    assert_eq!(bad(o, y, 1.0, 2.0), Torus::canonical(1.0, 2.0).unwrap_err());
    // An axis whose |a|² over- or underflows f64 is still a direction.
    for scale in [1e-200, 1e200] {
        let t = Torus::new_f64(o, DVec3::new(0.0, 3.0, 4.0) * scale, 2.0, 1.0).unwrap();
        assert!((t.axis_f64() - DVec3::new(0.0, 0.6, 0.8)).length() < 1e-15);
    }
}

#[test]
fn new_f64_of_f32_values_is_new() {
    let c = Vec3::new(1.0, -2.0, 0.5);
    let a = Vec3::new(1.0, 2.0, -3.0);
    let wide = Torus::new_f64(c.as_dvec3(), a.as_dvec3(), 3.0, 1.0).unwrap();
    let narrow = Torus::new(c, a, 3.0, 1.0).unwrap();
    assert_eq!(wide.bounds(), narrow.bounds());
    assert_eq!(wide.center_f64(), narrow.center_f64());
    assert_eq!(wide.near_origin_sq(), narrow.near_origin_sq());
    assert!((wide.axis_f64() - narrow.axis_f64()).length() < 1e-7);
}

#[test]
fn f64_bounds_hold_the_f64_tube() {
    // R rounds down by about 6e-8 (1 + 1e-7 is between two f32s): r is padded by it.
    let (big, small) = (1.0 + 1e-7, 0.25 + 1e-9);
    let t = Torus::new_f64(DVec3::ZERO, DVec3::Y, big, small).unwrap();
    let b = t.bounds();
    let (bb, bs) = (f64::from(b.major_radius()), f64::from(b.minor_radius()));
    assert!(bs >= small + (big - bb).abs(), "{bb} {bs}");
    assert!(bs - small < 1e-6);
    assert_eq!(t.major_radius(), big as f32);
    assert_eq!(t.minor_radius(), small as f32);
}

#[test]
fn transform_is_rigid_and_maps_axis_to_y() {
    for axis in [
        Vec3::Y,
        -Vec3::Y,
        Vec3::X,
        Vec3::Z,
        Vec3::new(1.0, 2.0, -3.0),
        Vec3::new(-1e-3, 1.0, 1e-3),
    ] {
        let t = Torus::new(Vec3::new(1.0, -2.0, 0.5), axis, 3.0, 1.0).unwrap();
        let m = t.to_local_rotation_f64();
        assert!((m.determinant() - 1.0).abs() < 1e-12);
        assert!((m * m.transpose() - DMat3::IDENTITY).abs_diff_eq(DMat3::ZERO, 1e-12));
        let y = m * t.axis().as_dvec3().normalize();
        assert!((y - DVec3::Y).length() < 1e-12, "{axis} -> {y}");
        let p = Vec3::new(0.3, 0.7, -0.2);
        assert!((t.point_to_world(t.point_to_local(p)) - p).length() < 1e-5);
    }
}

#[test]
fn world_aabb_contains_surface_samples() {
    let t = Torus::new(Vec3::new(1.0, 2.0, 3.0), Vec3::new(1.0, 1.0, 0.3), 2.0, 0.5).unwrap();
    let (lo, hi) = t.world_aabb();
    for i in 0..64 {
        for j in 0..16 {
            let phi = i as f32 * std::f32::consts::TAU / 64.0;
            let th = j as f32 * std::f32::consts::TAU / 16.0;
            let rho = 2.0 + 0.5 * th.cos();
            let local = Vec3::new(rho * phi.cos(), 0.5 * th.sin(), rho * phi.sin());
            let w = t.point_to_world(local);
            assert!(w.cmpge(lo - 1e-5).all() && w.cmple(hi + 1e-5).all());
        }
    }
}
