//! Tori in a GPU BVH ([`GpuScene`]): a WGSL compute traversal of an obvhs BVH2 over ring
//! tori, with a cull and the certified f32 intersection at each leaf, closest hit and any
//! hit (shadow rays with a `t_max`), for world rays and for secondary rays spawned on a
//! torus of the scene ([`SpawnedRay`], `scene_spawned.rs`).
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
//!   clipped on the host to where the scene's bounding sphere is (finite ends), and for a
//!   spawned ray (`scene_from_main`) its `TorusSceneOwn` after them
//!   ([`SceneBvh::prepare_from`], [`SPAWNED_WORDS`] words a ray in all); out, `(t, n.xyz)`
//!   and `(torus, status, f64 leaves, leaves)` as f32 over the ray's first 8 words.
//!
//! **The kernel** (`wgsl/scene.wgsl`) pops a node, tests its box against `[t_min, the
//! nearest hit so far]` (a slab test widened by 2⁻¹⁸ of each slab's size, so no box a
//! true hit lies in is skipped), pushes an inner node's children (the nearer last) and
//! at a leaf runs the f32 module with the range clipped to the torus's reach, on the ray
//! as the single-torus host packs it ([`super::Frame`]'s `pack`): where the shader has f64,
//! `o − c` from the f64 centre and a far origin moved to its foot point, in f64 on the
//! device (`wgsl/scene_f64.wgsl`), else `o − c` in f32 (`wgsl/scene_host.wgsl`); a spawned
//! ray's own torus runs the module's surface path on the host's record. A leaf it cannot
//! prove goes to the f64 finish on the device (`wgsl/scene_f64.wgsl`)
//! where the adapter has `SHADER_F64`; otherwise, or where that hands it back, the leaf
//! stays unproved, the walk goes on, and the ray's answer is the host's (the f64 path
//! over the BVH's candidates: [`SceneBvh::host_trace`]). An unproved leaf is never taken
//! for a miss, and a closest-hit walk never stops early: it ends when the stack is empty.
//!
//! **What the host answers itself** (counted as [`Finished::Host`]): a ray from a surface
//! point given without its torus ([`Ray::from_surface`] names no shape: [`GpuScene::trace`]
//! answers it as [`crate::intersect()`] over every torus would); an origin with a coordinate beyond [`super::MAX_COORDINATE`], a direction whose
//! largest component is outside [`DIRECTION_RANGE`], or a range the bounding sphere
//! cannot clip to finite f32 (the slab test's products stay finite within those).

use super::scene_bvh::{STATUS_HIT, STATUS_MISS};
use super::scene_kernel::{Kernel, Kernels};
use super::scene_spawned::{SPAWNED_WORDS, SpawnedRay};
use super::{Finished, GpuCull, GpuError, GpuIntersector, SceneBvh, SceneHit, as_bytes};
use crate::{Ray, Torus};
use glam::Vec3;

