//! `torus-cull time`: paired, interleaved timing ratios, one subcommand per kind of
//! timing, each with its own flags and the shared ones ([`args::Common`]) flattened in:
//!
//! - `time ring` (and a bare `time`, as before): the culls on the ring torus, the
//!   workload's cases × ν, one ray at a time or, `--mode both`, in batch mode too;
//! - `time secondary`: the same on one diffuse bounce spawned from every hit;
//! - `time family`, `time bend`: the torus family's members, the pipe bends;
//! - `time bvh`: the culls at the leaves of the workload's BVH scenes;
//! - `time gpu`: the WGSL kernel, rays resident on the device (feature `gpu`).
//!
//! A flag a subcommand does not read is not one of its flags: clap refuses it. The old
//! mode flags (`time --family`, `--bend`, `--bvh`, `--secondary`, `--device`, `--finish`,
//! `--workgroup`) are refused by [`old_spelling`] with the new command's name.

mod args;
mod bvh;
mod common;
mod gpu_bvh;
mod gpu_submissions;
mod ring;
mod shapes;
mod workers;

use std::ffi::OsString;
use std::process::ExitCode;

/// `torus-cull time`'s arguments: a subcommand, or none for `time ring` with the ring's
/// flags.
#[derive(clap::Args)]
#[command(args_conflicts_with_subcommands = true)]
pub struct TimeArgs {
    #[command(subcommand)]
    command: Option<TimeCommand>,
    /// A bare `time`: `time ring`'s flags.
    #[command(flatten)]
    ring: args::RingArgs,
}

/// The kinds of timing.
#[derive(clap::Subcommand)]
enum TimeCommand {
    /// The culls on the ring torus against cychosz and none, on the workload's cases × ν
    /// (what a bare `time` runs): `total_ns` and `cull_ns`, with `--mode both` the batch
    /// mode's too; `--runs` runs, each in a worker process, for a between-run interval.
    Ring(args::RingArgs),
    /// As `ring`, on secondary rays: for each batch, one diffuse bounce (cosine-weighted)
    /// spawned from every hit with `Torus::spawn`, so every ray starts on the surface
    /// (`Ray::from_surface`); the records' case is `<case>_bounce`. With `--mode both`
    /// this pairs the certified f32 wavefront against the f64 one on the rays a path
    /// tracer sends after its primary rays.
    Secondary(args::RingArgs),
    /// The torus family (`torus_cull::family`, docs/family.md): on uniform rays, the
    /// exact intersection of elliptical tubes (ν = 4, b/a = 1/4 … 4), the horn and two
    /// spindles over the circular torus (R, a), and each cull's total over `cychosz`'s on
    /// each member (metric `family_total_ns`; default file
    /// `results/<commit>-family-time.json`).
    Family(args::ShapeArgs),
    /// Pipe bends (`torus_cull::bend`, docs/bend.md): on uniform rays at the outer torus's
    /// box, each cull and each cull with the segment's wedge against `cychosz` and
    /// against no cull, at Δφ = 2π … π/6 and r_min/r_max = 0, 0.5, 0.9 (metric
    /// `bend_total_ns`; default file `results/<commit>-bend-time.json`).
    Bend(args::ShapeArgs),
    /// Inside the BVH (the workload's `bvh` scenes; the scenes it lacks at ν = 4): each
    /// cull at the leaves over `none` and `cychosz`, per ray, for closest-hit camera
    /// rays, any-hit shadow rays, closest-hit diffuse bounce rays from the camera hits
    /// and batched leaves; metrics `bvh_closest_ns`, `bvh_anyhit_ns`, `bvh_bounce_ns`,
    /// `bvh_batched_ns`.
    Bvh(args::BvhArgs),
    /// The WGSL kernel (a binary built with `--features gpu`; cull and certified f32
    /// intersection) with the rays resident on the device, per case × ν and every cull
    /// with a GPU form: ns per ray from the device's timestamps, each cull's paired ratio
    /// to none and cychosz, and its time over a copy kernel's (the bandwidth floor);
    /// upload and read-back timed apart. Written as `ratio` (metric `gpu_kernel_ns`,
    /// device `gpu`) and `estimates`, with the adapter in `meta.device`. A software
    /// adapter (device type Cpu, e.g. Mesa's lavapipe) is timed too, but as a CPU proxy,
    /// never as GPU speed.
    Gpu(args::GpuArgs),
    /// The GPU BVH (a binary built with `--features gpu`): each GPU cull at the leaves
    /// over none, closest hit and any hit, with within- and between-run intervals, rays
    /// per second and the copy kernel over the same ray bytes (docs/gpu.md).
    GpuBvh(gpu_bvh::GpuBvhArgs),
    /// Every submission of the single-torus GPU kernel logged (a binary built with
    /// `--features gpu`): wall and device time per batch size and contender (the copy
    /// kernel and the culls), for the slow state at 2^20 rays (docs/gpu.md).
    GpuSubmissions(gpu_submissions::SubmissionsArgs),
}

