//! Tori in a GPU BVH ([`GpuScene`]): a WGSL compute traversal of an obvhs BVH2 over ring
//! tori, with a cull and the certified f32 intersection at each leaf, closest hit and any
//! hit (shadow rays with a `t_max`).
//!
//! **Why BVH2.** obvhs builds BVH2 and CWBVH. CWBVH traverses incoherent rays about 2×
//! faster than the earlier binary traversal on NVIDIA hardware (Ylitie et al., HPG 2017),
//! but needs 8-wide compressed node decoding and an octant-ordered hit mask in WGSL; the
//! binary tree with a fixed stack is the simplest traversal to prove conservative, and
//! the first one to get right (docs/gpu.md, "Tori in a GPU BVH").
//!
//! **Layout** (storage buffers, none uniform: lavapipe recompiles a kernel per change of
//! an inlined uniform value, `wgsl/kernel.wgsl`):
//! - nodes (`TorusSceneNodes`): a 16-byte header row `(rays, cull, mode, nodes)` as
//!   `u32` (the library kernel's; a renderer leaves it zero), a reserved row, then one
//!   32-byte node per BVH2 node, the root first: `(lo.xyz, count)` and `(hi.xyz, index)`,
//!   `count` 0 for an inner node (children at `index`, `index + 1`), 1 for a leaf
//!   (`index` the torus's index: the tree is built with one torus a leaf, so the kernel
//!   needs no primitive-index buffer). The boxes are obvhs's, over [`Torus::world_aabb`]
//!   (rounded outward to f32).
//! - tori (`TorusSceneTorus`, 128 bytes each): the f32 module's `TorusParams`
//!   ([`super::ModuleTorus::params`]) and `(centre, R + r)`.
//! - tori in f64 (`TorusParams64`, 136 bytes each, [`super::ModuleTorus::params64`]):
//!   only where the device finishes in f64.
//! - rays, read and overwritten in place: in, `(o, t_min)`, `(d, t_max)` with the range
//!   clipped on the host to where the scene's bounding sphere is (finite ends); out,
//!   `(t, n.xyz)` and `(torus, status, f64 leaves, leaves)` as f32.
//!
//! **The kernel** (`wgsl/scene.wgsl`) pops a node, tests its box against `[t_min, the
//! nearest hit so far]` (a slab test widened by 2⁻¹⁸ of each slab's size, so no box a
//! true hit lies in is skipped), pushes an inner node's children (the nearer last) and
//! at a leaf runs the f32 module on `o − c` with the range clipped to the torus's reach.
//! A leaf it cannot prove goes to the f64 finish on the device (`wgsl/scene_f64.wgsl`)
//! where the adapter has `SHADER_F64`; otherwise, or where that hands it back, the leaf
//! stays unproved, the walk goes on, and the ray's answer is the host's (the f64 path
//! over the BVH's candidates: [`SceneBvh::host_trace`]). An unproved leaf is never taken
//! for a miss, and a closest-hit walk never stops early: it ends when the stack is empty.
//!
//! **What the host answers itself** (counted as [`Finished::Host`]): a ray from a surface
//! point ([`Ray::from_surface`]: its own torus needs the surface path, not yet in the
//! kernel); an origin with a coordinate beyond [`super::MAX_COORDINATE`], a direction whose
//! largest component is outside [`DIRECTION_RANGE`], or a range the bounding sphere
//! cannot clip to finite f32 (the slab test's products stay finite within those).

use super::scene_bvh::{STATUS_HIT, STATUS_MISS};
use super::{Finished, GpuCull, GpuError, GpuIntersector, SceneBvh, SceneHit, as_bytes};
use crate::{Ray, Torus};
use glam::Vec3;

/// Rays per dispatch (32 bytes each, in place).
const CHUNK: usize = 1 << 18;

/// A closest-hit answer and who gave it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SceneAnswer {
    /// The nearest hit in the ray's range, or `None`.
    pub hit: Option<SceneHit>,
    /// [`Finished::Proved`]: every leaf proved in f32 on the device; [`Finished::Device`]:
    /// some leaf finished by the device's f64; [`Finished::Host`]: the host's f64 path.
    pub by: Finished,
}

/// An any-hit (shadow ray) answer and who gave it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Occlusion {
    /// Some torus is hit within the ray's range.
    pub occluded: bool,
    /// Who gave the answer, as in [`SceneAnswer::by`].
    pub by: Finished,
}

/// Tori in a BVH on the device, ready to trace batches of rays.
pub struct GpuScene {
    bvh: SceneBvh,
    f64: bool,
    device: wgpu::Device,
    queue: wgpu::Queue,
    pipeline: wgpu::ComputePipeline,
    layout: wgpu::BindGroupLayout,
    node_buffer: wgpu::Buffer,
    tori_buffer: wgpu::Buffer,
    tori64_buffer: Option<wgpu::Buffer>,
    /// One dispatch at a time: each writes its header row into the node buffer before it
    /// submits, so two threads' writes and submissions must not interleave.
    dispatching: std::sync::Mutex<()>,
}

