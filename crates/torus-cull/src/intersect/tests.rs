//! The exact intersection's unit tests (moved out of mod.rs, which they outgrew).

use super::*;
use crate::geometry::draw::vec3_in;
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64;

fn canonical() -> Torus {
    Torus::canonical(2.0, 1.0).unwrap()
}

/// The geometric outward normal at a local point near the surface: (x − c)/|x − c| with
/// c = R·(x, 0, z)/ρ the nearest point of the tube's centre circle.
fn geometric_normal(major: f64, x: DVec3) -> DVec3 {
    let rho = (x.x * x.x + x.z * x.z).sqrt();
    let c = DVec3::new(x.x, 0.0, x.z) * (major / rho);
    (x - c).normalize()
}

/// Distance from a local point to the torus surface: |‖x − c‖ − r|.
fn surface_distance(major: f64, minor: f64, x: DVec3) -> f64 {
    let rho = (x.x * x.x + x.z * x.z).sqrt();
    ((rho - major).hypot(x.y) - minor).abs()
}

#[test]
fn hand_computed_hit_along_x() {
    let ray = Ray::new(Vec3::new(-5.0, 0.0, 0.0), Vec3::X).unwrap();
    let hit = intersect(&canonical(), &ray).expect("hits the outer equator");
    assert!((hit.t - 2.0).abs() < 1e-6, "{hit:?}");
    assert!(
        (hit.normal - Vec3::new(-1.0, 0.0, 0.0)).length() < 1e-6,
        "{hit:?}"
    );
    // All four crossings: x = −3, −1, 1, 3 → t = 2, 4, 6, 8.
    let roots = line_roots_local(
        2.0,
        1.0,
        DVec3::new(-5.0, 0.0, 0.0),
        DVec3::new(1.0, 0.0, 0.0),
    );
    let want = [2.0, 4.0, 6.0, 8.0];
    assert_eq!(roots.len(), 4, "{roots:?}");
    for (g, w) in roots.as_slice().iter().zip(want) {
        assert!((g - w).abs() < 1e-12, "{roots:?}");
    }
    // A non-unit direction: t in units of d.
    let ray = Ray::new(Vec3::new(-5.0, 0.0, 0.0), Vec3::new(4.0, 0.0, 0.0)).unwrap();
    let hit = intersect(&canonical(), &ray).unwrap();
    assert!((hit.t - 0.5).abs() < 1e-7, "{hit:?}");
    // Skala's Eq. 35 counterexample (docs/math.md, errata): hits at x = ±1.134, ±2.866.
    let roots = line_roots_local(
        2.0,
        1.0,
        DVec3::new(-6.0, 0.5, 0.0),
        DVec3::new(1.0, 0.0, 0.0),
    );
    let h = 0.75f64.sqrt();
    let want = [-2.0 - h, -2.0 + h, 2.0 - h, 2.0 + h].map(|x| x + 6.0);
    assert_eq!(roots.len(), 4, "{roots:?}");
    for (g, w) in roots.as_slice().iter().zip(want) {
        assert!((g - w).abs() < 1e-12, "{roots:?} vs {want:?}");
    }
}

