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
//! [`F32Verdict::Escalate`], and [`GpuIntersector::intersect_finished`] finishes those
//! rays with the f64 solver's method: on the device, by a second f64 pass in the same
//! command buffer, where the adapter offers `SHADER_F64` (`gpu/finish.rs`; what it
//! cannot hold finite is handed back to the host, counted), else on the host
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
//! line, to first order: derived step by step in `module.wgsl`, and taken about twice).
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
//! **One source for the constants.** The kernel's text is `module.wgsl` and `kernel.wgsl`
//! behind a header generated from the Rust constants the CPU uses ([`kernel_source`],
//! [`KernelConstants`]; the f64 pass's, `finish_module.wgsl` and `finish.wgsl`, from
//! [`FinishConstants`]): the cube-root seed, the trisection fit, the solver's thresholds,
//! the bracket, [`crate::cull::SAFETY_REL`], the culls' thresholds and the line error's
//! constants, as exact hexadecimal floats, and the result, cull and escalation codes.
//!
//! **A module a renderer includes.** [`wgsl_module`] is the header and `module.wgsl` alone:
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
pub(crate) mod finish;
mod module;
mod source;

pub use finish::{FinishCounts, Finished};
pub use module::{ModuleHit, ModuleHit64, ModuleTorus, PreparedRay, PreparedRay64};
pub use source::{
    FinishConstants, KernelConstants, finish_source, kernel_source, wgsl_finish_module, wgsl_module,
};
/// The wgpu this library's kernel runs on (and whose `naga` validates
/// [`wgsl_module`]): a renderer that includes the module uses the same version.
pub use wgpu;

use crate::certified::{F32Hit, F32Verdict};
use crate::cull::BatchCull;
use crate::{CullKind, Named, Ray, Torus};
use glam::Vec3;
use std::fmt;
use std::sync::{Mutex, mpsc};

mod timing;
pub use timing::{FinishTime, KernelTime, ResidentRays};

/// The Debian package that gives a machine without a GPU a software Vulkan adapter.
pub const SOFTWARE_VULKAN_PACKAGE: &str = "mesa-vulkan-drivers";

/// The cull the kernel runs before the intersection (a rejected ray is a miss): every
/// cull with a batch form ([`BatchCull`]), the CPU's math on the torus padded by the
/// GPU's margin (the CPU's η plus the kernel's line error; see the module doc and
/// docs/math.md, "The GPU's culls").
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum GpuCull {
    /// No cull: every ray goes to the certified intersection.
    None,
    /// The bounding sphere R + r ([`crate::SphereCull`]).
    Sphere,
    /// The torus's box ([`crate::AabbCull`]).
    Aabb,
    /// Cychosz's bounding sphere R + r plus the slab |y| ≤ r ([`crate::CychoszCull`]).
    Cychosz,
    /// The shell R − r ≤ ρ ≤ R + r, |y| ≤ r ([`crate::ThickCylinderCull`]).
    ThickCylinder,
    /// Skala's circle-based test ([`crate::SkalaCull`]).
    Skala,
    /// The outer ellipsoid and the slab ([`crate::EllipsoidCull`]).
    Ellipsoid,
    /// The outer ellipsoid, the slab and the inner hyperboloid ([`crate::QuadricCull`]),
    /// with the hyperboloid's test widened by its evaluation error.
    Quadric,
    /// The quartic's real-root classification ([`crate::DiscriminantCull`]), rejecting
    /// only where a running error bound proves the classification.
    Discriminant,
}

impl GpuCull {
    /// Every cull, in [`CullKind::TIMED`] order (the kernel's codes 0 to 8).
    pub const ALL: [GpuCull; 9] = [
        GpuCull::None,
        GpuCull::Sphere,
        GpuCull::Aabb,
        GpuCull::Cychosz,
        GpuCull::ThickCylinder,
        GpuCull::Skala,
        GpuCull::Ellipsoid,
        GpuCull::Quadric,
        GpuCull::Discriminant,
    ];

    /// The same cull in the registry of every cull.
    pub const fn kind(self) -> CullKind {
        self.batched().kind()
    }

    /// The same cull's batch form on the CPU.
    pub const fn batched(self) -> BatchCull {
        match self {
            GpuCull::None => BatchCull::NoCull,
            GpuCull::Sphere => BatchCull::Sphere,
            GpuCull::Aabb => BatchCull::Aabb,
            GpuCull::Cychosz => BatchCull::Cychosz,
            GpuCull::ThickCylinder => BatchCull::ThickCylinder,
            GpuCull::Skala => BatchCull::Skala,
            GpuCull::Ellipsoid => BatchCull::Ellipsoid,
            GpuCull::Quadric => BatchCull::Quadric,
            GpuCull::Discriminant => BatchCull::Discriminant,
        }
    }

    /// The stable name (as [`crate::CullKind`]'s).
    pub fn name(self) -> &'static str {
        Named::name(self.kind())
    }

    /// The kernel's code for the cull (`Params.config.y`).
    pub(crate) fn code(self) -> u32 {
        GpuCull::ALL
            .iter()
            .position(|&c| c == self)
            .expect("every cull is in ALL") as u32
    }
}

