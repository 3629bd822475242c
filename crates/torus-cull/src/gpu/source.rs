//! The kernel's WGSL text: `wgsl/module/*.wgsl` (the intersection as functions a renderer
//! can include, [`wgsl_module`]) and `wgsl/kernel.wgsl` (the library's bindings and entry
//! point), concatenated in order,
//! behind a header of `const` lines generated from the Rust constants the CPU uses
//! ([`KernelConstants`]), so that the two cannot drift apart: the cube-root seed and the trisection fit of the f32 solver, the solver's
//! thresholds, the culls' margin [`crate::cull::SAFETY_REL`] and their thresholds, the
//! certificate's bracket, and the GPU's own error constants, which the host also uses
//! for the culls' margin ([`super::bounds`]). The header also names the module's result
//! codes, its cull codes ([`super::GpuCull::ALL`]'s order) and its escalation codes
//! ([`super::Escalation::KERNEL`]), from the Rust values the host decodes them with.
//!
//! Every f32 is written as a WGSL hexadecimal float literal (`0x1.8p-3f`), which is
//! exact, so the kernel's value is the Rust value to the bit; the decimal follows in a
//! comment.

use crate::certified::certificate::{BRACKET, U32};
use crate::cull::{AXIS_PARALLEL_H2, HORIZONTAL_DY, SAFETY_REL};
use crate::intersect::from_surface::OWN_ROOT_REACH;
use crate::intersect::reduce::CHORD_SLACK;
use crate::num::cube_root::CBRT_F32_SEED;
use crate::quartic::factor::{NEAR_DOUBLE, SIGN_SURE, TOUCH};
use crate::quartic::resolvent::{DISC_NEAR, POLISH_BELOW, SMALL_ROOT};
use crate::quartic::{EPS, trisect};
use std::fmt::Write;

use super::bounds::{LINE_ABS, LINE_ABS_DIST, LINE_REL};
use super::{CODE_ESCALATE, CODE_HIT, CODE_KEPT, CODE_MISS, Escalation, GpuCull};

/// The files of one WGSL text, in order: the text they make, concatenated as they are, and
/// each `(path under src/gpu, text)` (for the test of their `mirrors:` headers).
macro_rules! wgsl_files {
    ($($path:literal),+ $(,)?) => {
        (concat!($(include_str!($path)),+), &[$(($path, include_str!($path))),+])
    };
}

/// The module's files before the culls' (`wgsl/module/*.wgsl`, then the culls' shared
/// parts, `culls/shared.wgsl`), in the order of [`module_body`]: each the WGSL side of the
/// Rust modules its header's `mirrors:` lines name.
const MODULE_HEAD: (&str, &[(&str, &str)]) = wgsl_files!(
    "wgsl/module/api.wgsl",
    "wgsl/module/solver.wgsl",
    "wgsl/module/certificate.wgsl",
    "wgsl/module/culls/shared.wgsl",
);

/// The module's files after the culls' dispatch, in the order of [`module_body`].
const MODULE_TAIL: (&str, &[(&str, &str)]) =
    wgsl_files!("wgsl/module/trace.wgsl", "wgsl/module/surface.wgsl",);

/// `CULL_FILES` from the rows of the table of culls (`cull/table.rs`) that have a `gpu`
/// form: each row's file `wgsl/module/culls/<name>.wgsl`, which declares
/// `fn tc_<name>_keeps(b: TcBounds, q: vec3<f32>, dh: vec3<f32>) -> bool`.
macro_rules! cull_wgsl_files {
    ($(
        $kind:ident $name:literal $module:ident :: $ty:ident
        [$($lanes:ident $($gpu:ident)?)?] [$($shape:ident)*], $doc:literal;
    )*) => {
        /// Each GPU cull's WGSL file `(path under src/gpu, text)`, in [`GpuCull::ALL`]'s
        /// order (the table's).
        const CULL_FILES: &[(&str, &str)] = &[$($($((
            cull_wgsl_files!(@path $name $gpu),
            include_str!(cull_wgsl_files!(@path $name $gpu)),
        ),)?)?)*];
    };
    (@path $name:literal $gpu:ident) => { concat!("wgsl/module/culls/", $name, ".wgsl") };
}
crate::cull::table::cull_table!(cull_wgsl_files);

