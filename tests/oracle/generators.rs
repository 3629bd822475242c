//! Each workload generator makes what its doc comment says.

// Every check here runs against the harness's oracle or CLI.

use glam::DVec3;
use torus_cull::Named;
use torus_cull::{Ray, Torus};
use torus_cull_lab::oracle::{OracleClass, classify};
use torus_cull_lab::workload::spec::Workload;
use torus_cull_lab::workload::{Case, GRAZING_OFFSETS, Pose, generate, generate_labeled};

const NUS: [f64; 4] = [1.1, 2.0, 8.0, 32.0];

/// Origin and direction of `ray` in the torus frame, f64.
fn local(torus: &Torus, ray: &Ray) -> (DVec3, DVec3) {
    torus.line_to_local_f64(ray)
}

#[test]
fn deterministic_by_seed_case_and_nu() {
    for &case in Case::ALL {
        let a = generate(case, 2.0, 200, 5, Pose::Random).unwrap();
        let b = generate(case, 2.0, 200, 5, Pose::Random).unwrap();
        assert_eq!(a.rays, b.rays, "{case}");
        assert_eq!(a.torus, b.torus);
        let c = generate(case, 2.5, 200, 5, Pose::Random).unwrap();
        assert_ne!(a.rays, c.rays, "{case}");
        let d = generate(case, 2.0, 200, 6, Pose::Random).unwrap();
        assert_ne!(a.rays, d.rays, "{case}");
        let e = generate(case, 2.0, 200, 5, Pose::Canonical).unwrap();
        assert_eq!(e.torus.center(), glam::Vec3::ZERO);
        assert_eq!(e.torus.axis(), glam::Vec3::Y);
        assert_ne!(
            a.torus.axis(),
            glam::Vec3::Y,
            "random pose must move the axis"
        );
    }
    assert!(generate(Case::Hole, 1.0, 10, 1, Pose::Random).is_err());
    assert!(generate(Case::Uniform, f64::NAN, 10, 1, Pose::Random).is_err());
}

#[test]
fn hole_rays_cross_inside_the_hole_and_miss() {
    for nu in NUS {
        let b = generate(Case::Hole, nu, 3_000, 11, Pose::Random).unwrap();
        let (big_r, r) = (1.0, 1.0 / nu);
        for ray in &b.rays {
            let (o, d) = local(&b.torus, ray);
            let t = -o.y / d.y;
            let p = o + d * t;
            let rho = (p.x * p.x + p.z * p.z).sqrt();
            assert!(t > 0.0, "crossing behind the origin");
            assert!(
                rho < (big_r - r) * (1.0 + 1e-5),
                "nu={nu}: crosses at rho={rho}"
            );
            assert_eq!(classify(&b.torus, ray).class, OracleClass::Miss);
        }
    }
}

#[test]
fn outer_band_rays_lie_in_band_planes() {
    for nu in NUS {
        let b = generate(Case::OuterBand, nu, 3_000, 12, Pose::Random).unwrap();
        let (big_r, r) = (1.0, 1.0 / nu);
        for ray in &b.rays {
            let (o, d) = local(&b.torus, ray);
            let h = (d.x * d.x + d.z * d.z).sqrt();
            let a = (o.x * d.z - o.z * d.x).abs() / h;
            // f32 placement moves the plane by ~1e-7·(R + r); near-vertical lines amplify it.
            let tol = 1e-6 * (big_r + r) / (h / d.length()).max(1e-3);
            assert!(a >= big_r - tol && a < big_r + r + tol, "nu={nu}: a={a}");
        }
    }
}

#[test]
fn grazing_margins_match_requested_offsets() {
    for nu in NUS {
        let b = generate(Case::Grazing, nu, 3_000, 13, Pose::Random).unwrap();
        // The torus's own (f32) tube radius, which the offsets are fractions of.
        let r = b.torus.minor_radius() as f64;
        assert_eq!(b.offsets.len(), b.rays.len());
        for (i, (ray, offset)) in b.rays.iter().zip(&b.offsets).enumerate() {
            assert_eq!(*offset, GRAZING_OFFSETS[i % GRAZING_OFFSETS.len()] * r);
            let margin = classify(&b.torus, ray).margin;
            assert!(
                (margin - offset).abs() <= 1e-6 * (1.0 + r),
                "nu={nu}: margin {margin:e} vs offset {offset:e}"
            );
        }
        // The ±1e-2 rays are resolved: their class follows the sign of the offset.
        for (ray, offset) in b.rays.iter().zip(&b.offsets).step_by(GRAZING_OFFSETS.len()) {
            assert!(*offset > 0.0);
            assert_eq!(classify(&b.torus, ray).class, OracleClass::Miss);
        }
        for (ray, _) in b
            .rays
            .iter()
            .zip(&b.offsets)
            .skip(1)
            .step_by(GRAZING_OFFSETS.len())
        {
            assert_eq!(classify(&b.torus, ray).class, OracleClass::Hit);
        }
    }
}

