//! Paired timing of the GPU BVH ([`torus_cull::gpu::GpuScene`], feature `gpu`): each GPU
//! cull at the leaves against `none` at the leaves, per ray traced through a whole scene
//! on the device, closest hit and any hit, with within- and between-run intervals, and
//! the copy kernel over the same ray bytes as the floor.
//!
//! Per scene × ν (the CPU BVH timing's scenes, [`super::bvh::units_of`]):
//!
//! - **closest-hit** ([`GPU_BVH_CLOSEST`]): `rays` camera rays (the first `rays` pixels,
//!   row-major, of a ⌈√rays⌉-wide image: a renderer's coherent primary rays), world rays
//!   through [`SceneRays::run`];
//! - **any-hit** ([`GPU_BVH_ANYHIT`]): one shadow ray per camera hit to the scene's light
//!   ([`crate::scene::rays::shadow_rays`]), spawned on the hit torus and traced as
//!   [`torus_cull::gpu::GpuScene::occluded_from`] does, stopping at the first proved hit;
//! - **copy** ([`COPY`]): the copy kernel over each kind of ray's records (32 bytes a
//!   camera ray read, 144 a shadow ray, 32 written): what the rays' own bytes cost.
//!
//! The rays stay resident ([`SceneRays`]); every contender runs once per round in an
//! order shuffled anew each round (seeded Pcg64), `repeats` passes in one submission
//! (about [`SUBMISSION`] of work), timed by the device's timestamps where the adapter has
//! them, else by the submission's wall clock. Each round gives `t(cull) / t(none)` under
//! the same metric, and `t(cull) / t(copy)`; a record's ratio is the median over the
//! rounds with a bootstrap 95 % interval ([`ratio_estimate`]). The scene × ν units are
//! visited in turn for [`VISIT`] each until the run's share of the time is spent, so that
//! a slow spell falls on all of them alike.
//!
//! **Runs.** `runs` runs, each with the scene uploaded afresh ([`GpuScene::new`]) and its
//! rays prepared and uploaded afresh (fresh buffers); [`combine_runs`] gives every record
//! its between-run interval, as `time bvh` does. The rays themselves are drawn once.
//!
//! **Answers checked.** In the first run, before any timing, every cull's closest and
//! any-hit answers on the resident rays (the host finishing what the device left) are
//! compared with `none`'s: the same hit or miss at the same t, the same occlusion. A cull
//! only ever skips a leaf that holds no hit, so any difference is a bug: the timing stops
//! with [`GpuBvhError::Mismatch`] naming the ray, and nothing is written.

use super::runs::{RunsDiffer, combine_runs};
use super::stats::{median, ratio_estimate};
use crate::results::{EstimateRecord, F32_PRECISION, RatioRecord};
use crate::scene::rays::{light, shadow_rays};
use crate::scene::{Scene, SceneKind};
use rand::SeedableRng;
use rand::seq::SliceRandom;
use rand_pcg::Pcg64;
use std::fmt;
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::{Duration, Instant};
use torus_cull::gpu::{
    FinishCounts, GpuCull, GpuError, GpuIntersector, GpuScene, SceneRays, SpawnedRay,
};
use torus_cull::{Named, Ray};

/// The closest-hit traversal's metric (camera rays).
pub const GPU_BVH_CLOSEST: &str = "gpu_bvh_closest_ns";
/// The any-hit traversal's metric (shadow rays spawned on the camera hits).
pub const GPU_BVH_ANYHIT: &str = "gpu_bvh_anyhit_ns";
/// The metrics, in table order.
pub const GPU_BVH_METRICS: [&str; 2] = [GPU_BVH_CLOSEST, GPU_BVH_ANYHIT];
/// The reference of the ratios over the copy kernel (and its contender's name).
pub const COPY: &str = "copy";

/// How long one visit to a scene × ν lasts before the next one's turn.
pub const VISIT: Duration = Duration::from_millis(100);