/// Every batch cull runs on the GPU.
impl From<BatchCull> for GpuCull {
    fn from(cull: BatchCull) -> GpuCull {
        match cull {
            BatchCull::NoCull => GpuCull::None,
            BatchCull::Sphere => GpuCull::Sphere,
            BatchCull::Aabb => GpuCull::Aabb,
            BatchCull::Cychosz => GpuCull::Cychosz,
            BatchCull::ThickCylinder => GpuCull::ThickCylinder,
            BatchCull::Skala => GpuCull::Skala,
            BatchCull::Ellipsoid => GpuCull::Ellipsoid,
            BatchCull::Quadric => GpuCull::Quadric,
            BatchCull::Discriminant => GpuCull::Discriminant,
        }
    }
}

impl From<GpuCull> for CullKind {
    fn from(cull: GpuCull) -> CullKind {
        cull.kind()
    }
}

/// A [`CullKind`] on the GPU: every one but `discriminant_f64` (no batch form).
impl TryFrom<CullKind> for GpuCull {
    type Error = CullKind;

    fn try_from(kind: CullKind) -> Result<GpuCull, CullKind> {
        kind.batched().map(GpuCull::from).ok_or(kind)
    }
}

impl fmt::Display for GpuCull {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// Why the GPU path could not run.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum GpuError {
    /// No adapter (no Vulkan, Metal or DX12 device, and no software Vulkan).
    NoAdapter(String),
    /// The adapter refused a device.
    RequestDevice(String),
    /// The kernel did not compile or validate on this adapter.
    Kernel(String),
    /// Reading the results back failed.
    Readback(String),
}

impl fmt::Display for GpuError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            GpuError::NoAdapter(why) => write!(
                f,
                "no GPU adapter ({why}); on a machine without a GPU install the Debian \
                 package {SOFTWARE_VULKAN_PACKAGE} (Mesa's software Vulkan, lavapipe)"
            ),
            GpuError::RequestDevice(why) => write!(f, "the GPU adapter refused a device: {why}"),
            GpuError::Kernel(why) => write!(f, "the WGSL kernel failed on this adapter: {why}"),
            GpuError::Readback(why) => write!(f, "reading the GPU results back failed: {why}"),
        }
    }
}

impl std::error::Error for GpuError {}

/// Rays per dispatch: 32 bytes in and 32 out each, 32 MiB per buffer (within WebGPU's
/// downlevel limit of 128 MiB per storage binding and 65 535 workgroups of 64).
pub(crate) const CHUNK: usize = 1 << 20;

/// Threads per workgroup (`@workgroup_size` in the kernel).
pub(crate) const WORKGROUP: usize = 64;

/// Bytes per ray, in and out: two `vec4<f32>` each.
pub(crate) const RAY_BYTES: u64 = 32;

/// Size of the uniform block (`Params` in the kernel): eight 16-byte rows, the module's
/// `TorusParams` (seven) and the kernel's `config`.
pub(crate) const PARAMS_BYTES: u64 = 128;

/// The module's result code (`TorusHit.code`, `TORUS_MISS`): a proved miss, or the cull
/// rejected the ray.
pub(crate) const CODE_MISS: u32 = 0;
/// `TORUS_HIT`: a proved hit.
pub(crate) const CODE_HIT: u32 = 1;
/// `TORUS_ESCALATE`: not proved; `why` says which step.
pub(crate) const CODE_ESCALATE: u32 = 2;
/// `TORUS_KEPT`: the cull alone kept the ray's line.
pub(crate) const CODE_KEPT: u32 = 3;

/// Origins farther than this many R from the centre (2²⁰) escalate without the kernel:
/// beyond, the f64 foot point's own error (about 10⁻¹⁵ of the distance) is no longer
/// negligible beside the kernel's line error bound.
const FAR_REL: f64 = 1_048_576.0;

/// Origins farther than this many (R + r) from the centre are moved to their line's foot
/// point on the host, in f64, before the kernel sees them (see [`Frame::pack`]).
const REBASE_REL: f64 = 2.0;

/// A wgpu device with the kernel compiled, ready for batches of rays.
pub struct GpuIntersector {
    pub(crate) device: wgpu::Device,
    pub(crate) queue: wgpu::Queue,
    pub(crate) pipeline: wgpu::ComputePipeline,
    pub(crate) layout: wgpu::BindGroupLayout,
    pub(crate) info: wgpu::AdapterInfo,
    /// The buffers of the last batch, kept for the next one (creating them per call would
    /// be four buffer allocations and a bind group per batch); one batch runs at a time.
    pub(crate) buffers: Mutex<Option<Buffers>>,
    /// The f64 finish pass (`gpu/finish.rs`), where the adapter offers `SHADER_F64`; else why
    /// not.
    pub(crate) finish: Result<finish::FinishPipeline, String>,
    /// Escalated rays go to the f64 pass where there is one (default), else to the host.
    pub(crate) device_finish: bool,
}

/// The uniform block, the rays, the results and their staging copy, for up to `rays`
/// rays a dispatch.
pub(crate) struct Buffers {
    pub(crate) rays: usize,
    pub(crate) params: wgpu::Buffer,
    pub(crate) input: wgpu::Buffer,
    pub(crate) output: wgpu::Buffer,
    pub(crate) staging: wgpu::Buffer,
    pub(crate) bind_group: wgpu::BindGroup,
    /// The f64 finish pass's buffers, where the device has the pass.
    pub(crate) finish: Option<finish::FinishBuffers>,
}

impl fmt::Debug for GpuIntersector {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("GpuIntersector")
            .field("adapter", &self.info.name)
            .field("device_type", &self.info.device_type)
            .field("backend", &self.info.backend)
            .finish_non_exhaustive()
    }
}

