//! The supported range, tested against the oracle at its edges: every timed cull stays
//! conservative for 10⁻¹⁵ ≤ R + r ≤ 10¹⁵, ν from 1.01 to 1000, direction lengths from
//! 10⁻¹⁸ to 10¹⁸ and origins up to 10⁶·(R + r) away; tori outside the range are refused
//! with an error that states it.

// Every check here runs against the harness's oracle or CLI.

use crate::common::{family, pairs, pushed_back};
use glam::Vec3;
use torus_cull::Named;
use torus_cull::{
    CullKind, MAX_OUTER_RADIUS, MIN_OUTER_RADIUS, NEAR_ORIGIN_REL, Ray, Torus, TorusError,
};
use torus_cull_lab::oracle::{OracleClass, classify_line};
use torus_cull_lab::workload::Case;

const NUS: [f64; 6] = [1.01, 1.1, 2.0, 10.0, 100.0, 1000.0];
const DIR_SCALES: [f32; 3] = [1e-18, 1.0, 1e18];
/// Origin distances, × (R + r): around the f64 switch, and far beyond it.
const FAR: [f32; 6] = [
    0.0,
    0.9 * NEAR_ORIGIN_REL,
    1.1 * NEAR_ORIGIN_REL,
    1e2,
    1e4,
    1e6,
];

struct Tally {
    hits: usize,
    /// Per timed cull, in `CullKind::TIMED` order.
    false_rejects: Vec<usize>,
    examples: Vec<String>,
}

impl Default for Tally {
    fn default() -> Tally {
        Tally {
            hits: 0,
            false_rejects: vec![0; CullKind::TIMED.len()],
            examples: Vec::new(),
        }
    }
}

impl Tally {
    fn check(&mut self, torus: &Torus, ray: &Ray) {
        if classify_line(torus, ray).class != OracleClass::Hit {
            return;
        }
        self.hits += 1;
        let line = torus.line_to_local(ray);
        let bounds = torus.bounds();
        for (i, cull) in CullKind::TIMED.iter().enumerate() {
            if !cull.keeps(bounds, line.origin, line.dir) {
                self.false_rejects[i] += 1;
                if self.examples.len() < 5 {
                    self.examples
                        .push(format!("{cull} rejects a hit: {torus:?} {ray:?}"));
                }
            }
        }
    }
}

/// The same line with its origin `distance` back along it, for any direction length.
fn back_along(ray: &Ray, distance: f32) -> Ray {
    Ray::new(ray.origin() - ray.dir().normalize() * distance, ray.dir()).unwrap()
}

/// The torus of ν with R + r = `outer` (nudged into the range if f32 rounding left it).
fn sized(pose: &Torus, nu: f64, outer: f64) -> (Torus, f32) {
    for nudge in [1.0, 1.0 + 1e-6, 1.0 - 1e-6] {
        let s = outer * nudge / (pose.major_radius() + pose.minor_radius()) as f64;
        let (big, small) = (
            (pose.major_radius() as f64 * s) as f32,
            (pose.minor_radius() as f64 * s) as f32,
        );
        if let Ok(t) = Torus::new(pose.center() * s as f32, pose.axis(), big, small) {
            return (t, s as f32);
        }
    }
    panic!("no torus of nu {nu} with R + r = {outer:e}")
}

