//! The count channel (`torus-cull count`): instructions per ray under callgrind, for a
//! fixed, seeded ray set, beside the paired wall ratios (docs/counts.md).
//!
//! **Why our own harness.** The regions are few and fixed, and callgrind's command line
//! already says everything a harness needs: `--collect-atstart=no` with
//! `--toggle-collect=<region>` counts only inside one function and what it calls, and
//! `--dump-after=<region>` writes one dump per call. So a hidden worker mode of the
//! `torus-cull` binary runs every region once, in order, announcing each on stdout
//! ([`region::Announcer`]), and the parent ([`callgrind`]) pairs the announcements with the
//! dumps. One valgrind process serves every record, so its start-up (about a second) is
//! paid once. gungraun (formerly iai-callgrind) would add a crate, its client-request C
//! header, and a runner binary that must be installed at the crate's exact version on
//! every machine: more to keep in step than the two dozen lines it would replace.
//!
//! **Plan.** The worker and the parent build the same [`Plan`] from the same flags: the
//! workload's cases × ν (each (case, ν) the first [`Plan::rays`] rays of its stream, as
//! `time` draws its batch), the culls (always with the references `cychosz` and `none`),
//! and which paths ([`Path`]) to count.

pub mod callgrind;
pub mod region;
pub mod shapes;

use crate::results::counts::{CountMeta, CountRecord};
use crate::solver_suite::{FAMILIES, family_cases};
use crate::workload::spec::Workload;
use crate::workload::{Case, generate};
use region::{Announcer, Batch, BatchBuffers, RingSet, Scalar, ScalarPass, batch_region};
use std::io::Write;
use torus_cull::batch::Dispatch;
use torus_cull::{CullKind, Named};

/// Rays per (case, ν) unless asked: `time`'s batch, so that a count and a wall ratio
/// are of the same rays. The quick workload's whole plan (916 records) then counts in
/// about 15 s under callgrind.
pub const DEFAULT_RAYS: usize = 1024;

/// The fewest rays per region accepted (`--rays`): below it one ray's path is most of
/// the record.
pub const MIN_RAYS: usize = 4;

/// The most rays per region accepted: beyond it a run takes minutes under callgrind.
pub const MAX_RAYS: usize = 65_536;

/// The references every plan counts: the count ratios are over `cychosz` (and the BVH's
/// over `none`), as the wall ratios are.
pub const REFERENCES: [CullKind; 2] = [CullKind::Cychosz, CullKind::NoCull];

crate::named::named_enum! {
    /// Which paths a plan counts (`torus-cull count --paths`).
    #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
    pub enum Path: "path" {
        /// One ray at a time: each cull alone (`cull`), and cull + exact intersection
        /// (`total`), per case × ν.
        Scalar = "scalar",
        /// The wavefront at the dispatch level: `batch_total`, `batch_cull`,
        /// `batch_f32_total` (the certified f32 path), per case × ν.
        Batch = "batch",
        /// The quartic solver on each line family's quartics (`solver_suite`), ours only.
        Solver = "solver",
        /// The BVH of each of the workload's `bvh` scenes: closest hit per camera ray and
        /// any hit per shadow ray, each cull at the leaves.
        Bvh = "bvh",
        /// The torus family's members (`paired::family::members`): the exact
        /// intersection alone and behind each cull, on each member's box rays.
        Family = "family",
        /// The pipe bends (`paired::bend::bends`): each cull, and each behind the
        /// segment's wedge, on each bend's box rays.
        Bend = "bend",
    }
}

/// What one count run counts.
#[derive(Debug, Clone)]
pub struct Plan {
    /// The workload (its cases already narrowed to those asked for).
    pub workload: Workload,
    /// The ν values, each one of the workload's.
    pub nus: Vec<f64>,
    /// The culls, the references included.
    pub culls: Vec<CullKind>,
    /// Rays per (case, ν).
    pub rays: usize,
    /// The paths counted, in [`Path::ALL`]'s order.
    pub paths: Vec<Path>,
}

/// What a plan is made from: the command's flags, unparsed (and, as JSON, the worker's
/// plan file).
#[derive(Debug, Clone, Default, serde::Serialize, serde::Deserialize)]
pub struct PlanArgs {
    /// `--culls`: names of timed culls (empty: every timed cull).
    pub culls: Vec<String>,
    /// `--cases`: the workload's cases (empty: all).
    pub cases: Vec<String>,
    /// `--nu`: the workload's ν values (empty: all).
    pub nu: Vec<f64>,
    /// `--rays` (None: [`DEFAULT_RAYS`], or the workload's rays if fewer).
    pub rays: Option<usize>,
    /// `--paths` (empty: all).
    pub paths: Vec<String>,
}

