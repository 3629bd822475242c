// The device's f64 finish as WGSL functions (src/gpu/finish.rs, source.rs's
// wgsl_finish_module): the CPU's f64 method for one ray the certified f32 module
// escalated, on an adapter with SHADER_F64, step for step:
//   src/intersect/{mod,nearest_hit,reduce}.rs   the line in the torus frame (f64), the
//                                               foot point scaled by 1/R, the chord test,
//                                               the depressed quartic's coefficients, t
//                                               and the normal;
//   src/quartic/nearest.rs                      surely_no_real_root, the even quartic,
//                                               Ferrari's split, the clear factors and
//                                               the near-double cold path;
//   src/quartic/{even,resolvent,trisect,factor}.rs;
//   src/intersect/from_surface.rs               a ray from a surface point: its origin's
//                                               own root divided out, the cubic's nearest
//                                               root past it.
// Every threshold comes from the generated header (TC_FIN_*), written from the Rust
// constants the CPU uses. Where the method cannot give the CPU's answer (a value it does
// not hold finite), it hands the ray back to the host: status TORUS_F64_STATUS_HOST.
//
// No bindings and no entry point: a renderer includes this text (with or without the f32
// module, in either order: the two declare no common name), and the library's own f64
// pass is this text plus finish.wgsl (its bindings and entry point). The API:
//   torus_finish_wanted(instruction, code, t, normal) -> bool
//   torus_finish_f64(ray: TorusWorldRay, torus: TorusParams64, instruction) -> TorusHit64
// Every other global name begins with tc_, Tc or TC_.

// The ray as the caller gave it, in world space (32 bytes, as the f32 module's
// TorusRay): origin, t_min, direction, t_max as f32, widened exactly; the range clipped
// to |t| ≤ (|o − c| + 4(R + r))/|d| (ModuleTorus::prepare_f64), beyond which no root
// lies, so no answer changes and no infinity reaches the device.
struct TorusWorldRay {
    origin: vec3<f32>,
    t_min: f32,
    direction: vec3<f32>,
    t_max: f32,
};

// The torus in f64 (136 bytes, 17 f64, ModuleTorus::params64): the centre, the columns
// of the world → torus rotation M, R, 1/R, r/R, 1 − (r/R)², 1 + r/R (the CPU's Tube).
struct TorusParams64 {
    center_x: f64,
    center_y: f64,
    center_z: f64,
    col0_x: f64,
    col0_y: f64,
    col0_z: f64,
    col1_x: f64,
    col1_y: f64,
    col1_z: f64,
    col2_x: f64,
    col2_y: f64,
    col2_z: f64,
    major: f64,
    inv_major: f64,
    minor_rel: f64,
    k_normal: f64,
    outer: f64,
};

// The f64 answer, each value rounded once from f64 as the CPU's Hit is: t along the
// world ray (in units of its direction), the unit world normal, the point o + t·d, and
// status: TORUS_F64_STATUS_FRONT (a hit from the outside, d·n < 0), _BACK (from the
// inside, or exactly tangent), _MISS (no hit in range), _HOST (handed back: finish it
// on the host with the f64 path).
struct TorusHit64 {
    t: f32,
    normal: vec3<f32>,
    point: vec3<f32>,
    status: u32,
};

// (x·x′ + y·y′) + z·z′, glam's order.
fn tc_dot64(a: vec3<f64>, b: vec3<f64>) -> f64 {
    return (a.x * b.x + a.y * b.y) + a.z * b.z;
}

fn tc_copysign64(x: f64, s: f64) -> f64 {
    return select(abs(x), -abs(x), s < 0.0);
}

fn tc_finite64(x: f64) -> bool {
    return abs(x) < TC_FIN_HUGE;
}

// x if it is a real root in [lo, hi], else TC_FIN_NONE (pick.rs, in_range).
fn tc_in_range64(x: f64, real: bool, lo: f64, hi: f64) -> f64 {
    return select(TC_FIN_NONE, x, real && x >= lo && x <= hi);
}

