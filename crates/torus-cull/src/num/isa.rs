//! Which instruction set the batch code runs on, picked at run time.
//!
//! One binary carries every level: pulp compiles the generic lane code once per level
//! (`#[target_feature]` functions) and [`Dispatch`] calls the best one the CPU has, so the
//! same build runs, and passes its tests, on a machine without AVX-512 or on AArch64.
//! `TORUS_CULL_ISA` forces a lower level, so that AVX2 or the scalar fallback can be
//! measured and tested on an AVX-512 machine.

use crate::names::Named;
use std::fmt;

/// The environment variable that forces a dispatch level (`avx512`, `avx2`, `neon`,
/// `scalar`); unset or empty means the best the CPU has.
pub const ISA_ENV: &str = "TORUS_CULL_ISA";

/// An instruction-set level the batch code can run on.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Isa {
    /// One lane at a time, portable Rust: the fallback every machine has.
    Scalar,
    /// AArch64 Advanced SIMD: 4 f32 / 2 f64 lanes.
    Neon,
    /// x86-64-v3 (AVX2 + FMA): 8 f32 / 4 f64 lanes.
    Avx2,
    /// x86-64-v4 (AVX-512 F/BW/CD/DQ/VL): 16 f32 / 8 f64 lanes, bit-mask registers.
    Avx512,
}

/// The stable names, as in `meta.isa` and `TORUS_CULL_ISA`; every level, lowest first.
impl Named for Isa {
    const KIND: &'static str = "instruction set";
    const ALL: &'static [Isa] = &[Isa::Scalar, Isa::Neon, Isa::Avx2, Isa::Avx512];

    fn name(self) -> &'static str {
        match self {
            Isa::Scalar => "scalar",
            Isa::Neon => "neon",
            Isa::Avx2 => "avx2",
            Isa::Avx512 => "avx512",
        }
    }
}

impl Isa {
    /// The levels this CPU can run, lowest first (always starts with `scalar`).
    pub fn available() -> Vec<Isa> {
        Isa::ALL
            .iter()
            .copied()
            .filter(|&isa| Dispatch::forced(isa).is_ok())
            .collect()
    }
}

crate::named_display_and_from_str!(Isa);

/// A `TORUS_CULL_ISA` that names no level, or a level this CPU lacks.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum IsaError {
    /// Not a level name.
    Unknown(String),
    /// A real level, but not on this CPU (or not compiled for this architecture).
    Unavailable(Isa),
}

impl fmt::Display for IsaError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let names = Isa::allowed();
        let here: Vec<&str> = Isa::available().iter().map(|i| i.name()).collect();
        match self {
            IsaError::Unknown(s) => write!(
                f,
                "{ISA_ENV}={s:?} is not an instruction set (allowed: {}; this CPU: {})",
                names.join(", "),
                here.join(", ")
            ),
            IsaError::Unavailable(isa) => write!(
                f,
                "{ISA_ENV}={isa}: this CPU cannot run it (this CPU: {})",
                here.join(", ")
            ),
        }
    }
}

impl std::error::Error for IsaError {}

/// A dispatch level proven available: hands the batch kernels to pulp's implementation for
/// that level.
///
/// ```
/// use torus_cull::Named;
/// use torus_cull::batch::{Dispatch, Isa};
///
/// // The best level this CPU has: the last of the available ones, scalar always among them.
/// let best = Dispatch::best();
/// let here = Isa::available();
/// assert_eq!(here.first(), Some(&Isa::Scalar));
/// assert_eq!(here.last(), Some(&best.isa()));
///
/// // A lower level on request (to measure or test it), by value or by its stable name.
/// let scalar = Dispatch::forced("scalar".parse()?)?;
/// assert_eq!(scalar.isa(), Isa::Scalar);
/// assert_eq!(scalar.isa().name(), "scalar");
///
/// // A level this CPU cannot run is an error, never a silent fallback.
/// if cfg!(target_arch = "x86_64") {
///     let err = Dispatch::forced(Isa::Neon).unwrap_err();
///     assert!(err.to_string().contains("this CPU cannot run it"), "{err}");
/// }
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, Copy)]
pub struct Dispatch {
    arch: pulp::Arch,
    isa: Isa,
}

