//! Tori in a GPU BVH (`torus_cull::gpu::GpuScene`) against the CPU's brute force
//! (`Scene::brute_force`: `torus_cull::intersect` over every torus, the nearest kept), on
//! whatever adapter wgpu finds (CI: lavapipe).
//!
//! For every GPU cull, on the lab's five scene layouts at R = 10⁻³, 1 and 10³: camera and
//! random rays (closest hit: hit or miss identical, the same torus, t within
//! 2·10⁻⁴·(R + r)/|d| + 4 ulp of the CPU's, or a tie: another torus the CPU hits at that
//! t within the same tolerance), and shadow rays (any hit, `t_max` at half and at 1.5×
//! the CPU's hit: occluded identical). And obvhs's t_min clamp cases, as literal rays
//! (tests/batch/bvh_family.rs's are spawned ones): tiny tori (R = 10⁻⁵) and directions
//! 10⁵ long, from just outside a hit, with hits below t = 10⁻⁴. Rays finished on the host
//! and leaves the device's f64 finished are counted and printed.
//!
//! CI runs a small size of each; `TORUS_CULL_GPU_SCENE_FULL=1` runs 200 tori and 16× the
//! rays (docs/gpu.md, "Tori in a GPU BVH").

#![cfg(feature = "gpu")]

use crate::gpu::gpu;
use glam::Vec3;
use std::io::Write;
use torus_cull::gpu::{Finished, GpuCull, GpuError, GpuScene, SceneAnswer, SpawnedRay};
use torus_cull::{Named, Ray, Torus, intersect};
use torus_cull_lab::scene::rays::{
    Spawned, Surfaces, bounce_rays, light, shadow_rays as spawned_shadows,
};
use torus_cull_lab::scene::{Scene, SceneKind};

/// Tori, camera size and random rays per scene: CI's size, or the full one.
fn size() -> (usize, usize, usize) {
    if std::env::var_os("TORUS_CULL_GPU_SCENE_FULL").is_some() {
        (200, 24, 576)
    } else {
        (24, 6, 36)
    }
}

#[derive(Default, Debug)]
struct Tally {
    rays: usize,
    hits: usize,
    mismatches: usize,
    ties: usize,
    host: usize,
    device: usize,
}

/// t tolerance of a proved f32 hit against the CPU's f64 one, on `torus`.
fn tolerance(torus: &Torus, ray: &Ray, t: f32) -> f32 {
    let size = torus.major_radius() + torus.minor_radius();
    2e-4 * size / ray.dir().length() * 1.01 + 4.0 * f32::EPSILON * t.abs()
}

fn count(tally: &mut Tally, by: Finished) {
    tally.rays += 1;
    match by {
        Finished::Host => tally.host += 1,
        Finished::Device => tally.device += 1,
        _ => {}
    }
}

/// Closest hits on the GPU against the brute force.
fn check_closest(
    scene: &Scene,
    gpu_scene: &GpuScene,
    cull: GpuCull,
    rays: &[Ray],
    what: &str,
    tally: &mut Tally,
) {
    let answers = gpu_scene.trace(cull, rays).expect("trace");
    assert_eq!(answers.len(), rays.len());
    for (ray, answer) in rays.iter().zip(answers) {
        let cpu = scene.brute_force(ray);
        judge_closest(scene, |_| *ray, answer, cpu, (what, cull), tally);
    }
}

/// Closest hits of spawned rays on the GPU against the brute force (the own torus sees
/// the surface ray, every other the literal one).
fn check_closest_from(
    scene: &Scene,
    gpu_scene: &GpuScene,
    cull: GpuCull,
    rays: &[Spawned],
    what: &str,
    tally: &mut Tally,
) {
    let spawned: Vec<SpawnedRay> = rays.iter().map(spawned_ray).collect();
    let answers = gpu_scene.trace_from(cull, &spawned).expect("trace_from");
    assert_eq!(answers.len(), rays.len());
    for (s, answer) in rays.iter().zip(answers) {
        let cpu = scene.brute_force_spawned(s);
        let literal = s.literal();
        let seen = |i: u32| *s.seen_by(i as usize, &literal);
        judge_closest(scene, seen, answer, cpu, (what, cull), tally);
    }
}

