//! Paired timing inside the BVH: each cull at the leaves against `none` and `cychosz`
//! at the leaves, per ray traced through a whole scene, in the module's interleaved
//! rounds (docs of [`super`]), with within- and between-run intervals.
//!
//! Per scene × ν, the contenders, one pass each over the same rays per round, in a
//! shuffled order:
//!
//! - **closest-hit** (`bvh_closest_ns`): the camera rays through [`Scene::trace`], each
//!   cull of the list at the leaves;
//! - **any-hit** (`bvh_anyhit_ns`): one shadow ray per camera hit to the scene's light
//!   ([`crate::scene::rays`]) through [`Scene::occluded_spawned`], stopping at the first
//!   blocker;
//! - **bounce** (`bvh_bounce_ns`): one diffuse bounce per camera hit
//!   ([`crate::scene::rays::bounce_rays`], cosine-weighted about the normal on the side the
//!   ray came from) through [`Scene::trace_spawned`], closest hit: the secondary rays a
//!   path tracer spends most of its rays on, which start on a surface, so that their own
//!   torus's foot point and range differ from a camera ray's (issue 53);
//! - **batched leaves** (`bvh_batched_ns`): the camera rays through
//!   [`crate::scene::LeafBatcher`] (every leaf candidate collected, then the wavefront torus
//!   by torus), for each cull with a batch form.
//!
//! With [`BvhTiming::family`], one more unit: the torus family's shapes
//! ([`FamilyScene`]: rings, elliptical tubes, horn and spindle tori, whole and cut pipe
//! bends, each cull applied by the shape's own rule), timed closest-hit and any-hit (it
//! has no batched form), recorded as the scene `family`, with its bounce rays too.
//!
//! Each ratio is a cull's time over `none`'s and over `cychosz`'s under the same metric;
//! a batched cull is also timed over its own scalar closest-hit traversal (reference
//! [`SCALAR_REFERENCE`]): whether batching the leaves pays.
//!
//! Runs: `runs` runs in this process, each on scenes and ray buffers built afresh (a
//! fresh heap layout), the scene × ν units visited in turn for [`VISIT`] each until the
//! run's share of the time is spent, so that a slow spell falls on all of them alike.
//! [`combine_runs`] gives every record its between-run interval, as for `time --runs`.

use super::engine::{Interleaver, timed_pass};
use super::runs::{RunsDiffer, combine_runs};
use super::stats::{QUIET_FRACTION, quiet_rounds, ratio_estimate};
use super::sweep::undisturbed;
use crate::results::{CPU_DEVICE, F64_PRECISION, RatioRecord};
use crate::scene::family::FamilyScene;
use crate::scene::rays::{Spawned, Surfaces, bounce_rays, light, shadow_rays};
use crate::scene::{LeafBatcher, Scene, SceneHit, SceneKind, TraceStats, same_hit};
use crate::workload::CameraView;
use glam::{DVec3, Vec3};
use std::cell::RefCell;
use std::fmt;
use std::hint::black_box;
use std::time::{Duration, Instant};
use torus_cull::batch::{BatchCull, Dispatch};
use torus_cull::{Cull, CullKind, CullVisitor, Named, NoCull, Ray};

/// The closest-hit traversal's metric.
pub const BVH_CLOSEST: &str = "bvh_closest_ns";
/// The any-hit (shadow ray) traversal's metric.
pub const BVH_ANYHIT: &str = "bvh_anyhit_ns";
/// The bounce rays' closest-hit traversal's metric.
pub const BVH_BOUNCE: &str = "bvh_bounce_ns";
/// The batched leaves' metric.
pub const BVH_BATCHED: &str = "bvh_batched_ns";
/// The BVH metrics, in table order.
pub const BVH_METRICS: [&str; 4] = [BVH_CLOSEST, BVH_ANYHIT, BVH_BOUNCE, BVH_BATCHED];
/// The reference of a batched cull timed over its own scalar closest-hit traversal.
pub const SCALAR_REFERENCE: &str = "scalar";

