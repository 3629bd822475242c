// The library's compute kernel (src/gpu/intersector.rs runs it): module/*.wgsl's functions
// behind their generated header, with the bindings and the entry point below. One ray per
// invocation; the output per ray is two vec4: (t, normal.xyz) and (code, why, 0, 0) as
// f32 (TORUS_MISS, TORUS_HIT, TORUS_ESCALATE; in the cull-only mode, config.z = 1,
// TORUS_MISS rejected and TORUS_KEPT kept). Where config.w = 1 each ray has a surface
// record beside it (a ray from a surface point, its cubic formed on the host).
//
// mirrors: main -> crate::gpu::intersector::GpuIntersector::dispatch_with (the kernel's pass)

struct Params {
    // The torus (112 bytes).
    torus: TorusParams,
    // x: rays in this dispatch, y: cull (TORUS_CULL_*), z: mode (0 intersect, 1 the cull
    // alone), w: 1 where `surfaces` is to be read.
    config: vec4<u32>,
};

// A read-only storage buffer, not a uniform one: Mesa's lavapipe inlines uniform values
// that steer control flow (the cull, the mode, the count) and recompiles the whole kernel
// whenever they change, about 0.1 s a dispatch, which made per-torus dispatches 500× slower
// there. Every ray reads the same 128 bytes, which any GPU caches either way.
@group(0) @binding(0) var<storage, read> params: Params;
// TorusRay: (origin − centre, t_min) and (dir, t_max), both ends finite.
@group(0) @binding(1) var<storage, read> rays: array<TorusRay>;
@group(0) @binding(2) var<storage, read_write> results: array<vec4<f32>>;
// TorusSurfaceRay per ray (read only where config.w = 1).
@group(0) @binding(3) var<storage, read> surfaces: array<TorusSurfaceRay>;

@compute @workgroup_size(64)
fn main(@builtin(global_invocation_id) gid: vec3<u32>) {
    let i = gid.x;
    if (i >= params.config.x) {
        return;
    }
    var v: TorusHit;
    if (params.config.w == 1u && params.config.z == 0u) {
        v = torus_intersect_from_surface(rays[i], surfaces[i], params.torus, params.config.y);
    } else {
        v = torus_trace(rays[i], params.torus, params.config.y, params.config.z == 1u);
    }
    results[2u * i] = vec4<f32>(v.t, v.normal);
    results[2u * i + 1u] = vec4<f32>(f32(v.code), f32(v.why), 0.0, 0.0);
}
