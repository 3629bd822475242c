//! The culls' per-torus constants as the kernel uses them: the CPU's [`CullBounds`] at
//! R = 1 (the kernel's line is scaled by 1/R), with the tube padded by the GPU's margin
//! [`gpu_margin`] instead of the CPU's η = [`crate::cull::SAFETY_REL`]·(R + r).

use crate::certified::certificate::U32;
use crate::cull::{CullBounds, SAFETY_REL};

/// The kernel's line error, relative part: the computed point q + u·d̂ stands within
/// `LINE_REL·(|q| + |u|) + LINE_ABS_DIST·|o − c|/R + LINE_ABS` of the true line's point
/// at u (units of R; derived in `wgsl/module/trace.wgsl`, about twice the first-order bound).
pub(crate) const LINE_REL: f32 = (48.0 * U32) as f32;

/// The kernel's line error, per unit of the origin's distance |o − c|/R.
pub(crate) const LINE_ABS_DIST: f32 = (32.0 * U32) as f32;

/// The kernel's line error, constant part (it covers the host's f64 foot point too).
pub(crate) const LINE_ABS: f32 = (32.0 * U32) as f32;

/// The GPU's margin for the culls at R = 1 and tube radius `rr` = r/R (as the kernel
/// gets it, rounded to f32), rounded up:
///
/// η_gpu = SAFETY_REL·(1 + rr) + E + 4u·rr, with E the kernel's line error on any line
/// that meets the torus: every point of such a line that lies in the torus has |u| ≤ 1 +
/// rr from the foot point and |q| ≤ 1 + rr + E, so |q| + |u| ≤ 2(1 + rr) + 1/64; its
/// origin is within 2(1 + rr)·(1 + 2⁻²⁰) of the centre (farther ones were moved to the
/// foot point by the host, which is then within 1 + rr). Hence
/// E = LINE_REL·(2(1 + rr) + 1/64) + LINE_ABS_DIST·2(1 + rr)(1 + 2⁻²⁰) + LINE_ABS, and
/// the kernel's computed line passes within E of every point where the true line is in
/// the torus: it meets the torus padded by E. The term 4u·rr covers rr's own rounding.
/// What is left, SAFETY_REL·(1 + rr), absorbs the culls' evaluation in f32 as on the CPU
/// (docs/math.md, "The GPU's culls").
pub(crate) fn gpu_margin(rr: f32) -> f32 {
    let rr = f64::from(rr);
    let outer = 1.0 + rr;
    let reach = 2.0 * outer + 1.0 / 64.0;
    let distance = 2.0 * outer * (1.0 + 1.0 / 1_048_576.0);
    let line =
        f64::from(LINE_REL) * reach + f64::from(LINE_ABS_DIST) * distance + f64::from(LINE_ABS);
    let eta = f64::from(SAFETY_REL) * outer + line + 4.0 * U32 * rr;
    // Up, past any rounding of the sum.
    let rounded = (eta * (1.0 + 1.0 / 1_048_576.0)) as f32;
    f32::from_bits(rounded.to_bits() + 1)
}

/// The culls' bounds for the kernel: R = 1, tube `rr`, margin [`gpu_margin`].
pub(crate) fn kernel_bounds(rr: f32) -> CullBounds {
    CullBounds::with_margin(1.0, rr, gpu_margin(rr))
}

/// `GPU_BOUNDS` from the rows of the table of per-torus constants
/// (`crate::geometry::cull_bounds_table`) with the form `gpu`.
macro_rules! define_gpu_bounds {
    ($($field:ident: $ty:ty [$($lanes:ident $($gpu:ident $wgsl:ident)?)?], $doc:literal;)*) => {
        /// The constants the kernel's culls read, in the table's order (the slots of
        /// `bounds_a`, `bounds_b`, `bounds_c`): each its WGSL name in `TcBounds` and its
        /// value in the kernel's [`CullBounds`].
        const GPU_BOUNDS: &[(&str, fn(&CullBounds) -> f32)] = &[
            $($($((stringify!($wgsl), |b: &CullBounds| -> f32 { b.$field }),)?)?)*
        ];
    };
}
crate::geometry::cull_bounds_table!(define_gpu_bounds);

