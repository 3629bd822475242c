//! `torus-cull eval`: every cull and the oracle on a user's own rays.
//!
//! Input: CSV with the header `ox,oy,oz,dx,dy,dz` (a UTF-8 byte-order mark before it is
//! accepted), one ray per row, in the torus frame (centre at the origin, axis y); the
//! direction need not be unit length.
//! Output: CSV with the header [`OUTPUT_HEADER`]. `oracle` is for the ray t ≥ 0; `t_hit`
//! is the nearest t ≥ 0 from the timed exact intersection, in units of the given
//! direction, empty when there is none; each cull column is `1` (keep) or `0` (reject).
//!
//! **Precision.** [`Precision::F64`] (the default of `torus-cull eval`) parses every value
//! as f64 and runs the oracle and the exact intersection on the f64 ray ([`torus_cull::DRay`]):
//! what a transport or CAD user's data needs. The culls see the line rounded to f32, as
//! they always do. [`Precision::F32`] rounds the row to an f32 [`Ray`] first, as a
//! renderer's ray is; `t_hit` is then the f32 answer. [`Precision::CertifiedF32`]
//! (`eval --exact f32`) rounds the row to an f32 ray too and takes `t_hit` from the
//! certified f32 path ([`torus_cull::intersect_f32`]), with a column `escalated` after `t_hit`:
//! 1 where f32 could not prove the answer and the f64 solver gave it.
//! [`Precision::CertifiedGpu`] (`eval --exact gpu`) is the same on the GPU kernel, and adds
//! after the CPU's cull columns one column per GPU cull, `gpu_<cull>` ([`GPU_CULLS`]):
//! the kernel's own verdict for that cull (1 keep, 0 reject), on the same ray, so that any
//! CSV of rays checks the kernel's culls against the CPU's and the oracle.
//!
//! **Errors stop the run.** A malformed row (wrong column count, a non-number, a zero or
//! non-finite direction) ends it with an error naming the input and the line number, and
//! the command exits non-zero: no answer is ever silently wrong or skipped.

use crate::oracle::{OracleClass, OracleLabel, Query, classify};
use glam::{DVec3, Vec3};
use std::fmt;
use std::io::{BufRead, Write};
use torus_cull::{CullKind, DRay, LocalLine, Ray, Torus, TorusError, intersect, intersect_f32};

/// The input header.
pub const INPUT_HEADER: &str = "ox,oy,oz,dx,dy,dz";

/// The output header.
pub const OUTPUT_HEADER: &str = "index,oracle,margin,t_hit,none,sphere,aabb,cychosz,\
    thick_cylinder,skala,ellipsoid,quadric,discriminant,discriminant_f64";

/// The GPU columns' culls, in [`CullKind::TIMED`] order: every cull with a batch form.
pub const GPU_CULLS: [torus_cull::batch::BatchCull; 9] = torus_cull::batch::BATCHED;

/// The output header of `--exact gpu`: [`OUTPUT_HEADER`] with `escalated` after `t_hit`
/// and one `gpu_<cull>` column per [`GPU_CULLS`] at the end.
pub fn gpu_output_header() -> String {
    let mut header = OUTPUT_HEADER.replace(",t_hit,", ",t_hit,escalated,");
    for cull in GPU_CULLS {
        header.push_str(",gpu_");
        header.push_str(torus_cull::Named::name(cull));
    }
    header
}

/// How a row is read and intersected.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[non_exhaustive]
pub enum Precision {
    /// f64 rays (the oracle and the exact intersection in f64, `t_hit` in f64).
    #[default]
    F64,
    /// Each row rounded to an f32 ray first, as a renderer shoots it.
    F32,
    /// Each row rounded to an f32 ray, intersected by the certified f32 path; the output
    /// has the column `escalated` after `t_hit`.
    CertifiedF32,
    /// As [`Precision::CertifiedF32`], on the GPU kernel (`torus_cull::gpu`, feature `gpu`):
    /// every row is read first and the rays go to the adapter in one batch; escalated
    /// rays are answered by the f64 solver. The output adds the kernel's cull verdicts,
    /// `gpu_<cull>` ([`gpu_output_header`]).
    CertifiedGpu,
}

