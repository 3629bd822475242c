//! The WGSL kernel (`torus_cull::gpu`) against the f64 oracle, on whatever adapter wgpu
//! finds (CI: Mesa's software Vulkan, lavapipe, from the Debian package
//! `mesa-vulkan-drivers`). Without an adapter every test here prints one loud SKIPPED
//! line and passes on a developer's machine, and fails under `CI=true` (CI must run the
//! kernel); the rest of `cargo test` does not depend on a GPU.
//!
//! Per family, for both GPU culls: no definite hit answered miss, no definite miss
//! answered hit, every proved hit's t within 2·10⁻⁴·(R + r) + 4 ulp(t) (along the
//! direction) of the oracle's first root; after `intersect_finished` (escalated rays
//! answered in f64) the hits and misses equal the f64 path's. Families: the five
//! workload generators at ν from 1.01 to 1000, the same lines seen from 10 to 10⁵·(R + r)
//! away, and lines hugging the hole's edge and tangent to the four special circles at
//! ±10⁻⁶·r, at random poses and scales. The escalation rate of each is printed.

#![cfg(feature = "gpu")]

use crate::common::adversarial::{
    DEVICE_T_TOLERANCE_REL, WIDE_NUS, edge_sets, escalating_families,
};
use crate::common::{family, pairs, pushed_back};
use glam::Vec3;
use rand::SeedableRng;
use rand_pcg::Pcg64;
use std::io::Write;
use std::sync::OnceLock;
use torus_cull::Named;
use torus_cull::gpu::{GpuCull, GpuError, GpuIntersector};
use torus_cull::{F32Verdict, Ray, Torus, intersect, intersect_f32_certified};
use torus_cull_lab::oracle::{OracleClass, Query, reference_roots};
use torus_cull_lab::workload::Case;
use torus_cull_lab::workload::adversarial::SpecialCircle;

/// The adapter, opened once for every test; `None` (after one loud line) without one.
pub(crate) fn gpu() -> Option<&'static GpuIntersector> {
    static GPU: OnceLock<Option<GpuIntersector>> = OnceLock::new();
    GPU.get_or_init(|| match GpuIntersector::new() {
        Ok(gpu) => {
            let kind = if gpu.is_software() {
                "software adapter: no GPU timing claimed"
            } else {
                "hardware adapter"
            };
            // Written to stderr directly: libtest captures println! of a passing test.
            let _ = writeln!(
                std::io::stderr(),
                "GPU adapter: {} ({:?}, {:?}; {kind})",
                gpu.adapter_name(),
                gpu.device_type(),
                gpu.backend()
            );
            Some(gpu)
        }
        Err(GpuError::NoAdapter(why)) => {
            // Panics under CI=true: CI must run the kernel.
            crate::common::no_adapter(&why.to_string());
            None
        }
        Err(e) => panic!("GPU adapter found but unusable: {e}"),
    })
    .as_ref()
}

/// What the CPU says of one ray: the oracle's query and label, the f64 path's hit, and
/// the CPU's certified f32 verdict (both are proofs, so they never disagree with the
/// kernel's on a proved answer).
#[derive(Clone, Copy)]
struct CpuAnswer {
    query: Query,
    label: torus_cull_lab::oracle::OracleLabel,
    f64_hit: Option<torus_cull::Hit>,
    cpu: F32Verdict,
}

fn cpu_answers(torus: &Torus, rays: &[Ray]) -> Vec<CpuAnswer> {
    rays.iter()
        .map(|ray| {
            let query = Query::ray(torus, ray);
            CpuAnswer {
                query,
                label: query.classify(),
                f64_hit: intersect(torus, ray),
                cpu: intersect_f32_certified(torus, ray),
            }
        })
        .collect()
}

/// What one family found, for one cull.
#[derive(Default)]
struct Tally {
    rays: usize,
    band: usize,
    escalated: usize,
    cpu_escalated: usize,
    hits: usize,
    misses: usize,
    worst: f64,
    why: std::collections::BTreeMap<&'static str, usize>,
    failures: Vec<String>,
}

impl Tally {
    fn fail(&mut self, text: String) {
        if self.failures.len() < 10 {
            self.failures.push(text);
        }
    }

