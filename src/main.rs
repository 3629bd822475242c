//! The `torus-cull` command line.
//!
//! Exit codes: 0 fine; 1 the measurement found a problem (a false reject in `run`, a
//! regression in `compare`); 2 the input or environment is bad (the message says which
//! file and field).

use clap::{Parser, Subcommand};
use indicatif::{ProgressBar, ProgressStyle};
use std::fs::File;
use std::io::{BufReader, BufWriter, Write};
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use torus_cull::results::{self, Results};
use torus_cull::workload::spec::Workload;
use torus_cull::{CullKind, measure, report};

mod cli {
    pub mod time;
}

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
    /// Run a workload: rejection counts for every case × ν × cull, tables, JSON and plots.
    Run {
        /// Workload file.
        #[arg(long, default_value = "workloads/default.json")]
        workload: PathBuf,
        /// Results JSON (default: results/<short commit>[-dirty].json).
        #[arg(long)]
        out: Option<PathBuf>,
        /// Worker threads (default: available cores).
        #[arg(long)]
        threads: Option<usize>,
        /// Skip the SVG plots.
        #[arg(long)]
        no_plots: bool,
        /// Culls to count, comma-separated (default: every timed cull). The
        /// paper-as-printed variants are accepted too, to watch the oracle catch them.
        #[arg(long, value_delimiter = ',')]
        culls: Vec<String>,
    },
    /// Time the culls against cychosz and none in paired, interleaved rounds (ratios with
    /// 95% intervals), in about 30 s.
    Time(cli::time::TimeArgs),
    /// Diff two results files; exits 1 on a regression (for CI gates).
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
    },
    /// Render a many-torus scene and its cull map (PNG).
    Render {
        /// Scene: ring_field, chain or facing_grid.
        #[arg(long)]
        scene: String,
        /// ν = R/r of the scene's tori (> 1).
        #[arg(long)]
        nu: f64,
        /// Output PNG; the cull map goes next to it as <stem>-cullmap.png.
        #[arg(long)]
        out: PathBuf,
        /// Image side in pixels.
        #[arg(long, default_value_t = 512)]
        size: usize,
        /// Tori in the scene.
        #[arg(long, default_value_t = 1000)]
        tori: usize,
        /// Scene seed.
        #[arg(long, default_value_t = 20261121)]
        seed: u64,
    },
    /// Write the SVG charts of a results file.
    Plot {
        /// Results JSON.
        file: PathBuf,
        /// Where to write the SVGs (default: next to the file).
        #[arg(long)]
        out_dir: Option<PathBuf>,
    },
    /// Check every cull and the oracle on your own rays (CSV in the torus frame).
    Eval {
        /// Major radius R.
        #[arg(long = "major")]
        major: f32,
        /// Minor radius r (R > r > 0).
        #[arg(long = "minor")]
        minor: f32,
        /// Input CSV with header ox,oy,oz,dx,dy,dz (`-` for stdin).
        #[arg(long)]
        rays: PathBuf,
        /// Output CSV (default: stdout).
        #[arg(long)]
        out: Option<PathBuf>,
    },
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    remove_temp_files_on_signals();
    let result = match cli.command {
        Command::Run {
            workload,
            out,
            threads,
            no_plots,
            culls,
        } => run(&workload, out, threads, no_plots, &culls),
        Command::Time(args) => cli::time::run(args),
        Command::Plot { file, out_dir } => plot(&file, out_dir),
        Command::Render {
            scene,
            nu,
            out,
            size,
            tori,
            seed,
        } => render(&scene, nu, &out, size, tori, seed),
        Command::Compare {
            old,
            new,
            threshold,
            only_changes,
        } => compare(&old, &new, threshold, only_changes),
        Command::Eval {
            major,
            minor,
            rays,
            out,
        } => eval(major, minor, &rays, out.as_deref()),
    };
    match result {
        Ok(code) => code,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }
    }
}

type CliResult = Result<ExitCode, Box<dyn std::error::Error>>;

/// On SIGINT, SIGTERM or SIGHUP, delete the temp files of unfinished outputs, then die of
/// the signal as if there were no handler (so the caller sees the usual status).
fn remove_temp_files_on_signals() {
    #[cfg(unix)]
    {
        use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
        // Without the handler an interrupt still stops the run; only the clean-up is lost.
        if let Ok(mut signals) = signal_hook::iterator::Signals::new([SIGINT, SIGTERM, SIGHUP]) {
            std::thread::spawn(move || {
                if let Some(signal) = signals.forever().next() {
                    torus_cull::output::remove_pending();
                    let _ = signal_hook::low_level::emulate_default_handler(signal);
                    std::process::exit(128 + signal);
                }
            });
        }
    }
}

