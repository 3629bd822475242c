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
//! tests/wgsl_module.rs runs this file's functions.

use glam::Vec3;
use std::sync::mpsc;
use torus_cull::gpu::wgpu::{self, naga};
use torus_cull::gpu::{ModuleTorus, PreparedRay, wgsl_module};
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

/// The combined shader: the module, then the renderer's part.
pub fn combined_shader() -> String {
    format!("{}\n{USER_SHADER}", wgsl_module())
}

/// Parses and validates `source` as wgpu would (naga), with a readable error.
pub fn validate(source: &str) -> Result<naga::Module, String> {
    let module = naga::front::wgsl::parse_str(source).map_err(|e| e.emit_to_string(source))?;
    naga::valid::Validator::new(
        naga::valid::ValidationFlags::all(),
        naga::valid::Capabilities::default(),
    )
    .validate(&module)
    .map_err(|e| format!("{e:?}"))?;
    Ok(module)
}

/// The shader's answer for one ray: (t, normal, code, why).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShaderHit {
    /// t along the prepared ray (add `PreparedRay::t0`; `PreparedRay::verdict` does).
    pub t: f32,
    /// The unit world normal of a hit.
    pub normal: Vec3,
    /// `TORUS_MISS`, `TORUS_HIT` or `TORUS_ESCALATE`.
    pub code: u32,
    /// `TORUS_WHY_*` of an escalated ray.
    pub why: u32,
}

/// A device with the renderer's pipeline built from [`combined_shader`].
pub struct Renderer {
    device: wgpu::Device,
    queue: wgpu::Queue,
    pipeline: wgpu::ComputePipeline,
    /// The adapter's name and device type.
    pub adapter: String,
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
            let (device, queue) = adapter
                .request_device(&wgpu::DeviceDescriptor {
                    label: Some("wgsl_module example"),
                    required_limits: wgpu::Limits::downlevel_defaults(),
                    ..Default::default()
                })
                .await
                .map_err(|e| format!("no device: {e}"))?;
            let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
            let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
                label: Some("renderer + torus-cull module"),
                source: wgpu::ShaderSource::Wgsl(combined_shader().into()),
            });
            // The layout from the shader (four buffers in group 0).
            let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
                label: Some("renderer pipeline"),
                layout: None,
                module: &module,
                entry_point: Some("shade"),
                compilation_options: Default::default(),
                cache: None,
            });
            if let Some(e) = scope.pop().await {
                return Err(format!("the combined shader failed on the adapter: {e}"));
            }
            Ok(Renderer {
                device,
                queue,
                pipeline,
                adapter: format!("{} ({:?})", info.name, info.device_type),
            })
        })
    }

    /// Runs the shader once over `rays` (prepared for `torus`) and reads back every
    /// pixel's answer.
    pub fn run(&self, torus: &ModuleTorus, rays: &[PreparedRay]) -> Result<Vec<ShaderHit>, String> {
        use wgpu::BufferUsages as Use;
        use wgpu::util::DeviceExt;
        let n = rays.len();
        let init = |label, contents: &[u8], usage| {
            self.device
                .create_buffer_init(&wgpu::util::BufferInitDescriptor {
                    label: Some(label),
                    contents,
                    usage,
                })
        };
        let blank = |label, size, usage| {
            self.device.create_buffer(&wgpu::BufferDescriptor {
                label: Some(label),
                size,
                usage,
                mapped_at_creation: false,
            })
        };
        let ray_bytes: Vec<u8> = rays.iter().flat_map(|r| r.bytes()).collect();
        let params = init("torus", &torus.params_bytes(), Use::UNIFORM);
        let input = init("pixel rays", &ray_bytes, Use::STORAGE);
        let mask_size = 4 * n as u64;
        let hits_size = 16 * n as u64;
        let mask = blank("hit mask", mask_size, Use::STORAGE | Use::COPY_SRC);
        let hits = blank("hit t normal", hits_size, Use::STORAGE | Use::COPY_SRC);
        let staging = blank(
            "staging",
            mask_size + hits_size,
            Use::MAP_READ | Use::COPY_DST,
        );
        let bind_group = self.device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("renderer bindings"),
            layout: &self.pipeline.get_bind_group_layout(0),
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
                    resource: mask.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 3,
                    resource: hits.as_entire_binding(),
                },
            ],
        });
        let mut encoder = self
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor { label: None });
        {
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor::default());
            pass.set_pipeline(&self.pipeline);
            pass.set_bind_group(0, &bind_group, &[]);
            pass.dispatch_workgroups(n.div_ceil(64) as u32, 1, 1);
        }
        encoder.copy_buffer_to_buffer(&mask, 0, &staging, 0, mask_size);
        encoder.copy_buffer_to_buffer(&hits, 0, &staging, mask_size, hits_size);
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
        let word = |k: usize| u32::from_le_bytes(view[4 * k..4 * k + 4].try_into().expect("4"));
        let out = (0..n)
            .map(|i| {
                let mask = word(i);
                let base = n + 4 * i;
                let f = |k| f32::from_bits(word(base + k));
                ShaderHit {
                    t: f(0),
                    normal: Vec3::new(f(1), f(2), f(3)),
                    code: mask & 0xff,
                    why: mask >> 8,
                }
            })
            .collect();
        drop(view);
        staging.unmap();
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
    let rays = example_rays(&torus);
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
    Ok(())
}
