// torus-cull's WGSL module: the certified f32 ray–torus intersection as functions a shader
// includes (torus_cull::gpu::wgsl_module() gives this text behind its generated `const`
// header; the library's own compute kernel is the same text plus its bindings and entry
// point, src/gpu/kernel.wgsl).
//
// Per ray: the world → torus-frame rotation (f32; the host has subtracted the centre, one
// rounding as in f32, and moved a far origin along its line to the foot point in f64), the
// line re-parameterised at its foot point and scaled by 1/R, the cull, Ferrari's split of
// the depressed quartic in f32 (the f64 solver's method, as src/batch/quartic runs it on
// f32 lanes), then the certificate of src/certified/certificate.rs with the GPU's error
// bounds: every spec term in u = 2⁻²⁴ is multiplied by 4 (WGSL may or may not contract
// a·b + c into an fma, division is good to 2.5 ulp, sqrt is not correctly rounded
// everywhere), and the line's own error is the one of an f32 rotation, which grows with
// the origin's distance |o − c|. What is not proved comes back TORUS_ESCALATE, and the
// host finishes it with the f64 solver (torus_cull::intersect).
//
// Every shared number (TC_U, TC_G, TC_SAFETY_REL, the solver's thresholds and fits, the
// line error's constants, the result, cull and escalation codes) is a `const` of the
// header that src/gpu/source.rs generates from the Rust constants the CPU uses: none is
// written here.
//
// NAMES. Every global name the module declares begins with torus_ / Torus / TORUS_ (the
// API below) or tc_ / Tc / TC_ (internals), so that it can sit in a renderer's shader
// beside names like `miss`, `Line` or `U` (WGSL has no namespaces, and a repeated global
// name is an error).
//
// THE PUBLIC ENTRY POINTS (everything else here is internal):
//
//   fn torus_intersect(ray: TorusRay, torus: TorusParams, cull: u32) -> TorusHit
//   fn torus_cull_keeps(ray: TorusRay, torus: TorusParams, cull: u32) -> bool
//
// `cull` is one of TORUS_CULL_NONE, _SPHERE, _AABB, _CYCHOSZ, _THICK_CYLINDER, _SKALA,
// _ELLIPSOID, _QUADRIC, _DISCRIMINANT (torus_cull::gpu::GpuCull::ALL's order); every
// cull is conservative here: a rejected ray is a proved miss.
//
// WHAT THE CALLER PREPARES (on the host, as torus_cull::gpu::ModuleTorus does):
//   - TorusParams, once per torus: ModuleTorus::params() (112 bytes, seven vec4<f32>).
//     The culls' bounds rows carry the GPU's margin (the CPU's η plus this module's line
//     error), computed in Rust: do not derive them in the shader.
//   - TorusRay, per ray: ModuleTorus::prepare(ray). The origin relative to the torus
//     centre, o − c formed in f64 and rounded once to f32; an origin farther than
//     2·(R + r) moved along its line to the foot point in f64 (the range shifted by the
//     same t0, clipped to where the bounding sphere can be; add t0 back to the hit's t);
//     an origin beyond 2²⁰·R is not sent (escalate it); a ray from a surface point
//     (torus_cull::Ray::from_surface) sent as its literal ray past the origin's own root,
//     or answered on the host (see ModuleTorus::prepare). A ray prepared otherwise is
//     outside what the certificate proves.
//
// WHAT THE ANSWER MEANS: TorusHit.code
//   TORUS_HIT: a proved hit; t (along the prepared ray's direction, from the prepared
//     origin) is within 2·10⁻⁴·(R + r)·|d|⁻¹ of the first root in [t_min, t_max], normal
//     the unit outward world normal;
//   TORUS_MISS: a proved miss (or the cull's proved rejection);
//   TORUS_ESCALATE: not proved either way; `why` says which step did not go through
//     (TORUS_WHY_*, torus_cull::gpu::Escalation). Finish it on the host with the f64 path
//     (torus_cull::intersect), or treat it as unknown: it is never a miss to assume.

