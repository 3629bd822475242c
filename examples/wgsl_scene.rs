//! A renderer's own compute shader around the library's scene traversal
//! (`torus_cull::gpu::wgsl_scene_module`): 1 000 tori in an obvhs BVH2, one camera ray
//! per pixel traced with `torus_scene_trace` behind Skala's cull, and every pixel's hit
//! checked against the CPU (`torus_cull::intersect` over all 1 000 tori, the nearest
//! kept); then one mirror bounce per hit, spawned on the hit torus (`Torus::spawn`) and
//! traced with `torus_scene_trace_from` (that torus on its surface path, the others on the
//! literal ray), checked the same way. The renderer owns the device, its rays and its output (group 1); the module's
//! bindings are at group 0 ([`SceneBvh`]'s bytes). Where the adapter offers
//! `SHADER_F64` the shader includes the f64 finish, so no ray needs the host; otherwise
//! the rays the shader marks `TORUS_SCENE_HOST` are finished by `SceneBvh::host_trace`.
//!
//! `cargo run --release --features gpu --example wgsl_scene`

use glam::Vec3;
use std::sync::mpsc;
use torus_cull::gpu::wgpu::{self, util::DeviceExt};
use torus_cull::gpu::{SPAWNED_WORDS, SceneBvh, SpawnedRay, wgsl_scene_module};
use torus_cull::{Ray, Torus, intersect};

/// The renderer's part of the shader: its rays and its output, and the call.
const USER_SHADER: &str = r#"
@group(1) @binding(0) var<storage, read> pixel_rays: array<TorusRay>;
@group(1) @binding(1) var<storage, read_write> pixel_hits: array<vec4<f32>>;

@compute @workgroup_size(64)
fn shade(@builtin(global_invocation_id) gid: vec3<u32>) {
    let i = gid.x;
    if (i >= arrayLength(&pixel_rays)) {
        return;
    }
    let h = torus_scene_trace(pixel_rays[i], TORUS_CULL_SKALA, false);
    let torus = select(-1.0, f32(h.torus), h.status == TORUS_SCENE_HIT);
    pixel_hits[2u * i] = vec4<f32>(h.t, h.normal);
    pixel_hits[2u * i + 1u] = vec4<f32>(torus, f32(h.status), 0.0, 0.0);
}

// A ray spawned on a hit: the world ray, then its own torus's record (SceneBvh::prepare_from).
struct BounceRay {
    ray: TorusRay,
    own: TorusSceneOwn,
};

@group(1) @binding(2) var<storage, read> bounce_rays: array<BounceRay>;
@group(1) @binding(3) var<storage, read_write> bounce_hits: array<vec4<f32>>;

@compute @workgroup_size(64)
fn bounce(@builtin(global_invocation_id) gid: vec3<u32>) {
    let i = gid.x;
    if (i >= arrayLength(&bounce_rays)) {
        return;
    }
    let b = bounce_rays[i];
    let h = torus_scene_trace_from(b.ray, b.own, TORUS_CULL_SKALA, false);
    let torus = select(-1.0, f32(h.torus), h.status == TORUS_SCENE_HIT);
    bounce_hits[2u * i] = vec4<f32>(h.t, h.normal);
    bounce_hits[2u * i + 1u] = vec4<f32>(torus, f32(h.status), 0.0, 0.0);
}
"#;

/// 1 000 tori (R = 1, r = 0.25) on a jittered 10×10×10 grid with varied axes.
fn scene() -> Vec<Torus> {
    let mut state = 0x2545_f491_4f6c_dd1du64;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 40) as f32 / (1u64 << 24) as f32 - 0.5
    };
    (0..1000)
        .map(|i| {
            let cell = Vec3::new((i % 10) as f32, ((i / 10) % 10) as f32, (i / 100) as f32);
            let centre = cell * 3.0 + Vec3::new(next(), next(), next());
            let axis = Vec3::new(next(), next() + 0.7, next());
            Torus::new(centre, axis, 1.0, 0.25).expect("a valid torus")
        })
        .collect()
}

