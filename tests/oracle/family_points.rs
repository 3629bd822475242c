//! Point queries of every family member (`Toroid::signed_distance`, `project_point`,
//! `contains`), elliptical horns and spindles among them, against a brute-force
//! reference: the member's meridian arc (the apple's, ρ = R + a cos θ ≥ 0) sampled at 256
//! angles, each local minimum of the samples refined by golden-section search, and the
//! cusps. The closest point of a solid of revolution lies in the point's meridian
//! half-plane (the reflected half-plane's points are farther), so the reference works in
//! (ρ, y) and never calls the library.
//!
//! Points: the axis (through the lemon and the cusps), the cusps and near them, the core
//! circle, near the surface at 10⁻⁸…10⁻¹ of the size inside and out (the apple's arc),
//! random in the box and far away; members ν ∈ {0.01, 0.1, 0.3, 0.5, 0.75, 1} × b/a ∈ {¼, ½,
//! 1, 2, 4} and rings, at scales 10⁻³, 1, 10³. Bound: |distance − reference| ≤
//! 10⁻¹³·(R + max(a, b) + |q|), q the point's offset from the tube's centre in its meridian
//! (the module docs of `torus_cull::family`'s point queries).

use glam::{DVec2, DVec3};
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64;
use std::f64::consts::{PI, TAU};
use torus_cull::family::Toroid;

/// The reference distance from (ρ, y) to the arc of (R, a, b) with ρ ≥ 0 (module docs).
fn reference(big: f64, a: f64, b: f64, p: DVec2) -> f64 {
    let top = if big >= a { PI } else { (-big / a).acos() };
    let dist = |t: f64| {
        let t = t.clamp(-top, top);
        let rho = (big + a * t.cos()).max(0.0);
        (p - DVec2::new(rho, b * t.sin())).length()
    };
    const N: usize = 256;
    let step = 2.0 * top / N as f64;
    let samples: Vec<f64> = (0..=N).map(|i| dist(-top + step * i as f64)).collect();
    let mut best = samples[0].min(samples[N]);
    for i in 0..=N {
        let left = if i == 0 {
            f64::INFINITY
        } else {
            samples[i - 1]
        };
        let right = if i == N {
            f64::INFINITY
        } else {
            samples[i + 1]
        };
        if samples[i] > left || samples[i] > right {
            continue;
        }
        // Golden section on [θᵢ − step, θᵢ + step].
        // (Within the arc: past a cusp the clamped distance is flat, no unimodal bracket.)
        let (mut lo, mut hi) = (
            (-top + step * (i as f64 - 1.0)).max(-top),
            (-top + step * (i as f64 + 1.0)).min(top),
        );
        let g = 0.5 * (5f64.sqrt() - 1.0);
        let (mut x1, mut x2) = (hi - g * (hi - lo), lo + g * (hi - lo));
        let (mut f1, mut f2) = (dist(x1), dist(x2));
        for _ in 0..90 {
            if f1 < f2 {
                hi = x2;
                (x2, f2) = (x1, f1);
                x1 = hi - g * (hi - lo);
                f1 = dist(x1);
            } else {
                lo = x1;
                (x1, f1) = (x2, f2);
                x2 = lo + g * (hi - lo);
                f2 = dist(x2);
            }
        }
        best = best.min(f1).min(f2).min(samples[i]);
    }
    best
}

/// The members: (R, a, b).
fn members() -> Vec<(f64, f64, f64)> {
    let mut all = Vec::new();
    for nu in [0.01, 0.1, 0.3, 0.5, 0.75, 1.0] {
        for aspect in [0.25, 0.5, 1.0, 2.0, 4.0] {
            all.push((nu, 1.0, aspect));
        }
    }
    all.extend([(1.25, 1.0, 0.25), (4.0, 1.0, 4.0), (4.0, 1.0, 0.5)]);
    all
}