#[test]
fn tangent_ray_on_top_is_a_double_root() {
    // y = r touches the top circle ρ = R at x = ±2: two double roots.
    let o = DVec3::new(-5.0, 1.0, 0.0);
    let roots = line_roots_local(2.0, 1.0, o, DVec3::X);
    assert_eq!(roots.len(), 4, "{roots:?}");
    for (g, w) in roots.as_slice().iter().zip([3.0, 3.0, 7.0, 7.0]) {
        assert!((g - w).abs() < 1e-7, "{roots:?}");
    }
    let ray = Ray::new(Vec3::new(-5.0, 1.0, 0.0), Vec3::X).unwrap();
    let hit = intersect(&canonical(), &ray).expect("tangent ray grazes the top");
    assert!((hit.t - 3.0).abs() < 1e-6, "{hit:?}");
    assert!((hit.normal - Vec3::Y).length() < 1e-6, "{hit:?}");
    // Tangent to the outer equator from above: x = R + r, along −y; double root at y = 0.
    let roots = line_roots_local(2.0, 1.0, DVec3::new(3.0, 5.0, 0.0), -DVec3::Y);
    assert_eq!(roots.len(), 2, "{roots:?}");
    for g in roots.as_slice() {
        assert!((g - 5.0).abs() < 1e-7, "{roots:?}");
    }
    // Slightly above the top: a miss.
    let ray = Ray::new(Vec3::new(-5.0, 1.0001, 0.0), Vec3::X).unwrap();
    assert!(intersect(&canonical(), &ray).is_none());
}

#[test]
fn tangent_rays_in_random_poses_are_found() {
    // A radial line at height y = r touches the top circle (ρ = R) twice: double roots.
    // In a random world pose the f32 ray is tangent only up to rounding, so the line is
    // nudged by 1e-5·r: inward it must hit near the tangent point (the chord half-length
    // is √(2r·δ) ≈ 2.2e-3), outward it must miss.
    // Along the top circle instead (its tangent direction), the contact is of order
    // four (ρ − R ≈ s²/2R), so the inward-nudged hit is ⁴√-far: |t − 10| ≈ 0.095.
    let mut rng = Pcg64::seed_from_u64(0x7051_0010);
    for _ in 0..2000 {
        let axis = vec3_in(&mut rng, Vec3::splat(1.0));
        if axis.length() < 0.1 {
            continue;
        }
        let center = vec3_in(&mut rng, Vec3::splat(5.0));
        let torus = Torus::new(center, axis, 2.0, 0.5).unwrap();
        let phi = rng.random_range(0.0..std::f32::consts::TAU);
        let (sn, cs) = phi.sin_cos();
        let radial = Vec3::new(cs, 0.0, sn);
        let along = Vec3::new(-sn, 0.0, cs);
        // Radial: the origin is at −8·radial, so the first touch is the far side's top,
        // ρ = R at −2·radial, t = 6.
        for (dir, t_hit, t_tol) in [(radial, 6.0, 3e-3), (along, 10.0, 0.12)] {
            for (nudge, hits) in [(-1e-5f32, true), (1e-5, false)] {
                let touch = Vec3::new(2.0 * cs, 0.5 * (1.0 + nudge), 2.0 * sn);
                let o_local = touch - 10.0 * dir;
                let ray = Ray::new(torus.point_to_world(o_local), torus.dir_to_world(dir)).unwrap();
                let hit = intersect(&torus, &ray);
                assert_eq!(hit.is_some(), hits, "{dir} nudge {nudge}: {hit:?}");
                if let Some(hit) = hit {
                    assert!((hit.t - t_hit).abs() < t_tol, "{dir}: {hit:?}");
                    assert!(
                        (hit.normal - torus.axis()).length() < 2e-2,
                        "{dir}: {hit:?}"
                    );
                }
            }
        }
    }
}

#[test]
fn ray_through_the_hole_along_the_axis_misses() {
    let ray = Ray::new(Vec3::new(0.0, 10.0, 0.0), -Vec3::Y).unwrap();
    assert!(intersect(&canonical(), &ray).is_none());
    assert!(line_roots_local(2.0, 1.0, DVec3::new(0.0, 10.0, 0.0), -DVec3::Y).is_empty());
    // Also the lib.rs doc example: a vertical ray onto the top of the tube at t = 9.
    let torus = Torus::new(Vec3::ZERO, Vec3::Y, 4.0, 1.0).unwrap();
    let ray = Ray::new(Vec3::new(4.0, 10.0, 0.0), -Vec3::Y).unwrap();
    let hit = intersect(&torus, &ray).unwrap();
    assert!((hit.t - 9.0).abs() < 1e-6);
}