/// Rays per dispatch (32 bytes each, in place).
pub(super) const CHUNK: usize = 1 << 18;

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
    pub(super) bvh: SceneBvh,
    pub(super) f64: bool,
    pub(super) device: wgpu::Device,
    pub(super) queue: wgpu::Queue,
    /// `scene_main`, for world rays.
    pub(super) kernel: Kernel,
    /// The device's compiled scene kernels: `scene_from_main`, for spawned rays, is
    /// compiled on the first [`GpuScene::trace_from`] or [`GpuScene::occluded_from`] on
    /// the device (the surface path makes it the larger kernel).
    pub(super) kernels: Kernels,
    node_buffer: wgpu::Buffer,
    pub(super) tori_buffer: wgpu::Buffer,
    pub(super) tori64_buffer: Option<wgpu::Buffer>,
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
        let kernels = gpu.scene_kernels.clone();
        let kernel = Kernel::get(&kernels, &device, f64, "scene_main")?;
        let mut scene = GpuScene {
            bvh,
            f64,
            queue: gpu.queue.clone(),
            kernel,
            kernels,
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

    /// [`GpuScene::new`] over members of the torus family: the circular ring members
    /// ([`SceneBvh::from_family`]).
    ///
    /// # Errors
    ///
    /// [`GpuError::Member`] for a member that is not a circular ring torus (its index and
    /// why); then as [`GpuScene::new`].
    pub fn from_family(
        gpu: &GpuIntersector,
        members: &[crate::family::Toroid],
    ) -> Result<GpuScene, GpuError> {
        GpuScene::new(gpu, &super::scene_bvh::ring_tori(members)?)
    }

    fn upload(&self, label: &str, bytes: &[u8]) -> wgpu::Buffer {
        let buffer = storage(&self.device, label, bytes.len() as u64);
        self.queue.write_buffer(&buffer, 0, bytes);
        buffer
    }

    /// A storage buffer the kernel writes, holding `bytes`, that can be copied out.
    fn upload_rw(&self, label: &str, bytes: &[u8]) -> wgpu::Buffer {
        use wgpu::BufferUsages as Use;
        let usage = Use::STORAGE | Use::COPY_DST | Use::COPY_SRC;
        let buffer = super::dispatch::buffer(&self.device, label, bytes.len() as u64, usage);
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
    /// A ray from a surface point ([`Ray::from_surface`]) is answered on the host, its
    /// mark seen by every torus (as [`crate::intersect()`] over all tori sees it): name the
    /// torus it starts on with [`GpuScene::trace_from`] to trace it on the device.
    ///
    /// # Errors
    ///
    /// [`GpuError::Readback`] where the device's results cannot be read.
    pub fn trace(&self, cull: GpuCull, rays: &[Ray]) -> Result<Vec<SceneAnswer>, GpuError> {
        let records = self.dispatch(cull, Mode::Closest, &self.prepare(rays))?;
        device_or_host(rays, records, closest, |ray| {
            Ok(host(self.bvh.host_trace(ray)))
        })
    }

    /// The nearest hit of each secondary ray ([`SpawnedRay`]: spawned on a torus of the
    /// scene): its own torus on the surface path (the module's
    /// `torus_intersect_from_surface`, its origin's root divided out), every other on the
    /// literal ray, as the CPU's brute force over the scene answers it
    /// ([`SceneBvh::host_trace_from`]).
    ///
    /// # Errors
    ///
    /// [`GpuError::Scene`] for a ray whose torus is not in the scene (naming the ray);
    /// [`GpuError::Readback`] where the device's results cannot be read.
    pub fn trace_from(
        &self,
        cull: GpuCull,
        rays: &[SpawnedRay],
    ) -> Result<Vec<SceneAnswer>, GpuError> {
        let records = self.dispatch(cull, Mode::ClosestFrom, &self.prepare_from(rays)?)?;
        device_or_host(rays, records, closest, |ray| {
            Ok(host(self.bvh.host_trace_from(ray)?))
        })
    }

    /// Whether any torus blocks each ray within its range (shadow rays), with `cull` at
    /// the leaves; the walk stops at the first proved hit. A ray from a surface point is
    /// answered on the host, as in [`GpuScene::trace`] ([`GpuScene::occluded_from`] traces
    /// it on the device).
    ///
    /// # Errors
    ///
    /// As [`GpuScene::trace`].
    pub fn occluded(&self, cull: GpuCull, rays: &[Ray]) -> Result<Vec<Occlusion>, GpuError> {
        let records = self.dispatch(cull, Mode::Any, &self.prepare(rays))?;
        device_or_host(rays, records, any, |ray| {
            Ok(host_occlusion(self.bvh.host_occluded(ray)))
        })
    }

    /// [`GpuScene::occluded`] of secondary rays (shadow rays from a hit): the own torus on
    /// the surface path, every other on the literal ray ([`SceneBvh::host_occluded_from`]).
    ///
    /// # Errors
    ///
    /// As [`GpuScene::trace_from`].
    pub fn occluded_from(
        &self,
        cull: GpuCull,
        rays: &[SpawnedRay],
    ) -> Result<Vec<Occlusion>, GpuError> {
        let records = self.dispatch(cull, Mode::AnyFrom, &self.prepare_from(rays)?)?;
        device_or_host(rays, records, any, |ray| {
            Ok(host_occlusion(self.bvh.host_occluded_from(ray)?))
        })
    }

    /// Each world ray's kernel record (`None` for a ray the host answers).
    fn prepare(&self, rays: &[Ray]) -> Vec<Option<[f32; 8]>> {
        rays.iter().map(|r| self.bvh.prepare(r)).collect()
    }

    /// Each spawned ray's kernel record, the error naming the first ray whose torus is not
    /// in the scene.
    fn prepare_from(
        &self,
        rays: &[SpawnedRay],
    ) -> Result<Vec<Option<[f32; SPAWNED_WORDS]>>, GpuError> {
        rays.iter()
            .enumerate()
            .map(|(k, r)| {
                self.bvh
                    .prepare_from(r)
                    .map_err(|e| GpuError::Scene(format!("spawned ray {k}: {e}")))
            })
            .collect()
    }

    /// One record `(t, n.xyz, torus, status, f64 leaves, leaves)` per ray from the
    /// kernel, `None` for a ray the host answers (`records[k]` is `None`); each record in
    /// is `N` words (8: a world ray; [`SPAWNED_WORDS`]: a spawned ray).
    fn dispatch<const N: usize>(
        &self,
        cull: GpuCull,
        mode: Mode,
        records: &[Option<[f32; N]>],
    ) -> Result<Vec<Option<[f32; 8]>>, GpuError> {
        let kernel = match mode {
            Mode::Closest | Mode::Any => self.kernel.clone(),
            Mode::ClosestFrom | Mode::AnyFrom => {
                Kernel::get(&self.kernels, &self.device, self.f64, "scene_from_main")?
            }
        };
        let _one_at_a_time = self.dispatching.lock().unwrap_or_else(|e| e.into_inner());
        let mut out = Vec::with_capacity(records.len());
        let placeholder = placeholder::<N>();
        for batch in records.chunks(CHUNK) {
            let mut words: Vec<f32> = batch
                .iter()
                .flat_map(|p| p.unwrap_or(placeholder))
                .collect();
            // Whole 32-byte records, so that the read back decodes every word.
            words.resize(words.len().next_multiple_of(8), 0.0);
            let header = [
                batch.len() as u32,
                cull.code(),
                mode as u32,
                self.bvh.node_count(),
            ];
            let header: Vec<u8> = header.iter().flat_map(|w| w.to_le_bytes()).collect();
            self.queue.write_buffer(&self.node_buffer, 0, &header);
            let bytes = (words.len() * 4) as u64;
            let rays_buffer = self.upload_rw("torus-cull scene rays", &as_bytes(&words));
            let staging = super::dispatch::buffer(
                &self.device,
                "torus-cull scene staging",
                bytes,
                wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
            );
            let mut buffers = vec![&self.node_buffer, &self.tori_buffer];
            buffers.extend(self.tori64_buffer.as_ref());
            buffers.push(&rays_buffer);
            let read = super::dispatch::run(
                &self.device,
                &self.queue,
                "torus-cull scene",
                &[super::dispatch::Pass {
                    pipeline: &kernel.pipeline,
                    bind_group: &super::dispatch::bind_group(
                        &self.device,
                        &kernel.layout,
                        "torus-cull scene bind group",
                        &buffers,
                    ),
                    groups: batch.len().div_ceil(64) as u32,
                }],
                &[super::dispatch::Read {
                    source: &rays_buffer,
                    staging: &staging,
                    bytes,
                }],
            )?;
            // Each ray's answer is over the first 8 of its N words.
            let words: Vec<f32> = read.into_iter().flatten().flatten().collect();
            if words.len() < batch.len() * N {
                return Err(GpuError::Readback(format!(
                    "{} words read back for {} rays of {N}",
                    words.len(),
                    batch.len()
                )));
            }
            out.extend(
                batch
                    .iter()
                    .zip(words.chunks_exact(N))
                    .map(|(p, w)| p.map(|_| w[..8].try_into().expect("8 words"))),
            );
        }
        Ok(out)
    }

    /// The BVH and its host side ([`SceneBvh::host_trace`], the buffers' bytes).
    pub fn bvh(&self) -> &SceneBvh {
        &self.bvh
    }
}

/// The header row's mode (bit 0: any hit; `wgsl/scene_kernel.wgsl`), and the entry point:
/// `scene_from_main` for spawned records ([`SPAWNED_WORDS`] words a ray).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Mode {
    Closest = 0,
    Any = 1,
    ClosestFrom = 2,
    AnyFrom = 3,
}

