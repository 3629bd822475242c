//! The nearest point on the ellipse and the on-surface rule.

use super::tests::{Pose, canonical_poses, shapes_and_scales, unit};
use super::*;
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64;

const INF: f64 = f64::INFINITY;
const TAU: f64 = std::f64::consts::TAU;

const ELLIPSES: [(f64, f64); 6] = [
    (1.0, 1.0),
    (1.0, 0.25),
    (1.0, 4.0),
    (2.0, 0.5),
    (1e-3, 2e-3),
    (1e3, 3e2),
];

#[test]
fn nearest_points_of_ellipse_points_and_their_normals() {
    for (a, b) in ELLIPSES {
        let big = a.max(b);
        // The least radius of curvature: an inward push shorter than it keeps the point.
        let curv = (a * a / b).min(b * b / a);
        for i in 0..720 {
            let th = TAU * f64::from(i) / 720.0;
            let (u, v) = (a * th.cos(), b * th.sin());
            let (x, y) = nearest_on_ellipse(a, b, u, v);
            assert!((x - u).abs() <= 4e-16 * big && (y - v).abs() <= 4e-16 * big);
            let n = DVec3::new(th.cos() / a, th.sin() / b, 0.0).normalize();
            for push in [
                1e-12 * big,
                1e-3 * big,
                10.0 * big,
                -0.5 * curv,
                -1e-9 * big,
            ] {
                let (x, y) = nearest_on_ellipse(a, b, u + push * n.x, v + push * n.y);
                let tol = 1e-14 * big * (1.0 + big / curv);
                assert!(
                    (x - u).abs() <= tol && (y - v).abs() <= tol,
                    "{a} {b} θ {th} push {push}: ({x}, {y}) want ({u}, {v})"
                );
            }
        }
    }
}

#[test]
fn nearest_points_against_brute_force() {
    let mut rng = Pcg64::seed_from_u64(8);
    for (a, b) in ELLIPSES {
        let big = a.max(b);
        let dist = |u: f64, v: f64, th: f64| (u - a * th.cos()).hypot(v - b * th.sin());
        for _ in 0..200 {
            let u = rng.random_range(-2.0..2.0) * a;
            let v = rng.random_range(-2.0..2.0) * b;
            let (x, y) = nearest_on_ellipse(a, b, u, v);
            let e = (x / a).hypot(y / b) - 1.0;
            assert!(e.abs() <= 4e-16, "{a} {b} ({u}, {v}): E − 1 = {e}");
            assert!(x * u >= 0.0 && y * v >= 0.0);
            let n = 20_000;
            let mut best = INF;
            let mut at = 0;
            for i in 0..n {
                let d = dist(u, v, TAU * f64::from(i) / f64::from(n));
                if d < best {
                    best = d;
                    at = i;
                }
            }
            // Refine by ternary search on the bracketing samples.
            let (mut lo, mut hi) = (
                TAU * (f64::from(at) - 1.0) / f64::from(n),
                TAU * (f64::from(at) + 1.0) / f64::from(n),
            );
            for _ in 0..200 {
                let (m1, m2) = (lo + (hi - lo) / 3.0, hi - (hi - lo) / 3.0);
                if dist(u, v, m1) <= dist(u, v, m2) {
                    hi = m2;
                } else {
                    lo = m1;
                }
            }
            best = best.min(dist(u, v, 0.5 * (lo + hi)));
            let ours = (x - u).hypot(y - v);
            assert!(
                ours <= best + 1e-14 * big,
                "{a} {b} ({u}, {v}): {ours} vs {best}"
            );
            assert!(
                ours >= best - 1e-9 * big,
                "{a} {b} ({u}, {v}): {ours} vs {best}"
            );
        }
    }
}

/// The label and first crossing of the ray from the torus-frame point `o` along `d`
/// over `[0, t_max]`.
fn from_surface(p: &Pose, o: DVec3, d: DVec3, t_max: f64) -> (OracleClass, Option<f64>) {
    let q = p.q(o, d).over(0.0, t_max);
    (
        q.classify_from_surface().class,
        q.first_crossing_from_surface(),
    )
}

