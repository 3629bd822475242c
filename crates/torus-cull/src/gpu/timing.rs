//! Rays resident on the device, so that the kernel can be timed without the transfers.
//!
//! [`GpuIntersector::intersect`] packs, uploads, dispatches and reads back in one call:
//! right for a renderer that hands over a batch and wants answers, wrong for asking how
//! fast the kernel is, because a small batch is then timed by its transfers and the
//! submission's latency. [`ResidentRays`] splits the three: [`GpuIntersector::upload`]
//! packs and uploads once (its wall time is kept), [`ResidentRays::run`] dispatches the
//! kernel over every resident ray `repeats` times in one submission and reports the
//! device's own timestamps where the adapter offers them (`TIMESTAMP_QUERY`), and
//! [`ResidentRays::read_back`] copies the last run's records back (its wall time kept
//! apart).

use super::escalation::FinishCounts;
use super::finish;
use super::finish_words::Status;
use super::{Buffers, CHUNK, Escalation, Frame, GpuCull, GpuError, GpuIntersector, RAY_BYTES};
use super::{Mode, WORKGROUP, as_bytes, decode_records, shifted, upload_surfaces, verdict};
use crate::Ray;
use crate::Torus;
use crate::certified::F32Verdict;
use std::time::{Duration, Instant};

/// A batch of rays packed and uploaded once, for timing the kernel alone.
pub struct ResidentRays<'g> {
    gpu: &'g GpuIntersector,
    frame: Frame,
    /// One set of buffers per dispatch of at most [`CHUNK`] rays.
    chunks: Vec<Buffers>,
    /// Rays in each chunk.
    counts: Vec<usize>,
    /// Whether each chunk has surface records for the kernel to read.
    surfaced: Vec<bool>,
    /// Per ray, what the host adds to the kernel's t ([`Frame::pack`]), and the rays the
    /// kernel is not asked about (far origins, on-surface rays).
    shifts: Vec<f64>,
    host: Vec<(usize, (F32Verdict, Option<Escalation>))>,
    /// Wall time of packing and uploading.
    upload: Duration,
    /// [`COPY_WGSL`] on the kernel's bindings.
    copy: wgpu::ComputePipeline,
    /// Per chunk, the f64 pass's instruction records as uploaded
    /// ([`ResidentRays::upload_finish`]; empty before): the pass overwrites its records
    /// in place, so each timed pass starts from a copy of these.
    instructions: Vec<wgpu::Buffer>,
}

/// The memory-bound floor of the kernel's access pattern: each thread reads its ray's
/// 32-byte record and writes 32 bytes, and computes nothing. The kernel's time over
/// this one's is how far it is from the adapter's bandwidth bound.
const COPY_WGSL: &str = "
@group(0) @binding(1) var<storage, read> rays: array<vec4<f32>>;
@group(0) @binding(2) var<storage, read_write> results: array<vec4<f32>>;
@compute @workgroup_size(64)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    let i = 2u * id.x;
    if (i + 1u < arrayLength(&rays)) {
        results[i] = rays[i];
        results[i + 1u] = rays[i + 1u];
    }
}
";

/// One [`ResidentRays::run_finished`]: `repeats` times the kernel's pass, then the f64
/// finish pass over the same rays.
#[derive(Debug, Clone, PartialEq)]
pub struct FinishTime {
    /// Wall time from submission to completion, over all repeats of both passes (and the
    /// copies that restore the pass's instruction records before each repeat).
    pub wall: Duration,
    /// The device's time of each repeat's kernel pass; empty without timestamp queries.
    pub kernel: Vec<Duration>,
    /// The device's time of each repeat's f64 finish pass; empty without timestamp
    /// queries.
    pub finish: Vec<Duration>,
}

/// One [`ResidentRays::run`]: `repeats` dispatches over every resident ray.
#[derive(Debug, Clone, PartialEq)]
pub struct KernelTime {
    /// Wall time from submission to completion, over all repeats (it includes the
    /// submission's latency, which a large batch and several repeats amortise).
    pub wall: Duration,
    /// The device's own time of each repeat, from timestamps written at the start and
    /// end of its compute pass; empty when the adapter has no timestamp queries.
    pub device: Vec<Duration>,
}

