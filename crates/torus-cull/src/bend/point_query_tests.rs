//! A pipe bend's point queries against a brute-force reference: the least distance over
//! a grid of each face's parameters (the tubes' (φ, θ), the caps' polar (s, θ)), refined
//! locally from every grid minimum by compass search. Points: the axis, the core circle,
//! near each cap's inner and outer edge, on the edge planes, in the cut-away arc, in the
//! bore, far away, at R from 10⁻³ to 10³. The sign against an independent inside test.

use super::{BendFace, PipeBend};
use crate::geometry::draw::dvec3_in;
use crate::{NonFinitePoint, Torus};
use glam::DVec3;
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64;
use std::f64::consts::{FRAC_PI_4, PI, TAU};

/// The unit roundoff, 2⁻⁵³: the module's bound is 8ε·(|p − centre| + R + r_max).
const EPS: f64 = f64::EPSILON / 2.0;

#[derive(Debug, Clone, Copy)]
struct Spec {
    big: f64,
    r_min: f64,
    r_max: f64,
    phi0: f64,
    dphi: f64,
}

impl Spec {
    fn scaled(self, k: f64) -> Spec {
        Spec {
            big: self.big * k,
            r_min: self.r_min * k,
            r_max: self.r_max * k,
            ..self
        }
    }

    fn bend(&self) -> PipeBend {
        PipeBend::canonical(self.big, self.r_min, self.r_max, self.phi0, self.dphi).unwrap()
    }

    fn whole(&self) -> bool {
        self.dphi >= TAU
    }
}

fn specs() -> Vec<Spec> {
    let s = |big, r_min, r_max, phi0, dphi| Spec {
        big,
        r_min,
        r_max,
        phi0,
        dphi,
    };
    vec![
        s(30.0, 5.0, 10.0, FRAC_PI_4, 3.0 * FRAC_PI_4), // VecGeom's solid
        s(4.0, 0.5, 1.0, -1.0, 5.0),                    // Δφ > π
        s(4.0, 0.0, 1.0, 0.3, 0.2),                     // a thin slice, no bore
        s(10.0, 2.0, 3.0, 0.0, PI),                     // a half ring: coplanar caps
        s(4.0, 0.5, 1.0, 0.0, TAU),                     // the whole ring with a bore
        s(1.1, 0.3, 1.0, 2.0, 1.0),                     // ν = 1.1
    ]
}

/// The canonical frame's direction of φ: from +x toward −z.
fn dir(phi: f64) -> DVec3 {
    DVec3::new(phi.cos(), 0.0, -phi.sin())
}

/// The eight neighbours of a grid cell (row, column offsets), in order.
const NEIGHBOURS: [(i8, i8); 8] = [
    (-1, -1),
    (-1, 0),
    (-1, 1),
    (0, -1),
    (0, 1),
    (1, -1),
    (1, 0),
    (1, 1),
];

