//! The results JSON (schema version 1): what `run` and `cargo bench` write and `compare`
//! reads. Files are written through [`crate::output`]: a regular file is replaced
//! atomically, so an interrupted run never leaves half a file. Field names are stable;
//! new fields may be added.

pub mod counts;
pub mod shapes;

use serde::{Deserialize, Serialize};
use std::fmt;
use std::path::{Path, PathBuf};

/// The schema version this build writes and reads.
pub const SCHEMA_VERSION: u32 = 1;

/// A results file.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Results {
    /// Always [`SCHEMA_VERSION`].
    pub schema_version: u32,
    /// Where and how the figures were made.
    pub meta: Meta,
    /// Rejection counts per case × ν × cull.
    pub rejection: Vec<RejectionRecord>,
    /// Criterion timings per case × ν × cull (filled by `cargo bench`).
    #[serde(default)]
    pub timing: Vec<TimingRecord>,
    /// Many-torus BVH figures per scene × ν × cull (filled by `cargo bench`).
    #[serde(default)]
    pub bvh: Vec<BvhRecord>,
    /// The quartic solver against a peer crate (filled by `cargo bench`).
    #[serde(default)]
    pub solver: Vec<SolverRecord>,
    /// Every criterion benchmark of the run as measured, per element (filled by
    /// `cargo bench`): what a filtered run keeps even when no derived record is complete.
    #[serde(default)]
    pub estimates: Vec<EstimateRecord>,
    /// Paired, interleaved timing ratios per case × ν × cull × reference × metric (filled
    /// by `torus-cull time` and `cargo bench`; absent from older files).
    #[serde(default)]
    pub ratio: Vec<RatioRecord>,
    /// Rejection counts per torus-family member or pipe bend × cull (filled by `run` from
    /// a workload's `shapes` key; absent from older files and when there are none).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub shapes: Vec<shapes::ShapeRecord>,
    /// Instructions per ray under callgrind per region (filled by `torus-cull count`;
    /// absent from older files and files without counts).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub counts: Vec<counts::CountRecord>,
}

/// Provenance of a results file.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Meta {
    /// The short commit the binary was built from, or null for a build outside a git
    /// checkout.
    pub commit: Option<String>,
    /// Whether the sources the binary was built from differed from the commit.
    pub dirty: bool,
    /// When the file was made, RFC 3339.
    pub created: String,
    /// The compiler that built the harness.
    pub rustc: String,
    /// The CPU model.
    pub cpu: String,
    /// The workload's name.
    pub workload: String,
    /// SHA-256 of the workload file.
    pub workload_sha256: String,
    /// The workload's seed.
    #[serde(default)]
    pub seed: Option<u64>,
    /// The harness version.
    #[serde(default)]
    pub torus_cull_version: Option<String>,
    /// What made the file: `run` or `bench`.
    #[serde(default)]
    pub tool: Option<String>,
    /// True when only part of the benchmark set was measured (a filtered `cargo bench`):
    /// such a file holds only what was measured, has no rejection sweep, and is written to
    /// a `-partial` name, never over a complete file.
    #[serde(default)]
    pub partial: bool,
    /// The `cargo bench` preset (`smoke`, `default`, `full`); null for `run`.
    #[serde(default)]
    pub preset: Option<String>,
    /// The sizes that shape the figures; null in files from before it was recorded.
    #[serde(default)]
    pub sizes: Option<Sizes>,
    /// The instruction set the batch (`"mode": "batch"`) timings ran on: `avx512`, `avx2`,
    /// `neon` or `scalar` (see [`torus_cull::batch::Isa`]); null when nothing was batched.
    #[serde(default)]
    pub isa: Option<String>,
    /// Logical cores the process could use (`available_parallelism`); null in older files.
    #[serde(default)]
    pub cores: Option<u64>,
    /// Worker threads the measurement ran on (`run --threads`; 1 for the timings, which
    /// run on one thread); null in older files.
    #[serde(default)]
    pub threads: Option<u64>,
    /// The operating system and architecture, and the kernel release where it can be read
    /// (e.g. `linux x86_64 6.8.0-49-generic`); null in older files.
    #[serde(default)]
    pub os: Option<String>,
    /// The GPU adapter a `time gpu` file was measured on: its name, device type
    /// and backend, and "software adapter: no GPU timing claimed" for a CPU rasteriser
    /// (lavapipe); absent from CPU timings and older files.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub device: Option<String>,
    /// A summary's full file (`torus-cull summarize`, [`crate::summary`]): this file holds
    /// only the records the docs quote; absent in a full file.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub summary_of: Option<String>,
    /// How the `counts` records were counted (valgrind's version, the dispatch level under
    /// it); absent from files without counts.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub counts: Option<counts::CountMeta>,
}

