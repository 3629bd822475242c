// ---------------------------------------------------------------------------------------
// The driver (intersect/mod.rs, exact and intersect_reduced; nearest_hit.rs).
//
// mirrors: tc_fin_status -> none (a TorusHit64; the host reads it with crate::gpu::finish::device_answer)
// mirrors: torus_finish_wanted -> crate::gpu::intersector::GpuIntersector::intersect_finished_where
// mirrors: torus_finish_f64 -> crate::intersect::exact

fn tc_fin_status(status: u32) -> TorusHit64 {
    return TorusHit64(0.0, vec3<f32>(0.0), vec3<f32>(0.0), status);
}

// Whether a ray needs the f64 finish, from the host's instruction (ModuleTorus::
// prepare_f64) and the f32 module's answer (TorusHit's code, t and normal): never for
// TORUS_F64_HOST; for TORUS_F64_FOLLOW and _SURFACE_FOLLOW unless the f32 answer is
// proved (the host's decode, PreparedRay::verdict: a miss, or a hit with a finite t and
// normal); always otherwise (TORUS_F64_ALWAYS, _SURFACE_ALWAYS: the host sent the f32
// module nothing it could prove).
fn torus_finish_wanted(instruction: u32, code: u32, t: f32, normal: vec3<f32>) -> bool {
    if (instruction == TORUS_F64_HOST) {
        return false;
    }
    if (instruction == TORUS_F64_FOLLOW || instruction == TORUS_F64_SURFACE_FOLLOW) {
        let proved_hit = code == TC_FIN_CODE_HIT && abs(t) < 3.0e38 && abs(normal.x) < 3.0e38
            && abs(normal.y) < 3.0e38 && abs(normal.z) < 3.0e38;
        return !(code == TC_FIN_CODE_MISS || proved_hit);
    }
    return true;
}

