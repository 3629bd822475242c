//! The Bevy adapter: Bevy's four torus kinds converted (or refused), its proposed ray cast
//! answered by the family's `intersect` bit for bit, the world box against Bevy's
//! `Bounded3d`, and non-finite inputs.

use bevy_math::{Dir3, Isometry3d, Quat, Vec3 as BVec3};
use bevy_shape::Bounded3d;
use bevy_shape::{Ray3d, Torus as BTorus, TorusKind};
use glam::{DVec3, Vec3};
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64;
use torus_cull::Ray;
use torus_cull::adapters::bevy::{
    BevyTorus, BevyTorusError, solid_ray_cast, toroid_from_bevy, torus_from_bevy, world_aabb,
};
use torus_cull::family::{Toroid, ToroidError, ToroidKind};

fn lv(v: BVec3) -> Vec3 {
    Vec3::from_array(v.to_array())
}

fn shape(major: f32, minor: f32) -> BTorus {
    BTorus {
        minor_radius: minor,
        major_radius: major,
    }
}

fn iso() -> Isometry3d {
    Isometry3d::new(
        BVec3::new(2.0, -1.0, 0.5),
        Quat::from_axis_angle(BVec3::new(1.0, 2.0, -0.5).normalize(), 0.9),
    )
}

#[test]
fn the_four_kinds_convert_or_are_refused() {
    let ring = shape(2.5, 1.0);
    assert_eq!(ring.kind(), TorusKind::Ring);
    let t = torus_from_bevy(&ring, iso()).unwrap();
    assert_eq!((t.major_radius(), t.minor_radius()), (2.5, 1.0));
    assert_eq!(t.center(), lv(BVec3::from(iso().translation)));
    assert_eq!(
        t.axis(),
        lv(iso().rotation * BVec3::Y)
            .as_dvec3()
            .normalize()
            .as_vec3()
    );
    assert_eq!(
        toroid_from_bevy(&ring, iso()).unwrap().kind(),
        ToroidKind::Ring
    );

    for (s, kind) in [
        (shape(1.0, 1.0), ToroidKind::Horn),
        (shape(0.75, 1.0), ToroidKind::Spindle),
    ] {
        let m = toroid_from_bevy(&s, iso()).unwrap();
        assert_eq!(m.kind(), kind);
        assert_eq!(
            (
                m.major_radius_f64(),
                m.radial_semi_axis_f64(),
                m.axial_semi_axis_f64()
            ),
            (f64::from(s.major_radius), 1.0, 1.0)
        );
        assert_eq!(
            torus_from_bevy(&s, iso()),
            Err(BevyTorusError::NotRing(kind))
        );
        assert!(BevyTorus::try_from(s).is_ok());
    }
    // Fat spindles down to the family's R/r = 1/100 (issue 54: Bevy's major radius 0.2,
    // minor 1), the same member as the family's own; fatter is refused.
    for major in [0.2, 0.01] {
        let m = toroid_from_bevy(&shape(major, 1.0), iso()).unwrap();
        assert_eq!(m.kind(), ToroidKind::Spindle);
        let own = Toroid::new(
            lv(BVec3::from(iso().translation)),
            lv(iso().rotation * BVec3::Y),
            major,
            1.0,
            1.0,
        )
        .unwrap();
        assert_eq!(m, own);
    }
    assert!(matches!(
        toroid_from_bevy(&shape(0.005, 1.0), iso()),
        Err(BevyTorusError::Toroid(ToroidError::TooFat { .. }))
    ));
    // Invalid: a typed error, whichever radius is bad.
    for (major, minor) in [
        (1.0, -1.0),
        (0.0, 1.0),
        (f32::NAN, 1.0),
        (2.0, f32::INFINITY),
    ] {
        let s = shape(major, minor);
        assert_eq!(s.kind(), TorusKind::Invalid);
        for e in [
            torus_from_bevy(&s, iso()).unwrap_err(),
            toroid_from_bevy(&s, iso()).unwrap_err(),
            BevyTorus::try_from(s).unwrap_err(),
        ] {
            assert!(matches!(e, BevyTorusError::Invalid { .. }), "{e}");
        }
    }
    // A non-finite pose: refused, typed.
    let bad = Isometry3d::from_translation(BVec3::new(f32::NAN, 0.0, 0.0));
    assert!(matches!(
        torus_from_bevy(&ring, bad),
        Err(BevyTorusError::Torus(_))
    ));
    assert!(matches!(
        toroid_from_bevy(&ring, bad),
        Err(BevyTorusError::Toroid(_))
    ));
}

