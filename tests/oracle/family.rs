//! The torus family (`torus_cull::family::Toroid`) against its own independent oracle
//! (`torus_cull_lab::oracle::family`): every member class (elliptical ring tori, the horn,
//! spindles) at several ν, aspects, scales and poses, on uniform, grazing, axis and
//! spawned rays. The exact intersection: 0 missed, 0 invented, `t` and every crossing
//! within 10⁻⁹ of the size; every cull: 0 false rejects.

use glam::DVec3;
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64;
use torus_cull::family::Toroid;
use torus_cull::{CullKind, DRay, Passage, Ray};
use torus_cull_lab::oracle::OracleClass;
use torus_cull_lab::oracle::family::{FamilyQuery, Passage as OraclePassage};
use torus_cull_lab::workload::box_rays::box_rays;

/// (R, a, b): ring tori at ν = 1.25, 4, 16 and b/a from 1/4 to 4, the horn, spindles.
const MEMBERS: [(f64, f64, f64); 19] = [
    (1.25, 1.0, 0.25),
    (1.25, 1.0, 4.0),
    (4.0, 1.0, 0.25),
    (4.0, 1.0, 0.5),
    (4.0, 1.0, 2.0),
    (4.0, 1.0, 4.0),
    (16.0, 1.0, 0.5),
    (16.0, 1.0, 4.0),
    (1.0, 1.0, 1.0),
    (1.0, 1.0, 0.25),
    (0.75, 1.0, 1.0),
    (0.5, 1.0, 0.5),
    (0.5, 1.0, 4.0),
    (0.3, 1.0, 1.0),
    (0.3, 1.0, 0.25),
    (0.1, 1.0, 1.0),
    (0.1, 1.0, 4.0),
    (0.01, 1.0, 1.0),
    (0.01, 1.0, 0.25),
];

/// A member at scale `scale` (R, a, b times it) and a random pose.
pub(crate) fn posed(rng: &mut Pcg64, (big, a, b): (f64, f64, f64), scale: f64) -> Toroid {
    let center = DVec3::new(
        rng.random_range(-3.0..3.0),
        rng.random_range(-3.0..3.0),
        rng.random_range(-3.0..3.0),
    ) * scale;
    let axis = DVec3::new(
        rng.random_range(-1.0..1.0),
        rng.random_range(-1.0..1.0),
        rng.random_range(-1.0..1.0),
    ) + DVec3::Y * 0.1;
    Toroid::new_f64(center, axis, big * scale, a * scale, b * scale).unwrap()
}

pub(crate) fn query(
    member: &Toroid,
    origin: DVec3,
    dir: DVec3,
    t_min: f64,
    t_max: f64,
) -> FamilyQuery {
    FamilyQuery::new(
        member.center_f64(),
        member.axis_f64(),
        member.major_radius_f64(),
        member.radial_semi_axis_f64(),
        member.axial_semi_axis_f64(),
        origin,
        dir,
        t_min,
        t_max,
    )
}

pub(crate) fn size(member: &Toroid) -> f64 {
    member.major_radius_f64()
        + member
            .radial_semi_axis_f64()
            .max(member.axial_semi_axis_f64())
}

/// A world point of the member's surface at tube angle θ and angle φ about the axis, its
/// outward normal, and a unit tangent there.
pub(crate) fn surface_point(member: &Toroid, theta: f64, phi: f64) -> (DVec3, DVec3, DVec3) {
    let axis = member.axis_f64();
    let (e0, e1) = axis.any_orthonormal_pair();
    let radial = e0 * phi.cos() + e1 * phi.sin();
    let (big, a, b) = (
        member.major_radius_f64(),
        member.radial_semi_axis_f64(),
        member.axial_semi_axis_f64(),
    );
    let rho = big + a * theta.cos();
    let p = member.center_f64() + radial * rho + axis * (b * theta.sin());
    let normal = (radial * (theta.cos() / a) + axis * (theta.sin() / b)).normalize();
    let tangent = normal.any_orthonormal_vector();
    (p, normal, tangent)
}

