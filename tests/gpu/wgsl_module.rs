//! The WGSL module a renderer includes (`torus_cull::gpu::wgsl_module`), through the
//! example's own shader (examples/wgsl_module.rs): the combined shader validates with
//! naga without an adapter, and on whatever adapter wgpu finds (CI: lavapipe) its answers,
//! finished in f64 on the host where they escalate, are the f64 path's on every ray
//! (camera rays near and 10⁴·(R + r) away, grazing rays past the silhouette, and bounces
//! spawned from the surface): 0 missed, 0 invented, every proved t within
//! 2·10⁻⁴·(R + r) (along the unit direction) of the f64 path's. Without an adapter the
//! second test prints one loud SKIPPED line and passes (under `CI=true` it fails).
//!
//! The f64 module (`torus_cull::gpu::wgsl_finish_module`), in the example's second shader
//! beside the f32 module: it validates with naga's `FLOAT64` (and not without), and where
//! the adapter offers `SHADER_F64` (lavapipe does) the shader, which calls
//! `torus_intersect` and then `torus_finish_f64` on the rays it does not prove, gives on
//! tests/gpu/gpu.rs's adversarial families (the hole at ν = 1.01, grazing rays at every ν,
//! near and 10⁵·(R + r) away, lines hugging the hole's edge and tangent to the special
//! circles at ±10⁻⁶·r, secondary rays from hit points) the library's
//! `intersect_finished_where` answers: the same hit or miss on every ray, 0 missed and 0
//! invented against the f64 path, device-finished t within 1.2·10⁻⁷ of the CPU's, none
//! handed to the host.

#![cfg(feature = "gpu")]

#[path = "../../examples/wgsl_module.rs"]
#[allow(dead_code)]
mod example;

use crate::common::adversarial::{DEVICE_T_TOLERANCE_REL, escalating_families};
use example::{
    Renderer, combined_shader, combined_shader_f64, compare, compare_f64, example_rays,
    example_torus, prepare_both, validate, validate_f64,
};
use glam::Vec3;
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64;
use std::io::Write;
use torus_cull::gpu::{
    Finished, GpuCull, GpuIntersector, ModuleTorus, PreparedRay, wgsl_finish_module, wgsl_module,
};
use torus_cull::{F32Verdict, Ray, Torus, intersect};

/// The library's own kernel, where an adapter exists (under CI=true: must exist).
fn kernel() -> Option<GpuIntersector> {
    match GpuIntersector::new() {
        Ok(kernel) => Some(kernel),
        Err(e) => {
            crate::common::no_adapter(&e.to_string());
            None
        }
    }
}

/// The names of a validated module's entry points.
fn entry_names(module: &torus_cull::gpu::wgpu::naga::Module) -> Vec<&str> {
    module
        .entry_points
        .iter()
        .map(|e| e.name.as_str())
        .collect()
}

#[test]
fn the_combined_shader_validates_without_an_adapter() {
    let source = combined_shader();
    let module = validate(&source).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(entry_names(&module), ["shade"]);
    // The renderer's four bindings, none of the library kernel's.
    assert_eq!(module.global_variables.len(), 4);
    assert!(source.starts_with(&wgsl_module()));
    // A renderer that redefines a module name is told so by naga, not silently shadowed.
    let clash = format!("{}\nfn torus_intersect() {{}}\n", wgsl_module());
    assert!(validate(&clash).is_err());
}

/// Rays that graze the torus's silhouette from outside, at random poses of the camera:
/// aimed at a point within ±10⁻³·r of the outer equator's distance from the axis.
fn grazing_rays(torus: &Torus, count: usize, rng: &mut Pcg64) -> Vec<Ray> {
    let c = torus.center();
    let axis = torus.axis();
    let outer = torus.major_radius() + torus.minor_radius();
    let side = axis.any_orthonormal_vector();
    let other = axis.cross(side);
    (0..count)
        .filter_map(|_| {
            let angle = rng.random_range(0.0..std::f32::consts::TAU);
            let radial = side * angle.cos() + other * angle.sin();
            let offset = 1.0 + rng.random_range(-1e-3f32..1e-3) * torus.minor_radius() / outer;
            let target = c + radial * (outer * offset);
            let tangent = axis.cross(radial);
            let tilt = rng.random_range(-0.5f32..0.5);
            let dir = (tangent + axis * tilt).normalize();
            Ray::new(target - dir * (3.0 * outer), dir).ok()
        })
        .collect()
}