impl Plan {
    /// The plan of `args` on `workload` (named `file` in errors), or an error naming the
    /// flag and what it allows.
    pub fn new(
        mut workload: Workload,
        file: &std::path::Path,
        args: &PlanArgs,
    ) -> Result<Plan, String> {
        let allowed_of = |have: Vec<String>| have.join(", ");
        for name in &args.cases {
            if !workload.cases.iter().any(|c| c.name() == name) {
                let have = workload
                    .cases
                    .iter()
                    .map(|c| c.name().to_string())
                    .collect();
                return Err(format!(
                    "--cases {name} is not in workload {} (allowed: {})",
                    file.display(),
                    allowed_of(have)
                ));
            }
        }
        if !args.cases.is_empty() {
            workload
                .cases
                .retain(|c| args.cases.iter().any(|n| n == c.name()));
        }
        let mut nus = Vec::new();
        for &nu in &args.nu {
            if !workload.nu.contains(&nu) {
                let have = workload.nu.iter().map(f64::to_string).collect();
                return Err(format!(
                    "--nu {} is not in workload {} (allowed: {})",
                    crate::number::Num(nu),
                    file.display(),
                    allowed_of(have)
                ));
            }
            if !nus.contains(&nu) {
                nus.push(nu);
            }
        }
        if nus.is_empty() {
            nus = workload.nu.clone();
        }
        let timed = || {
            allowed_of(
                CullKind::TIMED
                    .iter()
                    .map(|c| c.name().to_string())
                    .collect(),
            )
        };
        let mut culls = REFERENCES.to_vec();
        for name in &args.culls {
            let kind = CullKind::TIMED
                .into_iter()
                .find(|c| c.name() == name.trim())
                .ok_or_else(|| {
                    format!(
                        "--culls: '{}' is not a timed cull (allowed: {})",
                        name.trim(),
                        timed()
                    )
                })?;
            if !culls.contains(&kind) {
                culls.push(kind);
            }
        }
        if args.culls.is_empty() {
            culls = CullKind::TIMED.to_vec();
        } else {
            // Table order, whatever order they were asked in.
            culls = CullKind::TIMED
                .into_iter()
                .filter(|c| culls.contains(c))
                .collect();
        }
        let rays = match args.rays {
            None => DEFAULT_RAYS.min(workload.rays),
            Some(n) if (MIN_RAYS..=MAX_RAYS).contains(&n) => n,
            Some(n) => {
                return Err(format!(
                    "--rays {n} is invalid (allowed: {MIN_RAYS} ..= {MAX_RAYS} rays per case × ν)"
                ));
            }
        };
        let mut paths = Vec::new();
        for name in &args.paths {
            let path = Path::parse(name.trim()).map_err(|_| {
                format!(
                    "--paths: '{}' is not a path (allowed: {})",
                    name.trim(),
                    Path::allowed().join(", ")
                )
            })?;
            if !paths.contains(&path) {
                paths.push(path);
            }
        }
        if paths.is_empty() {
            paths = Path::ALL.to_vec();
        }
        paths.sort();
        Ok(Plan {
            workload,
            nus,
            culls,
            rays,
            paths,
        })
    }

    /// Whether the plan counts `path`.
    pub fn counts(&self, path: Path) -> bool {
        self.paths.contains(&path)
    }
}

/// The worker: every region of `plan`, announced on `out` (see [`region::Announcer`]),
/// with a line of progress per (case, ν) on stderr. First `isa <name>` (the dispatch
/// level chosen here), then `calibrate` and an empty region (the overhead every record
/// has), then the records.
pub fn work<W: Write>(plan: &Plan, out: W) -> Result<(), String> {
    let io = |e: std::io::Error| format!("count worker: writing to the parent: {e}");
    let dispatch = Dispatch::from_env().map_err(|e| e.to_string())?;
    let mut ann = Announcer::new(out);
    ann.line(&format!("isa {}", dispatch.isa().name()))
        .map_err(io)?;
    ann.line("calibrate").map_err(io)?;
    region::count_region(&mut || {});
    let units: Vec<(Case, f64)> = plan
        .workload
        .cases
        .iter()
        .flat_map(|&c| plan.nus.iter().map(move |&nu| (c, nu)))
        .collect();
    let ring = plan.counts(Path::Scalar) || plan.counts(Path::Batch);
    for (i, &(case, nu)) in units.iter().enumerate().filter(|_| ring) {
        eprintln!(
            "count: {} ν = {nu} ({}/{})",
            case.name(),
            i + 1,
            units.len()
        );
        let batch = generate(case, nu, plan.rays, plan.workload.seed, plan.workload.pose)
            .map_err(|e| e.to_string())?;
        let set = RingSet::new(&batch.torus, &batch.rays);
        ring_regions(plan, (case.name(), nu), &set, &dispatch, &mut ann).map_err(io)?;
    }
    if plan.counts(Path::Solver) {
        for family in FAMILIES {
            eprintln!("count: solver {family}");
            let seeds = (plan.workload.seed, plan.workload.pose);
            let cases = family_cases(family, &plan.nus, plan.rays, seeds, plan.workload.seed)
                .map_err(|e| e.to_string())?;
            let cases: Vec<([f64; 3], f64)> = cases.iter().map(|c| (c.c, c.u_origin)).collect();
            region::solver_regions(family, &cases, &dispatch, &mut ann).map_err(io)?;
        }
    }
    if plan.counts(Path::Bvh) {
        bvh_regions(plan, &mut ann)?;
    }
    let shape_rays = (plan.rays, plan.workload.seed);
    if plan.counts(Path::Family) {
        shapes::family(&plan.culls, shape_rays, &mut ann)?;
    }
    if plan.counts(Path::Bend) {
        shapes::bends(&plan.culls, shape_rays, &mut ann)?;
    }
    Ok(())
}