#[test]
fn hand_cases_from_the_surface() {
    use OracleClass::{Ambiguous, Hit, Miss};
    for (p, _) in canonical_poses() {
        let (big, ra, ax) = (p.big, p.ra, p.ax);
        let ctx = format!("{p:?}");
        let close =
            |got: Option<f64>, want: f64| got.is_some_and(|t| (t - want).abs() <= 1e-14 * p.size());
        // The top of the tube: straight up, nothing; down, the bottom at t = 2b.
        let top = DVec3::new(big, ax, 0.0);
        assert_eq!(from_surface(&p, top, DVec3::Y, INF).0, Miss, "{ctx}");
        let (c, t) = from_surface(&p, top, DVec3::NEG_Y, 2.5 * ax);
        assert!(c == Hit && close(t, 2.0 * ax), "{ctx} {c:?} {t:?}");
        assert_eq!(from_surface(&p, top, DVec3::NEG_Y, 1.5 * ax).0, Miss);
        // The exit exactly at t_max: not determined by the input.
        assert_eq!(from_surface(&p, top, DVec3::NEG_Y, 2.0 * ax).0, Ambiguous);
        // Nudged by rounding off the surface, the same answers.
        let nudged = top + DVec3::new(3e-16, -2e-16, 1e-16) * p.size();
        let (c, t) = from_surface(&p, nudged, DVec3::NEG_Y, 2.5 * ax);
        assert!(c == Hit && close(t, 2.0 * ax), "{ctx} {c:?} {t:?}");
        // Tangent at the top: nothing past the origin can be told.
        assert_eq!(from_surface(&p, top, DVec3::Z, INF).0, Ambiguous, "{ctx}");
        // The outer equator: outward nothing; inward, the far wall of the solid.
        let outer = DVec3::new(big + ra, 0.0, 0.0);
        assert_eq!(from_surface(&p, outer, DVec3::X, INF).0, Miss, "{ctx}");
        let (c, t) = from_surface(&p, outer, DVec3::NEG_X, INF);
        assert_eq!(c, Hit, "{ctx}");
        if p.is_ring() {
            // Out of the tube at the inner equator.
            assert!(close(t, 2.0 * ra), "{ctx} {t:?}");
            // From the inner equator across the hole: the far wall at t = 2(R − a).
            let inner = DVec3::new(big - ra, 0.0, 0.0);
            let (c, t) = from_surface(&p, inner, DVec3::NEG_X, INF);
            assert!(c == Hit && close(t, 2.0 * (big - ra)), "{ctx} {t:?}");
            let short = 0.5 * (big - ra);
            assert_eq!(from_surface(&p, inner, DVec3::NEG_X, short).0, Miss);
            let (c, t) = from_surface(&p, inner, DVec3::X, INF);
            assert!(c == Hit && close(t, 2.0 * ra), "{ctx} {t:?}");
        } else if p.is_horn() {
            // The centre, where the two sides of the tube touch.
            assert!(close(t, 2.0 * ra), "{ctx} {t:?}");
        } else {
            // Straight through the apple: no lemon at t = 2R or 2a.
            assert!(close(t, 2.0 * (big + ra)), "{ctx} {t:?}");
            let (c, _) = from_surface(&p, outer, DVec3::NEG_X, 1.9 * (big + ra));
            assert_eq!(c, Miss, "{ctx}");
            // The cusp on the axis is a singular point.
            let y0 = ax * (1.0 - (big / ra).powi(2)).sqrt();
            let cusp = DVec3::new(0.0, y0, 0.0);
            for d in [DVec3::X, DVec3::Y, DVec3::NEG_Y, DVec3::new(0.6, -0.8, 0.0)] {
                assert_eq!(from_surface(&p, cusp, d, INF).0, Ambiguous, "{ctx}");
            }
        }
        if p.is_horn() {
            for d in [DVec3::X, DVec3::Y, DVec3::new(0.6, 0.8, 0.0)] {
                let c = from_surface(&p, DVec3::ZERO, d, INF).0;
                assert_eq!(c, Ambiguous, "{ctx}");
            }
        }
    }
}