fn eval(
    major: f32,
    minor: f32,
    rays: &std::path::Path,
    out: Option<&std::path::Path>,
) -> CliResult {
    let name = rays.display().to_string();
    let input: Box<dyn std::io::BufRead> = if name == "-" {
        Box::new(std::io::stdin().lock())
    } else {
        let file = File::open(rays).map_err(|e| format!("--rays {name}: {e}"))?;
        Box::new(BufReader::new(file))
    };
    let result: Result<usize, Box<dyn std::error::Error>> = match out {
        // Written through `output`: a regular file appears only when complete.
        Some(path) => {
            let named = |e: std::io::Error| format!("--out {}: {e}", path.display());
            let mut file = torus_cull::output::Output::create(path).map_err(named)?;
            let rows = torus_cull::eval::eval_csv(
                major,
                minor,
                input,
                &name,
                BufWriter::new(Named(&mut file, format!("--out {}", path.display()))),
            );
            match rows {
                Ok(rows) => file.finish().map(|()| rows).map_err(|e| named(e).into()),
                Err(e) => Err(e.into()),
            }
        }
        None => torus_cull::eval::eval_csv(
            major,
            minor,
            input,
            &name,
            BufWriter::new(Named(std::io::stdout().lock(), "stdout".into())),
        )
        .map_err(Into::into),
    };
    let rows = match result {
        Ok(rows) => rows,
        // The reader went away (`eval … | head`): stop quietly, as `cat` would.
        Err(e) if is_broken_pipe(e.as_ref()) => return Ok(ExitCode::SUCCESS),
        Err(e) => return Err(e),
    };
    eprintln!("evaluated {rows} rays");
    Ok(ExitCode::SUCCESS)
}

/// A writer whose errors name what it writes to (the kind is kept).
struct Named<W>(W, String);

impl<W: Write> Write for Named<W> {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        self.0.write(buf).map_err(|e| self.name(e))
    }
    fn flush(&mut self) -> std::io::Result<()> {
        self.0.flush().map_err(|e| self.name(e))
    }
}

impl<W> Named<W> {
    fn name(&self, e: std::io::Error) -> std::io::Error {
        std::io::Error::new(e.kind(), format!("{}: {e}", self.1))
    }
}

/// Whether `e` is a write to a pipe whose reader has gone.
fn is_broken_pipe(e: &(dyn std::error::Error + 'static)) -> bool {
    let io = match e.downcast_ref::<torus_cull::eval::EvalError>() {
        Some(torus_cull::eval::EvalError::Io(io)) => Some(io),
        _ => e.downcast_ref::<std::io::Error>(),
    };
    io.is_some_and(|io| io.kind() == std::io::ErrorKind::BrokenPipe)
}

fn run(
    workload: &Path,
    out: Option<PathBuf>,
    threads: Option<usize>,
    no_plots: bool,
    culls: &[String],
) -> CliResult {
    let workload = Workload::load(workload)?;
    let culls: Vec<CullKind> = if culls.is_empty() {
        CullKind::TIMED.to_vec()
    } else {
        culls
            .iter()
            .map(|c| {
                c.trim()
                    .parse::<CullKind>()
                    .map_err(|e| format!("--culls: {e}"))
            })
            .collect::<Result<_, _>>()?
    };
    let threads = threads
        .unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get()))
        .max(1);
    // `run` has its own default name, so that it never overwrites `cargo bench`'s file.
    let path = out.unwrap_or_else(|| {
        let suffix = match workload.name.as_str() {
            "default" => "-run".to_string(),
            other => format!("-{other}-run"),
        };
        results::default_path(Path::new("results"), &suffix)
    });
    // Before the sweep, not after it: an unwritable --out must not cost the whole run.
    torus_cull::output::check_writable(&path)
        .map_err(|e| format!("--out {}: {e}", path.display()))?;
    let units = measure::units(&workload).len() as u64;
    let bar = ProgressBar::new(units * workload.rays as u64).with_style(
        ProgressStyle::with_template("{msg} [{bar:40}] {pos}/{len} rays ({eta})")
            .expect("valid template")
            .progress_chars("=> "),
    );
    bar.set_message(format!("{}: {} case x nu", workload.name, units));
    let (records, false_rejects) =
        measure::rejection_sweep(&workload, &culls, threads, &|n| bar.inc(n))?;
    bar.finish_and_clear();
    let mut results = Results::new(&workload, "run");
    results.meta.sizes = Some(results::Sizes::rejection_only(workload.rays as u64));
    results.rejection = records;
    print!("{}", report::miss_capture_tables(&results));
    // The project's central claim, stated every time. Each ray is counted once, with the
    // first cull's records: every cull sees the same rays.
    let of_one_cull = || {
        results
            .rejection
            .iter()
            .filter(|r| r.cull == culls[0].name())
    };
    let rays: u64 = of_one_cull().map(|r| r.rays).sum();
    let ambiguous: u64 = of_one_cull().map(|r| r.ambiguous).sum();
    let rejected_hits: u64 = results.rejection.iter().map(|r| r.false_rejects).sum();
    println!(
        "{rejected_hits} false rejects in {rays} rays (each checked by {} culls; {ambiguous} \
         rays the oracle calls ambiguous are not counted)",
        culls.len()
    );
    results.save(&path)?;
    println!("wrote {}", path.display());
    if !no_plots {
        let dir = path
            .parent()
            .map_or_else(|| PathBuf::from("."), Path::to_path_buf);
        let stem = path
            .file_stem()
            .map_or("results".into(), |s| s.to_string_lossy());
        let written = torus_cull::plot::plot_results(&results, &dir, &stem)?;
        println!(
            "wrote {} plots to {}/{stem}-*.svg",
            written.len(),
            dir.display()
        );
    }
    if !false_rejects.is_empty() {
        for f in false_rejects.iter().take(20) {
            eprintln!(
                "FALSE REJECT: cull {} case {} nu {} ray #{} (workload seed {}, stream seed {:#x}): \
                 origin {} dir {} margin {:e}",
                f.cull,
                f.case,
                f.nu,
                f.index,
                workload.seed,
                f.stream_seed,
                f.ray.origin(),
                f.ray.dir(),
                f.margin
            );
        }
        eprintln!(
            "error: {} false rejects: a cull rejected rays the oracle calls hits",
            false_rejects.len()
        );
        return Ok(ExitCode::from(1));
    }
    Ok(ExitCode::SUCCESS)
}

