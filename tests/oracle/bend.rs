//! Pipe bends (`torus_cull::bend`) against the independent bend oracle
//! (`torus_cull_lab::oracle::bend`): VecGeom's solid, Geant4 `testG4Torus`-style checks
//! (distances along the axes, `contains` on the surfaces and the φ planes, normals at the φ
//! edges, grazing sweeps across a 1 m / 10 cm torus), rays through the cut-away arc, along
//! the pipe's axis, through the hollow core, grazing the caps' edges and tangent to the
//! bore, the Δφ × r_min/r_max × ν × scale grid, random rays per (Δφ, r_min) class with the
//! culls and the wedge, rays spawned from every face, and the point queries against the
//! oracle's signed function (exact inside, a lower bound outside).

use crate::common::bend::{Spec, TOL, Tally, compare, face, from_surface_reference, rng, unit};
use glam::DVec3;
use rand::RngExt;
use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI, TAU};
use torus_cull::bend::BendFace;
use torus_cull::{CullKind, DRay, NoCull};
use torus_cull_lab::oracle::OracleClass;
use torus_cull_lab::oracle::bend::{BendQuery, Passage};

const DELTAS: [f64; 4] = [TAU, PI, FRAC_PI_2, PI / 6.0];
const RATIOS: [f64; 3] = [0.0, 0.5, 0.9];
const NUS: [f64; 3] = [1.25, 4.0, 16.0];
const SCALES: [f64; 3] = [1e-3, 1.0, 1e3];

fn vecgeom() -> Spec {
    Spec::canonical(30.0, 5.0, 10.0, FRAC_PI_4, 3.0 * FRAC_PI_4)
}

/// Compares every ray, prints the first few disagreements, and returns the tally.
fn run(spec: &Spec, rays: impl IntoIterator<Item = DRay>) -> Tally {
    let bend = spec.bend().unwrap();
    let mut total = Tally::default();
    let mut shown = 0;
    for ray in rays {
        let (t, why) = compare(spec, &bend, &ray);
        total.add(&t);
        if let Some(why) = why
            && shown < 3
        {
            eprintln!("DISAGREEMENT\n{why}\n");
            shown += 1;
        }
    }
    total
}

fn assert_clean(what: &str, t: &Tally) {
    assert_eq!(t.bad(), 0, "{what}: {t:?}");
}

fn oracle_f(spec: &Spec, p: DVec3) -> f64 {
    spec.query(&DRay::new(p, DVec3::X).unwrap()).f(0.0)
}

#[test]
fn vecgeom_solid_distances_along_the_axes() {
    let spec = vecgeom();
    let bend = spec.bend().unwrap();
    let dirs = [
        DVec3::X,
        DVec3::NEG_X,
        DVec3::Y,
        DVec3::NEG_Y,
        DVec3::Z,
        DVec3::NEG_Z,
    ];
    let mut rays = Vec::new();
    for d in dirs {
        // Lines along the axis d on a grid of offsets, from 100 out.
        let (u, v) = d.any_orthonormal_pair();
        for i in -9..=9 {
            for j in -9..=9 {
                let off = u * (5.0 * i as f64) + v * (5.0 * j as f64);
                rays.push(DRay::new(off - d * 100.0, d).unwrap());
            }
        }
        // From inside the material at φ = π/2, 7.5 from the core, and from the bore.
        rays.push(DRay::new(DVec3::new(0.0, 0.0, -37.5), d).unwrap());
        rays.push(DRay::new(DVec3::new(0.0, 1.0, -30.0), d).unwrap());
    }
    let t = run(&spec, rays);
    assert_clean("VecGeom axes", &t);
    assert!(t.hits > 100 && t.misses > 100, "{t:?}");
    // By hand, from (0, 0, −37.5): out through the outer face at z = −40 and the bore at
    // z = −35, 2.5 away; along ±y out at √(10² − 7.5²).
    let inside = DVec3::new(0.0, 0.0, -37.5);
    let want = [
        (DVec3::NEG_Z, 2.5, BendFace::Outer),
        (DVec3::Z, 2.5, BendFace::Inner),
        (DVec3::Y, 43.75f64.sqrt(), BendFace::Outer),
        (DVec3::NEG_Y, 43.75f64.sqrt(), BendFace::Outer),
    ];
    for (d, dist, f) in want {
        let hit = bend.intersect(&DRay::new(inside, d).unwrap()).unwrap();
        assert!(
            (hit.t - dist).abs() < 1e-12 * 40.0 && hit.face == f,
            "{d}: {hit:?}"
        );
        assert!(!hit.front_face);
    }
    // From outside along −y at φ = π/2 over the material: 40 down to the outer face.
    let hit = bend
        .intersect(&DRay::new(DVec3::new(0.0, 50.0, -37.5), DVec3::NEG_Y).unwrap())
        .unwrap();
    assert!((hit.t - (50.0 - 43.75f64.sqrt())).abs() < 1e-12 * 40.0);
}