/// How long one visit to a scene × ν lasts before the next one's turn.
pub const VISIT: Duration = Duration::from_millis(100);

/// The scene name of the torus family's unit in the records.
pub const FAMILY_SCENE: &str = "family";

/// How far apart the family's shapes stand, in outer diameters on average (as
/// `ring_field`'s tori).
const FAMILY_SPREAD: f64 = 1.5;

/// The ν of the scenes a workload does not list (`mixed_nu`, `dense`, and the torus
/// family's, whose shapes have their own): issue 40 times new scenes at one ν.
pub const NEW_SCENE_NU: f64 = 4.0;

/// The scene × ν units `time bvh` and `cargo bench` time: a workload's `scenes` at each
/// of `nus`, then every scene it lacks at [`NEW_SCENE_NU`] only.
#[must_use]
pub fn units_of(scenes: &[SceneKind], nus: &[f64]) -> Vec<(SceneKind, f64)> {
    let mut units: Vec<(SceneKind, f64)> = scenes
        .iter()
        .flat_map(|&k| nus.iter().map(move |&nu| (k, nu)))
        .collect();
    for &k in SceneKind::ALL {
        if !scenes.contains(&k) {
            units.push((k, NEW_SCENE_NU));
        }
    }
    units
}

/// The references of every ratio.
const REFERENCES: [CullKind; 2] = [CullKind::NoCull, CullKind::Cychosz];

/// What to time.
#[derive(Debug, Clone)]
pub struct BvhTiming {
    /// Scene layouts and the ν of their tori, in turn.
    pub units: Vec<(SceneKind, f64)>,
    /// Tori per scene.
    pub tori: usize,
    /// Scene seed.
    pub seed: u64,
    /// Culls at the leaves (`none` and `cychosz` are timed in any case).
    pub culls: Vec<CullKind>,
    /// Camera rays per timed pass (and at most as many shadow rays, and bounce rays).
    pub rays: usize,
    /// Seconds in all, shared by the runs.
    pub seconds: f64,
    /// Independent runs.
    pub runs: usize,
    /// The wavefront's instruction set, for the batched leaves.
    pub dispatch: Dispatch,
    /// Also the torus family's scene (`tori` shapes of R = 1), recorded at this ν (its
    /// shapes have their own); `None`: the tori's scenes only.
    pub family: Option<f64>,
}

/// Why a BVH timing failed.
#[derive(Debug, Clone, PartialEq)]
pub enum BvhTimingError {
    /// A scene could not be built.
    Scene(String),
    /// A cull gave another answer than `none` at the leaves (a bug: the culls are
    /// conservative and the tests hold them to brute force).
    Mismatch(String),
    /// A record had no usable round.
    NoRounds(String),
    /// The runs' records differ.
    Runs(RunsDiffer),
}

impl fmt::Display for BvhTimingError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            BvhTimingError::Scene(e) => write!(f, "BVH scene: {e}"),
            BvhTimingError::Mismatch(e) => write!(f, "BVH answers differ: {e}"),
            BvhTimingError::NoRounds(e) => write!(f, "BVH timing: no usable rounds for {e}"),
            BvhTimingError::Runs(e) => write!(f, "BVH timing: {e}"),
        }
    }
}

impl std::error::Error for BvhTimingError {}

/// A unit's scene: tori, or the torus family's shapes.
enum UnitScene {
    Tori(Scene),
    /// The family's scene and the ν its records carry.
    Family(FamilyScene, f64),
}

impl UnitScene {
    /// The records' scene name and ν.
    fn label(&self) -> (&'static str, f64) {
        match self {
            UnitScene::Tori(s) => (s.kind.name(), s.nu),
            UnitScene::Family(_, nu) => (FAMILY_SCENE, *nu),
        }
    }

