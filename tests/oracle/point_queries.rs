//! The ring torus's point queries (`Torus::signed_distance`, `project_point`,
//! `surface_coords`, `point_at`, `contains`, `world_aabb`) against an independent
//! reference: the surface sampled densely over (θ, φ) through `point_at`'s own formula
//! written out here, then refined by coordinate search. Adversarial points: the axis, the
//! core circle, the equators, the top circle, the saddle, far away, at R from 10⁻³ to 10³.

use glam::DVec3;
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64;
use std::f64::consts::{PI, TAU};
use torus_cull::Torus;
use torus_cull::family::Toroid;

/// The reference distance from the torus-frame point `x` to the surface of (R, r): the
/// minimum of |x − S(θ, φ)| over a 96 × 96 grid, refined by shrinking steps in θ and φ.
fn reference_distance(big: f64, small: f64, x: DVec3) -> f64 {
    reference_distance_family(big, small, small, x)
}

/// The same for a family member (R, a, b): the apple's points alone (ρ = R + a cos θ ≥ 0).
fn reference_distance_family(big: f64, a: f64, b: f64, x: DVec3) -> f64 {
    let s = |t: f64, f: f64| {
        let rho = big + a * t.cos();
        if rho < 0.0 {
            return f64::INFINITY;
        }
        (x - DVec3::new(rho * f.cos(), b * t.sin(), rho * f.sin())).length()
    };
    let n = 96;
    let (mut best, mut bt, mut bf) = (f64::INFINITY, 0.0, 0.0);
    for i in 0..n {
        for j in 0..n {
            let (t, f) = (TAU * i as f64 / n as f64, TAU * j as f64 / n as f64);
            let d = s(t, f);
            if d < best {
                (best, bt, bf) = (d, t, f);
            }
        }
    }
    let mut step = TAU / n as f64;
    while step > 1e-15 {
        let mut moved = false;
        for (dt, df) in [(step, 0.0), (-step, 0.0), (0.0, step), (0.0, -step)] {
            let d = s(bt + dt, bf + df);
            if d < best {
                (best, bt, bf, moved) = (d, bt + dt, bf + df, true);
            }
        }
        if !moved {
            step *= 0.5;
        }
    }
    best
}

/// `n` random points, uniform in the box |x|, |z| ≤ 2, |y| ≤ `half_height`, times `size`.
fn random_points(rng: &mut Pcg64, n: usize, half_height: f64, size: f64) -> Vec<DVec3> {
    (0..n)
        .map(|_| {
            let x = rng.random_range(-2.0..2.0);
            let y = rng.random_range(-half_height..half_height);
            DVec3::new(x, y, rng.random_range(-2.0..2.0)) * size
        })
        .collect()
}

#[test]
fn point_queries_against_dense_sampling_at_adversarial_points() {
    let mut rng = Pcg64::seed_from_u64(41);
    let (mut checked, mut worst) = (0, 0.0f64);
    for scale in [1e-3, 1.0, 1e3] {
        for nu in [1.25, 4.0, 32.0] {
            let (big, small) = (scale, scale / nu);
            let center = DVec3::new(0.3, -1.1, 2.0) * scale;
            let torus = Torus::new_f64(center, DVec3::new(0.2, 1.0, -0.4), big, small).unwrap();
            let size = big + small;
            // Torus-frame points: the axis, the core circle, both equators, the top, the
            // saddle's neighbourhood, far away, and random ones.
            let mut points = vec![
                DVec3::ZERO,
                DVec3::Y * 0.5 * small,
                DVec3::Y * 7.0 * size,
                DVec3::new(big, 0.0, 0.0),
                DVec3::new(0.0, 0.0, -big),
                DVec3::new(big + small, 0.0, 0.0),
                DVec3::new(big - small, 0.0, 0.0),
                DVec3::new(big, small, 0.0),
                DVec3::new(big - small * 0.999, 1e-6 * small, 0.0),
                DVec3::new(1e4 * size, 3e3 * size, -2e4 * size),
            ];
            points.extend(random_points(&mut rng, 60, 1.0, size));
            for x in points {
                let p = torus.point_to_world_f64(x);
                let got = torus.project_point(p).unwrap();
                let want = reference_distance(big, small, torus.point_to_local_f64(p).unwrap());
                let inside = torus.contains(p).unwrap();
                let err = (got.signed_distance.abs() - want).abs() / size;
                worst = worst.max(err);
                assert!(err < 1e-9, "R {big}, r {small}, x {x}: {got:?} vs {want}");
                // The closest point is on the surface, at that distance, with a unit normal
                // pointing from it toward the point (outward where the point is outside).
                let on = torus.signed_distance(got.point).unwrap();
                assert!(
                    on.abs() < 1e-12 * (size + (p - center).length()),
                    "{x}: {on}"
                );
                let gap = ((p - got.point).length() - want).abs() / size;
                assert!(gap < 1e-9, "{x}: {gap}");
                assert!((got.normal.length() - 1.0).abs() < 1e-12);
                let toward = (p - got.point).dot(got.normal);
                assert!(toward * got.signed_distance >= -1e-12 * size, "{x}");
                if want > 1e-9 * size {
                    assert_eq!(inside, got.signed_distance < 0.0, "{x}");
                }
                // (θ, φ) of the closest point give it back.
                let (theta, phi) = torus.surface_coords(p).unwrap();
                assert!(theta > -PI && theta <= PI && phi > -PI && phi <= PI);
                let back = torus.point_at(theta, phi);
                assert!(
                    (back - got.point).length() < 1e-9 * size,
                    "{x}: {back} {:?}",
                    got.point
                );
                checked += 1;
            }
            // The box holds the torus: sampled surface points in it.
            let (lo, hi) = torus.world_aabb();
            for _ in 0..500 {
                let q = torus.point_at(rng.random_range(0.0..TAU), rng.random_range(0.0..TAU));
                let q32 = q.as_vec3();
                assert!(
                    q.cmpge(lo.as_dvec3()).all() && q.cmple(hi.as_dvec3()).all(),
                    "{q}"
                );
                assert!(q32.cmpge(lo).all() && q32.cmple(hi).all());
            }
        }
    }
    eprintln!("point queries: {checked} points, worst distance error {worst:.2e} of the size");
    assert!(
        Torus::canonical(4.0, 1.0)
            .unwrap()
            .signed_distance(DVec3::NAN)
            .is_err()
    );
}