fn tally_at(outer: f64) -> Tally {
    let mut tally = Tally::default();
    for nu in NUS {
        for &case in Case::ALL {
            if case == Case::Hole && nu < 1.05 {
                continue; // the hole is too narrow to sample in reasonable time
            }
            for (unit, ray) in pairs(&family(case, nu, 300, 0x5CA1E ^ nu.to_bits())) {
                let (torus, s) = sized(unit, nu, outer);
                for dir_scale in DIR_SCALES {
                    let d = ray.dir().normalize() * dir_scale;
                    let near = Ray::new(ray.origin() * s, d).unwrap();
                    for far in FAR {
                        let r = if far == 0.0 {
                            near
                        } else {
                            back_along(&near, far * torus.outer_radius())
                        };
                        tally.check(&torus, &r);
                    }
                }
            }
        }
        // d_y = 0 lines across the case boundaries a = R − r, R, R + r, and axis-parallel
        // lines at every distance from the axis, from near and far.
        let (torus, _) = sized(
            &Torus::canonical(1.0, (1.0 / nu) as f32).unwrap(),
            nu,
            outer,
        );
        let (big, small) = (torus.major_radius(), torus.minor_radius());
        for i in 0..=100 {
            let s = i as f32 / 100.0;
            for far in [1.0, 1e6] {
                let back = far * torus.outer_radius();
                let y = (2.0 * s - 1.0) * small;
                for a in [big - small, big, big + small] {
                    for (o, d) in [
                        (Vec3::new(-back, y, a), Vec3::X),
                        (Vec3::new(a, y, back), -Vec3::Z),
                        (Vec3::new((1.05 * s) * (big + small), back, 0.0), -Vec3::Y),
                    ] {
                        tally.check(&torus, &Ray::new(o, d).unwrap());
                    }
                }
            }
        }
    }
    tally
}

#[test]
fn every_timed_cull_is_conservative_at_the_edges_of_the_range() {
    let sizes = [
        MIN_OUTER_RADIUS as f64,
        1e-6,
        1.0,
        1e6,
        MAX_OUTER_RADIUS as f64,
    ];
    let tallies: Vec<(f64, Tally)> = std::thread::scope(|s| {
        let handles: Vec<_> = sizes
            .iter()
            .map(|&outer| s.spawn(move || (outer, tally_at(outer))))
            .collect();
        handles.into_iter().map(|h| h.join().unwrap()).collect()
    });
    let mut failures = Vec::new();
    for (outer, t) in &tallies {
        println!(
            "R + r = {outer:e}: {} hits, false rejects {:?}",
            t.hits, t.false_rejects
        );
        assert!(t.hits > 20_000, "only {} hits at R + r = {outer:e}", t.hits);
        if t.false_rejects.iter().any(|&n| n > 0) {
            failures.push(format!(
                "R + r = {outer:e}: {:?}\n{}",
                t.false_rejects,
                t.examples.join("\n")
            ));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn tori_outside_the_range_are_refused_and_the_error_states_it() {
    for (big, small) in [
        (1e19, 1.0),
        (2e38, 1e38),
        (3e38, 3e38 * 0.9),
        (1e-20, 1e-21),
        (1e-16, 1e-17),
        (MAX_OUTER_RADIUS, 1.0),
    ] {
        let e = Torus::canonical(big, small).unwrap_err();
        assert!(
            matches!(e, TorusError::OutOfRange { .. }),
            "{big}, {small}: {e}"
        );
        let msg = e.to_string();
        assert!(msg.contains("1e-15") && msg.contains("1e15"), "{msg}");
    }
    // Just inside both ends.
    assert!(Torus::canonical(MAX_OUTER_RADIUS * 0.7, MAX_OUTER_RADIUS * 0.25).is_ok());
    assert!(Torus::canonical(MIN_OUTER_RADIUS * 0.75, MIN_OUTER_RADIUS * 0.25).is_ok());
}

/// A far origin is where the f32 transform used to lose the line: the same grazing hits
/// seen from 10⁴·(R + r) were rejected before the f64 foot point.
#[test]
fn far_origins_keep_every_hit() {
    let mut tally = Tally::default();
    for nu in [1.1, 4.0, 32.0] {
        for (torus, ray) in pairs(&family(Case::Grazing, nu, 4000, 77)) {
            for far in [1e4, 1e5, 1e6] {
                tally.check(torus, &pushed_back(ray, far * torus.outer_radius()));
            }
        }
    }
    assert!(tally.hits > 10_000, "{} hits", tally.hits);
    let none = vec![0; CullKind::TIMED.len()];
    assert_eq!(tally.false_rejects, none, "{}", tally.examples.join("\n"));
}
