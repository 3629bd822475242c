//! Rays resident on the device for the scene kernel ([`SceneRays`]), so that the BVH
//! traversal can be timed without its transfers, as [`super::ResidentRays`] times the
//! single-torus kernel.
//!
//! [`GpuScene::trace`] prepares, uploads, dispatches and reads back in one call; a small
//! batch is then timed by its transfers and the submission's latency. Here
//! [`GpuScene::upload_rays`] (world rays) or [`GpuScene::upload_spawned`] (rays spawned on
//! a torus of the scene) prepares and uploads once, [`SceneRays::run`] dispatches the
//! traversal over every resident ray `repeats` times in one submission (closest or any
//! hit, any cull) with the device's timestamps around each pass where the adapter has
//! them, and [`SceneRays::closest_answers`] / [`SceneRays::any_answers`] read the last
//! run's answers back (the host finishing what the device left, as `trace` does).
//!
//! **In place.** The kernel overwrites each ray's record with its answer (it keeps the
//! kernel within four storage buffers). So every repeat starts with a copy of the
//! pristine records over the working ones, outside the timed compute pass: the device's
//! timestamps time the traversal alone; the wall clock (without timestamps) times both.
//!
//! **The floor** ([`SceneRays::run_copy`]): a kernel that reads every byte of each ray's
//! record (32 bytes a world ray, 144 a spawned one) and writes 32 bytes, as the traversal
//! does at least, and computes nothing: the traversal's time over the copy's is how far it
//! is from the bandwidth its own rays need (the nodes and tori it reads come on top).
//!
//! **One header per chunk.** The kernel reads its ray count, cull and mode from the node
//! buffer's header row; each chunk of at most [`CHUNK`] rays has its own copy of the
//! nodes, so that one compute pass can dispatch every chunk.

use super::scene::{CHUNK, GpuScene, Mode, Occlusion, SceneAnswer, any, closest, host};
use super::scene_kernel::Kernel;
use super::scene_spawned::{SPAWNED_WORDS, SpawnedRay};
use super::{Finished, GpuCull, GpuError, KernelTime, as_bytes, dispatch};
use crate::Ray;
use std::cell::Cell;
use std::time::{Duration, Instant};

/// The copy kernel: each thread reads the `STRIDE` vec4 of its ray's record and writes
/// two (their sums over even and odd places: for a 2-vec4 world record, the record
/// itself), computing nothing else.
const COPY_WGSL: &str = "
@group(0) @binding(0) var<storage, read> records: array<vec4<f32>>;
@group(0) @binding(1) var<storage, read_write> copied: array<vec4<f32>>;
@compute @workgroup_size(64)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    let i = id.x;
    if (2u * i + 1u >= arrayLength(&copied)) {
        return;
    }
    var even = vec4<f32>(0.0);
    var odd = vec4<f32>(0.0);
    for (var k = 0u; k < STRIDE; k += 2u) {
        even += records[STRIDE * i + k];
        if (k + 1u < STRIDE) {
            odd += records[STRIDE * i + k + 1u];
        }
    }
    copied[2u * i] = even;
    copied[2u * i + 1u] = odd;
}
";

/// The rays, as given: world rays, or rays spawned on a torus of the scene.
enum Given {
    World(Vec<Ray>),
    Spawned(Vec<SpawnedRay>),
}

/// One dispatch's worth of resident rays.
struct Chunk {
    count: usize,
    /// The scene's nodes behind this chunk's own header row.
    nodes: wgpu::Buffer,
    /// The records as prepared, copied over `rays` before each timed pass.
    pristine: wgpu::Buffer,
    /// The records the kernel reads and overwrites.
    rays: wgpu::Buffer,
    bind_group: wgpu::BindGroup,
    /// The copy kernel's output (32 bytes a ray; held beside the bind group that uses
    /// it) and its bind group.
    _copied: wgpu::Buffer,
    copy_group: wgpu::BindGroup,
}

