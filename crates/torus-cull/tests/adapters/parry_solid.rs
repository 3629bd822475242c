//! The parry adapter over the shape interface: a parry `Compound` holding a ring torus
//! (`ParryTorus`), a family member (`ParryToroid`) and a pipe bend (`ParryBend`) answers
//! ray casts and point queries as the library does, bit for bit: each part's answer is the
//! library's on the local ray or point parry's pose makes, and the compound's the nearest
//! part's. And the mass properties: Pappus where a closed form exists, refused in words
//! where not.

use glam::{DVec3, Vec3};
use parry3d::math::{Pose, Vector};
use parry3d::query::{PointQuery, Ray as PRay, RayCast};
use parry3d::shape::{Compound, Shape, SharedShape};
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64;
use torus_cull::adapters::parry::{ParryBend, ParrySolid, ParryToroid, ParryTorus};
use torus_cull::bend::PipeBend;
use torus_cull::family::Toroid;
use torus_cull::{Ray, Solid, Torus};

fn pv(v: Vec3) -> Vector {
    Vector::from_array(v.to_array())
}
fn lv(v: Vector) -> Vec3 {
    Vec3::from_array(v.to_array())
}

/// The three parts, each as the library solid its parry shape answers with, in its own
/// frame, and parry's pose of it.
struct Parts {
    torus: Torus,
    toroid: Toroid,
    bend: PipeBend,
    poses: [Pose; 3],
}

impl Parts {
    fn new() -> Parts {
        Parts {
            torus: *ParryTorus::new(4.0, 1.0).unwrap().torus(),
            toroid: Toroid::canonical(3.0, 0.8, 1.4).unwrap(),
            bend: PipeBend::canonical(4.0, 0.6, 1.2, 0.4, 4.0).unwrap(),
            poses: [
                Pose::translation(0.0, 0.0, 0.0),
                Pose::translation(7.0, 1.0, -2.0),
                Pose::new(Vector::new(-6.0, -1.0, 3.0), Vector::new(0.0, 0.6, 0.2)),
            ],
        }
    }

    fn compound(&self) -> Compound {
        Compound::new(vec![
            (
                self.poses[0],
                SharedShape::new(ParryTorus::new(4.0, 1.0).unwrap()),
            ),
            (
                self.poses[1],
                SharedShape::new(ParryToroid::new(self.toroid)),
            ),
            (self.poses[2], SharedShape::new(ParryBend::new(self.bend))),
        ])
    }

    /// The library's answer to part `i`'s local ray: `t` and the normal facing the ray.
    fn hit(&self, i: usize, ray: &PRay, max: f32, solid: bool) -> Option<(f32, Vec3)> {
        let (o, d) = (lv(ray.origin), lv(ray.dir));
        let lib = Ray::with_range(o, d, 0.0, max).ok()?;
        let p = o.as_dvec3();
        let (inside, hit) = match i {
            0 => (
                self.torus.contains(p).ok()?,
                Solid::hit(&self.torus, &lib).map(|h| (h.t, h.normal, h.front_face)),
            ),
            1 => (
                self.toroid.contains(p).ok()?,
                self.toroid
                    .intersect(&lib)
                    .map(|h| (h.t, h.normal, h.front_face)),
            ),
            _ => (
                self.bend.contains(p),
                self.bend
                    .intersect(&lib)
                    .map(|h| (h.t, h.normal, h.front_face)),
            ),
        };
        if solid && inside {
            return Some((0.0, Vec3::ZERO));
        }
        hit.map(|(t, n, front)| (t, if front { n } else { -n }))
    }

    /// The library's closest point of part `i` to a local point, and whether inside.
    fn project(&self, i: usize, p: DVec3) -> Option<(Vec3, bool)> {
        let (point, d) = match i {
            0 => self
                .torus
                .project_point(p)
                .map(|q| (q.point, q.signed_distance))
                .ok()?,
            1 => self
                .toroid
                .project_point(p)
                .map(|q| (q.point, q.signed_distance))
                .ok()?,
            _ => self
                .bend
                .project_point(p)
                .map(|q| (q.point, q.signed_distance))
                .ok()?,
        };
        Some((point.as_vec3(), d <= 0.0))
    }

    fn contains(&self, i: usize, p: DVec3) -> bool {
        match i {
            0 => self.torus.contains(p).unwrap(),
            1 => self.toroid.contains(p).unwrap(),
            _ => self.bend.contains(p),
        }
    }
}

fn bits(v: Vec3) -> [u32; 3] {
    v.to_array().map(f32::to_bits)
}

