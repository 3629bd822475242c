//! The flags of `torus-cull time`'s subcommands: the ones every subcommand honours
//! ([`Common`], flattened into each), the case × ν × cull selection of the timings that
//! take it ([`Pick`]), and each subcommand's own. A subcommand offers only the flags it
//! reads, so clap refuses any other ("unexpected argument") and no flag is ever accepted
//! and ignored.

use crate::whole::Whole;
use std::path::PathBuf;

/// The flags every `time` subcommand honours.
#[derive(clap::Args, Debug, Clone)]
pub struct Common {
    /// Workload: `quick` or `default` (built into the binary), or a workload file. `family`
    /// and `bend` take its seed (their shapes are their own); `bvh` its `bvh` scenes.
    #[arg(long, default_value = "quick")]
    pub workload: PathBuf,
    /// Total measuring time in seconds, shared evenly by every unit timed (case × ν, scene
    /// × ν, shape).
    #[arg(long, default_value_t = 30.0)]
    pub seconds: f64,
    /// Rays per batch, timed by every contender in every round (default: 1024, or the
    /// workload's rays if fewer; `bvh`: camera rays a pass, default 1024; `gpu`: rays per
    /// case × ν, default 2 000 000, drawn from the workload's generators at that count).
    #[arg(long)]
    pub batch: Option<Whole>,
    /// Results JSON (default: results/<short commit>[-dirty]-<workload>-time.json, or
    /// …-time.json for the workload named `default`; `secondary`, `gpu` and `bvh` put
    /// their kind before `-time` (…-<workload>-gpu-time.json), `family` and `bend` write
    /// <commit>-family-time.json and -bend-time.json: no kind replaces another). Its
    /// directory must exist; the plots go next to it.
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Skip the SVG plots (by default each ratio, or on the GPU the ns per ray, is drawn
    /// with its interval, next to the results file).
    #[arg(long)]
    pub no_plots: bool,
}

/// Which of the workload's cases, ν and culls a timing covers.
#[derive(clap::Args, Debug, Clone, Default)]
pub struct Pick {
    /// Culls to time, comma-separated (default: all ten timed culls: none, sphere, aabb,
    /// cychosz, thick_cylinder, skala, ellipsoid, quadric, discriminant,
    /// discriminant_f64; on the GPU, its nine). The references cychosz and none are timed
    /// in any case.
    #[arg(long, value_delimiter = ',')]
    pub culls: Vec<String>,
    /// ν values to time, comma-separated, each one of the workload's (default: all).
    #[arg(long, value_delimiter = ',')]
    pub nu: Vec<f64>,
    /// Cases to time, comma-separated, each one of the workload's (default: all), in the
    /// workload's order.
    #[arg(long, value_delimiter = ',')]
    pub cases: Vec<String>,
}

/// `time ring` (and a bare `time`) and `time secondary`: the CPU's paired ratios.
#[derive(clap::Args, Debug, Clone)]
pub struct RingArgs {
    #[command(flatten)]
    pub common: Common,
    #[command(flatten)]
    pub pick: Pick,
    /// `scalar`: one ray at a time (`total_ns`, `cull_ns`); `both`: also the batch mode
    /// (`batch_total_ns`, `batch_cull_ns`: SIMD cull and wavefront; `batch_f32_total_ns`
    /// and `batch_f32_uncertified_ns`: the certified f32 wavefront and the same without
    /// its proof, also against the cull's f64 wavefront, with escalation rates) in the
    /// same rounds, for the culls with a batch form, at the instruction set
    /// `TORUS_CULL_ISA` names (default: the best this CPU has).
    #[arg(long, value_enum, default_value_t = Mode::Scalar)]
    pub mode: Mode,
    /// Independent runs sharing `--seconds` (default 5, fewer where `--seconds` is under
    /// 1.25, each run having at least 0.25 s; runs in a slow state of the machine are set
    /// aside, see `runs_set_aside`): each in a worker process of its own (a fresh copy of
    /// this binary: its own code and data placement, heap, and ray buffers shuffled and
    /// laid out afresh). Every ratio then carries, besides the within-run interval of its
    /// rounds, a between-run interval over the runs' ratios (`runs`, `run_ratios`,
    /// `ratio_ci_between`), which the console tables show and `compare` judges by. More
    /// runs give a narrower between-run interval. 1: one run in this process, with the
    /// within-run interval only.
    #[arg(long)]
    pub runs: Option<Whole>,
    /// Internal: this process is worker run K of a `--runs` timing (writes its records
    /// to `--out`, prints no tables).
    #[arg(long, hide = true)]
    pub worker_run: Option<u64>,
}

/// Which modes `time ring` and `time secondary` measure.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Mode {
    /// One ray at a time.
    Scalar,
    /// One ray at a time and batch mode, in the same rounds.
    Both,
}

impl Mode {
    /// The modes of the precision × engine axis timed (on the CPU, in f64 and, in batches,
    /// the certified f32 wavefront too).
    pub fn modes(self) -> &'static [torus_cull_lab::precision::Mode] {
        use torus_cull_lab::precision::Mode::{Batch, Scalar};
        match self {
            Mode::Scalar => &[Scalar],
            Mode::Both => &[Scalar, Batch],
        }
    }
}

/// `time family` and `time bend`: the shapes beyond the ring torus.
#[derive(clap::Args, Debug, Clone)]
pub struct ShapeArgs {
    #[command(flatten)]
    pub common: Common,
    /// Runs per shape, one after the other in this process (fresh ray buffers each),
    /// sharing `--seconds`: 2 or more give each ratio a between-run interval (default 3).
    #[arg(long)]
    pub runs: Option<Whole>,
}

/// `time bvh`: the paired ratios inside the BVH.
#[derive(clap::Args, Debug, Clone)]
pub struct BvhArgs {
    #[command(flatten)]
    pub common: Common,
    /// Culls to time at the leaves, comma-separated (default: all ten timed culls); none
    /// and cychosz are timed in any case.
    #[arg(long, value_delimiter = ',')]
    pub culls: Vec<String>,
    /// ν of the scenes' tori, comma-separated, any valid ν (default: the workload's `bvh`
    /// ν).
    #[arg(long, value_delimiter = ',')]
    pub nu: Vec<f64>,
    /// Runs, one after the other in this process, sharing `--seconds` (default 10: the
    /// slow-state runs set aside per batch leave 1 to 3 of 5 on a shared machine, and the
    /// t quantile of so few is wide).
    #[arg(long)]
    pub runs: Option<Whole>,
}

/// `time gpu`: the WGSL kernel with the rays resident on the device.
#[derive(clap::Args, Debug, Clone)]
pub struct GpuArgs {
    #[command(flatten)]
    pub common: Common,
    #[command(flatten)]
    pub pick: Pick,
    /// Also time the f64 finish pass after the kernel (an adapter with `SHADER_F64`), per
    /// case × ν × cull, as the library runs it (`intersect_finished`): its device time per
    /// ray of the batch and per escalated ray, as estimates `gpu_finish_ns-<case>/<cull>/<ν>`
    /// and `gpu_finish_per_escalated_ns-…`, in the same rounds as the kernel.
    #[arg(long)]
    pub finish: bool,
    /// Threads per workgroup of the kernel (32, 64, 128 or 256; the answers are the same,
    /// only the speed may differ). The results' device names it.
    #[arg(long, default_value_t = Whole(64))]
    pub workgroup: Whole,
}