/// A batch of rays prepared and uploaded once for [`GpuScene`]'s traversal, for timing it
/// alone.
pub struct SceneRays<'s> {
    scene: &'s GpuScene,
    given: Given,
    /// Words per record: 8 (world) or [`SPAWNED_WORDS`].
    words: usize,
    /// Per ray: whether the device traces it (else the host answers it: [`SceneBvh::prepare`]).
    ///
    /// [`SceneBvh::prepare`]: super::SceneBvh::prepare
    on_device: Vec<bool>,
    chunks: Vec<Chunk>,
    kernel: Kernel,
    copy: wgpu::ComputePipeline,
    upload: Duration,
    /// The mode of the last [`SceneRays::run`] (any hit or not); `None` before one.
    last: Cell<Option<bool>>,
}

impl GpuScene {
    /// Prepares `rays` ([`super::SceneBvh::prepare`]) and uploads them into buffers that
    /// stay on the device until the returned batch is dropped; a ray the host answers is
    /// sent as an empty range, as [`GpuScene::trace`] sends it.
    ///
    /// # Errors
    ///
    /// [`GpuError::Kernel`] where the copy kernel does not compile.
    pub fn upload_rays(&self, rays: &[Ray]) -> Result<SceneRays<'_>, GpuError> {
        let copy = CopyKernel::new(&self.device, 2)?;
        let start = Instant::now();
        let records: Vec<Option<[f32; 8]>> = rays.iter().map(|r| self.bvh.prepare(r)).collect();
        let kernel = self.kernel.clone();
        SceneRays::new(
            self,
            Given::World(rays.to_vec()),
            &records,
            kernel,
            copy,
            start,
        )
    }

    /// [`GpuScene::upload_rays`] for rays spawned on a torus of the scene, traced as
    /// [`GpuScene::trace_from`] traces them.
    ///
    /// # Errors
    ///
    /// [`GpuError::Scene`] for a ray whose torus is not in the scene (naming the ray);
    /// [`GpuError::Kernel`] where a kernel does not compile.
    pub fn upload_spawned(&self, rays: &[SpawnedRay]) -> Result<SceneRays<'_>, GpuError> {
        // Compiled before the clock starts: the upload time is the rays' alone.
        let kernel = Kernel::get(&self.kernels, &self.device, self.f64, "scene_from_main")?;
        let copy = CopyKernel::new(&self.device, SPAWNED_WORDS / 4)?;
        let start = Instant::now();
        let records = rays
            .iter()
            .enumerate()
            .map(|(k, r)| {
                self.bvh
                    .prepare_from(r)
                    .map_err(|e| GpuError::Scene(format!("spawned ray {k}: {e}")))
            })
            .collect::<Result<Vec<_>, _>>()?;
        let given = Given::Spawned(rays.to_vec());
        SceneRays::new(self, given, &records, kernel, copy, start)
    }

    /// Whether the device writes timestamps around each timed pass.
    pub fn has_timestamps(&self) -> bool {
        self.device
            .features()
            .contains(wgpu::Features::TIMESTAMP_QUERY)
    }
}