/// Each timed submission lasts about this long (repeats of the whole batch), so that the
/// wall clock's latency is small beside it where there are no timestamps.
pub const SUBMISSION: Duration = Duration::from_millis(4);

/// Rounds per unit and run at least, whatever the time share.
pub const MIN_ROUNDS: usize = 5;

/// What to time.
#[derive(Debug, Clone)]
pub struct GpuBvhTiming {
    /// Scene layouts and the ν of their tori, in turn.
    pub units: Vec<(SceneKind, f64)>,
    /// Tori per scene.
    pub tori: usize,
    /// Scene seed.
    pub seed: u64,
    /// Culls at the leaves (`none` is timed in any case, first).
    pub culls: Vec<GpuCull>,
    /// Camera rays per pass (and at most as many shadow rays).
    pub rays: usize,
    /// Seconds of timed rounds in all, shared by the runs (setup comes on top).
    pub seconds: f64,
    /// Independent runs.
    pub runs: usize,
}

/// Why a GPU BVH timing failed.
#[derive(Debug)]
pub enum GpuBvhError {
    /// A scene could not be built.
    Scene(String),
    /// The device failed (naming the scene).
    Gpu(String, GpuError),
    /// A cull gave another answer than `none` at the leaves (a bug).
    Mismatch(String),
    /// A record had no usable round.
    NoRounds(String),
    /// The runs' records differ.
    Runs(RunsDiffer),
}

impl fmt::Display for GpuBvhError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            GpuBvhError::Scene(e) => write!(f, "GPU BVH scene: {e}"),
            GpuBvhError::Gpu(what, e) => write!(f, "GPU BVH, {what}: {e}"),
            GpuBvhError::Mismatch(e) => write!(f, "GPU BVH answers differ from none's: {e}"),
            GpuBvhError::NoRounds(e) => write!(f, "GPU BVH timing: no usable rounds for {e}"),
            GpuBvhError::Runs(e) => write!(f, "GPU BVH timing: {e}"),
        }
    }
}

impl std::error::Error for GpuBvhError {}

/// Where the timing is, for a progress line from another thread: units set up and visits
/// made of all planned, and the step under way.
#[derive(Debug, Default)]
pub struct Progress {
    /// Steps done (a unit's setup in a run, or a visit).
    pub done: AtomicUsize,
    /// Steps planned (visits are estimated from the time share).
    pub all: AtomicUsize,
    /// What is under way, in words.
    pub step: Mutex<String>,
}

impl Progress {
    fn at(&self, step: String) {
        if let Ok(mut s) = self.step.lock() {
            *s = step;
        }
    }

    fn tick(&self) {
        self.done.fetch_add(1, Ordering::Relaxed);
    }
}

/// One unit's rays and what answered them, for the report.
#[derive(Debug, Clone, PartialEq)]
pub struct UnitReport {
    /// Scene name.
    pub scene: String,
    /// ν.
    pub nu: f64,
    /// Tori in the scene.
    pub tori: usize,
    /// BVH nodes.
    pub nodes: u32,
    /// Camera rays per closest-hit pass, and how many hit.
    pub camera_rays: usize,
    /// Camera rays that hit (`none`'s answers).
    pub camera_hits: usize,
    /// Shadow rays per any-hit pass (one per camera hit whose spawn succeeded).
    pub shadow_rays: usize,
    /// Shadow rays blocked (`none`'s answers).
    pub shadowed: usize,
    /// Per cull (in timing order): who answered the camera rays and the shadow rays.
    pub answered: Vec<(GpuCull, FinishCounts, FinishCounts)>,
    /// Median wall time of preparing and uploading the camera and the shadow rays, ns a
    /// ray, over the runs.
    pub upload_ns: [f64; 2],
}

