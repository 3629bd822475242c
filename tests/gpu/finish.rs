//! Spawned rays through the kernel, and the f64 finish on the device: who finishes each
//! escalated ray, and its answers against the oracle and the CPU.

use super::*;

/// Issue 26's goal on the GPU: the f32-check's spawned secondary-ray families (bounces,
/// with t_min = 10⁻⁴·r and 10⁻⁴·(R + r), grazing 10⁻⁴…10⁻¹ rad, aimed across at another
/// surface point; R 10⁻³…10³, ν 1.01…1000, random pose), labelled by the oracle's
/// on-surface rule, through the kernel (one torus per ray, so one dispatch each, 100 rays
/// a family to keep lavapipe's dispatches within CI's time): the certified verdicts miss
/// no hit, invent none and put no t outside the tolerance (escalated rays are the f64
/// path's, checked in tests/oracle/secondary_rays.rs).
#[test]
fn spawned_secondary_families_through_the_kernel_against_the_oracle() {
    use torus_cull_lab::check::shapes::ring::{Answer, Labeled, tally};
    let Some(gpu) = gpu() else { return };
    for family in crate::common::spawned_families() {
        let name = &family.name;
        let labeled: Vec<Labeled> = family
            .generate(100, 0x6E0_0026)
            .unwrap()
            .into_iter()
            .map(|(torus, ray)| Labeled::new(torus, ray))
            .collect();
        let certified = tally(&labeled, |torus, ray| {
            Answer::from(gpu.intersect(torus, GpuCull::Skala, &[*ray]).unwrap()[0])
        });
        eprintln!(
            "{name}: {} rays, kernel escalated {:.1} %, missed {} spurious {} far {}",
            labeled.len(),
            100.0 * certified.escalation_rate,
            certified.missed,
            certified.spurious,
            certified.far
        );
        assert!(!certified.failed(), "{name}: {certified:?}");
        // Issue 36's goal: the kernel proves rays from a surface point about as often as
        // the CPU does (its cubic certificate, the cubic formed on the host): at most 1 %
        // of bounces and 10 % of grazing, across and saddle rays escalate.
        let most = if name.starts_with("spawned_bounce") {
            0.01
        } else {
            0.10
        };
        assert!(
            certified.escalation_rate <= most,
            "{name}: the kernel escalated {:.1} % (at most {:.0} %)",
            100.0 * certified.escalation_rate,
            100.0 * most
        );
    }
}

/// One family's device finish: rays by who answered, and what the device's answers were
/// checked against.
#[derive(Default)]
struct FinishTally {
    rays: usize,
    counts: [usize; 3],
    /// Device answers the oracle labels definite hit that came back miss, and definite
    /// miss that came back hit.
    missed: usize,
    invented: usize,
    /// Device answers whose hit-or-miss differs from the CPU's f64 path (any label).
    differ_from_cpu: usize,
    /// Device hits with the same f32 t as the CPU's f64 path, bit for bit.
    same_t: usize,
    device_hits: usize,
    worst_vs_oracle: f64,
    worst_vs_cpu: f64,
    failures: Vec<String>,
}