/// A closest-hit answer from the device's record, `None` where the host answers.
pub(super) fn closest(record: Option<[f32; 8]>) -> Option<SceneAnswer> {
    match record {
        Some(r) if r[5] == STATUS_HIT as f32 && r[4] >= 0.0 => Some(SceneAnswer {
            hit: Some(SceneHit {
                torus: r[4] as u32,
                t: r[0],
                normal: Vec3::new(r[1], r[2], r[3]),
            }),
            by: device_by(&r),
        }),
        Some(r) if r[5] == STATUS_MISS as f32 => Some(SceneAnswer {
            hit: None,
            by: device_by(&r),
        }),
        _ => None,
    }
}

/// An any-hit answer from the device's record, `None` where the host answers.
pub(super) fn any(record: Option<[f32; 8]>) -> Option<Occlusion> {
    match record {
        Some(r) if r[5] == STATUS_HIT as f32 || r[5] == STATUS_MISS as f32 => Some(Occlusion {
            occluded: r[5] == STATUS_HIT as f32,
            by: device_by(&r),
        }),
        _ => None,
    }
}

/// The record of a ray the host answers, sent in its place: the origin, a unit direction,
/// an empty range (t_min 1 > t_max 0), no torus of its own (`N` words: 8 for a world ray,
/// [`SPAWNED_WORDS`] for a spawned one).
pub(super) fn placeholder<const N: usize>() -> [f32; N] {
    let mut p = [0.0f32; N];
    p[3] = 1.0;
    p[4] = 1.0;
    if N > 32 {
        p[32] = f32::from_bits(u32::MAX);
    }
    p
}

/// The host's closest-hit answer.
pub(super) fn host(hit: Option<SceneHit>) -> SceneAnswer {
    SceneAnswer {
        hit,
        by: Finished::Host,
    }
}

/// The host's occlusion answer.
fn host_occlusion(occluded: bool) -> Occlusion {
    Occlusion {
        occluded,
        by: Finished::Host,
    }
}

/// Each ray's answer: the device's where its record carries one (`device`: [`closest`]
/// or [`any`]), else the host's (`host`, whose error stops the whole batch). The four
/// scene queries differ only in their record, their mode and these two.
fn device_or_host<R, A>(
    rays: &[R],
    records: Vec<Option<[f32; 8]>>,
    device: fn(Option<[f32; 8]>) -> Option<A>,
    host: impl Fn(&R) -> Result<A, GpuError>,
) -> Result<Vec<A>, GpuError> {
    rays.iter()
        .zip(records)
        .map(|(ray, record)| device(record).map_or_else(|| host(ray), Ok))
        .collect()
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
    let usage = wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_DST;
    super::dispatch::buffer(device, label, size, usage)
}