/// Runs `torus-cull time`.
pub fn run(time: TimeArgs) -> Result<ExitCode, Box<dyn std::error::Error>> {
    match time.command {
        None => ring::run(&time.ring, false),
        Some(TimeCommand::Ring(args)) => ring::run(&args, false),
        Some(TimeCommand::Secondary(args)) => ring::run(&args, true),
        Some(TimeCommand::Family(args)) => shapes::run(&args, shapes::Shapes::Family),
        Some(TimeCommand::Bend(args)) => shapes::run(&args, shapes::Shapes::Bend),
        Some(TimeCommand::Bvh(args)) => bvh::run(&args),
        Some(TimeCommand::Gpu(args)) => {
            // Checked in any binary, the feature's or not: a bad value is named first.
            let workgroup =
                args.workgroup
                    .within("--workgroup", (32, 256), "; 32, 64, 128 or 256")?;
            gpu::run(&args, workgroup)
        }
        Some(TimeCommand::GpuBvh(args)) => gpu_bvh::run(&args),
        Some(TimeCommand::GpuSubmissions(args)) => gpu_submissions::run(&args),
    }
}

/// The subcommands' names, for [`old_spelling`].
const SUBCOMMANDS: [&str; 9] = [
    "ring",
    "secondary",
    "family",
    "bend",
    "bvh",
    "gpu",
    "gpu-bvh",
    "gpu-submissions",
    "help",
];

/// Where `argv` (the whole command line) is a bare `time` with one of the mode flags of
/// before the subcommands, the message that names the command it is now; `None`
/// otherwise. Words after a `--` are not flags.
pub fn old_spelling(argv: &[OsString]) -> Option<String> {
    let words: Vec<&str> = argv.iter().map(|a| a.to_str().unwrap_or("")).collect();
    if words.get(1) != Some(&"time") || words.get(2).is_some_and(|w| SUBCOMMANDS.contains(w)) {
        return None;
    }
    let mut i = 2;
    while i < words.len() && words[i] != "--" {
        let (flag, inline) = match words[i].split_once('=') {
            Some((flag, value)) => (flag, Some(value)),
            None => (words[i], None),
        };
        let value = inline.or_else(|| words.get(i + 1).copied()).unwrap_or("");
        let now = match flag {
            "--family" => Some("time family".to_string()),
            "--bend" => Some("time bend".into()),
            "--bvh" => Some("time bvh".into()),
            "--secondary" => Some("time secondary".into()),
            "--device" if value == "gpu" => Some("time gpu".into()),
            "--device" => Some("time ring (or a bare time: the CPU's timing)".into()),
            "--finish" => Some("time gpu --finish".into()),
            "--workgroup" => Some(format!("time gpu --workgroup {value}")),
            _ => None,
        };
        if let Some(now) = now {
            return Some(format!(
                "time {}: the kinds of timing are subcommands now: torus-cull {now} \
                 (its flags: torus-cull {} --help)",
                words[i],
                now.split(" (").next().unwrap_or(&now)
            ));
        }
        i += 1;
    }
    None
}

/// `torus-cull time gpu`.
#[cfg(feature = "gpu")]
mod gpu;

/// `torus-cull time gpu` in a binary built without the feature.
#[cfg(not(feature = "gpu"))]
mod gpu {
    use std::process::ExitCode;

    pub(super) fn run(
        _args: &super::args::GpuArgs,
        _workgroup: u32,
    ) -> Result<ExitCode, Box<dyn std::error::Error>> {
        Err("time gpu needs a binary built with the feature gpu: \
             cargo run --release --features gpu -- time gpu"
            .into())
    }
}

#[cfg(test)]
mod tests {
    use super::old_spelling;

    fn old(line: &str) -> Option<String> {
        let argv: Vec<std::ffi::OsString> = std::iter::once("torus-cull")
            .chain(line.split_whitespace())
            .map(Into::into)
            .collect();
        old_spelling(&argv)
    }

    #[test]
    fn the_old_mode_flags_name_their_subcommand() {
        for (line, now) in [
            ("time --family --seconds 9", "torus-cull time family"),
            ("time --workload quick --bend", "torus-cull time bend"),
            ("time --bvh", "torus-cull time bvh"),
            ("time --mode both --secondary", "torus-cull time secondary"),
            ("time --device gpu --finish", "torus-cull time gpu"),
            ("time --device=gpu", "torus-cull time gpu"),
            ("time --device cpu", "torus-cull time ring"),
            ("time --finish", "torus-cull time gpu --finish"),
            (
                "time --workgroup 128",
                "torus-cull time gpu --workgroup 128",
            ),
        ] {
            let message = old(line).unwrap_or_default();
            assert!(message.contains(now), "{line}: {message}");
        }
        for line in [
            "time",
            "time --seconds 3 --mode both",
            "time gpu --finish",
            "time ring --seconds 1",
            "run --family",
            "time -- --family",
        ] {
            assert_eq!(old(line), None, "{line}");
        }
    }
}