/// The sizes behind a results file's figures: two files compare only if these agree.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Sizes {
    /// Rays per (case, ν) in the rejection records (`smoke` caps the workload's count);
    /// null when the file has no rejection sweep.
    pub rejection_rays: Option<u64>,
    /// Rays per timed (case, ν) batch; null for `run`.
    pub timing_rays: Option<u64>,
    /// The timed ν values (empty for `run`).
    #[serde(default)]
    pub timed_nu: Vec<f64>,
    /// Criterion's warm-up per benchmark, seconds.
    pub warm_up_s: Option<f64>,
    /// Criterion's measurement per benchmark, seconds.
    pub measurement_s: Option<f64>,
    /// Criterion's samples per benchmark.
    pub samples: Option<u64>,
    /// The BVH scenes as benched (`smoke` shrinks them); null without BVH records.
    pub bvh: Option<BvhSizes>,
    /// The arguments passed to the bench harness (a filter, `--measurement-time`, …).
    #[serde(default)]
    pub bench_args: Vec<String>,
}

impl Sizes {
    /// The sizes of a file with only rejection counts (`torus-cull run`).
    pub fn rejection_only(rays: u64) -> Sizes {
        Sizes {
            rejection_rays: Some(rays),
            timing_rays: None,
            timed_nu: Vec::new(),
            warm_up_s: None,
            measurement_s: None,
            samples: None,
            bvh: None,
            bench_args: Vec::new(),
        }
    }
}

/// The BVH scenes' sizes as benched.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct BvhSizes {
    /// Scene names.
    pub scenes: Vec<String>,
    /// ν of the scenes' tori.
    pub nu: Vec<f64>,
    /// Tori per scene.
    pub tori: u64,
    /// Camera image side, pixels.
    pub image: u64,
    /// Random rays per scene.
    pub random_rays: u64,
}

/// One criterion benchmark as measured.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct EstimateRecord {
    /// Criterion's id, `group/function/parameter` (e.g. `total_ns-hole/skala/2`).
    pub benchmark: String,
    /// Elements (rays, lines or quartics) each timed iteration processes.
    pub elements: u64,
    /// Criterion's median per iteration, divided by `elements`: ns per element.
    pub ns_per_element: f64,
    /// Its confidence interval.
    pub ns_per_element_ci: [f64; 2],
}

/// The oracle's and one cull's counts on one (case, ν) batch.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct RejectionRecord {
    /// Workload case.
    pub case: String,
    /// ν = R/r.
    pub nu: f64,
    /// Cull name.
    pub cull: String,
    /// Rays in the batch.
    pub rays: u64,
    /// Oracle hits.
    pub hits: u64,
    /// Oracle misses.
    pub misses: u64,
    /// Oracle ambiguous (left out of false rejects).
    pub ambiguous: u64,
    /// Rays the cull rejected.
    pub rejected: u64,
    /// Rejected ∧ oracle hit: must be 0.
    pub false_rejects: u64,
    /// rejected / rays.
    pub rejection_rate: f64,
    /// rejected / misses; null when the batch has no misses.
    pub miss_capture: Option<f64>,
}

