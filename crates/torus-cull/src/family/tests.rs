//! The family's structured cases, each derivable by hand; the oracle's random and
//! adversarial rays are the lab's (`tests/oracle/family.rs`).

use super::{Toroid, ToroidError, ToroidKind};
use crate::cull::Shape;
use crate::geometry::draw::{dvec3_in, vec3_in};
use crate::{CullKind, DRay, Passage, Ray, Torus, intersect, intersect_all};
use glam::{DVec3, Vec3};
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64;

fn ts(toroid: &Toroid, ray: &DRay) -> Vec<(f64, Passage)> {
    let all = toroid.intersect_all(ray);
    all.as_slice().iter().map(|c| (c.t, c.passage)).collect()
}

fn close(got: &[(f64, Passage)], want: &[(f64, Passage)], tol: f64) -> bool {
    got.len() == want.len()
        && got
            .iter()
            .zip(want)
            .all(|(g, w)| (g.0 - w.0).abs() <= tol && g.1 == w.1)
}

#[test]
fn a_circular_ring_member_answers_as_its_torus_bit_for_bit() {
    let mut rng = Pcg64::seed_from_u64(38);
    for (major, minor) in [(4.0f32, 1.0f32), (1.25, 1.0), (16.0, 1.0), (1000.0, 1.0)] {
        let center = Vec3::new(0.5, -0.25, 2.0);
        let axis = Vec3::new(0.3, 1.0, -0.2);
        let torus = Torus::new(center, axis, major, minor).unwrap();
        let toroid = Toroid::new(center, axis, major, minor, minor).unwrap();
        assert_eq!(toroid.shape(), Shape::Ring);
        assert_eq!(toroid.as_torus().unwrap(), &torus);
        for i in 0..20_000 {
            let o = center + vec3_in(&mut rng, Vec3::splat(3.0)) * (major + minor);
            let aim = center + vec3_in(&mut rng, Vec3::new(1.0, 0.3, 1.0)) * (major + minor);
            let ray = if i % 3 == 0 {
                let hit = intersect(&torus, &Ray::new(o, aim - o).unwrap());
                match hit {
                    Some(h) => torus.spawn(&Ray::new(o, aim - o).unwrap(), h.t, o - aim),
                    None => Ray::new(o, aim - o),
                }
                .unwrap()
            } else {
                Ray::new(o, aim - o).unwrap()
            };
            assert_eq!(toroid.intersect(&ray), intersect(&torus, &ray), "{ray:?}");
            assert_eq!(
                toroid.intersect_all(&ray),
                intersect_all(&torus, &ray),
                "{ray:?}"
            );
            let dray = DRay::from(ray);
            assert_eq!(toroid.intersect(&dray), intersect(&torus, &dray), "{ray:?}");
            for kind in CullKind::TIMED {
                assert_eq!(
                    toroid.intersect_culled(&kind, &ray),
                    crate::intersect_culled(&kind, &torus, &ray),
                    "{kind} {ray:?}"
                );
            }
        }
    }
}