impl<'s> SceneRays<'s> {
    fn new<const N: usize>(
        scene: &'s GpuScene,
        given: Given,
        records: &[Option<[f32; N]>],
        kernel: Kernel,
        copy: CopyKernel,
        start: Instant,
    ) -> Result<SceneRays<'s>, GpuError> {
        use wgpu::BufferUsages as Use;
        let device = &scene.device;
        let node_bytes = scene.bvh.node_bytes();
        let placeholder = super::scene::placeholder::<N>();
        let mut chunks = Vec::new();
        for batch in records.chunks(CHUNK) {
            let words: Vec<f32> = batch
                .iter()
                .flat_map(|p| p.unwrap_or(placeholder))
                .collect();
            let bytes = as_bytes(&words);
            let size = bytes.len() as u64;
            let nodes = dispatch::buffer(
                device,
                "torus-cull timed scene nodes",
                node_bytes.len() as u64,
                Use::STORAGE | Use::COPY_DST,
            );
            scene.queue.write_buffer(&nodes, 0, &node_bytes);
            let pristine = dispatch::buffer(
                device,
                "torus-cull timed scene rays, as prepared",
                size,
                Use::STORAGE | Use::COPY_SRC | Use::COPY_DST,
            );
            scene.queue.write_buffer(&pristine, 0, &bytes);
            let rays = dispatch::buffer(
                device,
                "torus-cull timed scene rays",
                size,
                Use::STORAGE | Use::COPY_SRC | Use::COPY_DST,
            );
            scene.queue.write_buffer(&rays, 0, &bytes);
            let mut buffers = vec![&nodes, &scene.tori_buffer];
            buffers.extend(scene.tori64_buffer.as_ref());
            buffers.push(&rays);
            let bind_group = dispatch::bind_group(
                device,
                &kernel.layout,
                "torus-cull timed scene bind group",
                &buffers,
            );
            let copied = dispatch::buffer(
                device,
                "torus-cull scene copy kernel output",
                batch.len() as u64 * 32,
                Use::STORAGE,
            );
            let copy_group = dispatch::bind_group(
                device,
                &copy.layout,
                "torus-cull scene copy bind group",
                &[&pristine, &copied],
            );
            chunks.push(Chunk {
                count: batch.len(),
                nodes,
                pristine,
                rays,
                bind_group,
                _copied: copied,
                copy_group,
            });
        }
        scene.queue.submit([]);
        scene
            .device
            .poll(wgpu::PollType::wait_indefinitely())
            .map_err(|e| GpuError::Readback(e.to_string()))?;
        Ok(SceneRays {
            scene,
            given,
            words: N,
            on_device: records.iter().map(Option::is_some).collect(),
            chunks,
            kernel,
            copy: copy.pipeline,
            upload: start.elapsed(),
            last: Cell::new(None),
        })
    }

    /// Rays resident (those the host answers included).
    pub fn len(&self) -> usize {
        self.on_device.len()
    }

    /// No rays resident.
    pub fn is_empty(&self) -> bool {
        self.on_device.is_empty()
    }

    /// Rays the host answers without the device (an origin or direction out of the
    /// kernel's range, a surface ray given as a world ray: [`GpuScene`]'s module docs).
    pub fn host_rays(&self) -> usize {
        self.on_device.iter().filter(|&&d| !d).count()
    }

    /// Bytes of each ray's record the traversal reads (32 a world ray, 144 a spawned one)
    /// and writes (32): what [`SceneRays::run_copy`] moves per ray.
    pub fn bytes_per_ray(&self) -> u64 {
        self.words as u64 * 4 + 32
    }

    /// Wall time of preparing and uploading the rays.
    pub fn upload_time(&self) -> Duration {
        self.upload
    }

    /// Runs the traversal with `cull` at the leaves, closest hit or (`any_hit`) any hit,
    /// over every resident ray `repeats` times (at least once) in one submission, each
    /// repeat on the records as prepared, and waits for it.
    ///
    /// # Errors
    ///
    /// [`GpuError::Readback`] where the device cannot be waited for or its timestamps read.
    pub fn run(
        &self,
        cull: GpuCull,
        any_hit: bool,
        repeats: usize,
    ) -> Result<KernelTime, GpuError> {
        let mode = match (self.words == 8, any_hit) {
            (true, false) => Mode::Closest,
            (true, true) => Mode::Any,
            (false, false) => Mode::ClosestFrom,
            (false, true) => Mode::AnyFrom,
        };
        for c in &self.chunks {
            let header = [
                c.count as u32,
                cull.code(),
                mode as u32,
                self.scene.bvh.node_count(),
            ];
            let header: Vec<u8> = header.iter().flat_map(|w| w.to_le_bytes()).collect();
            self.scene.queue.write_buffer(&c.nodes, 0, &header);
        }
        self.last.set(Some(any_hit));
        self.submit(&self.kernel.pipeline, true, repeats)
    }

    /// Runs the copy kernel (module docs) over every resident ray `repeats` times: the
    /// bandwidth floor of the rays' own bytes. It leaves the last run's answers alone.
    ///
    /// # Errors
    ///
    /// As [`SceneRays::run`].
    pub fn run_copy(&self, repeats: usize) -> Result<KernelTime, GpuError> {
        self.submit(&self.copy, false, repeats)
    }

    /// `repeats` passes of `pipeline` over every chunk in one submission (each preceded by
    /// the pristine records' copy where `traversal`), with a timestamp pair around each
    /// pass where the device has them.
    fn submit(
        &self,
        pipeline: &wgpu::ComputePipeline,
        traversal: bool,
        repeats: usize,
    ) -> Result<KernelTime, GpuError> {
        let (device, queue) = (&self.scene.device, &self.scene.queue);
        let repeats = repeats.max(1);
        let queries = self.scene.has_timestamps().then(|| {
            let n = 2 * repeats as u32;
            let set = device.create_query_set(&wgpu::QuerySetDescriptor {
                label: Some("torus-cull scene timestamps"),
                ty: wgpu::QueryType::Timestamp,
                count: n,
            });
            let bytes = u64::from(n) * 8;
            use wgpu::BufferUsages as Use;
            let resolve = dispatch::buffer(
                device,
                "torus-cull scene timestamps resolved",
                bytes,
                Use::QUERY_RESOLVE | Use::COPY_SRC,
            );
            let read = dispatch::buffer(
                device,
                "torus-cull scene timestamps read",
                bytes,
                Use::MAP_READ | Use::COPY_DST,
            );
            (set, resolve, read, n)
        });
        let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
            label: Some("torus-cull timed scene"),
        });
        for rep in 0..repeats as u32 {
            if traversal {
                for c in &self.chunks {
                    let bytes = (c.count * self.words * 4) as u64;
                    encoder.copy_buffer_to_buffer(&c.pristine, 0, &c.rays, 0, bytes);
                }
            }
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                label: Some("torus-cull timed scene pass"),
                timestamp_writes: queries.as_ref().map(|(set, ..)| {
                    wgpu::ComputePassTimestampWrites {
                        query_set: set,
                        beginning_of_pass_write_index: Some(2 * rep),
                        end_of_pass_write_index: Some(2 * rep + 1),
                    }
                }),
            });
            pass.set_pipeline(pipeline);
            for c in &self.chunks {
                pass.set_bind_group(
                    0,
                    if traversal {
                        &c.bind_group
                    } else {
                        &c.copy_group
                    },
                    &[],
                );
                pass.dispatch_workgroups(c.count.div_ceil(64) as u32, 1, 1);
            }
        }
        if let Some((set, resolve, read, n)) = &queries {
            encoder.resolve_query_set(set, 0..*n, resolve, 0);
            encoder.copy_buffer_to_buffer(resolve, 0, read, 0, u64::from(*n) * 8);
        }
        let start = Instant::now();
        queue.submit([encoder.finish()]);
        device
            .poll(wgpu::PollType::wait_indefinitely())
            .map_err(|e| GpuError::Readback(e.to_string()))?;
        let wall = start.elapsed();
        let mut times = Vec::new();
        if let Some((_, _, read, _)) = &queries {
            let slice = read.slice(..);
            dispatch::map_read(device, &slice)?;
            let ticks: Vec<u64> = {
                let view = slice
                    .get_mapped_range()
                    .map_err(|e| GpuError::Readback(format!("{e:?}")))?;
                view.chunks_exact(8)
                    .map(|b| u64::from_le_bytes(b.try_into().expect("8 bytes")))
                    .collect()
            };
            read.unmap();
            let period = f64::from(queue.get_timestamp_period());
            times = ticks
                .chunks_exact(2)
                .map(|p| Duration::from_nanos((p[1].saturating_sub(p[0]) as f64 * period) as u64))
                .collect();
        }
        Ok(KernelTime {
            wall,
            device: times,
        })
    }

    /// Each ray's record from the device after the last run, `None` for the rays the host
    /// answers; an error before any run, or where the last run's mode is not `any_hit`.
    fn records(&self, any_hit: bool) -> Result<Vec<Option<[f32; 8]>>, GpuError> {
        match self.last.get() {
            None => {
                return Err(GpuError::Readback(
                    "no traversal has run on these rays yet".into(),
                ));
            }
            Some(last) if last != any_hit => {
                let name = |a: bool| if a { "any-hit" } else { "closest-hit" };
                return Err(GpuError::Readback(format!(
                    "the last run was {}, not {}",
                    name(last),
                    name(any_hit)
                )));
            }
            Some(_) => {}
        }
        let (device, queue) = (&self.scene.device, &self.scene.queue);
        let mut out = Vec::with_capacity(self.len());
        for c in &self.chunks {
            let bytes = (c.count * self.words * 4) as u64;
            let staging = dispatch::buffer(
                device,
                "torus-cull timed scene staging",
                bytes,
                wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
            );
            let mut encoder = device.create_command_encoder(&Default::default());
            encoder.copy_buffer_to_buffer(&c.rays, 0, &staging, 0, bytes);
            queue.submit([encoder.finish()]);
            let slice = staging.slice(..bytes);
            dispatch::map_read(device, &slice)?;
            {
                let view = slice
                    .get_mapped_range()
                    .map_err(|e| GpuError::Readback(format!("{e:?}")))?;
                let stride = self.words * 4;
                for record in view.chunks_exact(stride) {
                    let mut w = [0.0f32; 8];
                    for (k, b) in record[..32].chunks_exact(4).enumerate() {
                        w[k] = f32::from_le_bytes(b.try_into().expect("4 bytes"));
                    }
                    let i = out.len();
                    out.push(self.on_device[i].then_some(w));
                }
            }
            staging.unmap();
        }
        Ok(out)
    }

    /// The closest hits of the last run (a closest-hit one), the host finishing every ray
    /// the device did not prove, as [`GpuScene::trace`] and [`GpuScene::trace_from`] do.
    ///
    /// # Errors
    ///
    /// [`GpuError::Readback`] before any run, after an any-hit run, or where the records
    /// cannot be read.
    pub fn closest_answers(&self) -> Result<Vec<SceneAnswer>, GpuError> {
        let records = self.records(false)?;
        let bvh = &self.scene.bvh;
        match &self.given {
            Given::World(rays) => Ok(rays
                .iter()
                .zip(records)
                .map(|(ray, r)| closest(r).unwrap_or_else(|| host(bvh.host_trace(ray))))
                .collect()),
            Given::Spawned(rays) => rays
                .iter()
                .zip(records)
                .map(|(ray, r)| match closest(r) {
                    Some(answer) => Ok(answer),
                    None => Ok(host(bvh.host_trace_from(ray)?)),
                })
                .collect(),
        }
    }

    /// Whether each ray is blocked, from the last run (an any-hit one), the host finishing
    /// what the device did not prove, as [`GpuScene::occluded`] and
    /// [`GpuScene::occluded_from`] do.
    ///
    /// # Errors
    ///
    /// As [`SceneRays::closest_answers`], after a closest-hit run.
    pub fn any_answers(&self) -> Result<Vec<Occlusion>, GpuError> {
        let records = self.records(true)?;
        let bvh = &self.scene.bvh;
        let by_host = |occluded| Occlusion {
            occluded,
            by: Finished::Host,
        };
        match &self.given {
            Given::World(rays) => Ok(rays
                .iter()
                .zip(records)
                .map(|(ray, r)| any(r).unwrap_or_else(|| by_host(bvh.host_occluded(ray))))
                .collect()),
            Given::Spawned(rays) => rays
                .iter()
                .zip(records)
                .map(|(ray, r)| match any(r) {
                    Some(answer) => Ok(answer),
                    None => Ok(by_host(bvh.host_occluded_from(ray)?)),
                })
                .collect(),
        }
    }
}

