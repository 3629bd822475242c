//! `torus-cull eval`: every cull and the oracle on a user's own rays.
//!
//! Input: CSV with the header `ox,oy,oz,dx,dy,dz` (a UTF-8 byte-order mark before it is
//! accepted), one ray per row, in the torus frame (centre at the origin, axis y); the
//! direction need not be unit length. After the six, optional columns ([`OPTIONAL_COLUMNS`]),
//! any subset in this order, named in the header:
//! - `t_min`, `t_max`: the ray's range (default `[0, +∞)`; `inf` is allowed for `t_max`),
//!   with `0 ≤ t_min ≤ t_max`, in the row's precision;
//! - `on_surface`: `0` or `1` (default 0). `1`: the origin is a surface point a renderer
//!   got from a hit, as printed in f32 or f64 ([`torus_cull::Ray::from_surface`]); it must
//!   lie within [`torus_cull::ON_SURFACE_REL`]·(R + r) of the surface. Its own crossing
//!   is excluded, by the library and by the oracle alike (the oracle's rule:
//!   [`crate::oracle::classify_from_surface`], docs/math.md §9).
//!
//! Output: CSV with the header [`output_header`]. `oracle` is for the ray over its range;
//! `t_hit` is the nearest t in range from the timed exact intersection, in units of the
//! given direction, empty when there is none; each cull column is `1` (keep) or `0`
//! (reject). The oracle's `hit` means the ray comes within the tube in its range (margin
//! < 0), so a literal ray that starts inside the tube is a hit even where its range ends
//! before it leaves it (no `t_hit`); an `on_surface` ray into the tube is a hit where it
//! leaves the tube in range.
//!
//! **Precision.** [`Precision::F64`] (the default of `torus-cull eval`) parses every value
//! as f64 and runs the oracle and the exact intersection on the f64 ray ([`torus_cull::DRay`]):
//! what a transport or CAD user's data needs. The culls see the line rounded to f32, as
//! they always do. [`Precision::F32`] rounds the row to an f32 [`Ray`] first, as a
//! renderer's ray is; `t_hit` is then the f32 answer. [`Precision::CertifiedF32`]
//! (`eval --exact f32`) rounds the row to an f32 ray too and takes `t_hit` from the
//! certified f32 path ([`torus_cull::intersect_f32`]), with a column `escalated` after `t_hit`:
//! 1 where f32 could not prove the answer and the f64 solver gave it.
//! [`Precision::CertifiedGpu`] (`eval --exact gpu`) is the same on the GPU kernel, with a
//! column `finished` after `escalated` (`device` where the adapter's f64 pass finished an
//! escalated ray, `host` where the CPU did, empty where f32 proved the answer), and adds
//! after the CPU's cull columns one column per GPU cull, `gpu_<cull>` ([`GPU_CULLS`]):
//! the kernel's own verdict for that cull (1 keep, 0 reject), on the same ray, so that any
//! CSV of rays checks the kernel's culls against the CPU's and the oracle.
//!
//! **The torus family** ([`Target`], `eval --axial b`). With `--axial b ≠ r`, or with
//! R ≤ r (a horn or spindle torus, whose surface is the outer "apple"), the rows are
//! answered for the member (R, a = r, b) of `torus_cull::family`: `t_hit` from
//! `Toroid::intersect`, the culls from `Toroid::kept_by` (a cull that does not accept the
//! member's shape keeps every ray), the oracle column from the family oracle
//! ([`crate::family_label`]; its margin `(E − 1)·min(a, b)`), and an `on_surface` origin
//! must lie within `ON_SURFACE_REL`·(R + max(a, b)) of the member's surface. `--exact f32` and
//! `--exact gpu` take the circular ring torus only and refuse any other member. The
//! circular ring torus (no `--axial`, or `--axial` = `--minor`, with R > r) answers
//! exactly as it always has.
//!
//! **The pipe bend** (`--bore`, `--phi-start`, `--delta-phi`; [`Target::with_bend`]): its
//! rows add after the cull columns the wedge's ([`bend_wedge_columns`]): `wedge`, the
//! segment's wedge alone, then `wedge+<cull>` for each cull but `none`, the forms `bend`
//! and `time bend` price; the header names them.
//!
//! **Errors stop the run.** A malformed row (wrong column count, a non-number, a zero or
//! non-finite direction, a negative or non-finite `t_min`, a NaN `t_max`, `t_min > t_max`,
//! an `on_surface` other than 0 or 1, an `on_surface` origin off the surface) ends it with
//! an error naming the input, the line number and the column, and the command exits
//! non-zero: no answer is ever silently wrong or skipped.

