//! A renderer's own compute shader around the library's WGSL module
//! (`torus_cull::gpu::wgsl_module`): one camera ray per pixel, `torus_intersect` behind
//! Skala's cull, a hit mask and (t, normal) per pixel. The combined shader is validated
//! with naga (no adapter needed); where an adapter exists (a GPU, or Mesa's lavapipe) it
//! runs on a camera's rays plus a far camera's and some rays spawned from the surface,
//! and every answer is checked against the f64 path (`torus_cull::intersect`) after the
//! escalated rays are finished on the host.
//!
//! `cargo run --release --features gpu --example wgsl_module`
//!
//! The host side is `ModuleTorus` (the `TorusParams` block, the per-ray preparation) and
//! `PreparedRay::finish` (the shader's answer, finished in f64 where it escalated).
//!
//! Where the adapter offers `SHADER_F64`, a second shader of the renderer's
//! ([`combined_shader_f64`]) also includes the f64 module
//! (`torus_cull::gpu::wgsl_finish_module`) and finishes the escalated rays in the same
//! dispatch: `torus_intersect`, then `torus_finish_f64` where `torus_finish_wanted` says
//! so; the host reads both answers (`PreparedRay::finish_with_device`) and finishes only
//! what the device handed back. tests/gpu/wgsl_module.rs runs this file's functions.

use glam::Vec3;
use std::sync::mpsc;
use torus_cull::gpu::wgpu::{self, naga};
use torus_cull::gpu::{
    FinishCounts, Finished, ModuleHit, ModuleHit64, ModuleTorus, PreparedRay, PreparedRay64,
    wgsl_finish_module, wgsl_module,
};
use torus_cull::{F32Hit, Ray, Torus, intersect};

/// The renderer's shader: its own bindings and entry point, the module's functions.
pub const USER_SHADER: &str = r#"
// A renderer's shader: the torus (the module's TorusParams), one TorusRay per pixel as
// ModuleTorus::prepare packs it, and per pixel the hit mask (code | why << 8) and
// (t, normal) for shading.
@group(0) @binding(0) var<uniform> torus: TorusParams;
@group(0) @binding(1) var<storage, read> pixel_rays: array<TorusRay>;
@group(0) @binding(2) var<storage, read_write> hit_mask: array<u32>;
@group(0) @binding(3) var<storage, read_write> hit_t_normal: array<vec4<f32>>;

@compute @workgroup_size(64)
fn shade(@builtin(global_invocation_id) gid: vec3<u32>) {
    let i = gid.x;
    if (i >= arrayLength(&hit_mask)) {
        return;
    }
    let hit = torus_intersect(pixel_rays[i], torus, TORUS_CULL_SKALA);
    hit_mask[i] = hit.code | (hit.why << 8u);
    hit_t_normal[i] = vec4<f32>(hit.t, hit.normal);
}
"#;

/// The renderer's shader with the f64 finish: both modules, its own bindings (the f32
/// torus as a uniform, the f64 torus and the rays and answers as storage: three storage
/// buffers, within WebGPU's default of four), and one dispatch that runs the f32 module
/// and, on the rays it does not prove, the f64 module.
pub const USER_SHADER_F64: &str = r#"
// Per pixel, from the host: the f32 module's TorusRay (ModuleTorus::prepare), the f64
// module's TorusWorldRay and instruction (ModuleTorus::prepare_f64). 80 bytes.
struct PixelRay {
    ray: TorusRay,
    world: TorusWorldRay,
    instruction: u32,
};

// Per pixel, to the host: the f32 answer (t, normal; code, why) and the f64 answer
// (t, normal; point, status; TORUS_F64_STATUS_PROVED where it did not run). 64 bytes.
struct PixelAnswer {
    t_normal: vec4<f32>,
    code_why: vec4<u32>,
    t_normal64: vec4<f32>,
    point_status64: vec4<f32>,
};

@group(0) @binding(0) var<uniform> torus: TorusParams;
@group(0) @binding(1) var<storage, read> torus64: TorusParams64;
@group(0) @binding(2) var<storage, read> pixels: array<PixelRay>;
@group(0) @binding(3) var<storage, read_write> answers: array<PixelAnswer>;