/// The rays of one member: uniform at its box, grazing (tangent lines pushed ±10⁻⁸ …
/// 10⁻³·size along the normal), and near the axis (through a ring's hole, a spindle's
/// cusps); each with whether it is a grazing ray.
pub(crate) fn rays(member: &Toroid, rng: &mut Pcg64, count: usize) -> Vec<(DRay, bool)> {
    let s = size(member);
    let (c, axis) = (member.center_f64(), member.axis_f64());
    let mut out = Vec::new();
    // Uniform: the box rays of the canonical member, moved to the pose.
    let rot = glam::DQuat::from_rotation_arc(DVec3::Y, axis);
    let uniform = box_rays(
        member.major_radius_f64(),
        member.radial_semi_axis_f64(),
        member.axial_semi_axis_f64(),
        count,
        rng.random(),
    );
    for ray in uniform {
        let o = c + rot * ray.origin().as_dvec3();
        let d = rot * ray.dir().as_dvec3();
        out.push((DRay::new(o, d).unwrap(), false));
    }
    for _ in 0..count {
        let theta = rng.random_range(0.0..std::f64::consts::TAU);
        let phi = rng.random_range(0.0..std::f64::consts::TAU);
        let (p, n, t) = surface_point(member, theta, phi);
        let push =
            s * 10f64.powf(rng.random_range(-8.0..-3.0)) * if rng.random() { 1.0 } else { -1.0 };
        let spin = rng.random_range(0.0..std::f64::consts::TAU);
        let dir = t * spin.cos() + n.cross(t) * spin.sin();
        let o = p + n * push - dir * (2.0 * s);
        out.push((DRay::new(o, dir).unwrap(), true));
    }
    for _ in 0..count / 4 {
        let off = DVec3::new(
            rng.random_range(-1.0..1.0),
            0.0,
            rng.random_range(-1.0..1.0),
        ) * (s * 10f64.powf(rng.random_range(-6.0..-1.0)));
        let o = c + rot * (off + DVec3::Y * 3.0 * s);
        let tilt = DVec3::new(
            rng.random_range(-1e-2..1e-2),
            -1.0,
            rng.random_range(-1e-2..1e-2),
        );
        out.push((DRay::new(o, rot * tilt).unwrap(), false));
    }
    out
}

#[test]
fn the_family_exact_intersection_and_every_cull_against_the_oracle() {
    let mut rng = Pcg64::seed_from_u64(38_000);
    let (mut judged, mut ambiguous, mut hits, mut missed, mut invented, mut far) =
        (0, 0, 0, 0, 0, 0);
    let mut false_rejects = Vec::new();
    let (mut worst, mut grazing_judged) = (0.0f64, 0usize);
    for &member in &MEMBERS {
        for scale in [1e-3, 1.0, 1e3] {
            let toroid = posed(&mut rng, member, scale);
            let s = size(&toroid);
            for (ray, grazing) in rays(&toroid, &mut rng, 300) {
                let q = query(&toroid, ray.origin(), ray.dir(), ray.t_min(), ray.t_max());
                let label = q.classify();
                if label.class == OracleClass::Ambiguous {
                    ambiguous += 1;
                    continue;
                }
                judged += 1;
                grazing_judged += usize::from(grazing);
                let got = toroid.intersect(&ray);
                match (label.class, got) {
                    (OracleClass::Hit, None) => missed += 1,
                    (OracleClass::Miss, Some(_)) => invented += 1,
                    (OracleClass::Hit, Some(hit)) => {
                        hits += 1;
                        let want = q.first_crossing().expect("a hit has a crossing");
                        let err = (hit.t - want).abs() * ray.dir().length() / s;
                        worst = worst.max(err);
                        if err > 1e-9 {
                            far += 1;
                        }
                    }
                    _ => {}
                }
                if label.class == OracleClass::Hit {
                    let f32_ray = Ray::new(ray.origin().as_vec3(), ray.dir().as_vec3());
                    for kind in CullKind::TIMED {
                        if !toroid.kept_by(&kind, &ray) {
                            false_rejects.push(format!("{kind} {member:?}×{scale} {ray:?}"));
                        }
                        // f32 rays at small offsets from the box only (far f32 origins
                        // round by more than the margin of the label).
                        if let Ok(r) = f32_ray
                            && label.margin < -1e-4 * s
                            && !toroid.kept_by(&kind, &r)
                        {
                            false_rejects.push(format!("f32 {kind} {member:?}×{scale} {r:?}"));
                        }
                    }
                }
            }
        }
    }
    eprintln!(
        "family: {judged} judged ({hits} hits, {grazing_judged} grazing), {ambiguous} ambiguous; missed {missed}, \
         invented {invented}, far {far}; worst t error {worst:.2e} of the size"
    );
    assert!(judged > 20_000, "{judged}");
    assert_eq!((missed, invented, far), (0, 0, 0), "worst {worst:e}");
    assert!(
        false_rejects.is_empty(),
        "{}: {:?}",
        false_rejects.len(),
        &false_rejects[..false_rejects.len().min(5)]
    );
}