mod shape;
mod target;

use crate::number::{Echo, Num};
use crate::oracle::{OracleClass, OracleLabel};
use crate::precision::{self as axis, Engine, Path};
use glam::{DVec3, Vec3};
use std::fmt;
use std::io::{BufRead, Write};
use torus_cull::family::ToroidError;
use torus_cull::{DRay, Ray, Torus, TorusError};

pub use shape::{EvalShape, form_keeps, guard_columns};
pub use target::{BendFlags, Target, size};

/// The input header's six required columns.
pub const INPUT_HEADER: &str = "ox,oy,oz,dx,dy,dz";

/// The optional columns after the six: any subset, in this order, named in the header.
pub const OPTIONAL_COLUMNS: [&str; 3] = ["t_min", "t_max", "on_surface"];

/// The output header: `index,oracle,margin,t_hit`, then one column per cull, its stable
/// name in [`torus_cull::CullKind::TIMED`] order (the table of culls), so that a new row
/// of the table is a new column with no line to add here.
pub fn output_header() -> String {
    let mut header = String::from("index,oracle,margin,t_hit");
    for cull in torus_cull::CullKind::TIMED {
        header.push(',');
        header.push_str(torus_cull::Named::name(cull));
    }
    header
}

/// The columns a pipe bend's rows add after the culls' (`--bore`, `--phi-start`,
/// `--delta-phi`): `wedge`, the segment's wedge alone (`PipeBend::wedge_cull(NoCull)`),
/// then `wedge+<cull>`, each cull but `none` ([`torus_cull::CullKind::TIMED`] order) on the
/// outer torus behind the wedge: the forms `bend` and `time bend` price. 1 keeps, 0
/// rejects; a rejected ray is one the oracle calls a miss.
pub fn bend_wedge_columns() -> Vec<String> {
    torus_cull::CullKind::TIMED
        .iter()
        .map(|&c| match c {
            torus_cull::CullKind::NoCull => "wedge".to_string(),
            c => format!("wedge+{}", torus_cull::Named::name(c)),
        })
        .collect()
}

/// The GPU columns' culls, in [`torus_cull::CullKind::TIMED`] order: every cull with a batch form.
pub const GPU_CULLS: [torus_cull::batch::BatchCull; torus_cull::batch::BATCHED.len()] =
    torus_cull::batch::BATCHED;

/// The output header of `--exact gpu`: [`output_header`] with `escalated` and `finished`
/// after `t_hit` and one `gpu_<cull>` column per [`GPU_CULLS`] at the end. `finished` says
/// who answered an escalated ray: `device` (the adapter's f64 pass), `host` (the f64
/// path on the CPU), or empty where the f32 kernel proved the answer.
pub fn gpu_output_header() -> String {
    let mut header = output_header().replace(",t_hit,", ",t_hit,escalated,finished,");
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
    /// rays are answered by the f64 solver, on the device where the adapter has f64
    /// (`finished` = `device`) and on the host otherwise (`host`). The output adds the
    /// kernel's cull verdicts, `gpu_<cull>` ([`gpu_output_header`]).
    CertifiedGpu,
}

