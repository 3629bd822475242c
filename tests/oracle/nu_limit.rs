//! ν = R/r is limited to [`MAX_NU`]: the reproducer of issue 17 (R = 1, r = 3e-9, where
//! `intersect` reported a hit half a tube radius outside the surface) is refused with a
//! typed error, and at the limit the exact intersection agrees with the oracle on
//! thousands of rays, that family of lines included.

// Every check here runs against the harness's oracle.

use crate::common::assert_no_failures;
use glam::{DVec3, Vec3};
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64;
use torus_cull::{MAX_NU, Ray, Torus, TorusError, intersect};
use torus_cull_lab::oracle::{OracleClass, Query, classify, reference_roots};

#[test]
fn the_reproducer_and_anything_above_the_limit_are_refused() {
    let e = Torus::canonical(1.0, 3e-9).unwrap_err();
    assert!(matches!(e, TorusError::TooThin { .. }), "{e:?}");
    let msg = e.to_string();
    // The value typed (as the f32 it is, compact since issue 52), the ν it makes and the
    // allowed range.
    assert!(
        msg.contains("minor_radius = 3e-9") && msg.contains("3.33") && msg.contains("1000"),
        "{msg}"
    );
    for (major, minor) in [(1.0f32, 1.0 / 1001.0), (1e3, 0.99), (1e-3, 1e-6 * 0.999)] {
        assert!(
            matches!(
                Torus::canonical(major, minor),
                Err(TorusError::TooThin { .. })
            ),
            "R = {major}, r = {minor}"
        );
    }
    // ν = 1000 itself is allowed, however the radii round to f32.
    for major in [1e-3f32, 0.37, 1.0, 3.0, 1e3] {
        let minor = (major as f64 / MAX_NU) as f32;
        assert!(Torus::canonical(major, minor).is_ok(), "R = {major}");
        assert!(Torus::canonical(major, major / MAX_NU as f32).is_ok());
    }
}

/// `origin + t·dir` in the torus frame (centre 0, axis +y) mapped to the world pose
/// (`center`, `axis`, any basis around the axis: the torus is symmetric about it).
fn world_ray(center: DVec3, axis: DVec3, origin: DVec3, dir: DVec3) -> Ray {
    let (e1, e2) = axis.any_orthonormal_pair();
    let map = |v: DVec3| e1 * v.x + axis * v.y + e2 * v.z;
    Ray::new((center + map(origin)).as_vec3(), map(dir).as_vec3()).unwrap()
}

