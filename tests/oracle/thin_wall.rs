//! Thin walls (issue 52): pipe bends whose wall `r_max − r_min` is 10⁻² … 10⁻⁷·r_max, down
//! to the thinnest the library accepts (`MIN_WALL_REL`·(R + r_max)), against the bend
//! oracle. Bores of ν = R/r_min from 1.01 to 1000, the whole ring and a cut segment, each
//! posed at random: rays across the wall (from outside and from the bore), along it,
//! tangent to the outer and to the bore face within a fraction of the wall, through a
//! cap's thin annulus, and rays spawned from either face (half of them aimed into the
//! wall). Literal rays are judged by `check::shapes::bend::exact::compare`, spawned ones by
//! `compare_spawned` (the oracle's on-surface rule); the certified f32 path's proved
//! answers (a cut bend's misses) against the oracle on the f32 ray.
//!
//! Before the fix, a ray spawned from one face of a wall thinner than the library's face
//! reach (10⁻⁶·(R + r_max)) took both faces as its own and lost the other face's crossing:
//! `torus-cull bend --bore-ratio 0.999999` missed 588–1 084 hits per class.

use crate::common::bend::{Spec, Tally, compare, rng, unit};
use glam::DVec3;
use rand::RngExt;
use rand_pcg::Pcg64;
use std::f64::consts::{PI, TAU};
use torus_cull::bend::{BendError, MIN_WALL_REL, PipeBend};
use torus_cull::{DRay, Ray};
use torus_cull_lab::check::shapes::bend::exact::compare_spawned;
use torus_cull_lab::oracle::OracleClass;

/// The walls, × r_max.
const WALLS: [f64; 6] = [1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7];

/// The bores' ν = R/r_min.
const BORE_NUS: [f64; 4] = [1.01, 4.0, 100.0, 1000.0];

/// Whole ring, and a cut segment.
const DELTAS: [f64; 2] = [TAU, PI / 3.0];

/// Rays of each kind per bend.
const PER_KIND: usize = 40;

/// A point in the wall (D between r_min and r_max) at a φ of the segment.
fn in_wall(spec: &Spec, rng: &mut Pcg64, share: f64) -> (DVec3, f64, f64) {
    let phi = spec.start + rng.random_range(0.0..spec.delta);
    let psi = rng.random_range(0.0..TAU);
    let d = spec.bore + (spec.tube - spec.bore) * share;
    (spec.point(phi, psi, d), phi, psi)
}

/// The unit outward normal of the tube at (φ, ψ).
fn radial(spec: &Spec, phi: f64, psi: f64) -> DVec3 {
    (spec.point(phi, psi, spec.tube) - spec.point(phi, psi, 0.0)).normalize()
}

/// A unit direction within the cone of half-angle ~60° about `n`.
fn about(n: DVec3, rng: &mut Pcg64) -> DVec3 {
    (n + unit(rng) * 0.9).normalize()
}

/// The literal rays of one bend.
fn literal_rays(spec: &Spec, rng: &mut Pcg64) -> Vec<DRay> {
    let wall = spec.tube - spec.bore;
    let mut rays = Vec::new();
    for _ in 0..PER_KIND {
        // Across the wall, from outside the tube: aimed at a point of the wall.
        let share = rng.random_range(0.0..1.0);
        let (p, phi, psi) = in_wall(spec, rng, share);
        let d = about(-radial(spec, phi, psi), rng);
        rays.push(DRay::new(p - d * (spec.tube * rng.random_range(0.05..3.0)), d).unwrap());
        // Across the wall, from the bore outward.
        let d = about(radial(spec, phi, psi), rng);
        let start = spec.point(phi, psi, 0.5 * spec.bore);
        rays.push(DRay::new(start, p - start + d * 1e-3 * spec.tube).unwrap());
        // Along the wall: through its middle, tangent to the tube there.
        let (m, phi, psi) = in_wall(spec, rng, 0.5);
        let t = unit(rng)
            .reject_from_normalized(radial(spec, phi, psi))
            .normalize();
        rays.push(DRay::new(m - t * (5.0 * spec.tube), t).unwrap());
        // Tangent to the outer and to the bore face, off it by 10⁻³…1 of the wall (log),
        // either side.
        for r in [spec.tube, spec.bore] {
            let phi = spec.start + rng.random_range(0.0..spec.delta);
            let psi = rng.random_range(0.0..TAU);
            let n = radial(spec, phi, psi);
            let e = wall * 10f64.powf(rng.random_range(-3.0..0.0));
            let e = if rng.random_bool(0.5) { e } else { -e };
            let p = spec.point(phi, psi, r) + n * e;
            let t = unit(rng).reject_from_normalized(n).normalize();
            rays.push(DRay::new(p - t * (5.0 * spec.tube), t).unwrap());
        }
        // Through a cap's thin annulus (a cut bend): a point of the cap, from either
        // side, along the pipe's axis or in any direction.
        if spec.delta < TAU {
            let phi = if rng.random_bool(0.5) {
                spec.start
            } else {
                spec.start + spec.delta
            };
            let p = spec.point(phi, rng.random_range(0.0..TAU), {
                spec.bore + (spec.tube - spec.bore) * rng.random_range(0.0..1.0)
            });
            let g = spec.growing(phi) * if rng.random_bool(0.5) { 1.0 } else { -1.0 };
            let d = if rng.random_bool(0.5) {
                g
            } else {
                about(g, rng)
            };
            rays.push(DRay::new(p - d * (spec.tube * rng.random_range(0.05..3.0)), d).unwrap());
        }
    }
    rays
}