/// `side`×`side` pinhole rays looking at the grid from outside it.
fn camera(side: usize) -> Vec<Ray> {
    let eye = Vec3::new(-12.0, 35.0, -20.0);
    let forward = (Vec3::splat(13.5) - eye).normalize();
    let right = forward.cross(Vec3::Y).normalize();
    let up = right.cross(forward);
    let mut rays = Vec::with_capacity(side * side);
    for row in 0..side {
        for col in 0..side {
            let u = ((col as f32 + 0.5) / side as f32 * 2.0 - 1.0) * 0.6;
            let v = (1.0 - (row as f32 + 0.5) / side as f32 * 2.0) * 0.6;
            rays.push(Ray::new(eye, forward + u * right + v * up).expect("a valid ray"));
        }
    }
    rays
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let tori = scene();
    let bvh = SceneBvh::new(&tori)?;
    let rays = camera(64);
    let instance =
        wgpu::Instance::new(wgpu::InstanceDescriptor::new_without_display_handle_from_env());
    let Ok(adapter) = pollster::block_on(instance.request_adapter(&Default::default())) else {
        println!("no GPU adapter: install mesa-vulkan-drivers (lavapipe) to run this example");
        return Ok(());
    };
    let f64 = adapter.features().contains(wgpu::Features::SHADER_F64);
    let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
        required_features: adapter.features() & wgpu::Features::SHADER_F64,
        // The module's two or three storage buffers and the renderer's two.
        required_limits: wgpu::Limits {
            max_storage_buffers_per_shader_stage: 5,
            ..wgpu::Limits::downlevel_defaults()
        },
        ..Default::default()
    }))?;
    let source = format!("{}\n{USER_SHADER}", wgsl_scene_module(0, f64));
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("renderer with the torus scene"),
        source: wgpu::ShaderSource::Wgsl(source.into()),
    });
    let storage = |label, contents: &[u8], extra| {
        device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some(label),
            contents,
            usage: wgpu::BufferUsages::STORAGE | extra,
        })
    };
    let none = wgpu::BufferUsages::empty();
    let nodes = storage("nodes", &bvh.node_bytes(), none);
    let tori_buffer = storage("tori", &bvh.tori_bytes(), none);
    let tori64 = f64.then(|| storage("tori f64", &bvh.tori64_bytes(), none));
    let mut scene_buffers = vec![&nodes, &tori_buffer];
    scene_buffers.extend(tori64.as_ref());
    // One pass of `entry` over `count` records `words`: the answers, 8 words a ray.
    let run = |entry: &str,
               words: &[f32],
               count: usize|
     -> Result<Vec<f32>, Box<dyn std::error::Error>> {
        let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: Some(entry),
            layout: None,
            module: &module,
            entry_point: Some(entry),
            compilation_options: Default::default(),
            cache: None,
        });
        let bytes: Vec<u8> = words.iter().flat_map(|w| w.to_le_bytes()).collect();
        let input = storage("rays", &bytes, none);
        let size = count as u64 * 32;
        let output = storage(
            "hits",
            &vec![0; size as usize],
            wgpu::BufferUsages::COPY_SRC,
        );
        let staging = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("staging"),
            size,
            usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let group = |index: u32, buffers: &[&wgpu::Buffer], first: u32| {
            let entries: Vec<wgpu::BindGroupEntry> = buffers
                .iter()
                .zip(first..)
                .map(|(b, binding)| wgpu::BindGroupEntry {
                    binding,
                    resource: b.as_entire_binding(),
                })
                .collect();
            device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: None,
                layout: &pipeline.get_bind_group_layout(index),
                entries: &entries,
            })
        };
        let scene_group = group(0, &scene_buffers, 0);
        // The pixels' buffers at bindings 0 and 1, the bounces' at 2 and 3.
        let first = if entry == "shade" { 0 } else { 2 };
        let ray_group = group(1, &[&input, &output], first);
        let mut encoder = device.create_command_encoder(&Default::default());
        {
            let mut pass = encoder.begin_compute_pass(&Default::default());
            pass.set_pipeline(&pipeline);
            pass.set_bind_group(0, &scene_group, &[]);
            pass.set_bind_group(1, &ray_group, &[]);
            pass.dispatch_workgroups(count.div_ceil(64) as u32, 1, 1);
        }
        encoder.copy_buffer_to_buffer(&output, 0, &staging, 0, size);
        queue.submit([encoder.finish()]);
        let (tx, rx) = mpsc::channel();
        staging
            .slice(..)
            .map_async(wgpu::MapMode::Read, move |r| drop(tx.send(r)));
        device.poll(wgpu::PollType::wait_indefinitely())?;
        rx.recv()??;
        let records = staging
            .slice(..)
            .get_mapped_range()?
            .chunks_exact(4)
            .map(|b| f32::from_le_bytes(b.try_into().expect("4 bytes")))
            .collect();
        Ok(records)
    };
    // Every ray is in the kernel's domain here; a renderer would trace the `None`s on the
    // host (`bvh.host_trace`).
    let words: Vec<f32> = rays
        .iter()
        .flat_map(|r| bvh.prepare(r).expect("a camera ray the kernel takes"))
        .collect();
    let records = run("shade", &words, rays.len())?;
    let (mut hits_seen, mut host, mut mismatches) = (0, 0, 0);
    let mut bounces = Vec::new();
    for (ray, r) in rays.iter().zip(records.chunks_exact(8)) {
        let gpu = match r[5] as u32 {
            1 => Some((r[4] as u32, r[0])),
            0 => None,
            _ => {
                host += 1;
                bvh.host_trace(ray).map(|h| (h.torus, h.t))
            }
        };
        // The CPU: every torus, the nearest hit kept.
        let cpu = tori
            .iter()
            .enumerate()
            .filter_map(|(i, t)| intersect(t, ray).map(|h| (i as u32, h.t)))
            .min_by(|a, b| a.1.total_cmp(&b.1));
        hits_seen += usize::from(cpu.is_some());
        mismatches += usize::from(!same(gpu, cpu));
        // A mirror bounce from the CPU's hit, spawned on its torus.
        if let Some((i, t)) = cpu {
            let n = intersect(&tori[i as usize], ray).expect("the hit").normal;
            let d = ray.dir().normalize();
            let dir = d - 2.0 * d.dot(n) * n;
            if let Ok(ray) = tori[i as usize].spawn(ray, t, dir) {
                bounces.push(SpawnedRay { ray, from: i });
            }
        }
    }
    let words: Vec<f32> = bounces
        .iter()
        .flat_map(|b| -> [f32; SPAWNED_WORDS] {
            bvh.prepare_from(b)
                .expect("a torus of the scene")
                .expect("a bounce the kernel takes")
        })
        .collect();
    let records = run("bounce", &words, bounces.len())?;
    let (mut bounce_hits, mut bounce_host, mut bounce_mismatches) = (0, 0, 0);
    for (b, r) in bounces.iter().zip(records.chunks_exact(8)) {
        let gpu = match r[5] as u32 {
            1 => Some((r[4] as u32, r[0])),
            0 => None,
            _ => {
                bounce_host += 1;
                bvh.host_trace_from(b)?.map(|h| (h.torus, h.t))
            }
        };
        // The CPU: its own torus on the surface ray, every other on the literal one.
        let literal = b.ray.literal();
        let cpu = tori
            .iter()
            .enumerate()
            .filter_map(|(i, t)| {
                let seen = if i as u32 == b.from { &b.ray } else { &literal };
                intersect(t, seen).map(|h| (i as u32, h.t))
            })
            .min_by(|a, b| a.1.total_cmp(&b.1));
        bounce_hits += usize::from(cpu.is_some());
        bounce_mismatches += usize::from(!same(gpu, cpu));
    }
    println!(
        "{} ({:?}), f64 in the shader: {f64}: {} rays over {} tori, {hits_seen} hits, \
         {host} finished on the host, {mismatches} differ from the CPU; {} bounces, \
         {bounce_hits} hits, {bounce_host} finished on the host, {bounce_mismatches} differ",
        adapter.get_info().name,
        adapter.get_info().device_type,
        rays.len(),
        tori.len(),
        bounces.len()
    );
    if mismatches + bounce_mismatches > 0 {
        return Err(format!(
            "{mismatches} pixels and {bounce_mismatches} bounces differ from the CPU"
        )
        .into());
    }
    Ok(())
}

/// The same hit or miss, the same torus, t within the certified f32 bound (2·10⁻⁴·(R + r)
/// for unit-length directions, R + r = 1.25) and rounding.
fn same(gpu: Option<(u32, f32)>, cpu: Option<(u32, f32)>) -> bool {
    match (gpu, cpu) {
        (None, None) => true,
        (Some((i, t)), Some((j, u))) => i == j && (t - u).abs() <= 2.5e-4 * 1.25 + 4e-7 * u,
        _ => false,
    }
}