/// Why `eval` stopped.
#[derive(Debug)]
pub enum EvalError {
    /// The torus parameters are invalid.
    Torus(TorusError),
    /// A row could not be used.
    Row {
        /// The input's name (file path or `<stdin>`).
        input: String,
        /// 1-based line number in the input.
        line: usize,
        /// What is wrong.
        message: String,
    },
    /// Reading or writing failed.
    Io(std::io::Error),
    /// The GPU kernel could not run (`--exact gpu`): no adapter, or a binary built
    /// without the feature `gpu`.
    Gpu(String),
}

impl fmt::Display for EvalError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            EvalError::Torus(e) => write!(f, "--major/--minor: {e}"),
            EvalError::Row {
                input,
                line,
                message,
            } => write!(f, "{input}:{line}: {message}"),
            EvalError::Io(e) => write!(f, "i/o error: {e}"),
            EvalError::Gpu(e) => write!(f, "--exact gpu: {e}"),
        }
    }
}

impl std::error::Error for EvalError {}

impl From<std::io::Error> for EvalError {
    fn from(e: std::io::Error) -> EvalError {
        EvalError::Io(e)
    }
}

/// Evaluate every ray of `input` against the canonical torus (R, r); returns the row count.
pub fn eval_csv(
    major_radius: f32,
    minor_radius: f32,
    precision: Precision,
    input: impl BufRead,
    input_name: &str,
    mut output: impl Write,
) -> Result<usize, EvalError> {
    let torus = Torus::canonical(major_radius, minor_radius).map_err(EvalError::Torus)?;
    let row_error = |line: usize, message: String| EvalError::Row {
        input: input_name.to_string(),
        line,
        message,
    };
    let mut lines = input.lines();
    check_header(lines.next().transpose()?, &row_error)?;
    let (lines, mut gpu_answers) = if precision == Precision::CertifiedGpu {
        let (lines, answers) = read_for_gpu(&torus, lines, &row_error)?;
        (
            Box::new(lines.into_iter()) as Box<dyn Iterator<Item = std::io::Result<String>>>,
            answers.into_iter(),
        )
    } else {
        (
            Box::new(lines) as Box<dyn Iterator<Item = std::io::Result<String>>>,
            Vec::new().into_iter(),
        )
    };
    if precision == Precision::CertifiedGpu {
        writeln!(output, "{}", gpu_output_header())?;
    } else if precision == Precision::CertifiedF32 {
        writeln!(
            output,
            "{}",
            OUTPUT_HEADER.replace(",t_hit,", ",t_hit,escalated,")
        )?;
    } else {
        writeln!(output, "{OUTPUT_HEADER}")?;
    }
    let mut index = 0usize;
    for (i, line) in lines.enumerate() {
        let line_no = i + 2;
        let line = line?;
        if line.trim().is_empty() {
            continue;
        }
        let row = evaluate(&torus, precision, &line, &mut gpu_answers)
            .map_err(|m| row_error(line_no, m))?;
        write_row(&mut output, &torus, index, &row)?;
        index += 1;
    }
    output.flush()?;
    Ok(index)
}

/// The header row, without a spreadsheet's byte-order mark, must be [`INPUT_HEADER`].
fn check_header(
    header: Option<String>,
    row_error: &impl Fn(usize, String) -> EvalError,
) -> Result<(), EvalError> {
    let Some(header) = header else {
        return Err(row_error(
            1,
            format!("empty input, expected the header '{INPUT_HEADER}'"),
        ));
    };
    // Spreadsheets often save CSV with a UTF-8 byte-order mark: it is not data.
    let bare = header.strip_prefix('\u{feff}').unwrap_or(&header);
    if bare.trim().replace(' ', "") != INPUT_HEADER {
        return Err(row_error(
            1,
            format!("header is '{header}', expected '{INPUT_HEADER}'"),
        ));
    }
    Ok(())
}