    fn camera_rays(&self, size: usize) -> Vec<Ray> {
        match self {
            UnitScene::Tori(s) => s.camera_rays(size),
            UnitScene::Family(s, _) => s.camera_rays(size),
        }
    }

    #[inline]
    fn trace<C: Cull>(&self, cull: &C, ray: &Ray, stats: &mut TraceStats) -> SceneHit {
        match self {
            UnitScene::Tori(s) => s.trace(cull, ray, stats),
            UnitScene::Family(s, _) => s.trace(cull, ray, stats),
        }
    }

    #[inline]
    fn trace_spawned<C: Cull>(&self, cull: &C, s: &Spawned, stats: &mut TraceStats) -> SceneHit {
        match self {
            UnitScene::Tori(scene) => scene.trace_spawned(cull, s, stats),
            UnitScene::Family(scene, _) => scene.trace_spawned(cull, s, stats),
        }
    }

    #[inline]
    fn occluded_spawned<C: Cull>(&self, cull: &C, s: &Spawned, stats: &mut TraceStats) -> bool {
        match self {
            UnitScene::Tori(scene) => scene.occluded_spawned(cull, s, stats),
            UnitScene::Family(scene, _) => scene.occluded_spawned(cull, s, stats),
        }
    }
}

impl Surfaces for UnitScene {
    fn view(&self) -> (&CameraView, (DVec3, f64)) {
        match self {
            UnitScene::Tori(s) => s.view(),
            UnitScene::Family(s, _) => s.view(),
        }
    }

    fn facing_hit(&self, id: u32, ray: &Ray) -> Option<(f32, DVec3)> {
        match self {
            UnitScene::Tori(s) => s.facing_hit(id, ray),
            UnitScene::Family(s, _) => s.facing_hit(id, ray),
        }
    }

    fn spawn(&self, id: u32, ray: &Ray, t: f32, dir: Vec3) -> Option<Ray> {
        match self {
            UnitScene::Tori(s) => s.spawn(id, ray, t, dir),
            UnitScene::Family(s, _) => s.spawn(id, ray, t, dir),
        }
    }
}

/// One scene × ν with its rays and contenders.
struct Unit {
    scene: UnitScene,
    camera: Vec<Ray>,
    shadow: Vec<Spawned>,
    bounce: Vec<Spawned>,
    /// Its contenders (the family's scene has no batched leaves).
    lineup: Lineup,
    /// The batched leaves' buffers, kept from pass to pass as a renderer keeps them.
    batcher: RefCell<LeafBatcher>,
}

