//! The intersector: a wgpu device with the kernel compiled ([`GpuIntersector`]), its
//! buffers, the pipelines and the dispatch (upload, then `dispatch.rs`'s run and read
//! back), and the f64 finish pass chained in the same command buffer.

use super::{
    Escalation, Finished, Frame, GpuCull, Mode, PARAMS_BYTES, Packed, RAY_BYTES, SURFACE_BYTES,
    as_bytes, compute_pipeline, kernel_source, shifted, verdict,
};
use super::{GpuError, dispatch, finish};
use crate::certified::{F32Hit, F32Verdict};
use crate::{Ray, Torus};
use std::fmt;
use std::sync::Mutex;

/// Rays per dispatch: 32 bytes in and 32 out each, 32 MiB per buffer (within WebGPU's
/// downlevel limit of 128 MiB per storage binding and 65 535 workgroups of 64).
pub(crate) const CHUNK: usize = 1 << 20;

/// Threads per workgroup of the f64 finish pass, and the kernel's default
/// (`@workgroup_size` in each).
pub(crate) const WORKGROUP: usize = 64;

/// The kernel's workgroup sizes [`GpuIntersector::with_workgroup`] accepts: powers of two
/// from a warp to WebGPU's downlevel limit of 256 invocations.
pub const WORKGROUP_SIZES: [u32; 4] = [32, 64, 128, 256];

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
    /// Threads per workgroup of the kernel (one of [`WORKGROUP_SIZES`]).
    pub(crate) workgroup: u32,
    /// The scene kernels compiled so far, shared by every [`super::GpuScene`] on this
    /// device (the text depends on f64 alone, not on the scene).
    pub(crate) scene_kernels: super::scene_kernel::Kernels,
}

