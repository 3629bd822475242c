//! The bend oracle on hand-derived lines (VecGeom's solid, the caps, the bore, the cut-away
//! arc), against its second method (sampling) and the family oracle on random lines, and
//! its on-surface rule.

use super::*;
use crate::oracle::OracleClass;
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64;
use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI};

const INF: f64 = f64::INFINITY;

fn vecgeom(o: DVec3, d: DVec3) -> BendQuery {
    BendQuery::canonical((30.0, 5.0, 10.0), (FRAC_PI_4, 3.0 * FRAC_PI_4), o, d).over(0.0, INF)
}

fn close(got: &[(f64, Passage, Face)], want: &[(f64, Passage, Face)]) {
    assert_eq!(got.len(), want.len(), "{got:?} vs {want:?}");
    for (g, w) in got.iter().zip(want) {
        assert!((g.0 - w.0).abs() < 1e-12 * 40.0, "{got:?} vs {want:?}");
        assert_eq!((g.1, g.2), (w.1, w.2), "{got:?} vs {want:?}");
    }
}

#[test]
fn vecgeom_solid_by_hand() {
    use Face::*;
    use Passage::*;
    // Down through φ = π/2 (x = 0, z = −30): outer top, bore twice, outer bottom.
    let q = vecgeom(DVec3::new(0.0, 50.0, -30.0), DVec3::NEG_Y);
    close(
        &q.crossings(),
        &[
            (40.0, Entering, Outer),
            (45.0, Leaving, Inner),
            (55.0, Entering, Inner),
            (60.0, Leaving, Outer),
        ],
    );
    assert_eq!(q.classify().class, OracleClass::Hit);
    assert!((q.classify().margin + 2.5).abs() < 1e-12);
    // At φ = 0 the same line passes through the cut-away arc: 30·sin(π/4) from the
    // start cap's edge ray.
    let q = vecgeom(DVec3::new(30.0, 50.0, 0.0), DVec3::NEG_Y);
    assert!(q.crossings().is_empty());
    let m = q.classify();
    assert_eq!(m.class, OracleClass::Miss);
    assert!((m.margin - 30.0 * FRAC_PI_4.sin()).abs() < 1e-12, "{m:?}");
    // Along growing φ at φ = π/4, 7 from the core: into the start cap at t = 5, out of
    // the end cap (φ = π, the −x half-plane) after the arc.
    let s = DVec3::new(1.0, 0.0, -1.0).normalize();
    let t = DVec3::new(-1.0, 0.0, -1.0).normalize();
    let q = vecgeom(s * 37.0 - t * 5.0, t);
    let c = q.crossings();
    assert_eq!((c[0].1, c[0].2), (Entering, StartCap));
    assert!((c[0].0 - 5.0).abs() < 1e-12);
    assert_eq!((c[1].1, c[1].2), (Leaving, Outer));
    // The normal of the start cap faces −growing φ.
    assert!((q.normal(StartCap, s * 37.0) + t).length() < 1e-15);
    // Through the hollow core along the axis: nothing.
    let q = vecgeom(DVec3::new(0.0, 50.0, 0.0), DVec3::NEG_Y);
    assert_eq!(q.classify().class, OracleClass::Miss);
    // Along the pipe's axis (the core circle's tangent) at φ = π/2 through both caps'
    // planes: in the bore, a miss; 7 from the core, the ring's line crosses the tube.
    let q = vecgeom(DVec3::new(-100.0, 0.0, -30.0), DVec3::X).over(-INF, INF);
    let faces: Vec<Face> = q.crossings().iter().map(|c| c.2).collect();
    assert_eq!(faces, [Outer, Inner, Inner, Outer]);
    // Along x at z = 0: the end cap's half-plane (φ = π, −x) is crossed where the x axis
    // runs in it; y = 7 keeps it on the annulus: enters by the end cap? The line runs in
    // the plane z = 0, which is both caps' plane only for φ₀ = 0; here it meets the end
    // cap's plane along its whole length: no crossing of the cap, touches excluded.
    let q = vecgeom(DVec3::new(-100.0, 7.0, 0.0), DVec3::X).over(-INF, INF);
    assert!(q.crossings().len() <= 2);
}

