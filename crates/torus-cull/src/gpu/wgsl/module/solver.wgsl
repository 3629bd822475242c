// ---------------------------------------------------------------------------------------
// The solver: src/quartic/{resolvent,factor,nearest,trisect}.rs and src/num/cube_root.rs as
// the f32 lanes run them (src/quartic/lanes/{resolvent,nearest}.rs).
//
// mirrors: tc_poly5 -> crate::num::poly::poly5
// mirrors: tc_cbrt_halley -> crate::num::cube_root::cbrt_halley
// mirrors: tc_cbrt -> crate::num::cube_root::cbrt
// mirrors: tc_trisect_u -> crate::quartic::trisect::trisect_u
// mirrors: tc_cubic_of -> crate::quartic::resolvent::cubic
// mirrors: tc_cubic_h -> crate::quartic::resolvent::Cubic::h
// mirrors: tc_cubic_dh -> crate::quartic::resolvent::Cubic::dh
// mirrors: tc_greatest_root -> crate::quartic::lanes::resolvent::greatest_root
// mirrors: tc_copysign -> none (WGSL has no copysign)
// mirrors: tc_in_range -> crate::quartic::pick::in_range
// mirrors: tc_nearest_root -> crate::quartic::lanes::nearest::nearest_root

// Horner-free degree-5 polynomial, Estrin's scheme (num/poly.rs, poly5).
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

// u = 2 cos(arccos(x)/3) − 1 (quartic/trisect.rs, trisect_u).
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

// The greatest root z = m² ≥ 0 of the resolvent (quartic/lanes/resolvent.rs).
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

// The nearest root of x⁴ + p x² + q x + r in [lo, hi] (quartic/lanes/nearest.rs with
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