#[test]
fn contains_on_the_surfaces_and_the_phi_planes() {
    // φ from 0 to π/2: the caps lie in z = 0 (x > 0) and x = 0 (z < 0), exactly.
    for bore in [0.0, 5.0] {
        let spec = Spec::canonical(30.0, bore, 10.0, 0.0, FRAC_PI_2);
        let bend = spec.bend().unwrap();
        // On a face, exactly representable: inside (the boundary is the solid's). The
        // end cap's plane x = 0 is the library's only to rounding (cos(π/2) ≠ 0 in f64:
        // its plane is turned by 6e-17 rad), so its points are taken 1e-12·S inside.
        let e = 1e-12 * 40.0;
        let mut on = vec![
            DVec3::new(24.0, 0.0, -32.0), // outer equator, ρ = 40
            DVec3::new(12.0, 0.0, -16.0), // outer's inner equator, ρ = 20
            DVec3::new(e, 10.0, -30.0),   // outer top at the end cap's edge
            DVec3::new(30.0, -10.0, 0.0), // outer bottom at the start cap's edge
            DVec3::new(37.0, 3.0, 0.0),   // the start cap's annulus
            DVec3::new(e, -3.0, -37.0),   // the end cap's annulus
            DVec3::new(40.0, 0.0, 0.0),   // the start cap's outer edge
            DVec3::new(e, 0.0, -20.0),    // the end cap's inner edge (no bore)
        ];
        if bore > 0.0 {
            on.push(DVec3::new(21.0, 0.0, -28.0)); // the bore's equator, ρ = 35
            on.push(DVec3::new(15.0, 0.0, -20.0)); // ρ = 25
            on.push(DVec3::new(35.0, 0.0, 0.0)); // the start cap's inner edge
        } else {
            on.push(DVec3::new(e, 0.0, -30.0)); // the core circle on the end cap
            on.push(DVec3::new(30.0, 0.0, 0.0)); // the core circle on the start cap
        }
        for p in on {
            assert!(oracle_f(&spec, p) <= 1e-15 * 40.0, "{p}");
            assert!(bend.contains(p), "bore {bore}: {p} on a face is inside");
        }
        // Off the faces by 1e-9·S either way, and on the planes off the annulus: as the
        // oracle says.
        let mut rng = rng(0xc0);
        let mut checked = 0;
        for _ in 0..20_000 {
            let p = spec.point(
                rng.random_range(-0.3..FRAC_PI_2 + 0.3),
                rng.random_range(0.0..TAU),
                rng.random_range(0.0..12.0),
            );
            let f = oracle_f(&spec, p);
            if f.abs() > 1e-9 * 40.0 {
                assert_eq!(bend.contains(p), f < 0.0, "bore {bore}: {p} F = {f}");
                checked += 1;
            }
        }
        for p in [
            DVec3::new(37.0, 3.0, 1e-9),   // just before the start cap
            DVec3::new(-1e-9, 3.0, -37.0), // just past the end cap
            DVec3::new(41.0, 0.0, 0.0),    // the start plane beyond r_max
            DVec3::new(0.0, 0.0, -19.0),   // the end plane inside the ring's hole
            DVec3::new(-37.0, 0.0, 0.0),   // the start cap's plane, other half
        ] {
            assert!(!bend.contains(p), "{p}");
        }
        if bore > 0.0 {
            assert!(
                !bend.contains(DVec3::new(33.0, 0.0, 0.0)),
                "the bore on the cap"
            );
        }
        assert!(checked > 15_000);
    }
}

