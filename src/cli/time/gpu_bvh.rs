//! `torus-cull time gpu-bvh`: the GPU BVH timed
//! ([`torus_cull_lab::paired::gpu_bvh`]): each GPU cull at the leaves over `none`,
//! closest hit (camera rays) and any hit (shadow rays spawned on the hits), with within-
//! and between-run intervals, rays per second, and the copy kernel over the same ray bytes.
//! Written as `ratio` records (metrics `gpu_bvh_closest_ns`, `gpu_bvh_anyhit_ns`, device
//! `gpu`, references `none` and `copy`) and `estimates` (ns per ray), which `compare` and
//! `intervals` read; the adapter in `meta.device`.
//!
//! Every flag is this mode's own ([`GpuBvhArgs`]), so that it moves under a `time`
//! subcommand as it is.

use crate::whole::Whole;
use std::error::Error;
use std::path::PathBuf;
use std::process::ExitCode;

/// `torus-cull time gpu-bvh`'s arguments.
#[derive(clap::Args)]
pub struct GpuBvhArgs {
    /// Workload whose `bvh` key gives the scenes, ν and tori: `quick` or `default` (built
    /// into the binary), or a workload file.
    #[arg(long, default_value = "quick")]
    workload: PathBuf,
    /// Scene layouts, comma-separated (default: the workload's scenes at each of its ν,
    /// then every other layout at ν = 4, as `time bvh`): ring_field, chain,
    /// facing_grid, mixed_nu, dense.
    #[arg(long, value_delimiter = ',')]
    scenes: Vec<String>,
    /// ν of the scenes' tori, comma-separated (default: the workload's `bvh` ν); with
    /// `--scenes`, every scene named is timed at each.
    #[arg(long, value_delimiter = ',')]
    nu: Vec<f64>,
    /// Tori per scene (default: the workload's `bvh` tori: 100 for quick, 1 000 for
    /// default).
    #[arg(long)]
    tori: Option<Whole>,
    /// GPU culls at the leaves, comma-separated (default: all nine); `none` is timed in
    /// any case.
    #[arg(long, value_delimiter = ',')]
    culls: Vec<String>,
    /// Camera rays per pass: the first N pixels of a ⌈√N⌉-wide image, row-major
    /// (default 1 000 000); one shadow ray per hit.
    #[arg(long)]
    batch: Option<Whole>,
    /// Seconds of timed rounds, shared by the runs (the scenes' setup, the rays' upload
    /// and the answers' check come on top).
    #[arg(long, default_value_t = 30.0)]
    seconds: f64,
    /// Independent runs (each with the scene and rays uploaded afresh), for the
    /// between-run intervals.
    #[arg(long, default_value_t = Whole(5))]
    runs: Whole,
    /// Results JSON (default: results/<short commit>[-dirty]-<workload>-gpu-bvh-time.json).
    /// Its directory must exist.
    #[arg(long)]
    out: Option<PathBuf>,
    /// Skip the SVG plots (by default the ratios are drawn against ν, next to the file).
    #[arg(long)]
    no_plots: bool,
}

/// Runs `torus-cull time gpu-bvh`.
#[cfg(not(feature = "gpu"))]
pub fn run(_args: &GpuBvhArgs) -> Result<ExitCode, Box<dyn Error>> {
    Err("time gpu-bvh needs a binary built with the feature gpu: \
         cargo run --release --features gpu -- time gpu-bvh"
        .into())
}

/// Runs `torus-cull time gpu-bvh`.
#[cfg(feature = "gpu")]
pub fn run(args: &GpuBvhArgs) -> Result<ExitCode, Box<dyn Error>> {
    measure::run(args)
}

