// ---------------------------------------------------------------------------------------
// mirrors: tc_hyperboloid_reached -> crate::cull::quadric::reaches_hyperboloid
// mirrors: tc_quadric_keeps -> crate::cull::quadric::QuadricCull::keeps_lanes

// H = ρ² − c·y′² − (R − r_η)² at the computed point q + τ·d may be ≥ 0 at the exact point
// q + τ·d of the scaled line: the rounding (running bound) and the point's own error
// through H's gradient (|∂H| ≤ 2|x|, 2c|y′|, 2|z|) and its second order.
fn tc_hyperboloid_reached(b: TcBounds, q: vec3<f32>, d: vec3<f32>, tau: f32) -> bool {
    let x = q + tau * d;
    let c = tc_ev_exact(b.hyperboloid);
    let h = tc_ev_sub(
        tc_ev_sub(
            tc_ev_add(tc_ev_mul(tc_ev_exact(x.x), tc_ev_exact(x.x)), tc_ev_mul(tc_ev_exact(x.z), tc_ev_exact(x.z))),
            tc_ev_mul(c, tc_ev_mul(tc_ev_exact(x.y), tc_ev_exact(x.y))),
        ),
        tc_ev_exact(b.inner_sq),
    );
    let delta = tc_point_error(q, d, tau);
    let moved = 2.0 * (abs(x.x) + abs(x.z) + b.hyperboloid * abs(x.y)) * delta + 3.0 * delta * delta;
    return tc_ev_maybe_nonnegative(TcEv(h.v, h.e + moved));
}

// `quadric` (src/cull/quadric.rs): the ellipsoid's chord, clipped to the slab, must
// reach H ≥ 0: at an end, or at the vertex τ* = B/|A| when H(τ) = Aτ² + 2Bτ + C is
// concave, tested as C·|A| + B² ≥ 0. Each test is widened by its error bound, and the
// vertex is tried wherever it may be concave and inside (a vertex tried outside the
// clip only keeps more: its H is H's maximum).
fn tc_quadric_keeps(b: TcBounds, q0: vec3<f32>, d0: vec3<f32>) -> bool {
    let chord = tc_ellipsoid_slab(b, q0, d0);
    if (!chord.keep) {
        return false;
    }
    let q = chord.foot;
    let d = chord.dir;
    let half = sqrt(max(chord.half_chord_sq, 0.0) * chord.inv_len_sq);
    let dy = select(d.y, select(TC_HORIZONTAL_DY, -TC_HORIZONTAL_DY, d.y < 0.0), abs(d.y) < TC_HORIZONTAL_DY);
    let inv_dy = 1.0 / dy;
    let t_bottom = (-b.slab - q.y) * inv_dy;
    let t_top = (b.slab - q.y) * inv_dy;
    // Clamped to the chord on both sides: a no-op unless the clip is empty (which no
    // line through the torus gives: its points there are η inside), where it keeps
    // q + τ·d finite (WGSL may assume no infinities).
    let lo = clamp(max(-half, min(t_bottom, t_top)), -half, half);
    let hi = clamp(min(half, max(t_bottom, t_top)), -half, half);
    if (tc_hyperboloid_reached(b, q, d, lo) || tc_hyperboloid_reached(b, q, d, hi)) {
        return true;
    }
    let c = tc_ev_exact(b.hyperboloid);
    let qx = tc_ev_exact(q.x);
    let qy = tc_ev_exact(q.y);
    let qz = tc_ev_exact(q.z);
    let dx = tc_ev_exact(d.x);
    let dy_ = tc_ev_exact(d.y);
    let dz = tc_ev_exact(d.z);
    let neg_a = tc_ev_sub(tc_ev_sub(tc_ev_mul(c, tc_ev_mul(dy_, dy_)), tc_ev_mul(dx, dx)), tc_ev_mul(dz, dz));
    let half_b = tc_ev_sub(tc_ev_add(tc_ev_mul(qx, dx), tc_ev_mul(qz, dz)), tc_ev_mul(c, tc_ev_mul(qy, dy_)));
    let h_q = tc_ev_sub(
        tc_ev_sub(tc_ev_add(tc_ev_mul(qx, qx), tc_ev_mul(qz, qz)), tc_ev_mul(c, tc_ev_mul(qy, qy))),
        tc_ev_exact(b.inner_sq),
    );
    let maybe_concave = !tc_ev_positive(TcEv(-neg_a.v, neg_a.e));
    let after_lo = tc_ev_sub(half_b, tc_ev_mul(tc_ev_exact(lo), neg_a));
    let before_hi = tc_ev_sub(tc_ev_mul(tc_ev_exact(hi), neg_a), half_b);
    let maybe_inside = tc_ev_maybe_nonnegative(after_lo) && tc_ev_maybe_nonnegative(before_hi);
    let vertex = tc_ev_add(tc_ev_mul(h_q, neg_a), tc_ev_mul(half_b, half_b));
    return maybe_concave && maybe_inside && tc_ev_maybe_nonnegative(vertex);
}
