//! Secondary rays from a hit (`Torus::spawn`, `Ray::from_surface`) against the f64 oracle:
//! never a hit on their own origin, never a missed re-hit, in f32 and f64, through every
//! query (`intersect`, `occluded`, the f32 path, the wavefronts).
//!
//! Families, each spawned from hits of rays aimed at the tube, at ν from 1.01 to 1000 and
//! R from 10⁻³ to 10³ on random poses: cosine-weighted bounces, grazing directions
//! 10⁻⁴ … 10⁻¹ rad above the tangent plane, refraction into the tube, and rays aimed at
//! another point of the torus (across the hole or the tube, where re-hits are common).

use glam::{DVec3, Vec3};
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64;
use torus_cull::batch::{BatchCull, Dispatch, Wavefront};
use torus_cull::{DRay, Ray, Torus, intersect, intersect_f32, occluded};
use torus_cull_lab::oracle::{AMBIGUITY_REL, OracleClass, Query, reference_roots};
use torus_cull_lab::workload::unit_vector;

#[derive(Debug, Clone, Copy, PartialEq)]
enum Family {
    Bounce,
    Grazing,
    Into,
    Across,
}

const FAMILIES: [Family; 4] = [
    Family::Bounce,
    Family::Grazing,
    Family::Into,
    Family::Across,
];

fn random_torus(rng: &mut Pcg64, major: f32, nu: f32) -> Torus {
    let center = unit_vector(rng).as_vec3() * major * rng.random_range(0.0..3.0);
    Torus::new(center, unit_vector(rng).as_vec3(), major, major / nu).expect("a valid torus")
}

/// A point on the surface (world, f64) and the outward normal there.
fn surface_point(rng: &mut Pcg64, torus: &Torus) -> (DVec3, DVec3) {
    let (major, minor) = (torus.major_radius_f64(), torus.minor_radius_f64());
    let (phi, theta) = (
        rng.random_range(0.0..std::f64::consts::TAU),
        rng.random_range(0.0..std::f64::consts::TAU),
    );
    let radial = DVec3::new(phi.cos(), 0.0, phi.sin());
    let n_local = radial * theta.cos() + DVec3::Y * theta.sin();
    let p_local = radial * major + n_local * minor;
    let world = torus.to_local_rotation_f64().transpose();
    (world * p_local + torus.center_f64(), world * n_local)
}

/// A direction of `family` leaving the surface point `p` with outward normal `n`.
fn direction(rng: &mut Pcg64, family: Family, torus: &Torus, p: DVec3, n: DVec3) -> DVec3 {
    let t1 = n.any_orthonormal_vector();
    let t2 = n.cross(t1);
    match family {
        Family::Bounce | Family::Into => {
            // Cosine-weighted about ±n.
            let (r, a) = (
                rng.random_range(0.0f64..1.0).sqrt(),
                rng.random_range(0.0..std::f64::consts::TAU),
            );
            let up = (1.0 - r * r).sqrt();
            let side = if family == Family::Into { -1.0 } else { 1.0 };
            t1 * (r * a.cos()) + t2 * (r * a.sin()) + n * (side * up)
        }
        Family::Grazing => {
            let elevation = 10f64.powf(rng.random_range(-4.0..-1.0));
            let a = rng.random_range(0.0..std::f64::consts::TAU);
            (t1 * a.cos() + t2 * a.sin()) * elevation.cos() + n * elevation.sin()
        }
        Family::Across => {
            let (q, _) = surface_point(rng, torus);
            let d = q - p;
            if d.length_squared() > 0.0 { d } else { n }
        }
    }
}

/// At a world point near the surface: its distance from the surface, its distance ρ from
/// the axis, and the surface's outward unit normal there (all f64).
fn near_surface(torus: &Torus, x: DVec3) -> (f64, f64, DVec3) {
    let to_local = torus.to_local_rotation_f64();
    let local = to_local * (x - torus.center_f64());
    let rho = local.x.hypot(local.z);
    let core = DVec3::new(local.x, 0.0, local.z) * (torus.major_radius_f64() / rho);
    let off = local - core;
    let distance = (off.length() - torus.minor_radius_f64()).abs();
    (distance, rho, to_local.transpose() * off.normalize())
}

/// How far dropping the origin's root may move the crossing at `t` (docs/math.md §9):
/// `|Q(u₀)|/|Q′|` ≈ δ·(ρ₀/ρ)/|cos θ| along the unit direction, with |∇F| = 8Rrρ on the
/// surface; four times that, in units of `t`.
fn shift_bound(torus: &Torus, ray: &DRay, t: f64) -> f64 {
    let len = ray.dir().length();
    let (delta, rho0, _) = near_surface(torus, ray.origin());
    let (_, rho, n) = near_surface(torus, ray.at(t));
    let cos = n.dot(ray.dir() / len).abs().max(1e-12);
    4.0 * delta * (rho0 / rho) / cos / len
}