/// What a GPU BVH timing gives: the ratio records (every run combined), per-ray estimates
/// (median ns per ray of every contender, with the slowest and fastest run's medians as
/// its range), the units' reports, and whether the times are the device's.
#[derive(Debug, Clone)]
pub struct GpuBvhOutcome {
    /// Each cull over `none` (not `none` itself) and every contender over `copy`, per
    /// metric and unit.
    pub ratio: Vec<RatioRecord>,
    /// `gpu_bvh_closest_ns-<scene>/<cull>/<ν>`, `gpu_bvh_anyhit_ns-…`, and the copy
    /// kernel's `gpu_bvh_copy_closest_ns-<scene>/<ν>`, `gpu_bvh_copy_anyhit_ns-…`.
    pub estimates: Vec<EstimateRecord>,
    /// Per unit.
    pub units: Vec<UnitReport>,
    /// Whether every pass was timed by the device's timestamps (else the wall clock).
    pub timestamps: bool,
}

/// One unit's rays, drawn once.
struct UnitRays {
    scene: Scene,
    camera: Vec<Ray>,
    shadow: Vec<SpawnedRay>,
    report: UnitReport,
}

/// The contenders of a unit, in this order: copy over camera records, copy over shadow
/// records, then per cull its closest-hit pass and its any-hit pass.
fn contenders(culls: &[GpuCull]) -> usize {
    2 + 2 * culls.len()
}

/// The culls timed: `none` first, then the others asked for in [`GpuCull::ALL`]'s order.
#[must_use]
pub fn lineup(asked: &[GpuCull]) -> Vec<GpuCull> {
    let mut culls = vec![GpuCull::NoCull];
    culls.extend(
        GpuCull::ALL
            .iter()
            .copied()
            .filter(|c| *c != GpuCull::NoCull && asked.contains(c)),
    );
    culls
}