@compute @workgroup_size(64)
fn shade_f64(@builtin(global_invocation_id) gid: vec3<u32>) {
    let i = gid.x;
    if (i >= arrayLength(&answers)) {
        return;
    }
    let pixel = pixels[i];
    let hit = torus_intersect(pixel.ray, torus, TORUS_CULL_SKALA);
    var finished = TorusHit64(0.0, vec3<f32>(0.0), vec3<f32>(0.0), TORUS_F64_STATUS_PROVED);
    if (torus_finish_wanted(pixel.instruction, hit.code, hit.t, hit.normal)) {
        finished = torus_finish_f64(pixel.world, torus64, pixel.instruction);
    }
    answers[i] = PixelAnswer(
        vec4<f32>(hit.t, hit.normal),
        vec4<u32>(hit.code, hit.why, 0u, 0u),
        vec4<f32>(finished.t, finished.normal),
        vec4<f32>(finished.point, f32(finished.status)),
    );
}
"#;

/// The combined shader: the module, then the renderer's part.
pub fn combined_shader() -> String {
    format!("{}\n{USER_SHADER}", wgsl_module())
}

/// The combined shader with the f64 finish: the f32 module, the f64 module (the two
/// declare no common name), then the renderer's part.
pub fn combined_shader_f64() -> String {
    format!(
        "{}\n{}\n{USER_SHADER_F64}",
        wgsl_module(),
        wgsl_finish_module()
    )
}

/// Parses and validates `source` as wgpu would (naga), with a readable error.
pub fn validate(source: &str) -> Result<naga::Module, String> {
    validate_with(source, naga::valid::Capabilities::default())
}

/// [`validate`] with naga's `FLOAT64` capability (what `SHADER_F64` enables).
pub fn validate_f64(source: &str) -> Result<naga::Module, String> {
    validate_with(source, naga::valid::Capabilities::FLOAT64)
}

fn validate_with(
    source: &str,
    capabilities: naga::valid::Capabilities,
) -> Result<naga::Module, String> {
    let module = naga::front::wgsl::parse_str(source).map_err(|e| e.emit_to_string(source))?;
    naga::valid::Validator::new(naga::valid::ValidationFlags::all(), capabilities)
        .validate(&module)
        .map_err(|e| format!("{e:?}"))?;
    Ok(module)
}

/// The shader's answer for one ray: (t, normal, code, why).
pub type ShaderHit = ModuleHit;

/// A device with the renderer's pipeline built from [`combined_shader`], and the one
/// from [`combined_shader_f64`] where the adapter offers `SHADER_F64`.
pub struct Renderer {
    device: wgpu::Device,
    queue: wgpu::Queue,
    pipeline: wgpu::ComputePipeline,
    pipeline_f64: Result<wgpu::ComputePipeline, String>,
    /// The adapter's name and device type.
    pub adapter: String,
}

/// A compute pipeline of `source` at `entry`, its layout from the shader; an error where
/// the adapter refuses the shader.
async fn pipeline(
    device: &wgpu::Device,
    source: String,
    entry: &str,
) -> Result<wgpu::ComputePipeline, String> {
    let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some(entry),
        source: wgpu::ShaderSource::Wgsl(source.into()),
    });
    let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
        label: Some(entry),
        layout: None,
        module: &module,
        entry_point: Some(entry),
        compilation_options: Default::default(),
        cache: None,
    });
    match scope.pop().await {
        Some(e) => Err(format!("the combined shader failed on the adapter: {e}")),
        None => Ok(pipeline),
    }
}