fn spawned_ray(s: &Spawned) -> SpawnedRay {
    SpawnedRay {
        ray: s.ray,
        from: s.from,
    }
}

/// One closest-hit answer against the CPU's: hit or miss identical, the same torus and t
/// within the tolerance, or a tie (the GPU's torus is hit at its t too, the two t's
/// agree); `seen(i)` is the ray torus i sees.
fn judge_closest(
    scene: &Scene,
    seen: impl Fn(u32) -> Ray,
    answer: SceneAnswer,
    cpu: Option<(u32, f32)>,
    (what, cull): (&str, GpuCull),
    tally: &mut Tally,
) {
    count(tally, answer.by);
    let ok = match (answer.hit, cpu) {
        (None, None) => true,
        (Some(h), Some((i, t))) => {
            tally.hits += 1;
            let (mine, theirs) = (seen(h.torus), seen(i));
            let own = tolerance(&scene.tori[h.torus as usize], &mine, t);
            if h.torus == i {
                (h.t - t).abs() <= own
            } else {
                let at = intersect(&scene.tori[h.torus as usize], &mine).map(|x| x.t);
                let tie = at.is_some_and(|x| (x - h.t).abs() <= own)
                    && (h.t - t).abs() <= own + tolerance(&scene.tori[i as usize], &theirs, t);
                tally.ties += usize::from(tie);
                tie
            }
        }
        _ => false,
    };
    if !ok {
        tally.mismatches += 1;
        if tally.mismatches <= 5 {
            eprintln!(
                "MISMATCH {what} {}: {:?}: gpu {:?}, cpu {cpu:?}",
                cull.name(),
                seen(u32::MAX),
                answer.hit
            );
        }
    }
}

/// Shadow rays on the GPU against the brute force.
fn check_any(
    scene: &Scene,
    gpu_scene: &GpuScene,
    cull: GpuCull,
    rays: &[Ray],
    what: &str,
    tally: &mut Tally,
) {
    let answers = gpu_scene.occluded(cull, rays).expect("occluded");
    assert_eq!(answers.len(), rays.len());
    for (ray, answer) in rays.iter().zip(answers) {
        count(tally, answer.by);
        let cpu = scene.brute_force_occluded(ray);
        tally.hits += usize::from(cpu);
        if answer.occluded != cpu {
            tally.mismatches += 1;
            if tally.mismatches <= 5 {
                eprintln!(
                    "MISMATCH {what} {} any-hit: {ray:?}: gpu {}, cpu {cpu}",
                    cull.name(),
                    answer.occluded
                );
            }
        }
    }
}

/// Shadow rays spawned on a hit on the GPU against the brute force.
fn check_any_from(
    scene: &Scene,
    gpu_scene: &GpuScene,
    cull: GpuCull,
    rays: &[Spawned],
    what: &str,
    tally: &mut Tally,
) {
    let spawned: Vec<SpawnedRay> = rays.iter().map(spawned_ray).collect();
    let answers = gpu_scene
        .occluded_from(cull, &spawned)
        .expect("occluded_from");
    assert_eq!(answers.len(), rays.len());
    for (s, answer) in rays.iter().zip(answers) {
        count(tally, answer.by);
        let cpu = scene.brute_force_occluded_spawned(s);
        tally.hits += usize::from(cpu);
        if answer.occluded != cpu {
            tally.mismatches += 1;
            if tally.mismatches <= 5 {
                eprintln!(
                    "MISMATCH {what} {} any-hit from torus {}: {:?}: gpu {}, cpu {cpu}",
                    cull.name(),
                    s.from,
                    s.ray,
                    answer.occluded
                );
            }
        }
    }
}

/// Shadow rays from `rays`: t_max at half and at 1.5× each CPU hit.
fn shadow_rays(scene: &Scene, rays: &[Ray]) -> Vec<Ray> {
    rays.iter()
        .filter_map(|r| scene.brute_force(r).map(|(_, t)| (r, t)))
        .flat_map(|(r, t)| [r.with_t_max(0.5 * t), r.with_t_max(1.5 * t)])
        .map(|r| r.expect("a hit's t is a valid t_max"))
        .collect()
}

