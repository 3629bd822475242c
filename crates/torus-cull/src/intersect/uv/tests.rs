//! Hit coordinates round-trip through `point_at`; the tangents are orthonormal, normal to
//! the hit's normal, and `point_at`'s finite differences.

use super::*;
use crate::geometry::draw::dvec3_in;
use crate::{DRay, Ray, intersect};
use glam::Vec3;
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64;

/// The angle from `a` to `b`, wrapped into `[−π, π]`.
fn angle_diff(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(TAU);
    if d > PI { d - TAU } else { d }
}

fn random_tori(rng: &mut Pcg64) -> Vec<Torus> {
    let mut tori = vec![Torus::new_f64(DVec3::ZERO, DVec3::Y, 4.0, 1.0).unwrap()];
    for (big, small) in [
        (4.0, 1.0),
        (1.05, 1.0),
        (1e3, 1.0),
        (1e-3, 2e-4),
        (50.0, 20.0),
    ] {
        let c = dvec3_in(rng, DVec3::splat(3.0)) * big;
        let axis = dvec3_in(rng, DVec3::splat(1.0));
        tori.push(Torus::new_f64(c, axis, big, small).unwrap());
    }
    tori
}

/// A random surface point's coordinates, and the structured ones: the equators, the top
/// and bottom circles, the seams θ, φ = π.
fn coords(rng: &mut Pcg64) -> Vec<(f64, f64)> {
    let special = [0.0, PI / 2.0, PI, -PI / 2.0, 1e-9, PI - 1e-9, -PI + 1e-9];
    let mut all = Vec::new();
    for &t in &special {
        for &p in &special {
            all.push((t, p));
        }
    }
    for _ in 0..400 {
        all.push((rng.random_range(-PI..PI), rng.random_range(-PI..PI)));
    }
    all
}

#[test]
fn hit_uv_round_trips_through_point_at() {
    let mut rng = Pcg64::seed_from_u64(4101);
    let (mut worst_f64, mut worst_f32, mut n) = (0.0f64, 0.0f64, 0);
    for torus in random_tori(&mut rng) {
        let (big, small) = (torus.major_radius_f64(), torus.minor_radius_f64());
        for (theta, phi) in coords(&mut rng) {
            let p = torus.point_at(theta, phi);
            let normal = torus.project_point(p).unwrap().normal;
            // Back along the normal from just outside: the first hit is `p`.
            let o = p + normal * (0.01 * small);
            let hit = intersect(&torus, &DRay::new(o, -normal).unwrap()).expect("a hit");
            let uv = torus.hit_uv(&hit);
            assert!(uv.theta > -PI && uv.theta <= PI && uv.phi > -PI && uv.phi <= PI);
            let err = angle_diff(uv.theta, theta)
                .abs()
                .max(angle_diff(uv.phi, phi).abs());
            worst_f64 = worst_f64.max(err);
            assert!(err < 1e-9, "θ {theta} φ {phi}: {uv:?} R {big} r {small}");
            let back = torus.point_at(uv.theta, uv.phi);
            assert!(
                (back - hit.point).length() < 1e-12 * (big + small + torus.center_f64().length())
            );
            // The surface_coords of the hit point name the same point.
            let (t2, p2) = torus.surface_coords(hit.point).unwrap();
            assert!(angle_diff(t2, uv.theta).abs() < 1e-9 && angle_diff(p2, uv.phi).abs() < 1e-9);
            // An f32 ray: the coordinates to f32's rounding of the normal and the point.
            if let Ok(ray) = Ray::new(o.as_vec3(), (-normal).as_vec3())
                && let Some(h) = intersect(&torus, &ray)
            {
                let uv = torus.hit_uv(&h);
                let back = torus.point_at(uv.theta, uv.phi);
                let scale = big + small + torus.center_f64().length();
                let err = (back - h.point.as_dvec3()).length() / scale;
                worst_f32 = worst_f32.max(err);
                assert!(err < 1e-5, "f32: {uv:?} vs {h:?}");
            }
            n += 1;
        }
    }
    println!(
        "hit_uv: {n} hits, worst angle error {worst_f64:.2e} (f64), point error {worst_f32:.2e}·scale (f32)"
    );
}

#[test]
fn tangents_are_an_orthonormal_frame_and_point_at_derivatives() {
    let mut rng = Pcg64::seed_from_u64(4102);
    let (mut worst_fd, mut worst_orth) = (0.0f64, 0.0f64);
    for torus in random_tori(&mut rng) {
        for (theta, phi) in coords(&mut rng) {
            let uv = SurfaceCoords { theta, phi };
            let frame = torus.tangents(uv);
            let p = torus.point_at(theta, phi);
            let normal = torus.project_point(p).unwrap().normal;
            let (a, b) = (frame.along_ring, frame.around_tube);
            let orth = [
                a.dot(normal).abs(),
                b.dot(normal).abs(),
                a.dot(b).abs(),
                (a.length() - 1.0).abs(),
                (b.length() - 1.0).abs(),
                (a.cross(b) - normal).length(),
            ]
            .into_iter()
            .fold(0.0, f64::max);
            worst_orth = worst_orth.max(orth);
            assert!(orth < 1e-11, "{uv:?}: {frame:?} n {normal}");
            // Central differences of point_at, normalized: O(h²) off.
            let h = 1e-5;
            let dphi =
                (torus.point_at(theta, phi + h) - torus.point_at(theta, phi - h)).normalize();
            let dtheta =
                (torus.point_at(theta + h, phi) - torus.point_at(theta - h, phi)).normalize();
            let fd = (dphi - a).length().max((dtheta - b).length());
            worst_fd = worst_fd.max(fd);
            assert!(fd < 1e-6, "{uv:?}: {frame:?} vs {dphi} {dtheta}");
        }
    }
    // The f32 hit's normal against the tangents of its coordinates.
    let torus = Torus::canonical(4.0, 1.0).unwrap();
    let ray = Ray::new(Vec3::new(-10.0, 0.5, 0.3), Vec3::X).unwrap();
    let hit = intersect(&torus, &ray).unwrap();
    let frame = torus.tangents(torus.hit_uv(&hit));
    let n = hit.normal.as_dvec3();
    assert!(frame.along_ring.cross(frame.around_tube).dot(n) > 1.0 - 1e-6);
    println!(
        "tangents: worst orthonormality {worst_orth:.2e}, worst finite difference {worst_fd:.2e}"
    );
}

#[test]
fn texture_uv_spans_the_unit_square() {
    let uv = SurfaceCoords { theta: PI, phi: PI }.texture_uv();
    assert_eq!(uv, DVec2::ONE);
    let uv = SurfaceCoords {
        theta: 0.0,
        phi: -PI / 2.0,
    }
    .texture_uv();
    assert_eq!(uv, DVec2::new(0.25, 0.5));
}
