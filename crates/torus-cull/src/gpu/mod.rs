//! The certified f32 intersection as a WGSL compute kernel, on any Vulkan, Metal or DX12
//! adapter through wgpu (Mesa's software Vulkan, lavapipe, included). Feature `gpu`.
//!
//! One dispatch runs, per ray: the world → torus-frame rotation (f32), the line
//! re-parameterised at its foot point and scaled by 1/R, a cull ([`GpuCull`]), the f64
//! solver's method in f32 (depressed quartic, the resolvent's greatest root, Ferrari's
//! split), and the certificate of [`crate::certified`]: a hit is a proved sign change of
//! the signed distance within a bracket around the reported root, with F > 0 proved
//! before it (convex pieces split at F's lowest point); a miss is F > 0 proved over the
//! whole range (or a cull's rejection). Everything else comes back
//! [`F32Verdict::Escalate`](crate::certified::F32Verdict::Escalate), and
//! [`GpuIntersector::intersect_finished`] finishes those rays with the f64 solver's
//! method: on the device, by a second f64 pass in the same command buffer, where the
//! adapter offers `SHADER_F64` (`gpu/finish.rs`; what it cannot hold finite is handed
//! back to the host, counted), else on the host
//! ([`crate::intersect()`]). [`GpuIntersector::intersect_finished_where`] says which
//! answered each ray ([`Finished`]). A proved hit's `t` is within
//! 2·10⁻⁴·(R + r) of the first root in range (along the unit direction; plus half an ulp
//! of `t` for a rebased origin, below), as on the CPU.
//!
//! **What the host does.** It subtracts the torus centre in f64 and rounds once (the value
//! an f32 subtraction on the device would give), and moves an origin farther than
//! 2·(R + r) along its line to the foot point, in f64 (as [`crate::Torus::line_to_local`]
//! does for the culls), adding the shift back to the kernel's `t`: the kernel's line
//! error grows with the origin's distance, and this keeps far cameras as certifiable as
//! near ones. Origins beyond 2²⁰·R escalate without the kernel.
//!
//! **The GPU's error bounds.** WGSL may or may not contract `a·b + c` into an fma,
//! division is good to 2.5 ulp, `sqrt` is not correctly rounded on every device and
//! subnormals may flush; so every rounding term of the certificate (in u = 2⁻²⁴) is taken
//! four times larger than on the CPU, and the line's own error is the one of an f32
//! rotation and foot point (within 16.9u·|o − c|/R + 16u·|q| + 24.4u·|u| of the true
//! line, to first order: derived step by step in `wgsl/module/trace.wgsl`, and taken about twice).
//! On the CPU the line is formed in f64 and rounded once. The bracket is what remains of
//! 2·10⁻⁴·(R + r) after the kernel's own error in `t` (the foot point's `s = o·d̂` and the
//! division by |d|): at most the CPU's 1.9·10⁻⁴·R.
//!
//! **The culls.** Every cull with a batch form runs in the kernel ([`GpuCull`], the
//! CPU's math on the kernel's line, a foot point and a unit direction in units of R),
//! against the CPU's [`crate::CullBounds`] at R = 1 with the tube padded by the GPU's
//! margin: the CPU's η = [`crate::cull::SAFETY_REL`]·(R + r) plus the kernel's line error on
//! any line that meets the torus (at most 2.1·10⁻⁵·R more; `bounds.rs`). `quadric`,
//! `thick_cylinder`'s hole test and `discriminant` reject only what a running error bound
//! proves (docs/math.md, "The GPU's culls"). [`GpuIntersector::cull_keeps`] runs a cull
//! alone.
//!
//! **One source for the constants.** The kernel's text is `wgsl/module/*.wgsl` and
//! `wgsl/kernel.wgsl` behind a header generated from the Rust constants the CPU uses
//! ([`kernel_source`], [`KernelConstants`]; the f64 pass's, `wgsl/finish_module/*.wgsl`
//! and `wgsl/finish.wgsl`, from [`FinishConstants`]): the cube-root seed, the trisection
//! fit, the solver's thresholds, the bracket, [`crate::cull::SAFETY_REL`], the culls'
//! thresholds and the line error's constants, as exact hexadecimal floats, and the result,
//! cull and escalation codes. Each WGSL file's header names the Rust function behind each
//! of its functions (`// mirrors:` lines, checked by a test).
//!
//! **A module a renderer includes.** [`wgsl_module`] is the header and
//! `wgsl/module/*.wgsl` alone:
//! `torus_intersect(ray, torus, cull) -> TorusHit` and `torus_cull_keeps`, without the
//! kernel's bindings and entry point, for a renderer's own shader; the kernel is the same
//! text plus its bindings. [`ModuleTorus`] packs the torus and the rays as the kernel's
//! host does, and [`PreparedRay::finish`] reads an answer back, finishing an escalated ray
//! in f64 (docs/gpu.md, "Using the WGSL module in your renderer"). Where the device has
//! `SHADER_F64`, [`wgsl_finish_module`] is the f64 pass's method the same way
//! (`torus_finish_f64(ray, torus64, instruction) -> TorusHit64`, no name in common with
//! the f32 module, so both go in one shader); [`ModuleTorus::params64`] and
//! [`ModuleTorus::prepare_f64`] fill its inputs, [`PreparedRay::finish_with_device`]
//! reads both answers back.
//!
//! **The host, by part.** `cull.rs` ([`GpuCull`]), `wire.rs` (the bytes of a ray and a
//! result record, the codes), `frame.rs` (the torus as the parameter block, a ray prepared
//! and packed), `intersector.rs` ([`GpuIntersector`]: device, pipelines, dispatch),
//! `escalation.rs` ([`Escalation`], [`Finished`], [`FinishCounts`]), `finish.rs` (the f64
//! pass), `module.rs` (the includable module's host side), `source.rs` (the WGSL text),
//! `bounds.rs` (the culls' margin), `timing.rs` (the kernel timed alone),
//! `dispatch.rs` (the one dispatch path: pipeline, buffers, bind group, passes, read back),
//! `scene_bvh.rs` ([`SceneBvh`]: tori in an obvhs BVH2, laid out for the WGSL traversal,
//! and the host's answer), `scene_spawned.rs` ([`SpawnedRay`]: secondary rays, their own
//! torus on the surface path), `scene.rs` ([`GpuScene`]: the traversal kernel, closest
//! and any hit over many tori, docs/gpu.md "Tori in a GPU BVH") and `scene_timing.rs`
//! ([`SceneRays`]: rays resident for the traversal, timed alone, with its copy kernel).
//!
//! No timing claim is made from a software adapter: [`GpuIntersector::is_software`] says
//! when the adapter is the CPU (lavapipe reports device type `Cpu`).
//!
//! ```no_run
//! use torus_cull::gpu::{GpuCull, GpuIntersector};
//! use torus_cull::{Ray, Torus};
//! use glam::Vec3;
//! let gpu = GpuIntersector::new()?;
//! println!("{} ({:?})", gpu.adapter_name(), gpu.device_type());
//! let torus = Torus::new(Vec3::ZERO, Vec3::Y, 4.0, 1.0)?;
//! let rays = [Ray::new(Vec3::new(4.0, 10.0, 0.0), Vec3::NEG_Y)?];
//! let verdicts = gpu.intersect(&torus, GpuCull::Cychosz, &rays)?;
//! let finished = gpu.intersect_finished(&torus, GpuCull::Cychosz, &rays)?;
//! assert!(finished[0].hit.is_some());
//! # let _ = verdicts;
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

