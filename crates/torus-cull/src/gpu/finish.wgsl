// The device's f64 finish (src/gpu/finish.rs runs it): the second compute pass, on an
// adapter with SHADER_F64, that answers every ray the certified f32 kernel escalated with
// the CPU's f64 method, step for step:
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
// Every threshold comes from the generated header (FIN_*), written from the Rust
// constants the CPU uses. Where the pass cannot give the CPU's answer (a value it does
// not hold finite), it hands the ray back to the host: status FIN_HOST.
//
// Per ray, in: the world ray (origin, t_min, dir, t_max as f32, widened exactly) and the
// host's instruction in word 7 of its output record (FIN_FOLLOW: finish where the f32
// kernel escalated; FIN_ALWAYS: finish it whatever the kernel wrote; FIN_SURFACE_FOLLOW
// and FIN_SURFACE_ALWAYS: the same for a ray from a surface point; FIN_HOST: the host
// answers it). Out: (t, normal.xyz) and (point.xyz, status) as f32, t, the normal and
// the point rounded once from f64, as the CPU's Hit is.

struct Params {
    // The f32 kernel's uniform block: only config.x (rays in this dispatch) is read.
    torus: array<vec4<f32>, 7>,
    config: vec4<u32>,
};

@group(0) @binding(0) var<uniform> params: Params;
// (origin, t_min) and (dir, t_max), world space, as the caller gave them.
@group(0) @binding(1) var<storage, read> world: array<vec4<f32>>;
// The f32 kernel's records: (t, n.xyz) and (code, why, 0, 0).
@group(0) @binding(2) var<storage, read> verdicts: array<vec4<f32>>;
// The torus in f64: centre (3), the columns of the world → torus rotation M (9), R, 1/R,
// r/R, 1 − (r/R)², 1 + r/R (the CPU's Tube).
@group(0) @binding(3) var<storage, read> torus64: array<f64, 17>;
@group(0) @binding(4) var<storage, read_write> finished: array<vec4<f32>>;

// (x·x′ + y·y′) + z·z′, glam's order.
fn dot64(a: vec3<f64>, b: vec3<f64>) -> f64 {
    return (a.x * b.x + a.y * b.y) + a.z * b.z;
}

fn copysign64(x: f64, s: f64) -> f64 {
    return select(abs(x), -abs(x), s < 0.0);
}

fn finite64(x: f64) -> bool {
    return abs(x) < FIN_HUGE;
}

// x if it is a real root in [lo, hi], else FIN_NONE (pick.rs, in_range).
fn in_range64(x: f64, real: bool, lo: f64, hi: f64) -> f64 {
    return select(FIN_NONE, x, real && x >= lo && x <= hi);
}

// ---------------------------------------------------------------------------------------
// The cube root and the trisection (num/cube_root.rs, quartic/trisect.rs).

fn cbrt_halley64(t: f64, y: f64) -> f64 {
    let t3 = t * t * t;
    return t * ((t3 + 2.0 * y) / (2.0 * t3 + y));
}

// ∛y for y ≥ 0: y brought into the f32 seed's range by exact powers 2^±90 (cube root
// 2^±30), Kahan's f32 seed and two f32 Halley steps (relative error ≲ 2·10⁻⁷), then one
// f64 Halley step, which cubes it (≲ 10⁻²⁰, below rounding); the CPU's cbrt is a fit
// and one Halley step, also below rounding.
fn cbrt64(y0: f64) -> f64 {
    if (y0 <= 0.0) {
        return 0.0;
    }
    var y = y0;
    var scale = 1.0lf;
    for (var i = 0; i < 12 && y < FIN_CBRT_LOW; i++) {
        y = y * FIN_TWO_90;
        scale = scale * FIN_TWO_M30;
    }
    for (var i = 0; i < 12 && y > FIN_CBRT_HIGH; i++) {
        y = y * FIN_TWO_M90;
        scale = scale * FIN_TWO_30;
    }
    let y32 = f32(y);
    var s = bitcast<f32>(bitcast<u32>(y32) / 3u + FIN_CBRT_SEED);
    s = s * ((s * s * s + 2.0 * y32) / (2.0 * s * s * s + y32));
    s = s * ((s * s * s + 2.0 * y32) / (2.0 * s * s * s + y32));
    return cbrt_halley64(f64(s), y) * scale;
}