/// The paired GPU BVH ratios of `timing` on `gpu`, with `progress` kept up to date.
///
/// # Errors
///
/// [`GpuBvhError`]: a scene that cannot be built, a device failure, a cull whose answers
/// differ from `none`'s, a record without a usable round.
pub fn time_gpu_bvh(
    gpu: &GpuIntersector,
    timing: &GpuBvhTiming,
    progress: &Progress,
) -> Result<GpuBvhOutcome, GpuBvhError> {
    let culls = lineup(&timing.culls);
    let runs = timing.runs.max(1);
    let per_run = timing.seconds / runs as f64;
    let visits = ((per_run / VISIT.as_secs_f64()).ceil() as usize).max(timing.units.len());
    progress.all.store(
        timing.units.len() * (1 + runs) + visits * runs,
        Ordering::Relaxed,
    );
    let mut units = Vec::new();
    for &(kind, nu) in &timing.units {
        progress.at(format!("drawing the rays of {kind} nu={nu}"));
        units.push(unit_rays(gpu, kind, nu, timing)?);
        progress.tick();
    }
    let mut timestamps = true;
    let mut all_runs = Vec::new();
    // Per unit and contender, each run's median ns per pass.
    let mut medians = vec![vec![Vec::new(); contenders(&culls)]; units.len()];
    let mut uploads = vec![(Vec::new(), Vec::new()); units.len()];
    for run in 0..runs {
        let mut scenes = Vec::new();
        for u in &units {
            let what = format!("{} nu={} run {}", u.report.scene, u.report.nu, run + 1);
            progress.at(format!("uploading {what}"));
            let gpu_err = |e| GpuBvhError::Gpu(what.clone(), e);
            scenes.push(GpuScene::new(gpu, &u.scene.tori).map_err(gpu_err)?);
            progress.tick();
        }
        let mut resident = Vec::new();
        for (k, (u, scene)) in units.iter().zip(&scenes).enumerate() {
            let what = format!("{} nu={} run {}", u.report.scene, u.report.nu, run + 1);
            let gpu_err = |e| GpuBvhError::Gpu(what.clone(), e);
            let camera = scene.upload_rays(&u.camera).map_err(gpu_err)?;
            let shadow = scene.upload_spawned(&u.shadow).map_err(gpu_err)?;
            let per_ray = |d: Duration, n: usize| d.as_nanos() as f64 / n.max(1) as f64;
            uploads[k]
                .0
                .push(per_ray(camera.upload_time(), camera.len()));
            uploads[k]
                .1
                .push(per_ray(shadow.upload_time(), shadow.len()));
            timestamps &= scene.has_timestamps();
            resident.push((camera, shadow));
        }
        if run == 0 {
            for (u, (camera, shadow)) in units.iter_mut().zip(&resident) {
                progress.at(format!(
                    "checking every cull's answers on {} nu={}",
                    u.report.scene, u.report.nu
                ));
                check_answers(&culls, camera, shadow, &mut u.report)?;
            }
        }
        let mut rounds: Vec<Rounds> = Vec::new();
        for (k, (camera, _)) in resident.iter().enumerate() {
            let what = || format!("{} run {}", units[k].report.scene, run + 1);
            let once = camera
                .run(GpuCull::NoCull, false, 1)
                .map_err(|e| GpuBvhError::Gpu(what(), e))?
                .wall;
            let repeats = (SUBMISSION.as_secs_f64() / once.as_secs_f64().max(1e-9)).ceil();
            rounds.push(Rounds {
                ns: vec![Vec::new(); contenders(&culls)],
                repeats: (repeats as usize).clamp(1, 1000),
                rng: Pcg64::seed_from_u64(timing.seed ^ (run * 1000 + k) as u64),
            });
        }
        let start = Instant::now();
        let mut visit = 0;
        while start.elapsed().as_secs_f64() < per_run
            || rounds.iter().any(|r| r.ns[0].len() < MIN_ROUNDS)
        {
            let k = visit % units.len();
            progress.at(format!(
                "timing {} nu={}, run {} of {runs}",
                units[k].report.scene,
                units[k].report.nu,
                run + 1
            ));
            let (camera, shadow) = &resident[k];
            let began = Instant::now();
            loop {
                rounds[k].round(&culls, camera, shadow).map_err(|e| {
                    GpuBvhError::Gpu(format!("{} run {}", units[k].report.scene, run + 1), e)
                })?;
                if began.elapsed() >= VISIT {
                    break;
                }
            }
            visit += 1;
            progress.tick();
        }
        let mut records = Vec::new();
        for (k, (u, r)) in units.iter().zip(&rounds).enumerate() {
            let (camera, shadow) = &resident[k];
            push_records(
                &mut records,
                u,
                r,
                &culls,
                (camera.len(), shadow.len()),
                timing.seed,
            )?;
            for (c, ns) in r.ns.iter().enumerate() {
                let mut v = ns.clone();
                medians[k][c].push(median(&mut v));
            }
        }
        all_runs.push(records);
    }
    let ratio = combine_runs(&all_runs).map_err(GpuBvhError::Runs)?;
    let mut estimates = Vec::new();
    for (k, u) in units.iter_mut().enumerate() {
        let (scene, nu) = (&u.report.scene, u.report.nu);
        let rays = [u.report.camera_rays, u.report.shadow_rays];
        for (c, per_run) in medians[k].iter().enumerate() {
            let (metric, cull) = contender_name(&culls, c);
            let n = rays[c % 2] as f64;
            let name = match cull {
                None => format!(
                    "gpu_bvh_copy_{}-{scene}/{nu}",
                    metric.trim_start_matches("gpu_bvh_")
                ),
                Some(cull) => format!("{metric}-{scene}/{}/{nu}", cull.name()),
            };
            estimates.push(estimate(name, per_run, n));
        }
        let mut up = std::mem::take(&mut uploads[k]);
        u.report.upload_ns = [median(&mut up.0), median(&mut up.1)];
    }
    Ok(GpuBvhOutcome {
        ratio,
        estimates,
        units: units.into_iter().map(|u| u.report).collect(),
        timestamps,
    })
}

/// Contender `c`'s metric and cull (`None`: the copy kernel).
fn contender_name(culls: &[GpuCull], c: usize) -> (&'static str, Option<GpuCull>) {
    let metric = GPU_BVH_METRICS[c % 2];
    (metric, (c >= 2).then(|| culls[c / 2 - 1]))
}