#[test]
fn family_point_queries_against_dense_sampling() {
    let mut rng = Pcg64::seed_from_u64(4101);
    let (mut checked, mut worst) = (0, 0.0f64);
    for (big, a, b) in [
        (4.0, 1.0, 0.25),
        (4.0, 1.0, 4.0),
        (1.25, 1.0, 2.0),
        (16.0, 1.0, 0.5),
        (1.0, 1.0, 1.0),
        (0.75, 1.0, 1.0),
        (0.5, 1.0, 1.0),
    ] {
        for scale in [1e-3, 1.0, 1e3] {
            let (big, a, b) = (big * scale, a * scale, b * scale);
            let member = Toroid::canonical(big, a, b).unwrap();
            let size = big + a.max(b);
            let mut points = vec![
                DVec3::ZERO,
                DVec3::Y * 0.3 * b,
                DVec3::Y * 5.0 * size,
                DVec3::new(big, 0.0, 0.0),
                DVec3::new(big + a, 0.0, 0.0),
                DVec3::new(big, b, 0.0),
                DVec3::new(big + 0.5 * a, 0.2 * b, 0.0),
                DVec3::new(1e3 * size, -2e2 * size, 0.0),
            ];
            points.extend(random_points(&mut rng, 40, 1.5, size));
            for x in points {
                let got = member.project_point(x).unwrap();
                let want = reference_distance_family(big, a, b, x);
                let err = (got.signed_distance.abs() - want).abs() / size;
                worst = worst.max(err);
                assert!(err < 1e-9, "({big}, {a}, {b}) {x}: {got:?} vs {want}");
                assert!(((x - got.point).length() - want).abs() < 1e-9 * size, "{x}");
                if want > 1e-9 * size {
                    assert_eq!(
                        member.contains(x).unwrap(),
                        got.signed_distance < 0.0,
                        "{x}"
                    );
                }
                checked += 1;
            }
        }
    }
    eprintln!("family point queries: {checked} points, worst {worst:.2e} of the size");
    // Elliptical horns and spindles answer too (tests/oracle/family_points.rs).
    for (big, a, b) in [(0.75, 1.0, 2.0), (0.5, 1.0, 2.0), (1.0, 1.0, 0.25)] {
        let member = Toroid::canonical(big, a, b).unwrap();
        let want = reference_distance_family(big, a, b, DVec3::new(0.3, 0.2, 0.1));
        let got = member.signed_distance(DVec3::new(0.3, 0.2, 0.1)).unwrap();
        assert!(
            (got.abs() - want).abs() < 1e-9,
            "({big}, {a}, {b}): {got} vs {want}"
        );
    }
}