    /// Runs `rays` on `torus` through the kernel with `cull` and checks every answer
    /// against the CPU's (computed once for every cull).
    fn check(
        &mut self,
        gpu: &GpuIntersector,
        cull: GpuCull,
        torus: &Torus,
        rays: &[Ray],
        cpu_answers: &[CpuAnswer],
    ) {
        let explained = gpu.explain(torus, cull, rays).expect("dispatch");
        let mut verdicts = Vec::with_capacity(rays.len());
        for (verdict, why) in explained {
            if let Some(why) = why {
                *self.why.entry(why.name()).or_default() += 1;
            }
            verdicts.push(verdict);
        }
        let finished = gpu.intersect_finished(torus, cull, rays).expect("dispatch");
        assert_eq!(verdicts.len(), rays.len());
        for (((ray, verdict), done), answer) in
            rays.iter().zip(verdicts).zip(finished).zip(cpu_answers)
        {
            self.rays += 1;
            let CpuAnswer {
                query,
                label,
                f64_hit,
                cpu,
            } = *answer;
            if cpu == F32Verdict::Escalate {
                self.cpu_escalated += 1;
            }
            match (verdict, cpu) {
                (F32Verdict::Hit { .. }, F32Verdict::Miss)
                | (F32Verdict::Miss, F32Verdict::Hit { .. }) => self.fail(format!(
                    "{cull}: GPU {verdict:?}, CPU certified {cpu:?}: {ray:?} on {torus:?}"
                )),
                _ => {}
            }
            if label.class == OracleClass::Ambiguous {
                self.band += 1;
                if verdict == F32Verdict::Escalate {
                    self.escalated += 1;
                }
                continue;
            }
            let definite_hit = label.class == OracleClass::Hit;
            if done.hit.is_some() != f64_hit.is_some() {
                self.fail(format!(
                    "{cull}: finished {:?} (escalated {}), f64 {f64_hit:?}, oracle {label:?}: \
                     {ray:?} on {torus:?}",
                    done.hit, done.escalated
                ));
            }
            match verdict {
                F32Verdict::Escalate => self.escalated += 1,
                F32Verdict::Miss => {
                    self.misses += 1;
                    if definite_hit {
                        self.fail(format!(
                            "{cull}: miss for a definite hit {label:?}: {ray:?} on {torus:?}"
                        ));
                    }
                }
                F32Verdict::Hit { t, normal } => {
                    self.hits += 1;
                    if !definite_hit {
                        self.fail(format!(
                            "{cull}: hit t = {t} for a definite miss {label:?}: {ray:?} on {torus:?}"
                        ));
                        continue;
                    }
                    let reference = reference_roots(&query)[0];
                    let len = f64::from(ray.dir().length());
                    let ulp = f64::from(t.abs().max(f32::MIN_POSITIVE)) * f64::from(f32::EPSILON);
                    let err = (f64::from(t) - reference).abs() * len;
                    let allowed = 2e-4 * f64::from(torus.outer_radius()) + 4.0 * ulp * len;
                    self.worst = self.worst.max(err / f64::from(torus.outer_radius()));
                    if err > allowed || err.is_nan() {
                        self.fail(format!(
                            "{cull}: t = {t} vs oracle {reference} (off by {:e}·(R + r)): \
                             {ray:?} on {torus:?}",
                            err / f64::from(torus.outer_radius())
                        ));
                    }
                    if (normal.length() - 1.0).abs() >= 1e-3 || !normal.is_finite() {
                        self.fail(format!("{cull}: normal {normal} not unit: {ray:?}"));
                    }
                }
                _ => self.fail(format!("{cull}: unknown verdict {verdict:?}")),
            }
        }
    }

    fn report(&self, name: &str, cull: GpuCull) {
        println!(
            "{name:<24} {cull:<8} {:>7} rays: {:>6} proved hits, {:>6} proved misses, \
             escalated {:>5.1} % (CPU f32 path {:>5.1} %; {} in the oracle's band), worst t \
             error {:.1e}·(R + r)",
            self.rays,
            self.hits,
            self.misses,
            100.0 * self.escalated as f64 / self.rays.max(1) as f64,
            100.0 * self.cpu_escalated as f64 / self.rays.max(1) as f64,
            self.band,
            self.worst,
        );
        let why: Vec<String> = self.why.iter().map(|(k, n)| format!("{k} {n}")).collect();
        println!("    escalated because: {}", why.join(", "));
        assert!(
            self.failures.is_empty(),
            "{name} ({cull}):\n{}",
            self.failures.join("\n")
        );
    }
}