/// A per-ray estimate from the runs' medians of ns per pass: their median, with the
/// fastest and slowest run's.
fn estimate(benchmark: String, per_run: &[f64], rays: f64) -> EstimateRecord {
    let lo = per_run.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = per_run.iter().copied().fold(0.0, f64::max);
    let mut v = per_run.to_vec();
    EstimateRecord {
        benchmark,
        elements: rays as u64,
        ns_per_element: median(&mut v) / rays,
        ns_per_element_ci: [lo / rays, hi / rays],
    }
}

/// A unit's scene and rays: the camera rays, `none`'s answers on them (by the one-call
/// path, [`GpuScene::trace`]), and a shadow ray spawned on each hit.
fn unit_rays(
    gpu: &GpuIntersector,
    kind: SceneKind,
    nu: f64,
    timing: &GpuBvhTiming,
) -> Result<UnitRays, GpuBvhError> {
    let scene = Scene::build(kind, nu, timing.tori, timing.seed)
        .map_err(|e| GpuBvhError::Scene(e.to_string()))?;
    let side = (timing.rays as f64).sqrt().ceil() as usize;
    let mut camera = scene.camera_rays(side);
    camera.truncate(timing.rays);
    let what = || format!("{kind} nu={nu}");
    let gpu_scene = GpuScene::new(gpu, &scene.tori).map_err(|e| GpuBvhError::Gpu(what(), e))?;
    let answers = gpu_scene
        .trace(GpuCull::NoCull, &camera)
        .map_err(|e| GpuBvhError::Gpu(what(), e))?;
    let hits: Vec<Option<(u32, f32)>> = answers
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
    if shadow.is_empty() {
        return Err(GpuBvhError::Scene(format!(
            "{}: no shadow ray to time ({} of its {} camera rays hit a torus; allowed: a \
             scene and --batch whose camera rays hit)",
            what(),
            hits.iter().flatten().count(),
            camera.len()
        )));
    }
    let report = UnitReport {
        scene: kind.name().to_string(),
        nu,
        tori: scene.tori.len(),
        nodes: gpu_scene.bvh().node_count(),
        camera_rays: camera.len(),
        camera_hits: hits.iter().flatten().count(),
        shadow_rays: shadow.len(),
        shadowed: 0,
        answered: Vec::new(),
        upload_ns: [0.0; 2],
    };
    Ok(UnitRays {
        scene,
        camera,
        shadow,
        report,
    })
}

/// Every cull's answers on the resident rays against `none`'s, into `report`: per cull
/// who answered them (`answered`), and the shadow rays `none` finds blocked (`shadowed`).
fn check_answers(
    culls: &[GpuCull],
    camera: &SceneRays<'_>,
    shadow: &SceneRays<'_>,
    report: &mut UnitReport,
) -> Result<(), GpuBvhError> {
    let what = format!("{} nu={}", report.scene, report.nu);
    let gpu_err = |e| GpuBvhError::Gpu(what.clone(), e);
    let mut answered = Vec::new();
    let mut want = None;
    for &cull in culls {
        camera.run(cull, false, 1).map_err(gpu_err)?;
        let closest = camera.closest_answers().map_err(gpu_err)?;
        shadow.run(cull, true, 1).map_err(gpu_err)?;
        let any = shadow.any_answers().map_err(gpu_err)?;
        let counts = (
            FinishCounts::of(closest.iter().map(|a| &a.by)),
            FinishCounts::of(any.iter().map(|a| &a.by)),
        );
        answered.push((cull, counts.0, counts.1));
        let Some((none_closest, none_any)) = &want else {
            report.shadowed = any.iter().filter(|a| a.occluded).count();
            want = Some((closest, any));
            continue;
        };
        let none_closest: &Vec<torus_cull::gpu::SceneAnswer> = none_closest;
        for (i, (a, b)) in closest.iter().zip(none_closest).enumerate() {
            let same = match (a.hit, b.hit) {
                (None, None) => true,
                (Some(x), Some(y)) => x.t == y.t,
                _ => false,
            };
            if !same {
                return Err(GpuBvhError::Mismatch(format!(
                    "{what}, {} closest hit of camera ray {i}: {:?} vs none {:?}",
                    cull.name(),
                    a.hit,
                    b.hit
                )));
            }
        }
        let none_any: &Vec<torus_cull::gpu::Occlusion> = none_any;
        for (i, (a, b)) in any.iter().zip(none_any).enumerate() {
            if a.occluded != b.occluded {
                return Err(GpuBvhError::Mismatch(format!(
                    "{what}, {} any hit of shadow ray {i}: {} vs none {}",
                    cull.name(),
                    a.occluded,
                    b.occluded
                )));
            }
        }
    }
    report.answered = answered;
    Ok(())
}