/// What the oracle expects of a ray from a surface point: `Some(next)` (the first crossing
/// after the origin's own, or `None`), or `None` where the answer is not decidable at f64's
/// resolution (another crossing within the origin's own window, or a tangent).
fn expected(torus: &Torus, ray: &DRay) -> Option<Option<f64>> {
    let size = torus.outer_radius() as f64;
    let len = ray.dir().length();
    let line = Query::dray(torus, ray).over(f64::NEG_INFINITY, f64::INFINITY);
    let roots = reference_roots(&line);
    // The origin's own root lies within δ/|cos θ₀| of 0 (δ its distance from the surface,
    // θ₀ the angle to the normal there), with 1e-11·(R + r) for the oracle's own error.
    let (delta, _, n0) = near_surface(torus, ray.origin());
    let cos0 = n0.dot(ray.dir() / len).abs().max(1e-12);
    let window = 4.0 * (delta + 1e-11 * size) / cos0 / len;
    let own = roots
        .iter()
        .copied()
        .min_by(|a, b| a.abs().total_cmp(&b.abs()))?;
    if own.abs() > window {
        return None;
    }
    let mut rest = roots.iter().copied().filter(|&t| t != own);
    if rest.clone().any(|t| t.abs() <= window) {
        return None;
    }
    // A tangent (a double root) is decided outside the oracle's ambiguity band only; the
    // ray is within the band of the surface near its origin, so the check starts where it
    // has left the band (and a crossing before that point is undecidable too).
    let clear = window + 10.0 * AMBIGUITY_REL * size / cos0 / len;
    if rest.clone().any(|t| t.abs() <= clear) {
        return None;
    }
    let next = rest.find(|&t| t > 0.0);
    let after = Query::dray(torus, ray)
        .over(clear, f64::INFINITY)
        .classify();
    if after.class == OracleClass::Ambiguous {
        return None;
    }
    Some(next)
}

#[derive(Default, Debug)]
struct Tally {
    checked: usize,
    undecidable: usize,
    rehits: usize,
    self_hits: Vec<String>,
    missed: Vec<String>,
    wrong_t: Vec<String>,
}

impl Tally {
    fn check(&mut self, what: &str, want: Option<f64>, got: Option<f64>, tol: f64) {
        match (want, got) {
            (None, None) => {}
            (Some(w), Some(g)) if (g - w).abs() <= tol => {}
            (None, Some(g)) => self
                .self_hits
                .push(format!("{what}: hit at t = {g:e}, oracle: none")),
            (Some(w), None) => self.missed.push(format!("{what}: none, oracle t = {w:e}")),
            (Some(w), Some(g)) if g < w => self
                .self_hits
                .push(format!("{what}: t = {g:e} before the oracle's {w:e}")),
            (Some(w), Some(g)) => self
                .wrong_t
                .push(format!("{what}: t = {g:e}, oracle {w:e}")),
        }
    }
}