// ---------------------------------------------------------------------------------------
// The cube root and the trisection (num/cube_root.rs, quartic/trisect.rs).

fn tc_cbrt_halley64(t: f64, y: f64) -> f64 {
    let t3 = t * t * t;
    return t * ((t3 + 2.0 * y) / (2.0 * t3 + y));
}

// ∛y for y ≥ 0: y brought into the f32 seed's range by exact powers 2^±90 (cube root
// 2^±30), Kahan's f32 seed and two f32 Halley steps (relative error ≲ 2·10⁻⁷), then one
// f64 Halley step, which cubes it (≲ 10⁻²⁰, below rounding); the CPU's cbrt is a fit
// and one Halley step, also below rounding.
fn tc_cbrt64(y0: f64) -> f64 {
    if (y0 <= 0.0) {
        return 0.0;
    }
    var y = y0;
    var scale = 1.0lf;
    for (var i = 0; i < 12 && y < TC_FIN_CBRT_LOW; i++) {
        y = y * TC_FIN_TWO_90;
        scale = scale * TC_FIN_TWO_M30;
    }
    for (var i = 0; i < 12 && y > TC_FIN_CBRT_HIGH; i++) {
        y = y * TC_FIN_TWO_M90;
        scale = scale * TC_FIN_TWO_30;
    }
    let y32 = f32(y);
    var s = bitcast<f32>(bitcast<u32>(y32) / 3u + TC_FIN_CBRT_SEED);
    s = s * ((s * s * s + 2.0 * y32) / (2.0 * s * s * s + y32));
    s = s * ((s * s * s + 2.0 * y32) / (2.0 * s * s * s + y32));
    return tc_cbrt_halley64(f64(s), y) * scale;
}

// Estrin's degree-5 polynomial (num/poly.rs).
fn tc_poly5_64(x: f64) -> f64 {
    let x2 = x * x;
    let x4 = x2 * x2;
    let low = TC_FIN_TRISECT_FIT_4 * x + TC_FIN_TRISECT_FIT_5;
    let mid = TC_FIN_TRISECT_FIT_2 * x + TC_FIN_TRISECT_FIT_3;
    let high = TC_FIN_TRISECT_FIT_0 * x + TC_FIN_TRISECT_FIT_1;
    return (low + x2 * mid) + x4 * high;
}

// u = 2 cos(arccos(x)/3) − 1 (trisect.rs, trisect_u).
fn tc_trisect_u64(x: f64) -> f64 {
    let rhs = 2.0 * (1.0 + x);
    if (!(rhs > 0.0)) {
        return 0.0;
    }
    let s = sqrt(rhs * TC_FIN_THIRD);
    let u = s * tc_poly5_64(s - TC_FIN_TRISECT_HALF_RANGE);
    let f = u * u * (3.0 + u) - rhs;
    let df = (3.0 * u + 6.0) * u;
    let d2f = 6.0 * u + 6.0;
    let den = 2.0 * df * df - f * d2f;
    if (den == 0.0) {
        return u;
    }
    return u - 2.0 * f * df / den;
}

// ---------------------------------------------------------------------------------------
// The resolvent's greatest root (resolvent.rs).

struct TcCubic64 {
    a: f64,
    b: f64,
    c: f64,
    a3: f64,
    third_p: f64,
    half_q: f64,
    disc: f64,
    scale: f64,
};

fn tc_cubic64(p: f64, q: f64, r: f64) -> TcCubic64 {
    let a = 2.0 * p;
    let b = p * p - 4.0 * r;
    let c = -q * q;
    let a3 = a * TC_FIN_THIRD;
    let p2 = p * p;
    let r43 = r * TC_FIN_FOUR_THIRDS;
    let third_p = -(p2 * TC_FIN_NINTH + r43);
    let half_q = p * (r43 - p2 * TC_FIN_TWENTY_SEVENTH) - 0.5 * (q * q);
    let cube = third_p * third_p * third_p;
    let disc = half_q * half_q + cube;
    let scale = half_q * half_q + abs(cube);
    return TcCubic64(a, b, c, a3, third_p, half_q, disc, scale);
}