/// Every GPU cull on every scene layout at R = 10⁻³, 1 and 10³: 0 mismatches.
#[test]
fn gpu_scene_matches_the_brute_force() {
    let Some(gpu) = gpu() else { return };
    let (tori, side, random) = size();
    let start = std::time::Instant::now();
    let _ = writeln!(
        std::io::stderr(),
        "GPU scene: f64 on the device: {:?}",
        gpu.device_finish_unavailable()
    );
    let mut total = Tally::default();
    for &kind in SceneKind::ALL {
        for scale in [1e-3, 1.0, 1e3] {
            let scene = Scene::build_scaled(kind, 4.0, tori, 7, scale).expect("scene");
            let gpu_scene = GpuScene::new(gpu, &scene.tori).expect("GPU scene");
            let mut rays = scene.camera_rays(side);
            rays.extend(scene.random_rays(random, 11));
            let shadows = shadow_rays(&scene, &rays);
            let what = format!("{} R={scale:e}", kind.name());
            let mut tally = Tally::default();
            for cull in GpuCull::ALL {
                check_closest(&scene, &gpu_scene, cull, &rays, &what, &mut tally);
                check_any(&scene, &gpu_scene, cull, &shadows, &what, &mut tally);
            }
            let _ = writeln!(
                std::io::stderr(),
                "{what}: {} rays x culls, {} hits, {} ties, {} mismatches, {} on the device's f64, {} on the host (depth {})",
                tally.rays,
                tally.hits,
                tally.ties,
                tally.mismatches,
                tally.device,
                tally.host,
                gpu_scene.bvh().depth()
            );
            total.rays += tally.rays;
            total.hits += tally.hits;
            total.mismatches += tally.mismatches;
            total.ties += tally.ties;
            total.host += tally.host;
            total.device += tally.device;
        }
    }
    let _ = writeln!(
        std::io::stderr(),
        "GPU scene, all: {total:?} in {:.1} s",
        start.elapsed().as_secs_f64()
    );
    assert_eq!(total.mismatches, 0, "{total:?}");
    assert!(
        total.hits > total.rays / 10,
        "too few hits to mean anything: {total:?}"
    );
    if gpu.finishes_on_device() {
        assert_eq!(
            total.host, 0,
            "rays finished on the host with f64 on the device: {total:?}"
        );
    }
}

/// Secondary rays spawned on the primary rays' hits (`Torus::spawn`: one diffuse bounce and
/// one shadow ray to the scene's light per hit, the lab's `bounce_rays` and
/// `shadow_rays`), traced on the device with their own torus on the surface path and every
/// other on the literal ray: for every GPU cull, on the five layouts at R = 10⁻³, 1 and
/// 10³, and at R = 1 with directions 10⁵ long too (obvhs's clamp case: hits at t below
/// 10⁻⁴), bounces and shadow rays as closest hits and shadow rays as any hits against
/// the CPU's brute force over the scene (`brute_force_spawned`): 0 mismatches.
#[test]
fn gpu_scene_traces_secondary_rays() {
    let Some(gpu) = gpu() else { return };
    let (tori, side, random) = size();
    let start = std::time::Instant::now();
    let mut total = Tally::default();
    let (mut rehits, mut shallow, mut refused) = (0, 0, 0);
    for &kind in SceneKind::ALL {
        for (scale, stretch) in [(1e-3, 1.0), (1.0, 1.0), (1e3, 1.0), (1.0, 1e5)] {
            let scene = Scene::build_scaled(kind, 4.0, tori, 7, scale).expect("scene");
            let gpu_scene = GpuScene::new(gpu, &scene.tori).expect("GPU scene");
            let mut primary = scene.camera_rays(side);
            primary.extend(scene.random_rays(random, 11));
            let hits: Vec<_> = primary.iter().map(|r| scene.brute_force(r)).collect();
            let mut bounces = bounce_rays(&scene, &primary, &hits, 5, stretch);
            bounces.extend(into_and_along(&scene, &primary, &hits, stretch));
            let shadows = spawned_shadows(&scene, &primary, &hits, light(&scene), stretch);
            // Directions beyond [1e-6, 1e6] (shadow rays 1e5 times the way to the light)
            // are the host's (SceneBvh::prepare), once per check and cull.
            refused += 3
                * GpuCull::ALL.len()
                * (bounces.iter())
                    .chain(&shadows)
                    .filter(|s| gpu_scene.bvh().prepare(&s.literal()).is_none())
                    .count();
            for b in &bounces {
                let cpu = scene.brute_force_spawned(b);
                rehits += usize::from(cpu.is_some_and(|(i, _)| i == b.from));
                shallow += usize::from(cpu.is_some_and(|(_, t)| t < 1e-4));
            }
            let what = format!("{} R={scale:e} stretch={stretch:e}", kind.name());
            let mut tally = Tally::default();
            for cull in GpuCull::ALL {
                check_closest_from(&scene, &gpu_scene, cull, &bounces, &what, &mut tally);
                check_closest_from(&scene, &gpu_scene, cull, &shadows, &what, &mut tally);
                check_any_from(&scene, &gpu_scene, cull, &shadows, &what, &mut tally);
            }
            let _ = writeln!(
                std::io::stderr(),
                "{what}: {} bounces, {} shadow rays; {tally:?}",
                bounces.len(),
                shadows.len()
            );
            total.rays += tally.rays;
            total.hits += tally.hits;
            total.mismatches += tally.mismatches;
            total.ties += tally.ties;
            total.host += tally.host;
            total.device += tally.device;
        }
    }
    let _ = writeln!(
        std::io::stderr(),
        "GPU scene, secondary rays: {total:?}; {rehits} bounces re-hit their own torus, \
         {shallow} hit below t = 1e-4; {:.1} s",
        start.elapsed().as_secs_f64()
    );
    assert_eq!(total.mismatches, 0, "{total:?}");
    assert!(total.hits > total.rays / 10, "too few hits: {total:?}");
    assert!(
        rehits > 0 && shallow > 0,
        "{rehits} re-hits, {shallow} shallow hits"
    );
    if gpu.finishes_on_device() {
        assert!(
            total.host <= refused,
            "rays finished on the host: {total:?}"
        );
    }
}