impl Dispatch {
    /// The best level this CPU has.
    pub fn best() -> Dispatch {
        let arch = pulp::Arch::new();
        Dispatch {
            isa: isa_of(arch),
            arch,
        }
    }

    /// Exactly `isa`, or an error if this CPU (or this build's architecture) lacks it.
    pub fn forced(isa: Isa) -> Result<Dispatch, IsaError> {
        let arch = arch_for(isa).ok_or(IsaError::Unavailable(isa))?;
        Ok(Dispatch { arch, isa })
    }

    /// The level `TORUS_CULL_ISA` asks for, or [`Dispatch::best`] when it is unset or
    /// empty; an unknown or unavailable name is an error that names the allowed values.
    pub fn from_env() -> Result<Dispatch, IsaError> {
        match std::env::var(ISA_ENV) {
            Ok(s) if !s.trim().is_empty() => {
                let isa = Isa::parse(s.trim()).map_err(|e| IsaError::Unknown(e.name().into()))?;
                Dispatch::forced(isa)
            }
            Ok(_) | Err(std::env::VarError::NotPresent) => Ok(Dispatch::best()),
            Err(std::env::VarError::NotUnicode(s)) => {
                Err(IsaError::Unknown(s.to_string_lossy().into_owned()))
            }
        }
    }

    /// The level in use.
    pub fn isa(&self) -> Isa {
        self.isa
    }

    /// Runs `op` with the SIMD token of this level.
    #[inline(always)]
    pub(crate) fn run<Op: pulp::WithSimd>(&self, op: Op) -> Op::Output {
        self.arch.dispatch(op)
    }
}

#[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
fn isa_of(arch: pulp::Arch) -> Isa {
    match arch {
        pulp::Arch::V4(_) => Isa::Avx512,
        pulp::Arch::V3(_) => Isa::Avx2,
        _ => Isa::Scalar,
    }
}

#[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
fn arch_for(isa: Isa) -> Option<pulp::Arch> {
    match isa {
        Isa::Scalar => Some(pulp::Arch::Scalar),
        Isa::Avx2 => pulp::x86::V3::try_new().map(pulp::Arch::V3),
        Isa::Avx512 => pulp::x86::V4::try_new().map(pulp::Arch::V4),
        Isa::Neon => None,
    }
}

#[cfg(target_arch = "aarch64")]
fn isa_of(arch: pulp::Arch) -> Isa {
    match arch {
        pulp::Arch::Neon(_) => Isa::Neon,
        _ => Isa::Scalar,
    }
}

#[cfg(target_arch = "aarch64")]
fn arch_for(isa: Isa) -> Option<pulp::Arch> {
    match isa {
        Isa::Scalar => Some(pulp::Arch::Scalar),
        Isa::Neon => pulp::aarch64::Neon::try_new().map(pulp::Arch::Neon),
        _ => None,
    }
}

#[cfg(not(any(target_arch = "x86", target_arch = "x86_64", target_arch = "aarch64")))]
fn isa_of(_: pulp::Arch) -> Isa {
    Isa::Scalar
}

#[cfg(not(any(target_arch = "x86", target_arch = "x86_64", target_arch = "aarch64")))]
fn arch_for(isa: Isa) -> Option<pulp::Arch> {
    (isa == Isa::Scalar).then(pulp::Arch::default)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip_and_bad_names_are_clear_errors() {
        for &isa in Isa::ALL {
            assert_eq!(isa.name().parse::<Isa>().unwrap(), isa);
        }
        let err = "sse9".parse::<Isa>().unwrap_err().to_string();
        assert!(err.contains("sse9") && err.contains("avx512"), "{err}");
    }

    #[test]
    fn scalar_is_always_available_and_best_is_the_highest() {
        let here = Isa::available();
        assert_eq!(here.first(), Some(&Isa::Scalar));
        assert_eq!(Dispatch::best().isa(), *here.last().unwrap());
        for isa in here {
            assert_eq!(Dispatch::forced(isa).unwrap().isa(), isa);
        }
    }
}