/// The parameter block, the rays, their surface records, the results and their staging
/// copy, for up to `rays` rays a dispatch.
pub(crate) struct Buffers {
    pub(crate) rays: usize,
    pub(crate) params: wgpu::Buffer,
    pub(crate) input: wgpu::Buffer,
    pub(crate) surfaces: wgpu::Buffer,
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
        Self::with_workgroup(WORKGROUP as u32)
    }

    /// As [`GpuIntersector::new`], with the kernel compiled for `threads` invocations per
    /// workgroup (one of [`WORKGROUP_SIZES`]; 64 by default). The answers are the same
    /// whatever the size: each invocation handles one ray. Another size is an error
    /// naming the allowed ones.
    pub fn with_workgroup(threads: u32) -> Result<GpuIntersector, GpuError> {
        if !WORKGROUP_SIZES.contains(&threads) {
            return Err(GpuError::Kernel(format!(
                "workgroup size {threads} is not one of {WORKGROUP_SIZES:?}"
            )));
        }
        pollster::block_on(Self::new_async(threads))
    }

    /// Threads per workgroup of the kernel ([`GpuIntersector::with_workgroup`]).
    #[must_use]
    pub fn workgroup(&self) -> u32 {
        self.workgroup
    }

    async fn new_async(threads: u32) -> Result<GpuIntersector, GpuError> {
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
                // Five storage buffers for the f64 pass (its parameter block is one since
                // the kernel's moved out of a uniform): the downlevel default is 4, which
                // made the pass fail validation and every escalated ray go to the host.
                required_limits: wgpu::Limits {
                    max_storage_buffers_per_shader_stage: adapter
                        .limits()
                        .max_storage_buffers_per_shader_stage
                        .min(8),
                    ..wgpu::Limits::downlevel_defaults()
                },
                ..Default::default()
            })
            .await
            .map_err(|e| GpuError::RequestDevice(e.to_string()))?;
        // A kernel that does not compile or validate on this adapter is an error to return,
        // not a panic in wgpu's default handler.
        let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
        use wgpu::BufferBindingType as B;
        // The entry point's one attribute, resized; everything else is the text as shipped.
        let default = format!("@compute @workgroup_size({WORKGROUP})");
        let source = kernel_source();
        if source.matches(&default).count() != 1 {
            return Err(GpuError::Kernel(format!(
                "the kernel must hold `{default}` once, to resize it"
            )));
        }
        let source = source.replacen(&default, &format!("@compute @workgroup_size({threads})"), 1);
        let (pipeline, layout) = compute_pipeline(
            &device,
            "torus-cull",
            source,
            &[
                B::Storage { read_only: true },
                B::Storage { read_only: true },
                B::Storage { read_only: false },
                B::Storage { read_only: true },
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
            workgroup: threads,
            scene_kernels: Default::default(),
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
        let buffer = |label, size, usage| dispatch::buffer(&self.device, label, size, usage);
        use wgpu::BufferUsages as Use;
        let [params, input, surfaces, output, staging] = [
            (
                "torus-cull params",
                PARAMS_BYTES,
                Use::STORAGE | Use::COPY_DST,
            ),
            ("torus-cull rays", size, Use::STORAGE | Use::COPY_DST),
            (
                "torus-cull surface records",
                rays as u64 * SURFACE_BYTES,
                Use::STORAGE | Use::COPY_DST,
            ),
            ("torus-cull results", size, Use::STORAGE | Use::COPY_SRC),
            ("torus-cull staging", size, Use::MAP_READ | Use::COPY_DST),
        ]
        .map(|(label, size, usage)| buffer(label, size, usage));
        let bind_group = dispatch::bind_group(
            &self.device,
            &self.layout,
            "torus-cull bind group",
            &[&params, &input, &output, &surfaces],
        );
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
            surfaces,
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
        Ok(firsts(self.explain(torus, cull, rays)?))
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
                out.push(p.kernel_host().unwrap_or_else(|| shifted(verdict(w), p.t0)));
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
            let surfaces = upload_surfaces(self, buffers, &packed);
            match self.dispatch(
                buffers,
                &frame.params(batch.len() as u32, cull, mode, surfaces),
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

    /// One dispatch of up to [`CHUNK`] packed rays with the parameter block `params`:
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
        let groups = packed.len().div_ceil(self.workgroup as usize) as u32;
        let mut passes = vec![dispatch::Pass {
            pipeline: &self.pipeline,
            bind_group,
            groups,
        }];
        let mut reads = vec![dispatch::Read {
            source: output,
            staging,
            bytes,
        }];
        if let (Some(input), Some(fb), Ok(pass)) = (finish, &buffers.finish, &self.finish) {
            let world: Vec<f32> = input.world.iter().flatten().copied().collect();
            let instructions: Vec<f32> = input.instructions.iter().flatten().copied().collect();
            self.queue.write_buffer(&fb.torus, 0, input.torus);
            self.queue.write_buffer(&fb.world, 0, &as_bytes(&world));
            self.queue
                .write_buffer(&fb.finished, 0, &as_bytes(&instructions));
            passes.push(dispatch::Pass {
                pipeline: &pass.pipeline,
                bind_group: &fb.bind_group,
                groups,
            });
            reads.push(dispatch::Read {
                source: &fb.finished,
                staging: &fb.staging,
                bytes,
            });
        }
        let mut read = dispatch::run(
            &self.device,
            &self.queue,
            "torus-cull dispatch",
            &passes,
            &reads,
        )?
        .into_iter();
        let records = read.next().expect("the kernel's records");
        Ok((records, read.next()))
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
        Ok(firsts(self.intersect_finished_where(torus, cull, rays)?))
    }

    /// [`GpuIntersector::intersect_finished`] with who answered each ray: the f32 kernel
    /// ([`Finished::Proved`]), the device's f64 pass ([`Finished::Device`]) or the host
    /// ([`Finished::Host`]: no f64 on the adapter, or a ray the pass hands back, such as
    /// one whose range f32 cannot clip; see `gpu/finish.rs`). [`FinishCounts::of`](super::FinishCounts::of) counts
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
                        let (world, instruction) =
                            finish::world_record(torus, ray, p.kernel_host());
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
            let surfaces = upload_surfaces(self, buffers, &packed);
            let params = frame.params(batch.len() as u32, cull, Mode::Intersect, surfaces);
            let (records, finished) = match self.dispatch_with(buffers, &params, &packed, second) {
                Ok(answer) => answer,
                Err(e) => {
                    *cache = None;
                    return Err(e);
                }
            };
            for (k, (ray, p)) in batch.iter().zip(&packed).enumerate() {
                let (verdict, _) = p
                    .kernel_host()
                    .unwrap_or_else(|| shifted(verdict(records[k]), p.t0));
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

/// Uploads the surface records of `packed` where any ray has one; whether it did (the
/// parameter block's `config.w`, [`Frame::params`]).
pub(crate) fn upload_surfaces(gpu: &GpuIntersector, buffers: &Buffers, packed: &[Packed]) -> bool {
    let any = packed.iter().any(Packed::has_surface);
    if any {
        let records: Vec<f32> = packed.iter().flat_map(|p| p.surface).collect();
        gpu.queue
            .write_buffer(&buffers.surfaces, 0, &as_bytes(&records));
    }
    any
}

/// One dispatch's records: the kernel's `(t, n.xyz, code, why, 0, 0)`, and the f64
/// pass's `(t, n.xyz, point.xyz, status)` where it ran.
pub(crate) type Dispatched = (Vec<[f32; 8]>, Option<Vec<[f32; 8]>>);

impl GpuIntersector {
    /// Maps `slice` for reading and waits for it ([`super::map_read`] on this device).
    pub(crate) fn map_read(&self, slice: &wgpu::BufferSlice<'_>) -> Result<(), GpuError> {
        super::map_read(&self.device, slice)
    }
}

/// Each answer of `pairs` without what came with it (a diagnostic, who answered).
fn firsts<A, B>(pairs: Vec<(A, B)>) -> Vec<A> {
    pairs.into_iter().map(|(a, _)| a).collect()
}