/// Per hit, two rays spawned on the hit torus that its own surface path must answer: into
/// the tube (the facing normal reversed, tilted: every one leaves the tube through its own
/// torus) and along the tangent plane (a grazing ray, 10⁻³ of the normal off it).
fn into_and_along(
    scene: &Scene,
    primary: &[Ray],
    hits: &[Option<(u32, f32)>],
    stretch: f32,
) -> Vec<Spawned> {
    let mut out = Vec::new();
    for (ray, hit) in primary.iter().zip(hits) {
        let Some((id, _)) = *hit else { continue };
        let Some((t, facing)) = scene.facing_hit(id, ray) else {
            continue;
        };
        let n = facing.as_vec3();
        let tangent = n.cross(ray.dir()).normalize_or_zero();
        for dir in [-n + 0.3 * tangent, tangent + 1e-3 * n] {
            if let Some(r) = scene.spawn(id, ray, t, dir.normalize() * stretch) {
                out.push(Spawned { ray: r, from: id });
            }
        }
    }
    out
}

/// Without the device's f64 (turned off), an unproved leaf sends the ray to the host,
/// which answers it with the f64 path over the BVH's candidates: still 0 mismatches, for
/// world rays and for rays spawned on a hit (bounces, into the tube, grazing, shadow rays).
#[test]
fn gpu_scene_without_f64_finishes_on_the_host() {
    if gpu().is_none() {
        return;
    }
    let mut host_only = torus_cull::gpu::GpuIntersector::new().expect("a second device");
    host_only.set_device_finish(false);
    let scene = Scene::build_scaled(SceneKind::RingField, 4.0, 24, 7, 1.0).expect("scene");
    let gpu_scene = GpuScene::new(&host_only, &scene.tori).expect("GPU scene");
    assert!(!gpu_scene.finishes_on_device());
    let mut rays = scene.camera_rays(6);
    rays.extend(scene.random_rays(36, 11));
    let shadows = shadow_rays(&scene, &rays);
    let hits: Vec<_> = rays.iter().map(|r| scene.brute_force(r)).collect();
    let mut bounces = bounce_rays(&scene, &rays, &hits, 5, 1.0);
    bounces.extend(into_and_along(&scene, &rays, &hits, 1.0));
    let lights = spawned_shadows(&scene, &rays, &hits, light(&scene), 1.0);
    let mut tally = Tally::default();
    for cull in [GpuCull::ALL[0], GpuCull::ALL[GpuCull::ALL.len() - 1]] {
        check_closest(&scene, &gpu_scene, cull, &rays, "host-only", &mut tally);
        check_any(&scene, &gpu_scene, cull, &shadows, "host-only", &mut tally);
        check_closest_from(&scene, &gpu_scene, cull, &bounces, "host-only", &mut tally);
        check_any_from(&scene, &gpu_scene, cull, &lights, "host-only", &mut tally);
    }
    let _ = writeln!(std::io::stderr(), "GPU scene without f64: {tally:?}");
    assert_eq!(tally.mismatches, 0, "{tally:?}");
    assert!(tally.host > 0 && tally.device == 0, "{tally:?}");
}

