//! Pipe bends: hand-derived cases (the axes, the caps, the bore, VecGeom's solid), the
//! whole torus bit for bit, rays spawned from every face, and the wedge cull. The
//! oracle's random and adversarial rays are the lab's.

use super::{BendError, BendFace, PipeBend};
use crate::cull::NoCull;
use crate::geometry::draw::{dvec3_in, vec3_in};
use crate::{CullKind, DRay, Passage, Ray, Torus, intersect, intersect_all};
use glam::{DVec3, Vec3};
use rand::SeedableRng;
use rand_pcg::Pcg64;
use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI, TAU};

fn vecgeom() -> PipeBend {
    PipeBend::canonical(30.0, 5.0, 10.0, FRAC_PI_4, 3.0 * FRAC_PI_4).unwrap()
}

fn crossings(bend: &PipeBend, ray: &DRay) -> Vec<(f64, Passage, BendFace)> {
    let all = bend.intersect_all(ray);
    all.iter().map(|c| (c.t, c.passage, c.face)).collect()
}

fn close(got: &[(f64, Passage, BendFace)], want: &[(f64, Passage, BendFace)]) -> bool {
    got.len() == want.len()
        && got
            .iter()
            .zip(want)
            .all(|(g, w)| (g.0 - w.0).abs() < 1e-9 && g.1 == w.1 && g.2 == w.2)
}

#[test]
fn the_whole_torus_answers_as_its_torus_bit_for_bit() {
    let mut rng = Pcg64::seed_from_u64(39);
    let torus = Torus::canonical(4.0, 1.0).unwrap();
    let bend = PipeBend::canonical(4.0, 0.0, 1.0, 0.0, TAU).unwrap();
    for _ in 0..20_000 {
        let o = vec3_in(&mut rng, Vec3::splat(12.0));
        let aim = vec3_in(&mut rng, Vec3::new(5.0, 1.0, 5.0));
        let ray = Ray::new(o, aim - o).unwrap();
        let want = intersect(&torus, &ray);
        let got = bend.intersect(&ray);
        assert_eq!(
            got.map(|h| (h.t, h.normal, h.point, h.front_face)),
            want.map(|h| (h.t, h.normal, h.point, h.front_face))
        );
        let all = intersect_all(&torus, &ray);
        let mine = bend.intersect_all(&ray);
        let ts: Vec<(f32, Vec3, Passage)> =
            mine.iter().map(|c| (c.t, c.normal, c.passage)).collect();
        let theirs: Vec<(f32, Vec3, Passage)> = all
            .as_slice()
            .iter()
            .map(|c| (c.t, c.normal, c.passage))
            .collect();
        assert_eq!(ts, theirs);
        assert_eq!(mine.starts_inside(), all.starts_inside());
    }
}