#[test]
fn range_is_respected() {
    let torus = canonical();
    let o = Vec3::new(-5.0, 0.0, 0.0);
    let at = |t_min: f32, t_max: f32| {
        intersect(&torus, &Ray::with_range(o, Vec3::X, t_min, t_max).unwrap()).map(|h| h.t)
    };
    let close = |a: Option<f32>, b: f32| a.is_some_and(|a| (a - b).abs() < 1e-6);
    assert!(close(at(0.0, f32::INFINITY), 2.0));
    assert!(close(at(2.5, 100.0), 4.0));
    assert!(close(at(4.5, 100.0), 6.0));
    assert!(close(at(7.0, 8.5), 8.0));
    // A negative t_min is refused (issue 52): a ray starts at its origin.
    assert!(Ray::with_range(o, Vec3::X, -100.0, 100.0).is_err());
    assert_eq!(at(8.5, 100.0), None);
    assert_eq!(at(0.0, 1.9), None);
    assert_eq!(at(2.1, 3.9), None);
    // Origin inside the tube (x = −2.5): the nearest forward hit is the exit at t = 1.5,
    // with the normal pointing out of the tube, i.e. towards +x here.
    let ray = Ray::new(Vec3::new(-2.5, 0.0, 0.0), Vec3::X).unwrap();
    let hit = intersect(&torus, &ray).unwrap();
    assert!((hit.t - 1.5).abs() < 1e-6 && (hit.normal - Vec3::X).length() < 1e-6);
    // Behind the origin only: miss.
    let ray = Ray::new(Vec3::new(5.0, 0.0, 0.0), Vec3::X).unwrap();
    assert!(intersect(&torus, &ray).is_none());
}

/// A random pose, R in [1e-3, 1e3] log-uniform, ν in (1.2, 10).
fn random_torus(rng: &mut Pcg64) -> Torus {
    let major = 10f32.powf(rng.random_range(-3.0..3.0));
    let nu = rng.random_range(1.2..10.0);
    // A uniform axis by rejection from the unit ball (the harness's generators are not
    // part of the renderer build).
    let mut cube = || vec3_in(rng, Vec3::splat(1.0));
    let axis = loop {
        let v = cube();
        if (0.01..=1.0).contains(&v.length_squared()) {
            break v.normalize();
        }
    };
    let center = cube() * 3.0 * major;
    Torus::new(center, axis, major, major / nu).expect("valid radii at any pose")
}

/// An origin in the box ±`reach`·R around the centre, and the direction from it to a
/// point near the tube (|x|, |z| ≤ 1.5R, |y| ≤ 0.5R), unnormalized.
fn aimed_at_the_tube(rng: &mut Pcg64, torus: &Torus, reach: f32) -> (Vec3, Vec3) {
    let big = torus.major_radius();
    let mut offset = |x: f32, y: f32| vec3_in(rng, Vec3::new(x, y, x)) * big;
    let o = torus.center() + offset(reach, reach);
    let target = torus.center() + offset(1.5, 0.5);
    (o, target - o)
}

