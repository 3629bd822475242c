//! The parry adapter: the torus in a parry `Compound` beside parry's own `Ball` and
//! `Cuboid`, asked through parry's API, answers with the library's answers: bit for bit in
//! the local frame (and for the local ray parry's pose transform makes), and within that
//! transform's rounding against the library's posed torus.

use glam::{DVec3, Vec3};
use parry3d::math::{Pose, Vector};
use parry3d::query::{PointQuery, Ray as PRay, RayCast};
use parry3d::shape::{Ball, Compound, Cuboid, Shape, ShapeType, SharedShape};
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64;
use torus_cull::adapters::parry::ParryTorus;
use torus_cull::{Ray, Torus, intersect};

const R: f32 = 4.0;
const SMALL: f32 = 1.0;

fn pv(v: Vec3) -> Vector {
    Vector::from_array(v.to_array())
}
fn lv(v: Vector) -> Vec3 {
    Vec3::from_array(v.to_array())
}

fn torus_pose() -> Pose {
    Pose::new(Vector::new(1.0, 2.0, -3.0), Vector::new(0.3, -0.7, 0.4))
}

/// The torus, a ball and a cuboid, placed so that some rays meet several of them.
fn scene() -> (ParryTorus, Compound, [(Pose, SharedShape); 3]) {
    let torus = ParryTorus::new(R, SMALL).unwrap();
    let parts = [
        (torus_pose(), SharedShape::new(torus)),
        (
            Pose::translation(9.0, 2.0, -3.0),
            SharedShape::new(Ball::new(1.5)),
        ),
        (
            Pose::new(Vector::new(-8.0, 0.0, 0.0), Vector::new(0.0, 0.5, 0.0)),
            SharedShape::new(Cuboid::new(Vector::new(1.0, 2.0, 1.0))),
        ),
    ];
    (torus, Compound::new(parts.to_vec()), parts)
}

/// The library's answer to parry's local query: `t` and the normal facing the ray.
fn library_local(torus: &Torus, ray: &PRay, max: f32, solid: bool) -> Option<(f32, Vec3)> {
    let (o, d) = (lv(ray.origin), lv(ray.dir));
    let lib = Ray::with_range(o, d, 0.0, max).ok()?;
    if solid && torus.contains(o.as_dvec3()).unwrap() {
        return Some((0.0, Vec3::ZERO));
    }
    let hit = intersect(torus, &lib)?;
    Some((
        hit.t,
        if hit.front_face {
            hit.normal
        } else {
            -hit.normal
        },
    ))
}

fn bits(v: Vec3) -> [u32; 3] {
    v.to_array().map(f32::to_bits)
}

/// One local ray through parry's API against the library; returns the answer.
fn check_local(torus: &ParryTorus, ray: &PRay, max: f32, solid: bool) -> Option<(f32, Vec3)> {
    let want = library_local(torus.torus(), ray, max, solid);
    let got = torus.cast_local_ray_and_get_normal(ray, max, solid);
    let got = got.map(|h| (h.time_of_impact, lv(h.normal)));
    assert_eq!(
        got.map(|(t, n)| (t.to_bits(), bits(n))),
        want.map(|(t, n)| (t.to_bits(), bits(n))),
        "local ray {ray:?} max {max} solid {solid}: parry {got:?}, library {want:?}"
    );
    assert_eq!(
        torus.cast_local_ray(ray, max, solid).map(f32::to_bits),
        want.map(|(t, _)| t.to_bits())
    );
    want
}