#[test]
fn elliptical_tube_crossings_along_the_axes() {
    for (major, a, b) in [
        (4.0, 1.0, 0.25),
        (4.0, 1.0, 4.0),
        (2.0, 1.0, 0.5),
        (1.25, 1.0, 2.0),
    ] {
        let toroid = Toroid::canonical(major, a, b).unwrap();
        assert_eq!(toroid.shape(), Shape::Elliptic);
        assert!(toroid.as_torus().is_err());
        // In the equatorial plane along x from x = −10: ρ = R ± a on each side.
        let ray = DRay::new(DVec3::new(-10.0, 0.0, 0.0), DVec3::X).unwrap();
        let want = [
            (10.0 - major - a, Passage::Enter),
            (10.0 - major + a, Passage::Exit),
            (10.0 + major - a, Passage::Enter),
            (10.0 + major + a, Passage::Exit),
        ];
        let got = ts(&toroid, &ray);
        assert!(close(&got, &want, 1e-12), "{got:?}");
        // Down onto the top of the tube at ρ = R: y = b, outward normal +y.
        let down = DRay::new(DVec3::new(major, 10.0, 0.0), DVec3::NEG_Y * 2.0).unwrap();
        let hit = toroid.intersect(&down).unwrap();
        assert!((hit.t - (10.0 - b) / 2.0).abs() < 1e-12, "{hit:?}");
        assert!((hit.normal - DVec3::Y).length() < 1e-12 && hit.front_face);
        // A line at y = b·(1 − 10⁻⁶) crosses; at y = b·(1 + 10⁻⁶) it misses.
        for (y, hits) in [(b * (1.0 - 1e-6), true), (b * (1.0 + 1e-6), false)] {
            let ray = DRay::new(DVec3::new(major, y, -10.0), DVec3::Z).unwrap();
            assert_eq!(
                toroid.intersect(&ray).is_some(),
                hits,
                "{major} {a} {b} {y}"
            );
        }
        // The normal on the ellipse at angle θ: ∝ (cos θ / a, sin θ / b) in (ρ, y).
        let theta = 0.7f64;
        let p = DVec3::new(major + a * theta.cos(), b * theta.sin(), 0.0);
        let ray = DRay::new(p * 3.0, -p).unwrap();
        let hit = toroid.intersect(&ray).unwrap();
        let want = DVec3::new(theta.cos() / a, theta.sin() / b, 0.0).normalize();
        assert!((hit.point - p).length() < 1e-12, "{hit:?}");
        assert!((hit.normal - want).length() < 1e-12, "{hit:?} {want}");
    }
}

#[test]
fn spindle_and_horn_cross_the_apple_alone() {
    for (major, a, b) in [
        (0.5, 1.0, 1.0),
        (0.75, 1.0, 0.5),
        (0.5, 1.0, 2.0),
        (1.0, 1.0, 1.0),
    ] {
        let toroid = Toroid::canonical(major, a, b).unwrap();
        let kind = if major == a {
            ToroidKind::Horn
        } else {
            ToroidKind::Spindle
        };
        assert_eq!((toroid.kind(), toroid.shape()), (kind, Shape::Spindle));
        // Through the centre along x: the apple at ρ = R + a on both sides; the lemon
        // (ρ = a − R) is no surface, and the horn's centre is a touch from inside.
        let ray = DRay::new(DVec3::new(-5.0, 0.0, 0.0), DVec3::X).unwrap();
        let mut want = vec![(5.0 - major - a, Passage::Enter)];
        if kind == ToroidKind::Horn {
            want.push((5.0, Passage::Touch));
        }
        want.push((5.0 + major + a, Passage::Exit));
        let got = ts(&toroid, &ray);
        assert!(close(&got, &want, 1e-7), "{major} {a} {b}: {got:?}");
        let hit = toroid.intersect(&ray).unwrap();
        assert!((hit.t - want[0].0).abs() < 1e-12 && hit.front_face);
        // Down the axis: a spindle is entered and left at its cusps y = ±b·√(1 − (R/a)²);
        // the horn is touched at the centre.
        let axis = DRay::new(DVec3::new(0.0, 5.0, 0.0), DVec3::NEG_Y).unwrap();
        let got = ts(&toroid, &axis);
        if kind == ToroidKind::Spindle {
            let cusp = b * (1.0 - (major / a) * (major / a)).sqrt();
            let want = [(5.0 - cusp, Passage::Enter), (5.0 + cusp, Passage::Exit)];
            assert!(close(&got, &want, 1e-6), "{major} {a} {b}: {got:?}");
            // Beside the axis, by 10⁻³·a: still the apple's two crossings near the cusps.
            let beside = DRay::new(DVec3::new(1e-3 * a, 5.0, 0.0), DVec3::NEG_Y).unwrap();
            let got = ts(&toroid, &beside);
            assert_eq!(got.len(), 2, "{major} {a} {b}: {got:?}");
            assert!(got[0].1 == Passage::Enter && got[1].1 == Passage::Exit);
        } else {
            assert!(got.len() == 1 && got[0].1 == Passage::Touch, "{got:?}");
        }
        // From the centre of a spindle (inside the apple): out at ρ = R + a.
        if kind == ToroidKind::Spindle {
            let out = DRay::new(DVec3::ZERO, DVec3::Z).unwrap();
            let hit = toroid.intersect(&out).unwrap();
            assert!(
                (hit.t - (major + a)).abs() < 1e-12 && !hit.front_face,
                "{hit:?}"
            );
        }
    }
}

