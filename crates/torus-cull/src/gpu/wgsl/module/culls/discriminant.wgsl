// ---------------------------------------------------------------------------------------
// mirrors: tc_discriminant_keeps -> crate::cull::discriminant::no_real_root

// `discriminant` (src/cull/discriminant.rs): F(t) = t⁴ + 2P t² + 8Q t + S along the line
// from its foot point f (unit d, R = 1) has no real root iff Δ′ > 0 and (P > 0 or
// S > P²), Δ′ = S(S − P²)² − 8Q²(P³ − 9PS + 54Q²). On the CPU that this suffices in f32
// is measured; here it is proved: the exact line is q + t·dh, whose exact foot point
// f* and unit direction d* the kernel does not have, so ρ², f_y² and d*_y² carry an
// error bound (f = q − (q·dh/|dh|²)·dh is within δ_f of f*), the whole evaluation runs
// on `Ev`, and a rejection needs every sign proved. A rejected line then misses the
// padded torus exactly, and the true line (within E of it) misses the torus.
fn tc_discriminant_keeps(b: TcBounds, q: vec3<f32>, d: vec3<f32>) -> bool {
    if (!tc_sphere_keeps(b, q, d)) {
        return false;
    }
    let n2 = dot(d, d);
    let along = dot(q, d) / n2;
    let f = q - along * d;
    let q_len = length(q);
    // along's error: the dot product's G·3u·|q||d| over |d|² (1 within 16.5u), the
    // division's; f's: that times |d|, and each component's own rounding.
    let delta_f = TC_G * 8.0 * TC_U * (q_len + abs(along)) * 1.01 + TC_FLUSH_FLOOR;
    // |ρ(f) − ρ(f*)| and |f_y − f*_y| are at most δ_f, so the squares move by at most
    // 2|·|δ_f + δ_f² (|·| of f, plus 1 % for its own rounding).
    let rho_sq = tc_ev_add(tc_ev_mul(tc_ev_exact(f.x), tc_ev_exact(f.x)), tc_ev_mul(tc_ev_exact(f.z), tc_ev_exact(f.z)));
    let fy_sq = tc_ev_mul(tc_ev_exact(f.y), tc_ev_exact(f.y));
    let rho_len = sqrt(rho_sq.v) * 1.01;
    let rho_sq_in = TcEv(rho_sq.v, rho_sq.e + 2.0 * rho_len * delta_f + delta_f * delta_f);
    let fy_sq_in = TcEv(fy_sq.v, fy_sq.e + 2.0 * abs(f.y) * 1.01 * delta_f + delta_f * delta_f);
    // d*_y² = dh_y²/|dh|²: a product, a sum of three squares and a division (2.5 ulp).
    let uy = d.y * d.y / n2;
    let unit_y_sq = TcEv(uy, TC_G * 4.0 * TC_U * uy + TC_FLUSH_FLOOR);
    let one = tc_ev_exact(1.0);
    let rho_sq_m1 = tc_ev_sub(rho_sq_in, one);
    let bb = tc_ev_sub(fy_sq_in, tc_ev_exact(b.minor_rel_sq));
    let p = tc_ev_add(tc_ev_add(rho_sq_m1, bb), tc_ev_scale(2.0, unit_y_sq));
    let s = tc_ev_add(
        tc_ev_mul(rho_sq_m1, rho_sq_m1),
        tc_ev_mul(bb, tc_ev_add(tc_ev_scale(2.0, tc_ev_add(rho_sq_in, one)), bb)),
    );
    let q_sq = tc_ev_mul(fy_sq_in, unit_y_sq);
    let p_sq = tc_ev_mul(p, p);
    let s_minus_p_sq = tc_ev_sub(s, p_sq);
    let cubic = tc_ev_add(
        tc_ev_sub(tc_ev_mul(p_sq, p), tc_ev_scale(9.0, tc_ev_mul(p, s))),
        tc_ev_scale(54.0, q_sq),
    );
    let delta = tc_ev_sub(
        tc_ev_mul(tc_ev_mul(s, s_minus_p_sq), s_minus_p_sq),
        tc_ev_scale(8.0, tc_ev_mul(q_sq, cubic)),
    );
    let rootless = tc_ev_positive(delta) && (tc_ev_positive(p) || tc_ev_positive(s_minus_p_sq));
    return !rootless;
}