#[test]
fn the_combined_shader_agrees_with_the_f64_path_on_the_adapter() {
    let renderer = match Renderer::new() {
        Ok(r) => r,
        Err(why) => {
            // Panics under CI=true: CI must run the shader.
            crate::common::no_adapter(&why);
            return;
        }
    };
    let mut rng = Pcg64::seed_from_u64(274);
    let example = example_torus();
    let big = Torus::new(
        Vec3::new(-1e3, 40.0, 7.0),
        Vec3::new(-0.4, 0.2, 1.0),
        40.0,
        4.0,
    )
    .expect("a valid torus");
    let mut total = 0;
    for torus in [example, big] {
        let module_torus = ModuleTorus::new(&torus);
        let mut rays = example_rays(&torus);
        rays.extend(grazing_rays(&torus, 200, &mut rng));
        let prepared: Vec<PreparedRay> = rays.iter().map(|r| module_torus.prepare(r)).collect();
        let answers = renderer
            .run(&module_torus, &prepared)
            .expect("the shader ran");
        let c = compare(&torus, &rays, &prepared, &answers);
        let _ = writeln!(
            std::io::stderr(),
            "{} (ν = {}): {} rays, {} hits (f64), {} proved hits, {} escalated; {} missed, \
             {} invented, worst proved |Δt|·|d| = {:.2e}·(R + r)",
            renderer.adapter,
            torus.nu(),
            c.rays,
            c.exact_hits,
            c.proved_hits,
            c.escalated,
            c.missed,
            c.invented,
            c.worst_t_rel
        );
        assert_eq!((c.missed, c.invented), (0, 0), "{c:?}");
        // The library's kernel (the same module text behind its own bindings) on the same
        // rays: no proved answer contradicts the user shader's.
        if let Some(kernel) = kernel() {
            let verdicts = kernel
                .explain(&torus, GpuCull::Skala, &rays)
                .expect("the kernel ran");
            let mut same = 0;
            for ((p, a), (k, _)) in prepared.iter().zip(&answers).zip(&verdicts) {
                let (v, _) = p.verdict(a.t, a.normal, a.code, a.why);
                let contradiction = matches!(
                    (v, *k),
                    (F32Verdict::Hit { .. }, F32Verdict::Miss)
                        | (F32Verdict::Miss, F32Verdict::Hit { .. })
                );
                assert!(!contradiction, "{v:?} vs the kernel's {k:?}");
                same += usize::from(v == *k);
            }
            let _ = writeln!(
                std::io::stderr(),
                "  the library's kernel gives the same verdict (t and normal to the bit) on \
                 {same} of {} rays",
                rays.len()
            );
        }
        assert!(c.worst_t_rel <= 2e-4, "{c:?}");
        // The module proves most of them: it is not escalating its way to agreement.
        assert!(2 * c.proved_hits > c.exact_hits, "{c:?}");
        assert!(c.escalated < c.rays / 2, "{c:?}");
        total += c.rays;
    }
    assert!(total >= 500, "{total} rays");
}

#[test]
fn the_f64_shader_validates_with_float64_without_an_adapter() {
    let source = combined_shader_f64();
    let module = validate_f64(&source).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(entry_names(&module), ["shade_f64"]);
    // The renderer's four bindings, none of the library passes'.
    assert_eq!(module.global_variables.len(), 4);
    assert!(source.starts_with(&format!("{}\n{}", wgsl_module(), wgsl_finish_module())));
    for call in [
        "torus_intersect(",
        "torus_finish_wanted(",
        "torus_finish_f64(",
    ] {
        assert!(example::USER_SHADER_F64.contains(call), "{call}");
    }
    // f64 needs the capability (SHADER_F64 on the device).
    assert!(validate(&source).is_err());
    // The f64 module alone validates; a renderer that redefines one of its names is told.
    validate_f64(&wgsl_finish_module()).unwrap_or_else(|e| panic!("{e}"));
    let clash = format!("{}\nfn torus_finish_f64() {{}}\n", wgsl_finish_module());
    assert!(validate_f64(&clash).is_err());
}

