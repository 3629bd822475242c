// ---------------------------------------------------------------------------------------
// The certificate (src/certified/certificate.rs; /work/f32-spec.md §3–5), GPU constants.
//
// mirrors: tc_point_bound -> crate::certified::certificate::point_bound
// mirrors: tc_convex_positive -> crate::certified::certificate::convex_positive
// mirrors: tc_lowest -> crate::certified::certificate::lowest
// mirrors: tc_convex_piece_positive -> crate::certified::certificate::convex_piece_positive
// mirrors: tc_positive -> crate::certified::certificate::positive

struct TcLine {
    q: vec3<f32>,
    d: vec3<f32>,
    rr: f32,
    // ε_p(u) = line_rel·(|q| + |u|) + line_abs: the computed point's distance from the
    // true line's point at u, before the point's own rounding.
    line_rel: f32,
    line_abs: f32,
    q_len: f32,
    k: f32, // 1 − rr²
    c2_err: f32,
};

struct TcPointBound {
    f_lo: f32,
    slope_lo: f32,
    slope_hi: f32,
    sdf_lo: f32,
    sdf_hi: f32,
};

fn tc_point_bound(l: TcLine, u: f32) -> TcPointBound {
    // Mul then add (an fma, if the compiler contracts, is only more accurate).
    let p = l.q + u * l.d;
    let eps_p = l.line_rel * (l.q_len + abs(u)) + l.line_abs + TC_G * 3.1 * TC_U * (l.q_len + abs(u));
    let rho_sq = p.x * p.x + p.z * p.z;
    let rho = sqrt(rho_sq);
    let e = rho - 1.0;
    let h = sqrt(e * e + p.y * p.y);
    let sdf = h - l.rr;
    // As the CPU's (3U·(ρ + h) + U·(1 + 2rr) of rounding, bounded by 4U·(ρ + h) +
    // 2U·(1 + rr)), times G: that also covers a sqrt good to 4.5 ulp only.
    let sdf_err = eps_p + TC_G * 4.0 * TC_U * (rho + h) + TC_G * 2.0 * TC_U * (1.0 + l.rr);
    var b: TcPointBound;
    b.sdf_lo = sdf - sdf_err;
    b.sdf_hi = sdf + sdf_err;
    let g_plus_lo = l.k + 2.0 * max(rho - sdf_err, 0.0);
    let f_lo = b.sdf_lo * (2.0 * l.rr + b.sdf_lo) * g_plus_lo * (1.0 - TC_G * 8.0 * TC_U);
    b.f_lo = select(-1.0, f_lo, b.sdf_lo > 0.0 && tc_finite(f_lo));
    let p_sq = rho_sq + p.y * p.y;
    let a = p_sq + l.k;
    let bb = dot(p, l.d);
    let c = p.x * l.d.x + p.z * l.d.z;
    let slope = 4.0 * a * bb - 8.0 * c;
    // |p| ≤ (|q| + |u|)·(1 + 17U) (|d̂| = 1 within 16.5U), as on the CPU.
    let p_len = (l.q_len + abs(u)) * (1.0 + 32.0 * TC_U);
    // Rounding (at most 10 roundings in a monomial), the line's error through F's Hessian
    // (‖H‖ ≤ 12|p|² + 12), and d̂'s error through ‖∇F‖ ≤ 4|p|³ + 12|p|: on the CPU d̂'s
    // rounding (2U), here the f32 transform's 24.4U (line_rel) plus that.
    let slope_err = TC_G * 10.0 * TC_U * (4.0 * abs(a) * abs(bb) + 8.0 * abs(c))
        + (12.0 * p_sq + 12.0) * eps_p
        + (4.0 * p_sq * p_len + 12.0 * p_len) * (l.line_rel + TC_G * 2.0 * TC_U);
    b.slope_lo = slope - slope_err;
    b.slope_hi = slope + slope_err;
    return b;
}

// F > 0 on the convex piece [alpha, beta].
fn tc_convex_positive(alpha: f32, beta: f32, at_a: TcPointBound, at_b: TcPointBound) -> bool {
    let both = at_a.f_lo > 0.0 && at_b.f_lo > 0.0;
    let sa = at_a.slope_lo;
    let sb = at_b.slope_hi;
    let lhs = at_a.f_lo * sb + at_b.f_lo * (-sa);
    let rhs = (-sa) * sb * (beta - alpha) * (1.0 + TC_G * 8.0 * TC_U);
    return both && (sa >= 0.0 || sb <= 0.0 || lhs > rhs);
}