fn tc_cubic_h64(k: TcCubic64, z: f64) -> f64 {
    return ((z + k.a) * z + k.b) * z + k.c;
}

fn tc_cubic_dh64(k: TcCubic64, z: f64) -> f64 {
    return (3.0 * z + 2.0 * k.a) * z + k.b;
}

// Cardano's (u, v) for disc ≥ 0: the cube root of the larger-magnitude term.
fn tc_cardano64(third_p: f64, half_q: f64, disc: f64) -> vec2<f64> {
    let cube = abs(half_q) + sqrt(max(disc, 0.0));
    let big = tc_cbrt64(cube);
    if (big == 0.0) {
        return vec2<f64>(0.0, 0.0);
    }
    let ratio = -third_p / cube;
    let v = ratio * big * big;
    if (half_q > 0.0) {
        return vec2<f64>(-big, -v);
    }
    return vec2<f64>(big, v);
}

// The greatest of three real roots: 2k cos(θ/3), k = √(−P′), cos θ = −Q′/k³.
fn tc_trigonometric64(third_p: f64, half_q: f64) -> f64 {
    if (!(third_p < 0.0)) {
        // k = 0 (the CPU's clamped NaN gives k·(1 + u) = 0 too).
        return 0.0;
    }
    let k = sqrt(-third_p);
    let cos3 = clamp((half_q / third_p) * sqrt(-1.0 / third_p), -1.0, 1.0);
    return k + k * tc_trisect_u64(cos3);
}

// Δ ≈ 0: whether the top pair is real decides the greatest root (resolvent.rs,
// near_double).
fn tc_resolvent_near_double64(k: TcCubic64) -> f64 {
    let one = tc_cardano64(k.third_p, k.half_q, 0.0);
    let crit = k.a * k.a - 3.0 * k.b;
    if (crit <= 0.0) {
        return one.x + one.y;
    }
    let sq = sqrt(crit);
    var z_min: f64;
    if (k.a > 0.0) {
        z_min = -k.b / (k.a + sq);
    } else {
        z_min = (sq - k.a) / 3.0;
    }
    if (tc_cubic_h64(k, z_min) <= 0.0) {
        return max(tc_trigonometric64(k.third_p, k.half_q), z_min + k.a3);
    }
    return one.x + one.y;
}

fn tc_polish64(k: TcCubic64, z0: f64) -> f64 {
    var z = z0;
    var hz = tc_cubic_h64(k, z);
    for (var i = 0; i < 2; i++) {
        let dh = tc_cubic_dh64(k, z);
        if (dh == 0.0) {
            break;
        }
        let zn = max(z - hz / dh, 0.0);
        let hn = tc_cubic_h64(k, zn);
        if (abs(hn) < abs(hz)) {
            z = zn;
            hz = hn;
        }
    }
    return z;
}

struct TcRoot64 {
    z: f64,
    dh: f64,
    m: f64,
    q_over_m: f64,
    q_over_m_exact: bool,
    z_early: f64,
};