/// The BVH regions of every scene × ν of the workload's `bvh` key (none without it): the
/// rays as `time bvh` draws them, `plan.rays` of each kind evenly strided out of the
/// camera image (side √(4·rays)) and the shadow rays spawned from its hits (`none`'s).
fn bvh_regions<W: Write>(plan: &Plan, ann: &mut Announcer<W>) -> Result<(), String> {
    use crate::scene::rays::{light, shadow_rays};
    use crate::scene::{Scene, TraceStats};
    let io = |e: std::io::Error| format!("count worker: writing to the parent: {e}");
    let Some(spec) = &plan.workload.bvh else {
        return Ok(());
    };
    let n = plan.rays;
    for &kind in &spec.scenes {
        for &nu in &spec.nu {
            eprintln!("count: bvh {} ν = {nu}", kind.name());
            let scene =
                Scene::build(kind, nu, spec.tori, plan.workload.seed).map_err(|e| e.to_string())?;
            let side = ((4 * n) as f64).sqrt().ceil() as usize;
            let image = scene.camera_rays(side);
            let hits: Vec<_> = image
                .iter()
                .map(|r| scene.trace(&torus_cull::NoCull, r, &mut TraceStats::default()))
                .collect();
            let stride = image.len().div_ceil(n).max(1);
            let camera: Vec<_> = image.iter().step_by(stride).copied().collect();
            let shadow = shadow_rays(&scene, &image, &hits, light(&scene), 1.0);
            let stride = shadow.len().div_ceil(n).max(1);
            let shadow: Vec<_> = shadow.into_iter().step_by(stride).collect();
            for &cull in &plan.culls {
                cull.visit(region::BvhPass {
                    scene: &scene,
                    camera: &camera,
                    shadow: &shadow,
                    announcer: ann,
                    unit: (kind.name(), nu),
                })
                .map_err(io)?;
            }
        }
    }
    Ok(())
}

/// The ring regions of one (case, ν): the scalar ones, then the wavefront's.
fn ring_regions<W: Write>(
    plan: &Plan,
    (case, nu): (&str, f64),
    set: &RingSet<'_>,
    dispatch: &Dispatch,
    ann: &mut Announcer<W>,
) -> std::io::Result<()> {
    if plan.counts(Path::Scalar) {
        for (metric, name) in [(Scalar::Total, "total"), (Scalar::Cull, "cull")] {
            for &cull in &plan.culls {
                // `none` alone is an empty loop: nothing of a cull to count.
                if metric == Scalar::Cull && cull == CullKind::NoCull {
                    continue;
                }
                let key = ("ring", case, nu, cull.name(), name);
                cull.visit(ScalarPass {
                    metric,
                    set,
                    announcer: ann,
                    key,
                })?;
            }
        }
    }
    if plan.counts(Path::Batch) {
        let mut buffers = BatchBuffers::default();
        let metrics = [
            (Batch::Total, "batch_total"),
            (Batch::Cull, "batch_cull"),
            (Batch::F32Total, "batch_f32_total"),
        ];
        for (metric, name) in metrics {
            for &cull in &plan.culls {
                let Some(batched) = cull.batched() else {
                    continue;
                };
                if metric == Batch::Cull && cull == CullKind::NoCull {
                    continue;
                }
                let key = ("ring", case, nu, cull.name(), name);
                batch_region((dispatch, metric, batched), set, &mut buffers, ann, key)?;
            }
        }
    }
    Ok(())
}