impl GpuIntersector {
    /// The first adapter wgpu offers (high-performance preferred; the backends from the
    /// environment, `WGPU_BACKEND`), a device on it and the kernel compiled.
    pub fn new() -> Result<GpuIntersector, GpuError> {
        pollster::block_on(Self::new_async())
    }

    async fn new_async() -> Result<GpuIntersector, GpuError> {
        let instance =
            wgpu::Instance::new(wgpu::InstanceDescriptor::new_without_display_handle_from_env());
        let adapter = instance
            .request_adapter(&wgpu::RequestAdapterOptions {
                power_preference: wgpu::PowerPreference::HighPerformance,
                ..Default::default()
            })
            .await
            .map_err(|e| GpuError::NoAdapter(e.to_string()))?;
        let info = adapter.get_info();
        let (device, queue) = adapter
            .request_device(&wgpu::DeviceDescriptor {
                label: Some("torus-cull"),
                // Timestamps only time the kernel (`ResidentRays::run`); an adapter
                // without them still runs it. f64 runs the finish pass (`finish`); an
                // adapter without it finishes escalated rays on the host.
                required_features: adapter.features()
                    & (wgpu::Features::TIMESTAMP_QUERY | wgpu::Features::SHADER_F64),
                required_limits: wgpu::Limits::downlevel_defaults(),
                ..Default::default()
            })
            .await
            .map_err(|e| GpuError::RequestDevice(e.to_string()))?;
        // A kernel that does not compile or validate on this adapter is an error to return,
        // not a panic in wgpu's default handler.
        let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
        use wgpu::BufferBindingType as B;
        let (pipeline, layout) = compute_pipeline(
            &device,
            "torus-cull",
            kernel_source(),
            &[
                B::Uniform,
                B::Storage { read_only: true },
                B::Storage { read_only: false },
            ],
            "main",
        );
        if let Some(e) = scope.pop().await {
            return Err(GpuError::Kernel(e.to_string()));
        }
        let finish = if device.features().contains(wgpu::Features::SHADER_F64) {
            // A driver that refuses the f64 pass leaves the host to finish (and says why).
            finish::FinishPipeline::new(&device)
                .await
                .map_err(|e| e.to_string())
        } else {
            Err("the adapter does not offer SHADER_F64".into())
        };
        Ok(GpuIntersector {
            device,
            queue,
            pipeline,
            layout,
            info,
            buffers: Mutex::new(None),
            finish,
            device_finish: true,
        })
    }

    /// Whether escalated rays are finished on the device (`gpu/finish.rs`; the adapter offers
    /// `SHADER_F64`, the pass compiled, and [`GpuIntersector::set_device_finish`] did not
    /// turn it off).
    pub fn finishes_on_device(&self) -> bool {
        self.device_finish && self.finish.is_ok()
    }

    /// Why escalated rays are not finished on the device, if they are not.
    pub fn device_finish_unavailable(&self) -> Option<String> {
        match &self.finish {
            Err(why) => Some(why.clone()),
            Ok(_) if !self.device_finish => Some("turned off (set_device_finish)".into()),
            Ok(_) => None,
        }
    }

    /// Finish escalated rays on the device where it can (`true`, the default) or always
    /// on the host (`false`: the f64 path of [`crate::intersect()`], as without f64).
    pub fn set_device_finish(&mut self, on: bool) {
        self.device_finish = on;
        // The cached buffers may lack (or hold) the pass's.
        *self.buffers.get_mut().unwrap_or_else(|e| e.into_inner()) = None;
    }