/// The kernel's cull dispatch `tc_cull_keeps`, generated from [`GpuCull::ALL`] (the table
/// of culls): a case per cull, `TORUS_CULL_<NAME>` (the header's codes) calling its
/// file's `tc_<name>_keeps`; an unknown code keeps the line (conservative).
fn cull_switch() -> String {
    let mut out = String::from(
        "// The cull `code` (GpuCull::ALL's order) on the scaled line: true keeps it. Generated\n\
         // from the table of culls (torus_cull::gpu::source); mirrors\n\
         // crate::cull::kernel::keeps_scalar (the dispatch).\n\
         fn tc_cull_keeps(code: u32, b: TcBounds, q: vec3<f32>, dh: vec3<f32>) -> bool {\n    \
         switch code {\n",
    );
    for cull in GpuCull::ALL {
        let name = cull.name();
        let code = name.to_uppercase();
        let _ = writeln!(
            out,
            "        case TORUS_CULL_{code}: {{\n            return tc_{name}_keeps(b, q, dh);\n        }}"
        );
    }
    out.push_str("        default: {\n            return true;\n        }\n    }\n}\n");
    out
}

/// The module's body (the intersection as WGSL functions, no bindings): the head files,
/// the generated `TcBounds` (`super::bounds::bounds_wgsl`), each GPU cull's file in the
/// table's order, the generated dispatch, the tail files.
/// Every shared number comes from the generated header.
fn module_body() -> String {
    let culls: String = CULL_FILES.iter().map(|&(_, text)| text).collect();
    format!(
        "{}{}\n{culls}\n{}\n{}",
        MODULE_HEAD.0,
        super::bounds::bounds_wgsl(),
        cull_switch(),
        MODULE_TAIL.0
    )
}

/// The library kernel's bindings and entry point (`wgsl/kernel.wgsl`), around
/// [`module_body`].
const KERNEL_BODY: &str = include_str!("wgsl/kernel.wgsl");

/// The GPU's factor on every rounding term in u = 2⁻²⁴: WGSL may or may not contract
/// `a·b + c` into an fma, division is good to 2.5 ulp, `sqrt` is not correctly rounded on
/// every device, and subnormals may flush.
pub(crate) const GPU_ROUNDING_FACTOR: f32 = 4.0;

/// "Finite" below this magnitude in the kernel (WGSL may assume no infinities or NaNs,
/// so the kernel never makes one on purpose and tests magnitudes instead).
pub(crate) const BIG: f32 = 1e30;

/// An absolute error the kernel's running error bounds add per operation: a result or an
/// operand that is subnormal may be flushed to 0 (2⁻¹⁰⁰, far above 2⁻¹²⁶).
pub(crate) const FLUSH_FLOOR: f32 = f32::from_bits((127 - 100) << 23);

/// A direction component below this (the direction unit) is parallel to its axis in the
/// kernel's `aabb` and `thick_cylinder`: over the |t| ≤ 4 where the torus can be, the line
/// moves by less than 4·10⁻²⁰ along the axis (the CPU divides by 0 instead, which WGSL
/// may not).
pub(crate) const PARALLEL_COMPONENT: f32 = 1e-20;

/// The range of the argument of the kernel's f32 cube root (Cardano's case); outside it
/// the solver escalates.
pub(crate) const CBRT_RANGE_F32: (f32, f32) = (1e-30, 1e30);