#[test]
fn random_poses_hits_lie_on_the_surface_with_correct_normals() {
    // Rays from a box of ±4R aimed at random points near the torus. For each hit:
    // the local hit point is within 1e-9·R of the surface (relative to the f64 line), the
    // normal is unit to 1e-6 and within 1e-6 of the geometric normal, the hit is the
    // nearest root in range, and the f32 world hit is within 1e-5·R of the surface.
    let mut rng = Pcg64::seed_from_u64(0x7051_0011);
    let mut hits = 0;
    for _ in 0..5000 {
        let torus = random_torus(&mut rng);
        let (o, dir) = aimed_at_the_tube(&mut rng, &torus, 4.0);
        let dir = dir * rng.random_range(0.01..100.0);
        let Ok(ray) = Ray::new(o, dir) else { continue };
        let (lo, ld) = torus.line_to_local_f64(&ray);
        let (major, minor) = (
            f64::from(torus.major_radius()),
            f64::from(torus.minor_radius()),
        );
        let all = line_roots_local(major, minor, lo, ld);
        for &t in all.as_slice() {
            let dist = surface_distance(major, minor, lo + t * ld);
            assert!(
                dist < 1e-9 * major,
                "root off the surface by {dist}: {all:?}"
            );
        }
        let Some(hit) = intersect(&torus, &ray) else {
            assert!(all.as_slice().iter().all(|&t| t < 0.0), "missed {all:?}");
            continue;
        };
        hits += 1;
        let first = all.as_slice().iter().copied().find(|&t| t >= 0.0).unwrap();
        assert!((f64::from(hit.t) - first).abs() <= 1e-6 * first.abs().max(1e-30));
        let (t_loc, n_loc) = intersect_local(major, minor, lo, ld, 0.0, f64::INFINITY).unwrap();
        let x = lo + t_loc * ld;
        let geo = geometric_normal(major, x);
        assert!((n_loc.length() - 1.0).abs() < 1e-12);
        assert!((n_loc - geo).length() < 1e-6, "{n_loc} vs {geo}");
        assert!((hit.normal.length() - 1.0).abs() < 1e-6, "{hit:?}");
        let n_world = torus.dir_to_world(geo.as_vec3());
        assert!(
            (hit.normal - n_world).length() < 1e-5,
            "{hit:?} vs {n_world}"
        );
        let p_world = ray.at(hit.t);
        let p_loc = torus.point_to_local(p_world).as_dvec3();
        let dist = surface_distance(major, minor, p_loc);
        let tol = 1e-5 * (major + (o - torus.center()).length() as f64);
        assert!(
            dist < tol,
            "world hit off the surface by {dist} (tol {tol})"
        );
    }
    assert!(hits > 1000, "only {hits} hits");
}

#[test]
fn roots_scale_with_the_torus() {
    // The same configuration at scale k: every root t scales by k (rel. 1e-6; the f32
    // world data round differently at each scale) and normals are unchanged.
    let base = Torus::new(
        Vec3::new(0.3, -0.2, 0.1),
        Vec3::new(0.2, 1.0, -0.4),
        2.0,
        0.7,
    )
    .unwrap();
    let o = Vec3::new(-6.0, 1.3, 0.4);
    let dir = Vec3::new(1.0, -0.25, 0.05);
    let ray = Ray::new(o, dir).unwrap();
    let h1 = intersect(&base, &ray).unwrap();
    let (lo, ld) = base.line_to_local_f64(&ray);
    let r1 = line_roots_local(2.0, 0.7, lo, ld);
    assert_eq!(r1.len(), 4, "{r1:?}");
    for k in [1e-3f32, 0.5e-3 * 3.0, 1.0, 37.0, 1e3] {
        let torus = Torus::new(base.center() * k, base.axis(), 2.0 * k, 0.7 * k).unwrap();
        let ray = Ray::new(o * k, dir).unwrap();
        let h = intersect(&torus, &ray).unwrap();
        assert!(
            ((h.t / k - h1.t) / h1.t).abs() < 1e-5,
            "k = {k}: {h:?} vs {h1:?}"
        );
        assert!((h.normal - h1.normal).length() < 1e-5, "k = {k}");
        // In f64 from the exact scaled line, all four roots scale to 1e-12.
        let kd = f64::from(k);
        let rk = line_roots_local(2.0 * kd, 0.7 * kd, lo * kd, ld);
        assert_eq!(rk.len(), 4);
        for (a, b) in rk.as_slice().iter().zip(r1.as_slice()) {
            assert!(
                (a / kd - b).abs() < 1e-12 * b.abs(),
                "k = {k}: {rk:?} vs {r1:?}"
            );
        }
    }
}

