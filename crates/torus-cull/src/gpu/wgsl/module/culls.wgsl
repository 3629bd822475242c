// ---------------------------------------------------------------------------------------
// The culls (src/cull/*.rs): the CPU's math on the kernel's line, q (the foot point, in
// units of R) and dh (a unit direction), against the torus R = 1, r = rr padded by the
// GPU's margin η_gpu = SAFETY_REL·(1 + rr) + E (the bounds in Params, made by the host:
// src/gpu/bounds.rs). E bounds the kernel's line error on every line that meets the
// torus, so the computed line meets the torus padded by E; what is left of the margin,
// SAFETY_REL·(1 + rr) = 4096u·(1 + rr), absorbs each cull's own f32 evaluation as on the
// CPU (docs/math.md, "The GPU's culls"): the kernel's line is a foot point with |q| ≲ 2
// and a unit direction, so every rounding acts like moving the line (or a radius) by a
// few G·u·(1 + rr), far below. Two culls compare values whose margin is not of that
// size, and carry an explicit error bound instead: `quadric` (H's margin is only
// (R − r)·η) and `discriminant` (Δ has no margin at a tangent: a running error bound).
// `thick_cylinder`'s hole test bounds its ρ² the same way (margin 2(R − r)·η).
// WGSL may assume no infinities or NaNs: every division below has a divisor bounded
// away from 0, where the CPU's divides by 0 and lets ±∞ decide.
//
// mirrors: tc_bounds_of -> crate::gpu::bounds::bounds_rows (the rows it unpacks)
// mirrors: tc_ev_exact -> none (the GPU culls' running error bound)
// mirrors: tc_ev_round -> none
// mirrors: tc_ev_add -> none
// mirrors: tc_ev_sub -> none
// mirrors: tc_ev_mul -> none
// mirrors: tc_ev_scale -> none
// mirrors: tc_ev_positive -> none
// mirrors: tc_ev_maybe_nonnegative -> none
// mirrors: tc_point_error -> none (the GPU's point error)
// mirrors: tc_sphere_keeps -> crate::cull::sphere::SphereCull::keeps_lanes
// mirrors: tc_aabb_axis -> crate::cull::aabb::AabbCull::keeps_lanes (one axis)
// mirrors: tc_aabb_keeps -> crate::cull::aabb::AabbCull::keeps_lanes
// mirrors: tc_sphere_slab -> crate::cull::cychosz::sphere_slab
// mirrors: tc_inside_hole -> crate::cull::thick_cylinder::ThickCylinderCull::keeps_lanes (the hole test)
// mirrors: tc_thick_cylinder_keeps -> crate::cull::thick_cylinder::ThickCylinderCull::keeps_lanes
// mirrors: tc_skala_keeps -> crate::cull::skala::skala_keeps
// mirrors: tc_ellipsoid_slab -> crate::cull::ellipsoid::ellipsoid_slab
// mirrors: tc_hyperboloid_reached -> crate::cull::quadric::reaches_hyperboloid
// mirrors: tc_quadric_keeps -> crate::cull::quadric::QuadricCull::keeps_lanes
// mirrors: tc_discriminant_keeps -> crate::cull::discriminant::no_real_root
// mirrors: tc_cull_keeps -> crate::cull::kernel::keeps_scalar (the dispatch; codes in GpuCull::ALL's order)

struct TcBounds {
    outer: f32,
    outer_sq: f32,
    minor: f32,
    minor_sq: f32,
    inner_sq: f32,
    y_scale: f32,
    slab: f32,
    hyperboloid: f32,
    minor_rel_sq: f32,
};

fn tc_bounds_of(torus: TorusParams) -> TcBounds {
    var b: TcBounds;
    b.outer = torus.bounds_a.x;
    b.outer_sq = torus.bounds_a.y;
    b.minor = torus.bounds_a.z;
    b.minor_sq = torus.bounds_a.w;
    b.inner_sq = torus.bounds_b.x;
    b.y_scale = torus.bounds_b.y;
    b.slab = torus.bounds_b.z;
    b.hyperboloid = torus.bounds_b.w;
    b.minor_rel_sq = torus.bounds_c.x;
    return b;
}

// A value and a bound on its distance from the exact value of the same expression on
// exact inputs: |v − exact| ≤ e. Each operation adds its own rounding, G·u·|result|
// (+, −, × are correctly rounded in WGSL, G = 4 leaves room), plus FLUSH_FLOOR for a flushed
// subnormal; a product adds |a|e_b + |b|e_a + e_a·e_b, which is exact, not first
// order. The bounds are themselves rounded (down by at most ~1 + 200u over a cull):
// `ev_certain` widens them by 2⁻¹⁰ before a sign is read.
struct TcEv {
    v: f32,
    e: f32,
};

fn tc_ev_exact(v: f32) -> TcEv {
    return TcEv(v, 0.0);
}

fn tc_ev_round(v: f32) -> f32 {
    return TC_G * TC_U * abs(v) + TC_FLUSH_FLOOR;
}

fn tc_ev_add(a: TcEv, b: TcEv) -> TcEv {
    let s = a.v + b.v;
    return TcEv(s, a.e + b.e + tc_ev_round(s));
}

fn tc_ev_sub(a: TcEv, b: TcEv) -> TcEv {
    let s = a.v - b.v;
    return TcEv(s, a.e + b.e + tc_ev_round(s));
}

fn tc_ev_mul(a: TcEv, b: TcEv) -> TcEv {
    let p = a.v * b.v;
    return TcEv(p, abs(a.v) * b.e + abs(b.v) * a.e + a.e * b.e + tc_ev_round(p));
}