/// obvhs's t_min clamp cases (tests/batch/bvh_family.rs), as literal rays: tiny tori
/// (R = 10⁻⁵, unit directions) and directions 10⁵ long (R = 1), each ray reflected from
/// a hit and started 10⁻³·r outside it, so that neighbours are hit below t = 10⁻⁴.
#[test]
fn gpu_scene_passes_the_obvhs_clamp_cases() {
    let Some(gpu) = gpu() else { return };
    for (scale, length) in [(1e-5, 1.0f32), (1.0, 1e5)] {
        let scene = Scene::build_scaled(SceneKind::Dense, 4.0, 60, 3, scale).expect("scene");
        let gpu_scene = GpuScene::new(gpu, &scene.tori).expect("GPU scene");
        let primary = scene.camera_rays(12);
        let mut bounces = Vec::new();
        for ray in &primary {
            let Some((i, _)) = scene.brute_force(ray) else {
                continue;
            };
            let hit = intersect(&scene.tori[i as usize], ray).expect("a hit");
            let d = ray.dir().normalize();
            let reflected = d - 2.0 * d.dot(hit.normal) * hit.normal;
            let origin = hit.point + hit.normal * (1e-3 * scene.tori[i as usize].minor_radius());
            bounces.push(Ray::new(origin, reflected * length).expect("ray"));
        }
        let shallow = bounces
            .iter()
            .filter(|r| scene.brute_force(r).is_some_and(|(_, t)| t < 1e-4))
            .count();
        let what = format!("clamp case R={scale:e} |d|={length:e}");
        let mut tally = Tally::default();
        for cull in GpuCull::ALL {
            check_closest(&scene, &gpu_scene, cull, &bounces, &what, &mut tally);
        }
        let _ = writeln!(
            std::io::stderr(),
            "{what}: {shallow} bounces hit below t = 1e-4; {tally:?}"
        );
        assert!(shallow > 5, "{what}: only {shallow} hits below t = 1e-4");
        assert_eq!(tally.mismatches, 0, "{what}: {tally:?}");
    }
}