#[test]
fn tangent_to_the_bore_and_grazing_a_caps_edge() {
    // A horizontal line at y = 5 over φ = π/2: tangent to the bore from inside the
    // material, y = 10 tangent to the outer torus (margin 0, ambiguous).
    let q = vecgeom(DVec3::new(-100.0, 10.0, -30.0), DVec3::X).over(-INF, INF);
    assert_eq!(q.classify().class, OracleClass::Ambiguous);
    let q = vecgeom(DVec3::new(-100.0, 10.0 + 1e-6, -30.0), DVec3::X).over(-INF, INF);
    assert_eq!(q.classify().class, OracleClass::Miss);
    assert!((q.classify().margin - 1e-6).abs() < 1e-12);
    // The start cap's outer edge at φ = π/4: the point s·40, grazed along the axis
    // direction (+y) from just outside the segment.
    let s = DVec3::new(1.0, 0.0, -1.0).normalize();
    let growing = DVec3::new(-1.0, 0.0, -1.0).normalize();
    for (off, class) in [(-1e-6, OracleClass::Miss), (1e-6, OracleClass::Hit)] {
        let o = s * 40.0 + growing * off - DVec3::Y * 5.0 - s * 1e-3;
        let q = vecgeom(o, DVec3::Y).over(-INF, INF);
        let l = q.classify();
        assert_eq!(l.class, class, "{l:?}");
        assert!((l.margin.abs() - 1e-6).abs() < 1e-9, "{l:?}");
    }
}

/// A random bend and a line aimed near it.
fn random_query(rng: &mut Pcg64) -> BendQuery {
    let scale = [1e-3, 1.0, 1e3][rng.random_range(0..3)];
    let nu = [1.25, 4.0, 16.0][rng.random_range(0..3)];
    let tube = scale;
    let major = nu * tube;
    let bore = tube * [0.0, 0.5, 0.9][rng.random_range(0..3)];
    let delta = [2.0 * PI, PI, FRAC_PI_2, PI / 6.0, 1.5 * PI][rng.random_range(0..5)];
    let start = rng.random_range(-PI..PI);
    let unit = |rng: &mut Pcg64| {
        DVec3::new(
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
        )
        .normalize()
    };
    let size = major + tube;
    let center = unit(rng) * size * rng.random_range(0.0..2.0);
    let axis = unit(rng);
    let phi_zero = unit(rng);
    let origin = center + unit(rng) * size * rng.random_range(0.0..3.0);
    let aim = center + unit(rng) * size * rng.random_range(0.0..1.0);
    BendQuery::new(
        (center, axis, phi_zero),
        (major, bore, tube),
        (start, delta),
        origin,
        aim - origin,
        (0.0, INF),
    )
}

#[test]
fn the_margin_agrees_with_sampling_and_the_crossings() {
    let mut rng = Pcg64::seed_from_u64(0xbe4d);
    let (mut hits, mut misses, mut loose) = (0, 0, 0);
    for _ in 0..3000 {
        let q = random_query(&mut rng);
        let size = q.size();
        let label = q.classify();
        if let Some(sampled) = q.margin_by_sampling(2000) {
            assert!(
                sampled >= label.margin - 1e-12 * size,
                "{q:?}: {sampled} < {label:?}"
            );
            if sampled - label.margin > 1e-6 * size {
                loose += 1;
            }
        }
        // The label and the crossings tell the same story.
        let cs = q.crossings();
        match label.class {
            OracleClass::Hit => {
                hits += 1;
                assert!(!cs.is_empty() || q.starts_inside(), "{q:?}");
            }
            OracleClass::Miss => {
                misses += 1;
                assert!(cs.is_empty() && !q.starts_inside(), "{q:?}: {cs:?}");
            }
            OracleClass::Ambiguous => {}
        }
        // Crossings alternate, and F has the side they say at midpoints.
        let mut inside = q.starts_inside();
        for c in &cs {
            match c.1 {
                Passage::Entering => assert!(!inside, "{q:?} {cs:?}"),
                Passage::Leaving => assert!(inside, "{q:?} {cs:?}"),
                Passage::Touching => continue,
            }
            inside = c.1 == Passage::Entering;
        }
    }
    assert!(hits > 500 && misses > 500, "{hits} {misses}");
    assert!(
        loose < 30,
        "sampling far above the exact minimum {loose} times"
    );
}