/// ν of the generator families (the hole needs ν ≥ 1.01).

#[test]
fn generators_near_and_far() {
    let Some(gpu) = gpu() else { return };
    // Near, far (10³·(R + r)) and very far (10⁵): the origin's f32 rounding at 10 is
    // the near case's, and CI's 15 minutes pay for three distances, not four.
    for back in [0.0f32, 1e3, 1e5] {
        // Per cull, per case; the CPU's answers once per batch for every cull.
        let mut tallies: Vec<Vec<Tally>> = GpuCull::ALL
            .iter()
            .map(|_| Case::ALL.iter().map(|_| Tally::default()).collect())
            .collect();
        for (c, &case) in Case::ALL.iter().enumerate() {
            for nu in WIDE_NUS {
                if nu < case.min_nu() {
                    continue;
                }
                let batches = family(case, nu, 2000, 0x6E0 ^ nu.to_bits());
                for batch in &batches {
                    let torus = batch.torus;
                    let rays: Vec<Ray> = pairs(std::slice::from_ref(batch))
                        .map(|(_, ray)| {
                            if back == 0.0 {
                                *ray
                            } else {
                                pushed_back(ray, back * torus.outer_radius())
                            }
                        })
                        .collect();
                    let answers = cpu_answers(&torus, &rays);
                    for (k, &cull) in GpuCull::ALL.iter().enumerate() {
                        tallies[k][c].check(gpu, cull, &torus, &rays, &answers);
                    }
                }
            }
        }
        for (cull, per_case) in GpuCull::ALL.into_iter().zip(&tallies) {
            let mut all = Tally::default();
            for (&case, tally) in Case::ALL.iter().zip(per_case) {
                tally.report(&format!("{case} back {back:e}·(R+r)"), cull);
                all.rays += tally.rays;
                all.escalated += tally.escalated;
                all.hits += tally.hits;
                if back == 0.0 && matches!(case, Case::OuterBand | Case::Uniform | Case::Camera) {
                    // Near origins: the kernel must prove most of the ordinary rays, or it
                    // saves nothing (hole and grazing rays are near misses and near
                    // tangents by design, and escalate far more: see the printed rates).
                    let rate = tally.escalated as f64 / tally.rays.max(1) as f64;
                    assert!(
                        rate < 0.35,
                        "{cull}: {case} escalated {:.1} %",
                        100.0 * rate
                    );
                }
            }
            println!(
                "generators back {back:e}·(R+r), {cull}: {} rays, {} proved hits, escalated {:.1} %",
                all.rays,
                all.hits,
                100.0 * all.escalated as f64 / all.rays.max(1) as f64
            );
        }
    }
}

#[test]
fn adversarial_lines() {
    let Some(gpu) = gpu() else { return };
    let mut rng = Pcg64::seed_from_u64(0x0006_B0AD);
    // Per cull: the hole's edge, then each special circle; the same lines for every cull,
    // the CPU's answers computed once.
    let mut tallies: Vec<Vec<Tally>> = GpuCull::ALL
        .iter()
        .map(|_| {
            (0..=SpecialCircle::ALL.len())
                .map(|_| Tally::default())
                .collect()
        })
        .collect();
    let mut check = |slot: usize, torus: &Torus, rays: &[Ray]| {
        let answers = cpu_answers(torus, rays);
        for (k, &cull) in GpuCull::ALL.iter().enumerate() {
            tallies[k][slot].check(gpu, cull, torus, rays, &answers);
        }
    };
    let edges = edge_sets(&mut rng, &[1.01, 1.1, 2.0, 8.0, 100.0, 1000.0], 300, 150);
    for (torus, rays) in &edges.hole_edge {
        check(0, torus, rays);
    }
    for (i, per_torus) in edges.tangent.iter().enumerate() {
        for (torus, rays) in per_torus {
            check(1 + i, torus, rays);
        }
    }
    for (cull, per_family) in GpuCull::ALL.into_iter().zip(&tallies) {
        per_family[0].report("hole_edge_line", cull);
        for (circle, tally) in SpecialCircle::ALL.into_iter().zip(&per_family[1..]) {
            tally.report(&format!("tangent ±1e-6 r {}", circle.name()), cull);
        }
    }
}

