// The library's scene kernels (src/gpu/scene.rs, GpuScene): scene.wgsl's traversal behind
// its bindings, one ray per invocation: scene_main for world rays, scene_from_main for
// rays spawned on a torus of the scene (two entry points, so that a scene that traces no
// secondary ray does not compile the surface path). The rays buffer is read and
// overwritten in place (it keeps the kernel within four storage buffers, wgpu's downlevel
// limit). The header row of the node buffer: rays, cull, mode (bit 0: any hit), nodes.
// In, per ray: the world ray (origin, t_min) and (direction, t_max); for scene_from_main,
// seven vec4 more, the TorusSceneOwn (its info row as u32 bits: SceneBvh::prepare_from).
// Out, over the ray's first two vec4: (t, normal.xyz) and (torus, status, f64 leaves,
// leaves) as f32.
//
// mirrors: tc_scene_ray_at -> none (the world ray of a record)
// mirrors: tc_scene_write -> none (the answer over the record)
// mirrors: scene_main -> crate::gpu::scene::GpuScene::dispatch
// mirrors: scene_from_main -> crate::gpu::scene::GpuScene::dispatch

fn tc_scene_ray_at(base: u32) -> TorusRay {
    let r0 = torus_scene_rays[base];
    let r1 = torus_scene_rays[base + 1u];
    return TorusRay(r0.xyz, r0.w, r1.xyz, r1.w);
}

fn tc_scene_write(base: u32, h: TorusSceneHit) {
    let torus = select(-1.0, f32(h.torus), h.status == TORUS_SCENE_HIT);
    torus_scene_rays[base] = vec4<f32>(h.t, h.normal);
    torus_scene_rays[base + 1u] = vec4<f32>(torus, f32(h.status), f32(h.f64_leaves), f32(h.leaves));
}

@compute @workgroup_size(64)
fn scene_main(@builtin(global_invocation_id) gid: vec3<u32>) {
    let config = torus_scene_nodes.config;
    if (gid.x >= config.x) {
        return;
    }
    let base = 2u * gid.x;
    tc_scene_write(base, torus_scene_trace(tc_scene_ray_at(base), config.y, (config.z & 1u) != 0u));
}

@compute @workgroup_size(64)
fn scene_from_main(@builtin(global_invocation_id) gid: vec3<u32>) {
    let config = torus_scene_nodes.config;
    if (gid.x >= config.x) {
        return;
    }
    let base = 9u * gid.x;
    let o0 = torus_scene_rays[base + 2u];
    let o1 = torus_scene_rays[base + 3u];
    let surface = TorusSurfaceRay(torus_scene_rays[base + 4u], torus_scene_rays[base + 5u],
        torus_scene_rays[base + 6u], torus_scene_rays[base + 7u]);
    let info = bitcast<vec4<u32>>(torus_scene_rays[base + 8u]);
    let own = TorusSceneOwn(TorusRay(o0.xyz, o0.w, o1.xyz, o1.w), surface, info);
    let h = torus_scene_trace_from(tc_scene_ray_at(base), own, config.y, (config.z & 1u) != 0u);
    tc_scene_write(base, h);
}
