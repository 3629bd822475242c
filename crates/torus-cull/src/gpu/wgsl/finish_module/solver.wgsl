// ---------------------------------------------------------------------------------------
// The cube root and the trisection (num/cube_root.rs, quartic/trisect.rs).
//
// mirrors: tc_cbrt_halley64 -> crate::num::cube_root::cbrt_halley
// mirrors: tc_cbrt64 -> crate::num::cube_root::cbrt
// mirrors: tc_poly5_64 -> crate::num::poly::poly5
// mirrors: tc_trisect_u64 -> crate::quartic::trisect::trisect_u
// mirrors: tc_cubic64 -> crate::quartic::resolvent::cubic
// mirrors: tc_cubic_h64 -> crate::quartic::resolvent::Cubic::h
// mirrors: tc_cubic_dh64 -> crate::quartic::resolvent::Cubic::dh
// mirrors: tc_cardano64 -> crate::quartic::resolvent::cardano
// mirrors: tc_trigonometric64 -> crate::quartic::resolvent::trigonometric
// mirrors: tc_resolvent_near_double64 -> crate::quartic::resolvent::near_double
// mirrors: tc_polish64 -> crate::quartic::resolvent::polish
// mirrors: tc_greatest_root64 -> crate::quartic::resolvent::greatest_root
// mirrors: tc_split64 -> crate::quartic::factor::split_at
// mirrors: tc_eval2_64 -> crate::quartic::eval2
// mirrors: tc_eval1_64 -> crate::quartic::eval
// mirrors: tc_magnitude64 -> crate::quartic::pieces::magnitude
// mirrors: tc_near_double_root64 -> crate::quartic::factor::near_double_root
// mirrors: tc_quadratic_factor64 -> crate::quartic::factor::quadratic_factor
// mirrors: tc_surely_no_real_root64 -> crate::quartic::discriminant::surely_no_real_root
// mirrors: tc_mantissa64 -> crate::quartic::exact_sign::mantissa
// mirrors: tc_limbs64 -> crate::quartic::exact_sign::limbs
// mirrors: tc_disc_sign64 -> crate::quartic::exact_sign::disc_sign
// mirrors: tc_even_nearest64 -> crate::quartic::even::nearest_root
// mirrors: tc_nearest_root64 -> crate::quartic::nearest::nearest_root_in_range

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

// |x| = m·2^e with m an integer in [2⁵², 2⁵³), for finite nonzero x: scalings by powers
// of two, each exact, in loops bounded by f64's exponent range.
struct TcMantissa64 {
    m: f64,
    e: i32,
}

fn tc_mantissa64(x: f64) -> TcMantissa64 {
    let two_32 = 4294967296.0lf;
    let two_52 = 4503599627370496.0lf;
    let two_53 = 9007199254740992.0lf;
    var m = abs(x);
    var e = 0;
    for (var i = 0; i < 40 && m >= two_53 * two_32; i++) {
        m *= 1.0lf / two_32;
        e += 32;
    }
    for (var i = 0; i < 40 && m < two_52 / two_32; i++) {
        m *= two_32;
        e -= 32;
    }
    for (var i = 0; i < 40 && m >= two_53; i++) {
        m *= 0.5;
        e += 1;
    }
    for (var i = 0; i < 40 && m < two_52; i++) {
        m *= 2.0;
        e -= 1;
    }
    return TcMantissa64(m, e);
}

// The base-2¹⁸ limbs of an integer m < 2⁵³, lowest first.
fn tc_limbs64(m: f64) -> array<f64, 3> {
    let limb_base = 262144.0lf;
    let m2 = floor(m * (1.0lf / (limb_base * limb_base)));
    let rest = m - m2 * (limb_base * limb_base);
    let m1 = floor(rest * (1.0lf / limb_base));
    return array<f64, 3>(rest - m1 * limb_base, m1, m2);
}

// The exact sign of p² − 4r (−1, 0, 1), where the CPU rounds a fused multiply-add once.
// WGSL may contract a·b + c or not, and a shader compiler may re-associate sums it is not
// told are exact, so this works on integers held exactly in f64 (every value an integer
// below 2⁵³, or an exact power-of-two scaling), where any such rewriting gives the same
// bits: |p| = a·2^ea, 4r = d·2^ed with a, d in [2⁵², 2⁵³); the sign of a² − d·2^k,
// k = ed − 2ea, needs the product only for k = 52, 53, formed in 18-bit limbs and carried.
fn tc_disc_sign64(p: f64, r: f64) -> i32 {
    if (r <= 0.0) {
        return select(1, 0, p == 0.0 && r == 0.0);
    }
    if (p == 0.0) {
        return -1;
    }
    let a = tc_mantissa64(p);
    let d = tc_mantissa64(4.0 * r);
    let k = d.e - 2 * a.e;
    if (k <= 51) {
        return 1;
    }
    if (k >= 54) {
        return -1;
    }
    let limb_base = 262144.0lf;
    let x = tc_limbs64(a.m);
    let y = tc_limbs64(d.m);
    // d·2^k = Σ y_j·2^s·B^(j+2), k = 36 + s.
    let s = select(131072.0lf, 65536.0lf, k == 52);
    var limb = array<f64, 6>(
        x[0] * x[0],
        2.0 * x[0] * x[1],
        2.0 * x[0] * x[2] + x[1] * x[1] - y[0] * s,
        2.0 * x[1] * x[2] - y[1] * s,
        x[2] * x[2] - y[2] * s,
        0.0,
    );
    for (var i = 0; i < 5; i++) {
        let carry = floor(limb[i] * (1.0lf / limb_base));
        limb[i] -= carry * limb_base;
        limb[i + 1] += carry;
    }
    // Every limb below the top is in [0, 2¹⁸): the top's sign is the sign, if it has one.
    if (limb[5] != 0.0) {
        return select(-1, 1, limb[5] > 0.0);
    }
    let rest = limb[0] + limb[1] + limb[2] + limb[3] + limb[4];
    return select(0, 1, rest > 0.0);
}

// The even quartic x⁴ + p x² + r (even.rs, nearest_root), away from a tangent
// the nearest root in range or TC_FIN_NONE, its near-tangent sign exact.
fn tc_even_nearest64(p: f64, r: f64, lo: f64, hi: f64) -> f64 {
    var disc = p * p - 4.0 * r;
    if (abs(disc) <= TC_FIN_NEAR_DOUBLE * (p * p + 4.0 * abs(r))) {
        // A near-double y (a tangent at two points symmetric about the foot point): real
        // iff p² − 4r ≥ 0, decided exactly; its value good to an ulp of p², fused or not.
        let sign = tc_disc_sign64(p, r);
        if (sign < 0) {
            return TC_FIN_NONE;
        }
        disc = select(max(fma(p, p, -4.0 * r), 0.0), 0.0, sign == 0);
    }
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