#[test]
fn normals_at_the_phi_edges() {
    let mut bad = Vec::new();
    for (bore, start, delta) in [
        (5.0, FRAC_PI_4, 3.0 * FRAC_PI_4),
        (0.0, 0.3, PI / 6.0),
        (9.0, -1.0, 1.5 * PI),
    ] {
        let spec = Spec::canonical(30.0, bore, 10.0, start, delta);
        let bend = spec.bend().unwrap();
        let (e0, e1, _) = spec.frame();
        let growing = |phi: f64| e1 * phi.cos() - e0 * phi.sin();
        for (phi, outward, cap) in [
            (start, -growing(start), BendFace::StartCap),
            (start + delta, growing(start + delta), BendFace::EndCap),
        ] {
            for psi in (0..16).map(|k| k as f64 * TAU / 16.0) {
                // Onto the cap, just inside each edge, from outside the segment.
                for d in [10.0 - 1e-6, bore + 1e-6, 0.5 * (bore + 10.0)] {
                    let p = spec.point(phi, psi, d);
                    let ray = DRay::new(p + outward * 3.0, -outward).unwrap();
                    let hit = bend.intersect(&ray);
                    let ok = hit.is_some_and(|h| {
                        h.face == cap
                            && h.front_face
                            && (h.normal - outward).length() < 1e-9
                            && (h.t - 3.0).abs() < 1e-9 * 40.0
                    });
                    if !ok {
                        bad.push(format!("{cap:?} at {p}: {hit:?}"));
                    }
                }
                // Onto the outer face next to the edge, along its normal: the outer
                // normal.
                let inside_phi = phi
                    + if cap == BendFace::StartCap {
                        1e-6
                    } else {
                        -1e-6
                    };
                let p = spec.point(inside_phi, psi, 10.0);
                let n = (p - spec.point(inside_phi, psi, 0.0)).normalize();
                let hit = bend.intersect(&DRay::new(p + n * 2.0, -n).unwrap());
                let ok = hit.is_some_and(|h| {
                    h.face == BendFace::Outer
                        && (h.normal - n).length() < 1e-9
                        && (h.t - 2.0).abs() < 1e-9 * 40.0
                });
                if !ok {
                    bad.push(format!("outer by {cap:?} at {p}: {hit:?}"));
                }
            }
        }
    }
    assert!(bad.is_empty(), "{} bad:\n{}", bad.len(), bad.join("\n"));
}

#[test]
fn grazing_sweeps_across_a_metre_torus() {
    // R = 1 m, r_max = 10 cm, in mm; h steps across each tangency, the band is 1.1e-6.
    let h = 2e-7;
    for (bore, delta) in [(0.0, TAU), (50.0, FRAC_PI_2), (90.0, PI / 6.0)] {
        let start = FRAC_PI_2 - 0.5 * delta;
        let spec = Spec::canonical(1000.0, bore, 100.0, start, delta);
        let mut rays = Vec::new();
        for k in -40..=40 {
            let e = k as f64 * h;
            // Over the top at φ = π/2 (z = −1000), along x.
            rays.push(DRay::new(DVec3::new(-3000.0, 100.0 + e, -1000.0), DVec3::X).unwrap());
            // Down past the outer equator and the hole's rim.
            rays.push(DRay::new(DVec3::new(0.0, 500.0, -1100.0 - e), DVec3::NEG_Y).unwrap());
            rays.push(DRay::new(DVec3::new(0.0, 500.0, -900.0 + e), DVec3::NEG_Y).unwrap());
            if bore > 0.0 {
                // Tangent to the bore's top from inside it, along the pipe.
                rays.push(DRay::new(DVec3::new(-50.0, bore + e, -1000.0), DVec3::X).unwrap());
            }
            // Across the start cap's outer edge along the axis direction.
            let s = DVec3::new(start.cos(), 0.0, -start.sin());
            let g = DVec3::new(-start.sin(), 0.0, -start.cos());
            rays.push(DRay::new(s * (1100.0 + e) + g * 1e-3 - DVec3::Y * 500.0, DVec3::Y).unwrap());
            rays.push(DRay::new(s * 1099.0 + g * e - DVec3::Y * 500.0, DVec3::Y).unwrap());
        }
        let t = run(&spec, rays);
        assert_clean("grazing sweep", &t);
        assert!(t.ambiguous > 0 && t.hits > 0 && t.misses > 0, "{t:?}");
    }
}