/// Criterion timings of one cull on one (case, ν) batch.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct TimingRecord {
    /// Workload case.
    pub case: String,
    /// ν.
    pub nu: f64,
    /// Cull name.
    pub cull: String,
    /// The cull alone, ns per ray (criterion median).
    pub cull_ns: f64,
    /// Cull + exact intersection when kept, ns per ray (criterion median).
    pub total_ns: f64,
    /// Criterion's confidence interval of `total_ns`.
    pub total_ns_ci: [f64; 2],
    /// total_ns(none) / total_ns(this cull), same run.
    pub speedup_vs_none: f64,
    /// cull_ns + (hits/rays)·solve_ns: this cull's cost if it rejected every miss.
    pub ideal_total_ns: f64,
    /// The exact intersection on the batch's oracle hits only, ns per ray: a hit costs
    /// more to solve than the average ray (more real roots, polish, normal).
    #[serde(default)]
    pub solve_hit_ns: Option<f64>,
    /// cull_ns + (hits/rays)·solve_hit_ns: the ideal at the true cost of a hit.
    #[serde(default)]
    pub ideal_total_ns_at_hit_cost: Option<f64>,
    /// Where the figures come from (`criterion`).
    pub source: String,
    /// `scalar` (one ray at a time, [`torus_cull::intersect_culled`]) or `batch` (the
    /// wavefront of [`torus_cull::batch`]: SIMD cull, compaction, batch solve); a record
    /// without it is scalar, so older files still load.
    #[serde(default = "scalar_mode")]
    pub mode: String,
    /// The exact intersection's precision: `f64`, or `f32` for the certified f32
    /// wavefront ([`torus_cull::batch::Wavefront::intersect_f32`]); a record without it is
    /// f64, so older files still load.
    #[serde(default = "f64_precision")]
    pub precision: String,
    /// Where it ran: `cpu` (the only device so far); a record without it ran on the CPU.
    #[serde(default = "cpu_device")]
    pub device: String,
    /// On an f32 record: the rays the f32 path could not prove and gave to the f64
    /// solver, over the batch's rays (one untimed pass); absent on f64 records.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub escalation_rate: Option<f64>,
}

impl TimingRecord {
    /// Whether this record times the batch (wavefront) mode.
    pub fn is_batch(&self) -> bool {
        self.mode == BATCH_MODE
    }

    /// Whether this record times the f32 path.
    pub fn is_f32(&self) -> bool {
        self.precision == F32_PRECISION
    }

    /// The cull name, with ` (batch)` appended for a batch record (` (batch f32)` for
    /// the f32 wavefront, and the device when it is not the CPU): what tables and
    /// comparisons key on, so modes, precisions and devices never pair with each other.
    pub fn label(&self) -> String {
        let mut tags: Vec<&str> = Vec::new();
        if self.is_batch() {
            tags.push("batch");
        }
        if self.precision != F64_PRECISION {
            tags.push(&self.precision);
        }
        if self.device != CPU_DEVICE {
            tags.push(&self.device);
        }
        if tags.is_empty() {
            self.cull.clone()
        } else {
            format!("{} ({})", self.cull, tags.join(" "))
        }
    }
}

/// [`TimingRecord::mode`] of one-ray-at-a-time timings.
pub const SCALAR_MODE: &str = crate::precision::Mode::Scalar.name();
/// [`TimingRecord::mode`] of wavefront timings.
pub const BATCH_MODE: &str = crate::precision::Mode::Batch.name();

fn scalar_mode() -> String {
    SCALAR_MODE.into()
}