/// Every number the kernel takes from Rust, by name. [`KernelConstants::CPU`] holds the
/// values the CPU uses; a different value (a test's) gives a different kernel text.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KernelConstants {
    /// u = 2⁻²⁴, the unit roundoff of f32.
    pub unit_roundoff: f32,
    /// The GPU's factor on every rounding term.
    pub rounding_factor: f32,
    /// The culls' relative margin, [`crate::cull::SAFETY_REL`].
    pub safety_rel: f32,
    /// The kernel's "finite" bound.
    pub big: f32,
    /// The f64 solver's ε, as its f32 lanes splat it.
    pub f64_eps: f32,
    /// The resolvent's near-double threshold on |Δ|/scale.
    pub disc_near: f32,
    /// A factor's near-double threshold.
    pub near_double: f32,
    /// The resolvent's small-root threshold.
    pub small_root: f32,
    /// The certificate's bracket half-width, in units of R.
    pub bracket: f32,
    /// Kahan's seed for the f32 cube root (an integer added to the word over 3).
    pub cbrt_seed: u32,
    /// The cube root's argument range.
    pub cbrt_range: (f32, f32),
    /// The trisection's degree-5 fit, highest power first.
    pub trisect_fit: [f32; 6],
    /// The fit's centre, 1/√3.
    pub trisect_half_range: f32,
    /// The culls' "parallel to the axis" threshold on h²/|d|².
    pub axis_parallel_h2: f32,
    /// `quadric`'s "horizontal" threshold on |d_y|.
    pub horizontal_dy: f32,
    /// The kernel's line error: relative, per unit of |o − c|/R, constant.
    pub line_error: [f32; 3],
    /// The running error bounds' absolute floor per operation (flushed subnormals).
    pub flush_floor: f32,
    /// The kernel's "parallel to an axis" threshold on a unit direction's component.
    pub parallel_component: f32,
}

impl KernelConstants {
    /// The values the CPU uses (and the host's margin for the culls).
    pub const CPU: KernelConstants = KernelConstants {
        unit_roundoff: U32 as f32,
        rounding_factor: GPU_ROUNDING_FACTOR,
        safety_rel: SAFETY_REL,
        big: BIG,
        f64_eps: EPS as f32,
        disc_near: DISC_NEAR as f32,
        near_double: NEAR_DOUBLE as f32,
        small_root: SMALL_ROOT as f32,
        bracket: BRACKET as f32,
        cbrt_seed: CBRT_F32_SEED,
        cbrt_range: CBRT_RANGE_F32,
        trisect_fit: [
            trisect::FIT[0] as f32,
            trisect::FIT[1] as f32,
            trisect::FIT[2] as f32,
            trisect::FIT[3] as f32,
            trisect::FIT[4] as f32,
            trisect::FIT[5] as f32,
        ],
        trisect_half_range: trisect::HALF_RANGE as f32,
        axis_parallel_h2: AXIS_PARALLEL_H2,
        horizontal_dy: HORIZONTAL_DY,
        line_error: [LINE_REL, LINE_ABS_DIST, LINE_ABS],
        flush_floor: FLUSH_FLOOR,
        parallel_component: PARALLEL_COMPONENT,
    };

    /// The WGSL `const` declarations, one a line.
    pub fn header(&self) -> String {
        let mut floats: Vec<(String, f32)> = vec![
            ("U".into(), self.unit_roundoff),
            ("G".into(), self.rounding_factor),
            ("SAFETY_REL".into(), self.safety_rel),
            ("BIG".into(), self.big),
            ("F64_EPS".into(), self.f64_eps),
            ("DISC_NEAR".into(), self.disc_near),
            ("NEAR_DOUBLE".into(), self.near_double),
            ("SMALL_ROOT".into(), self.small_root),
            ("BRACKET".into(), self.bracket),
            ("CBRT_LOW".into(), self.cbrt_range.0),
            ("CBRT_HIGH".into(), self.cbrt_range.1),
            ("TRISECT_HALF_RANGE".into(), self.trisect_half_range),
            ("AXIS_PARALLEL_H2".into(), self.axis_parallel_h2),
            ("HORIZONTAL_DY".into(), self.horizontal_dy),
            ("LINE_REL".into(), self.line_error[0]),
            ("LINE_ABS_DIST".into(), self.line_error[1]),
            ("LINE_ABS".into(), self.line_error[2]),
            ("FLUSH_FLOOR".into(), self.flush_floor),
            ("PARALLEL_COMPONENT".into(), self.parallel_component),
        ];
        for (i, c) in self.trisect_fit.iter().enumerate() {
            floats.push((format!("TRISECT_FIT_{i}"), *c));
        }
        let mut out = String::from(
            "// Generated from the Rust constants (torus_cull::gpu::KernelConstants::CPU) when\n\
             // the pipeline is built: exact hexadecimal floats, the decimal in the comment.\n",
        );
        for (name, value) in floats {
            let _ = writeln!(
                out,
                "const TC_{name}: f32 = {}; // {value:e}",
                hex_f32(value)
            );
        }
        let _ = writeln!(out, "const TC_CBRT_SEED: u32 = {}u;", self.cbrt_seed);
        out.push_str(&codes());
        out
    }