impl KernelTime {
    /// ns of one pass over the batch: the mean of the device's timestamps where the
    /// adapter has them, else the submission's wall time over its `repeats` (which then
    /// includes the submission's latency).
    pub fn pass_ns(&self, repeats: usize) -> f64 {
        if self.device.is_empty() {
            self.wall.as_nanos() as f64 / repeats as f64
        } else {
            let total: Duration = self.device.iter().sum();
            total.as_nanos() as f64 / self.device.len() as f64
        }
    }
}

impl GpuIntersector {
    /// Packs `rays` for `torus` (as [`GpuIntersector::intersect`] does) and uploads them
    /// into buffers that stay on the device until the returned batch is dropped.
    pub fn upload(&self, torus: &Torus, rays: &[Ray]) -> Result<ResidentRays<'_>, GpuError> {
        let start = Instant::now();
        let frame = Frame::of(torus);
        let mut chunks = Vec::new();
        let mut counts = Vec::new();
        let mut surfaced = Vec::new();
        let mut shifts = Vec::with_capacity(rays.len());
        let mut host = Vec::new();
        for (k, batch) in rays.chunks(CHUNK).enumerate() {
            let buffers = self.buffers(batch.len());
            let packed: Vec<_> = batch.iter().map(|ray| frame.prepare(ray)).collect();
            for (i, p) in packed.iter().enumerate() {
                shifts.push(p.t0);
                if let Some(answer) = p.kernel_host() {
                    host.push((k * CHUNK + i, answer));
                }
            }
            let words: Vec<f32> = packed.iter().flat_map(|p| p.words).collect();
            self.queue
                .write_buffer(&buffers.input, 0, &as_bytes(&words));
            surfaced.push(upload_surfaces(self, &buffers, &packed));
            chunks.push(buffers);
            counts.push(batch.len());
        }
        let copy = self.copy_pipeline()?;
        self.queue.submit([]);
        self.device
            .poll(wgpu::PollType::wait_indefinitely())
            .map_err(|e| GpuError::Readback(e.to_string()))?;
        Ok(ResidentRays {
            gpu: self,
            frame,
            chunks,
            counts,
            surfaced,
            shifts,
            host,
            upload: start.elapsed(),
            copy,
            instructions: Vec::new(),
        })
    }

    /// [`COPY_WGSL`] compiled on the kernel's bind group layout.
    fn copy_pipeline(&self) -> Result<wgpu::ComputePipeline, GpuError> {
        let scope = self.device.push_error_scope(wgpu::ErrorFilter::Validation);
        let module = self
            .device
            .create_shader_module(wgpu::ShaderModuleDescriptor {
                label: Some("torus-cull copy"),
                // Resized as the kernel is, so that both take the same dispatch.
                source: wgpu::ShaderSource::Wgsl(
                    COPY_WGSL
                        .replacen(
                            &format!("@workgroup_size({WORKGROUP})"),
                            &format!("@workgroup_size({})", self.workgroup),
                            1,
                        )
                        .into(),
                ),
            });
        let layout = self
            .device
            .create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
                label: Some("torus-cull copy layout"),
                bind_group_layouts: &[Some(&self.layout)],
                immediate_size: 0,
            });
        let pipeline = self
            .device
            .create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
                label: Some("torus-cull copy pipeline"),
                layout: Some(&layout),
                module: &module,
                entry_point: Some("main"),
                compilation_options: Default::default(),
                cache: None,
            });
        if let Some(e) = pollster::block_on(scope.pop()) {
            return Err(GpuError::Kernel(e.to_string()));
        }
        Ok(pipeline)
    }

    /// Whether the adapter offers `SHADER_F64` (the device was opened with it where it
    /// does); [`GpuIntersector::finishes_on_device`] says whether the f64 pass also
    /// compiled and is on.
    pub fn has_shader_f64(&self) -> bool {
        self.device.features().contains(wgpu::Features::SHADER_F64)
    }

    /// The adapter's driver and its version string, as wgpu reports them (may be empty).
    pub fn driver(&self) -> String {
        format!("{} {}", self.info.driver, self.info.driver_info)
            .trim()
            .to_string()
    }

    /// Whether [`ResidentRays::run`] reports the device's own timestamps.
    pub fn has_timestamps(&self) -> bool {
        self.device
            .features()
            .contains(wgpu::Features::TIMESTAMP_QUERY)
    }
}

