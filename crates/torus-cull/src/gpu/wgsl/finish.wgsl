// The library's f64 finish pass (src/gpu/finish.rs runs it, on an adapter with
// SHADER_F64): finish_module/*.wgsl's functions behind their generated header, with the
// bindings and the entry point below. One ray per invocation.
//
// Per ray, in: the world ray (TorusWorldRay) and the host's instruction in word 7 of its
// output record (TORUS_F64_FOLLOW: finish where the f32 kernel escalated;
// TORUS_F64_ALWAYS: finish it whatever the kernel wrote; TORUS_F64_SURFACE_FOLLOW and
// TORUS_F64_SURFACE_ALWAYS: the same for a ray from a surface point; TORUS_F64_HOST: the
// host answers it). Out: (t, normal.xyz) and (point.xyz, status) as f32 (TorusHit64);
// status TORUS_F64_STATUS_PROVED where the f32 kernel proved the answer.
//
// mirrors: write_answer -> none (a record; the host reads it with crate::gpu::finish::device_answer)
// mirrors: finish_main -> crate::gpu::intersector::GpuIntersector::dispatch_with (the f64 pass)

struct Params {
    // The f32 kernel's parameter block: only config.x (rays in this dispatch) is read.
    torus: array<vec4<f32>, 7>,
    config: vec4<u32>,
};

// Storage, as in kernel.wgsl (lavapipe recompiles a kernel per change of an inlined uniform).
@group(0) @binding(0) var<storage, read> params: Params;
@group(0) @binding(1) var<storage, read> world: array<TorusWorldRay>;
// The f32 kernel's records: (t, n.xyz) and (code, why, 0, 0).
@group(0) @binding(2) var<storage, read> verdicts: array<vec4<f32>>;
@group(0) @binding(3) var<storage, read> torus64: TorusParams64;
@group(0) @binding(4) var<storage, read_write> finished: array<vec4<f32>>;

fn write_answer(i: u32, answer: TorusHit64) {
    finished[2u * i] = vec4<f32>(answer.t, answer.normal);
    finished[2u * i + 1u] = vec4<f32>(answer.point, f32(answer.status));
}

@compute @workgroup_size(64)
fn finish_main(@builtin(global_invocation_id) gid: vec3<u32>) {
    let i = gid.x;
    if (i >= params.config.x) {
        return;
    }
    let instruction = u32(finished[2u * i + 1u].w);
    if (instruction == TORUS_F64_HOST) {
        write_answer(i, tc_fin_status(TORUS_F64_STATUS_HOST));
        return;
    }
    // The host's decode of the f32 record (gpu/escalation.rs, verdict): a miss, or a hit with a
    // finite t and normal, is proved; everything else escalated.
    let v0 = verdicts[2u * i];
    let code = u32(verdicts[2u * i + 1u].x);
    if (!torus_finish_wanted(instruction, code, v0.x, v0.yzw)) {
        write_answer(i, tc_fin_status(TORUS_F64_STATUS_PROVED));
        return;
    }
    write_answer(i, torus_finish_f64(world[i], torus64, instruction));
}