#[test]
fn uniform_lines_meet_the_sphere_with_isotropic_directions() {
    let n = 40_000;
    let b = generate(Case::Uniform, 3.0, n, 14, Pose::Random).unwrap();
    let outer = 1.0 + 1.0 / 3.0;
    const BINS: usize = 10;
    let mut z_bins = [0usize; BINS];
    let mut azimuth_bins = [0usize; BINS];
    let mut sum = DVec3::ZERO;
    for ray in &b.rays {
        let (o, d) = local(&b.torus, ray);
        let u = d.normalize();
        let foot = o - u * o.dot(u);
        assert!(foot.length() <= outer * (1.0 + 1e-6), "misses the sphere");
        // World-space direction: isotropy must survive the random pose.
        let w = ray.dir().as_dvec3().normalize();
        sum += w;
        z_bins[(((w.z + 1.0) / 2.0 * BINS as f64) as usize).min(BINS - 1)] += 1;
        let az = w.y.atan2(w.x) + std::f64::consts::PI;
        azimuth_bins[((az / std::f64::consts::TAU * BINS as f64) as usize).min(BINS - 1)] += 1;
    }
    // Chi-square with 9 degrees of freedom: 27.9 is the 0.1 % critical value.
    let chi2 = |bins: &[usize; BINS]| {
        let e = n as f64 / BINS as f64;
        bins.iter()
            .map(|&o| (o as f64 - e).powi(2) / e)
            .sum::<f64>()
    };
    assert!(chi2(&z_bins) < 27.9, "z bins {z_bins:?}");
    assert!(chi2(&azimuth_bins) < 27.9, "azimuth bins {azimuth_bins:?}");
    assert!((sum / n as f64).length() < 0.02, "mean direction {sum}");
}

#[test]
fn camera_frustum_contains_the_torus() {
    for nu in NUS {
        let b = generate(Case::Camera, nu, 500, 15, Pose::Random).unwrap();
        let cam = b.camera.expect("camera batches carry their view");
        let t = &b.torus;
        let (big_r, r) = (1.0f32, (1.0 / nu) as f32);
        for i in 0..72 {
            for j in 0..24 {
                let phi = i as f32 * std::f32::consts::TAU / 72.0;
                let th = j as f32 * std::f32::consts::TAU / 24.0;
                let rho = big_r + r * th.cos();
                let p = t
                    .point_to_world(glam::Vec3::new(
                        rho * phi.cos(),
                        r * th.sin(),
                        rho * phi.sin(),
                    ))
                    .as_dvec3();
                let v = p - cam.eye;
                let z = v.dot(cam.forward);
                assert!(z > 0.0, "surface behind the camera");
                assert!((v.dot(cam.right) / z).abs() <= cam.tan_half_fov);
                assert!((v.dot(cam.up) / z).abs() <= cam.tan_half_fov);
            }
        }
        for ray in &b.rays {
            assert!((ray.origin().as_dvec3() - cam.eye).length() < 1e-5);
        }
    }
}

/// `generate_labeled` draws the rays `generate` draws, and hands on with them the labels
/// the oracle gives each (the samplers' own for `hole` and `grazing`), bit for bit.
#[test]
fn labeled_batches_carry_the_oracles_labels() {
    let workload = Workload::drawn("t", 11, 300, "labeled batches");
    for &case in Case::ALL {
        for nu in [1.1, 4.0] {
            let (batch, labels) = generate_labeled(&workload, case, nu).unwrap();
            let plain = generate(case, nu, 300, 11, Pose::Random).unwrap();
            assert_eq!(batch.rays, plain.rays, "{case} {nu}");
            assert_eq!(labels.len(), batch.rays.len(), "{case} {nu}");
            for (ray, label) in batch.rays.iter().zip(&labels) {
                let asked = classify(&batch.torus, ray);
                assert_eq!(label.class, asked.class, "{case} {nu} {ray:?}");
                assert_eq!(
                    label.margin.to_bits(),
                    asked.margin.to_bits(),
                    "{case} {nu}"
                );
            }
        }
    }
}
