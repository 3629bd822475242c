// The scene traversal's leaf where the shader has no f64 (src/gpu/scene.rs).
//
// tc_scene_plan: the certified f32 module on o − c, an f32 subtraction (the value the
// library's host rounds to for a near origin), unmoved: with no f64 the foot point cannot
// be formed within what the module's line error assumes (o − c would already carry
// u·|o − c| across the line), so the module's error grows with |o − c|/R and a far
// origin often escalates. A torus whose centre f32 does not hold (Torus::new_f64; the
// tori buffer marks it with a negative R + r) and an origin beyond 2²⁰·R skip the module.
//
// tc_scene_escalated: the leaf stays escalated, and the ray goes to the host
// (TORUS_SCENE_HOST).
//
// mirrors: tc_scene_plan -> crate::gpu::frame::Frame::pack (o − c alone, in f32)
// mirrors: tc_scene_shift -> none (t0 = 0)
// mirrors: tc_scene_escalated -> none (the host finishes the ray: crate::gpu::scene_bvh::host_leaf)

fn tc_scene_plan(ray: TorusRay, i: u32, lo: f32, hi: f32) -> TcScenePlan {
    let tor = torus_scene_tori[i];
    let v = ray.origin - tor.center.xyz;
    if (!(tor.center.w > 0.0) || !(length(v) < TC_SCENE_FAR * tor.params.rot_x.w)) {
        return tc_scene_decided(TORUS_ESCALATE);
    }
    var plan = tc_scene_decided(TC_SCENE_RUN);
    plan.ray = TorusRay(v, lo, ray.direction, hi);
    return plan;
}

// The origin is not moved: t is the ray's.
fn tc_scene_shift(t: f32, t0: vec2<f32>) -> f32 {
    return t;
}

fn tc_scene_escalated(ray: TorusRay, i: u32, from_surface: bool) -> TcSceneLeaf {
    var leaf: TcSceneLeaf;
    leaf.code = TORUS_ESCALATE;
    leaf.by_f64 = false;
    return leaf;
}