#[test]
fn every_crossing_of_the_family_against_the_oracle() {
    let mut rng = Pcg64::seed_from_u64(38_001);
    let (mut compared, mut wrong) = (0, Vec::new());
    for &member in &MEMBERS {
        let toroid = posed(&mut rng, member, 1.0);
        let s = size(&toroid);
        for (ray, _) in rays(&toroid, &mut rng, 200) {
            let q = query(&toroid, ray.origin(), ray.dir(), ray.t_min(), ray.t_max());
            if q.classify().class == OracleClass::Ambiguous {
                continue;
            }
            let want: Vec<(f64, Passage)> = q
                .crossings()
                .iter()
                .filter_map(|c| match c.passage {
                    OraclePassage::Entering => Some((c.t, Passage::Enter)),
                    OraclePassage::Leaving => Some((c.t, Passage::Exit)),
                    OraclePassage::Touching => None,
                })
                .collect();
            // Crossings closer than 10⁻⁶ of the size are a near-tangent pair that f64
            // may resolve as a touch: not compared.
            let close_pair = want
                .windows(2)
                .any(|w| (w[1].0 - w[0].0) * ray.dir().length() < 1e-6 * s);
            if close_pair {
                continue;
            }
            let got: Vec<(f64, Passage)> = toroid
                .intersect_all(&ray)
                .as_slice()
                .iter()
                .filter(|c| c.passage != Passage::Touch)
                .map(|c| (c.t, c.passage))
                .collect();
            compared += 1;
            let same = got.len() == want.len()
                && got
                    .iter()
                    .zip(&want)
                    .all(|(g, w)| g.1 == w.1 && (g.0 - w.0).abs() * ray.dir().length() <= 1e-8 * s);
            if !same {
                wrong.push(format!("{member:?} {ray:?}: got {got:?}, want {want:?}"));
            }
        }
    }
    eprintln!(
        "family crossings: {compared} rays compared, {} wrong",
        wrong.len()
    );
    assert!(compared > 5_000, "{compared}");
    assert!(
        wrong.is_empty(),
        "{}: {:?}",
        wrong.len(),
        &wrong[..wrong.len().min(5)]
    );
}

#[test]
fn rays_spawned_on_the_family_against_the_oracle() {
    let mut rng = Pcg64::seed_from_u64(38_002);
    let (mut judged, mut undecided, mut missed, mut invented, mut far) = (0, 0, 0, 0, 0);
    let mut worst = 0.0f64;
    for &member in &MEMBERS {
        let toroid = posed(&mut rng, member, 1.0);
        let s = size(&toroid);
        for (ray, _) in rays(&toroid, &mut rng, 200) {
            let ray = Ray::new(ray.origin().as_vec3(), ray.dir().as_vec3()).unwrap();
            let Some(hit) = toroid.intersect(&ray) else {
                continue;
            };
            for _ in 0..2 {
                let dir = DVec3::new(
                    rng.random_range(-1.0..1.0),
                    rng.random_range(-1.0..1.0),
                    rng.random_range(-1.0..1.0),
                );
                let spawned = toroid.spawn(&ray, hit.t, dir.as_vec3()).unwrap();
                let q = query(
                    &toroid,
                    spawned.origin().as_dvec3(),
                    spawned.dir().as_dvec3(),
                    0.0,
                    f64::INFINITY,
                );
                let label = q.classify_from_surface();
                if label.class == OracleClass::Ambiguous {
                    undecided += 1;
                    continue;
                }
                judged += 1;
                match (label.class, toroid.intersect(&spawned)) {
                    (OracleClass::Hit, None) => missed += 1,
                    (OracleClass::Miss, Some(_)) => invented += 1,
                    (OracleClass::Hit, Some(h)) => {
                        let want = q.first_crossing_from_surface().unwrap();
                        let err = (f64::from(h.t) - want).abs() * dir.length() / s;
                        worst = worst.max(err);
                        // The hit's t is f32.
                        if err > 1e-6 {
                            far += 1;
                        }
                    }
                    _ => {}
                }
            }
        }
    }
    eprintln!(
        "family spawned: {judged} judged, {undecided} undecided; missed {missed}, invented \
         {invented}, far {far}; worst {worst:.2e}"
    );
    assert!(judged > 3_000, "{judged}");
    assert_eq!((missed, invented, far), (0, 0, 0));
}