impl std::fmt::Debug for GpuScene {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("GpuScene")
            .field("bvh", &self.bvh)
            .field("f64", &self.f64)
            .finish_non_exhaustive()
    }
}

/// The library's scene kernel: [`wgsl_scene_module`] at group 0 and `wgsl/scene_kernel.wgsl`.
pub(crate) fn kernel_source(f64: bool) -> String {
    let rays = if f64 { 3 } else { 2 };
    format!(
        "{}\n@group(0) @binding({rays}) var<storage, read_write> torus_scene_rays: array<vec4<f32>>;\n{}",
        super::wgsl_scene_module(0, f64),
        super::scene_bvh::SCENE_FILES[3].1
    )
}

impl GpuScene {
    /// Builds an obvhs BVH2 over `tori` (one torus a leaf) on the host and uploads it to
    /// `gpu`'s device, with the kernel compiled: in f64 where `gpu` finishes on the
    /// device ([`GpuIntersector::finishes_on_device`]), else escalated leaves go to the
    /// host.
    ///
    /// # Errors
    ///
    /// [`GpuError::Scene`] for no tori, more than 2²⁴, a box coordinate beyond
    /// [`super::MAX_COORDINATE`], or a tree deeper than the kernel's stack ([`super::STACK`]);
    /// [`GpuError::Kernel`] where the kernel does not compile.
    pub fn new(gpu: &GpuIntersector, tori: &[Torus]) -> Result<GpuScene, GpuError> {
        let bvh = SceneBvh::new(tori)?;
        let f64 = gpu.finishes_on_device();
        let device = gpu.device.clone();
        let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
        use wgpu::BufferBindingType as B;
        let mut bindings = vec![B::Storage { read_only: true }; if f64 { 3 } else { 2 }];
        bindings.push(B::Storage { read_only: false });
        let (pipeline, layout) = super::compute_pipeline(
            &device,
            "torus-cull scene",
            kernel_source(f64),
            &bindings,
            "scene_main",
        );
        if let Some(e) = pollster::block_on(scope.pop()) {
            return Err(GpuError::Kernel(format!("the scene kernel: {e}")));
        }
        let mut scene = GpuScene {
            bvh,
            f64,
            queue: gpu.queue.clone(),
            pipeline,
            layout,
            node_buffer: storage(&device, "torus-cull scene nodes", 0),
            tori_buffer: storage(&device, "torus-cull scene tori", 0),
            tori64_buffer: None,
            dispatching: std::sync::Mutex::new(()),
            device,
        };
        scene.node_buffer = scene.upload("torus-cull scene nodes", &scene.bvh.node_bytes());
        scene.tori_buffer = scene.upload("torus-cull scene tori", &scene.bvh.tori_bytes());
        if f64 {
            scene.tori64_buffer =
                Some(scene.upload("torus-cull scene tori f64", &scene.bvh.tori64_bytes()));
        }
        Ok(scene)
    }

    fn upload(&self, label: &str, bytes: &[u8]) -> wgpu::Buffer {
        let buffer = storage(&self.device, label, bytes.len() as u64);
        self.queue.write_buffer(&buffer, 0, bytes);
        buffer
    }

    /// Whether unproved leaves are finished in f64 on the device (else on the host).
    pub fn finishes_on_device(&self) -> bool {
        self.f64
    }

    /// The nearest hit of each ray over every torus, with `cull` at the leaves: hit or
    /// miss and torus as [`crate::intersect()`] over all tori, t within the tolerance of
    /// [`SceneHit::t`].
    ///
    /// # Errors
    ///
    /// [`GpuError::Readback`] where the device's results cannot be read.
    pub fn trace(&self, cull: GpuCull, rays: &[Ray]) -> Result<Vec<SceneAnswer>, GpuError> {
        let records = self.dispatch(cull, Mode::Closest, rays)?;
        Ok(rays
            .iter()
            .zip(records)
            .map(|(ray, record)| match record {
                Some(r) if r[5] == STATUS_HIT as f32 && r[4] >= 0.0 => SceneAnswer {
                    hit: Some(SceneHit {
                        torus: r[4] as u32,
                        t: r[0],
                        normal: Vec3::new(r[1], r[2], r[3]),
                    }),
                    by: device_by(&r),
                },
                Some(r) if r[5] == STATUS_MISS as f32 => SceneAnswer {
                    hit: None,
                    by: device_by(&r),
                },
                _ => SceneAnswer {
                    hit: self.bvh.host_trace(ray),
                    by: Finished::Host,
                },
            })
            .collect())
    }

