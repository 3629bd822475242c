//! The saddle family (issue 36): rays spawned from the inner half of the tube, nearly
//! along the ring, 10⁻⁵ … 10⁻² rad above the tangent plane. There the surface curves
//! back to meet the ray after an excursion α²/(2κ) high, which at small α is below the
//! rounding of an f32 origin: solved literally from that origin the re-hit is lost.
//!
//! A structured grid, not random draws: ν ∈ {1.01, 1.5, 4, 32, 1000}, R ∈ {10⁻³, 1, 10³}
//! on a posed torus, α ∈ {10⁻⁵, 10⁻⁴, 10⁻³, 10⁻²}, five angles θ across the inner half,
//! three turns off the ring's direction and both ways along it. Each ray is checked
//! against a reference from the **true surface point** (f64, before rounding), through
//! `intersect` (f64 and f32 rays), `occluded`, `intersect_all`'s first crossing, the
//! certified f32 path and both wavefronts.
//!
//! **What the input cannot determine.** An f32 origin places its surface point only to
//! within its rounding τ along the surface too, which turns the normal by about τ/r: at
//! R = 10³, r = 1 and α = 10⁻⁵ that is more than α itself. So a row is judged only where
//! the reference from the true point and from that point moved by ±τ along both tangent
//! directions agree (the class, and `t` within their spread); the others are counted as
//! undecided, never as right.

use crate::common::from_surface_reference;
use glam::{DVec3, Vec3};
use torus_cull::batch::{BatchCull, Dispatch, Wavefront};
use torus_cull::{DRay, Ray, Torus, intersect, intersect_all, intersect_f32, occluded};
use torus_cull_lab::check::shapes::ring::families::{saddle_direction, tube_point};

const NUS: [f64; 5] = [1.01, 1.5, 4.0, 32.0, 1000.0];
const MAJORS: [f64; 3] = [1e-3, 1.0, 1e3];
const ALPHAS: [f64; 4] = [1e-5, 1e-4, 1e-3, 1e-2];

/// A posed torus: centre off the origin by 2R, axis tilted.
fn posed(major: f64, nu: f64) -> Torus {
    let axis = Vec3::new(0.3, 1.0, -0.2).normalize();
    let center = Vec3::new(2.0, -1.0, 0.5) * major as f32;
    Torus::new(center, axis, major as f32, (major / nu) as f32).expect("a valid torus")
}

/// One saddle ray: the true surface point, the direction and the outward normal there
/// (world, f64).
fn saddle_ray(
    torus: &Torus,
    theta: f64,
    phi: f64,
    turn: f64,
    sign: f64,
    alpha: f64,
) -> (DVec3, DVec3, DVec3) {
    let (big, r) = (torus.major_radius_f64(), torus.minor_radius_f64());
    let (p, n) = tube_point(DVec3::new(phi.cos(), 0.0, phi.sin()), theta, big, r);
    let d = saddle_direction(p, n, alpha, turn, sign);
    let world = torus.to_local_rotation_f64().transpose();
    (world * p + torus.center_f64(), world * d, world * n)
}

/// The reference from a surface point `p` along `d`: `Some(t of the next crossing)` or
/// `Some(None)` for none, `None` undecided.
fn reference(torus: &Torus, p: DVec3, d: DVec3) -> Option<Option<f64>> {
    from_surface_reference(torus, &DRay::from_surface(p, d).ok()?)
}

/// The references from `p` and from `p` moved by ±τ along both tangent directions: the
/// class they agree on and the spread of `t`, or `None` where the input cannot decide.
fn robust_reference(
    torus: &Torus,
    (p, d, normal): (DVec3, DVec3, DVec3),
    tau: f64,
) -> Option<Option<(f64, f64)>> {
    let t1 = normal.any_orthonormal_vector();
    let t2 = normal.cross(t1);
    let mut spread: Option<(f64, f64)> = None;
    let mut class = None;
    for shift in [DVec3::ZERO, t1 * tau, -t1 * tau, t2 * tau, -t2 * tau] {
        let moved = torus.nearest_surface_point(p + shift);
        let want = reference(torus, moved, d)?;
        if class.is_some_and(|c| c != want.is_some()) {
            return None;
        }
        class = Some(want.is_some());
        if let Some(t) = want {
            spread = Some(spread.map_or((t, t), |(lo, hi)| (lo.min(t), hi.max(t))));
        }
    }
    Some(spread)
}

#[derive(Default)]
struct Tally {
    rows: usize,
    undecided: usize,
    rehits: usize,
    escalated_f32: usize,
    wrong: Vec<String>,
}

impl Tally {
    fn check(&mut self, what: &str, want: Option<(f64, f64)>, got: Option<f64>, tol: f64) {
        let ok = match (want, got) {
            (None, None) => true,
            (Some((lo, hi)), Some(t)) => t >= lo - tol && t <= hi + tol,
            _ => false,
        };
        if !ok {
            self.wrong
                .push(format!("{what}: got {got:?}, reference {want:?}"));
        }
    }
}