impl ResidentRays<'_> {
    /// Rays resident.
    pub fn len(&self) -> usize {
        self.shifts.len()
    }

    /// No rays resident.
    pub fn is_empty(&self) -> bool {
        self.shifts.is_empty()
    }

    /// Bytes the kernel reads and writes per ray (one record in, one out).
    pub const BYTES_PER_RAY: u64 = 2 * RAY_BYTES;

    /// Wall time of packing and uploading the rays.
    pub fn upload_time(&self) -> Duration {
        self.upload
    }

    /// Runs the kernel with `cull` over every resident ray `repeats` times (at least
    /// once), in one submission, and waits for it.
    pub fn run(&self, cull: GpuCull, repeats: usize) -> Result<KernelTime, GpuError> {
        self.write_params(cull);
        self.dispatch(&self.gpu.pipeline, repeats)
    }

    /// Runs the copy kernel (each ray's record read and written, nothing computed) over
    /// every resident ray `repeats` times: the memory-bound floor that [`ResidentRays::run`]
    /// is measured against. It overwrites the results of the last run.
    pub fn run_copy(&self, repeats: usize) -> Result<KernelTime, GpuError> {
        self.dispatch(&self.copy, repeats)
    }

    /// Uploads what the f64 finish pass reads of these rays (`rays` and `torus` must be
    /// the ones [`GpuIntersector::upload`] was given): the torus in f64, each ray's world
    /// record and the host's instruction, as
    /// [`GpuIntersector::intersect_finished_where`] sends them. Returns the wall time of
    /// preparing and uploading them (not in [`ResidentRays::upload_time`]). An error where
    /// the device has no f64 pass ([`GpuIntersector::finishes_on_device`]).
    pub fn upload_finish(&mut self, torus: &Torus, rays: &[Ray]) -> Result<Duration, GpuError> {
        let start = Instant::now();
        if let Some(why) = self.gpu.device_finish_unavailable() {
            return Err(GpuError::Kernel(format!(
                "no f64 finish pass on the device: {why}"
            )));
        }
        assert_eq!(rays.len(), self.len(), "the rays that were uploaded");
        let torus64 = finish::torus_bytes(torus);
        let mut instructions = Vec::with_capacity(self.chunks.len());
        for (buffers, batch) in self.chunks.iter().zip(rays.chunks(CHUNK)) {
            let fb = buffers
                .finish
                .as_ref()
                .ok_or_else(|| GpuError::Kernel("the f64 pass's buffers are missing".into()))?;
            let mut world: Vec<f32> = Vec::with_capacity(batch.len() * 8);
            let mut orders: Vec<f32> = Vec::with_capacity(batch.len() * 8);
            for ray in batch {
                let p = self.frame.prepare(ray);
                let (w, instruction) = finish::world_record(torus, ray, p.kernel_host());
                world.extend_from_slice(&w);
                orders.extend_from_slice(&finish::instruction_record(instruction));
            }
            let pristine = self.gpu.device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("torus-cull finish instructions"),
                size: batch.len() as u64 * RAY_BYTES,
                usage: wgpu::BufferUsages::COPY_SRC | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            });
            self.gpu.queue.write_buffer(&fb.torus, 0, &torus64);
            self.gpu.queue.write_buffer(&fb.world, 0, &as_bytes(&world));
            self.gpu
                .queue
                .write_buffer(&pristine, 0, &as_bytes(&orders));
            instructions.push(pristine);
        }
        self.gpu.queue.submit([]);
        self.gpu
            .device
            .poll(wgpu::PollType::wait_indefinitely())
            .map_err(|e| GpuError::Readback(e.to_string()))?;
        self.instructions = instructions;
        Ok(start.elapsed())
    }

    /// Runs, `repeats` times (at least once) in one submission, the kernel with `cull`
    /// over every resident ray and then the f64 finish pass over its records, as
    /// [`GpuIntersector::intersect_finished_where`] does; each repeat's finish pass starts
    /// from the instructions [`ResidentRays::upload_finish`] uploaded (restored by a copy
    /// outside both timed passes). Needs [`ResidentRays::upload_finish`] first.
    pub fn run_finished(&self, cull: GpuCull, repeats: usize) -> Result<FinishTime, GpuError> {
        let Ok(pass) = &self.gpu.finish else {
            return Err(GpuError::Kernel("no f64 finish pass on the device".into()));
        };
        if self.instructions.len() != self.chunks.len() {
            return Err(GpuError::Kernel(
                "run_finished before upload_finish: the f64 pass has no input".into(),
            ));
        }
        self.write_params(cull);
        let (wall, mut device) = self.submit(&self.gpu.pipeline, Some(&pass.pipeline), repeats)?;
        let finish = device.pop().unwrap_or_default();
        let kernel = device.pop().unwrap_or_default();
        Ok(FinishTime {
            wall,
            kernel,
            finish,
        })
    }

    /// Who answered each ray in the last [`ResidentRays::run_finished`], from the f64
    /// pass's records: proved by the f32 kernel, finished by the pass, or handed back to
    /// the host (the host's own answers, far origins and such, are counted where the pass
    /// put them).
    pub fn finish_counts(&self) -> Result<FinishCounts, GpuError> {
        let gpu = self.gpu;
        let mut counts = FinishCounts::default();
        let mut encoder = gpu
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                label: Some("torus-cull read back finished"),
            });
        let mut staged = Vec::new();
        for (buffers, &count) in self.chunks.iter().zip(&self.counts) {
            if let Some(fb) = &buffers.finish {
                let bytes = count as u64 * RAY_BYTES;
                encoder.copy_buffer_to_buffer(&fb.finished, 0, &fb.staging, 0, bytes);
                staged.push((&fb.staging, bytes));
            }
        }
        gpu.queue.submit([encoder.finish()]);
        for (staging, bytes) in staged {
            let slice = staging.slice(..bytes);
            gpu.map_read(&slice)?;
            {
                let view = slice
                    .get_mapped_range()
                    .map_err(|e| GpuError::Readback(format!("{e:?}")))?;
                for w in decode_records(&view) {
                    match Status::of(w[7]) {
                        Some(Status::Proved) => counts.proved += 1,
                        Some(Status::Front | Status::Back | Status::Miss) => counts.device += 1,
                        Some(Status::Host) | None => counts.host += 1,
                    }
                }
            }
            staging.unmap();
        }
        Ok(counts)
    }

    /// Writes each chunk's kernel parameters for an intersect pass with `cull`, before
    /// every timed run: the cull may differ from the last run's.
    fn write_params(&self, cull: GpuCull) {
        for ((buffers, &count), &surfaces) in
            self.chunks.iter().zip(&self.counts).zip(&self.surfaced)
        {
            self.gpu.queue.write_buffer(
                &buffers.params,
                0,
                &self
                    .frame
                    .params(count as u32, cull, Mode::Intersect, surfaces),
            );
        }
    }

    fn dispatch(
        &self,
        pipeline: &wgpu::ComputePipeline,
        repeats: usize,
    ) -> Result<KernelTime, GpuError> {
        let (wall, mut device) = self.submit(pipeline, None, repeats)?;
        Ok(KernelTime {
            wall,
            device: device.pop().unwrap_or_default(),
        })
    }

    /// `repeats` times `pipeline`'s pass over every chunk, each followed by the f64
    /// finish pass where `finish` is given (its instruction records restored first), in
    /// one submission; the wall time, and per pass (the kernel's, then the finish pass's)
    /// the device time of each repeat (empty lists without timestamp queries).
    fn submit(
        &self,
        pipeline: &wgpu::ComputePipeline,
        finish: Option<&wgpu::ComputePipeline>,
        repeats: usize,
    ) -> Result<(Duration, Vec<Vec<Duration>>), GpuError> {
        let gpu = self.gpu;
        let threads = gpu.workgroup as usize;
        let repeats = repeats.max(1);
        let passes = 1 + usize::from(finish.is_some());
        let queries = gpu.has_timestamps().then(|| {
            let n = 2 * (passes * repeats) as u32;
            let set = gpu.device.create_query_set(&wgpu::QuerySetDescriptor {
                label: Some("torus-cull timestamps"),
                ty: wgpu::QueryType::Timestamp,
                count: n,
            });
            let bytes = u64::from(n) * 8;
            let resolve = gpu.device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("torus-cull timestamps resolved"),
                size: bytes,
                usage: wgpu::BufferUsages::QUERY_RESOLVE | wgpu::BufferUsages::COPY_SRC,
                mapped_at_creation: false,
            });
            let read = gpu.device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("torus-cull timestamps read"),
                size: bytes,
                usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            });
            (set, resolve, read, n)
        });
        let mut encoder = gpu
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                label: Some("torus-cull timed dispatch"),
            });
        for rep in 0..repeats {
            let writes = |p: usize| {
                let k = 2 * (rep * passes + p) as u32;
                queries
                    .as_ref()
                    .map(|(set, ..)| wgpu::ComputePassTimestampWrites {
                        query_set: set,
                        beginning_of_pass_write_index: Some(k),
                        end_of_pass_write_index: Some(k + 1),
                    })
            };
            {
                let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                    label: Some("torus-cull timed pass"),
                    timestamp_writes: writes(0),
                });
                pass.set_pipeline(pipeline);
                for (buffers, &count) in self.chunks.iter().zip(&self.counts) {
                    pass.set_bind_group(0, &buffers.bind_group, &[]);
                    pass.dispatch_workgroups(count.div_ceil(threads) as u32, 1, 1);
                }
            }
            if let Some(finish) = finish {
                let mut targets = Vec::with_capacity(self.chunks.len());
                for ((buffers, &count), pristine) in
                    self.chunks.iter().zip(&self.counts).zip(&self.instructions)
                {
                    let fb = buffers.finish.as_ref().ok_or_else(|| {
                        GpuError::Kernel("the f64 pass's buffers are missing".into())
                    })?;
                    let bytes = count as u64 * RAY_BYTES;
                    encoder.copy_buffer_to_buffer(pristine, 0, &fb.finished, 0, bytes);
                    targets.push((fb, count));
                }
                let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                    label: Some("torus-cull timed f64 finish pass"),
                    timestamp_writes: writes(1),
                });
                pass.set_pipeline(finish);
                for (fb, count) in targets {
                    pass.set_bind_group(0, &fb.bind_group, &[]);
                    pass.dispatch_workgroups(count.div_ceil(WORKGROUP) as u32, 1, 1);
                }
            }
        }
        if let Some((set, resolve, read, n)) = &queries {
            encoder.resolve_query_set(set, 0..*n, resolve, 0);
            encoder.copy_buffer_to_buffer(resolve, 0, read, 0, u64::from(*n) * 8);
        }
        let start = Instant::now();
        gpu.queue.submit([encoder.finish()]);
        gpu.device
            .poll(wgpu::PollType::wait_indefinitely())
            .map_err(|e| GpuError::Readback(e.to_string()))?;
        let wall = start.elapsed();
        let mut device = vec![Vec::new(); passes];
        if let Some((_, _, read, _)) = &queries {
            let ticks = map_words(gpu, read)?;
            let period = f64::from(gpu.queue.get_timestamp_period());
            for (k, p) in ticks.chunks_exact(2).enumerate() {
                let d = Duration::from_nanos((p[1].saturating_sub(p[0]) as f64 * period) as u64);
                device[k % passes].push(d);
            }
        }
        Ok((wall, device))
    }

    /// The verdicts of the last [`ResidentRays::run`] (as [`GpuIntersector::explain`]
    /// gives them), and the wall time of copying them back.
    #[allow(clippy::type_complexity)]
    pub fn read_back(&self) -> Result<(Vec<(F32Verdict, Option<Escalation>)>, Duration), GpuError> {
        let gpu = self.gpu;
        let start = Instant::now();
        let mut out = Vec::with_capacity(self.len());
        let mut encoder = gpu
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                label: Some("torus-cull read back"),
            });
        for (buffers, &count) in self.chunks.iter().zip(&self.counts) {
            let bytes = count as u64 * RAY_BYTES;
            encoder.copy_buffer_to_buffer(&buffers.output, 0, &buffers.staging, 0, bytes);
        }
        gpu.queue.submit([encoder.finish()]);
        for (buffers, &count) in self.chunks.iter().zip(&self.counts) {
            let bytes = count as u64 * RAY_BYTES;
            let slice = buffers.staging.slice(..bytes);
            gpu.map_read(&slice)?;
            {
                let view = slice
                    .get_mapped_range()
                    .map_err(|e| GpuError::Readback(format!("{e:?}")))?;
                for w in decode_records(&view) {
                    let t0 = self.shifts[out.len()];
                    out.push(shifted(verdict(w), t0));
                }
            }
            buffers.staging.unmap();
        }
        for &(i, answer) in &self.host {
            out[i] = answer;
        }
        Ok((out, start.elapsed()))
    }
}