/// Rays spawned from either face of the wall: from a point of the outer or the bore face
/// (`PipeBend::spawn` at t = 0 of a ray from it), in any direction or into the wall.
fn spawned_rays(spec: &Spec, bend: &PipeBend, rng: &mut Pcg64) -> Vec<DRay> {
    let mut rays = Vec::new();
    for i in 0..2 * PER_KIND {
        let outer = i % 2 == 0;
        let phi = spec.start + rng.random_range(0.0..spec.delta);
        let psi = rng.random_range(0.0..TAU);
        let r = if outer { spec.tube } else { spec.bore };
        let n = radial(spec, phi, psi);
        let into = if outer { -n } else { n };
        let d = if rng.random_bool(0.5) {
            about(into, rng)
        } else {
            unit(rng)
        };
        let from = DRay::new(spec.point(phi, psi, r), DVec3::X).unwrap();
        rays.push(bend.spawn(&from, 0.0, d).unwrap());
    }
    rays
}

/// The f32 path's proved answers (not escalated) are misses the oracle agrees with, on
/// the ray rounded to f32 (the oracle asked about the rounded ray itself); escalated
/// answers are the f64 solid's. Returns (proved misses, wrong).
fn f32_path(spec: &Spec, bend: &PipeBend, ray: &DRay) -> (u64, u64) {
    let (o, d) = (ray.origin().as_vec3(), ray.dir().as_vec3());
    let Ok(r32) = Ray::new(o, d) else {
        return (0, 0);
    };
    let answer = bend.intersect_f32(&r32);
    if answer.escalated {
        return (0, u64::from(answer.hit != bend.intersect(&r32)));
    }
    let wide = DRay::new(o.as_dvec3(), d.as_dvec3()).unwrap();
    let class = spec.query(&wide).classify().class;
    (
        1,
        u64::from(answer.hit.is_some() || class == OracleClass::Hit),
    )
}

/// Whether the library refuses the wall: thinner than `MIN_WALL_REL`·(R + r_max).
fn refused(spec: &Spec) -> bool {
    spec.tube - spec.bore < MIN_WALL_REL * spec.size() * (1.0 - 1e-6)
}