/// The structured rays, in the torus frame: (origin, dir, expected t where known).
fn structured() -> Vec<(Vec3, Vec3, Option<Option<f32>>)> {
    let (r, s) = (R, SMALL);
    vec![
        // Through the hole, along the axis and off it: no hit.
        (Vec3::new(0.0, 10.0, 0.0), Vec3::NEG_Y, Some(None)),
        (Vec3::new(1.5, 10.0, 0.5), Vec3::NEG_Y, Some(None)),
        (Vec3::new(0.0, -10.0, 0.0), Vec3::Y, Some(None)),
        // Down onto the top of the tube, and with a non-unit direction.
        (Vec3::new(r, 10.0, 0.0), Vec3::NEG_Y, Some(Some(9.0))),
        (Vec3::new(r, 10.0, 0.0), Vec3::NEG_Y * 3.0, Some(Some(3.0))),
        // Across the equatorial plane through the centre.
        (Vec3::new(-10.0, 0.0, 0.0), Vec3::X, Some(Some(5.0))),
        // Grazing the outer equator, and the top circle: tangent lines.
        (Vec3::new(r + s, 0.0, -10.0), Vec3::Z, None),
        (Vec3::new(-10.0, s, 0.0), Vec3::X, None),
        (Vec3::new(r + s + 1e-3, 0.0, -10.0), Vec3::Z, Some(None)),
        (Vec3::new(0.0, s * 0.999_999, -10.0), Vec3::Z, None),
        // From inside the tube: outwards, and inwards across the hole.
        (Vec3::new(r, 0.0, 0.0), Vec3::X, Some(Some(1.0))),
        (Vec3::new(r, 0.0, 0.0), Vec3::NEG_X, Some(Some(1.0))),
        (Vec3::new(r, 0.5, 0.0), Vec3::Y, Some(Some(0.5))),
        // A diagonal into the tube and from a surface point.
        (Vec3::new(-9.0, 7.0, 2.0), Vec3::new(1.0, -0.8, -0.1), None),
        (Vec3::new(r + s, 0.0, 0.0), Vec3::NEG_X, None),
    ]
}

#[test]
fn structured_local_rays_are_the_librarys_bit_for_bit() {
    let (torus, _, _) = scene();
    let mut hits = 0;
    for (o, d, expect) in structured() {
        for solid in [false, true] {
            let ray = PRay::new(pv(o), pv(d));
            let got = check_local(&torus, &ray, f32::MAX, solid);
            hits += usize::from(got.is_some());
            if let Some(expect) = expect {
                let inside = torus.torus().contains(o.as_dvec3()).unwrap();
                let expect = if solid && inside { Some(0.0) } else { expect };
                assert_eq!(got.map(|(t, _)| t), expect, "ray {o} {d} solid {solid}");
            }
            // A shorter range than the hit: nothing.
            if let Some((t, _)) = got.filter(|&(t, _)| t > 0.0) {
                assert!(torus.cast_local_ray(&ray, t * 0.99, solid).is_none());
            }
        }
    }
    assert!(hits >= 20, "{hits} hits");
    // From inside the tube, solid = false: the exit at x = 5, its normal facing the ray.
    let out = torus.cast_local_ray_and_get_normal(
        &PRay::new(pv(Vec3::new(R, 0.0, 0.0)), pv(Vec3::X)),
        10.0,
        false,
    );
    let out = out.unwrap();
    assert_eq!((out.time_of_impact, lv(out.normal)), (1.0, Vec3::NEG_X));
    // solid = true: time of impact 0, a zero normal.
    let inside = torus.cast_local_ray_and_get_normal(
        &PRay::new(pv(Vec3::new(R, 0.0, 0.0)), pv(Vec3::X)),
        10.0,
        true,
    );
    assert_eq!(
        inside.map(|h| (h.time_of_impact, lv(h.normal))),
        Some((0.0, Vec3::ZERO))
    );
    // Rays the library refuses hit nothing.
    let bad = [
        PRay::new(pv(Vec3::new(f32::NAN, 0.0, 0.0)), pv(Vec3::X)),
        PRay::new(pv(Vec3::new(-10.0, 0.0, 0.0)), pv(Vec3::ZERO)),
        PRay::new(
            pv(Vec3::new(-10.0, 0.0, 0.0)),
            pv(Vec3::new(f32::INFINITY, 0.0, 0.0)),
        ),
    ];
    for ray in bad {
        assert!(torus.cast_local_ray(&ray, 100.0, true).is_none());
    }
    let ray = PRay::new(pv(Vec3::new(-10.0, 0.0, 0.0)), pv(Vec3::X));
    assert!(torus.cast_local_ray(&ray, f32::NAN, false).is_none());
    assert!(torus.cast_local_ray(&ray, -1.0, false).is_none());
}

