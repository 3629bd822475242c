//! `torus-cull eval`: every cull and the oracle on the user's rays, CSV in and out.

use super::CliResult;
use std::fs::File;
use std::io::{BufReader, BufWriter, Write};
use std::process::ExitCode;

/// Runs `eval`.
pub fn eval(
    ((major, minor, axial), bend): ((f32, f32, Option<f32>), torus_cull_lab::eval::BendFlags),
    precision: torus_cull_lab::eval::Precision,
    rays: &std::path::Path,
    out: Option<&std::path::Path>,
) -> CliResult {
    // The shape first: a bad flag is reported before any file is opened.
    let target = torus_cull_lab::eval::Target::with_bend(major, minor, axial, bend)?;
    let name = rays.display().to_string();
    if let Some(out) = out {
        if name != "-" {
            torus_cull_lab::output::check_not_input(("--out", out), &[("--rays", rays)])?;
        }
    }
    let input: Box<dyn std::io::BufRead> = if name == "-" {
        Box::new(std::io::stdin().lock())
    } else {
        let file = File::open(rays).map_err(|e| format!("--rays {name}: {e}"))?;
        if file.metadata().is_ok_and(|m| m.is_dir()) {
            return Err(format!("--rays {name}: is a directory (expected a CSV file)").into());
        }
        Box::new(BufReader::new(file))
    };
    let result: Result<usize, Box<dyn std::error::Error>> = match out {
        // Written through `output`: a regular file appears only when complete.
        Some(path) => {
            let named = |e: std::io::Error| format!("--out {}: {e}", path.display());
            let mut file = torus_cull_lab::output::Output::create(path).map_err(named)?;
            let rows = torus_cull_lab::eval::eval_target_csv(
                target,
                precision,
                input,
                &name,
                BufWriter::new(Named(&mut file, format!("--out {}", path.display()))),
            );
            match rows {
                Ok(rows) => file.finish().map(|()| rows).map_err(|e| named(e).into()),
                Err(e) => Err(e.into()),
            }
        }
        None => torus_cull_lab::eval::eval_target_csv(
            target,
            precision,
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

/// Parses `--major`/`--minor`: a finite number whose magnitude is a normal f32,
/// `f32::MIN_POSITIVE <= |value| <= f32::MAX`, judged as typed, so that the error names
/// the value typed, not what f32 made of it (`1e300` is not `inf`, `1e-300` is not `0`).
/// `NaN` and `inf` are not radii at all. Zero and negative radii pass here and are
/// refused by the torus, which names both radii.
pub fn parse_radius(s: &str) -> Result<f32, String> {
    use torus_cull_lab::number::Num;
    let range = format!(
        "allowed: a finite number with {} <= |value| <= {}",
        Num::from(f32::MIN_POSITIVE),
        Num::from(f32::MAX)
    );
    let v: f64 = s
        .trim()
        .parse()
        .map_err(|_| format!("'{s}' is not a number ({range})"))?;
    if !v.is_finite() {
        return Err(format!("{s} is not a finite number ({range})"));
    }
    let f = v as f32;
    if !f.is_finite() {
        return Err(format!("{s} is too large for f32 ({range})"));
    }
    if v != 0.0 && !f.is_normal() {
        return Err(format!("{s} is too small for f32 ({range})"));
    }
    Ok(f)
}

/// Whether `e` is a write to a pipe whose reader has gone.
fn is_broken_pipe(e: &(dyn std::error::Error + 'static)) -> bool {
    let io = match e.downcast_ref::<torus_cull_lab::eval::EvalError>() {
        Some(torus_cull_lab::eval::EvalError::Io(io)) => Some(io),
        _ => e.downcast_ref::<std::io::Error>(),
    };
    io.is_some_and(|io| io.kind() == std::io::ErrorKind::BrokenPipe)
}