/// The least of `f` over `u ∈ [u0, u1]` and `v ∈ [v0, v1]` (clamped; or periodic with
/// period 2π where `periodic`): a grid, then compass search from its local minima (the 8
/// lowest).
fn grid_min(
    f: &dyn Fn(f64, f64) -> f64,
    (u0, u1): (f64, f64),
    (v0, v1): (f64, f64),
    periodic: bool,
    (nu, nv): (usize, usize),
) -> f64 {
    let du = (u1 - u0) / (nu - 1) as f64;
    let dv = if periodic {
        TAU / nv as f64
    } else {
        (v1 - v0) / (nv - 1) as f64
    };
    let clamp_v = |v: f64| if periodic { v } else { v.clamp(v0, v1) };
    let at = |i: usize, j: usize| f(u0 + du * i as f64, v0 + dv * j as f64);
    let grid: Vec<Vec<f64>> = (0..nu)
        .map(|i| (0..nv).map(|j| at(i, j)).collect())
        .collect();
    let mut minima = Vec::new();
    for i in 0..nu {
        for j in 0..nv {
            let g = grid[i][j];
            let mut low = true;
            for (a, b) in NEIGHBOURS {
                let ii = (i as i64 + i64::from(a)).clamp(0, nu as i64 - 1) as usize;
                let jj = if periodic {
                    (j as i64 + i64::from(b)).rem_euclid(nv as i64)
                } else {
                    (j as i64 + i64::from(b)).clamp(0, nv as i64 - 1)
                } as usize;
                low &= g <= grid[ii][jj];
            }
            if low {
                minima.push((g, i, j));
            }
        }
    }
    minima.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut best = f64::INFINITY;
    for &(g, i, j) in minima.iter().take(8) {
        let (mut u, mut v, mut fb) = (u0 + du * i as f64, v0 + dv * j as f64, g);
        let (mut su, mut sv) = (du, dv);
        for _ in 0..4000 {
            let mut moved = false;
            for (a, b) in NEIGHBOURS {
                let (a, b) = (f64::from(a), f64::from(b));
                let (uu, vv) = ((u + a * su).clamp(u0, u1), clamp_v(v + b * sv));
                let fv = f(uu, vv);
                if fv < fb {
                    (u, v, fb, moved) = (uu, vv, fv, true);
                }
            }
            if !moved {
                su *= 0.5;
                sv *= 0.5;
                if su < 1e-17 * (u1 - u0) && sv < 1e-17 * (v1 - v0).max(1.0) {
                    break;
                }
            }
        }
        best = best.min(fb);
    }
    best.sqrt()
}

/// The reference distance from `x` (canonical frame) to the bend's surface.
fn reference_distance(spec: &Spec, x: DVec3) -> f64 {
    let tube = |r: f64| {
        move |phi: f64, theta: f64| {
            let p = dir(phi) * (spec.big + r * theta.cos()) + DVec3::Y * (r * theta.sin());
            (x - p).length_squared()
        }
    };
    // A cap in polar coordinates (s, θ) about the core point in its plane, s over
    // [r_min, r_max]. A disk (no bore) is also searched in Cartesian (a, y), each point
    // outside moved radially onto the rim: polar stalls at its centre, Cartesian against
    // its rim, and each search's least is a surface point's distance.
    let cap = |phi: f64| {
        move |s: f64, theta: f64| {
            let p = dir(phi) * (spec.big + s * theta.cos()) + DVec3::Y * (s * theta.sin());
            (x - p).length_squared()
        }
    };
    let disk = |phi: f64| {
        move |a: f64, y: f64| {
            let s = a.hypot(y);
            let k = if s > spec.r_max { spec.r_max / s } else { 1.0 };
            let p = dir(phi) * (spec.big + a * k) + DVec3::Y * (y * k);
            (x - p).length_squared()
        }
    };
    let span = (spec.phi0, spec.phi0 + spec.dphi);
    let theta = (0.0, TAU);
    let mut d = grid_min(&tube(spec.r_max), span, theta, true, (96, 64));
    if spec.r_min > 0.0 {
        d = d.min(grid_min(&tube(spec.r_min), span, theta, true, (96, 64)));
    }
    if !spec.whole() {
        for phi in [span.0, span.1] {
            d = d.min(grid_min(
                &cap(phi),
                (spec.r_min, spec.r_max),
                theta,
                true,
                (32, 64),
            ));
            if spec.r_min == 0.0 {
                let side = (-spec.r_max, spec.r_max);
                d = d.min(grid_min(&disk(phi), side, side, false, (48, 48)));
            }
        }
    }
    d
}

/// Independent of the library: `r_min ≤ D ≤ r_max` and `(φ − φ₀) mod 2π ≤ Δφ`.
fn inside_reference(spec: &Spec, x: DVec3) -> bool {
    let d = (x.x.hypot(x.z) - spec.big).hypot(x.y);
    let phi = (-x.z).atan2(x.x);
    let rel = (phi - spec.phi0).rem_euclid(TAU);
    d >= spec.r_min && d <= spec.r_max && (spec.whole() || rel <= spec.dphi)
}