#[test]
fn the_whole_torus_is_the_family_oracles() {
    let mut rng = Pcg64::seed_from_u64(7);
    for _ in 0..2000 {
        let mut q = random_query(&mut rng);
        q.bore = 0.0;
        q.delta_phi = 2.0 * PI;
        let family = FamilyQuery::new(
            q.center, q.axis, q.major, q.tube, q.tube, q.origin, q.dir, q.t_min, q.t_max,
        );
        let (a, b) = (q.classify(), family.classify());
        assert_eq!(a.class, b.class, "{q:?}");
        if a.margin < q.size() {
            assert!(
                (a.margin - b.margin).abs() <= 1e-12 * q.size(),
                "{a:?} {b:?}"
            );
        }
        let ts: Vec<f64> = q.crossings().iter().map(|c| c.0).collect();
        let want: Vec<f64> = family.crossings().iter().map(|c| c.t).collect();
        assert_eq!(ts.len(), want.len(), "{q:?}");
        for (a, b) in ts.iter().zip(&want) {
            assert!(
                (a - b).abs() * q.dir.length() <= 1e-12 * q.size(),
                "{ts:?} {want:?}"
            );
        }
    }
}

#[test]
fn rays_from_every_face_skip_their_own_crossing() {
    use Face::*;
    let s = DVec3::new(1.0, 0.0, -1.0).normalize();
    let growing = DVec3::new(-1.0, 0.0, -1.0).normalize();
    // From the outer top at φ = π/2, down: the bore at t = 5.
    let q = vecgeom(DVec3::new(0.0, 10.0, -30.0), DVec3::NEG_Y);
    let first = q.first_crossing_from_surface().unwrap();
    assert!(
        (first.0 - 5.0).abs() < 1e-12 && first.2 == Inner,
        "{first:?}"
    );
    // From the same point, up: a miss.
    let q = vecgeom(DVec3::new(0.0, 10.0, -30.0), DVec3::Y);
    assert_eq!(q.classify_from_surface().class, OracleClass::Miss);
    // From the bore's top, up: the outer face at 5.
    let q = vecgeom(DVec3::new(0.0, 5.0, -30.0), DVec3::Y);
    assert!((q.first_crossing_from_surface().unwrap().0 - 5.0).abs() < 1e-12);
    // From the start cap at 7 from the core, along growing φ: the outer face.
    let q = vecgeom(s * 37.0, growing);
    let first = q.first_crossing_from_surface().unwrap();
    assert_eq!((first.1, first.2), (Passage::Leaving, Outer));
    // From the start cap outward (−growing): a miss.
    let q = vecgeom(s * 37.0, -growing);
    assert_eq!(q.classify_from_surface().class, OracleClass::Miss);
    // From the cap's outer edge (both faces), inward and down: leaves through the outer.
    let q = vecgeom(s * 40.0, growing - s * 0.5);
    let (moved, faces) = q.on_surface().unwrap();
    assert_eq!(faces, [Outer, StartCap]);
    assert!((moved.origin - s * 40.0).length() < 1e-13);
    assert_eq!(
        q.first_crossing_from_surface().map(|c| (c.1, c.2)),
        Some((Passage::Leaving, Outer))
    );
    // Tangent: ambiguous.
    let q = vecgeom(DVec3::new(0.0, 10.0, -30.0), DVec3::X);
    assert_eq!(q.classify_from_surface().class, OracleClass::Ambiguous);
    // Not on a face: ambiguous.
    let q = vecgeom(DVec3::new(0.0, 11.0, -30.0), DVec3::NEG_Y);
    assert_eq!(q.classify_from_surface().class, OracleClass::Ambiguous);
}