// The f64 path's answer for one world ray (crate::intersect, or its from_surface path for
// TORUS_F64_SURFACE_FOLLOW and _SURFACE_ALWAYS); TORUS_F64_HOST gives status _HOST.
fn torus_finish_f64(ray: TorusWorldRay, torus: TorusParams64, instruction: u32) -> TorusHit64 {
    if (instruction == TORUS_F64_HOST) {
        return tc_fin_status(TORUS_F64_STATUS_HOST);
    }
    // A ray from a surface point (Ray::from_surface): its own root divided out, as the
    // CPU's exact() does.
    let surface = instruction == TORUS_F64_SURFACE_FOLLOW
        || instruction == TORUS_F64_SURFACE_ALWAYS;
    let origin = vec3<f64>(f64(ray.origin.x), f64(ray.origin.y), f64(ray.origin.z));
    let dir = vec3<f64>(f64(ray.direction.x), f64(ray.direction.y), f64(ray.direction.z));
    let t_min = f64(ray.t_min);
    let t_max = f64(ray.t_max);
    // The line in the torus frame, in f64 (Torus::line_to_local_f64): M·(o − c), M·d.
    let c = vec3<f64>(torus.center_x, torus.center_y, torus.center_z);
    let m0 = vec3<f64>(torus.col0_x, torus.col0_y, torus.col0_z);
    let m1 = vec3<f64>(torus.col1_x, torus.col1_y, torus.col1_z);
    let m2 = vec3<f64>(torus.col2_x, torus.col2_y, torus.col2_z);
    let major = torus.major;
    let inv_major = torus.inv_major;
    let minor_rel = torus.minor_rel;
    let k_normal = torus.k_normal;
    let outer = torus.outer;
    let rel = origin - c;
    let literal = (m0 * rel.x + m1 * rel.y) + m2 * rel.z;
    let d = (m0 * dir.x + m1 * dir.y) + m2 * dir.z;
    // A ray from a surface point is solved from its origin moved onto the surface
    // (from_surface.rs, SurfaceCubic::new; tube.rs, nearest_surface_point).
    let on_surface = surface && tc_starts_on_the_surface64(literal, inv_major, minor_rel);
    var o = literal;
    if (on_surface) {
        o = tc_nearest_surface_point64(literal, major, minor_rel * major);
    }
    // The foot point scaled by 1/R (reduce.rs, foot_line).
    let inv_len = 1.0 / sqrt(tc_dot64(d, d));
    let dh = d * inv_len;
    let s = tc_dot64(o, dh);
    let p = (o - dh * s) * inv_major;
    // The depressed quartic (reduce.rs, coefficients).
    let rho = sqrt(p.x * p.x + p.z * p.z);
    let tube = (p.y - minor_rel) * (p.y + minor_rel);
    let c2 = 2.0 * (rho - 1.0) * (rho + 1.0) + 2.0 * tube + 4.0 * dh.y * dh.y;
    let delta = tc_dot64(p, dh);
    let c1 = 8.0 * (p.y - delta * dh.y) * dh.y;
    let c0 = ((rho - 1.0) * (rho - 1.0) + tube) * ((rho + 1.0) * (rho + 1.0) + tube);
    var u: f64;
    var t: f64;
    if (on_surface) {
        // The origin's own root u₀ (Q(u₀) is f64 rounding, dropped), the cubic in
        // v = u − u₀, its nearest root past the origin (from_surface.rs, SurfaceCubic).
        let own = s * inv_major;
        let e = tc_eval1_64(c2, c1, c0, own);
        let a3 = 4.0 * own;
        let a2 = 6.0 * own * own + c2;
        let a1 = e.y;
        let v_per_t = inv_major / inv_len;
        let v_lo = max(max(t_min, 0.0) * v_per_t, 0.0);
        let v_hi = t_max * v_per_t;
        let root = tc_nearest_cubic_root64(a3, a2, a1, v_lo, v_hi);
        if (!root.found) {
            return tc_fin_status(TORUS_F64_STATUS_MISS);
        }
        t = root.v / v_per_t;
        u = own + root.v;
    } else {
        let chord_sq = outer * outer * TC_FIN_CHORD_SCALE - tc_dot64(p, p);
        if (chord_sq < 0.0) {
            return tc_fin_status(TORUS_F64_STATUS_MISS);
        }
        let len = 1.0 / inv_len;
        let lo = (t_min * len + s) * inv_major;
        let hi = (t_max * len + s) * inv_major;
        if ((lo > 0.0 && lo * lo > chord_sq) || (hi < 0.0 && hi * hi > chord_sq)) {
            return tc_fin_status(TORUS_F64_STATUS_MISS);
        }
        let found = tc_nearest_root64(c2, c1, c0, lo, hi);
        if (found.host) {
            return tc_fin_status(TORUS_F64_STATUS_HOST);
        }
        if (!found.found) {
            return tc_fin_status(TORUS_F64_STATUS_MISS);
        }
        u = found.u;
        t = (u * major - s) * inv_len;
    }
    // The normal (reduce.rs, normal), then to the world: Mᵀ·n.
    let x = p + dh * u;
    let w = tc_dot64(x, x) + k_normal;
    let grad = vec3<f64>(w * x.x - 2.0 * x.x, w * x.y, w * x.z - 2.0 * x.z);
    let n = grad * (1.0 / sqrt(tc_dot64(grad, grad)));
    let nw = vec3<f64>(tc_dot64(m0, n), tc_dot64(m1, n), tc_dot64(m2, n));
    // FromExact: t must fit an f32 (round to nearest overflows from 2¹²⁸ − 2¹⁰³ up).
    if (!(abs(t) < TC_FIN_F32_OVERFLOW)) {
        return tc_fin_status(TORUS_F64_STATUS_MISS);
    }
    let point = origin + dir * t;
    if (!(abs(point.x) < TC_FIN_F32_OVERFLOW && abs(point.y) < TC_FIN_F32_OVERFLOW
        && abs(point.z) < TC_FIN_F32_OVERFLOW)) {
        // A point f32 cannot hold (the CPU's would be infinite): the host's answer.
        return tc_fin_status(TORUS_F64_STATUS_HOST);
    }
    let front = tc_dot64(dir, nw) < 0.0;
    return TorusHit64(
        f32(t),
        vec3<f32>(f32(nw.x), f32(nw.y), f32(nw.z)),
        vec3<f32>(f32(point.x), f32(point.y), f32(point.z)),
        select(TORUS_F64_STATUS_BACK, TORUS_F64_STATUS_FRONT, front),
    );
}