/// The u64 words of a mappable buffer.
fn map_words(gpu: &GpuIntersector, buffer: &wgpu::Buffer) -> Result<Vec<u64>, GpuError> {
    let slice = buffer.slice(..);
    gpu.map_read(&slice)?;
    let words = {
        let view = slice
            .get_mapped_range()
            .map_err(|e| GpuError::Readback(format!("{e:?}")))?;
        view.chunks_exact(8)
            .map(|b| u64::from_le_bytes(b.try_into().expect("8 bytes")))
            .collect()
    };
    buffer.unmap();
    Ok(words)
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec3;

    /// The resident path gives the same verdicts as the one-call path.
    #[test]
    fn resident_rays_give_the_same_verdicts_as_intersect() {
        let Ok(gpu) = GpuIntersector::new() else {
            eprintln!("no GPU adapter: skipped");
            return;
        };
        let torus = Torus::new(
            Vec3::new(0.5, -1.0, 2.0),
            Vec3::new(0.2, 1.0, 0.1),
            3.0,
            1.0,
        )
        .expect("valid torus");
        let rays: Vec<Ray> = (0..500)
            .map(|i| {
                let a = i as f32 * 0.37;
                let o = Vec3::new(8.0 * a.cos(), 3.0 * (a * 0.7).sin(), 8.0 * a.sin());
                let target = Vec3::new((a * 1.3).sin(), 0.2 * a.cos(), (a * 0.9).cos());
                Ray::new(o, target - o).expect("valid ray")
            })
            .collect();
        for cull in GpuCull::ALL {
            let want = gpu.explain(&torus, cull, &rays).expect("dispatch");
            let resident = gpu.upload(&torus, &rays).expect("upload");
            let time = resident.run(cull, 3).expect("run");
            let copy = resident.run_copy(2).expect("copy");
            assert!(copy.device.is_empty() || copy.device.len() == 2);
            resident.run(cull, 1).expect("run");
            assert!(time.device.is_empty() || time.device.len() == 3);
            let (got, _) = resident.read_back().expect("read back");
            assert_eq!(got, want, "{cull}");
            assert!(
                want.iter()
                    .any(|(v, _)| matches!(v, F32Verdict::Hit { .. }))
            );
        }
    }

    /// The timed kernel-and-finish run gives the answers the one-call path gives: as many
    /// rays finished on the device, handed to the host and proved by f32, repeat after
    /// repeat (each repeat's pass starts from the uploaded instructions).
    #[test]
    fn timed_finish_pass_counts_the_answers_of_intersect_finished() {
        let Ok(gpu) = GpuIntersector::new() else {
            eprintln!("no GPU adapter: skipped");
            return;
        };
        if !gpu.finishes_on_device() {
            eprintln!("no f64 pass on this adapter: skipped");
            return;
        }
        let torus = Torus::new(Vec3::ZERO, Vec3::Y, 3.0, 1.0).expect("valid torus");
        // Lines grazing the outer equator at ±1e-6, and some plain ones.
        let rays: Vec<Ray> = (0..600)
            .map(|i| {
                let b = i as f32 * 0.61;
                let tangent = Vec3::new(-b.sin(), 0.0, b.cos());
                let y = if i % 3 == 0 {
                    0.3
                } else {
                    1e-6 * (i % 2) as f32
                };
                let touch = Vec3::new(4.0 * b.cos(), y, 4.0 * b.sin());
                Ray::new(touch - 10.0 * tangent, tangent).expect("valid ray")
            })
            .collect();
        let want = FinishCounts::of(
            gpu.intersect_finished_where(&torus, GpuCull::NoCull, &rays)
                .expect("dispatch")
                .iter()
                .map(|(_, f)| f),
        );
        assert!(want.device > 0, "{want:?}");
        let mut resident = gpu.upload(&torus, &rays).expect("upload");
        assert!(resident.run_finished(GpuCull::NoCull, 1).is_err());
        resident
            .upload_finish(&torus, &rays)
            .expect("upload finish");
        let time = resident.run_finished(GpuCull::NoCull, 3).expect("run");
        assert!(time.finish.is_empty() || time.finish.len() == 3);
        assert_eq!(time.kernel.len(), time.finish.len());
        assert_eq!(resident.finish_counts().expect("read back"), want);
    }
}