/// [`TimingRecord::precision`] and [`RatioRecord::precision`] of the f64 paths (what a
/// record without the field means).
pub const F64_PRECISION: &str = crate::precision::Precision::F64.name();
/// [`TimingRecord::precision`] and [`RatioRecord::precision`] of the certified f32 path.
pub const F32_PRECISION: &str = crate::precision::Precision::F32.name();
/// [`TimingRecord::device`] and [`RatioRecord::device`] of CPU timings (what a record
/// without the field means).
pub const CPU_DEVICE: &str = crate::precision::Engine::Cpu.name();
/// [`RatioRecord::reference`] of the headline f32 ratio: the same cull's f64 wavefront
/// (metric `batch_total_ns`) in the same rounds, so the ratio is t(f32) / t(f64).
pub const F64_REFERENCE: &str = "f64";

fn f64_precision() -> String {
    F64_PRECISION.into()
}

fn cpu_device() -> String {
    CPU_DEVICE.into()
}

/// One cull timed against a reference in the same interleaved rounds (see
/// [`crate::paired`]): the median of the per-round ratios `t(cull) / t(reference)`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct RatioRecord {
    /// Workload case.
    pub case: String,
    /// ν.
    pub nu: f64,
    /// Cull name.
    pub cull: String,
    /// The cull it is timed against (`cychosz` or `none`, under the same metric), or
    /// [`F64_REFERENCE`] (`f64`): the same cull's f64 wavefront (`batch_total_ns`), for
    /// the f32 metrics.
    pub reference: String,
    /// `total_ns` (cull + exact intersection when kept), `cull_ns` (the cull alone), their
    /// batch forms `batch_total_ns` and `batch_cull_ns`, or the f32 wavefront's
    /// `batch_f32_total_ns` (certified) and `batch_f32_uncertified_ns` (no proof: what
    /// the proof costs); see [`crate::paired::Metric`].
    pub metric: String,
    /// Median per-round t(cull) / t(reference): below 1 the cull is faster. Of several
    /// [`runs`](Self::runs), the geometric mean of the runs' medians.
    pub ratio: f64,
    /// The within-run interval, `[lo, hi]`: the percentile bootstrap 95 % interval of
    /// that median. Of several runs, the runs' intervals pooled as if the runs did not
    /// differ: on the log scale, each side's half-width is √(Σ hₖ²) / K around the
    /// geometric mean (the standard error of a mean of K independent estimates); it
    /// says how well the rounds pinned the figure down, not how far the next run may land
    /// (that is [`ratio_ci_between`](Self::ratio_ci_between)).
    pub ratio_ci: [f64; 2],
    /// Rounds the ratio was taken over: the quietest quarter of those the operating
    /// system did not switch the thread out of (of all, if it did so in most).
    pub rounds: u64,
    /// Rounds measured in all.
    pub rounds_measured: u64,
    /// Rays per timing (the batch).
    pub rays: u64,
    /// The cull's median ns per ray over the rounds.
    pub ns_per_ray: f64,
    /// The reference's median ns per ray over the same rounds.
    pub reference_ns_per_ray: f64,
    /// The cull's exact intersection: `f64`, or `f32` for the f32 wavefront metrics; a
    /// record without it is f64, so older files still load.
    #[serde(default = "f64_precision")]
    pub precision: String,
    /// Where it ran: `cpu`; a record without it ran on the CPU.
    #[serde(default = "cpu_device")]
    pub device: String,
    /// On every f32 record: the rays of this cull's f32 pass that were not proved and
    /// went to the f64 solver, over the batch's rays (escalated / rays, from one untimed
    /// pass on the same (case, ν) batch); absent on f64 records.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub escalation_rate: Option<f64>,
    /// Independent runs the record combines (`time --runs`: worker processes; `cargo
    /// bench`: fresh layouts in one process; see [`crate::paired::runs`]); a record
    /// without it is one run, as every record was before the field existed.
    #[serde(default = "one_run")]
    pub runs: u64,
    /// Runs set aside as run in a slow state of the machine (the batch's exact
    /// intersection alone took more than [`crate::paired::runs::SLOW_STATE`] longer per
    /// ray than in its fastest run); `runs` counts those kept. Absent when none was.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub runs_set_aside: u64,
    /// Each kept run's own ratio (its median over its rounds), in run order; absent for a
    /// single run.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub run_ratios: Vec<f64>,
    /// The between-run 95 % interval, `[lo, hi]`: a Student t interval of the geometric
    /// mean of [`run_ratios`](Self::run_ratios) (t with runs − 1 degrees of freedom, on
    /// their logarithms), widened where needed to hold [`ratio_ci`](Self::ratio_ci). It
    /// covers what moves a whole run (code and data placement, the machine's state) as
    /// well as round-to-round noise; absent for a single run, whose between-run spread
    /// is unknown. `compare` judges by it when both files have it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ratio_ci_between: Option<[f64; 2]>,
    /// The run-to-run spread behind [`ratio_ci_between`](Self::ratio_ci_between): the
    /// standard deviation of ln(run ratio), this record's own or the one pooled over every
    /// cull and ν of the same comparison on the same case, whichever gives the wider
    /// interval (see [`crate::paired::runs`]).
    /// Absent where no spread is known (a single run, or files written before it).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub run_spread: Option<RunSpread>,
}

