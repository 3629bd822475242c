// ---------------------------------------------------------------------------------------
// mirrors: tc_inside_hole -> crate::cull::thick_cylinder::ThickCylinderCull::keeps_lanes (the hole test)
// mirrors: tc_thick_cylinder_keeps -> crate::cull::thick_cylinder::ThickCylinderCull::keeps_lanes

// ρ² at the point q + τ·d, proved below the padded hole's (R − r_η)² (the margin of a
// point in the torus is 2(R − r)η, which G·u·ρ² may not be at ν = 1.01): the point's
// own error through ρ²'s gradient, and the rounding.
fn tc_inside_hole(b: TcBounds, q: vec3<f32>, d: vec3<f32>, tau: f32) -> bool {
    let x = q + tau * d;
    let delta = tc_point_error(q, d, tau);
    let rho_sq = tc_ev_add(tc_ev_mul(tc_ev_exact(x.x), tc_ev_exact(x.x)), tc_ev_mul(tc_ev_exact(x.z), tc_ev_exact(x.z)));
    let moved = 2.0 * (abs(x.x) + abs(x.z)) * delta + 2.0 * delta * delta;
    return rho_sq.v + (rho_sq.e + moved) * (1.0 + 0.0009765625) < b.inner_sq;
}

// `thick_cylinder`: clip the line to the slab and the outer cylinder; reject if nothing
// is left or both ends are in the hole (ρ² is convex along the line).
fn tc_thick_cylinder_keeps(b: TcBounds, q: vec3<f32>, d: vec3<f32>) -> bool {
    let n = d / sqrt(dot(d, d));
    var lo = -4.0;
    var hi = 4.0;
    if (abs(n.y) < TC_PARALLEL_COMPONENT) {
        if (abs(q.y) > b.minor) {
            return false;
        }
    } else {
        let inv = 1.0 / n.y;
        let t0 = (-b.minor - q.y) * inv;
        let t1 = (b.minor - q.y) * inv;
        lo = max(lo, min(t0, t1));
        hi = min(hi, max(t0, t1));
    }
    let h2 = n.x * n.x + n.z * n.z;
    let half_b = q.x * n.x + q.z * n.z;
    let rho2_foot = q.x * q.x + q.z * q.z;
    if (h2 < TC_AXIS_PARALLEL_H2) {
        return rho2_foot <= b.outer_sq && rho2_foot >= b.inner_sq;
    }
    let disc = half_b * half_b - h2 * (rho2_foot - b.outer_sq);
    if (disc < 0.0) {
        return false;
    }
    let root = sqrt(disc);
    lo = max(lo, (-half_b - root) / h2);
    hi = min(hi, (-half_b + root) / h2);
    if (lo > hi) {
        return false;
    }
    return !(tc_inside_hole(b, q, n, lo) && tc_inside_hole(b, q, n, hi));
}