/// A scene the kernel cannot hold is an error that names the limit, not a panic; a ray
/// from a surface point is answered on the host, with the CPU's answer.
#[test]
fn gpu_scene_refuses_what_it_cannot_hold() {
    let Some(gpu) = gpu() else { return };
    let err = GpuScene::new(gpu, &[]).expect_err("no tori");
    assert!(
        matches!(err, GpuError::Scene(_)) && err.to_string().contains("at least one torus"),
        "{err}"
    );
    let far = Torus::new(Vec3::splat(2e12), Vec3::Y, 1.0, 0.25).unwrap();
    let err = GpuScene::new(gpu, &[far]).expect_err("too far");
    assert!(
        err.to_string().contains("allowed: coordinates below"),
        "{err}"
    );
    let torus = Torus::new(Vec3::ZERO, Vec3::Y, 1.0, 0.25).unwrap();
    let scene = GpuScene::new(gpu, &[torus]).expect("one torus");
    let down = Ray::new(Vec3::new(1.0, 5.0, 0.0), Vec3::NEG_Y).unwrap();
    let hit = intersect(&torus, &down).expect("a hit");
    let spawned = torus
        .spawn(&down, hit.t, Vec3::new(0.3, 1.0, 0.1))
        .expect("spawned");
    let answers = scene
        .trace(GpuCull::ALL[0], &[down, spawned])
        .expect("trace");
    assert_eq!(answers[0].hit.map(|h| h.torus), Some(0));
    assert_eq!(answers[1].by, Finished::Host);
    assert_eq!(
        answers[1].hit.map(|h| h.t),
        intersect(&torus, &spawned).map(|h| h.t)
    );
    // Named with its torus, the device answers it (the surface path) as the CPU does: the
    // ray up leaves the torus, the ray down through the tube exits it.
    let into = torus
        .spawn(&down, hit.t, Vec3::new(0.1, -1.0, 0.05))
        .expect("spawned");
    let own = SpawnedRay {
        ray: spawned,
        from: 0,
    };
    let through = SpawnedRay { ray: into, from: 0 };
    let from = scene
        .trace_from(GpuCull::ALL[0], &[own, through])
        .expect("trace_from");
    assert!(intersect(&torus, &into).is_some());
    for (answer, ray) in from.iter().zip([spawned, into]) {
        assert_ne!(answer.by, Finished::Host);
        let (gpu_t, cpu_t) = (
            answer.hit.map(|h| h.t),
            intersect(&torus, &ray).map(|h| h.t),
        );
        assert!(
            gpu_t == cpu_t
                || gpu_t
                    .zip(cpu_t)
                    .is_some_and(|(g, c)| (g - c).abs() <= tolerance(&torus, &ray, c)),
            "{gpu_t:?} vs {cpu_t:?}"
        );
    }
    // From the top of the tube along the tangent plane (the origin's root double: the
    // host forms no cubic), and across the hole to the far side's top: the device's f64
    // finish from the surface answers the own torus where f32 proves nothing.
    let top = Vec3::new(1.0, 0.25, 0.0);
    let grazing: Vec<SpawnedRay> = [Vec3::Z, Vec3::X, Vec3::NEG_X, Vec3::new(-1.0, -1e-3, 0.0)]
        .into_iter()
        .map(|d| SpawnedRay {
            ray: Ray::from_surface(top, d).expect("ray"),
            from: 0,
        })
        .collect();
    let answers = scene
        .trace_from(GpuCull::ALL[0], &grazing)
        .expect("trace_from");
    let mut on_device = 0;
    for (s, answer) in grazing.iter().zip(&answers) {
        let (gpu_t, cpu_t) = (
            answer.hit.map(|h| h.t),
            intersect(&torus, &s.ray).map(|h| h.t),
        );
        assert!(
            gpu_t == cpu_t
                || gpu_t
                    .zip(cpu_t)
                    .is_some_and(|(g, c)| (g - c).abs() <= tolerance(&torus, &s.ray, c)),
            "{:?}: {gpu_t:?} vs {cpu_t:?}",
            s.ray
        );
        on_device += usize::from(answer.by == Finished::Device);
    }
    if scene.finishes_on_device() {
        // Measured on lavapipe: the three rays in the tangent plane.
        assert!(
            on_device >= 2,
            "{on_device} own-torus answers from the f64 finish"
        );
    }
    // A torus the scene does not hold is an error naming the ray and the range.
    let stray = SpawnedRay { from: 1, ..own };
    let err = scene
        .trace_from(GpuCull::ALL[0], &[own, stray])
        .expect_err("no torus 1");
    assert!(
        err.to_string().contains("spawned ray 1") && err.to_string().contains("allowed: 0 ..= 0"),
        "{err}"
    );
    let err = scene
        .occluded_from(GpuCull::ALL[0], &[stray])
        .expect_err("no torus 1");
    assert!(err.to_string().contains("spawned ray 0"), "{err}");
}