fn tc_greatest_root64(p: f64, q: f64, r: f64) -> TcRoot64 {
    let k = tc_cubic64(p, q, r);
    let near = abs(k.disc) <= TC_FIN_DISC_NEAR * k.scale;
    var z: f64;
    var m: f64;
    var q_over_m: f64;
    var z_early: f64;
    var small = false;
    var vieta = false;
    if (!near && k.disc > 0.0) {
        let uv = tc_cardano64(k.third_p, k.half_q, k.disc);
        z = max(uv.x + uv.y - k.a3, 0.0);
        let pair = (z + k.a) * (z + k.a) + 3.0 * (uv.x - uv.y) * (uv.x - uv.y);
        vieta = z < abs(k.a3) && pair > 0.0;
        z_early = z;
        if (vieta) {
            let half_sp = 0.5 * sqrt(pair);
            m = abs(q) / half_sp;
            q_over_m = tc_copysign64(half_sp, q);
            z = 4.0 * q * q / pair;
        } else {
            m = sqrt(z);
            q_over_m = q / m;
        }
    } else {
        var w: f64;
        if (near) {
            w = tc_resolvent_near_double64(k);
        } else {
            w = tc_trigonometric64(k.third_p, k.half_q);
        }
        z = max(w - k.a3, 0.0);
        small = k.b > 0.0 && z * (z + abs(k.a)) <= TC_FIN_SMALL_ROOT * k.b;
        if (small) {
            let z0 = q * q / k.b;
            z = q * q / ((z0 + k.a) * z0 + k.b);
        }
        m = sqrt(z);
        q_over_m = q / z * m;
        z_early = z;
    }
    if (!vieta && (small || abs(k.disc) <= TC_FIN_POLISH_BELOW * k.scale)) {
        z = tc_polish64(k, z);
        m = sqrt(z);
        q_over_m = q / m;
        z_early = z;
    }
    return TcRoot64(z, tc_cubic_dh64(k, z_early), m, q_over_m, vieta, z_early);
}

// ---------------------------------------------------------------------------------------
// Ferrari's split (factor.rs, split_at).

struct TcSplit64 {
    z: f64,
    m: f64,
    n1: f64,
    n2: f64,
};

fn tc_split64(p: f64, q: f64, r: f64) -> TcSplit64 {
    let root = tc_greatest_root64(p, q, r);
    let s = p + root.z_early;
    let w2 = s * s - 4.0 * r;
    let b_abs = p * p + 4.0 * abs(r);
    let ze = root.z_early;
    let h_mag = ((ze + 2.0 * abs(p)) * ze + b_abs) * ze + q * q;
    let zdh = root.z * root.dh;
    let err_w_zdh = TC_FIN_EPS
        * ((s * s + 4.0 * abs(r) + 2.0 * abs(s) * abs(p)) * zdh + 2.0 * abs(s) * h_mag * root.z);
    let use_q_over_m = root.q_over_m_exact
        || (zdh > 0.0 && (w2 <= 0.0 || TC_FIN_EPS * h_mag * w2 <= err_w_zdh));
    var d: f64;
    if (use_q_over_m) {
        d = root.q_over_m;
    } else {
        d = tc_copysign64(sqrt(max(w2, 0.0)), q);
    }
    let n1_direct = 0.5 * (s - d);
    let n2_direct = 0.5 * (s + d);
    let n2_bigger = abs(n2_direct) >= abs(n1_direct);
    let big = select(n1_direct, n2_direct, n2_bigger);
    var other = 0.0lf;
    if (big != 0.0) {
        other = r / big;
    }
    let n1 = select(n1_direct, other, n2_bigger);
    let n2 = select(other, n2_direct, n2_bigger);
    return TcSplit64(root.z, root.m, n1, n2);
}

// ---------------------------------------------------------------------------------------
// The near-double cold path (factor.rs, quadratic_factor and near_double_root), on the
// depressed quartic itself: orig = [1, 0, p, q, r], shift 0.

struct TcEval2_64 {
    f: f64,
    df: f64,
    d2f: f64,
};