    /// Whether any torus blocks each ray within its range (shadow rays), with `cull` at
    /// the leaves; the walk stops at the first proved hit.
    ///
    /// # Errors
    ///
    /// As [`GpuScene::trace`].
    pub fn occluded(&self, cull: GpuCull, rays: &[Ray]) -> Result<Vec<Occlusion>, GpuError> {
        let records = self.dispatch(cull, Mode::Any, rays)?;
        Ok(rays
            .iter()
            .zip(records)
            .map(|(ray, record)| match record {
                Some(r) if r[5] == STATUS_HIT as f32 || r[5] == STATUS_MISS as f32 => Occlusion {
                    occluded: r[5] == STATUS_HIT as f32,
                    by: device_by(&r),
                },
                _ => Occlusion {
                    occluded: self.bvh.host_occluded(ray),
                    by: Finished::Host,
                },
            })
            .collect())
    }

    /// One record per ray from the kernel, `None` for a ray the host answers.
    fn dispatch(
        &self,
        cull: GpuCull,
        mode: Mode,
        rays: &[Ray],
    ) -> Result<Vec<Option<[f32; 8]>>, GpuError> {
        let _one_at_a_time = self.dispatching.lock().unwrap_or_else(|e| e.into_inner());
        let mut out = Vec::with_capacity(rays.len());
        for batch in rays.chunks(CHUNK) {
            let prepared: Vec<Option<[f32; 8]>> =
                batch.iter().map(|r| self.bvh.prepare(r)).collect();
            let words: Vec<f32> = prepared
                .iter()
                .flat_map(|p| p.unwrap_or([0.0, 0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 0.0]))
                .collect();
            let bytes = as_bytes(&words);
            let size = bytes.len() as u64;
            use wgpu::BufferUsages as Use;
            let rays_buffer = self.device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("torus-cull scene rays"),
                size,
                usage: Use::STORAGE | Use::COPY_DST | Use::COPY_SRC,
                mapped_at_creation: false,
            });
            let staging = self.device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("torus-cull scene staging"),
                size,
                usage: Use::MAP_READ | Use::COPY_DST,
                mapped_at_creation: false,
            });
            self.queue.write_buffer(&rays_buffer, 0, &bytes);
            let header = [
                batch.len() as u32,
                cull.code(),
                mode as u32,
                self.bvh.node_count(),
            ];
            let header: Vec<u8> = header.iter().flat_map(|w| w.to_le_bytes()).collect();
            self.queue.write_buffer(&self.node_buffer, 0, &header);
            let mut buffers = vec![&self.node_buffer, &self.tori_buffer];
            buffers.extend(self.tori64_buffer.as_ref());
            buffers.push(&rays_buffer);
            let entries: Vec<wgpu::BindGroupEntry> = buffers
                .iter()
                .zip(0..)
                .map(|(b, binding)| wgpu::BindGroupEntry {
                    binding,
                    resource: b.as_entire_binding(),
                })
                .collect();
            let bind_group = self.device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some("torus-cull scene bind group"),
                layout: &self.layout,
                entries: &entries,
            });
            let mut encoder = self
                .device
                .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                    label: Some("torus-cull scene"),
                });
            {
                let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                    label: Some("torus-cull scene pass"),
                    timestamp_writes: None,
                });
                pass.set_pipeline(&self.pipeline);
                pass.set_bind_group(0, &bind_group, &[]);
                pass.dispatch_workgroups(batch.len().div_ceil(64) as u32, 1, 1);
            }
            encoder.copy_buffer_to_buffer(&rays_buffer, 0, &staging, 0, size);
            self.queue.submit([encoder.finish()]);
            let slice = staging.slice(..);
            super::map_read(&self.device, &slice)?;
            {
                let view = slice
                    .get_mapped_range()
                    .map_err(|e| GpuError::Readback(format!("{e:?}")))?;
                let records = super::decode_records(&view);
                out.extend(prepared.iter().zip(records).map(|(p, r)| p.map(|_| r)));
            }
            staging.unmap();
        }
        Ok(out)
    }

    /// The BVH and its host side ([`SceneBvh::host_trace`], the buffers' bytes).
    pub fn bvh(&self) -> &SceneBvh {
        &self.bvh
    }
}

#[derive(Debug, Clone, Copy)]
enum Mode {
    Closest = 0,
    Any = 1,
}

/// Who answered a ray the device answered.
fn device_by(record: &[f32; 8]) -> Finished {
    if record[6] > 0.0 {
        Finished::Device
    } else {
        Finished::Proved
    }
}

fn storage(device: &wgpu::Device, label: &str, size: u64) -> wgpu::Buffer {
    device.create_buffer(&wgpu::BufferDescriptor {
        label: Some(label),
        size: size.max(16),
        usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    })
}
