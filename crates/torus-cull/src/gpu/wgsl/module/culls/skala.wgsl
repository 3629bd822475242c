// ---------------------------------------------------------------------------------------
// mirrors: tc_skala_keeps -> crate::cull::skala::skala_keeps

// `skala` (src/cull/skala.rs): Cychosz's sphere and slab, then in the plane through the
// line parallel to the axis (distance a from it; A = a·h): the outer band a ≥ R shrinks
// the slab to the section's height h_c, and the hole a < R − r rejects a line that falls
// between the circles k, k′. R = 1 here; d is unit, so no rescaling.
fn tc_skala_keeps(b: TcBounds, q: vec3<f32>, d: vec3<f32>) -> bool {
    let ss = tc_sphere_slab(b, q, d);
    if (!ss.keep) {
        return false;
    }
    let len_sq = dot(d, d);
    let h_sq = d.x * d.x + d.z * d.z;
    if (h_sq < TC_AXIS_PARALLEL_H2 * len_sq) {
        return q.x * q.x + q.z * q.z > b.inner_sq;
    }
    let a_h = abs(q.x * d.z - q.z * d.x);
    let a_h_sq = a_h * a_h;
    if (a_h_sq >= h_sq) {
        // Outer band (case c; h_c² < 0 is case d).
        let reach_sq = ss.unit_y_sq * ss.half_chord_sq;
        if (q.y * q.y <= reach_sq) {
            return true;
        }
        let lowest = abs(q.y) - sqrt(reach_sq);
        let h = sqrt(h_sq);
        let off = a_h - h;
        return lowest * lowest * h_sq <= b.minor_sq * h * h - off * off;
    }
    if (a_h_sq < b.inner_sq * h_sq) {
        // Hole (case a): reject iff x_B·h·|d_y| ≥ |M| + r·h·(|d| − |d_y|).
        let moment = (q.x * d.x + q.z * d.z) * d.y - q.y * h_sq;
        let edge = (b.inner_sq * h_sq - a_h_sq) * (d.y * d.y);
        if (edge < moment * moment) {
            return true;
        }
        let rhs = abs(moment) + b.minor * sqrt(h_sq) * (sqrt(len_sq) - abs(d.y));
        return edge < rhs * rhs;
    }
    // Case b: sphere and slab keep it.
    return true;
}