/// On the core circle every surface point of its meridian's circle is closest: the one
/// returned must still be a surface point (issue 41: the offset's rounding once left the
/// meridian there, and the point landed up to 0.036·r off the surface), with the distance
/// −r, at 1 000 angles, on a canonical and a posed torus at three scales.
#[test]
fn core_circle_points_project_onto_the_surface() {
    for scale in [1e-3, 1.0, 1e3] {
        let (big, small) = (4.0 * scale, scale);
        for torus in [
            Torus::new_f64(DVec3::ZERO, DVec3::Y, big, small).unwrap(),
            Torus::new_f64(
                DVec3::new(0.3, -1.1, 2.0) * scale,
                DVec3::new(0.2, 1.0, -0.4),
                big,
                small,
            )
            .unwrap(),
        ] {
            for k in 0..1000 {
                let phi = k as f64 * TAU / 1000.0;
                let x = DVec3::new(big * phi.cos(), 0.0, big * phi.sin());
                let p = torus.point_to_world_f64(x);
                let got = torus.project_point(p).unwrap();
                let on = torus.signed_distance(got.point).unwrap();
                assert!(on.abs() < 1e-12 * (big + small), "phi {phi}: {got:?}, {on}");
                assert!(
                    (got.signed_distance + small).abs() < 1e-12 * big,
                    "phi {phi}: {got:?}"
                );
            }
        }
    }
}

/// Issue 41's count: 10⁶ adversarial points on ring tori (ν 1.01…1000, R 10⁻³…10³),
/// cycling through five kinds: near the surface (D = r·(1 ± 10⁻⁸…10⁻¹)), near the axis,
/// near the core circle, in the box, and far away. Inside/outside is held to the implicit
/// quartic's sign, `(|x|² + R² − r²)² − 4R²(x² + z²) < 0`, written out here (its rounding
/// is far below the band of 10⁻⁹·(R + r) left out), and the signed distance to the
/// meridian's closed form, to 10⁻¹⁴ of the size.
#[test]
fn a_million_adversarial_points_inside_outside_and_distance() {
    let mut rng = Pcg64::seed_from_u64(0x41_0001);
    let (mut checked, mut in_band, mut inside_count, mut worst) = (0u64, 0u64, 0u64, 0.0f64);
    // |v| > 10⁻³: the lab's rejection-sampled direction.
    let unit = |rng: &mut Pcg64| torus_cull_lab::random::ball_direction(rng, 1e-6);
    for scale in [1e-3, 1.0, 1e3] {
        for nu in [1.01, 1.25, 4.0, 32.0, 1000.0] {
            let (big, small) = (scale, scale / nu);
            let torus = Torus::new_f64(DVec3::ZERO, DVec3::Y, big, small).unwrap();
            let size = big + small;
            for k in 0..66_667 {
                let phi = rng.random_range(0.0..TAU);
                let radial = DVec3::new(phi.cos(), 0.0, phi.sin());
                let x = match k % 5 {
                    0 => {
                        let theta = rng.random_range(0.0..TAU);
                        let sign = if rng.random::<bool>() { 1.0 } else { -1.0 };
                        let d = small * (1.0 + sign * 10f64.powf(rng.random_range(-8.0..-1.0)));
                        radial * (big + d * theta.cos()) + DVec3::Y * (d * theta.sin())
                    }
                    1 => {
                        radial * (size * 10f64.powf(rng.random_range(-12.0..-1.0)))
                            + DVec3::Y * (size * rng.random_range(-2.0..2.0))
                    }
                    2 => {
                        radial * big
                            + unit(&mut rng) * (small * 10f64.powf(rng.random_range(-12.0..-1.0)))
                    }
                    3 => {
                        DVec3::new(
                            rng.random_range(-2.0..2.0),
                            rng.random_range(-1.0..1.0),
                            rng.random_range(-2.0..2.0),
                        ) * size
                    }
                    _ => unit(&mut rng) * (size * 10f64.powf(rng.random_range(1.0..4.0))),
                };
                let rho_sq = x.x * x.x + x.z * x.z;
                let s = x.length_squared() + big * big - small * small;
                let implicit = s * s - 4.0 * big * big * rho_sq;
                let meridian = (rho_sq.sqrt() - big).hypot(x.y) - small;
                let got = torus.signed_distance(x).unwrap();
                let err = (got - meridian).abs() / (size + x.length());
                worst = worst.max(err);
                assert!(
                    err < 1e-14,
                    "R {big}, r {small}, x {x}: {got} vs {meridian}"
                );
                if meridian.abs() > 1e-9 * size {
                    let inside = torus.contains(x).unwrap();
                    assert_eq!(inside, implicit < 0.0, "R {big}, r {small}, x {x}");
                    inside_count += u64::from(inside);
                } else {
                    in_band += 1;
                }
                checked += 1;
            }
        }
    }
    eprintln!(
        "point queries: {checked} points, {inside_count} inside, {in_band} in the band; worst \
         distance error {worst:.1e} of the size"
    );
    assert!(checked >= 1_000_000 && inside_count > 100_000);
}