impl Renderer {
    /// The first adapter wgpu offers, or why there is none.
    pub fn new() -> Result<Renderer, String> {
        pollster::block_on(async {
            let instance = wgpu::Instance::new(
                wgpu::InstanceDescriptor::new_without_display_handle_from_env(),
            );
            let adapter = instance
                .request_adapter(&wgpu::RequestAdapterOptions::default())
                .await
                .map_err(|e| format!("no adapter: {e}"))?;
            let info = adapter.get_info();
            // f64 where the adapter has it: the f64 module needs it, the f32 one does not.
            let f64_feature = adapter.features() & wgpu::Features::SHADER_F64;
            let (device, queue) = adapter
                .request_device(&wgpu::DeviceDescriptor {
                    label: Some("wgsl_module example"),
                    required_features: f64_feature,
                    required_limits: wgpu::Limits::downlevel_defaults(),
                    ..Default::default()
                })
                .await
                .map_err(|e| format!("no device: {e}"))?;
            let main = pipeline(&device, combined_shader(), "shade").await?;
            let pipeline_f64 = if f64_feature.is_empty() {
                Err("the adapter does not offer SHADER_F64".to_string())
            } else {
                pipeline(&device, combined_shader_f64(), "shade_f64").await
            };
            Ok(Renderer {
                device,
                queue,
                pipeline: main,
                pipeline_f64,
                adapter: format!("{} ({:?})", info.name, info.device_type),
            })
        })
    }

    /// Why the f64 shader is not available, if it is not.
    pub fn f64_unavailable(&self) -> Option<&str> {
        self.pipeline_f64.as_ref().err().map(String::as_str)
    }

    /// Runs `pipeline` once over `n` rays: binding k of group 0 is `inputs[k]` (its
    /// bytes and usage), then one storage buffer per size in `outputs`; returns the
    /// outputs' words, concatenated.
    fn dispatch(
        &self,
        pipeline: &wgpu::ComputePipeline,
        n: usize,
        inputs: &[(&[u8], wgpu::BufferUsages)],
        outputs: &[u64],
    ) -> Result<Vec<u32>, String> {
        use wgpu::BufferUsages as Use;
        use wgpu::util::DeviceExt;
        let mut buffers: Vec<wgpu::Buffer> = inputs
            .iter()
            .map(|(contents, usage)| {
                self.device
                    .create_buffer_init(&wgpu::util::BufferInitDescriptor {
                        label: Some("renderer input"),
                        contents,
                        usage: *usage,
                    })
            })
            .collect();
        let blank = |label, size, usage| {
            self.device.create_buffer(&wgpu::BufferDescriptor {
                label: Some(label),
                size,
                usage,
                mapped_at_creation: false,
            })
        };
        for size in outputs {
            buffers.push(blank(
                "renderer output",
                *size,
                Use::STORAGE | Use::COPY_SRC,
            ));
        }
        let total: u64 = outputs.iter().sum();
        let staging = blank("staging", total, Use::MAP_READ | Use::COPY_DST);
        let entries: Vec<wgpu::BindGroupEntry> = buffers
            .iter()
            .enumerate()
            .map(|(k, b)| wgpu::BindGroupEntry {
                binding: k as u32,
                resource: b.as_entire_binding(),
            })
            .collect();
        let bind_group = self.device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("renderer bindings"),
            layout: &pipeline.get_bind_group_layout(0),
            entries: &entries,
        });
        let mut encoder = self
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor { label: None });
        {
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor::default());
            pass.set_pipeline(pipeline);
            pass.set_bind_group(0, &bind_group, &[]);
            pass.dispatch_workgroups(n.div_ceil(64) as u32, 1, 1);
        }
        let mut offset = 0;
        for (buffer, size) in buffers[inputs.len()..].iter().zip(outputs) {
            encoder.copy_buffer_to_buffer(buffer, 0, &staging, offset, *size);
            offset += size;
        }
        self.queue.submit([encoder.finish()]);
        let slice = staging.slice(..);
        let (tx, rx) = mpsc::channel();
        slice.map_async(wgpu::MapMode::Read, move |r| {
            let _ = tx.send(r);
        });
        self.device
            .poll(wgpu::PollType::wait_indefinitely())
            .map_err(|e| e.to_string())?;
        rx.recv()
            .map_err(|e| e.to_string())?
            .map_err(|e| e.to_string())?;
        let view = slice.get_mapped_range().map_err(|e| format!("{e:?}"))?;
        let words = view
            .chunks_exact(4)
            .map(|w| u32::from_le_bytes(w.try_into().expect("4")))
            .collect();
        drop(view);
        staging.unmap();
        Ok(words)
    }

    /// Runs the shader once over `rays` (prepared for `torus`) and reads back every
    /// pixel's answer.
    pub fn run(&self, torus: &ModuleTorus, rays: &[PreparedRay]) -> Result<Vec<ShaderHit>, String> {
        use wgpu::BufferUsages as Use;
        let n = rays.len();
        let ray_bytes: Vec<u8> = rays.iter().flat_map(|r| r.bytes()).collect();
        let words = self.dispatch(
            &self.pipeline,
            n,
            &[
                (&torus.params_bytes(), Use::UNIFORM),
                (&ray_bytes, Use::STORAGE),
            ],
            &[4 * n as u64, 16 * n as u64],
        )?;
        let out = (0..n)
            .map(|i| {
                let mask = words[i];
                let base = n + 4 * i;
                let f = |k| f32::from_bits(words[base + k]);
                ShaderHit {
                    t: f(0),
                    normal: Vec3::new(f(1), f(2), f(3)),
                    code: mask & 0xff,
                    why: mask >> 8,
                }
            })
            .collect();
        Ok(out)
    }

    /// Runs the f64 shader ([`combined_shader_f64`]) once over `rays`, each prepared for
    /// both modules, and reads back every pixel's two answers; an error without
    /// `SHADER_F64`.
    pub fn run_f64(
        &self,
        torus: &ModuleTorus,
        rays: &[(PreparedRay, PreparedRay64)],
    ) -> Result<Vec<(ShaderHit, ModuleHit64)>, String> {
        use wgpu::BufferUsages as Use;
        let pipeline = self.pipeline_f64.as_ref().map_err(Clone::clone)?;
        let n = rays.len();
        // PixelRay: TorusRay (32 bytes), TorusWorldRay (32), the instruction, 12 of padding.
        let mut pixels = Vec::with_capacity(80 * n);
        for (ray, ray64) in rays {
            pixels.extend_from_slice(&ray.bytes());
            pixels.extend_from_slice(&ray64.bytes());
            pixels.extend_from_slice(&ray64.instruction.to_le_bytes());
            pixels.extend_from_slice(&[0; 12]);
        }
        let words = self.dispatch(
            pipeline,
            n,
            &[
                (&torus.params_bytes(), Use::UNIFORM),
                (&torus.params64_bytes(), Use::STORAGE),
                (&pixels, Use::STORAGE),
            ],
            &[64 * n as u64],
        )?;
        let out = words
            .chunks_exact(16)
            .map(|w| {
                let f = |k: usize| f32::from_bits(w[k]);
                let hit = ShaderHit {
                    t: f(0),
                    normal: Vec3::new(f(1), f(2), f(3)),
                    code: w[4],
                    why: w[5],
                };
                let hit64 = ModuleHit64 {
                    t: f(8),
                    normal: Vec3::new(f(9), f(10), f(11)),
                    point: Vec3::new(f(12), f(13), f(14)),
                    status: f(15) as u32,
                };
                (hit, hit64)
            })
            .collect();
        Ok(out)
    }
}