/// The standard deviation of ln(run ratio) behind a between-run interval, and what it
/// rests on: a spread estimated from few runs is itself uncertain, which the t quantile
/// of its degrees of freedom carries.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct RunSpread {
    /// Standard deviation of the logarithms of the run ratios.
    pub log_sd: f64,
    /// Its degrees of freedom: runs − 1 for the record's own, the sum of (runs − 1) over
    /// the records pooled.
    pub df: u64,
    /// Whether the pooled spread gave the wider interval, and so is the one used.
    pub pooled: bool,
}

/// Serde: leave a zero count out.
fn is_zero(n: &u64) -> bool {
    *n == 0
}

fn one_run() -> u64 {
    1
}

/// A record of one run with no escalation and nothing set aside: what a caller fills in
/// is the key, the estimate and its sizes, and `..RatioRecord::default()` gives the rest
/// (`runs` 1, `precision` f64, `device` cpu, empty strings and zeros for the key).
impl Default for RatioRecord {
    fn default() -> RatioRecord {
        RatioRecord {
            case: String::new(),
            nu: 0.0,
            cull: String::new(),
            reference: String::new(),
            metric: String::new(),
            ratio: 0.0,
            ratio_ci: [0.0; 2],
            rounds: 0,
            rounds_measured: 0,
            rays: 0,
            ns_per_ray: 0.0,
            reference_ns_per_ray: 0.0,
            precision: f64_precision(),
            device: cpu_device(),
            escalation_rate: None,
            runs: one_run(),
            runs_set_aside: 0,
            run_ratios: Vec::new(),
            ratio_ci_between: None,
            run_spread: None,
        }
    }
}

impl RatioRecord {
    /// Whether this record times the f32 path.
    pub fn is_f32(&self) -> bool {
        self.precision == F32_PRECISION
    }
}

/// One cull inside an obvhs BVH over one many-torus scene.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct BvhRecord {
    /// Scene name.
    pub scene: String,
    /// ν of the scene's tori.
    pub nu: f64,
    /// Cull used at the leaves.
    pub cull: String,
    /// Which rays: `camera` (the framing pinhole view) or `random` (lines through the
    /// scene's bounds).
    #[serde(default = "camera_rays")]
    pub ray_set: String,
    /// Rays traced.
    pub rays: u64,
    /// Rays with a closest hit.
    pub hits: u64,
    /// Leaf (primitive) visits per ray.
    pub leaf_visits_per_ray: f64,
    /// Cull rejections per ray.
    pub cull_rejects_per_ray: f64,
    /// Quartic solves per ray.
    pub quartic_solves_per_ray: f64,
    /// Million rays per second (criterion median).
    pub mrays_per_s: f64,
    /// Closest hits identical to brute force with the `none` cull.
    pub matches_brute_force: bool,
}