/// The slots of `TorusParams`'s three bounds rows: the culls' constants ([`GPU_BOUNDS`])
/// then two for diagnostics, R − r_η and η_gpu (no cull reads them).
const SLOTS: usize = 12;
const _: () = assert!(
    GPU_BOUNDS.len() + 2 <= SLOTS,
    "TorusParams holds 10 culls' constants: a new one needs a fourth bounds row"
);

/// The bounds as three rows of the kernel's parameter block (`Params.bounds_*`): the
/// constants of [`GPU_BOUNDS`] in order, then R − r_η and η_gpu, then zeros.
pub(crate) fn bounds_rows(b: &CullBounds) -> [[f32; 4]; 3] {
    let mut slots = [0.0f32; SLOTS];
    let n = GPU_BOUNDS.len();
    for (slot, (_, value)) in slots.iter_mut().zip(GPU_BOUNDS) {
        *slot = value(b);
    }
    slots[n] = b.inner_safe;
    slots[n + 1] = gpu_margin_of(b);
    [
        [slots[0], slots[1], slots[2], slots[3]],
        [slots[4], slots[5], slots[6], slots[7]],
        [slots[8], slots[9], slots[10], slots[11]],
    ]
}

/// The WGSL `TcBounds` (the culls' constants by name) and `tc_bounds_of`, which unpacks
/// them from a `TorusParams` in [`bounds_rows`]'s slots: generated from [`GPU_BOUNDS`]
/// (mirrors `bounds_rows`), so that the two cannot disagree.
pub(crate) fn bounds_wgsl() -> String {
    let mut fields = String::new();
    let mut reads = String::new();
    for (i, (name, _)) in GPU_BOUNDS.iter().enumerate() {
        let row = ["a", "b", "c"][i / 4];
        let lane = ["x", "y", "z", "w"][i % 4];
        fields.push_str(&format!("    {name}: f32,\n"));
        reads.push_str(&format!("    b.{name} = torus.bounds_{row}.{lane};\n"));
    }
    format!(
        "// The culls' per-torus constants (generated from the table in src/geometry/bounds.rs;\n\
         // the host packs them: torus_cull::gpu::bounds::bounds_rows).\n\
         struct TcBounds {{\n{fields}}};\n\n\
         fn tc_bounds_of(torus: TorusParams) -> TcBounds {{\n    var b: TcBounds;\n{reads}    return b;\n}}\n"
    )
}

/// The margin the bounds were made with (for the kernel's diagnostics): r_η − r.
fn gpu_margin_of(b: &CullBounds) -> f32 {
    b.minor_safe - b.minor_radius
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_margin_is_the_cpus_plus_the_line_error() {
        for rr in [0.001f32, 0.1, 0.5, 1.0 / 1.01] {
            let eta = gpu_margin(rr);
            let cpu = SAFETY_REL * (1.0 + rr);
            // At most 2·10⁻⁵ more than the CPU's 2.4·10⁻⁴·(1 + rr): the rejection rates
            // stay the CPU's.
            assert!(eta > cpu && eta < cpu + 2.5e-5, "rr {rr}: {eta} vs {cpu}");
            let b = kernel_bounds(rr);
            assert!(b.minor_safe >= rr + eta * (1.0 - 1e-6));
            assert_eq!(b.major_radius, 1.0);
        }
    }

    /// The generated packing is `TorusParams`'s documented layout (api.wgsl; a renderer
    /// fills it from `ModuleTorus::params`), and the WGSL reads each constant from its
    /// slot.
    #[test]
    fn the_bounds_rows_keep_the_params_layout() {
        let b = kernel_bounds(0.25);
        assert_eq!(
            bounds_rows(&b),
            [
                [b.outer_safe, b.outer_safe_sq, b.minor_safe, b.minor_safe_sq],
                [
                    b.inner_safe_sq,
                    b.ellipsoid_y_scale,
                    b.ellipsoid_slab,
                    b.hyperboloid_y_coef
                ],
                [b.minor_rel_sq, b.inner_safe, gpu_margin_of(&b), 0.0],
            ]
        );
        let wgsl = bounds_wgsl();
        for read in [
            "b.outer = torus.bounds_a.x;",
            "b.minor_sq = torus.bounds_a.w;",
            "b.inner_sq = torus.bounds_b.x;",
            "b.hyperboloid = torus.bounds_b.w;",
            "b.minor_rel_sq = torus.bounds_c.x;",
        ] {
            assert!(wgsl.contains(read), "{read} in\n{wgsl}");
        }
    }
}
