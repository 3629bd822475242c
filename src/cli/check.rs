//! `torus-cull check`: every cull and intersector of one shape against the oracle, class
//! by class, at one precision (`torus_cull_lab::check`), one file kind, one table, one
//! chart set. `torus-cull <shape>` (each name of `--shape`) is `check --shape <shape>`,
//! and `torus-cull f32-check` is `check --shape ring --precision f32` (its `--family
//! TEXT` is `--class TEXT`): the commands the check replaced, kept as aliases
//! ([`expand_aliases`]).

use super::CliResult;
use crate::console::out;
use crate::whole::Whole;
use std::ffi::OsString;
use std::path::PathBuf;
use std::process::ExitCode;
use torus_cull_lab::check::record::CheckFile;
use torus_cull_lab::check::shapes::{self, Options, SHAPES};

/// The most timing rounds per class: 1000 rounds of 20 000 rays are already hours.
const MAX_ROUNDS: u32 = 1000;

/// `torus-cull check`'s arguments.
#[derive(clap::Args)]
pub struct CheckArgs {
    /// The shape: `family` (the torus family: elliptical ring, horn and spindle tori),
    /// `bend` (pipe bends: a bore, a φ segment, end caps) or `ring` (the ring torus's f32
    /// paths on the adversarial ray families).
    #[arg(long, default_value = "family")]
    shape: String,
    /// `f64` (the culls and the exact intersection: family, bend) or `f32` (the
    /// certified f32 verdict, the whole f32 path and the shaders' plain f32 closed form:
    /// ring). Default: the shape's.
    #[arg(long)]
    precision: Option<String>,
    /// Rays per class, 1 ..= 1 000 000 (bend: 10 000 000).
    #[arg(long, default_value_t = Whole(20_000))]
    rays: Whole,
    /// The seed every class draws its rays from (default: the shape's, 20261127 family,
    /// 20261128 bend, 20261121 ring).
    #[arg(long)]
    seed: Option<Whole>,
    /// Only the classes whose label contains this text (e.g. `spawned`, `horn`,
    /// `dphi=90`); each draws the rays it draws in the whole check.
    #[arg(long)]
    class: Option<String>,
    /// Worker threads, 1 ..= 1024 (default: the available cores); the counts do not
    /// depend on it, and the timings run on one.
    #[arg(long)]
    threads: Option<Whole>,
    /// Results JSON (default: results/<short commit>[-dirty]-check-<shape>-<precision>.json).
    /// Its directory must exist.
    #[arg(long)]
    out: Option<PathBuf>,
    /// Skip the SVG charts, otherwise written next to the JSON as `<stem>-*.svg`.
    #[arg(long)]
    no_plots: bool,
    /// bend: ν = R/r_max of the classes, comma-separated (each 1 < ν <= 1000; with a bore
    /// ratio > 0, ν <= 1000·ratio; default 4).
    #[arg(long, value_delimiter = ',')]
    nu: Vec<f64>,
    /// bend: the segments Δφ in radians, comma-separated (each 0 < Δφ <= 2π; default 2π,
    /// π, π/2, π/6).
    #[arg(long = "delta-phi", value_delimiter = ',', allow_hyphen_values = true)]
    delta_phi: Vec<f64>,
    /// bend: r_min/r_max of the classes, comma-separated (each 0, or ν/1000 <= ratio <= 1
    /// − 10⁻⁷·(ν + 1); default 0, 0.5, 0.9).
    #[arg(long = "bore-ratio", value_delimiter = ',', allow_hyphen_values = true)]
    bore_ratio: Vec<f64>,
    /// bend: a workload file (or `quick`/`default`) whose `bend` key names the classes and
    /// the rays per class, its `seed` the seed: instead of --nu, --delta-phi,
    /// --bore-ratio, --rays and --seed.
    #[arg(long, conflicts_with_all = ["nu", "delta_phi", "bore_ratio", "rays", "seed"])]
    workload: Option<PathBuf>,
    /// ring (f32): timing rounds per class, 0 ..= 1000 (default 5; 0: no timings).
    #[arg(long)]
    rounds: Option<Whole>,
}