#[test]
fn far_origin_finds_the_same_hit() {
    // Move the origin back by 100·R (and 1000·R) along the ray: the hit is found and
    // t_far − shift agrees with the near t to relative 1e-5.
    let mut rng = Pcg64::seed_from_u64(0x7051_0012);
    let mut checked = 0;
    for _ in 0..3000 {
        let torus = random_torus(&mut rng);
        let big = torus.major_radius();
        let (o, dir) = aimed_at_the_tube(&mut rng, &torus, 3.0);
        let dir = dir.normalize();
        let Ok(near) = Ray::new(o, dir) else { continue };
        let Some(hn) = intersect(&torus, &near) else {
            continue;
        };
        // Only origins with the whole torus in front (no root behind), so that moving the
        // origin back along the line cannot add an earlier hit.
        let (lo, ld) = torus.line_to_local_f64(&near);
        let all = line_roots_local(f64::from(big), f64::from(torus.minor_radius()), lo, ld);
        if all.as_slice().iter().any(|&t| t < 0.0) {
            continue;
        }
        // Skip grazing hits, whose position is ill-conditioned in f32 itself.
        let (_, n) = intersect_local(
            f64::from(big),
            f64::from(torus.minor_radius()),
            lo,
            ld,
            0.0,
            f64::INFINITY,
        )
        .unwrap();
        let cos = n.dot(ld.normalize()).abs();
        if cos < 0.1 {
            continue;
        }
        for back in [100.0f32, 1000.0] {
            let shift = back * big;
            let far = Ray::new(o - dir * shift, dir).unwrap();
            let hf = intersect(&torus, &far).expect("far ray must still hit");
            let t_far = f64::from(hf.t);
            let expect = f64::from(hn.t) + f64::from(shift);
            assert!(
                ((t_far - expect) / expect).abs() < 1e-5,
                "back {back}: {t_far} vs {expect}"
            );
            // The far f32 origin is rounded by ~6e-8·back·R; on a tube of radius r = R/ν
            // hit at incidence cos, the normal moves by about that / (r·cos).
            let n_tol = 2e-6 * f64::from(back) * f64::from(torus.nu()) / cos;
            let dn = f64::from((hf.normal - hn.normal).length());
            assert!(dn < n_tol, "back {back}: normal moved {dn} (tol {n_tol})");
        }
        checked += 1;
    }
    assert!(checked > 500, "only {checked}");
}

#[test]
fn coefficients_match_the_documented_substitution() {
    // F(t) from the unscaled coefficients of docs/math.md equals R⁴·Q(u) (|d| = 1 here) at
    // u = (t|d| + o·d̂)/R, for a few t.
    let (major, minor) = (3.0, 1.25);
    let o = DVec3::new(-7.0, 0.8, 2.0);
    let d = DVec3::new(0.9, -0.1, -0.3).normalize();
    let c = quartic_coefficients_local(major, minor, o, d);
    assert_eq!((c[0], c[1]), (1.0, 0.0));
    let k = o.length_squared() + major * major - minor * minor;
    let od = o.dot(d);
    let big = [
        1.0,
        4.0 * od,
        2.0 * k + 4.0 * od * od - 4.0 * major * major * (d.x * d.x + d.z * d.z),
        4.0 * od * k - 8.0 * major * major * (o.x * d.x + o.z * d.z),
        k * k - 4.0 * major * major * (o.x * o.x + o.z * o.z),
    ];
    let ev = |c: &[f64; 5], x: f64| c.iter().fold(0.0, |a, ci| a * x + ci);
    for t in [-1.0, 0.0, 3.5, 8.0, 12.0] {
        let u = (t + od) / major;
        let lhs = ev(&big, t);
        let rhs = major.powi(4) * ev(&c, u);
        assert!(
            (lhs - rhs).abs() < 1e-9 * lhs.abs().max(1e3),
            "t = {t}: {lhs} vs {rhs}"
        );
    }
}
