// ---------------------------------------------------------------------------------------
// The path for one ray (src/certified/mod.rs, prove): the line in the torus frame, the
// cull, the solver and the certificate; the public entry points.
//
// mirrors: tc_escalate -> none (a TorusHit; the host reads it with crate::gpu::escalation::verdict)
// mirrors: tc_miss -> none
// mirrors: tc_kept -> none
// mirrors: torus_trace -> crate::certified::prove
// mirrors: torus_intersect -> crate::certified::intersect_f32_certified
// mirrors: torus_cull_keeps -> crate::gpu::intersector::GpuIntersector::cull_keeps

fn tc_escalate(why: u32) -> TorusHit {
    return TorusHit(0.0, vec3<f32>(0.0), TORUS_ESCALATE, why);
}

fn tc_miss() -> TorusHit {
    return TorusHit(0.0, vec3<f32>(0.0), TORUS_MISS, 0u);
}

// The cull-only answer.
fn tc_kept(keep: bool) -> TorusHit {
    return TorusHit(0.0, vec3<f32>(0.0), select(TORUS_MISS, TORUS_KEPT, keep), 0u);
}

// The whole path for one ray; `cull_only` stops after the cull (TORUS_KEPT or
// TORUS_MISS; a line that is not finite is kept).
fn torus_trace(ray: TorusRay, torus: TorusParams, cull: u32, cull_only: bool) -> TorusHit {
    let v = ray.origin;
    let t_min = ray.t_min;
    let dir = ray.direction;
    let t_max = ray.t_max;
    let major = torus.rot_x.w;
    let rr = torus.rot_z.w;
    let inv_major = torus.scale.x;
    let rot = mat3x3<f32>(torus.rot_x.xyz, torus.rot_y.xyz, torus.rot_z.xyz); // columns = rows of M
    // World → torus frame: o_l = M v with v = o − c, d_l = M d (M's rows are rot_x,
    // rot_y, rot_z; v * rot is the row vector times the matrix, that is M v).
    let ol = v * rot;
    // The direction scaled by a power of two (exact) so that its squares cannot underflow.
    let dmax = max(abs(dir.x), max(abs(dir.y), abs(dir.z)));
    let ex = frexp(dmax).exp;
    let ds = ldexp(dir, vec3<i32>(-ex));
    let dl = ds * rot;
    let len = sqrt(dot(dl, dl)); // |d| = len·2^ex
    let dh = dl * (1.0 / len);
    let s = dot(ol, dh);
    var foot = fma(vec3<f32>(-s), dh, ol);
    let s2 = dot(foot, dh);
    foot = fma(vec3<f32>(-s2), dh, foot);
    let q = foot * inv_major;
    let v_rel = length(v) * inv_major; // |o − c|/R

    // The line's error: how far the computed point q + u·d̂ (before its own rounding) can
    // stand from the true line's point at u, to first order in U (each step's worst case,
    // fma contracted or not, sqrt to 4.5 ulp, division to 2.5 ulp):
    // - o_l = M (o − c): o − c rounds by U·|v|, M's entries by U (√3·U·|v|), the dot
    //   products by 3U·|v| per component (3√3·U·|v|): 7.9U·|v| in all; d_l likewise,
    //   6.9U in angle;
    // - d̂ = d_l·(1/|d_l|): the angle gains U, the length is 1 within 16.5U, so
    //   |d̂ − d̂_true| ≤ 24.4U;
    // - the foot point o_l − s·d̂: o_l's 7.9U·|v| across the line, plus |s| ≤ |v| times
    //   d̂'s 7.9U of angle, plus U·|v| of rounding: 16.9U·|v| across; the re-projection
    //   leaves q within 12U·|q| along the line of the true foot point, and 1/R adds 2U·|q|.
    // Hence ε(u) ≤ 16.9U·|o − c|/R + 16U·|q| + 24.4U·|u|, taken about twice. (A foot
    // point the host formed in f64 is within 10⁻⁹·R of the line before its rounding to
    // f32, which the constant 32U ≈ 1.9·10⁻⁶ covers.)
    let line_abs = TC_LINE_ABS_DIST * v_rel + TC_LINE_ABS;
    let line_rel = TC_LINE_REL;

    let q_len_sq = dot(q, q);
    let q_len = sqrt(q_len_sq);
    let line_at_foot = line_rel * q_len + line_abs + TC_G * 3.1 * TC_U * q_len;

    // The range in u: lo = (t_min·|d| + s)/R, clamped to ±4 (every root has |u| < 2),
    // with its error: s = o_l·d̂ within 35.3U·|o − c| of the true one (o_l's 7.9U·|v|,
    // d̂'s 24.4U times |v|, 3U of rounding; taken 64U), |d| within 18U, the roundings.
    let tmin_d = ldexp(t_min, ex) * len;
    let tmax_d = ldexp(t_max, ex) * len;
    let lo_raw = (tmin_d + s) * inv_major;
    let hi_raw = (tmax_d + s) * inv_major;
    let s_err = 64.0 * TC_U * v_rel;
    let lo_err = s_err + 40.0 * TC_U * (abs(tmin_d) * inv_major + abs(s) * inv_major);
    let hi_err = s_err + 40.0 * TC_U * (abs(tmax_d) * inv_major + abs(s) * inv_major);
    let lo_out = clamp(lo_raw - lo_err, -4.0, 4.0);
    let lo_in = clamp(lo_raw + lo_err, -4.0, 4.0);
    let hi_out = clamp(hi_raw + hi_err, -4.0, 4.0);
    let hi_in = clamp(hi_raw - hi_err, -4.0, 4.0);

    let all_finite = tc_finite(v_rel) && tc_finite(q_len_sq) && tc_finite(lo_raw) && tc_finite(hi_raw)
        && tc_finite(s) && len > 0.0 && tc_finite(len);
    if (!all_finite) {
        if (cull_only) {
            return tc_kept(true);
        }
        return tc_escalate(TORUS_WHY_NON_FINITE_LINE);
    }

    // The cull, on the scaled line: the bounds' margin covers the line's error.
    let keep = tc_cull_keeps(cull, tc_bounds_of(torus), q, dh);
    if (cull_only) {
        return tc_kept(keep);
    }
    if (!keep) {
        return tc_miss();
    }

    // The quartic (forms that do not cancel, as in src/intersect/reduce.rs).
    let rho = sqrt(q.x * q.x + q.z * q.z);
    let tube = (q.y - rr) * (q.y + rr);
    let c2 = 2.0 * (rho - 1.0) * (rho + 1.0) + 2.0 * tube + 4.0 * dh.y * dh.y;
    let delta = dot(q, dh);
    let c1 = 8.0 * (q.y - delta * dh.y) * dh.y;
    let c0 = ((rho - 1.0) * (rho - 1.0) + tube) * ((rho + 1.0) * (rho + 1.0) + tube);
    let rho_plus = rho + 1.0;
    var l: TcLine;
    l.q = q;
    l.d = dh;
    l.rr = rr;
    l.line_rel = line_rel;
    l.line_abs = line_abs;
    l.q_len = q_len;
    l.k = 1.0 - rr * rr;
    l.c2_err = TC_G * 16.0 * TC_U * (2.0 * rho_plus * rho_plus + 2.0 * (q.y * q.y + rr * rr) + 4.0)
        + 8.0 * line_at_foot + TC_G * 8.0 * TC_U;

    // The chord: every true root has u² ≤ (1 + rr)² − |q_true|².
    let outer = 1.0 + rr;
    let chord_sq = outer * outer * (1.0 + TC_G * 16.0 * TC_U) - q_len_sq * (1.0 - TC_G * 16.0 * TC_U)
        + 4.0 * line_at_foot * (1.0 + q_len);
    if (chord_sq < 0.0) {
        return tc_miss();
    }
    let chord = sqrt(chord_sq);
    // The widest the true range can be (for "no root here" proofs) and the narrowest (where
    // a reported root must lie).
    let lo = max(lo_out, -chord);
    let hi = min(hi_out, chord);
    if (hi < lo) {
        return tc_miss();
    }
    let lo_narrow = max(lo_in, -chord);
    let hi_narrow = min(hi_in, chord);

    // The solver's "careful" flag is not escalated on its word (as on the CPU): soundness
    // rests on the proof below alone, which fails wherever the f32 root is wrong.
    let nr = tc_nearest_root(c2, c1, c0, lo, hi);
    let found = nr.root < TC_BIG;
    if (!(tc_finite(c2) && tc_finite(c1) && tc_finite(c0))) {
        return tc_escalate(TORUS_WHY_SOLVER_UNSURE);
    }
    if (!found) {
        if (tc_positive(l, c2, c1, lo, hi)) {
            return tc_miss();
        }
        return tc_escalate(TORUS_WHY_MISS_NOT_PROVED);
    }
    // t = (u·R − s)/|d| (|d| = len·2^ex). Its error, in length units, is the bracket's
    // half-width plus what the kernel adds: s's error (s_err·R), and the relative error of
    // u·R − s, of |d| (18U) and of the division (5U), taken 48U. The bracket is what
    // remains of the promised 2·10⁻⁴·(R + r) (less 0.5 %): on the CPU, whose back map is
    // f64, it is 1.9·10⁻⁴·R; here it shrinks as the origin moves away.
    let u_star = nr.root;
    let along = u_star * major - s;
    let t = ldexp(along / len, -ex);
    let t_extra = s_err * major + 48.0 * TC_U * (abs(along) + abs(u_star * major) + abs(s));
    let bracket = min(TC_BRACKET, 1.99e-4 * (1.0 + rr) - t_extra * inv_major * (1.0 + 4.0 * TC_U));
    if (!(bracket > 1e-6) || !tc_finite(t)) {
        return tc_escalate(TORUS_WHY_T_ERROR);
    }
    // A hit: sdf > 0 at the bracket's start, < 0 at its end, F > 0 before it.
    let left = max(u_star - bracket, lo_narrow);
    let right = min(u_star + bracket, hi_narrow);
    if (!(left <= right)) {
        return tc_escalate(TORUS_WHY_EMPTY_BRACKET);
    }
    let at_left = tc_point_bound(l, left);
    let at_right = tc_point_bound(l, right);
    if (!(at_left.sdf_lo > 0.0 && at_right.sdf_hi < 0.0)) {
        return tc_escalate(TORUS_WHY_NO_SIGN_CHANGE);
    }
    if (!tc_positive(l, c2, c1, lo, left)) {
        return tc_escalate(TORUS_WHY_EARLIER_ROOT);
    }
    // The normal: ∇F ∝ (|p|² + 1 − rr²)·p − 2(px, 0, pz), back to the world.
    let p = q + u_star * dh;
    let wgt = dot(p, p) + l.k;
    let g = vec3<f32>(wgt * p.x - 2.0 * p.x, wgt * p.y, wgt * p.z - 2.0 * p.z);
    let n_world = rot * g; // Mᵀ g
    let n_len = length(n_world);
    return TorusHit(t, n_world / select(1.0, n_len, n_len > 0.0), TORUS_HIT, 0u);
}

// The certified intersection of `ray` with `torus` behind the cull `cull` (TORUS_CULL_*):
// TORUS_HIT with t and the world normal, TORUS_MISS, or TORUS_ESCALATE with `why`.
fn torus_intersect(ray: TorusRay, torus: TorusParams, cull: u32) -> TorusHit {
    return torus_trace(ray, torus, cull, false);
}

// The cull alone on the ray's line: false is a proved miss of the whole line, true keeps
// it (a line that is not finite in f32 is kept).
fn torus_cull_keeps(ray: TorusRay, torus: TorusParams, cull: u32) -> bool {
    return torus_trace(ray, torus, cull, true).code == TORUS_KEPT;
}