/// One torus-frame point of kind `k` for the member.
fn point(rng: &mut Pcg64, (big, a, b): (f64, f64, f64), k: usize) -> DVec3 {
    let size = big + a.max(b);
    let top = if big >= a { PI } else { (-big / a).acos() };
    let v_c = b * (1.0 - (big / a).powi(2)).max(0.0).sqrt();
    let phi = rng.random_range(0.0..TAU);
    let radial = DVec3::new(phi.cos(), 0.0, phi.sin());
    let tiny = |rng: &mut Pcg64| size * 10f64.powf(rng.random_range(-8.0..-1.0));
    let sign = |rng: &mut Pcg64| if rng.random::<bool>() { 1.0 } else { -1.0 };
    match k % 6 {
        // The axis: anywhere along it (the lemon, the cusps, beyond).
        0 => DVec3::Y * (size * rng.random_range(-2.0..2.0)),
        // At a cusp, or 10⁻⁸…10⁻¹ of the size from it in any direction.
        1 => {
            let at = DVec3::Y * (v_c * sign(rng));
            if rng.random_range(0..8) == 0 {
                at
            } else {
                let dir = DVec3::new(
                    rng.random_range(-1.0..1.0),
                    rng.random_range(-1.0..1.0),
                    rng.random_range(-1.0..1.0),
                )
                .normalize_or(DVec3::Y);
                at + dir * tiny(rng)
            }
        }
        // The core circle, or 10⁻⁸…10⁻¹ off it.
        2 => {
            let off = if rng.random::<bool>() { 0.0 } else { tiny(rng) };
            let t = rng.random_range(0.0..TAU);
            radial * (big + off * t.cos()) + DVec3::Y * (off * t.sin())
        }
        // Near the apple's arc, along its normal, inside or out.
        3 => {
            let t = rng.random_range(-top..top);
            let rho = (big + a * t.cos()).max(0.0);
            let n = DVec2::new(t.cos() / a, t.sin() / b).normalize();
            let off = tiny(rng) * sign(rng);
            let m = DVec2::new(rho, b * t.sin()) + n * off;
            radial * m.x.max(0.0) + DVec3::Y * m.y
        }
        // In the box.
        4 => DVec3::new(
            rng.random_range(-1.2..1.2) * size,
            rng.random_range(-1.2..1.2) * b,
            rng.random_range(-1.2..1.2) * size,
        ),
        // Far away.
        _ => {
            let d = DVec3::new(
                rng.random_range(-1.0..1.0),
                rng.random_range(-1.0..1.0),
                rng.random_range(-1.0..1.0),
            )
            .normalize_or(DVec3::X);
            d * (size * 10f64.powf(rng.random_range(0.5..3.0)))
        }
    }
}

/// Checks `count` points per member and scale; returns (points, worst error / bound).
fn check(count: usize, seed: u64) -> (usize, f64) {
    let mut rng = Pcg64::seed_from_u64(seed);
    let (mut checked, mut worst) = (0usize, 0.0f64);
    for (big, a, b) in members() {
        for scale in [1e-3, 1.0, 1e3] {
            let (big, a, b) = (big * scale, a * scale, b * scale);
            let size = big + a.max(b);
            // Posed: the point queries work in the torus frame of a posed member too.
            let center = DVec3::new(0.3, -1.1, 2.0) * scale;
            let axis = DVec3::new(0.2, 1.0, -0.4).normalize();
            let member = Toroid::new_f64(center, axis, big, a, b).unwrap();
            let rot = glam::DQuat::from_rotation_arc(DVec3::Y, axis);
            for k in 0..count {
                let local = point(&mut rng, (big / scale, a / scale, b / scale), k) * scale;
                let world = center + rot * local;
                // The reference in the meridian of the point as the member sees it
                // (its own rotation of the world point: a rounding of the pose's size).
                let m = DVec2::new(local.x.hypot(local.z), local.y);
                let want = reference(big, a, b, m);
                let inside = ((m.x - big) / a).powi(2) + (m.y / b).powi(2) <= 1.0;
                let got = member.project_point(world).unwrap_or_else(|e| {
                    panic!("({big}, {a}, {b}) {local}: {e}");
                });
                let q = (m - DVec2::new(big, 0.0)).length();
                // The bound, plus the pose's rounding (the point's frame offsets in f64).
                let bound = 1e-13 * (size + q) + 1e-14 * (center.length() + world.length());
                let err = (got.signed_distance.abs() - want).abs();
                worst = worst.max(err / bound);
                assert!(
                    err <= bound,
                    "({big}, {a}, {b}) {local}: {} vs {want} ({:.1} bounds)",
                    got.signed_distance,
                    err / bound
                );
                assert!(got.normal.is_finite() && (got.normal.length() - 1.0).abs() < 1e-12);
                assert!(((world - got.point).length() - want).abs() <= 2.0 * bound + 1e-9 * want);
                if want > 1e-9 * size {
                    assert_eq!(
                        got.signed_distance < 0.0,
                        inside,
                        "({big}, {a}, {b}) {local}"
                    );
                    assert_eq!(member.contains(world).unwrap(), inside);
                }
                checked += 1;
            }
        }
    }
    (checked, worst)
}

/// Every member answers (none `Unsupported`), within the bound, on 33 members × 3 scales
/// × 120 points (about 12 000).
#[test]
fn every_member_s_point_queries_against_a_brute_force_reference() {
    let (checked, worst) = check(120, 54_100);
    eprintln!("family point queries: {checked} points, worst error {worst:.3} of the bound");
    assert!(checked > 10_000);
}

/// The count: 10⁶ points (33 members × 3 scales × 10 102), in release about
/// 20 s (2 shared cores): `cargo test --release --test oracle a_million_family -- --ignored`.
#[test]
#[ignore]
fn a_million_family_points_against_a_brute_force_reference() {
    let (checked, worst) = check(10_102, 54_101);
    eprintln!("family point queries: {checked} points, worst error {worst:.3} of the bound");
    assert!(checked >= 1_000_000);
}