#[test]
fn the_ray_cast_is_the_familys_intersect_bit_for_bit() {
    let mut rng = Pcg64::seed_from_u64(0xbe71_0041);
    let mut counts = Vec::new();
    for s in [
        shape(2.5, 1.0),
        shape(1.0, 1.0),
        shape(0.75, 1.0),
        shape(0.2, 1.0),
    ] {
        let torus = BevyTorus::try_from(s).unwrap();
        let member = torus.toroid();
        let (mut hits, mut inside) = (0, 0);
        for i in 0..3000 {
            let mut v = |a: f32| {
                Vec3::new(
                    rng.random_range(-a..a),
                    rng.random_range(-a..a),
                    rng.random_range(-a..a),
                )
            };
            let o = if i % 4 == 0 {
                v(1.5) * Vec3::new(2.0, 0.6, 2.0)
            } else {
                v(8.0)
            };
            let d = (v(3.0) - o).normalize_or(Vec3::X);
            let solid = i % 2 == 0;
            let max = if i % 7 == 0 { 3.0 } else { f32::MAX };
            let ray = Ray3d::new(
                BVec3::from_array(o.to_array()),
                Dir3::new(BVec3::from_array(d.to_array())).unwrap(),
            );
            let got = torus.local_ray_cast(ray, max, solid);
            // The interface's cast on the same member: the same answer.
            assert_eq!(solid_ray_cast(member, ray, max, solid), got);
            let dir = lv(*ray.direction);
            let contains = member.contains(o.as_dvec3()).unwrap();
            inside += usize::from(contains);
            let want = if solid && contains {
                Some((0.0, -dir))
            } else {
                member
                    .intersect(&Ray::with_range(o, dir, 0.0, max).unwrap())
                    .map(|h| (h.t, if h.front_face { h.normal } else { -h.normal }))
            };
            let key = |x: Option<(f32, Vec3)>| {
                x.map(|(t, n)| (t.to_bits(), n.to_array().map(f32::to_bits)))
            };
            assert_eq!(
                key(got.map(|h| (h.distance, lv(*h.normal)))),
                key(want),
                "{s:?} ray {o} {d} max {max} solid {solid}"
            );
            hits += usize::from(got.is_some());
            // Posed: Bevy's provided method, the ray moved by the inverse isometry.
            let world = Ray3d {
                origin: iso().transform_point(ray.origin).into(),
                direction: iso().rotation * ray.direction,
            };
            let local = Ray3d {
                origin: iso().inverse_transform_point(world.origin).into(),
                direction: iso().rotation.inverse() * world.direction,
            };
            let posed = torus.ray_cast(iso(), world, max, solid);
            let expect = torus.local_ray_cast(local, max, solid);
            assert_eq!(
                posed.map(|h| h.distance.to_bits()),
                expect.map(|h| h.distance.to_bits())
            );
            assert_eq!(
                posed.map(|h| *h.normal),
                expect.map(|h| iso().rotation * *h.normal)
            );
            assert_eq!(
                torus.intersects_ray(iso(), world, max),
                torus.ray_cast(iso(), world, max, true).is_some()
            );
        }
        assert!(
            hits > 500 && inside > 50,
            "{s:?}: {hits} hits, {inside} origins inside"
        );
        counts.push(hits);
    }
    eprintln!("bevy: 4 × 3000 rays (ring, horn, spindles R/r 0.75 and 0.2), hits {counts:?}");
    // Issue 54's torus (major 0.2, minor 1): down the axis onto its cusp at
    // y = √(1 − 0.2²), the normal there along the axis, facing the ray.
    let fat = BevyTorus::try_from(shape(0.2, 1.0)).unwrap();
    let down = Ray3d::new(BVec3::new(0.0, 10.0, 0.0), Dir3::NEG_Y);
    let hit = fat.local_ray_cast(down, 100.0, false).unwrap();
    assert!(
        (hit.distance - (10.0 - 0.96f32.sqrt())).abs() < 1e-5,
        "{hit:?}"
    );
    assert_eq!(hit.normal, Dir3::Y);
    // A known answer: down onto the top of the ring's tube, the normal facing the ray.
    let ring = BevyTorus::try_from(shape(2.5, 1.0)).unwrap();
    let hit = ring
        .local_ray_cast(
            Ray3d::new(BVec3::new(2.5, 10.0, 0.0), Dir3::NEG_Y),
            100.0,
            false,
        )
        .unwrap();
    assert_eq!((hit.distance, hit.normal), (9.0, Dir3::Y));
    let exit = ring
        .local_ray_cast(Ray3d::new(BVec3::new(2.5, 0.0, 0.0), Dir3::X), 100.0, false)
        .unwrap();
    assert_eq!((exit.distance, exit.normal), (1.0, Dir3::NEG_X));
    let solid = ring
        .local_ray_cast(Ray3d::new(BVec3::new(2.5, 0.0, 0.0), Dir3::X), 100.0, true)
        .unwrap();
    assert_eq!((solid.distance, solid.normal), (0.0, Dir3::NEG_X));
}