#[test]
fn saddle_rays_find_their_rehit_in_f64_f32_and_the_wavefronts() {
    let dispatch = Dispatch::best();
    let mut wavefront = Wavefront::new();
    let mut tally = Tally::default();
    for nu in NUS {
        for major in MAJORS {
            let torus = posed(major, nu);
            let size = torus.outer_radius() as f64;
            let (mut rays, mut wants, mut tols) = (Vec::new(), Vec::new(), Vec::new());
            for alpha in ALPHAS {
                for k in 0..5 {
                    let theta = std::f64::consts::PI * (0.55 + 0.225 * k as f64);
                    for (j, phi) in [0.3f64, 1.9, 3.6, 5.1].into_iter().enumerate() {
                        for turn in [-0.05, 0.0, 0.05] {
                            for sign in [1.0, -1.0] {
                                let (p, d, n) = saddle_ray(&torus, theta, phi, turn, sign, alpha);
                                let origin = p.as_vec3();
                                let dir = d.as_vec3();
                                let ray = Ray::from_surface(origin, dir).expect("a ray");
                                tally.rows += 1;
                                // The f32 origin's rounding, as a distance along the surface.
                                let tau = (origin.as_dvec3() - p)
                                    .length()
                                    .max(p.abs().max_element() * f64::from(f32::EPSILON));
                                let Some(want) =
                                    robust_reference(&torus, (p, dir.as_dvec3(), n), tau)
                                else {
                                    tally.undecided += 1;
                                    continue;
                                };
                                tally.rehits += usize::from(want.is_some());
                                let len = dir.as_dvec3().length();
                                let what = format!(
                                    "nu={nu} R={major} alpha={alpha:e} theta#{k} phi#{j} turn={turn} {sign} {ray:?}"
                                );
                                // f64 on the f32 ray: the t of an f32 hit is rounded.
                                let f64_tol =
                                    1e-9 * size / len + want.map_or(0.0, |(_, hi)| hi * 1.2e-7);
                                let got = intersect(&torus, &ray).map(|h| f64::from(h.t));
                                tally.check(&format!("f64 {what}"), want, got, f64_tol);
                                assert_eq!(occluded(&torus, &ray), got.is_some(), "{what}");
                                let all = intersect_all(&torus, &ray);
                                let first = all.as_slice().first().map(|c| f64::from(c.t));
                                tally.check(&format!("all {what}"), want, first, f64_tol);
                                // An f64 ray from the rounded origin: the same rule.
                                let wide = DRay::from_surface(origin.as_dvec3(), dir.as_dvec3())
                                    .expect("a ray");
                                let got_wide = intersect(&torus, &wide).map(|h| h.t);
                                tally.check(
                                    &format!("DRay {what}"),
                                    want,
                                    got_wide,
                                    1e-9 * size / len,
                                );
                                // Certified f32: a proof brackets the root within 2·10⁻⁴·R.
                                let f32_tol = f64_tol + 2e-4 * size / len;
                                let f32_path = intersect_f32(&torus, &ray);
                                tally.escalated_f32 += usize::from(f32_path.escalated);
                                let got32 = f32_path.hit.map(|h| f64::from(h.t));
                                tally.check(&format!("certified f32 {what}"), want, got32, f32_tol);
                                rays.push(ray);
                                wants.push(want);
                                tols.push((f64_tol, f32_tol));
                            }
                        }
                    }
                }
            }
            let mut hits = Vec::new();
            wavefront.intersect(&dispatch, BatchCull::Discriminant, &torus, &rays, &mut hits);
            for ((h, &w), &(tol, _)) in hits.iter().zip(&wants).zip(&tols) {
                let what = format!("f64 wavefront nu={nu} R={major}");
                tally.check(&what, w, h.map(|h| f64::from(h.t)), tol);
            }
            wavefront.intersect_f32(&dispatch, BatchCull::Skala, &torus, &rays, &mut hits);
            for ((h, &w), &(_, tol)) in hits.iter().zip(&wants).zip(&tols) {
                let what = format!("f32 wavefront nu={nu} R={major}");
                tally.check(&what, w, h.map(|h| f64::from(h.t)), tol);
            }
        }
    }
    let judged = tally.rows - tally.undecided;
    println!(
        "saddle grid: {} rays, {} undecided by the input, {} judged ({} re-hits); \
         certified f32 escalated {} of {}",
        tally.rows, tally.undecided, judged, tally.rehits, tally.escalated_f32, judged
    );
    let show = tally.wrong[..tally.wrong.len().min(10)].join("\n");
    assert!(
        tally.wrong.is_empty(),
        "{} wrong:\n{show}",
        tally.wrong.len()
    );
    // The grid must mean something: most rows judged, most of them re-hits.
    assert!(
        judged * 10 >= tally.rows * 7,
        "{judged} of {} judged",
        tally.rows
    );
    assert!(
        tally.rehits * 2 >= judged,
        "{} re-hits of {judged}",
        tally.rehits
    );
    // Escalation of saddle rays in certified f32 (issue 36's goal: ≤ 10 %).
    assert!(
        tally.escalated_f32 * 10 <= judged,
        "{} escalated",
        tally.escalated_f32
    );
}