#[test]
fn spawned_rays_leave_their_own_surface() {
    let mut rng = Pcg64::seed_from_u64(3801);
    for (major, a, b) in [
        (4.0, 1.0, 0.25),
        (4.0, 1.0, 4.0),
        (0.5, 1.0, 1.0),
        (0.75, 1.0, 2.0),
    ] {
        let toroid = Toroid::canonical(major, a, b).unwrap();
        for _ in 0..2000 {
            let o = dvec3_in(&mut rng, DVec3::splat(4.0)) * (major + a);
            let aim = DVec3::new(
                rng.random_range(-1.0..1.0),
                0.0,
                rng.random_range(-1.0..1.0),
            ) * major;
            let ray = Ray::new(o.as_vec3(), (aim - o).as_vec3()).unwrap();
            let Some(hit) = toroid.intersect(&ray) else {
                continue;
            };
            // Back the way it came, from the surface: never the origin itself.
            let back = toroid.spawn(&ray, hit.t, -ray.dir()).unwrap();
            if let Some(again) = toroid.intersect(&back) {
                assert!(again.t > 1e-3, "{major} {a} {b}: {ray:?} {hit:?} {again:?}");
            }
            // On through the solid it entered: the exit, beyond the origin.
            if !hit.front_face {
                continue;
            }
            let on = toroid.spawn(&ray, hit.t, ray.dir()).unwrap();
            let exit = toroid.intersect(&on).unwrap_or_else(|| {
                panic!("{major} {a} {b}: leaves the solid it entered: {ray:?} {hit:?} {on:?}")
            });
            assert!(exit.t > 0.0 && !exit.front_face, "{ray:?} {hit:?} {exit:?}");
        }
    }
}

#[test]
fn bad_members_are_refused_by_name() {
    let err = |r: Result<Toroid, ToroidError>| r.unwrap_err().to_string();
    assert!(err(Toroid::canonical(4.0, 1.0, 0.0)).contains("axial_semi_axis"));
    assert!(err(Toroid::canonical(4.0, f64::NAN, 1.0)).contains("radial_semi_axis"));
    assert!(err(Toroid::canonical(-1.0, 1.0, 1.0)).contains("major_radius"));
    assert!(err(Toroid::canonical(4.0, 1.0, 5.0)).contains("0.25 ..= 4"));
    assert!(err(Toroid::canonical(0.009, 1.0, 1.0)).contains("below the supported 0.01"));
    assert!(Toroid::canonical(0.01, 1.0, 4.0).is_ok());
    assert!(err(Toroid::canonical(2000.0, 1.0, 1.0)).contains("nu"));
    assert!(matches!(
        Toroid::canonical(0.5, 1.0, 1.0).unwrap().as_torus(),
        Err(ToroidError::NotCircular { .. })
    ));
}