#[test]
fn rounded_surface_points_give_the_exact_points_answer() {
    let mut rng = Pcg64::seed_from_u64(12);
    let (mut hits, mut misses, mut ambiguous, mut total) = (0, 0, 0, 0);
    for (shape, k) in shapes_and_scales() {
        for _ in 0..120 {
            let p = Pose::random(&mut rng, shape, k);
            let size = p.size();
            let (surf, n) = surface_point(&mut rng, &p);
            let d = loop {
                let d = unit(&mut rng);
                if d.dot(n).abs() >= 0.05 {
                    break d;
                }
            };
            let q = p.q(surf, d).over(0.0, INF);
            total += 1;
            // The origin rounds the surface point; on_surface puts it back.
            let on = q.on_surface();
            let ratio = p.ra.max(p.ax) / p.min_ab();
            assert!(on.g(0.0).abs() <= 1e-14 * size * ratio, "{q:?}");
            assert!((on.origin - q.origin).length() <= 1e-14 * size);
            // The exact answer: the general crossings of the line, past the origin's.
            let ts: Vec<f64> = q.crossings().iter().map(|c| c.t).collect();
            let gap = 1e-6 * size;
            let next = ts.iter().copied().find(|&t| t > gap);
            if ts.iter().any(|&t| t > 1e-12 * size && t <= gap) {
                continue;
            }
            let label = q.classify_from_surface();
            let ctx = format!("{q:?} {label:?} crossings {ts:?}");
            match label.class {
                OracleClass::Ambiguous => {
                    ambiguous += 1;
                    continue;
                }
                OracleClass::Hit => hits += 1,
                OracleClass::Miss => misses += 1,
            }
            assert_eq!(label.class == OracleClass::Hit, next.is_some(), "{ctx}");
            let first = q.first_crossing_from_surface();
            if let (Some(a), Some(b)) = (first, next) {
                assert!((a - b).abs() <= 1e-12 * size, "{ctx} {first:?}");
            }
            // A nudge of rounding size changes nothing.
            let nudged = FamilyQuery {
                origin: q.origin + unit(&mut rng) * 1e-14 * size,
                ..q
            };
            assert_eq!(nudged.classify_from_surface().class, label.class, "{ctx}");
            if let (Some(a), Some(b)) = (nudged.first_crossing_from_surface(), first) {
                assert!((a - b).abs() <= 1e-12 * size, "{ctx}");
            }
        }
    }
    assert!(hits > 500 && misses > 500, "{hits} {misses} {ambiguous}");
    assert!(ambiguous * 50 <= total, "{ambiguous} of {total}");
}

#[test]
fn near_tangent_rays_from_the_surface_stay_consistent() {
    let mut rng = Pcg64::seed_from_u64(13);
    let mut decided = 0;
    for (shape, k) in shapes_and_scales() {
        for _ in 0..60 {
            let p = Pose::random(&mut rng, shape, k);
            let size = p.size();
            let (surf, n) = surface_point(&mut rng, &p);
            let (t1, t2) = n.any_orthonormal_pair();
            let psi = rng.random_range(0.0..TAU);
            let tilt = [1e-3, -1e-3, 1e-6, -1e-6, 1e-9, -1e-9, 0.0][rng.random_range(0..7)];
            let d = (psi.cos() * t1 + psi.sin() * t2 + tilt * n).normalize();
            let q = p.q(surf, d).over(0.0, INF);
            let label = q.classify_from_surface();
            let first = q.first_crossing_from_surface();
            let ctx = format!("{q:?} {label:?} {first:?}");
            match label.class {
                OracleClass::Hit => {
                    decided += 1;
                    let t = first.expect("a hit has a first crossing");
                    assert!(t > 0.0, "{ctx}");
                    let on = q.on_surface();
                    let tol = 1e-13 * size * p.ra.max(p.ax) / p.min_ab();
                    assert!(on.g(t).abs() <= tol, "{ctx}");
                }
                OracleClass::Miss => {
                    decided += 1;
                    assert!(first.is_none(), "{ctx}");
                    assert!(label.margin >= 0.0, "{ctx}");
                }
                OracleClass::Ambiguous => assert!(first.is_none(), "{ctx}"),
            }
            if tilt == 0.0 {
                assert_eq!(label.class, OracleClass::Ambiguous, "{ctx}");
            }
        }
    }
    assert!(decided > 500, "{decided}");
}

/// A random surface point of `p` and its outward normal, off the axis by more than 5 % of
/// a (ρ = R + a cos θ > 0.05 a: a spindle's tips, where the normal turns, are left out).
fn surface_point(rng: &mut Pcg64, p: &Pose) -> (DVec3, DVec3) {
    let theta = loop {
        let th: f64 = rng.random_range(0.0..TAU);
        if p.big + p.ra * th.cos() > 0.05 * p.ra {
            break th;
        }
    };
    p.surface(rng.random_range(0.0..TAU), theta)
}