impl Precision {
    /// The precision the rows are read in: f64 for [`Precision::F64`], else f32 (the
    /// ray a renderer shoots).
    #[must_use]
    pub fn rays(self) -> axis::Precision {
        match self {
            Precision::F64 => axis::Precision::F64,
            _ => axis::Precision::F32,
        }
    }

    /// The path that answers `t_hit` on the precision × engine axis: the CPU's f64 path
    /// (on the f64 or the f32 ray), its certified f32 path, or the GPU kernel's.
    #[must_use]
    pub fn exact(self) -> Path {
        match self {
            Precision::F64 | Precision::F32 => Path::SCALAR_F64,
            Precision::CertifiedF32 => Path::SCALAR_F32,
            Precision::CertifiedGpu => Path::GPU_F32,
        }
    }
}

/// Why `eval` stopped.
#[derive(Debug)]
pub enum EvalError {
    /// The torus parameters are invalid.
    Torus(TorusError),
    /// The family member's parameters are invalid (`--axial`, or a horn or spindle).
    Toroid(ToroidError),
    /// The pipe bend's parameters are invalid (`--bore`, `--phi-start`, `--delta-phi`),
    /// the message naming the flag and the allowed range.
    Bend(String),
    /// The mode (`--exact f32`, `--exact gpu`) takes a circular ring torus only.
    Mode {
        /// The flag as typed.
        mode: &'static str,
        /// Why, naming the shape.
        message: String,
    },
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
            EvalError::Toroid(e) => write!(f, "{}", target::flag_error(e)),
            EvalError::Bend(e) => write!(f, "{e}"),
            EvalError::Mode { mode, message } => write!(f, "{mode}: {message}"),
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
    output: impl Write,
) -> Result<usize, EvalError> {
    eval_family_csv(
        (major_radius, minor_radius, None),
        precision,
        input,
        input_name,
        output,
    )
}

/// [`eval_csv`] for a member of the torus family: `(R, r, b)`, b the tube's semi-axis
/// along the axis (`None`: b = r). The circular ring torus answers as [`eval_csv`]'s;
/// any other member through [`Target::Family`].
pub fn eval_family_csv(
    (major_radius, minor_radius, axial): (f32, f32, Option<f32>),
    precision: Precision,
    input: impl BufRead,
    input_name: &str,
    output: impl Write,
) -> Result<usize, EvalError> {
    let target = Target::new(major_radius, minor_radius, axial)?;
    eval_target_csv(target, precision, input, input_name, output)
}

/// [`eval_csv`] for any [`Target`]: the ring torus, a family member or a pipe bend
/// ([`Target::with_bend`]).
pub fn eval_target_csv(
    target: Target,
    precision: Precision,
    input: impl BufRead,
    input_name: &str,
    output: impl Write,
) -> Result<usize, EvalError> {
    eval_shape_csv(&target, precision, input, input_name, output)
}