/// One record to make: the cull, the metric, its contender, and each reference's name
/// and contender.
type Planned = (CullKind, &'static str, usize, Vec<(String, usize)>);

/// The contenders of a unit: the culls' closest-hit passes, their any-hit passes, their
/// bounce passes, then the batched culls' passes.
struct Lineup {
    culls: Vec<CullKind>,
    batched: Vec<BatchCull>,
}

impl Lineup {
    /// The culls asked for and the references; `batched`: also their batched forms.
    fn new(asked: &[CullKind], batched: bool) -> Lineup {
        let mut culls: Vec<CullKind> = CullKind::TIMED
            .iter()
            .copied()
            .filter(|k| asked.contains(k) || REFERENCES.contains(k))
            .collect();
        culls.dedup();
        let batched = if batched {
            culls.iter().filter_map(|k| k.batched()).collect()
        } else {
            Vec::new()
        };
        Lineup { culls, batched }
    }

    fn len(&self) -> usize {
        3 * self.culls.len() + self.batched.len()
    }

    fn closest(&self, k: CullKind) -> usize {
        self.culls
            .iter()
            .position(|&c| c == k)
            .expect("in the lineup")
    }

    fn anyhit(&self, k: CullKind) -> usize {
        self.culls.len() + self.closest(k)
    }

    fn bounce(&self, k: CullKind) -> usize {
        2 * self.culls.len() + self.closest(k)
    }

    fn batched(&self, k: CullKind) -> Option<usize> {
        let b = k.batched()?;
        let i = self.batched.iter().position(|&c| c == b)?;
        Some(3 * self.culls.len() + i)
    }

    /// (cull, metric, contender, [(reference name, reference contender)]) of every record.
    fn records(&self) -> Vec<Planned> {
        let mut out = Vec::new();
        let against = |of: &dyn Fn(CullKind) -> Option<usize>, k: CullKind| {
            REFERENCES
                .iter()
                .filter(|&&r| r != k)
                .filter_map(|&r| Some((r.name().to_string(), of(r)?)))
                .collect::<Vec<_>>()
        };
        for &k in &self.culls {
            let closest = |c| Some(self.closest(c));
            out.push((k, BVH_CLOSEST, self.closest(k), against(&closest, k)));
        }
        for &k in &self.culls {
            let anyhit = |c| Some(self.anyhit(c));
            out.push((k, BVH_ANYHIT, self.anyhit(k), against(&anyhit, k)));
        }
        for &k in &self.culls {
            let bounce = |c| Some(self.bounce(c));
            out.push((k, BVH_BOUNCE, self.bounce(k), against(&bounce, k)));
        }
        for &k in &self.culls {
            if let Some(i) = self.batched(k) {
                let mut refs = against(&|c| self.batched(c), k);
                refs.push((SCALAR_REFERENCE.to_string(), self.closest(k)));
                out.push((k, BVH_BATCHED, i, refs));
            }
        }
        out
    }
}

/// The paired BVH ratios of `timing`, `progress(done, all)` called after every visit.
pub fn time_bvh(
    timing: &BvhTiming,
    progress: &mut dyn FnMut(usize, usize),
) -> Result<Vec<RatioRecord>, BvhTimingError> {
    let per_run = timing.seconds / timing.runs.max(1) as f64;
    let units_count = timing.units.len() + usize::from(timing.family.is_some());
    let visits_per_run = ((per_run / VISIT.as_secs_f64()).ceil() as usize).max(units_count);
    let all = visits_per_run * timing.runs;
    let mut done = 0;
    let mut runs = Vec::new();
    for run in 0..timing.runs {
        let units = build_units(timing)?;
        let mut rounds: Vec<Interleaver> = (0..units.len())
            .map(|u| Interleaver::new(units[u].lineup.len(), timing.seed ^ (run * 1000 + u) as u64))
            .collect();
        let start = Instant::now();
        let mut visit = 0;
        while visit < units.len() || start.elapsed().as_secs_f64() < per_run {
            let u = visit % units.len();
            let mut time_one = |i: usize| pass(&units[u], i, &timing.dispatch);
            let discard = usize::from(visit < units.len());
            rounds[u].visit(&mut time_one, discard, VISIT, 3, usize::MAX);
            visit += 1;
            done += 1;
            progress(done.min(all), all);
        }
        let mut records = Vec::new();
        for (unit, r) in units.iter().zip(&rounds) {
            push_records(&mut records, unit, r, timing.seed)?;
        }
        runs.push(records);
    }
    combine_runs(&runs).map_err(BvhTimingError::Runs)
}

/// Every scene × ν (and the family's scene), built afresh, with its camera, shadow and
/// bounce rays; checks that every cull gives `none`'s answers on them.
fn build_units(timing: &BvhTiming) -> Result<Vec<Unit>, BvhTimingError> {
    let scene_error = |e: crate::scene::SceneError| BvhTimingError::Scene(e.to_string());
    let mut scenes = Vec::new();
    for &(kind, nu) in &timing.units {
        let scene = Scene::build(kind, nu, timing.tori, timing.seed).map_err(scene_error)?;
        scenes.push(UnitScene::Tori(scene));
    }
    if let Some(nu) = timing.family {
        let scene = FamilyScene::build(timing.tori, timing.seed, 1.0, FAMILY_SPREAD)
            .map_err(scene_error)?;
        scenes.push(UnitScene::Family(scene, nu));
    }
    let mut units = Vec::new();
    for scene in scenes {
        let (camera, shadow, bounce) = unit_rays(&scene, timing.rays, timing.seed);
        let lineup = Lineup::new(&timing.culls, matches!(scene, UnitScene::Tori(_)));
        for &cull in &lineup.culls {
            if let Some(e) = cull.visit(Agree(&scene, &camera, &shadow, &bounce)) {
                let (name, nu) = scene.label();
                return Err(BvhTimingError::Mismatch(format!(
                    "{} {name} nu={nu}: {e}",
                    cull.name()
                )));
            }
        }
        units.push(Unit {
            scene,
            camera,
            shadow,
            bounce,
            lineup,
            batcher: RefCell::new(LeafBatcher::new()),
        });
    }
    Ok(units)
}

/// `n` camera rays (every 4th of an image of about 4n pixels), and one shadow ray and one
/// diffuse bounce (drawn from `seed`) per hit of the whole image, each evenly strided down
/// to at most `n`.
fn unit_rays(scene: &UnitScene, n: usize, seed: u64) -> (Vec<Ray>, Vec<Spawned>, Vec<Spawned>) {
    let side = ((4 * n.max(1)) as f64).sqrt().ceil() as usize;
    let image = scene.camera_rays(side);
    let hits: Vec<_> = image
        .iter()
        .map(|r| scene.trace(&NoCull, r, &mut TraceStats::default()))
        .collect();
    let stride = image.len().div_ceil(n.max(1)).max(1);
    let camera: Vec<Ray> = image.iter().step_by(stride).copied().collect();
    let shadow = shadow_rays(scene, &image, &hits, light(scene), 1.0);
    let stride = shadow.len().div_ceil(n.max(1)).max(1);
    let shadow = shadow.into_iter().step_by(stride).collect();
    let bounce = bounce_rays(scene, &image, &hits, seed, 1.0);
    let stride = bounce.len().div_ceil(n.max(1)).max(1);
    let bounce = bounce.into_iter().step_by(stride).collect();
    (camera, shadow, bounce)
}

/// Whether a cull at the leaves answers as `none` does on a unit's rays: `None`, or the
/// first ray that differs.
struct Agree<'a>(&'a UnitScene, &'a [Ray], &'a [Spawned], &'a [Spawned]);

impl CullVisitor for Agree<'_> {
    type Output = Option<String>;
    fn visit<C: Cull>(self, cull: C) -> Option<String> {
        let (scene, camera, shadow, bounce) = (self.0, self.1, self.2, self.3);
        let mut stats = TraceStats::default();
        let mut both = |ray: &Ray| {
            let a = scene.trace(&cull, ray, &mut stats);
            (a, scene.trace(&NoCull, ray, &mut stats))
        };
        if let Some(first) = disagreement("closest", camera, &mut both, same_hit) {
            return Some(first);
        }
        let mut both = |s: &Spawned| {
            let a = scene.occluded_spawned(&cull, s, &mut stats);
            (a, scene.occluded_spawned(&NoCull, s, &mut stats))
        };
        if let Some(first) = disagreement("any-hit", shadow, &mut both, |a, b| a == b) {
            return Some(first);
        }
        let mut both = |s: &Spawned| {
            let a = scene.trace_spawned(&cull, s, &mut stats);
            (a, scene.trace_spawned(&NoCull, s, &mut stats))
        };
        disagreement("bounce", bounce, &mut both, same_hit)
    }
}