/// The example's rays on `torus` (centre `c`, outer radius `outer`): a 32 × 24 camera
/// at 3·outer, the same camera 10⁴·outer away, and a bounce from each surface point the
/// near camera hits (`Torus::spawn`, mirror direction).
pub fn example_rays(torus: &Torus) -> Vec<Ray> {
    let c = torus.center();
    let outer = torus.major_radius() + torus.minor_radius();
    let mut rays = Vec::new();
    for distance in [3.0 * outer, 1e4 * outer] {
        let eye = c + Vec3::new(0.2, 0.6, 1.0).normalize() * distance;
        let forward = (c - eye).normalize();
        let right = forward.cross(Vec3::Y).normalize();
        let up = right.cross(forward);
        let half = 1.3 * outer / distance;
        for row in 0..24 {
            for col in 0..32 {
                let x = (col as f32 + 0.5) / 32.0 * 2.0 - 1.0;
                let y = (row as f32 + 0.5) / 24.0 * 2.0 - 1.0;
                let dir = forward + right * (x * half) + up * (y * half * 0.75);
                if let Ok(ray) = Ray::new(eye, dir) {
                    rays.push(ray);
                }
            }
        }
    }
    let primaries = rays.len() / 2;
    for i in 0..primaries {
        let ray = rays[i];
        if let Some(hit) = intersect(torus, &ray) {
            let d = ray.dir();
            let mirror = d - hit.normal * (2.0 * d.dot(hit.normal));
            if let Ok(bounce) = torus.spawn(&ray, hit.t, mirror) {
                rays.push(bounce);
            }
        }
    }
    rays
}

