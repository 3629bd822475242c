// ---------------------------------------------------------------------------------------
// mirrors: tc_sphere_keeps -> crate::cull::sphere::SphereCull::keeps_lanes

// `sphere`: the foot point within the padded bounding sphere.
fn tc_sphere_keeps(b: TcBounds, q: vec3<f32>, dh: vec3<f32>) -> bool {
    return dot(q, q) <= b.outer_sq;
}
