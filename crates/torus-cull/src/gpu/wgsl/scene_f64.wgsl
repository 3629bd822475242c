// The scene traversal's escalated leaf where the shader has f64 (src/gpu/scene.rs): the
// device's f64 finish (finish_module/*.wgsl, the CPU's f64 path step for step) on the
// world ray over the leaf's clipped range; what it hands back (TORUS_F64_STATUS_HOST)
// stays escalated, for the host.
//
// mirrors: tc_scene_escalated -> crate::gpu::scene_bvh::host_leaf (the f64 path, on the device)

fn tc_scene_escalated(ray: TorusRay, i: u32) -> TcSceneLeaf {
    let world = TorusWorldRay(ray.origin, ray.t_min, ray.direction, ray.t_max);
    let h = torus_finish_f64(world, torus_scene_tori64[i], TORUS_F64_FOLLOW);
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