fn plot(file: &Path, out_dir: Option<PathBuf>) -> CliResult {
    let results = Results::load(file)?;
    let dir = out_dir.unwrap_or_else(|| {
        file.parent()
            .map_or_else(|| PathBuf::from("."), Path::to_path_buf)
    });
    let stem = file
        .file_stem()
        .map_or("results".into(), |s| s.to_string_lossy());
    let written = torus_cull::plot::plot_results(&results, &dir, &stem)?;
    for p in &written {
        println!("wrote {}", p.display());
    }
    Ok(ExitCode::SUCCESS)
}

fn compare(old: &Path, new: &Path, threshold: f64, only_changes: bool) -> CliResult {
    if !(threshold.is_finite() && threshold >= 0.0) {
        return Err(
            format!("--threshold {threshold} is invalid (allowed: a percentage >= 0)").into(),
        );
    }
    let (a, b) = (Results::load(old)?, Results::load(new)?);
    torus_cull::compare::comparable(&a, &b)
        .map_err(|e| format!("{} vs {}: {e}", old.display(), new.display()))?;
    let report = torus_cull::compare::compare(&a, &b, threshold / 100.0);
    let name = |p: &Path| {
        p.file_stem()
            .map_or("?".into(), |s| s.to_string_lossy().into_owned())
    };
    print!(
        "{}",
        torus_cull::compare::render(&report, &name(old), &name(new), only_changes)
    );
    if report.rows.is_empty() {
        // A comparison of nothing must not pass a CI gate.
        return Err(format!(
            "{} and {} share no record: nothing was compared",
            old.display(),
            new.display()
        )
        .into());
    }
    Ok(if report.regressions() > 0 {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    })
}

fn render(scene: &str, nu: f64, out: &Path, size: usize, tori: usize, seed: u64) -> CliResult {
    let kind: torus_cull::scene::SceneKind = scene.parse().map_err(|e| format!("--scene: {e}"))?;
    if !(1..=8192).contains(&size) {
        return Err(format!("--size {size} is invalid (allowed: 1 ..= 8192)").into());
    }
    if !(1..=1_000_000).contains(&tori) {
        return Err(format!("--tori {tori} is invalid (allowed: 1 ..= 1000000)").into());
    }
    let scene =
        torus_cull::scene::Scene::build(kind, nu, tori, seed).map_err(|e| format!("--nu: {e}"))?;
    let image = torus_cull::render::render(&scene, size);
    let map_path = out.with_file_name(format!(
        "{}-cullmap.png",
        out.file_stem()
            .map_or("render".into(), |s| s.to_string_lossy())
    ));
    torus_cull::render::write_png(out, size, &image.shaded)?;
    torus_cull::render::write_png(&map_path, size, &image.cull_map)?;
    let c = image.counts;
    let total = (size * size) as f64;
    println!("wrote {} and {}", out.display(), map_path.display());
    for (name, n) in [
        ("hit", c.hit),
        ("reached the quartic and missed (skala)", c.quartic_missed),
        ("rejected only by skala", c.skala_only),
        ("rejected by cychosz", c.cychosz),
        ("entered no box", c.no_box),
    ] {
        println!("  {name:<40} {n:>8} ({:.1}%)", 100.0 * n as f64 / total);
    }
    Ok(ExitCode::SUCCESS)
}