/// The GPU answers every row at once: all rows are read first (a malformed row still
/// stops the run with its line number, before the adapter is opened).
fn read_for_gpu(
    torus: &Torus,
    lines: impl Iterator<Item = std::io::Result<String>>,
    row_error: &impl Fn(usize, String) -> EvalError,
) -> Result<(Vec<std::io::Result<String>>, Vec<GpuAnswer>), EvalError> {
    let lines: Vec<std::io::Result<String>> = lines.collect();
    let mut rays = Vec::new();
    for (i, line) in lines.iter().enumerate() {
        let Ok(line) = line else { break };
        if !line.trim().is_empty() {
            rays.push(parse_ray(line).map_err(|m| row_error(i + 2, m))?);
        }
    }
    let answers = gpu_answers(torus, &rays)?;
    Ok((lines, answers))
}

/// The GPU's answer for one row: the certified intersection (finished in f64), and each
/// of [`GPU_CULLS`]'s verdict (true keeps).
struct GpuAnswer {
    hit: torus_cull::F32Hit,
    keeps: [bool; GPU_CULLS.len()],
}

/// One row's answers: the oracle's label, the exact `t`, whether f32 escalated, the
/// line the culls see, and the GPU's cull verdicts (`--exact gpu`).
struct Row {
    label: OracleLabel,
    t_hit: Option<String>,
    escalated: Option<bool>,
    line: LocalLine,
    gpu_keeps: Option<[bool; GPU_CULLS.len()]>,
}

/// Parses one row in the given precision and answers it.
fn evaluate(
    torus: &Torus,
    precision: Precision,
    line: &str,
    gpu_answers: &mut impl Iterator<Item = GpuAnswer>,
) -> Result<Row, String> {
    if precision == Precision::F64 {
        let ray = parse_dray(line)?;
        return Ok(Row {
            label: Query::dray(torus, &ray).classify(),
            t_hit: intersect(torus, &ray).map(|hit| hit.t.to_string()),
            escalated: None,
            line: torus.dline_to_local(&ray),
            gpu_keeps: None,
        });
    }
    let ray = parse_ray(line)?;
    let (t, escalated, gpu_keeps) = match precision {
        Precision::CertifiedF32 => {
            let answer = intersect_f32(torus, &ray);
            (answer.hit.map(|hit| hit.t), Some(answer.escalated), None)
        }
        Precision::CertifiedGpu => {
            let answer = gpu_answers.next().expect("one GPU answer per row");
            (
                answer.hit.hit.map(|hit| hit.t),
                Some(answer.hit.escalated),
                Some(answer.keeps),
            )
        }
        _ => (intersect(torus, &ray).map(|hit| hit.t), None, None),
    };
    Ok(Row {
        label: classify(torus, &ray),
        t_hit: t.map(|t| t.to_string()),
        escalated,
        // The culls' own input: far origins go to the foot point, as in a renderer.
        line: torus.line_to_local(&ray),
        gpu_keeps,
    })
}

/// `index,oracle,margin,t_hit[,escalated],<one 0/1 per cull>[,<one 0/1 per GPU cull>]`.
fn write_row(
    output: &mut impl Write,
    torus: &Torus,
    index: usize,
    row: &Row,
) -> std::io::Result<()> {
    let oracle = match row.label.class {
        OracleClass::Hit => "hit",
        OracleClass::Miss => "miss",
        OracleClass::Ambiguous => "ambiguous",
    };
    write!(output, "{index},{oracle},{:e},", row.label.margin)?;
    if let Some(t) = &row.t_hit {
        write!(output, "{t}")?;
    }
    if let Some(escalated) = row.escalated {
        write!(output, ",{}", u8::from(escalated))?;
    }
    for cull in CullKind::TIMED {
        let keep = cull.keeps(torus.bounds(), row.line.origin, row.line.dir);
        write!(output, ",{}", u8::from(keep))?;
    }
    for keep in row.gpu_keeps.iter().flatten() {
        write!(output, ",{}", u8::from(*keep))?;
    }
    writeln!(output)
}