/// Counts every region of `plan` under callgrind: runs `exe` (a `torus-cull` binary, whose
/// hidden `count --worker` mode is the worker) with the plan as flags, `workload` the
/// workload as the worker should open it. Returns how the counts were made and the
/// records, each with its ratio over its reference.
pub fn count(
    exe: &std::path::Path,
    workload: &std::path::Path,
    plan: &Plan,
) -> Result<(CountMeta, Vec<CountRecord>), String> {
    let text = serde_json::to_string(&WorkerPlan::of(workload, plan)?).expect("a plan serializes");
    let dumps = callgrind::run(exe, &text)?;
    let (isa, overhead, records) = records(&dumps.announced, &dumps.totals)?;
    let meta = CountMeta {
        valgrind: dumps.valgrind,
        isa,
        rays: plan.rays as u64,
        overhead,
    };
    Ok((meta, records))
}

/// The worker's plan file: the workload's text and the flags. The text, not the path:
/// a plan file's length and the worker's allocations before its regions place its heap
/// blocks, which the SIMD code's copies are sensitive to (see [`callgrind::run`]), so one
/// workload spelled two ways (`quick`, `workloads/quick.json`) must give one plan file.
#[derive(Debug, Clone, serde::Serialize, serde::Deserialize)]
pub struct WorkerPlan {
    /// The workload file's text.
    pub workload: String,
    /// The rest, resolved (every list given, so the worker needs no default).
    pub args: PlanArgs,
}

impl WorkerPlan {
    /// The plan file of `plan`, whose workload was opened from `workload`.
    fn of(workload: &std::path::Path, plan: &Plan) -> Result<WorkerPlan, String> {
        let text = match crate::workload::spec::built_in(workload) {
            Some(text) => text.to_string(),
            None => std::fs::read_to_string(workload)
                .map_err(|e| format!("{}: {e}", workload.display()))?,
        };
        let names = |v: Vec<&str>| v.into_iter().map(str::to_string).collect();
        Ok(WorkerPlan {
            workload: text,
            args: PlanArgs {
                culls: names(plan.culls.iter().map(|c| c.name()).collect()),
                cases: names(plan.workload.cases.iter().map(|c| c.name()).collect()),
                nu: plan.nus.clone(),
                rays: Some(plan.rays),
                paths: names(plan.paths.iter().map(|p| p.name()).collect()),
            },
        })
    }

    /// Reads a plan file and makes its plan.
    pub fn load(file: &std::path::Path) -> Result<Plan, String> {
        let text = std::fs::read_to_string(file).map_err(|e| format!("{}: {e}", file.display()))?;
        let wp: WorkerPlan = serde_json::from_str(&text)
            .map_err(|e| format!("{}: not a count plan: {e}", file.display()))?;
        let workload = Workload::parse(wp.workload.as_bytes(), file).map_err(|e| e.to_string())?;
        Plan::new(workload, file, &wp.args)
    }
}

/// The records the worker announced (`lines`, its stdout) with the dumps' instruction
/// totals (`totals`, in dump order): the first dump is the empty region, subtracted from
/// every other. The error says what did not match.
pub fn records(lines: &str, totals: &[u64]) -> Result<(String, u64, Vec<CountRecord>), String> {
    let mut isa = None;
    let mut announced = Vec::new();
    let mut calibrated = false;
    for line in lines.lines() {
        let words: Vec<&str> = line.split(' ').collect();
        match *words.as_slice() {
            ["isa", name] => isa = Some(name.to_string()),
            ["calibrate"] => calibrated = true,
            ["record", group, case, nu, cull, metric, rays] => {
                let nu: f64 = nu.parse().map_err(|_| format!("bad ν in `{line}`"))?;
                let rays: u64 = rays.parse().map_err(|_| format!("bad rays in `{line}`"))?;
                announced.push((group, case, nu, cull, metric, rays));
            }
            _ => return Err(format!("unexpected line from the worker: `{line}`")),
        }
    }
    let isa = isa.ok_or("the worker did not say which instruction set it dispatched to")?;
    if !calibrated || totals.len() != announced.len() + 1 {
        return Err(format!(
            "callgrind wrote {} dumps for {} regions and the calibration: the region \
             function was not matched as expected",
            totals.len(),
            announced.len()
        ));
    }
    let overhead = totals[0];
    let mut out = Vec::new();
    for ((group, case, nu, cull, metric, rays), &total) in announced.into_iter().zip(&totals[1..]) {
        let instructions = total.saturating_sub(overhead);
        out.push(CountRecord {
            group: group.to_string(),
            case: case.to_string(),
            nu,
            cull: cull.to_string(),
            metric: metric.to_string(),
            rays,
            instructions,
            per_ray: instructions as f64 / rays.max(1) as f64,
            reference: None,
            ratio: None,
        });
    }
    crate::results::counts::fill_ratios(&mut out);
    Ok((isa, overhead, out))
}