#[test]
fn non_finite_inputs_hit_nothing() {
    let ring = BevyTorus::try_from(shape(2.5, 1.0)).unwrap();
    let ray = Ray3d::new(BVec3::new(-10.0, 0.0, 0.0), Dir3::X);
    assert!(ring.local_ray_cast(ray, 100.0, false).is_some());
    assert!(ring.local_ray_cast(ray, f32::NAN, false).is_none());
    assert!(ring.local_ray_cast(ray, -1.0, true).is_none());
    for o in [
        BVec3::new(f32::NAN, 0.0, 0.0),
        BVec3::new(f32::INFINITY, 0.0, 0.0),
    ] {
        for solid in [false, true] {
            assert!(
                ring.local_ray_cast(Ray3d::new(o, Dir3::X), 100.0, solid)
                    .is_none()
            );
        }
    }
    let bad = Isometry3d::from_translation(BVec3::new(f32::NAN, 0.0, 0.0));
    assert!(ring.ray_cast(bad, ray, 100.0, false).is_none());
}

#[test]
fn the_world_box_agrees_with_bevys_bounded3d() {
    let mut rng = Pcg64::seed_from_u64(0xbe71_0042);
    let (mut equal, mut n, mut worst, mut bevy_short) = (0, 0, 0.0_f32, 0);
    for s in [
        shape(2.5, 1.0),
        shape(1.0, 1.0),
        shape(0.75, 1.0),
        shape(300.0, 0.5),
    ] {
        for _ in 0..500 {
            let axis = BVec3::new(
                rng.random_range(-1.0..1.0),
                rng.random_range(-1.0..1.0),
                rng.random_range(-1.0..1.0),
            )
            .normalize_or(BVec3::Y);
            let at = BVec3::new(
                rng.random_range(-50.0..50.0),
                rng.random_range(-50.0..50.0),
                rng.random_range(-50.0..50.0),
            );
            let iso = Isometry3d::new(at, Quat::from_axis_angle(axis, rng.random_range(-3.0..3.0)));
            let (lo, hi) = world_aabb(&s, iso).unwrap();
            let theirs = s.aabb_3d(iso);
            let (blo, bhi) = (BVec3::from(theirs.min), BVec3::from(theirs.max));
            // Both are iq's disc box expanded by r. The library's is formed in f64 and
            // rounded outward; Bevy's in f32, where 1 − aᵢ² cancels for an axis near a
            // coordinate axis and √(1 − aᵢ²)·R is off by up to about √ε·R.
            let tol = 2.0 * f32::EPSILON.sqrt() * s.major_radius
                + 8.0 * f32::EPSILON * (at.abs().max_element() + s.major_radius + s.minor_radius);
            let off = (lo - blo)
                .abs()
                .max_element()
                .max((hi - bhi).abs().max_element());
            assert!(off <= tol, "{s:?}: {lo} {hi} vs {blo} {bhi}");
            worst = worst.max(off / s.major_radius);
            equal += usize::from(lo == blo && hi == bhi);
            n += 1;
            // The library's box holds the surface (sampled in f64 from its own member).
            let member = toroid_from_bevy(&s, iso).unwrap();
            let (c, a) = (member.center_f64(), member.axis_f64());
            let u = a.any_orthonormal_vector();
            let w = a.cross(u);
            let (big, r) = (member.major_radius_f64(), member.radial_semi_axis_f64());
            for k in 0..32 {
                for j in 0..32 {
                    let (th, ph) = (f64::from(k) * 0.196, f64::from(j) * 0.196);
                    let rho = big + r * th.cos();
                    let p = c + (u * ph.cos() + w * ph.sin()) * rho + a * (r * th.sin());
                    let (lo, hi) = (lv(lo).as_dvec3(), lv(hi).as_dvec3());
                    let slack = DVec3::splat(1e-12 * (c.length() + big + r));
                    assert!(
                        p.cmpge(lo - slack).all() && p.cmple(hi + slack).all(),
                        "{p} outside {lo} {hi}"
                    );
                    let (blo, bhi) = (lv(blo).as_dvec3(), lv(bhi).as_dvec3());
                    bevy_short += usize::from(!(p.cmpge(blo).all() && p.cmple(bhi).all()));
                }
            }
        }
    }
    eprintln!(
        "bevy boxes: {equal} of {n} equal to Bevy's bit for bit; the largest difference {worst:e}·R; \
         surface samples outside Bevy's box {bevy_short} (none outside the library's)"
    );
}