    /// The module's WGSL text ([`wgsl_module`]) with these constants.
    pub fn module(&self) -> String {
        format!("{}\n{}", self.header(), module_body())
    }

    /// The kernel's full WGSL text: the module ([`KernelConstants::module`]) and the
    /// kernel's bindings and entry point.
    pub fn source(&self) -> String {
        format!("{}\n{KERNEL_BODY}", self.module())
    }
}

/// The f64 finish module's files (`wgsl/finish_module/*.wgsl`), in the order of
/// [`FINISH_MODULE_BODY`].
const FINISH_MODULE_FILES: (&str, &[(&str, &str)]) = wgsl_files!(
    "wgsl/finish_module/api.wgsl",
    "wgsl/finish_module/solver.wgsl",
    "wgsl/finish_module/surface.wgsl",
    "wgsl/finish_module/intersect.wgsl",
);

/// The f64 finish as WGSL functions (`wgsl/finish_module/*.wgsl`, no bindings): the CPU's
/// f64 method for one ray; every threshold from [`FinishConstants::header`].
const FINISH_MODULE_BODY: &str = FINISH_MODULE_FILES.0;

/// The library's f64 finish pass's bindings and entry point `finish_main`
/// (`wgsl/finish.wgsl`), around [`FINISH_MODULE_BODY`].
const FINISH_BODY: &str = include_str!("wgsl/finish.wgsl");

/// Every number the device's f64 finish (`gpu/finish.rs`) takes from Rust, by name:
/// the f64 solver's thresholds and fits, as the CPU's [`crate::intersect()`] uses them.
/// [`FinishConstants::CPU`] holds those values; a different value (a test's) gives a
/// different pass.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FinishConstants {
    /// ε of f64 (the solver's rounding unit).
    pub eps: f64,
    /// A factor's near-double threshold ([`crate::quartic`]'s `NEAR_DOUBLE`).
    pub near_double: f64,
    /// The resolvent's near-double threshold on |Δ|/scale.
    pub disc_near: f64,
    /// The resolvent's small-root threshold.
    pub small_root: f64,
    /// Below this |Δ|/scale the resolvent's closed form is Newton-polished.
    pub polish_below: f64,
    /// The bounding-sphere chord test's relative slack.
    pub chord_slack: f64,
    /// The trisection's degree-5 fit, highest power first.
    pub trisect_fit: [f64; 6],
    /// The fit's centre, 1/√3.
    pub trisect_half_range: f64,
    /// Kahan's seed for the f32 cube root that seeds the f64 one.
    pub cbrt_seed: u32,
    /// The f32 seed's argument range.
    pub cbrt_range: (f64, f64),
    /// How far from `u₀` (units of R) a ray from a surface point may find its origin's
    /// own root (`intersect/from_surface.rs`).
    pub own_root_reach: f64,
}

impl FinishConstants {
    /// The values the CPU's f64 path uses.
    pub const CPU: FinishConstants = FinishConstants {
        eps: EPS,
        near_double: NEAR_DOUBLE,
        disc_near: DISC_NEAR,
        small_root: SMALL_ROOT,
        polish_below: POLISH_BELOW,
        chord_slack: CHORD_SLACK,
        trisect_fit: trisect::FIT,
        trisect_half_range: trisect::HALF_RANGE,
        cbrt_seed: CBRT_F32_SEED,
        cbrt_range: (CBRT_RANGE_F32.0 as f64, CBRT_RANGE_F32.1 as f64),
        own_root_reach: OWN_ROOT_REACH,
    };