/// `count` rays that graze the torus's silhouette: from 3·outer away, aimed within
/// ±10⁻³·r of the outer equator's distance from the axis, tilted along the axis; the
/// f32 module cannot prove many of them (they escalate).
pub fn silhouette_rays(torus: &Torus, count: usize) -> Vec<Ray> {
    let c = torus.center();
    let axis = torus.axis();
    let outer = torus.major_radius() + torus.minor_radius();
    let side = axis.any_orthonormal_vector();
    let other = axis.cross(side);
    (0..count)
        .filter_map(|k| {
            let angle = k as f32 * std::f32::consts::TAU / count as f32;
            let radial = side * angle.cos() + other * angle.sin();
            let offset = 1.0 + ((k % 21) as f32 - 10.0) * 1e-4 * torus.minor_radius() / outer;
            let tangent = axis.cross(radial);
            let tilt = ((k % 7) as f32 - 3.0) / 6.0;
            let dir = (tangent + axis * tilt).normalize();
            Ray::new(c + radial * (outer * offset) - dir * (3.0 * outer), dir).ok()
        })
        .collect()
}

/// How the shader's answers, finished on the host, compare with the f64 path.
#[derive(Debug, Default, Clone, Copy)]
pub struct Comparison {
    /// Rays run.
    pub rays: usize,
    /// Hits of the f64 path.
    pub exact_hits: usize,
    /// Proved hits (the shader's, or the host's before the shader).
    pub proved_hits: usize,
    /// Escalated, finished in f64 on the host.
    pub escalated: usize,
    /// The f64 path hits, the finished answer misses.
    pub missed: usize,
    /// The finished answer hits, the f64 path misses.
    pub invented: usize,
    /// The largest |t − t_f64| of a proved hit, over the outer radius times |d|⁻¹.
    pub worst_t_rel: f64,
}

/// Finishes every answer on the host and compares it with `torus_cull::intersect`.
pub fn compare(
    torus: &Torus,
    rays: &[Ray],
    prepared: &[PreparedRay],
    answers: &[ShaderHit],
) -> Comparison {
    let outer = f64::from(torus.major_radius() + torus.minor_radius());
    let mut c = Comparison {
        rays: rays.len(),
        ..Comparison::default()
    };
    for ((ray, p), a) in rays.iter().zip(prepared).zip(answers) {
        let finished: F32Hit = p.finish(torus, ray, a.t, a.normal, a.code, a.why);
        let exact = intersect(torus, ray);
        c.exact_hits += usize::from(exact.is_some());
        if finished.escalated {
            c.escalated += 1;
        } else if let Some(hit) = finished.hit {
            c.proved_hits += 1;
            if let Some(e) = exact {
                let dt = f64::from(hit.t - e.t).abs() * f64::from(ray.dir().length());
                c.worst_t_rel = c.worst_t_rel.max(dt / outer);
            }
        }
        match (finished.hit.is_some(), exact.is_some()) {
            (false, true) => c.missed += 1,
            (true, false) => c.invented += 1,
            _ => {}
        }
    }
    c
}

/// Each ray prepared for both modules: the f32 module's `TorusRay` and the f64 module's
/// `TorusWorldRay` and instruction.
pub fn prepare_both(torus: &ModuleTorus, rays: &[Ray]) -> Vec<(PreparedRay, PreparedRay64)> {
    rays.iter()
        .map(|ray| {
            let prepared = torus.prepare(ray);
            (prepared, torus.prepare_f64(ray, &prepared))
        })
        .collect()
}

/// How the f64 shader's answers compare with the f64 path.
#[derive(Debug, Default, Clone)]
pub struct ComparisonF64 {
    /// Rays run.
    pub rays: usize,
    /// Hits of the f64 path.
    pub exact_hits: usize,
    /// Who answered: the f32 module, the f64 module, the host.
    pub counts: FinishCounts,
    /// The f64 path hits, the answer misses.
    pub missed: usize,
    /// The answer hits, the f64 path misses.
    pub invented: usize,
    /// Every ray's answer and who gave it (`PreparedRay::finish_with_device`).
    pub answers: Vec<(F32Hit, Finished)>,
}