fn mixed_family() -> String {
    "mixed".into()
}

fn camera_rays() -> String {
    "camera".into()
}

/// A quartic solver's speed and accuracy on the bench's coefficient sets.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SolverRecord {
    /// Solver name.
    pub solver: String,
    /// The line family the quartics come from (`uniform`, `hole_edge`, `tangent`,
    /// `tangent_limit`); files from before families were split say `mixed`.
    #[serde(default = "mixed_family")]
    pub family: String,
    /// Quartics solved (one per non-ambiguous line).
    pub coefficient_sets: u64,
    /// Roots in the oracle's high-precision reference.
    pub reference_roots: u64,
    /// Reference roots with no solver root within 1e-6·(R + r).
    pub missed_roots: u64,
    /// Solver roots with no reference root within 1e-6·(R + r).
    pub spurious_roots: u64,
    /// Largest |t − t_ref|·|d|/(R + r) over the matched roots.
    pub max_rel_t_error: f64,
    /// ns per solve (criterion median).
    pub ns_per_solve: f64,
    /// Its confidence interval.
    pub ns_per_solve_ci: [f64; 2],
    /// `criterion`.
    pub source: String,
    /// Paired, interleaved t(solver) / t(`roots_0.0.8`) on the same quartics in the same
    /// run; null in files written before it.
    #[serde(default)]
    pub paired_vs_roots: Option<SolverPairedRatio>,
}

/// One solver's time against `roots_0.0.8`'s, every solver timed once per round over the
/// family's quartics in a shuffled order (see [`crate::paired`]).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SolverPairedRatio {
    /// Median per-round ratio: below 1 the solver is faster.
    pub ratio: f64,
    /// Percentile bootstrap 95 % interval of that median, `[lo, hi]`.
    pub ratio_ci: [f64; 2],
    /// Rounds the ratio was taken over: the quietest quarter of those the operating
    /// system did not switch the thread out of (of all, if it did so in most).
    pub rounds: u64,
    /// The solver's median ns per solve over those rounds.
    pub ns_per_solve: f64,
}

/// A results file that cannot be read.
#[derive(Debug)]
pub enum ResultsError {
    /// Reading or writing failed.
    Io(PathBuf, std::io::Error),
    /// Not JSON, or not this schema.
    Parse(PathBuf, String),
    /// Another schema version.
    Version(PathBuf, serde_json::Value),
}

impl fmt::Display for ResultsError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ResultsError::Io(p, e) => write!(f, "{}: {e}", p.display()),
            ResultsError::Parse(p, e) => {
                write!(f, "{}: not a torus-cull results file: {e}", p.display())
            }
            ResultsError::Version(p, v) => write!(
                f,
                "{}: field `schema_version` is {v}, this build reads only {SCHEMA_VERSION}",
                p.display()
            ),
        }
    }
}

impl std::error::Error for ResultsError {}

impl Results {
    /// An empty results file with fresh metadata for `workload`.
    pub fn new(workload: &crate::workload::spec::Workload, tool: &str) -> Results {
        let (commit, dirty) = git_state();
        Results {
            schema_version: SCHEMA_VERSION,
            meta: Meta {
                commit,
                dirty,
                created: humantime::format_rfc3339_seconds(std::time::SystemTime::now())
                    .to_string(),
                rustc: env!("TORUS_CULL_RUSTC").to_string(),
                cpu: cpu_model(),
                workload: workload.name.clone(),
                workload_sha256: workload.sha256.clone(),
                seed: Some(workload.seed),
                torus_cull_version: Some(env!("CARGO_PKG_VERSION").to_string()),
                tool: Some(tool.to_string()),
                partial: false,
                preset: None,
                sizes: None,
                isa: None,
                cores: std::thread::available_parallelism()
                    .ok()
                    .map(|n| n.get() as u64),
                threads: None,
                os: Some(os_description()),
                device: None,
                summary_of: None,
                counts: None,
            },
            rejection: Vec::new(),
            timing: Vec::new(),
            bvh: Vec::new(),
            solver: Vec::new(),
            estimates: Vec::new(),
            ratio: Vec::new(),
            shapes: Vec::new(),
            counts: Vec::new(),
        }
    }