/// The first of `rays` whose two answers (the cull's and `none`'s) are not the `same`,
/// named with its kind `what`; `None` when all agree.
fn disagreement<R: fmt::Debug, T: fmt::Debug + Copy>(
    what: &str,
    rays: &[R],
    both: &mut dyn FnMut(&R) -> (T, T),
    same: fn(T, T) -> bool,
) -> Option<String> {
    rays.iter().find_map(|ray| {
        let (a, b) = both(ray);
        (!same(a, b)).then(|| format!("{what} {ray:?}: {a:?} vs none {b:?}"))
    })
}

/// One timed pass of contender `i` over its unit's rays.
fn pass(unit: &Unit, i: usize, dispatch: &Dispatch) -> Duration {
    let lineup = &unit.lineup;
    let n = lineup.culls.len();
    if i < n {
        lineup.culls[i].visit(ScenePass(unit, Traced::Closest))
    } else if i < 2 * n {
        lineup.culls[i - n].visit(ScenePass(unit, Traced::AnyHit))
    } else if i < 3 * n {
        lineup.culls[i - 2 * n].visit(ScenePass(unit, Traced::Bounce))
    } else {
        let cull = lineup.batched[i - 3 * n];
        let UnitScene::Tori(scene) = &unit.scene else {
            unreachable!("the family's lineup has no batched contender")
        };
        let start = Instant::now();
        let mut stats = crate::scene::LeafBatchStats::default();
        let mut batcher = unit.batcher.borrow_mut();
        let hits = batcher.trace(scene, dispatch, cull, black_box(&unit.camera), &mut stats);
        black_box((hits, stats));
        start.elapsed()
    }
}