// A ray as the module reads it (32 bytes, two vec4<f32> in a storage buffer): the origin
// relative to the torus centre, the range's start, the direction (any length, finite,
// non-zero), the range's end; both ends finite.
struct TorusRay {
    origin: vec3<f32>,
    t_min: f32,
    direction: vec3<f32>,
    t_max: f32,
};

// A torus as the module reads it (112 bytes, seven vec4<f32>; a uniform or storage
// struct): rows of the world → torus rotation M (torus.to_local_rotation()) with, in w,
// R, r and r/R; 1/R (yzw unused); the culls' bounds at R = 1 with the tube padded by the
// GPU's margin (src/gpu/bounds.rs): (R + r_η, (R + r_η)², r_η, r_η²), ((R − r_η)², s,
// s·r_η, the hyperboloid's y coefficient), ((r_η/R)², R − r_η, η_gpu, 0).
struct TorusParams {
    rot_x: vec4<f32>,
    rot_y: vec4<f32>,
    rot_z: vec4<f32>,
    scale: vec4<f32>,
    bounds_a: vec4<f32>,
    bounds_b: vec4<f32>,
    bounds_c: vec4<f32>,
};

// The answer: `code` is TORUS_MISS, TORUS_HIT or TORUS_ESCALATE (TORUS_KEPT from the
// cull alone); for a hit, `t` and the unit world `normal`; for an escalation, `why`
// (TORUS_WHY_*), else 0.
struct TorusHit {
    t: f32,
    normal: vec3<f32>,
    code: u32,
    why: u32,
};

fn tc_finite(x: f32) -> bool {
    return abs(x) < TC_BIG;
}

// ---------------------------------------------------------------------------------------
// The solver: src/quartic/{resolvent,factor,nearest,cube_root}.rs as the f32 lanes run it
// (src/batch/quartic/{resolvent,nearest}.rs).

// Horner-free degree-5 polynomial, Estrin's scheme (cube_root.rs, poly5).
fn tc_poly5(c0: f32, c1: f32, c2: f32, c3: f32, c4: f32, c5: f32, x: f32) -> f32 {
    let x2 = x * x;
    let x4 = x2 * x2;
    let low = c4 * x + c5;
    let mid = c2 * x + c3;
    let high = c0 * x + c1;
    return (low + x2 * mid) + x4 * high;
}

fn tc_cbrt_halley(t: f32, y: f32) -> f32 {
    let t3 = t * t * t;
    return t * ((t3 + 2.0 * y) / (2.0 * t3 + y));
}

// ∛y for y in [1e-30, 1e30]: Kahan's bit trick for f32 (within ~6 %), two Halley steps.
fn tc_cbrt(y: f32) -> f32 {
    let bits = bitcast<u32>(y);
    var t = bitcast<f32>(bits / 3u + TC_CBRT_SEED);
    t = tc_cbrt_halley(t, y);
    t = tc_cbrt_halley(t, y);
    return t;
}

// u = 2 cos(arccos(x)/3) − 1 (cube_root.rs, trisect_u).
fn tc_trisect_u(x: f32) -> f32 {
    let rhs = 2.0 * (1.0 + x);
    let s = sqrt(max(rhs * (1.0 / 3.0), 0.0));
    var u = s * tc_poly5(
        TC_TRISECT_FIT_0,
        TC_TRISECT_FIT_1,
        TC_TRISECT_FIT_2,
        TC_TRISECT_FIT_3,
        TC_TRISECT_FIT_4,
        TC_TRISECT_FIT_5,
        s - TC_TRISECT_HALF_RANGE,
    );
    let f = u * u * (3.0 + u) - rhs;
    let df = (3.0 * u + 6.0) * u;
    let d2f = 6.0 * u + 6.0;
    let den = 2.0 * df * df - f * d2f;
    let ok = rhs > 0.0 && den != 0.0;
    let step = 2.0 * f * df / select(1.0, den, ok);
    return select(0.0, u - step, ok);
}