/// Reads both answers of every ray (`PreparedRay::finish_with_device`: the host finishes
/// only what the device handed back) and compares them with `torus_cull::intersect`.
pub fn compare_f64(
    torus: &Torus,
    rays: &[Ray],
    prepared: &[(PreparedRay, PreparedRay64)],
    answers: &[(ShaderHit, ModuleHit64)],
) -> ComparisonF64 {
    let mut c = ComparisonF64 {
        rays: rays.len(),
        ..ComparisonF64::default()
    };
    for ((ray, (p, _)), (hit, hit64)) in rays.iter().zip(prepared).zip(answers) {
        let answer = p.finish_with_device(torus, ray, hit, Some(hit64));
        let exact = intersect(torus, ray);
        c.exact_hits += usize::from(exact.is_some());
        match (answer.0.hit.is_some(), exact.is_some()) {
            (false, true) => c.missed += 1,
            (true, false) => c.invented += 1,
            _ => {}
        }
        c.answers.push(answer);
    }
    c.counts = FinishCounts::of(c.answers.iter().map(|(_, f)| f));
    c
}

/// The example's torus: off the origin, tilted, ν = R/r = 2.5.
pub fn example_torus() -> Torus {
    Torus::new(
        Vec3::new(3.0, -1.0, 2.0),
        Vec3::new(0.3, 1.0, 0.2),
        2.0,
        0.8,
    )
    .expect("a valid torus")
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let source = combined_shader();
    let module = validate(&source)?;
    println!(
        "combined shader: {} lines, {} functions, entry point {:?}: valid (naga)",
        source.lines().count(),
        module.functions.len(),
        module
            .entry_points
            .iter()
            .map(|e| &e.name)
            .collect::<Vec<_>>()
    );
    let renderer = match Renderer::new() {
        Ok(r) => r,
        Err(why) => {
            println!("not run: {why} (install mesa-vulkan-drivers for lavapipe)");
            return Ok(());
        }
    };
    let torus = example_torus();
    let module_torus = ModuleTorus::new(&torus);
    let mut rays = example_rays(&torus);
    rays.extend(silhouette_rays(&torus, 400));
    let prepared: Vec<PreparedRay> = rays.iter().map(|r| module_torus.prepare(r)).collect();
    let answers = renderer.run(&module_torus, &prepared)?;
    let c = compare(&torus, &rays, &prepared, &answers);
    println!(
        "{}: {} rays, {} hits (f64), {} proved hits, {} escalated (finished in f64 on \
         the host); against the f64 path: {} missed, {} invented, worst proved |Δt|·|d| = {:.2e}·(R + r)",
        renderer.adapter,
        c.rays,
        c.exact_hits,
        c.proved_hits,
        c.escalated,
        c.missed,
        c.invented,
        c.worst_t_rel
    );
    if c.missed + c.invented > 0 {
        return Err("the module disagrees with the f64 path".into());
    }
    // The f64 finish in the renderer's own shader, where the adapter offers SHADER_F64.
    if let Some(why) = renderer.f64_unavailable() {
        println!("f64 module not run: {why}; the host finishes the escalated rays");
        return Ok(());
    }
    let source = combined_shader_f64();
    validate_f64(&source)?;
    let both = prepare_both(&module_torus, &rays);
    let answers = renderer.run_f64(&module_torus, &both)?;
    let c = compare_f64(&torus, &rays, &both, &answers);
    println!(
        "{} with the f64 module ({} lines): {} rays, proved by f32 {}, finished on the \
         device {}, on the host {}; against the f64 path: {} missed, {} invented",
        renderer.adapter,
        source.lines().count(),
        c.rays,
        c.counts.proved,
        c.counts.device,
        c.counts.host,
        c.missed,
        c.invented
    );
    if c.missed + c.invented > 0 {
        return Err("the f64 module disagrees with the f64 path".into());
    }
    Ok(())
}