#[test]
fn thin_walls_from_a_hundredth_to_the_thinnest_accepted() {
    let mut rng = rng(0x7417);
    let (mut literal, mut spawned) = (Tally::default(), Tally::default());
    let (mut bends, mut refusals, mut proved, mut f32_wrong) = (0, 0, 0, 0);
    let mut shown = 0;
    for bore_nu in BORE_NUS {
        for delta in DELTAS {
            // The listed walls, and the thinnest accepted at this ν (the floor itself).
            // The wall w = MIN_WALL_REL·(R + 1) with R = ν_bore·(1 − w).
            let floor = MIN_WALL_REL * (bore_nu + 1.0) / (1.0 + MIN_WALL_REL * bore_nu);
            let mut walls = WALLS.to_vec();
            walls.push(floor);
            for wall in walls {
                let ratio = 1.0 - wall;
                // The outer torus a ring torus too (ν = 1.01 and a wall of 10⁻² is not).
                if bore_nu * ratio <= 1.001 {
                    continue;
                }
                let spec = Spec::canonical(bore_nu * ratio, ratio, 1.0, 0.0, delta);
                let spec = if rng.random_bool(0.5) {
                    spec.posed(&mut rng)
                } else {
                    spec
                };
                let built = spec.bend();
                if refused(&spec) {
                    assert!(
                        matches!(built, Err(BendError::ThinWall { .. })),
                        "{spec:?}: {built:?}"
                    );
                    refusals += 1;
                    continue;
                }
                let bend = built.unwrap_or_else(|e| panic!("{spec:?}: {e}"));
                bends += 1;
                for ray in literal_rays(&spec, &mut rng) {
                    let (t, why) = compare(&spec, &bend, &ray);
                    literal.add(&t);
                    let (p, w) = f32_path(&spec, &bend, &ray);
                    (proved, f32_wrong) = (proved + p, f32_wrong + w);
                    if let Some(why) = why
                        && shown < 4
                    {
                        eprintln!("THIN WALL DISAGREEMENT (wall {wall:e})\n{why}\n");
                        shown += 1;
                    }
                }
                for ray in spawned_rays(&spec, &bend, &mut rng) {
                    let label = spec.query(&ray).classify_from_surface();
                    let (t, why) = compare_spawned(&spec, &bend, &ray, &label);
                    spawned.add(&t);
                    if let Some(why) = why
                        && shown < 4
                    {
                        eprintln!("THIN WALL SPAWNED DISAGREEMENT (wall {wall:e})\n{why}\n");
                        shown += 1;
                    }
                }
            }
        }
    }
    eprintln!(
        "thin walls: {bends} bends ({refusals} refused); literal {literal:?}; spawned \
         {spawned:?}; f32: {proved} proved misses, {f32_wrong} wrong"
    );
    assert_eq!(literal.bad(), 0, "literal: {literal:?}");
    assert_eq!(spawned.bad(), 0, "spawned: {spawned:?}");
    assert_eq!(f32_wrong, 0);
    // The family tests something: most rays judged, hits and misses both, some refused.
    for (what, t) in [("literal", &literal), ("spawned", &spawned)] {
        assert!(t.hits > t.rays / 4 && t.misses > 0, "{what}: {t:?}");
        assert!(t.ambiguous < t.rays / 5, "{what}: {t:?}");
    }
    assert!(refusals > 0 && bends > 20 && proved > 0);
}

#[test]
fn a_wall_below_the_floor_is_refused_with_its_range() {
    // ν = 4, r_max = 1: the floor is 10⁻⁷·5, so r_min ≤ 1 − 5·10⁻⁷.
    let e = PipeBend::canonical(4.0, 0.9999999, 1.0, 0.0, PI).unwrap_err();
    let BendError::ThinWall {
        bore_radius,
        tube_radius,
        max_bore_radius,
    } = e
    else {
        panic!("{e:?}")
    };
    assert_eq!((bore_radius, tube_radius), (0.9999999, 1.0));
    assert!((max_bore_radius - (1.0 - 5e-7)).abs() < 1e-15);
    let text = e.to_string();
    assert!(
        text.contains("bore_radius = 0.9999999") && text.contains("0 < bore_radius <= 0.9999995"),
        "{text}"
    );
    // The bound itself, the repro (a wall of 10⁻⁶) and VecGeom-sized walls pass.
    for bore in [1.0 - 5e-7, 0.999999, 0.99999, 0.5] {
        PipeBend::canonical(4.0, bore, 1.0, 0.0, PI).unwrap();
    }
    // At ν = 1000 the floor is about 10⁻⁴·r_max.
    assert!(PipeBend::canonical(999.0, 0.9999, 1.0, 0.0, TAU).is_ok());
    assert!(matches!(
        PipeBend::canonical(999.0, 0.99995, 1.0, 0.0, TAU),
        Err(BendError::ThinWall { .. })
    ));
}

/// A double-double number `hi + lo` (|lo| ≤ ½ulp(hi)): about 106 bits, the reference that
/// resolves a wall of 10⁻⁷ with 30 digits to spare. Nothing of the library or the oracle.
#[derive(Clone, Copy)]
struct Dd(f64, f64);