    /// Read a results file, refusing other schema versions with a clear error.
    pub fn load(path: &Path) -> Result<Results, ResultsError> {
        let value = read_json(path)?;
        serde_json::from_value(value).map_err(|e| ResultsError::Parse(path.into(), e.to_string()))
    }

    /// Write the file (atomically when it is a regular file; see [`crate::output`]),
    /// compact: one line of JSON and a newline. Pretty printing made a full bench file half
    /// again as large (5.3 MB against 3.55 MB for f53cc7f's) for readers that are programs
    /// (`plot`, `compare`, `intervals`) or `jq`.
    pub fn save(&self, path: &Path) -> Result<(), ResultsError> {
        let mut text = serde_json::to_string(self).expect("results serialize");
        text.push('\n');
        write_atomic(path, text.as_bytes()).map_err(|e| ResultsError::Io(path.into(), e))
    }
}

/// The JSON of a file this tool wrote (a results file or an f32-check file), after
/// checking its `schema_version`: other versions are refused with a clear error.
pub fn read_json(path: &Path) -> Result<serde_json::Value, ResultsError> {
    let text = std::fs::read_to_string(path).map_err(|e| ResultsError::Io(path.into(), e))?;
    let value: serde_json::Value = serde_json::from_str(&text)
        .map_err(|e| ResultsError::Parse(path.into(), json_error(&text, &e)))?;
    match value.get("schema_version") {
        Some(v) if v.as_u64() == Some(SCHEMA_VERSION as u64) => Ok(value),
        Some(v) => Err(ResultsError::Version(path.into(), v.clone())),
        None => Err(ResultsError::Parse(
            path.into(),
            "missing field `schema_version`".into(),
        )),
    }
}

/// serde_json's message for `e`, and where the text holds a `NaN` or `Infinity` token at
/// the error (what Python's `json.dump` writes for a non-finite float), that word: JSON
/// has no such number, and "expected value at line 1 column 681" alone does not say so.
fn json_error(text: &str, e: &serde_json::Error) -> String {
    let line = text.lines().nth(e.line().saturating_sub(1)).unwrap_or("");
    // The column is 1-based, in bytes; the token starts at it or one before (a sign).
    let start = e.column().saturating_sub(2);
    let near = line.get(start..).unwrap_or("");
    let near = near.get(..near.len().min(12)).unwrap_or(near);
    let token = ["NaN", "Infinity", "inf", "nan"]
        .into_iter()
        .find(|t| near.contains(t));
    match token {
        Some(t) => format!(
            "{e}: `{t}` is not a JSON number (JSON has no NaN or Infinity; write a finite \
             number, or null where the field allows it)"
        ),
        None => e.to_string(),
    }
}

/// Write `bytes` to `path` the way every output of this crate is written: a regular file
/// is replaced atomically (temp file + rename), symlinks are followed, a FIFO or device is
/// written in place; see [`crate::output`].
pub fn write_atomic(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    crate::output::write_file(path, bytes)
}

/// The default output path: `<results_dir>/<short commit>[-dirty]<suffix>.json`, or
/// `<results_dir>/latest<suffix>.json` for a build outside a git checkout. The commit is
/// the one the binary was built from (see [`git_state`]).
pub fn default_path(results_dir: &Path, suffix: &str) -> PathBuf {
    let (commit, dirty) = git_state();
    let stem = match commit {
        Some(c) if dirty => format!("{c}-dirty"),
        Some(c) => c,
        None => "latest".to_string(),
    };
    results_dir.join(format!("{stem}{suffix}.json"))
}