    /// Buffers for `rays` rays a dispatch.
    pub(crate) fn buffers(&self, rays: usize) -> Buffers {
        let size = rays as u64 * RAY_BYTES;
        let buffer = |label, size, usage| {
            self.device.create_buffer(&wgpu::BufferDescriptor {
                label: Some(label),
                size,
                usage,
                mapped_at_creation: false,
            })
        };
        use wgpu::BufferUsages as Use;
        let [params, input, output, staging] = [
            (
                "torus-cull params",
                PARAMS_BYTES,
                Use::UNIFORM | Use::COPY_DST,
            ),
            ("torus-cull rays", size, Use::STORAGE | Use::COPY_DST),
            ("torus-cull results", size, Use::STORAGE | Use::COPY_SRC),
            ("torus-cull staging", size, Use::MAP_READ | Use::COPY_DST),
        ]
        .map(|(label, size, usage)| buffer(label, size, usage));
        let bind_group = self.device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("torus-cull bind group"),
            layout: &self.layout,
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: params.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: input.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 2,
                    resource: output.as_entire_binding(),
                },
            ],
        });
        let finish = match &self.finish {
            Ok(pass) if self.device_finish => {
                Some(pass.buffers(&self.device, rays, &params, &output))
            }
            _ => None,
        };
        Buffers {
            rays,
            params,
            input,
            output,
            staging,
            bind_group,
            finish,
        }
    }

    /// The adapter's name (lavapipe: `llvmpipe (LLVM …)`).
    pub fn adapter_name(&self) -> &str {
        &self.info.name
    }

    /// The adapter's device type (lavapipe: `Cpu`).
    pub fn device_type(&self) -> wgpu::DeviceType {
        self.info.device_type
    }

    /// The adapter's backend (Vulkan, Metal, DX12, …).
    pub fn backend(&self) -> wgpu::Backend {
        self.info.backend
    }

    /// The adapter runs on the CPU (a software rasteriser such as lavapipe): its timings
    /// say nothing about a GPU.
    pub fn is_software(&self) -> bool {
        self.info.device_type == wgpu::DeviceType::Cpu
    }

    /// The certified f32 verdict of every ray on `torus` behind `cull`, from the kernel:
    /// a proved hit (t and the world normal), a proved miss, or
    /// [`F32Verdict::Escalate`].
    pub fn intersect(
        &self,
        torus: &Torus,
        cull: GpuCull,
        rays: &[Ray],
    ) -> Result<Vec<F32Verdict>, GpuError> {
        Ok(self
            .explain(torus, cull, rays)?
            .into_iter()
            .map(|(v, _)| v)
            .collect())
    }

    /// [`GpuIntersector::intersect`] with, for each escalated ray, the step of the
    /// certificate that did not go through (a diagnostic: the kernel writes it anyway).
    pub fn explain(
        &self,
        torus: &Torus,
        cull: GpuCull,
        rays: &[Ray],
    ) -> Result<Vec<(F32Verdict, Option<Escalation>)>, GpuError> {
        let mut out = Vec::with_capacity(rays.len());
        self.run(torus, cull, Mode::Intersect, rays, |packed, records| {
            for (p, &w) in packed.iter().zip(records) {
                out.push(p.host.unwrap_or_else(|| shifted(verdict(w), p.t0)));
            }
        })?;
        Ok(out)
    }

    /// The cull's verdict alone, per ray's line: `true` keeps it (the intersection would
    /// run), `false` is a proved miss of the line. The kernel stops after its cull. A ray
    /// the kernel is not sent (an origin beyond 2²⁰·R) is kept.
    pub fn cull_keeps(
        &self,
        torus: &Torus,
        cull: GpuCull,
        rays: &[Ray],
    ) -> Result<Vec<bool>, GpuError> {
        let mut out = Vec::with_capacity(rays.len());
        self.run(torus, cull, Mode::CullOnly, rays, |packed, records| {
            for (p, w) in packed.iter().zip(records) {
                out.push(!p.sendable || w[4] != 0.0);
            }
        })?;
        Ok(out)
    }

    /// Runs the kernel in `mode` over `rays`, in dispatches of up to [`CHUNK`] rays, and
    /// hands each dispatch's packed rays ([`Frame::prepare`]) and their result records to
    /// `each`.
    pub(crate) fn run(
        &self,
        torus: &Torus,
        cull: GpuCull,
        mode: Mode,
        rays: &[Ray],
        mut each: impl FnMut(&[Packed], &[[f32; 8]]),
    ) -> Result<(), GpuError> {
        if rays.is_empty() {
            return Ok(());
        }
        let chunk = rays.len().min(CHUNK);
        let mut cache = self.buffers.lock().unwrap_or_else(|e| e.into_inner());
        if cache.as_ref().is_none_or(|b| b.rays < chunk) {
            *cache = Some(self.buffers(chunk));
        }
        let buffers = cache.as_ref().expect("just made");
        let frame = Frame::of(torus);
        for batch in rays.chunks(CHUNK) {
            // A ray from a surface point goes as its literal ray past the origin's root.
            let packed: Vec<Packed> = batch.iter().map(|ray| frame.prepare(ray)).collect();
            match self.dispatch(
                buffers,
                &frame.params(batch.len() as u32, cull, mode),
                &packed,
            ) {
                Ok(records) => each(&packed, &records),
                Err(e) => {
                    // The staging buffer may be left mapped: the next call makes new ones.
                    *cache = None;
                    return Err(e);
                }
            }
        }
        Ok(())
    }

    /// One dispatch of up to [`CHUNK`] packed rays with the uniform block `params`:
    /// upload, run, read back; one record `(t, n.xyz, code, why, 0, 0)` per ray.
    pub(crate) fn dispatch(
        &self,
        buffers: &Buffers,
        params: &[u8],
        packed: &[Packed],
    ) -> Result<Vec<[f32; 8]>, GpuError> {
        self.dispatch_with(buffers, params, packed, None)
            .map(|(records, _)| records)
    }

    /// [`GpuIntersector::dispatch`], followed, when `finish` holds the torus in f64 and
    /// each ray's world and instruction records ([`finish::world_record`]), by the f64
    /// finish pass in the same command buffer; its records `(t, n.xyz, point.xyz,
    /// status)` come back too.
    pub(crate) fn dispatch_with(
        &self,
        buffers: &Buffers,
        params: &[u8],
        packed: &[Packed],
        finish: Option<finish::FinishInput<'_>>,
    ) -> Result<Dispatched, GpuError> {
        let Buffers {
            params: params_buffer,
            input,
            output,
            staging,
            bind_group,
            ..
        } = buffers;
        let words: Vec<f32> = packed.iter().flat_map(|p| p.words).collect();
        self.queue.write_buffer(params_buffer, 0, params);
        self.queue.write_buffer(input, 0, &as_bytes(&words));
        let bytes = packed.len() as u64 * RAY_BYTES;
        let groups = packed.len().div_ceil(WORKGROUP) as u32;
        let mut encoder = self
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                label: Some("torus-cull dispatch"),
            });
        {
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                label: Some("torus-cull pass"),
                timestamp_writes: None,
            });
            pass.set_pipeline(&self.pipeline);
            pass.set_bind_group(0, bind_group, &[]);
            pass.dispatch_workgroups(groups, 1, 1);
        }
        encoder.copy_buffer_to_buffer(output, 0, staging, 0, bytes);
        let second = match (finish, &buffers.finish, &self.finish) {
            (Some(input), Some(fb), Ok(pass)) => {
                let world: Vec<f32> = input.world.iter().flatten().copied().collect();
                let instructions: Vec<f32> = input.instructions.iter().flatten().copied().collect();
                self.queue.write_buffer(&fb.torus, 0, input.torus);
                self.queue.write_buffer(&fb.world, 0, &as_bytes(&world));
                self.queue
                    .write_buffer(&fb.finished, 0, &as_bytes(&instructions));
                {
                    let mut second = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                        label: Some("torus-cull f64 finish pass"),
                        timestamp_writes: None,
                    });
                    second.set_pipeline(&pass.pipeline);
                    second.set_bind_group(0, &fb.bind_group, &[]);
                    second.dispatch_workgroups(groups, 1, 1);
                }
                encoder.copy_buffer_to_buffer(&fb.finished, 0, &fb.staging, 0, bytes);
                Some(&fb.staging)
            }
            _ => None,
        };
        self.queue.submit([encoder.finish()]);
        let read = |staging: &wgpu::Buffer| -> Result<Vec<[f32; 8]>, GpuError> {
            let slice = staging.slice(..bytes);
            self.map_read(&slice)?;
            let records = {
                let view = slice
                    .get_mapped_range()
                    .map_err(|e| GpuError::Readback(format!("{e:?}")))?;
                decode_records(&view).collect()
            };
            staging.unmap();
            Ok(records)
        };
        let records = read(staging)?;
        let finished = second.map(read).transpose()?;
        Ok((records, finished))
    }

    /// [`GpuIntersector::intersect`], finished: every escalated ray is answered in f64,
    /// by the device's f64 pass (`gpu/finish.rs`) where the adapter has one, else by the host
    /// ([`crate::intersect()`]); so the hits and misses are the f64 path's.
    pub fn intersect_finished(
        &self,
        torus: &Torus,
        cull: GpuCull,
        rays: &[Ray],
    ) -> Result<Vec<F32Hit>, GpuError> {
        Ok(self
            .intersect_finished_where(torus, cull, rays)?
            .into_iter()
            .map(|(hit, _)| hit)
            .collect())
    }

    /// [`GpuIntersector::intersect_finished`] with who answered each ray: the f32 kernel
    /// ([`Finished::Proved`]), the device's f64 pass ([`Finished::Device`]) or the host
    /// ([`Finished::Host`]: no f64 on the adapter, or a ray the pass hands back, such as
    /// one whose range f32 cannot clip; see `gpu/finish.rs`). [`FinishCounts::of`] counts
    /// them.
    pub fn intersect_finished_where(
        &self,
        torus: &Torus,
        cull: GpuCull,
        rays: &[Ray],
    ) -> Result<Vec<(F32Hit, Finished)>, GpuError> {
        let mut out = Vec::with_capacity(rays.len());
        if rays.is_empty() {
            return Ok(out);
        }
        let chunk = rays.len().min(CHUNK);
        let mut cache = self.buffers.lock().unwrap_or_else(|e| e.into_inner());
        if cache.as_ref().is_none_or(|b| b.rays < chunk) {
            *cache = Some(self.buffers(chunk));
        }
        let buffers = cache.as_ref().expect("just made");
        let on_device = buffers.finish.is_some();
        let frame = Frame::of(torus);
        let torus64 = finish::torus_bytes(torus);
        for batch in rays.chunks(CHUNK) {
            let packed: Vec<Packed> = batch.iter().map(|ray| frame.prepare(ray)).collect();
            let (world, instructions): (Vec<[f32; 8]>, Vec<[f32; 8]>) = if on_device {
                batch
                    .iter()
                    .zip(&packed)
                    .map(|(ray, p)| {
                        let (world, instruction) = finish::world_record(torus, ray, p.host);
                        (world, finish::instruction_record(instruction))
                    })
                    .unzip()
            } else {
                (Vec::new(), Vec::new())
            };
            let second = on_device.then_some(finish::FinishInput {
                torus: &torus64,
                world: &world,
                instructions: &instructions,
            });
            let params = frame.params(batch.len() as u32, cull, Mode::Intersect);
            let (records, finished) = match self.dispatch_with(buffers, &params, &packed, second) {
                Ok(answer) => answer,
                Err(e) => {
                    *cache = None;
                    return Err(e);
                }
            };
            for (k, (ray, p)) in batch.iter().zip(&packed).enumerate() {
                let (verdict, _) = p.host.unwrap_or_else(|| shifted(verdict(records[k]), p.t0));
                if verdict != F32Verdict::Escalate {
                    out.push((
                        crate::certified::finish(verdict, torus, ray),
                        Finished::Proved,
                    ));
                    continue;
                }
                match finished.as_ref().and_then(|f| finish::device_answer(f[k])) {
                    Some(answer) => out.push((answer, Finished::Device)),
                    None => out.push((
                        crate::certified::finish(verdict, torus, ray),
                        Finished::Host,
                    )),
                }
            }
        }
        Ok(out)
    }
}