/// The structured adversarial points of a bend, and random ones.
fn points(spec: &Spec, rng: &mut Pcg64, random: usize) -> Vec<DVec3> {
    let (big, r0, r1) = (spec.big, spec.r_min, spec.r_max);
    let ends = [spec.phi0, spec.phi0 + spec.dphi];
    let mut pts = Vec::new();
    // The axis.
    for y in [0.0, 0.5 * r1, -r1, big, -3.0 * big, 1e3 * big] {
        pts.push(DVec3::new(0.0, y, 0.0));
    }
    // The core circle: in the segment, at its edges, in the cut-away arc.
    for k in 0..16 {
        pts.push(dir(spec.phi0 + spec.dphi * k as f64 / 15.0) * big);
        pts.push(dir(spec.phi0 + spec.dphi + (TAU - spec.dphi) * k as f64 / 15.0) * big);
    }
    // Near each cap's inner and outer edge, on its plane and off it on both sides.
    for phi in ends {
        let (s, g) = (dir(phi), dir(phi + PI / 2.0));
        for r in [r0, r1, 0.5 * (r0 + r1)] {
            for theta in [0.0, 0.7, PI / 2.0, PI, -2.0] {
                let rim = s * (big + r * theta.cos()) + DVec3::Y * (r * theta.sin());
                let radial = s * theta.cos() + DVec3::Y * theta.sin();
                for e in [0.0, 1e-9, -1e-9, 1e-3, -1e-3, 0.1, -0.1, 0.7] {
                    let e = e * r1;
                    pts.push(rim + g * e);
                    pts.push(rim + radial * e);
                    pts.push(rim + (g + radial) * e);
                }
            }
        }
        // The edge planes themselves, across the axis too.
        for a in [-2.0, -0.5, 0.0, 0.3, 1.0, 1.5] {
            for y in [0.0, 0.5 * r1, 2.0 * r1] {
                pts.push(s * (a * big) + DVec3::Y * y);
            }
        }
    }
    // The cut-away arc, the bore, and far away.
    for _ in 0..random {
        let rel = if spec.whole() {
            rng.random_range(0.0..TAU)
        } else {
            spec.dphi + rng.random_range(0.0..(TAU - spec.dphi))
        };
        let (phi, theta) = (spec.phi0 + rel, rng.random_range(0.0..TAU));
        let r = rng.random_range(0.0..2.0 * r1);
        pts.push(dir(phi) * (big + r * theta.cos()) + DVec3::Y * (r * theta.sin()));
        if r0 > 0.0 {
            let phi = spec.phi0 + rng.random_range(0.0..spec.dphi);
            let r = rng.random_range(0.0..r0);
            pts.push(dir(phi) * (big + r * theta.cos()) + DVec3::Y * (r * theta.sin()));
        }
        let far = dvec3_in(rng, DVec3::splat(1.0));
        pts.push(far.normalize() * big * rng.random_range(10.0..1e3));
        let s = 1.5 * (big + r1);
        pts.push(dvec3_in(rng, DVec3::splat(s)));
    }
    pts
}