/// One unit's rounds in one run.
struct Rounds {
    /// ns per pass, `ns[contender][round]`.
    ns: Vec<Vec<f64>>,
    /// Passes per timed submission.
    repeats: usize,
    rng: Pcg64,
}

impl Rounds {
    /// Every contender once, in a shuffled order.
    fn round(
        &mut self,
        culls: &[GpuCull],
        camera: &SceneRays<'_>,
        shadow: &SceneRays<'_>,
    ) -> Result<(), GpuError> {
        let mut order: Vec<usize> = (0..self.ns.len()).collect();
        order.shuffle(&mut self.rng);
        for c in order {
            let rays = if c % 2 == 0 { camera } else { shadow };
            let time = match contender_name(culls, c).1 {
                None => rays.run_copy(self.repeats)?,
                Some(cull) => rays.run(cull, c % 2 == 1, self.repeats)?,
            };
            self.ns[c].push(time.pass_ns(self.repeats));
        }
        Ok(())
    }
}

/// One unit's records of one run: every cull but `none` over `none`, and every contender
/// over the copy kernel, per metric.
fn push_records(
    records: &mut Vec<RatioRecord>,
    unit: &UnitRays,
    rounds: &Rounds,
    culls: &[GpuCull],
    (camera, shadow): (usize, usize),
    seed: u64,
) -> Result<(), GpuBvhError> {
    let report = &unit.report;
    for c in 2..rounds.ns.len() {
        let (metric, cull) = contender_name(culls, c);
        let cull = cull.expect("a cull's contender");
        let rays = if c % 2 == 0 { camera } else { shadow };
        let answered = report
            .answered
            .iter()
            .find(|(k, ..)| *k == cull)
            .map(|(_, a, b)| if c % 2 == 0 { *a } else { *b });
        let escalation_rate = answered.map(|a| (a.device + a.host) as f64 / rays.max(1) as f64);
        let none = 2 + c % 2;
        let mut references = vec![(COPY, c % 2)];
        if c != none {
            references.insert(0, (GpuCull::NoCull.name(), none));
        }
        for (reference, r) in references {
            let bootstrap_seed = seed ^ (records.len() as u64 + 1).wrapping_mul(0x9E37_79B9);
            let e = ratio_estimate(&rounds.ns[c], &rounds.ns[r], rays as f64, bootstrap_seed)
                .ok_or_else(|| {
                    GpuBvhError::NoRounds(format!(
                        "{} {} {}/{reference} {metric}",
                        report.scene,
                        report.nu,
                        cull.name()
                    ))
                })?;
            records.push(RatioRecord {
                case: report.scene.clone(),
                nu: report.nu,
                cull: cull.name().to_string(),
                reference: reference.to_string(),
                metric: metric.to_string(),
                ratio: e.ratio,
                ratio_ci: e.ratio_ci,
                rounds: e.rounds as u64,
                rounds_measured: rounds.ns[c].len() as u64,
                rays: rays as u64,
                ns_per_ray: e.ns_per_ray,
                reference_ns_per_ray: e.reference_ns_per_ray,
                precision: F32_PRECISION.to_string(),
                device: "gpu".to_string(),
                escalation_rate,
                ..RatioRecord::default()
            });
        }
    }
    Ok(())
}