/// One dispatch's records: the kernel's `(t, n.xyz, code, why, 0, 0)`, and the f64
/// pass's `(t, n.xyz, point.xyz, status)` where it ran.
pub(crate) type Dispatched = (Vec<[f32; 8]>, Option<Vec<[f32; 8]>>);

/// A compute pipeline of the WGSL `source` at `entry_point`, and its bind group layout:
/// binding k is a buffer of type `bindings[k]`, visible to compute. The kernel and the f64
/// finish pass are built so; a caller wraps this in a validation error scope to get a
/// shader that does not compile on the adapter back as an error.
fn compute_pipeline(
    device: &wgpu::Device,
    label: &str,
    source: String,
    bindings: &[wgpu::BufferBindingType],
    entry_point: &str,
) -> (wgpu::ComputePipeline, wgpu::BindGroupLayout) {
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some(&format!("{label} module")),
        source: wgpu::ShaderSource::Wgsl(source.into()),
    });
    let entries: Vec<wgpu::BindGroupLayoutEntry> = bindings
        .iter()
        .zip(0..)
        .map(|(&ty, binding)| wgpu::BindGroupLayoutEntry {
            binding,
            visibility: wgpu::ShaderStages::COMPUTE,
            ty: wgpu::BindingType::Buffer {
                ty,
                has_dynamic_offset: false,
                min_binding_size: None,
            },
            count: None,
        })
        .collect();
    let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some(&format!("{label} bindings")),
        entries: &entries,
    });
    let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
        label: Some(&format!("{label} layout")),
        bind_group_layouts: &[Some(&layout)],
        immediate_size: 0,
    });
    let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
        label: Some(&format!("{label} pipeline")),
        layout: Some(&pipeline_layout),
        module: &module,
        entry_point: Some(entry_point),
        compilation_options: Default::default(),
        cache: None,
    });
    (pipeline, layout)
}