#[test]
fn an_empty_batch_and_a_clear_hit() {
    let Some(gpu) = gpu() else { return };
    let torus = Torus::new(glam::Vec3::ZERO, glam::Vec3::Y, 4.0, 1.0).unwrap();
    assert!(
        gpu.intersect(&torus, GpuCull::NoCull, &[])
            .unwrap()
            .is_empty()
    );
    let ray = Ray::new(glam::Vec3::new(4.0, 10.0, 0.0), glam::Vec3::NEG_Y).unwrap();
    let verdict = gpu.intersect(&torus, GpuCull::Cychosz, &[ray]).unwrap()[0];
    let F32Verdict::Hit { t, normal } = verdict else {
        panic!("straight down onto the tube's top: {verdict:?}");
    };
    assert!((t - 9.0).abs() < 1e-3, "t = {t}");
    assert!((normal - glam::Vec3::Y).length() < 1e-3, "normal {normal}");
    let hole = Ray::new(glam::Vec3::new(0.5, 10.0, 0.0), glam::Vec3::NEG_Y).unwrap();
    assert_eq!(
        gpu.intersect(&torus, GpuCull::Cychosz, &[hole]).unwrap()[0],
        F32Verdict::Miss
    );
}

fn torus_cull(args: &[&str]) -> std::process::Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_torus-cull"))
        .args(args)
        .output()
        .expect("run torus-cull")
}