/// A ray aimed near the torus from up to 12 away (local frame).
fn random_ray(rng: &mut Pcg64) -> (Vec3, Vec3) {
    let mut v = |a: f32| {
        Vec3::new(
            rng.random_range(-a..a),
            rng.random_range(-a..a),
            rng.random_range(-a..a),
        )
    };
    let o = v(12.0);
    let target = v(5.5) * Vec3::new(1.0, 0.3, 1.0);
    let d = (target - o).normalize_or(Vec3::X);
    (o, d)
}

#[test]
fn random_rays_through_a_compound_are_the_librarys() {
    let (torus, compound, parts) = scene();
    let pose = torus_pose();
    let world_torus = torus.posed(&pose).unwrap();
    let mut rng = Pcg64::seed_from_u64(0x9a77_0041);
    let (mut torus_wins, mut compared, mut tangent_skips) = (0, 0, 0);
    let n = 4000;
    for i in 0..n {
        let (o, d) = random_ray(&mut rng);
        let solid = i % 3 == 0;
        // Local: bit for bit.
        check_local(&torus, &PRay::new(pv(o), pv(d)), f32::MAX, solid);
        // World: the same ray placed by the torus's pose, through the compound.
        let world = PRay::new(pv(o), pv(d)).transform_by(&pose);
        let got = compound.cast_ray_and_get_normal(&Pose::identity(), &world, f32::MAX, solid);
        // The compound's answer is the nearest part's, the torus's being the library's
        // on the local ray parry's pose transform makes.
        let torus_t = library_local(
            torus.torus(),
            &world.inverse_transform_by(&pose),
            f32::MAX,
            solid,
        );
        let others = parts[1..]
            .iter()
            .filter_map(|(p, s)| s.cast_ray(p, &world, f32::MAX, solid))
            .fold(f32::INFINITY, f32::min);
        let want = torus_t.map_or(others, |(t, _)| t.min(others));
        assert_eq!(
            got.map(|h| h.time_of_impact.to_bits()),
            want.is_finite().then(|| want.to_bits()),
            "world ray {world:?}"
        );
        if let (Some(h), Some((t, n))) = (got, torus_t)
            && t < others
        {
            torus_wins += 1;
            assert_eq!(h.subshape, 0);
            // The normal, rotated back to the world by parry's pose.
            assert_eq!(bits(lv(h.normal)), bits(lv(pose.rotation * pv(n))));
        }
        // Against the library's posed torus, in the world: within the pose's f32 rounding.
        let lib = Ray::new(lv(world.origin), lv(world.dir)).unwrap();
        let posed = intersect(&world_torus, &lib);
        let mine = torus.cast_ray(&pose, &world, f32::MAX, false);
        match (posed, mine) {
            (Some(h), Some(t)) => {
                let cos = h.normal.dot(lv(world.dir)).abs();
                if cos > 1e-2 {
                    compared += 1;
                    let tol = 1e-5 * (lv(world.origin).length() + 10.0) / cos;
                    assert!(
                        (h.t - t).abs() <= tol,
                        "world ray {world:?}: {t} vs {}",
                        h.t
                    );
                } else {
                    tangent_skips += 1;
                }
            }
            (None, None) => {}
            (h, t) => {
                // Only a grazing ray may hit in one frame and miss in the other.
                let cos = h.map(|h| h.normal.dot(lv(world.dir)).abs());
                assert!(
                    cos.is_none_or(|c| c < 1e-2),
                    "world ray {world:?}: library {h:?} parry {t:?}"
                );
                tangent_skips += 1;
            }
        }
    }
    eprintln!(
        "parry: {n} random rays, torus nearest in the compound {torus_wins}, world t compared {compared}, grazing skipped {tangent_skips}"
    );
    assert!(torus_wins > n / 5 && compared > n / 4 && tangent_skips < n / 50);
}