#[test]
fn vecgeom_solid_along_the_axes_and_through_the_caps() {
    let bend = vecgeom();
    use BendFace::*;
    use Passage::*;
    // φ grows from +x toward −z. Down through the bend at φ = π/2: the outer top, the
    // bore (twice), the outer bottom.
    let down = DRay::new(DVec3::new(0.0, 50.0, -30.0), DVec3::NEG_Y).unwrap();
    let want = [
        (40.0, Enter, Outer),
        (45.0, Exit, Inner),
        (55.0, Enter, Inner),
        (60.0, Exit, Outer),
    ];
    let got = crossings(&bend, &down);
    assert!(close(&got, &want), "{got:?}");
    let all = bend.intersect_all(&down);
    let n: Vec<DVec3> = all.iter().map(|c| c.normal).collect();
    for (got, want) in n
        .iter()
        .zip([DVec3::Y, DVec3::NEG_Y, DVec3::Y, DVec3::NEG_Y])
    {
        assert!((*got - want).length() < 1e-12, "{n:?}");
    }
    // The same at φ = 0 and φ = 3π/2: the cut-away arc, nothing.
    for at in [DVec3::new(30.0, 50.0, 0.0), DVec3::new(0.0, 50.0, 30.0)] {
        assert!(crossings(&bend, &DRay::new(at, DVec3::NEG_Y).unwrap()).is_empty());
    }
    // Along x at z = −33 (φ from 0 to π, in the segment where x ≤ 33): the tube's
    // material at ρ = 35 … 40 on both sides of the axis, the bore (D < 5) between.
    let across = DRay::new(DVec3::new(-50.0, 0.0, -33.0), DVec3::X).unwrap();
    let (a, b) = (
        (35.0f64 * 35.0 - 33.0 * 33.0).sqrt(),
        (40.0f64 * 40.0 - 33.0 * 33.0).sqrt(),
    );
    let want = [
        (50.0 - b, Enter, Outer),
        (50.0 - a, Exit, Inner),
        (50.0 + a, Enter, Inner),
        (50.0 + b, Exit, Outer),
    ];
    let got = crossings(&bend, &across);
    assert!(close(&got, &want), "{got:?}");
    // From inside the tube near the end cap (φ = π is the half-plane x < 0, z = 0): out
    // through the end cap, outward normal +z.
    let out = DRay::new(DVec3::new(-37.0, 0.0, -5.0), DVec3::Z).unwrap();
    let hit = bend.intersect(&out).unwrap();
    assert_eq!((hit.face, hit.front_face), (EndCap, false));
    assert!((hit.t - 5.0).abs() < 1e-12 && (hit.normal - DVec3::Z).length() < 1e-12);
    assert!(bend.intersect_all(&out).starts_inside());
    // Into the start cap (φ = π/4) through its annulus, on through the tube: a chord of
    // the tube straight on, leaving by the outer torus.
    let s = DVec3::new(1.0, 0.0, -1.0).normalize();
    let t = DVec3::new(-1.0, 0.0, -1.0).normalize();
    let into = DRay::new(s * 37.0 - t * 5.0, t).unwrap();
    let got = crossings(&bend, &into);
    assert_eq!((got[0].1, got[0].2), (Enter, StartCap), "{got:?}");
    assert!((got[0].0 - 5.0).abs() < 1e-12);
    // ρ = √(37² + u²) reaches 40 at u = √(40² − 37²).
    let exit = 5.0 + (40.0f64 * 40.0 - 37.0 * 37.0).sqrt();
    assert!(
        (got[1].0 - exit).abs() < 1e-9 && got[1].1 == Exit && got[1].2 == Outer,
        "{got:?}"
    );
    // Into the bore's annulus hole on the cap (D < r_min): the cap is not there, the
    // line enters by the bore's torus.
    let bore = DRay::new(s * 31.0 - t * 5.0, t).unwrap();
    let got = crossings(&bend, &bore);
    assert!(got.iter().all(|c| c.2 != StartCap), "{got:?}");
}

#[test]
fn rays_spawned_from_every_face_never_hit_their_origin() {
    let mut rng = Pcg64::seed_from_u64(3901);
    for (rmin, dphi) in [
        (5.0, 3.0 * FRAC_PI_4),
        (0.0, FRAC_PI_2),
        (9.0, PI),
        (5.0, 1.9 * PI),
    ] {
        let bend = PipeBend::canonical(30.0, rmin, 10.0, FRAC_PI_4, dphi).unwrap();
        let mut faces = [0usize; 4];
        for _ in 0..4000 {
            let o = dvec3_in(&mut rng, DVec3::new(60.0, 30.0, 60.0));
            let aim = dvec3_in(&mut rng, DVec3::new(40.0, 10.0, 40.0));
            let ray = Ray::new(o.as_vec3(), (aim - o).as_vec3()).unwrap();
            let Some(hit) = bend.intersect(&ray) else {
                continue;
            };
            faces[hit.face as usize] += 1;
            for dir in [ray.dir(), -ray.dir(), hit.normal, -hit.normal] {
                let spawned = bend.spawn(&ray, hit.t, dir).unwrap();
                if let Some(next) = bend.intersect(&spawned) {
                    assert!(
                        next.t * dir.length() > 1e-3,
                        "Δφ {dphi}, r_min {rmin}: {ray:?} {hit:?} -> {spawned:?} {next:?}"
                    );
                }
            }
            // Straight on from an entry: the solid's exit comes next.
            if hit.front_face {
                let on = bend.spawn(&ray, hit.t, ray.dir()).unwrap();
                let all = bend.intersect_all(&on);
                assert!(all.starts_inside(), "{ray:?} {hit:?}");
                let first = all.crossings()[0];
                assert_eq!(first.passage, Passage::Exit, "{ray:?} {hit:?}");
            }
        }
        assert!(faces.iter().filter(|&&n| n > 0).count() >= 2, "{faces:?}");
    }
}

#[test]
fn the_wedge_cull_keeps_every_hit_and_rejects_the_cut_away_arc() {
    let mut rng = Pcg64::seed_from_u64(3902);
    for dphi in [PI / 6.0, FRAC_PI_2, PI, 1.5 * PI, TAU] {
        let bend = PipeBend::canonical(4.0, 0.5, 1.0, 0.3, dphi).unwrap();
        let (mut misses, mut rejected) = (0, 0);
        for _ in 0..20_000 {
            let o = dvec3_in(&mut rng, DVec3::splat(15.0));
            let aim = dvec3_in(&mut rng, DVec3::new(5.0, 1.0, 5.0));
            let ray = Ray::new(o.as_vec3(), (aim - o).as_vec3()).unwrap();
            let hit = bend.intersect(&ray).is_some();
            for kind in CullKind::TIMED {
                let keeps = bend.kept_by(&bend.wedge_cull(kind), &ray);
                assert!(keeps || !hit, "Δφ {dphi} {kind}: {ray:?}");
            }
            let torus_hit = intersect(bend.outer(), &ray).is_some();
            if torus_hit && !hit {
                misses += 1;
                rejected += usize::from(!bend.kept_by(&bend.wedge_cull(NoCull), &ray));
            }
        }
        if dphi <= PI {
            assert!(rejected * 4 > misses, "Δφ {dphi}: {rejected} of {misses}");
        }
    }
}