/// The copy kernel compiled for records of some number of vec4, and its bindings.
struct CopyKernel {
    pipeline: wgpu::ComputePipeline,
    layout: wgpu::BindGroupLayout,
}

impl CopyKernel {
    /// [`COPY_WGSL`] for records of `stride` vec4, or the validation error in words.
    fn new(device: &wgpu::Device, stride: usize) -> Result<CopyKernel, GpuError> {
        let layout = copy_layout(device);
        let pipeline = copy_pipeline(device, &layout, stride)?;
        Ok(CopyKernel { pipeline, layout })
    }
}

/// The copy kernel's bindings: the records (read) and its output.
fn copy_layout(device: &wgpu::Device) -> wgpu::BindGroupLayout {
    use wgpu::BufferBindingType as B;
    let entries: Vec<wgpu::BindGroupLayoutEntry> = [
        B::Storage { read_only: true },
        B::Storage { read_only: false },
    ]
    .into_iter()
    .zip(0..)
    .map(|(ty, binding)| wgpu::BindGroupLayoutEntry {
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
    device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some("torus-cull scene copy bindings"),
        entries: &entries,
    })
}

/// [`COPY_WGSL`] for records of `stride` vec4, or the validation error in words.
fn copy_pipeline(
    device: &wgpu::Device,
    layout: &wgpu::BindGroupLayout,
    stride: usize,
) -> Result<wgpu::ComputePipeline, GpuError> {
    let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
    let source = format!("const STRIDE: u32 = {stride}u;\n{COPY_WGSL}");
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("torus-cull scene copy"),
        source: wgpu::ShaderSource::Wgsl(source.into()),
    });
    let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
        label: Some("torus-cull scene copy layout"),
        bind_group_layouts: &[Some(layout)],
        immediate_size: 0,
    });
    let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
        label: Some("torus-cull scene copy pipeline"),
        layout: Some(&pipeline_layout),
        module: &module,
        entry_point: Some("main"),
        compilation_options: Default::default(),
        cache: None,
    });
    if let Some(e) = pollster::block_on(scope.pop()) {
        return Err(GpuError::Kernel(format!("the scene copy kernel: {e}")));
    }
    Ok(pipeline)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Torus;
    use glam::Vec3;

    /// The resident path answers as the one-call path does, closest and any hit, for
    /// world and spawned rays, run after run (each repeat starts from the records as
    /// prepared); the copy kernel runs; answers before a run or of the other mode are
    /// refused.
    #[test]
    fn resident_scene_rays_answer_as_trace_and_occluded() {
        let Ok(gpu) = super::super::GpuIntersector::new() else {
            eprintln!("no GPU adapter: skipped");
            return;
        };
        let tori: Vec<Torus> = (0..12)
            .map(|i| {
                let c = Vec3::new((i % 4) as f32 * 6.0, (i / 4) as f32 * 6.0, 0.0);
                Torus::new(c, Vec3::new(0.1, 0.3, 1.0), 2.0, 0.5).expect("valid torus")
            })
            .collect();
        let scene = GpuScene::new(&gpu, &tori).expect("scene");
        let rays: Vec<Ray> = (0..150)
            .map(|k| {
                let (x, y) = ((k % 15) as f32 * 1.4 - 2.0, (k / 15) as f32 * 1.4 - 2.0);
                Ray::new(Vec3::new(x, y, 20.0), Vec3::new(0.01, 0.02, -1.0)).expect("valid ray")
            })
            .collect();
        let resident = scene.upload_rays(&rays).expect("upload");
        assert!(resident.closest_answers().is_err(), "before a run");
        let want = scene.trace(GpuCull::Skala, &rays).expect("trace");
        assert!(want.iter().any(|a| a.hit.is_some()));
        resident.run(GpuCull::Skala, false, 3).expect("run");
        assert!(resident.any_answers().is_err(), "after a closest-hit run");
        assert_eq!(resident.closest_answers().expect("read"), want);
        let copy = resident.run_copy(2).expect("copy");
        assert!(copy.device.is_empty() || copy.device.len() == 2);
        resident.run(GpuCull::NoCull, true, 2).expect("run");
        let occluded = scene.occluded(GpuCull::NoCull, &rays).expect("occluded");
        assert_eq!(resident.any_answers().expect("read"), occluded);
        // Spawned: a ray back up from every hit, on its torus.
        let spawned: Vec<SpawnedRay> = rays
            .iter()
            .zip(&want)
            .filter_map(|(ray, a)| {
                let h = a.hit?;
                let ray = tori[h.torus as usize].spawn(ray, h.t, Vec3::Z).ok()?;
                Some(SpawnedRay { ray, from: h.torus })
            })
            .collect();
        assert!(!spawned.is_empty());
        let resident = scene.upload_spawned(&spawned).expect("upload spawned");
        assert_eq!(resident.bytes_per_ray(), SPAWNED_WORDS as u64 * 4 + 32);
        resident.run(GpuCull::Cychosz, false, 2).expect("run");
        let want = scene
            .trace_from(GpuCull::Cychosz, &spawned)
            .expect("trace_from");
        assert_eq!(resident.closest_answers().expect("read"), want);
        resident.run(GpuCull::Cychosz, true, 1).expect("run");
        let want = scene
            .occluded_from(GpuCull::Cychosz, &spawned)
            .expect("occluded_from");
        assert_eq!(resident.any_answers().expect("read"), want);
        resident.run_copy(1).expect("copy");
    }
}
