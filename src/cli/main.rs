//! The `torus-cull` command line.
//!
//! Exit codes: 0 fine; 1 the measurement found a problem (a false reject in `run`, a
//! regression or records missing from the new file in `compare`, a missed, spurious or
//! misplaced hit of the f32 path in `f32-check`); 2 the input or
//! environment is bad (the message says which file and field). A closed stdout (`| head`)
//! is not an error: output stops, the files are still written, and the exit code is the
//! command's own.

use clap::{CommandFactory, FromArgMatches, Parser, Subcommand};
use std::path::PathBuf;
use std::process::ExitCode;
use whole::Whole;

mod check;
mod compare;
mod console;
mod count;
mod eval;
mod gpu_info;
mod plot;
mod render;
mod run;
mod summarize;
mod threads;
mod time;
mod whole;

#[derive(Parser)]
#[command(
    name = "torus-cull",
    version,
    about = "Measure ray-torus culls against an f64 oracle"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Run a workload: rejection counts for every case × ν × cull, and for every family
    /// member and pipe bend of its `shapes` × cull, tables, JSON and plots.
    Run {
        /// Workload: `default` or `quick` (built into the binary), or a workload file.
        #[arg(long, default_value = "default")]
        workload: PathBuf,
        /// Results JSON (default: results/<short commit>[-dirty]-<workload>-run.json, or
        /// …-run.json for the workload named `default`). Its directory must exist; the
        /// plots go next to it.
        #[arg(long)]
        out: Option<PathBuf>,
        /// Worker threads, 1 ..= 1024 (default: available cores).
        #[arg(long)]
        threads: Option<Whole>,
        /// Skip the SVG plots.
        #[arg(long)]
        no_plots: bool,
        /// Culls to count, comma-separated (default: every timed cull). The
        /// paper-as-printed variants are accepted too, to watch the oracle catch them.
        #[arg(long, value_delimiter = ',')]
        culls: Vec<String>,
    },
    /// Time the culls against cychosz and none in paired, interleaved rounds (ratios with
    /// 95% intervals), in about 30 s: `time ring` (a bare `time`), `secondary`, `family`,
    /// `bend`, `bvh`, `gpu`.
    Time(time::TimeArgs),
    /// Count instructions per ray under callgrind (valgrind): each cull alone and with the
    /// exact intersection per case × ν, the wavefront, the solver's families; written as
    /// the `counts` records of a results file that `compare` judges beside the wall ratios.
    Count(count::CountArgs),
    /// Diff two results files (or two f32-check files); exits 1 on a regression or when
    /// records of OLD are missing from NEW, 2 on unusable input (for CI gates).
    Compare {
        /// The older results JSON.
        old: PathBuf,
        /// The newer results JSON.
        new: PathBuf,
        /// Slowdown (percent) beyond which a timing with disjoint intervals is a regression.
        #[arg(long, default_value_t = 10.0)]
        threshold: f64,
        /// Show only records with a flag.
        #[arg(long)]
        only_changes: bool,
        /// Records of OLD missing from NEW only warn instead of failing (exit 1).
        #[arg(long)]
        allow_missing: bool,
        /// Give timing verdicts even when the files were measured on different machines
        /// (`meta.cpu`, `meta.isa`, `meta.device` or the architecture differ); without it
        /// such timings are shown but decide nothing.
        #[arg(long)]
        across_machines: bool,
        /// Change (percent) of a `counts` record's instructions per ray beyond which it is
        /// a change, with its direction; more instructions is a regression (default 0.1;
        /// counts of one build on one ray set are identical).
        #[arg(long)]
        count_threshold: Option<f64>,
    },
    /// Check that paired-ratio intervals hold from run to run: the share of each run's
    /// ratios inside the other runs' intervals, and the headline ratios' spread. Exits 1
    /// when a goal (coverage >= 95 %, worst headline change <= 3 %) is not met.
    Intervals {
        /// Two or more `torus-cull time` results files of one workload on one machine,
        /// written back to back (benches/honest_intervals.sh makes three).
        #[arg(required = true, num_args = 2..)]
        runs: Vec<PathBuf>,
    },
    /// Write the summary of a full results file (a `cargo bench` one): the records the docs
    /// quote (headline ratios with their intervals, the rejection, solver, BVH and timing
    /// tables, the metadata), small enough to commit. `compare` and `intervals` read it.
    Summarize {
        /// The full results JSON.
        full: PathBuf,
        /// Where to write the summary (default: FULL's name with `-summary`, beside it).
        #[arg(long)]
        out: Option<PathBuf>,
    },
    /// Render a many-torus scene and its cull map (PNG).
    Render {
        /// Scene: ring_field, chain or facing_grid.
        #[arg(long)]
        scene: String,
        /// ν = R/r of the scene's tori (> 1).
        #[arg(long)]
        nu: f64,
        /// Output PNG (a name ending in .png); the cull map goes next to it as
        /// <stem>-cullmap.png.
        #[arg(long)]
        out: PathBuf,
        /// Image side in pixels.
        #[arg(long, default_value_t = Whole(512))]
        size: Whole,
        /// Tori in the scene.
        #[arg(long, default_value_t = Whole(1000))]
        tori: Whole,
        /// Scene seed.
        #[arg(long, default_value_t = Whole(20261121))]
        seed: Whole,
    },
    /// Write the SVG charts of a results file (run, time, cargo bench) or an f32-check file.
    Plot {
        /// Results JSON.
        file: PathBuf,
        /// Where to write the SVGs, an existing directory (default: next to the file).
        #[arg(long)]
        out_dir: Option<PathBuf>,
    },
    /// Check every cull and intersector of one shape against the oracle, class by class:
    /// false rejects, rejection rate, capture of far misses (and a shape's own captures),
    /// missed, invented, misplaced hits and escalations of each intersector, at f64 (the
    /// culls and the exact intersection) or f32 (the f32 paths). Exits 1 on a false
    /// reject or a wrong answer of ours. Aliases: `torus-cull family`, `torus-cull bend`
    /// (`check --shape family|bend`) and `torus-cull f32-check` (`check --shape ring
    /// --precision f32`, its `--family` is `--class`).
    Check(check::CheckArgs),
    /// The GPU adapter wgpu picks (a binary built with `--features gpu`), one `key: value`
    /// a line: adapter, device_type, backend, driver, software (a CPU rasteriser such as
    /// lavapipe), shader_f64, f64_finish_pass (and why not), timestamps. Exits 2 with one
    /// line where there is no adapter.
    GpuInfo,
    /// Check every cull and the oracle on your own rays (CSV in the torus frame).
    Eval {
        /// Major radius R.
        #[arg(long = "major", allow_hyphen_values = true, value_parser = eval::parse_radius)]
        major: f32,
        /// Minor radius r > 0: the tube's semi-axis in the equatorial plane (a). R > r is
        /// a ring torus; R = r the horn and R < r the spindle (down to R/r = 0.01), whose
        /// surface is the outer "apple".
        #[arg(long = "minor", allow_hyphen_values = true, value_parser = eval::parse_radius)]
        minor: f32,
        /// The tube's semi-axis along the axis, b (default: b = r, a circular tube), with
        /// 0.25 <= b/r <= 4. With b != r the rows are answered for the elliptical member
        /// of the torus family (--exact f64 only).
        #[arg(long = "axial", allow_hyphen_values = true, value_parser = eval::parse_radius)]
        axial: Option<f32>,
        /// A pipe bend's bore r_min: 0, or R/1000 <= r_min <= r - 1e-7·(R + r), the bore's
        /// torus's ν at most 1000 and the wall no thinner than tested (default 0): with
        /// --bore, --phi-start
        /// or --delta-phi the rows are answered for the solid of a pipe bend (centre 0,
        /// axis +y, φ = 0 along +x, φ growing toward −z) whose outer tube is --minor: its
        /// nearest crossing of any face, the torus culls on its outer torus, and the bend
        /// oracle (--exact f64, or f32: the misses of the outer torus proved in f32, the
        /// rest escalated; a whole bend is the ring torus). A bend's rows add after the
        /// culls' columns `wedge` (the segment's wedge alone) and `wedge+<cull>` (each cull
        /// but none behind the wedge), as `bend` and `time bend` price them.
        #[arg(long = "bore", allow_hyphen_values = true)]
        bore: Option<f64>,
        /// The bend's segment start φ₀ in radians, finite (default 0).
        #[arg(long = "phi-start", allow_hyphen_values = true)]
        phi_start: Option<f64>,
        /// The bend's segment Δφ in radians, 0 < Δφ <= 2π (default 2π).
        #[arg(long = "delta-phi", allow_hyphen_values = true)]
        delta_phi: Option<f64>,
        /// Input CSV with header ox,oy,oz,dx,dy,dz (`-` for stdin), optionally followed
        /// by t_min, t_max, on_surface (any subset, in this order).
        ///
        /// t_min, t_max: the ray's range (default 0 and inf), 0 <= t_min <= t_max, in units
        /// of the direction. on_surface: 0 or 1 (default 0); 1 marks the origin as a
        /// surface point a renderer got from a hit (printed in f32 or f64), which must lie
        /// within 1e-4·(R + r) of the surface. Such a ray never hits its own origin: the
        /// library divides the origin's crossing out, and the oracle labels the row by the
        /// rule of docs/math.md §9: with δ the origin's distance from the surface and θ the
        /// angle between the direction and the normal there, the origin's own crossing is
        /// the one nearest t = 0, within w = 4·(δ + 1e-11·(R + r))/(|cos θ|·|d|); the row is
        /// ambiguous if there is none, if a second crossing lies within w plus the
        /// ambiguity band (1e-8·(R + r)/(|cos θ|·|d|)), or if the range ends there;
        /// otherwise it is labelled over the rest of its range (a ray into the tube: hit
        /// if it leaves the tube in range). A bad value stops the run with the line
        /// number and the column.
        #[arg(long)]
        rays: PathBuf,
        /// Output CSV (default: stdout).
        #[arg(long)]
        out: Option<PathBuf>,
        /// `f64`: read the rays as f64 and intersect them in f64 (t_hit to f64 precision);
        /// `f32`: round each ray to f32 first, as a renderer's ray is. Default: f64, or
        /// f32 with `--exact f32`.
        #[arg(long, value_enum)]
        precision: Option<EvalPrecision>,
        /// The exact intersection behind t_hit: `f64` (the default) or `f32`, the
        /// certified f32 path, which adds the column `escalated` (1: f32 could not prove
        /// the answer, the f64 solver gave it) and takes f32 rays; `gpu`, the same on the
        /// GPU kernel (a binary built with `--features gpu`), plus a column `finished`
        /// (`device`: the adapter's f64 pass finished the escalated ray; `host`: the
        /// CPU did; empty: f32 proved it) and one column per GPU cull, gpu_<cull> (1
        /// keep, 0 reject: the kernel's own verdict).
        #[arg(long, value_enum, default_value_t = EvalExact::F64)]
        exact: EvalExact,
    },
}