#[test]
fn secondary_rays_never_hit_their_origin_and_never_miss_a_rehit() {
    let mut rng = Pcg64::seed_from_u64(0x5EC0_0026);
    let dispatch = Dispatch::best();
    let mut wavefront = Wavefront::new();
    let mut tally = Tally::default();
    let mut per_family = [0usize; 4];
    for &nu in &[1.01f32, 1.1, 2.0, 4.0, 16.0, 100.0, 1000.0] {
        for &major in &[1e-3f32, 1.0, 1e3] {
            let torus = random_torus(&mut rng, major, nu);
            let size = torus.outer_radius() as f64;
            for (k, &family) in FAMILIES.iter().enumerate() {
                let mut rays = Vec::new();
                let mut wants = Vec::new();
                for _ in 0..400 {
                    // A primary ray from outside aimed at a surface point; the family's
                    // direction leaves its first hit, relative to the normal there.
                    let (p, n) = surface_point(&mut rng, &torus);
                    let from = p + (n * 2.0 + unit_vector(&mut rng)) * size;
                    let primary = DRay::new(from, p - from).unwrap();
                    let Some(hit) = intersect(&torus, &primary) else {
                        continue;
                    };
                    let at = primary.at(hit.t);
                    let d = direction(&mut rng, family, &torus, at, hit.normal);
                    let Ok(secondary) = torus.spawn(&primary, hit.t, d) else {
                        continue;
                    };
                    tally.checked += 1;
                    let Some(want) = expected(&torus, &secondary) else {
                        tally.undecidable += 1;
                        continue;
                    };
                    tally.rehits += usize::from(want.is_some());
                    per_family[k] += 1;
                    let len = d.length();
                    let bound = |ray: &DRay, want: Option<f64>| {
                        want.map_or(0.0, |t| shift_bound(&torus, ray, t))
                    };
                    let tol = 1e-9 * size / len + bound(&secondary, want);
                    let what = format!("{family:?} nu={nu} R={major} f64 {secondary:?}");
                    tally.check(&what, want, intersect(&torus, &secondary).map(|h| h.t), tol);
                    assert_eq!(
                        occluded(&torus, &secondary),
                        intersect(&torus, &secondary).is_some()
                    );
                    // The same in f32: the primary ray and its hit as a renderer has them.
                    let primary32 = Ray::new(from.as_vec3(), (p - from).as_vec3()).unwrap();
                    let Some(hit32) = intersect(&torus, &primary32) else {
                        continue;
                    };
                    let Ok(secondary32) = torus.spawn(&primary32, hit32.t, d.as_vec3()) else {
                        continue;
                    };
                    let Some(want32) = expected(&torus, &DRay::from(secondary32)) else {
                        tally.undecidable += 1;
                        continue;
                    };
                    let wide = DRay::from(secondary32);
                    let tol32 =
                        1e-9 * size / len + want32.unwrap_or(0.0) * 1.2e-7 + bound(&wide, want32);
                    let got32 = intersect(&torus, &secondary32).map(|h| f64::from(h.t));
                    let what32 = format!("{family:?} nu={nu} R={major} f32 {secondary32:?}");
                    tally.check(&what32, want32, got32, tol32);
                    let f32_path = intersect_f32(&torus, &secondary32);
                    assert!(f32_path.escalated, "an on-surface ray is answered by f64");
                    assert_eq!(f32_path.hit.map(|h| h.t), got32.map(|t| t as f32));
                    rays.push(secondary32);
                    wants.push(got32);
                }
                // The wavefronts give the scalar answers, for every on-surface ray.
                let mut hits = Vec::new();
                let stats = wavefront.intersect(
                    &dispatch,
                    BatchCull::Discriminant,
                    &torus,
                    &rays,
                    &mut hits,
                );
                for (h, w) in hits.iter().zip(&wants) {
                    assert_eq!(
                        h.map(|h| f64::from(h.t)),
                        *w,
                        "wavefront, {family:?} nu={nu} R={major}"
                    );
                }
                assert!(stats.scalar_fallbacks <= rays.len());
                let stats =
                    wavefront.intersect_f32(&dispatch, BatchCull::Skala, &torus, &rays, &mut hits);
                for (h, w) in hits.iter().zip(&wants) {
                    assert_eq!(
                        h.map(|h| f64::from(h.t)),
                        *w,
                        "f32 wavefront, {family:?} nu={nu} R={major}"
                    );
                }
                assert_eq!(
                    stats.escalated, stats.kept,
                    "every kept on-surface ray escalates"
                );
            }
        }
    }
    println!(
        "{} secondary rays, {} undecidable at f64's resolution, {} re-hits; per family {per_family:?}; \
         self-hits {}, missed re-hits {}, t off {}",
        tally.checked,
        tally.undecidable,
        tally.rehits,
        tally.self_hits.len(),
        tally.missed.len(),
        tally.wrong_t.len()
    );
    let show = |v: &Vec<String>| v[..v.len().min(8)].join("\n");
    assert!(
        tally.self_hits.is_empty(),
        "self-hits:\n{}",
        show(&tally.self_hits)
    );
    assert!(
        tally.missed.is_empty(),
        "missed re-hits:\n{}",
        show(&tally.missed)
    );
    assert!(tally.wrong_t.is_empty(), "t off:\n{}", show(&tally.wrong_t));
    assert!(
        tally.rehits > 2_000,
        "too few re-hits to mean anything: {}",
        tally.rehits
    );
    // Mostly grazing rays at 10⁻⁴ rad, whose next crossing is a near-tangent.
    assert!(
        tally.undecidable * 10 < tally.checked,
        "{} undecidable of {}",
        tally.undecidable,
        tally.checked
    );
}

/// The literal semantics are unchanged for a ray that is not marked: from a surface point
/// with `t_min = 0` it may hit its own origin, which is why renderers need the flag.
#[test]
fn a_literal_ray_from_a_rounded_surface_point_can_hit_its_origin() {
    let torus = Torus::canonical(4.0, 1.0).unwrap();
    // The inner equator point (3, 0, 0) nudged into the tube, looking across the hole.
    let inside = Vec3::new(3.000_001, 0.0, 0.0);
    let literal = Ray::new(inside, Vec3::NEG_X).unwrap();
    let own = intersect(&torus, &literal).expect("leaves the tube at once");
    assert!(own.t < 1e-5);
    let spawned = Ray::from_surface(inside, Vec3::NEG_X).unwrap();
    let across = intersect(&torus, &spawned).expect("the far side of the hole");
    assert!((across.t - 6.000_001).abs() < 1e-5, "{across:?}");
}