impl Dd {
    fn from(a: f64) -> Dd {
        Dd(a, 0.0)
    }
    /// Knuth's two-sum, renormalised.
    fn add(self, b: Dd) -> Dd {
        let s = self.0 + b.0;
        let v = s - self.0;
        let e = (self.0 - (s - v)) + (b.0 - v) + self.1 + b.1;
        let hi = s + e;
        Dd(hi, e - (hi - s))
    }
    fn neg(self) -> Dd {
        Dd(-self.0, -self.1)
    }
    /// The exact product of the highs by a fused multiply-add, plus the cross terms.
    fn mul(self, b: Dd) -> Dd {
        let p = self.0 * b.0;
        let e = self.0.mul_add(b.0, -p) + (self.0 * b.1 + self.1 * b.0);
        let hi = p + e;
        Dd(hi, e - (hi - p))
    }
    /// One Newton step from the f64 root: `s + (a − s²)/(2s)`.
    fn sqrt(self) -> Dd {
        let s = self.0.sqrt();
        let r = self.add(Dd::from(s).mul(Dd::from(s)).neg());
        Dd::from(s).add(Dd::from(r.0 / (2.0 * s)))
    }
}

/// `D(t)² − r²` on the canonical bend's line `o + t·d` (axis +y), in double-double.
fn band_dd(o: DVec3, d: DVec3, t: f64, major: f64, r: f64) -> f64 {
    let c = |o: f64, d: f64| Dd::from(o).add(Dd::from(t).mul(Dd::from(d)));
    let (x, y, z) = (c(o.x, d.x), c(o.y, d.y), c(o.z, d.z));
    let rho = x.mul(x).add(z.mul(z)).sqrt();
    let a = rho.add(Dd::from(major).neg());
    let r2 = Dd::from(r).mul(Dd::from(r));
    let v = a.mul(a).add(y.mul(y)).add(r2.neg());
    v.0 + v.1
}

#[test]
fn spawned_rays_across_the_wall_against_a_double_double_reference() {
    // The wall (10⁻⁶·r_max at ν = 4 and at a bore of ν = 1.01) and the floor at
    // ν = 4 and ν = 999, whole rings in the canonical frame (the line is the reference's
    // own, no pose to round): from either face into the wall at 17° … 73° from its normal, the next crossing is
    // the wall's other face, at t ≈ wall/cos. The library's t against the double-double
    // root of D(t) = r of that face, found by bisection.
    let mut rng = rng(0xdd);
    let mut worst: f64 = 0.0;
    let mut n = 0;
    for (nu, ratio) in [
        (4.0, 0.999999),
        (4.0, 1.0 - 5e-7),
        (999.0, 0.9999),
        (1.01 * 0.999999, 0.999999),
    ] {
        let spec = Spec::canonical(nu, ratio, 1.0, 0.0, TAU);
        let bend = spec.bend().unwrap();
        let wall = spec.tube - spec.bore;
        for i in 0..200 {
            let outer = i % 2 == 0;
            let (phi, psi) = (rng.random_range(0.0..TAU), rng.random_range(0.0..TAU));
            let n_out = radial(&spec, phi, psi);
            let into = if outer { -n_out } else { n_out };
            let d = loop {
                let d = (into + unit(&mut rng) * 0.9).normalize();
                if (0.3..0.95).contains(&d.dot(into)) {
                    break d;
                }
            };
            let r = if outer { spec.tube } else { spec.bore };
            let from = DRay::new(spec.point(phi, psi, r), DVec3::X).unwrap();
            let ray = bend.spawn(&from, 0.0, d).unwrap();
            let hit = bend.intersect(&ray).expect("a ray into the wall leaves it");
            let want_face = if outer {
                torus_cull::bend::BendFace::Inner
            } else {
                torus_cull::bend::BendFace::Outer
            };
            assert_eq!((hit.face, hit.front_face), (want_face, false), "{ray:?}");
            // The other face's root: the band function changes sign between a hundredth
            // of the wall past the origin and three walls past it (|d| = 1).
            let other = if outer { spec.bore } else { spec.tube };
            let f = |t: f64| band_dd(ray.origin(), ray.dir(), t, spec.major, other);
            let (mut lo, mut hi) = (1e-2 * wall, 3.0 * wall / d.dot(into));
            assert!(f(lo).signum() != f(hi).signum(), "{ray:?}");
            let s = f(lo).signum();
            for _ in 0..80 {
                let mid = 0.5 * (lo + hi);
                if f(mid).signum() == s {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            worst = worst.max((hit.t - lo).abs() / wall);
            n += 1;
        }
    }
    eprintln!("double-double: {n} rays across the wall, worst |t − t_ref| = {worst:e}·wall");
    assert!(worst < 1e-4, "{worst:e}");
}