// Estrin's degree-5 polynomial (num/poly.rs).
fn poly5_64(x: f64) -> f64 {
    let x2 = x * x;
    let x4 = x2 * x2;
    let low = FIN_TRISECT_FIT_4 * x + FIN_TRISECT_FIT_5;
    let mid = FIN_TRISECT_FIT_2 * x + FIN_TRISECT_FIT_3;
    let high = FIN_TRISECT_FIT_0 * x + FIN_TRISECT_FIT_1;
    return (low + x2 * mid) + x4 * high;
}

// u = 2 cos(arccos(x)/3) − 1 (trisect.rs, trisect_u).
fn trisect_u64(x: f64) -> f64 {
    let rhs = 2.0 * (1.0 + x);
    if (!(rhs > 0.0)) {
        return 0.0;
    }
    let s = sqrt(rhs * FIN_THIRD);
    let u = s * poly5_64(s - FIN_TRISECT_HALF_RANGE);
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

struct Cubic64 {
    a: f64,
    b: f64,
    c: f64,
    a3: f64,
    third_p: f64,
    half_q: f64,
    disc: f64,
    scale: f64,
};

fn cubic64(p: f64, q: f64, r: f64) -> Cubic64 {
    let a = 2.0 * p;
    let b = p * p - 4.0 * r;
    let c = -q * q;
    let a3 = a * FIN_THIRD;
    let p2 = p * p;
    let r43 = r * FIN_FOUR_THIRDS;
    let third_p = -(p2 * FIN_NINTH + r43);
    let half_q = p * (r43 - p2 * FIN_TWENTY_SEVENTH) - 0.5 * (q * q);
    let cube = third_p * third_p * third_p;
    let disc = half_q * half_q + cube;
    let scale = half_q * half_q + abs(cube);
    return Cubic64(a, b, c, a3, third_p, half_q, disc, scale);
}

fn cubic_h64(k: Cubic64, z: f64) -> f64 {
    return ((z + k.a) * z + k.b) * z + k.c;
}

fn cubic_dh64(k: Cubic64, z: f64) -> f64 {
    return (3.0 * z + 2.0 * k.a) * z + k.b;
}

// Cardano's (u, v) for disc ≥ 0: the cube root of the larger-magnitude term.
fn cardano64(third_p: f64, half_q: f64, disc: f64) -> vec2<f64> {
    let cube = abs(half_q) + sqrt(max(disc, 0.0));
    let big = cbrt64(cube);
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
fn trigonometric64(third_p: f64, half_q: f64) -> f64 {
    if (!(third_p < 0.0)) {
        // k = 0 (the CPU's clamped NaN gives k·(1 + u) = 0 too).
        return 0.0;
    }
    let k = sqrt(-third_p);
    let cos3 = clamp((half_q / third_p) * sqrt(-1.0 / third_p), -1.0, 1.0);
    return k + k * trisect_u64(cos3);
}

// Δ ≈ 0: whether the top pair is real decides the greatest root (resolvent.rs,
// near_double).
fn resolvent_near_double64(k: Cubic64) -> f64 {
    let one = cardano64(k.third_p, k.half_q, 0.0);
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
    if (cubic_h64(k, z_min) <= 0.0) {
        return max(trigonometric64(k.third_p, k.half_q), z_min + k.a3);
    }
    return one.x + one.y;
}

fn polish64(k: Cubic64, z0: f64) -> f64 {
    var z = z0;
    var hz = cubic_h64(k, z);
    for (var i = 0; i < 2; i++) {
        let dh = cubic_dh64(k, z);
        if (dh == 0.0) {
            break;
        }
        let zn = max(z - hz / dh, 0.0);
        let hn = cubic_h64(k, zn);
        if (abs(hn) < abs(hz)) {
            z = zn;
            hz = hn;
        }
    }
    return z;
}

struct Root64 {
    z: f64,
    dh: f64,
    m: f64,
    q_over_m: f64,
    q_over_m_exact: bool,
    z_early: f64,
};

fn greatest_root64(p: f64, q: f64, r: f64) -> Root64 {
    let k = cubic64(p, q, r);
    let near = abs(k.disc) <= FIN_DISC_NEAR * k.scale;
    var z: f64;
    var m: f64;
    var q_over_m: f64;
    var z_early: f64;
    var small = false;
    var vieta = false;
    if (!near && k.disc > 0.0) {
        let uv = cardano64(k.third_p, k.half_q, k.disc);
        z = max(uv.x + uv.y - k.a3, 0.0);
        let pair = (z + k.a) * (z + k.a) + 3.0 * (uv.x - uv.y) * (uv.x - uv.y);
        vieta = z < abs(k.a3) && pair > 0.0;
        z_early = z;
        if (vieta) {
            let half_sp = 0.5 * sqrt(pair);
            m = abs(q) / half_sp;
            q_over_m = copysign64(half_sp, q);
            z = 4.0 * q * q / pair;
        } else {
            m = sqrt(z);
            q_over_m = q / m;
        }
    } else {
        var w: f64;
        if (near) {
            w = resolvent_near_double64(k);
        } else {
            w = trigonometric64(k.third_p, k.half_q);
        }
        z = max(w - k.a3, 0.0);
        small = k.b > 0.0 && z * (z + abs(k.a)) <= FIN_SMALL_ROOT * k.b;
        if (small) {
            let z0 = q * q / k.b;
            z = q * q / ((z0 + k.a) * z0 + k.b);
        }
        m = sqrt(z);
        q_over_m = q / z * m;
        z_early = z;
    }
    if (!vieta && (small || abs(k.disc) <= FIN_POLISH_BELOW * k.scale)) {
        z = polish64(k, z);
        m = sqrt(z);
        q_over_m = q / m;
        z_early = z;
    }
    return Root64(z, cubic_dh64(k, z_early), m, q_over_m, vieta, z_early);
}

// ---------------------------------------------------------------------------------------
// Ferrari's split (factor.rs, split_at).

struct Split64 {
    z: f64,
    m: f64,
    n1: f64,
    n2: f64,
};

fn split64(p: f64, q: f64, r: f64) -> Split64 {
    let root = greatest_root64(p, q, r);
    let s = p + root.z_early;
    let w2 = s * s - 4.0 * r;
    let b_abs = p * p + 4.0 * abs(r);
    let ze = root.z_early;
    let h_mag = ((ze + 2.0 * abs(p)) * ze + b_abs) * ze + q * q;
    let zdh = root.z * root.dh;
    let err_w_zdh = FIN_EPS
        * ((s * s + 4.0 * abs(r) + 2.0 * abs(s) * abs(p)) * zdh + 2.0 * abs(s) * h_mag * root.z);
    let use_q_over_m = root.q_over_m_exact
        || (zdh > 0.0 && (w2 <= 0.0 || FIN_EPS * h_mag * w2 <= err_w_zdh));
    var d: f64;
    if (use_q_over_m) {
        d = root.q_over_m;
    } else {
        d = copysign64(sqrt(max(w2, 0.0)), q);
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
    return Split64(root.z, root.m, n1, n2);
}

// ---------------------------------------------------------------------------------------
// The near-double cold path (factor.rs, quadratic_factor and near_double_root), on the
// depressed quartic itself: orig = [1, 0, p, q, r], shift 0.

struct Eval2 {
    f: f64,
    df: f64,
    d2f: f64,
};

fn eval2_64(p: f64, q: f64, r: f64, x: f64) -> Eval2 {
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
    return Eval2(f, df, d2f);
}

fn eval1_64(p: f64, q: f64, r: f64, x: f64) -> vec2<f64> {
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
fn magnitude64(p: f64, q: f64, r: f64, x: f64) -> f64 {
    let ax = abs(x);
    return (((ax + 0.0) * ax + abs(p)) * ax + abs(q)) * ax + abs(r);
}

// The nearest in [lo, hi] of a near-double pair around x0 (FIN_NONE: complex, or out of
// range).
fn near_double_root64(p: f64, q: f64, r: f64, x0: f64, spread: f64, lo: f64, hi: f64) -> f64 {
    let t0 = x0;
    let mag0 = magnitude64(p, q, r, t0);
    let e0 = eval2_64(p, q, r, t0);
    let halfwidth = spread + 4.0 * sqrt(FIN_EIGHT_EPS * mag0 / abs(e0.d2f));
    var t = t0;
    for (var i = 0; i < 4; i++) {
        let e = eval2_64(p, q, r, t);
        if (e.d2f == 0.0) {
            break;
        }
        let tn = t - e.df / e.d2f;
        if (!(abs(tn - t0) <= halfwidth)) {
            break;
        }
        let step = abs(tn - t);
        t = tn;
        if (step <= FIN_FOUR_EPS * abs(t)) {
            break;
        }
    }
    let e = eval2_64(p, q, r, t);
    let mag = magnitude64(p, q, r, t);
    let zero = abs(e.f) <= FIN_THIRTY_TWO_EPS * mag;
    if (!(zero || e.f * e.d2f < 0.0)) {
        return FIN_NONE;
    }
    var delta = 0.0lf;
    if (!(zero || e.d2f == 0.0)) {
        delta = sqrt(-2.0 * e.f / e.d2f);
    }
    if (delta == 0.0) {
        return in_range64(t, true, lo, hi);
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
            let e1 = eval1_64(p, q, r, x);
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
            live[k] = step > FIN_FOUR_EPS * abs(xn);
        }
    }
    return min(in_range64(xs[0], true, lo, hi), in_range64(xs[1], true, lo, hi));
}

// The roots of x² + b x + c (b² = z) nearest in [lo, hi], the near-double ones decided on
// the quartic.
fn quadratic_factor64(p: f64, q: f64, r: f64, b: f64, c: f64, z: f64, lo: f64, hi: f64) -> f64 {
    let disc = z - 4.0 * c;
    let scale = z + 4.0 * abs(c);
    if (abs(disc) > FIN_NEAR_DOUBLE * scale) {
        if (disc > 0.0) {
            let t = -0.5 * (b + copysign64(sqrt(disc), b));
            var other = FIN_NONE;
            if (t != 0.0) {
                other = in_range64(c / t, true, lo, hi);
            }
            return min(in_range64(t, true, lo, hi), other);
        }
        return FIN_NONE;
    }
    return near_double_root64(p, q, r, -0.5 * b, sqrt(abs(disc)), lo, hi);
}

// ---------------------------------------------------------------------------------------
// The nearest root in range (nearest.rs, nearest_root_in_range). Returns (u, found,
// host): host is true where the pass cannot decide like the CPU (a value not finite).

struct Nearest64 {
    u: f64,
    found: bool,
    host: bool,
};

fn surely_no_real_root64(p: f64, q: f64, r: f64) -> bool {
    let p2 = p * p;
    let q2 = q * q;
    let r_abs = abs(r);
    let e = p2 - 4.0 * r;
    let e_abs = p2 + 4.0 * r_abs;
    let g = 4.0 * p * (p2 - 36.0 * r) + 27.0 * q2;
    let g_abs = 4.0 * abs(p) * (p2 + 36.0 * r_abs) + 27.0 * q2;
    let disc = 16.0 * r * e * e - q2 * g;
    let disc_abs = 16.0 * r_abs * e_abs * e_abs + q2 * g_abs;
    return disc > FIN_THIRTY_TWO_EPS * disc_abs && (p > 0.0 || -e > FIN_EIGHT_EPS * e_abs);
}

// Whether the even quartic's p² − 4r lies within rounding of 0 (a tangent at the foot
// point), where its sign decides hit or miss. The CPU takes it from a fused multiply-add,
// rounded once; WGSL's `fma` need not be fused on every driver (Vulkan allows a separate
// multiply and add), so the device does not decide it and hands the ray to the host.
fn even_near_double64(p: f64, r: f64) -> bool {
    let disc = p * p - 4.0 * r;
    let scale = p * p + 4.0 * abs(r);
    return abs(disc) <= FIN_NEAR_DOUBLE * scale;
}

// The even quartic x⁴ + p x² + r (even.rs, nearest_root), away from a tangent
// (`even_near_double64` false): the nearest root in range or FIN_NONE.
fn even_nearest64(p: f64, r: f64, lo: f64, hi: f64) -> f64 {
    let disc = p * p - 4.0 * r;
    if (disc < 0.0) {
        return FIN_NONE;
    }
    let y1 = -0.5 * (p + copysign64(sqrt(disc), p));
    var y2 = 0.0lf;
    if (y1 != 0.0) {
        y2 = r / y1;
    }
    let x1 = sqrt(max(y1, 0.0));
    let x2 = sqrt(max(y2, 0.0));
    let real1 = y1 >= 0.0;
    let real2 = y2 >= 0.0;
    return min(
        min(in_range64(-x1, real1, lo, hi), in_range64(x1, real1, lo, hi)),
        min(in_range64(-x2, real2, lo, hi), in_range64(x2, real2, lo, hi)),
    );
}

fn nearest_root64(p: f64, q: f64, r: f64, lo: f64, hi: f64) -> Nearest64 {
    if (!(finite64(p) && finite64(q) && finite64(r))) {
        return Nearest64(0.0, false, true);
    }
    if (surely_no_real_root64(p, q, r)) {
        return Nearest64(0.0, false, false);
    }
    if (q == 0.0 && p * p + 4.0 * abs(r) < FIN_HUGE) {
        if (even_near_double64(p, r)) {
            return Nearest64(0.0, false, true);
        }
        let best = even_nearest64(p, r, lo, hi);
        return Nearest64(best, best < FIN_NONE, false);
    }
    let f = split64(p, q, r);
    if (!(finite64(f.z) && finite64(f.m) && finite64(f.n1) && finite64(f.n2))) {
        return Nearest64(0.0, false, true);
    }
    let disc1 = f.z - 4.0 * f.n1;
    let disc2 = f.z - 4.0 * f.n2;
    let clear = abs(disc1) > FIN_NEAR_DOUBLE * (f.z + 4.0 * abs(f.n1))
        && abs(disc2) > FIN_NEAR_DOUBLE * (f.z + 4.0 * abs(f.n2));
    var best: f64;
    if (clear) {
        let s1 = sqrt(max(disc1, 0.0));
        let s2 = sqrt(max(disc2, 0.0));
        let ok1 = disc1 > 0.0;
        let ok2 = disc2 > 0.0;
        let half_m = 0.5 * f.m;
        let first = min(
            in_range64(-half_m - 0.5 * s1, ok1, lo, hi),
            in_range64(-half_m + 0.5 * s1, ok1, lo, hi),
        );
        let second = min(
            in_range64(half_m - 0.5 * s2, ok2, lo, hi),
            in_range64(half_m + 0.5 * s2, ok2, lo, hi),
        );
        best = min(first, second);
    } else {
        best = min(
            quadratic_factor64(p, q, r, f.m, f.n1, f.z, lo, hi),
            quadratic_factor64(p, q, r, -f.m, f.n2, f.z, lo, hi),
        );
    }
    return Nearest64(best, best < FIN_NONE, false);
}

// ---------------------------------------------------------------------------------------
// A ray from a surface point (intersect/from_surface.rs): the origin's own root divided
// out of the quartic, the nearest root of the cubic left, past it.

// g(v) = v³ + a v² + b v + c and g′(v).
fn cubic_g64(a: f64, b: f64, c: f64, v: f64) -> vec2<f64> {
    return vec2<f64>(((v + a) * v + b) * v + c, (3.0 * v + 2.0 * a) * v + b);
}

// A bound on g's rounding at v.
fn cubic_rounding64(a: f64, b: f64, c: f64, v: f64) -> f64 {
    let x = abs(v);
    return FIN_EIGHT_EPS * (((x + abs(a)) * x + abs(b)) * x + abs(c));
}

// The root of g in [x, y], where g is monotone and changes sign (gx of the sign of g(x)):
// Newton inside the shrinking bracket, bisection where a step would leave it.
fn bracketed_root64(a: f64, b: f64, c: f64, x0: f64, y0: f64, gx: f64) -> f64 {
    let rising = gx < 0.0;
    var x = x0;
    var y = y0;
    var v = 0.5 * (x + y);
    for (var i = 0; i < 200; i++) {
        let g = cubic_g64(a, b, c, v);
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
        if (abs(next - v) <= FIN_TWO_EPS * abs(next) || y - x <= FIN_TWO_EPS * max(abs(y), abs(x))) {
            return next;
        }
        v = next;
    }
    return v;
}

struct CubicRoot64 {
    v: f64,
    found: bool,
};

// The smallest root of g in (lo, hi] (in [lo, hi] for lo > 0) by monotone pieces
// between the critical points (from_surface.rs, nearest_cubic_root).
fn nearest_cubic_root64(a: f64, b: f64, c: f64, lo: f64, hi_in: f64) -> CubicRoot64 {
    let none = CubicRoot64(0.0, false);
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
        let q = -(a + copysign64(sqrt(disc), a));
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
    var gx = cubic_g64(a, b, c, lo).x;
    if (gx == 0.0 && !open) {
        return CubicRoot64(lo, true);
    }
    for (var k = 1; k <= n; k++) {
        let y = ends[k];
        let gy = cubic_g64(a, b, c, y).x;
        if ((gx < 0.0 && gy > 0.0) || (gx > 0.0 && gy < 0.0)) {
            return CubicRoot64(bracketed_root64(a, b, c, x, y, gx), true);
        }
        let at_end = y == hi;
        if (gy == 0.0 || (!at_end && abs(gy) <= cubic_rounding64(a, b, c, y))) {
            return CubicRoot64(y, true);
        }
        x = y;
        gx = gy;
    }
    return none;
}

// The origin at u₀ is on the surface within FIN_OWN_ROOT_REACH (in units of R;
// from_surface.rs, starts_on_the_surface; √(a² + b²) for the CPU's hypot).
fn starts_on_the_surface64(o: vec3<f64>, inv_major: f64, minor_rel: f64) -> bool {
    let x = o * inv_major;
    let rho = sqrt(x.x * x.x + x.z * x.z);
    let off = abs(sqrt((rho - 1.0) * (rho - 1.0) + x.y * x.y) - minor_rel);
    return off <= FIN_OWN_ROOT_REACH;
}

// ---------------------------------------------------------------------------------------
// The driver (intersect/mod.rs, exact and intersect_reduced; nearest_hit.rs).

fn write_status(i: u32, status: u32) {
    finished[2u * i] = vec4<f32>(0.0, 0.0, 0.0, 0.0);
    finished[2u * i + 1u] = vec4<f32>(0.0, 0.0, 0.0, f32(status));
}

@compute @workgroup_size(64)
fn finish_main(@builtin(global_invocation_id) gid: vec3<u32>) {
    let i = gid.x;
    if (i >= params.config.x) {
        return;
    }
    let instruction = u32(finished[2u * i + 1u].w);
    if (instruction == FIN_HOST) {
        write_status(i, FIN_STATUS_HOST);
        return;
    }
    // A ray from a surface point (Ray::from_surface): its own root divided out, as the
    // CPU's exact() does.
    let surface = instruction == FIN_SURFACE_FOLLOW || instruction == FIN_SURFACE_ALWAYS;
    if (instruction == FIN_FOLLOW || instruction == FIN_SURFACE_FOLLOW) {
        // The host's decode of the f32 record (gpu/mod.rs, verdict): a miss, or a hit with
        // a finite t and normal, is proved; everything else escalated.
        let v0 = verdicts[2u * i];
        let code = verdicts[2u * i + 1u].x;
        let proved_hit = code == f32(FIN_CODE_HIT) && abs(v0.x) < 3.0e38
            && abs(v0.y) < 3.0e38 && abs(v0.z) < 3.0e38 && abs(v0.w) < 3.0e38;
        if (code == f32(FIN_CODE_MISS) || proved_hit) {
            write_status(i, FIN_STATUS_PROVED);
            return;
        }
    }
    let wo = world[2u * i];
    let wd = world[2u * i + 1u];
    let origin = vec3<f64>(f64(wo.x), f64(wo.y), f64(wo.z));
    let dir = vec3<f64>(f64(wd.x), f64(wd.y), f64(wd.z));
    let t_min = f64(wo.w);
    let t_max = f64(wd.w);
    // The line in the torus frame, in f64 (Torus::line_to_local_f64): M·(o − c), M·d.
    let c = vec3<f64>(torus64[0], torus64[1], torus64[2]);
    let m0 = vec3<f64>(torus64[3], torus64[4], torus64[5]);
    let m1 = vec3<f64>(torus64[6], torus64[7], torus64[8]);
    let m2 = vec3<f64>(torus64[9], torus64[10], torus64[11]);
    let major = torus64[12];
    let inv_major = torus64[13];
    let minor_rel = torus64[14];
    let k_normal = torus64[15];
    let outer = torus64[16];
    let rel = origin - c;
    let o = (m0 * rel.x + m1 * rel.y) + m2 * rel.z;
    let d = (m0 * dir.x + m1 * dir.y) + m2 * dir.z;
    // The foot point scaled by 1/R (reduce.rs, foot_line).
    let inv_len = 1.0 / sqrt(dot64(d, d));
    let dh = d * inv_len;
    let s = dot64(o, dh);
    let p = (o - dh * s) * inv_major;
    // The depressed quartic (reduce.rs, coefficients).
    let rho = sqrt(p.x * p.x + p.z * p.z);
    let tube = (p.y - minor_rel) * (p.y + minor_rel);
    let c2 = 2.0 * (rho - 1.0) * (rho + 1.0) + 2.0 * tube + 4.0 * dh.y * dh.y;
    let delta = dot64(p, dh);
    let c1 = 8.0 * (p.y - delta * dh.y) * dh.y;
    let c0 = ((rho - 1.0) * (rho - 1.0) + tube) * ((rho + 1.0) * (rho + 1.0) + tube);
    var u: f64;
    var t: f64;
    if (surface && starts_on_the_surface64(o, inv_major, minor_rel)) {
        // The origin's own root (three guarded Newton steps on Q from u₀), the cubic in
        // v = u − own, its nearest root past the origin (from_surface.rs, SurfaceCubic).
        let u0 = s * inv_major;
        var own = u0;
        var e = eval1_64(c2, c1, c0, u0);
        for (var it = 0; it < 3; it++) {
            if (e.x == 0.0 || e.y == 0.0) {
                break;
            }
            let next = own - e.x / e.y;
            let en = eval1_64(c2, c1, c0, next);
            if (!(abs(next - u0) <= FIN_OWN_ROOT_REACH && abs(en.x) < abs(e.x))) {
                break;
            }
            own = next;
            e = en;
        }
        let a3 = 4.0 * own;
        let a2 = 6.0 * own * own + c2;
        let a1 = e.y;
        let v_per_t = inv_major / inv_len;
        let shift = own - u0;
        let v_lo = max(max(t_min, 0.0) * v_per_t - shift, 0.0);
        let v_hi = t_max * v_per_t - shift;
        let root = nearest_cubic_root64(a3, a2, a1, v_lo, v_hi);
        if (!root.found) {
            write_status(i, FIN_STATUS_MISS);
            return;
        }
        t = (root.v + shift) / v_per_t;
        u = own + root.v;
    } else {
        let chord_sq = outer * outer * FIN_CHORD_SCALE - dot64(p, p);
        if (chord_sq < 0.0) {
            write_status(i, FIN_STATUS_MISS);
            return;
        }
        let len = 1.0 / inv_len;
        let lo = (t_min * len + s) * inv_major;
        let hi = (t_max * len + s) * inv_major;
        if ((lo > 0.0 && lo * lo > chord_sq) || (hi < 0.0 && hi * hi > chord_sq)) {
            write_status(i, FIN_STATUS_MISS);
            return;
        }
        let found = nearest_root64(c2, c1, c0, lo, hi);
        if (found.host) {
            write_status(i, FIN_STATUS_HOST);
            return;
        }
        if (!found.found) {
            write_status(i, FIN_STATUS_MISS);
            return;
        }
        u = found.u;
        t = (u * major - s) * inv_len;
    }
    // The normal (reduce.rs, normal), then to the world: Mᵀ·n.
    let x = p + dh * u;
    let w = dot64(x, x) + k_normal;
    let grad = vec3<f64>(w * x.x - 2.0 * x.x, w * x.y, w * x.z - 2.0 * x.z);
    let n = grad * (1.0 / sqrt(dot64(grad, grad)));
    let nw = vec3<f64>(dot64(m0, n), dot64(m1, n), dot64(m2, n));
    // FromExact: t must fit an f32 (round to nearest overflows from 2¹²⁸ − 2¹⁰³ up).
    if (!(abs(t) < FIN_F32_OVERFLOW)) {
        write_status(i, FIN_STATUS_MISS);
        return;
    }
    let point = origin + dir * t;
    if (!(abs(point.x) < FIN_F32_OVERFLOW && abs(point.y) < FIN_F32_OVERFLOW
        && abs(point.z) < FIN_F32_OVERFLOW)) {
        // A point f32 cannot hold (the CPU's would be infinite): the host's answer.
        write_status(i, FIN_STATUS_HOST);
        return;
    }
    let front = dot64(dir, nw) < 0.0;
    finished[2u * i] = vec4<f32>(f32(t), f32(nw.x), f32(nw.y), f32(nw.z));
    finished[2u * i + 1u] = vec4<f32>(
        f32(point.x),
        f32(point.y),
        f32(point.z),
        f32(select(FIN_STATUS_BACK, FIN_STATUS_FRONT, front)),
    );
}