fn tc_eval2_64(p: f64, q: f64, r: f64, x: f64) -> TcEval2_64 {
    // Horner over [1, 0, p, q, r] (quartic/mod.rs, eval2), unrolled.
    var f = 1.0lf;
    var df = 0.0lf;
    var d2f = 0.0lf;
    d2f = d2f * x + 2.0 * df;
    df = df * x + f;
    f = f * x + 0.0;
    d2f = d2f * x + 2.0 * df;
    df = df * x + f;
    f = f * x + p;
    d2f = d2f * x + 2.0 * df;
    df = df * x + f;
    f = f * x + q;
    d2f = d2f * x + 2.0 * df;
    df = df * x + f;
    f = f * x + r;
    return TcEval2_64(f, df, d2f);
}

fn tc_eval1_64(p: f64, q: f64, r: f64, x: f64) -> vec2<f64> {
    // Horner over [1, 0, p, q, r] (quartic/mod.rs, eval), unrolled.
    var f = 1.0lf;
    var df = 0.0lf;
    df = df * x + f;
    f = f * x + 0.0;
    df = df * x + f;
    f = f * x + p;
    df = df * x + f;
    f = f * x + q;
    df = df * x + f;
    f = f * x + r;
    return vec2<f64>(f, df);
}

// Σ|cᵢ|·|x|ⁱ, Horner on absolute values.
fn tc_magnitude64(p: f64, q: f64, r: f64, x: f64) -> f64 {
    let ax = abs(x);
    return (((ax + 0.0) * ax + abs(p)) * ax + abs(q)) * ax + abs(r);
}

// The nearest in [lo, hi] of a near-double pair around x0 (TC_FIN_NONE: complex, or out of
// range).
fn tc_near_double_root64(p: f64, q: f64, r: f64, x0: f64, spread: f64, lo: f64, hi: f64) -> f64 {
    let t0 = x0;
    let mag0 = tc_magnitude64(p, q, r, t0);
    let e0 = tc_eval2_64(p, q, r, t0);
    let halfwidth = spread + 4.0 * sqrt(TC_FIN_EIGHT_EPS * mag0 / abs(e0.d2f));
    var t = t0;
    for (var i = 0; i < 4; i++) {
        let e = tc_eval2_64(p, q, r, t);
        if (e.d2f == 0.0) {
            break;
        }
        let tn = t - e.df / e.d2f;
        if (!(abs(tn - t0) <= halfwidth)) {
            break;
        }
        let step = abs(tn - t);
        t = tn;
        if (step <= TC_FIN_FOUR_EPS * abs(t)) {
            break;
        }
    }
    let e = tc_eval2_64(p, q, r, t);
    let mag = tc_magnitude64(p, q, r, t);
    let real = e.f * e.d2f < 0.0;
    if (!(real || abs(e.f) <= TC_FIN_TOUCH_EPS * mag)) {
        return TC_FIN_NONE;
    }
    // Split where the sign of f(t*) is beyond the evaluation's rounding (SIGN_SURE).
    var delta = 0.0lf;
    if (real && abs(e.f) > TC_FIN_SIGN_SURE_EPS * mag) {
        delta = sqrt(-2.0 * e.f / e.d2f);
    }
    if (delta == 0.0) {
        return tc_in_range64(t, true, lo, hi);
    }
    var xs = array<f64, 2>(t - delta, t + delta);
    var live = array<bool, 2>(true, true);
    for (var it = 0; it < 3; it++) {
        for (var k = 0; k < 2; k++) {
            if (!live[k]) {
                continue;
            }
            let side = select(1.0lf, -1.0lf, k == 0);
            let x = xs[k];
            let e1 = tc_eval1_64(p, q, r, x);
            var ok = e1.x != 0.0 && e1.y != 0.0;
            var xn = x;
            if (ok) {
                xn = x - e1.x / e1.y;
                ok = (xn - t) * side > 0.0 && abs(xn - t) <= 4.0 * delta;
            }
            if (!ok) {
                live[k] = false;
                continue;
            }
            let step = abs(xn - x);
            xs[k] = xn;
            live[k] = step > TC_FIN_FOUR_EPS * abs(xn);
        }
    }
    return min(tc_in_range64(xs[0], true, lo, hi), tc_in_range64(xs[1], true, lo, hi));
}

