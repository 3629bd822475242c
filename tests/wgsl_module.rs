//! The WGSL module a renderer includes (`torus_cull::gpu::wgsl_module`), through the
//! example's own shader (examples/wgsl_module.rs): the combined shader validates with
//! naga without an adapter, and on whatever adapter wgpu finds (CI: lavapipe) its answers,
//! finished in f64 on the host where they escalate, are the f64 path's on every ray
//! (camera rays near and 10⁴·(R + r) away, grazing rays past the silhouette, and bounces
//! spawned from the surface): 0 missed, 0 invented, every proved t within
//! 2·10⁻⁴·(R + r) (along the unit direction) of the f64 path's. Without an adapter the
//! second test prints one loud SKIPPED line and passes.

#![cfg(feature = "gpu")]

#[path = "../examples/wgsl_module.rs"]
#[allow(dead_code)]
mod example;

use example::{Renderer, combined_shader, compare, example_rays, example_torus, validate};
use glam::Vec3;
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64;
use std::io::Write;
use torus_cull::gpu::{GpuCull, GpuIntersector, ModuleTorus, PreparedRay, wgsl_module};
use torus_cull::{F32Verdict, Ray, Torus};

/// The library's own kernel, where an adapter exists.
fn kernel() -> Option<GpuIntersector> {
    GpuIntersector::new().ok()
}

#[test]
fn the_combined_shader_validates_without_an_adapter() {
    let source = combined_shader();
    let module = validate(&source).unwrap_or_else(|e| panic!("{e}"));
    let entries: Vec<&str> = module
        .entry_points
        .iter()
        .map(|e| e.name.as_str())
        .collect();
    assert_eq!(entries, ["shade"]);
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
            let _ = writeln!(
                std::io::stderr(),
                "SKIPPED: {why}; install the Debian package mesa-vulkan-drivers to run it"
            );
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
