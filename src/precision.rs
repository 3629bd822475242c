//! The precision × engine axis of the lab, named once: which arithmetic a path's exact
//! intersection runs in ([`Precision`]), where it runs ([`Engine`]) and how it takes its
//! rays ([`Mode`]), one point of the three a [`Path`].
//!
//! Every place that names a path says it through these: `eval`'s `--precision` and
//! `--exact` ([`crate::eval::Precision::exact`]), `time`'s subcommands and `--mode`
//! (`time ring --mode both`: scalar and batch; `time gpu`: the GPU engine, `--finish` its
//! f64 pass), the paired metrics ([`crate::paired::Metric::path`]) and the results'
//! fields, whose strings are these names: a record's `precision` is
//! [`Precision::name`] (`f64`, `f32`), its `device` [`Engine::name`] (`cpu`, `gpu`), a
//! timing's `mode` [`Mode::name`] (`scalar`, `batch`). The strings are the results
//! format's: they never change, so files written before this module read the same.
//!
//! The ground floor of the lab: it imports nothing.

/// The arithmetic of a path's exact intersection. The culls always see the line rounded
/// to f32; this is what answers the rays they keep.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Precision {
    /// The exact intersection in f64 (the lab's reference path, and what a record without
    /// a `precision` field means).
    F64,
    /// The certified f32 path: solved and proved in f32, the rays it cannot prove
    /// escalated to the f64 solver, so its answers are the f64 path's within its bound.
    F32,
}

impl Precision {
    /// Both, in the order tables list them.
    pub const ALL: [Precision; 2] = [Precision::F64, Precision::F32];

    /// The results' `precision` string: `f64` or `f32`.
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            Precision::F64 => "f64",
            Precision::F32 => "f32",
        }
    }
}

/// Where a path runs.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Engine {
    /// This CPU (what a record without a `device` field means).
    Cpu,
    /// A GPU adapter through the library's WGSL kernel (feature `gpu`).
    Gpu,
}

impl Engine {
    /// Both, in the order tables list them.
    pub const ALL: [Engine; 2] = [Engine::Cpu, Engine::Gpu];

    /// The results' `device` string: `cpu` or `gpu`.
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            Engine::Cpu => "cpu",
            Engine::Gpu => "gpu",
        }
    }
}

/// How a path takes its rays.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Mode {
    /// One ray at a time (what a record without a `mode` field means).
    Scalar,
    /// Batches: SIMD lanes and the wavefront on the CPU, a dispatch on the GPU.
    Batch,
}

impl Mode {
    /// The results' `mode` string: `scalar` or `batch`.
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            Mode::Scalar => "scalar",
            Mode::Batch => "batch",
        }
    }
}

/// One point of the axis: a path's precision, engine and mode.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Path {
    /// The exact intersection's arithmetic.
    pub precision: Precision,
    /// Where it runs.
    pub engine: Engine,
    /// How it takes its rays.
    pub mode: Mode,
}

impl Path {
    /// The CPU's f64 path, one ray at a time: `intersect`, `time ring`'s `total_ns`.
    pub const SCALAR_F64: Path = Path::cpu(Precision::F64, Mode::Scalar);
    /// The CPU's f64 wavefront: `time ring --mode both`'s `batch_total_ns`.
    pub const BATCH_F64: Path = Path::cpu(Precision::F64, Mode::Batch);
    /// The CPU's certified f32 path, one ray at a time: `intersect_f32`, `eval --exact
    /// f32`.
    pub const SCALAR_F32: Path = Path::cpu(Precision::F32, Mode::Scalar);
    /// The CPU's certified f32 wavefront: `batch_f32_total_ns`.
    pub const BATCH_F32: Path = Path::cpu(Precision::F32, Mode::Batch);
    /// The GPU kernel's certified f32 path: `time gpu`'s `gpu_kernel_ns`, `eval --exact
    /// gpu`.
    pub const GPU_F32: Path = Path {
        precision: Precision::F32,
        engine: Engine::Gpu,
        mode: Mode::Batch,
    };
    /// The GPU's f64 finish pass after the kernel: `time gpu --finish`.
    pub const GPU_F64: Path = Path {
        precision: Precision::F64,
        engine: Engine::Gpu,
        mode: Mode::Batch,
    };

    /// A path on the CPU.
    #[must_use]
    pub const fn cpu(precision: Precision, mode: Mode) -> Path {
        Path {
            precision,
            engine: Engine::Cpu,
            mode,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The names are the results format's strings, as files have always held them.
    #[test]
    fn the_names_are_the_results_strings() {
        let names: Vec<&str> = Precision::ALL.iter().map(|p| p.name()).collect();
        assert_eq!(names, ["f64", "f32"]);
        let names: Vec<&str> = Engine::ALL.iter().map(|e| e.name()).collect();
        assert_eq!(names, ["cpu", "gpu"]);
        assert_eq!(
            (Mode::Scalar.name(), Mode::Batch.name()),
            ("scalar", "batch")
        );
        assert_eq!(Path::GPU_F32.engine.name(), "gpu");
        assert_ne!(Path::SCALAR_F32, Path::BATCH_F32);
    }
}