/// Every cull that lists a shape keeps every line the member's exact intersection hits
/// (the oracle's test is the lab's; this one runs with the library's own tests).
#[test]
fn the_culls_keep_every_hit_of_the_shapes_they_accept() {
    let mut rng = Pcg64::seed_from_u64(3802);
    let shapes = [
        (4.0, 1.0, 0.25),
        (4.0, 1.0, 4.0),
        (1.25, 1.0, 0.5),
        (16.0, 1.0, 2.0),
        (1.0, 1.0, 1.0),
        (1.0, 1.0, 0.25),
        (0.75, 1.0, 1.0),
        (0.5, 1.0, 0.5),
        (0.5, 1.0, 4.0),
    ];
    let mut wrong = Vec::new();
    for (major, a, b) in shapes {
        let toroid = Toroid::canonical(major, a, b).unwrap();
        let size = major + a.max(b);
        for _ in 0..40_000 {
            let dir = dvec3_in(&mut rng, DVec3::splat(1.0));
            // Aimed at a point near the surface: ρ = R + a·cos θ, y = b·sin θ, pushed
            // by up to 10⁻³ either side.
            let theta: f64 = rng.random_range(0.0..std::f64::consts::TAU);
            let phi: f64 = rng.random_range(0.0..std::f64::consts::TAU);
            let push = 1.0 + rng.random_range(-1e-3..1e-3);
            let rho = (major + a * theta.cos() * push).abs();
            let at = DVec3::new(rho * phi.cos(), b * theta.sin() * push, rho * phi.sin());
            let dir = if dir.length() > 1e-3 { dir } else { DVec3::X };
            let o = at - dir.normalize() * 4.0 * size;
            let ray = Ray::new(o.as_vec3(), dir.as_vec3()).unwrap();
            let Some(hit) = toroid.intersect(&ray) else {
                continue;
            };
            for kind in CullKind::TIMED {
                if !toroid.kept_by(&kind, &ray) {
                    wrong.push(format!("{kind} ({major}, {a}, {b}) {ray:?} {hit:?}"));
                }
            }
        }
    }
    // Exactly along the axis, through a spindle's cusps or the horn's centre (skala once
    // rejected these: its test of lines parallel to the axis kept only ρ² > the padded
    // hole's, which is 0 once the hole closes).
    for &(major, a, b) in shapes.iter().filter(|s| s.0 <= s.1) {
        let toroid = Toroid::canonical(major, a, b).unwrap();
        for dir in [Vec3::NEG_Y, Vec3::Y * 1e3] {
            let ray = Ray::new(-dir.normalize() * 10.0, dir).unwrap();
            assert!(toroid.intersect(&ray).is_some(), "{major} {a} {b}");
            for kind in CullKind::TIMED {
                if !toroid.kept_by(&kind, &ray) {
                    wrong.push(format!("{kind} ({major}, {a}, {b}) along the axis"));
                }
            }
        }
    }
    assert!(
        wrong.is_empty(),
        "{} false rejects, first: {:?}",
        wrong.len(),
        &wrong[..wrong.len().min(10)]
    );
}

/// `world_aabb` holds every surface point of posed members (rings, horns, spindles, flat
/// and tall tubes, at several scales), each formed in f64 from the meridian ellipse, and
/// is tight: each face of the box is within 1 % of the size of the farthest point.
#[test]
fn the_world_box_holds_the_surface_and_is_tight() {
    let mut rng = Pcg64::seed_from_u64(4104);
    for (major, a, b) in [
        (4.0, 1.0, 0.25),
        (4.0, 1.0, 4.0),
        (1.0, 1.0, 2.0),
        (0.5, 1.0, 0.5),
    ] {
        for scale in [1e-3, 1.0, 1e3] {
            let center = DVec3::new(3.0, -2.0, 5.0) * scale;
            let axis = DVec3::new(0.3, 1.0, -0.2);
            let toroid =
                Toroid::new_f64(center, axis, major * scale, a * scale, b * scale).unwrap();
            let (lo, hi) = toroid.world_aabb();
            let (lo, hi) = (lo.as_dvec3(), hi.as_dvec3());
            let to_world = toroid.image().to_local_rotation_f64().transpose();
            let (mut seen_lo, mut seen_hi) = (DVec3::INFINITY, DVec3::NEG_INFINITY);
            for _ in 0..20_000 {
                let theta: f64 = rng.random_range(0.0..std::f64::consts::TAU);
                let phi: f64 = rng.random_range(0.0..std::f64::consts::TAU);
                let rho = (major + a * theta.cos()) * scale;
                let local = DVec3::new(rho * phi.cos(), b * scale * theta.sin(), rho * phi.sin());
                let p = toroid.center_f64() + to_world * local;
                assert!(
                    p.cmpge(lo).all() && p.cmple(hi).all(),
                    "({major}, {a}, {b}) × {scale}: {p} outside {lo} .. {hi}"
                );
                seen_lo = seen_lo.min(p);
                seen_hi = seen_hi.max(p);
            }
            let size = (major + a.max(b)) * scale;
            let gap = (seen_lo - lo).max(hi - seen_hi).max_element();
            assert!(
                gap < 1e-2 * size,
                "({major}, {a}, {b}) × {scale}: gap {gap}"
            );
        }
    }
}
