// The scene traversal's escalated leaf where the shader has no f64 (src/gpu/scene.rs): the
// leaf stays escalated, and the ray goes to the host (TORUS_SCENE_HOST).
//
// mirrors: tc_scene_escalated -> none (the host finishes the ray: crate::gpu::scene_bvh::host_leaf)

fn tc_scene_escalated(ray: TorusRay, i: u32) -> TcSceneLeaf {
    var leaf: TcSceneLeaf;
    leaf.code = TORUS_ESCALATE;
    leaf.by_f64 = false;
    return leaf;
}