/// OpenMC's filter for R < r (its PR 2589), in its own notation, on every root of the
/// image's quartic: a root at the point s (relative to the centre, s₃ along the axis) is
/// kept when `D·s₃² + s₁² + s₂² + A² − C² ≥ 0`, D = C²/B² (A = R, B = b, C = a). The
/// library's apple test is the same sign (docs/family.md); both against the oracle.
#[test]
fn openmc_s_sign_test_keeps_the_apple_s_roots_alone() {
    let mut rng = Pcg64::seed_from_u64(38_003);
    let (mut roots_seen, mut lemon_dropped, mut compared) = (0, 0, 0);
    for &(big, a, b) in MEMBERS.iter().filter(|m| m.0 <= m.1) {
        let toroid = Toroid::canonical(big, a, b).unwrap();
        for (ray, _) in rays(&toroid, &mut rng, 150) {
            let (o, d) = (ray.origin(), ray.dir());
            let q = query(&toroid, o, d, f64::NEG_INFINITY, f64::INFINITY);
            if q.classify().class == OracleClass::Ambiguous {
                continue;
            }
            // The image line (y scaled by a/b) and its quartic's every root.
            let scale = DVec3::new(1.0, a / b, 1.0);
            let all = torus_cull::intersect::line_roots_local(big, a, o * scale, d * scale);
            let dd = (a * a) / (b * b);
            let kept: Vec<f64> = all
                .as_slice()
                .iter()
                .copied()
                .filter(|&t| {
                    let s = o + d * t;
                    dd * s.y * s.y + s.x * s.x + s.z * s.z + big * big - a * a >= 0.0
                })
                .collect();
            roots_seen += all.len();
            lemon_dropped += all.len() - kept.len();
            let want: Vec<f64> = q.crossings().iter().map(|c| c.t).collect();
            // Roots of a near-tangent pair or a cusp may come back merged or split: compare
            // rays whose oracle crossings are well apart.
            let s = size(&toroid);
            let apart = want
                .windows(2)
                .all(|w| (w[1] - w[0]) * d.length() > 1e-6 * s);
            let distinct: Vec<f64> = kept.iter().fold(Vec::new(), |mut v, &t| {
                if v.last()
                    .is_none_or(|&l: &f64| (t - l) * d.length() > 1e-6 * s)
                {
                    v.push(t);
                }
                v
            });
            if !apart {
                continue;
            }
            compared += 1;
            assert_eq!(
                distinct.len(),
                want.len(),
                "({big}, {a}, {b}) {ray:?}: {kept:?} vs {want:?}"
            );
            for (g, w) in distinct.iter().zip(&want) {
                assert!(
                    (g - w).abs() * d.length() < 1e-8 * s,
                    "{ray:?}: {kept:?} vs {want:?}"
                );
            }
        }
    }
    eprintln!(
        "OpenMC's sign test: {compared} rays, {roots_seen} quartic roots, {lemon_dropped} \
         lemon roots dropped, the rest equal to the oracle's crossings"
    );
    assert!(
        compared > 1_000 && lemon_dropped > 100,
        "{compared} {lemon_dropped}"
    );
}