/// The interface's cast on a pipe bend: the bend's own nearest hit, its normal facing the
/// ray, bit for bit (a bend with a bore, over a segment).
#[test]
fn the_interface_cast_on_a_bend_is_the_bends_intersect() {
    let bend = torus_cull::bend::PipeBend::canonical(4.0, 0.5, 1.2, 0.3, 2.5).unwrap();
    let mut rng = Pcg64::seed_from_u64(0xbe71_0b3d);
    let mut hits = 0;
    for i in 0..500 {
        let mut v = |a: f32| {
            Vec3::new(
                rng.random_range(-a..a),
                rng.random_range(-a..a),
                rng.random_range(-a..a),
            )
        };
        let o = v(9.0);
        let d = (v(5.0) * Vec3::new(1.0, 0.3, 1.0) - o).normalize_or(Vec3::X);
        let ray = Ray3d::new(
            BVec3::from_array(o.to_array()),
            Dir3::new(BVec3::from_array(d.to_array())).unwrap(),
        );
        let (solid, d) = (i % 2 == 0, lv(*ray.direction)); // Dir3::new renormalizes
        let got = solid_ray_cast(&bend, ray, f32::MAX, solid);
        let want = if solid && bend.contains(o.as_dvec3()) {
            Some((0.0, -d))
        } else {
            bend.intersect(&Ray::with_range(o, d, 0.0, f32::MAX).unwrap())
                .map(|h| (h.t, if h.front_face { h.normal } else { -h.normal }))
        };
        assert_eq!(got.map(|h| (h.distance, lv(*h.normal))), want, "{o} {d}");
        hits += usize::from(got.is_some());
    }
    assert!(hits > 100, "{hits}");
}