// F's lowest point on a convex piece [alpha, beta], approximately (any point is sound, a
// better one proves more): Newton on F′ = 4u³ + 2c2·u + c1 from the piece's outer end.
fn tc_lowest(c2: f32, c1: f32, start_at: f32, alpha: f32, beta: f32) -> f32 {
    var u = start_at;
    for (var i = 0; i < 5; i++) {
        let slope = (4.0 * u * u + 2.0 * c2) * u + c1;
        let curvature = 12.0 * u * u + 2.0 * c2;
        let next = u - slope / select(1.0, curvature, curvature > 0.0);
        u = select(u, next, curvature > 0.0 && tc_finite(next));
    }
    return clamp(u, alpha, beta);
}

// F > 0 on the convex piece [alpha, beta], split at F's lowest point m: sdf(m) > s > 0
// keeps the line outside the tube on [m − s, m + s] (sdf is 1-Lipschitz, d̂ a unit
// vector up to the line's error, which sdf_lo includes); the tangents prove each side.
fn tc_convex_piece_positive(
    l: TcLine,
    c2: f32,
    c1: f32,
    start_at: f32,
    alpha: f32,
    at_a: TcPointBound,
    beta: f32,
    at_b: TcPointBound,
) -> bool {
    let m = tc_lowest(c2, c1, start_at, alpha, beta);
    let at_m = tc_point_bound(l, m);
    if (!(at_m.sdf_lo > 0.0)) {
        return false;
    }
    // |d̂| may exceed 1 by 16.5U: the clearance shrinks by as much (and more).
    let clear = at_m.sdf_lo * (1.0 - 64.0 * TC_U);
    let before = max(m - clear, alpha);
    let after = min(m + clear, beta);
    return tc_convex_positive(alpha, before, at_a, tc_point_bound(l, before))
        && tc_convex_positive(after, beta, tc_point_bound(l, after), at_b);
}

// F > 0 on [lo, hi], proved (true for an empty interval): F″ = 12u² + 2c2 makes F convex
// left of −w and right of w, concave (at most) between.
fn tc_positive(l: TcLine, c2: f32, c1: f32, lo: f32, hi: f32) -> bool {
    if (hi < lo) {
        return true;
    }
    let w = sqrt(max((l.c2_err - c2) * ((1.0 + TC_G * 8.0 * TC_U) / 6.0), 0.0));
    let at_lo = tc_point_bound(l, lo);
    let at_hi = tc_point_bound(l, hi);
    // Left convex piece [lo, min(hi, −w)].
    if (lo <= -w) {
        let end = min(hi, -w);
        var at_end = at_hi;
        if (hi > -w) {
            at_end = tc_point_bound(l, -w);
        }
        if (!tc_convex_piece_positive(l, c2, c1, lo, lo, at_lo, end, at_end)) {
            return false;
        }
    }
    // Right convex piece [max(lo, w), hi].
    if (w <= hi) {
        let start = max(lo, w);
        var at_start = at_lo;
        if (lo < w) {
            at_start = tc_point_bound(l, w);
        }
        if (!tc_convex_piece_positive(l, c2, c1, hi, start, at_start, hi, at_hi)) {
            return false;
        }
    }
    // Middle piece [max(lo, −w), min(hi, w)]: F″ ≤ 4·c2_err there.
    let alpha = max(lo, -w);
    let beta = min(hi, w);
    if (alpha <= beta) {
        var f_alpha = at_lo.f_lo;
        if (lo < -w) {
            f_alpha = tc_point_bound(l, -w).f_lo;
        }
        var f_beta = at_hi.f_lo;
        if (hi > w) {
            f_beta = tc_point_bound(l, w).f_lo;
        }
        let span = beta - alpha;
        let sag = 0.5 * (1.0 + TC_G * 8.0 * TC_U) * l.c2_err * span * span;
        if (!(f_alpha > 0.0 && f_beta > 0.0 && min(f_alpha, f_beta) > sag)) {
            return false;
        }
    }
    return true;
}