#[test]
fn signed_distance_and_closest_point_match_the_brute_force_reference() {
    let mut rng = Pcg64::seed_from_u64(4103);
    let (mut n, mut worst, mut worst_point) = (0usize, 0.0f64, 0.0f64);
    for spec0 in specs() {
        for k in [1e-3, 1.0, 1e3] {
            let spec = spec0.scaled(k);
            let bend = spec.bend();
            let random = if k == 1.0 { 60 } else { 15 };
            for x in points(&spec, &mut rng, random) {
                let scale = x.length() + spec.big + spec.r_max;
                let near = bend.project_point(x).unwrap();
                let sd = near.signed_distance;
                assert!(sd.is_finite() && near.point.is_finite() && near.normal.is_finite());
                let want = reference_distance(&spec, x);
                let err = (sd.abs() - want).abs() / scale;
                worst = worst.max(err);
                assert!(
                    err < 8.0 * EPS,
                    "{spec:?} x = {x}: {near:?}, reference {want}"
                );
                if want > 1e-9 * scale {
                    assert_eq!(sd < 0.0, inside_reference(&spec, x), "{spec:?} {x}: {sd}");
                }
                assert_eq!(bend.signed_distance(x), Ok(sd));
                // The point is at that distance, and on its face.
                let gap = ((x - near.point).length() - sd.abs()).abs() / scale;
                worst_point = worst_point.max(gap);
                assert!(gap < 8.0 * EPS, "{spec:?} {x}: {near:?}");
                let p = near.point;
                let d = (p.x.hypot(p.z) - spec.big).hypot(p.y);
                let tol = 8.0 * EPS * scale;
                let rel = ((-p.z).atan2(p.x) - spec.phi0).rem_euclid(TAU);
                let in_segment = spec.whole() || rel <= spec.dphi + 1e-12 || rel >= TAU - 1e-12;
                match near.face {
                    BendFace::Outer => assert!(
                        (d - spec.r_max).abs() < tol && in_segment,
                        "{spec:?} {x}: {near:?} d {d} rel {rel}"
                    ),
                    BendFace::Inner => assert!(
                        (d - spec.r_min).abs() < tol && in_segment,
                        "{spec:?} {x}: {near:?} d {d} rel {rel}"
                    ),
                    face => {
                        let phi = if face == BendFace::StartCap {
                            spec.phi0
                        } else {
                            spec.phi0 + spec.dphi
                        };
                        let h = p.dot(dir(phi + PI / 2.0));
                        assert!(h.abs() < tol && p.dot(dir(phi)) > 0.0, "{near:?}");
                        assert!(d > spec.r_min - tol && d < spec.r_max + tol, "{near:?}");
                    }
                }
                assert!((near.normal.length() - 1.0).abs() < 1e-12);
                n += 1;
            }
        }
    }
    let eps = EPS;
    println!(
        "bend point queries: {n} points, worst |distance| error {:.1}ε·(|x| + R + r_max), closest point {:.1}ε",
        worst / eps,
        worst_point / eps
    );
}

#[test]
fn sign_agrees_with_the_inside_test_off_the_surface_band() {
    // 10⁶ points over the structured sets' neighbourhoods and the bounding box.
    let mut rng = Pcg64::seed_from_u64(4104);
    let (mut checked, mut inside) = (0usize, 0usize);
    for spec0 in specs() {
        for k in [1e-3, 1.0, 1e3] {
            let spec = spec0.scaled(k);
            let bend = spec.bend();
            let band = 1e-9 * (spec.big + spec.r_max);
            let mut n = 0;
            while n < 1_000_000 / 18 {
                // Half over the bounding box, half about the tube.
                let x = if n % 2 == 0 {
                    let s = 1.3 * (spec.big + spec.r_max);
                    DVec3::new(
                        rng.random_range(-s..s),
                        rng.random_range(-spec.r_max * 1.3..spec.r_max * 1.3),
                        rng.random_range(-s..s),
                    )
                } else {
                    let (phi, theta) = (rng.random_range(0.0..TAU), rng.random_range(0.0..TAU));
                    let r = rng.random_range(0.0..1.3 * spec.r_max);
                    dir(phi) * (spec.big + r * theta.cos()) + DVec3::Y * (r * theta.sin())
                };
                // Off the band: away from both tubes and both caps' planes.
                let d = (x.x.hypot(x.z) - spec.big).hypot(x.y);
                let planes =
                    [spec.phi0, spec.phi0 + spec.dphi].map(|p| x.dot(dir(p + PI / 2.0)).abs());
                if (d - spec.r_max).abs() < band
                    || (d - spec.r_min).abs() < band
                    || (!spec.whole() && planes.iter().any(|&h| h < band))
                {
                    continue;
                }
                let sd = bend.signed_distance(x).unwrap();
                let want = inside_reference(&spec, x);
                assert_eq!(sd < 0.0, want, "{spec:?} {x}: {sd}");
                assert_eq!(bend.contains(x), want, "{spec:?} {x}");
                inside += usize::from(want);
                n += 1;
            }
            checked += n;
        }
    }
    println!("bend sign: {checked} points off the band, {inside} inside, 0 wrong");
    assert!(inside > 100_000);
}