    /// The pass's WGSL `const` declarations, one a line (f64 literals written in Rust's
    /// shortest round-trip decimal, so the WGSL value is the Rust value to the bit; the
    /// CPU's products of constants, such as `8.0 * EPS` and `1.0 / 3.0`, computed here in
    /// Rust as the CPU computes them).
    pub fn header(&self) -> String {
        let mut floats: Vec<(String, f64)> = vec![
            ("FIN_EPS".into(), self.eps),
            ("FIN_TWO_EPS".into(), 2.0 * self.eps),
            ("FIN_FOUR_EPS".into(), 4.0 * self.eps),
            ("FIN_EIGHT_EPS".into(), 8.0 * self.eps),
            ("FIN_THIRTY_TWO_EPS".into(), 32.0 * self.eps),
            // The near-double factor's decisions on f(t*) (quartic/factor.rs).
            ("FIN_SIGN_SURE_EPS".into(), SIGN_SURE * self.eps),
            ("FIN_TOUCH_EPS".into(), TOUCH * self.eps),
            ("FIN_NEAR_DOUBLE".into(), self.near_double),
            ("FIN_DISC_NEAR".into(), self.disc_near),
            ("FIN_SMALL_ROOT".into(), self.small_root),
            ("FIN_POLISH_BELOW".into(), self.polish_below),
            ("FIN_CHORD_SCALE".into(), 1.0 + self.chord_slack),
            ("FIN_OWN_ROOT_REACH".into(), self.own_root_reach),
            ("FIN_THIRD".into(), 1.0 / 3.0),
            ("FIN_NINTH".into(), 1.0 / 9.0),
            ("FIN_TWENTY_SEVENTH".into(), 1.0 / 27.0),
            ("FIN_FOUR_THIRDS".into(), 4.0 / 3.0),
            ("FIN_TRISECT_HALF_RANGE".into(), self.trisect_half_range),
            ("FIN_CBRT_LOW".into(), self.cbrt_range.0),
            ("FIN_CBRT_HIGH".into(), self.cbrt_range.1),
            ("FIN_TWO_90".into(), 2f64.powi(90)),
            ("FIN_TWO_M90".into(), 2f64.powi(-90)),
            ("FIN_TWO_30".into(), 2f64.powi(30)),
            ("FIN_TWO_M30".into(), 2f64.powi(-30)),
            // Round to nearest takes an f64 to f32 infinity from 2¹²⁸ − 2¹⁰³ up.
            ("FIN_F32_OVERFLOW".into(), 2f64.powi(128) - 2f64.powi(103)),
            // "No root" (the CPU's ∞; WGSL may assume no infinities) and "finite".
            ("FIN_NONE".into(), 1e308),
            ("FIN_HUGE".into(), 1e300),
        ];
        for (i, c) in self.trisect_fit.iter().enumerate() {
            floats.push((format!("FIN_TRISECT_FIT_{i}"), *c));
        }
        let mut out = String::from(
            "// Generated from the Rust constants (torus_cull::gpu::FinishConstants::CPU) when\n\
             // the pipeline is built: f64 in shortest round-trip decimal, exact.\n",
        );
        for (name, value) in floats {
            let _ = writeln!(out, "const TC_{name}: f64 = {};", literal_f64(value));
        }
        let _ = writeln!(out, "const TC_FIN_CBRT_SEED: u32 = {}u;", self.cbrt_seed);
        // The f32 module's codes under the f64 module's own names, so that the two can be
        // included together or apart.
        let _ = writeln!(out, "const TC_FIN_CODE_MISS: u32 = {CODE_MISS}u;");
        let _ = writeln!(out, "const TC_FIN_CODE_HIT: u32 = {CODE_HIT}u;");
        out.push_str("// The host's instructions and the answer's status (torus_cull::gpu).\n");
        for (name, code) in super::finish_words::Instruction::ALL
            .iter()
            .map(|i| (i.name(), *i as u32))
            .chain(
                super::finish_words::Status::ALL
                    .iter()
                    .map(|s| (s.name(), *s as u32)),
            )
        {
            let _ = writeln!(out, "const TORUS_F64_{name}: u32 = {code}u;");
        }
        out
    }

    /// The f64 module's WGSL text ([`wgsl_finish_module`]) with these constants: the
    /// header and `wgsl/finish_module/*.wgsl`.
    pub fn module(&self) -> String {
        format!("{}\n{FINISH_MODULE_BODY}", self.header())
    }

    /// The library's f64 pass's full WGSL text: the module ([`FinishConstants::module`])
    /// and the pass's bindings and entry point (`wgsl/finish.wgsl`).
    pub fn source(&self) -> String {
        format!("{}\n{FINISH_BODY}", self.module())
    }
}