#[test]
fn bad_bends_are_refused_by_name() {
    let err = |r: Result<PipeBend, BendError>| r.unwrap_err().to_string();
    assert!(err(PipeBend::canonical(30.0, 10.0, 10.0, 0.0, 1.0)).contains("bore_radius"));
    assert!(err(PipeBend::canonical(30.0, -1.0, 10.0, 0.0, 1.0)).contains("bore_radius"));
    assert!(err(PipeBend::canonical(30.0, 5.0, 10.0, 0.0, 0.0)).contains("delta_phi"));
    assert!(err(PipeBend::canonical(30.0, 5.0, 10.0, 0.0, 7.0)).contains("delta_phi"));
    assert!(err(PipeBend::canonical(30.0, 5.0, 10.0, f64::NAN, 1.0)).contains("start_phi"));
    assert!(err(PipeBend::canonical(30.0, 5.0, 40.0, 0.0, 1.0)).contains("outer"));
    let axis = PipeBend::new_f64(DVec3::ZERO, DVec3::Y, DVec3::Y, 30.0, 5.0, 10.0, 0.0, 1.0);
    assert!(err(axis).contains("phi_zero"));
    assert!(matches!(vecgeom().as_torus(), Err(BendError::NotWhole)));
}

#[test]
fn rays_from_the_caps_edges_never_hit_their_origin() {
    let mut rng = Pcg64::seed_from_u64(3903);
    let bend = vecgeom();
    // φ₀ = π/4 and φ₁ = π: the caps' directions (φ grows toward −z).
    let caps = [
        DVec3::new(1.0, 0.0, -1.0).normalize(),
        DVec3::new(-1.0, 0.0, 0.0),
    ];
    let mut hits = 0;
    for cap in caps {
        for r in [5.0, 10.0] {
            for k in 0..64 {
                let theta = TAU * k as f64 / 64.0;
                let at = cap * (30.0 + r * theta.cos()) + DVec3::Y * r * theta.sin();
                for _ in 0..16 {
                    let dir = dvec3_in(&mut rng, DVec3::splat(1.0));
                    let ray = DRay::from_surface(at, dir).unwrap();
                    if let Some(next) = bend.intersect(&ray) {
                        hits += 1;
                        assert!(next.t > 1e-6, "edge r = {r}, θ = {theta}: {ray:?} {next:?}");
                    }
                }
            }
        }
    }
    assert!(hits > 100, "{hits}");
}

/// Regression (found by the lab's bend oracle): with no bore, the interval test left the
/// core circle itself out of the solid (`D² > 0`), so a ray whose two outer crossings
/// have their midpoint exactly on the core circle (down through it, or radially across
/// it) was answered as a miss.
#[test]
fn a_ray_through_the_core_circle_of_a_solid_bend_hits() {
    let bend = PipeBend::canonical(30.0, 0.0, 10.0, FRAC_PI_4, 3.0 * FRAC_PI_4).unwrap();
    let rays = [
        (
            DRay::new(DVec3::new(0.0, 50.0, -30.0), DVec3::NEG_Y).unwrap(),
            40.0,
            60.0,
        ),
        (
            DRay::new(DVec3::new(-50.0, 0.0, -30.0), DVec3::X).unwrap(),
            50.0 - 700f64.sqrt(),
            50.0 + 700f64.sqrt(),
        ),
    ];
    for (ray, enter, exit) in rays {
        let hit = bend
            .intersect(&ray)
            .unwrap_or_else(|| panic!("{ray:?} missed"));
        assert!(hit.front_face && hit.face == BendFace::Outer);
        assert!((hit.t - enter).abs() < 1e-12 * 40.0, "{hit:?}");
        let all = crossings(&bend, &ray);
        assert_eq!(all.len(), 2, "{all:?}");
        assert!((all[1].0 - exit).abs() < 1e-12 * 40.0 && all[1].1 == Passage::Exit);
        assert!(bend.occluded(&ray));
    }
    // The core circle itself is inside.
    assert!(bend.contains(DVec3::new(0.0, 0.0, -30.0)));
}