impl FinishTally {
    fn run(&mut self, gpu: &GpuIntersector, torus: &Torus, rays: &[Ray]) {
        use torus_cull::gpu::Finished;
        let answers = gpu
            .intersect_finished_where(torus, GpuCull::NoCull, rays)
            .expect("dispatch");
        for (ray, (answer, finished)) in rays.iter().zip(answers) {
            self.rays += 1;
            self.counts[match finished {
                Finished::Proved => 0,
                Finished::Device => 1,
                _ => 2,
            }] += 1;
            if finished != Finished::Device {
                continue;
            }
            let cpu = intersect(torus, ray);
            let query = Query::ray(torus, ray);
            // A ray from a surface point is labelled past its origin's own root.
            let label = if ray.starts_on_surface() {
                torus_cull_lab::oracle::classify_from_surface(&query)
            } else {
                query.classify()
            };
            let mut fail = |text: String| {
                if self.failures.len() < 10 {
                    self.failures.push(format!("{text}: {ray:?} on {torus:?}"));
                }
            };
            if answer.hit.is_some() != cpu.is_some() {
                self.differ_from_cpu += 1;
                fail(format!(
                    "device {:?}, CPU f64 {cpu:?} ({label:?})",
                    answer.hit
                ));
            }
            match (label.class, answer.hit) {
                (OracleClass::Hit, None) => {
                    self.missed += 1;
                    fail(format!("device miss for a definite hit {label:?}"));
                }
                (OracleClass::Miss, Some(hit)) => {
                    self.invented += 1;
                    fail(format!("device hit {hit:?} for a definite miss {label:?}"));
                }
                _ => {}
            }
            let Some(hit) = answer.hit else { continue };
            self.device_hits += 1;
            let len = f64::from(ray.dir().length());
            let scale = |t_ref: f64| t_ref.abs().max(f64::from(torus.outer_radius()) / len);
            if let Some(cpu) = cpu {
                self.same_t += usize::from(cpu.t.to_bits() == hit.t.to_bits());
                let rel = f64::from(hit.t - cpu.t).abs() / scale(f64::from(cpu.t));
                self.worst_vs_cpu = self.worst_vs_cpu.max(rel);
                if rel > DEVICE_T_TOLERANCE_REL || cpu.front_face != hit.front_face {
                    fail(format!("device {hit:?} vs CPU f64 {cpu:?}"));
                }
                if (hit.normal - cpu.normal).length() > 1e-5 {
                    fail(format!(
                        "device normal {} vs CPU {}",
                        hit.normal, cpu.normal
                    ));
                }
            }
            if label.class == OracleClass::Hit && !ray.starts_on_surface() {
                let reference = reference_roots(&query)[0];
                let rel = (f64::from(hit.t) - reference).abs() / scale(reference);
                self.worst_vs_oracle = self.worst_vs_oracle.max(rel);
                if rel > DEVICE_T_TOLERANCE_REL {
                    fail(format!("device t = {} vs oracle {reference}", hit.t));
                }
            }
        }
    }

    fn report(&self, name: &str) {
        let [proved, device, host] = self.counts;
        println!(
            "{name:<34} {:>6} rays: proved {proved:>6}, finished on the device {device:>5}, \
             on the host {host:>4}; device: {} hits ({} with the CPU's t to the bit), \
             missed {}, invented {}, differ from CPU f64 {}, worst t vs oracle {:.1e}, vs \
             CPU {:.1e}",
            self.rays,
            self.device_hits,
            self.same_t,
            self.missed,
            self.invented,
            self.differ_from_cpu,
            self.worst_vs_oracle,
            self.worst_vs_cpu,
        );
    }
}