/// `eval --exact`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
enum EvalExact {
    /// The f64 solver.
    F64,
    /// The certified f32 path, escalating to f64.
    F32,
    /// The certified f32 path on the GPU kernel (a binary built with `--features gpu`),
    /// escalating to f64 on the device where the adapter has f64, else on the host, and
    /// the kernel's culls (columns gpu_<cull>).
    Gpu,
}

/// `eval --precision`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
enum EvalPrecision {
    /// f64 rays end to end.
    F64,
    /// Rays rounded to f32 first.
    F32,
}

fn main() -> ExitCode {
    // Every flag takes a leading '-' (src/cli/whole.rs), so a negative value meets the
    // flag's own range check.
    let argv = check::expand_aliases(std::env::args_os().collect());
    if let Some(message) = time::old_spelling(&argv) {
        eprintln!("error: {message}");
        return ExitCode::from(2);
    }
    let matches = whole::negative_numbers(Cli::command()).get_matches_from(argv);
    let cli = Cli::from_arg_matches(&matches).unwrap_or_else(|e| e.exit());
    remove_temp_files_on_signals();
    let result = match cli.command {
        Command::Run {
            workload,
            out,
            threads,
            no_plots,
            culls,
        } => run::run(&workload, out, threads, no_plots, &culls),
        Command::Time(args) => time::run(args),
        Command::Count(args) => count::run(args),
        Command::Check(args) => check::run(args),
        Command::GpuInfo => gpu_info::run(),
        Command::Plot { file, out_dir } => plot::plot(&file, out_dir),
        Command::Render {
            scene,
            nu,
            out,
            size,
            tori,
            seed,
        } => render::render(&scene, nu, &out, size, tori, seed),
        Command::Intervals { runs } => compare::intervals(&runs),
        Command::Summarize { full, out } => summarize::summarize(&full, out.as_deref()),
        Command::Compare {
            old,
            new,
            threshold,
            only_changes,
            allow_missing,
            across_machines,
            count_threshold,
        } => compare::compare(
            &old,
            &new,
            &compare::CompareOptions {
                threshold,
                only_changes,
                allow_missing,
                across_machines,
                count_threshold,
            },
        ),
        Command::Eval {
            major,
            minor,
            axial,
            bore,
            phi_start,
            delta_phi,
            rays,
            out,
            precision,
            exact,
        } => {
            use torus_cull_lab::eval::Precision;
            let precision = match (precision, exact) {
                (None | Some(EvalPrecision::F64), EvalExact::F64) => Ok(Precision::F64),
                (Some(EvalPrecision::F32), EvalExact::F64) => Ok(Precision::F32),
                (None | Some(EvalPrecision::F32), EvalExact::F32) => Ok(Precision::CertifiedF32),
                (Some(EvalPrecision::F64), EvalExact::F32) => Err(
                    "--exact f32 takes f32 rays: drop --precision f64, or use --exact f64".into(),
                ),
                (None | Some(EvalPrecision::F32), EvalExact::Gpu) => Ok(Precision::CertifiedGpu),
                (Some(EvalPrecision::F64), EvalExact::Gpu) => Err(
                    "--exact gpu takes f32 rays: drop --precision f64, or use --exact f64".into(),
                ),
            };
            precision.and_then(|p| {
                let shape = ((major, minor, axial), (bore, phi_start, delta_phi));
                eval::eval(shape, p, &rays, out.as_deref())
            })
        }
    };
    match result {
        Ok(code) => code,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }
    }
}