#[test]
fn at_the_limit_intersect_agrees_with_the_oracle_including_the_reproducer_family() {
    let mut rng = Pcg64::seed_from_u64(17);
    let (mut checked, mut hits, mut ambiguous) = (0usize, 0usize, 0usize);
    let mut failures = Vec::new();
    for major in [1e-3f64, 1.0, 1e3] {
        let minor = major / MAX_NU;
        for pose in 0..2 {
            let (center, axis) = if pose == 0 {
                (DVec3::ZERO, DVec3::Y)
            } else {
                let a = DVec3::new(
                    rng.random_range(-1.0..1.0),
                    rng.random_range(-1.0..1.0),
                    rng.random_range(-1.0..1.0),
                );
                (
                    DVec3::splat(major * rng.random_range(-1.0..1.0)),
                    a.normalize(),
                )
            };
            let torus =
                Torus::new(center.as_vec3(), axis.as_vec3(), major as f32, minor as f32).unwrap();
            let axis = torus.axis().as_dvec3().normalize();
            let (big, small) = (torus.major_radius() as f64, torus.minor_radius() as f64);
            let outer = big + small;
            let mut rays = Vec::new();
            // The reproducer's family: lines perpendicular to the axis, at heights around
            // the tube's top and bottom (y = k·r), passing the axis at distances around
            // the tube (z0), in several directions. The reproducer itself is
            // (−5, 1.5 r, 0) + t(1, 0, 0), scaled.
            let ks = [0.0, 0.5, 0.9, 0.99, 0.999, 1.001, 1.01, 1.1, 1.5, 2.0, 3.0];
            let z0s = [
                0.0,
                big - 2.0 * small,
                big - small * 0.5,
                big,
                big + 0.5 * small,
                big + 0.99 * small,
                big + 1.01 * small,
                big + 1.5 * small,
            ];
            for i in 0..8 {
                let phi = i as f64 * std::f64::consts::TAU / 8.0 + 0.1 * pose as f64;
                let d = DVec3::new(phi.cos(), 0.0, phi.sin());
                let side = DVec3::new(-phi.sin(), 0.0, phi.cos());
                for k in ks {
                    for sign in [1.0, -1.0] {
                        for z0 in z0s {
                            let o = DVec3::new(0.0, sign * k * small, 0.0) + side * z0
                                - d * (5.0 * outer);
                            rays.push(world_ray(center, axis, o, d));
                        }
                    }
                }
            }
            // Isotropic lines through the bounding sphere, and lines aimed at the tube.
            for _ in 0..1000 {
                let d = random_unit(&mut rng);
                let target = random_unit(&mut rng) * outer * rng.random::<f64>().cbrt();
                rays.push(world_ray(center, axis, target - d * (3.0 * outer), d));
                let theta = rng.random_range(0.0..std::f64::consts::TAU);
                let on_core = DVec3::new(big * theta.cos(), 0.0, big * theta.sin());
                let near = on_core + random_unit(&mut rng) * small * rng.random_range(0.0..2.0);
                rays.push(world_ray(center, axis, near - d * (3.0 * outer), d));
            }
            for ray in &rays {
                let label = classify(&torus, ray);
                if label.class == OracleClass::Ambiguous {
                    ambiguous += 1;
                    continue;
                }
                checked += 1;
                let found = intersect(&torus, ray);
                if found.is_some() != (label.class == OracleClass::Hit) {
                    failures.push(format!(
                        "R = {big}: intersect {found:?} but oracle {label:?} for {ray:?}"
                    ));
                    continue;
                }
                let Some(hit) = found else { continue };
                hits += 1;
                let roots = reference_roots(&Query::ray(&torus, ray));
                let size = outer / ray.dir().as_dvec3().length();
                let err = (hit.t as f64 - roots[0]).abs() / roots[0].abs().max(size);
                if err > 1e-6 {
                    failures.push(format!(
                        "R = {big}: t {} vs reference {} ({err:e}) for {ray:?}",
                        hit.t, roots[0]
                    ));
                }
            }
        }
    }
    println!("{checked} rays checked, {hits} hits, {ambiguous} ambiguous");
    assert_no_failures(&failures);
    assert!(
        checked > 5_000 && hits > 1_000,
        "{checked} checked, {hits} hits"
    );
}

/// The reproducer's own ray, at the limit: half a tube radius above the tube, a miss.
#[test]
fn the_reproducer_ray_scaled_to_the_limit_misses() {
    let r = (1.0 / MAX_NU) as f32;
    let torus = Torus::canonical(1.0, r).unwrap();
    let ray = Ray::new(Vec3::new(-5.0, 1.5 * r, 0.0), Vec3::X).unwrap();
    assert_eq!(classify(&torus, &ray).class, OracleClass::Miss);
    assert_eq!(intersect(&torus, &ray), None);
    // And a quarter radius below the top, a hit at the tube's outer side.
    let ray = Ray::new(Vec3::new(-5.0, 0.75 * r, 0.0), Vec3::X).unwrap();
    assert_eq!(classify(&torus, &ray).class, OracleClass::Hit);
    let hit = intersect(&torus, &ray).expect("a hit");
    assert!((hit.t - 4.0).abs() < 2.0 * r, "{hit:?}");
}

fn random_unit(rng: &mut Pcg64) -> DVec3 {
    let z: f64 = rng.random_range(-1.0..1.0);
    let phi = rng.random_range(0.0..std::f64::consts::TAU);
    let s = (1.0 - z * z).max(0.0).sqrt();
    DVec3::new(s * phi.cos(), s * phi.sin(), z)
}