/// [`eval_csv`] for any [`EvalShape`]: a [`Target`] of the flags, or any lab shape
/// ([`crate::lab_shape::LabShape`]: a test's own shape answers its rows through the same
/// path, its cull columns from the interface's `kept_by`).
///
/// # Errors
///
/// A mode the shape refuses, a malformed row (named by input and line), an i/o error.
pub fn eval_shape_csv<T: EvalShape>(
    target: &T,
    precision: Precision,
    input: impl BufRead,
    input_name: &str,
    mut output: impl Write,
) -> Result<usize, EvalError> {
    target.check_mode(precision)?;
    let row_error = |line: usize, message: String| EvalError::Row {
        input: input_name.to_string(),
        line,
        message,
    };
    // A line that is not UTF-8 text is a row error, named by input and line, not a bare
    // i/o error.
    let not_text = |line: usize, e: std::io::Error| {
        if e.kind() == std::io::ErrorKind::InvalidData {
            row_error(
                line,
                format!("not UTF-8 text ({e}): the input must be a UTF-8 CSV file"),
            )
        } else {
            EvalError::Io(e)
        }
    };
    let mut lines = input.lines();
    let header = lines.next().transpose().map_err(|e| not_text(1, e))?;
    let columns = check_header(header, &row_error)?;
    let on_gpu = precision.exact().engine == Engine::Gpu;
    let (lines, mut gpu_answers) = if on_gpu {
        let (lines, answers) = read_for_gpu(target, &columns, lines, &row_error)?;
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
    // A bend's rows end with the wedge's columns (`--exact gpu` refused it above).
    let wedge: String = target
        .guard_columns()
        .iter()
        .map(|c| format!(",{c}"))
        .collect();
    if on_gpu {
        writeln!(output, "{}", gpu_output_header())?;
    } else if precision.exact().precision == axis::Precision::F32 {
        writeln!(
            output,
            "{}{wedge}",
            output_header().replace(",t_hit,", ",t_hit,escalated,")
        )?;
    } else {
        writeln!(output, "{}{wedge}", output_header())?;
    }
    let mut index = 0usize;
    for (i, line) in lines.enumerate() {
        let line_no = i + 2;
        let line = line.map_err(|e| not_text(line_no, e))?;
        if line.trim().is_empty() {
            continue;
        }
        let row = evaluate(target, &columns, precision, &line, &mut gpu_answers)
            .map_err(|m| row_error(line_no, m))?;
        write_row(&mut output, index, &row)?;
        index += 1;
    }
    output.flush()?;
    Ok(index)
}

/// The header row, without a spreadsheet's byte-order mark: [`INPUT_HEADER`], then any
/// of [`OPTIONAL_COLUMNS`] in their order; the optional columns it names.
fn check_header(
    header: Option<String>,
    row_error: &impl Fn(usize, String) -> EvalError,
) -> Result<Columns, EvalError> {
    let expected = || {
        format!(
            "'{INPUT_HEADER}', then any of {} in this order",
            OPTIONAL_COLUMNS.join(",")
        )
    };
    let Some(header) = header else {
        return Err(row_error(
            1,
            format!("empty input, expected the header {}", expected()),
        ));
    };
    // Spreadsheets often save CSV with a UTF-8 byte-order mark: it is not data.
    let bare = header.strip_prefix('\u{feff}').unwrap_or(&header);
    let bare = bare.trim().replace(' ', "");
    let wrong = || row_error(1, format!("header is '{header}', expected {}", expected()));
    let Some(rest) = bare.strip_prefix(INPUT_HEADER) else {
        return Err(wrong());
    };
    let mut columns = Columns::default();
    if !rest.is_empty() {
        let Some(rest) = rest.strip_prefix(',') else {
            return Err(wrong());
        };
        // Each name must come after the one before it in OPTIONAL_COLUMNS.
        let mut next = 0;
        for name in rest.split(',') {
            let Some(k) = OPTIONAL_COLUMNS[next..].iter().position(|c| *c == name) else {
                return Err(wrong());
            };
            next += k + 1;
            columns.present[next - 1] = true;
        }
    }
    Ok(columns)
}

/// Which of [`OPTIONAL_COLUMNS`] the input has.
#[derive(Debug, Clone, Copy, Default)]
struct Columns {
    present: [bool; 3],
}

impl Columns {
    /// The names of a row's columns, in order.
    fn names(&self) -> Vec<&'static str> {
        let six = ["ox", "oy", "oz", "dx", "dy", "dz"];
        let extra = OPTIONAL_COLUMNS
            .iter()
            .zip(self.present)
            .filter_map(|(name, p)| p.then_some(*name));
        six.into_iter().chain(extra).collect()
    }
}