mod bounds;
mod cull;
mod dispatch;
mod error;
mod escalation;
pub(crate) mod finish;
mod finish_words;
mod frame;
mod intersector;
mod module;
mod scene;
pub(crate) mod scene_bvh;
mod scene_kernel;
mod scene_spawned;
mod scene_timing;
mod source;
mod timing;
mod wire;

pub use cull::GpuCull;
pub use error::{GpuError, SOFTWARE_VULKAN_PACKAGE};
pub use escalation::{Escalation, FinishCounts, Finished};
pub use intersector::{GpuIntersector, WORKGROUP_SIZES};
pub use module::{ModuleHit, ModuleHit64, ModuleTorus, PreparedRay, PreparedRay64};
pub use scene::{GpuScene, Occlusion, SceneAnswer};
pub use scene_bvh::{
    DIRECTION_RANGE, MAX_COORDINATE, STACK, SceneBvh, SceneHit, wgsl_scene_module,
};
pub use scene_spawned::{SPAWNED_WORDS, SpawnedRay};
pub use scene_timing::SceneRays;
pub use source::{
    FinishConstants, KernelConstants, finish_source, kernel_source, wgsl_finish_module, wgsl_module,
};
pub use timing::{FinishTime, KernelTime, ResidentRays};
/// The wgpu this library's kernel runs on (and whose `naga` validates
/// [`wgsl_module`]): a renderer that includes the module uses the same version.
pub use wgpu;

pub(crate) use dispatch::{compute_pipeline, map_read};
pub(crate) use escalation::{shifted, verdict};
pub(crate) use frame::{Frame, Packed};
pub(crate) use intersector::{Buffers, CHUNK, WORKGROUP, upload_surfaces};
pub(crate) use wire::{
    CODE_ESCALATE, CODE_HIT, CODE_KEPT, CODE_MISS, Mode, PARAMS_BYTES, RAY_BYTES, SURFACE_BYTES,
    as_bytes, decode_records,
};
