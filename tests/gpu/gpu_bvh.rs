//! The GPU BVH timed (`torus-cull time gpu-bvh`, `torus_cull_lab::paired::gpu_bvh`,
//! `torus_cull::gpu::SceneRays`) at smoke size on whatever adapter wgpu finds (CI:
//! lavapipe, where the figures are a CPU's and say so), and the device script's smoke run
//! of its BVH step.

#![cfg(feature = "gpu")]

use crate::gpu::gpu;
use torus_cull::gpu::{GpuCull, GpuScene, SpawnedRay};
use torus_cull_lab::paired::gpu_bvh::{COPY, GPU_BVH_ANYHIT, GPU_BVH_CLOSEST, GPU_BVH_METRICS};
use torus_cull_lab::results::Results;
use torus_cull_lab::scene::rays::{light, shadow_rays};
use torus_cull_lab::scene::{Scene, SceneKind};

/// The command line of the mode, before its flags: `time gpu-bvh` once `time` has
/// subcommands.
const MODE: &[&str] = &["time", "gpu-bvh"];

fn torus_cull(args: &[&str]) -> std::process::Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_torus-cull"))
        .args(MODE.iter().chain(args))
        .output()
        .expect("run torus-cull")
}

/// Every cull's closest and any-hit answers on resident rays equal `none`'s (a cull never
/// changes an answer) and the one-call path's, on a lab scene with its camera rays and the
/// shadow rays spawned on their hits; the copy kernel runs over both.
#[test]
fn resident_leaf_culls_answer_as_none() {
    let Some(gpu) = gpu() else { return };
    let scene = Scene::build(SceneKind::Chain, 4.0, 48, 7).unwrap();
    let camera = scene.camera_rays(16);
    let gpu_scene = GpuScene::new(gpu, &scene.tori).unwrap();
    let hits: Vec<Option<(u32, f32)>> = gpu_scene
        .trace(GpuCull::NoCull, &camera)
        .unwrap()
        .iter()
        .map(|a| a.hit.map(|h| (h.torus, h.t)))
        .collect();
    let shadow: Vec<SpawnedRay> = shadow_rays(&scene, &camera, &hits, light(&scene), 1.0)
        .into_iter()
        .map(|s| SpawnedRay {
            ray: s.ray,
            from: s.from,
        })
        .collect();
    assert!(shadow.len() > 20, "{} camera hits", shadow.len());
    let camera_rays = gpu_scene.upload_rays(&camera).unwrap();
    let shadow_rays = gpu_scene.upload_spawned(&shadow).unwrap();
    camera_rays.run(GpuCull::NoCull, false, 2).unwrap();
    let none_closest = camera_rays.closest_answers().unwrap();
    shadow_rays.run(GpuCull::NoCull, true, 2).unwrap();
    let none_any = shadow_rays.any_answers().unwrap();
    assert_eq!(
        none_closest,
        gpu_scene.trace(GpuCull::NoCull, &camera).unwrap()
    );
    assert!(none_any.iter().any(|a| a.occluded) && none_any.iter().any(|a| !a.occluded));
    for cull in GpuCull::ALL {
        camera_rays.run(cull, false, 1).unwrap();
        let closest = camera_rays.closest_answers().unwrap();
        for (i, (a, b)) in closest.iter().zip(&none_closest).enumerate() {
            let (a, b) = (a.hit.map(|h| (h.torus, h.t)), b.hit.map(|h| (h.torus, h.t)));
            assert_eq!(a, b, "{cull} camera ray {i}");
        }
        shadow_rays.run(cull, true, 1).unwrap();
        let any = shadow_rays.any_answers().unwrap();
        for (i, (a, b)) in any.iter().zip(&none_any).enumerate() {
            assert_eq!(a.occluded, b.occluded, "{cull} shadow ray {i}");
        }
    }
    for rays in [&camera_rays, &shadow_rays] {
        let copy = rays.run_copy(2).unwrap();
        assert!(copy.wall.as_nanos() > 0);
        assert!(copy.device.is_empty() || copy.device.len() == 2);
    }
}