// The roots of x² + b x + c (b² = z) nearest in [lo, hi], the near-double ones decided on
// the quartic.
fn tc_quadratic_factor64(p: f64, q: f64, r: f64, b: f64, c: f64, z: f64, lo: f64, hi: f64) -> f64 {
    let disc = z - 4.0 * c;
    let scale = z + 4.0 * abs(c);
    if (abs(disc) > TC_FIN_NEAR_DOUBLE * scale) {
        if (disc > 0.0) {
            let t = -0.5 * (b + tc_copysign64(sqrt(disc), b));
            var other = TC_FIN_NONE;
            if (t != 0.0) {
                other = tc_in_range64(c / t, true, lo, hi);
            }
            return min(tc_in_range64(t, true, lo, hi), other);
        }
        return TC_FIN_NONE;
    }
    return tc_near_double_root64(p, q, r, -0.5 * b, sqrt(abs(disc)), lo, hi);
}

// ---------------------------------------------------------------------------------------
// The nearest root in range (nearest.rs, nearest_root_in_range). Returns (u, found,
// host): host is true where the pass cannot decide like the CPU (a value not finite).

struct TcNearest64 {
    u: f64,
    found: bool,
    host: bool,
};

fn tc_surely_no_real_root64(p: f64, q: f64, r: f64) -> bool {
    let p2 = p * p;
    let q2 = q * q;
    let r_abs = abs(r);
    let e = p2 - 4.0 * r;
    let e_abs = p2 + 4.0 * r_abs;
    let g = 4.0 * p * (p2 - 36.0 * r) + 27.0 * q2;
    let g_abs = 4.0 * abs(p) * (p2 + 36.0 * r_abs) + 27.0 * q2;
    let disc = 16.0 * r * e * e - q2 * g;
    let disc_abs = 16.0 * r_abs * e_abs * e_abs + q2 * g_abs;
    return disc > TC_FIN_THIRTY_TWO_EPS * disc_abs && (p > 0.0 || -e > TC_FIN_EIGHT_EPS * e_abs);
}

// Whether the even quartic's p² − 4r lies within rounding of 0 (a tangent at the foot
// point), where its sign decides hit or miss. The CPU takes it from a fused multiply-add,
// rounded once; WGSL's `fma` need not be fused on every driver (Vulkan allows a separate
// multiply and add), so the device does not decide it and hands the ray to the host.
fn tc_even_near_double64(p: f64, r: f64) -> bool {
    let disc = p * p - 4.0 * r;
    let scale = p * p + 4.0 * abs(r);
    return abs(disc) <= TC_FIN_NEAR_DOUBLE * scale;
}

// The even quartic x⁴ + p x² + r (even.rs, nearest_root), away from a tangent
// (`tc_even_near_double64` false): the nearest root in range or TC_FIN_NONE.
fn tc_even_nearest64(p: f64, r: f64, lo: f64, hi: f64) -> f64 {
    let disc = p * p - 4.0 * r;
    if (disc < 0.0) {
        return TC_FIN_NONE;
    }
    let y1 = -0.5 * (p + tc_copysign64(sqrt(disc), p));
    var y2 = 0.0lf;
    if (y1 != 0.0) {
        y2 = r / y1;
    }
    let x1 = sqrt(max(y1, 0.0));
    let x2 = sqrt(max(y2, 0.0));
    let real1 = y1 >= 0.0;
    let real2 = y2 >= 0.0;
    return min(
        min(tc_in_range64(-x1, real1, lo, hi), tc_in_range64(x1, real1, lo, hi)),
        min(tc_in_range64(-x2, real2, lo, hi), tc_in_range64(x2, real2, lo, hi)),
    );
}