#[cfg(feature = "gpu")]
mod measure {
    use super::GpuBvhArgs;
    use crate::console::outln;
    use std::error::Error;
    use std::path::{Path, PathBuf};
    use std::process::ExitCode;
    use std::sync::atomic::{AtomicBool, Ordering};
    use std::time::{Duration, Instant};
    use torus_cull::Named;
    use torus_cull::gpu::{GpuCull, GpuIntersector};
    use torus_cull_lab::number::Num;
    use torus_cull_lab::paired::bvh::units_of;
    use torus_cull_lab::paired::gpu_bvh::{
        COPY, GPU_BVH_METRICS, GpuBvhOutcome, GpuBvhTiming, Progress, lineup, time_gpu_bvh,
    };
    use torus_cull_lab::results::{self, BvhSizes, RatioRecord, Results, Sizes};
    use torus_cull_lab::scene::SceneKind;
    use torus_cull_lab::workload::spec::Workload;

    /// `--batch` unless given: camera rays per pass, a 1000 × 1000 image (a GPU needs about a
    /// million rays in flight; not 2²⁰, which ran in a slow state on the H100, docs/gpu.md).
    const DEFAULT_RAYS: usize = 1_000_000;

    /// The most camera rays per pass: their records, prepared and working copies, and the
    /// shadow rays' (144 bytes each) stay within a few GiB of device memory.
    const MAX_RAYS: usize = 1 << 24;

    /// The most tori per scene (the kernel takes up to 2²⁴; the host builds each scene).
    const MAX_TORI: usize = 1 << 20;

    /// Progress goes to stderr at least this often.
    const EVERY: Duration = Duration::from_secs(5);

    pub(super) fn run(args: &GpuBvhArgs) -> Result<ExitCode, Box<dyn Error>> {
        let workload = Workload::open(&args.workload)?;
        let spec = workload.bvh.clone().ok_or_else(|| {
            format!(
                "time gpu-bvh: workload {} has no `bvh` key (its scenes)",
                args.workload.display()
            )
        })?;
        for &nu in &args.nu {
            if !(nu.is_finite() && nu > 1.0) {
                return Err(
                    format!("--nu {} is invalid (allowed: nu > 1, finite)", Num(nu)).into(),
                );
            }
        }
        let nus = if args.nu.is_empty() {
            spec.nu.clone()
        } else {
            args.nu.clone()
        };
        let units = if args.scenes.is_empty() {
            units_of(&spec.scenes, &nus)
        } else {
            let scenes = parse_scenes(&args.scenes)?;
            scenes
                .iter()
                .flat_map(|&k| nus.iter().map(move |&nu| (k, nu)))
                .collect()
        };
        let tori = match args.tori {
            Some(t) => t.within("--tori", (1, MAX_TORI), "")?,
            None => spec.tori,
        };
        let rays = match args.batch {
            Some(b) => b.within("--batch", (16, MAX_RAYS), " with time gpu-bvh")?,
            None => DEFAULT_RAYS,
        };
        let seconds = args.seconds;
        if !(seconds.is_finite() && seconds > 0.0 && seconds <= 3600.0) {
            return Err(format!(
                "--seconds {} is invalid (allowed: 0 < seconds <= 3600)",
                Num(seconds)
            )
            .into());
        }
        let runs = args.runs.within("--runs", (1, 100), "")?;
        let culls = parse_culls(&args.culls)?;
        let path = out_path(args.out.clone(), &workload.name)?;
        torus_cull_lab::output::check_writable(&path)
            .map_err(|e| format!("--out {}: {e}", path.display()))?;
        if !args.no_plots {
            crate::plot::check_plot_paths(&path)?;
        }
        if torus_cull_lab::workload::spec::built_in(&args.workload).is_none() {
            torus_cull_lab::output::check_not_input(
                ("--out", &path),
                &[("--workload", &args.workload)],
            )?;
        }

        let gpu = GpuIntersector::new()?;
        let device = crate::time::gpu::announce_adapter(
            &gpu,
            "its submission's wall clock (with the copy that restores the rays before it)",
        )?;
        let timing = GpuBvhTiming {
            units,
            tori,
            seed: workload.seed,
            culls,
            rays,
            seconds,
            runs,
        };
        eprintln!(
            "time gpu-bvh: {} scene x nu, {tori} tori, {rays} camera rays a pass, {runs} runs, {} s of rounds",
            timing.units.len(),
            Num(seconds)
        );
        let outcome = with_progress(&gpu, &timing)?;
        report(&outcome)?;
        let mut results = Results::new(&workload, "time");
        results.ratio = outcome.ratio.clone();
        results.estimates = outcome.estimates.clone();
        let note = if outcome.timestamps {
            ""
        } else {
            "; timed by the submission's wall clock (no timestamps)"
        };
        results.meta.device = Some(format!("{device}{note}"));
        results.meta.threads = Some(1);
        let mut scenes: Vec<String> = Vec::new();
        let mut nu: Vec<f64> = Vec::new();
        for &(k, v) in &timing.units {
            if !scenes.contains(&k.name().to_string()) {
                scenes.push(k.name().to_string());
            }
            if !nu.contains(&v) {
                nu.push(v);
            }
        }
        results.meta.sizes = Some(Sizes {
            rejection_rays: None,
            timing_rays: Some(rays as u64),
            timed_nu: nu.clone(),
            warm_up_s: None,
            measurement_s: Some(seconds),
            samples: None,
            bvh: Some(BvhSizes {
                scenes,
                nu,
                tori: tori as u64,
                image: (rays as f64).sqrt().ceil() as u64,
                random_rays: 0,
            }),
            bench_args: Vec::new(),
        });
        results.save(&path)?;
        outln!("wrote {}", path.display())?;
        if !args.no_plots {
            crate::plot::write_plots(&Results::load(&path)?, &path)?;
        }
        Ok(ExitCode::SUCCESS)
    }