/// What the kernel does per ray (`Params.config.z`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Mode {
    /// The cull, then the certified intersection.
    Intersect = 0,
    /// The cull alone: code 0 rejected, 3 kept.
    CullOnly = 1,
}

impl GpuIntersector {
    /// Maps `slice` for reading and waits for it.
    fn map_read(&self, slice: &wgpu::BufferSlice<'_>) -> Result<(), GpuError> {
        let (tx, rx) = mpsc::channel();
        slice.map_async(wgpu::MapMode::Read, move |r| {
            let _ = tx.send(r);
        });
        self.device
            .poll(wgpu::PollType::wait_indefinitely())
            .map_err(|e| GpuError::Readback(e.to_string()))?;
        rx.recv()
            .map_err(|e| GpuError::Readback(e.to_string()))?
            .map_err(|e| GpuError::Readback(e.to_string()))
    }
}

/// The result records `(t, n.xyz, code, why, 0, 0)` of mapped result bytes.
fn decode_records(bytes: &[u8]) -> impl Iterator<Item = [f32; 8]> + '_ {
    bytes.chunks_exact(RAY_BYTES as usize).map(|record| {
        std::array::from_fn(|k| {
            f32::from_le_bytes(record[4 * k..4 * k + 4].try_into().expect("4 bytes"))
        })
    })
}

/// A result record `(t, n.xyz, code, why, 0, 0)` as a verdict and, for an escalated ray,
/// why; an unknown code escalates.
pub(crate) fn verdict(w: [f32; 8]) -> (F32Verdict, Option<Escalation>) {
    let normal = Vec3::new(w[1], w[2], w[3]);
    if w[4] == CODE_MISS as f32 {
        (F32Verdict::Miss, None)
    } else if w[4] == CODE_HIT as f32 && w[0].is_finite() && normal.is_finite() {
        (F32Verdict::Hit { t: w[0], normal }, None)
    } else {
        (
            F32Verdict::Escalate,
            Some(Escalation::from_code(w[5] as u32)),
        )
    }
}

/// A verdict for a ray whose origin the host moved `t0` along it: the ray's own t.
pub(crate) fn shifted(
    (verdict, why): (F32Verdict, Option<Escalation>),
    t0: f64,
) -> (F32Verdict, Option<Escalation>) {
    match verdict {
        F32Verdict::Hit { t, normal } if t0 != 0.0 => {
            let t = (f64::from(t) + t0) as f32;
            if t.is_finite() {
                (F32Verdict::Hit { t, normal }, None)
            } else {
                (F32Verdict::Escalate, Some(Escalation::TErrorTooLarge))
            }
        }
        _ => (verdict, why),
    }
}

/// Why the kernel escalated a ray: the step of the certificate that did not go through.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
#[non_exhaustive]
pub enum Escalation {
    /// The origin is more than 2²⁰·R from the centre: not sent to the kernel.
    FarOrigin,
    /// The line or its range is not finite in f32.
    NonFiniteLine,
    /// The quartic is not finite, or the solver flagged it (near-double resolvent root,
    /// near-tangent factor, cube root out of range).
    SolverUnsure,
    /// No root found, but F > 0 over the range was not proved.
    MissNotProved,
    /// The bracket around the root is empty (the root at the range's ends, within their
    /// error).
    EmptyBracket,
    /// The signed distance's sign change across the bracket was not proved (a tangent, an
    /// origin inside the tube, or a line error as large as the bracket).
    NoSignChange,
    /// A root before the bracket was not ruled out (F > 0 not proved there).
    EarlierRootNotRuledOut,
    /// The reported t would not be within 1.9·10⁻⁴·(R + r) of the root.
    TErrorTooLarge,
    /// The ray starts on the surface ([`crate::Ray::from_surface`]) and does not leave
    /// into the outside by a margin (into the tube, or along the tangent plane): the host
    /// divides its origin's root out in f64. Rays that leave into the outside go to the
    /// kernel as the literal ray past their origin's root.
    OnSurface,
    /// A code the host does not know.
    Unknown,
}