fn tc_nearest_root64(p: f64, q: f64, r: f64, lo: f64, hi: f64) -> TcNearest64 {
    if (!(tc_finite64(p) && tc_finite64(q) && tc_finite64(r))) {
        return TcNearest64(0.0, false, true);
    }
    if (tc_surely_no_real_root64(p, q, r)) {
        return TcNearest64(0.0, false, false);
    }
    if (q == 0.0 && p * p + 4.0 * abs(r) < TC_FIN_HUGE) {
        if (tc_even_near_double64(p, r)) {
            return TcNearest64(0.0, false, true);
        }
        let best = tc_even_nearest64(p, r, lo, hi);
        return TcNearest64(best, best < TC_FIN_NONE, false);
    }
    let f = tc_split64(p, q, r);
    if (!(tc_finite64(f.z) && tc_finite64(f.m) && tc_finite64(f.n1) && tc_finite64(f.n2))) {
        return TcNearest64(0.0, false, true);
    }
    let disc1 = f.z - 4.0 * f.n1;
    let disc2 = f.z - 4.0 * f.n2;
    let clear = abs(disc1) > TC_FIN_NEAR_DOUBLE * (f.z + 4.0 * abs(f.n1))
        && abs(disc2) > TC_FIN_NEAR_DOUBLE * (f.z + 4.0 * abs(f.n2));
    var best: f64;
    if (clear) {
        let s1 = sqrt(max(disc1, 0.0));
        let s2 = sqrt(max(disc2, 0.0));
        let ok1 = disc1 > 0.0;
        let ok2 = disc2 > 0.0;
        let half_m = 0.5 * f.m;
        let first = min(
            tc_in_range64(-half_m - 0.5 * s1, ok1, lo, hi),
            tc_in_range64(-half_m + 0.5 * s1, ok1, lo, hi),
        );
        let second = min(
            tc_in_range64(half_m - 0.5 * s2, ok2, lo, hi),
            tc_in_range64(half_m + 0.5 * s2, ok2, lo, hi),
        );
        best = min(first, second);
    } else {
        best = min(
            tc_quadratic_factor64(p, q, r, f.m, f.n1, f.z, lo, hi),
            tc_quadratic_factor64(p, q, r, -f.m, f.n2, f.z, lo, hi),
        );
    }
    return TcNearest64(best, best < TC_FIN_NONE, false);
}

// ---------------------------------------------------------------------------------------
// A ray from a surface point (intersect/from_surface.rs): the origin's own root divided
// out of the quartic, the nearest root of the cubic left, past it.

// g(v) = v³ + a v² + b v + c and g′(v).
fn tc_cubic_g64(a: f64, b: f64, c: f64, v: f64) -> vec2<f64> {
    return vec2<f64>(((v + a) * v + b) * v + c, (3.0 * v + 2.0 * a) * v + b);
}

// A bound on g's rounding at v.
fn tc_cubic_rounding64(a: f64, b: f64, c: f64, v: f64) -> f64 {
    let x = abs(v);
    return TC_FIN_EIGHT_EPS * (((x + abs(a)) * x + abs(b)) * x + abs(c));
}

// The root of g in [x, y], where g is monotone and changes sign (gx of the sign of g(x)):
// Newton inside the shrinking bracket, bisection where a step would leave it.
fn tc_bracketed_root64(a: f64, b: f64, c: f64, x0: f64, y0: f64, gx: f64) -> f64 {
    let rising = gx < 0.0;
    var x = x0;
    var y = y0;
    var v = 0.5 * (x + y);
    for (var i = 0; i < 200; i++) {
        let g = tc_cubic_g64(a, b, c, v);
        if (g.x == 0.0) {
            return v;
        }
        if ((g.x < 0.0) == rising) {
            x = v;
        } else {
            y = v;
        }
        var next = 0.5 * (x + y);
        if (g.y != 0.0) {
            let newton = v - g.x / g.y;
            if (newton > x && newton < y) {
                next = newton;
            }
        }
        if (abs(next - v) <= TC_FIN_TWO_EPS * abs(next) || y - x <= TC_FIN_TWO_EPS * max(abs(y), abs(x))) {
            return next;
        }
        v = next;
    }
    return v;
}