/// The certified f32 answers of the GPU kernel (no cull in front of the intersection:
/// `eval` reports the culls apart), escalated rays finished in f64, and each GPU cull's
/// verdict on every ray.
#[cfg(feature = "gpu")]
fn gpu_answers(torus: &Torus, rays: &[Ray]) -> Result<Vec<GpuAnswer>, EvalError> {
    use torus_cull::gpu::{GpuCull, GpuIntersector};
    let gpu_error = |e: torus_cull::gpu::GpuError| EvalError::Gpu(e.to_string());
    let gpu = GpuIntersector::new().map_err(gpu_error)?;
    let hits = gpu
        .intersect_finished(torus, GpuCull::None, rays)
        .map_err(gpu_error)?;
    let mut keeps = vec![[true; GPU_CULLS.len()]; rays.len()];
    for (k, cull) in GPU_CULLS.into_iter().enumerate() {
        let verdicts = gpu
            .cull_keeps(torus, GpuCull::from(cull), rays)
            .map_err(gpu_error)?;
        for (row, keep) in keeps.iter_mut().zip(verdicts) {
            row[k] = keep;
        }
    }
    Ok(hits
        .into_iter()
        .zip(keeps)
        .map(|(hit, keeps)| GpuAnswer { hit, keeps })
        .collect())
}

/// Without the feature `gpu` there is no kernel to ask.
#[cfg(not(feature = "gpu"))]
fn gpu_answers(_torus: &Torus, _rays: &[Ray]) -> Result<Vec<GpuAnswer>, EvalError> {
    Err(EvalError::Gpu(
        "this binary was built without the feature gpu (cargo build --release --features gpu)"
            .to_string(),
    ))
}

/// The six numbers of a row in the float type `T` (each finite), and the fields as typed
/// (for messages).
fn parse_row<T: std::str::FromStr + Copy + Default>(
    line: &str,
    is_finite: fn(T) -> bool,
) -> Result<([T; 6], Vec<&str>), String> {
    const NAMES: [&str; 6] = ["ox", "oy", "oz", "dx", "dy", "dz"];
    let fields: Vec<&str> = line.split(',').map(str::trim).collect();
    if fields.len() != NAMES.len() {
        return Err(format!(
            "expected 6 columns ({INPUT_HEADER}), found {}",
            fields.len()
        ));
    }
    let mut v = [T::default(); 6];
    for ((slot, field), name) in v.iter_mut().zip(&fields).zip(NAMES) {
        *slot = field
            .parse::<T>()
            .map_err(|_| format!("column {name}: '{field}' is not a number"))?;
        if !is_finite(*slot) {
            return Err(format!("column {name}: {field} is not finite"));
        }
    }
    Ok((v, fields))
}

/// How a refused direction is reported: the error, and the direction as typed.
fn as_typed(e: impl fmt::Display, fields: &[&str]) -> String {
    format!(
        "{e} (as typed: dx,dy,dz = {},{},{})",
        fields[3], fields[4], fields[5]
    )
}

fn parse_ray(line: &str) -> Result<Ray, String> {
    let (v, fields) = parse_row::<f32>(line, f32::is_finite)?;
    Ray::new(Vec3::new(v[0], v[1], v[2]), Vec3::new(v[3], v[4], v[5]))
        .map_err(|e| as_typed(e, &fields))
}

fn parse_dray(line: &str) -> Result<DRay, String> {
    let (v, fields) = parse_row::<f64>(line, f64::is_finite)?;
    DRay::new(DVec3::new(v[0], v[1], v[2]), DVec3::new(v[3], v[4], v[5]))
        .map_err(|e| as_typed(e, &fields))
}

#[cfg(test)]
mod tests {
    use super::*;
    use torus_cull::Named;

    #[test]
    fn header_names_every_timed_cull_in_order() {
        let names: Vec<&str> = CullKind::TIMED.iter().map(|c| c.name()).collect();
        assert_eq!(
            OUTPUT_HEADER,
            format!("index,oracle,margin,t_hit,{}", names.join(","))
        );
        let gpu: Vec<String> = GPU_CULLS
            .iter()
            .map(|c| format!("gpu_{}", c.name()))
            .collect();
        assert_eq!(
            gpu_output_header(),
            format!(
                "index,oracle,margin,t_hit,escalated,{},{}",
                names.join(","),
                gpu.join(",")
            )
        );
        assert!(
            gpu_output_header().ends_with(",gpu_skala,gpu_ellipsoid,gpu_quadric,gpu_discriminant")
        );
    }
}