use console::CliResult;

/// On SIGINT, SIGTERM or SIGHUP, delete the temp files of unfinished outputs, say so in
/// one line on stderr, then die of the signal as if there were no handler (so the caller
/// sees the usual status, 130 for Ctrl-C in a shell).
fn remove_temp_files_on_signals() {
    #[cfg(unix)]
    {
        use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
        // Without the handler an interrupt still stops the run; only the clean-up is lost.
        if let Ok(mut signals) = signal_hook::iterator::Signals::new([SIGINT, SIGTERM, SIGHUP]) {
            std::thread::spawn(move || {
                if let Some(signal) = signals.forever().next() {
                    torus_cull_lab::output::remove_pending();
                    // One line, so that a status of 128 + n is not the only trace.
                    eprintln!(
                        "torus-cull: interrupted by {}: stopped; no partial output was \
                         left (files finished before it are kept)",
                        signal_name(signal)
                    );
                    let _ = signal_hook::low_level::emulate_default_handler(signal);
                    std::process::exit(128 + signal);
                }
            });
        }
    }
}

/// The name of a signal the handler above catches.
#[cfg(unix)]
fn signal_name(signal: i32) -> &'static str {
    use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
    match signal {
        SIGINT => "SIGINT (Ctrl-C)",
        SIGTERM => "SIGTERM",
        SIGHUP => "SIGHUP",
        _ => "a signal",
    }
}