struct TcCubic {
    a: f32,
    b: f32,
    c: f32,
    a3: f32,
    third_p: f32,
    half_q: f32,
    disc: f32,
    scale: f32,
};

fn tc_cubic_of(p: f32, q: f32, r: f32) -> TcCubic {
    var k: TcCubic;
    k.a = 2.0 * p;
    k.b = p * p - 4.0 * r;
    k.c = -q * q;
    k.a3 = k.a * (1.0 / 3.0);
    let p2 = p * p;
    let r43 = r * (4.0 / 3.0);
    k.third_p = -(p2 * (1.0 / 9.0) + r43);
    k.half_q = p * (r43 - p2 * (1.0 / 27.0)) - 0.5 * (q * q);
    let tp3 = k.third_p * k.third_p * k.third_p;
    k.disc = k.half_q * k.half_q + tp3;
    k.scale = k.half_q * k.half_q + abs(tp3);
    return k;
}

fn tc_cubic_h(k: TcCubic, z: f32) -> f32 {
    return ((z + k.a) * z + k.b) * z + k.c;
}

fn tc_cubic_dh(k: TcCubic, z: f32) -> f32 {
    return (3.0 * z + 2.0 * k.a) * z + k.b;
}

struct TcResolvent {
    z: f32,
    dh: f32,
    fallback: bool,
};

// The greatest root z = m² ≥ 0 of the resolvent (batch/quartic/resolvent.rs).
fn tc_greatest_root(p: f32, q: f32, r: f32) -> TcResolvent {
    let k = tc_cubic_of(p, q, r);
    let near_double = !(abs(k.disc) > TC_DISC_NEAR * k.scale);
    let one_real = k.disc > 0.0;
    // Cardano (one real root).
    let cube = abs(k.half_q) + sqrt(max(k.disc, 0.0));
    let cube_ok = cube == 0.0 || (cube >= TC_CBRT_LOW && cube <= TC_CBRT_HIGH);
    let big = select(0.0, tc_cbrt(cube), cube > 0.0 && cube_ok);
    let ratio = -k.third_p / select(1.0, cube, cube > 0.0);
    var cu = big;
    var cv = ratio * big * big;
    if (k.half_q > 0.0) {
        cu = -cu;
        cv = -cv;
    }
    let cardano = select(0.0, cu + cv, big != 0.0);
    // Trigonometric (three real roots): 2k cos(θ/3) = k(1 + u).
    let tp = select(-1.0, k.third_p, k.third_p < 0.0);
    let kk = sqrt(max(-k.third_p, 0.0));
    let cos3 = clamp((k.half_q / tp) * sqrt(-1.0 / tp), -1.0, 1.0);
    let trig = select(0.0, kk + kk * tc_trisect_u(cos3), k.third_p < 0.0);
    let w = select(trig, cardano, one_real);
    var z = max(w - k.a3, 0.0);
    // A small greatest root from the fixed point z = q²/((z + a)z + b).
    let tiny = k.b > 0.0 && z * (z + abs(k.a)) <= TC_SMALL_ROOT * k.b;
    if (tiny) {
        let z0 = q * q / k.b;
        let den = (z0 + k.a) * z0 + k.b;
        z = select(z, q * q / den, den > 0.0);
    }
    // Two guarded Newton steps.
    var hz = tc_cubic_h(k, z);
    for (var i = 0; i < 2; i++) {
        let d = tc_cubic_dh(k, z);
        let zn = max(z - hz / select(1.0, d, d != 0.0), 0.0);
        let hn = tc_cubic_h(k, zn);
        let better = d != 0.0 && abs(hn) < abs(hz);
        z = select(z, zn, better);
        hz = select(hz, hn, better);
    }
    var res: TcResolvent;
    res.z = z;
    res.dh = tc_cubic_dh(k, z);
    res.fallback = near_double || (one_real && !cube_ok) || !tc_finite(z) || !tc_finite(res.dh);
    return res;
}