/// The GPU answers every row at once: all rows are read first (a malformed row still
/// stops the run with its line number, before the adapter is opened).
fn read_for_gpu<T: EvalShape>(
    target: &T,
    columns: &Columns,
    lines: impl Iterator<Item = std::io::Result<String>>,
    row_error: &impl Fn(usize, String) -> EvalError,
) -> Result<(Vec<std::io::Result<String>>, Vec<GpuAnswer>), EvalError> {
    let lines: Vec<std::io::Result<String>> = lines.collect();
    let mut rays = Vec::new();
    for (i, line) in lines.iter().enumerate() {
        let Ok(line) = line else { break };
        if !line.trim().is_empty() {
            rays.push(parse_ray(target, columns, line).map_err(|m| row_error(i + 2, m))?);
        }
    }
    let answers = gpu_answers(target.gpu_torus()?, &rays)?;
    Ok((lines, answers))
}

/// The GPU's answer for one row: the certified intersection (finished in f64), and each
/// of [`GPU_CULLS`]'s verdict (true keeps).
struct GpuAnswer {
    hit: torus_cull::F32Hit,
    /// Who answered: `""` (the f32 kernel proved it), `"device"` or `"host"`.
    finished: &'static str,
    keeps: [bool; GPU_CULLS.len()],
}

/// One row's answers: the oracle's label, the exact `t`, whether f32 escalated, the
/// culls' verdicts, and the GPU's cull verdicts (`--exact gpu`).
struct Row {
    label: OracleLabel,
    t_hit: Option<String>,
    escalated: Option<bool>,
    /// `--exact gpu`: who finished the ray (`device`, `host`, or empty).
    finished: Option<&'static str>,
    /// [`torus_cull::CullKind::TIMED`]'s verdicts, in order (true keeps).
    keeps: Vec<bool>,
    gpu_keeps: Option<[bool; GPU_CULLS.len()]>,
}

/// Parses one row in the given precision and answers it.
fn evaluate<T: EvalShape>(
    target: &T,
    columns: &Columns,
    precision: Precision,
    line: &str,
    gpu_answers: &mut impl Iterator<Item = GpuAnswer>,
) -> Result<Row, String> {
    if precision.rays() == axis::Precision::F64 {
        let ray = parse_dray(target, columns, line)?;
        return Ok(Row {
            label: target.oracle(&ray)?,
            t_hit: target.t_hit_f64(&ray).map(|t| Num(t).to_string()),
            escalated: None,
            finished: None,
            keeps: target.keeps(&ray),
            gpu_keeps: None,
        });
    }
    let ray = parse_ray(target, columns, line)?;
    let (t, escalated, finished, gpu_keeps) = match precision {
        Precision::CertifiedF32 => {
            let (t, escalated) = target.certified_f32(&ray).map_err(|e| e.to_string())?;
            (t, Some(escalated), None, None)
        }
        Precision::CertifiedGpu => {
            let answer = gpu_answers.next().expect("one GPU answer per row");
            (
                answer.hit.hit.map(|hit| hit.t),
                Some(answer.hit.escalated),
                Some(answer.finished),
                Some(answer.keeps),
            )
        }
        _ => (target.t_hit_f32(&ray), None, None, None),
    };
    Ok(Row {
        label: target.oracle(&DRay::from(ray))?,
        t_hit: t.map(|t| Num::from(t).to_string()),
        escalated,
        finished,
        keeps: target.keeps(&ray),
        gpu_keeps,
    })
}