/// The device's f64 finish pass with the CPU's constants: what the second pipeline
/// compiles where the adapter has `SHADER_F64`.
pub fn finish_source() -> String {
    FinishConstants::CPU.source()
}

/// The device's f64 finish as WGSL a renderer includes in its own shader, beside the f32
/// module ([`wgsl_module`]) or alone: the generated `const` header (the f64 path's
/// constants, exact; the instruction and status codes) and the functions of
/// `wgsl/finish_module/*.wgsl`, without the library pass's bindings and entry point. The
/// library's f64 pass is this same text plus its bindings ([`finish_source`]). It needs
/// `wgpu::Features::SHADER_F64` on the device (naga's `FLOAT64`); without it, finish the
/// escalated rays on the host ([`super::PreparedRay::finish`]).
///
/// Every global name begins with `torus_`, `Torus` or `TORUS_` (the API) or `tc_`, `Tc`
/// or `TC_` (internals), and none is one the f32 module declares: the two can be
/// included in one shader, in either order, or apart. The entry points:
///
/// ```wgsl
/// fn torus_finish_wanted(instruction: u32, code: u32, t: f32, normal: vec3<f32>) -> bool
/// fn torus_finish_f64(ray: TorusWorldRay, torus: TorusParams64, instruction: u32) -> TorusHit64
/// ```
///
/// - `TorusParams64` (136 bytes, 17 `f64`): from [`super::ModuleTorus::params64`], once
///   per torus: the centre, the columns of the world → torus rotation, R, 1/R, r/R,
///   1 − (r/R)², 1 + r/R, in f64 (the f32 `TorusParams` is rounded; the f64 path needs
///   the torus as the CPU holds it).
/// - `TorusWorldRay` (32 bytes, the layout of `TorusRay`) and the `instruction` (a
///   `u32`, `TORUS_F64_FOLLOW`, `_ALWAYS`, `_SURFACE_FOLLOW`, `_SURFACE_ALWAYS` or
///   `_HOST`): from [`super::ModuleTorus::prepare_f64`], per ray. The ray is the world
///   ray as the caller gave it (not `o − c`, not moved to its foot point), its range
///   clipped to where the torus can be.
/// - `torus_finish_wanted(instruction, hit.code, hit.t, hit.normal)` on the f32 module's
///   `TorusHit` says whether the ray needs the f64 finish (the f32 answer is not proved,
///   or the host sent the f32 module nothing it could prove).
/// - `TorusHit64`: `t` along the world ray, the unit world `normal`, the `point`, each
///   rounded once from f64, and `status`: `TORUS_F64_STATUS_FRONT` or `_BACK` (a hit
///   from the outside or the inside), `_MISS`, or `_HOST` (the method cannot give the
///   CPU's answer: finish it on the host). [`super::ModuleHit64::answer`] decodes it.
///
/// docs/gpu.md, "Using the WGSL module in your renderer", gives the buffers and an
/// example (`examples/wgsl_module.rs`).
pub fn wgsl_finish_module() -> String {
    FinishConstants::CPU.module()
}

/// `x` as an exact WGSL f64 literal: Rust's shortest round-trip decimal and `lf`.
fn literal_f64(x: f64) -> String {
    assert!(x.is_finite(), "a pass constant must be finite: {x:e}");
    format!("{x:?}lf")
}

/// The module's codes as WGSL `const u32` lines: the result codes (`TORUS_MISS`,
/// `TORUS_HIT`, `TORUS_ESCALATE`, `TORUS_KEPT`), the culls (`TORUS_CULL_<NAME>`, the
/// code the kernel's switch reads) and why a ray escalated (`TORUS_WHY_<NAME>`, as
/// [`Escalation::name`]); the host decodes the records with the same values.
fn codes() -> String {
    let mut out = String::from("// Result, cull and escalation codes (torus_cull::gpu).\n");
    for (name, code) in [
        ("MISS", CODE_MISS),
        ("HIT", CODE_HIT),
        ("ESCALATE", CODE_ESCALATE),
        ("KEPT", CODE_KEPT),
    ] {
        let _ = writeln!(out, "const TORUS_{name}: u32 = {code}u;");
    }
    for cull in GpuCull::ALL {
        let name = cull.name().to_uppercase();
        let _ = writeln!(out, "const TORUS_CULL_{name}: u32 = {}u;", cull.code());
    }
    for why in Escalation::KERNEL {
        let name = why.name().to_uppercase();
        let code = why.code().expect("the kernel's escalations have codes");
        let _ = writeln!(out, "const TORUS_WHY_{name}: u32 = {code}u;");
    }
    out
}