/// Escalation on the device (issue 27, item 2): on an adapter with f64 every ray of the
/// families that escalate (the hole at ν = 1.01, grazing rays at every ν, near and
/// 10⁵·(R + r) away, lines hugging the hole's edge and tangent to the special circles at
/// ±10⁻⁶·r) is finished on the device (0 on the host), and every device answer is the
/// CPU's f64 path's: 0 missed and 0 invented against the oracle, the same hit or miss as
/// the CPU, t within 1.2·10⁻⁷ (relative) of the CPU's and of the oracle's first root.
/// The f32-check families of secondary rays from hit points (`Ray::from_surface`, their
/// own root divided out on the device as on the CPU) are held to the same, their oracle
/// label taken past the origin.
#[test]
fn escalated_rays_are_finished_on_the_device_in_f64() {
    let Some(gpu) = gpu() else { return };
    if !gpu.finishes_on_device() {
        let _ = writeln!(
            std::io::stderr(),
            "SKIPPED device finish: {}",
            gpu.device_finish_unavailable().unwrap_or_default()
        );
        return;
    }
    let families = escalating_families(1);
    let mut failures = Vec::new();
    let mut total_device = 0;
    for (name, sets) in &families {
        let mut tally = FinishTally::default();
        for (torus, rays) in sets {
            tally.run(gpu, torus, rays);
        }
        tally.report(name);
        let [_, device, host] = tally.counts;
        total_device += device;
        if host != 0 || !tally.failures.is_empty() {
            failures.push(format!(
                "{name}: {device} finished on the device, {host} on the host\n{}",
                tally.failures.join("\n")
            ));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    assert!(
        total_device > 10_000,
        "{total_device} finished on the device"
    );
}

/// Rays from a surface point that the kernel escalates (exactly tangent to the surface:
/// neither the cubic, whose constant is 0, nor a literal start proves them) are finished
/// on the device where it has f64, with the CPU's answer; rays into the tube are proved by
/// the kernel's cubic, with the CPU's answer too.
#[test]
fn rays_from_the_surface_are_finished_on_the_device() {
    use torus_cull::gpu::FinishCounts;
    let Some(gpu) = gpu() else { return };
    let torus = Torus::canonical(4.0, 1.0).unwrap();
    // Into the tube from the top of it (the cubic proves their exit), out of it, off the
    // surface, and along the top circle's tangents (escalated).
    let rays = [
        Ray::from_surface(Vec3::new(4.0, 1.0, 0.0), Vec3::NEG_Y).unwrap(),
        Ray::from_surface(Vec3::new(4.0, 1.0, 0.0), Vec3::new(0.3, -1.0, 0.1)).unwrap(),
        Ray::from_surface(Vec3::new(5.0, 0.0, 0.0), Vec3::X).unwrap(),
        Ray::from_surface(Vec3::new(4.0, 1.0, 0.0), Vec3::X).unwrap(),
        Ray::from_surface(Vec3::new(4.0, 1.0, 0.0), Vec3::Z).unwrap(),
    ];
    let answers = gpu
        .intersect_finished_where(&torus, GpuCull::NoCull, &rays)
        .expect("dispatch");
    for (ray, (answer, _)) in rays.iter().zip(&answers) {
        let cpu = intersect(&torus, ray);
        assert_eq!(answer.hit.is_some(), cpu.is_some(), "{ray:?}");
        if let (Some(h), Some(c)) = (answer.hit, cpu) {
            assert!(
                (h.t - c.t).abs() <= 1e-6 * c.t.abs().max(1.0),
                "{ray:?}: {h:?} vs {c:?}"
            );
            assert_eq!(h.front_face, c.front_face, "{ray:?}");
        }
    }
    let counts = FinishCounts::of(answers.iter().map(|(_, f)| f));
    let escalated = counts.device + counts.host;
    assert!(escalated >= 2, "{counts:?}");
    if gpu.finishes_on_device() {
        assert_eq!(counts.host, 0, "{counts:?}");
    } else {
        assert_eq!(counts.device, 0, "{counts:?}");
    }
}

/// `set_device_finish(false)` finishes every escalated ray on the host, and the host's
/// answers are the device's (the same hit or miss, the same f32 t) on the grazing rays.
#[test]
fn host_and_device_finishes_agree() {
    use torus_cull::gpu::{FinishCounts, Finished};
    let Some(gpu) = gpu() else { return };
    if !gpu.finishes_on_device() {
        return;
    }
    let mut host = GpuIntersector::new().expect("the same adapter again");
    host.set_device_finish(false);
    assert!(!host.finishes_on_device());
    assert!(host.device_finish_unavailable().is_some());
    for batch in family(Case::Grazing, 3.0, 500, 0xF4) {
        let rays: Vec<Ray> = pairs(std::slice::from_ref(&batch))
            .map(|(_, r)| *r)
            .collect();
        let on_device = gpu
            .intersect_finished_where(&batch.torus, GpuCull::NoCull, &rays)
            .unwrap();
        let on_host = host
            .intersect_finished_where(&batch.torus, GpuCull::NoCull, &rays)
            .unwrap();
        let (d, h) = (
            FinishCounts::of(on_device.iter().map(|(_, f)| f)),
            FinishCounts::of(on_host.iter().map(|(_, f)| f)),
        );
        assert_eq!(h.device, 0, "{h:?}");
        assert_eq!(
            (d.proved, d.device + d.host),
            (h.proved, h.host),
            "{d:?} {h:?}"
        );
        for (ray, ((a, fa), (b, fb))) in rays.iter().zip(on_device.iter().zip(&on_host)) {
            assert_eq!(*fb == Finished::Host, *fa == Finished::Device, "{ray:?}");
            assert_eq!(
                a.hit.map(|h| h.t.to_bits()),
                b.hit.map(|h| h.t.to_bits()),
                "{ray:?}"
            );
        }
    }
}

/// Lines perpendicular to the axis at the height of the tube's top (an even quartic whose
/// `p² − 4r` is within rounding of 0: tangent at two points symmetric about the foot
/// point), and at ±1…±6 f32 steps above and below it, at three sizes and poses off the
/// origin, in many directions: the CPU decides the sign with a fused multiply-add, the
/// device with its fma-free exact sign (`tc_disc_sign64`, proved against the fused one in
/// quartic/exact_sign.rs). Every escalated ray is finished on the device, none on the
/// host, with the CPU's hit or miss and t within the device tolerance.
#[test]
fn even_tangents_at_the_foot_point_are_finished_on_the_device() {
    use torus_cull::gpu::{FinishCounts, Finished};
    let Some(gpu) = gpu() else { return };
    if !gpu.finishes_on_device() {
        return;
    }
    let (mut rays_total, mut bits_equal, mut hits) = (0, 0, 0);
    let mut counts = [0usize; 3];
    for (centre, major, minor) in [
        (Vec3::ZERO, 4.0f32, 1.0f32),
        (Vec3::new(3.0, -2.0, 7.0), 2.0, 0.5),
        (Vec3::new(-1e3, 250.0, 40.0), 300.0, 0.75),
    ] {
        let torus = Torus::new(centre, Vec3::Y, major, minor).unwrap();
        let mut rays = Vec::new();
        for step in -6i32..=6 {
            let top = centre.y + minor;
            let y = f32::from_bits((top.to_bits() as i32 + step) as u32);
            for k in 0..24 {
                let angle = k as f32 * 0.2618;
                let dir = Vec3::new(angle.cos(), 0.0, angle.sin());
                // Through foot points from the axis out past the tube: the line at the
                // top's height touches it twice wherever its foot point is inside R.
                let foot = centre + Vec3::new(-dir.z, 0.0, dir.x) * (major * (k % 8) as f32 / 6.0);
                let origin = Vec3::new(foot.x, y, foot.z) - dir * (3.0 * (major + minor));
                rays.push(Ray::new(origin, dir).unwrap());
            }
        }
        let answers = gpu
            .intersect_finished_where(&torus, GpuCull::NoCull, &rays)
            .unwrap();
        let c = FinishCounts::of(answers.iter().map(|(_, f)| f));
        for (sum, n) in counts.iter_mut().zip([c.proved, c.device, c.host]) {
            *sum += n;
        }
        for (ray, (answer, finished)) in rays.iter().zip(&answers) {
            assert_ne!(*finished, Finished::Host, "{ray:?}: handed to the host");
            let cpu = torus_cull::intersect(&torus, ray);
            assert_eq!(
                answer.hit.is_some(),
                cpu.is_some(),
                "{ray:?}: {answer:?} vs {cpu:?}"
            );
            if let (Some(h), Some(c)) = (answer.hit, cpu) {
                hits += 1;
                bits_equal += usize::from(h.t.to_bits() == c.t.to_bits());
                assert!(
                    (h.t - c.t).abs() as f64 <= DEVICE_T_TOLERANCE_REL * c.t.abs() as f64,
                    "{ray:?}: {h:?} vs {c:?}"
                );
            }
        }
        rays_total += rays.len();
    }
    eprintln!(
        "even tangents: {rays_total} rays, [proved, device, host] {counts:?}, {hits} hits ({bits_equal} with the CPU's t to the bit)"
    );
    assert!(counts[1] >= 100, "{counts:?}: too few reached the f64 pass");
}

/// Under `CI=true` the device's f64 pass must exist: CI's adapter (lavapipe) offers
/// `SHADER_F64`, and where the pass fails to build every f64 test here prints SKIPPED and
/// passes. That hid a regression once: a fifth storage buffer over wgpu's default limit
/// of four switched the pass off on lavapipe. An adapter without f64 sets
/// `TORUS_CULL_GPU_WITHOUT_F64=1` to run the rest.
#[test]
fn under_ci_the_device_finish_pass_exists() {
    let Some(gpu) = gpu() else { return };
    let allowed = std::env::var("TORUS_CULL_GPU_WITHOUT_F64").is_ok_and(|v| v == "1");
    if crate::common::under_ci() && !allowed {
        assert!(
            gpu.finishes_on_device(),
            "the device's f64 finish pass is unavailable under CI=true: {}",
            gpu.device_finish_unavailable().unwrap_or_default()
        );
    }
}