/// `index,oracle,margin,t_hit[,escalated][,finished],<one 0/1 per cull>[,<one 0/1 per GPU
/// cull>]`.
fn write_row(output: &mut impl Write, index: usize, row: &Row) -> std::io::Result<()> {
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
    if let Some(finished) = row.finished {
        write!(output, ",{finished}")?;
    }
    for keep in &row.keeps {
        write!(output, ",{}", u8::from(*keep))?;
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
        .intersect_finished_where(torus, GpuCull::NoCull, rays)
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
        .map(|((hit, finished), keeps)| GpuAnswer {
            hit,
            finished: finished.name(),
            keeps,
        })
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

/// A row's float: f32 or f64.
trait Float: std::str::FromStr + Copy + PartialOrd + fmt::Display {
    const ZERO: Self;
    const INFINITY: Self;
    /// The precision's name and its largest finite value (for messages).
    const NAME: &'static str;
    fn finite(self) -> bool;
    fn max() -> Num;
}

/// [`Float`] for each `type => to_num` given: `to_num` writes the type's largest finite
/// value as a [`Num`] (an f32 by its own shortest text, [`Num::from`]).
macro_rules! impl_float {
    ($($t:ident => $to_num:path),+) => {$(
        impl Float for $t {
            const ZERO: $t = 0.0;
            const INFINITY: $t = $t::INFINITY;
            const NAME: &'static str = stringify!($t);
            fn finite(self) -> bool {
                self.is_finite()
            }
            fn max() -> Num {
                $to_num($t::MAX)
            }
        }
    )+};
}

impl_float!(f32 => Num::from, f64 => Num);

/// One row's values in the float `T`.
struct Fields<'a, T> {
    /// ox, oy, oz, dx, dy, dz (each finite).
    six: [T; 6],
    /// The range: `0 ≤ t_min ≤ t_max`, t_min finite.
    t_min: T,
    t_max: T,
    on_surface: bool,
    /// The fields as typed (for messages).
    typed: Vec<&'a str>,
}

/// A row's values in the float type `T`, each checked with an error naming its column.
fn parse_row<'a, T: Float>(columns: &Columns, line: &'a str) -> Result<Fields<'a, T>, String> {
    let names = columns.names();
    let typed: Vec<&str> = line.split(',').map(str::trim).collect();
    if typed.len() != names.len() {
        return Err(format!(
            "expected {} columns ({}), found {}",
            names.len(),
            names.join(","),
            typed.len()
        ));
    }
    let mut fields = Fields {
        six: [T::ZERO; 6],
        t_min: T::ZERO,
        t_max: T::INFINITY,
        on_surface: false,
        typed: Vec::new(),
    };
    let number = |name: &str, field: &str| {
        field
            .parse::<T>()
            .map_err(|_| format!("column {name}: '{}' is not a number", Echo(field)))
    };
    for (k, (name, field)) in names.iter().zip(&typed).enumerate() {
        match *name {
            "t_min" => {
                let v = number(name, field)?;
                if !v.finite() {
                    return Err(format!(
                        "column t_min: {} is not finite (allowed: 0 ≤ t_min ≤ t_max)",
                        Echo(field)
                    ));
                }
                if v < T::ZERO {
                    return Err(format!(
                        "column t_min: {} is negative (allowed: 0 ≤ t_min ≤ t_max)",
                        Echo(field)
                    ));
                }
                fields.t_min = v;
            }
            "t_max" => {
                let v = number(name, field)?;
                // NaN compares with nothing: `partial_cmp` is None for it.
                if !matches!(
                    v.partial_cmp(&T::ZERO),
                    Some(std::cmp::Ordering::Greater | std::cmp::Ordering::Equal)
                ) {
                    return Err(format!(
                        "column t_max: {} is not a number ≥ 0 (allowed: t_min ≤ t_max ≤ inf)",
                        Echo(field)
                    ));
                }
                fields.t_max = v;
            }
            "on_surface" => {
                fields.on_surface = match *field {
                    "0" => false,
                    "1" => true,
                    _ => {
                        return Err(format!(
                            "column on_surface: '{}' is not 0 or 1",
                            Echo(field)
                        ));
                    }
                };
            }
            _ => {
                let v = number(name, field)?;
                if !v.finite() {
                    return Err(not_finite(name, field, (T::NAME, T::max())));
                }
                fields.six[k] = v;
            }
        }
    }
    if fields.t_min > fields.t_max {
        // As typed (`1e200`, not its 201 digits): both columns are there, as neither
        // default (0, inf) can make the range empty.
        let typed_of = |column: &str| {
            names
                .iter()
                .position(|n| *n == column)
                .map_or("?", |k| typed[k].trim())
        };
        return Err(format!(
            "columns t_min, t_max: t_min = {} > t_max = {} (allowed: 0 ≤ t_min ≤ t_max)",
            Echo(typed_of("t_min")),
            Echo(typed_of("t_max"))
        ));
    }
    fields.typed = typed;
    Ok(fields)
}