/// The torus family's members: the circular ring ones are taken (as the certified f32 path
/// takes them, the same answers as the `Torus`); a horn, a spindle and an elliptical tube
/// are refused in words, naming the member and why.
#[test]
fn gpu_scene_takes_the_familys_ring_members_only() {
    let Some(gpu) = gpu() else { return };
    use torus_cull::family::{Toroid, ToroidError, ToroidKind};
    let ring = Toroid::new(Vec3::ZERO, Vec3::Y, 1.0, 0.25, 0.25).expect("ring");
    let torus = Torus::new(Vec3::ZERO, Vec3::Y, 1.0, 0.25).expect("torus");
    let scene = GpuScene::from_family(gpu, &[ring]).expect("a circular ring member");
    let down = Ray::new(Vec3::new(1.0, 5.0, 0.0), Vec3::NEG_Y).unwrap();
    let hit = scene.trace(GpuCull::ALL[0], &[down]).expect("trace")[0].hit;
    assert_eq!(hit.map(|h| h.torus), Some(0));
    let cpu = intersect(&torus, &down).expect("a hit").t;
    assert!(hit.is_some_and(|h| (h.t - cpu).abs() <= tolerance(&torus, &down, cpu)));
    for (member, kind) in [
        (
            Toroid::new(Vec3::ZERO, Vec3::Y, 1.0, 1.0, 1.0),
            ToroidKind::Horn,
        ),
        (
            Toroid::new(Vec3::ZERO, Vec3::Y, 0.5, 1.0, 1.0),
            ToroidKind::Spindle,
        ),
        (
            Toroid::new(Vec3::ZERO, Vec3::Y, 1.0, 0.25, 0.5),
            ToroidKind::Ring,
        ),
    ] {
        let member = member.expect("a valid member");
        let err = GpuScene::from_family(gpu, &[ring, member]).expect_err("refused");
        match &err {
            GpuError::Member {
                index: 1,
                error: ToroidError::NotCircular { kind: k, .. },
            } => assert_eq!(*k, kind),
            e => panic!("{e:?}"),
        }
        let words = err.to_string();
        assert!(
            words.contains("family member 1") && words.contains("not a circular ring torus"),
            "{words}"
        );
    }
}

/// A torus whose centre f32 does not hold (`Torus::new_f64`, 10³ from the world origin,
/// R = 10⁻²): rays from near it are answered as the CPU answers them. With f64 on the
/// device the leaf forms o − c from the f64 centre (and moves a far origin to its foot
/// point) before the f32 module, so it proves most of them; without, the f32 leaf (which
/// would see an f32-rounded centre) is skipped and the host answers.
#[test]
fn gpu_scene_takes_a_centre_given_in_f64() {
    let Some(gpu) = gpu() else { return };
    use glam::DVec3;
    let c = DVec3::new(1e3 + 1.0 / 3.0, 0.1, -1e3 - 0.2);
    let torus = Torus::new_f64(c, DVec3::new(0.2, 1.0, 0.1), 1e-2, 3e-3).unwrap();
    assert_ne!(torus.center().as_dvec3(), torus.center_f64());
    // From above the ring (along the axis), aimed at points of the core circle: most hit.
    let n = DVec3::new(0.2, 1.0, 0.1).normalize();
    let u = n.cross(DVec3::X).normalize();
    let w = n.cross(u);
    let mut rays = Vec::new();
    for i in 0..64 {
        let a = f64::from(i) * 0.37;
        let target = c + 1e-2 * (a.cos() * u + a.sin() * w);
        let origin = c + 0.05 * n + 0.01 * (a.sin() * u);
        rays.push(Ray::new(origin.as_vec3(), (target - origin).as_vec3()).unwrap());
    }
    let mut host_only = torus_cull::gpu::GpuIntersector::new().expect("a second device");
    host_only.set_device_finish(false);
    for device in [gpu, &host_only] {
        let scene = GpuScene::new(device, &[torus]).expect("one torus");
        let answers = scene.trace(GpuCull::ALL[0], &rays).expect("trace");
        let (mut hits, mut proved) = (0, 0);
        for (ray, a) in rays.iter().zip(&answers) {
            let cpu = intersect(&torus, ray).map(|h| h.t);
            hits += usize::from(cpu.is_some());
            match (a.hit.map(|h| h.t), cpu) {
                (None, None) => {}
                (Some(g), Some(c)) => {
                    assert!((g - c).abs() <= tolerance(&torus, ray, c), "{g} vs {c}")
                }
                (g, c) => panic!("{ray:?}: gpu {g:?}, cpu {c:?}"),
            }
            proved += usize::from(a.hit.is_some() && a.by == Finished::Proved);
        }
        assert!(hits > 10, "{hits} hits");
        if scene.finishes_on_device() {
            assert!(proved > hits / 2, "{proved} of {hits} hits proved in f32");
        } else {
            // A hit came from a leaf, and the f32 leaf is skipped for this torus (a miss
            // may be the box test's, proved on the device).
            assert_eq!(proved, 0, "the f32 leaf must be skipped without f64");
        }
    }
}