/// The command line with the aliases spelled out: `torus-cull <shape> …` as `torus-cull
/// check --shape <shape> …`, and `torus-cull f32-check …` as `torus-cull check --shape
/// ring --precision f32 …` with its `--family` as `--class`.
pub fn expand_aliases(args: Vec<OsString>) -> Vec<OsString> {
    let Some(first) = args.get(1).and_then(|a| a.to_str()) else {
        return args;
    };
    let (head, tail) = args.split_at(2);
    let mut out: Vec<OsString> = head[..1].to_vec();
    if SHAPES.iter().any(|(s, _)| *s == first) {
        out.extend(["check", "--shape", first].map(OsString::from));
        out.extend_from_slice(tail);
    } else if first == "f32-check" {
        let spelled = ["check", "--shape", "ring", "--precision", "f32"];
        out.extend(spelled.map(OsString::from));
        out.extend(tail.iter().map(|a| match a.to_str() {
            Some("--family") => OsString::from("--class"),
            Some(s) if s.starts_with("--family=") => {
                OsString::from(s.replacen("--family=", "--class=", 1))
            }
            _ => a.clone(),
        }));
    } else {
        return args;
    }
    out
}

/// Runs `check`. Exit 1 when a cull rejected a hit of the oracle, or one of our
/// intersectors missed, invented or misplaced a hit.
pub fn run(args: CheckArgs) -> CliResult {
    let rounds = args
        .rounds
        .map(|r| r.within("--rounds", (0, MAX_ROUNDS), ""))
        .transpose()?;
    let options = Options {
        shape: args.shape.clone(),
        precision: args.precision.clone(),
        nu: args.nu.clone(),
        delta_phi: args.delta_phi.clone(),
        bore_ratio: args.bore_ratio.clone(),
        workload: args.workload.clone(),
        rounds,
    };
    let built = shapes::build(&options)?;
    let shape = built.shape.as_ref();
    let about = shape.about();
    let (rays, seed) = match built.rays_seed {
        Some((rays, seed)) => (i128::try_from(rays).map_or(Whole(i128::MAX), Whole), seed),
        None => {
            let seed = args.seed.unwrap_or(Whole(i128::from(built.default_seed)));
            (args.rays, seed.seed("--seed")?)
        }
    };
    let rays = super::plot::check_rays(rays, built.max_rays)?;
    let threads = super::threads::pick(args.threads)?;
    let labels = shape.labels();
    let selected: Vec<usize> = match &args.class {
        None => (0..labels.len()).collect(),
        Some(part) => {
            let kept: Vec<usize> = (0..labels.len())
                .filter(|&i| labels[i].contains(part.as_str()))
                .collect();
            if kept.is_empty() {
                return Err(format!(
                    "--class {part}: no class of --shape {} has it in its label (e.g. {})",
                    about.name,
                    labels.first().map_or("", String::as_str)
                )
                .into());
            }
            kept
        }
    };
    // Before the work, not after it.
    let suffix = format!("-check-{}-{}", about.name, about.precision);
    let path = super::plot::check_file_out(args.out, &suffix, args.no_plots)?;
    let jobs = selected.len() * shape.jobs(rays);
    let heartbeat = crate::console::Heartbeat::new(
        format!(
            "check {} {}: {} classes x {rays} rays",
            about.name,
            about.precision,
            selected.len()
        ),
        "jobs",
    );
    heartbeat.update(0, jobs as u64);
    let checked =
        torus_cull_lab::check::check(shape, &selected, (rays, seed), threads, &|d, a| {
            heartbeat.update(d as u64, a as u64);
        })?;
    out!("{}", torus_cull_lab::check::table::table(&checked.records))?;
    for (class, why) in &checked.disagreements {
        eprintln!("disagreement in {class}:\n{why}\n");
    }
    let failed: Vec<String> = checked
        .records
        .iter()
        .filter(|r| r.failed())
        .map(|r| r.label.clone())
        .collect();
    let file = CheckFile::new(shape, checked.records, rays, seed);
    super::plot::write_check_file(&path, &file)?;
    if !args.no_plots {
        super::plot::write_charts(&path, |dir, stem| {
            torus_cull_lab::plot::check::plot_check(&file, dir, stem)
        })?;
    }
    if !failed.is_empty() {
        eprintln!(
            "error: a false reject, or a missed, invented or misplaced hit of ours, in: {}",
            failed.join(", ")
        );
        return Ok(ExitCode::from(1));
    }
    Ok(ExitCode::SUCCESS)
}