    /// The timing, with a line on stderr at least every [`EVERY`] saying where it is.
    fn with_progress(
        gpu: &GpuIntersector,
        timing: &GpuBvhTiming,
    ) -> Result<GpuBvhOutcome, Box<dyn Error>> {
        let progress = Progress::default();
        let stop = AtomicBool::new(false);
        let start = Instant::now();
        std::thread::scope(|scope| {
            scope.spawn(|| {
                let mut last = Instant::now();
                while !stop.load(Ordering::Relaxed) {
                    std::thread::sleep(Duration::from_millis(100));
                    if last.elapsed() >= EVERY {
                        last = Instant::now();
                        let step = progress.step.lock().map(|s| s.clone()).unwrap_or_default();
                        eprintln!(
                            "time gpu-bvh: {step}; {}/{} steps, {:.0} s",
                            progress.done.load(Ordering::Relaxed),
                            progress.all.load(Ordering::Relaxed),
                            start.elapsed().as_secs_f64()
                        );
                    }
                }
            });
            let outcome = time_gpu_bvh(gpu, timing, &progress);
            stop.store(true, Ordering::Relaxed);
            Ok(outcome?)
        })
    }

    /// The tables: per unit its rays and who answered them, then per metric each cull's ns
    /// per ray, rays per second, ratio over `none` (within-run and between-run 95 %
    /// intervals) and over the copy kernel.
    fn report(outcome: &GpuBvhOutcome) -> std::io::Result<()> {
        for u in &outcome.units {
            outln!(
                "{} nu={}: {} tori, {} nodes; {} camera rays ({} hit), {} shadow rays ({} blocked); upload {:.1} / {:.1} ns a ray",
                u.scene,
                u.nu,
                u.tori,
                u.nodes,
                u.camera_rays,
                u.camera_hits,
                u.shadow_rays,
                u.shadowed,
                u.upload_ns[0],
                u.upload_ns[1]
            )?;
            for (cull, camera, shadow) in &u.answered {
                if camera.device + camera.host + shadow.device + shadow.host > 0 {
                    outln!(
                        "  {:<15} not proved in f32: camera {} by the device's f64, {} by the host; shadow {} / {}",
                        cull.name(),
                        camera.device,
                        camera.host,
                        shadow.device,
                        shadow.host
                    )?;
                }
            }
        }
        for metric in GPU_BVH_METRICS {
            outln!("\n{metric}:")?;
            outln!(
                "{:<11} {:>5} {:<15} {:>9} {:>9} {:>26} {:>17} {:>9}",
                "scene",
                "nu",
                "cull",
                "ns/ray",
                "Mrays/s",
                "vs none [within]",
                "[between]",
                "vs copy"
            )?;
            let of = |r: &&RatioRecord| r.metric == metric;
            for copy in outcome
                .ratio
                .iter()
                .filter(of)
                .filter(|r| r.reference == COPY)
            {
                let none = outcome.ratio.iter().filter(of).find(|r| {
                    r.reference == GpuCull::NoCull.name()
                        && r.case == copy.case
                        && r.nu == copy.nu
                        && r.cull == copy.cull
                });
                let (within, between) = match none {
                    Some(r) => (
                        format!("{:.3} [{:.3},{:.3}]", r.ratio, r.ratio_ci[0], r.ratio_ci[1]),
                        r.ratio_ci_between
                            .map_or("-".into(), |b| format!("[{:.3},{:.3}]", b[0], b[1])),
                    ),
                    None => ("-".into(), "-".into()),
                };
                outln!(
                    "{:<11} {:>5} {:<15} {:>9.3} {:>9.1} {:>26} {:>17} {:>9.2}",
                    copy.case,
                    copy.nu,
                    copy.cull,
                    copy.ns_per_ray,
                    1e3 / copy.ns_per_ray,
                    within,
                    between,
                    copy.ratio
                )?;
            }
            for e in &outcome.estimates {
                let copy = format!("gpu_bvh_copy_{}-", metric.trim_start_matches("gpu_bvh_"));
                if let Some(unit) = e.benchmark.strip_prefix(&copy) {
                    outln!(
                        "{:<27} {COPY:<5} {:>9.3} {:>9.1}   (the rays' own bytes read and 32 written)",
                        unit,
                        e.ns_per_element,
                        1e3 / e.ns_per_element
                    )?;
                }
            }
        }
        Ok(())
    }