#[test]
fn the_cut_away_arc_the_pipes_axis_the_hollow_core_and_the_caps_edges() {
    // The ray kinds of `torus-cull bend` (`check::shapes::bend::rays`), at the test's size.
    let mut rng = rng(0xa1c);
    let mut total = Tally::default();
    for delta in [PI, FRAC_PI_2, PI / 6.0] {
        for ratio in RATIOS {
            let spec = Spec::canonical(4.0, ratio, 1.0, 0.2, delta).posed(&mut rng);
            let mut rays = Vec::new();
            let bend = spec.bend().unwrap();
            for _ in 0..200 {
                // Through the cut-away arc, along the axis through the tube: a miss.
                let ray = spec.cut_away_axial(&mut rng);
                assert!(bend.intersect(&ray).is_none(), "cut-away {ray:?}");
                assert_eq!(spec.query(&ray).classify().class, OracleClass::Miss);
                rays.push(ray);
                rays.push(spec.cut_away_any(&mut rng));
                // Along the pipe's axis at mid-segment, through both caps' planes, in the
                // material or the bore; through the hole.
                rays.push(spec.pipe_axis(&mut rng));
                rays.push(spec.pipe_axis(&mut rng));
                rays.push(spec.hole(&mut rng));
                // Grazing the caps' edges (outer and bore circles) by ±1e-7..1e-3.
                for _ in 0..4 {
                    rays.push(spec.cap_edge(&mut rng));
                }
                // Tangent to the bore (offset by ±1e-8..1e-4).
                if ratio > 0.0 {
                    rays.push(spec.bore_tangent(&mut rng));
                }
            }
            total.add(&run(&spec, rays));
        }
    }
    assert_clean("structured", &total);
    eprintln!("structured: {total:?}");
}

#[test]
fn the_delta_phi_ratio_nu_scale_grid() {
    let mut rng = rng(0x9e1d);
    let mut total = Tally::default();
    for delta in DELTAS {
        for ratio in RATIOS {
            for nu in NUS {
                for scale in SCALES {
                    let spec = Spec::canonical(nu * scale, ratio * scale, scale, 0.0, delta)
                        .posed(&mut rng);
                    let rays: Vec<DRay> = (0..150).map(|_| spec.random_ray(&mut rng)).collect();
                    let t = run(&spec, rays);
                    assert_clean(
                        &format!("Δφ {delta} ratio {ratio} ν {nu} scale {scale}"),
                        &t,
                    );
                    total.add(&t);
                }
            }
        }
    }
    eprintln!("grid: {total:?}");
}

/// Random rays of one (Δφ, r_min/r_max) class: `n` rays over ν, scales and poses.
/// Returns the tally, (cut-away misses: rays that hit the whole outer torus but miss its
/// segment; of them rejected by the wedge alone), and the culls' false rejects.
fn random_class(delta: f64, ratio: f64, n: usize, seed: u64) -> (Tally, (u64, u64), u64) {
    let mut rng = rng(seed);
    let mut total = Tally::default();
    let (mut cut_away, mut captured, mut false_rejects) = (0, 0, 0);
    let per_pose = 500;
    for k in 0..n.div_ceil(per_pose) {
        let (nu, scale) = (NUS[k % 3], SCALES[(k / 3) % 3]);
        let spec = Spec::canonical(nu * scale, ratio * scale, scale, 0.0, delta).posed(&mut rng);
        let bend = spec.bend().unwrap();
        let whole = Spec {
            bore: 0.0,
            delta: TAU,
            ..spec
        };
        let segment = Spec { bore: 0.0, ..spec };
        let count = per_pose.min(n - k * per_pose);
        let rays: Vec<DRay> = (0..count).map(|_| spec.random_ray(&mut rng)).collect();
        for ray in &rays {
            let label = spec.query(ray).classify();
            if label.class == OracleClass::Hit {
                for kind in CullKind::TIMED {
                    let kept =
                        bend.kept_by(&kind, ray) && bend.kept_by(&bend.wedge_cull(kind), ray);
                    if !kept {
                        false_rejects += 1;
                        eprintln!("FALSE REJECT {kind}: {spec:?} {ray:?}");
                    }
                }
            } else if label.class == OracleClass::Miss
                && whole.query(ray).classify().class == OracleClass::Hit
                && segment.query(ray).classify().class == OracleClass::Miss
            {
                // Through the cut-away arc: the whole torus is hit, its segment is not.
                cut_away += 1;
                captured += u64::from(!bend.kept_by(&bend.wedge_cull(NoCull), ray));
            }
        }
        total.add(&run(&spec, rays));
    }
    (total, (cut_away, captured), false_rejects)
}