/// Why `field` (column `name`) did not give a finite number: it is `inf` or `NaN` as
/// typed, or a number beyond the precision's largest finite value `max` (`1e39` in f32,
/// which f64 would read).
fn not_finite(name: &str, field: &str, (precision, max): (&str, Num)) -> String {
    let word = field.trim_start_matches(['+', '-']).to_ascii_lowercase();
    if matches!(word.as_str(), "inf" | "infinity" | "nan") {
        return format!(
            "column {name}: {} is not finite (allowed: a finite number)",
            Echo(field)
        );
    }
    let hint = if precision == "f32" {
        "; the rays are read as f32 (--precision f32, --exact f32 or gpu): \
         --precision f64 --exact f64 reads them as f64"
    } else {
        ""
    };
    format!(
        "column {name}: {} is out of {precision} range (allowed: |value| <= {max}){hint}",
        Echo(field)
    )
}

/// How a refused ray is reported: the error, and the direction as typed.
fn as_typed(e: impl fmt::Display, fields: &[&str]) -> String {
    format!(
        "{e} (as typed: dx,dy,dz = {},{},{})",
        Echo(fields[3]),
        Echo(fields[4]),
        Echo(fields[5])
    )
}

fn parse_ray<T: EvalShape>(target: &T, columns: &Columns, line: &str) -> Result<Ray, String> {
    let f = parse_row::<f32>(columns, line)?;
    let v = f.six;
    let (o, d) = (Vec3::new(v[0], v[1], v[2]), Vec3::new(v[3], v[4], v[5]));
    if f.on_surface {
        target.check_on_surface(o.as_dvec3())?;
        Ray::from_surface_with_range(o, d, f.t_min, f.t_max)
    } else {
        Ray::with_range(o, d, f.t_min, f.t_max)
    }
    .map_err(|e| as_typed(e, &f.typed))
}

fn parse_dray<T: EvalShape>(target: &T, columns: &Columns, line: &str) -> Result<DRay, String> {
    let f = parse_row::<f64>(columns, line)?;
    let v = f.six;
    let (o, d) = (DVec3::new(v[0], v[1], v[2]), DVec3::new(v[3], v[4], v[5]));
    if f.on_surface {
        target.check_on_surface(o)?;
        DRay::from_surface_with_range(o, d, f.t_min, f.t_max)
    } else {
        DRay::with_range(o, d, f.t_min, f.t_max)
    }
    .map_err(|e| as_typed(e, &f.typed))
}

#[cfg(test)]
mod tests {
    use super::*;
    use torus_cull::{CullKind, Named};

    #[test]
    fn header_names_every_timed_cull_in_order() {
        let names: Vec<&str> = CullKind::TIMED.iter().map(|c| c.name()).collect();
        let header = output_header();
        let columns: Vec<&str> = header.split(',').collect();
        assert_eq!(columns[..4], ["index", "oracle", "margin", "t_hit"]);
        assert_eq!(columns[4..], names[..]);
        // The names are CSV columns: no comma, no repeat (tests/cli/data/*.expected pin
        // the whole line).
        let unique: std::collections::BTreeSet<&str> = columns.iter().copied().collect();
        assert_eq!(unique.len(), columns.len(), "{header}");
        let gpu: Vec<String> = GPU_CULLS
            .iter()
            .map(|c| format!("gpu_{}", c.name()))
            .collect();
        assert_eq!(
            gpu_output_header(),
            format!(
                "index,oracle,margin,t_hit,escalated,finished,{},{}",
                names.join(","),
                gpu.join(",")
            )
        );
        // A cull without a batch form has no GPU column.
        assert!(!gpu_output_header().contains("gpu_discriminant_f64"));
    }
}