    /// `--scenes`: each a scene layout.
    fn parse_scenes(names: &[String]) -> Result<Vec<SceneKind>, String> {
        let mut out = Vec::new();
        for name in names {
            let kind = SceneKind::ALL
                .iter()
                .copied()
                .find(|k| k.name() == name.trim())
                .ok_or_else(|| {
                    let allowed: Vec<&str> = SceneKind::ALL.iter().map(|k| k.name()).collect();
                    format!(
                        "--scenes: '{}' is not a scene (allowed: {})",
                        name.trim(),
                        allowed.join(", ")
                    )
                })?;
            if !out.contains(&kind) {
                out.push(kind);
            }
        }
        Ok(out)
    }

    /// `--culls`: each a GPU cull (default all); `none` is added by the timing.
    fn parse_culls(names: &[String]) -> Result<Vec<GpuCull>, String> {
        if names.is_empty() {
            return Ok(GpuCull::ALL.to_vec());
        }
        let mut out = Vec::new();
        for name in names {
            let cull = GpuCull::ALL
                .iter()
                .copied()
                .find(|c| c.name() == name.trim())
                .ok_or_else(|| {
                    let allowed: Vec<&str> = GpuCull::ALL.iter().map(|c| c.name()).collect();
                    format!(
                        "--culls: '{}' is not a GPU cull (allowed: {})",
                        name.trim(),
                        allowed.join(", ")
                    )
                })?;
            out.push(cull);
        }
        Ok(lineup(&out))
    }

    /// `--out`, or the default file under `results/` named by commit and workload (its
    /// folder made): `<commit>[-<workload>]-gpu-bvh-time.json`.
    fn out_path(out: Option<PathBuf>, workload: &str) -> Result<PathBuf, String> {
        if let Some(path) = out {
            return Ok(path);
        }
        let suffix = if workload == "default" {
            "-gpu-bvh-time".to_string()
        } else {
            format!("-{workload}-gpu-bvh-time")
        };
        let path = results::default_path(Path::new("results"), &suffix);
        torus_cull_lab::output::create_default_dir(&path)
            .map_err(|e| format!("--out {}: {e}", path.display()))?;
        Ok(path)
    }
}