fn random_classes(n: usize) {
    let mut bad = Vec::new();
    for (i, delta) in DELTAS.into_iter().enumerate() {
        let (mut cut, mut cap) = (0, 0);
        for (j, ratio) in RATIOS.into_iter().enumerate() {
            let (t, (c, k), fr) = random_class(delta, ratio, n, 0xbe0 + (i * 3 + j) as u64);
            eprintln!("Δφ = {delta:.4}, r_min/r_max = {ratio}: {t:?}, false rejects {fr}");
            if t.bad() > 0 || fr > 0 {
                bad.push((delta, ratio, t, fr));
            }
            cut += c;
            cap += k;
        }
        let rate = cap as f64 / cut.max(1) as f64;
        eprintln!(
            "Δφ = {delta:.4}: wedge alone rejects {cap} of {cut} cut-away misses ({rate:.3})"
        );
        if delta <= PI {
            assert!(cut > 0 && rate > 0.25, "Δφ {delta}: capture {cap}/{cut}");
        }
    }
    assert!(bad.is_empty(), "{bad:?}");
}

#[test]
fn random_rays_per_class_and_every_cull() {
    random_classes(2_000);
}

/// The 10⁵ rays per (Δφ, r_min) class: `cargo test --release --test oracle
/// bend -- --ignored`.
#[test]
#[ignore = "the issue's full count; about 2 minutes in release on one core"]
fn random_rays_per_class_full() {
    random_classes(100_000);
}

/// Compares the library's answer for a ray spawned from a face point with the oracle's
/// on-surface rule; returns (compared, ambiguous, bad).
fn spawned(spec: &Spec, ray: &DRay) -> (usize, usize, Option<String>) {
    let bend = spec.bend().unwrap();
    let tol = TOL * spec.size();
    let got = bend.intersect(ray);
    let Some(want) = from_surface_reference(spec, ray) else {
        return (0, 1, None);
    };
    let ok = match (want, got) {
        (None, None) => true,
        (Some((t, p, f)), Some(h)) => {
            let q: BendQuery = spec.query(ray).on_surface().unwrap().0;
            let point = q.origin + q.dir * t;
            (h.t - t).abs() * ray.dir().length() <= tol
                && (face(h.face) == f || q.faces_at(point, tol).contains(&face(h.face)))
                && h.front_face == (p == Passage::Entering)
        }
        _ => false,
    };
    let why = (!ok).then(|| format!("{spec:?}\n{ray:?}\nlibrary {got:?}, oracle {want:?}"));
    (1, 0, why)
}

#[test]
fn rays_spawned_from_every_face() {
    let mut rng = rng(0x5a);
    let (mut compared, mut ambiguous) = (0, 0);
    let mut per_face = [0usize; 4];
    let mut bad = Vec::new();
    for delta in DELTAS {
        for ratio in RATIOS {
            for nu in NUS {
                let spec = Spec::canonical(nu, ratio, 1.0, 0.0, delta).posed(&mut rng);
                let bend = spec.bend().unwrap();
                // From a random crossing of a random ray, or from a cap's point (its edges
                // included): `check::shapes::bend::rays`' spawned rays, counted by the oracle's faces
                // at the origin.
                let mut rays = Vec::new();
                for _ in 0..270 {
                    let Some(ray) = spec.spawned(&bend, &mut rng) else {
                        continue;
                    };
                    if let Some((_, faces)) = spec.query(&ray).on_surface() {
                        for f in faces {
                            per_face[f as usize] += 1;
                        }
                    }
                    rays.push(ray);
                }
                for ray in rays {
                    let (c, a, why) = spawned(&spec, &ray);
                    compared += c;
                    ambiguous += a;
                    if let Some(why) = why {
                        bad.push(why);
                    }
                }
            }
        }
    }
    eprintln!(
        "spawned: {compared} compared, {ambiguous} ambiguous, {} bad; crossings per face {per_face:?}",
        bad.len()
    );
    for b in bad.iter().take(5) {
        eprintln!("SPAWN DISAGREEMENT\n{b}\n");
    }
    assert!(bad.is_empty(), "{} spawned rays disagree", bad.len());
    assert!(per_face.iter().all(|&n| n > 50), "{per_face:?}");
}