/// The kernel's WGSL text with the CPU's constants: what the pipeline compiles.
pub fn kernel_source() -> String {
    KernelConstants::CPU.source()
}

/// The certified f32 intersection as WGSL a renderer includes in its own shader: the
/// generated `const` header (the CPU's constants, exact; the result, cull and escalation
/// codes) and the functions, without the library kernel's bindings and entry point.
/// The library's kernel is this same text plus its bindings ([`kernel_source`]).
///
/// The public entry points (every other name in the text is internal, and every global
/// name begins with `torus_`, `Torus` or `TORUS_` for the API, or `tc_`, `Tc` or `TC_`
/// for internals, so that a shader that includes it avoids clashes by avoiding those
/// prefixes):
///
/// ```wgsl
/// fn torus_intersect(ray: TorusRay, torus: TorusParams, cull: u32) -> TorusHit
/// fn torus_intersect_from_surface(ray: TorusRay, surf: TorusSurfaceRay, torus: TorusParams, cull: u32) -> TorusHit
/// fn torus_cull_keeps(ray: TorusRay, torus: TorusParams, cull: u32) -> bool
/// ```
///
/// - `TorusParams` (112 bytes, seven `vec4<f32>`): from [`super::ModuleTorus::params`],
///   once per torus. It holds the rotation into the torus frame, R, r, r/R, 1/R and the
///   culls' bounds padded by the GPU's margin, which only the Rust side computes.
/// - `TorusRay` (32 bytes: `origin: vec3<f32>, t_min, direction: vec3<f32>, t_max`):
///   from [`super::ModuleTorus::prepare`], per ray. The origin is o − c formed in f64 and
///   rounded once; an origin farther than 2·(R + r) is moved along its line to the foot
///   point (in f64; add the returned `t0` back to the hit's t); one beyond 2²⁰·R is not
///   sent; a ray from a surface point goes as its literal ray past the origin's root, or
///   the host answers it. A ray prepared otherwise is outside what the certificate
///   proves.
/// - `TorusSurfaceRay` (64 bytes), for `torus_intersect_from_surface`: from
///   [`super::PreparedRay::surface`], per ray: a ray from a surface point's cubic, its
///   origin's root divided out in f64, tried before the literal ray (zeros for a literal
///   ray); decode the answers through [`super::PreparedRay::from_surface`].
/// - `cull`: `TORUS_CULL_<NAME>`, [`super::GpuCull::ALL`]'s order.
/// - `TorusHit`: `code` is `TORUS_HIT` (t within 2·10⁻⁴·(R + r) of the first root in
///   range along the unit direction, `normal` the unit world normal), `TORUS_MISS` (a
///   proved miss), or `TORUS_ESCALATE` with `why` = `TORUS_WHY_<NAME>` (the
///   [`super::Escalation`] of that name): not proved either way, finish it on the host
///   with the f64 path ([`crate::intersect()`]); [`super::PreparedRay::verdict`] decodes
///   a record as the library's kernel does.
///
/// docs/gpu.md, "Using the WGSL module in your renderer", gives the buffers and an
/// example (`examples/wgsl_module.rs`).
pub fn wgsl_module() -> String {
    KernelConstants::CPU.module()
}

/// `x` as an exact WGSL hexadecimal float literal: `0x1.hhhhhhp±ef` (a normal f32, or 0).
fn hex_f32(x: f32) -> String {
    assert!(
        x == 0.0 || x.is_normal(),
        "a kernel constant must be 0 or a normal f32: {x:e}"
    );
    if x == 0.0 {
        return "0.0f".into();
    }
    let bits = x.to_bits();
    let sign = if x < 0.0 { "-" } else { "" };
    let exp = ((bits >> 23) & 0xff) as i32 - 127;
    let mantissa = (bits & 0x7f_ffff) << 1; // 24 bits: six hex digits
    format!("{sign}0x1.{mantissa:06x}p{exp}f")
}

#[cfg(test)]
mod tests;