/// `eval --exact gpu` answers every row as `--exact f32` does (both certified, escalated
/// rays finished in f64): the same hits and misses, t within the two bounds.
#[test]
fn eval_exact_gpu_agrees_with_the_cpu_path() {
    let Some(_) = gpu() else { return };
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("rays.csv");
    let mut csv = String::from("ox,oy,oz,dx,dy,dz\n");
    for batch in family(Case::Uniform, 4.0, 300, 0x0E7A)
        .iter()
        .chain(&family(Case::Camera, 4.0, 300, 0x0E7B))
    {
        // eval's torus is the canonical one: the rays in its frame, then pushed back.
        let m = batch.torus.to_local_rotation();
        for ray in &batch.rays {
            let o = batch.torus.point_to_local(ray.origin());
            let d = m * ray.dir();
            csv.push_str(&format!(
                "{},{},{},{},{},{}\n",
                o.x, o.y, o.z, d.x, d.y, d.z
            ));
        }
    }
    std::fs::write(&input, csv).unwrap();
    let rows = |exact: &str| {
        let out_path = dir.path().join(format!("{exact}.csv"));
        let out = torus_cull(&[
            "eval",
            "--major",
            "1",
            "--minor",
            "0.25",
            "--rays",
            input.to_str().unwrap(),
            "--exact",
            exact,
            "--out",
            out_path.to_str().unwrap(),
        ]);
        assert!(
            out.status.success(),
            "eval --exact {exact}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let text = std::fs::read_to_string(&out_path).unwrap();
        assert!(
            text.starts_with("index,oracle,margin,t_hit,escalated,"),
            "{exact}"
        );
        text.lines()
            .skip(1)
            .map(|l| {
                let f: Vec<&str> = l.split(',').collect();
                (f[3].parse::<f64>().ok(), f[4] == "1", f[5].to_string())
            })
            .collect::<Vec<_>>()
    };
    let (gpu_rows, cpu_rows) = (rows("gpu"), rows("f32"));
    assert_eq!(gpu_rows.len(), 600);
    assert_eq!(gpu_rows.len(), cpu_rows.len());
    let escalated = gpu_rows.iter().filter(|r| r.1).count();
    // `finished`: empty where f32 proved the answer; else who finished it (the device
    // where the adapter has f64: none of these rays starts on the surface).
    let finisher = if gpu().is_some_and(|g| g.finishes_on_device()) {
        "device"
    } else {
        "host"
    };
    for (i, (_, escalated, finished)) in gpu_rows.iter().enumerate() {
        let want = if *escalated { finisher } else { "" };
        assert_eq!(finished, want, "row {i}");
    }
    for (i, ((g, _, _), (c, _, _))) in gpu_rows.iter().zip(&cpu_rows).enumerate() {
        assert_eq!(g.is_some(), c.is_some(), "row {i}: gpu {g:?}, f32 {c:?}");
        if let (Some(g), Some(c)) = (g, c) {
            assert!(
                (g - c).abs() <= 4e-4 * 1.25 + 1e-5 * c.abs(),
                "row {i}: {g} vs {c}"
            );
        }
    }
    println!("eval --exact gpu: {escalated} of 600 rows escalated, finished by the {finisher}");
}

/// `time gpu` writes Mrays/s per cull as estimates, with the adapter in meta.device (and
/// says so when the adapter is the CPU), at the `--workgroup` asked for, which the device
/// names; its `--workload`, `--nu`, `--batch` and `--out` read back from the file, its
/// plots drawn.
#[test]
fn time_device_gpu_names_the_adapter() {
    let Some(gpu) = gpu() else { return };
    let dir = tempfile::tempdir().unwrap();
    let out_path = dir.path().join("time.json");
    let out = torus_cull(&[
        "time",
        "gpu",
        "--workgroup",
        "128",
        "--workload",
        concat!(env!("CARGO_MANIFEST_DIR"), "/workloads/quick.json"),
        "--nu",
        "2",
        "--seconds",
        "0.5",
        "--batch",
        "4096",
        "--out",
        out_path.to_str().unwrap(),
    ]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{stdout}{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(stdout.contains("Mrays/s"), "{stdout}");
    assert!(stdout.contains(gpu.adapter_name()), "{stdout}");
    if gpu.is_software() {
        // The backend actually used (Vulkan with lavapipe, Gl with wgpu's GL fallback).
        let through = format!("this CPU through {:?}, not a GPU", gpu.backend());
        assert!(stdout.contains(&through), "{stdout}");
    }
    let results = torus_cull_lab::results::Results::load(&out_path).unwrap();
    let device = results.meta.device.expect("meta.device");
    assert!(device.contains(gpu.adapter_name()), "{device}");
    assert!(device.contains("workgroup 128"), "{device}");
    assert_eq!(results.meta.workload, "quick");
    assert_eq!(
        device.contains("no GPU timing claimed"),
        gpu.is_software(),
        "{device}"
    );
    // Five cases at one ν: per case the upload, the read-back, the copy kernel and
    // every cull, each timed apart; every cull paired against none and cychosz.
    let culls = torus_cull::gpu::GpuCull::ALL.len();
    assert_eq!(results.estimates.len(), 5 * (3 + culls));
    for prefix in ["gpu_upload_ns-", "gpu_readback_ns-", "gpu_copy_ns-"] {
        let n = results
            .estimates
            .iter()
            .filter(|e| e.benchmark.starts_with(prefix))
            .count();
        assert_eq!(n, 5, "{prefix}");
    }
    assert!(results.estimates.iter().all(|e| e.ns_per_element > 0.0
        && e.ns_per_element_ci[0] <= e.ns_per_element
        && e.ns_per_element <= e.ns_per_element_ci[1]));
    // Each cull against none and cychosz, but not against itself.
    assert_eq!(results.ratio.len(), 5 * (2 * culls - 2));
    for r in &results.ratio {
        assert_eq!(
            (r.device.as_str(), r.metric.as_str()),
            ("gpu", "gpu_kernel_ns")
        );
        assert!(
            r.ratio_ci[0] <= r.ratio && r.ratio <= r.ratio_ci[1],
            "{r:?}"
        );
        assert!(r.ratio > 0.0 && r.rays == 4096, "{r:?}");
        assert_ne!(r.cull, r.reference);
    }
    assert!(
        stdout.contains("vs none") && stdout.contains("copy"),
        "{stdout}"
    );
    // Issue 29: its plots are written next to it, each case's ratios against ν.
    assert!(
        dir.path()
            .join("time-ratio-hole-gpu_kernel_ns-vs-none.svg")
            .is_file(),
        "{stdout}"
    );
}

/// `gpu-info` describes the adapter wgpu picks, one `key: value` a line, as
/// benches/gpu_device.sh reads it.
#[test]
fn gpu_info_describes_the_adapter() {
    let Some(gpu) = gpu() else { return };
    let out = torus_cull(&["gpu-info"]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{stdout}{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let field = |key: &str| {
        stdout
            .lines()
            .find_map(|l| l.strip_prefix(&format!("{key}: ")))
            .unwrap_or_else(|| panic!("no {key}: in {stdout}"))
            .to_string()
    };
    let yes = |b: bool| if b { "yes" } else { "no" };
    assert_eq!(field("adapter"), gpu.adapter_name());
    assert_eq!(field("device_type"), format!("{:?}", gpu.device_type()));
    assert_eq!(field("backend"), format!("{:?}", gpu.backend()));
    assert_eq!(field("software"), yes(gpu.is_software()));
    assert_eq!(field("shader_f64"), yes(gpu.has_shader_f64()));
    assert_eq!(field("timestamps"), yes(gpu.has_timestamps()));
    let finish = field("f64_finish_pass");
    assert_eq!(finish == "yes", gpu.finishes_on_device(), "{finish}");
    assert!(finish == "yes" || finish.starts_with("no ("), "{finish}");
    field("driver");
}

/// `time gpu --finish --cases --culls --no-plots`: the f64 pass timed after the kernel, per case ×
/// ν × cull, only on the cases asked for, with who answered the escalated rays.
#[test]
fn time_device_gpu_times_the_finish_pass() {
    let Some(gpu) = gpu() else { return };
    let dir = tempfile::tempdir().unwrap();
    let out_path = dir.path().join("finish.json");
    let args = [
        "time",
        "gpu",
        "--finish",
        "--workload",
        concat!(env!("CARGO_MANIFEST_DIR"), "/workloads/quick.json"),
        "--cases",
        "grazing,hole",
        "--culls",
        "none",
        "--nu",
        "1.1",
        "--seconds",
        "0.2",
        "--batch",
        "2048",
        "--no-plots",
        "--out",
        out_path.to_str().unwrap(),
    ];
    let out = torus_cull(&args);
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    if !gpu.finishes_on_device() {
        assert_eq!(out.status.code(), Some(2), "{stdout}{stderr}");
        assert!(stderr.contains("--finish"), "{stderr}");
        return;
    }
    assert!(out.status.success(), "{stdout}{stderr}");
    let results = torus_cull_lab::results::Results::load(&out_path).unwrap();
    let names: Vec<&str> = results
        .estimates
        .iter()
        .map(|e| e.benchmark.as_str())
        .collect();
    // The references none and cychosz, on the two cases asked for (in the workload's
    // order), and nothing else.
    for case in ["hole", "grazing"] {
        for cull in ["none", "cychosz"] {
            let name = format!("gpu_finish_ns-{case}/{cull}/1.1");
            assert!(names.contains(&name.as_str()), "{name} in {names:?}");
        }
    }
    assert!(!names.iter().any(|n| n.contains("uniform")), "{names:?}");
    // Grazing rays escalate: their finish pass has a time per escalated ray.
    assert!(
        names.contains(&"gpu_finish_per_escalated_ns-grazing/none/1.1"),
        "{names:?}"
    );
    assert!(stdout.contains("f64 finish pass:"), "{stdout}");
    assert!(stdout.contains("finished on the device"), "{stdout}");
    assert!(results.estimates.iter().all(|e| e.ns_per_element > 0.0));
    // --no-plots: no SVG beside the file.
    let svgs = std::fs::read_dir(dir.path())
        .unwrap()
        .filter(|e| {
            e.as_ref()
                .is_ok_and(|e| e.file_name().to_string_lossy().ends_with(".svg"))
        })
        .count();
    assert_eq!(svgs, 0);
}

/// Rays from surface points (`Torus::spawn`): the kernel proves them from the cubic left
/// once the origin's root is divided out (formed on the host in f64), or from the literal
/// ray past that root, within 2·10⁻⁴·(R + r) of the f64 path's answer and on its face, rays
/// into the tube included (their exit, from inside); what it escalates is finished on the
/// device or the host. Never a hit on the origin.
#[test]
fn secondary_rays_from_hits_are_proved_past_their_origin_or_finished_on_the_host() {
    let Some(gpu) = gpu() else { return };
    let torus = Torus::canonical(4.0, 1.0).unwrap();
    let mut rays = Vec::new();
    let mut into = Vec::new();
    for i in 0..64 {
        let x = -4.9 + 0.15 * i as f32;
        let primary = Ray::new(Vec3::new(x, 10.0, 0.3), Vec3::new(0.05, -1.0, 0.02)).unwrap();
        if let Some(hit) = intersect(&torus, &primary) {
            for dir in [hit.normal, -hit.normal, Vec3::X, Vec3::NEG_X, Vec3::Z] {
                rays.push(torus.spawn(&primary, hit.t, dir).unwrap());
                into.push(dir.dot(hit.normal) < 0.0);
            }
        }
    }
    assert!(rays.len() > 100);
    let answers = gpu
        .intersect_finished_where(&torus, GpuCull::NoCull, &rays)
        .expect("dispatch");
    // An escalated ray is finished on the device where it has f64, else on the host.
    let counts = torus_cull::gpu::FinishCounts::of(answers.iter().map(|(_, f)| f));
    println!(
        "secondary rays from hits: {} rays, {} proved, {} finished on the host, {} on the device",
        rays.len(),
        counts.proved,
        counts.host,
        counts.device
    );
    if gpu.finishes_on_device() {
        assert_eq!(counts.host, 0, "{counts:?}");
    } else {
        assert_eq!(counts.device, 0, "{counts:?}");
    }
    let on_device: Vec<bool> = answers
        .iter()
        .map(|(_, f)| *f == torus_cull::gpu::Finished::Device)
        .collect();
    let finished: Vec<_> = answers.into_iter().map(|(hit, _)| hit).collect();
    assert_eq!(
        counts.host + counts.device,
        finished.iter().filter(|a| a.escalated).count()
    );
    let mut proved = 0;
    for (((ray, answer), &into), &device) in rays.iter().zip(&finished).zip(&into).zip(&on_device) {
        let exact = intersect(&torus, ray);
        if answer.escalated && device {
            // The device's f64 pass: the CPU's answer to rounding.
            assert_eq!(answer.hit.is_some(), exact.is_some(), "{ray:?}");
            if let (Some(h), Some(e)) = (answer.hit, exact) {
                assert!(
                    (h.t - e.t).abs() <= 1.2e-7 * e.t.abs().max(5.0),
                    "{ray:?}: {h:?} vs {e:?}"
                );
            }
        } else if answer.escalated {
            assert_eq!(answer.hit, exact, "{ray:?}");
        } else {
            proved += 1;
            match (answer.hit, exact) {
                (None, None) => {}
                (Some(h), Some(e)) => {
                    assert!((h.t - e.t).abs() <= 2e-4 * 5.0, "{ray:?}");
                    assert_eq!(h.front_face, e.front_face, "{ray:?}");
                    assert!(!into || !h.front_face, "an exit from inside: {ray:?}");
                }
                (h, e) => panic!("{ray:?}: kernel {h:?}, f64 {e:?}"),
            }
        }
        if let Some(hit) = answer.hit {
            assert!(hit.t > 1e-3, "a hit on its own origin: {ray:?} {hit:?}");
        }
    }
    // Along ±normal and the axes, most rays are proved, those into the tube included.
    let inward = into.iter().filter(|i| **i).count();
    assert!(inward > 50, "{inward} rays into the tube");
    assert!(
        proved * 10 >= rays.len() * 9,
        "{proved} of {} proved",
        rays.len()
    );
}

/// `eval --exact gpu` takes the optional columns t_min, t_max, on_surface as the CPU
/// modes do (tests/cli/eval_cli.rs): the same labels and answers, every on-surface row
/// escalated to the host, and a bad value named by row and column before the adapter runs.
#[test]
fn eval_exact_gpu_takes_range_and_on_surface_columns() {
    let Some(_) = gpu() else { return };
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("rays.csv");
    // The CPU modes' rows up to the two from inside the tube.
    let rows = &crate::common::RANGE_ROWS[..7];
    let csv = std::iter::once("ox,oy,oz,dx,dy,dz,t_min,t_max,on_surface")
        .chain(rows.iter().map(|r| r.0))
        .collect::<Vec<_>>()
        .join("\n");
    std::fs::write(&input, &csv).unwrap();
    let args = [
        "eval",
        "--major",
        "4",
        "--minor",
        "1",
        "--rays",
        input.to_str().unwrap(),
        "--exact",
        "gpu",
    ];
    let out = torus_cull(&args);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).unwrap();
    for ((row, class, t), line) in rows.iter().zip(text.lines().skip(1)) {
        let f: Vec<&str> = line.split(',').collect();
        assert_eq!(f[1], *class, "{row}");
        assert_eq!(f[3].parse::<f64>().ok().map(|g| g.round()), *t, "{row}");
    }
    std::fs::write(&input, format!("{csv}\n4,10,0,0,-1,0,2,1,0\n")).unwrap();
    let out = torus_cull(&args);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success());
    assert!(
        err.contains("rays.csv:9:") && err.contains("columns t_min, t_max"),
        "{err}"
    );
}

#[path = "culls.rs"]
mod culls;
#[path = "finish.rs"]
mod finish;
#[path = "surface.rs"]
mod surface;
