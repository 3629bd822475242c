// The library's scene kernel (src/gpu/scene.rs, GpuScene): scene.wgsl's traversal behind
// its bindings, one ray per invocation. The rays buffer is read and overwritten in place
// (it keeps the kernel within four storage buffers, wgpu's downlevel limit): in, the
// world ray (origin, t_min) and (direction, t_max); out, (t, normal.xyz) and
// (torus, status, f64 leaves, leaves) as f32. The header row of the node buffer: rays,
// cull, mode (0 closest hit, 1 any hit), nodes.
//
// mirrors: scene_main -> crate::gpu::scene::GpuScene::dispatch

@compute @workgroup_size(64)
fn scene_main(@builtin(global_invocation_id) gid: vec3<u32>) {
    let i = gid.x;
    let config = torus_scene_nodes.config;
    if (i >= config.x) {
        return;
    }
    let r0 = torus_scene_rays[2u * i];
    let r1 = torus_scene_rays[2u * i + 1u];
    let h = torus_scene_trace(TorusRay(r0.xyz, r0.w, r1.xyz, r1.w), config.y, config.z == 1u);
    let torus = select(-1.0, f32(h.torus), h.status == TORUS_SCENE_HIT);
    torus_scene_rays[2u * i] = vec4<f32>(h.t, h.normal);
    torus_scene_rays[2u * i + 1u] = vec4<f32>(torus, f32(h.status), f32(h.f64_leaves), f32(h.leaves));
}