/// Bad flags are refused naming the flag and what is allowed, before any work.
#[test]
fn time_gpu_bvh_refuses_bad_flags() {
    for (args, want) in [
        (
            &["--culls", "bogus"][..],
            "--culls: 'bogus' is not a GPU cull (allowed: none,",
        ),
        (
            &["--batch", "3"][..],
            "--batch 3 is invalid (allowed: 16 ..=",
        ),
        (
            &["--scenes", "ring"][..],
            "--scenes: 'ring' is not a scene (allowed: ring_field",
        ),
        (&["--nu", "0.5"][..], "--nu 0.5 is invalid (allowed: nu > 1"),
        (&["--tori", "0"][..], "--tori 0 is invalid (allowed: 1 ..="),
        (&["--seconds", "0"][..], "--seconds 0 is invalid"),
        (
            &["--runs", "0"][..],
            "--runs 0 is invalid (allowed: 1 ..= 100)",
        ),
    ] {
        let out = torus_cull(args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(stderr.contains(want), "{args:?}: {stderr}");
    }
}

/// `benches/gpu_device.sh --smoke --steps bvh,subm`: the script's checks, its BVH step
/// (`time gpu-bvh` at smoke size) and its submissions log (`time gpu-submissions`)
/// through the binary under test, a finished log; the submissions' CSV, a line per
/// submission; and the BVH step's records: every GPU cull over `none` (closest and any hit) and every cull over
/// the copy kernel, positive times, the adapter named (a software one called a CPU proxy),
/// a between-run interval where both runs were kept; `compare` reads them and `plot` draws
/// them.
#[test]
fn device_script_smoke_times_the_gpu_bvh() {
    let Some(gpu) = gpu() else { return };
    let dir = tempfile::tempdir().unwrap();
    let out = std::process::Command::new("bash")
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .env_remove("OUT")
        .args([
            "benches/gpu_device.sh",
            "--smoke",
            "--steps",
            "bvh,subm",
            "--bin",
            env!("CARGO_BIN_EXE_torus-cull"),
            "--out",
            dir.path().to_str().unwrap(),
        ])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    let log = std::fs::read_to_string(dir.path().join("summary.log")).unwrap();
    assert!(log.contains("bvh: done"), "{log}");
    assert!(log.contains("none") && log.contains("Mrays/s"), "{log}");
    assert!(log.contains("exit 0"), "{log}");
    assert!(log.contains("subm: done"), "{log}");
    // Copy, none and discriminant, 2 submissions each, at 2 batch sizes; and a header.
    let csv = std::fs::read_to_string(dir.path().join("subm-submissions.csv")).unwrap();
    assert_eq!(csv.lines().count(), 1 + 2 * 3 * 2, "{csv}");
    assert!(
        csv.lines().any(|l| l.starts_with("4032,discriminant,1,")),
        "{csv}"
    );
    let subm = Results::load(&dir.path().join("subm.json")).unwrap();
    assert!(
        subm.estimates
            .iter()
            .any(|e| e.benchmark == "gpu_submission_ns-uniform/copy/4096" && e.ns_per_element > 0.0),
        "{:?}",
        subm.estimates
    );
    let path = dir.path().join("bvh.json");
    let results = Results::load(&path).unwrap();
    let device = results.meta.device.clone().unwrap();
    assert!(device.contains(gpu.adapter_name()), "{device}");
    assert_eq!(gpu.is_software(), device.contains("CPU proxy"), "{device}");
    let scenes = ["ring_field", "facing_grid"];
    for scene in scenes {
        for metric in GPU_BVH_METRICS {
            for cull in GpuCull::ALL {
                let find = |reference: &str| {
                    results.ratio.iter().find(|r| {
                        (r.case.as_str(), r.nu, r.cull.as_str(), r.metric.as_str())
                            == (scene, 4.0, cull.name(), metric)
                            && r.reference == reference
                    })
                };
                let copy = find(COPY).unwrap_or_else(|| panic!("{scene} {cull} {metric} copy"));
                assert!(
                    copy.ns_per_ray > 0.0 && copy.reference_ns_per_ray > 0.0,
                    "{copy:?}"
                );
                let over_none = find("none");
                if cull == GpuCull::NoCull {
                    assert!(over_none.is_none());
                    continue;
                }
                let r = over_none.unwrap_or_else(|| panic!("{scene} {cull} {metric} none"));
                assert!(r.ratio.is_finite() && r.ratio > 0.0, "{r:?}");
                assert!(r.ns_per_ray > 0.0 && r.reference_ns_per_ray > 0.0, "{r:?}");
                assert_eq!((r.device.as_str(), r.precision.as_str()), ("gpu", "f32"));
                assert_eq!(r.runs + r.runs_set_aside, 2, "{r:?}");
                if r.runs == 2 {
                    let [lo, hi] = r.ratio_ci_between.expect("a between-run interval");
                    assert!(lo <= r.ratio && r.ratio <= hi, "{r:?}");
                }
                assert!(r.escalation_rate.is_some_and(|e| (0.0..=1.0).contains(&e)));
                if metric == GPU_BVH_CLOSEST {
                    assert_eq!(r.rays, 256, "{r:?}");
                } else {
                    assert!(r.rays > 0 && r.rays <= 256, "{r:?}");
                }
            }
        }
        for metric in [GPU_BVH_CLOSEST, GPU_BVH_ANYHIT] {
            let copy = format!(
                "gpu_bvh_copy_{}-{scene}/4",
                metric.trim_start_matches("gpu_bvh_")
            );
            let e = results.estimates.iter().find(|e| e.benchmark == copy);
            assert!(e.is_some_and(|e| e.ns_per_element > 0.0), "{copy}");
        }
    }
    let table = std::fs::read_to_string(dir.path().join("bvh.txt")).unwrap();
    assert!(table.contains("Mrays/s"), "{table}");
    let run = |args: &[&str]| {
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_torus-cull"))
            .args(args)
            .output()
            .unwrap();
        let text = String::from_utf8_lossy(&out.stdout).into_owned();
        assert!(out.status.success(), "{args:?}: {text}");
        text
    };
    let file = path.to_str().unwrap();
    let text = run(&["compare", file, file]);
    assert!(text.contains("gpu_bvh_anyhit_ns [f32 gpu]"), "{text}");
    run(&["plot", file, "--out-dir", dir.path().to_str().unwrap()]);
    for plot in ["closest_ns-vs-none", "anyhit_ns-vs-copy"] {
        let svg = dir
            .path()
            .join(format!("bvh-ratio-facing_grid-gpu_bvh_{plot}.svg"));
        assert!(svg.is_file(), "{}", svg.display());
    }
}