/// The world point at angle φ about the axis, distance `rho` from it and height `y`.
fn bend_point(spec: &Spec, phi: f64, rho: f64, y: f64) -> DVec3 {
    let a = spec.axis.normalize();
    let e0 = spec.phi_zero.reject_from(a).normalize();
    let e1 = a.cross(e0);
    spec.center + (e0 * phi.cos() + e1 * phi.sin()) * rho + a * y
}

#[test]
fn point_queries_against_the_oracle_signed_function() {
    // The oracle's F = max(f_rad, f_w) is the exact signed distance inside the solid (the
    // distance to the complement of an intersection is the least of the distances to the
    // complements) and a lower bound outside it. So inside, the library's signed distance
    // equals F; outside it is at least F; off the band their signs agree (10⁶ points).
    let mut rng = rng(4107);
    let eps = f64::EPSILON / 2.0;
    let (mut n, mut inside, mut worst_inside) = (0usize, 0usize, 0.0f64);
    let specs: Vec<Spec> = [
        (30.0, 5.0, 10.0, FRAC_PI_4, 3.0 * FRAC_PI_4),
        (4.0, 0.0, 1.0, 0.3, PI / 6.0),
        (4.0, 2.0, 3.0, -1.0, 5.0),
        (4.0, 0.5, 1.0, 0.0, TAU),
        (1.25, 0.0, 1.0, 2.0, PI),
    ]
    .into_iter()
    .flat_map(|(big, r0, r1, s, d)| SCALES.map(|k| Spec::canonical(big * k, r0 * k, r1 * k, s, d)))
    .collect();
    let per = 1_000_000 / (2 * specs.len()) + 1;
    for spec0 in specs {
        for spec in [spec0, spec0.posed(&mut rng)] {
            let bend = spec.bend().unwrap();
            let size = spec.size();
            let band = 1e-9 * size;
            for i in 0..per {
                let p = match i % 4 {
                    // About the tube, in and out of the segment.
                    0 | 1 => {
                        let (phi, th) = (rng.random_range(0.0..TAU), rng.random_range(0.0..TAU));
                        let r = spec.tube * rng.random_range(0.0..1.3f64);
                        bend_point(
                            &spec,
                            spec.start + phi,
                            spec.major + r * th.cos(),
                            r * th.sin(),
                        )
                    }
                    // Near the axis and the core circle.
                    2 => {
                        let phi = spec.start + rng.random_range(0.0..TAU);
                        let rho = if i % 8 == 2 { 0.0 } else { spec.major };
                        bend_point(&spec, phi, rho, spec.tube * rng.random_range(-2.0..2.0))
                    }
                    // The bounding box and far away.
                    _ => spec.center + unit(&mut rng) * size * rng.random_range(0.0..30.0),
                };
                let f = oracle_f(&spec, p);
                let sd = bend.signed_distance(p).unwrap();
                let tol = 32.0 * eps * ((p - spec.center).length() + size);
                if f < -band {
                    assert!(sd < 0.0 && bend.contains(p), "{spec:?} {p}: sd {sd}, F {f}");
                    assert!((sd - f).abs() <= tol, "{spec:?} {p}: sd {sd}, F {f}");
                    worst_inside = worst_inside.max((sd - f).abs() / tol * 32.0);
                    inside += 1;
                } else if f > band {
                    assert!(
                        sd > 0.0 && !bend.contains(p),
                        "{spec:?} {p}: sd {sd}, F {f}"
                    );
                    assert!(sd >= f - tol, "{spec:?} {p}: sd {sd} below F {f}");
                }
                n += 1;
            }
        }
    }
    println!(
        "bend point queries vs the oracle: {n} points, {inside} inside (sd = F within {worst_inside:.1}ε·scale), 0 wrong signs"
    );
    assert!(inside > 100_000);
}