fn tc_copysign(x: f32, s: f32) -> f32 {
    return select(abs(x), -abs(x), s < 0.0);
}

// x if a real root in [lo, hi], else +BIG (no root).
fn tc_in_range(x: f32, real: bool, lo: f32, hi: f32) -> f32 {
    return select(TC_BIG, x, real && x >= lo && x <= hi);
}

struct TcNearest {
    // The nearest root in [lo, hi], or BIG for none.
    root: f32,
    // The solver could not settle this quartic (near-double factor, resolvent fallback).
    careful: bool,
};

// The nearest root of x⁴ + p x² + q x + r in [lo, hi] (batch/quartic/nearest.rs with
// quartic/factor.rs's split_at and quartic/nearest.rs's clear_factors, nearest_of_clear).
fn tc_nearest_root(p: f32, q: f32, r: f32, lo: f32, hi: f32) -> TcNearest {
    let res = tc_greatest_root(p, q, r);
    let z = res.z;
    let dh = res.dh;
    let m = sqrt(z);
    let q_over_m = q / select(1.0, m, m > 0.0);
    // split_at
    let s = p + z;
    let w2 = s * s - 4.0 * r;
    let b_abs = p * p + 4.0 * abs(r);
    let h_mag = ((z + 2.0 * abs(p)) * z + b_abs) * z + q * q;
    let zdh = z * dh;
    let err_w_zdh = TC_F64_EPS * ((s * s + 4.0 * abs(r) + 2.0 * abs(s) * abs(p)) * zdh
        + 2.0 * abs(s) * h_mag * z);
    let use_q_over_m = m > 0.0 && zdh > 0.0 && (w2 <= 0.0 || TC_F64_EPS * h_mag * w2 <= err_w_zdh);
    let d = select(tc_copysign(sqrt(max(w2, 0.0)), q), q_over_m, use_q_over_m);
    let n1d = 0.5 * (s - d);
    let n2d = 0.5 * (s + d);
    let n2_bigger = abs(n2d) >= abs(n1d);
    let bigger = select(n1d, n2d, n2_bigger);
    let other = select(r / select(1.0, bigger, bigger != 0.0), 0.0, bigger == 0.0);
    let n1 = select(n1d, other, n2_bigger);
    let n2 = select(other, n2d, n2_bigger);
    // clear_factors
    let disc1 = z - 4.0 * n1;
    let disc2 = z - 4.0 * n2;
    let clear = abs(disc1) > TC_NEAR_DOUBLE * (z + 4.0 * abs(n1)) && abs(disc2) > TC_NEAR_DOUBLE * (z + 4.0 * abs(n2));
    // nearest_of_clear
    let s1 = sqrt(max(disc1, 0.0));
    let s2 = sqrt(max(disc2, 0.0));
    let ok1 = disc1 > 0.0;
    let ok2 = disc2 > 0.0;
    let half_m = 0.5 * m;
    let first = min(tc_in_range(-half_m - 0.5 * s1, ok1, lo, hi), tc_in_range(-half_m + 0.5 * s1, ok1, lo, hi));
    let second = min(tc_in_range(half_m - 0.5 * s2, ok2, lo, hi), tc_in_range(half_m + 0.5 * s2, ok2, lo, hi));
    var out: TcNearest;
    out.root = min(first, second);
    let bad_input = !(tc_finite(p) && tc_finite(q) && tc_finite(r));
    out.careful = res.fallback || !clear || bad_input;
    return out;
}

// ---------------------------------------------------------------------------------------
// The certificate (src/certified/certificate.rs; /work/f32-spec.md §3–5), GPU constants.

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

    // The quartic (forms that do not cancel, as in src/intersect.rs's reduce).
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
