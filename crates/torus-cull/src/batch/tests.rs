//! The wavefront's every-crossing pass on f64 rays: the scalar `intersect_all`'s answers,
//! exactly, behind every batched cull and none, on tangent, hole, grazing and random rays.

use super::{BATCHED, BatchCull, Dispatch, Wavefront};
use crate::geometry::draw::dvec3_in;
use crate::{DRay, Torus, intersect_all};
use glam::DVec3;
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64;
use std::f64::consts::TAU;

/// Rays that touch, graze, or thread the torus (R, r) in its own frame, then posed.
fn adversarial(big: f64, small: f64) -> Vec<DRay> {
    let mut rays = Vec::new();
    let mut push = |o: DVec3, d: DVec3| rays.push(DRay::new(o, d).unwrap());
    for eps in [0.0, 1e-12, -1e-12, 1e-9, -1e-9, 1e-6, -1e-6] {
        let e = eps * big;
        // Along x, tangent to the top circle (y = r): touches it twice.
        push(DVec3::new(-3.0 * big, small + e, 0.0), DVec3::X);
        // Down, tangent to the outer equator and to the inner one.
        push(DVec3::new(big + small + e, 3.0 * big, 0.0), DVec3::NEG_Y);
        push(DVec3::new(big - small + e, 3.0 * big, 0.0), DVec3::NEG_Y);
        // Along z at the inner equator's radius: tangent to it from inside the hole.
        push(DVec3::new(big - small + e, 0.0, -3.0 * big), DVec3::Z);
        // Along z at the outer equator's radius: tangent from outside.
        push(DVec3::new(big + small + e, 0.0, -3.0 * big), DVec3::Z);
        // Tangent to the tube at the saddle's neighbourhood, oblique.
        let p = DVec3::new(big - small * 0.6, small * 0.8, 0.0);
        let n = DVec3::new(-0.6, 0.8, 0.0);
        let t = DVec3::new(0.8, 0.6, 0.3).reject_from(n).normalize();
        push(p + n * e - t * 2.0 * big, t);
    }
    // Through the hole: down the axis, down off it, along y = 0 through the centre (four
    // crossings), and starting at the centre.
    push(DVec3::new(0.0, 3.0 * big, 0.0), DVec3::NEG_Y);
    push(
        DVec3::new(0.5 * (big - small), 3.0 * big, 0.1),
        DVec3::NEG_Y,
    );
    push(DVec3::new(-3.0 * big, 0.0, 0.0), DVec3::X);
    push(DVec3::ZERO, DVec3::new(1.0, 0.01, 0.3));
    // From inside the tube, and from far away.
    push(DVec3::new(big, 0.0, 0.0), DVec3::new(0.3, 1.0, 0.2));
    push(
        DVec3::new(1e4 * big, 1e3 * big, 0.0),
        DVec3::new(-1.0, -0.1, 0.0),
    );
    rays
}

fn posed(torus: &Torus, rays: &[DRay]) -> Vec<DRay> {
    rays.iter()
        .map(|r| {
            let o = torus.point_to_world_f64(r.origin());
            let d = torus.to_local_rotation_f64().transpose() * r.dir();
            DRay::new(o, d).unwrap()
        })
        .collect()
}

#[test]
fn intersect_all_on_drays_is_the_scalar_answer() {
    let dispatch = Dispatch::best();
    let mut wavefront = Wavefront::new();
    let mut all = Vec::new();
    let mut rng = Pcg64::seed_from_u64(41);
    let (mut checked, mut crossings, mut culled) = (0usize, 0usize, 0usize);
    for (big, small) in [
        (4.0, 1.0),
        (1.01, 1.0),
        (1e3, 1.0),
        (1e-3, 0.25e-3),
        (500.0, 0.5),
    ] {
        let center = dvec3_in(&mut rng, DVec3::splat(5.0)) * big;
        let axis = dvec3_in(&mut rng, DVec3::splat(1.0));
        for torus in [
            Torus::new_f64(DVec3::ZERO, DVec3::Y, big, small).unwrap(),
            Torus::new_f64(center, axis, big, small).unwrap(),
        ] {
            let mut rays = posed(&torus, &adversarial(big, small));
            for _ in 0..400 {
                let s = 3.0 * (big + small);
                let o = dvec3_in(&mut rng, DVec3::splat(s));
                let phi = rng.random_range(0.0..TAU);
                let aim = DVec3::new(
                    big * phi.cos(),
                    rng.random_range(-small..small),
                    big * phi.sin(),
                );
                let d = (aim - o).normalize() + DVec3::splat(rng.random_range(-0.1..0.1));
                rays.push(
                    DRay::new(
                        torus.point_to_world_f64(o),
                        torus.to_local_rotation_f64().transpose() * d,
                    )
                    .unwrap(),
                );
            }
            // A limited range too: t_max inside the tube.
            let limited: Vec<DRay> = rays
                .iter()
                .map(|r| r.with_t_max(2.5 * big).unwrap())
                .collect();
            rays.extend(limited);
            for cull in BATCHED.into_iter().chain([BatchCull::NoCull]) {
                let stats = wavefront.intersect_all(&dispatch, cull, &torus, &rays, &mut all);
                assert_eq!(all.len(), rays.len());
                culled += stats.rays - stats.kept;
                for (ray, got) in rays.iter().zip(&all) {
                    let want = intersect_all(&torus, ray);
                    assert_eq!(got, &want, "{cull:?} R = {big}, r = {small}: {ray:?}");
                    crossings += want.len();
                    checked += 1;
                }
            }
        }
    }
    println!(
        "wavefront intersect_all on DRays: {checked} answers equal, {crossings} crossings, {culled} culled"
    );
    assert!(crossings > 10_000 && culled > 1_000);
}
