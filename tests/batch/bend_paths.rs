//! The pipe bend's certified f32 entry (`PipeBend::intersect_f32`) and its SIMD lanes
//! (`Wavefront::intersect_bend`) against the scalar f64 solid (`PipeBend::intersect`, which
//! `tests/oracle/bend.rs` holds to the bend oracle): the same answer for every ray of every
//! kind `torus-cull bend` draws (random, through the cut-away arc, along the pipe's axis,
//! through the hole, grazing the caps' edges, tangent to the bore, spawned from every face),
//! over Δφ × r_min/r_max × ν × scale, posed, in f32 and f64 rays, at every dispatch level;
//! and what f32 proves, counted.

use crate::common::bend::{Spec, rng};
use crate::dispatch_levels;
use std::f64::consts::{FRAC_PI_2, PI, TAU};
use torus_cull::batch::{BatchCull, Wavefront};
use torus_cull::{DRay, Ray};
use torus_cull_lab::check::shapes::bend::rays::{RayKind, draw};

/// The f64 ray rounded to f32, a surface ray staying one (`None` where f32 refuses it).
fn f32_ray(ray: &DRay) -> Option<Ray> {
    let (o, d) = (ray.origin().as_vec3(), ray.dir().as_vec3());
    let (t_min, t_max) = (ray.t_min() as f32, ray.t_max() as f32);
    if ray.starts_on_surface() {
        Ray::from_surface_with_range(o, d, t_min, t_max).ok()
    } else {
        Ray::with_range(o, d, t_min, t_max).ok()
    }
}

#[test]
fn f32_and_lanes_give_the_solids_answer() {
    let mut rng = rng(0xB3_4D32);
    let levels = dispatch_levels();
    let mut wavefront = Wavefront::new();
    // Per (whole, cut): rays, proved by f32, and the lanes' rays answered by the lanes alone.
    let mut rays_in = [0usize; 2];
    let mut proved = [0usize; 2];
    let mut lanes_only = [0usize; 2];
    let mut checked = 0usize;
    for delta in [TAU, PI, FRAC_PI_2, PI / 6.0] {
        for ratio in [0.0, 0.5, 0.9] {
            for nu in [1.25, 4.0, 16.0] {
                for scale in [1e-3, 1.0, 1e3] {
                    let spec = Spec::canonical(nu * scale, ratio * scale, scale, 0.3, delta)
                        .posed(&mut rng);
                    let bend = spec.bend().unwrap();
                    let cut = usize::from(bend.as_torus().is_err());
                    let mut rays64 = Vec::new();
                    for kind in RayKind::ALL {
                        for _ in 0..20 {
                            rays64.push(draw(&spec, &bend, kind, &mut rng).0);
                        }
                    }
                    let rays32: Vec<Ray> = rays64.iter().filter_map(f32_ray).collect();
                    for ray in &rays32 {
                        let answer = bend.intersect_f32(ray);
                        let want = bend.intersect(ray);
                        // A proved hit is f32's (t within its proof); every other answer is
                        // the solid's, exactly.
                        match (answer.hit, answer.escalated) {
                            (Some(got), false) => {
                                let want = want.expect("a proved hit");
                                assert_eq!(got.face, want.face);
                                let tol = 2e-4 * (spec.size() as f32) / ray.dir().length();
                                assert!((got.t - want.t).abs() <= tol, "{got:?} vs {want:?}");
                            }
                            (got, _) => assert_eq!(got, want, "{ray:?} of {bend:?}"),
                        }
                        rays_in[cut] += 1;
                        proved[cut] += usize::from(!answer.escalated);
                    }
                    for dispatch in &levels {
                        for cull in [BatchCull::NoCull, BatchCull::Skala, BatchCull::Discriminant] {
                            let mut hits = Vec::new();
                            wavefront.intersect_bend(dispatch, cull, &bend, &rays32, &mut hits);
                            for (ray, hit) in rays32.iter().zip(&hits) {
                                assert_eq!(*hit, bend.intersect(ray), "{cull:?} {ray:?}");
                            }
                            lanes_only[cut] += rays32.len() - wavefront.finished_in_f64().len();
                            let mut dhits = Vec::new();
                            wavefront.intersect_bend(dispatch, cull, &bend, &rays64, &mut dhits);
                            // A whole bend's lanes are the ring torus's wavefront: its f64
                            // hits are the batch solver's, to its rounding.
                            let tol = 1e-9 * spec.size();
                            for (ray, hit) in rays64.iter().zip(&dhits) {
                                match (hit, bend.intersect(ray)) {
                                    (Some(a), Some(b)) if cut == 0 => {
                                        assert_eq!((a.face, a.front_face), (b.face, b.front_face));
                                        let dt = (a.t - b.t).abs() * ray.dir().length();
                                        assert!(dt <= tol, "{cull:?} {ray:?}: {a:?} vs {b:?}");
                                    }
                                    (a, b) => assert_eq!(*a, b, "{cull:?} {ray:?}"),
                                }
                            }
                            checked += rays32.len() + rays64.len();
                        }
                    }
                }
            }
        }
    }
    eprintln!(
        "f32: whole bends {} of {} rays proved, cut bends {} of {}; lanes answered alone \
         {} (whole) and {} (cut) of the f32 rays; {checked} lane answers checked",
        proved[0], rays_in[0], proved[1], rays_in[1], lanes_only[0], lanes_only[1]
    );
    // The f32 path proves most of a whole bend's rays and a share of a cut one's (the
    // misses of the outer torus from outside it): it is not a pass-through.
    assert!(proved[0] * 10 > rays_in[0] * 7, "{proved:?} of {rays_in:?}");
    assert!(proved[1] * 10 > rays_in[1], "{proved:?} of {rays_in:?}");
    assert!(lanes_only[1] > 0);
}