#[test]
fn point_queries_are_the_librarys() {
    let (torus, compound, parts) = scene();
    let pose = torus_pose();
    let world_torus = torus.posed(&pose).unwrap();
    let lib = torus.torus();
    let mut points = vec![
        Vec3::ZERO,                     // the centre: on the axis
        Vec3::new(0.0, 3.0, 0.0),       // on the axis
        Vec3::new(R, 0.0, 0.0),         // on the core circle
        Vec3::new(0.0, 0.0, -R),        // on the core circle
        Vec3::new(R + SMALL, 0.0, 0.0), // the outer equator
        Vec3::new(R - SMALL, 0.0, 0.0), // the inner equator
        Vec3::new(R, SMALL, 0.0),       // the top circle
        Vec3::new(1e4, -3e3, 2e4),      // far away
    ];
    let mut rng = Pcg64::seed_from_u64(0x9a77_0042);
    points.extend((0..3000).map(|_| {
        Vec3::new(
            rng.random_range(-7.0..7.0),
            rng.random_range(-2.5..2.5),
            rng.random_range(-7.0..7.0),
        )
    }));
    let mut inside = 0;
    for p in points {
        let x = p.as_dvec3();
        let want = lib.project_point(x).unwrap();
        let is_in = lib.contains(x).unwrap();
        inside += usize::from(is_in);
        for solid in [false, true] {
            let got = torus.project_local_point(pv(p), solid);
            assert_eq!(got.is_inside, is_in, "{p}");
            let point = if solid && is_in {
                p
            } else {
                want.point.as_vec3()
            };
            assert_eq!(bits(lv(got.point)), bits(point), "{p} solid {solid}");
            let dist = if solid {
                want.signed_distance.max(0.0)
            } else {
                want.signed_distance
            };
            assert_eq!(
                torus.distance_to_local_point(pv(p), solid).to_bits(),
                (dist as f32).to_bits(),
                "{p}"
            );
        }
        assert_eq!(torus.contains_local_point(pv(p)), is_in);
        // World: parry's pose transform, then the library; and the posed library torus.
        let w = pose * pv(p);
        let local = pose.inverse_transform_point(w);
        assert_eq!(
            torus.contains_point(&pose, w),
            lib.contains(lv(local).as_dvec3()).unwrap()
        );
        let d_world = torus.distance_to_point(&pose, w, false);
        let d_lib = world_torus.signed_distance(lv(w).as_dvec3()).unwrap();
        let scale = f64::from(lv(w).length()) + 10.0;
        assert!(
            (f64::from(d_world) - d_lib).abs() <= 1e-6 * scale,
            "{p}: {d_world} vs {d_lib}"
        );
        let proj = torus.project_point(&pose, w, false);
        let lib_proj = world_torus.project_point(lv(w).as_dvec3()).unwrap();
        // Off the axis and the core circle, where the closest point is unique, the points
        // agree.
        let rho = p.x.hypot(p.z);
        if rho > 1e-2 && (rho - R).hypot(p.y) > 1e-2 {
            let off = (lv(proj.point).as_dvec3() - lib_proj.point).length();
            assert!(
                off <= 1e-5 * scale,
                "{p}: {:?} vs {}",
                proj.point,
                lib_proj.point
            );
        }
        // The compound holds the point iff one of its parts does.
        let any = parts.iter().any(|(pp, s)| s.contains_point(pp, w));
        assert_eq!(compound.contains_point(&Pose::identity(), w), any);
    }
    assert!(inside > 100, "{inside} points inside the tube");
    // A non-finite point: not inside, its distance +∞, no NaN invented.
    let far = Vector::new(f32::INFINITY, 0.0, 0.0);
    assert!(!torus.contains_local_point(far));
    assert_eq!(torus.distance_to_local_point(far, true), f32::INFINITY);
    assert!(!torus.contains_local_point(Vector::new(f32::NAN, 0.0, 0.0)));
}

