// ---------------------------------------------------------------------------------------
// mirrors: tc_aabb_axis -> crate::cull::aabb::AabbCull::keeps_lanes (one axis)
// mirrors: tc_aabb_keeps -> crate::cull::aabb::AabbCull::keeps_lanes

// One axis of `aabb`'s slab method: (lo, hi) narrowed to where |q_i + t d_i| ≤ half.
// A component below PARALLEL_COMPONENT is parallel (over |t| ≤ 4 the line moves by
// less than 4·10⁻²⁰ along the axis): in the slab or not at all; x = 2 marks "empty".
fn tc_aabb_axis(range: vec2<f32>, q: f32, d: f32, half: f32) -> vec2<f32> {
    if (abs(d) < TC_PARALLEL_COMPONENT) {
        return select(vec2<f32>(2.0, -2.0), range, abs(q) <= half);
    }
    let inv = 1.0 / d;
    let t0 = (-half - q) * inv;
    let t1 = (half - q) * inv;
    return vec2<f32>(max(range.x, min(t0, t1)), min(range.y, max(t0, t1)));
}

// `aabb`: the box [−(R + r_η), R + r_η] × [−r_η, r_η] × [−(R + r_η), R + r_η]. The line's
// points in the torus are within |t| ≤ 1 + rr + E < 4 of the foot point, so the slabs
// are intersected with t ∈ [−4, 4] (where the CPU's are unbounded).
fn tc_aabb_keeps(b: TcBounds, q: vec3<f32>, d: vec3<f32>) -> bool {
    var range = vec2<f32>(-4.0, 4.0);
    range = tc_aabb_axis(range, q.x, d.x, b.outer);
    range = tc_aabb_axis(range, q.y, d.y, b.minor);
    range = tc_aabb_axis(range, q.z, d.z, b.outer);
    return range.x <= range.y;
}