/// Which rays a [`ScenePass`] traces: closest-hit camera rays, any-hit shadow rays, or
/// closest-hit bounce rays (the spawned rays' traversal).
#[derive(Debug, Clone, Copy)]
enum Traced {
    Closest,
    AnyHit,
    Bounce,
}

/// A timed pass over one kind of the unit's rays, monomorphized per cull: the kind is
/// chosen once, before the clock starts, and each kind's loop is its own.
struct ScenePass<'a>(&'a Unit, Traced);

impl CullVisitor for ScenePass<'_> {
    type Output = Duration;
    #[inline(never)]
    fn visit<C: Cull>(self, cull: C) -> Duration {
        let (unit, scene) = (self.0, &self.0.scene);
        match self.1 {
            Traced::Closest => timed_pass(&unit.camera, |ray, stats: &mut TraceStats| {
                scene.trace(&cull, ray, stats).is_some()
            }),
            Traced::AnyHit => timed_pass(&unit.shadow, |s, stats: &mut TraceStats| {
                scene.occluded_spawned(&cull, s, stats)
            }),
            Traced::Bounce => timed_pass(&unit.bounce, |s, stats: &mut TraceStats| {
                scene.trace_spawned(&cull, s, stats).is_some()
            }),
        }
    }
}

/// Appends one unit's records of one run, from its quiet rounds.
fn push_records(
    records: &mut Vec<RatioRecord>,
    unit: &Unit,
    r: &Interleaver,
    seed: u64,
) -> Result<(), BvhTimingError> {
    let lineup = &unit.lineup;
    let quiet = quiet_rounds(&r.ns, &undisturbed(&r.disturbed), QUIET_FRACTION);
    let pick = |i: usize| quiet.iter().map(|&k| r.ns[i][k]).collect::<Vec<f64>>();
    let (scene, nu) = unit.scene.label();
    for (cull, metric, contender, references) in lineup.records() {
        let rays = match metric {
            BVH_ANYHIT => unit.shadow.len(),
            BVH_BOUNCE => unit.bounce.len(),
            _ => unit.camera.len(),
        };
        for (reference, reference_index) in references {
            let bootstrap_seed = seed ^ (records.len() as u64 + 1).wrapping_mul(0x9E37_79B9);
            let e = ratio_estimate(
                &pick(contender),
                &pick(reference_index),
                rays as f64,
                bootstrap_seed,
            )
            .ok_or_else(|| {
                BvhTimingError::NoRounds(format!(
                    "{scene} {nu} {}/{reference} {metric}",
                    cull.name()
                ))
            })?;
            records.push(RatioRecord {
                case: scene.to_string(),
                nu,
                cull: cull.name().to_string(),
                reference,
                metric: metric.to_string(),
                ratio: e.ratio,
                ratio_ci: e.ratio_ci,
                rounds: e.rounds as u64,
                rounds_measured: r.rounds() as u64,
                rays: rays as u64,
                ns_per_ray: e.ns_per_ray,
                reference_ns_per_ray: e.reference_ns_per_ray,
                precision: F64_PRECISION.to_string(),
                device: CPU_DEVICE.to_string(),
                ..RatioRecord::default()
            });
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every cull, metric and reference comes out, finite, with a between-run interval,
    /// at a tiny size (speed is the command's).
    #[test]
    fn every_record_is_reported_with_a_between_run_interval() {
        let timing = BvhTiming {
            units: vec![(SceneKind::FacingGrid, 4.0)],
            tori: 16,
            seed: 3,
            culls: CullKind::TIMED.to_vec(),
            rays: 32,
            seconds: 0.2,
            runs: 2,
            dispatch: Dispatch::best(),
            family: None,
        };
        let records = time_bvh(&timing, &mut |_, _| {}).unwrap();
        let n = CullKind::TIMED.len();
        let batched = CullKind::TIMED
            .iter()
            .filter(|k| k.batched().is_some())
            .count();
        // Each cull over none and cychosz but itself, per metric (closest, any-hit,
        // bounce); batched also over scalar.
        assert_eq!(records.len(), 3 * (2 * n - 2) + (2 * batched - 2) + batched);
        for r in &records {
            assert!(r.ratio.is_finite() && r.ratio > 0.0, "{r:?}");
            assert_eq!(r.runs + r.runs_set_aside, 2, "{r:?}");
            assert!(BVH_METRICS.contains(&r.metric.as_str()));
        }
        assert!(records.iter().any(|r| r.reference == SCALAR_REFERENCE));
        // Bounce rays: every cull over none, each with a between-run interval, on as many
        // rays as the scene's hits gave (at most the camera rays' count).
        let bounce: Vec<_> = records
            .iter()
            .filter(|r| r.metric == BVH_BOUNCE && r.reference == "none")
            .collect();
        assert_eq!(bounce.len(), n - 1, "{bounce:?}");
        for r in bounce {
            let [lo, hi] = r.ratio_ci_between.expect("a between-run interval");
            assert!(lo <= r.ratio && r.ratio <= hi, "{r:?}");
            assert!(r.rays > 0 && r.rays <= 32, "{r:?}");
        }
    }

    /// The family's scene adds closest-hit and any-hit records under the scene name
    /// `family` at the ν asked, and no batched one.
    #[test]
    fn the_family_scene_is_timed_closest_and_any_hit() {
        let culls = vec![CullKind::NoCull, CullKind::Cychosz, CullKind::Skala];
        let timing = BvhTiming {
            units: Vec::new(),
            tori: 24,
            seed: 5,
            culls: culls.clone(),
            rays: 32,
            seconds: 0.2,
            runs: 2,
            dispatch: Dispatch::best(),
            family: Some(4.0),
        };
        let records = time_bvh(&timing, &mut |_, _| {}).unwrap();
        // none over cychosz, cychosz over none, skala over both; per metric (closest,
        // any-hit, bounce).
        assert_eq!(records.len(), 3 * 4, "{records:?}");
        for r in &records {
            assert_eq!((r.case.as_str(), r.nu), (FAMILY_SCENE, 4.0), "{r:?}");
            assert_ne!(r.metric, BVH_BATCHED, "{r:?}");
            assert!(r.ratio.is_finite() && r.ratio > 0.0, "{r:?}");
        }
    }
}