#[test]
fn bounds_mass_and_scale() {
    let (torus, compound, _) = scene();
    let pose = torus_pose();
    // The world box is the library's posed box, and holds the posed surface.
    let aabb = torus.compute_aabb(&pose);
    let (lo, hi) = torus.posed(&pose).unwrap().world_aabb();
    assert_eq!(
        (bits(lv(aabb.mins)), bits(lv(aabb.maxs))),
        (bits(lo), bits(hi))
    );
    let rotated = torus.compute_local_aabb().transform_by(&pose);
    assert!(lv(rotated.mins).cmple(lo).all() && lv(rotated.maxs).cmpge(hi).all());
    assert!((hi - lo).element_sum() < (lv(rotated.maxs) - lv(rotated.mins)).element_sum());
    let world = torus.posed(&pose).unwrap();
    for i in 0..64 {
        for j in 0..64 {
            let (th, ph) = (f64::from(i) * 0.0982, f64::from(j) * 0.0982);
            let s = world.point_at(th, ph).as_vec3();
            assert!(s.cmpge(lo).all() && s.cmple(hi).all(), "{s}");
        }
    }
    let whole = compound.local_aabb();
    assert!(lv(whole.mins).cmple(lo).all() && lv(whole.maxs).cmpge(hi).all());
    // The local box and sphere: R + r wide, r high.
    let local = torus.compute_local_aabb();
    assert_eq!(
        (lv(local.mins), lv(local.maxs)),
        (Vec3::new(-5.0, -1.0, -5.0), Vec3::new(5.0, 1.0, 5.0))
    );
    assert_eq!(torus.compute_local_bounding_sphere().radius(), 5.0);
    assert_eq!(torus.shape_type(), ShapeType::Custom);

    // Mass properties against a seeded Monte-Carlo integral over the box.
    let mp = torus.mass_properties(2.0);
    let mut rng = Pcg64::seed_from_u64(0x9a77_0043);
    let (n, mut count, mut iy, mut ix) = (400_000, 0.0, 0.0, 0.0);
    for _ in 0..n {
        let p = DVec3::new(
            rng.random_range(-5.0..5.0),
            rng.random_range(-1.0..1.0),
            rng.random_range(-5.0..5.0),
        );
        if torus.torus().contains(p).unwrap() {
            count += 1.0;
            iy += p.x * p.x + p.z * p.z;
            ix += p.y * p.y + p.z * p.z;
        }
    }
    let cell = 100.0 * 2.0 / f64::from(n);
    let mass = 2.0 * count * cell;
    let close = |a: f64, b: f64| (a - b).abs() <= 0.02 * b;
    assert!(close(f64::from(mp.mass()), mass), "{} vs {mass}", mp.mass());
    let inertia = lv(mp.principal_inertia()).as_dvec3();
    assert!(
        close(inertia.y, 2.0 * iy * cell) && close(inertia.x, 2.0 * ix * cell),
        "{inertia}"
    );
    assert!(close(inertia.z, inertia.x));

    // Uniform scale: the scaled torus; non-uniform: refused.
    let scaled = torus.scale_dyn(Vector::splat(-2.0), 8).unwrap();
    let scaled = scaled.as_shape::<ParryTorus>().unwrap();
    assert_eq!(
        (scaled.torus().major_radius(), scaled.torus().minor_radius()),
        (8.0, 2.0)
    );
    assert!(torus.scale_dyn(Vector::new(1.0, 2.0, 1.0), 8).is_none());
    assert!(torus.scale_dyn(Vector::ZERO, 8).is_none());
}