#[test]
fn a_compound_of_torus_toroid_and_bend_answers_as_the_library() {
    let parts = Parts::new();
    let compound = parts.compound();
    let mut rng = Pcg64::seed_from_u64(0x55_0a_9e);
    let mut v = |a: f32| {
        Vec3::new(
            rng.random_range(-a..a),
            rng.random_range(-a..a),
            rng.random_range(-a..a),
        )
    };
    let (mut hits, mut by_part, mut inside) = (0, [0; 3], 0);
    for i in 0..600 {
        let o = v(16.0);
        let target = v(9.0) * Vec3::new(1.0, 0.4, 1.0);
        let d = (target - o).normalize_or(Vec3::X);
        let ray = PRay::new(pv(o), pv(d));
        let (max, solid) = (if i % 5 == 0 { 8.0 } else { f32::MAX }, i % 3 == 0);
        // Each part alone, through parry's pose: the library's answer on the local ray.
        let mut best: Option<(f32, Vec3, usize)> = None;
        let mut tie = false;
        for (k, pose) in parts.poses.iter().enumerate() {
            let local = ray.inverse_transform_by(pose);
            let want = parts.hit(k, &local, max, solid);
            let shape = compound.shapes()[k].1.as_ref();
            let got = shape
                .cast_local_ray_and_get_normal(&local, max, solid)
                .map(|h| (h.time_of_impact.to_bits(), bits(lv(h.normal))));
            assert_eq!(
                got,
                want.map(|(t, n)| (t.to_bits(), bits(n))),
                "part {k} ray {i}"
            );
            if let Some((t, n)) = want {
                let n = lv(pose.rotation * pv(n));
                match best {
                    Some((b, ..)) if t > b => {}
                    Some((b, ..)) if t == b => tie = true,
                    _ => {
                        tie = false;
                        best = Some((t, n, k));
                    }
                }
            }
        }
        // The compound: the nearest part's.
        let got = compound.cast_local_ray_and_get_normal(&ray, max, solid);
        assert_eq!(
            got.map(|h| h.time_of_impact.to_bits()),
            best.map(|(t, ..)| t.to_bits()),
            "ray {i}: {o} {d}"
        );
        if let (Some(h), Some((_, n, k)), false) = (got, best, tie) {
            assert_eq!(bits(lv(h.normal)), bits(n), "ray {i}");
            hits += 1;
            by_part[k] += 1;
        }
        // A point: contained by some part, and projected onto the nearest part's point.
        let p = v(10.0) * Vec3::new(1.0, 0.4, 1.0);
        let mut nearest: Option<(f32, Vec3, bool)> = None;
        let mut any_inside = false;
        for (k, pose) in parts.poses.iter().enumerate() {
            let local = pose.inverse_transform_point(pv(p));
            any_inside |= parts.contains(k, lv(local).as_dvec3());
            let (q, is_in) = parts.project(k, lv(local).as_dvec3()).unwrap();
            let shape = compound.shapes()[k].1.as_ref();
            let got = shape.project_local_point(local, false);
            assert_eq!(
                (bits(lv(got.point)), got.is_inside),
                (bits(q), is_in),
                "part {k}"
            );
            let world = lv(pose.transform_point(pv(q)));
            let dist = (pv(world) - pv(p)).length();
            if nearest.is_none_or(|(b, ..)| dist < b) {
                nearest = Some((dist, world, is_in));
            }
        }
        assert_eq!(
            compound.contains_local_point(pv(p)),
            any_inside,
            "point {p}"
        );
        inside += usize::from(any_inside);
        let got = compound.project_local_point(pv(p), false);
        let (_, world, is_in) = nearest.unwrap();
        assert_eq!(
            (bits(lv(got.point)), got.is_inside),
            (bits(world), is_in),
            "point {p}"
        );
    }
    assert!(
        hits > 150 && by_part.iter().all(|&n| n > 20),
        "{hits} {by_part:?}"
    );
    assert!(inside > 20, "{inside} points inside");
}

#[test]
fn mass_properties_where_a_closed_form_exists_and_words_where_not() {
    let rho = 2.0_f32;
    let close = |a: f32, b: f64| ((f64::from(a) - b) / b).abs() < 1e-6;
    // The circular ring member: the torus's own formula.
    let ring = ParryToroid::new(Toroid::canonical(4.0, 1.0, 1.0).unwrap());
    let torus = ParryTorus::new(4.0, 1.0).unwrap();
    let (got, want) = (ring.mass_properties(rho), torus.mass_properties(rho));
    assert!(close(got.mass(), f64::from(want.mass())));
    // An elliptical ring: m = ρ·2π²Rab.
    let pi2 = std::f64::consts::PI.powi(2);
    let ellipse = ParryToroid::new(Toroid::canonical(4.0, 1.0, 0.5).unwrap());
    let m = ellipse.try_mass_properties(rho).unwrap();
    assert!(close(m.mass(), 2.0 * 2.0 * pi2 * 4.0 * 0.5));
    // A whole bend with a bore: the ring minus the bore, m = ρ·2π²R(r² − s²).
    let bend =
        ParryBend::new(PipeBend::canonical(4.0, 0.5, 1.0, 0.0, std::f64::consts::TAU).unwrap());
    let m = bend.try_mass_properties(rho).unwrap();
    assert!(close(m.mass(), 2.0 * 2.0 * pi2 * 4.0 * 0.75));
    // Refused in words: a horn, a spindle, a bend segment, a bad density.
    let horn = ParrySolid::new(Toroid::canonical(1.0, 1.0, 1.0).unwrap());
    let spindle = ParrySolid::new(Toroid::canonical(0.8, 1.0, 1.2).unwrap());
    let segment = ParryBend::new(PipeBend::canonical(4.0, 0.5, 1.0, 0.0, 1.0).unwrap());
    for why in [
        horn.try_mass_properties(rho).unwrap_err(),
        spindle.try_mass_properties(rho).unwrap_err(),
    ] {
        assert!(why.contains("horn or spindle"), "{why}");
    }
    let why = segment.try_mass_properties(rho).unwrap_err();
    assert!(why.contains("segment"), "{why}");
    assert!(
        ellipse
            .try_mass_properties(f32::NAN)
            .unwrap_err()
            .contains("density")
    );
    // parry's trait cannot refuse: zero mass, as parry's shapes without a volume.
    assert_eq!(segment.mass_properties(rho).mass(), 0.0);
}