/// (short commit, dirty) of the build: recorded by `build.rs` when the binary was
/// compiled, not read from whatever repository the current directory is in. `dirty`
/// means the sources the binary was built from (`src/`, `benches/`, `build.rs`,
/// `Cargo.toml`, `Cargo.lock`) differed from the commit.
pub fn git_state() -> (Option<String>, bool) {
    let commit = env!("TORUS_CULL_GIT_COMMIT");
    (
        (!commit.is_empty()).then(|| commit.to_string()),
        env!("TORUS_CULL_GIT_DIRTY") == "true",
    )
}

/// `<os> <arch>[ <kernel release>]`.
fn os_description() -> String {
    let base = format!("{} {}", std::env::consts::OS, std::env::consts::ARCH);
    match std::fs::read_to_string("/proc/sys/kernel/osrelease") {
        Ok(release) if !release.trim().is_empty() => format!("{base} {}", release.trim()),
        _ => base,
    }
}

fn cpu_model() -> String {
    std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("model name"))
                .and_then(|l| l.split(':').nth(1))
                .map(|m| m.trim().to_string())
        })
        .unwrap_or_else(|| std::env::consts::ARCH.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A timing record from before `mode` existed reads as scalar, and a meta block from
    /// before `isa` existed reads as null; a batch record keys apart from its scalar twin.
    #[test]
    fn old_records_read_as_scalar_and_modes_key_apart() {
        let old = r#"{"case":"uniform","nu":4.0,"cull":"skala","cull_ns":5.0,"total_ns":20.0,
            "total_ns_ci":[19.0,21.0],"speedup_vs_none":3.0,"ideal_total_ns":6.0,
            "source":"criterion"}"#;
        let r: TimingRecord = serde_json::from_str(old).unwrap();
        assert_eq!(r.mode, SCALAR_MODE);
        assert!(!r.is_batch());
        assert_eq!(r.label(), "skala");
        assert_eq!((r.precision.as_str(), r.device.as_str()), ("f64", "cpu"));
        assert!(!r.is_f32() && r.escalation_rate.is_none());
        let batch = TimingRecord {
            mode: BATCH_MODE.into(),
            ..r.clone()
        };
        assert!(batch.is_batch());
        assert_eq!(batch.label(), "skala (batch)");
        let f32 = TimingRecord {
            precision: F32_PRECISION.into(),
            escalation_rate: Some(0.0),
            ..batch.clone()
        };
        assert!(f32.is_f32());
        assert_eq!(f32.label(), "skala (batch f32)");
        let text = serde_json::to_string(&batch).unwrap();
        assert!(text.contains(r#""mode":"batch""#), "{text}");
        let meta = r#"{"commit":null,"dirty":false,"created":"x","rustc":"r","cpu":"c",
            "workload":"w","workload_sha256":"s"}"#;
        let m: Meta = serde_json::from_str(meta).unwrap();
        assert_eq!(m.isa, None);
        assert_eq!((m.cores, m.threads, m.os), (None, None, None));
    }

    /// A solver record from before the paired ratio reads with none, and one with it
    /// round-trips.
    #[test]
    fn old_solver_records_have_no_paired_ratio() {
        let old = r#"{"solver":"torus_cull","family":"uniform","coefficient_sets":1,
            "reference_roots":1,"missed_roots":0,"spurious_roots":0,"max_rel_t_error":0.0,
            "ns_per_solve":40.0,"ns_per_solve_ci":[39.0,41.0],"source":"criterion"}"#;
        let r: SolverRecord = serde_json::from_str(old).unwrap();
        assert_eq!(r.paired_vs_roots, None);
        let paired = SolverRecord {
            paired_vs_roots: Some(SolverPairedRatio {
                ratio: 0.6,
                ratio_ci: [0.59, 0.61],
                rounds: 100,
                ns_per_solve: 40.0,
            }),
            ..r
        };
        let text = serde_json::to_string(&paired).unwrap();
        assert_eq!(serde_json::from_str::<SolverRecord>(&text).unwrap(), paired);
    }
}