struct TcCubicRoot64 {
    v: f64,
    found: bool,
};

// The smallest root of g in (lo, hi] (in [lo, hi] for lo > 0) by monotone pieces
// between the critical points (from_surface.rs, nearest_cubic_root).
fn tc_nearest_cubic_root64(a: f64, b: f64, c: f64, lo: f64, hi_in: f64) -> TcCubicRoot64 {
    let none = TcCubicRoot64(0.0, false);
    if (!(lo <= hi_in)) {
        return none;
    }
    let bound = 1.0 + max(abs(a), max(abs(b), abs(c)));
    let hi = min(hi_in, bound);
    if (lo > hi) {
        return none;
    }
    var ends = array<f64, 4>(lo, hi, hi, hi);
    var n = 1;
    // The critical points (roots of 3v² + 2av + b), ascending, without cancellation.
    let disc = a * a - 3.0 * b;
    if (disc > 0.0) {
        let q = -(a + tc_copysign64(sqrt(disc), a));
        let x = q / 3.0;
        var y = 0.0lf;
        if (q != 0.0) {
            y = b / q;
        }
        let first = min(x, y);
        let second = max(x, y);
        if (first > lo && first < hi) {
            ends[n] = first;
            n++;
        }
        if (second > lo && second < hi) {
            ends[n] = second;
            n++;
        }
    }
    ends[n] = hi;
    let open = lo == 0.0;
    var x = lo;
    var gx = tc_cubic_g64(a, b, c, lo).x;
    if (gx == 0.0 && !open) {
        return TcCubicRoot64(lo, true);
    }
    for (var k = 1; k <= n; k++) {
        let y = ends[k];
        let gy = tc_cubic_g64(a, b, c, y).x;
        if ((gx < 0.0 && gy > 0.0) || (gx > 0.0 && gy < 0.0)) {
            return TcCubicRoot64(tc_bracketed_root64(a, b, c, x, y, gx), true);
        }
        let at_end = y == hi;
        if (gy == 0.0 || (!at_end && abs(gy) <= tc_cubic_rounding64(a, b, c, y))) {
            return TcCubicRoot64(y, true);
        }
        x = y;
        gx = gy;
    }
    return none;
}

// The origin at u₀ is on the surface within TC_FIN_OWN_ROOT_REACH (in units of R;
// from_surface.rs, starts_on_the_surface; √(a² + b²) for the CPU's hypot).
fn tc_starts_on_the_surface64(o: vec3<f64>, inv_major: f64, minor_rel: f64) -> bool {
    let x = o * inv_major;
    let rho = sqrt(x.x * x.x + x.z * x.z);
    let off = abs(sqrt((rho - 1.0) * (rho - 1.0) + x.y * x.y) - minor_rel);
    return off <= TC_FIN_OWN_ROOT_REACH;
}

// The surface point nearest to o (torus frame): the core circle's nearest point, then r
// along the way to o (tube.rs, Tube::nearest_surface_point); o itself on the axis or the
// core circle, or where the result is not finite.
fn tc_nearest_surface_point64(o: vec3<f64>, major: f64, minor: f64) -> vec3<f64> {
    let rho = sqrt(o.x * o.x + o.z * o.z);
    if (!(rho > 0.0)) {
        return o;
    }
    let core = vec3<f64>(o.x, 0.0, o.z) * (major / rho);
    let off = o - core;
    let len = sqrt(tc_dot64(off, off));
    if (!(len > 0.0)) {
        return o;
    }
    return core + off * (minor / len);
}

// ---------------------------------------------------------------------------------------
// The driver (intersect/mod.rs, exact and intersect_reduced; nearest_hit.rs).

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