// k·a for a small integer or power of two k (exact in f32).
fn tc_ev_scale(k: f32, a: TcEv) -> TcEv {
    let p = k * a.v;
    return TcEv(p, abs(k) * a.e + tc_ev_round(p));
}

// The exact value is > 0.
fn tc_ev_positive(a: TcEv) -> bool {
    return a.v > a.e * (1.0 + 0.0009765625);
}

// The exact value may be ≥ 0 (not proved < 0).
fn tc_ev_maybe_nonnegative(a: TcEv) -> bool {
    return a.v >= -a.e * (1.0 + 0.0009765625);
}

// How far the computed point q + τ·d (each component one product and one sum, fused or
// not) can stand from the exact one, in each coordinate.
fn tc_point_error(q: vec3<f32>, d: vec3<f32>, tau: f32) -> f32 {
    return TC_G * 2.0 * TC_U * (length(q) + length(d) * abs(tau)) * 1.01 + TC_FLUSH_FLOOR;
}

// `sphere`: the foot point within the padded bounding sphere.
fn tc_sphere_keeps(b: TcBounds, q: vec3<f32>) -> bool {
    return dot(q, q) <= b.outer_sq;
}

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

struct TcSphereSlab {
    half_chord_sq: f32,
    unit_y_sq: f32,
    keep: bool,
};

// `cychosz`: the sphere chord and the slab, squared, without a root (src/cull/cychosz.rs).
fn tc_sphere_slab(b: TcBounds, q: vec3<f32>, d: vec3<f32>) -> TcSphereSlab {
    var out: TcSphereSlab;
    out.half_chord_sq = b.outer_sq - dot(q, q);
    out.unit_y_sq = d.y * d.y / dot(d, d);
    let above = abs(q.y) - b.minor;
    let beyond_slab = above > 0.0 && above * above > out.unit_y_sq * out.half_chord_sq;
    out.keep = out.half_chord_sq >= 0.0 && !beyond_slab;
    return out;
}

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

struct TcEllipsoidChord {
    foot: vec3<f32>,
    dir: vec3<f32>,
    inv_len_sq: f32,
    half_chord_sq: f32,
    keep: bool,
};

// `ellipsoid` (src/cull/ellipsoid.rs): y scaled by s turns the outer ellipsoid into the
// sphere R + r_η; Cychosz's chord and slab |y′| ≤ s·r_η on the scaled line.
fn tc_ellipsoid_slab(b: TcBounds, q: vec3<f32>, d: vec3<f32>) -> TcEllipsoidChord {
    var out: TcEllipsoidChord;
    out.dir = vec3<f32>(d.x, b.y_scale * d.y, d.z);
    let o = vec3<f32>(q.x, b.y_scale * q.y, q.z);
    out.inv_len_sq = 1.0 / dot(out.dir, out.dir);
    out.foot = o - out.dir * (dot(o, out.dir) * out.inv_len_sq);
    out.half_chord_sq = b.outer_sq - dot(out.foot, out.foot);
    let unit_y_sq = out.dir.y * out.dir.y * out.inv_len_sq;
    let above = abs(out.foot.y) - b.slab;
    let beyond_slab = above > 0.0 && above * above > unit_y_sq * out.half_chord_sq;
    out.keep = out.half_chord_sq >= 0.0 && !beyond_slab;
    return out;
}

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

// `discriminant` (src/cull/discriminant.rs): F(t) = t⁴ + 2P t² + 8Q t + S along the line
// from its foot point f (unit d, R = 1) has no real root iff Δ′ > 0 and (P > 0 or
// S > P²), Δ′ = S(S − P²)² − 8Q²(P³ − 9PS + 54Q²). On the CPU that this suffices in f32
// is measured; here it is proved: the exact line is q + t·dh, whose exact foot point
// f* and unit direction d* the kernel does not have, so ρ², f_y² and d*_y² carry an
// error bound (f = q − (q·dh/|dh|²)·dh is within δ_f of f*), the whole evaluation runs
// on `Ev`, and a rejection needs every sign proved. A rejected line then misses the
// padded torus exactly, and the true line (within E of it) misses the torus.
fn tc_discriminant_keeps(b: TcBounds, q: vec3<f32>, d: vec3<f32>) -> bool {
    if (!tc_sphere_keeps(b, q)) {
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

// The cull `code` (GpuCull::ALL's order) on the scaled line: true keeps it.
fn tc_cull_keeps(code: u32, b: TcBounds, q: vec3<f32>, dh: vec3<f32>) -> bool {
    switch code {
        case TORUS_CULL_SPHERE: {
            return tc_sphere_keeps(b, q);
        }
        case TORUS_CULL_AABB: {
            return tc_aabb_keeps(b, q, dh);
        }
        case TORUS_CULL_CYCHOSZ: {
            return tc_sphere_slab(b, q, dh).keep;
        }
        case TORUS_CULL_THICK_CYLINDER: {
            return tc_thick_cylinder_keeps(b, q, dh);
        }
        case TORUS_CULL_SKALA: {
            return tc_skala_keeps(b, q, dh);
        }
        case TORUS_CULL_ELLIPSOID: {
            return tc_ellipsoid_slab(b, q, dh).keep;
        }
        case TORUS_CULL_QUADRIC: {
            return tc_quadric_keeps(b, q, dh);
        }
        case TORUS_CULL_DISCRIMINANT: {
            return tc_discriminant_keeps(b, q, dh);
        }
        default: {
            return true;
        }
    }
}