impl Escalation {
    /// The escalations the module reports, in the order of their codes 1 to 7
    /// (`TorusHit.why`, `TORUS_WHY_<NAME>` with NAME = [`Escalation::name`] in capitals).
    pub const KERNEL: [Escalation; 7] = [
        Escalation::NonFiniteLine,
        Escalation::SolverUnsure,
        Escalation::MissNotProved,
        Escalation::EmptyBracket,
        Escalation::NoSignChange,
        Escalation::EarlierRootNotRuledOut,
        Escalation::TErrorTooLarge,
    ];

    /// The module's code (`TorusHit.why`) for an escalation it reports; `None` for the
    /// host's own ([`Escalation::FarOrigin`], [`Escalation::OnSurface`],
    /// [`Escalation::Unknown`]).
    pub fn code(self) -> Option<u32> {
        Escalation::KERNEL
            .iter()
            .position(|&e| e == self)
            .map(|i| i as u32 + 1)
    }

    /// The escalation of a module code (`TorusHit.why`); an unknown code is
    /// [`Escalation::Unknown`].
    pub fn from_code(code: u32) -> Escalation {
        match code {
            1..=7 => Escalation::KERNEL[code as usize - 1],
            _ => Escalation::Unknown,
        }
    }

    /// The stable name.
    pub fn name(self) -> &'static str {
        match self {
            Escalation::FarOrigin => "far_origin",
            Escalation::NonFiniteLine => "non_finite_line",
            Escalation::SolverUnsure => "solver_unsure",
            Escalation::MissNotProved => "miss_not_proved",
            Escalation::EmptyBracket => "empty_bracket",
            Escalation::NoSignChange => "no_sign_change",
            Escalation::EarlierRootNotRuledOut => "earlier_root",
            Escalation::TErrorTooLarge => "t_error",
            Escalation::OnSurface => "on_surface",
            Escalation::Unknown => "unknown",
        }
    }
}

/// The torus as the kernel's uniform block, and what packing a ray needs of it (f64).
pub(crate) struct Frame {
    torus: Torus,
    rows: [Vec3; 3],
    /// The culls' bounds at R = 1 with the GPU's margin ([`bounds::kernel_bounds`]).
    bounds: [[f32; 4]; 3],
    major: f32,
    minor: f32,
    center: glam::DVec3,
    major_f64: f64,
    outer: f64,
}

/// A ray as the kernel reads it, and what the host adds back.
pub(crate) struct Packed {
    /// `(o − c, t_min − t0, d, t_max − t0)`, the range clipped (see [`Frame::pack`]).
    pub(crate) words: [f32; 8],
    /// How far along the ray the uploaded origin is: the kernel's t plus this is the ray's.
    pub(crate) t0: f64,
    /// Within [`FAR_REL`]·R of the centre: the kernel may answer.
    pub(crate) sendable: bool,
    /// The host's own answer, whatever the kernel writes ([`Frame::prepare`]).
    pub(crate) host: Option<(F32Verdict, Option<Escalation>)>,
}

impl Frame {
    pub(crate) fn of(torus: &Torus) -> Frame {
        let m = torus.to_local_rotation().transpose(); // columns of Mᵀ = rows of M
        let major_f64 = torus.major_radius_f64();
        let rr = (torus.minor_radius_f64() / major_f64) as f32;
        Frame {
            torus: *torus,
            rows: [m.x_axis, m.y_axis, m.z_axis],
            bounds: bounds::bounds_rows(&bounds::kernel_bounds(rr)),
            major: torus.major_radius(),
            minor: torus.minor_radius(),
            center: torus.center_f64(),
            major_f64,
            outer: major_f64 + torus.minor_radius_f64(),
        }
    }

    /// `ray` packed for the kernel ([`Frame::pack`]), with the host's own answer where it
    /// has one: an origin beyond [`FAR_REL`]·R escalates ([`Escalation::FarOrigin`]); a ray
    /// from a surface point goes as the literal ray past its origin's own root
    /// ([`crate::certified::on_surface`]), or is answered here when it has no such start:
    /// a proved miss (its range ends first), or escalated (it goes into the tube).
    pub(crate) fn prepare(&self, ray: &Ray) -> Packed {
        use crate::certified::on_surface::{Start, start};
        let (sent, on_surface) = if ray.starts_on_surface() {
            match start(&self.torus, ray) {
                Start::Literal(literal) => (literal, None),
                Start::Miss => (*ray, Some((F32Verdict::Miss, None))),
                Start::Escalate => (
                    *ray,
                    Some((F32Verdict::Escalate, Some(Escalation::OnSurface))),
                ),
            }
        } else {
            (*ray, None)
        };
        let mut packed = self.pack(&sent);
        packed.host = if packed.sendable {
            on_surface
        } else {
            Some((F32Verdict::Escalate, Some(Escalation::FarOrigin)))
        };
        packed
    }

    /// The uniform block: the torus ([`Frame::torus_params`]); the count, the cull and
    /// the mode.
    pub(crate) fn params(&self, count: u32, cull: GpuCull, mode: Mode) -> Vec<u8> {
        let mut bytes = Vec::with_capacity(PARAMS_BYTES as usize);
        for f in self.torus_params() {
            bytes.extend_from_slice(&f.to_le_bytes());
        }
        for u in [count, cull.code(), mode as u32, 0] {
            bytes.extend_from_slice(&u.to_le_bytes());
        }
        bytes
    }