#[test]
fn the_f64_shader_gives_the_librarys_finished_answers_on_the_adapter() {
    let renderer = match Renderer::new() {
        Ok(r) => r,
        Err(why) => {
            // Panics under CI=true: CI must run the shader.
            crate::common::no_adapter(&why);
            return;
        }
    };
    if let Some(why) = renderer.f64_unavailable() {
        // Under CI=true, lavapipe offers f64: a module that does not build there is a
        // failure, not a skip (see finish.rs, under_ci_the_device_finish_pass_exists).
        let allowed = std::env::var("TORUS_CULL_GPU_WITHOUT_F64").is_ok_and(|v| v == "1");
        assert!(
            !crate::common::under_ci() || allowed,
            "the f64 module is unavailable under CI=true: {why}"
        );
        let _ = writeln!(std::io::stderr(), "SKIPPED f64 module: {why}");
        return;
    }
    let kernel = GpuIntersector::new().expect("the library's kernel on the same adapter");
    let _ = writeln!(
        std::io::stderr(),
        "{}; the library finishes on the device: {}",
        renderer.adapter,
        kernel.finishes_on_device()
    );
    let mut failures = Vec::new();
    let (mut total, mut total_device) = (0, 0);
    let clock = std::time::Instant::now();
    for (name, sets) in escalating_families(2) {
        let (mut rays_n, mut device, mut host, mut lib_device, mut lib_host) = (0, 0, 0, 0, 0);
        let (mut differ, mut missed, mut invented, mut same_who) = (0, 0, 0, 0);
        let (mut both_hit, mut same_t) = (0, 0);
        let (mut worst_vs_cpu, mut worst_vs_library) = (0f64, 0f64);
        for (torus, rays) in &sets {
            let module_torus = ModuleTorus::new(torus);
            let both = prepare_both(&module_torus, rays);
            let answers = renderer
                .run_f64(&module_torus, &both)
                .expect("the shader ran");
            let c = compare_f64(torus, rays, &both, &answers);
            let library = kernel
                .intersect_finished_where(torus, GpuCull::Skala, rays)
                .expect("the library ran");
            rays_n += c.rays;
            device += c.counts.device;
            host += c.counts.host;
            missed += c.missed;
            invented += c.invented;
            for ((ray, (mine, who)), (theirs, their_who)) in
                rays.iter().zip(&c.answers).zip(&library)
            {
                lib_device += usize::from(*their_who == Finished::Device);
                lib_host += usize::from(*their_who == Finished::Host);
                same_who += usize::from(who == their_who);
                match (mine.hit, theirs.hit) {
                    (Some(a), Some(b)) => {
                        both_hit += 1;
                        same_t += usize::from(a.t.to_bits() == b.t.to_bits());
                        // Both are the first root's t: f64-finished to rounding, or proved
                        // within 2·10⁻⁴·(R + r) along the unit direction.
                        let len = f64::from(ray.dir().length());
                        let rel =
                            f64::from(a.t - b.t).abs() * len / f64::from(torus.outer_radius());
                        worst_vs_library = worst_vs_library.max(rel);
                        if a.front_face != b.front_face || rel > 4e-4 {
                            differ += 1;
                            if failures.len() < 10 {
                                failures.push(format!(
                                    "{name}: shader {a:?} ({who:?}), library {b:?} \
                                     ({their_who:?}): {ray:?} on {torus:?}"
                                ));
                            }
                        }
                    }
                    (None, None) => {}
                    _ => {
                        differ += 1;
                        if failures.len() < 10 {
                            failures.push(format!(
                                "{name}: shader {mine:?} ({who:?}), library {theirs:?} \
                                 ({their_who:?}): {ray:?} on {torus:?}"
                            ));
                        }
                    }
                }
                if *who != Finished::Device {
                    continue;
                }
                if let (Some(hit), Some(cpu)) = (mine.hit, intersect(torus, ray)) {
                    let len = f64::from(ray.dir().length());
                    let scale = f64::from(cpu.t)
                        .abs()
                        .max(f64::from(torus.outer_radius()) / len);
                    let rel = f64::from(hit.t - cpu.t).abs() / scale;
                    worst_vs_cpu = worst_vs_cpu.max(rel);
                    if rel > DEVICE_T_TOLERANCE_REL && failures.len() < 10 {
                        failures.push(format!("{name}: device {hit:?} vs CPU f64 {cpu:?}"));
                    }
                }
            }
        }
        println!(
            "{name:<30} {rays_n:>4} rays: shader device {device:>4} host {host}, library \
             device {lib_device:>4} host {lib_host}; same who {same_who}, differ {differ}, \
             both hit {both_hit} (same t bits {same_t}, worst |Δt|·|d| \
             {worst_vs_library:.1e}·(R+r)); vs f64 path missed {missed} invented \
             {invented}, worst device t vs CPU {worst_vs_cpu:.1e} ({} tori, {:.1} s in)",
            sets.len(),
            clock.elapsed().as_secs_f64()
        );
        if differ + missed + invented > 0 || host > lib_host {
            failures.push(format!(
                "{name}: {differ} differ from the library, {missed} missed, {invented} \
                 invented, {host} on the host (library {lib_host})"
            ));
        }
        total += rays_n;
        total_device += device;
    }
    println!("total: {total} rays, {total_device} finished by the shader's f64 module");
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    assert!(
        total_device > 3_000,
        "{total_device} finished by the f64 module"
    );
}