#[test]
fn the_whole_ring_without_bore_is_the_torus() {
    let mut rng = Pcg64::seed_from_u64(4105);
    let (mut agree, mut worst, eps) = (0, 0.0f64, f64::EPSILON / 2.0);
    for (big, small) in [(4.0, 1.0), (1e-3, 0.5e-3), (1e3, 1.0), (1.01, 1.0)] {
        let c = DVec3::new(rng.random_range(-9.0..9.0), 1.0, 2.0) * big;
        let axis = DVec3::new(0.3, rng.random_range(-1.0..1.0), -0.7);
        let torus = Torus::new_f64(c, axis, big, small).unwrap();
        let bend = PipeBend::new_f64(
            c,
            axis,
            DVec3::new(1.0, 0.2, 0.1),
            big,
            0.0,
            small,
            0.4,
            TAU,
        )
        .unwrap();
        let to_world = |x: DVec3| torus.point_to_world_f64(x);
        let mut pts = vec![to_world(DVec3::ZERO), to_world(DVec3::new(big, 0.0, 0.0))];
        for _ in 0..20_000 {
            let s = 2.0 * (big + small);
            pts.push(to_world(dvec3_in(&mut rng, DVec3::splat(s))));
        }
        for p in pts {
            let (want, got) = (
                torus.signed_distance(p).unwrap(),
                bend.signed_distance(p).unwrap(),
            );
            let scale = (p - c).length() + big + small;
            let err = (got - want).abs() / scale;
            worst = worst.max(err);
            assert!(err < 8.0 * eps, "{p}: {got} vs {want}");
            if want.abs() > 1e-12 * scale {
                assert_eq!(got < 0.0, want < 0.0, "{p}");
                agree += 1;
            }
            let (a, b) = (
                torus.project_point(p).unwrap(),
                bend.project_point(p).unwrap(),
            );
            assert!((a.point - b.point).length() <= 1e-12 * (big + small + p.length()));
        }
    }
    println!(
        "whole ring: {agree} signs agree off the band, worst difference {:.1}ε·scale",
        worst / eps
    );
    assert!(agree > 70_000);
}

#[test]
fn a_posed_bend_answers_as_its_canonical_one() {
    let mut rng = Pcg64::seed_from_u64(4106);
    let spec = specs()[0];
    let canonical = spec.bend();
    let (c, axis, phi_zero) = (
        DVec3::new(3.0, -7.0, 11.0),
        DVec3::new(0.2, 0.9, -0.4),
        DVec3::new(1.0, 0.5, 0.3),
    );
    let posed = PipeBend::new_f64(
        c, axis, phi_zero, spec.big, spec.r_min, spec.r_max, spec.phi0, spec.dphi,
    )
    .unwrap();
    let a = axis.normalize();
    let e0 = phi_zero.reject_from(a).normalize();
    let e1 = a.cross(e0);
    for x in points(&spec, &mut rng, 50) {
        let p = c + e0 * x.x + a * x.y - e1 * x.z;
        let (want, got) = (
            canonical.project_point(x).unwrap(),
            posed.project_point(p).unwrap(),
        );
        let tol = 1e-13 * (x.length() + spec.big + spec.r_max);
        assert!(
            (want.signed_distance - got.signed_distance).abs() < tol,
            "{x}: {want:?} {got:?}"
        );
        // Near the axis or the core circle the closest point is a near tie: the frames'
        // rounding may pick another.
        let rho = x.x.hypot(x.z);
        if rho < 1e-9 * spec.big || (rho - spec.big).hypot(x.y) < 1e-9 * spec.big {
            continue;
        }
        let back = c + e0 * want.point.x + a * want.point.y - e1 * want.point.z;
        assert!(
            (back - got.point).length() < tol || want.face != got.face,
            "{x}: {want:?} {got:?} back {back}"
        );
    }
}

#[test]
fn non_finite_points_are_refused() {
    let bend = specs()[0].bend();
    for p in [
        DVec3::new(f64::NAN, 0.0, 0.0),
        DVec3::new(0.0, f64::INFINITY, 0.0),
        DVec3::splat(f64::NEG_INFINITY),
    ] {
        assert!(matches!(bend.signed_distance(p), Err(NonFinitePoint(_))));
        assert!(matches!(bend.project_point(p), Err(NonFinitePoint(_))));
    }
}