    /// The module's `TorusParams`: rows of M with R, r, r/R; 1/R; the culls' bounds
    /// (three rows).
    pub(crate) fn torus_params(&self) -> [f32; 28] {
        let rr = (f64::from(self.minor) / self.major_f64) as f32;
        let inv_major = (1.0 / self.major_f64) as f32;
        let floats: [f32; 16] = [
            self.rows[0].x,
            self.rows[0].y,
            self.rows[0].z,
            self.major,
            self.rows[1].x,
            self.rows[1].y,
            self.rows[1].z,
            self.minor,
            self.rows[2].x,
            self.rows[2].y,
            self.rows[2].z,
            rr,
            inv_major,
            0.0,
            0.0,
            0.0,
        ];
        let mut out = [0.0; 28];
        for (o, f) in out
            .iter_mut()
            .zip(floats.into_iter().chain(self.bounds.into_iter().flatten()))
        {
            *o = f;
        }
        out
    }

    /// A ray as the kernel reads it.
    ///
    /// The origin goes relative to the centre, `o − c` formed in f64 and rounded once
    /// (the same value as an f32 subtraction on the device). An origin farther than
    /// [`REBASE_REL`]·(R + r) first moves along its line to the foot point, `t0 = −(o −
    /// c)·d/|d|²` (f64, as [`Torus::line_to_local`] does for the culls): the kernel's line
    /// error grows with the origin's distance, and from there it is that of a near ray.
    /// The range becomes `[t_min − t0, t_max − t0]`, clipped to `|t| ≤ T`, T = (|foot| +
    /// 4(R + r))/|d| rounded up: no point beyond is within the bounding sphere, so no
    /// root is lost, and the kernel's sums stay finite.
    pub(crate) fn pack(&self, ray: &Ray) -> Packed {
        let d = ray.dir().as_dvec3();
        let rel = ray.origin().as_dvec3() - self.center;
        let sendable = rel.length() <= FAR_REL * self.major_f64;
        let len_sq = d.length_squared();
        let t0 = if rel.length() > REBASE_REL * self.outer {
            -rel.dot(d) / len_sq
        } else {
            0.0
        };
        let start = rel + d * t0;
        let reach = (start.length() + 4.0 * self.outer) / len_sq.sqrt();
        let limit = (reach * (1.0 + 1e-6)).min(f64::from(f32::MAX));
        let t_min = (f64::from(ray.t_min()) - t0).clamp(-limit, limit) as f32;
        let t_max = (f64::from(ray.t_max()) - t0).clamp(-limit, limit) as f32;
        let (o, d) = (start.as_vec3(), ray.dir());
        Packed {
            words: [o.x, o.y, o.z, t_min, d.x, d.y, d.z, t_max],
            t0,
            sendable,
            host: None,
        }
    }
}

fn as_bytes(words: &[f32]) -> Vec<u8> {
    words.iter().flat_map(|w| w.to_le_bytes()).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cull::BATCHED;

    #[test]
    fn every_batch_cull_is_a_gpu_cull_by_the_same_name() {
        assert_eq!(GpuCull::ALL.len(), BATCHED.len());
        for (i, (&gpu, &batch)) in GpuCull::ALL.iter().zip(&BATCHED).enumerate() {
            assert_eq!(GpuCull::from(batch), gpu);
            assert_eq!(gpu.batched(), batch);
            assert_eq!(gpu.kind(), batch.kind());
            assert_eq!(gpu.name(), Named::name(batch.kind()));
            assert_eq!(GpuCull::try_from(batch.kind()), Ok(gpu));
            // The kernel's switch reads the code in this order.
            assert_eq!(gpu.code(), i as u32);
        }
        assert_eq!(
            GpuCull::try_from(CullKind::DiscriminantF64),
            Err(CullKind::DiscriminantF64)
        );
    }

    #[test]
    fn every_escalation_code_round_trips() {
        for (i, why) in Escalation::KERNEL.into_iter().enumerate() {
            assert_eq!(why.code(), Some(i as u32 + 1));
            assert_eq!(Escalation::from_code(i as u32 + 1), why);
            let record = [
                0.0,
                0.0,
                0.0,
                0.0,
                CODE_ESCALATE as f32,
                (i + 1) as f32,
                0.0,
                0.0,
            ];
            assert_eq!(verdict(record), (F32Verdict::Escalate, Some(why)));
        }
        for host in [
            Escalation::FarOrigin,
            Escalation::OnSurface,
            Escalation::Unknown,
        ] {
            assert_eq!(host.code(), None);
        }
        assert_eq!(Escalation::from_code(0), Escalation::Unknown);
        assert_eq!(Escalation::from_code(8), Escalation::Unknown);
    }

    #[test]
    fn the_uniform_block_has_its_size() {
        let torus = Torus::canonical(4.0, 1.0).unwrap();
        let frame = Frame::of(&torus);
        let bytes = frame.params(7, GpuCull::Skala, Mode::CullOnly);
        assert_eq!(bytes.len() as u64, PARAMS_BYTES);
        let word = |k: usize| u32::from_le_bytes(bytes[4 * k..4 * k + 4].try_into().unwrap());
        // config = (count, cull, mode, 0), the last row.
        assert_eq!([word(28), word(29), word(30), word(31)], [7, 5, 1, 0]);
    }
}
