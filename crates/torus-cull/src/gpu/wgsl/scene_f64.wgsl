// The scene traversal's leaf where the shader has f64 (src/gpu/scene.rs).
//
// tc_scene_plan: the ray as the library's host packs it for the single-torus kernel
// (Frame::pack), formed here in f64: o − c from the f64 centre, an origin farther than
// TC_SCENE_REBASE·(R + r) moved along its line to the foot point, t0 = −(o − c)·d/|d|²,
// the range shifted by −t0 and clipped to |t| ≤ (|foot| + 4(R + r))/|d|, each rounded
// once to f32, for the certified f32 module; its t shifted back by t0 in f64. The
// f32 line's error then no longer grows with the origin's distance (the module's
// 16.9u·|o − c|/R term is taken at the foot point), so a far origin is proved in f32
// where o − c sent unmoved would need the f64 finish. WGSL's f64 → f32 conversion may
// round either way (one ulp, not half): the module's line error takes its terms about
// twice (32u for the 16.9u derived), which covers it. The centre need not be an f32
// value (Torus::new_f64): o − c is formed from its f64 value.
//
// tc_scene_escalated: the device's f64 finish (finish_module/*.wgsl, the CPU's f64 path
// step for step) on the world ray over the leaf's clipped range, from the surface for a
// spawned ray's own torus; what it hands back (TORUS_F64_STATUS_HOST) stays escalated,
// for the host.
//
// mirrors: tc_scene_plan -> crate::gpu::frame::Frame::pack (on the device, in f64)
// mirrors: tc_scene_shift -> crate::gpu::escalation::shifted
// mirrors: tc_scene_escalated -> crate::gpu::scene_bvh::host_leaf (the f64 path, on the device)

fn tc_scene_plan(ray: TorusRay, i: u32, lo: f32, hi: f32) -> TcScenePlan {
    let t64 = torus_scene_tori64[i];
    let c = vec3<f64>(t64.center_x, t64.center_y, t64.center_z);
    let d = vec3<f64>(f64(ray.direction.x), f64(ray.direction.y), f64(ray.direction.z));
    let rel = vec3<f64>(f64(ray.origin.x), f64(ray.origin.y), f64(ray.origin.z)) - c;
    let dist = sqrt(tc_dot64(rel, rel));
    // Beyond 2²⁰·R the f64 foot point's own error is no longer negligible beside the
    // module's line error (Frame::pack's FAR_REL): the f64 finish answers.
    if (!(dist <= f64(TC_SCENE_FAR) * t64.major)) {
        return tc_scene_decided(TORUS_ESCALATE);
    }
    let outer = t64.outer * t64.major;
    let len_sq = tc_dot64(d, d);
    var t0 = 0.0lf;
    if (dist > f64(TC_SCENE_REBASE) * outer) {
        t0 = -tc_dot64(rel, d) / len_sq;
    }
    let start = rel + d * t0;
    let reach = (sqrt(tc_dot64(start, start)) + 4.0 * outer) / sqrt(len_sq);
    let limit = min(reach * (1.0 + 1e-6), f64(TC_SCENE_F32_MAX));
    var plan = tc_scene_decided(TC_SCENE_RUN);
    plan.ray = TorusRay(
        vec3<f32>(f32(start.x), f32(start.y), f32(start.z)),
        f32(clamp(f64(lo) - t0, -limit, limit)),
        ray.direction,
        f32(clamp(f64(hi) - t0, -limit, limit)),
    );
    let t0_hi = f32(t0);
    plan.t0 = vec2<f32>(t0_hi, f32(t0 - f64(t0_hi)));
    return plan;
}

// The module's t on the moved ray, back on the ray: t + t0 in f64, rounded once (a t
// beyond f32 comes back infinite, which the leaf's range test refuses: escalated).
fn tc_scene_shift(t: f32, t0: vec2<f32>) -> f32 {
    return f32((f64(t) + f64(t0.x)) + f64(t0.y));
}

fn tc_scene_escalated(ray: TorusRay, i: u32, from_surface: bool) -> TcSceneLeaf {
    let world = TorusWorldRay(ray.origin, ray.t_min, ray.direction, ray.t_max);
    let instruction = select(TORUS_F64_FOLLOW, TORUS_F64_SURFACE_ALWAYS, from_surface);
    let h = torus_finish_f64(world, torus_scene_tori64[i], instruction);
    var leaf: TcSceneLeaf;
    leaf.by_f64 = true;
    leaf.t = h.t;
    leaf.normal = h.normal;
    if (h.status == TORUS_F64_STATUS_FRONT || h.status == TORUS_F64_STATUS_BACK) {
        leaf.code = TORUS_HIT;
    } else if (h.status == TORUS_F64_STATUS_MISS) {
        leaf.code = TORUS_MISS;
    } else {
        leaf.code = TORUS_ESCALATE;
        leaf.by_f64 = false;
    }
    return leaf;
}
